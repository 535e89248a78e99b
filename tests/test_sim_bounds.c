/* SPDX-License-Identifier: MIT */
/* Bounce stages: the thesis's zarobi bit for bit, and the sound reflection
 * that keeps every particle inside. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/bounds.h"
#include "iskra/integrate.h"
#include "iskra/rng.h"
#include "iskra/teach.h"
#include "sanitized.h"

Test(sim_bounds, thesis_floor_value_is_ymin_plus_0_1_in_double)
{
    isk_bounds b;
    cr_assert_eq(isk_bounds_thesis(&b, -10, 10, -10, 10, ISK_SIDE_BOTTOM), ISK_OK);
    double x = 0, y = -12, vx = 1, vy = -3;
    isk_bounds_apply_arrays(&b, 1, &x, &y, &vx, &vy);
    uint64_t bits;
    memcpy(&bits, &y, 8);
    cr_assert_eq(bits, 0xc023cccccccccccdull);
    cr_assert_eq(vy, 3.0);
    cr_assert_eq(vx, 1.0);
}

Test(sim_bounds, thesis_flip_is_unconditional_and_strict)
{
    isk_bounds b;
    isk_bounds_thesis(&b, 0, 10, 0, 10, ISK_SIDE_ALL);
    /* beyond the right wall but already moving inward: flipped outward anyway */
    double x = 9.95, y = 5, vx = -1, vy = 0;
    isk_bounds_apply_arrays(&b, 1, &x, &y, &vx, &vy);
    cr_assert_eq(vx, 1.0);
    cr_assert_eq(x, 9.95); /* no clamp on the right */
    /* exactly on the wall: strict comparison, nothing happens */
    x = 10 - 0.1;
    vx = 2;
    isk_bounds_apply_arrays(&b, 1, &x, &y, &vx, &vy);
    cr_assert_eq(vx, 2.0);
    /* top: flip, no clamp */
    y = 9.95;
    vy = 1;
    isk_bounds_apply_arrays(&b, 1, &x, &y, &vx, &vy);
    cr_assert_eq(vy, -1.0);
    cr_assert_eq(y, 9.95);
}

/* Store stage == per-particle teaching zarobi, every side combination. */
Test(sim_bounds, thesis_stage_equals_teaching_zarobi)
{
    enum { N = 1000 };
    static double x[N], y[N], vx[N], vy[N];
    isk_rng r;
    isk_rng_seed(&r, 3);
    for (unsigned sides = 0; sides < 16; sides++) {
        isk_particle c[N];
        for (int i = 0; i < N; i++) {
            x[i] = isk_rng_range(&r, -0.5, 10.5);
            y[i] = isk_rng_range(&r, -0.5, 10.5);
            vx[i] = isk_rng_range(&r, -3, 3);
            vy[i] = isk_rng_range(&r, -3, 3);
            isk_particle_init(&c[i], 1, isk_vec2_make(x[i], y[i]), isk_vec2_make(vx[i], vy[i]));
        }
        isk_bounds b;
        isk_bounds_thesis(&b, 0, 10, 0, 10, sides);
        isk_bounds_apply_arrays(&b, N, x, y, vx, vy);
        for (int i = 0; i < N; i++) {
            isk_particle_zarobi_box(&c[i], 0, 10, 0, 10, (sides & ISK_SIDE_TOP) != 0,
                                    (sides & ISK_SIDE_RIGHT) != 0, (sides & ISK_SIDE_BOTTOM) != 0,
                                    (sides & ISK_SIDE_LEFT) != 0);
            cr_assert(memcmp(&c[i].mp.r.x, &x[i], 8) == 0 && memcmp(&c[i].mp.r.y, &y[i], 8) == 0);
            cr_assert(memcmp(&c[i].mp.v.x, &vx[i], 8) == 0 && memcmp(&c[i].mp.v.y, &vy[i], 8) == 0);
        }
    }
}

Test(sim_bounds, reflect_mirrors_overshoot_scaled_by_restitution)
{
    isk_bounds b;
    cr_assert_eq(isk_bounds_reflect(&b, 0, 10, 0, 10, ISK_SIDE_ALL, 0, 0.5), ISK_OK);
    double x = -0.4, y = 5, vx = -2, vy = 0;
    isk_bounds_apply_arrays(&b, 1, &x, &y, &vx, &vy);
    cr_assert_float_eq(x, 0.2, 1e-15);
    cr_assert_eq(vx, 1.0);
    /* outside but moving inward: position mirrored, velocity kept */
    x = 10.2;
    vx = -1;
    isk_bounds_apply_arrays(&b, 1, &x, &y, &vx, &vy);
    cr_assert_float_eq(x, 9.9, 1e-15);
    cr_assert_eq(vx, -1.0);
    /* restitution 0: lands on the wall at rest (perpendicular) */
    isk_bounds_reflect(&b, 0, 10, 0, 10, ISK_SIDE_ALL, 0, 0);
    y = -3;
    vy = -5;
    vx = 2;
    isk_bounds_apply_arrays(&b, 1, &x, &y, &vx, &vy);
    cr_assert_eq(y, 0.0);
    cr_assert_eq(vy, 0.0);
    cr_assert_eq(vx, 2.0);
}

Test(sim_bounds, reflect_several_walls_in_one_step)
{
    isk_bounds b;
    isk_bounds_reflect(&b, 0, 10, 0, 10, ISK_SIDE_ALL, 0, 1);
    double x = 25, y = 5, vx = 30, vy = 0; /* right: 10-15 = -5, left: 5 */
    isk_bounds_apply_arrays(&b, 1, &x, &y, &vx, &vy);
    cr_assert_float_eq(x, 5.0, 1e-12);
    cr_assert_eq(vx, 30.0); /* flipped twice */
    x = 1e15;
    y = -1e15;
    vx = 1e300;
    vy = -1e300;
    isk_bounds_apply_arrays(&b, 1, &x, &y, &vx, &vy);
    cr_assert(x >= 0 && x <= 10 && y >= 0 && y <= 10, "%g %g", x, y);
    cr_assert(isfinite(vx) && isfinite(vy));
}

static int count_outside(const isk_particles *p, double lo, double hi)
{
    int out = 0;
    for (size_t i = 0; i < p->count; i++)
        out += !(p->x[i] >= lo && p->x[i] <= hi && p->y[i] >= lo && p->y[i] <= hi);
    return out;
}

/* 10 000 particles x 10 000 steps with gravity in a box, restitution 0,
 * 0.5 and 1: after every step none is outside and none is NaN.
 * The sanitizer build (-O1, every access instrumented) runs 1 000 steps,
 * which takes ~2 s there instead of ~16 s; ISKRA_SIM_STEPS=<n> overrides
 * the step count in either build. */
static int reflect_steps(void)
{
    const char *e = getenv("ISKRA_SIM_STEPS");
    if (e && atoi(e) > 0)
        return atoi(e);
#if TEST_SANITIZED
    return 1000;
#else
    return 10000;
#endif
}

Test(sim_bounds, reflect_keeps_ten_thousand_inside, .timeout = 120)
{
    int steps = reflect_steps();
    double cs[3] = {0, 0.5, 1};
    for (int k = 0; k < 3; k++) {
        isk_particles p;
        isk_particles_init(&p, 10000, 0);
        isk_rng r;
        isk_rng_seed(&r, 11 + k);
        for (int i = 0; i < 10000; i++)
            isk_particles_add(&p, isk_rng_range(&r, 0, 10), isk_rng_range(&r, 0, 10),
                              isk_rng_range(&r, -40, 40), isk_rng_range(&r, -40, 40), 1 + isk_rng_uniform(&r),
                              NULL);
        isk_bounds b;
        isk_bounds_reflect(&b, 0, 10, 0, 10, ISK_SIDE_ALL, 0, cs[k]);
        isk_forces f = {.gravity = 9.81};
        static isk_scratch s;
        for (int t = 0; t < steps; t++) {
            isk_integrate_range(ISK_INTEGRATE_SEMI_EULER, &f, &s, &p, 0, p.count, 0.01);
            isk_bounds_apply(&b, &p, 0, p.count);
            int out = count_outside(&p, 0, 10);
            if (out)
                cr_assert_fail("c=%g step %d: %d outside", cs[k], t, out);
        }
        /* and it is not stuck: with c > 0 the particles still move */
        if (cs[k] > 0) {
            double e = 0;
            for (size_t i = 0; i < p.count; i++)
                e += p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i];
            cr_assert_gt(e, 0.0);
        }
        isk_particles_free(&p);
    }
}

Test(sim_bounds, huge_coordinates_and_speeds_end_inside_and_finite)
{
    double c[3] = {0, 0.5, 1};
    for (int k = 0; k < 3; k++) {
        isk_bounds b;
        isk_bounds_reflect(&b, -10, 10, -10, 10, ISK_SIDE_ALL, 0.1, c[k]);
        double x[6] = {1e15, -1e15, 3, 1e300, -1e300, 0};
        double y[6] = {1e15, 7, -1e15, -1e300, 1e300, 0};
        double vx[6] = {1e15, -1e15, 1e200, 1e300, -1e300, 1e308};
        double vy[6] = {-1e15, 1e15, -1e200, 1e300, 1e300, -1e308};
        for (int step = 0; step < 100; step++) {
            for (int i = 0; i < 6; i++) { /* a huge explicit move each step */
                x[i] = x[i] + 0.5 * vx[i];
                y[i] = y[i] + 0.5 * vy[i];
                if (!isfinite(x[i])) x[i] = copysign(1e308, x[i]);
                if (!isfinite(y[i])) y[i] = copysign(1e308, y[i]);
            }
            isk_bounds_apply_arrays(&b, 6, x, y, vx, vy);
            for (int i = 0; i < 6; i++) {
                cr_assert(x[i] >= -9.9 && x[i] <= 9.9 && y[i] >= -9.9 && y[i] <= 9.9, "c %g i %d: %g %g",
                          c[k], i, x[i], y[i]);
                cr_assert(isfinite(vx[i]) && isfinite(vy[i]));
            }
        }
    }
}

Test(sim_bounds, reflect_with_open_sides_and_nan_safety_net)
{
    isk_bounds b;
    isk_bounds_reflect(&b, 0, 10, 0, 10, ISK_SIDE_BOTTOM, 0, 0.5); /* floor only */
    double x = 50, y = 30, vx = 1, vy = 1;
    isk_bounds_apply_arrays(&b, 1, &x, &y, &vx, &vy);
    cr_assert_eq(x, 50.0);
    cr_assert_eq(y, 30.0);
    y = NAN;
    isk_bounds_apply_arrays(&b, 1, &x, &y, &vx, &vy);
    cr_assert_eq(y, 0.0);
    /* an infinite velocity is not left to throw the particle out again */
    y = -1;
    vy = -INFINITY;
    isk_bounds_apply_arrays(&b, 1, &x, &y, &vx, &vy);
    cr_assert(y >= 0.0 && isfinite(y) && vy == 0.0, "y %g vy %g", y, vy);
}

Test(sim_bounds, validation)
{
    isk_bounds b;
    cr_assert_eq(isk_bounds_reflect(&b, 0, 10, 0, 10, ISK_SIDE_ALL, 0, 1.5), ISK_ERR_RANGE);
    cr_assert_eq(isk_bounds_reflect(&b, 0, 10, 0, 10, ISK_SIDE_ALL, 0, -0.1), ISK_ERR_RANGE);
    cr_assert_eq(isk_bounds_reflect(&b, 0, 10, 0, 10, ISK_SIDE_ALL, 6, 0.5), ISK_ERR_RANGE);
    cr_assert_eq(isk_bounds_reflect(&b, 0, NAN, 0, 10, ISK_SIDE_ALL, 0, 0.5), ISK_ERR_NAN);
    cr_assert_eq(isk_bounds_thesis(&b, 10, 0, 0, 10, ISK_SIDE_ALL), ISK_ERR_RANGE);
    cr_assert_eq(isk_bounds_thesis(&b, 0, 10, 0, 10, 99), ISK_ERR_RANGE);
    cr_assert_eq(isk_bounds_thesis(NULL, 0, 10, 0, 10, 1), ISK_ERR_NULL);
}
