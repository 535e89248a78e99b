/* The walls' screen, portable, AVX2 and AVX-512 (see wall_screen.h). */
#include "sim/wall_screen.h"

#include <string.h>

#include "raster/span_simd.h" /* ISK__SPAN_AVX2, ISK__AVX2_FN, isk__have_avx2 */

_Static_assert(ISK_WALL_SCREEN_SPAN == ISK_WALL_SCREEN * ISK_WALL_SCREEN_GROUPS, "one bit per group");
_Static_assert(ISK_WALL_SCREEN_GROUPS <= 64, "the flags are one 64-bit word");

/* 1 when a sign bit is set in some x - left, right - x, y - bottom or
 * top - y of [0, n): or-ed as integers, so the loop vectorizes.  Not
 * unrolled: with a full group's constant trip count GCC would unroll it
 * completely before vectorizing and leave 64 scalar subtractions. */
static inline int any_outside(size_t n, const double *restrict x, const double *restrict y, const isk_wall_box *w)
{
    const double left = w->left, right = w->right, bottom = w->bottom, top = w->top;
    uint64_t acc = 0;
#pragma GCC unroll 1
    for (size_t i = 0; i < n; i++) {
        double a = x[i] - left, b = right - x[i], c = y[i] - bottom, d = top - y[i];
        uint64_t ua, ub, uc, ud;
        memcpy(&ua, &a, sizeof ua);
        memcpy(&ub, &b, sizeof ub);
        memcpy(&uc, &c, sizeof uc);
        memcpy(&ud, &d, sizeof ud);
        acc |= (ua | ub) | (uc | ud);
    }
    return (int)(acc >> 63);
}

/* Full groups have the constant trip count ISK_WALL_SCREEN (no remainder
 * loop), the tail its own. */
uint64_t isk_wall_screen_portable(size_t n, const double *x, const double *y, const isk_wall_box *w)
{
    uint64_t flags = 0;
    size_t g = 0, o = 0;
    for (; o + ISK_WALL_SCREEN <= n && g < ISK_WALL_SCREEN_GROUPS; o += ISK_WALL_SCREEN, g++)
        flags |= (uint64_t)any_outside(ISK_WALL_SCREEN, x + o, y + o, w) << g;
    if (o < n && g < ISK_WALL_SCREEN_GROUPS)
        flags |= (uint64_t)any_outside(n - o < ISK_WALL_SCREEN ? n - o : ISK_WALL_SCREEN, x + o, y + o, w) << g;
    return flags;
}

#if ISK__SPAN_AVX2
/* The same subtractions four lanes at a time (IEEE subtraction: the same
 * results, NaN signs included, as the portable loop's), the sign bits read
 * with movemask. */
static ISK__AVX2_FN uint64_t screen_avx2(size_t n, const double *x, const double *y, const isk_wall_box *w)
{
    const __m256d L = _mm256_set1_pd(w->left), R = _mm256_set1_pd(w->right);
    const __m256d B = _mm256_set1_pd(w->bottom), T = _mm256_set1_pd(w->top);
    uint64_t flags = 0;
    size_t g = 0, o = 0;
    for (; o + ISK_WALL_SCREEN <= n && g < ISK_WALL_SCREEN_GROUPS; o += ISK_WALL_SCREEN, g++) {
        __m256d acc = _mm256_setzero_pd();
        for (size_t k = o; k < o + ISK_WALL_SCREEN; k += 4) {
            const __m256d X = _mm256_loadu_pd(x + k), Y = _mm256_loadu_pd(y + k);
            const __m256d ox = _mm256_or_pd(_mm256_sub_pd(X, L), _mm256_sub_pd(R, X));
            const __m256d oy = _mm256_or_pd(_mm256_sub_pd(Y, B), _mm256_sub_pd(T, Y));
            acc = _mm256_or_pd(acc, _mm256_or_pd(ox, oy));
        }
        flags |= (uint64_t)(_mm256_movemask_pd(acc) != 0) << g;
    }
    if (o < n && g < ISK_WALL_SCREEN_GROUPS)
        flags |= (uint64_t)any_outside(n - o < ISK_WALL_SCREEN ? n - o : ISK_WALL_SCREEN, x + o, y + o, w) << g;
    return flags;
}
#endif

#if ISK__SPAN_AVX512
/* The same subtractions eight lanes at a time, the sign bits read into a
 * mask register (AVX-512DQ's movepi64). */
static ISK__AVX512_FN uint64_t screen_avx512(size_t n, const double *x, const double *y, const isk_wall_box *w)
{
    const __m512d L = _mm512_set1_pd(w->left), R = _mm512_set1_pd(w->right);
    const __m512d B = _mm512_set1_pd(w->bottom), T = _mm512_set1_pd(w->top);
    uint64_t flags = 0;
    size_t g = 0, o = 0;
    for (; o + ISK_WALL_SCREEN <= n && g < ISK_WALL_SCREEN_GROUPS; o += ISK_WALL_SCREEN, g++) {
        __m512d acc = _mm512_setzero_pd();
        for (size_t k = o; k < o + ISK_WALL_SCREEN; k += 8) {
            const __m512d X = _mm512_loadu_pd(x + k), Y = _mm512_loadu_pd(y + k);
            const __m512d ox = _mm512_or_pd(_mm512_sub_pd(X, L), _mm512_sub_pd(R, X));
            const __m512d oy = _mm512_or_pd(_mm512_sub_pd(Y, B), _mm512_sub_pd(T, Y));
            acc = _mm512_or_pd(acc, _mm512_or_pd(ox, oy));
        }
        flags |= (uint64_t)(_mm512_movepi64_mask(_mm512_castpd_si512(acc)) != 0) << g;
    }
    if (o < n && g < ISK_WALL_SCREEN_GROUPS)
        flags |= (uint64_t)any_outside(n - o < ISK_WALL_SCREEN ? n - o : ISK_WALL_SCREEN, x + o, y + o, w) << g;
    return flags;
}
#endif

isk_wall_screen_fn isk_wall_screen_avx512(void)
{
#if ISK__SPAN_AVX512
    if (isk__have_avx512())
        return screen_avx512;
#endif
    return NULL;
}

isk_wall_screen_fn isk_wall_screen_avx2(void)
{
#if ISK__SPAN_AVX2
    if (isk__have_avx2())
        return screen_avx2;
#endif
    return NULL;
}

isk_wall_screen_fn isk_wall_screen_pick(void)
{
    isk_wall_screen_fn f = isk_wall_screen_avx512();
    if (!f)
        f = isk_wall_screen_avx2();
    return f ? f : isk_wall_screen_portable;
}
