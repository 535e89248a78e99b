/* SPDX-License-Identifier: MIT */
/* iskra/problems.h — reference problems with closed-form answers, for
 * measuring how accurate the integrators are (tests, `iskra bench accuracy`).
 *
 * A problem is plain data: a kind, its physical parameters, an end time T
 * and a particle count.  isk_problem_setup() turns an initialised
 * isk_system into that problem (forces and particles); the caller keeps its
 * own integrator and substeps and steps the system with isk_system_step(),
 * so whatever is measured is the library's real pipeline.
 * isk_problem_measure() then compares the system's state with the exact
 * answer at the system's current time.  Everything here is deterministic
 * and clock-free: timing belongs to the caller.
 *
 * Example: velocity Verlet's errors on the oscillator, 2000 steps:
 *
 *     isk_problem pb = isk_problem_defaults(ISK_PROBLEM_OSCILLATOR);
 *     isk_system s;
 *     isk_status st = isk_system_init(&s, 1, 0);
 *     if (st == ISK_OK) st = isk_system_set_integrator(&s, ISK_INTEGRATE_VERLET);
 *     if (st == ISK_OK) st = isk_problem_setup(&pb, &s);
 *     for (int k = 0; k < 2000 && st == ISK_OK; k++) st = isk_system_step(&s, pb.T / 2000);
 *     isk_problem_error e;
 *     if (st == ISK_OK) st = isk_problem_measure(&pb, &s, &e);
 *     if (st == ISK_OK) printf("errors: position %.2g, energy %.2g\n", e.position, e.energy);
 *     isk_system_free(&s);
 *     return st != ISK_OK;
 *
 * Particle i of n starts from two spreads in (0, 1): u = (i + 1/2)/n (an
 * angle or phase) and w = frac(1/2 + i/phi) (golden ratio: an even spread
 * of sizes, uncorrelated with u), with lerp(w) = start_min + (start_max -
 * start_min) w.  Mass m for all.  The closed forms (a = (0, -g), k = b/m):
 *
 * ISK_PROBLEM_PROJECTILE — gravity g and linear drag b (F = m a - b v).
 *   r0 = (0, 0), v0 = lerp(w) (cos th, sin th), th = 0.2 + 1.2 u rad.
 *       v(t) = v0 e^{-kt} + a t phi1(kt)
 *       r(t) = r0 + v0 t phi1(kt) + a t^2 phi2(kt)
 *   phi1(h) = (1 - e^{-h})/h, phi2(h) = (h - 1 + e^{-h})/h^2 (1 and 1/2 at
 *   h = 0: no drag is the parabola).  The same thing as the textbook
 *   v = v_inf + (v0 - v_inf) e^{-kt}, v_inf = a/k, without its cancellation
 *   for small k.  Errors: position, velocity.  Energy is not conserved.
 *
 * ISK_PROBLEM_OSCILLATOR — the thesis potential with code exponent P = 0 at
 *   the origin is a linear spring F = kQ (0 - r): w^2 = kQ/m (omega).
 *   A = lerp(w), ph = 2 pi u:  r0 = (A cos ph, A/2 sin ph),
 *   v0 = (-A w sin ph, A/2 w cos ph) (an ellipse, every phase represented).
 *       r(t) = r0 cos wt + (v0/w) sin wt,   v(t) = v0 cos wt - r0 w sin wt
 *       E = m|v|^2/2 + kQ |r|^2/2
 *   Errors: position, velocity, relative energy, phase.  Phase: per
 *   coordinate c (x, y) the phase-space point z = c - i v_c/w turns at rate
 *   w; the phase error is arg(z_numerical / z_exact) in (-pi, pi] (> 0: the
 *   numerical particle is ahead) and we report its largest magnitude.
 *
 * ISK_PROBLEM_RADIAL — the thesis Coulomb potential, P = 2, attracting,
 *   at the origin with core radius min (min_dist), x_mult 1:
 *   |F| = kQ d/min^2 for d <= min (linear) and kQ/d outside.  Particles
 *   start at rest at d0 = lerp(w) on the line at angle 2 pi u through the
 *   centre and oscillate along it, through the core.  The potential energy
 *   (U(0) = 0, dU/dd = |F|, continuous with continuous slope kQ/min at min):
 *       U(d) = kQ d^2 / (2 min^2)              d <= min
 *       U(d) = kQ/2 + kQ ln(d/min)             d >= min
 *       E = m|v|^2/2 + U(|r|),  E0 = U(d0) > 0
 *   There is no closed form for r(t); the error is the relative drift of
 *   the conserved energy.  |F| has a kink at d = min (its slope jumps from
 *   +kQ/min^2 to -kQ/min^2): high-order methods lose order there.
 *
 * ISK_PROBLEM_BOUNCE — gravity g onto a reflecting floor at y = 0 (the
 *   sound walls, restitution c, bouncing at the time of impact,
 *   iskra/impact.h).  Particle i is dropped at rest from h0 = lerp(w) at
 *   x = 0.  The exact motion: a fall of t_f = sqrt(2 h0/g) to speed
 *   V0 = g t_f, then flights of 2 V_k/g with V_k = c^k V0 (for c = 1 a
 *   period of 2 t_f: every apex is h0; for c < 1 the hops end at rest after
 *   t_f (1 + 2c/(1 - c))).  E = m (|v|^2/2 + g y) is m g h0 c^(2k) after k
 *   bounces.  Errors: position, velocity, relative energy |E - E_k| / E0.
 *   Before bounces were found at their time of impact (with the
 *   end-of-step velocity reflected) this problem's energy grew at every
 *   bounce with every integrator but the Euler forms.
 *
 * ISK_PROBLEM_KEPLER — the library's own P = 3 law (|F| = kQ/d^2, the
 *   inverse square: iskra/forces.h) from a potential at the origin, no
 *   core: every particle is on a Kepler ellipse of semi-major axis
 *   a = lerp(w) and eccentricity e (0.6 by default), periapsis towards
 *   angle 2 pi u, starting at mean anomaly 2 pi w.  With mu = kQ/m and the
 *   mean motion n = sqrt(mu/a^3) the exact position at t solves Kepler's
 *   equation E - e sin E = M0 + n t (Newton, to rounding):
 *       r' = (a (cos E - e), b sin E),  v' = (-a sin E, b cos E) n / (1 - e cos E)
 *   with b = a sqrt(1 - e^2), turned by the periapsis angle.  Conserved:
 *   E = m|v|^2/2 - kQ/d = -kQ/(2a) and L = m (x vy - y vx) =
 *   m sqrt(mu a (1 - e^2)).  Errors: position, velocity, relative energy,
 *   relative angular momentum, and the relative error of the period the
 *   numerical orbit has, (E0/E)^(3/2) - 1 (period ~ a^(3/2) ~ (-E)^(-3/2)).
 *
 * Errors are maxima over all particles.  A particle whose state is not
 * finite makes every error that applies +INFINITY and is counted in
 * `nonfinite`; errors that do not apply to the kind are NaN.
 */
#ifndef ISKRA_PROBLEMS_H
#define ISKRA_PROBLEMS_H

#include <stddef.h>

#include "iskra/status.h"
#include "iskra/system.h"
#include "iskra/vec2.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum isk_problem_kind {
    ISK_PROBLEM_PROJECTILE = 0, /* gravity + linear drag: exact r(t), v(t) */
    ISK_PROBLEM_OSCILLATOR,     /* P = 0 potential: harmonic, exact r, v, E, phase */
    ISK_PROBLEM_RADIAL,         /* P = 2 potential with a core: energy conserved */
    ISK_PROBLEM_BOUNCE,         /* gravity onto a reflecting floor: exact bounces */
    ISK_PROBLEM_KEPLER,         /* the P = 3 inverse-square law: Kepler ellipses */
    ISK_PROBLEM_COUNT
} isk_problem_kind;

typedef struct isk_problem {
    isk_problem_kind kind;
    size_t count;      /* particles, 1 .. ISK_PARTICLES_MAX */
    double T;          /* end time in seconds (> 0); the caller steps to it */
    double mass;       /* every particle's mass (> 0) */
    double gravity;    /* projectile: g, any finite value (F_y = -m g) */
    double drag;       /* projectile: b >= 0 */
    double kq;         /* oscillator, radial: k*Q > 0 (attracting) */
    double min_dist;   /* radial: core radius > 0 */
    double start_min;  /* spread of the start: launch speed (projectile), amplitude */
    double start_max;  /* (oscillator), release distance (radial), drop height (bounce),
                          semi-major axis (kepler); 0 < min <= max */
    double restitution; /* bounce: the floor's c in [0, 1] */
    double eccentricity; /* kepler: e in [0, 1) */
} isk_problem;

/* One particle's state. */
typedef struct isk_problem_state {
    isk_vec2 r, v;
} isk_problem_state;

typedef struct isk_problem_error {
    double time;      /* the system time at which it was measured */
    double position;  /* max |r - r_exact|             (projectile, oscillator) */
    double velocity;  /* max |v - v_exact|             (projectile, oscillator) */
    double energy;    /* max |E - E0| / E0              (oscillator, radial) */
    double phase;     /* max |phase error| in radians   (oscillator) */
    size_t nonfinite; /* particles with a NaN or infinite coordinate */
    double angular_momentum; /* max |L - L0| / |L0|        (kepler) */
    double period;    /* max |(E0/E)^(3/2) - 1|          (kepler) */
} isk_problem_error;

/* The parameters the accuracy study uses (count 1024; the study runs the
 * costlier oscillator and radial problems with 256):
 *   projectile  g 9.81, b 0.8, m 1, T 2 s, launch speeds 5..15
 *   oscillator  kQ 4 pi^2, m 1 (period 1 s), T 10.25 s, A 0.5..2 (a whole
 *               number of periods would sample the symplectic methods'
 *               bounded energy wobble at its zero and hide it)
 *   radial      kQ 4, min 0.1, m 1, T 5 s, d0 0.5..2 (periods 1.3..5 s)
 *   bounce      g 9.81, c 1, m 1, T 10 s, drop heights 1..4 m (4 to 11 bounces)
 *   kepler      kQ 4 pi^2, m 1, e 0.6, a 0.8..1.25 (periods 0.72..1.4 s), T 10.25 s
 * An unknown kind gives count 0 (which fails validation). */
isk_problem isk_problem_defaults(isk_problem_kind kind);

/* "projectile", "oscillator", "radial", "bounce", "kepler"; "?" if unknown. */
const char *isk_problem_name(isk_problem_kind kind);

/* Checks the fields the kind uses (others are ignored).  Errors:
 * ISK_ERR_NULL; ISK_ERR_RANGE (unknown kind; T, mass, kq, min_dist,
 * start_min <= 0; drag < 0; start_max < start_min; restitution outside
 * [0, 1]; eccentricity outside [0, 1); bounce gravity <= 0); ISK_ERR_SIZE
 * (count 0 or > ISK_PARTICLES_MAX); ISK_ERR_NAN (a used field not
 * finite). */
isk_status isk_problem_validate(const isk_problem *p);

/* State of particle i (< count) at t = 0.  Errors: validation, ISK_ERR_NULL,
 * ISK_ERR_RANGE (i >= count). */
isk_status isk_problem_initial(const isk_problem *p, size_t i, isk_problem_state *out);

/* Exact state of particle i at time t >= 0.  Errors as isk_problem_initial,
 * ISK_ERR_NAN / ISK_ERR_RANGE for a non-finite / negative t, and
 * ISK_ERR_UNSUPPORTED for ISK_PROBLEM_RADIAL (no closed form for r(t)). */
/* (For ISK_PROBLEM_BOUNCE the energy isk_problem_energy gives is the
 * state's; the exact one after k bounces is m g h0 c^(2k).) */
isk_status isk_problem_exact(const isk_problem *p, size_t i, double t, isk_problem_state *out);

/* Energy of a state (oscillator, radial, bounce, kepler; see the top).  Errors:
 * validation, ISK_ERR_NULL, ISK_ERR_UNSUPPORTED (projectile: drag removes
 * energy).  A non-finite state gives a non-finite *E, not an error. */
isk_status isk_problem_energy(const isk_problem *p, const isk_problem_state *st, double *E);

/* Makes the initialised system `s` run problem p: clears its particles and
 * adds p->count of them, replaces its forces (gravity, drag, potentials;
 * no acceleration), turns walls off (bounce: on, the floor alone, sound,
 * in the step), ageing and pending multi-Coulomb batches off and sets time
 * to 0.  Keeps the integrator, substeps, speed divisor
 * and rng: those are the caller's to choose.  All-or-nothing.  Errors:
 * validation, ISK_ERR_NULL, ISK_ERR_NOMEM. */
isk_status isk_problem_setup(const isk_problem *p, isk_system *s);

/* Errors of s (set up by isk_problem_setup and stepped since) against the
 * exact answer at s->time.  Errors: validation, ISK_ERR_NULL, ISK_ERR_SIZE
 * (the particle count is not p->count), ISK_ERR_NAN (s->time not finite). */
isk_status isk_problem_measure(const isk_problem *p, const isk_system *s, isk_problem_error *out);

/* The conserved-quantity errors now (energy; kepler: also angular momentum
 * and period), raised into *acc's running maxima, so that calling it after
 * every step gives their maxima over [0, T] instead of their values at T
 * (a bounded wobble sampled at T can sit at its zero).  Cheap: no exact
 * solve (the references are closed forms: E0, L0, and the bouncing ball's
 * E0 c^(2k)).  Start with acc's fields at 0.  Non-finite states raise them
 * to +INFINITY.  Errors as isk_problem_measure, ISK_ERR_UNSUPPORTED for the
 * projectile (it has no conserved quantity). */
isk_status isk_problem_track(const isk_problem *p, const isk_system *s, isk_problem_error *acc);

/* ---- a spring on a floor ----------------------------------------------------
 * The hard case of a bounce under a force that varies along the path: a
 * particle of mass 1 on a spring (a potential with P = 0, kQ = 4: omega =
 * 2) centred at the origin, released at rest from (0.6, 2) above a
 * restitution-1 floor at y = -1, which it meets once a swing (about every
 * 2 s).  E = |v|^2/2 + 2 |r|^2 is conserved, so a bounce must give back
 * the energy it took, to the integrator's own order (iskra/contacts.h).
 * isk_problem_spring_floor steps it with isk_system (walls at the time of
 * impact) for `seconds` at dt with `method`, with the floor (floor = 1) or
 * without (0: the integrator's own drift over the same time), and gives
 * the relative change of the energy E_end / E_0 - 1 and, with the floor,
 * the bounces (0 without).  The energy per bounce is then
 * (1 + change)^(1 / bounces) - 1 (docs/accuracy.md has the table, from
 * `iskra bench accuracy`).  Errors: ISK_ERR_RANGE (a method that is not
 * one of the eight, dt not in (0, ISK_DT_MAX], seconds not in (0, 1e6]),
 * ISK_ERR_NAN, ISK_ERR_NULL, ISK_ERR_NOMEM. */
typedef struct isk_spring_floor {
    double change; /* E_end / E_0 - 1 */
    int bounces;   /* contacts with the floor (0 without it) */
} isk_spring_floor;

isk_status isk_problem_spring_floor(isk_integrator method, double dt, double seconds, int floor,
                                    isk_spring_floor *out);
/* The same problem in your own system (an isk_system_init'ed one: its
 * forces, walls, particles and clock are replaced): `count` particles
 * all starting alike (more of them only make timings steadier), the floor
 * or not; and particle i's energy per unit mass, the conserved E.
 * ISK_ERR_NULL, ISK_ERR_RANGE (count 0 or over ISK_PARTICLES_MAX),
 * ISK_ERR_NOMEM. */
isk_status isk_problem_spring_floor_setup(isk_system *s, size_t count, int floor);
double isk_problem_spring_floor_energy(const isk_particles *p, size_t i);

#ifdef __cplusplus
}
#endif

#endif
