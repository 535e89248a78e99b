/* SPDX-License-Identifier: MIT */
/* Sprites: the fire thesis's checks, masks against the analytic falloff,
 * byte-identity with isk_blend_pixel_cov, additive order independence,
 * clipping, the cache, and reference images. */
#include <criterion/criterion.h>
#include <criterion/logging.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/blend.h"
#include "iskra/canvas.h"
#include "iskra/rng.h"
#include "iskra/sprite.h"
#include "refimg.h"

#define PI 3.14159265358979323846

static isk_canvas canvas(int w, int h, isk_color bg)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, w, h), ISK_OK);
    isk_canvas_fill(&c, bg);
    return c;
}

/* Fire thesis §5 check 2: S=32 gradient centred on a pixel centre, additive
 * on black. */
Test(sprite, thesis_linear_gradient)
{
    isk_canvas c = canvas(64, 64, ISK_BLACK);
    isk_sprite s;
    cr_assert_eq(isk_sprite_init(&s, ISK_SPRITE_LINEAR, 32, isk_rgba(255, 128, 0, 255)), ISK_OK);
    const double cx = 32.5, cy = 30.5; /* centre of pixel (32, 30) */
    isk_draw_sprite(&c, &s, cx, cy, ISK_BLEND_ADD);
    /* d = 8 along both axes */
    int pts[4][2] = {{40, 30}, {24, 30}, {32, 38}, {32, 22}};
    for (int k = 0; k < 4; k++) {
        isk_color p = isk_canvas_get(&c, pts[k][0], pts[k][1]);
        cr_expect(abs(p.r - 128) <= 1 && abs(p.g - 64) <= 1 && p.b == 0, "(%d,%d) = %d %d %d", pts[k][0],
                  pts[k][1], p.r, p.g, p.b);
    }
    isk_color centre = isk_canvas_get(&c, 32, 30);
    cr_expect_eq(centre.r, 255);
    cr_expect_eq(centre.g, 128);
    long lit = 0;
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            isk_color p = isk_canvas_get(&c, x, y);
            double d = hypot(x + 0.5 - cx, y + 0.5 - cy);
            if (d >= 16.0)
                cr_assert(p.r == 0 && p.g == 0 && p.b == 0 && p.a == 255, "pixel (%d,%d) at d=%g lit", x, y, d);
            lit += p.r != 0;
        }
    cr_expect_gt(lit, 700); /* ~pi 16^2 = 804 pixels inside the rim */
    isk_sprite_free(&s);
    isk_canvas_free(&c);
}

/* Fire thesis §5 check 3: solid S=64 touches pi 32^2 pixels (+-1 %), none
 * outside radius 32; at a pixel corner and at a pixel centre. */
Test(sprite, thesis_solid_disc_area)
{
    isk_sprite s;
    cr_assert_eq(isk_sprite_init(&s, ISK_SPRITE_DISC, 64, isk_rgba(200, 10, 10, 255)), ISK_OK);
    double centres[3][2] = {{50.0, 50.0}, {50.5, 50.5}, {50.5, 50.0}};
    for (int k = 0; k < 3; k++) {
        isk_canvas c = canvas(100, 100, ISK_BLACK);
        isk_draw_sprite(&c, &s, centres[k][0], centres[k][1], ISK_BLEND_OVER);
        long n = 0;
        for (int y = 0; y < 100; y++)
            for (int x = 0; x < 100; x++) {
                isk_color p = isk_canvas_get(&c, x, y);
                if (p.r) {
                    n++;
                    cr_assert_lt(hypot(x + 0.5 - centres[k][0], y + 0.5 - centres[k][1]), 32.0);
                }
            }
        double want = PI * 32 * 32;
        cr_expect_leq(fabs(n - want), 0.01 * want, "centre %g,%g: %ld pixels", centres[k][0], centres[k][1], n);
        isk_canvas_free(&c);
    }
    isk_sprite_free(&s);
}

/* Every mask value is the analytic alpha within one level (particle-engine
 * check 37), for every phase; exact in the integer-defined cases. */
static void check_masks(int size)
{
    for (int kind = 0; kind < 3; kind++) {
        isk_sprite s;
        cr_assert_eq(isk_sprite_init(&s, (isk_sprite_kind)kind, size, ISK_WHITE), ISK_OK);
        for (int p = 0; p < 4; p++) {
            double hx = 0.5 * (p & 1), hy = 0.5 * (p >> 1);
            for (int j = 0; j < size; j++) {
                int first = size, last = 0;
                for (int i = 0; i < size; i++) {
                    double d = hypot(i + 0.5 - size / 2.0 - hx, j + 0.5 - size / 2.0 - hy);
                    double a = 255.0 * isk_sprite_alpha((isk_sprite_kind)kind, d, size);
                    int m = s.mask[p][j * size + i];
                    cr_assert_leq(fabs(m - a), 1.0, "kind %d S=%d phase %d (%d,%d): %d vs %g", kind, size, p, i, j,
                                  m, a);
                    /* disc: exact; everything outside the rim: 0 */
                    if (kind == ISK_SPRITE_DISC)
                        cr_assert_eq(m, (int)a);
                    if (d >= size / 2.0)
                        cr_assert_eq(m, 0);
                    if (m) {
                        first = i < first ? i : first;
                        last = i + 1;
                    }
                }
                if (first > last)
                    first = last = 0;
                cr_assert_eq(s.span[p][2 * j], first);
                cr_assert_eq(s.span[p][2 * j + 1], last);
            }
        }
        isk_sprite_free(&s);
    }
}

Test(sprite, masks_match_analytic)
{
    for (int size = 1; size <= 48; size++)
        check_masks(size);
    int big[] = {63, 64, 100, 127, 255, 256};
    for (size_t k = 0; k < sizeof big / sizeof big[0]; k++)
        check_masks(big[k]);
}

/* Reference rendering straight from the documented rule with
 * isk_blend_pixel_cov. */
static void draw_reference(isk_canvas *c, const isk_sprite *s, double cx, double cy, isk_blend mode)
{
    int S = s->size;
    double sx = floor(2.0 * cx + 0.5) / 2.0, sy = floor(2.0 * cy + 0.5) / 2.0;
    int x0 = (int)floor(sx - S / 2.0), y0 = (int)floor(sy - S / 2.0);
    int p = (sx - S / 2.0 != x0) + 2 * (sy - S / 2.0 != y0);
    for (int j = 0; j < S; j++)
        for (int i = 0; i < S; i++) {
            int x = x0 + i, y = y0 + j;
            if (x >= 0 && y >= 0 && x < c->width && y < c->height)
                isk_blend_pixel_cov(isk_canvas_at(c, x, y), s->color, s->mask[p][j * S + i], mode);
        }
}

Test(sprite, identical_to_blend_pixel_cov)
{
    isk_rng r;
    isk_rng_seed(&r, 5);
    isk_blend modes[3] = {ISK_BLEND_REPLACE, ISK_BLEND_OVER, ISK_BLEND_ADD};
    for (int mi = 0; mi < 3; mi++) {
        isk_canvas a = canvas(90, 70, ISK_TRANSPARENT), b = canvas(90, 70, ISK_TRANSPARENT);
        /* a background with varied alpha, so OVER's general path is used */
        for (int y = 0; y < 70; y++)
            for (int x = 0; x < 90; x++) {
                uint8_t *pa = isk_canvas_at(&a, x, y), *pb = isk_canvas_at(&b, x, y);
                for (int k = 0; k < 4; k++)
                    pa[k] = pb[k] = (uint8_t)isk_rng_below(&r, 256);
            }
        for (int n = 0; n < 300; n++) {
            isk_color col = isk_rgba((uint8_t)isk_rng_below(&r, 256), (uint8_t)isk_rng_below(&r, 256),
                                     (uint8_t)isk_rng_below(&r, 256), (uint8_t)isk_rng_below(&r, 256));
            isk_sprite s;
            cr_assert_eq(isk_sprite_init(&s, (isk_sprite_kind)isk_rng_below(&r, 3), 1 + (int)isk_rng_below(&r, 40), col),
                         ISK_OK);
            double cx = isk_rng_range(&r, -30, 120), cy = isk_rng_range(&r, -30, 100);
            if (n % 3 == 0) { /* exact halves and corners too */
                cx = floor(cx * 2) / 2;
                cy = floor(cy * 2) / 2;
            }
            isk_draw_sprite(&a, &s, cx, cy, modes[mi]);
            draw_reference(&b, &s, cx, cy, modes[mi]);
            isk_sprite_free(&s);
        }
        cr_assert(isk_canvas_equal(&a, &b), "mode %d differs", mi);
        isk_canvas_free(&a);
        isk_canvas_free(&b);
    }
}

/* With additive blending the image does not depend on draw order. */
Test(sprite, additive_order_independent)
{
    enum { N = 200 };
    isk_sprite_cache *cache;
    cr_assert_eq(isk_sprite_cache_create(&cache, 256), ISK_OK);
    const isk_sprite *spr[N];
    double x[N], y[N];
    int perm[N];
    isk_rng r;
    isk_rng_seed(&r, 11);
    for (int i = 0; i < N; i++) {
        isk_color col = isk_rgba((uint8_t)(128 + isk_rng_below(&r, 128)), (uint8_t)isk_rng_below(&r, 200),
                                 (uint8_t)isk_rng_below(&r, 60), (uint8_t)(40 + isk_rng_below(&r, 216)));
        cr_assert_eq(isk_sprite_cache_get(cache, (isk_sprite_kind)isk_rng_below(&r, 3), 2 + (int)isk_rng_below(&r, 60),
                                          col, &spr[i]),
                     ISK_OK);
        x[i] = isk_rng_range(&r, -20, 180);
        y[i] = isk_rng_range(&r, -20, 140);
        perm[i] = i;
    }
    for (int i = N - 1; i > 0; i--) { /* Fisher-Yates */
        int j = (int)isk_rng_below(&r, (uint32_t)i + 1u);
        int t = perm[i];
        perm[i] = perm[j];
        perm[j] = t;
    }
    isk_canvas a = canvas(160, 120, isk_rgba(10, 10, 20, 255)), b = canvas(160, 120, isk_rgba(10, 10, 20, 255));
    for (int i = 0; i < N; i++)
        isk_draw_sprite(&a, spr[i], x[i], y[i], ISK_BLEND_ADD);
    for (int i = 0; i < N; i++)
        isk_draw_sprite(&b, spr[perm[i]], x[perm[i]], y[perm[i]], ISK_BLEND_ADD);
    cr_assert_eq(memcmp(a.pixels, b.pixels, a.stride * 120u), 0);
    /* and reversed order */
    isk_canvas_fill(&b, isk_rgba(10, 10, 20, 255));
    for (int i = N - 1; i >= 0; i--)
        isk_draw_sprite(&b, spr[i], x[i], y[i], ISK_BLEND_ADD);
    cr_assert_eq(memcmp(a.pixels, b.pixels, a.stride * 120u), 0);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_sprite_cache_destroy(cache);
}

Test(sprite, snapping_rule)
{
    isk_sprite s;
    cr_assert_eq(isk_sprite_init(&s, ISK_SPRITE_LINEAR, 9, ISK_WHITE), ISK_OK);
    isk_canvas a = canvas(40, 40, ISK_BLACK), b = canvas(40, 40, ISK_BLACK);
    /* 10.3 and 10.7 both snap to 10.5; 10.25 (a tie) goes up to 10.5;
     * 10.74 to 10.5, 10.75 to 11.0 */
    isk_draw_sprite(&a, &s, 10.5, 20.0, ISK_BLEND_REPLACE);
    double same[] = {10.3, 10.7, 10.25, 10.74, 10.5000001};
    for (size_t k = 0; k < sizeof same / sizeof same[0]; k++) {
        isk_canvas_fill(&b, ISK_BLACK);
        isk_draw_sprite(&b, &s, same[k], 19.9, ISK_BLEND_REPLACE);
        cr_expect(isk_canvas_equal(&a, &b), "cx=%g", same[k]);
    }
    isk_canvas_fill(&a, ISK_BLACK);
    isk_canvas_fill(&b, ISK_BLACK);
    isk_draw_sprite(&a, &s, 11.0, 20.0, ISK_BLEND_REPLACE);
    isk_draw_sprite(&b, &s, 10.75, 20.0, ISK_BLEND_REPLACE);
    cr_expect(isk_canvas_equal(&a, &b));
    /* Odd S centred on a pixel centre: the brightest pixel is that pixel. */
    isk_canvas_fill(&a, ISK_BLACK);
    isk_draw_sprite(&a, &s, 10.5, 20.5, ISK_BLEND_REPLACE);
    cr_expect_eq(isk_canvas_get(&a, 10, 20).a, 255);
    cr_expect_eq(isk_canvas_get(&a, 11, 20).a, isk_canvas_get(&a, 9, 20).a);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_sprite_free(&s);
}

Test(sprite, clipping_any_coordinates)
{
    isk_sprite s;
    cr_assert_eq(isk_sprite_init(&s, ISK_SPRITE_SMOOTH, 256, ISK_WHITE), ISK_OK);
    isk_canvas c = canvas(50, 30, ISK_BLACK), ref = canvas(50, 30, ISK_BLACK);
    double bad[] = {NAN, INFINITY, -INFINITY, 1e300, -1e300, 1e18, -1e18, 4e9, -4e9, 200.0, -129.0, 179.0};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        for (size_t j = 0; j < sizeof bad / sizeof bad[0]; j++)
            for (int m = 0; m < 3; m++)
                isk_draw_sprite(&c, &s, bad[i], bad[j], (isk_blend)m);
    cr_expect(isk_canvas_equal(&c, &ref), "off-canvas or non-finite centres drew something");
    /* Partly visible at every edge: no out-of-bounds access (ASan). */
    double edge[] = {-127.0, -100.3, 0.0, 25.0, 49.9, 150.0, 177.0};
    for (size_t i = 0; i < sizeof edge / sizeof edge[0]; i++)
        for (size_t j = 0; j < sizeof edge / sizeof edge[0]; j++)
            isk_draw_sprite(&c, &s, edge[i], edge[j], ISK_BLEND_ADD);
    cr_expect(!isk_canvas_equal(&c, &ref));
    /* A 0x0 view and an invalid mode draw nothing. */
    isk_canvas v;
    cr_assert_eq(isk_canvas_view(&v, &ref, 100, 100, 5, 5), ISK_OK);
    isk_draw_sprite(&v, &s, 0, 0, ISK_BLEND_ADD);
    isk_draw_sprite(&ref, &s, 25, 15, (isk_blend)7);
    isk_draw_sprite(NULL, &s, 25, 15, ISK_BLEND_ADD);
    isk_draw_sprite(&ref, NULL, 25, 15, ISK_BLEND_ADD);
    isk_canvas black = canvas(50, 30, ISK_BLACK);
    cr_expect(isk_canvas_equal(&black, &ref));
    isk_canvas_free(&black);
    isk_canvas_free(&c);
    isk_canvas_free(&ref);
    isk_sprite_free(&s);
}

Test(sprite, init_validates)
{
    isk_sprite s;
    cr_expect_eq(isk_sprite_init(NULL, ISK_SPRITE_DISC, 8, ISK_WHITE), ISK_ERR_NULL);
    cr_expect_eq(isk_sprite_init(&s, (isk_sprite_kind)3, 8, ISK_WHITE), ISK_ERR_RANGE);
    cr_expect_eq(isk_sprite_init(&s, (isk_sprite_kind)-1, 8, ISK_WHITE), ISK_ERR_RANGE);
    cr_expect_eq(isk_sprite_init(&s, ISK_SPRITE_DISC, 0, ISK_WHITE), ISK_ERR_SIZE);
    cr_expect_eq(isk_sprite_init(&s, ISK_SPRITE_DISC, 257, ISK_WHITE), ISK_ERR_SIZE);
    cr_expect_eq(isk_sprite_init(&s, ISK_SPRITE_DISC, -5, ISK_WHITE), ISK_ERR_SIZE);
    cr_assert_eq(isk_sprite_init(&s, ISK_SPRITE_DISC, 1, ISK_WHITE), ISK_OK);
    cr_expect_eq(s.mask[0][0], 255); /* S=1, phase 0: centred on the pixel centre */
    cr_expect_eq(s.mask[3][0], 0);   /* phase 3: centre on a corner, d = 0.707 > 0.5 */
    isk_sprite_free(&s);
    isk_sprite_free(&s); /* safe twice */
    isk_sprite_free(NULL);
}

Test(sprite, cache_bakes_once_and_bounds)
{
    isk_sprite_cache *c;
    cr_expect_eq(isk_sprite_cache_create(&c, 0), ISK_ERR_SIZE);
    cr_expect_eq(isk_sprite_cache_create(&c, ISK_SPRITE_CACHE_MAX + 1), ISK_ERR_SIZE);
    cr_expect_eq(isk_sprite_cache_create(NULL, 4), ISK_ERR_NULL);
    cr_assert_eq(isk_sprite_cache_create(&c, 3), ISK_OK);
    const isk_sprite *a, *b, *d;
    /* A frame of 10000 particles sharing three sprites bakes three. */
    for (int i = 0; i < 10000; i++) {
        cr_assert_eq(isk_sprite_cache_get(c, (isk_sprite_kind)(i % 3), 16, ISK_YELLOW, &a), ISK_OK);
        cr_assert_eq(a->kind, (isk_sprite_kind)(i % 3));
    }
    cr_expect_eq(isk_sprite_cache_bakes(c), 3);
    cr_expect_eq(isk_sprite_cache_count(c), 3);
    cr_assert_eq(isk_sprite_cache_get(c, ISK_SPRITE_DISC, 16, ISK_YELLOW, &a), ISK_OK);
    cr_assert_eq(isk_sprite_cache_get(c, ISK_SPRITE_DISC, 16, ISK_YELLOW, &b), ISK_OK);
    cr_expect_eq(a, b);
    /* Full: no eviction, an error, and the old pointers stay valid. */
    d = NULL;
    cr_expect_eq(isk_sprite_cache_get(c, ISK_SPRITE_DISC, 17, ISK_YELLOW, &d), ISK_ERR_FULL);
    cr_expect_null(d);
    cr_expect_eq(isk_sprite_cache_get(c, ISK_SPRITE_DISC, 16, ISK_RED, &d), ISK_ERR_FULL);
    cr_expect_eq(a->size, 16);
    cr_expect_eq(isk_sprite_cache_get(c, ISK_SPRITE_DISC, 0, ISK_RED, &d), ISK_ERR_SIZE);
    cr_expect_eq(isk_sprite_cache_get(c, (isk_sprite_kind)9, 4, ISK_RED, &d), ISK_ERR_RANGE);
    cr_expect_eq(isk_sprite_cache_get(NULL, ISK_SPRITE_DISC, 4, ISK_RED, &d), ISK_ERR_NULL);
    /* Colour is part of the key. */
    isk_sprite_cache_clear(c);
    cr_expect_eq(isk_sprite_cache_count(c), 0);
    cr_assert_eq(isk_sprite_cache_get(c, ISK_SPRITE_DISC, 16, ISK_RED, &a), ISK_OK);
    cr_assert_eq(isk_sprite_cache_get(c, ISK_SPRITE_DISC, 16, ISK_BLUE, &b), ISK_OK);
    cr_expect_neq(a, b);
    cr_expect_eq(a->color.r, 255);
    cr_expect_eq(b->color.b, 255);
    /* Cached sprites draw byte-identically frame after frame. */
    isk_canvas f1 = canvas(40, 40, ISK_BLACK), f2 = canvas(40, 40, ISK_BLACK);
    isk_draw_sprite(&f1, a, 20.3, 19.6, ISK_BLEND_OVER);
    cr_assert_eq(isk_sprite_cache_get(c, ISK_SPRITE_DISC, 16, ISK_RED, &b), ISK_OK);
    isk_draw_sprite(&f2, b, 20.3, 19.6, ISK_BLEND_OVER);
    cr_expect(isk_canvas_equal(&f1, &f2));
    isk_canvas_free(&f1);
    isk_canvas_free(&f2);
    isk_sprite_cache_destroy(c);
    isk_sprite_cache_destroy(NULL);
}

/* The three kinds at several sizes, "over" (left half) and "add" (right
 * half) on a dark background, with an overlapping red/green/blue trio per
 * kind to show how the modes combine. */
Test(refimg, sprite_kinds)
{
    isk_canvas c = canvas(640, 240, isk_rgba(18, 18, 28, 255));
    isk_sprite_cache *cache;
    cr_assert_eq(isk_sprite_cache_create(&cache, 64), ISK_OK);
    const int sizes[6] = {3, 6, 11, 16, 32, 48};
    const isk_color trio[3] = {{255, 60, 40, 220}, {60, 230, 60, 220}, {60, 90, 255, 220}};
    for (int half = 0; half < 2; half++) {
        isk_blend mode = half ? ISK_BLEND_ADD : ISK_BLEND_OVER;
        double ox = half * 320.0;
        for (int k = 0; k < 3; k++) {
            double cy = 40.0 + 80.0 * k;
            double cx = ox + 8.0;
            for (int i = 0; i < 6; i++) {
                const isk_sprite *s;
                cr_assert_eq(isk_sprite_cache_get(cache, (isk_sprite_kind)k, sizes[i], isk_rgba(255, 170, 60, 255), &s),
                             ISK_OK);
                cx += sizes[i] / 2.0 + 4.0;
                isk_draw_sprite(&c, s, cx + 0.25 * i, cy, mode); /* varied sub-pixel phases */
                cx += sizes[i] / 2.0;
            }
            for (int t = 0; t < 3; t++) {
                const isk_sprite *s;
                cr_assert_eq(isk_sprite_cache_get(cache, (isk_sprite_kind)k, 56, trio[t], &s), ISK_OK);
                const double tx[3] = {230.0, 256.0, 243.0}, ty[3] = {-8.0, -8.0, 14.0};
                isk_draw_sprite(&c, s, ox + tx[t], cy + ty[t], mode);
            }
        }
    }
    cr_expect(refimg_check("sprite_kinds", &c));
    isk_sprite_cache_destroy(cache);
    isk_canvas_free(&c);
}

/* Many overlapping additive gradient sprites: a glowing flame-like cloud
 * that saturates towards white-yellow in the core. */
Test(refimg, sprite_additive_glow)
{
    isk_canvas c = canvas(256, 256, ISK_BLACK);
    isk_sprite_cache *cache;
    cr_assert_eq(isk_sprite_cache_create(&cache, 512), ISK_OK);
    isk_rng r;
    isk_rng_seed(&r, 2014);
    for (int i = 0; i < 600; i++) {
        double z0, z1;
        isk_rng_normal2(&r, &z0, &z1);
        double h = isk_rng_uniform(&r);                /* 0 = base, 1 = tip */
        double x = 128.0 + z0 * 22.0 * (1.0 - 0.8 * h);
        double y = 220.0 - h * 170.0 + z1 * 6.0;
        int size = 10 + (int)(36.0 * (1.0 - h)) + (int)isk_rng_below(&r, 8);
        isk_color col = isk_rgba(255, (uint8_t)(40 + 120 * (1.0 - h)), (uint8_t)(10 + 20 * (1.0 - h)),
                                 (uint8_t)(28 + 40 * (1.0 - h)));
        const isk_sprite *s;
        cr_assert_eq(isk_sprite_cache_get(cache, ISK_SPRITE_LINEAR, size, col, &s), ISK_OK);
        isk_draw_sprite(&c, s, x, y, ISK_BLEND_ADD);
    }
    cr_expect(refimg_check("sprite_additive_glow", &c));
    isk_sprite_cache_destroy(cache);
    isk_canvas_free(&c);
}
