/* SPDX-License-Identifier: MIT */
/* src/sim/segment_exact.h — exact geometry of one segment (internal): the
 * error-free transformations, a segment in canonical form, the side of a
 * point and the crossing of a path, exact for segments of any length.
 *
 *     isk__seg s = isk__seg_canon(&deflector);
 *     double t = isk__seg_crossing(&s, x0, y0, x1, y1);  // -1: no hit
 *     if (t >= 0.0) ... the path (x0, y0) -> (x1, y1) hits at x0 + t (x1 - x0)
 *
 * Every function is static inline: the contact pass tests every path
 * against every segment, and the tests must stay inlined into its loop.
 * Round to nearest, no fused multiply-add (the build uses
 * -ffp-contract=off): the transformations below are exact only then.
 * The touching convention is iskra/deflector.h's; test_deflector_far
 * checks the precision far from the origin. */
#ifndef ISKRA_SIM_SEGMENT_EXACT_H
#define ISKRA_SIM_SEGMENT_EXACT_H

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "iskra/deflector.h"

/* ---- error-free transformations ------------------------------------------ */

/* Knuth's sum: a + b = s + e exactly. */
static inline void isk__two_sum(double a, double b, double *s, double *e)
{
    double x = a + b, bv = x - a, av = x - bv;
    *s = x;
    *e = (a - av) + (b - bv);
}

/* Veltkamp's split: a = hi + lo, each half 26 bits (|a| < 1e300). */
static inline void isk__split(double a, double *hi, double *lo)
{
    double c = 134217729.0 * a; /* 2^27 + 1 */
    double h = c - (c - a);
    *hi = h;
    *lo = a - h;
}

/* Dekker's product: a*b = p + e exactly. */
static inline void isk__two_prod(double a, double b, double *p, double *e)
{
    double ah, al, bh, bl;
    isk__split(a, &ah, &al);
    isk__split(b, &bh, &bl);
    double x = a * b;
    *p = x;
    *e = ((ah * bh - x) + ah * bl + al * bh) + al * bl;
}

/* The sum of four doubles, exactly as a nonoverlapping expansion (Shewchuk's
 * grow-expansion), then added from the smallest part: within an ulp of the
 * exact sum however much it cancels. */
static inline double isk__sum4(double a, double b, double c, double d)
{
    double e[8], h[8], in[4] = {a, b, c, d};
    int n = 0;
    for (int j = 0; j < 4; j++) {
        double q = in[j];
        int m = 0;
        for (int i = 0; i < n; i++) {
            double s, t;
            isk__two_sum(q, e[i], &s, &t);
            q = s;
            if (t != 0.0)
                h[m++] = t;
        }
        if (q != 0.0 || m == 0)
            h[m++] = q;
        memcpy(e, h, (size_t)m * sizeof *e);
        n = m;
    }
    double s = 0.0;
    for (int i = 0; i < n; i++)
        s += e[i];
    return s;
}

/* ---- a segment in canonical form ----------------------------------------- */

/* Endpoint A first (lexicographic on x, y), d = B - A (rounded; dl its
 * exact remainder), K = cross(A, B) rounded from its exact value, and the
 * unit normal n = (-dy, dx)/|d|.  Adding 0.0 turns -0 into +0 so reversed
 * input is bit-identical even there: a segment given either way round
 * deflects alike. */
typedef struct isk__seg {
    double ax, ay, bx, by, dx, dy;
    double dlx, dly, K;
    double nx, ny, len;
} isk__seg;

/* 1 when the deflector's end points are already in canonical order. */
static inline int isk__seg_in_order(const isk_deflector *d)
{
    return d->x0 < d->x1 || (d->x0 == d->x1 && d->y0 <= d->y1);
}

static inline isk__seg isk__seg_canon(const isk_deflector *d)
{
    isk__seg s;
    int keep = isk__seg_in_order(d);
    s.ax = (keep ? d->x0 : d->x1) + 0.0;
    s.ay = (keep ? d->y0 : d->y1) + 0.0;
    s.bx = (keep ? d->x1 : d->x0) + 0.0;
    s.by = (keep ? d->y1 : d->y0) + 0.0;
    isk__two_sum(s.bx, -s.ax, &s.dx, &s.dlx);
    isk__two_sum(s.by, -s.ay, &s.dy, &s.dly);
    double k1, f1, k2, f2;
    isk__two_prod(s.ax, s.by, &k1, &f1);
    isk__two_prod(s.ay, s.bx, &k2, &f2);
    s.K = isk__sum4(k1, f1, -k2, -f2);
    s.len = hypot(s.dx, s.dy);
    s.nx = -s.dy / s.len;
    s.ny = s.dx / s.len;
    return s;
}

/* ---- the predicates ------------------------------------------------------ */

/* Side of P relative to the line through the segment, cross(B - A, P - A).
 * The direct formula relative to A carries the rounding of |P - A|: for a
 * segment reaching to 1e12 a point near the origin is resolved only to
 * 1e-4, and at 1e150 not at all.  So it is used only where its error bound
 * (Shewchuk's orient2d bound) shows it accurate to 2^-32 of its value;
 * otherwise the same determinant is evaluated as cross(B - A, P) + K in
 * twice the working precision (exact products, exact B - A and K), whose
 * error is that of a point at |P| on a segment through the origin: the
 * precision no longer depends on where the endpoints are. */
static inline double isk__seg_side(const isk__seg *s, double px, double py)
{
    double l = s->dx * (py - s->ay), r = s->dy * (px - s->ax);
    double o = l - r;
    const double bound = 0x1p32 * 3.3306690738754716e-16 * (fabs(l) + fabs(r)); /* (3 + 16 eps) eps */
    if (fabs(o) > bound || !(fabs(px) < 1e300 && fabs(py) < 1e300))
        return o;
    double p1, e1, p2, e2, u, eu, w, ew;
    isk__two_prod(s->dx, py, &p1, &e1);
    isk__two_prod(s->dy, px, &p2, &e2);
    isk__two_sum(p1, -p2, &u, &eu);
    isk__two_sum(u, s->K, &w, &ew);
    return w + (((e1 - e2) + (eu + ew)) + (s->dlx * py - s->dly * px));
}

static inline int isk__sgn(double v)
{
    return (v > 0.0) - (v < 0.0);
}

/* Crossing parameter of path P0 -> P1 with the segment, or -1 for no hit.
 * A path that starts on the line is leaving it (no hit); one that ends on
 * it hits (iskra/deflector.h). */
static inline double isk__seg_crossing(const isk__seg *s, double x0, double y0, double x1, double y1)
{
    double o1 = isk__seg_side(s, x0, y0);
    int s1 = isk__sgn(o1);
    if (s1 == 0)
        return -1.0; /* starting on the line: leaving it */
    double o2 = isk__seg_side(s, x1, y1);
    if (isk__sgn(o2) == s1)
        return -1.0;
    /* The path's own side tests of A and B: the same expression for a vertex
     * shared by two segments, so shared vertices are watertight. */
    double px = x1 - x0, py = y1 - y0;
    int s3 = isk__sgn(px * (s->ay - y0) - py * (s->ax - x0));
    int s4 = isk__sgn(px * (s->by - y0) - py * (s->bx - x0));
    if (s3 != 0 && s3 == s4)
        return -1.0;
    return o1 / (o1 - o2); /* opposite signs: no cancellation, in (0, 1] */
}

#endif
