/* SPDX-License-Identifier: MIT */
/* Batched drawing of a particle store through a view (isk_draw_dots,
 * isk_draw_dots_browser, isk_draw_pixels in iskra/view.h).
 *
 * One loop per (view kind, dot rule, blend mode), chosen once per batch:
 * the transform is isk_view_to_screen's arithmetic inlined (view/
 * view_transform.h's isk__view_axis_map, so the same doubles), the dot weights are raster/dot_kernel.h's
 * rules, the blend raster/blend_px.h's with the mode a constant and the
 * colour prepared once (a coverage table).  The result is byte-identical to
 * calling the single-dot functions in index order (tests/test_raster_fast.c).
 */
#include "iskra/view.h"

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "core/fast_paths.h"
#include "view/dot_block.h"
#include "view/view_transform.h"
#include "view/world_batch.h"


/* isk_draw_pixels, in blocks of PIXEL_BLOCK points: a first pass
 * transforms each point and finds its pixel (prefetching it: a random
 * access the hardware cannot guess), a second blends in index order.  The
 * colour is prepared once: its coverage-255 table entry, since
 * isk__px_lut(d, t, 255, mode) is isk__blend_px(d, col, mode) (div255(a*255) = a). */
#define PIXEL_BLOCK 64

/* The batch's k-th point: k itself, or the k-th entry of a list of indices
 * (a band's points, isk__draw_batch_list_rows).  `list` is a constant of
 * each inlined copy, so the plain batch pays nothing for it. */
#define POINT(list, k) ((list) ? (size_t)(list)[k] : (size_t)(k))

/* Point (X, Y)'s pixel offset into *off, and whether it lies on the tile
 * [X0, X1) x [Y0, Y1).  Without branches: on a band of a threaded draw
 * about half the points may be someone else's, in no order a predictor can
 * learn.  An outside point gets a harmless offset (the tile's first pixel)
 * and the caller does not count it; the test also keeps NaN and huge
 * values out of the conversions. */
static ISK__INLINE int pixel_offset(double X, double Y, double X0, double Y0, double X1, double Y1, size_t stride,
                                    size_t *off)
{
    const int in = (X >= X0) & (Y >= Y0) & (X < X1) & (Y < Y1);
    const double Xs = in ? X : X0, Ys = in ? Y : Y0;
    *off = (size_t)(int)Ys * stride + (size_t)(int)Xs * 4u;
    return in;
}

static ISK__INLINE void run_pixels(const isk_canvas *c, int r0, int r1, int c0, int c1, const isk_view *v, size_t n,
                                   const uint32_t *list, const double *x, const double *y, isk_color col,
                                   int camera, int keep, isk_blend mode)
{
    /* isk_view_to_screen's arithmetic (view_transform.h) */
    const isk__view_axis ax = isk__view_axis_x(v), ay = isk__view_axis_y(v);
    const double X0 = c0, X1 = c1, Y0 = r0, Y1 = r1;
    const size_t stride = c->stride;
    uint8_t *const pixels = c->pixels;
    /* A band of rows first runs the dots' select (dot_block.h: vector
     * compares, no branch): the compiler made a branch of the tile test,
     * and on two bands its mispredictions cost each band three times the
     * whole draw on one thread.  The select keeps lo < Y < hi, a superset
     * of the rows [r0, r1) (keep applied as below: the same doubles); the
     * tile test then runs on what it kept, nearly all inside.  The whole
     * canvas keeps nearly every point and goes without (the select cost it
     * 8-12 %). */
    const int banded = r0 > 0 || r1 < c->height;
    const select_fn select = pick_select();
    const select_view sv = {camera, keep, ay, Y0 - 1.0, Y1, c->height};
    isk__cov_lut t;
    isk__cov_lut_entry(&t, col, 255);
    size_t off[PIXEL_BLOCK];
    double by[PIXEL_BLOCK], yb[PIXEL_BLOCK];
    int32_t bix[PIXEL_BLOCK];
    for (size_t i0 = 0; i0 < n; i0 += PIXEL_BLOCK) {
        const int m = n - i0 < PIXEL_BLOCK ? (int)(n - i0) : PIXEL_BLOCK;
        size_t k = 0;
        if (banded) {
            const double *ys = y + i0;
            if (list) { /* a band's points: their y gathered into the block first */
                for (int q = 0; q < m; q++)
                    yb[q] = y[list[i0 + (size_t)q]];
                ys = yb;
            }
            const int kept = select(&sv, ys, m, by, bix);
            for (int q = 0; q < kept; q++) {
                const size_t j = POINT(list, i0 + (size_t)bix[q]);
                double X = isk__view_axis_map(ax, camera, x[j]);
                if (keep) /* a batch constant: the branch is hoisted */
                    X = isk__keep_on_canvas(X, c->width);
                const int in = pixel_offset(X, by[q], X0, Y0, X1, Y1, stride, &off[k]);
#if defined(__GNUC__)
                __builtin_prefetch(pixels + off[k], 1);
#endif
                k += (size_t)in;
            }
        } else {
            for (int q = 0; q < m; q++) {
                const size_t j = POINT(list, i0 + (size_t)q);
                double X = isk__view_axis_map(ax, camera, x[j]), Y = isk__view_axis_map(ay, camera, y[j]);
                if (keep) {
                    X = isk__keep_on_canvas(X, c->width);
                    Y = isk__keep_on_canvas(Y, c->height);
                }
                const int in = pixel_offset(X, Y, X0, Y0, X1, Y1, stride, &off[k]);
#if defined(__GNUC__)
                __builtin_prefetch(pixels + off[k], 1); /* a random access the hardware cannot guess */
#endif
                k += (size_t)in;
            }
        }
        for (size_t i = 0; i < k; i++)
            isk__px_lut(pixels + off[i], &t, 255, mode);
    }
}

/* The exact-area dot over a batch, in blocks of DOT_BLOCK points:
 *   1. transform the block (the view's arithmetic, as isk_view_to_screen),
 *      keeping the points that can touch the tile, gathered over blocks
 *      until at least DOT_BLOCK are kept (dot_block.h's DOT_BATCH);
 *   2. for each point whose 2x2 block is wholly on the canvas, its top-left
 *      pixel and four weights (raster/dot_kernel.h's rule; 4 or 8 points
 *      per step with AVX2 or AVX-512 when the CPU has it: the same IEEE
 *      operations in the same order, so the same doubles);
 *   3. blend in index order, the whole 2x2 block at once for source-over
 *      on opaque pixels, else two pixels of a row at a time (SSE2), from
 *      the batch's coverage table; a block cut by the canvas's last column
 *      or row or by the band's rows gets its weights all the same and
 *      blends only its pixels on them (DOT_EDGE); points off the canvas go
 *      through the single-dot kernel (clipping), in their turn.
 * Pass 2 is pure arithmetic, independent from point to point, so the
 * processor overlaps it freely.  The canvas's rows are not prefetched:
 * with the weights two groups at a time the blends' loads overlap well
 * enough on their own (the same time for points all over an 800x600
 * canvas), and where the points crowd into a small part of the canvas
 * the prefetches' own loop cost more than they saved (docs/vectorization.md).
 * The stages are view/dot_block.h's. */

/* The pixels of a DOT_EDGE point's block that lie on the tile's rows
 * [r0, r1) and columns [c0, c1) (the single dot's clipping,
 * isk__blend_2x2, with the weights already known; the top-left pixel is at
 * least at column c0 - 1 and row r0 - 1, and on the canvas). */
static ISK__INLINE void edge_row(uint8_t *p, int right, isk_color col, const isk__cov_lut *lut, uint32_t wa,
                                 uint32_t wb, isk_blend mode)
{
    if (right && lut) {
        px2(p, col, lut, wa, wb, mode);
    } else {
        isk__px_w(p, col, lut, wa, mode);
        if (right)
            isk__px_w(p + 4, col, lut, wb, mode);
    }
}

static ISK__INLINE void edge_block(uint8_t *pixels, size_t stride, int r0, int r1, int c0, int c1, int ix, int iy,
                                   const uint8_t w[4], isk_color col, const isk__cov_lut *lut, isk_blend mode)
{
    uint8_t *p = pixels + (size_t)ix * 4u;
    uint32_t wa = w[0], wb = w[1], wc = w[2], wd = w[3];
    int right = ix + 1 < c1;
    if (ix < c0) { /* only the right column is the tile's */
        p += 4;
        wa = wb;
        wc = wd;
        right = 0;
    }
    if (iy >= r0)
        edge_row(p + (size_t)iy * stride, right, col, lut, wa, wb, mode);
    if (iy + 1 < r1)
        edge_row(p + (size_t)(iy + 1) * stride, right, col, lut, wc, wd, mode);
}

/* A point's 2x2 block at p (rows p and p + stride), wholly on the tile,
 * at weights w (a block cut by the tile's edges: edge_block): the replay's
 * (isk__draw_batch_replay), the same blends as run_dots_blocked's loop
 * (tests/test_retain.c compares them in every mode). */
static ISK__INLINE void full_block(uint8_t *p, size_t stride, isk_color col, const isk__cov_lut *lut,
                                   const uint8_t w[4], isk_blend mode)
{
    if (lut) {
        px4(p, stride, col, lut, w, mode);
    } else {
        isk__px_cov(p, col, w[0], mode);
        isk__px_cov(p + 4, col, w[1], mode);
        isk__px_cov(p + stride, col, w[2], mode);
        isk__px_cov(p + stride + 4, col, w[3], mode);
    }
}

/* A blended point into the recording (world_batch.h): its block and
 * weights, or, for a point the single-dot kernel clips, the end of it. */
static ISK__INLINE void record_point(isk__dot_recording *rec, uint8_t fast, int ix, int iy, const uint8_t w[4])
{
    if (!fast) {
        rec->failed = 1;
        return;
    }
    isk__dot_rec *r = &rec->rec[rec->n++];
    r->ix = (uint16_t)ix; /* both in [0, ISK_CANVAS_MAX_DIM): the flag's bit is free */
    r->iy = (uint16_t)(iy | (fast == DOT_FULL ? ISK__REC_FULL : 0));
    memcpy(r->w, w, 4);
}

/* lut: the batch's coverage table (run_rule makes one for every batch it
 * draws here). */
static ISK__INLINE void run_dots_blocked(const isk_canvas *c, int r0, int r1, int c0, int c1, const isk_view *v, size_t n,
                                         const uint32_t *list, const double *x, const double *y, isk_color col,
                                         const isk__cov_lut *lut, int camera, int browser, int keep,
                                         isk__dot_recording *rec, isk_blend mode)
{
    const isk__view_axis ax = isk__view_axis_x(v), ay = isk__view_axis_y(v); /* view_transform.h */
    const double X0 = c0, X1 = c1 - 1.0, Y0 = r0, H1 = r1 - 1.0;
    /* A point whose dot cannot touch the rows [r0, r1) is dropped before
     * anything else is computed for it: the single-dot kernels' own row
     * test (so dropping it changes nothing), and on a band of a threaded
     * draw most points are someone else's. */
    const double lo = browser ? Y0 - 2.0 : Y0 - 1.0, hi = browser ? r1 + 1.0 : (double)r1;
    const size_t stride = c->stride;
    uint8_t *const pixels = c->pixels;
    const weights_fn weights = pick_weights(browser);
    const select_fn select = pick_select();
    const select_view sv = {camera, keep, ay, lo, hi, c->height};
    /* A band of columns (whole rows, no list) selects its points by their
     * X instead, with the same select on the X axis. */
    const int by_columns = !list && r0 == 0 && r1 == c->height && (c0 > 0 || c1 < c->width);
    const select_view sc = {camera, keep, ax, browser ? X0 - 2.0 : X0 - 1.0, browser ? c1 + 1.0 : (double)c1,
                            c->width};
    dot_block b;
    int have = 0; /* the batch's points (dot_block.h's DOT_BATCH) */
    for (size_t i0 = 0; i0 < n; i0 += DOT_BLOCK) {
        const int m = n - i0 < DOT_BLOCK ? (int)(n - i0) : DOT_BLOCK;
        /* b.ix: the point's place in its block, until the weights overwrite it */
        const double *yb = y + i0;
        double gathered[DOT_BLOCK];
        if (list) { /* a band's points: their y gathered into the block first */
            for (int k = 0; k < m; k++)
                gathered[k] = y[list[i0 + k]];
            yb = gathered;
        } else {
            dot_block_prefetch_ahead(x, y, i0, n);
        }
        int kept;
        if (by_columns) {
            kept = select(&sc, x + i0, m, b.x + have, b.ix + have);
            for (int k = have; k < have + kept; k++) {
                const double Y = select_screen(&sv, y[i0 + (size_t)b.ix[k]]);
                b.y[k] = keep ? isk__keep_on_canvas(Y, c->height) : Y;
            }
        } else {
            kept = select(&sv, yb, m, b.y + have, b.ix + have);
            for (int k = have; k < have + kept; k++) {
                const double xi = x[POINT(list, i0 + (size_t)b.ix[k])];
                const double X = isk__view_axis_map(ax, camera, xi);
                b.x[k] = keep ? isk__keep_on_canvas(X, c->width) : X;
            }
        }
        have += kept;
        const int last = i0 + (size_t)m >= n;
        if (have < DOT_BLOCK && !last)
            continue;
        /* the batch's whole steps, or at the end all of it */
        const int batch = last ? have : have / DOT_STEP * DOT_STEP;
        weights(&b, batch, X0, X1, Y0, H1);
        for (int k = 0; k < batch; k++) {
            if (rec) /* a constant of each inlined copy: the plain draws pay nothing */
                record_point(rec, b.fast[k], b.ix[k], b.iy[k], b.w[k]);
            if (b.fast[k] == DOT_EDGE) {
                edge_block(pixels, stride, r0, r1, c0, c1, b.ix[k], b.iy[k], b.w[k], col, lut, mode);
            } else if (b.fast[k]) { /* full_block's blends with the table (written out: through it, the
                                       compiler laid this loop out otherwise) */
                px4(pixels + (size_t)b.iy[k] * stride + (size_t)b.ix[k] * 4u, stride, col, lut, b.w[k], mode);
            } else if (browser) {
                isk__dot_browser_tile(c, r0, r1, c0, c1, b.x[k], b.y[k], col, lut, mode);
            } else {
                isk__dot_tile(c, r0, r1, c0, c1, b.x[k], b.y[k], col, lut, mode);
            }
        }
        for (int k = batch; k < have; k++) { /* fewer than DOT_STEP: to the next batch */
            b.x[k - batch] = b.x[k];
            b.y[k - batch] = b.y[k];
        }
        have -= batch;
    }
}

static ISK__INLINE void run_kind(const isk_canvas *c, int r0, int r1, int c0, int c1, const isk_view *v, size_t n,
                                 const uint32_t *list, const double *x, const double *y, isk_color col,
                                 const isk__cov_lut *lut, isk__batch_rule rule, int keep, isk__dot_recording *rec,
                                 isk_blend mode)
{
    const int camera = isk__view_is_camera(v);
    if (rule == ISK__BATCH_DOT && camera)
        run_dots_blocked(c, r0, r1, c0, c1, v, n, list, x, y, col, lut, 1, 0, keep, rec, mode);
    else if (rule == ISK__BATCH_DOT)
        run_dots_blocked(c, r0, r1, c0, c1, v, n, list, x, y, col, lut, 0, 0, keep, rec, mode);
    else if (rule == ISK__BATCH_DOT_BROWSER && camera)
        run_dots_blocked(c, r0, r1, c0, c1, v, n, list, x, y, col, lut, 1, 1, keep, rec, mode);
    else if (rule == ISK__BATCH_DOT_BROWSER)
        run_dots_blocked(c, r0, r1, c0, c1, v, n, list, x, y, col, lut, 0, 1, keep, rec, mode);
    else if (camera)
        run_pixels(c, r0, r1, c0, c1, v, n, list, x, y, col, 1, keep, mode);
    else
        run_pixels(c, r0, r1, c0, c1, v, n, list, x, y, col, 0, keep, mode);
}

/* Batches this short skip the 256-entry table: building it would cost
 * more than it saves.  They are drawn by the single-dot kernels, point by
 * point (run_dots_single), rather than by a copy of the blocked loop
 * without the table: the blocked loop is byte-identical to that anyway
 * (tests/test_raster_fast.c), and it is this file's bulk (a copy for every
 * entry point, blend mode, view kind and dot rule), which every CI build
 * waited for: without the table's copies, and with the recording's only
 * for the exact-area dot, it compiles in less than half the time
 * (docs/performance.md, "Where the constants come from"). */
#define LUT_MIN_BATCH 64

/* A short batch: each point through the view (isk_view_to_screen, whose
 * arithmetic the blocked loop inlines) and the single dot cut to the tile,
 * in index order. */
static ISK__INLINE void run_dots_single(const isk_canvas *c, int r0, int r1, int c0, int c1, const isk_view *v,
                                        size_t n, const uint32_t *list, const double *x, const double *y,
                                        isk_color col, int browser, int keep, isk_blend mode)
{
    for (size_t k = 0; k < n; k++) {
        const size_t i = POINT(list, k);
        double X, Y;
        isk_view_to_screen(v, x[i], y[i], &X, &Y);
        if (keep) {
            X = isk__keep_on_canvas(X, c->width);
            Y = isk__keep_on_canvas(Y, c->height);
        }
        if (browser)
            isk__dot_browser_tile(c, r0, r1, c0, c1, X, Y, col, NULL, mode);
        else
            isk__dot_tile(c, r0, r1, c0, c1, X, Y, col, NULL, mode);
    }
}

static ISK__INLINE void run_rule(const isk_canvas *c, int r0, int r1, int c0, int c1, const isk_view *v, size_t n,
                                 const uint32_t *list, const double *x, const double *y, isk_color col,
                                 unsigned rule, isk_blend mode)
{
    const int keep = (rule & ISK__BATCH_KEEP_ON_CANVAS) != 0;
    rule &= ~(unsigned)ISK__BATCH_KEEP_ON_CANVAS;
    isk__cov_lut lut;
    switch (rule) {
    case ISK__BATCH_DOT:
    case ISK__BATCH_DOT_BROWSER:
        if (!ISK__FAST_BATCH || n < LUT_MIN_BATCH) { /* the reference: one dot at a time */
            run_dots_single(c, r0, r1, c0, c1, v, n, list, x, y, col, rule == ISK__BATCH_DOT_BROWSER, keep, mode);
            break;
        }
        isk__cov_lut_init(&lut, col);
        if (rule == ISK__BATCH_DOT)
            run_kind(c, r0, r1, c0, c1, v, n, list, x, y, col, &lut, ISK__BATCH_DOT, keep, NULL, mode);
        else
            run_kind(c, r0, r1, c0, c1, v, n, list, x, y, col, &lut, ISK__BATCH_DOT_BROWSER, keep, NULL, mode);
        break;
    case ISK__BATCH_PIXEL:
        run_kind(c, r0, r1, c0, c1, v, n, list, x, y, col, NULL, ISK__BATCH_PIXEL, keep, NULL, mode);
        break;
    default:
        break;
    }
}

/* The exact-area dots recorded as they are drawn (the blocked loop, with
 * the table whatever the batch's size: only it knows the blocks). */
static ISK__INLINE void record_dots(const isk_canvas *c, int r0, int r1, int c0, int c1, const isk_view *v, size_t n,
                                    const uint32_t *list, const double *x, const double *y, isk_color col, int keep,
                                    isk__dot_recording *rec, isk_blend mode)
{
    isk__cov_lut lut;
    isk__cov_lut_init(&lut, col);
    run_kind(c, r0, r1, c0, c1, v, n, list, x, y, col, &lut, ISK__BATCH_DOT, keep, rec, mode);
}

/* The tile clamped to c: whether anything of it is left. */
static int clamp_tile(const isk_canvas *c, int *r0, int *r1, int *c0, int *c1)
{
    *r0 = *r0 < 0 ? 0 : *r0;
    *r1 = *r1 > c->height ? c->height : *r1;
    *c0 = *c0 < 0 ? 0 : *c0;
    *c1 = *c1 > c->width ? c->width : *c1;
    return *r0 < *r1 && *c0 < *c1;
}

/* Whether there is anything to draw, the tile clamped to the canvas. */
static int drawable(const isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y, int *r0,
                    int *r1, int *c0, int *c1)
{
    return c && c->pixels && v && x && y && n > 0 && clamp_tile(c, r0, r1, c0, c1);
}

void isk__draw_batch_tile(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                          isk_color col, isk_blend mode, unsigned rule, int r0, int r1, int c0, int c1)
{
    if (drawable(c, v, n, x, y, &r0, &r1, &c0, &c1))
        ISK__BLEND_DISPATCH(mode, run_rule, c, r0, r1, c0, c1, v, n, NULL, x, y, col, rule);
}

void isk__draw_batch_rows(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                          isk_color col, isk_blend mode, unsigned rule, int r0, int r1)
{
    isk__draw_batch_tile(c, v, n, x, y, col, mode, rule, r0, r1, 0, c ? c->width : 0);
}

/* isk__draw_batch_tile of list[0..m), or of every point when list is NULL
 * (each its own copy of the loops: a list's is read through it). */
static void draw_points(isk_canvas *c, const isk_view *v, const uint32_t *list, size_t m, const double *x,
                        const double *y, isk_color col, isk_blend mode, unsigned rule, int r0, int r1, int c0, int c1)
{
    if (!list)
        isk__draw_batch_tile(c, v, m, x, y, col, mode, rule, r0, r1, c0, c1);
    else if (drawable(c, v, m, x, y, &r0, &r1, &c0, &c1))
        ISK__BLEND_DISPATCH(mode, run_rule, c, r0, r1, c0, c1, v, m, list, x, y, col, rule);
}

void isk__draw_batch_list_rows(isk_canvas *c, const isk_view *v, const uint32_t *list, size_t m, const double *x,
                               const double *y, isk_color col, isk_blend mode, unsigned rule, int r0, int r1)
{
    if (list)
        draw_points(c, v, list, m, x, y, col, mode, rule, r0, r1, 0, c ? c->width : 0);
}

void isk__draw_batch_record(isk_canvas *c, const isk_view *v, size_t n, const uint32_t *list, const double *x,
                            const double *y, isk_color col, isk_blend mode, unsigned rule, int r0, int r1, int c0,
                            int c1, isk__dot_recording *rec)
{
    /* Only the exact-area dot is recorded: the browser's dot has no edge
     * blocks (it clips every one), and pixels have no weights. */
    if (!rec || (rule & ~(unsigned)ISK__BATCH_KEEP_ON_CANVAS) != ISK__BATCH_DOT) {
        if (rec)
            rec->failed = 1;
        draw_points(c, v, list, n, x, y, col, mode, rule, r0, r1, c0, c1);
        return;
    }
    const int keep = (rule & ISK__BATCH_KEEP_ON_CANVAS) != 0;
    if (drawable(c, v, n, x, y, &r0, &r1, &c0, &c1))
        ISK__BLEND_DISPATCH(mode, record_dots, c, r0, r1, c0, c1, v, n, list, x, y, col, keep, rec);
}

/* The recorded blends, in their order, as run_dots_blocked's loop does them. */
static ISK__INLINE void replay_rule(isk_canvas *c, const isk__dot_rec *rec, size_t n, isk_color col, int r0, int r1,
                                    int c0, int c1, isk_blend mode)
{
    isk__cov_lut table;
    const isk__cov_lut *lut = NULL; /* as run_rule's; the bytes are the same either way */
    if (n >= LUT_MIN_BATCH) {
        isk__cov_lut_init(&table, col);
        lut = &table;
    }
    for (size_t k = 0; k < n; k++) {
        const isk__dot_rec *r = &rec[k];
        const int iy = r->iy & (ISK__REC_FULL - 1u);
        if (r->iy & ISK__REC_FULL)
            full_block(c->pixels + (size_t)iy * c->stride + (size_t)r->ix * 4u, c->stride, col, lut, r->w, mode);
        else
            edge_block(c->pixels, c->stride, r0, r1, c0, c1, r->ix, iy, r->w, col, lut, mode);
    }
}

void isk__draw_batch_replay(isk_canvas *c, const isk__dot_rec *rec, size_t n, isk_color col, isk_blend mode, int r0,
                            int r1, int c0, int c1)
{
    if (c && c->pixels && rec && n > 0 && clamp_tile(c, &r0, &r1, &c0, &c1))
        ISK__BLEND_DISPATCH(mode, replay_rule, c, rec, n, col, r0, r1, c0, c1);
}

/* The view's Y axis, for select_screen and the selects (no keep). */
static select_view rows_view(const isk_view *v, double lo, double hi)
{
    return (select_view){.camera = isk__view_is_camera(v), .axis = isk__view_axis_y(v), .lo = lo, .hi = hi};
}

int isk__batch_select_rows(const isk_view *v, const double *y, int m, double lo, double hi, double *oy,
                           int32_t *oix)
{
    const select_view sv = rows_view(v, lo, hi);
    return pick_select()(&sv, y, m, oy, oix);
}

void isk__batch_bin(const isk_view *v, int height, const double *y, size_t i0, size_t i1, int reach,
                    const uint8_t *band_of_row, uint16_t *code, size_t *count)
{
    const select_view sv = rows_view(v, 0.0, 0.0);
    const double lo = -(reach + 1.0), hi = height + (double)reach;
    /* counted here and added at the end: the threads' count arrays share
     * cache lines, and a store to one every point would bounce them */
    size_t mine[256] = {0};
    unsigned nb = 0;
    for (size_t i = i0; i < i1; i++) {
        const double Y = select_screen(&sv, y[i]);
        uint16_t k = ISK__BIN_NONE;
        if (Y > lo && Y < hi) { /* also false for NaN; keeps the conversion defined */
            const int fy = (int)(Y + (reach + 1.0)) - (reach + 1); /* floor */
            const int rlo = fy - reach < 0 ? 0 : fy - reach;
            const int rhi = fy + reach >= height ? height - 1 : fy + reach;
            if (rlo <= rhi) {
                const unsigned first = band_of_row[rlo], last = band_of_row[rhi];
                k = (uint16_t)(first | last << 8);
                nb = last + 1 > nb ? last + 1 : nb;
                for (unsigned b = first; b <= last; b++)
                    mine[b]++;
            }
        }
        code[i] = k;
    }
    for (unsigned b = 0; b < nb; b++)
        count[b] += mine[b];
}

static void draw_batch(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                       isk_color col, isk_blend mode, unsigned rule)
{
    isk__draw_batch_rows(c, v, n, x, y, col, mode, rule, 0, c ? c->height : 0);
}

void isk_draw_dots(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                   isk_color color, isk_blend mode)
{
    draw_batch(c, v, n, x, y, color, mode, ISK__BATCH_DOT);
}

void isk_draw_dots_browser(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                           isk_color color, isk_blend mode)
{
    draw_batch(c, v, n, x, y, color, mode, ISK__BATCH_DOT_BROWSER);
}

void isk_draw_pixels(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                     isk_color color, isk_blend mode)
{
    draw_batch(c, v, n, x, y, color, mode, ISK__BATCH_PIXEL);
}
