/* SPDX-License-Identifier: MIT */
/* Drawing fire: tinted sprites (one mask per size serves a whole colour
 * ramp), additive order independence, draw order, over-life ramps read
 * through the effect, per-emitter colour/size/blend. */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "iskra/draw.h"
#include "iskra/effect.h"
#include "iskra/rng.h"
#include "iskra/sprite.h"
#include "scene/effect_internal.h"

#define PI 3.14159265358979323846

static isk_effect *make(const isk_effect_def *d)
{
    isk_effect *e = NULL;
    isk_error err = {0};
    isk_status s = isk_effect_create(&e, d, &err);
    cr_assert_eq(s, ISK_OK, "create: %s", err.message);
    return e;
}

static void noise_fill(isk_canvas *c, uint64_t seed)
{
    isk_rng r;
    isk_rng_seed(&r, seed);
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++) {
            uint8_t *p = isk_canvas_at(c, x, y);
            for (int k = 0; k < 4; k++)
                p[k] = (uint8_t)isk_rng_below(&r, 256);
        }
}

/* isk_draw_sprite_tinted with any colour == isk_draw_sprite of a sprite
 * baked in that colour (itself == isk_blend_pixel_cov per pixel), for
 * every kind, several sizes, every blend mode, positions on and off the
 * half-pixel grid and partly off the canvas, over random pixels. */
Test(fire_render, tinted_equals_baked_sprite)
{
    const isk_color cols[3] = {{255, 128, 0, 255}, {30, 200, 90, 77}, {255, 255, 255, 1}};
    const int sizes[4] = {1, 7, 16, 33};
    const double pos[4][2] = {{20.5, 20.5}, {20, 20}, {13.37, 28.81}, {-3.2, 39.6}};
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, 48, 44), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 48, 44), ISK_OK);
    for (int kind = 0; kind <= 2; kind++)
        for (int si = 0; si < 4; si++) {
            isk_sprite mask_spr;
            cr_assert_eq(isk_sprite_init(&mask_spr, (isk_sprite_kind)kind, sizes[si], ISK_WHITE), ISK_OK);
            for (int ci = 0; ci < 3; ci++) {
                isk_sprite col_spr;
                cr_assert_eq(isk_sprite_init(&col_spr, (isk_sprite_kind)kind, sizes[si], cols[ci]), ISK_OK);
                for (int mode = 0; mode <= 2; mode++)
                    for (int pi = 0; pi < 4; pi++) {
                        noise_fill(&a, (uint64_t)(pi + 10 * mode));
                        noise_fill(&b, (uint64_t)(pi + 10 * mode));
                        isk_draw_sprite(&a, &col_spr, pos[pi][0], pos[pi][1], (isk_blend)mode);
                        isk_draw_sprite_tinted(&b, &mask_spr, pos[pi][0], pos[pi][1], cols[ci], (isk_blend)mode);
                        cr_assert(isk_canvas_equal(&a, &b), "kind %d size %d colour %d mode %d pos %d", kind,
                                  sizes[si], ci, mode, pi);
                    }
                isk_sprite_free(&col_spr);
            }
            isk_sprite_free(&mask_spr);
        }
    /* And directly against isk_blend_pixel_cov, sprite centred on a pixel
     * corner (phase 0 for even S): pixel (i, j) of the mask at (x0+i, y0+j). */
    isk_sprite s;
    cr_assert_eq(isk_sprite_init(&s, ISK_SPRITE_SMOOTH, 16, ISK_WHITE), ISK_OK);
    isk_color col = {200, 100, 50, 180};
    noise_fill(&a, 99);
    noise_fill(&b, 99);
    isk_draw_sprite_tinted(&a, &s, 20, 20, col, ISK_BLEND_OVER);
    for (int j = 0; j < 16; j++)
        for (int i = 0; i < 16; i++)
            isk_blend_pixel_cov(isk_canvas_at(&b, 12 + i, 12 + j), col, s.mask[0][j * 16 + i], ISK_BLEND_OVER);
    cr_assert(isk_canvas_equal(&a, &b));
    isk_sprite_free(&s);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

/* Fire thesis check 2: S = 32 gradient centred on a pixel centre, colour
 * (255, 128, 0, 255), additive on black: at d = 8, R = 128 +- 1 and
 * G = 64 +- 1; every pixel with d >= 16 (the square's corners) stays 0. */
Test(fire_render, thesis_gradient_sprite_tinted)
{
    isk_sprite s;
    cr_assert_eq(isk_sprite_init(&s, ISK_SPRITE_LINEAR, 32, ISK_WHITE), ISK_OK);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 64, 64), ISK_OK);
    isk_canvas_fill(&c, isk_rgba(0, 0, 0, 0));
    isk_draw_sprite_tinted(&c, &s, 32.5, 32.5, isk_rgba(255, 128, 0, 255), ISK_BLEND_ADD);
    const uint8_t *p = isk_canvas_at(&c, 32 + 8, 32);
    cr_assert(abs(p[0] - 128) <= 1 && abs(p[1] - 64) <= 1, "R %d G %d", p[0], p[1]);
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            double d = hypot(x + 0.5 - 32.5, y + 0.5 - 32.5);
            if (d >= 16)
                cr_assert_eq(isk_canvas_at(&c, x, y)[0] | isk_canvas_at(&c, x, y)[1], 0, "(%d, %d)", x, y);
        }
    isk_canvas_free(&c);
    isk_sprite_free(&s);
}

/* A flame emitter: additive gradient sprites, colour/alpha/size ramps. */
static void flame_def(isk_effect_def *d, int ramps, isk_blend blend)
{
    isk_effect_def_init(d);
    d->width = 200;
    d->height = 200;
    d->seed = 5;
    isk_emitter_def *e = isk_effect_def_add_emitter(d, "flame");
    e->born.source = ISK_SOURCE_STREAM;
    e->born.position = isk_vec2_make(0, -6);
    e->born.shape = ISK_SHAPE_ELLIPSE;
    e->born.shape_a = 3;
    e->born.shape_b = 1;
    e->launch.kind = ISK_VELGEN_CONE;
    e->launch.angle = PI / 2;
    e->launch.spread = 0.6;
    e->launch.speed_min = 4;
    e->launch.speed_max = 8;
    e->motion.weight = 3;
    e->born.rate = 300;
    e->life.seconds = 0.8;
    e->life.range = 1.0;
    e->motion.osc_omega_min = -9;
    e->motion.osc_omega_max = 9;
    e->motion.osc_amplitude_min = 0.3;
    e->motion.osc_amplitude_max = 1;
    e->look.draw = ISK_DRAW_SPRITE;
    e->look.sprite = ISK_SPRITE_LINEAR;
    e->look.size = 4;
    e->look.color = isk_rgba(255, 140, 30, 90);
    e->look.blend = blend;
    if (ramps) {
        e->look.color_over_life.n = 4;
        e->look.color_over_life.stops[0] = (isk_color_stop){0.0, isk_rgba(255, 230, 120, 90)};
        e->look.color_over_life.stops[1] = (isk_color_stop){0.3, isk_rgba(255, 140, 30, 90)};
        e->look.color_over_life.stops[2] = (isk_color_stop){0.7, isk_rgba(200, 40, 10, 60)};
        e->look.color_over_life.stops[3] = (isk_color_stop){1.0, isk_rgba(60, 0, 0, 0)};
        e->look.alpha_over_life.n = 2;
        e->look.alpha_over_life.stops[0] = (isk_scalar_stop){0.0, 1.0};
        e->look.alpha_over_life.stops[1] = (isk_scalar_stop){1.0, 0.5};
        e->look.size_over_life.n = 2;
        e->look.size_over_life.stops[0] = (isk_scalar_stop){0.0, 1.0};
        e->look.size_over_life.stops[1] = (isk_scalar_stop){1.0, 0.3};
    }
}

static void reverse_store(isk_particles *p)
{
    double *arr[7] = {p->x, p->y, p->vx, p->vy, p->m, p->age, p->life};
    for (int k = 0; k < 7; k++)
        for (size_t i = 0, j = p->count - 1; i < j; i++, j--) {
            double t = arr[k][i];
            arr[k][i] = arr[k][j];
            arr[k][j] = t;
        }
}

/* Fire thesis check 4: additive sprites give the same bytes in any order.
 * Rendered, then rendered again with the particle store reversed: equal
 * with additive (with and without ramps), different with overpaint. */
Test(fire_render, additive_independent_of_draw_order)
{
    for (int ramps = 0; ramps <= 1; ramps++)
        for (int blend = ISK_BLEND_OVER; blend <= ISK_BLEND_ADD; blend++) {
            isk_effect_def d;
            flame_def(&d, ramps, (isk_blend)blend);
            isk_effect *fx = make(&d);
            for (int i = 0; i < 90; i++)
                isk_effect_step(fx);
            isk_canvas a, b;
            cr_assert_eq(isk_canvas_init(&a, 200, 200), ISK_OK);
            cr_assert_eq(isk_canvas_init(&b, 200, 200), ISK_OK);
            isk_particles *p = (isk_particles *)isk_effect_particles(fx, 0);
            cr_assert_gt(p->count, 200u);
            isk_effect_render(fx, &a);
            reverse_store(p);
            isk_effect_render(fx, &b);
            long differ = 0;
            for (int y = 0; y < 200; y++)
                differ += memcmp(isk_canvas_at(&a, 0, y), isk_canvas_at(&b, 0, y), 800) != 0;
            if (blend == ISK_BLEND_ADD)
                cr_assert_eq(differ, 0, "ramps %d: %ld rows differ", ramps, differ);
            else
                cr_assert_gt(differ, 0, "overpaint should depend on order");
            isk_canvas_free(&a);
            isk_canvas_free(&b);
            isk_effect_destroy(fx);
            isk_effect_def_free(&d);
        }
}

/* A colour ramp does not bake a sprite per colour: a flame of hundreds of
 * particles with a 4-stop ramp and a size ramp bakes one mask per pixel
 * size (here sizes 12..40 px at most). */
Test(fire_render, ramp_bakes_per_size_not_per_colour)
{
    isk_effect_def d;
    flame_def(&d, 1, ISK_BLEND_ADD);
    isk_effect *fx = make(&d);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 200, 200), ISK_OK);
    for (int i = 0; i < 120; i++) {
        isk_effect_step(fx);
        isk_effect_render(fx, &c);
    }
    long bakes = isk_sprite_cache_bakes(fx->sprites);
    cr_assert_leq(bakes, 29, "%ld bakes", bakes);
    cr_assert_geq(bakes, 20, "%ld bakes", bakes);
    isk_canvas_free(&c);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* Fire thesis check 6: two overlapping opaque emitters, overpaint: the
 * one drawn last wins, and swapping `order` swaps the colour; additive:
 * swapping changes nothing. */
Test(fire_render, emitter_draw_order)
{
    for (int blend = ISK_BLEND_OVER; blend <= ISK_BLEND_ADD; blend++) {
        isk_canvas c[2];
        for (int swap = 0; swap <= 1; swap++) {
            isk_effect_def d;
            isk_effect_def_init(&d);
            d.width = d.height = 100;
            const isk_color cols[2] = {{255, 0, 0, 255}, {0, 0, 255, 255}};
            for (int k = 0; k < 2; k++) {
                isk_emitter_def *e = isk_effect_def_add_emitter(&d, k ? "blue" : "red");
                e->look.draw = ISK_DRAW_SPRITE;
                e->look.sprite = ISK_SPRITE_DISC;
                e->look.size = 4;
                e->look.color = cols[k];
                e->look.blend = (isk_blend)blend;
                e->look.order = swap ? 1 - k : k;
            }
            isk_effect *fx = make(&d);
            cr_assert_eq(isk_canvas_init(&c[swap], 100, 100), ISK_OK);
            isk_effect_render(fx, &c[swap]);
            isk_effect_destroy(fx);
            isk_effect_def_free(&d);
        }
        const uint8_t *p0 = isk_canvas_at(&c[0], 50, 50), *p1 = isk_canvas_at(&c[1], 50, 50);
        if (blend == ISK_BLEND_OVER) {
            cr_assert(p0[0] == 0 && p0[2] == 255, "blue drawn last");
            cr_assert(p1[0] == 255 && p1[2] == 0, "red drawn last");
        } else {
            cr_assert(isk_canvas_equal(&c[0], &c[1]));
            cr_assert(p0[0] == 255 && p0[2] == 255);
        }
        isk_canvas_free(&c[0]);
        isk_canvas_free(&c[1]);
    }
}

/* Ramps with several stops, read through the effect: one motionless
 * particle of life 1 s drawn as a replaced pixel at every 1/8 s; at each
 * age its colour equals the exact interpolation isk_color_gradient_eval
 * (at the stops 0, 0.25, 0.5 and 0.875: the stop colours), and the alpha
 * ramp multiplies alpha with rounding half up. */
Test(fire_render, ramps_equal_exact_interpolation)
{
    const isk_color_stop stops[5] = {{0.0, {255, 255, 200, 255}}, {0.25, {255, 160, 40, 255}},
                                     {0.5, {200, 40, 10, 200}},   {0.875, {60, 0, 0, 40}},
                                     {1.0, {0, 0, 0, 0}}};
    const isk_scalar_stop astops[3] = {{0.0, 1.0}, {0.5, 0.5}, {1.0, 0.25}};
    for (int with_alpha = 0; with_alpha <= 1; with_alpha++) {
        isk_effect_def d;
        isk_effect_def_init(&d);
        d.width = d.height = 20;
        d.dt = 0.125;
        isk_emitter_def *e = isk_effect_def_add_emitter(&d, "p");
        e->life.seconds = 1.0;
        e->look.draw = ISK_DRAW_PIXEL;
        e->look.blend = ISK_BLEND_REPLACE;
        e->look.color_over_life.n = 5;
        memcpy(e->look.color_over_life.stops, stops, sizeof stops);
        if (with_alpha) {
            e->look.alpha_over_life.n = 3;
            memcpy(e->look.alpha_over_life.stops, astops, sizeof astops);
        }
        isk_effect *fx = make(&d);
        isk_canvas c;
        cr_assert_eq(isk_canvas_init(&c, 20, 20), ISK_OK);
        for (int k = 0; k < 8; k++) {
            double t = k * 0.125;
            isk_effect_render(fx, &c);
            isk_color want = isk_color_gradient_eval(stops, 5, t);
            if (with_alpha) {
                double a = want.a * isk_scalar_gradient_eval(astops, 3, t);
                want.a = (uint8_t)(int)(a + 0.5);
            }
            const uint8_t *p = isk_canvas_at(&c, 10, 10);
            cr_assert(p[0] == want.r && p[1] == want.g && p[2] == want.b && p[3] == want.a,
                      "t = %g: (%d %d %d %d) vs (%d %d %d %d)", t, p[0], p[1], p[2], p[3], want.r, want.g, want.b,
                      want.a);
            for (int s = 0; s < 5; s++)
                if (stops[s].t == t && !with_alpha)
                    cr_assert(p[0] == stops[s].color.r && p[3] == stops[s].color.a);
            isk_effect_step(fx);
        }
        isk_canvas_free(&c);
        isk_effect_destroy(fx);
        isk_effect_def_free(&d);
    }
}

/* Per-emitter colour, size, blend and draw mode, and the size ramp: the
 * effect's pixels equal drawing the sprite by hand at the rounded pixel
 * size (world size * multiplier * 10 px per unit). */
Test(fire_render, per_emitter_parameters_and_size_ramp)
{
    const isk_color col = {30, 200, 90, 150};
    for (int ramp = 0; ramp <= 1; ramp++) {
        isk_effect_def d;
        isk_effect_def_init(&d);
        d.width = d.height = 200; /* -10..10: 10 px per unit */
        d.dt = 0.25;
        isk_emitter_def *e = isk_effect_def_add_emitter(&d, "p");
        e->born.position = isk_vec2_make(0.05, -0.05);
        e->life.seconds = 1.0;
        e->look.draw = ISK_DRAW_SPRITE;
        e->look.sprite = ISK_SPRITE_SMOOTH;
        e->look.size = 1.7; /* 17 px */
        e->look.color = col;
        e->look.blend = ISK_BLEND_OVER;
        if (ramp) {
            e->look.size_over_life.n = 2;
            e->look.size_over_life.stops[0] = (isk_scalar_stop){0.0, 1.0};
            e->look.size_over_life.stops[1] = (isk_scalar_stop){1.0, 3.0};
        }
        isk_effect *fx = make(&d);
        isk_canvas a, b;
        cr_assert_eq(isk_canvas_init(&a, 200, 200), ISK_OK);
        cr_assert_eq(isk_canvas_init(&b, 200, 200), ISK_OK);
        for (int k = 0; k < 4; k++) {
            double mult = ramp ? 1.0 + 2.0 * k * 0.25 : 1.0;
            int px = (int)(1.7 * mult * 10 + 0.5); /* 17, 26, 34, 43 */
            isk_effect_render(fx, &a);
            isk_canvas_fill(&b, ISK_BLACK);
            isk_sprite s;
            cr_assert_eq(isk_sprite_init(&s, ISK_SPRITE_SMOOTH, px, col), ISK_OK);
            isk_draw_sprite(&b, &s, 100.5, 100.5, ISK_BLEND_OVER);
            isk_sprite_free(&s);
            cr_assert(isk_canvas_equal(&a, &b), "ramp %d step %d (%d px)", ramp, k, px);
            isk_effect_step(fx);
        }
        isk_canvas_free(&a);
        isk_canvas_free(&b);
        isk_effect_destroy(fx);
        isk_effect_def_free(&d);
    }
}
