/* SPDX-License-Identifier: MIT */
/* Convergence orders and energy behaviour on the closed-form problems of
 * iskra/problems.h, run through the real pipeline (isk_system_step); the
 * closed forms themselves checked independently; validation. */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "iskra/problems.h"

/* Runs problem pb with `frames` steps of T/frames; returns the errors. */
static isk_problem_error run(const isk_problem *pb, isk_integrator method, int substeps, long frames)
{
    isk_system s;
    cr_assert_eq(isk_system_init(&s, 1, 0), ISK_OK);
    cr_assert_eq(isk_system_set_integrator(&s, method), ISK_OK);
    cr_assert_eq(isk_system_set_substeps(&s, substeps), ISK_OK);
    cr_assert_eq(isk_problem_setup(pb, &s), ISK_OK);
    for (long f = 0; f < frames; f++)
        cr_assert_eq(isk_system_step(&s, pb->T / (double)frames), ISK_OK);
    isk_problem_error e;
    cr_assert_eq(isk_problem_measure(pb, &s, &e), ISK_OK);
    cr_assert_eq(e.nonfinite, 0);
    cr_assert_float_eq(e.time, pb->T, 1e-12 * pb->T);
    isk_system_free(&s);
    return e;
}

static isk_problem small(isk_problem_kind kind)
{
    isk_problem pb = isk_problem_defaults(kind);
    pb.count = 16;
    return pb;
}

/* The errors at `frames` steps and at twice as many (dt halved). */
typedef struct halving {
    isk_integrator method;
    isk_problem_error coarse, fine;
} halving;

static halving halve(const isk_problem *pb, isk_integrator m, long frames)
{
    halving h = {m, run(pb, m, 1, frames), run(pb, m, 1, 2 * frames)};
    return h;
}

/* err(dt) / err(dt/2) must be `want` within 20 %. */
static void assert_ratio(const char *what, isk_integrator m, double coarse, double fine, double want)
{
    double r = coarse / fine;
    cr_assert(fabs(r / want - 1.0) < 0.2, "%s, %s: error %.3e -> %.3e, ratio %.3f, want %g", what,
              isk_integrator_name(m), coarse, fine, r, want);
}

/* h must be a variable (it is named three times). */
#define ASSERT_ORDER(what, h, field, want) assert_ratio(what, (h).method, (h).coarse.field, (h).fine.field, want)

/* Projectile (gravity + drag), position error at T = 2 s.  Both Euler
 * forms are first order.  Velocity Verlet is also only FIRST order here:
 * its second order needs a force that depends on position alone, and its
 * closing kick uses the drag at the half-kicked velocity v + (dt/2) a
 * instead of the new velocity.  RK4 is fourth order (the force is smooth).
 * The ranges are where the ratio has settled (from `iskra bench accuracy`:
 * 40 -> 80 steps is well inside the first-order regime, 20 -> 40 inside
 * RK4's, whose errors there are 4e-6 and 2e-7, far above rounding). */
Test(convergence, projectile_orders)
{
    isk_problem pb = small(ISK_PROBLEM_PROJECTILE);
    const isk_integrator first[3] = {ISK_INTEGRATE_EULER, ISK_INTEGRATE_SEMI_EULER, ISK_INTEGRATE_VERLET};
    for (int i = 0; i < 3; i++) {
        halving h = halve(&pb, first[i], 40);
        ASSERT_ORDER("projectile position", h, position, 2.0);
        ASSERT_ORDER("projectile velocity", h, velocity, 2.0);
    }
    halving h = halve(&pb, ISK_INTEGRATE_RK4, 20);
    ASSERT_ORDER("projectile position", h, position, 16.0);
    cr_assert(h.fine.position > 1e-9, "RK4 error %.3e: the test would be measuring rounding", h.fine.position);
}

/* Harmonic oscillator (P = 0 spring), position error after 10.25 periods.
 * Velocity Verlet is second order on a position-only force; RK4 fourth.
 * Explicit Euler's position error is first order (amplitude growth).
 * Semi-implicit Euler's positions obey Verlet's recurrence
 * x_{n+1} - 2 x_n + x_{n-1} = -(w dt)^2 x_n and differ from Verlet's only
 * in x_1 (by dt^2 a_0 / 2): a first-order amplitude error of size
 * ~ w dt |x_0| / 2 on top of Verlet's second-order phase drift
 * ~ (w dt)^2 w T / 24.  Over 10 periods the drift dominates down to
 * w dt ~ 0.1, so we take steps ten times finer, where order 1 shows. */
Test(convergence, oscillator_orders)
{
    isk_problem pb = small(ISK_PROBLEM_OSCILLATOR);
    halving verlet = halve(&pb, ISK_INTEGRATE_VERLET, 480), rk4 = halve(&pb, ISK_INTEGRATE_RK4, 240);
    halving euler = halve(&pb, ISK_INTEGRATE_EULER, 15360), semi = halve(&pb, ISK_INTEGRATE_SEMI_EULER, 7680);
    ASSERT_ORDER("oscillator position", verlet, position, 4.0);
    ASSERT_ORDER("oscillator position", rk4, position, 16.0);
    ASSERT_ORDER("oscillator position", euler, position, 2.0);
    ASSERT_ORDER("oscillator position", semi, position, 2.0);
    ASSERT_ORDER("oscillator velocity", semi, velocity, 2.0);
    /* Energy: semi-Euler's bounded wobble is O(w dt), Verlet's O((w dt)^2). */
    halving semi_e = halve(&pb, ISK_INTEGRATE_SEMI_EULER, 960), verlet_e = halve(&pb, ISK_INTEGRATE_VERLET, 960);
    ASSERT_ORDER("oscillator energy", semi_e, energy, 2.0);
    ASSERT_ORDER("oscillator energy", verlet_e, energy, 4.0);
}

/* The symplectic and splitting methods: leapfrog (kick-drift-kick with the
 * drag split symmetrically) is second order with drag too, where velocity
 * Verlet is first; Yoshida's composition of it fourth; the Strang splitting
 * with the exact drag flight second.  Projectile (gravity + drag) and
 * oscillator (a position-only force), position and velocity. */
Test(convergence, symplectic_and_splitting_orders)
{
    isk_problem proj = small(ISK_PROBLEM_PROJECTILE), osc = small(ISK_PROBLEM_OSCILLATOR);
    const isk_integrator second[2] = {ISK_INTEGRATE_LEAPFROG, ISK_INTEGRATE_STRANG};
    for (int i = 0; i < 2; i++) {
        halving p = halve(&proj, second[i], 40), o = halve(&osc, second[i], 480);
        ASSERT_ORDER("projectile position", p, position, 4.0);
        ASSERT_ORDER("projectile velocity", p, velocity, 4.0);
        ASSERT_ORDER("oscillator position", o, position, 4.0);
        ASSERT_ORDER("oscillator velocity", o, velocity, 4.0);
        ASSERT_ORDER("oscillator energy", o, energy, 4.0);
    }
    halving p = halve(&proj, ISK_INTEGRATE_YOSHIDA4, 40), o = halve(&osc, ISK_INTEGRATE_YOSHIDA4, 480);
    ASSERT_ORDER("projectile position", p, position, 16.0);
    ASSERT_ORDER("projectile velocity", p, velocity, 16.0);
    ASSERT_ORDER("oscillator position", o, position, 16.0);
    ASSERT_ORDER("oscillator energy", o, energy, 16.0);
    cr_assert(o.fine.position > 1e-9, "Yoshida error %.3e: the test would be measuring rounding", o.fine.position);
}

/* Radial motion through the Coulomb core: the kink in |F| at d = min
 * costs RK4 its order.  Measured with `iskra bench accuracy`: energy drift
 * ratios per halving scatter between 2^1.3 and 2^2.6 (median order 2): a
 * kinked acceleration integrated by Simpson-like stages loses O(dt^2) of
 * velocity at every crossing.  What we can assert: RK4 converges, and
 * clearly slower than 16x per halving. */
Test(convergence, radial_rk4_loses_order_at_the_kink)
{
    isk_problem pb = small(ISK_PROBLEM_RADIAL);
    double a = run(&pb, ISK_INTEGRATE_RK4, 1, 800).energy;
    double b = run(&pb, ISK_INTEGRATE_RK4, 1, 3200).energy; /* two halvings */
    cr_assert(a / b > 4.0 && a / b < 64.0, "two halvings: %.3e -> %.3e (x%.1f)", a, b, a / b);
    /* Particles that never leave the core feel a smooth linear force:
     * there RK4 is fourth order again. */
    pb.start_min = 0.02;
    pb.start_max = 0.09;
    a = run(&pb, ISK_INTEGRATE_RK4, 1, 400).energy;
    b = run(&pb, ISK_INTEGRATE_RK4, 1, 800).energy;
    cr_assert(a / b > 16.0, "inside the core: %.3e -> %.3e", a, b);
}

/* The exact-drag integrator solves gravity + linear drag exactly at any
 * step, up to rounding. */
Test(convergence, exact_drag_is_exact_on_the_projectile)
{
    isk_problem pb = small(ISK_PROBLEM_PROJECTILE);
    const long frames[3] = {1, 5, 100};
    for (int i = 0; i < 3; i++) {
        isk_problem_error e = run(&pb, ISK_INTEGRATE_EXACT_DRAG, 1, frames[i]);
        cr_assert_lt(e.position, 1e-12, "%ld steps: %.3e", frames[i], e.position);
        cr_assert_lt(e.velocity, 1e-12, "%ld steps: %.3e", frames[i], e.velocity);
    }
}

/* N substeps of dt are N steps of dt/N: identical particle states. */
Test(convergence, substeps_equal_smaller_steps)
{
    isk_problem pb = small(ISK_PROBLEM_RADIAL);
    for (int m = 0; m < ISK_INTEGRATOR_COUNT; m++) {
        isk_system a, b;
        isk_system_init(&a, 1, 0);
        isk_system_init(&b, 1, 0);
        a.integrator = b.integrator = (isk_integrator)m;
        a.substeps = 4;
        cr_assert_eq(isk_problem_setup(&pb, &a), ISK_OK);
        cr_assert_eq(isk_problem_setup(&pb, &b), ISK_OK);
        for (int f = 0; f < 50; f++)
            isk_system_step(&a, 0.04);
        for (int f = 0; f < 200; f++)
            isk_system_step(&b, 0.01);
        size_t bytes = pb.count * sizeof(double);
        cr_assert(memcmp(a.particles.x, b.particles.x, bytes) == 0, "%s", isk_integrator_name(m));
        cr_assert(memcmp(a.particles.vy, b.particles.vy, bytes) == 0, "%s", isk_integrator_name(m));
        isk_system_free(&a);
        isk_system_free(&b);
    }
}

/* Same problem, same steps: the same bits, twice. */
Test(convergence, deterministic)
{
    for (int k = 0; k < ISK_PROBLEM_COUNT; k++) {
        isk_problem pb = small((isk_problem_kind)k);
        for (int m = 0; m < ISK_INTEGRATOR_COUNT; m++) {
            isk_problem_error a = run(&pb, (isk_integrator)m, 2, 37);
            isk_problem_error b = run(&pb, (isk_integrator)m, 2, 37);
            cr_assert(memcmp(&a, &b, sizeof a) == 0, "%s %s", isk_problem_name(pb.kind),
                      isk_integrator_name((isk_integrator)m));
        }
    }
}

/* ---- the closed forms, checked without the closed forms ------------------- */

/* RK4 at a tiny step agrees with the closed forms (an independent solver
 * reaching the same answer). */
Test(convergence, rk4_at_a_tiny_step_agrees_with_the_closed_forms)
{
    isk_problem pb = small(ISK_PROBLEM_PROJECTILE);
    isk_problem_error e = run(&pb, ISK_INTEGRATE_RK4, 1, 2000);
    cr_assert_lt(e.position, 1e-10);
    cr_assert_lt(e.velocity, 1e-10);
    pb = small(ISK_PROBLEM_OSCILLATOR);
    pb.T = 1.25;
    e = run(&pb, ISK_INTEGRATE_RK4, 1, 5000);
    cr_assert_lt(e.position, 1e-10, "%.3e", e.position);
    cr_assert_lt(e.velocity, 1e-10, "%.3e", e.velocity);
    cr_assert_lt(e.energy, 1e-10, "%.3e", e.energy);
    cr_assert_lt(e.phase, 1e-10, "%.3e", e.phase);
}

/* The exact velocity is the time derivative of the exact position
 * (central differences), for every particle and several times. */
Test(convergence, exact_velocity_is_the_derivative_of_position)
{
    const isk_problem_kind kinds[2] = {ISK_PROBLEM_PROJECTILE, ISK_PROBLEM_OSCILLATOR};
    for (int k = 0; k < 2; k++) {
        isk_problem pb = small(kinds[k]);
        pb.drag = 0.8;
        const double ts[4] = {0.01, 0.3, 1.1, 1.9};
        const double eps = 1e-5;
        for (size_t i = 0; i < pb.count; i++)
            for (int j = 0; j < 4; j++) {
                isk_problem_state a, b, c;
                cr_assert_eq(isk_problem_exact(&pb, i, ts[j] - eps, &a), ISK_OK);
                cr_assert_eq(isk_problem_exact(&pb, i, ts[j] + eps, &b), ISK_OK);
                cr_assert_eq(isk_problem_exact(&pb, i, ts[j], &c), ISK_OK);
                double dx = (b.r.x - a.r.x) / (2 * eps), dy = (b.r.y - a.r.y) / (2 * eps);
                double scale = 1.0 + hypot(c.v.x, c.v.y);
                cr_assert(fabs(dx - c.v.x) < 1e-7 * scale && fabs(dy - c.v.y) < 1e-7 * scale,
                          "%s particle %zu t %g: (%.12g, %.12g) vs (%.12g, %.12g)", isk_problem_name(pb.kind), i,
                          ts[j], dx, dy, c.v.x, c.v.y);
                /* and the acceleration of the velocity is the force law's */
                double ax = (b.v.x - a.v.x) / (2 * eps), ay = (b.v.y - a.v.y) / (2 * eps);
                double wx, wy;
                if (pb.kind == ISK_PROBLEM_PROJECTILE) {
                    wx = -pb.drag / pb.mass * c.v.x;
                    wy = -pb.gravity - pb.drag / pb.mass * c.v.y;
                } else {
                    wx = -pb.kq / pb.mass * c.r.x;
                    wy = -pb.kq / pb.mass * c.r.y;
                }
                scale = 1.0 + hypot(wx, wy);
                cr_assert(fabs(ax - wx) < 1e-6 * scale && fabs(ay - wy) < 1e-6 * scale,
                          "%s particle %zu t %g: a (%.12g, %.12g) vs (%.12g, %.12g)", isk_problem_name(pb.kind),
                          i, ts[j], ax, ay, wx, wy);
            }
        /* t = 0 is the start */
        isk_problem_state s0, e0;
        isk_problem_initial(&pb, 3, &s0);
        isk_problem_exact(&pb, 3, 0.0, &e0);
        cr_assert(memcmp(&s0, &e0, sizeof s0) == 0);
    }
}

/* No drag: the projectile's closed form is the parabola (the phi series
 * limit, not 0/0). */
Test(convergence, projectile_without_drag_is_the_parabola)
{
    isk_problem pb = small(ISK_PROBLEM_PROJECTILE);
    pb.drag = 0.0;
    isk_problem_state s0, e;
    isk_problem_initial(&pb, 5, &s0);
    cr_assert_eq(isk_problem_exact(&pb, 5, 1.5, &e), ISK_OK);
    cr_assert_float_eq(e.r.x, s0.v.x * 1.5, 1e-13);
    cr_assert_float_eq(e.r.y, s0.v.y * 1.5 - 0.5 * pb.gravity * 2.25, 1e-13);
    cr_assert_float_eq(e.v.y, s0.v.y - pb.gravity * 1.5, 1e-13);
}

static double energy_at(const isk_problem *pb, double d)
{
    isk_problem_state st = {{d * 0.6, d * 0.8}, {0, 0}};
    double E;
    cr_assert_eq(isk_problem_energy(pb, &st, &E), ISK_OK);
    return E;
}

/* The radial potential energy: continuous at d = min, and its slope is the
 * magnitude of the library's own force (isk_potential_force) everywhere,
 * inside, at and outside the core. */
Test(convergence, radial_energy_matches_the_force)
{
    isk_problem pb = isk_problem_defaults(ISK_PROBLEM_RADIAL);
    const double mn = pb.min_dist;
    double below = energy_at(&pb, mn * (1 - 1e-12)), at = energy_at(&pb, mn), above = energy_at(&pb, mn * (1 + 1e-12));
    cr_assert_float_eq(at, pb.kq / 2, 1e-14);
    cr_assert(fabs(above - below) < 1e-11 * pb.kq, "jump %.3e", above - below);
    isk_potential pot;
    isk_potential_init(&pot, pb.kq, isk_vec2_make(0, 0), 1.0);
    pot.min_dist = mn;
    const double ds[6] = {0.013, 0.05, 0.0999, 0.1001, 0.4, 1.7};
    for (int i = 0; i < 6; i++) {
        double d = ds[i], h = 1e-6;
        double slope = (energy_at(&pb, d + h) - energy_at(&pb, d - h)) / (2 * h);
        isk_vec2 F = isk_potential_force(&pot, d * 0.6, d * 0.8, ISK_FIDELITY_SOUND);
        double f = hypot(F.x, F.y);
        cr_assert(fabs(slope - f) < 1e-6 * f, "d %g: dU/dd %.10g, |F| %.10g", d, slope, f);
        /* attracting: F points to the centre */
        cr_assert(F.x < 0 && F.y < 0);
    }
    /* Same check for the oscillator's U = kQ d^2/2 against the P = 0 force. */
    isk_problem osc = isk_problem_defaults(ISK_PROBLEM_OSCILLATOR);
    isk_potential spring;
    isk_potential_init(&spring, osc.kq, isk_vec2_make(0, 0), 1.0);
    spring.P = 0;
    for (int i = 0; i < 6; i++) {
        double d = ds[i], h = 1e-6;
        double slope = (energy_at(&osc, d + h) - energy_at(&osc, d - h)) / (2 * h);
        isk_vec2 F = isk_potential_force(&spring, d * 0.6, d * 0.8, ISK_FIDELITY_SOUND);
        cr_assert(fabs(slope - hypot(F.x, F.y)) < 1e-6 * slope, "d %g", d);
    }
}

/* The starts are what the header says: spreads inside [start_min,
 * start_max], the radial particles at rest, the oscillator on its ellipse. */
Test(convergence, initial_states)
{
    for (int k = 0; k < ISK_PROBLEM_COUNT; k++) {
        isk_problem pb = isk_problem_defaults((isk_problem_kind)k);
        double lo = INFINITY, hi = 0;
        for (size_t i = 0; i < pb.count; i++) {
            isk_problem_state s;
            cr_assert_eq(isk_problem_initial(&pb, i, &s), ISK_OK);
            double E = 0;
            if (k == ISK_PROBLEM_KEPLER)
                cr_assert_eq(isk_problem_energy(&pb, &s, &E), ISK_OK);
            double size = k == ISK_PROBLEM_PROJECTILE ? hypot(s.v.x, s.v.y)
                          : k == ISK_PROBLEM_RADIAL   ? hypot(s.r.x, s.r.y)
                          : k == ISK_PROBLEM_BOUNCE   ? s.r.y
                          : k == ISK_PROBLEM_KEPLER   ? -pb.kq / (2 * E) /* the semi-major axis */
                                                      : hypot(s.r.x, 2 * s.r.y);
            lo = fmin(lo, size);
            hi = fmax(hi, size);
            if (k == ISK_PROBLEM_RADIAL)
                cr_assert(s.v.x == 0 && s.v.y == 0);
        }
        cr_assert(lo >= pb.start_min * (1 - 1e-12) && hi <= pb.start_max * (1 + 1e-12));
        cr_assert(hi - lo > 0.9 * (pb.start_max - pb.start_min), "%s spread %g..%g", isk_problem_name(pb.kind), lo,
                  hi);
    }
}

/* ---- energy over a million steps -------------------------------------------- */

/* Max relative energy error of the oscillator over n = 10^6 steps of
 * h = 1e-3 (theta = w h = 2 pi 1e-3), sampled every 100 steps; *last
 * receives E(end)/E0 of particle 0. */
static double energy_run(isk_integrator m, double *last)
{
    isk_problem pb = isk_problem_defaults(ISK_PROBLEM_OSCILLATOR);
    pb.count = 4;
    isk_system s;
    isk_system_init(&s, 1, 0);
    s.integrator = m;
    s.substeps = 100; /* 10^4 frames of 100 steps: the per-frame overhead stays small */
    cr_assert_eq(isk_problem_setup(&pb, &s), ISK_OK);
    double E0[4], worst = 0;
    for (size_t i = 0; i < 4; i++) {
        isk_problem_state st;
        isk_problem_initial(&pb, i, &st);
        isk_problem_energy(&pb, &st, &E0[i]);
    }
    for (int f = 0; f < 10000; f++) {
        isk_system_step(&s, 0.1);
        for (size_t i = 0; i < 4; i++) {
            isk_problem_state st = {{s.particles.x[i], s.particles.y[i]}, {s.particles.vx[i], s.particles.vy[i]}};
            double E;
            isk_problem_energy(&pb, &st, &E);
            worst = fmax(worst, fabs(E - E0[i]) / E0[i]);
            if (i == 0)
                *last = E / E0[0];
        }
    }
    isk_system_free(&s);
    return worst;
}

/* The issue: "semi-implicit Euler and Verlet keep the harmonic oscillator's
 * energy bounded over 10^6 steps; explicit Euler's grows".  With
 * theta = w h and E = v^2/2 + w^2 x^2/2 (m = 1):
 *  - semi-implicit Euler (v first) conserves exactly
 *        H~ = E - (h w^2/2) x v,   and |x v| <= E/w,
 *    so E stays within H~/(1 +- theta/2): |E/E0 - 1| <= theta/(1 - theta/2);
 *  - velocity Verlet conserves exactly H~ = E - (theta^2/4) w^2 x^2/2, so
 *    0 <= E - H~ <= (theta^2/4) E: |E/E0 - 1| <= (theta^2/4)/(1 - theta^2/4);
 *  - explicit Euler multiplies E by exactly (1 + theta^2) per step (its
 *    amplitude by sqrt(1 + theta^2)): after 10^6 steps E/E0 = (1+theta^2)^1e6
 *    = e^39.5 = 1.4e17.
 * The lower bounds show each wobble is really there, of that order: for
 * these four starts (E0 = 5/8 A^2 w^2, x v and |r|^2 swinging through
 * their full ranges) the peaks are about 0.55 theta and 0.3 theta^2/4. */
Test(convergence, energy_over_a_million_steps, .timeout = 30)
{
    const double theta = 6.283185307179586 * 1e-3;
    double last;
    double se = energy_run(ISK_INTEGRATE_SEMI_EULER, &last);
    double bound = theta / (1 - theta / 2);
    cr_assert(se <= bound && se > bound / 4, "semi-euler max %.4e, bound %.4e", se, bound);
    double vv = energy_run(ISK_INTEGRATE_VERLET, &last);
    double q = theta * theta / 4, vbound = q / (1 - q);
    cr_assert(vv <= vbound * (1 + 1e-6) && vv > vbound / 5, "verlet max %.4e, bound %.4e", vv, vbound);
    energy_run(ISK_INTEGRATE_EULER, &last);
    double growth = pow(1 + theta * theta, 1e6);
    cr_assert(growth > 1e17 && growth < 2e17);
    cr_assert(fabs(last / growth - 1) < 1e-8, "euler E/E0 %.10e, (1+theta^2)^n %.10e", last, growth);
}

/* ---- validation --------------------------------------------------------------- */

Test(convergence, problem_validation)
{
    cr_assert_eq(isk_problem_validate(NULL), ISK_ERR_NULL);
    for (int k = 0; k < ISK_PROBLEM_COUNT; k++) {
        isk_problem ok = isk_problem_defaults((isk_problem_kind)k), p;
        cr_assert_eq(isk_problem_validate(&ok), ISK_OK, "%s", isk_problem_name(ok.kind));
        p = ok; p.count = 0;              cr_assert_eq(isk_problem_validate(&p), ISK_ERR_SIZE);
        p = ok; p.count = ISK_PARTICLES_MAX + 1; cr_assert_eq(isk_problem_validate(&p), ISK_ERR_SIZE);
        p = ok; p.T = 0;                  cr_assert_eq(isk_problem_validate(&p), ISK_ERR_RANGE);
        p = ok; p.T = -1;                 cr_assert_eq(isk_problem_validate(&p), ISK_ERR_RANGE);
        p = ok; p.T = NAN;                cr_assert_eq(isk_problem_validate(&p), ISK_ERR_NAN);
        p = ok; p.T = INFINITY;           cr_assert_eq(isk_problem_validate(&p), ISK_ERR_NAN);
        p = ok; p.mass = 0;               cr_assert_eq(isk_problem_validate(&p), ISK_ERR_RANGE);
        p = ok; p.mass = NAN;             cr_assert_eq(isk_problem_validate(&p), ISK_ERR_NAN);
        p = ok; p.start_min = 0;          cr_assert_eq(isk_problem_validate(&p), ISK_ERR_RANGE);
        p = ok; p.start_max = p.start_min / 2; cr_assert_eq(isk_problem_validate(&p), ISK_ERR_RANGE);
        p = ok; p.start_max = NAN;        cr_assert_eq(isk_problem_validate(&p), ISK_ERR_NAN);
        if (k == ISK_PROBLEM_BOUNCE) {
            p = ok; p.gravity = 0;        cr_assert_eq(isk_problem_validate(&p), ISK_ERR_RANGE);
            p = ok; p.restitution = 1.5;  cr_assert_eq(isk_problem_validate(&p), ISK_ERR_RANGE);
            p = ok; p.restitution = NAN;  cr_assert_eq(isk_problem_validate(&p), ISK_ERR_NAN);
            p = ok; p.kq = NAN;           cr_assert_eq(isk_problem_validate(&p), ISK_OK); /* unused */
        } else if (k == ISK_PROBLEM_PROJECTILE) {
            p = ok; p.drag = -0.1;        cr_assert_eq(isk_problem_validate(&p), ISK_ERR_RANGE);
            p = ok; p.drag = NAN;         cr_assert_eq(isk_problem_validate(&p), ISK_ERR_NAN);
            p = ok; p.gravity = INFINITY; cr_assert_eq(isk_problem_validate(&p), ISK_ERR_NAN);
            p = ok; p.gravity = -3;       cr_assert_eq(isk_problem_validate(&p), ISK_OK);
            p = ok; p.kq = NAN;           cr_assert_eq(isk_problem_validate(&p), ISK_OK); /* unused */
        } else {
            p = ok; p.kq = 0;             cr_assert_eq(isk_problem_validate(&p), ISK_ERR_RANGE);
            p = ok; p.kq = -4;            cr_assert_eq(isk_problem_validate(&p), ISK_ERR_RANGE);
            p = ok; p.kq = NAN;           cr_assert_eq(isk_problem_validate(&p), ISK_ERR_NAN);
            p = ok; p.min_dist = 0;
            cr_assert_eq(isk_problem_validate(&p), k == ISK_PROBLEM_RADIAL ? ISK_ERR_RANGE : ISK_OK);
            p = ok; p.eccentricity = 1;
            cr_assert_eq(isk_problem_validate(&p), k == ISK_PROBLEM_KEPLER ? ISK_ERR_RANGE : ISK_OK);
        }
    }
    isk_problem bad = isk_problem_defaults(ISK_PROBLEM_COUNT);
    cr_assert_eq(bad.count, 0);
    cr_assert_eq(isk_problem_validate(&bad), ISK_ERR_RANGE);
    cr_assert_str_eq(isk_problem_name(ISK_PROBLEM_COUNT), "?");
    cr_assert_str_eq(isk_problem_name(ISK_PROBLEM_RADIAL), "radial");
}

Test(convergence, problem_functions_validate)
{
    isk_problem pb = small(ISK_PROBLEM_PROJECTILE), nan = pb;
    nan.mass = NAN;
    isk_problem_state st;
    double E;
    cr_assert_eq(isk_problem_initial(&pb, 0, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_problem_initial(&nan, 0, &st), ISK_ERR_NAN);
    cr_assert_eq(isk_problem_initial(&pb, pb.count, &st), ISK_ERR_RANGE);
    cr_assert_eq(isk_problem_exact(&pb, 0, -1, &st), ISK_ERR_RANGE);
    cr_assert_eq(isk_problem_exact(&pb, 0, NAN, &st), ISK_ERR_NAN);
    cr_assert_eq(isk_problem_energy(&pb, &st, &E), ISK_ERR_UNSUPPORTED);
    isk_problem rad = small(ISK_PROBLEM_RADIAL);
    cr_assert_eq(isk_problem_exact(&rad, 0, 1, &st), ISK_ERR_UNSUPPORTED);
    cr_assert_eq(isk_problem_energy(&rad, NULL, &E), ISK_ERR_NULL);
    cr_assert_eq(isk_problem_energy(&rad, &st, NULL), ISK_ERR_NULL);

    isk_system s;
    isk_system_init(&s, 1, 0);
    isk_problem_error e;
    cr_assert_eq(isk_problem_setup(NULL, &s), ISK_ERR_NULL);
    cr_assert_eq(isk_problem_setup(&pb, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_problem_measure(&pb, NULL, &e), ISK_ERR_NULL);
    /* a failed setup leaves the system as it was */
    isk_particles_add(&s.particles, 1, 2, 3, 4, 5, NULL);
    s.forces.gravity = 1.5;
    cr_assert_eq(isk_problem_setup(&nan, &s), ISK_ERR_NAN);
    cr_assert_eq(s.particles.count, 1);
    cr_assert_eq(s.forces.gravity, 1.5);
    cr_assert_eq(isk_problem_measure(&pb, &s, &e), ISK_ERR_SIZE); /* 1 particle, not 16 */
    /* setup replaces everything that would change the motion */
    s.bounds.sides = ISK_SIDE_BOTTOM;
    s.ageing = 1;
    s.time = 7;
    cr_assert_eq(isk_problem_setup(&rad, &s), ISK_OK);
    cr_assert_eq(isk_problem_setup(&rad, &s), ISK_OK); /* twice: still one potential */
    cr_assert_eq(s.forces.npot, 1);
    cr_assert_eq(s.forces.gravity, 0);
    cr_assert_eq(s.forces.pot[0].P, 2.0);
    cr_assert_eq(s.forces.pot[0].min_dist, rad.min_dist);
    cr_assert_eq(s.particles.count, rad.count);
    cr_assert_eq(s.bounds.sides, 0);
    cr_assert_eq(s.ageing, 0);
    cr_assert_eq(s.time, 0);
    cr_assert_eq(isk_problem_measure(&rad, &s, &e), ISK_OK);
    cr_assert_eq(e.energy, 0.0); /* nothing has moved yet */
    cr_assert(isnan(e.position) && isnan(e.phase));
    s.time = NAN;
    cr_assert_eq(isk_problem_measure(&rad, &s, &e), ISK_ERR_NAN);
    s.time = 0;
    /* a diverged particle: infinite errors, counted */
    s.particles.vx[3] = INFINITY;
    cr_assert_eq(isk_problem_measure(&rad, &s, &e), ISK_OK);
    cr_assert_eq(e.nonfinite, 1);
    cr_assert(isinf(e.energy));
    isk_system_free(&s);
}

/* ---- the bouncing ball and the Kepler ellipse --------------------------------- */

/* The closed forms: the ball's every apex is h0 (c = 1) or h0 c^(2k), its
 * energy m g h0 c^(2k); the ellipse conserves E = -kQ/(2a) and L and its
 * velocity is the derivative of its position. */
Test(convergence, bounce_and_kepler_closed_forms)
{
    isk_problem b = small(ISK_PROBLEM_BOUNCE);
    b.restitution = 0.8;
    for (size_t i = 0; i < b.count; i += 5) {
        isk_problem_state s0, e;
        cr_assert_eq(isk_problem_initial(&b, i, &s0), ISK_OK);
        const double h0 = s0.r.y, tf = sqrt(2 * h0 / b.gravity), V0 = b.gravity * tf;
        /* at the top of the k-th hop: height h0 c^(2k), at rest */
        double t = tf;
        for (int k = 1; k <= 4; k++) {
            double V = V0 * pow(0.8, k);
            cr_assert_eq(isk_problem_exact(&b, i, t + V / b.gravity, &e), ISK_OK);
            cr_assert(fabs(e.r.y - h0 * pow(0.8, 2 * k)) < 1e-12 * h0 && fabs(e.v.y) < 1e-12 * V0, "k %d: %.15g", k,
                      e.r.y);
            t += 2 * V / b.gravity;
        }
        cr_assert_eq(isk_problem_exact(&b, i, 1e3, &e), ISK_OK); /* long after the hops ended */
        cr_assert(e.r.y == 0 && e.v.y == 0);
    }
    isk_problem k = small(ISK_PROBLEM_KEPLER);
    for (size_t i = 0; i < k.count; i++) {
        isk_problem_state s0, a, c;
        double E0, E;
        cr_assert_eq(isk_problem_initial(&k, i, &s0), ISK_OK);
        cr_assert_eq(isk_problem_energy(&k, &s0, &E0), ISK_OK);
        const double L0 = s0.r.x * s0.v.y - s0.r.y * s0.v.x;
        const double ts[3] = {0.1, 3.7, 10.25};
        for (int j = 0; j < 3; j++) {
            double h = 1e-6;
            cr_assert_eq(isk_problem_exact(&k, i, ts[j], &a), ISK_OK);
            cr_assert_eq(isk_problem_exact(&k, i, ts[j] + h, &c), ISK_OK);
            cr_assert_eq(isk_problem_energy(&k, &a, &E), ISK_OK);
            cr_assert(fabs(E - E0) < 1e-12 * fabs(E0), "E %.15g vs %.15g", E, E0);
            cr_assert(fabs((a.r.x * a.v.y - a.r.y * a.v.x) - L0) < 1e-12 * fabs(L0));
            /* dr/dt = v (a central difference would be better; this is enough at 1e-6) */
            cr_assert(fabs((c.r.x - a.r.x) / h - a.v.x) < 1e-4 * (1 + fabs(a.v.x)), "particle %zu t %g", i, ts[j]);
        }
    }
}

/* Every integrator bounces the ball at the time of impact: the exact-flight
 * ones end on the closed form, and the energy, tracked over the whole run,
 * never grows (before, Verlet's climbed by 125 % in 20 bounces). */
Test(convergence, the_bouncing_ball_keeps_its_energy_with_every_integrator)
{
    isk_problem b = small(ISK_PROBLEM_BOUNCE);
    /* 600 steps, and 20: a step of 0.5 s is longer than a 1 m drop (a bounce
     * in the step, not resting contact) */
    const int frames[2] = {600, 20};
    for (int m = 0; m < ISK_INTEGRATOR_COUNT; m++)
        for (int j = 0; j < 2; j++) {
            isk_system s;
            cr_assert_eq(isk_system_init(&s, 1, 0), ISK_OK);
            cr_assert_eq(isk_system_set_integrator(&s, (isk_integrator)m), ISK_OK);
            cr_assert_eq(isk_problem_setup(&b, &s), ISK_OK);
            isk_problem_error acc = {0};
            for (int f = 0; f < frames[j]; f++) {
                cr_assert_eq(isk_system_step(&s, b.T / frames[j]), ISK_OK);
                cr_assert_eq(isk_problem_track(&b, &s, &acc), ISK_OK);
            }
            isk_problem_error e;
            cr_assert_eq(isk_problem_measure(&b, &s, &e), ISK_OK);
            const double h = b.T / frames[j];
            /* the Euler forms store a velocity half a step off the parabola
             * their positions follow: their energy reads off by ~ g h V / (g h0) */
            const int euler = m == ISK_INTEGRATE_SEMI_EULER || m == ISK_INTEGRATE_EULER;
            double tol = euler ? 2 * 9.81 * h * sqrt(2 * 9.81 * 4) / (9.81 * 1) : 1e-12;
            cr_assert(acc.energy < tol, "%s h=%g: energy error up to %.3e over the run",
                      isk_integrator_name((isk_integrator)m), h, acc.energy);
            if (!euler)
                cr_assert(e.position < 1e-9, "%s h=%g: position %.3e", isk_integrator_name((isk_integrator)m), h,
                          e.position);
            isk_system_free(&s);
        }
}

/* The symplectic methods keep the Kepler angular momentum to rounding (a
 * central force: every kick is along r); RK4 does not. */
Test(convergence, kepler_angular_momentum)
{
    isk_problem k = small(ISK_PROBLEM_KEPLER);
    const isk_integrator keep[5] = {ISK_INTEGRATE_SEMI_EULER, ISK_INTEGRATE_VERLET, ISK_INTEGRATE_LEAPFROG,
                                    ISK_INTEGRATE_YOSHIDA4, ISK_INTEGRATE_STRANG};
    for (int j = 0; j < 5; j++) {
        isk_problem_error e = run(&k, keep[j], 1, 2000);
        cr_assert(e.angular_momentum < 1e-12, "%s: %.3e", isk_integrator_name(keep[j]), e.angular_momentum);
    }
    isk_problem_error r = run(&k, ISK_INTEGRATE_RK4, 1, 2000);
    cr_assert(r.angular_momentum > 1e-9);
}
