/* SPDX-License-Identifier: MIT */
/* Filled circles: aliased (pixel centres strictly inside) and anti-aliased
 * (exact area of disc ∩ pixel square, computed analytically).
 *
 * Analytic area: with the centre at the origin and h(x) = sqrt(r^2 - x^2),
 *   area(disc ∩ [x0,x1]x[y0,y1]) = I(y1) - I(y0),
 *   I(y) = sign(y) * integral over [x0,x1] of min(|y|, h(x)) dx,
 * and min(c, h) integrates in closed form with H(x) = (x h(x) + r^2 asin(x/r))/2.
 * Only pixels the circle's edge crosses use it; whole pixels are 0 or 255.
 * The formula subtracts values of size r^2, so above r = 2^16 (where it would
 * lose digits) the edge is treated as its tangent line at the point nearest
 * the pixel: the arc deviates from that line by < 1e-5 px across a pixel.
 */
#include "iskra/draw.h"

#include <string.h>

#include "raster/circle_rows.h"
#include "raster/circle_loops.h"
#include "raster/clip.h"
#include "raster/span.h"

#define BIG_R_ALIASED 67108864.0 /* 2^26: d^2 and r^2 stay exact enough below */
#define BIG_R_AA 65536.0         /* 2^16, see above */

static int disc_misses_rect(double cx, double cy, double r, double x0, double y0,
                            double x1, double y1)
{
    double dx = cx < x0 ? x0 - cx : (cx > x1 ? cx - x1 : 0.0);
    double dy = cy < y0 ? y0 - cy : (cy > y1 ? cy - y1 : 0.0);
    return dx >= r || dy >= r;
}

void isk_fill_circle(isk_canvas *c, double cx, double cy, double r, isk_color color, isk_blend mode)
{
    if (!isk__canvas_ok(c) || !isk__finite2(cx, cy) || !isfinite(r) || !(r > 0.0))
        return;
    /* No pixel centre can be strictly inside: nothing to do.  This also
     * bounds |cx|, |cy| by r + canvas size for the arithmetic below. */
    if (disc_misses_rect(cx, cy, r, 0.5, 0.5, c->width - 0.5, c->height - 0.5))
        return;
    int big = r > BIG_R_ALIASED;
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
                isk_blend_pixel(isk_canvas_at(c, i, j), color, mode);
        }
    }
}

/* Antiderivative of min(cl, h(x)) (cl >= 0), for x in [-r, r]. */
static double min_antideriv(double x, double cl, double r)
{
    double w = cl < r ? sqrt((r - cl) * (r + cl)) : 0.0;
    if (x > w)
        return cl * w + h_integral(x, r) - h_integral(w, r);
    if (x < -w)
        return -cl * w + h_integral(x, r) + h_integral(w, r);
    return cl * x;
}

static double strip_integral(double a, double b, double y, double r)
{
    a = isk__clampd(a, -r, r);
    b = isk__clampd(b, -r, r);
    double cl = fabs(y);
    double v = min_antideriv(b, cl, r) - min_antideriv(a, cl, r);
    return y < 0.0 ? -v : v;
}

/* Exact area of the disc of radius r at the origin ∩ [x0,x1]x[y0,y1]. */
static double disc_rect_area(double x0, double x1, double y0, double y1, double r)
{
    return strip_integral(x0, x1, y1, r) - strip_integral(x0, x1, y0, r);
}

/* Area of the unit pixel with top-left (x0, y0) (relative to the centre) on
 * the inner side of the tangent at the point of the circle nearest to it. */
static double tangent_area(double x0, double y0, double r)
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

/* The tangent rule for big discs and the plain per-pixel walk for discs
 * wider than the row caches below (the original per-pixel code). */
static void fill_circle_aa_pixels(isk_canvas *c, double cx, double cy, double r, isk_color color, isk_blend mode,
                                  int r0, int r1)
{
    int big = r > BIG_R_AA;
    double r2 = r * r;
    int j0 = isk__floor_clamp(cy - r, -1, c->height);
    int j1 = isk__floor_clamp(cy + r, -1, c->height);
    if (j0 < r0) j0 = r0;
    if (j1 > r1 - 1) j1 = r1 - 1;
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
                    area = disc_rect_area(x0, x1, y0, y1, r);
            } else {
                if (hypot(fx, fy) <= r)
                    area = 1.0;
                else if (hypot(nx, ny) >= r)
                    continue;
                else
                    area = tangent_area(x0, y0, r);
            }
            isk_blend_pixel_cov(isk_canvas_at(c, i, j), color, isk__coverage(area), mode);
        }
    }
}

/* Discs up to ROW_CACHE columns wide: the row walk with cached integrals
 * (raster/circle_loops.h, the same bytes as the per-pixel walk above), its
 * portable build; circle_avx2.c has the AVX2 one. */
AA_ROWS_FN(aa_rows_small, static, ROW_SMALL, isk__span_cov, NULL)
AA_ROWS_FN(aa_rows_big, static, ROW_CACHE, isk__span_cov, NULL)

void isk__fill_circle_aa_rows(isk_canvas *c, double cx, double cy, double r, isk_color color, isk_blend mode, int r0,
                              int r1)
{
    if (!isk__canvas_ok(c) || !isk__finite2(cx, cy) || !isfinite(r) || !(r > 0.0))
        return;
    r0 = r0 < 0 ? 0 : r0;
    r1 = r1 > c->height ? c->height : r1;
    if (r0 >= r1 || disc_misses_rect(cx, cy, r, 0.0, r0, c->width, r1))
        return;
    /* every row's columns lie in the disc's column range */
    int i0g = isk__floor_clamp(cx - r, -1, c->width), i1g = isk__floor_clamp(cx + r, -1, c->width);
    if (i0g < 0) i0g = 0;
    if (i1g > c->width - 1) i1g = c->width - 1;
    if (r > BIG_R_AA || i1g - i0g + 1 > ROW_CACHE) {
        fill_circle_aa_pixels(c, cx, cy, r, color, mode, r0, r1);
        return;
    }
    if (i1g - i0g + 1 <= ROW_SMALL) {
#if ISK__CPU_AVX2
        if (isk__have_avx2()) { /* coverage 4 pixels a step, blends 8 (circle_avx2.c) */
            isk__circle_aa_rows_small_avx2(c, cx, cy, r, color, i0g, i1g, r0, r1, mode);
            return;
        }
#endif
        aa_rows_small(c, cx, cy, r, color, i0g, i1g, r0, r1, mode);
        return;
    }
    aa_rows_big(c, cx, cy, r, color, i0g, i1g, r0, r1, mode);
}

void isk_fill_circle_aa(isk_canvas *c, double cx, double cy, double r, isk_color color, isk_blend mode)
{
    isk__fill_circle_aa_rows(c, cx, cy, r, color, mode, 0, c ? c->height : 0);
}
