/* SPDX-License-Identifier: MIT */
/* Trails (isk_stroke_trail, iskra/draw.h): the library against a brute-force
 * transcription of the rule (every pixel against every segment, no tiles,
 * no culling), bands of rows, the coverage area against exact polygon
 * areas, one shape (a trail doubling back paints nothing twice), the fade
 * along the length, thin widths, the guard box, bad input, and the
 * approximation at caps measured against a fine supersampling. */
#include <criterion/criterion.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/draw.h"
#include "iskra/rng.h"
#include "canvas_pair.h"
#include "raster/clip.h"
#include "raster/trail_rows.h"

static const isk_blend MODES[3] = {ISK_BLEND_REPLACE, ISK_BLEND_OVER, ISK_BLEND_ADD};

/* ---- the rule, pixel by pixel ----------------------------------------------------- */

typedef struct rseg {
    double ax, ay, ex, ey, il2, len;
    int ok;
} rseg;

static rseg ref_seg(const double *xy, int n, int k, const isk_canvas *c, int guarded)
{
    rseg s;
    int b = n > 1 ? k + 1 : k;
    double ax = xy[2 * k], ay = xy[2 * k + 1], bx = xy[2 * b], by = xy[2 * b + 1];
    s.ok = 1;
    if (guarded && !isk__clip_segment(&ax, &ay, &bx, &by, -ISK__GUARD, -ISK__GUARD, c->width + ISK__GUARD,
                                      c->height + ISK__GUARD)) {
        memset(&s, 0, sizeof s);
        return s;
    }
    s.ax = ax;
    s.ay = ay;
    s.ex = bx - ax;
    s.ey = by - ay;
    double l2 = s.ex * s.ex + s.ey * s.ey;
    s.il2 = l2 > 0 ? 1.0 / l2 : 0.0;
    s.len = sqrt(l2);
    return s;
}

static void ref_trail(isk_canvas *c, const double *xy, int n, double width, isk_color color, double fade,
                      isk_blend mode)
{
    if (!xy || n < 1 || !(width > 0 && width <= 4096) || isnan(fade) || (int)mode < 0 || mode >= ISK_BLEND_COUNT)
        return;
    int guarded = 0;
    for (int k = 0; k < n; k++) {
        if (!isfinite(xy[2 * k]) || !isfinite(xy[2 * k + 1]))
            return;
        if (!(xy[2 * k] >= -ISK__GUARD && xy[2 * k] <= c->width + ISK__GUARD && xy[2 * k + 1] >= -ISK__GUARD &&
              xy[2 * k + 1] <= c->height + ISK__GUARD))
            guarded = 1;
    }
    fade = fade < 0 ? 0 : fade > 1 ? 1 : fade;
    double hw = 0.5 * (width < 0.5 ? 0.5 : width), gain = width < 0.5 ? width / 0.5 : 1.0;
    double reach = hw + 0.70710678118654757, reach2 = reach * reach;
    int nseg = n > 1 ? n - 1 : 1;
    double total = 0;
    for (int k = 0; k < nseg; k++)
        total += ref_seg(xy, n, k, c, guarded).len;
    double rtotal = total > 0 ? 1.0 / total : 0.0;
    for (int j = 0; j < c->height; j++)
        for (int i = 0; i < c->width; i++) {
            double px = i + 0.5, py = j + 0.5, best = INFINITY, bt = 0, s0 = 0;
            int bk = -1;
            rseg bs;
            memset(&bs, 0, sizeof bs);
            for (int k = 0; k < nseg; k++) {
                rseg s = ref_seg(xy, n, k, c, guarded);
                if (s.ok) {
                    double t = ((px - s.ax) * s.ex + (py - s.ay) * s.ey) * s.il2;
                    t = t > 0 ? t : 0;
                    t = t < 1 ? t : 1;
                    double dx = px - (s.ax + t * s.ex), dy = py - (s.ay + t * s.ey), d2 = dx * dx + dy * dy;
                    if (d2 <= best && d2 <= reach2) { /* ties: the later segment */
                        best = d2;
                        bk = k;
                        bs = s;
                        bt = total > 0 ? (s0 + t * s.len) * rtotal : 1.0;
                    }
                }
                s0 += s.len;
            }
            if (bk < 0)
                continue;
            double t = ((px - bs.ax) * bs.ex + (py - bs.ay) * bs.ey) * bs.il2;
            t = t > 0 ? t : 0;
            t = t < 1 ? t : 1;
            double dx = px - (bs.ax + t * bs.ex), dy = py - (bs.ay + t * bs.ey);
            double area = isk__trail_pixel_area(dx, dy, hw, bs.ex, bs.ey, bs.len);
            double f = gain * (1.0 - fade * (1.0 - bt));
            uint8_t cov = isk__coverage(area * f);
            if (cov)
                isk_blend_pixel_cov(isk_canvas_at(c, i, j), color, cov, mode);
        }
}

/* ---- random inputs ------------------------------------------------------------------- */

enum { MAXP = 48 }; /* points of a random trail, at most */

static isk_color rnd_color(isk_rng *r)
{
    isk_color c; /* one draw a statement: an initializer list's order is unspecified */
    c.r = (uint8_t)isk_rng_below(r, 256);
    c.g = (uint8_t)isk_rng_below(r, 256);
    c.b = (uint8_t)isk_rng_below(r, 256);
    c.a = (uint8_t)(isk_rng_below(r, 3) == 0 ? 255 : isk_rng_below(r, 256));
    return c;
}

/* A random trail: a walk of small steps (a particle's positions), long
 * straight stretches, repeated points, self-crossings, an occasional wild
 * coordinate. */
static int rnd_trail(isk_rng *r, double *xy, int w, int h)
{
    int n = isk_rng_below(r, 8) == 0 ? 1 + (int)isk_rng_below(r, 3) : 2 + (int)isk_rng_below(r, MAXP - 1);
    double x = isk_rng_range(r, -6, w + 6), y = isk_rng_range(r, -6, h + 6);
    double step = isk_rng_below(r, 3) == 0 ? isk_rng_range(r, 2, 12) : isk_rng_range(r, 0.1, 1.5);
    double a = isk_rng_range(r, 0, 6.283), turn = isk_rng_range(r, -0.8, 0.8);
    for (int k = 0; k < n; k++) {
        xy[2 * k] = x;
        xy[2 * k + 1] = y;
        if (isk_rng_below(r, 6) == 0)
            continue; /* a repeated point */
        x += step * cos(a);
        y += step * sin(a);
        a += turn;
        if (isk_rng_below(r, 10) == 0)
            turn = -turn;
    }
    if (isk_rng_below(r, 12) == 0) {
        int k = (int)isk_rng_below(r, (uint32_t)(2 * n));
        const double wild[6] = {1e300, -1e300, 1e9, -3e7, DBL_MAX, 2e7};
        xy[k] = wild[isk_rng_below(r, 6)];
    }
    if (isk_rng_below(r, 40) == 0) {
        uint32_t at = isk_rng_below(r, (uint32_t)(2 * n));
        xy[at] = isk_rng_below(r, 2) ? NAN : INFINITY;
    }
    return n;
}

static double rnd_width(isk_rng *r)
{
    switch (isk_rng_below(r, 10)) {
    case 0: return isk_rng_range(r, 0.01, 0.5);
    case 1: return isk_rng_range(r, 4, 9);
    case 2: return (double)(1 + isk_rng_below(r, 4));
    case 3: return isk_rng_below(r, 2) ? 0.5 : 0.0;
    default: return isk_rng_range(r, 0.5, 3.5);
    }
}

static double rnd_fade(isk_rng *r)
{
    switch (isk_rng_below(r, 8)) {
    case 0: return 0.0;
    case 1: return 1.0;
    case 2: return isk_rng_range(r, -1, 2);
    default: return isk_rng_range(r, 0, 1);
    }
}

/* The trail drawn by the library on p's first canvas and by the rule on
 * its second, with a random fade, colour and mode: the bytes must agree. */
static void expect_the_rule(canvas_pair *p, isk_rng *r, const double *xy, int m, double width, int n, int k)
{
    double fade = rnd_fade(r);
    isk_color col = rnd_color(r);
    isk_blend mode = MODES[isk_rng_below(r, 3)];
    isk_stroke_trail(&p->c[0], xy, m, width, col, fade, mode);
    ref_trail(&p->c[1], xy, m, width, col, fade, mode);
    size_t at;
    cr_assert(canvas_pair_equal(p, &at),
              "case %d.%d: byte %zu differs (library %d, rule %d): %d points, width %.17g, fade %.17g, mode %d, "
              "canvas %dx%d",
              n, k, at, p->buf[0][at], p->buf[1][at], m, width, fade, mode, p->c[0].width, p->c[0].height);
}

Test(trail, equals_the_rule)
{
    isk_rng r;
    isk_rng_seed(&r, 21);
    double xy[2 * MAXP];
    for (int n = 0; n < 2500; n++) {
        int w = 1 + (int)isk_rng_below(&r, 40), h = 1 + (int)isk_rng_below(&r, 40);
        canvas_pair p = canvas_pair_make(&r, w, h);
        for (int k = 0; k < 2; k++) {
            int m = rnd_trail(&r, xy, w, h);
            expect_the_rule(&p, &r, xy, m, rnd_width(&r), n, k);
        }
        canvas_pair_free(&p);
    }
}

/* A long trail over a canvas wider than a tile (32 x 16 px): tiles change
 * nothing either. */
Test(trail, equals_the_rule_across_tiles)
{
    isk_rng r;
    isk_rng_seed(&r, 22);
    double xy[2 * MAXP];
    for (int n = 0; n < 150; n++) {
        int w = 40 + (int)isk_rng_below(&r, 60), h = 20 + (int)isk_rng_below(&r, 40);
        canvas_pair p = canvas_pair_make(&r, w, h);
        int m = 2 + (int)isk_rng_below(&r, MAXP - 1);
        for (int k = 0; k < m; k++) {
            xy[2 * k] = isk_rng_range(&r, -10, w + 10);
            xy[2 * k + 1] = isk_rng_range(&r, -10, h + 10);
        }
        expect_the_rule(&p, &r, xy, m, rnd_width(&r), n, 0);
        canvas_pair_free(&p);
    }
}

/* Wide trails (trail.c skips, tile by tile, the segments that cannot be
 * nearest to any of its pixels): long walks that turn and cross
 * themselves, 20 to 600 px wide, over canvases several tiles across. */
Test(trail, wide_trails_equal_the_rule)
{
    isk_rng r;
    isk_rng_seed(&r, 23);
    double xy[2 * MAXP];
    for (int n = 0; n < 60; n++) {
        int w = 40 + (int)isk_rng_below(&r, 60), h = 20 + (int)isk_rng_below(&r, 40);
        canvas_pair p = canvas_pair_make(&r, w, h);
        int m = 2 + (int)isk_rng_below(&r, MAXP - 1);
        double x = isk_rng_range(&r, -30, w + 30), y = isk_rng_range(&r, -30, h + 30);
        double a = isk_rng_range(&r, 0, 6.283), turn = isk_rng_range(&r, -0.9, 0.9), step = isk_rng_range(&r, 1, 9);
        for (int k = 0; k < m; k++) {
            xy[2 * k] = x;
            xy[2 * k + 1] = y;
            x += step * cos(a);
            y += step * sin(a);
            a += turn;
        }
        expect_the_rule(&p, &r, xy, m, isk_rng_range(&r, 20, 600), n, 0);
        canvas_pair_free(&p);
    }
}

Test(trail, bands_of_rows_equal_the_whole_call)
{
    isk_rng r;
    isk_rng_seed(&r, 23);
    double xy[2 * MAXP];
    for (int n = 0; n < 2000; n++) {
        int w = 1 + (int)isk_rng_below(&r, 48), h = 1 + (int)isk_rng_below(&r, 48);
        canvas_pair p = canvas_pair_make(&r, w, h);
        int cut = (int)isk_rng_below(&r, (uint32_t)h + 1);
        int cut2 = cut + (int)isk_rng_below(&r, (uint32_t)(h - cut) + 1);
        for (int k = 0; k < 3; k++) {
            int m = rnd_trail(&r, xy, w, h);
            double width = rnd_width(&r), fade = rnd_fade(&r);
            isk_color col = rnd_color(&r);
            isk_blend mode = MODES[isk_rng_below(&r, 3)];
            isk_stroke_trail(&p.c[0], xy, m, width, col, fade, mode);
            isk__stroke_trail_rows(&p.c[1], xy, m, width, col, fade, mode, cut2, h + 4);
            isk__stroke_trail_rows(&p.c[1], xy, m, width, col, fade, mode, -2, cut);
            isk__stroke_trail_rows(&p.c[1], xy, m, width, col, fade, mode, cut, cut2);
        }
        size_t at;
        cr_assert(canvas_pair_equal(&p, &at), "case %d: byte %zu differs (whole %d, bands %d)", n, at, p.buf[0][at],
                  p.buf[1][at]);
        canvas_pair_free(&p);
    }
}

/* The coverage area is exact: the unit square inside a straight band,
 * against the polygon clipping of clip.h, for any normal, offset and width. */
Test(trail, band_area_is_the_exact_area)
{
    isk_rng r;
    isk_rng_seed(&r, 24);
    for (int n = 0; n < 200000; n++) {
        double a = isk_rng_range(&r, 0, 6.283185307179586);
        if (n % 16 == 0)
            a = 1.5707963267948966 * (double)isk_rng_below(&r, 4); /* axis-aligned */
        double nx = cos(a), ny = sin(a), d = isk_rng_range(&r, 0, 4), w = isk_rng_range(&r, 0.05, 6);
        /* the band as a long rectangle, the pixel centred at the origin */
        double tx = -ny, ty = nx, L = 100;
        double c0 = -d; /* centre line offset along n from the pixel centre */
        isk__poly band;
        band.n = 4;
        double o[2] = {c0 - 0.5 * w, c0 + 0.5 * w};
        band.x[0] = o[0] * nx - L * tx; band.y[0] = o[0] * ny - L * ty;
        band.x[1] = o[0] * nx + L * tx; band.y[1] = o[0] * ny + L * ty;
        band.x[2] = o[1] * nx + L * tx; band.y[2] = o[1] * ny + L * ty;
        band.x[3] = o[1] * nx - L * tx; band.y[3] = o[1] * ny - L * ty;
        isk__poly_orient(&band);
        double exact = isk__pixel_area(-0.5, -0.5, &band, NULL, NULL);
        double got = isk__trail_band_area(d, nx, ny, w);
        cr_assert(fabs(got - exact) < 1e-9, "normal %.17g (%g, %g), d %g, w %g: %.17g, exact %.17g", a, nx, ny, d, w, got,
                  exact);
    }
}

/* Along a straight stretch the pixels get the exact area of the ribbon in
 * them: a 2-point trail, fade 0, white added onto black, every pixel whose
 * square lies within the segment's slab (away from the caps). */
Test(trail, straight_stretches_get_the_exact_area)
{
    isk_rng r;
    isk_rng_seed(&r, 25);
    for (int n = 0; n < 300; n++) {
        double a = isk_rng_range(&r, 0, 6.283185307179586), w = isk_rng_range(&r, 0.5, 5);
        double x0 = isk_rng_range(&r, 10, 20), y0 = isk_rng_range(&r, 10, 20), L = isk_rng_range(&r, 15, 30);
        double ux = cos(a), uy = sin(a), xy[4] = {x0, y0, x0 + L * ux, y0 + L * uy};
        isk_canvas c;
        cr_assert_eq(isk_canvas_init(&c, 64, 64), ISK_OK);
        isk_canvas_fill(&c, ISK_TRANSPARENT);
        isk_stroke_trail(&c, xy, 2, w, ISK_WHITE, 0.0, ISK_BLEND_ADD);
        isk__poly rect;
        rect.n = 4;
        double nx = -uy * 0.5 * w, ny = ux * 0.5 * w;
        rect.x[0] = xy[0] + nx; rect.y[0] = xy[1] + ny;
        rect.x[1] = xy[2] + nx; rect.y[1] = xy[3] + ny;
        rect.x[2] = xy[2] - nx; rect.y[2] = xy[3] - ny;
        rect.x[3] = xy[0] - nx; rect.y[3] = xy[1] - ny;
        isk__poly_orient(&rect);
        int checked = 0;
        for (int j = 0; j < 64; j++)
            for (int i = 0; i < 64; i++) {
                /* the square's projection on the direction, inside (0, L) */
                double lo = INFINITY, hi = -INFINITY;
                for (int q = 0; q < 4; q++) {
                    double t = (i + (q & 1) - xy[0]) * ux + (j + (q >> 1) - xy[1]) * uy;
                    lo = t < lo ? t : lo;
                    hi = t > hi ? t : hi;
                }
                if (!(lo > 0 && hi < L))
                    continue;
                uint8_t want = isk__coverage(isk__pixel_area(i, j, &rect, NULL, NULL));
                uint8_t got = isk_canvas_at(&c, i, j)[3];
                cr_assert_eq(got, want, "case %d: pixel (%d, %d): %d, exact area %d (angle %g, width %g)", n, i, j, got,
                             want, a, w);
                checked++;
            }
        cr_assert(checked > 20);
        isk_canvas_free(&c);
    }
}

/* One shape: a trail that doubles back over itself paints each pixel once,
 * so with no fade it is the single pass. */
Test(trail, doubling_back_paints_nothing_twice)
{
    isk_rng r;
    isk_rng_seed(&r, 26);
    for (int n = 0; n < 200; n++) {
        double a[2], b[2];
        a[0] = isk_rng_range(&r, 5, 35);
        a[1] = isk_rng_range(&r, 5, 35);
        b[0] = isk_rng_range(&r, 5, 35);
        b[1] = isk_rng_range(&r, 5, 35);
        double once[4] = {a[0], a[1], b[0], b[1]};
        double thrice[8] = {a[0], a[1], b[0], b[1], a[0], a[1], b[0], b[1]};
        double w = isk_rng_range(&r, 0.5, 4);
        isk_color col = rnd_color(&r);
        isk_blend mode = MODES[isk_rng_below(&r, 3)];
        isk_canvas c1, c2;
        cr_assert_eq(isk_canvas_init(&c1, 40, 40), ISK_OK);
        cr_assert_eq(isk_canvas_init(&c2, 40, 40), ISK_OK);
        isk_canvas_fill(&c1, isk_rgba(10, 20, 30, 255));
        isk_canvas_fill(&c2, isk_rgba(10, 20, 30, 255));
        isk_stroke_trail(&c1, once, 2, w, col, 0.0, mode);
        isk_stroke_trail(&c2, thrice, 4, w, col, 0.0, mode);
        cr_assert(isk_canvas_equal(&c1, &c2), "case %d", n);
        isk_canvas_free(&c1);
        isk_canvas_free(&c2);
    }
}

/* The fade: along a horizontal trail covering a row exactly, each pixel's
 * coverage is 255 (1 - fade (1 - t)), t its centre's share of the length
 * from the oldest point. */
Test(trail, alpha_falls_linearly_to_the_oldest_point)
{
    const double xy[6] = {10, 20.5, 30, 20.5, 50, 20.5}; /* oldest at x = 10 */
    const double fades[3] = {0.0, 0.5, 1.0};
    for (int k = 0; k < 3; k++) {
        isk_canvas c;
        cr_assert_eq(isk_canvas_init(&c, 60, 40), ISK_OK);
        isk_stroke_trail(&c, xy, 3, 1.0, ISK_WHITE, fades[k], ISK_BLEND_ADD);
        for (int i = 10; i < 50; i++) {
            double t = (i + 0.5 - 10) / 40.0;
            uint8_t want = isk__coverage(1.0 - fades[k] * (1.0 - t));
            cr_assert_eq(isk_canvas_at(&c, i, 20)[3], want, "fade %g, pixel %d", fades[k], i);
            cr_assert_eq(isk_canvas_at(&c, i, 19)[3], 0);
            cr_assert_eq(isk_canvas_at(&c, i, 21)[3], 0);
        }
        isk_canvas_free(&c);
    }
    /* the newest point at full alpha, the colour's alpha scaling it */
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 60, 40), ISK_OK);
    isk_stroke_trail(&c, xy, 3, 1.0, isk_rgba(255, 255, 255, 100), 1.0, ISK_BLEND_ADD);
    cr_assert_eq(isk_canvas_at(&c, 49, 20)[3], isk_div255(100u * isk__coverage(1.0 - (1.0 - 39.5 / 40.0))));
    isk_canvas_free(&c);
}

/* Widths below 0.5 px: drawn 0.5 px wide at alpha width / 0.5. */
Test(trail, thin_widths_fade_out)
{
    const double xy[4] = {4, 10.5, 36, 10.5};
    const double widths[4] = {0.5, 0.25, 0.1, 0.001};
    for (int k = 0; k < 4; k++) {
        isk_canvas c;
        cr_assert_eq(isk_canvas_init(&c, 40, 20), ISK_OK);
        isk_stroke_trail(&c, xy, 2, widths[k], ISK_WHITE, 0.0, ISK_BLEND_ADD);
        cr_assert_eq(isk_canvas_at(&c, 20, 10)[3], isk__coverage(0.5 * widths[k] / 0.5), "width %g", widths[k]);
        isk_canvas_free(&c);
    }
}

/* One point, or all points equal: a disc of diameter `width`, at full
 * alpha (t = 1). */
Test(trail, one_point_is_a_disc)
{
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, 20, 20), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 20, 20), ISK_OK);
    const double one[2] = {9.3, 10.1}, same[8] = {9.3, 10.1, 9.3, 10.1, 9.3, 10.1, 9.3, 10.1};
    isk_stroke_trail(&a, one, 1, 5.0, ISK_WHITE, 1.0, ISK_BLEND_ADD);
    isk_stroke_trail(&b, same, 4, 5.0, ISK_WHITE, 1.0, ISK_BLEND_ADD);
    cr_assert(isk_canvas_equal(&a, &b));
    long sum = 0;
    for (int y = 0; y < 20; y++)
        for (int x = 0; x < 20; x++) {
            uint8_t v = isk_canvas_at(&a, x, y)[3];
            double dx = x + 0.5 - 9.3, dy = y + 0.5 - 10.1;
            if (dx * dx + dy * dy < 1.79 * 1.79) /* the whole square inside */
                cr_assert_eq(v, 255, "(%d, %d) inside the disc", x, y);
            if (dx * dx + dy * dy > 3.3 * 3.3)
                cr_assert_eq(v, 0, "(%d, %d) outside the disc", x, y);
            sum += v;
        }
    double ratio = (double)sum / 255.0 / (3.14159265358979 * 2.5 * 2.5);
    cr_assert(ratio > 0.99 && ratio < 1.03, "a disc of width 5: %.3f of its area", ratio);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

/* The approximation at caps and joins, measured: short random trails
 * against 64x64 supersampling of the exact shape (points within width/2 of
 * the polyline).  The bounds are the ones the header states. */
static double exact_cov(const double *xy, int n, double w, int i, int j)
{
    int hits = 0;
    for (int t = 0; t < 64; t++)
        for (int s = 0; s < 64; s++) {
            double px = i + (s + 0.5) / 64, py = j + (t + 0.5) / 64;
            for (int k = 0; k + 1 < n || k == 0; k++) {
                int b = n > 1 ? k + 1 : k;
                double ex = xy[2 * b] - xy[2 * k], ey = xy[2 * b + 1] - xy[2 * k + 1], l2 = ex * ex + ey * ey;
                double u = l2 > 0 ? ((px - xy[2 * k]) * ex + (py - xy[2 * k + 1]) * ey) / l2 : 0;
                u = u < 0 ? 0 : u > 1 ? 1 : u;
                double dx = px - xy[2 * k] - u * ex, dy = py - xy[2 * k + 1] - u * ey;
                if (dx * dx + dy * dy <= 0.25 * w * w) {
                    hits++;
                    break;
                }
                if (n == 1)
                    break;
            }
        }
    return hits / 4096.0;
}

Test(trail, caps_and_joins_stay_close_to_the_exact_shape, .timeout = 120)
{
    isk_rng r;
    isk_rng_seed(&r, 27);
    const double widths[3] = {1.0, 2.0, 4.0};
    for (int wi = 0; wi < 3; wi++) {
        double w = widths[wi], sum_err = 0, sum_area = 0, sum_exact = 0, max_err = 0;
        for (int n = 0; n < 40; n++) {
            double xy[16];
            int m = 1 + (int)isk_rng_below(&r, 8);
            double x = isk_rng_range(&r, 8, 10), y = isk_rng_range(&r, 8, 10), a = isk_rng_range(&r, 0, 6.28);
            for (int k = 0; k < m; k++) {
                xy[2 * k] = x;
                xy[2 * k + 1] = y;
                x += 0.8 * cos(a);
                y += 0.8 * sin(a);
                a += isk_rng_range(&r, -1.2, 1.2);
            }
            isk_canvas c;
            cr_assert_eq(isk_canvas_init(&c, 20, 20), ISK_OK);
            isk_stroke_trail(&c, xy, m, w, ISK_WHITE, 0.0, ISK_BLEND_ADD);
            for (int j = 0; j < 20; j++)
                for (int i = 0; i < 20; i++) {
                    double got = isk_canvas_at(&c, i, j)[3] / 255.0, ex = exact_cov(xy, m, w, i, j);
                    double e = fabs(got - ex);
                    sum_err += e;
                    sum_area += got;
                    sum_exact += ex;
                    max_err = e > max_err ? e : max_err;
                }
            isk_canvas_free(&c);
        }
        cr_log_info("trail width %g: total area %.4f of the exact, mean error %.4f of its area, worst pixel %.3f", w,
                    sum_area / sum_exact, sum_err / sum_exact, max_err);
        const double max_ratio[3] = {1.15, 1.06, 1.03};
        cr_assert(sum_area / sum_exact < max_ratio[wi] && sum_area / sum_exact > 0.97, "width %g: %.4f", w,
                  sum_area / sum_exact);
    }
}

/* Far coordinates are cut to the guard box: a line from -1e300 to 1e300
 * across the canvas is the line across it. */
Test(trail, huge_coordinates_are_clipped_not_undefined)
{
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, 30, 20), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 30, 20), ISK_OK);
    const double far[4] = {-1e300, 7.3, 1e300, 7.3}, near[4] = {-200, 7.3, 230, 7.3};
    isk_stroke_trail(&a, far, 2, 2.5, ISK_WHITE, 0.0, ISK_BLEND_ADD);
    isk_stroke_trail(&b, near, 2, 2.5, ISK_WHITE, 0.0, ISK_BLEND_ADD);
    cr_assert(isk_canvas_equal(&a, &b));
    const double wild[8] = {DBL_MAX, -DBL_MAX, -DBL_MAX, DBL_MAX, 5, 5, 1e18, 3};
    isk_stroke_trail(&a, wild, 4, 3.0, ISK_WHITE, 0.7, ISK_BLEND_OVER); /* defined, whatever it draws */
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(trail, bad_input_draws_nothing)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 16, 16), ISK_OK);
    isk_canvas_fill(&c, isk_rgba(9, 8, 7, 6));
    const double ok[4] = {2, 2, 12, 12};
    const double nan_pt[4] = {2, 2, NAN, 12}, inf_pt[4] = {2, INFINITY, 12, 12};
    isk_stroke_trail(&c, nan_pt, 2, 2, ISK_WHITE, 0, ISK_BLEND_REPLACE);
    isk_stroke_trail(&c, inf_pt, 2, 2, ISK_WHITE, 0, ISK_BLEND_REPLACE);
    isk_stroke_trail(&c, NULL, 2, 2, ISK_WHITE, 0, ISK_BLEND_REPLACE);
    isk_stroke_trail(&c, ok, 0, 2, ISK_WHITE, 0, ISK_BLEND_REPLACE);
    isk_stroke_trail(&c, ok, -5, 2, ISK_WHITE, 0, ISK_BLEND_REPLACE);
    const double bad_w[5] = {0.0, -1.0, NAN, INFINITY, 4097.0};
    for (int k = 0; k < 5; k++)
        isk_stroke_trail(&c, ok, 2, bad_w[k], ISK_WHITE, 0, ISK_BLEND_REPLACE);
    isk_stroke_trail(&c, ok, 2, 2, ISK_WHITE, NAN, ISK_BLEND_REPLACE);
    isk_stroke_trail(&c, ok, 2, 2, ISK_WHITE, 0, (isk_blend)3);
    isk_stroke_trail(NULL, ok, 2, 2, ISK_WHITE, 0, ISK_BLEND_REPLACE);
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            isk_color g = isk_canvas_get(&c, x, y);
            cr_assert(g.r == 9 && g.g == 8 && g.b == 7 && g.a == 6, "pixel (%d, %d) was drawn", x, y);
        }
    /* fade outside [0, 1] is clamped */
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, 16, 16), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 16, 16), ISK_OK);
    isk_stroke_trail(&a, ok, 2, 2, ISK_WHITE, 7.0, ISK_BLEND_ADD);
    isk_stroke_trail(&b, ok, 2, 2, ISK_WHITE, 1.0, ISK_BLEND_ADD);
    cr_assert(isk_canvas_equal(&a, &b));
    isk_stroke_trail(&a, ok, 2, 2, ISK_WHITE, -3.0, ISK_BLEND_ADD);
    isk_stroke_trail(&b, ok, 2, 2, ISK_WHITE, 0.0, ISK_BLEND_ADD);
    cr_assert(isk_canvas_equal(&a, &b));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_canvas_free(&c);
}

/* The header's figures for lone dots (one point) of width 1, 2, 4 at
 * random sub-pixel positions: total coverage over the disc's area. */
Test(trail, lone_dots_area_as_documented)
{
    isk_rng r;
    isk_rng_seed(&r, 28);
    const double widths[3] = {1.0, 2.0, 4.0}, lo[3] = {1.19, 1.05, 1.01}, hi[3] = {1.41, 1.12, 1.03};
    for (int k = 0; k < 3; k++)
        for (int n = 0; n < 300; n++) {
            double xy[2];
            xy[0] = isk_rng_range(&r, 10, 11);
            xy[1] = isk_rng_range(&r, 10, 11);
            isk_canvas c;
            cr_assert_eq(isk_canvas_init(&c, 24, 24), ISK_OK);
            isk_stroke_trail(&c, xy, 1, widths[k], ISK_WHITE, 0.0, ISK_BLEND_ADD);
            long sum = 0;
            for (int y = 0; y < 24; y++)
                for (int x = 0; x < 24; x++)
                    sum += isk_canvas_at(&c, x, y)[3];
            double ratio = (double)sum / 255.0 / (3.14159265358979 * widths[k] * widths[k] / 4.0);
            cr_assert(ratio >= lo[k] && ratio <= hi[k], "width %g at (%g, %g): %.3f of the disc", widths[k], xy[0], xy[1],
                      ratio);
            isk_canvas_free(&c);
        }
}
