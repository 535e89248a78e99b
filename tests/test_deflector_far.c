/* SPDX-License-Identifier: MIT */
/* Deflector segments that reach far away (endpoints at +-1e12, +-1e16,
 * +-1e150) keep their precision near the particles: short paths that cross
 * them near the origin never tunnel (before: most did at 1e12, and at 1e150
 * the segment was not seen at all). */
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>

#include "iskra/deflector.h"
#include "iskra/effect.h"
#include "iskra/scene.h"

static const double REACH[3] = {1e12, 1e16, 1e150};

/* Paths across the line y = m x (through the origin: the endpoints are
 * +-(L, m L) with m = 0.375, exact in binary) at points x in [-100, 100],
 * from delta above it to delta below it, delta down to 1e-12: every one
 * bounces and ends above the line again. */
Test(deflector_far, short_paths_across_a_long_diagonal_never_tunnel)
{
    const double m = 0.375, nx = -m / sqrt(1 + m * m), ny = 1 / sqrt(1 + m * m);
    const double deltas[5] = {1e-12, 1e-9, 1e-6, 1e-3, 1.0};
    for (int r = 0; r < 3; r++) {
        const double L = REACH[r];
        isk_deflector d = isk_deflector_segment(-L, -m * L, L, m * L);
        cr_assert_eq(isk_deflector_check(&d), ISK_OK);
        long paths = 0, tunnelled = 0;
        for (int k = 0; k <= 40; k++)
            for (int j = 0; j < 5; j++) {
                double t = -100 + 5.0 * k + 0.123, dl = deltas[j];
                double x0 = t + dl * nx, y0 = m * t + dl * ny;
                double x = t - dl * nx, y = m * t - dl * ny, vx = -nx, vy = -ny;
                cr_assert(m * x0 - y0 < 0 && m * x - y > 0); /* the path does cross */
                cr_assert_eq(isk_deflect(&d, 1, &x, &y, &vx, &vy, &x0, &y0, 1, NULL, NULL, NULL), ISK_OK);
                paths++;
                tunnelled += !(m * x - y < 0) || !(vx * nx + vy * ny > 0);
            }
        cr_assert_eq(tunnelled, 0, "L = %g: %ld of %ld paths tunnelled", L, tunnelled, paths);
    }
}

/* Particles falling through a scene onto a far horizontal floor and a far
 * slope y = x/4 bounce off both (and settle on them), at every reach. */
Test(deflector_far, particles_fall_onto_far_segments_and_bounce)
{
    for (int r = 0; r < 3; r++) {
        char text[1200];
        snprintf(text, sizeof text,
                 "[scene]\ndt = 1/60\nintegrator = verlet\n[force gravity]\ng = 9.81\n"
                 "[deflector floor]\nsegment = %.17g, -1, %.17g, -1\nrestitution = 0.5\n"
                 "[deflector slope]\nsegment = %.17g, %.17g, %.17g, %.17g\nrestitution = 0.5\n"
                 "[emitter rain]\nsource = layer\nrect = -8, 8, 3, 9\ncount = 300\nforces = gravity\n"
                 "deflectors = floor, slope\nbounded = false\ndraw = none\n",
                 -REACH[r], REACH[r], -REACH[r], -REACH[r] * 0.25, REACH[r], REACH[r] * 0.25);
        isk_effect_def def;
        isk_error err;
        isk_effect *fx = NULL;
        cr_assert_eq(isk_scene_load_string(&def, text, "far", &err), ISK_OK, "%s", err.message);
        cr_assert_eq(isk_effect_create(&fx, &def, &err), ISK_OK, "%s", err.message);
        isk_effect_def_free(&def);
        const isk_particles *p = isk_effect_particles(fx, 0);
        for (int f = 0; f < 300; f++) {
            cr_assert_eq(isk_effect_step(fx), ISK_OK);
            for (size_t i = 0; i < p->count; i++) {
                cr_assert(p->y[i] > -1, "reach %g frame %d: through the floor at (%g, %g)", REACH[r], f, p->x[i],
                          p->y[i]);
                cr_assert(0.25 * p->x[i] - p->y[i] < 1e-12, "reach %g frame %d: through the slope at (%g, %g)",
                          REACH[r], f, p->x[i], p->y[i]);
            }
        }
        isk_effect_destroy(fx);
    }
}

/* Endpoints beyond 1e150 are refused (so every product of coordinates the
 * side tests form stays finite). */
Test(deflector_far, endpoints_beyond_the_limit_are_refused)
{
    isk_deflector d = isk_deflector_segment(-1e151, 0, 1, 0);
    cr_assert_eq(isk_deflector_check(&d), ISK_ERR_RANGE);
    d = isk_deflector_segment(-ISK_COORD_MAX, 0, ISK_COORD_MAX, 1);
    cr_assert_eq(isk_deflector_check(&d), ISK_OK);
    d.restitution = ISK_DEFLECT_RESTITUTION_MAX * 1.5;
    cr_assert_eq(isk_deflector_check(&d), ISK_ERR_RANGE);
}
