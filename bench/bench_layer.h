/* SPDX-License-Identifier: MIT */
/* bench/bench_layer.h — the effect bench_frame times and bench_dense
 * dissects: one layer emitter of n particles filling an 800x600 view,
 * gravity and drag moving it, reflecting walls keeping it on the screen,
 * drawn as coverage dots or 8 px discs (source-over), or 8 px additive
 * sprites.
 *
 *     isk_effect *fx;
 *     isk_error err = {0};
 *     if (bench_layer_effect(&fx, 16000000, ISK_DRAW_DOT, &err) != ISK_OK) ...
 *
 * Header-only (a static function) so each benchmark stays one program. */
#ifndef ISKRA_BENCH_LAYER_H
#define ISKRA_BENCH_LAYER_H

#include "iskra/effect.h"

enum { BENCH_LAYER_W = 800, BENCH_LAYER_H = 600 };

static inline isk_status bench_layer_effect(isk_effect **fx, size_t n, isk_draw_mode draw, isk_error *err)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    d.width = BENCH_LAYER_W;
    d.height = BENCH_LAYER_H;
    d.xmin = -4;
    d.xmax = 4;
    d.ymin = -3;
    d.ymax = 3;
    d.dt = 1.0 / 60.0;
    d.clear = 1; /* the render clears to the background first, as a scene's does (on the threads) */
    isk_bounds_reflect(&d.bounds, -4, 4, -3, 3, ISK_SIDE_ALL, 0.0, 0.8);
    int g = isk_effect_def_add_force(&d, "gravity", ISK_FORCE_GRAVITY);
    int b = isk_effect_def_add_force(&d, "drag", ISK_FORCE_DRAG);
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "layer");
    isk_status s = ISK_ERR_NOMEM;
    if (g >= 0 && b >= 0 && e) {
        d.forces[g].g = 9.81;
        d.forces[b].b = 0.3;
        e->motion.forces[0] = g;
        e->motion.forces[1] = b;
        e->motion.nforces = 2;
        e->born.source = ISK_SOURCE_LAYER;
        e->born.rect[0] = -3.9;
        e->born.rect[1] = 3.9;
        e->born.rect[2] = -2.9;
        e->born.rect[3] = 2.9;
        e->born.count = e->born.limit = e->born.capacity = n;
        e->look.draw = draw;
        e->look.color = isk_rgba(255, 200, 120, 160);
        e->look.blend = draw == ISK_DRAW_SPRITE ? ISK_BLEND_ADD : ISK_BLEND_OVER;
        e->look.size = 8.0 * (8.0 / BENCH_LAYER_W); /* 8 px sprites and discs */
        s = isk_effect_create(fx, &d, err);
    }
    isk_effect_def_free(&d);
    return s;
}

#endif
