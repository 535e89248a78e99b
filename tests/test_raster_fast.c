/* SPDX-License-Identifier: MIT */
/* Byte identity of the rasterizer's fast paths (span kernels, tables, SWAR
 * and vector code, batched draws) with the per-pixel reference
 * implementation frozen in tests/raster_ref.h.
 *
 * Every test draws the same random input with both and compares every byte
 * of the canvas, including pixels outside the drawn area: random canvas
 * sizes (1x1 up), canvases that are views of a larger buffer (stride >
 * 4*width, sentinel bytes around), positions clipped at every edge, huge,
 * infinite and NaN coordinates, every blend mode, source alpha 0, 255 and in
 * between, destinations opaque, transparent and in between.  The small
 * arithmetic identities the kernels rely on are checked exhaustively. */
#include <criterion/criterion.h>

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "canvas_pair.h"
#include "iskra/rng.h"
#include "iskra/view.h"
#include "raster/blend_px.h"
#include "raster_ref.h"
#include "raster/circle_rows.h"
#include "raster/sprite_rows.h"
#include "view/world_batch.h"

static const isk_blend MODES[3] = {ISK_BLEND_REPLACE, ISK_BLEND_OVER, ISK_BLEND_ADD};

static uint8_t rnd_byte(isk_rng *r)
{
    switch (isk_rng_below(r, 6)) {
    case 0: return 0;
    case 1: return 255;
    default: return (uint8_t)isk_rng_below(r, 256);
    }
}

static isk_color rnd_color(isk_rng *r)
{
    isk_color c = {(uint8_t)isk_rng_below(r, 256), (uint8_t)isk_rng_below(r, 256), (uint8_t)isk_rng_below(r, 256),
                   rnd_byte(r)};
    return c;
}

/* Two identical random canvases with sentinel margins (tests/canvas_pair.h). */
typedef canvas_pair pair;
#define make_pair canvas_pair_make

static void check_pair(pair *p, const char *what, int n)
{
    size_t at;
    const int same = canvas_pair_equal(p, &at);
    cr_assert(same, "%s (case %d): byte %zu differs: fast %d, reference %d", what, n, at,
              at < p->bytes ? p->buf[0][at] : 0, at < p->bytes ? p->buf[1][at] : 0);
    canvas_pair_free(p);
}

static int rnd_size(isk_rng *r)
{
    return isk_rng_below(r, 5) == 0 ? 1 + (int)isk_rng_below(r, 3) : 1 + (int)isk_rng_below(r, 48);
}

/* A screen coordinate for a canvas dimension n: mostly on or near the
 * canvas (edges included), sometimes wild. */
static double rnd_coord(isk_rng *r, int n)
{
    switch (isk_rng_below(r, 24)) {
    case 0: return NAN;
    case 1: return isk_rng_below(r, 2) ? INFINITY : -INFINITY;
    case 2: return isk_rng_below(r, 2) ? 1e300 : -1e300;
    case 3: return isk_rng_below(r, 2) ? DBL_MAX : -DBL_MAX;
    case 4: return isk_rng_range(r, -1e9, 1e9);
    case 5: return (double)(int)isk_rng_below(r, (uint32_t)n + 4) - 2.0;            /* integers */
    case 6: return ((double)(int)isk_rng_below(r, 2u * (uint32_t)n + 8) - 4.0) / 2.0; /* halves */
    case 7: return (isk_rng_below(r, 2) ? -1.0 : (double)n) + isk_rng_range(r, -1e-9, 1e-9);
    case 8: return isk_rng_below(r, 2) ? -0.0 : 1e-300;
    case 9: return nextafter((double)(int)isk_rng_below(r, (uint32_t)n + 2), -INFINITY);
    default: return isk_rng_range(r, -3.0, n + 3.0);
    }
}

/* ---- arithmetic identities (exhaustive) ----------------------------------- */

Test(raster_fast, div255_lanes_exact_for_every_product)
{
    for (uint64_t x = 0; x <= 255u * 255u; x++) {
        uint64_t v = isk__div255_lanes(x | x << 16 | x << 32 | x << 48);
        uint64_t want = isk_div255((uint32_t)x);
        cr_assert_eq(v, want | want << 16 | want << 32 | want << 48, "x = %llu", (unsigned long long)x);
    }
}

Test(raster_fast, swar_saturating_add_every_pair)
{
    for (uint32_t a = 0; a < 256u; a++)
        for (uint32_t b = 0; b < 256u; b++) {
            uint32_t s = a + b > 255u ? 255u : a + b;
            /* each byte position, with other lanes near overflow too */
            uint32_t va = a | (255u - a) << 8 | b << 16 | a << 24;
            uint32_t vb = b | a << 8 | 255u << 16 | b << 24;
            uint32_t got = isk__sat_add_u8x4(va, vb);
            uint32_t s1 = (255u - a) + a > 255u ? 255u : 255u;
            uint32_t s2 = b + 255u > 255u ? 255u : b + 255u;
            cr_assert_eq(got, s | s1 << 8 | s2 << 16 | s << 24, "a=%u b=%u", a, b);
        }
}

/* Source-over onto an opaque pixel takes one path, without a test of the
 * source alpha, for every alpha (0 and 255 too): every alpha, colour and
 * destination channel value against the rule, in the inlined form and in
 * the library's (its SSE2 twin where the build has one). */
Test(raster_fast, over_opaque_destination_every_alpha)
{
    for (uint32_t sa = 0; sa < 256u; sa++)
        for (uint32_t c = 0; c < 256u; c++)
            for (uint32_t v = 0; v < 256u; v++) {
                const isk_color s = {(uint8_t)c, (uint8_t)(255u - c), (uint8_t)(c ^ 0x5Au), (uint8_t)sa};
                uint8_t a[4] = {(uint8_t)v, (uint8_t)(v ^ 0xA5u), (uint8_t)(255u - v), 255u}, b[4], f[4];
                memcpy(b, a, 4);
                memcpy(f, a, 4);
                isk__px(a, s, ISK_BLEND_OVER);
                isk__blend_px(f, s, ISK_BLEND_OVER);
                isk__rule_pixel(b, s, ISK_BLEND_OVER);
                if (memcmp(a, b, 4) != 0 || memcmp(f, b, 4) != 0)
                    cr_assert_fail("sa %u colour %u destination %u: %u %u %u %u (library %u %u %u %u), the rule "
                                   "%u %u %u %u",
                                   sa, c, v, a[0], a[1], a[2], a[3], f[0], f[1], f[2], f[3], b[0], b[1], b[2], b[3]);
            }
}

/* The one-pixel forms against the readable rule (src/raster/blend_rule.h):
 * the one a program's isk_draw_pixel inlines (iskra/blend_inline.h's
 * isk__px, plain C with its shortcuts: an opaque destination first, the
 * source alphas 0 and 255) and the library's (isk__blend_px: its SSE2
 * twin where the build has one), over and add, for every pair of source
 * and destination alpha, each with every colour channel value (three
 * relations between source and destination channel, one per channel). */
Test(raster_fast, one_pixel_rule_every_alpha_pair)
{
    for (uint32_t sa = 0; sa < 256u; sa++)
        for (uint32_t da = 0; da < 256u; da++)
            for (uint32_t c = 0; c < 256u; c++)
                for (int mi = 1; mi < 3; mi++) {
                    const isk_color s = {(uint8_t)c, (uint8_t)(255u - c), (uint8_t)(c * 37u + sa), (uint8_t)sa};
                    uint8_t a[4] = {(uint8_t)(c + da), (uint8_t)c, (uint8_t)(c * 11u ^ da), (uint8_t)da}, b[4], f[4];
                    memcpy(b, a, 4);
                    memcpy(f, a, 4);
                    isk__px(a, s, MODES[mi]);
                    isk__blend_px(f, s, MODES[mi]);
                    isk__rule_pixel(b, s, MODES[mi]);
                    if (memcmp(a, b, 4) != 0 || memcmp(f, b, 4) != 0)
                        cr_assert_fail("mode %d sa %u da %u colour %u: %u %u %u %u (library %u %u %u %u), the rule "
                                       "%u %u %u %u",
                                       mi, sa, da, c, a[0], a[1], a[2], a[3], f[0], f[1], f[2], f[3], b[0], b[1], b[2],
                                       b[3]);
                }
}

/* Every colour's table against the per-pixel rule, for every coverage. */
Test(raster_fast, coverage_table_equals_blend_pixel_cov)
{
    isk_rng r;
    isk_rng_seed(&r, 1);
    for (int n = 0; n < 400; n++) {
        isk_color col = rnd_color(&r);
        isk__cov_lut lut;
        isk__cov_lut_init(&lut, col);
        for (uint32_t cov = 0; cov < 256u; cov++)
            for (int mi = 0; mi < 3; mi++) {
                uint8_t a[4], b[4];
                for (int k = 0; k < 4; k++)
                    a[k] = b[k] = rnd_byte(&r);
                isk__px_lut(a, &lut, cov, MODES[mi]);
                isk__rule_pixel_cov(b, col, (uint8_t)cov, MODES[mi]);
                cr_assert(memcmp(a, b, 4) == 0, "colour %d cov %u mode %d", n, cov, mi);
                isk_blend_pixel_cov(a, col, (uint8_t)cov, MODES[mi]);
                isk__rule_pixel_cov(b, col, (uint8_t)cov, MODES[mi]);
                cr_assert(memcmp(a, b, 4) == 0, "isk_blend_pixel_cov: colour %d cov %u mode %d", n, cov, mi);
            }
    }
}

Test(raster_fast, dot_weights_equal_reference)
{
    isk_rng r;
    isk_rng_seed(&r, 2);
    for (int n = 0; n < 200000; n++) {
        double x = rnd_coord(&r, 64), y = rnd_coord(&r, 64);
        if (n % 4 == 0) { /* fractions with few bits: many ties */
            x = floor(x * 8) / 8;
            y = floor(y * 4) / 4;
        }
        uint8_t a[4], b[4];
        int ia, ib;
        cr_assert_eq(isk_dot_weights(x, y, a), ref_dot_weights(x, y, b));
        cr_assert(memcmp(a, b, 4) == 0, "isk_dot_weights(%a, %a)", x, y);
        int ax = 7, ay = 7, bx = 7, by = 7;
        ia = isk_dot_weights_browser(x, y, &ax, &ay, a);
        ib = ref_dot_weights_browser(x, y, &bx, &by, b);
        cr_assert_eq(ia, ib);
        cr_assert(memcmp(a, b, 4) == 0 && ax == bx && ay == by, "browser weights (%a, %a)", x, y);
    }
}

/* ---- primitives against the reference ---------------------------------- */

/* isk_draw_pixel is a macro over an inline copy (iskra/draw.h): inlined
 * into a loop, its colour's part is computed once and its mode chosen
 * once, so the loop's code is not the function's.  Both must give the
 * same bytes: the macro in loops of one colour and one mode (the shape a
 * compiler rearranges most) against the function through a pointer, on
 * every style of destination, with invalid modes and coordinates off the
 * canvas (and a NULL canvas, which both ignore). */
static void pixels_by_macro(isk_canvas *c, const int *xs, const int *ys, int n, isk_color col, isk_blend mode)
{
    for (int i = 0; i < n; i++)
        isk_draw_pixel(c, xs[i], ys[i], col, mode);
}

Test(raster_fast, pixel_macro_equals_function)
{
    void (*fn)(isk_canvas *, int, int, isk_color, isk_blend) = isk_draw_pixel; /* the function, by name */
    const isk_blend modes[5] = {ISK_BLEND_REPLACE, ISK_BLEND_OVER, ISK_BLEND_ADD, (isk_blend)3, (isk_blend)-1};
    isk_rng r;
    isk_rng_seed(&r, 11);
    int xs[64], ys[64];
    for (int n = 0; n < 400; n++) {
        int w = rnd_size(&r), h = rnd_size(&r);
        pair p = make_pair(&r, w, h);
        for (int k = 0; k < 6; k++) {
            const isk_color col = rnd_color(&r);
            const isk_blend mode = modes[isk_rng_below(&r, 5)];
            const int m = 1 + (int)isk_rng_below(&r, 64);
            for (int i = 0; i < m; i++) {
                xs[i] = (int)isk_rng_below(&r, (uint32_t)w + 4) - 2;
                ys[i] = isk_rng_below(&r, 9) ? (int)isk_rng_below(&r, (uint32_t)h + 4) - 2 : INT_MIN;
            }
            pixels_by_macro(&p.c[0], xs, ys, m, col, mode);
            for (int i = 0; i < m; i++)
                (k % 2 ? fn : (isk_draw_pixel))(&p.c[1], xs[i], ys[i], col, mode);
        }
        isk_draw_pixel(NULL, 0, 0, ISK_WHITE, ISK_BLEND_OVER);
        fn(NULL, 0, 0, ISK_WHITE, ISK_BLEND_OVER);
        check_pair(&p, "isk_draw_pixel macro / function", n);
    }
}

Test(raster_fast, pixel_and_rect_equal_reference)
{
    isk_rng r;
    isk_rng_seed(&r, 3);
    for (int n = 0; n < 600; n++) {
        int w = rnd_size(&r), h = rnd_size(&r);
        pair p = make_pair(&r, w, h);
        for (int k = 0; k < 30; k++) {
            isk_color col = rnd_color(&r);
            isk_blend mode = MODES[isk_rng_below(&r, 3)];
            int x = (int)isk_rng_below(&r, (uint32_t)w + 4) - 2, y = (int)isk_rng_below(&r, (uint32_t)h + 4) - 2;
            if (k % 2) {
                isk_draw_pixel(&p.c[0], x, y, col, mode);
                ref_draw_pixel(&p.c[1], x, y, col, mode);
            } else {
                int rw = (int)isk_rng_below(&r, 12) - 4, rh = (int)isk_rng_below(&r, 12) - 4;
                isk_fill_rect(&p.c[0], x, y, rw, rh, col, mode);
                for (int j = 0; j < abs(rh); j++) /* the rect rule, pixel by pixel */
                    for (int i = 0; i < abs(rw); i++)
                        ref_draw_pixel(&p.c[1], (rw < 0 ? x + rw : x) + i, (rh < 0 ? y + rh : y) + j, col, mode);
            }
        }
        check_pair(&p, "pixel/rect", n);
    }
}

Test(raster_fast, dot_equals_reference)
{
    isk_rng r;
    isk_rng_seed(&r, 4);
    for (int n = 0; n < 1500; n++) {
        int w = rnd_size(&r), h = rnd_size(&r);
        pair p = make_pair(&r, w, h);
        int browser = n % 2;
        for (int k = 0; k < 40; k++) {
            isk_color col = rnd_color(&r);
            isk_blend mode = MODES[isk_rng_below(&r, 3)];
            double x = rnd_coord(&r, w), y = rnd_coord(&r, h);
            if (browser) {
                isk_draw_dot_browser(&p.c[0], x, y, col, mode);
                ref_draw_dot_browser(&p.c[1], x, y, col, mode);
            } else {
                isk_draw_dot(&p.c[0], x, y, col, mode);
                ref_draw_dot(&p.c[1], x, y, col, mode);
            }
        }
        check_pair(&p, browser ? "browser dot" : "dot", n);
    }
}

/* isk_draw_dots / _browser / isk_draw_pixels against the loop of single
 * reference calls they replace, for both view kinds and batch sizes on both
 * sides of the table threshold and the block size. */
/* A random camera (odd cases) or window view of a w x h canvas. */
static void rnd_view(isk_rng *r, int camera, int w, int h, isk_view *v)
{
    if (camera)
        cr_assert_eq(isk_view_camera(v, w, h, isk_rng_range(r, 0.5, 20), isk_rng_range(r, -2, 2),
                                     isk_rng_range(r, -2, 2)),
                     ISK_OK);
    else
        cr_assert_eq(isk_view_window(v, w, h, -3, 3 + isk_rng_uniform(r), -2, 2), ISK_OK);
}

/* What a batch of `rule` (isk__batch_rule) must draw: the per-pixel
 * reference of each point in index order, at coordinates kept on the canvas
 * when `keep` (isk__keep_on_canvas). */
static void ref_draw_batch(isk_canvas *c, const isk_view *v, size_t m, const double *x, const double *y,
                           isk_color col, isk_blend mode, unsigned rule, int keep)
{
    for (size_t i = 0; i < m; i++) {
        double X, Y;
        isk_view_to_screen(v, x[i], y[i], &X, &Y);
        if (keep) {
            X = isk__keep_on_canvas(X, c->width);
            Y = isk__keep_on_canvas(Y, c->height);
        }
        if (rule == ISK__BATCH_DOT)
            ref_draw_dot(c, X, Y, col, mode);
        else if (rule == ISK__BATCH_DOT_BROWSER)
            ref_draw_dot_browser(c, X, Y, col, mode);
        else if (X >= 0 && Y >= 0 && X < c->width && Y < c->height)
            ref_draw_pixel(c, (int)X, (int)Y, col, mode);
    }
}

Test(raster_fast, batches_equal_loop_of_single_calls)
{
    isk_rng r;
    isk_rng_seed(&r, 5);
    static const size_t counts[] = {1, 2, 31, 32, 33, 63, 64, 65, 100, 1000};
    double *x = malloc(1000 * sizeof *x), *y = malloc(1000 * sizeof *y);
    cr_assert(x && y);
    for (int n = 0; n < 900; n++) {
        int w = rnd_size(&r), h = rnd_size(&r);
        pair p = make_pair(&r, w, h);
        isk_view v;
        rnd_view(&r, n % 2, w, h, &v);
        size_t m = counts[isk_rng_below(&r, sizeof counts / sizeof counts[0])];
        for (size_t i = 0; i < m; i++) {
            double X = rnd_coord(&r, w), Y = rnd_coord(&r, h);
            isk_view_to_world(&v, X, Y, &x[i], &y[i]);
            if (isk_rng_below(&r, 30) == 0) /* wild world values too */
                x[i] = rnd_coord(&r, w) * 1e10;
        }
        isk_color col = rnd_color(&r);
        isk_blend mode = MODES[isk_rng_below(&r, 3)];
        int rule = (int)isk_rng_below(&r, 3);
        if (rule == 0)
            isk_draw_dots(&p.c[0], &v, m, x, y, col, mode);
        else if (rule == 1)
            isk_draw_dots_browser(&p.c[0], &v, m, x, y, col, mode);
        else
            isk_draw_pixels(&p.c[0], &v, m, x, y, col, mode);
        ref_draw_batch(&p.c[1], &v, m, x, y, col, mode, (unsigned)rule, 0);
        check_pair(&p, rule == 0 ? "isk_draw_dots" : rule == 1 ? "isk_draw_dots_browser" : "isk_draw_pixels", n);
    }
    /* NULL and empty arguments draw nothing */
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 4, 4), ISK_OK);
    isk_view v;
    cr_assert_eq(isk_view_window(&v, 4, 4, 0, 4, 0, 4), ISK_OK);
    x[0] = y[0] = 1.5;
    isk_draw_dots(NULL, &v, 1, x, y, ISK_WHITE, ISK_BLEND_ADD);
    isk_draw_dots(&c, NULL, 1, x, y, ISK_WHITE, ISK_BLEND_ADD);
    isk_draw_dots(&c, &v, 1, NULL, y, ISK_WHITE, ISK_BLEND_ADD);
    isk_draw_pixels(&c, &v, 0, x, y, ISK_WHITE, ISK_BLEND_ADD);
    isk_draw_dots_browser(&c, &v, 1, x, NULL, ISK_WHITE, ISK_BLEND_ADD);
    for (int i = 0; i < 4 * 4 * 4; i++)
        cr_assert_eq(c.pixels[i], 0);
    isk_canvas_free(&c);
    free(x);
    free(y);
}

/* ISK__BATCH_KEEP_ON_CANVAS (reflect walls' particles on the far edge):
 * the batch equals single calls at coordinates moved by isk__keep_on_canvas,
 * with many points exactly on and just inside the far edges. */
Test(raster_fast, kept_batches_equal_single_calls_at_kept_coordinates)
{
    isk_rng r;
    isk_rng_seed(&r, 6);
    static const size_t counts[] = {1, 3, 4, 5, 31, 32, 33, 64, 100, 1000};
    double *x = malloc(1000 * sizeof *x), *y = malloc(1000 * sizeof *y);
    cr_assert(x && y);
    for (int n = 0; n < 600; n++) {
        int w = rnd_size(&r), h = rnd_size(&r);
        pair p = make_pair(&r, w, h);
        isk_view v;
        rnd_view(&r, n % 2, w, h, &v);
        size_t m = counts[isk_rng_below(&r, sizeof counts / sizeof counts[0])];
        for (size_t i = 0; i < m; i++) {
            double X = rnd_coord(&r, w), Y = rnd_coord(&r, h);
            switch (isk_rng_below(&r, 4)) {
            case 0: X = w; break;                                /* on the right edge */
            case 1: Y = h; break;                                /* on the bottom edge */
            case 2: Y = h - isk_rng_uniform(&r); break;          /* within the last row */
            default: break;
            }
            isk_view_to_world(&v, X, Y, &x[i], &y[i]);
        }
        isk_color col = rnd_color(&r);
        isk_blend mode = MODES[isk_rng_below(&r, 3)];
        unsigned rule = isk_rng_below(&r, 3);
        isk__draw_batch_rows(&p.c[0], &v, m, x, y, col, mode, rule | ISK__BATCH_KEEP_ON_CANVAS, 0, h);
        ref_draw_batch(&p.c[1], &v, m, x, y, col, mode, rule, 1);
        check_pair(&p, "kept batch", n);
    }
    free(x);
    free(y);
}

/* A batch cut into bands of rows (isk__draw_batch_rows: the renderer's
 * threads each draw one) gives the bytes of the whole batch, whatever the
 * cuts and the order the bands are drawn in. */
Test(raster_fast, bands_of_rows_equal_the_whole_batch)
{
    isk_rng r;
    isk_rng_seed(&r, 11);
    double *x = malloc(700 * sizeof *x), *y = malloc(700 * sizeof *y);
    cr_assert(x && y);
    for (int n = 0; n < 600; n++) {
        int w = rnd_size(&r), h = rnd_size(&r);
        pair p = make_pair(&r, w, h);
        isk_view v;
        rnd_view(&r, n % 2, w, h, &v);
        size_t m = 1 + isk_rng_below(&r, 700);
        for (size_t i = 0; i < m; i++) {
            double X = rnd_coord(&r, w), Y = rnd_coord(&r, h);
            isk_view_to_world(&v, X, Y, &x[i], &y[i]);
        }
        isk_color col = rnd_color(&r);
        isk_blend mode = MODES[isk_rng_below(&r, 3)];
        /* every rule, kept on the canvas or not (the banded pixels select
         * their rows with keep applied, the whole batch without a select) */
        const unsigned rule = (unsigned)isk_rng_below(&r, 3) | (isk_rng_below(&r, 2) ? ISK__BATCH_KEEP_ON_CANVAS : 0u);
        isk__draw_batch_rows(&p.c[0], &v, m, x, y, col, mode, rule, 0, h);
        /* up to 6 cuts (repeats make empty bands), bands drawn last to first */
        int cut[8], nc = 0;
        cut[nc++] = 0;
        for (int k = (int)isk_rng_below(&r, 7); k > 0; k--)
            cut[nc++] = (int)isk_rng_below(&r, (uint32_t)h + 1);
        cut[nc++] = h;
        for (int i = 1; i < nc; i++) /* sort */
            for (int j = i; j > 0 && cut[j - 1] > cut[j]; j--) {
                int t = cut[j];
                cut[j] = cut[j - 1];
                cut[j - 1] = t;
            }
        for (int b = nc - 2; b >= 0; b--)
            isk__draw_batch_rows(&p.c[1], &v, m, x, y, col, mode, rule, cut[b], cut[b + 1]);
        check_pair(&p, "bands", n);
    }
    free(x);
    free(y);
}

/* nb in [1, max] and the cuts 0 = cut[0] <= cut[1] <= ... <= cut[nb] = n,
 * the inner ones at random (repeats make empty bands); returns nb. */
static int random_cuts(isk_rng *r, int n, int max, int *cut)
{
    const int nb = 1 + (int)isk_rng_below(r, (uint32_t)max);
    cut[0] = 0;
    cut[nb] = n;
    for (int k = 1; k < nb; k++)
        cut[k] = (int)isk_rng_below(r, (uint32_t)n + 1);
    for (int i = 1; i < nb; i++)
        for (int j = i; j > 1 && cut[j - 1] > cut[j]; j--) {
            int t = cut[j];
            cut[j] = cut[j - 1];
            cut[j - 1] = t;
        }
    for (int i = 1; i <= nb; i++)
        cr_assert_leq(cut[i - 1], cut[i]);
    return nb;
}

/* One random batch for the threaded draws' tests: a canvas pair, a view,
 * m points (a third of them on or just inside the far edges when
 * `far_edges`), a colour, mode and rule; the whole batch drawn on p.c[0]. */
typedef struct batch {
    int w, h;
    pair p;
    isk_view v;
    size_t m;
    isk_color col;
    isk_blend mode;
    unsigned rule;
} batch;

static void random_batch(isk_rng *r, int n, size_t maxn, int far_edges, double *x, double *y, batch *b)
{
    b->w = rnd_size(r);
    b->h = rnd_size(r);
    b->p = make_pair(r, b->w, b->h);
    rnd_view(r, n % 2, b->w, b->h, &b->v);
    b->m = 1 + isk_rng_below(r, (uint32_t)maxn);
    for (size_t i = 0; i < b->m; i++) {
        double X = rnd_coord(r, b->w), Y = rnd_coord(r, b->h);
        if (far_edges && isk_rng_below(r, 3) == 0)
            Y = b->h - (isk_rng_below(r, 2) ? 0.0 : isk_rng_range(r, 0.0, 1.0));
        isk_view_to_world(&b->v, X, Y, &x[i], &y[i]);
    }
    b->col = rnd_color(r);
    b->mode = MODES[isk_rng_below(r, 3)];
    b->rule = isk_rng_below(r, 3) | (isk_rng_below(r, 2) ? ISK__BATCH_KEEP_ON_CANVAS : 0u);
    isk__draw_batch_rows(&b->p.c[0], &b->v, b->m, x, y, b->col, b->mode, b->rule, 0, b->h);
}

/* A threaded draw's sorting (isk__batch_bin): each band drawing only the
 * points binned to it, the store split in shares binned one after the other,
 * gives the bytes of the whole batch, for every rule, with and without
 * keeping points on the canvas, on views that put points on, near and far
 * off the canvas (and NaN: rnd_coord). */
Test(raster_fast, binned_bands_equal_the_whole_batch)
{
    isk_rng r;
    isk_rng_seed(&r, 12);
    enum { MAXN = 700, MAXB = 8 };
    double *x = malloc(MAXN * sizeof *x), *y = malloc(MAXN * sizeof *y);
    uint16_t *code = malloc(MAXN * sizeof *code);
    uint32_t *idx = malloc(MAXN * 5 * sizeof *idx); /* a point reaches at most 5 rows */
    cr_assert(x && y && code && idx);
    for (int n = 0; n < 600; n++) {
        batch bt;
        random_batch(&r, n, MAXN, 0, x, y, &bt);
        const int h = bt.h;
        const size_t m = bt.m;
        int cut[MAXB + 1];
        const int nb = random_cuts(&r, h, MAXB, cut);
        uint8_t *band_of_row = malloc((size_t)h);
        cr_assert(band_of_row);
        for (int b = 0; b < nb; b++)
            for (int row = cut[b]; row < cut[b + 1]; row++)
                band_of_row[row] = (uint8_t)b;
        /* two shares, binned apart; band b's list: share 0's, then share 1's */
        size_t count[2][MAXB] = {{0}}, split = isk_rng_below(&r, (uint32_t)m + 1);
        isk__batch_bin(&bt.v, h, y, 0, split, ISK__DOT_REACH, band_of_row, code, count[0]);
        isk__batch_bin(&bt.v, h, y, split, m, ISK__DOT_REACH, band_of_row, code, count[1]);
        size_t pos[2][MAXB], start[MAXB + 1], total = 0;
        for (int b = 0; b < nb; b++) {
            start[b] = total;
            for (int t = 0; t < 2; t++) {
                pos[t][b] = total;
                total += count[t][b];
            }
        }
        start[nb] = total;
        cr_assert_leq(total, (size_t)MAXN * 5);
        for (size_t i = 0; i < m; i++) {
            const int t = i >= split;
            if (code[i] != ISK__BIN_NONE)
                for (unsigned b = code[i] & 255u; b <= (unsigned)code[i] >> 8; b++)
                    idx[pos[t][b]++] = (uint32_t)i;
        }
        for (int b = nb - 1; b >= 0; b--) /* last to first: bands are independent */
            isk__draw_batch_list_rows(&bt.p.c[1], &bt.v, idx + start[b], start[b + 1] - start[b], x, y, bt.col,
                                      bt.mode, bt.rule, cut[b], cut[b + 1]);
        free(band_of_row);
        check_pair(&bt.p, "binned bands", n);
    }
    free(x);
    free(y);
    free(code);
    free(idx);
}

/* A threaded draw's tiles (isk__draw_batch_tile): the canvas cut into
 * rows and columns at random, each tile drawn on its own in any order,
 * gives the bytes of the whole batch, for every rule, with and without
 * keeping points on the canvas (many of them on its far edges, as a scene
 * settled on its floor has them). */
Test(raster_fast, tiles_equal_the_whole_batch)
{
    isk_rng r;
    isk_rng_seed(&r, 13);
    enum { MAXN = 500, MAXC = 5 };
    double *x = malloc(MAXN * sizeof *x), *y = malloc(MAXN * sizeof *y);
    cr_assert(x && y);
    for (int n = 0; n < 600; n++) {
        batch bt;
        random_batch(&r, n, MAXN, 1, x, y, &bt);
        int rows[MAXC + 1], cols[MAXC + 1];
        const int nr = random_cuts(&r, bt.h, MAXC, rows), nc = random_cuts(&r, bt.w, MAXC, cols);
        for (int t = nr * nc - 1; t >= 0; t--) /* last to first: tiles are independent */
            isk__draw_batch_tile(&bt.p.c[1], &bt.v, bt.m, x, y, bt.col, bt.mode, bt.rule, rows[t / nc],
                                 rows[t / nc + 1], cols[t % nc], cols[t % nc + 1]);
        check_pair(&bt.p, "tiles", n);
    }
    free(x);
    free(y);
}

static double rnd_radius(isk_rng *r)
{
    switch (isk_rng_below(r, 16)) {
    case 0: return NAN;
    case 1: return INFINITY;
    case 2: return -isk_rng_range(r, 0, 5);
    case 3: return 0.0;
    case 4: return isk_rng_range(r, 1e-6, 0.2);
    case 5: return isk_rng_range(r, 65536.0, 2e5); /* the tangent rule */
    case 6: return 1.0;
    case 7: return 3.0;
    case 8: return 8.0;
    case 9: return (double)(int)isk_rng_below(r, 12) / 2.0;
    default: return isk_rng_range(r, 0.2, 30);
    }
}

Test(raster_fast, aa_disc_equals_reference)
{
    isk_rng r;
    isk_rng_seed(&r, 6);
    for (int n = 0; n < 1200; n++) {
        int w = rnd_size(&r), h = rnd_size(&r);
        pair p = make_pair(&r, w, h);
        for (int k = 0; k < 6; k++) {
            isk_color col = rnd_color(&r);
            isk_blend mode = MODES[isk_rng_below(&r, 3)];
            double cx = rnd_coord(&r, w), cy = rnd_coord(&r, h), rad = rnd_radius(&r);
            if (rad > 60000 && isk_rng_below(&r, 2)) /* a huge disc whose edge crosses the canvas */
                cx = -rad + isk_rng_range(&r, 0, w);
            isk_fill_circle_aa(&p.c[0], cx, cy, rad, col, mode);
            ref_fill_circle_aa(&p.c[1], cx, cy, rad, col, mode);
        }
        check_pair(&p, "isk_fill_circle_aa", n);
    }
}

Test(raster_fast, sprites_equal_reference)
{
    isk_rng r;
    isk_rng_seed(&r, 7);
    for (int n = 0; n < 1200; n++) {
        int w = rnd_size(&r), h = rnd_size(&r);
        pair p = make_pair(&r, w, h);
        isk_sprite s;
        int size = isk_rng_below(&r, 8) == 0 ? 1 + (int)isk_rng_below(&r, 256) : 1 + (int)isk_rng_below(&r, 40);
        cr_assert_eq(isk_sprite_init(&s, (isk_sprite_kind)isk_rng_below(&r, 3), size, rnd_color(&r)), ISK_OK);
        for (int k = 0; k < 8; k++) {
            isk_blend mode = MODES[isk_rng_below(&r, 3)];
            double cx = rnd_coord(&r, w), cy = rnd_coord(&r, h);
            if (isk_rng_below(&r, 3) == 0) { /* far from the canvas but overlapping it */
                cx = isk_rng_range(&r, -size, w + size);
                cy = isk_rng_range(&r, -size, h + size);
            }
            if (k % 2) {
                isk_color col = rnd_color(&r);
                isk_draw_sprite_tinted(&p.c[0], &s, cx, cy, col, mode);
                ref_draw_sprite_tinted(&p.c[1], &s, cx, cy, col, mode);
            } else {
                isk_draw_sprite(&p.c[0], &s, cx, cy, mode);
                ref_draw_sprite(&p.c[1], &s, cx, cy, mode);
            }
        }
        isk_sprite_free(&s);
        check_pair(&p, "sprite", n);
    }
}

/* Discs cut into bands of rows (isk__fill_circle_aa_rows) give the bytes
 * of the whole disc in every mode: small and big row walks, the per-pixel
 * walk (wider than its row cache) and the tangent rule, the bands drawn
 * out of order. */
Test(raster_fast, disc_bands_equal_the_whole_disc)
{
    isk_rng r;
    isk_rng_seed(&r, 17);
    for (int n = 0; n < 800; n++) {
        int w = n % 8 == 0 ? 600 : rnd_size(&r), h = rnd_size(&r); /* 600: room for the per-pixel walk */
        pair p = make_pair(&r, w, h);
        int cut = (int)isk_rng_below(&r, (uint32_t)h + 1), cut2 = cut + (int)isk_rng_below(&r, (uint32_t)(h - cut) + 1);
        for (int k = 0; k < 6; k++) {
            isk_color col = rnd_color(&r);
            isk_blend mode = MODES[isk_rng_below(&r, 3)];
            double cx = rnd_coord(&r, w), cy = rnd_coord(&r, h), rad = rnd_radius(&r);
            if (k == 5) /* wider than the row cache: the per-pixel walk where the canvas is that wide */
                rad = isk_rng_range(&r, 256.0, 400.0);
            if (rad > 60000 && isk_rng_below(&r, 2)) /* a huge disc whose edge crosses the canvas */
                cx = -rad + isk_rng_range(&r, 0, w);
            isk_fill_circle_aa(&p.c[0], cx, cy, rad, col, mode);
            isk__fill_circle_aa_rows(&p.c[1], cx, cy, rad, col, mode, cut2, h);
            isk__fill_circle_aa_rows(&p.c[1], cx, cy, rad, col, mode, 0, cut);
            isk__fill_circle_aa_rows(&p.c[1], cx, cy, rad, col, mode, cut, cut2);
        }
        check_pair(&p, "disc bands", n);
    }
}

/* Sprites cut into bands of rows (isk__draw_sprite_rows) give the bytes of
 * the whole sprite, tinted or not, in every mode. */
Test(raster_fast, sprite_bands_equal_the_whole_sprite)
{
    isk_rng r;
    isk_rng_seed(&r, 13);
    for (int n = 0; n < 800; n++) {
        int w = rnd_size(&r), h = rnd_size(&r);
        pair p = make_pair(&r, w, h);
        isk_sprite s;
        int size = 1 + (int)isk_rng_below(&r, 48);
        cr_assert_eq(isk_sprite_init(&s, (isk_sprite_kind)isk_rng_below(&r, 3), size, rnd_color(&r)), ISK_OK);
        int cut = (int)isk_rng_below(&r, (uint32_t)h + 1), cut2 = cut + (int)isk_rng_below(&r, (uint32_t)(h - cut) + 1);
        for (int k = 0; k < 6; k++) {
            isk_blend mode = MODES[isk_rng_below(&r, 3)];
            double cx = isk_rng_range(&r, -size, w + size), cy = isk_rng_range(&r, -size, h + size);
            isk_color col = rnd_color(&r);
            const isk_color *tint = k % 2 ? &col : NULL;
            if (tint)
                isk_draw_sprite_tinted(&p.c[0], &s, cx, cy, col, mode);
            else
                isk_draw_sprite(&p.c[0], &s, cx, cy, mode);
            isk__draw_sprite_rows(&p.c[1], &s, cx, cy, tint, mode, cut2, h);
            isk__draw_sprite_rows(&p.c[1], &s, cx, cy, tint, mode, 0, cut);
            isk__draw_sprite_rows(&p.c[1], &s, cx, cy, tint, mode, cut, cut2);
        }
        isk_sprite_free(&s);
        check_pair(&p, "sprite bands", n);
    }
}
