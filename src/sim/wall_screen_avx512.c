/* SPDX-License-Identifier: MIT */
/* The walls' screen in AVX-512 (see wall_screen.h), for a CPU that has it. */
#include "core/cpu.h"

#if ISK__CPU_AVX512
#include <immintrin.h>

#include "sim/wall_screen_loops.h"

/* The same eight lanes at a time, the signs and the compares read into
 * mask registers. */
static ISK__INLINE ISK__AVX512_FN int fires8(const double *x, const double *y, __m512d L, __m512d R, __m512d B,
                                             __m512d T)
{
    __m512d acc = _mm512_setzero_pd();
    for (unsigned k = 0; k < ISK_WALL_SCREEN; k += 8) {
        const __m512d X = _mm512_loadu_pd(x + k), Y = _mm512_loadu_pd(y + k);
        const __m512d ox = _mm512_or_pd(_mm512_sub_pd(X, L), _mm512_sub_pd(R, X));
        const __m512d oy = _mm512_or_pd(_mm512_sub_pd(Y, B), _mm512_sub_pd(T, Y));
        acc = _mm512_or_pd(acc, _mm512_or_pd(ox, oy));
    }
    return _mm512_movepi64_mask(_mm512_castpd_si512(acc)) != 0;
}

static ISK__INLINE ISK__AVX512_FN unsigned out8(const double *p, __m512d lo, __m512d hi)
{
    const __m512d v = _mm512_loadu_pd(p);
    return (unsigned)(_mm512_cmp_pd_mask(v, lo, _CMP_NGE_UQ) | _mm512_cmp_pd_mask(v, hi, _CMP_NLE_UQ));
}

ISK__AVX512_FN uint64_t isk__wall_screen_in_avx512(size_t n, const double *x, const double *y, const isk_wall_box *w,
                                             isk_wall_outside *out)
{
    const __m512d L = _mm512_set1_pd(w->left), R = _mm512_set1_pd(w->right);
    const __m512d B = _mm512_set1_pd(w->bottom), T = _mm512_set1_pd(w->top);
    SCREEN_GROUPS(fires8, out8, 8, L, R, B, T);
}
#else
typedef int isk__wall_screen_avx512_unused; /* ISO C wants a declaration in every file */
#endif
