/* SPDX-License-Identifier: MIT */
/* src/view/dot_block.h — the stages of a batched dot draw over a block of
 * points (world_batch.c: a store drawn onto a band of rows), in a header of
 * their own so that tests/test_dot_block.c can check every build of them,
 * including those the CPU does not pick (internal).
 *
 *   select   which points of the block can touch rows (lo, hi): their
 *            screen Y, in block order;
 *   weights  for each selected point whose 2x2 block lies wholly on the
 *            canvas, its top-left pixel and its four exact-area weights
 *            (raster/dot_kernel.h's rule; the browser rule's integer
 *            weights);
 *   px2      two pixels of a row blended from a coverage table;
 *   px4      a point's whole 2x2 block (source-over on opaque pixels in
 *            one set of lanes, anything else px2 a row at a time).
 *
 * Every stage does the single-dot kernels' IEEE operations in their order,
 * so anything built from them draws the bytes of the loop of single calls.
 * The functions here are the plain ones (static inline: each includer
 * keeps the ones it uses) and pick their twins: px2 and px4 in SSE2
 * (dot_block_sse2.h) or, on other targets, vector extensions
 * (dot_block_vector.h), the weights and the select in AVX2
 * (dot_block_avx2.c, 4 points a step) and AVX-512 (dot_block_avx512.c, 8),
 * chosen at run time by pick_weights and pick_select. */
#ifndef ISKRA_VIEW_DOT_BLOCK_H
#define ISKRA_VIEW_DOT_BLOCK_H

#include <stdint.h>
#include <string.h>

#include "core/cpu.h"
#include "iskra/canvas.h"
#include "raster/blend_px.h"
#include "raster/dot_kernel.h"
#include "view/view_transform.h"
#include "view/world_batch.h" /* isk__keep_on_canvas */
#if ISK__CPU_SSE2
#include "view/dot_block_sse2.h"
#elif ISK__CPU_VECTOR
#include "view/dot_block_vector.h"
#endif

/* Points per block.  On a band of a threaded draw only part of a block is
 * kept, and with blocks of 32 the few kept points left the weights and the
 * prefetches little to overlap: a half band (every other point kept) cost
 * 0.65 of the whole canvas, 0.60 with 64, where the same points kept in one
 * run cost 0.51 (the whole canvas itself the same; 96 and 128 made it
 * slower). */
#define DOT_BLOCK 64

/* The weights run in steps of DOT_STEP points (WEIGHTS_GROUPS groups of 8
 * lanes), and a step's lanes past the last point are work thrown away.  On
 * a band only part of each block is kept, a varying number, so the kept
 * points of successive blocks are gathered into one batch and the weights
 * and blends run on the batch's whole steps (at least DOT_BLOCK points),
 * the few left over carried to the next batch (docs/performance.md, "Where the constants come from").
 * A batch holds fewer than
 * DOT_BLOCK points gathered so far and a block's kept points, and the
 * selects' and the weights' whole-vector stores past them (which stay
 * within a block's DOT_BLOCK entries after where it starts). */
#define DOT_STEP 16
#define DOT_BATCH (2 * DOT_BLOCK)

typedef struct dot_block {
    double x[DOT_BATCH], y[DOT_BATCH];
    int32_t ix[DOT_BATCH], iy[DOT_BATCH];
    uint8_t w[DOT_BATCH][4];
    uint8_t fast[DOT_BATCH];
} dot_block;

/* Blocks ahead whose positions are prefetched: the store is read in
 * order, but the blends between its reads hold the processor's few line
 * fills, and a 10^6-point frame drew about 10 % faster with the positions
 * asked for early (any distance from 2 to 32 blocks did the same). */
#define DOT_AHEAD 4

/* Prefetches the x and y of the block DOT_AHEAD blocks after the one at
 * point s, when it is before `end`. */
static ISK__INLINE void dot_block_prefetch_ahead(const double *x, const double *y, size_t s, size_t end)
{
#if defined(__GNUC__)
    const size_t t = s + DOT_AHEAD * DOT_BLOCK;
    if (t + DOT_BLOCK <= end)
        for (int q = 0; q < DOT_BLOCK; q += 8) { /* 8 doubles a line */
            __builtin_prefetch(x + t + q, 0);
            __builtin_prefetch(y + t + q, 0);
        }
#else
    (void)x, (void)y, (void)s, (void)end;
#endif
}

/* fast[k], for the tile of columns [X0, X1 + 1] and rows [Y0, H1 + 1]
 * (X0, Y0 >= 0; the whole canvas: X0 = Y0 = 0, X1 and H1 its last column
 * and row):
 *   DOT_FULL  the point's whole 2x2 block lies on the tile;
 *   DOT_EDGE  its top-left pixel is on the tile or just left of or above
 *             it (X in [max(X0 - 1, 0), X1 + 1), Y in [max(Y0 - 1, 0),
 *             H1 + 1)) but the block is cut by the tile's edge: the
 *             weights are computed all the same, and the blend skips the
 *             pixels off the tile (what the single dot's clipping does).  Reflect walls hold their resting particles
 *             on the far edges (isk__keep_on_canvas), so a scene settled on
 *             its floor is almost all edge points: through the single-dot
 *             kernel they cost 3.7 times as much;
 *   DOT_OTHER anything else (off the canvas, negative, NaN): the single
 *             dot's kernel. */
enum { DOT_OTHER = 0, DOT_FULL = 1, DOT_EDGE = 2 };
typedef void (*weights_fn)(dot_block *b, int m, double X0, double X1, double Y0, double H1);

/* The lowest X or Y of an edge point (the truncations below need >= 0). */
static ISK__INLINE double dot_edge_first(double first)
{
    return first >= 1.0 ? first - 1.0 : 0.0;
}

static ISK__INLINE void weight_one(dot_block *b, int k, double X0, double X1, double Y0, double H1)
{
    double X = b->x[k], Y = b->y[k];
    /* the whole 2x2 block on the tile: floor(X) in [X0, X1 - 1] */
    const double Xe = dot_edge_first(X0), Ye = dot_edge_first(Y0);
    const int full = (X >= X0) & (X < X1) & (Y >= Y0) & (Y < H1);
    const int edge = (X >= Xe) & (X < X1 + 1.0) & (Y >= Ye) & (Y < H1 + 1.0);
    b->fast[k] = (uint8_t)(full ? DOT_FULL : edge ? DOT_EDGE : DOT_OTHER);
    if (!edge)
        return;
    int ix = (int)X, iy = (int)Y; /* >= 0: truncation is floor */
    uint32_t w[4];
    isk__dot_weights_frac(X - ix, Y - iy, w);
    b->ix[k] = ix;
    b->iy[k] = iy;
    for (int q = 0; q < 4; q++)
        b->w[k][q] = (uint8_t)w[q];
}

static inline void weights_scalar(dot_block *b, int m, double X0, double X1, double Y0, double H1)
{
    for (int k = 0; k < m; k++)
        weight_one(b, k, X0, X1, Y0, H1);
}

/* The vector weights take WEIGHTS_GROUPS groups of points through each
 * step side by side.  One group is a chain of about 60 dependent
 * operations, more than the processor's floating-point queue looks past,
 * so one at a time it waited on each latency in turn; three, four or
 * eight did no better than two (docs/performance.md, "Where the constants come from"). */
#define WEIGHTS_GROUPS 2

/* The browser rule's weights (integer arithmetic, already cheap). */
static inline void weights_browser(dot_block *b, int m, double X0, double X1, double Y0, double H1)
{
    for (int k = 0; k < m; k++) {
        double X = b->x[k], Y = b->y[k];
        int ix, iy;
        uint32_t w[4];
        /* isk__dot_browser's range test, then its weights; fast when the
         * 2x2 block is wholly on the tile */
        const int full = X > X0 - 2.0 && X < X1 + 2.0 && Y > Y0 - 2.0 && Y < H1 + 2.0 &&
                         isk__dot_weights_browser(X, Y, &ix, &iy, w) && ix >= X0 && ix < X1 && iy >= Y0 && iy < H1;
        b->fast[k] = full ? DOT_FULL : DOT_OTHER;
        if (!b->fast[k])
            continue;
        b->ix[k] = ix;
        b->iy[k] = iy;
        for (int q = 0; q < 4; q++)
            b->w[k][q] = (uint8_t)w[q];
    }
}

/* Two pixels of a row (8 bytes at p) at coverages wa, wb. */
static ISK__INLINE void px2(uint8_t *p, isk_color col, const isk__cov_lut *lut, uint32_t wa, uint32_t wb,
                            isk_blend mode)
{
#if ISK__CPU_SSE2
    if (px2_sse2(p, lut, wa, wb, mode)) /* add, or over on two opaque pixels: one register */
        return;
#elif ISK__CPU_VECTOR
    if (px2_vector(p, lut, wa, wb, mode)) /* the same in one vector */
        return;
#endif
    isk__px_w(p, col, lut, wa, mode);
    isk__px_w(p + 4, col, lut, wb, mode);
}

/* The whole 2x2 block of a point at p (rows p and p + stride) at
 * coverages w[0..3]: over on four opaque pixels in one set of lanes (one
 * test of their alphas, one pack), anything else a row at a time. */
static ISK__INLINE void px4(uint8_t *p, size_t stride, isk_color col, const isk__cov_lut *lut, const uint8_t w[4],
                            isk_blend mode)
{
#if ISK__CPU_SSE2
    if (px4_sse2(p, stride, lut, w, mode)) /* over on four opaque pixels: one set of lanes */
        return;
#elif ISK__CPU_VECTOR
    if (px4_vector(p, stride, lut, w, mode)) /* the same in vector-extension lanes */
        return;
#endif
    px2(p, col, lut, w[0], w[1], mode);
    px2(p + stride, col, lut, w[2], w[3], mode);
}

/* Step 1 of a block without a list: the points whose dot can touch the
 * rows, their screen Y in b->y and their place in the block in b->ix, in
 * block order; returns how many.  Without branches (on a band most points
 * may be another band's, in an order no predictor learns).  A band of
 * columns selects on X the same way (the axis is X). */
typedef struct select_view {
    int camera, keep;
    isk__view_axis axis;        /* the view's axis the points are mapped on (view_transform.h) */
    double lo, hi;              /* kept: lo < U < hi, U the point's screen coordinate */
    int height;                 /* keep: (height - 1, height] -> height - 1 (the axis's canvas size) */
} select_view;

typedef int (*select_fn)(const select_view *s, const double *y, int m, double *oy, int32_t *oix);

/* The point's screen coordinate on the select's axis: view_transform.h's
 * arithmetic. */
static ISK__INLINE double select_screen(const select_view *s, double u)
{
    return isk__view_axis_map(s->axis, s->camera, u);
}

static inline int select_scalar(const select_view *s, const double *y, int m, double *oy, int32_t *oix)
{
    int kept = 0;
    for (int k = 0; k < m; k++) {
        const double Y0k = select_screen(s, y[k]);
        const double Y = s->keep ? isk__keep_on_canvas(Y0k, s->height) : Y0k;
        oy[kept] = Y;
        oix[kept] = k;
        kept += (Y > s->lo) & (Y < s->hi);
    }
    return kept;
}

/* The twins of weights_scalar and select_scalar, for a CPU that has their
 * instruction set (pick_weights, pick_select; tests/test_dot_block.c runs
 * each against the scalar code). */
#if ISK__CPU_AVX2
void isk__dot_weights_avx2(dot_block *b, int m, double X0, double X1, double Y0, double H1);
int isk__dot_select_avx2(const select_view *s, const double *y, int m, double *oy, int32_t *oix);
#endif
#if ISK__CPU_AVX512
void isk__dot_weights_avx512(dot_block *b, int m, double X0, double X1, double Y0, double H1);
int isk__dot_select_avx512(const select_view *s, const double *y, int m, double *oy, int32_t *oix);
#endif

static inline weights_fn pick_weights(int browser)
{
    if (browser)
        return weights_browser;
#if ISK__CPU_AVX512
    if (isk__have_avx512())
        return isk__dot_weights_avx512;
#endif
#if ISK__CPU_AVX2
    if (isk__have_avx2())
        return isk__dot_weights_avx2;
#endif
    return weights_scalar;
}

static inline select_fn pick_select(void)
{
#if ISK__CPU_AVX512
    if (isk__have_avx512())
        return isk__dot_select_avx512;
#endif
#if ISK__CPU_AVX2
    if (isk__have_avx2())
        return isk__dot_select_avx2;
#endif
    return select_scalar;
}

#endif
