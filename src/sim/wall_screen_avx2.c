/* SPDX-License-Identifier: MIT */
/* The walls' screen in AVX2 (see wall_screen.h), for a CPU that has it. */
#include "core/cpu.h"

#if ISK__CPU_AVX2
#include <immintrin.h>

#include "sim/wall_screen_loops.h"

/* The sign test four lanes at a time (IEEE subtraction: the portable
 * loop's results, NaN signs included), and the masks by
 * not-greater-or-equal and not-less-or-equal compares (unordered: true
 * for a NaN), read with movemask. */
static ISK__INLINE ISK__AVX2_FN int fires4(const double *x, const double *y, __m256d L, __m256d R, __m256d B,
                                           __m256d T)
{
    __m256d acc = _mm256_setzero_pd();
    for (unsigned k = 0; k < ISK_WALL_SCREEN; k += 4) {
        const __m256d X = _mm256_loadu_pd(x + k), Y = _mm256_loadu_pd(y + k);
        const __m256d ox = _mm256_or_pd(_mm256_sub_pd(X, L), _mm256_sub_pd(R, X));
        const __m256d oy = _mm256_or_pd(_mm256_sub_pd(Y, B), _mm256_sub_pd(T, Y));
        acc = _mm256_or_pd(acc, _mm256_or_pd(ox, oy));
    }
    return _mm256_movemask_pd(acc) != 0;
}

static ISK__INLINE ISK__AVX2_FN unsigned out4(const double *p, __m256d lo, __m256d hi)
{
    const __m256d v = _mm256_loadu_pd(p);
    return (unsigned)_mm256_movemask_pd(
        _mm256_or_pd(_mm256_cmp_pd(v, lo, _CMP_NGE_UQ), _mm256_cmp_pd(v, hi, _CMP_NLE_UQ)));
}

ISK__AVX2_FN uint64_t isk__wall_screen_in_avx2(size_t n, const double *x, const double *y, const isk_wall_box *w,
                                         isk_wall_outside *out)
{
    const __m256d L = _mm256_set1_pd(w->left), R = _mm256_set1_pd(w->right);
    const __m256d B = _mm256_set1_pd(w->bottom), T = _mm256_set1_pd(w->top);
    SCREEN_GROUPS(fires4, out4, 4, L, R, B, T);
}
#else
typedef int isk__wall_screen_avx2_unused; /* ISO C wants a declaration in every file */
#endif
