/* Batched drawing of a particle store through a view (isk_draw_dots,
 * isk_draw_dots_browser, isk_draw_pixels in iskra/view.h).
 *
 * One loop per (view kind, dot rule, blend mode), chosen once per batch:
 * the transform is isk_view_to_screen's arithmetic inlined (same operations,
 * same order, so the same doubles), the dot weights are raster/dot_kernel.h's
 * rules, the blend raster/blend_px.h's with the mode a constant and the
 * colour prepared once (a coverage table).  The result is byte-identical to
 * calling the single-dot functions in index order (tests/test_raster_fast.c).
 */
#include "iskra/view.h"

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "raster/blend_px.h"
#include "raster/dot_kernel.h"
#include "raster/span_simd.h"
#include "view/world_batch.h"


/* isk_draw_pixels, in blocks of PIXEL_BLOCK points: a first pass
 * transforms each point and finds its pixel (prefetching it: a random
 * access the hardware cannot guess), a second blends in index order.  The
 * colour is prepared once: its coverage-255 table entry, since
 * isk__px_lut(d, t, 255, mode) is isk__px(d, col, mode) (div255(a*255) = a). */
#define PIXEL_BLOCK 64

/* The batch's k-th point: k itself, or the k-th entry of a list of indices
 * (a band's points, isk__draw_batch_list_rows).  `list` is a constant of
 * each inlined copy, so the plain batch pays nothing for it. */
#define POINT(list, k) ((list) ? (size_t)(list)[k] : (size_t)(k))

static ISK__INLINE void run_pixels(const isk_canvas *c, int r0, int r1, const isk_view *v, size_t n,
                                   const uint32_t *list, const double *x, const double *y, isk_color col,
                                   int camera, int keep, isk_blend mode)
{
    /* isk_view_to_screen: camera  X = w/2 + a*(x + tx),  Y = h/2 - a*(y + ty);
     *                     window  X = sx*x + px,          Y = sy*y + py. */
    const double hw = v->width / 2.0, hh = v->height / 2.0, a = v->a, tx = v->tx, ty = v->ty;
    const double sx = v->sx, sy = v->sy, px = v->px, py = v->py;
    const double W = c->width, Y0 = r0, Y1 = r1;
    const size_t stride = c->stride;
    isk__cov_lut t;
    isk__cov_lut_entry(&t, col, 255);
    size_t off[PIXEL_BLOCK];
    for (size_t i0 = 0; i0 < n; i0 += PIXEL_BLOCK) {
        const size_t m = n - i0 < PIXEL_BLOCK ? n - i0 : PIXEL_BLOCK;
        size_t k = 0;
        for (size_t i = 0; i < m; i++) {
            const size_t j = POINT(list, i0 + i);
            double X, Y;
            if (camera) {
                X = hw + a * (x[j] + tx);
                Y = hh - a * (y[j] + ty);
            } else {
                X = sx * x[j] + px;
                Y = sy * y[j] + py;
            }
            if (keep) { /* a batch constant: the branch is hoisted */
                X = isk__keep_on_canvas(X, c->width);
                Y = isk__keep_on_canvas(Y, c->height);
            }
            /* Without branches: on a band of a threaded draw about half
             * the points are someone else's, in no order a predictor can
             * learn.  An outside point writes a harmless offset and is not
             * counted (the select also keeps NaN and huge values out of the
             * conversions). */
            const int in = (X >= 0) & (Y >= Y0) & (X < W) & (Y < Y1);
            const double Xs = in ? X : 0.0, Ys = in ? Y : Y0;
            off[k] = (size_t)(int)Ys * stride + (size_t)(int)Xs * 4u;
#if defined(__GNUC__)
            __builtin_prefetch(c->pixels + off[k], 1);
#endif
            k += (size_t)in;
        }
        for (size_t i = 0; i < k; i++)
            isk__px_lut(c->pixels + off[i], &t, 255, mode);
    }
}

/* The exact-area dot over a batch, in blocks of BLOCK points:
 *   1. transform the block (the view's arithmetic, as isk_view_to_screen);
 *   2. for each point whose 2x2 block is wholly on the canvas, its top-left
 *      pixel and four weights (raster/dot_kernel.h's rule; 4 points per
 *      step with AVX2 when the CPU has it: the same IEEE operations in the
 *      same order, so the same doubles), and prefetch its two rows;
 *   3. blend in index order, two pixels of a row at a time (SSE2) from the
 *      batch's coverage table; points near the edges or off the canvas go
 *      through the single-dot kernel (clipping), in their turn.
 * Pass 2 is pure arithmetic, independent from point to point, so the
 * processor overlaps it freely; the blends then find their pixels loaded.
 * 64 points: on a band of a threaded draw only part of a block is kept, and
 * with blocks of 32 the few kept points left the weights and the prefetches
 * little to overlap: a half band (every other point kept) cost 0.65 of the
 * whole canvas, 0.60 with 64, where the same points kept in one run cost
 * 0.51 (the whole canvas itself the same; 96 and 128 made it slower). */
#define BLOCK 64

typedef struct dot_block {
    double x[BLOCK], y[BLOCK];
    int32_t ix[BLOCK], iy[BLOCK];
    uint8_t w[BLOCK][4];
    uint8_t fast[BLOCK];
} dot_block;

/* fast[k]: the point's whole 2x2 block lies on the canvas columns and on
 * the rows [Y0, H1 + 1] (Y0 >= 0). */
typedef void (*weights_fn)(dot_block *b, int m, double W1, double Y0, double H1);

static ISK__INLINE void weight_one(dot_block *b, int k, double W1, double Y0, double H1)
{
    double X = b->x[k], Y = b->y[k];
    /* the whole 2x2 block on the canvas: floor(X) in [0, width-2] */
    b->fast[k] = (X >= 0.0) & (X < W1) & (Y >= Y0) & (Y < H1);
    if (!b->fast[k])
        return;
    int ix = (int)X, iy = (int)Y; /* >= 0: truncation is floor */
    uint32_t w[4];
    isk__dot_weights_frac(X - ix, Y - iy, w);
    b->ix[k] = ix;
    b->iy[k] = iy;
    for (int q = 0; q < 4; q++)
        b->w[k][q] = (uint8_t)w[q];
}

static void weights_scalar(dot_block *b, int m, double W1, double Y0, double H1)
{
    for (int k = 0; k < m; k++)
        weight_one(b, k, W1, Y0, H1);
}

#if ISK__SPAN_AVX2
/* weights_scalar for 4 points a step.  Each lane does the scalar code's
 * operations: products left to right, floors by truncation of values
 * >= 0, the rank selection as 0/1 doubles (small integers, exact). */
static ISK__AVX2_FN void weights_avx2(dot_block *b, int m, double W1, double Y0, double H1)
{
    const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0), k255 = _mm256_set1_pd(255.0);
    const __m256d vW1 = _mm256_set1_pd(W1), vY0 = _mm256_set1_pd(Y0), vH1 = _mm256_set1_pd(H1);
    int k = 0;
    for (; k + 4 <= m; k += 4) {
        __m256d X = _mm256_loadu_pd(b->x + k), Y = _mm256_loadu_pd(b->y + k);
        __m256d ok = _mm256_and_pd(_mm256_and_pd(_mm256_cmp_pd(X, zero, _CMP_GE_OQ), _mm256_cmp_pd(X, vW1, _CMP_LT_OQ)),
                                   _mm256_and_pd(_mm256_cmp_pd(Y, vY0, _CMP_GE_OQ), _mm256_cmp_pd(Y, vH1, _CMP_LT_OQ)));
        int okbits = _mm256_movemask_pd(ok);
        for (int q = 0; q < 4; q++)
            b->fast[k + q] = (uint8_t)((okbits >> q) & 1);
        if (!okbits)
            continue;
        X = _mm256_and_pd(X, ok); /* other lanes: 0, harmless */
        Y = _mm256_and_pd(Y, ok);
        __m128i ix = _mm256_cvttpd_epi32(X), iy = _mm256_cvttpd_epi32(Y);
        _mm_storeu_si128((__m128i *)(void *)(b->ix + k), ix);
        _mm_storeu_si128((__m128i *)(void *)(b->iy + k), iy);
        __m256d fx = _mm256_sub_pd(X, _mm256_cvtepi32_pd(ix)), fy = _mm256_sub_pd(Y, _mm256_cvtepi32_pd(iy));
        __m256d gx = _mm256_sub_pd(one, fx), gy = _mm256_sub_pd(one, fy);
        __m256d a0 = _mm256_mul_pd(_mm256_mul_pd(k255, gx), gy), a1 = _mm256_mul_pd(_mm256_mul_pd(k255, fx), gy);
        __m256d a2 = _mm256_mul_pd(_mm256_mul_pd(k255, gx), fy), a3 = _mm256_mul_pd(_mm256_mul_pd(k255, fx), fy);
        __m128i i0 = _mm256_cvttpd_epi32(a0), i1 = _mm256_cvttpd_epi32(a1);
        __m128i i2 = _mm256_cvttpd_epi32(a2), i3 = _mm256_cvttpd_epi32(a3);
        __m256d d0 = _mm256_cvtepi32_pd(i0), d1 = _mm256_cvtepi32_pd(i1);
        __m256d d2 = _mm256_cvtepi32_pd(i2), d3 = _mm256_cvtepi32_pd(i3);
        __m256d f0 = _mm256_sub_pd(a0, d0), f1 = _mm256_sub_pd(a1, d1);
        __m256d f2 = _mm256_sub_pd(a2, d2), f3 = _mm256_sub_pd(a3, d3);
        __m256d left = _mm256_sub_pd(k255, _mm256_add_pd(_mm256_add_pd(d0, d1), _mm256_add_pd(d2, d3)));
#define GE01(p, q) _mm256_and_pd(_mm256_cmp_pd(p, q, _CMP_GE_OQ), one)
        __m256d c01 = GE01(f0, f1), c02 = GE01(f0, f2), c03 = GE01(f0, f3);
        __m256d c12 = GE01(f1, f2), c13 = GE01(f1, f3), c23 = GE01(f2, f3);
#undef GE01
        __m256d r0 = _mm256_sub_pd(_mm256_sub_pd(_mm256_sub_pd(_mm256_set1_pd(3.0), c01), c02), c03);
        __m256d r1 = _mm256_sub_pd(_mm256_sub_pd(_mm256_add_pd(_mm256_set1_pd(2.0), c01), c12), c13);
        __m256d r2 = _mm256_sub_pd(_mm256_add_pd(_mm256_add_pd(one, c02), c12), c23);
        __m256d r3 = _mm256_add_pd(_mm256_add_pd(c03, c13), c23);
#define BUMP(d, r) _mm256_cvttpd_epi32(_mm256_add_pd(d, _mm256_and_pd(_mm256_cmp_pd(r, left, _CMP_LT_OQ), one)))
        __m128i w0 = BUMP(d0, r0), w1 = BUMP(d1, r1), w2 = BUMP(d2, r2), w3 = BUMP(d3, r3);
#undef BUMP
        /* bytes w0 w0 w0 w0 w1 ... w3 (4 points each), then per point */
        __m128i bytes = _mm_packus_epi16(_mm_packs_epi32(w0, w1), _mm_packs_epi32(w2, w3));
        bytes = _mm_shuffle_epi8(bytes, _mm_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15));
        _mm_storeu_si128((__m128i *)(void *)b->w[k], bytes);
    }
    for (; k < m; k++)
        weight_one(b, k, W1, Y0, H1);
}
#endif

/* The browser rule's weights (integer arithmetic, already cheap). */
static void weights_browser(dot_block *b, int m, double W1, double Y0, double H1)
{
    for (int k = 0; k < m; k++) {
        double X = b->x[k], Y = b->y[k];
        int ix, iy;
        uint32_t w[4];
        /* isk__dot_browser's range test, then its weights; fast when the
         * 2x2 block is wholly on the canvas */
        b->fast[k] = X > -2.0 && X < W1 + 2.0 && Y > Y0 - 2.0 && Y < H1 + 2.0 &&
                     isk__dot_weights_browser(X, Y, &ix, &iy, w) && ix >= 0 && ix < W1 && iy >= Y0 && iy < H1;
        if (!b->fast[k])
            continue;
        b->ix[k] = ix;
        b->iy[k] = iy;
        for (int q = 0; q < 4; q++)
            b->w[k][q] = (uint8_t)w[q];
    }
}

static weights_fn pick_weights(int browser)
{
    if (browser)
        return weights_browser;
#if ISK__SPAN_AVX2
    if (isk__have_avx2())
        return weights_avx2;
#endif
    return weights_scalar;
}

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
        /* div255(c a' + d (255 - a')) on both pixels' lanes */
        __m128i P = _mm_set_epi64x((long long)lut->over_p[wb], (long long)lut->over_p[wa]);
        __m128i I = _mm_set_epi64x((long long)lut->over_inv[wb], (long long)lut->over_inv[wa]);
        __m128i v = _mm_loadl_epi64((const __m128i *)(const void *)p);
        __m128i x = _mm_add_epi16(_mm_mullo_epi16(_mm_unpacklo_epi8(v, _mm_setzero_si128()), I), P);
        _mm_storel_epi64((__m128i *)(void *)p, _mm_packus_epi16(isk__s_div255(x), x));
        return;
    }
#endif
    isk__px_w(p, col, lut, wa, mode);
    isk__px_w(p + 4, col, lut, wb, mode);
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

static int select_scalar(const select_view *s, const double *y, int m, double *oy, int32_t *oix)
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
 * oix may be written up to 4 entries past what is kept: the block's arrays
 * hold BLOCK entries and kept + 4 <= k + 4 <= m). */
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

static ISK__AVX2_FN int select_avx2(const select_view *s, const double *y, int m, double *oy, int32_t *oix)
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

static select_fn pick_select(void)
{
#if ISK__SPAN_AVX2
    if (isk__have_avx2())
        return select_avx2;
#endif
    return select_scalar;
}

static ISK__INLINE void run_dots_blocked(const isk_canvas *c, int r0, int r1, const isk_view *v, size_t n,
                                         const uint32_t *list, const double *x, const double *y, isk_color col,
                                         const isk__cov_lut *lut, int camera, int browser, int keep,
                                         isk_blend mode)
{
    const double hw = v->width / 2.0, hh = v->height / 2.0, a = v->a, tx = v->tx, ty = v->ty;
    const double sx = v->sx, sy = v->sy, px = v->px, py = v->py;
    const double W1 = c->width - 1.0, Y0 = r0, H1 = r1 - 1.0;
    /* A point whose dot cannot touch the rows [r0, r1) is dropped before
     * anything else is computed for it: the single-dot kernels' own row
     * test (so dropping it changes nothing), and on a band of a threaded
     * draw most points are someone else's. */
    const double lo = browser ? Y0 - 2.0 : Y0 - 1.0, hi = browser ? r1 + 1.0 : (double)r1;
    const size_t stride = c->stride;
    uint8_t *const pixels = c->pixels;
    const weights_fn weights = pick_weights(browser);
    const select_fn select = pick_select();
    const select_view sv = {camera, keep, hh, a, ty, sy, py, lo, hi, c->height};
    dot_block b;
    for (size_t i0 = 0; i0 < n; i0 += BLOCK) {
        const int m = n - i0 < BLOCK ? (int)(n - i0) : BLOCK;
        /* b.ix: the point's place in the block, until the weights overwrite it */
        const double *yb = y + i0;
        double gathered[BLOCK];
        if (list) { /* a band's points: their y gathered into the block first */
            for (int k = 0; k < m; k++)
                gathered[k] = y[list[i0 + k]];
            yb = gathered;
        }
        const int kept = select(&sv, yb, m, b.y, b.ix);
        for (int k = 0; k < kept; k++) {
            const double xi = x[POINT(list, i0 + (size_t)b.ix[k])];
            const double X = camera ? hw + a * (xi + tx) : sx * xi + px;
            b.x[k] = keep ? isk__keep_on_canvas(X, c->width) : X;
        }
        weights(&b, kept, W1, Y0, H1);
#if defined(__GNUC__)
        for (int k = 0; k < kept; k++)
            if (b.fast[k]) {
                const uint8_t *q = pixels + (size_t)b.iy[k] * stride + (size_t)b.ix[k] * 4u;
                __builtin_prefetch(q, 1);
                __builtin_prefetch(q + stride, 1);
            }
#endif
        for (int k = 0; k < kept; k++) {
            if (b.fast[k]) {
                uint8_t *p = pixels + (size_t)b.iy[k] * stride + (size_t)b.ix[k] * 4u;
                if (lut) {
                    px2(p, col, lut, b.w[k][0], b.w[k][1], mode);
                    px2(p + stride, col, lut, b.w[k][2], b.w[k][3], mode);
                } else {
                    isk__px_cov(p, col, b.w[k][0], mode);
                    isk__px_cov(p + 4, col, b.w[k][1], mode);
                    isk__px_cov(p + stride, col, b.w[k][2], mode);
                    isk__px_cov(p + stride + 4, col, b.w[k][3], mode);
                }
            } else if (browser) {
                isk__dot_browser_rows(c, r0, r1, b.x[k], b.y[k], col, lut, mode);
            } else {
                isk__dot_rows(c, r0, r1, b.x[k], b.y[k], col, lut, mode);
            }
        }
    }
}

static ISK__INLINE void run_kind(const isk_canvas *c, int r0, int r1, const isk_view *v, size_t n,
                                 const uint32_t *list, const double *x, const double *y, isk_color col,
                                 const isk__cov_lut *lut, isk__batch_rule rule, int keep, isk_blend mode)
{
    const int camera = v->kind == ISK_VIEW_CAMERA;
    if (rule == ISK__BATCH_DOT && camera)
        run_dots_blocked(c, r0, r1, v, n, list, x, y, col, lut, 1, 0, keep, mode);
    else if (rule == ISK__BATCH_DOT)
        run_dots_blocked(c, r0, r1, v, n, list, x, y, col, lut, 0, 0, keep, mode);
    else if (rule == ISK__BATCH_DOT_BROWSER && camera)
        run_dots_blocked(c, r0, r1, v, n, list, x, y, col, lut, 1, 1, keep, mode);
    else if (rule == ISK__BATCH_DOT_BROWSER)
        run_dots_blocked(c, r0, r1, v, n, list, x, y, col, lut, 0, 1, keep, mode);
    else if (camera)
        run_pixels(c, r0, r1, v, n, list, x, y, col, 1, keep, mode);
    else
        run_pixels(c, r0, r1, v, n, list, x, y, col, 0, keep, mode);
}

/* Batches this short skip the 256-entry table: building it would cost
 * more than it saves. */
#define LUT_MIN_BATCH 64

static ISK__INLINE void run_rule(const isk_canvas *c, int r0, int r1, const isk_view *v, size_t n,
                                 const uint32_t *list, const double *x, const double *y, isk_color col,
                                 unsigned rule, isk_blend mode)
{
    const int keep = (rule & ISK__BATCH_KEEP_ON_CANVAS) != 0;
    rule &= ~(unsigned)ISK__BATCH_KEEP_ON_CANVAS;
    isk__cov_lut lut;
    switch (rule) {
    case ISK__BATCH_DOT:
    case ISK__BATCH_DOT_BROWSER:
        if (n >= LUT_MIN_BATCH) {
            isk__cov_lut_init(&lut, col);
            if (rule == ISK__BATCH_DOT)
                run_kind(c, r0, r1, v, n, list, x, y, col, &lut, ISK__BATCH_DOT, keep, mode);
            else
                run_kind(c, r0, r1, v, n, list, x, y, col, &lut, ISK__BATCH_DOT_BROWSER, keep, mode);
        } else if (rule == ISK__BATCH_DOT) {
            run_kind(c, r0, r1, v, n, list, x, y, col, NULL, ISK__BATCH_DOT, keep, mode);
        } else {
            run_kind(c, r0, r1, v, n, list, x, y, col, NULL, ISK__BATCH_DOT_BROWSER, keep, mode);
        }
        break;
    case ISK__BATCH_PIXEL:
        run_kind(c, r0, r1, v, n, list, x, y, col, NULL, ISK__BATCH_PIXEL, keep, mode);
        break;
    default:
        break;
    }
}

/* Whether there is anything to draw, the rows clamped to the canvas. */
static int drawable(const isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y, int *r0,
                    int *r1)
{
    if (!c || !c->pixels || !v || !x || !y || n == 0)
        return 0;
    if (*r0 < 0)
        *r0 = 0;
    if (*r1 > c->height)
        *r1 = c->height;
    return *r0 < *r1;
}

void isk__draw_batch_rows(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                          isk_color col, isk_blend mode, unsigned rule, int r0, int r1)
{
    if (drawable(c, v, n, x, y, &r0, &r1))
        ISK__BLEND_DISPATCH(mode, run_rule, c, r0, r1, v, n, NULL, x, y, col, rule);
}

void isk__draw_batch_list_rows(isk_canvas *c, const isk_view *v, const uint32_t *list, size_t m, const double *x,
                               const double *y, isk_color col, isk_blend mode, unsigned rule, int r0, int r1)
{
    if (list && drawable(c, v, m, x, y, &r0, &r1))
        ISK__BLEND_DISPATCH(mode, run_rule, c, r0, r1, v, m, list, x, y, col, rule);
}

void isk__batch_bin(const isk_view *v, int height, const double *y, size_t i0, size_t i1,
                    const uint8_t *band_of_row, uint16_t *code, size_t *count)
{
    const select_view sv = {.camera = v->kind == ISK_VIEW_CAMERA, .hh = v->height / 2.0, .a = v->a, .ty = v->ty,
                            .sy = v->sy, .py = v->py};
    const double lo = -(ISK__BIN_MARGIN + 1.0), hi = height + (double)ISK__BIN_MARGIN;
    /* counted here and added at the end: the threads' count arrays share
     * cache lines, and a store to one every point would bounce them */
    size_t mine[256] = {0};
    unsigned nb = 0;
    for (size_t i = i0; i < i1; i++) {
        const double Y = screen_y(&sv, y[i]);
        uint16_t k = ISK__BIN_NONE;
        if (Y > lo && Y < hi) { /* also false for NaN; keeps the conversion defined */
            const int fy = (int)(Y + (ISK__BIN_MARGIN + 1.0)) - (ISK__BIN_MARGIN + 1); /* floor */
            const int rlo = fy - ISK__BIN_MARGIN < 0 ? 0 : fy - ISK__BIN_MARGIN;
            const int rhi = fy + ISK__BIN_MARGIN >= height ? height - 1 : fy + ISK__BIN_MARGIN;
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
