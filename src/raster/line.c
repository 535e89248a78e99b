/* SPDX-License-Identifier: MIT */
/* Aliased 1-pixel lines (Bresenham) and triangle outlines.
 *
 * The line is defined in closed form so it can be clipped exactly: between the
 * pixels (X0,Y0) and (X1,Y1) containing the end points, walked along the major
 * axis from the end with the smaller major coordinate, step i (0..da) lights
 * minor offset m_i = floor((2*i*db + da) / (2*da)), i.e. i*db/da rounded half
 * up.  Walking from a canonical end makes line(A,B) and line(B,A) the same
 * pixel set; the closed form lets us jump straight to the first pixel on the
 * canvas instead of stepping through up to 2^25 invisible ones. */
#include "iskra/draw.h"

#include <stdlib.h>

#include "raster/clip.h"

static long long floordiv(long long a, long long b) /* b > 0 */
{
    long long q = a / b;
    if (a % b != 0 && a < 0)
        q--;
    return q;
}

static long long ceildiv(long long a, long long b) /* b > 0 */
{
    return -floordiv(-a, b);
}

/* Largest |pixel coordinate| after guard clipping (exactly representable). */
#define PIX_LIMIT 33554432LL /* 2^25 */

static long long pix_floor(double v)
{
    return (long long)floor(isk__clampd(v, -(double)PIX_LIMIT, (double)PIX_LIMIT));
}

/* Draws the Bresenham pixels between pixel (X0,Y0) and (X1,Y1), both ends
 * included, except pixel (skx, sky) when skip != 0. */
static void bresenham(isk_canvas *c, long long X0, long long Y0, long long X1, long long Y1,
                      int skip, long long skx, long long sky, isk_color color, isk_blend mode)
{
    int xmajor = llabs(X1 - X0) >= llabs(Y1 - Y0);
    /* (a, b) = (major, minor) coordinates. */
    long long A0 = xmajor ? X0 : Y0, B0 = xmajor ? Y0 : X0;
    long long A1 = xmajor ? X1 : Y1, B1 = xmajor ? Y1 : X1;
    if (A1 < A0) {
        long long t = A0; A0 = A1; A1 = t;
        t = B0; B0 = B1; B1 = t;
    }
    long long da = A1 - A0, db = llabs(B1 - B0);
    int sb = B1 >= B0 ? 1 : -1;
    long long amax = xmajor ? c->width : c->height;
    long long bmax = xmajor ? c->height : c->width;

    long long ilo = A0 < 0 ? -A0 : 0;
    long long ihi = amax - 1 - A0 < da ? amax - 1 - A0 : da;
    long long mlo = sb > 0 ? -B0 : B0 - bmax + 1;
    long long mhi = sb > 0 ? bmax - 1 - B0 : B0;
    if (mlo > db || mhi < 0)
        return;
    if (db == 0) {
        if (mlo > 0)
            return;
    } else {
        /* m_i >= mlo  <=>  i >= ceil((2*da*mlo - da) / (2*db)) */
        if (mlo > 0) {
            long long i = ceildiv(2 * da * mlo - da, 2 * db);
            if (i > ilo) ilo = i;
        }
        /* m_i <= mhi  <=>  i <= ceil((2*da*(mhi+1) - da) / (2*db)) - 1 */
        if (mhi < db) {
            long long i = ceildiv(2 * da * (mhi + 1) - da, 2 * db) - 1;
            if (i < ihi) ihi = i;
        }
    }
    if (ilo > ihi)
        return;

    long long den = 2 * da;
    long long m = 0, rem = 0;
    if (da > 0) {
        long long num = 2 * ilo * db + da;
        m = num / den;
        rem = num % den;
    }
    for (long long i = ilo; i <= ihi; i++) {
        long long a = A0 + i, b = B0 + sb * m;
        long long x = xmajor ? a : b, y = xmajor ? b : a;
        if (!(skip && x == skx && y == sky))
            isk_blend_pixel(isk_canvas_at(c, (int)x, (int)y), color, mode);
        rem += 2 * db;
        if (rem >= den) {
            rem -= den;
            m++;
        }
    }
}

/* Clips (x0,y0)-(x1,y1) to the guard box and returns the end pixels. */
static int line_pixels(const isk_canvas *c, double x0, double y0, double x1, double y1,
                       long long *X0, long long *Y0, long long *X1, long long *Y1)
{
    if (!isk__finite2(x0, y0) || !isk__finite2(x1, y1))
        return 0;
    if (!isk__clip_segment(&x0, &y0, &x1, &y1, -ISK__GUARD, -ISK__GUARD,
                           c->width + ISK__GUARD, c->height + ISK__GUARD))
        return 0;
    *X0 = pix_floor(x0); *Y0 = pix_floor(y0);
    *X1 = pix_floor(x1); *Y1 = pix_floor(y1);
    return 1;
}

void isk_draw_line(isk_canvas *c, double x0, double y0, double x1, double y1,
                   isk_color color, isk_blend mode)
{
    long long X0, Y0, X1, Y1;
    if (!isk__canvas_ok(c) || !line_pixels(c, x0, y0, x1, y1, &X0, &Y0, &X1, &Y1))
        return;
    bresenham(c, X0, Y0, X1, Y1, 0, 0, 0, color, mode);
}

/* Each edge a→b is drawn without the pixel of b, which the next edge starts
 * on, so every vertex pixel is blended once (translucent and additive outlines
 * show no dark corners).  An edge whose ends share a pixel adds nothing of its
 * own.  Pixels shared by two edges near a very sharp vertex can still be
 * blended twice. */
void isk_draw_triangle(isk_canvas *c, double x0, double y0, double x1, double y1,
                       double x2, double y2, isk_color color, isk_blend mode)
{
    const double vx[3] = {x0, x1, x2}, vy[3] = {y0, y1, y2};
    if (!isk__canvas_ok(c))
        return;
    for (int k = 0; k < 3; k++)
        if (!isk__finite2(vx[k], vy[k]))
            return;
    long long px[3], py[3];
    for (int k = 0; k < 3; k++) {
        px[k] = pix_floor(vx[k]);
        py[k] = pix_floor(vy[k]);
    }
    int drawn = 0;
    for (int k = 0; k < 3; k++) {
        int e = (k + 1) % 3;
        if (px[k] == px[e] && py[k] == py[e])
            continue;
        long long X0, Y0, X1, Y1;
        if (!line_pixels(c, vx[k], vy[k], vx[e], vy[e], &X0, &Y0, &X1, &Y1)) {
            drawn = 1;
            continue;
        }
        bresenham(c, X0, Y0, X1, Y1, 1, px[e], py[e], color, mode);
        drawn = 1;
    }
    if (!drawn) /* all three vertices in one pixel */
        isk_draw_pixel(c, (int)isk__clampd((double)px[0], -1.0, (double)c->width),
                       (int)isk__clampd((double)py[0], -1.0, (double)c->height), color, mode);
}
