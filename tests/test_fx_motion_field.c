/* SPDX-License-Identifier: MIT */
/* The accelerations that depend on where a particle is
 * (src/sim/field.h): radial and tangential around the emitter's current
 * position, and turbulence, the curl of a seeded gradient noise -- its
 * divergence (finite differences, to round-off), its determinism and its
 * seeding, and the same bytes on any number of threads. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/rng.h"
#include "iskra/scene.h"
#include "scene_text.h"
#include "sim/field.h"

Test(fx_motion_field, radial_and_tangential_directions)
{
    isk_field f = {0};
    f.radial = 2;
    f.tangential = 1;
    f.cx = 1;
    f.cy = 1;
    double ax, ay;
    isk__field_accel(&f, 3, 4, 0, 0, &ax, &ay); /* (2, 3) from the centre */
    const double r = sqrt(13.0), ux = 2 / r, uy = 3 / r;
    cr_assert_float_eq(ax, 2 * ux - 1 * uy, 1e-15);
    cr_assert_float_eq(ay, 2 * uy + 1 * ux, 1e-15);
    /* counter-clockwise: on the +x side the tangential pull is +y */
    f.radial = 0;
    isk__field_accel(&f, 5, 1, 0, 0, &ax, &ay);
    cr_assert(ax == 0 && ay == 1, "(%g, %g)", ax, ay);
    /* exactly on the emitter at rest: no direction, zero, never NaN */
    f.radial = -7;
    isk__field_accel(&f, 1, 1, 0, 0, &ax, &ay);
    cr_assert(ax == 0 && ay == 0, "(%g, %g)", ax, ay);
    /* exactly on the emitter and moving: the direction it leaves in */
    isk__field_accel(&f, 1, 1, 0, 3, &ax, &ay);
    cr_assert(ax == -1 && ay == -7, "(%g, %g)", ax, ay);
    /* far away: still a unit direction, no overflow */
    f.cx = f.cy = 0;
    f.tangential = 0;
    isk__field_accel(&f, 1e200, 1e200, 0, 0, &ax, &ay);
    cr_assert_float_eq(ax, -7 / sqrt(2.0), 1e-12, "%g", ax);
    cr_assert(isfinite(ay));
}

static void turb_accel(const isk_field *f, double x, double y, double *ax, double *ay)
{
    isk__field_accel(f, x, y, 0, 0, ax, ay);
}

/* div a = dax/dx + day/dy by central differences: zero up to the
 * differences' own error, while each term alone is of the order of
 * strength/scale. */
Test(fx_motion_field, turbulence_is_divergence_free)
{
    isk_field f = {0};
    f.turb[f.nturb++] = isk__field_turbulence(3.0, 1.7, 0.4, isk__noise_key(42, 0));
    f.t = 2.25;
    isk_rng rng;
    isk_rng_seed(&rng, 9);
    double worst_div = 0, largest_term = 0;
    const double d = 1e-5;
    for (int i = 0; i < 2000; i++) {
        double x = 40 * isk_rng_uniform(&rng) - 20, y = 40 * isk_rng_uniform(&rng) - 20;
        double axp, ayp, axm, aym, bxp, byp, bxm, bym;
        turb_accel(&f, x + d, y, &axp, &ayp);
        turb_accel(&f, x - d, y, &axm, &aym);
        turb_accel(&f, x, y + d, &bxp, &byp);
        turb_accel(&f, x, y - d, &bxm, &bym);
        double dax = (axp - axm) / (2 * d), day = (byp - bym) / (2 * d);
        worst_div = fmax(worst_div, fabs(dax + day));
        largest_term = fmax(largest_term, fmax(fabs(dax), fabs(day)));
    }
    cr_assert_gt(largest_term, 1.0, "the field hardly varies: %g", largest_term);
    /* O(d^2) truncation and O(eps/d) round-off: 1e-9 of a term here */
    cr_assert_lt(worst_div, 1e-7 * largest_term, "div up to %g (terms up to %g)", worst_div, largest_term);
}

Test(fx_motion_field, turbulence_is_seeded_and_deterministic)
{
    isk_field a = {0}, b = {0}, c = {0};
    a.turb[a.nturb++] = isk__field_turbulence(1, 1, 1, isk__noise_key(7, 0));
    b.turb[b.nturb++] = isk__field_turbulence(1, 1, 1, isk__noise_key(7, 0));
    c.turb[c.nturb++] = isk__field_turbulence(1, 1, 1, isk__noise_key(7, 1)); /* another force */
    int differ = 0;
    double sum = 0;
    for (int i = 0; i < 400; i++) {
        double x = 0.37 * i - 50, y = 0.11 * i;
        a.t = b.t = c.t = 0.01 * i;
        double ax, ay, bx, by, cx, cy;
        isk__field_accel(&a, x, y, 0, 0, &ax, &ay);
        isk__field_accel(&b, x, y, 0, 0, &bx, &by);
        isk__field_accel(&c, x, y, 0, 0, &cx, &cy);
        cr_assert(ax == bx && ay == by);
        differ += ax != cx || ay != cy;
        sum += hypot(ax, ay);
        cr_assert(isfinite(ax) && isfinite(ay));
    }
    cr_assert_gt(differ, 390, "another index gives another field");
    cr_assert(sum / 400 > 0.2 && sum / 400 < 3, "mean |a| %g is of the order of strength", sum / 400);
    cr_assert_neq(isk__noise_key(7, 0), isk__noise_key(8, 0));
    /* huge and non-finite noise coordinates are clamped, never converted */
    double du, dv;
    double n = isk__noise3(1, 1e300, -1e300, NAN, &du, &dv);
    cr_assert(isfinite(n) && isfinite(du) && isfinite(dv));
}

/* Where the noise lattice has no fraction left (|x/scale| or |y/scale|
 * from 2^52 on) there is no turbulence: before, every such point was the
 * clamped corner, a uniform wind of sqrt 2 x strength.  Just inside, the
 * field is still there. */
Test(fx_motion_field, no_turbulence_past_the_lattice)
{
    int inside = 0;
    for (int k = 0; k < 200; k++) {
        const double far = ldexp(1.0, 52 + k % 60) * (1.0 + k / 200.0), t = 0.37 * k;
        const double pts[4][2] = {{far, 0.3}, {-far, 2.7}, {1.5, far}, {far, -far}};
        for (int q = 0; q < 4; q++) {
            double du = 1, dv = 1;
            const double n = isk__noise3(isk__noise_key(3, k), pts[q][0], pts[q][1], t, &du, &dv);
            cr_assert(n == 0.0 && du == 0.0 && dv == 0.0, "(%g, %g): noise %g, gradient (%g, %g)", pts[q][0],
                      pts[q][1], n, du, dv);
        }
        double du, dv;
        isk__noise3(isk__noise_key(3, k), 0x1p50 + 0.3 + k, 0.6 * k, t, &du, &dv);
        inside += du != 0.0 || dv != 0.0;
    }
    cr_assert_gt(inside, 150, "inside the lattice the field is there");
}

/* The field's time: speed*t moves the pattern; speed 0 is still. */
Test(fx_motion_field, turbulence_evolves_with_speed)
{
    isk_field f = {0};
    f.turb[f.nturb++] = isk__field_turbulence(1, 2, 0, isk__noise_key(1, 0));
    double a0, b0, a1, b1;
    f.t = 0;
    isk__field_accel(&f, 0.3, 0.7, 0, 0, &a0, &b0);
    f.t = 5;
    isk__field_accel(&f, 0.3, 0.7, 0, 0, &a1, &b1);
    cr_assert(a0 == a1 && b0 == b1);
    f.turb[0].speed = 0.5;
    isk__field_accel(&f, 0.3, 0.7, 0, 0, &a1, &b1);
    cr_assert(a0 != a1 || b0 != b1);
}

static const char *smoke = "[scene]\nseed = 11\n"
                           "[force swirl]\nkind = turbulence\nstrength = 6\nscale = 1.5\nspeed = 0.5\n"
                           "[emitter smoke]\nsource = stream\nrate = 20000\nshape = disc\nshape_a = 2\n"
                           "launch = disc\nspeed_max = 1\nlife = 2\ncapacity = 100000\nforces = swirl\n"
                           "radial_accel = 1\ntangential_accel = 2\nemitter_velocity = 1, 0\n";

static isk_effect *open_text(const char *text, int threads) { return scene_text_open(text, threads); }

/* Thousands of particles (many blocks): the same state on 1 and 3 threads. */
Test(fx_motion_field, same_state_on_any_number_of_threads, .timeout = 60)
{
    isk_effect *a = open_text(smoke, 1), *b = open_text(smoke, 3);
    for (int i = 0; i < 20; i++) {
        cr_assert_eq(isk_effect_step(a), ISK_OK);
        cr_assert_eq(isk_effect_step(b), ISK_OK);
    }
    const isk_particles *p = isk_effect_particles(a, 0), *q = isk_effect_particles(b, 0);
    cr_assert_gt(p->count, 5000);
    cr_assert_eq(p->count, q->count);
    cr_assert(!memcmp(p->x, q->x, p->count * sizeof *p->x) && !memcmp(p->y, q->y, p->count * sizeof *p->y) &&
              !memcmp(p->vx, q->vx, p->count * sizeof *p->vx) && !memcmp(p->vy, q->vy, p->count * sizeof *p->vy));
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

/* Around the emitter's current position: a moving emitter's pull follows
 * it, and a stream born on a ring with tangential acceleration alone turns
 * counter-clockwise. */
Test(fx_motion_field, centred_on_the_moving_emitter)
{
    isk_effect *fx = open_text("[scene]\nseed = 2\n[emitter e]\nsource = stream\nrate = 600\nshape = circle\n"
                               "shape_a = 2\nposition = 1, 1\ntangential_accel = 5\n",
                               1);
    for (int i = 0; i < 3; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_gt(p->count, 20);
    size_t moving = 0;
    for (size_t i = 0; i < p->count; i++) {
        if (p->vx[i] == 0 && p->vy[i] == 0)
            continue; /* born at the very end of the step: no time to feel it yet */
        moving++;
        double rx = p->x[i] - 1, ry = p->y[i] - 1;
        double cross = rx * p->vy[i] - ry * p->vx[i]; /* > 0: counter-clockwise */
        double along = rx * p->vx[i] + ry * p->vy[i];
        cr_assert_gt(cross, 0, "%zu", i);
        cr_assert_lt(fabs(along), 0.05 * cross + 1e-12, "%zu: tangential only (%g, %g)", i, along, cross);
    }
    cr_assert_gt(moving, 20);
    isk_effect_destroy(fx);
}
