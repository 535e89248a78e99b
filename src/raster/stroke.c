/* SPDX-License-Identifier: MIT */
/* Anti-aliased width-1 strokes that look like HTML canvas stroke(): a single
 * segment (isk_stroke_line) and a whole path drawn as one shape
 * (isk_stroke_polyline; a line is a path of two points, so both agree).
 *
 * The shape is the union of convex "pieces": one rectangle of half-width 0.5
 * per segment (butt caps) and one join polygon per interior vertex (bevel
 * triangle, plus the miter triangle when the miter ratio 1/sin(θ/2) <= 10, as
 * canvas's default miterLimit).  Coverage of a pixel is the exact area of the
 * union inside it:
 *   - 1 piece touches the pixel: area of piece ∩ pixel (Sutherland–Hodgman);
 *   - 2 or 3 pieces (every join): inclusion–exclusion, each term the exact
 *     area of an intersection of convex polygons;
 *   - 4 or more (only where very short segments crowd one pixel): 16x16
 *     supersampling, exactly 256 samples at (i + (s+0.5)/16, j + (t+0.5)/16),
 *     coverage = (count*255 + 128) / 256 (rounded, half up).
 * Areas become bytes by the rule in clip.h: floor(255*a + 0.5).  Every pixel
 * is blended once, so joins are not painted twice.
 *
 * Cost: each row scans every piece and each touched pixel rescans them, so a
 * path of n points costs O(touched pixels * n); geometry of the first
 * PIECE_CACHE pieces is kept on the stack, further pieces are recomputed.
 * Nothing allocates.
 */
#include "iskra/draw.h"

#include "raster/clip.h"

#define MARGIN 8.0      /* segments are clipped to the canvas grown by this */
#define PIECE_CACHE 64
#define MITER_LIMIT 10.0

typedef struct piece {
    int n; /* 0: empty piece */
    double x[4], y[4];
    double x0, y0, x1, y1; /* bounding box */
} piece;

typedef struct path {
    const double *xy;
    int n, closed, nseg, npieces;
    double bx0, by0, bx1, by1; /* clip box */
    piece cache[PIECE_CACHE];
    double span_a[PIECE_CACHE], span_b[PIECE_CACHE]; /* current row */
} path;

static int same_point(const double *xy, int a, int b)
{
    return xy[2 * a] == xy[2 * b] && xy[2 * a + 1] == xy[2 * b + 1];
}

/* Unit direction from point a to point b; 0 when they coincide.  Half
 * differences keep huge coordinates from overflowing. */
static int unit_dir(const double *xy, int a, int b, double *ux, double *uy)
{
    double hx = 0.5 * xy[2 * b] - 0.5 * xy[2 * a];
    double hy = 0.5 * xy[2 * b + 1] - 0.5 * xy[2 * a + 1];
    double len = hypot(hx, hy);
    if (!(len > 0.0) || !isfinite(len))
        return 0;
    *ux = hx / len;
    *uy = hy / len;
    return 1;
}

static void piece_finish(piece *p)
{
    isk__poly q;
    q.n = p->n;
    for (int i = 0; i < p->n; i++) { q.x[i] = p->x[i]; q.y[i] = p->y[i]; }
    isk__poly_orient(&q);
    for (int i = 0; i < p->n; i++) { p->x[i] = q.x[i]; p->y[i] = q.y[i]; }
    p->x0 = p->x1 = p->x[0];
    p->y0 = p->y1 = p->y[0];
    for (int i = 1; i < p->n; i++) {
        if (p->x[i] < p->x0) p->x0 = p->x[i];
        if (p->x[i] > p->x1) p->x1 = p->x[i];
        if (p->y[i] < p->y0) p->y0 = p->y[i];
        if (p->y[i] > p->y1) p->y1 = p->y[i];
    }
}

static void make_segment(const path *ph, int s, piece *p)
{
    int a = s, b = (s + 1) % ph->n;
    double ux, uy;
    p->n = 0;
    if (same_point(ph->xy, a, b) || !unit_dir(ph->xy, a, b, &ux, &uy))
        return;
    double ax = ph->xy[2 * a], ay = ph->xy[2 * a + 1];
    double bx = ph->xy[2 * b], by = ph->xy[2 * b + 1];
    if (!isk__clip_segment(&ax, &ay, &bx, &by, ph->bx0, ph->by0, ph->bx1, ph->by1))
        return;
    /* The normal comes from the unclipped points so that it matches the
     * join polygons bit for bit. */
    double nx = -uy * 0.5, ny = ux * 0.5;
    p->n = 4;
    p->x[0] = ax + nx; p->y[0] = ay + ny;
    p->x[1] = bx + nx; p->y[1] = by + ny;
    p->x[2] = bx - nx; p->y[2] = by - ny;
    p->x[3] = ax - nx; p->y[3] = ay - ny;
    piece_finish(p);
}

static void make_join(const path *ph, int v, piece *p)
{
    const double *xy = ph->xy;
    int n = ph->n;
    p->n = 0;
    if (!ph->closed && (v < 1 || v > n - 2))
        return;
    int next = (v + 1) % n;
    /* Only the last point of a run of repeated points carries the join. */
    if (same_point(xy, v, next))
        return;
    int prev = v, steps = 0;
    do {
        prev = prev - 1;
        if (prev < 0) {
            if (!ph->closed)
                return;
            prev = n - 1;
        }
    } while (same_point(xy, prev, v) && ++steps < n);
    if (same_point(xy, prev, v))
        return;
    double vx = xy[2 * v], vy = xy[2 * v + 1];
    /* A join reaches at most MITER_LIMIT/2 px from its vertex. */
    if (!(vx >= ph->bx0 && vx <= ph->bx1 && vy >= ph->by0 && vy <= ph->by1))
        return;
    double u1x, u1y, u2x, u2y;
    if (!unit_dir(xy, prev, v, &u1x, &u1y) || !unit_dir(xy, v, next, &u2x, &u2y))
        return;
    double cross = u1x * u2y - u1y * u2x;
    if (cross == 0.0) /* straight on, or a U-turn whose bevel and miter are empty */
        return;
    /* Outer side: away from the turn.  These offsets equal the segments'
     * half-width normals (same products), so the join shares their corners. */
    double o1x = -u1y * 0.5, o1y = u1x * 0.5, o2x = -u2y * 0.5, o2y = u2x * 0.5;
    if (cross > 0.0) {
        o1x = -o1x; o1y = -o1y; o2x = -o2x; o2y = -o2y;
    }
    p->x[0] = vx;       p->y[0] = vy;
    p->x[1] = vx + o1x; p->y[1] = vy + o1y;
    /* cos of the angle between the outer normals; miter ratio^2 = 2/(1+c). */
    double cdot = 4.0 * (o1x * o2x + o1y * o2y);
    if (1.0 + cdot > 0.0 && 2.0 / (1.0 + cdot) <= MITER_LIMIT * MITER_LIMIT) {
        double k = 1.0 / (1.0 + cdot);
        p->x[2] = vx + (o1x + o2x) * k; p->y[2] = vy + (o1y + o2y) * k;
        p->x[3] = vx + o2x; p->y[3] = vy + o2y;
        p->n = 4;
    } else {
        p->x[2] = vx + o2x; p->y[2] = vy + o2y;
        p->n = 3;
    }
    piece_finish(p);
}

/* Piece k: even k is segment k/2, odd k the join at the end of that segment. */
static void make_piece(const path *ph, int k, piece *p)
{
    if (k % 2 == 0)
        make_segment(ph, k / 2, p);
    else
        make_join(ph, (k / 2 + 1) % ph->n, p);
}

static const piece *get_piece(const path *ph, int k, piece *tmp)
{
    if (k < PIECE_CACHE)
        return &ph->cache[k];
    make_piece(ph, k, tmp);
    return tmp;
}

/* x extent of piece ∩ strip y in [y0, y1]; 0 when they do not meet. */
static int strip_span(const piece *p, double y0, double y1, double *xa, double *xb)
{
    if (p->n == 0 || p->y1 < y0 || p->y0 > y1)
        return 0;
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0, j = p->n - 1; i < p->n; j = i++) {
        double ax = p->x[j], ay = p->y[j], bx = p->x[i], by = p->y[i];
        double ta = 0.0, tb = 1.0, dy = by - ay;
        if (dy == 0.0) {
            if (ay < y0 || ay > y1)
                continue;
        } else {
            double t0 = (y0 - ay) / dy, t1 = (y1 - ay) / dy;
            if (t0 > t1) { double t = t0; t0 = t1; t1 = t; }
            if (t0 > ta) ta = t0;
            if (t1 < tb) tb = t1;
            if (ta > tb)
                continue;
        }
        double x0 = ax + ta * (bx - ax), x1 = ax + tb * (bx - ax);
        if (x0 < lo) lo = x0;
        if (x0 > hi) hi = x0;
        if (x1 < lo) lo = x1;
        if (x1 > hi) hi = x1;
    }
    *xa = lo;
    *xb = hi;
    return lo <= hi;
}

static int row_span(path *ph, int k, int j, double *xa, double *xb)
{
    if (k < PIECE_CACHE) {
        *xa = ph->span_a[k];
        *xb = ph->span_b[k];
        return *xa <= *xb;
    }
    piece tmp;
    const piece *p = get_piece(ph, k, &tmp);
    return strip_span(p, j, j + 1.0, xa, xb);
}

static void to_poly(const piece *p, isk__poly *q)
{
    q->n = p->n;
    for (int i = 0; i < p->n; i++) { q->x[i] = p->x[i]; q->y[i] = p->y[i]; }
}

#define MAX_TOUCH 16

/* 16x16 supersampled coverage of the union of the given pieces. */
static uint8_t supersample(const isk__poly *q, int count, int i, int j)
{
    int hits = 0;
    for (int t = 0; t < 16; t++) {
        double y = j + (t + 0.5) / 16.0;
        for (int s = 0; s < 16; s++) {
            double x = i + (s + 0.5) / 16.0;
            for (int k = 0; k < count; k++)
                if (isk__poly_contains(&q[k], x, y)) {
                    hits++;
                    break;
                }
        }
    }
    return (uint8_t)((hits * 255 + 128) / 256);
}

static uint8_t pixel_coverage(const isk__poly *q, int count, int i, int j)
{
    double px = i, py = j, a;
    switch (count) {
    case 1:
        a = isk__pixel_area(px, py, &q[0], NULL, NULL);
        break;
    case 2:
        a = isk__pixel_area(px, py, &q[0], NULL, NULL) + isk__pixel_area(px, py, &q[1], NULL, NULL) -
            isk__pixel_area(px, py, &q[0], &q[1], NULL);
        break;
    case 3:
        a = isk__pixel_area(px, py, &q[0], NULL, NULL) + isk__pixel_area(px, py, &q[1], NULL, NULL) +
            isk__pixel_area(px, py, &q[2], NULL, NULL) - isk__pixel_area(px, py, &q[0], &q[1], NULL) -
            isk__pixel_area(px, py, &q[0], &q[2], NULL) - isk__pixel_area(px, py, &q[1], &q[2], NULL) +
            isk__pixel_area(px, py, &q[0], &q[1], &q[2]);
        break;
    default:
        return supersample(q, count, i, j);
    }
    return isk__coverage(a);
}

/* Coverage when more than MAX_TOUCH pieces touch the pixel (pathological
 * paths): supersample against every piece. */
static uint8_t crowded_coverage(path *ph, int i, int j)
{
    int hits = 0;
    for (int t = 0; t < 16; t++) {
        double y = j + (t + 0.5) / 16.0;
        for (int s = 0; s < 16; s++) {
            double x = i + (s + 0.5) / 16.0;
            for (int k = 0; k < ph->npieces; k++) {
                piece tmp;
                const piece *p = get_piece(ph, k, &tmp);
                if (p->n == 0 || x < p->x0 || x > p->x1 || y < p->y0 || y > p->y1)
                    continue;
                isk__poly q;
                to_poly(p, &q);
                if (isk__poly_contains(&q, x, y)) {
                    hits++;
                    break;
                }
            }
        }
    }
    return (uint8_t)((hits * 255 + 128) / 256);
}

static void draw_path(isk_canvas *c, path *ph, isk_color color, isk_blend mode)
{
    double ymin = INFINITY, ymax = -INFINITY;
    for (int k = 0; k < ph->npieces; k++) {
        piece tmp;
        if (k < PIECE_CACHE)
            make_piece(ph, k, &ph->cache[k]);
        const piece *p = get_piece(ph, k, &tmp);
        if (p->n == 0)
            continue;
        if (p->y0 < ymin) ymin = p->y0;
        if (p->y1 > ymax) ymax = p->y1;
    }
    if (!(ymin <= ymax))
        return;
    int j0 = isk__floor_clamp(ymin, -1, c->height), j1 = isk__floor_clamp(ymax, -1, c->height);
    if (j0 < 0) j0 = 0;
    if (j1 > c->height - 1) j1 = c->height - 1;
    int ncache = ph->npieces < PIECE_CACHE ? ph->npieces : PIECE_CACHE;
    for (int j = j0; j <= j1; j++) {
        double first = INFINITY;
        for (int k = 0; k < ph->npieces; k++) {
            double xa, xb;
            int hit;
            if (k < ncache) {
                hit = strip_span(&ph->cache[k], j, j + 1.0, &xa, &xb);
                ph->span_a[k] = hit ? xa : 1.0;
                ph->span_b[k] = hit ? xb : 0.0;
            } else {
                hit = row_span(ph, k, j, &xa, &xb);
            }
            if (hit && xb > 0.0 && xa < first)
                first = xa;
        }
        if (!(first < c->width))
            continue;
        int i = isk__floor_clamp(first, 0, c->width);
        while (i < c->width) {
            isk__poly q[MAX_TOUCH];
            int count = 0;
            double next = INFINITY;
            for (int k = 0; k < ph->npieces; k++) {
                double xa, xb;
                if (!row_span(ph, k, j, &xa, &xb) || xb <= i)
                    continue;
                if (xa < i + 1.0) {
                    if (count < MAX_TOUCH) {
                        piece tmp;
                        to_poly(get_piece(ph, k, &tmp), &q[count]);
                    }
                    count++;
                    if (xb > i + 1.0 && i + 1.0 < next)
                        next = i + 1.0;
                } else if (xa < next) {
                    next = xa;
                }
            }
            if (count > 0) {
                uint8_t cov = count <= MAX_TOUCH ? pixel_coverage(q, count, i, j)
                                                 : crowded_coverage(ph, i, j);
                isk_blend_pixel_cov(isk_canvas_at(c, i, j), color, cov, mode);
            }
            if (!(next < c->width))
                break;
            int ni = isk__floor_clamp(next, 0, c->width);
            i = ni > i ? ni : i + 1;
        }
    }
}

void isk_stroke_polyline(isk_canvas *c, const double *xy, int n, int closed,
                         isk_color color, isk_blend mode)
{
    if (!isk__canvas_ok(c) || !xy || n < 2)
        return;
    for (int k = 0; k < 2 * n; k++)
        if (!isfinite(xy[k]))
            return;
    /* A path of 2^30 or more points cannot be indexed by int pieces. */
    if (n > (1 << 29))
        return;
    path ph;
    ph.xy = xy;
    ph.n = n;
    ph.closed = closed != 0;
    ph.nseg = ph.closed ? n : n - 1;
    ph.npieces = 2 * ph.nseg;
    ph.bx0 = -MARGIN;
    ph.by0 = -MARGIN;
    ph.bx1 = c->width + MARGIN;
    ph.by1 = c->height + MARGIN;
    draw_path(c, &ph, color, mode);
}

void isk_stroke_line(isk_canvas *c, double x0, double y0, double x1, double y1,
                     isk_color color, isk_blend mode)
{
    const double xy[4] = {x0, y0, x1, y1};
    isk_stroke_polyline(c, xy, 2, 0, color, mode);
}
