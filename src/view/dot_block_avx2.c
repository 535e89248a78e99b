/* SPDX-License-Identifier: MIT */
/* The batched dot's weights and select in AVX2 (view/dot_block.h), for a
 * CPU that has it: 4 points a group. */
#include "core/cpu.h"

#if ISK__CPU_AVX2
#include <immintrin.h>

#include "view/dot_block.h"

/* weights_scalar for 4 points a group, WEIGHTS_GROUPS groups a step.  Each
 * lane does the scalar code's operations: products left to right, floors
 * by truncation of values >= 0, the rank selection as 0/1 doubles (small
 * integers, exact).  The last points (fewer than a step's groups) take the
 * scalar code. */
ISK__AVX2_FN void isk__dot_weights_avx2(dot_block *b, int m, double X0, double X1, double Y0, double H1)
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

ISK__AVX2_FN int isk__dot_select_avx2(const select_view *s, const double *y, int m, double *oy, int32_t *oix)
{
    /* view_transform.h's isk__view_axis_map, lane by lane */
    const __m256d axc = _mm256_set1_pd(s->axis.c), axk = _mm256_set1_pd(s->axis.k), axt = _mm256_set1_pd(s->axis.t);
    const __m256d axs = _mm256_set1_pd(s->axis.s), axp = _mm256_set1_pd(s->axis.p);
    const __m256d lo = _mm256_set1_pd(s->lo), hi = _mm256_set1_pd(s->hi);
    const __m256d n1 = _mm256_set1_pd(s->height - 1.0), n = _mm256_set1_pd((double)s->height);
    int kept = 0, k = 0;
    for (; k + 4 <= m; k += 4) {
        const __m256d v = _mm256_loadu_pd(y + k);
        __m256d Y = s->camera ? _mm256_sub_pd(axc, _mm256_mul_pd(axk, _mm256_add_pd(v, axt)))
                              : _mm256_add_pd(_mm256_mul_pd(axs, v), axp);
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
#else
typedef int isk__dot_block_avx2_unused; /* ISO C wants a declaration in every file */
#endif
