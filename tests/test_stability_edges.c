/* SPDX-License-Identifier: MIT */
/* iskra/stability.h: each integrator's drag edge is where its step under
 * drag alone stops shrinking a velocity, checked against the integrators'
 * own kernels without iskra's cap, and a scene's b*h/m is read from its
 * definition. */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/integrate.h"
#include "iskra/stability.h"

/* |v| after one step of explicit Euler's kernel under an uncapped drag
 * b*h/m = x, from v = 1. */
static double euler_factor(double x)
{
    double px = 0, py = 0, vx = 1, vy = 0, m = 1, fx = -x * vx, fy = 0; /* b = x, h = 1 */
    isk_integrate_euler(1, &px, &py, &vx, &vy, &m, &fx, &fy, 1.0);
    return fabs(vx);
}

Test(stability_edges, explicit_euler_grows_past_exactly_two_without_the_cap)
{
    cr_assert_eq(isk_integrator_drag_edge(ISK_INTEGRATE_EULER), 2.0);
    cr_assert_eq(isk_integrator_drag_edge(ISK_INTEGRATE_SEMI_EULER), 2.0);
    cr_assert_lt(euler_factor(1.999), 1.0);
    cr_assert_eq(euler_factor(2.0), 1.0);
    cr_assert_gt(euler_factor(2.001), 1.0);
}

Test(stability_edges, every_edge_is_where_the_amplification_reaches_one)
{
    double x = isk_integrator_drag_edge(ISK_INTEGRATE_RK4);
    double R = 1 - x + x * x / 2 - x * x * x / 6 + x * x * x * x / 24;
    cr_assert_float_eq(R, 1.0, 1e-13, "rk4: R(-%.17g) = %.17g", x, R);
    cr_assert(x > 2.78 && x < 2.79);
    x = isk_integrator_drag_edge(ISK_INTEGRATE_VERLET);
    cr_assert_eq((1 - x / 2) * (1 - x / 2), 1.0);
    x = isk_integrator_drag_edge(ISK_INTEGRATE_YOSHIDA4);
    const double w1 = 1 / (2 - cbrt(2.0)), w0 = 1 - 2 * w1;
#define G(z) ((1 - (z) / 2) / (1 + (z) / 2))
    const double Y = G(w1 * x) * G(w1 * x) * G(w0 * x);
    cr_assert_float_eq(Y, 1.0, 1e-12, "yoshida4: %.17g", Y);
    for (double y = 0.01; y < x; y += 0.01) /* no earlier crossing */
        cr_assert_lt(fabs(G(w1 * y) * G(w1 * y) * G(w0 * y)), 1.0, "at %g", y);
#undef G
    cr_assert(isinf(isk_integrator_drag_edge(ISK_INTEGRATE_EXACT_DRAG)));
    cr_assert(isinf(isk_integrator_drag_edge(ISK_INTEGRATE_LEAPFROG)));
    cr_assert(isinf(isk_integrator_drag_edge(ISK_INTEGRATE_STRANG)));
    cr_assert(isnan(isk_integrator_drag_edge(ISK_INTEGRATOR_COUNT)));
    cr_assert(isnan(isk_integrator_drag_edge(ISK_INTEGRATE_INHERIT)));
    /* every edge lies beyond iskra's cap: no drag alone ever crosses one */
    for (int m = 0; m < ISK_INTEGRATOR_COUNT; m++)
        cr_assert_gt(isk_integrator_drag_edge((isk_integrator)m), ISK_DRAG_SATURATION);
}

Test(stability_edges, a_scenes_drag_ratio_comes_from_its_definition)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    int drag = isk_effect_def_add_force(&d, "drag", ISK_FORCE_DRAG);
    int drag2 = isk_effect_def_add_force(&d, "more", ISK_FORCE_DRAG);
    int g = isk_effect_def_add_force(&d, "gravity", ISK_FORCE_GRAVITY);
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "a");
    cr_assert(drag >= 0 && drag2 >= 0 && g >= 0 && e);
    d.forces[drag].b = 3;
    d.forces[drag2].b = 1;
    d.forces[g].g = 9.81;
    cr_assert_eq(isk_emitter_use_force(e, drag), ISK_OK);
    cr_assert_eq(isk_emitter_use_force(e, drag2), ISK_OK);
    cr_assert_eq(isk_emitter_use_force(e, g), ISK_OK);
    e->launch.mass = 0.5;
    d.dt = 0.25;
    d.substeps = 2;
    d.speed_divisor = 2;
    /* b = 4, h = 0.25 / 2 / 2, m = 0.5 */
    cr_assert_float_eq(isk_effect_def_drag_ratio(&d, 0), 4 * 0.0625 / 0.5, 1e-15);
    cr_assert_eq(isk_effect_def_emitter_integrator(&d, 0), ISK_INTEGRATE_SEMI_EULER);
    e->motion.integrator = ISK_INTEGRATE_RK4;
    e->motion.substeps = 4;
    cr_assert_eq(isk_effect_def_emitter_integrator(&d, 0), ISK_INTEGRATE_RK4);
    cr_assert_eq(isk_effect_def_emitter_substeps(&d, 0), 4);
    cr_assert_float_eq(isk_effect_def_drag_ratio(&d, 0), 4 * (0.25 / 4 / 2) / 0.5, 1e-15);
    cr_assert_eq(isk_effect_def_drag_ratio(&d, 1), 0.0, "no such emitter");
    cr_assert_eq(isk_effect_def_emitter_integrator(&d, 1), ISK_INTEGRATE_INHERIT);
    cr_assert_eq(isk_effect_def_drag_ratio(NULL, 0), 0.0);
    isk_effect_def_free(&d);
}

/* The 2x2 matrix of one leapfrog kick-drift-kick step of t on x'' = -x. */
static void leapfrog(double t, double a[2][2])
{
    a[0][0] = 1 - t * t / 2;
    a[0][1] = t;
    a[1][0] = -t + t * t * t / 4;
    a[1][1] = 1 - t * t / 2;
}

static void mul(double a[2][2], double b[2][2], double out[2][2])
{
    double r[2][2];
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j];
    memcpy(out, r, sizeof r);
}

static double yoshida_trace(double h)
{
    const double w1 = 1 / (2 - cbrt(2.0)), w0 = 1 - 2 * w1;
    double a[2][2], b[2][2];
    leapfrog(w1 * h, a);
    leapfrog(w0 * h, b);
    mul(a, b, b);
    mul(b, a, b);
    return b[0][0] + b[1][1];
}

Test(stability_edges, the_spring_edges_are_where_the_step_stops_being_bounded)
{
    cr_assert_eq(isk_integrator_spring_edge(ISK_INTEGRATE_SEMI_EULER), 2.0);
    cr_assert_eq(isk_integrator_spring_edge(ISK_INTEGRATE_LEAPFROG), 2.0);
    cr_assert_eq(isk_integrator_spring_edge(ISK_INTEGRATE_EULER), 0.0, "explicit Euler grows at any step");
    cr_assert_eq(isk_integrator_spring_edge(ISK_INTEGRATE_EXACT_DRAG), 0.0);
    /* RK4 on the imaginary axis: |R(iy)|^2 = 1 - y^6/72 + y^8/576 */
    const double y = isk_integrator_spring_edge(ISK_INTEGRATE_RK4);
    cr_assert_float_eq(1 - pow(y, 6) / 72 + pow(y, 8) / 576, 1.0, 1e-13);
    cr_assert_float_eq(y, 2 * sqrt(2.0), 1e-15);
    /* Yoshida: the composed step is bounded while |trace| <= 2 */
    const double h = isk_integrator_spring_edge(ISK_INTEGRATE_YOSHIDA4);
    cr_assert_float_eq(fabs(yoshida_trace(h)), 2.0, 1e-12, "%.17g", yoshida_trace(h));
    for (double t = 0.01; t < h; t += 0.01)
        cr_assert_leq(fabs(yoshida_trace(t)), 2.0, "bounded below the edge, at %g", t);
    cr_assert_gt(fabs(yoshida_trace(h + 1e-6)), 2.0);
    cr_assert(isnan(isk_integrator_spring_edge(ISK_INTEGRATOR_COUNT)));
}

Test(stability_edges, a_potentials_core_is_a_spring_of_known_stiffness)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    int c = isk_effect_def_add_force(&d, "core", ISK_FORCE_POTENTIAL);
    int r = isk_effect_def_add_force(&d, "repels", ISK_FORCE_POTENTIAL);
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "a");
    cr_assert(c >= 0 && r >= 0 && e);
    /* P = 9 inside min 2: w^2 = kQ / (m min^9) = 2^9 * 4 / (2^9 * 1) = 4 */
    d.forces[c].pot.k = 2048;
    d.forces[c].pot.charge = 1;
    d.forces[c].exponent = 9;
    d.forces[c].pot.min_dist = 2;
    d.forces[r].pot.k = 1e9; /* repels: no spring, however stiff */
    d.forces[r].pot.charge = -1;
    d.forces[r].exponent = 0;
    cr_assert_eq(isk_emitter_use_force(e, c), ISK_OK);
    cr_assert_eq(isk_emitter_use_force(e, r), ISK_OK);
    d.dt = 0.1;
    cr_assert_float_eq(isk_effect_def_spring_ratio(&d, 0), 2 * 0.1, 1e-15, "w h = 2 * 0.1");
    e->launch.mass = 4; /* w = 1 */
    cr_assert_float_eq(isk_effect_def_spring_ratio(&d, 0), 0.1, 1e-15);
    d.forces[c].pot.min_dist = -1; /* no core: singular, no spring */
    cr_assert_eq(isk_effect_def_spring_ratio(&d, 0), 0.0);
    isk_effect_def_free(&d);
}
