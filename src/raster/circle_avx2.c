/* SPDX-License-Identifier: MIT */
/* The anti-aliased disc's row walk (raster/circle_loops.h) for AVX2: a
 * row's coverage four pixels a step (row_cov_avx2, pixel_cov's arithmetic
 * lane by lane, its tests as selects: the same doubles, no FMA) and its
 * blend eight pixels a step (raster/span_avx2.h: integer arithmetic, the
 * same bytes).  circle.c calls it for small discs where isk__have_avx2(). */
#include "core/cpu.h"

#if ISK__CPU_AVX2
#include <immintrin.h>

#include "raster/circle_loops.h"
#include "raster/span_avx2.h"

/* min_antideriv_cached on four lanes */
static ISK__INLINE ISK__AVX2_FN __m256d mac4(__m256d x, __m256d hx, const edge_y *e)
{
    const __m256d cw = _mm256_set1_pd(e->cw), hw = _mm256_set1_pd(e->hw), w = _mm256_set1_pd(e->w);
    __m256d t1 = _mm256_sub_pd(_mm256_add_pd(cw, hx), hw);
    __m256d t2 = _mm256_add_pd(_mm256_add_pd(_mm256_set1_pd(-e->cw), hx), hw);
    __m256d t3 = _mm256_mul_pd(_mm256_set1_pd(e->cl), x);
    __m256d t = _mm256_blendv_pd(t3, t2, _mm256_cmp_pd(x, _mm256_set1_pd(-e->w), _CMP_LT_OQ));
    return _mm256_blendv_pd(t, t1, _mm256_cmp_pd(x, w, _CMP_GT_OQ));
}

/* strip_cached on four lanes */
static ISK__INLINE ISK__AVX2_FN __m256d strip4(__m256d a, __m256d ha, __m256d b, __m256d hb, const edge_y *e)
{
    __m256d v = _mm256_sub_pd(mac4(b, hb, e), mac4(a, ha, e));
    return e->y < 0.0 ? _mm256_xor_pd(v, _mm256_set1_pd(-0.0)) : v;
}

static ISK__INLINE ISK__AVX2_FN void row_cov_avx2(uint8_t *cov, int kb, int n, const double *ca, const double *ha,
                                                  const double *cb, const double *hb, const double *fx2,
                                                  const double *nx2, double r2, double fy2, double ny2,
                                                  const edge_y *e0, const edge_y *e1)
{
    const __m256d R2 = _mm256_set1_pd(r2), FY2 = _mm256_set1_pd(fy2), NY2 = _mm256_set1_pd(ny2);
    const __m256d one = _mm256_set1_pd(1.0), k255 = _mm256_set1_pd(255.0), half = _mm256_set1_pd(0.5);
    for (int i = 0; i < n; i += 4) {
        const int k = kb + i;
        /* four pixels wholly inside (the middle of a wide row): 255 each,
         * what the selects below give them, without the strips */
        const __m256d full = _mm256_cmp_pd(_mm256_add_pd(_mm256_loadu_pd(fx2 + k), FY2), R2, _CMP_LE_OQ);
        if (_mm256_movemask_pd(full) == 15) {
            memset(cov + i, 255, 4);
            continue;
        }
        __m256d a = _mm256_loadu_pd(ca + k), b = _mm256_loadu_pd(cb + k);
        __m256d hav = _mm256_loadu_pd(ha + k), hbv = _mm256_loadu_pd(hb + k);
        __m256d area = _mm256_sub_pd(strip4(a, hav, b, hbv, e1), strip4(a, hav, b, hbv, e0));
        /* isk__coverage: floor(255 area + 0.5), below 1 -> 0, from 255 on -> 255 */
        __m256d v = _mm256_add_pd(_mm256_mul_pd(k255, area), half);
        v = _mm256_and_pd(v, _mm256_cmp_pd(v, one, _CMP_GE_OQ));
        v = _mm256_blendv_pd(v, k255, _mm256_cmp_pd(v, k255, _CMP_GE_OQ));
        /* outside the disc: 0; wholly inside: 255 (tested in that order last) */
        v = _mm256_andnot_pd(_mm256_cmp_pd(_mm256_add_pd(_mm256_loadu_pd(nx2 + k), NY2), R2, _CMP_GE_OQ), v);
        v = _mm256_blendv_pd(v, k255, full);
        __m128i q = _mm256_cvttpd_epi32(v);
        q = _mm_packus_epi16(_mm_packs_epi32(q, q), q);
        int32_t w4 = _mm_cvtsi128_si32(q);
        memcpy(cov + i, &w4, 4);
    }
}

AA_ROWS_FN(isk__circle_aa_rows_small_avx2, ISK__AVX2_FN, ROW_SMALL, isk__span_cov_avx2, row_cov_avx2)
#else
typedef int isk__circle_avx2_unused; /* ISO C wants a declaration in every file */
#endif
