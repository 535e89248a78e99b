/* SPDX-License-Identifier: MIT */
/* src/raster/clip.h — internal geometry helpers shared by the raster primitives:
 * safe double→int conversion, Liang–Barsky segment clipping, convex polygon
 * clipping (Sutherland–Hodgman) and area, and the coverage→byte rounding rule.
 *
 * Everything here is static inline and free of state.  The point of this
 * header is that no primitive ever converts an unchecked double to int (C makes
 * an out-of-range conversion undefined) and that huge coordinates are cut down
 * to a guard box before any arithmetic whose precision matters.
 */
#ifndef ISKRA_RASTER_CLIP_H
#define ISKRA_RASTER_CLIP_H

#include <math.h>
#include <stdint.h>

#include "iskra/canvas.h"

/* Guard distance around the canvas: geometry is clipped to the canvas grown by
 * this much before it is converted to integers.  2^24 keeps every product of
 * two guarded coordinates (< 2^25 in magnitude) exact in int64 and well inside
 * double's 53-bit mantissa, while being far larger than any canvas, so clipping
 * to it never changes what lands on the canvas in practice. */
#define ISK__GUARD 16777216.0

/* Largest vertex count a clipped convex polygon can reach here: a convex
 * polygon of at most 4 vertices clipped by up to 4 convex clippers of at most
 * 4 edges each, plus slack. */
#define ISK__POLY_MAX 24

static inline int isk__finite2(double a, double b)
{
    return isfinite(a) && isfinite(b);
}

/* Clamps v into [lo, hi]; NaN gives lo (callers reject NaN earlier, this only
 * keeps a later conversion defined whatever happens). */
static inline double isk__clampd(double v, double lo, double hi)
{
    if (!(v >= lo))
        return lo;
    if (v > hi)
        return hi;
    return v;
}

/* floor(v) as an int clamped into [lo, hi]; defined for every double.
 * The floor is the int conversion corrected by one below zero (exact for
 * the clamped value, and no libm call on the primitives' hot paths). */
static inline int isk__floor_clamp(double v, int lo, int hi)
{
    double f = isk__clampd(v, (double)lo, (double)hi);
    int i = (int)f;
    return i - ((double)i > f);
}

/* Liang–Barsky: clips the segment (x0,y0)-(x1,y1) to [xmin,xmax]x[ymin,ymax].
 * Returns 0 when nothing is left.  End points already inside the box are
 * returned bit-for-bit unchanged, so ordinary geometry stays exact.  Works on
 * half differences so that coordinates up to DBL_MAX never overflow; the
 * clipped points are clamped into the box to absorb rounding.  Inputs must be
 * finite. */
static inline int isk__clip_segment(double *x0, double *y0, double *x1, double *y1,
                                    double xmin, double ymin, double xmax, double ymax)
{
    double hx = 0.5 * *x1 - 0.5 * *x0, hy = 0.5 * *y1 - 0.5 * *y0;
    /* Parameter u runs 0..2 along P0 + u*(hx, hy). */
    double u0 = 0.0, u1 = 2.0;
    int k0 = -1, k1 = -1; /* which box side set u0 / u1 */
    double p[4] = {-hx, hx, -hy, hy};
    double q[4] = {*x0 - xmin, xmax - *x0, *y0 - ymin, ymax - *y0};
    const double side[4] = {xmin, xmax, ymin, ymax};
    for (int k = 0; k < 4; k++) {
        if (p[k] == 0.0) {
            if (q[k] < 0.0)
                return 0;
            continue;
        }
        double u = q[k] / p[k];
        if (!isfinite(u)) /* q overflowed: treat as far outside/inside */
            u = (u > 0) ? 2.0 : 0.0;
        if (p[k] < 0.0) {
            if (u > u1)
                return 0;
            if (u > u0) {
                u0 = u;
                k0 = k;
            }
        } else {
            if (u < u0)
                return 0;
            if (u < u1) {
                u1 = u;
                k1 = k;
            }
        }
    }
    /* A clipped end lies exactly on the side that clipped it; computing that
     * coordinate as x0 + u*hx instead would cancel catastrophically for huge
     * inputs (e.g. -1e300 + 1e300). */
    double ax = *x0, ay = *y0, bx = *x1, by = *y1;
    if (k0 >= 0) {
        ax = k0 < 2 ? side[k0] : isk__clampd(*x0 + u0 * hx, xmin, xmax);
        ay = k0 >= 2 ? side[k0] : isk__clampd(*y0 + u0 * hy, ymin, ymax);
    }
    if (k1 >= 0) {
        bx = k1 < 2 ? side[k1] : isk__clampd(*x0 + u1 * hx, xmin, xmax);
        by = k1 >= 2 ? side[k1] : isk__clampd(*y0 + u1 * hy, ymin, ymax);
    }
    *x0 = ax; *y0 = ay; *x1 = bx; *y1 = by;
    return 1;
}

/* ---- convex polygons ------------------------------------------------------
 * Vertices are ordered so that the interior is on the side where
 * cross(b - a, p - a) >= 0 for every edge a→b (clockwise on screen, since y
 * grows down). */
typedef struct isk__poly {
    int n;
    double x[ISK__POLY_MAX], y[ISK__POLY_MAX];
} isk__poly;

/* Twice the signed area (positive for our orientation). */
static inline double isk__poly_area2(const isk__poly *p)
{
    double s = 0.0;
    for (int i = 0, j = p->n - 1; i < p->n; j = i++)
        s += (p->x[j] - p->x[i]) * (p->y[j] + p->y[i]);
    return s;
}

/* Makes the orientation positive (reverses a negatively wound polygon). */
static inline void isk__poly_orient(isk__poly *p)
{
    if (isk__poly_area2(p) < 0.0) {
        for (int i = 0, j = p->n - 1; i < j; i++, j--) {
            double tx = p->x[i], ty = p->y[i];
            p->x[i] = p->x[j]; p->y[i] = p->y[j];
            p->x[j] = tx; p->y[j] = ty;
        }
    }
}

/* Keeps the part of `in` on the inner side of the directed line a→b
 * (one Sutherland–Hodgman pass).  in and out must differ. */
static inline void isk__poly_clip_edge(const isk__poly *in, isk__poly *out,
                                       double ax, double ay, double bx, double by)
{
    double ex = bx - ax, ey = by - ay;
    out->n = 0;
    if (in->n == 0)
        return;
    int j = in->n - 1;
    double dj = ex * (in->y[j] - ay) - ey * (in->x[j] - ax);
    for (int i = 0; i < in->n; j = i++) {
        double di = ex * (in->y[i] - ay) - ey * (in->x[i] - ax);
        if ((di >= 0.0) != (dj >= 0.0) && out->n < ISK__POLY_MAX) {
            double t = dj / (dj - di);
            out->x[out->n] = in->x[j] + t * (in->x[i] - in->x[j]);
            out->y[out->n] = in->y[j] + t * (in->y[i] - in->y[j]);
            out->n++;
        }
        if (di >= 0.0 && out->n < ISK__POLY_MAX) {
            out->x[out->n] = in->x[i];
            out->y[out->n] = in->y[i];
            out->n++;
        }
        dj = di;
    }
}

/* Keeps the part of `in` where nx*x + ny*y <= off (one Sutherland–Hodgman
 * pass against a half-plane).  in and out must differ. */
static inline void isk__poly_clip_halfplane(const isk__poly *in, isk__poly *out,
                                            double nx, double ny, double off)
{
    out->n = 0;
    if (in->n == 0)
        return;
    int j = in->n - 1;
    double dj = off - (nx * in->x[j] + ny * in->y[j]);
    for (int i = 0; i < in->n; j = i++) {
        double di = off - (nx * in->x[i] + ny * in->y[i]);
        if ((di >= 0.0) != (dj >= 0.0) && out->n < ISK__POLY_MAX) {
            double t = dj / (dj - di);
            out->x[out->n] = in->x[j] + t * (in->x[i] - in->x[j]);
            out->y[out->n] = in->y[j] + t * (in->y[i] - in->y[j]);
            out->n++;
        }
        if (di >= 0.0 && out->n < ISK__POLY_MAX) {
            out->x[out->n] = in->x[i];
            out->y[out->n] = in->y[i];
            out->n++;
        }
        dj = di;
    }
}

/* *p = *p ∩ clip, both convex with positive orientation. */
static inline void isk__poly_clip(isk__poly *p, const isk__poly *clip)
{
    isk__poly tmp;
    for (int i = 0, j = clip->n - 1; i < clip->n && p->n > 0; j = i++) {
        isk__poly_clip_edge(p, &tmp, clip->x[j], clip->y[j], clip->x[i], clip->y[i]);
        *p = tmp;
    }
}

/* The unit pixel square [px, px+1] x [py, py+1] as a polygon. */
static inline void isk__poly_pixel(isk__poly *p, double px, double py)
{
    p->n = 4;
    p->x[0] = px;       p->y[0] = py;
    p->x[1] = px + 1.0; p->y[1] = py;
    p->x[2] = px + 1.0; p->y[2] = py + 1.0;
    p->x[3] = px;       p->y[3] = py + 1.0;
}

/* Area of (pixel (px,py)) ∩ a ∩ b ∩ c; b and c may be NULL. */
static inline double isk__pixel_area(double px, double py, const isk__poly *a,
                                     const isk__poly *b, const isk__poly *c)
{
    isk__poly s;
    isk__poly_pixel(&s, px, py);
    isk__poly_clip(&s, a);
    if (b)
        isk__poly_clip(&s, b);
    if (c)
        isk__poly_clip(&s, c);
    return s.n >= 3 ? 0.5 * isk__poly_area2(&s) : 0.0;
}

/* 1 when (x, y) is inside or on the boundary of a convex polygon. */
static inline int isk__poly_contains(const isk__poly *p, double x, double y)
{
    for (int i = 0, j = p->n - 1; i < p->n; j = i++) {
        double ex = p->x[i] - p->x[j], ey = p->y[i] - p->y[j];
        if (ex * (y - p->y[j]) - ey * (x - p->x[j]) < 0.0)
            return 0;
    }
    return p->n >= 3;
}

/* Coverage rule for every exact-area primitive: an area a in [0, 1] becomes
 * floor(255*a + 0.5) (round half up), so a half-covered pixel gets 128.
 * NaN and out-of-range areas are clamped (NaN → 0). */
static inline uint8_t isk__coverage(double area)
{
    double v = 255.0 * area + 0.5;
    if (!(v >= 1.0))
        return 0;
    if (v >= 255.0)
        return 255;
    return (uint8_t)v; /* truncation == floor for v in [1, 255) */
}

/* 1 when the canvas can be drawn into at all. */
static inline int isk__canvas_ok(const isk_canvas *c)
{
    return c && c->pixels && c->width > 0 && c->height > 0;
}

#endif
