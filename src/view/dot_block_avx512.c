/* SPDX-License-Identifier: MIT */
/* The batched dot's weights and select in AVX-512 (view/dot_block.h), for
 * a CPU that has it (F, VL, BW, DQ): 8 points a group, masks in mask
 * registers. */
#include "core/cpu.h"

#if ISK__CPU_AVX512
#include <immintrin.h>

#include "view/dot_block.h"

/* isk__dot_weights_avx2 (dot_block_avx2.c) for 8 points a group,
 * WEIGHTS_GROUPS groups a step: the same operations on the doubles; the
 * rank selection in 32-bit lanes instead of 0/1 doubles (small integers
 * either way: the same comparisons, the same sums), with the comparisons
 * as mask registers.
 * Plain stores, no masked ones: the block's arrays hold DOT_BATCH entries
 * (m <= DOT_BATCH) and a group never starts past its last 8, so what lands
 * past the m-th point is scratch nobody reads, and a load that follows a
 * masked store must wait for it to reach the cache instead of being
 * forwarded. */
_Static_assert(DOT_STEP == 8 * WEIGHTS_GROUPS && DOT_BATCH % DOT_STEP == 0,
               "a step is the weights' groups, and whole steps fit the block's arrays");

ISK__AVX512_FN void isk__dot_weights_avx512(dot_block *b, int m, double X0, double X1, double Y0, double H1)
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

/* Eight points a step, the last one masked: isk__dot_select_avx2's
 * operations, the lanes compressed by the mask register (oy and oix may
 * be written up to 8 entries past what is kept, kept <= k and k + 8 <=
 * DOT_BLOCK: within a batch's arrays after what it has, fewer than
 * DOT_BLOCK). */
ISK__AVX512_FN int isk__dot_select_avx512(const select_view *s, const double *y, int m, double *oy, int32_t *oix)
{
    /* view_transform.h's isk__view_axis_map, lane by lane */
    const __m512d axc = _mm512_set1_pd(s->axis.c), axk = _mm512_set1_pd(s->axis.k), axt = _mm512_set1_pd(s->axis.t);
    const __m512d axs = _mm512_set1_pd(s->axis.s), axp = _mm512_set1_pd(s->axis.p);
    const __m512d lo = _mm512_set1_pd(s->lo), hi = _mm512_set1_pd(s->hi);
    const __m512d n1 = _mm512_set1_pd(s->height - 1.0), n = _mm512_set1_pd((double)s->height);
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    int kept = 0;
    for (int k = 0; k < m; k += 8) {
        const __mmask8 valid = m - k >= 8 ? (__mmask8)0xFF : (__mmask8)((1u << (m - k)) - 1u);
        const __m512d v = _mm512_maskz_loadu_pd(valid, y + k);
        __m512d Y = s->camera ? _mm512_sub_pd(axc, _mm512_mul_pd(axk, _mm512_add_pd(v, axt)))
                              : _mm512_add_pd(_mm512_mul_pd(axs, v), axp);
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
#else
typedef int isk__dot_block_avx512_unused; /* ISO C wants a declaration in every file */
#endif
