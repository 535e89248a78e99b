/* SPDX-License-Identifier: MIT */
/* Integrators with real numbers: projectile errors, convergence order,
 * exact drag against the closed form, stability, long runs. */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "iskra/integrate.h"
#include "iskra/teach.h"

/* One particle through isk_integrate_range with the given forces. */
typedef struct one {
    isk_particles p;
    isk_scratch s;
} one;

static void one_init(one *o, double x, double y, double vx, double vy, double m)
{
    isk_particles_init(&o->p, 1, 0);
    isk_particles_add(&o->p, x, y, vx, vy, m, NULL);
}

static void run(one *o, isk_integrator method, isk_forces *f, double dt, int steps)
{
    for (int i = 0; i < steps; i++)
        cr_assert_eq(isk_integrate_range(method, f, &o->s, &o->p, 0, o->p.count, dt), ISK_OK);
}

/* Gravity only, a_y = -g.  After T = n*dt:
 *   explicit Euler   y - exact = -a_y*T*dt/2 = +g*T*dt/2  (lags behind)
 *   semi-implicit    y - exact = +a_y*T*dt/2 = -g*T*dt/2  (runs ahead)
 *   Verlet, RK4      exact up to rounding.
 * (The issue writes these as -+g*T*dt/2 with g the signed acceleration.) */
Test(sim_integrate, gravity_only_position_errors)
{
    const double g = 9.81, dt = 0.01, m = 1.5, y0 = 100, vy0 = 3;
    const int n = 100;
    const double T = n * dt, exact = y0 + vy0 * T - 0.5 * g * T * T;
    isk_forces f = {.gravity = g};
    double want[4] = {+g * T * dt / 2, -g * T * dt / 2, 0, 0};
    isk_integrator which[4] = {ISK_INTEGRATE_EULER, ISK_INTEGRATE_SEMI_EULER, ISK_INTEGRATE_VERLET,
                               ISK_INTEGRATE_RK4};
    for (int k = 0; k < 4; k++) {
        one o;
        one_init(&o, 0, y0, 1, vy0, m);
        run(&o, which[k], &f, dt, n);
        cr_assert_float_eq(o.p.y[0] - exact, want[k], 1e-12, "%s: err %.17g", isk_integrator_name(which[k]),
                           o.p.y[0] - exact);
        cr_assert_float_eq(o.p.vy[0], vy0 - g * T, 1e-12);
        cr_assert_float_eq(o.p.x[0], T, 1e-12);
        isk_particles_free(&o.p);
    }
    /* Exact-drag with b = 0 is the exact constant-acceleration update. */
    one o;
    one_init(&o, 0, y0, 1, vy0, m);
    run(&o, ISK_INTEGRATE_EXACT_DRAG, &f, dt, n);
    cr_assert_float_eq(o.p.y[0], exact, 1e-12);
    isk_particles_free(&o.p);
}

/* A P = 0 potential is a linear spring F = kQ*(c - r) (|F| = kQ d): a
 * harmonic oscillator, here with omega = 2.  Error at T = 1 with dt and
 * dt/2: the ratio shows the order (2, 2, 4, 16). */
static double osc_error(isk_integrator method, double dt)
{
    isk_potential pot;
    isk_potential_init(&pot, 4.0, isk_vec2_make(0, 0), 1.0);
    isk_potential_set_law(&pot, ISK_COULOMB_LAW_CODE, 0);
    isk_forces f = {.pot = &pot, .npot = 1};
    one o;
    one_init(&o, 1, 0, 0, 0, 1);
    int n = (int)lround(1.0 / dt);
    run(&o, method, &f, dt, n);
    double err = fabs(o.p.x[0] - cos(2.0));
    isk_particles_free(&o.p);
    return err;
}

Test(sim_integrate, convergence_orders_on_a_spring)
{
    isk_integrator which[4] = {ISK_INTEGRATE_EULER, ISK_INTEGRATE_SEMI_EULER, ISK_INTEGRATE_VERLET,
                               ISK_INTEGRATE_RK4};
    double ratio_want[4] = {2, 2, 4, 16};
    for (int k = 0; k < 4; k++) {
        double dt = k == 3 ? 0.02 : 0.001;
        double r = osc_error(which[k], dt) / osc_error(which[k], dt / 2);
        cr_assert(fabs(r / ratio_want[k] - 1) < 0.2, "%s ratio %g", isk_integrator_name(which[k]), r);
    }
}

/* Energy of the spring after 10^4 steps: explicit Euler grows, the
 * symplectic methods stay bounded. */
Test(sim_integrate, energy_behaviour)
{
    isk_integrator which[3] = {ISK_INTEGRATE_EULER, ISK_INTEGRATE_SEMI_EULER, ISK_INTEGRATE_VERLET};
    for (int k = 0; k < 3; k++) {
        isk_potential pot;
        isk_potential_init(&pot, 1.0, isk_vec2_make(0, 0), 1.0);
        pot.P = 0;
        isk_forces f = {.pot = &pot, .npot = 1};
        one o;
        one_init(&o, 1, 0, 0, 0, 1);
        run(&o, which[k], &f, 0.05, 10000);
        double E = 0.5 * (o.p.vx[0] * o.p.vx[0] + o.p.x[0] * o.p.x[0]);
        if (k == 0)
            cr_assert_gt(E, 1e5);
        else
            cr_assert(fabs(E - 0.5) < 0.02, "%s E %g", isk_integrator_name(which[k]), E);
        isk_particles_free(&o.p);
    }
}

/* Closed form of m dv/dt = -b v + F (F constant):
 *   v(t) = vt + (v0 - vt) e^{-kt},  x(t) = x0 + vt t + (v0 - vt)(1 - e^{-kt})/k,
 *   k = b/m, vt = F/b. */
Test(sim_integrate, exact_drag_matches_closed_form)
{
    const double b = 0.3, m = 2.0, g = 9.81, dt = 0.05;
    const int n = 400;
    isk_forces f = {.gravity = g, .drag = b};
    one o;
    one_init(&o, 1, 2, 3, -1, m);
    run(&o, ISK_INTEGRATE_EXACT_DRAG, &f, dt, n);
    double k = b / m, T = n * dt, e = exp(-k * T);
    double vtx = 0, vty = -m * g / b;
    double vx = vtx + (3 - vtx) * e, vy = vty + (-1 - vty) * e;
    double x = 1 + vtx * T + (3 - vtx) * (1 - e) / k;
    double y = 2 + vty * T + (-1 - vty) * (1 - e) / k;
    cr_assert(fabs(o.p.vx[0] - vx) <= 1e-12 * fabs(vx), "vx %.17g %.17g", o.p.vx[0], vx);
    cr_assert(fabs(o.p.vy[0] - vy) <= 1e-12 * fabs(vy));
    cr_assert(fabs(o.p.x[0] - x) <= 1e-12 * fabs(x));
    cr_assert(fabs(o.p.y[0] - y) <= 1e-12 * fabs(y), "y %.17g %.17g", o.p.y[0], y);
    isk_particles_free(&o.p);
}

/* Small k*dt goes through the series branch: compare with the closed form too. */
Test(sim_integrate, exact_drag_small_h_series)
{
    const double b = 1e-4, m = 3.0, dt = 0.01;
    isk_forces f = {.gravity = 1.0, .drag = b};
    one o;
    one_init(&o, 0, 0, 5, 0, m);
    run(&o, ISK_INTEGRATE_EXACT_DRAG, &f, dt, 1000);
    double k = b / m, T = 10, e = exp(-k * T), vty = -m / b;
    double y = vty * T + (0 - vty) * (1 - e) / k; /* = -T^2/2 (1 - kT/3 ...) */
    double x = 5 * (1 - e) / k;
    cr_assert(fabs(o.p.x[0] - x) <= 1e-12 * fabs(x));
    cr_assert(fabs(o.p.y[0] - y) <= 1e-9 * fabs(y), "y %.17g %.17g", o.p.y[0], y);
    isk_particles_free(&o.p);
}

/* Stiff drag: b*dt/m = 0.5, 1.5, 2.5, 1e6.  The exact update decays
 * monotonically without sign change; explicit Euler, which oscillated for
 * > 1 and blew up for > 2, now stops the particle within one step there:
 * the drag saturates at m/dt (iskra/limits.h). */
Test(sim_integrate, stiff_drag_stability)
{
    double h[4] = {0.5, 1.5, 2.5, 1e6};
    for (int k = 0; k < 4; k++) {
        const double m = 2.0, dt = 0.1, b = h[k] * m / dt;
        isk_forces f = {.drag = b};
        one ex, eu;
        one_init(&ex, 0, 0, 10, -10, m);
        one_init(&eu, 0, 0, 10, -10, m);
        double prev = 10, prevx = 0;
        for (int i = 0; i < 100; i++) {
            run(&ex, ISK_INTEGRATE_EXACT_DRAG, &f, dt, 1);
            run(&eu, ISK_INTEGRATE_EULER, &f, dt, 1);
            cr_assert(ex.p.vx[0] >= 0 && ex.p.vx[0] <= prev, "h=%g step %d", h[k], i);
            cr_assert(ex.p.x[0] >= prevx && ex.p.x[0] <= 10 * m / b * 1.0000001);
            prev = ex.p.vx[0];
            prevx = ex.p.x[0];
        }
        cr_assert(isfinite(ex.p.x[0]) && isfinite(ex.p.y[0]));
        if (h[k] >= 1.0)
            cr_assert(eu.p.vx[0] == 0 && isfinite(eu.p.x[0]), "h=%g: %g", h[k], eu.p.vx[0]); /* 1 - min(h, 1) */
        if (h[k] == 0.5)
            cr_assert_lt(fabs(eu.p.vx[0]), 1e-20);
        isk_particles_free(&ex.p);
        isk_particles_free(&eu.p);
    }
}

/* Stiff drag plus gravity: straight to terminal velocity, no overshoot. */
Test(sim_integrate, stiff_drag_reaches_terminal_velocity)
{
    const double m = 1, b = 1e6, g = 9.81;
    isk_forces f = {.gravity = g, .drag = b};
    one o;
    one_init(&o, 0, 0, 0, 0, m);
    run(&o, ISK_INTEGRATE_EXACT_DRAG, &f, 0.1, 10);
    cr_assert_float_eq(o.p.vy[0], -m * g / b, 1e-18);
    isk_particles_free(&o.p);
}

/* The store kernel and the teaching API are the same code: bit-identical. */
Test(sim_integrate, store_semi_euler_equals_teaching_move)
{
    isk_material_point mp = {2.37, {-4, -4}, {1, -2}};
    one o;
    one_init(&o, -4, -4, 1, -2, 2.37);
    isk_forces f = {.gravity = 0.25, .drag = 0.1};
    for (int i = 0; i < 1000; i++) {
        isk_vec2 F = isk_vec2_add(isk_gravity_force(&mp, 0.25), isk_drag_force(&mp, 0.1));
        isk_mp_move(&mp, 0.25, F);
        run(&o, ISK_INTEGRATE_SEMI_EULER, &f, 0.25, 1);
        cr_assert(memcmp(&mp.r.x, &o.p.x[0], 8) == 0 && memcmp(&mp.r.y, &o.p.y[0], 8) == 0);
        cr_assert(memcmp(&mp.v.x, &o.p.vx[0], 8) == 0 && memcmp(&mp.v.y, &o.p.vy[0], 8) == 0);
    }
    isk_particles_free(&o.p);
}

/* 10^6 steps of a single particle in a softened attracting potential with
 * drag, every integrator: stays finite. */
Test(sim_integrate, long_runs_stay_finite)
{
    for (int k = 0; k < ISK_INTEGRATOR_COUNT; k++) {
        isk_potential pot;
        isk_potential_init(&pot, 50, isk_vec2_make(0, 0), 1);
        pot.min_dist = 0.05;
        isk_forces f = {.gravity = 1, .drag = 0.01, .pot = &pot, .npot = 1};
        one o;
        one_init(&o, 1, 0, 0, 3, 1);
        int steps = k == ISK_INTEGRATE_SEMI_EULER ? 1000000 : 200000;
        run(&o, (isk_integrator)k, &f, 0.001, steps);
        cr_assert(isfinite(o.p.x[0]) && isfinite(o.p.y[0]) && isfinite(o.p.vx[0]) && isfinite(o.p.vy[0]),
                  "%s", isk_integrator_name((isk_integrator)k));
        isk_particles_free(&o.p);
    }
}

Test(sim_integrate, validates)
{
    one o;
    one_init(&o, 0, 0, 0, 0, 1);
    isk_forces f = {0};
    cr_assert_eq(isk_integrate_range(ISK_INTEGRATOR_COUNT, &f, &o.s, &o.p, 0, 1, 0.1), ISK_ERR_RANGE);
    cr_assert_eq(isk_integrate_range(ISK_INTEGRATE_RK4, &f, &o.s, &o.p, 0, 2, 0.1), ISK_ERR_RANGE);
    cr_assert_eq(isk_integrate_range(ISK_INTEGRATE_RK4, &f, &o.s, &o.p, 0, 1, NAN), ISK_ERR_NAN);
    cr_assert_eq(isk_integrate_range(ISK_INTEGRATE_RK4, NULL, &o.s, &o.p, 0, 1, 0.1), ISK_ERR_NULL);
    isk_particles_free(&o.p);
}
