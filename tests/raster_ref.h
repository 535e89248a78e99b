/* SPDX-License-Identifier: MIT */
/* tests/raster_ref.h — the rasterizer's per-pixel reference implementation,
 * frozen as it was before the span kernels (one blend call and a
 * blend-mode switch per pixel).  The blend of one pixel is the library's
 * readable rule (src/raster/blend_rule.h: isk__rule_pixel,
 * isk__rule_pixel_cov), the definition every fast form is tested against.
 * The fast paths in src/raster must give exactly these bytes:
 * tests/test_raster_fast.c draws random input with both and compares
 * canvases.  Header-only (static), included by the raster tests only.
 * Do not "optimize" this file: its point is to stay the old code. */
#ifndef ISKRA_TESTS_RASTER_REF_H
#define ISKRA_TESTS_RASTER_REF_H

#include <math.h>
#include <stdint.h>

#include "iskra/draw.h"
#include "iskra/sprite.h"
#include "raster/blend_rule.h"
#include "raster/clip.h"

static inline void ref_weights_frac(double fx, double fy, uint8_t w[4])
{
    if (fx == 0.0 && fy == 0.0) { /* integer position: one whole pixel */
        w[0] = 255; w[1] = 0; w[2] = 0; w[3] = 0;
        return;
    }
    double gx = 1.0 - fx, gy = 1.0 - fy;
    double a[4] = {255.0 * gx * gy, 255.0 * fx * gy, 255.0 * gx * fy, 255.0 * fx * fy};
    double frac[4];
    int sum = 0;
    for (int k = 0; k < 4; k++) {
        int f = (int)a[k]; /* a[k] in [0, 255]: truncation is floor */
        w[k] = (uint8_t)f;
        frac[k] = a[k] - f;
        sum += f;
    }
    for (int left = 255 - sum; left > 0; left--) {
        int best = -1;
        for (int k = 0; k < 4; k++)
            if (frac[k] >= 0.0 && (best < 0 || frac[k] > frac[best]))
                best = k;
        if (best < 0)
            break;
        w[best]++;
        frac[best] = -1.0; /* each pixel gets at most one extra unit */
    }
}

static inline int ref_dot_weights(double x, double y, uint8_t w[4])
{
    if (!isk__finite2(x, y)) {
        w[0] = w[1] = w[2] = w[3] = 0;
        return 0;
    }
    ref_weights_frac(x - floor(x), y - floor(y), w);
    return 1;
}

static inline void ref_blend_2x2(isk_canvas *c, int ix, int iy, const uint8_t w[4], isk_color color, isk_blend mode)
{
    int left = ix >= 0 && ix < c->width, right = ix + 1 >= 0 && ix + 1 < c->width;
    int top = iy >= 0 && iy < c->height, bottom = iy + 1 >= 0 && iy + 1 < c->height;
    if (top) {
        uint8_t *p = c->pixels + (size_t)iy * c->stride;
        if (left) isk__rule_pixel_cov(p + (size_t)ix * 4u, color, w[0], mode);
        if (right) isk__rule_pixel_cov(p + (size_t)(ix + 1) * 4u, color, w[1], mode);
    }
    if (bottom) {
        uint8_t *p = c->pixels + (size_t)(iy + 1) * c->stride;
        if (left) isk__rule_pixel_cov(p + (size_t)ix * 4u, color, w[2], mode);
        if (right) isk__rule_pixel_cov(p + (size_t)(ix + 1) * 4u, color, w[3], mode);
    }
}

static inline void ref_draw_dot(isk_canvas *c, double x, double y, isk_color color, isk_blend mode)
{
    /* The square [x, x+1) x [y, y+1) touches the canvas only for x in
     * (-1, width) and y in (-1, height); the test also rejects NaN and keeps
     * the conversions below defined. */
    if (!c || !c->pixels || !(x > -1.0 && x < c->width && y > -1.0 && y < c->height))
        return;
    double fx0 = floor(x), fy0 = floor(y);
    uint8_t w[4];
    ref_weights_frac(x - fx0, y - fy0, w);
    ref_blend_2x2(c, (int)fx0, (int)fy0, w, color, mode);
}

/* The browser's rule (Skia's anti-aliased rectangle fill, which Chrome's
 * canvas used for the thesis's fillRect(x, y, 1, 1)): the edges go through
 * float and 16.16 fixed point and are rounded to 1/256 px; a partly covered
 * row gets 256 - frac(top) (top) or frac(bottom) (bottom) of 256, a whole row
 * 255; columns likewise with 256 for a whole column; a pixel's coverage is
 * row * column >> 8 (truncated), or the row alone when the column is whole.
 * Slivers thinner than 1/256 px therefore contribute nothing, and a dot's
 * four weights may sum to a little less than 255. */
static inline int ref_dot_weights_browser(double x, double y, int *ix, int *iy, uint8_t w[4])
{
    w[0] = w[1] = w[2] = w[3] = 0;
    /* |x| < 16400 keeps x * 65536 inside int (and rejects NaN). */
    if (!(x > -16400.0 && x < 16400.0 && y > -16400.0 && y < 16400.0))
        return 0;
    float xf = (float)x, yf = (float)y;
    int L = (((int)(xf * 65536.0f)) + 0x80) >> 8;
    int T = (((int)(yf * 65536.0f)) + 0x80) >> 8;
    int l = L & 255, t = T & 255;
    int col[2] = {l ? 256 - l : 256, l};
    int row[2] = {t ? 256 - t : 255, t};
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++)
            w[2 * j + i] = (uint8_t)(col[i] == 256 ? row[j] : (row[j] * col[i]) >> 8);
    *ix = L >> 8; /* arithmetic shift: floor for negative values too */
    *iy = T >> 8;
    return 1;
}

static inline void ref_draw_dot_browser(isk_canvas *c, double x, double y, isk_color color, isk_blend mode)
{
    if (!c || !c->pixels || !(x > -2.0 && x < c->width + 1.0 && y > -2.0 && y < c->height + 1.0))
        return;
    int ix, iy;
    uint8_t w[4];
    if (ref_dot_weights_browser(x, y, &ix, &iy, w))
        ref_blend_2x2(c, ix, iy, w, color, mode);
}
#define REF_BIG_R_ALIASED 67108864.0 /* 2^26: d^2 and r^2 stay exact enough below */
#define REF_BIG_R_AA 65536.0         /* 2^16, see above */

static inline int ref_disc_misses_rect(double cx, double cy, double r, double x0, double y0,
                            double x1, double y1)
{
    double dx = cx < x0 ? x0 - cx : (cx > x1 ? cx - x1 : 0.0);
    double dy = cy < y0 ? y0 - cy : (cy > y1 ? cy - y1 : 0.0);
    return dx >= r || dy >= r;
}

static inline void ref_fill_circle(isk_canvas *c, double cx, double cy, double r, isk_color color, isk_blend mode)
{
    if (!isk__canvas_ok(c) || !isk__finite2(cx, cy) || !isfinite(r) || !(r > 0.0))
        return;
    /* No pixel centre can be strictly inside: nothing to do.  This also
     * bounds |cx|, |cy| by r + canvas size for the arithmetic below. */
    if (ref_disc_misses_rect(cx, cy, r, 0.5, 0.5, c->width - 0.5, c->height - 0.5))
        return;
    int big = r > REF_BIG_R_ALIASED;
    double r2 = r * r;
    int j0 = isk__floor_clamp(cy - r - 0.5, -1, c->height);
    int j1 = isk__floor_clamp(cy + r - 0.5, -1, c->height) + 1;
    if (j0 < 0) j0 = 0;
    if (j1 > c->height - 1) j1 = c->height - 1;
    for (int j = j0; j <= j1; j++) {
        double dy = (j + 0.5) - cy;
        double ady = fabs(dy);
        if (!(ady < r))
            continue;
        double hw = big ? sqrt((r - ady) * (r + ady)) : sqrt(r2 - dy * dy);
        int i0 = isk__floor_clamp(cx - hw - 0.5, -2, c->width) - 1;
        int i1 = isk__floor_clamp(cx + hw - 0.5, -2, c->width) + 1;
        if (i0 < 0) i0 = 0;
        if (i1 > c->width - 1) i1 = c->width - 1;
        for (int i = i0; i <= i1; i++) {
            double dx = (i + 0.5) - cx;
            int in = big ? hypot(dx, dy) < r : dx * dx + dy * dy < r2;
            if (in)
                isk__rule_pixel(isk_canvas_at(c, i, j), color, mode);
        }
    }
}

/* Integral of h over [0, x], |x| <= r. */
static inline double ref_h_integral(double x, double r)
{
    double q = r * r - x * x;
    return 0.5 * (x * sqrt(q > 0.0 ? q : 0.0) + r * r * asin(x / r));
}

/* Antiderivative of min(cl, h(x)) (cl >= 0), for x in [-r, r]. */
static inline double ref_min_antideriv(double x, double cl, double r)
{
    double w = cl < r ? sqrt((r - cl) * (r + cl)) : 0.0;
    if (x > w)
        return cl * w + ref_h_integral(x, r) - ref_h_integral(w, r);
    if (x < -w)
        return -cl * w + ref_h_integral(x, r) + ref_h_integral(w, r);
    return cl * x;
}

static inline double ref_strip_integral(double a, double b, double y, double r)
{
    a = isk__clampd(a, -r, r);
    b = isk__clampd(b, -r, r);
    double cl = fabs(y);
    double v = ref_min_antideriv(b, cl, r) - ref_min_antideriv(a, cl, r);
    return y < 0.0 ? -v : v;
}

/* Exact area of the disc of radius r at the origin ∩ [x0,x1]x[y0,y1]. */
static inline double ref_disc_rect_area(double x0, double x1, double y0, double y1, double r)
{
    return ref_strip_integral(x0, x1, y1, r) - ref_strip_integral(x0, x1, y0, r);
}

/* Area of the unit pixel with top-left (x0, y0) (relative to the centre) on
 * the inner side of the tangent at the point of the circle nearest to it. */
static inline double ref_tangent_area(double x0, double y0, double r)
{
    double pcx = x0 + 0.5, pcy = y0 + 0.5;
    double d = hypot(pcx, pcy);
    if (!(d > 0.0))
        return 1.0;
    double nx = pcx / d, ny = pcy / d;
    double off = (r - d) + 0.5 * (nx + ny);
    isk__poly sq, out;
    isk__poly_pixel(&sq, 0.0, 0.0);
    isk__poly_clip_halfplane(&sq, &out, nx, ny, off);
    return out.n >= 3 ? 0.5 * isk__poly_area2(&out) : 0.0;
}

static inline void ref_fill_circle_aa(isk_canvas *c, double cx, double cy, double r, isk_color color, isk_blend mode)
{
    if (!isk__canvas_ok(c) || !isk__finite2(cx, cy) || !isfinite(r) || !(r > 0.0))
        return;
    if (ref_disc_misses_rect(cx, cy, r, 0.0, 0.0, c->width, c->height))
        return;
    int big = r > REF_BIG_R_AA;
    double r2 = r * r;
    int j0 = isk__floor_clamp(cy - r, -1, c->height);
    int j1 = isk__floor_clamp(cy + r, -1, c->height);
    if (j0 < 0) j0 = 0;
    if (j1 > c->height - 1) j1 = c->height - 1;
    for (int j = j0; j <= j1; j++) {
        double y0 = j - cy, y1 = y0 + 1.0;
        double ny = (y0 <= 0.0 && y1 >= 0.0) ? 0.0 : fmin(fabs(y0), fabs(y1));
        double fy = fmax(fabs(y0), fabs(y1));
        if (!(ny < r))
            continue;
        double hw = sqrt((r - ny) * (r + ny));
        int i0 = isk__floor_clamp(cx - hw, -1, c->width);
        int i1 = isk__floor_clamp(cx + hw, -1, c->width);
        if (i0 < 0) i0 = 0;
        if (i1 > c->width - 1) i1 = c->width - 1;
        for (int i = i0; i <= i1; i++) {
            double x0 = i - cx, x1 = x0 + 1.0;
            double nx = (x0 <= 0.0 && x1 >= 0.0) ? 0.0 : fmin(fabs(x0), fabs(x1));
            double fx = fmax(fabs(x0), fabs(x1));
            double area;
            if (!big) {
                if (fx * fx + fy * fy <= r2)
                    area = 1.0;
                else if (nx * nx + ny * ny >= r2)
                    continue;
                else
                    area = ref_disc_rect_area(x0, x1, y0, y1, r);
            } else {
                if (hypot(fx, fy) <= r)
                    area = 1.0;
                else if (hypot(nx, ny) >= r)
                    continue;
                else
                    area = ref_tangent_area(x0, y0, r);
            }
            isk__rule_pixel_cov(isk_canvas_at(c, i, j), color, isk__coverage(area), mode);
        }
    }
}
static inline double ref_twice_snapped(double v)
{
    double t = 2.0 * v;
    double h = floor(t);
    if (t - h >= 0.5)
        h += 1.0;
    return h;
}

static inline uint8_t ref_sprite_sat_add(uint32_t a, uint32_t b)
{
    uint32_t s = a + b;
    return (uint8_t)(s > 255u ? 255u : s);
}

/* Where the sprite lands: mask phase, origin and the clipped row/column
 * ranges.  0 when nothing is visible (or the input is NaN/Inf/huge). */
typedef struct ref_placement {
    int p, x0, y0, jb, je, ib, ie;
} ref_placement;

static inline int ref_place(const isk_canvas *c, const isk_sprite *s, double cx, double cy, isk_blend mode, ref_placement *pl)
{
    if (!c || !c->pixels || !s || !s->mask[0])
        return 0;
    if (mode != ISK_BLEND_REPLACE && mode != ISK_BLEND_OVER && mode != ISK_BLEND_ADD)
        return 0;
    int S = s->size;
    double tx = ref_twice_snapped(cx) - S, ty = ref_twice_snapped(cy) - S; /* 2 * mask origin */
    double ox = floor(0.5 * tx), oy = floor(0.5 * ty);
    /* Rejects NaN, Inf and anything off-canvas before converting to int. */
    if (!(ox > -S && ox < c->width && oy > -S && oy < c->height))
        return 0;
    pl->x0 = (int)ox;
    pl->y0 = (int)oy;
    pl->p = (tx - 2.0 * ox != 0.0) + 2 * (ty - 2.0 * oy != 0.0);
    pl->jb = pl->y0 < 0 ? -pl->y0 : 0;
    pl->je = c->height - pl->y0 < S ? c->height - pl->y0 : S;
    pl->ib = pl->x0 < 0 ? -pl->x0 : 0;
    pl->ie = c->width - pl->x0 < S ? c->width - pl->x0 : S;
    return 1;
}

static inline void ref_draw_sprite_tinted(isk_canvas *c, const isk_sprite *s, double cx, double cy, isk_color color,
                            isk_blend mode)
{
    ref_placement pl;
    if (!ref_place(c, s, cx, cy, mode, &pl))
        return;
    const int S = s->size;
    const uint8_t *mask = s->mask[pl.p];
    const uint16_t *span = s->span[pl.p];
    const uint32_t ca = color.a;
    for (int j = pl.jb; j < pl.je; j++) {
        int b = span[2 * j] > pl.ib ? span[2 * j] : pl.ib;
        int e = span[2 * j + 1] < pl.ie ? span[2 * j + 1] : pl.ie;
        const uint8_t *mrow = mask + (size_t)j * (size_t)S;
        uint8_t *d = isk_canvas_at(c, pl.x0 + b, pl.y0 + j);
        if (mode == ISK_BLEND_ADD) {
            /* isk_blend_pixel_cov's arithmetic, inlined: a' = div255(a*m),
             * then dst += div255(c*a') per channel, saturating. */
            for (int i = b; i < e; i++, d += 4) {
                uint32_t m = mrow[i];
                if (!m)
                    continue;
                uint32_t a = isk_div255(ca * m);
                d[0] = ref_sprite_sat_add(d[0], isk_div255((uint32_t)color.r * a));
                d[1] = ref_sprite_sat_add(d[1], isk_div255((uint32_t)color.g * a));
                d[2] = ref_sprite_sat_add(d[2], isk_div255((uint32_t)color.b * a));
                d[3] = ref_sprite_sat_add(d[3], a);
            }
        } else {
            for (int i = b; i < e; i++, d += 4)
                if (mrow[i])
                    isk__rule_pixel_cov(d, color, mrow[i], mode);
        }
    }
}

static inline void ref_draw_sprite(isk_canvas *c, const isk_sprite *s, double cx, double cy, isk_blend mode)
{
    ref_placement pl;
    if (!ref_place(c, s, cx, cy, mode, &pl))
        return;
    int S = s->size;
    int x0 = pl.x0, y0 = pl.y0;
    const uint8_t *mask = s->mask[pl.p];
    const uint16_t *span = s->span[pl.p];
    int jb = pl.jb, je = pl.je, ib = pl.ib, ie = pl.ie;
    for (int j = jb; j < je; j++) {
        int b = span[2 * j] > ib ? span[2 * j] : ib;
        int e = span[2 * j + 1] < ie ? span[2 * j + 1] : ie;
        const uint8_t *mrow = mask + (size_t)j * (size_t)S;
        uint8_t *d = isk_canvas_at(c, x0 + b, y0 + j);
        switch (mode) {
        case ISK_BLEND_ADD:
            for (int i = b; i < e; i++, d += 4) {
                const uint8_t *v = s->lut[mrow[i]];
                if (!mrow[i])
                    continue;
                d[0] = ref_sprite_sat_add(d[0], v[0]);
                d[1] = ref_sprite_sat_add(d[1], v[1]);
                d[2] = ref_sprite_sat_add(d[2], v[2]);
                d[3] = ref_sprite_sat_add(d[3], v[3]);
            }
            break;
        case ISK_BLEND_OVER:
            for (int i = b; i < e; i++, d += 4) {
                if (!mrow[i])
                    continue;
                isk_color src = {s->color.r, s->color.g, s->color.b, s->lut[mrow[i]][3]};
                isk__rule_pixel(d, src, ISK_BLEND_OVER);
            }
            break;
        case ISK_BLEND_REPLACE:
            for (int i = b; i < e; i++, d += 4) {
                if (!mrow[i])
                    continue;
                d[0] = s->color.r;
                d[1] = s->color.g;
                d[2] = s->color.b;
                d[3] = s->lut[mrow[i]][3];
            }
            break;
        default:
            break;
        }
    }
}


static inline void ref_draw_pixel(isk_canvas *c, int x, int y, isk_color color, isk_blend mode)
{
    if (!isk__canvas_ok(c) || x < 0 || y < 0 || x >= c->width || y >= c->height)
        return;
    isk__rule_pixel(isk_canvas_at(c, x, y), color, mode);
}

#endif
