/* SPDX-License-Identifier: MIT */
/* The fire thesis's interactive capacity: "several tens of thousands of
 * particles" (its conclusion, no figures given).  The fire digest makes it a
 * check: 30,000 particles drawn as 8-pixel additive gradient sprites on an
 * 800x600 canvas, update + raster at >= 30 frames per second on one core,
 * measured headless.
 *
 * One stream emitter (rate and life chosen so ~30,000 are alive), rising by
 * buoyancy, oscillating through the sine table, colour over life; timed
 * separately: isk_effect_step (update) and isk_effect_render (raster),
 * median of the frames after the population has settled. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "bench_util.h"
#include "iskra/effect.h"

enum { WARM = 150, MEASURE = 90 };

int main(void)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    d.width = 800;
    d.height = 600;
    d.view_kind = ISK_VIEWDEF_CAMERA;
    d.zoom = 10; /* 70 px per unit: 8 px = 0.1143 units */
    d.dt = 1.0 / 60.0;
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "fire");
    e->born.source = ISK_SOURCE_STREAM;
    e->born.position = isk_vec2_make(0, -3.5);
    e->born.shape = ISK_SHAPE_RECT;
    e->born.shape_a = 4.5;
    e->born.shape_b = 0.2;
    e->launch.kind = ISK_VELGEN_CONE;
    e->launch.angle = 1.5707963267948966;
    e->launch.spread = 0.6;
    e->launch.speed_min = 0.5;
    e->launch.speed_max = 1.5;
    e->motion.weight = 1.2;
    e->born.rate = 15000;
    e->life.seconds = 1.5;
    e->life.range = 1.0; /* mean 2 s: ~30,000 alive */
    e->born.capacity = 40000;
    e->motion.osc_omega_min = -8;
    e->motion.osc_omega_max = 8;
    e->motion.osc_amplitude_min = 0.05;
    e->motion.osc_amplitude_max = 0.2;
    e->look.draw = ISK_DRAW_SPRITE;
    e->look.sprite = ISK_SPRITE_LINEAR;
    e->look.size = 8.0 / 70.0;
    e->look.blend = ISK_BLEND_ADD;
    e->look.color_over_life.n = 3;
    e->look.color_over_life.stops[0] = (isk_color_stop){0.0, isk_rgba(255, 220, 120, 120)};
    e->look.color_over_life.stops[1] = (isk_color_stop){0.5, isk_rgba(255, 120, 30, 90)};
    e->look.color_over_life.stops[2] = (isk_color_stop){1.0, isk_rgba(120, 20, 0, 0)};
    d.threads = 1; /* the digest's check is one core's; bench_frame times the threads */
    isk_effect *fx;
    isk_error err;
    isk_canvas c;
    if (isk_effect_create(&fx, &d, &err) != ISK_OK || isk_canvas_init(&c, 800, 600) != ISK_OK) {
        fprintf(stderr, "bench_fire_capacity: %s\n", err.message);
        return 1;
    }
    isk_effect_def_free(&d);
    for (int i = 0; i < WARM; i++)
        isk_effect_step(fx);
    double tu[MEASURE], tr[MEASURE], tt[MEASURE];
    size_t alive = 0;
    for (int i = 0; i < MEASURE; i++) {
        double t0 = bench_now();
        isk_effect_step(fx);
        double t1 = bench_now();
        isk_effect_render(fx, &c);
        double t2 = bench_now();
        tu[i] = t1 - t0;
        tr[i] = t2 - t1;
        tt[i] = t2 - t0;
        alive += isk_effect_particle_count(fx);
    }
    double update = bench_median(tu, MEASURE), raster = bench_median(tr, MEASURE);
    double frame = bench_median(tt, MEASURE);
    printf("fire capacity: %zu particles on average, 8 px additive gradient sprites, 800x600, one core\n",
           alive / MEASURE);
    printf("  update %.2f ms, raster %.2f ms, frame %.2f ms (medians of %d frames) -> %.0f frames/s\n",
           update * 1e3, raster * 1e3, frame * 1e3, MEASURE, 1.0 / frame);
    printf("  target (fire digest check 21): >= 30 frames/s with 30,000 particles: %s\n",
           1.0 / frame >= 30.0 ? "met" : "NOT met");
    isk_canvas_free(&c);
    isk_effect_destroy(fx);
    return 0;
}
