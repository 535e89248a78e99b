/* SPDX-License-Identifier: MIT */
/* Aliased filled triangles: pixels whose centre is inside, top-left rule for
 * centres exactly on an edge.
 *
 * Why the edge function is evaluated "canonically": two triangles sharing an
 * edge see it with opposite directions.  Evaluating a→b and b→a separately in
 * floating point need not give exactly opposite values, which would let a
 * pixel near the edge land in both triangles or in neither.  We always
 * evaluate from the lexicographically smaller end point and negate, so the two
 * triangles get bit-identical magnitudes with opposite signs, and the
 * top-left rule settles the exact zeros: a shared edge is drawn exactly once.
 */
#include "iskra/draw.h"

#include "raster/clip.h"

typedef struct edge {
    double ax, ay, bx, by; /* canonical order: (ax,ay) lexicographically <= (bx,by) */
    double sign;           /* +1 or -1: turns the canonical value into the polygon's */
    int topleft;           /* centres exactly on the edge are inside */
} edge;

static void edge_init(edge *e, double x0, double y0, double x1, double y1)
{
    /* Interior is on the side where cross(p1 - p0, p - p0) > 0.  With y down,
     * a top edge runs left to right (dy == 0, dx > 0), a left edge runs up. */
    double dx = x1 - x0, dy = y1 - y0;
    e->topleft = (dy < 0.0) || (dy == 0.0 && dx > 0.0);
    if (x0 < x1 || (x0 == x1 && y0 <= y1)) {
        e->ax = x0; e->ay = y0; e->bx = x1; e->by = y1; e->sign = 1.0;
    } else {
        e->ax = x1; e->ay = y1; e->bx = x0; e->by = y0; e->sign = -1.0;
    }
}

static int edge_inside(const edge *e, double px, double py)
{
    double v = e->sign * ((e->bx - e->ax) * (py - e->ay) - (e->by - e->ay) * (px - e->ax));
    return v > 0.0 || (v == 0.0 && e->topleft);
}

/* Fills a positively oriented convex polygon (vertices within the guard box). */
static void fill_convex(isk_canvas *c, const isk__poly *p, isk_color color, isk_blend mode)
{
    edge e[ISK__POLY_MAX];
    double ymin = p->y[0], ymax = p->y[0];
    for (int i = 0; i < p->n; i++) {
        int k = (i + 1) % p->n;
        edge_init(&e[i], p->x[i], p->y[i], p->x[k], p->y[k]);
        if (p->y[i] < ymin) ymin = p->y[i];
        if (p->y[i] > ymax) ymax = p->y[i];
    }
    int j0 = isk__floor_clamp(ymin - 0.5, -1, c->height); /* conservative */
    int j1 = isk__floor_clamp(ymax - 0.5, -1, c->height);
    if (j0 < 0) j0 = 0;
    if (j1 > c->height - 1) j1 = c->height - 1;
    for (int j = j0; j <= j1; j++) {
        double cy = j + 0.5;
        /* Conservative span from the linear edge constraints; the exact
         * test below decides each pixel. */
        double xlo = -1.0, xhi = c->width + 1.0;
        for (int i = 0; i < p->n; i++) {
            int k = (i + 1) % p->n;
            double dx = p->x[k] - p->x[i], dy = p->y[k] - p->y[i];
            if (dy == 0.0)
                continue;
            double x = p->x[i] + dx * (cy - p->y[i]) / dy;
            if (dy > 0.0) { if (x < xhi) xhi = x; }
            else if (x > xlo) xlo = x;
        }
        int i0 = isk__floor_clamp(xlo - 0.5, -2, c->width) - 1;
        int i1 = isk__floor_clamp(xhi - 0.5, -2, c->width) + 1;
        if (i0 < 0) i0 = 0;
        if (i1 > c->width - 1) i1 = c->width - 1;
        for (int i = i0; i <= i1; i++) {
            double cx = i + 0.5;
            int in = 1;
            for (int k = 0; k < p->n && in; k++)
                in = edge_inside(&e[k], cx, cy);
            if (in)
                isk_blend_pixel(isk_canvas_at(c, i, j), color, mode);
        }
    }
}

void isk_fill_triangle(isk_canvas *c, double x0, double y0, double x1, double y1,
                       double x2, double y2, isk_color color, isk_blend mode)
{
    if (!isk__canvas_ok(c) || !isk__finite2(x0, y0) || !isk__finite2(x1, y1) ||
        !isk__finite2(x2, y2))
        return;
    isk__poly p;
    p.n = 3;
    p.x[0] = x0; p.y[0] = y0;
    p.x[1] = x1; p.y[1] = y1;
    p.x[2] = x2; p.y[2] = y2;

    const double gx0 = -ISK__GUARD, gy0 = -ISK__GUARD;
    const double gx1 = c->width + ISK__GUARD, gy1 = c->height + ISK__GUARD;
    int outside = 0;
    for (int i = 0; i < 3; i++)
        if (!(p.x[i] >= gx0 && p.x[i] <= gx1 && p.y[i] >= gy0 && p.y[i] <= gy1))
            outside = 1;
    if (outside) {
        /* Far-away vertices: cut the triangle to the guard box first (the
         * shape on the canvas is unchanged up to rounding; only here is the
         * shared-edge guarantee approximate).  Coordinates are limited to
         * 1e150 so the clipping products cannot overflow. */
        for (int i = 0; i < 3; i++) {
            p.x[i] = isk__clampd(p.x[i], -1e150, 1e150);
            p.y[i] = isk__clampd(p.y[i], -1e150, 1e150);
        }
        isk__poly_orient(&p);
        isk__poly box;
        box.n = 4;
        box.x[0] = gx0; box.y[0] = gy0;
        box.x[1] = gx1; box.y[1] = gy0;
        box.x[2] = gx1; box.y[2] = gy1;
        box.x[3] = gx0; box.y[3] = gy1;
        isk__poly_clip(&p, &box);
        /* Absorb rounding and drop repeated vertices. */
        int m = 0;
        for (int i = 0; i < p.n; i++) {
            double x = isk__clampd(p.x[i], gx0, gx1), y = isk__clampd(p.y[i], gy0, gy1);
            if (m > 0 && x == p.x[m - 1] && y == p.y[m - 1])
                continue;
            p.x[m] = x; p.y[m] = y; m++;
        }
        while (m > 1 && p.x[m - 1] == p.x[0] && p.y[m - 1] == p.y[0])
            m--;
        p.n = m;
        if (p.n < 3)
            return;
    }
    double a2 = isk__poly_area2(&p);
    if (!(a2 != 0.0)) /* degenerate: no centre is strictly inside */
        return;
    isk__poly_orient(&p);
    fill_convex(c, &p, color, mode);
}
