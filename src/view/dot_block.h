/* SPDX-License-Identifier: MIT */
/* src/view/dot_block.h — the stages of a batched dot draw over a block of
 * points (world_batch.c: a store drawn onto a band of rows), in a header of
 * their own so that tests/test_dot_block.c can check every build of them,
 * including those the CPU does not pick (internal).
 *
 *   select   which points of the block can touch rows (lo, hi): their
 *            screen Y, in block order (SSE2 or AVX2);
 *   weights  for each selected point whose 2x2 block lies wholly on the
 *            canvas, its top-left pixel and its four exact-area weights
 *            (raster/dot_kernel.h's rule, 4 points a step with AVX2; the
 *            browser rule's integer weights);
 *   px2      two pixels of a row blended from a coverage table;
 *   px4      a point's whole 2x2 block (source-over on opaque pixels in
 *            one set of lanes, anything else px2 a row at a time).
 *
 * Every stage does the single-dot kernels' IEEE operations in their order,
 * so anything built from them draws the bytes of the loop of single calls.
 * Functions are static inline: each includer keeps the ones it uses. */
#ifndef ISKRA_VIEW_DOT_BLOCK_H
#define ISKRA_VIEW_DOT_BLOCK_H

#include <stdint.h>
#include <string.h>

#include "iskra/canvas.h"
#include "raster/blend_px.h"
#include "raster/dot_kernel.h"
#include "raster/span_simd.h"
#include "view/world_batch.h" /* isk__keep_on_canvas */

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
 * the few left over carried to the next batch.  Against block by block
 * (10^6 dots, one process, the two interleaved, medians of 31): the draw
 * on two bands 0.94-0.99x the time, falling, settled or at rest, on one
 * thread 0.97-0.98x; 10^5 dots 0.97x.  A batch holds fewer than
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
 * so one at a time it waited on each latency in turn: AVX-512 3.3 ns a
 * point on Zen 4, 2.3 ns with two (AVX2 4.4 -> 3.4); three, four or eight
 * did no better. */
#define WEIGHTS_GROUPS 2

#if ISK__SPAN_AVX2
/* weights_scalar for 4 points a group, WEIGHTS_GROUPS groups a step.  Each
 * lane does the scalar code's operations: products left to right, floors
 * by truncation of values >= 0, the rank selection as 0/1 doubles (small
 * integers, exact).  The last points (fewer than a step's groups) take the
 * scalar code. */
static inline ISK__AVX2_FN void weights_avx2(dot_block *b, int m, double X0, double X1, double Y0, double H1)
{
    enum { G = WEIGHTS_GROUPS };
    const __m256d one = _mm256_set1_pd(1.0), k255 = _mm256_set1_pd(255.0);
    const __m256d vX0 = _mm256_set1_pd(X0), vX1 = _mm256_set1_pd(X1), vY0 = _mm256_set1_pd(Y0), vH1 = _mm256_set1_pd(H1);
    const __m256d vXe = _mm256_set1_pd(dot_edge_first(X0)), vW = _mm256_set1_pd(X1 + 1.0);
    const __m256d vYe = _mm256_set1_pd(dot_edge_first(Y0)), vH = _mm256_set1_pd(H1 + 1.0);
    int k0 = 0;
    for (; k0 + 4 * G <= m; k0 += 4 * G) {
        __m256d X[G], Y[G], a[G][4], d[G][4];
        for (int g = 0; g < G; g++) {
            const int k = k0 + 4 * g;
            X[g] = _mm256_loadu_pd(b->x + k);
            Y[g] = _mm256_loadu_pd(b->y + k);
            const __m256d full = _mm256_and_pd(
                _mm256_and_pd(_mm256_cmp_pd(X[g], vX0, _CMP_GE_OQ), _mm256_cmp_pd(X[g], vX1, _CMP_LT_OQ)),
                _mm256_and_pd(_mm256_cmp_pd(Y[g], vY0, _CMP_GE_OQ), _mm256_cmp_pd(Y[g], vH1, _CMP_LT_OQ)));
            const __m256d ok = _mm256_and_pd(
                _mm256_and_pd(_mm256_cmp_pd(X[g], vXe, _CMP_GE_OQ), _mm256_cmp_pd(X[g], vW, _CMP_LT_OQ)),
                _mm256_and_pd(_mm256_cmp_pd(Y[g], vYe, _CMP_GE_OQ), _mm256_cmp_pd(Y[g], vH, _CMP_LT_OQ)));
            const int okbits = _mm256_movemask_pd(ok), fullbits = _mm256_movemask_pd(full);
            for (int q = 0; q < 4; q++)
                b->fast[k + q] = (uint8_t)((okbits >> q & 1) + ((okbits & ~fullbits) >> q & 1));
            X[g] = _mm256_and_pd(X[g], ok); /* other lanes: 0, harmless */
            Y[g] = _mm256_and_pd(Y[g], ok);
        }
        for (int g = 0; g < G; g++) {
            const int k = k0 + 4 * g;
            const __m128i ix = _mm256_cvttpd_epi32(X[g]), iy = _mm256_cvttpd_epi32(Y[g]);
            _mm_storeu_si128((__m128i *)(void *)(b->ix + k), ix);
            _mm_storeu_si128((__m128i *)(void *)(b->iy + k), iy);
            const __m256d fx = _mm256_sub_pd(X[g], _mm256_cvtepi32_pd(ix)), fy = _mm256_sub_pd(Y[g], _mm256_cvtepi32_pd(iy));
            const __m256d gx = _mm256_sub_pd(one, fx), gy = _mm256_sub_pd(one, fy);
            a[g][0] = _mm256_mul_pd(_mm256_mul_pd(k255, gx), gy);
            a[g][1] = _mm256_mul_pd(_mm256_mul_pd(k255, fx), gy);
            a[g][2] = _mm256_mul_pd(_mm256_mul_pd(k255, gx), fy);
            a[g][3] = _mm256_mul_pd(_mm256_mul_pd(k255, fx), fy);
        }
        for (int g = 0; g < G; g++)
            for (int q = 0; q < 4; q++)
                d[g][q] = _mm256_cvtepi32_pd(_mm256_cvttpd_epi32(a[g][q]));
        for (int g = 0; g < G; g++) {
            const __m256d d0 = d[g][0], d1 = d[g][1], d2 = d[g][2], d3 = d[g][3];
            const __m256d f0 = _mm256_sub_pd(a[g][0], d0), f1 = _mm256_sub_pd(a[g][1], d1);
            const __m256d f2 = _mm256_sub_pd(a[g][2], d2), f3 = _mm256_sub_pd(a[g][3], d3);
            const __m256d left = _mm256_sub_pd(k255, _mm256_add_pd(_mm256_add_pd(d0, d1), _mm256_add_pd(d2, d3)));
#define GE01(p, q) _mm256_and_pd(_mm256_cmp_pd(p, q, _CMP_GE_OQ), one)
            const __m256d c01 = GE01(f0, f1), c02 = GE01(f0, f2), c03 = GE01(f0, f3);
            const __m256d c12 = GE01(f1, f2), c13 = GE01(f1, f3), c23 = GE01(f2, f3);
#undef GE01
            const __m256d r0 = _mm256_sub_pd(_mm256_sub_pd(_mm256_sub_pd(_mm256_set1_pd(3.0), c01), c02), c03);
            const __m256d r1 = _mm256_sub_pd(_mm256_sub_pd(_mm256_add_pd(_mm256_set1_pd(2.0), c01), c12), c13);
            const __m256d r2 = _mm256_sub_pd(_mm256_add_pd(_mm256_add_pd(one, c02), c12), c23);
            const __m256d r3 = _mm256_add_pd(_mm256_add_pd(c03, c13), c23);
#define BUMP(d, r) _mm256_cvttpd_epi32(_mm256_add_pd(d, _mm256_and_pd(_mm256_cmp_pd(r, left, _CMP_LT_OQ), one)))
            const __m128i w0 = BUMP(d0, r0), w1 = BUMP(d1, r1), w2 = BUMP(d2, r2), w3 = BUMP(d3, r3);
#undef BUMP
            /* bytes w0 w0 w0 w0 w1 ... w3 (4 points each), then per point */
            __m128i bytes = _mm_packus_epi16(_mm_packs_epi32(w0, w1), _mm_packs_epi32(w2, w3));
            bytes = _mm_shuffle_epi8(bytes, _mm_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15));
            _mm_storeu_si128((__m128i *)(void *)b->w[k0 + 4 * g], bytes);
        }
    }
    for (int k = k0; k < m; k++)
        weight_one(b, k, X0, X1, Y0, H1);
}
#endif

#if ISK__SPAN_AVX512
/* weights_avx2 for 8 points a group, WEIGHTS_GROUPS groups a step: the
 * same operations on the doubles; the rank selection in 32-bit lanes
 * instead of 0/1 doubles (small integers either way: the same comparisons,
 * the same sums), with the comparisons as mask registers.
 * Plain stores, no masked ones: the block's arrays hold DOT_BATCH entries
 * (m <= DOT_BATCH) and a group never starts past its last 8, so what lands
 * past the m-th point is scratch nobody reads, and a load that follows a
 * masked store must wait for it to reach the cache instead of being
 * forwarded. */
_Static_assert(DOT_STEP == 8 * WEIGHTS_GROUPS && DOT_BATCH % DOT_STEP == 0,
               "a step is the weights' groups, and whole steps fit the block's arrays");

static inline ISK__AVX512_FN void weights_avx512(dot_block *b, int m, double X0, double X1, double Y0, double H1)
{
    enum { G = WEIGHTS_GROUPS };
    const __m512d one = _mm512_set1_pd(1.0), k255 = _mm512_set1_pd(255.0);
    const __m512d vX0 = _mm512_set1_pd(X0), vX1 = _mm512_set1_pd(X1), vY0 = _mm512_set1_pd(Y0), vH1 = _mm512_set1_pd(H1);
    const __m512d vXe = _mm512_set1_pd(dot_edge_first(X0)), vW = _mm512_set1_pd(X1 + 1.0);
    const __m512d vYe = _mm512_set1_pd(dot_edge_first(Y0)), vH = _mm512_set1_pd(H1 + 1.0);
    const __m256i i1 = _mm256_set1_epi32(1);
    for (int k0 = 0; k0 < m; k0 += 8 * G) {
        __m512d X[G], Y[G], a[G][4], f[G][4];
        __m256i w[G][4];
        for (int g = 0; g < G; g++) {
            const int k = k0 + 8 * g, left = m - k;
            const __mmask8 valid = left >= 8 ? (__mmask8)0xFF : left <= 0 ? 0 : (__mmask8)((1u << left) - 1u);
            X[g] = _mm512_maskz_loadu_pd(valid, b->x + k);
            Y[g] = _mm512_maskz_loadu_pd(valid, b->y + k);
            const __mmask8 full = valid & _mm512_cmp_pd_mask(X[g], vX0, _CMP_GE_OQ) &
                                  _mm512_cmp_pd_mask(X[g], vX1, _CMP_LT_OQ) & _mm512_cmp_pd_mask(Y[g], vY0, _CMP_GE_OQ) &
                                  _mm512_cmp_pd_mask(Y[g], vH1, _CMP_LT_OQ);
            const __mmask8 ok = valid & _mm512_cmp_pd_mask(X[g], vXe, _CMP_GE_OQ) &
                                _mm512_cmp_pd_mask(X[g], vW, _CMP_LT_OQ) & _mm512_cmp_pd_mask(Y[g], vYe, _CMP_GE_OQ) &
                                _mm512_cmp_pd_mask(Y[g], vH, _CMP_LT_OQ);
            _mm_storel_epi64((__m128i *)(void *)(b->fast + k),
                             _mm_add_epi8(_mm_maskz_set1_epi8(ok, 1), _mm_maskz_set1_epi8((__mmask16)(ok & ~full), 1)));
            X[g] = _mm512_maskz_mov_pd(ok, X[g]); /* other lanes: 0, harmless */
            Y[g] = _mm512_maskz_mov_pd(ok, Y[g]);
        }
        for (int g = 0; g < G; g++) {
            const int k = k0 + 8 * g;
            const __m256i ix = _mm512_cvttpd_epi32(X[g]), iy = _mm512_cvttpd_epi32(Y[g]);
            _mm256_storeu_si256((__m256i *)(void *)(b->ix + k), ix);
            _mm256_storeu_si256((__m256i *)(void *)(b->iy + k), iy);
            const __m512d fx = _mm512_sub_pd(X[g], _mm512_cvtepi32_pd(ix)), fy = _mm512_sub_pd(Y[g], _mm512_cvtepi32_pd(iy));
            const __m512d gx = _mm512_sub_pd(one, fx), gy = _mm512_sub_pd(one, fy);
            a[g][0] = _mm512_mul_pd(_mm512_mul_pd(k255, gx), gy);
            a[g][1] = _mm512_mul_pd(_mm512_mul_pd(k255, fx), gy);
            a[g][2] = _mm512_mul_pd(_mm512_mul_pd(k255, gx), fy);
            a[g][3] = _mm512_mul_pd(_mm512_mul_pd(k255, fx), fy);
        }
        for (int g = 0; g < G; g++)
            for (int q = 0; q < 4; q++) {
                w[g][q] = _mm512_cvttpd_epi32(a[g][q]);
                f[g][q] = _mm512_sub_pd(a[g][q], _mm512_cvtepi32_pd(w[g][q]));
            }
        for (int g = 0; g < G; g++) {
            const int k = k0 + 8 * g;
            const __m256i left = _mm256_sub_epi32(_mm256_set1_epi32(255), _mm256_add_epi32(_mm256_add_epi32(w[g][0], w[g][1]),
                                                                                     _mm256_add_epi32(w[g][2], w[g][3])));
            const __mmask8 c01 = _mm512_cmp_pd_mask(f[g][0], f[g][1], _CMP_GE_OQ);
            const __mmask8 c02 = _mm512_cmp_pd_mask(f[g][0], f[g][2], _CMP_GE_OQ);
            const __mmask8 c03 = _mm512_cmp_pd_mask(f[g][0], f[g][3], _CMP_GE_OQ);
            const __mmask8 c12 = _mm512_cmp_pd_mask(f[g][1], f[g][2], _CMP_GE_OQ);
            const __mmask8 c13 = _mm512_cmp_pd_mask(f[g][1], f[g][3], _CMP_GE_OQ);
            const __mmask8 c23 = _mm512_cmp_pd_mask(f[g][2], f[g][3], _CMP_GE_OQ);
            /* r0 = 3 - c01 - c02 - c03, r1 = 2 + c01 - c12 - c13, r2 = 1 + c02 + c12 - c23, r3 = c03 + c13 + c23 */
            __m256i r0 = _mm256_set1_epi32(3), r1 = _mm256_set1_epi32(2), r2 = i1, r3 = _mm256_setzero_si256();
            r0 = _mm256_mask_sub_epi32(r0, c01, r0, i1);
            r0 = _mm256_mask_sub_epi32(r0, c02, r0, i1);
            r0 = _mm256_mask_sub_epi32(r0, c03, r0, i1);
            r1 = _mm256_mask_add_epi32(r1, c01, r1, i1);
            r1 = _mm256_mask_sub_epi32(r1, c12, r1, i1);
            r1 = _mm256_mask_sub_epi32(r1, c13, r1, i1);
            r2 = _mm256_mask_add_epi32(r2, c02, r2, i1);
            r2 = _mm256_mask_add_epi32(r2, c12, r2, i1);
            r2 = _mm256_mask_sub_epi32(r2, c23, r2, i1);
            r3 = _mm256_mask_add_epi32(r3, c03, r3, i1);
            r3 = _mm256_mask_add_epi32(r3, c13, r3, i1);
            r3 = _mm256_mask_add_epi32(r3, c23, r3, i1);
            const __m256i w0 = _mm256_mask_add_epi32(w[g][0], _mm256_cmplt_epi32_mask(r0, left), w[g][0], i1);
            const __m256i w1 = _mm256_mask_add_epi32(w[g][1], _mm256_cmplt_epi32_mask(r1, left), w[g][1], i1);
            const __m256i w2 = _mm256_mask_add_epi32(w[g][2], _mm256_cmplt_epi32_mask(r2, left), w[g][2], i1);
            const __m256i w3 = _mm256_mask_add_epi32(w[g][3], _mm256_cmplt_epi32_mask(r3, left), w[g][3], i1);
            /* bytes per point: w0 w1 w2 w3 of point 0, then of point 1, ... */
            const __m128i p01 = _mm_unpacklo_epi8(_mm256_cvtepi32_epi8(w0), _mm256_cvtepi32_epi8(w1));
            const __m128i p23 = _mm_unpacklo_epi8(_mm256_cvtepi32_epi8(w2), _mm256_cvtepi32_epi8(w3));
            _mm_storeu_si128((__m128i *)(void *)b->w[k], _mm_unpacklo_epi16(p01, p23));
            _mm_storeu_si128((__m128i *)(void *)b->w[k + 4], _mm_unpackhi_epi16(p01, p23));
        }
    }
}
#endif

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

static inline weights_fn pick_weights(int browser)
{
    if (browser)
        return weights_browser;
#if ISK__SPAN_AVX512
    if (isk__have_avx512())
        return weights_avx512;
#endif
#if ISK__SPAN_AVX2
    if (isk__have_avx2())
        return weights_avx2;
#endif
    return weights_scalar;
}

#if ISK__SPAN_SSE2
/* Source-over on two opaque pixels whose bytes are the low 8 of v, at
 * coverages wa, wb: div255(c a' + d (255 - a')) in their 16-bit lanes, from
 * the coverage table (blend_px.h's isk__over_opaque_lanes, two at once). */
static ISK__INLINE __m128i over2_opaque(__m128i v, const isk__cov_lut *lut, uint32_t wa, uint32_t wb)
{
    const __m128i P = _mm_set_epi64x((long long)lut->over_p[wb], (long long)lut->over_p[wa]);
    const __m128i I = _mm_set_epi64x((long long)lut->over_inv[wb], (long long)lut->over_inv[wa]);
    return isk__s_div255(_mm_add_epi16(_mm_mullo_epi16(_mm_unpacklo_epi8(v, _mm_setzero_si128()), I), P));
}
#endif

/* Two pixels of a row (8 bytes at p) at coverages wa, wb. */
static ISK__INLINE void px2(uint8_t *p, isk_color col, const isk__cov_lut *lut, uint32_t wa, uint32_t wb,
                            isk_blend mode)
{
#if ISK__SPAN_SSE2
    if (mode == ISK_BLEND_ADD) {
        uint32_t ia, ib;
        memcpy(&ia, lut->add[wa], 4);
        memcpy(&ib, lut->add[wb], 4);
        __m128i inc = _mm_unpacklo_epi32(_mm_cvtsi32_si128((int)ia), _mm_cvtsi32_si128((int)ib));
        __m128i v = _mm_loadl_epi64((const __m128i *)(const void *)p);
        _mm_storel_epi64((__m128i *)(void *)p, _mm_adds_epu8(v, inc));
        return;
    }
    if (mode == ISK_BLEND_OVER && p[3] == 255u && p[7] == 255u) {
        const __m128i x = over2_opaque(_mm_loadl_epi64((const __m128i *)(const void *)p), lut, wa, wb);
        _mm_storel_epi64((__m128i *)(void *)p, _mm_packus_epi16(x, x));
        return;
    }
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
#if ISK__SPAN_SSE2
    if (mode == ISK_BLEND_OVER) {
        /* integer loads and stores: the rows are 4-byte aligned, and a
         * double's (_mm_loadh_pd) would claim 8 */
        uint8_t *q = p + stride;
        const __m128i vp = _mm_loadl_epi64((const __m128i *)(const void *)p);
        const __m128i vq = _mm_loadl_epi64((const __m128i *)(const void *)q);
        const __m128i v = _mm_unpacklo_epi64(vp, vq);
        if ((_mm_movemask_epi8(_mm_cmpeq_epi8(v, _mm_set1_epi8(-1))) & 0x8888) == 0x8888) {
            const __m128i r = _mm_packus_epi16(over2_opaque(vp, lut, w[0], w[1]), over2_opaque(vq, lut, w[2], w[3]));
            _mm_storel_epi64((__m128i *)(void *)p, r);
            _mm_storel_epi64((__m128i *)(void *)q, _mm_unpackhi_epi64(r, r));
            return;
        }
    }
#endif
    px2(p, col, lut, w[0], w[1], mode);
    px2(p + stride, col, lut, w[2], w[3], mode);
}

/* Step 1 of a block without a list: the points whose dot can touch the
 * rows, their screen Y in b->y and their place in the block in b->ix, in
 * block order; returns how many.  Without branches (on a band most points
 * may be another band's, in an order no predictor learns). */
typedef struct select_view {
    int camera, keep;
    double hh, a, ty, sy, py;   /* the view's Y arithmetic (isk_view_to_screen) */
    double lo, hi;              /* kept: lo < Y < hi */
    int height;                 /* keep: (height - 1, height] -> height - 1 */
} select_view;

typedef int (*select_fn)(const select_view *s, const double *y, int m, double *oy, int32_t *oix);

/* isk_view_to_screen's Y, its operations in its order. */
static ISK__INLINE double screen_y(const select_view *s, double y)
{
    return s->camera ? s->hh - s->a * (y + s->ty) : s->sy * y + s->py;
}

static inline int select_scalar(const select_view *s, const double *y, int m, double *oy, int32_t *oix)
{
    int kept = 0;
    for (int k = 0; k < m; k++) {
        const double Y0k = screen_y(s, y[k]);
        const double Y = s->keep ? isk__keep_on_canvas(Y0k, s->height) : Y0k;
        oy[kept] = Y;
        oix[kept] = k;
        kept += (Y > s->lo) & (Y < s->hi);
    }
    return kept;
}

#if ISK__SPAN_AVX2
/* Four points a step: the same IEEE operations as select_scalar, lanes
 * compressed by a permutation looked up from the comparison's mask (oy and
 * oix may be written up to 4 entries past what is kept, kept + 4 <= k + 4
 * <= m: a batch holds a block's m <= DOT_BLOCK after what it has). */
static const int32_t SELECT_PERM[16][8] = {
    {0, 0, 0, 0, 0, 0, 0, 0},
    {0, 1, 0, 0, 0, 0, 0, 0},
    {2, 3, 0, 0, 0, 0, 0, 0},
    {0, 1, 2, 3, 0, 0, 0, 0},
    {4, 5, 0, 0, 0, 0, 0, 0},
    {0, 1, 4, 5, 0, 0, 0, 0},
    {2, 3, 4, 5, 0, 0, 0, 0},
    {0, 1, 2, 3, 4, 5, 0, 0},
    {6, 7, 0, 0, 0, 0, 0, 0},
    {0, 1, 6, 7, 0, 0, 0, 0},
    {2, 3, 6, 7, 0, 0, 0, 0},
    {0, 1, 2, 3, 6, 7, 0, 0},
    {4, 5, 6, 7, 0, 0, 0, 0},
    {0, 1, 4, 5, 6, 7, 0, 0},
    {2, 3, 4, 5, 6, 7, 0, 0},
    {0, 1, 2, 3, 4, 5, 6, 7},
};
static const int32_t SELECT_LANE[16][8] = {
    {0, 0, 0, 0, 0, 0, 0, 0},
    {0, 0, 0, 0, 0, 0, 0, 0},
    {1, 0, 0, 0, 0, 0, 0, 0},
    {0, 1, 0, 0, 0, 0, 0, 0},
    {2, 0, 0, 0, 0, 0, 0, 0},
    {0, 2, 0, 0, 0, 0, 0, 0},
    {1, 2, 0, 0, 0, 0, 0, 0},
    {0, 1, 2, 0, 0, 0, 0, 0},
    {3, 0, 0, 0, 0, 0, 0, 0},
    {0, 3, 0, 0, 0, 0, 0, 0},
    {1, 3, 0, 0, 0, 0, 0, 0},
    {0, 1, 3, 0, 0, 0, 0, 0},
    {2, 3, 0, 0, 0, 0, 0, 0},
    {0, 2, 3, 0, 0, 0, 0, 0},
    {1, 2, 3, 0, 0, 0, 0, 0},
    {0, 1, 2, 3, 0, 0, 0, 0},
};

static inline ISK__AVX2_FN int select_avx2(const select_view *s, const double *y, int m, double *oy, int32_t *oix)
{
    const __m256d hh = _mm256_set1_pd(s->hh), a = _mm256_set1_pd(s->a), ty = _mm256_set1_pd(s->ty);
    const __m256d sy = _mm256_set1_pd(s->sy), py = _mm256_set1_pd(s->py);
    const __m256d lo = _mm256_set1_pd(s->lo), hi = _mm256_set1_pd(s->hi);
    const __m256d n1 = _mm256_set1_pd(s->height - 1.0), n = _mm256_set1_pd((double)s->height);
    int kept = 0, k = 0;
    for (; k + 4 <= m; k += 4) {
        const __m256d v = _mm256_loadu_pd(y + k);
        __m256d Y = s->camera ? _mm256_sub_pd(hh, _mm256_mul_pd(a, _mm256_add_pd(v, ty)))
                              : _mm256_add_pd(_mm256_mul_pd(sy, v), py);
        if (s->keep)
            Y = _mm256_blendv_pd(Y, n1, _mm256_and_pd(_mm256_cmp_pd(Y, n1, _CMP_GT_OQ), _mm256_cmp_pd(Y, n, _CMP_LE_OQ)));
        const int mask =
            _mm256_movemask_pd(_mm256_and_pd(_mm256_cmp_pd(Y, lo, _CMP_GT_OQ), _mm256_cmp_pd(Y, hi, _CMP_LT_OQ)));
        const __m256i perm = _mm256_loadu_si256((const __m256i *)(const void *)SELECT_PERM[mask]);
        const __m256i lane = _mm256_loadu_si256((const __m256i *)(const void *)SELECT_LANE[mask]);
        _mm256_storeu_pd(oy + kept, _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(Y), perm)));
        _mm_storeu_si128((__m128i *)(void *)(oix + kept),
                         _mm256_castsi256_si128(_mm256_add_epi32(lane, _mm256_set1_epi32(k))));
        kept += __builtin_popcount((unsigned)mask);
    }
    if (k < m) {
        const int t = select_scalar(s, y + k, m - k, oy + kept, oix + kept);
        for (int q = kept; q < kept + t; q++)
            oix[q] += k;
        kept += t;
    }
    return kept;
}
#endif

#if ISK__SPAN_AVX512
/* Eight points a step, the last one masked: select_avx2's operations, the
 * lanes compressed by the mask register (oy and oix may be written up to 8
 * entries past what is kept, kept <= k and k + 8 <= DOT_BLOCK: within a
 * batch's arrays after what it has, fewer than DOT_BLOCK). */
static inline ISK__AVX512_FN int select_avx512(const select_view *s, const double *y, int m, double *oy, int32_t *oix)
{
    const __m512d hh = _mm512_set1_pd(s->hh), a = _mm512_set1_pd(s->a), ty = _mm512_set1_pd(s->ty);
    const __m512d sy = _mm512_set1_pd(s->sy), py = _mm512_set1_pd(s->py);
    const __m512d lo = _mm512_set1_pd(s->lo), hi = _mm512_set1_pd(s->hi);
    const __m512d n1 = _mm512_set1_pd(s->height - 1.0), n = _mm512_set1_pd((double)s->height);
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    int kept = 0;
    for (int k = 0; k < m; k += 8) {
        const __mmask8 valid = m - k >= 8 ? (__mmask8)0xFF : (__mmask8)((1u << (m - k)) - 1u);
        const __m512d v = _mm512_maskz_loadu_pd(valid, y + k);
        __m512d Y = s->camera ? _mm512_sub_pd(hh, _mm512_mul_pd(a, _mm512_add_pd(v, ty)))
                              : _mm512_add_pd(_mm512_mul_pd(sy, v), py);
        if (s->keep)
            Y = _mm512_mask_mov_pd(Y, _mm512_cmp_pd_mask(Y, n1, _CMP_GT_OQ) & _mm512_cmp_pd_mask(Y, n, _CMP_LE_OQ), n1);
        const __mmask8 mask = valid & _mm512_cmp_pd_mask(Y, lo, _CMP_GT_OQ) & _mm512_cmp_pd_mask(Y, hi, _CMP_LT_OQ);
        _mm512_storeu_pd(oy + kept, _mm512_maskz_compress_pd(mask, Y));
        _mm256_storeu_si256((__m256i *)(void *)(oix + kept),
                            _mm256_maskz_compress_epi32(mask, _mm256_add_epi32(lane, _mm256_set1_epi32(k))));
        kept += __builtin_popcount(mask);
    }
    return kept;
}
#endif

static inline select_fn pick_select(void)
{
#if ISK__SPAN_AVX512
    if (isk__have_avx512())
        return select_avx512;
#endif
#if ISK__SPAN_AVX2
    if (isk__have_avx2())
        return select_avx2;
#endif
    return select_scalar;
}

#endif
