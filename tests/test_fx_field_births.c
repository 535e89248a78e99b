/* SPDX-License-Identifier: MIT */
/* Back-dated births feel the field stage (radial, tangential, turbulence)
 * for their part of the frame, as they feel constant forces: a birth at
 * time t within a step is run through the emitter's stages for its age.
 *
 * The closed form used here: a particle leaving the emitter's centre at
 * speed v0 under radial_accel a moves along a straight line, its speed
 * v0 + a*t and its distance v0*t + a*t^2/2.  Semi-implicit Euler gets the
 * speed exactly (the direction never changes) and overshoots the distance
 * by a*h*t/2 for steps of h, so two frame rates agree on the positions to
 * within a*T*(h1 - h2)/2 after T seconds. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>

#include "iskra/effect.h"
#include "scene_text.h"

/* Ten births a second from the origin, launched along +x at 1 unit/s,
 * under radial_accel = 1, stepped at `fps` frames a second. */
static isk_effect *radial_stream(double fps)
{
    char text[400];
    snprintf(text, sizeof text,
             "[scene]\ndt = %.17g\n[emitter e]\nsource = stream\nrate = 10\nposition = 0, 0\nvelocity = 1, 0\n"
             "radial_accel = 1\nbounded = false\ndraw = none\n",
             1.0 / fps);
    return scene_text_open(text, 1);
}

/* One frame of 1 s: ten births at 0.1, 0.2, ..., 1.0 s, aged 0.9 ... 0 s.
 * Each leaves at 1 + its age (they all read 1.000 when the field was not
 * felt from the emitter's centre), straight along +x, within the one
 * step's overshoot of the closed-form distance. */
Test(fx_field_births, ten_births_in_a_frame_speed_up_by_their_age)
{
    isk_effect *fx = radial_stream(1.0);
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_eq(p->count, 10);
    for (size_t i = 0; i < p->count; i++) {
        const double age = 1.0 - 0.1 * (double)(i + 1);
        const double speed = hypot(p->vx[i], p->vy[i]);
        cr_assert_float_eq(speed, 1.0 + age, 1e-12, "birth %zu (age %g): speed %.15g", i, age, speed);
        cr_assert_eq(p->vy[i], 0.0);
        const double exact = age + 0.5 * age * age;
        cr_assert(p->x[i] >= exact - 1e-12 && p->x[i] <= exact + 0.5 * age * age + 1e-12,
                  "birth %zu (age %g): x %.15g, closed form %.15g", i, age, p->x[i], exact);
    }
    isk_effect_destroy(fx);
}

/* The same emitter at 30 and at 144 steps a second: after 1 s the same
 * ten particles, speeds equal to the closed form, positions within
 * a*T*(1/30 - 1/144)/2 = 0.0132 of each other (they differed by up to
 * 0.015 when the births' first moments missed the field). */
Test(fx_field_births, frame_rates_agree_within_the_integrators_error)
{
    isk_effect *a = radial_stream(30), *b = radial_stream(144);
    for (int f = 0; f < 30; f++)
        cr_assert_eq(isk_effect_step(a), ISK_OK);
    for (int f = 0; f < 144; f++)
        cr_assert_eq(isk_effect_step(b), ISK_OK);
    const isk_particles *p = isk_effect_particles(a, 0), *q = isk_effect_particles(b, 0);
    cr_assert_eq(p->count, 10);
    cr_assert_eq(q->count, 10);
    const double bound = 1.0 * 1.0 * (1.0 / 30 - 1.0 / 144) / 2;
    double worst = 0;
    for (size_t i = 0; i < p->count; i++) {
        const double age = 1.0 - 0.1 * (double)(i + 1);
        cr_assert_float_eq(p->vx[i], 1.0 + age, 1e-9, "30/s birth %zu: %.15g", i, p->vx[i]);
        cr_assert_float_eq(q->vx[i], 1.0 + age, 1e-9, "144/s birth %zu: %.15g", i, q->vx[i]);
        worst = fmax(worst, fabs(p->x[i] - q->x[i]));
    }
    cr_assert_leq(worst, bound + 1e-12, "positions differ by up to %.6g (bound %.6g)", worst, bound);
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

/* ---- the field stage's order ------------------------------------------------
 * The field stage kicks the velocity by a(x)*h before the forces and the
 * integrator (a Lie splitting), so the field's part of a step is first
 * order whatever the integrator: one particle starting at rest on the unit
 * circle, pulled in (radial_accel = -1) and turned (tangential_accel = 1),
 * at t = 1 s with N, 2N and 4N steps; the order is
 * log2(|x_N - x_2N| / |x_2N - x_4N|). */
static void spiral_at_1s(const char *integrator, int steps, double *x, double *y)
{
    char text[600];
    snprintf(text, sizeof text,
             "[scene]\ndt = %.17g\nintegrator = %s\nseed = 4\n[emitter e]\nsource = stream\nrate = 0\ncount = 1\n"
             "shape = circle\nshape_a = 1\nposition = 0, 0\nvelocity = 0, 0\nradial_accel = -1\n"
             "tangential_accel = 1\nbounded = false\ndraw = none\n",
             1.0 / steps, integrator);
    isk_effect *fx = scene_text_open(text, 1);
    for (int f = 0; f < steps; f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_eq(p->count, 1);
    *x = p->x[0];
    *y = p->y[0];
    isk_effect_destroy(fx);
}

static double measured_order(const char *integrator, int n)
{
    double x1, y1, x2, y2, x4, y4;
    spiral_at_1s(integrator, n, &x1, &y1);
    spiral_at_1s(integrator, 2 * n, &x2, &y2);
    spiral_at_1s(integrator, 4 * n, &x4, &y4);
    return log2(hypot(x1 - x2, y1 - y2) / hypot(x2 - x4, y2 - y4));
}

/* docs/accuracy.md quotes these orders: 1.0 for every integrator, the
 * fourth-order ones included. */
Test(fx_field_births, the_field_stage_is_first_order_whatever_the_integrator)
{
    const char *const methods[] = {"semi-euler", "verlet", "rk4", "leapfrog", "yoshida4"};
    for (size_t k = 0; k < sizeof methods / sizeof methods[0]; k++) {
        const double p = measured_order(methods[k], 50);
        cr_log_info("%s: order %.3f", methods[k], p);
        cr_assert(p > 0.9 && p < 1.1, "%s: measured order %.3f", methods[k], p);
    }
}
