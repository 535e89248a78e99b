/* SPDX-License-Identifier: MIT */
/* Trails (trail, trail_width, trail_fade): the store's history column (a
 * ring of the last N positions that moves with its particle through
 * growth, removal and both culls), recorded once per frame; the drawing
 * through the view in bands (the same bytes on any number of threads); and
 * the reference images of the sub-emitter and trail scenes. */
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/limits.h"
#include "iskra/particles.h"
#include "iskra/scene.h"
#include "refimg.h"
#include "scene/effect_internal.h" /* band_min_work */
#include "scene_text.h"

/* Particle i's trail point k (0: oldest). */
static void point(const isk_particles *p, size_t i, int k, double *x, double *y)
{
    int slot = (p->trail_head + 1 + k) % p->trail_len;
    *x = p->trail[2 * (size_t)p->trail_len * i + 2 * (size_t)slot];
    *y = p->trail[2 * (size_t)p->trail_len * i + 2 * (size_t)slot + 1];
}

Test(fx_trail, the_column_is_a_ring_that_moves_with_its_particle)
{
    isk_particles p;
    cr_assert_eq(isk_particles_init(&p, 0, ISK_PARTICLES_TRAIL), ISK_ERR_SIZE, "the trail needs its length");
    cr_assert_eq(isk_particles_init(&p, 0, ISK_PARTICLES_HIT), ISK_OK);
    cr_assert_eq(isk_particles_set_trail(&p, ISK_TRAIL_MAX + 1), ISK_ERR_RANGE);
    cr_assert_eq(isk_particles_set_trail(&p, -1), ISK_ERR_RANGE);
    cr_assert_eq(isk_particles_set_trail(&p, 4), ISK_OK);
    cr_assert(p.flags & ISK_PARTICLES_TRAIL);
    for (int i = 0; i < 300; i++) /* grows past 256: the arrays move */
        cr_assert_eq(isk_particles_add(&p, i, -i, 0, 0, 1, NULL), ISK_OK);
    for (int k = 0; k < 4; k++) {
        double x, y;
        point(&p, 7, k, &x, &y);
        cr_assert(x == 7 && y == -7, "a new particle's points are all its position");
    }
    for (int f = 1; f <= 6; f++) { /* frame f: x = i + 1000 f */
        for (size_t i = 0; i < p.count; i++)
            p.x[i] = (double)i + 1000.0 * f;
        isk_particles_record_trail(&p);
    }
    for (size_t i = 0; i < p.count; i++) {
        p.life[i] = i % 3 == 0 ? 0.0 : INFINITY; /* every third dies */
        p.hit[i] = (unsigned char)(i % 200);
    }
    isk_particles_cull(&p);
    cr_assert_eq(p.count, 200);
    for (size_t k = 0; k < p.count; k++) {
        const double i = p.y[k] * -1.0;
        cr_assert(fmod(i, 3) != 0);
        cr_assert_eq(p.hit[k], (unsigned char)((int)i % 200));
        for (int j = 0; j < 4; j++) {
            double x, y;
            point(&p, k, j, &x, &y);
            cr_assert(x == i + 1000.0 * (3 + j) && y == -i, "particle %g point %d: %g", i, j, x);
        }
    }
    for (size_t k = 0; k < p.count; k++)
        p.life[k] = k % 2 ? 0.0 : INFINITY;
    isk_particles_cull_unordered(&p);
    isk_particles_remove(&p, 0);
    cr_assert_eq(p.count, 99);
    for (size_t k = 0; k < p.count; k++) {
        const double i = -p.y[k];
        cr_assert_eq(p.hit[k], (unsigned char)((int)i % 200));
        double x, y;
        point(&p, k, 3, &x, &y);
        cr_assert(x == i + 6000.0 && y == -i);
    }
    cr_assert_eq(isk_particles_set_trail(&p, 0), ISK_OK);
    cr_assert_null(p.trail);
    cr_assert_not_null(p.hit);
    cr_assert_eq(p.count, 99);
    isk_particles_free(&p);
}

static isk_effect *make(const char *text, int threads) { return scene_text_open(text, threads); }

/* The trail is the particle's position at the end of each of the last N
 * frames, whatever the substeps. */
Test(fx_trail, one_point_per_frame)
{
    isk_effect *fx = make("[scene]\nwidth = 64\nheight = 64\nsubsteps = 4\n"
                          "[emitter e]\nsource = particle\nvelocity = 1, 0\ntrail = 5\n",
                          1);
    const isk_particles *p = isk_effect_particles(fx, 0);
    double xs[20];
    for (int f = 0; f < 20; f++) {
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        xs[f] = p->x[0];
    }
    for (int k = 0; k < 5; k++) {
        double x, y;
        point(p, 0, k, &x, &y);
        cr_assert_eq(x, xs[15 + k]);
    }
    isk_effect_destroy(fx);
}

/* 20000 trailed particles, drawn in bands from 2 threads: the same bytes
 * on 1, 2, 3 and 7 threads, and different from the scene without trails. */
Test(fx_trail, the_same_bytes_on_any_number_of_threads, .timeout = 120)
{
    static const char *text = "[scene]\nwidth = 160\nheight = 120\n[force gravity]\ng = 9.81\n"
                              "[emitter e]\nsource = stream\ncount = 20000\nlaunch = disc\nspeed_max = 6\n"
                              "forces = gravity\nblend = add\ncolor = #402010\ntrail = 6\ntrail_width = 1.5\n";
    isk_canvas ref = {0};
    const int threads[] = {1, 2, 3, 7};
    for (int t = 0; t < 4; t++) {
        isk_effect *fx = make(text, threads[t]);
        fx->band_min_work = 0; /* the trails' draw in bands, as a bigger scene's would be */
        isk_canvas c;
        cr_assert_eq(isk_canvas_init(&c, 160, 120), ISK_OK);
        cr_assert_eq(isk_effect_run(fx, &c, 8), ISK_OK);
        if (t == 0) {
            ref = c;
        } else {
            cr_assert_eq(memcmp(c.pixels, ref.pixels, (size_t)c.stride * 120), 0, "%d threads", threads[t]);
            isk_canvas_free(&c);
        }
        isk_effect_destroy(fx);
    }
    isk_canvas_free(&ref);
}

/* The example scenes (scenes/fx_*.ini) are compared with refimg/NAME.png
 * by tests/test_scene_render.c, with every scene that has an image. */
