/* SPDX-License-Identifier: MIT */
/* Anti-aliased hairlines: how a browser's canvas draws stroke() at width 1.
 *
 * Chrome's Skia treats an anti-aliased stroke no wider than one device pixel
 * as a hairline.  A hairline gives every pixel step along the major axis
 * exactly one pixel's worth of coverage, split between the two pixels
 * nearest the line's centre across it; so a horizontal line on a pixel
 * boundary lights two rows at 127 and 128, and a diagonal stays two pixels
 * wide (the exact-area width-1 rectangle of isk_stroke_line spreads over
 * three with 1.25 pixels of coverage per row).
 *
 * Rule, for a line whose major axis is y (x is symmetric): for each pixel
 * row j the segment crosses, let L be the length of [j, j+1) inside the
 * segment's y range (1 for inner rows, a fraction at the ends) and xc the
 * line's x at the middle of that piece minus one half; with i = floor(xc)
 * and a8 = floor(256 * (xc - i)) (at most 255), pixel i gets 255 - a8 and
 * pixel i + 1 gets a8, both scaled by L (times 256, truncated, as Skia's
 * caps).  Each segment of a polyline is drawn on its own: no joins, no caps.
 */
#include <math.h>

#include "iskra/draw.h"
#include "raster/clip.h"

/* Keeps coordinates where doubles still resolve a pixel and ints do not
 * overflow; returns 0 for non-finite input. */
static int hair_clip(isk_canvas *c, double *x0, double *y0, double *x1, double *y1)
{
    const double guard = 1 << 24;
    if (!(isfinite(*x0) && isfinite(*y0) && isfinite(*x1) && isfinite(*y1)))
        return 0;
    return isk__clip_segment(x0, y0, x1, y1, -guard, -guard, c->width + guard, c->height + guard);
}

static void plot(isk_canvas *c, int x, int y, int cov, isk_color color, isk_blend mode, int swap)
{
    if (swap) {
        int t = x;
        x = y;
        y = t;
    }
    if (cov <= 0 || x < 0 || y < 0 || x >= c->width || y >= c->height)
        return;
    isk_blend_pixel_cov(isk_canvas_at(c, x, y), color, (uint8_t)(cov > 255 ? 255 : cov), mode);
}

/* Major axis "v" (rows), minor "u"; swap says whether (u, v) is (y, x). */
static void hairline_major(isk_canvas *c, double u0, double v0, double u1, double v1, isk_color color,
                           isk_blend mode, int swap)
{
    if (v0 > v1) {
        double t = u0; u0 = u1; u1 = t;
        t = v0; v0 = v1; v1 = t;
    }
    double dv = v1 - v0;
    if (!(dv > 0))
        return;
    double slope = (u1 - u0) / dv;
    int vmax = swap ? c->width : c->height;
    double first = floor(v0), last = ceil(v1) - 1;
    if (first < -1) first = -1;
    if (last > vmax) last = vmax;
    for (double jj = first; jj <= last; jj++) {
        double lo = v0 > jj ? v0 : jj, hi = v1 < jj + 1 ? v1 : jj + 1;
        double L = hi - lo;
        if (!(L > 0))
            continue;
        int L256 = (int)(L * 256.0);
        if (L256 > 256) L256 = 256;
        double uc = u0 + (0.5 * (lo + hi) - v0) * slope - 0.5;
        double fi = floor(uc);
        if (!(fi > -2.0 && fi < (double)(swap ? c->height : c->width) + 1.0))
            continue;
        int a8 = (int)((uc - fi) * 256.0);
        if (a8 > 255) a8 = 255;
        int i = (int)fi, j = (int)jj;
        int near = ((255 - a8) * L256) >> 8, far = (a8 * L256) >> 8;
        plot(c, i, j, near, color, mode, swap);
        plot(c, i + 1, j, far, color, mode, swap);
    }
}

void isk_stroke_hairline(isk_canvas *c, double x0, double y0, double x1, double y1, isk_color color,
                         isk_blend mode)
{
    if (!c || !c->pixels || !hair_clip(c, &x0, &y0, &x1, &y1))
        return;
    if (fabs(y1 - y0) >= fabs(x1 - x0))
        hairline_major(c, x0, y0, x1, y1, color, mode, 0); /* rows: v = y */
    else
        hairline_major(c, y0, x0, y1, x1, color, mode, 1); /* columns: v = x */
}

void isk_stroke_polyline_hairline(isk_canvas *c, const double *xy, int n, int closed, isk_color color,
                                  isk_blend mode)
{
    if (!c || !xy || n < 2)
        return;
    for (int k = 0; k + 1 < n; k++)
        isk_stroke_hairline(c, xy[2 * k], xy[2 * k + 1], xy[2 * k + 2], xy[2 * k + 3], color, mode);
    if (closed && n > 2)
        isk_stroke_hairline(c, xy[2 * n - 2], xy[2 * n - 1], xy[0], xy[1], color, mode);
}
