/* SPDX-License-Identifier: MIT */
/* isk_stroke_trail: a fading ribbon through a particle's last positions
 * (the rule is in iskra/draw.h).
 *
 * The canvas under the trail is cut into tiles of TILE_W x TILE_H pixels.
 * For a tile, every segment near it visits the pixels within its reach
 * (rows of its bounding box, and in each row the columns the segment
 * crosses within that row's slab, widened by the reach) and records, per
 * pixel, the smallest squared distance, the segment and the fade parameter
 * there; a second pass turns each pixel's record into coverage and blends
 * it once.  A pixel's record depends only on the pixel and the whole trail
 * (segments are visited in order everywhere, ties go to the later one), so
 * tiles and bands of rows change no byte; the culling only skips segments
 * farther than the reach, which the rule ignores.  The geometry of the first
 * SEG_CACHE segments stays on the stack; later ones are recomputed.  Nothing
 * allocates. */
#include "iskra/draw.h"

#include <math.h>
#include <string.h>

#include "core/fast_paths.h"
#include "raster/blend_px.h"
#include "raster/clip.h"
#include "raster/trail_rows.h"

#define TILE_W 32
#define TILE_H 16
#define SEG_CACHE 64
#define MIN_WIDTH 0.5
#define MAX_WIDTH 4096.0
#define MAX_POINTS (1 << 28)
/* A pixel's square reaches at most sqrt(2)/2 beyond the band (this double
 * is just above it). */
#define HALF_DIAG 0.70710678118654757
/* The culling boxes are grown by this much more than the reach: far more
 * than the rounding of a box's bounds (their inputs are < 2^26). */
#define CULL_MARGIN (1.0 / 16.0)

typedef struct seg {
    double ax, ay, ex, ey; /* start and b - a */
    double il2, len;       /* 1 / |e|^2 (0 for a point) and |e| */
    double iey;            /* 1 / ey (0 when ey = 0) */
    double x0, y0, x1, y1; /* bounding box */
    int ok;                /* 0: wholly outside the guard box (no pixel, no length) */
} seg;

typedef struct trail {
    const double *xy;
    int n, nseg, guarded;
    double gx0, gy0, gx1, gy1; /* guard box */
    double hw, reach, total;   /* half width, reach of a pixel, length */
    double rtotal;             /* 1 / total (0 for a trail of length 0) */
    double gain, fade;         /* width / 0.5 below 0.5 px (else 1), fade in [0, 1] */
    seg cache[SEG_CACHE];
} trail;

static void make_seg(const trail *tr, int k, seg *s)
{
    int b = tr->n > 1 ? k + 1 : k; /* one point: a segment of length 0 */
    double ax = tr->xy[2 * k], ay = tr->xy[2 * k + 1], bx = tr->xy[2 * b], by = tr->xy[2 * b + 1];
    s->ok = 1;
    if (tr->guarded && !isk__clip_segment(&ax, &ay, &bx, &by, tr->gx0, tr->gy0, tr->gx1, tr->gy1)) {
        memset(s, 0, sizeof *s);
        return;
    }
    s->ax = ax;
    s->ay = ay;
    s->ex = bx - ax;
    s->ey = by - ay;
    double l2 = s->ex * s->ex + s->ey * s->ey;
    s->il2 = l2 > 0.0 ? 1.0 / l2 : 0.0;
    s->iey = s->ey != 0.0 ? 1.0 / s->ey : 0.0;
    s->len = sqrt(l2);
    s->x0 = ax < bx ? ax : bx;
    s->x1 = ax < bx ? bx : ax;
    s->y0 = ay < by ? ay : by;
    s->y1 = ay < by ? by : ay;
}

static inline const seg *get_seg(const trail *tr, int k, seg *tmp)
{
    if (k < SEG_CACHE)
        return &tr->cache[k];
    make_seg(tr, k, tmp);
    return tmp;
}

/* Squared distance from (px, py) to the segment; its nearest point's
 * parameter and the offset p - q. */
static inline double seg_d2(const seg *s, double px, double py, double *tau, double *dx, double *dy)
{
    double t = ((px - s->ax) * s->ex + (py - s->ay) * s->ey) * s->il2;
    t = t > 0.0 ? t : 0.0; /* max and min, branch-free */
    t = t < 1.0 ? t : 1.0;
    *dx = px - (s->ax + t * s->ex);
    *dy = py - (s->ay + t * s->ey);
    *tau = t;
    return *dx * *dx + *dy * *dy;
}

/* The coverage rule's area.  Projected onto a direction (U, V) (both >= 0,
 * not normalised), the unit pixel square centred at the origin spreads as
 * the sum of two uniform variables of widths U and V, so the part of it
 * with x.(U, V) <= t is the trapezoid's integral
 *   H(t) = [R(t + C) - R(t + E) - R(t - E) + R(t - C)] / (2 U V),
 *   R(x) = max(x, 0)^2, C = (U + V) / 2, E = |V - U| / 2,
 * exact, branch-free, one division; when one of U, V is below 2^-20 of the
 * other the square's corners are negligible (< 2^-23 of a pixel) and H is
 * the edge's linear ramp.  The band is lo <= x.(U, V) <= hi. */
static inline double ramp2(double x)
{
    x = x > 0.0 ? x : 0.0;
    return x * x;
}

static inline double band_area(double lo, double hi, double U, double V)
{
    double mn = U < V ? U : V, mx = U < V ? V : U;
    if (mn < 0x1p-20 * mx) {
        double a = 0.5 + hi / mx, b = 0.5 + lo / mx;
        a = a < 1.0 ? a : 1.0;
        b = b > 0.0 ? b : 0.0;
        return a > b ? a - b : 0.0;
    }
    double C = 0.5 * (mn + mx), E = 0.5 * (mx - mn);
    double h = ramp2(hi + C) - ramp2(hi + E) - ramp2(hi - E) + ramp2(hi - C);
    double l = ramp2(lo + C) - ramp2(lo + E) - ramp2(lo - E) + ramp2(lo - C);
    return (h - l) / (2.0 * U * V);
}

double isk__trail_band_area(double d, double nx, double ny, double w)
{
    return band_area(-0.5 * w - d, 0.5 * w - d, fabs(nx), fabs(ny));
}

/* The band across p - q, in units scaled by |p - q|, or across the
 * segment (direction (ex, ey), length len) when p is on it. */
double isk__trail_pixel_area(double dx, double dy, double hw, double ex, double ey, double len)
{
    double d2 = dx * dx + dy * dy;
    if (d2 > 0.0) {
        double d = sqrt(d2);
        return band_area(-hw * d - d2, hw * d - d2, fabs(dx), fabs(dy));
    }
    if (len > 0.0)
        return band_area(-hw * len, hw * len, fabs(ey), fabs(ex));
    return band_area(-hw, hw, 1.0, 0.0);
}

/* ---- one tile ------------------------------------------------------------ */

typedef struct tile {
    int x, y, w, h;
    double best[TILE_W * TILE_H]; /* squared distance of the nearest segment */
    double t[TILE_W * TILE_H];    /* fade parameter at its nearest point */
    int k[TILE_W * TILE_H];       /* that segment, -1: none within the reach */
} tile;

/* The pixels of the tile within the reach of segment k (whose arc length
 * starts at s0) take it when it is at least as near as their record.  A
 * segment spanning more than 2 R rows is cut to each row's slab; a shorter
 * one uses its bounding box's columns in every row. */
static void visit(const trail *tr, tile *tl, const seg *s, int k, double s0)
{
    const double R = tr->reach + CULL_MARGIN;
    int j0 = isk__floor_clamp(s->y0 - R - 0.5, tl->y - 1, tl->y + tl->h) + 1;
    int j1 = isk__floor_clamp(s->y1 + R - 0.5, tl->y - 1, tl->y + tl->h - 1) + 1;
    if (j0 < tl->y)
        j0 = tl->y;
    const double reach2 = tr->reach * tr->reach, rtotal = tr->rtotal, len = s->len;
    const int zero = !(tr->total > 0.0); /* a trail of length 0: t = 1 */
    const int slabs = s->y1 - s->y0 > 2.0 * R;
    int i0 = 0, i1 = 0;
    if (!slabs) {
        i0 = isk__floor_clamp(s->x0 - R - 0.5, tl->x - 1, tl->x + tl->w) + 1;
        i1 = isk__floor_clamp(s->x1 + R - 0.5, tl->x - 1, tl->x + tl->w - 1) + 1;
        if (i0 < tl->x)
            i0 = tl->x;
    }
    for (int j = j0; j < j1; j++) {
        double py = j + 0.5;
        if (slabs) { /* the part of the segment within the slab |y - py| <= R */
            double t0 = (py - R - s->ay) * s->iey, t1 = (py + R - s->ay) * s->iey;
            double ta = t0 < t1 ? t0 : t1, tb = t0 < t1 ? t1 : t0;
            ta = ta > 0.0 ? ta : 0.0;
            tb = tb < 1.0 ? tb : 1.0;
            if (ta > tb)
                continue;
            double xa = s->ax + ta * s->ex, xb = s->ax + tb * s->ex;
            i0 = isk__floor_clamp((xa < xb ? xa : xb) - R - 0.5, tl->x - 1, tl->x + tl->w) + 1;
            i1 = isk__floor_clamp((xa < xb ? xb : xa) + R - 0.5, tl->x - 1, tl->x + tl->w - 1) + 1;
            if (i0 < tl->x)
                i0 = tl->x;
        }
        double *best = tl->best + (j - tl->y) * TILE_W - tl->x, *tp = tl->t + (j - tl->y) * TILE_W - tl->x;
        int *kk = tl->k + (j - tl->y) * TILE_W - tl->x;
        /* the record, taken branch-free (the outcome is data) */
        for (int i = i0; i < i1; i++) {
            double tau, dx, dy, d2 = seg_d2(s, i + 0.5, py, &tau, &dx, &dy);
            double t = zero ? 1.0 : (s0 + tau * len) * rtotal;
            int take = (d2 <= best[i]) & (d2 <= reach2);
            best[i] = take ? d2 : best[i];
            tp[i] = take ? t : tp[i];
            kk[i] = take ? k : kk[i];
        }
    }
}

/* Whether the segment can reach a pixel centre in [X0, X1] x [Y0, Y1]
 * (the tile's, widened by the reach). */
static inline int reaches(const seg *s, double X0, double X1, double Y0, double Y1)
{
    return s->ok && s->x0 <= X1 && s->x1 >= X0 && s->y0 <= Y1 && s->y1 >= Y0;
}

/* The tile's pixel centres: [x0, x1] x [y0, y1]. */
typedef struct centres {
    double x0, x1, y0, y1;
} centres;

/* Squared distance from the segment's bounding box to the tile's pixel
 * centres: at most the distance from any of them to the segment. */
static inline double box_d2(const seg *s, const centres *b)
{
    double dx = s->x0 - b->x1 > b->x0 - s->x1 ? s->x0 - b->x1 : b->x0 - s->x1;
    double dy = s->y0 - b->y1 > b->y0 - s->y1 ? s->y0 - b->y1 : b->y0 - s->y1;
    dx = dx > 0.0 ? dx : 0.0;
    dy = dy > 0.0 ? dy : 0.0;
    return dx * dx + dy * dy;
}

/* On a wide trail every segment reaches every pixel of a tile, and each
 * pixel would be measured against all of them (docs/performance.md, "Where the constants come from").
 * A segment whose bounding
 * box lies farther from the tile's pixels than some segment's farthest
 * pixel is then nearest to none of them (a pixel takes the nearest, the
 * later of equals), so it is skipped.  This returns that farthest
 * distance, the least over the segments that reach the tile (the distance
 * to a segment is convex, so its largest over the tile is at a corner),
 * grown by far more than the rounding of the distances (< 2^-40 of them
 * here): any segment beyond it is strictly farther, and the bytes are
 * those of the full search.  INFINITY when no segment reaches the tile. */
#define WIDE_REACH 16.0
static double nearest_bound(const trail *tr, const centres *b, double X0, double X1, double Y0, double Y1)
{
    const double cx[4] = {b->x0, b->x1, b->x0, b->x1}, cy[4] = {b->y0, b->y0, b->y1, b->y1};
    double least = INFINITY;
    for (int k = 0; k < tr->nseg; k++) {
        seg tmp;
        const seg *s = get_seg(tr, k, &tmp);
        if (!reaches(s, X0, X1, Y0, Y1))
            continue;
        double most = 0.0;
        for (int q = 0; q < 4; q++) {
            double tau, dx, dy, d2 = seg_d2(s, cx[q], cy[q], &tau, &dx, &dy);
            most = d2 > most ? d2 : most;
        }
        least = most < least ? most : least;
    }
    return least * (1.0 + 0x1p-20) + 1.0;
}

/* Coverage of every recorded pixel, blended once (mode a constant). */
static ISK__INLINE void finish(isk_canvas *c, const trail *tr, const tile *tl, isk_color color, isk_blend mode)
{
    for (int j = 0; j < tl->h; j++) {
        uint8_t *row = c->pixels + (size_t)(tl->y + j) * c->stride + 4u * (size_t)tl->x;
        for (int i = 0; i < tl->w; i++) {
            int at = j * TILE_W + i, k = tl->k[at];
            if (k < 0)
                continue;
            seg tmp;
            const seg *s = get_seg(tr, k, &tmp);
            double tau, dx, dy;
            seg_d2(s, tl->x + i + 0.5, tl->y + j + 0.5, &tau, &dx, &dy);
            double area = isk__trail_pixel_area(dx, dy, tr->hw, s->ex, s->ey, s->len);
            double f = tr->gain * (1.0 - tr->fade * (1.0 - tl->t[at]));
            uint8_t cov = isk__coverage(area * f); /* clamps the area's last-bit overshoot */
            if (cov)
                isk__px_cov(row + 4 * i, color, cov, mode);
        }
    }
}

static void finish_replace(isk_canvas *c, const trail *tr, const tile *tl, isk_color col)
{
    finish(c, tr, tl, col, ISK_BLEND_REPLACE);
}
static void finish_over(isk_canvas *c, const trail *tr, const tile *tl, isk_color col)
{
    finish(c, tr, tl, col, ISK_BLEND_OVER);
}
static void finish_add(isk_canvas *c, const trail *tr, const tile *tl, isk_color col)
{
    finish(c, tr, tl, col, ISK_BLEND_ADD);
}
typedef void (*finish_fn)(isk_canvas *, const trail *, const tile *, isk_color);
static const finish_fn FINISH[ISK_BLEND_COUNT] = {
    [ISK_BLEND_REPLACE] = finish_replace, [ISK_BLEND_OVER] = finish_over, [ISK_BLEND_ADD] = finish_add};

void isk__stroke_trail_rows(isk_canvas *c, const double *xy, int n, double width, isk_color color, double fade,
                            isk_blend mode, int r0, int r1)
{
    if (!isk__canvas_ok(c) || !xy || n < 1 || n > MAX_POINTS)
        return;
    if (mode != ISK_BLEND_REPLACE && mode != ISK_BLEND_OVER && mode != ISK_BLEND_ADD)
        return;
    if (!(width > 0.0 && width <= MAX_WIDTH) || isnan(fade))
        return;
    trail tr;
    tr.xy = xy;
    tr.n = n;
    tr.nseg = n > 1 ? n - 1 : 1;
    tr.gx0 = -ISK__GUARD;
    tr.gy0 = -ISK__GUARD;
    tr.gx1 = c->width + ISK__GUARD;
    tr.gy1 = c->height + ISK__GUARD;
    tr.guarded = 0;
    for (int k = 0; k < 2 * n; k += 2) {
        double x = xy[k], y = xy[k + 1];
        if (!isk__finite2(x, y))
            return;
        if (!(x >= tr.gx0 && x <= tr.gx1 && y >= tr.gy0 && y <= tr.gy1))
            tr.guarded = 1;
    }
    tr.hw = 0.5 * (width < MIN_WIDTH ? MIN_WIDTH : width);
    tr.gain = width < MIN_WIDTH ? width / MIN_WIDTH : 1.0;
    tr.reach = tr.hw + HALF_DIAG;
    tr.fade = fade < 0.0 ? 0.0 : fade > 1.0 ? 1.0 : fade;

    /* length and bounding box, the first segments kept */
    double total = 0.0, bx0 = INFINITY, by0 = INFINITY, bx1 = -INFINITY, by1 = -INFINITY;
    for (int k = 0; k < tr.nseg; k++) {
        seg tmp, *s = k < SEG_CACHE ? &tr.cache[k] : &tmp;
        make_seg(&tr, k, s);
        if (!s->ok)
            continue;
        total += s->len;
        bx0 = s->x0 < bx0 ? s->x0 : bx0;
        by0 = s->y0 < by0 ? s->y0 : by0;
        bx1 = s->x1 > bx1 ? s->x1 : bx1;
        by1 = s->y1 > by1 ? s->y1 : by1;
    }
    if (!(bx0 <= bx1))
        return;
    tr.total = total;
    tr.rtotal = total > 0.0 ? 1.0 / total : 0.0;
    int i0 = isk__floor_clamp(bx0 - tr.reach, 0, c->width), i1 = isk__floor_clamp(bx1 + tr.reach, -1, c->width - 1) + 1;
    int j0 = isk__floor_clamp(by0 - tr.reach, 0, c->height), j1 = isk__floor_clamp(by1 + tr.reach, -1, c->height - 1) + 1;
    if (j0 < r0)
        j0 = r0;
    if (j1 > r1)
        j1 = r1;
    if (i0 >= i1 || j0 >= j1)
        return;

    tile tl;
    const double R = tr.reach + CULL_MARGIN;
    for (int ty = j0; ty < j1; ty += TILE_H)
        for (int tx = i0; tx < i1; tx += TILE_W) {
            tl.x = tx;
            tl.y = ty;
            tl.w = i1 - tx < TILE_W ? i1 - tx : TILE_W;
            tl.h = j1 - ty < TILE_H ? j1 - ty : TILE_H;
            for (int j = 0; j < tl.h; j++)
                for (int i = 0; i < tl.w; i++) {
                    tl.best[j * TILE_W + i] = INFINITY;
                    tl.k[j * TILE_W + i] = -1;
                }
            /* pixel centres of the tile, and widened by the reach */
            const centres b = {tx + 0.5, tx + tl.w - 0.5, ty + 0.5, ty + tl.h - 0.5};
            const double X0 = b.x0 - R, X1 = b.x1 + R, Y0 = b.y0 - R, Y1 = b.y1 + R;
            const int wide = ISK__FAST_CULL && tr.reach >= WIDE_REACH; /* the reference: every segment */
            const double far = wide ? nearest_bound(&tr, &b, X0, X1, Y0, Y1) : INFINITY;
            double s0 = 0.0;
            for (int k = 0; k < tr.nseg; k++) {
                seg tmp;
                const seg *s = get_seg(&tr, k, &tmp);
                if (reaches(s, X0, X1, Y0, Y1) && !(wide && box_d2(s, &b) > far))
                    visit(&tr, &tl, s, k, s0);
                s0 += s->len;
            }
            FINISH[mode](c, &tr, &tl, color);
        }
}

void isk_stroke_trail(isk_canvas *c, const double *xy, int n, double width, isk_color color, double fade,
                      isk_blend mode)
{
    isk__stroke_trail_rows(c, xy, n, width, color, fade, mode, 0, c ? c->height : 0);
}
