/* SPDX-License-Identifier: MIT */
/* iskra/forces.h — gravity, linear drag and the thesis's Coulomb potentials.
 *
 * Forces are stages: each one is a tight loop that ADDS its force into the
 * caller's accumulators.  The order is fixed and documented, because it is
 * what makes the thesis simulator's sums bit-identical:
 *
 *     fx = fy = 0
 *     gravity:  fy += m*(-g)                       (SilaTeza: F = (0, m*(-g)))
 *     accel:    fx += m*ax, fy += m*ay             (wind / buoyancy, iskra/effect.h)
 *     drag:     fx += (-b)*vx,  fy += (-b)*vy      (Otpor: F = -b*v)
 *     potentials, summed on their own:  P = ((0 + P1) + P2) + ...  (list order)
 *     F = (gravity + drag) + P
 *
 * A stage with zero strength (g == 0, b == 0, k*Q == 0, or a potential that
 * is switched off) is skipped and costs nothing; skipping is bit-exact (its
 * terms are zeros), except that the thesis code would produce NaN for a
 * particle sitting exactly on a switched-off or k=0 potential (0*n/0); we
 * give 0.
 *
 * Example: the forces on two particles, one of them 3 units from a potential:
 *
 *     isk_potential pot;
 *     isk_potential_init(&pot, 800, isk_vec2_make(5, 5), +1);   // k, r, Q
 *     isk_potential_set_law(&pot, ISK_COULOMB_LAW_CODE, 4);     // P = 4: |F| = 800/d^3
 *     pot.min_dist = 0.5;  pot.max_dist = 0.1;
 *     isk_forces f = { .gravity = 9.81, .drag = 0.47, .pot = &pot, .npot = 1 };
 *     double x[2] = {5, 0}, y[2] = {2, 0}, vx[2] = {0, 1}, vy[2] = {0, 0}, m[2] = {1, 2};
 *     double fx[2], fy[2], px[2], py[2];            // the forces; scratch for the potentials
 *     isk_forces_eval(&f, 2, x, y, vx, vy, m, fx, fy, px, py, 1);
 *     printf("F0 = (%g, %g), F1 = (%g, %g)\n", fx[0], fy[0], fx[1], fy[1]);
 *
 * Coulomb law (CoulombovPotencijal.F, thesis code):
 *     n = r_pot - r,  n.x *= x_mult,  d = |r_pot - r| (Euclidean, x_mult NOT applied)
 *     if max_dist > d: enabled = 0 for good (sticky), force 0 from this particle on
 *     if min_dist > d: d = min_dist      (clamps only the denominator)
 *     F = n * ((enabled*(Q*k)) / d^P)
 * so |F| = k|Q| d^(1-P) outside the min radius, and k*Q > 0 ATTRACTS (n points
 * to the potential).  Inside min_dist: F = kQ n / min^P, linear in the offset.
 * "Off" for min/max is any value <= 0 (the thesis uses -1, ISK_DIST_OFF).
 *
 * Exponent: the code's P is the text's p + 2.  The text writes
 *     F_i = k Q_i q (r - r_i) / |r - r_i|^(p+2),  magnitude k|Q_i q| / d^(p+1),
 * the code has magnitude k|Q| d^(1-P): equal when P = p + 2 (and the text's
 * sign equals ours with particle charge q = -1).  isk_potential_set_law takes
 * either: ISK_COULOMB_LAW_CODE with P, ISK_COULOMB_LAW_TEXT with p.  With the
 * thesis's P = 2 (all explosions) the force falls off as 1/d.
 * d^P: P == 2 is d*d and P == 1 is d (bit-exact with JavaScript); any other P
 * uses pow(), which JS engines do not reproduce bit for bit (catalogue §1.6).
 *
 * Exactly at the centre (d == 0): with a min distance the force is 0 (n = 0).
 * Without one, the thesis computes 0*(kQ/0) = NaN; that is what
 * ISK_FIDELITY_THESIS reproduces (and close to the centre it overflows to
 * +-Inf just as the thesis would).  ISK_FIDELITY_SOUND (the default, 0)
 * never produces NaN or Inf:
 *   - exactly at the centre (n = 0) the force is (0, 0): the law has no
 *     direction there, and a symmetric field pulls equally every way;
 *   - wherever the law's force is not representable or has a component
 *     beyond ISK_FORCE_LIMIT (1e150) in magnitude (d^P underflowing, e.g.
 *     d = 1e-150 with P = 9, or simply a huge force near the centre), it
 *     SATURATES: same direction n, larger component exactly +-1e150.
 *   - a particle whose offset from the potential is not finite (an Inf or
 *     NaN position) feels no force from it.
 * Forces below the limit are bit-identical to the thesis's.  1e150 is far
 * beyond any physical scene, and small enough that F^2, v^2 and v*dt sums
 * stay finite, so a saturated kick never turns into Inf downstream.  Near
 * the centre without a min distance the force is still as large as the law
 * says up to the limit (use min_dist to soften it).
 *
 * Motion: a potential moves by `vel * param` (the thesis's pomak(param) =
 * (0, 20*param) is vel = (0, 20)) or, when `motion` is set, by the vector the
 * callback returns: r = r + motion(ctx, param).
 */
#ifndef ISKRA_FORCES_H
#define ISKRA_FORCES_H

#include <stddef.h>

#include "iskra/limits.h" /* ISK_FORCE_LIMIT: the largest force component (see the top) */
#include "iskra/status.h"
#include "iskra/vec2.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ISK_DIST_OFF (-1.0)

typedef enum isk_fidelity {
    ISK_FIDELITY_SOUND = 0,  /* physically sound, never NaN (default) */
    ISK_FIDELITY_THESIS = 1, /* the thesis code's exact behaviour, quirks included */
    ISK_FIDELITY_COUNT
} isk_fidelity;

typedef enum isk_coulomb_law {
    ISK_COULOMB_LAW_CODE = 0, /* exponent is the code's P: |F| = k|Q| d^(1-P) */
    ISK_COULOMB_LAW_TEXT = 1, /* exponent is the text's p: P = p + 2, |F| = k|Q| / d^(p+1) */
    ISK_COULOMB_LAW_COUNT
} isk_coulomb_law;

/* Names as scene files spell them, indexed by value. */
extern const char *const isk_fidelity_names[ISK_FIDELITY_COUNT];  /* "sound", "thesis" */
extern const char *const isk_coulomb_law_names[ISK_COULOMB_LAW_COUNT]; /* "code", "text" */

/* Displacement of a moving potential for a motion parameter (the thesis
 * passes the frame's simulated time dt/f). */
typedef isk_vec2 (*isk_potential_motion_fn)(void *ctx, double param);

typedef struct isk_potential {
    int id;            /* 1, 2, 3, ... assigned by the system (the thesis's br) */
    isk_vec2 r;        /* position */
    double k;          /* strength */
    double charge;     /* Q (naboj); k*Q > 0 attracts */
    double P;          /* code exponent (potencijalUdaljenosti), default 2 */
    double min_dist;   /* minUdaljenost, <= 0 off (default -1) */
    double max_dist;   /* maxUdaljenost, <= 0 off (default -1); sticky switch-off */
    double x_mult;     /* xMnozitelj, scales n.x only (default 1) */
    int enabled;       /* ukljuci: 1 on, 0 off */
    isk_vec2 vel;      /* motion: r += vel*param (default (0,0)) */
    isk_potential_motion_fn motion; /* overrides vel when non-NULL */
    void *motion_ctx;
} isk_potential;

/* The thesis constructor's defaults: P 2, min/max off, x_mult 1, on, still. */
void isk_potential_init(isk_potential *pot, double k, isk_vec2 r, double charge);

/* Sets P from either law.  Errors: ISK_ERR_NULL, ISK_ERR_NAN (non-finite
 * exponent), ISK_ERR_RANGE (unknown law). */
isk_status isk_potential_set_law(isk_potential *pot, isk_coulomb_law law, double exponent);

/* Checks every field (finite numbers, enabled 0/1, and the limits of
 * iskra/limits.h: P in [ISK_P_MIN, ISK_P_MAX], position within ISK_COORD_MAX,
 * velocity within ISK_SPEED_LIMIT).  Errors: ISK_ERR_NULL, ISK_ERR_NAN,
 * ISK_ERR_RANGE. */
isk_status isk_potential_validate(const isk_potential *pot);

/* Force on one particle at (x, y); may switch the potential off (max_dist).
 * A switched-off potential gives (0, 0). */
isk_vec2 isk_potential_force(isk_potential *pot, double x, double y, isk_fidelity centre);

/* r = r + displacement(param). */
void isk_potential_move(isk_potential *pot, double param);

typedef struct isk_forces {
    double gravity;       /* g, F = (0, m*(-g)); 0 skips the stage */
    double ax, ay;        /* a constant acceleration (wind, buoyancy): F = m*(ax, ay),
                             added after gravity; (0, 0) skips the stage */
    double drag;          /* b, F = -b*v; 0 skips the stage */
    isk_potential *pot;   /* potentials, acted in list order */
    size_t npot;
    const size_t *pick;   /* NULL: every potential pot[0..npot) acts; otherwise only
                             pot[pick[0]], ..., pot[pick[npick-1]], in that order (a system of
                             many emitters shares one array of potentials, each emitter picks) */
    size_t npick;
    isk_fidelity centre;  /* behaviour exactly on a potential without min (see top) */
} isk_forces;

/* The force laws, as bits of a set: what acts in an isk_forces.  Every
 * evaluation sums the laws that act, in this order (gravity, constant
 * acceleration, drag, then the potentials summed on their own and added
 * last); a fast path that knows only some laws runs only when the set
 * holds nothing else, so a law added to the library is never skipped. */
enum {
    ISK_LAW_GRAVITY = 1u << 0,  /* F = (0, m*(-g)) */
    ISK_LAW_ACCEL = 1u << 1,    /* F = m*(ax, ay) */
    ISK_LAW_DRAG = 1u << 2,     /* F = -b*v */
    ISK_LAW_POWER_2 = 1u << 3,  /* a potential with P = 2 (Coulomb's inverse square) */
    ISK_LAW_POWER_1 = 1u << 4,  /* a potential with P = 1 */
    ISK_LAW_POWER = 1u << 5,    /* a potential with any other P (a pow() a particle) */
    ISK_LAW_CUTOFF = 1u << 6    /* a potential that switches itself off at max_dist */
};
/* The laws that act in f: those whose strength is not 0, and each enabled
 * potential of non-zero k*charge (0: no force at all). */
unsigned isk_forces_laws(const isk_forces *f);
/* A law's name ("gravity", "drag", "power 2", ...), NULL for anything but
 * one ISK_LAW_* bit. */
const char *isk_force_law_name(unsigned law);

/* Stage kernels on n particles (pointers may be offset into a store).
 * Each ADDS into its accumulators. */
void isk_force_gravity(size_t n, const double *m, double g, double *fy);
void isk_force_drag(size_t n, const double *vx, const double *vy, double b, double *fx, double *fy);
void isk_force_accel(size_t n, const double *m, double ax, double ay, double *fx, double *fy);
/* Adds one potential's force into (px, py); handles the sticky switch. */
void isk_force_potential(isk_potential *pot, size_t n, const double *x, const double *y, double *px,
                         double *py, isk_fidelity centre);

/* The whole force pipeline in the documented order: fx, fy receive
 * (gravity + drag) + P_sum; px, py are scratch of n doubles (unused when
 * there are no potentials).  with_drag = 0 leaves the drag out (the exact
 * drag integrator handles it analytically).  The drag stage first flushes
 * velocity components below ISK_FLUSH_TINY to zero (iskra/integrate.h:
 * why), which is why vx, vy are not const. */
void isk_forces_eval(isk_forces *f, size_t n, const double *x, const double *y, double *vx, double *vy,
                     const double *m, double *fx, double *fy, double *px, double *py, int with_drag);

/* The same for a step of h > 0 (what the integrators call): the drag
 * saturates at m/h per particle, so b*h/m never exceeds 1 and an explicit
 * step can stop a particle but never reverse its velocity (without it,
 * b*h/m = 10 multiplies v by -9 every step: the explicit methods' (1 -
 * b h/m)^n overflows; iskra/limits.h).  Where b*h <= m, which is every
 * ordinary scene, the forces are the bits of isk_forces_eval. */
void isk_forces_eval_step(isk_forces *f, size_t n, const double *x, const double *y, double *vx, double *vy,
                          const double *m, double *fx, double *fy, double *px, double *py, int with_drag,
                          double h);

/* ---- potential energy -------------------------------------------------------
 * The potential energy of n particles (the sum, particle by particle in
 * order) under the forces f applies: for each law that acts
 * (isk_forces_laws), the U whose negative gradient is that law's force,
 * F = -grad U, in the order the forces are summed:
 *
 *     gravity        U = m g y                       F = (0, -m g)
 *     acceleration   U = -m (ax x + ay y)            F = m (ax, ay)   (wind, an emitter's weight)
 *     drag           none: F = -b v depends on the velocity, so the energy
 *                    it takes shows as a falling total
 *     a potential    U = kQ d^(2-P) / (2-P), kQ ln d for P = 2
 *                    (d its distance; F = kQ (r_pot - r) / d^P, |F| = k|Q| d^(1-P));
 *                    inside min_dist, where F = kQ (r_pot - r) / min^P:
 *                    U = kQ (d^2 - min^2) / (2 min^P) + U(min), a spring
 *                    joined continuously at min
 *
 * Zeros: gravity's and the acceleration's at the origin; a potential's far
 * away for P > 2 (a particle out of its reach adds nothing), at its centre
 * for P < 2, at distance 1 for P = 2.  Only an energy's changes mean
 * something; the zeros only fix the numbers.
 * Potentials count as the force does: those f picks (all without a pick),
 * enabled, of k*charge != 0; a potential that switched itself off (its
 * max_dist) counts no more.  An x_mult other than 1 makes a potential's
 * force non-conservative (no U has it as gradient): its U is that of
 * x_mult 1.  Exactly on a potential without a min distance U is the law's
 * limit: 0 for P < 2, infinite for P >= 2 (-Inf when it attracts); near
 * it, as large as the law says (the force saturates at ISK_FORCE_LIMIT, U
 * does not).
 *
 *     double u;
 *     if (isk_forces_potential_energy(&f, store.count, store.x, store.y, store.m, &u) == ISK_OK)
 *         printf("potential energy %g\n", u);
 *
 * Errors: ISK_ERR_NULL (f or energy NULL, x, y or m NULL with n > 0,
 * potentials NULL with a count); ISK_ERR_UNSUPPORTED when a law acts that
 * has no row here (none of the laws above): a number that left a force
 * out would look right and be wrong. */
isk_status isk_forces_potential_energy(const isk_forces *f, size_t n, const double *x, const double *y,
                                       const double *m, double *energy);

#ifdef __cplusplus
}
#endif

#endif
