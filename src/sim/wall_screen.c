/* SPDX-License-Identifier: MIT */
/* The walls' screen, portable, AVX2 and AVX-512 (see wall_screen.h). */
#include "sim/wall_screen.h"

#include <math.h>
#include <string.h>

#include "raster/span_simd.h" /* ISK__SPAN_AVX2/512, ISK__AVX2_FN/512_FN, isk__have_avx2/512 */

_Static_assert(ISK_WALL_SCREEN_SPAN == ISK_WALL_SCREEN * ISK_WALL_SCREEN_GROUPS, "one bit per group");
_Static_assert(ISK_WALL_SCREEN_GROUPS <= 64, "the flags are one 64-bit word");
_Static_assert(ISK_WALL_SCREEN <= 16, "a group's mask is 16 bits");

/* 1 when a sign bit is set in some x - left, right - x, y - bottom or
 * top - y of [0, n): or-ed as integers, so the loop vectorizes.  The cheap
 * test run on every group: it catches every finite particle outside (and
 * a -0 on a +0 wall, which the masks then clear); a NaN whose sign bit is
 * clear escapes it.  Not unrolled: with a full group's constant trip count
 * GCC would unroll it completely before vectorizing and leave 64 scalar
 * subtractions. */
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

/* Bit i: !(lo <= p[i] <= hi), NaN included (quiet compares, no short
 * circuit, so the loop needs no branch). */
static inline unsigned outside_mask(size_t n, const double *p, double lo, double hi)
{
    unsigned m = 0;
    for (size_t i = 0; i < n; i++)
        m |= (unsigned)!(isgreaterequal(p[i], lo) & islessequal(p[i], hi)) << i;
    return m;
}

/* Group g's masks stored, its flag returned. */
static inline uint64_t store_group(isk_wall_outside *out, size_t g, unsigned mx, unsigned my)
{
    out->x[g] = (uint16_t)mx;
    out->y[g] = (uint16_t)my;
    return (uint64_t)((mx | my) != 0) << g;
}

/* Group g, [o, o + len), by the portable tests. */
static inline uint64_t group_portable(size_t len, size_t o, size_t g, const double *x, const double *y,
                                      const isk_wall_box *w, isk_wall_outside *out)
{
    if (!any_outside(len, x + o, y + o, w))
        return store_group(out, g, 0, 0);
    return store_group(out, g, outside_mask(len, x + o, w->left, w->right),
                       outside_mask(len, y + o, w->bottom, w->top));
}

/* The group past the last whole one, if any. */
static inline uint64_t screen_tail(size_t n, size_t o, size_t g, const double *x, const double *y,
                                   const isk_wall_box *w, isk_wall_outside *out)
{
    if (o >= n || g >= ISK_WALL_SCREEN_GROUPS)
        return 0;
    return group_portable(n - o < ISK_WALL_SCREEN ? n - o : ISK_WALL_SCREEN, o, g, x, y, w, out);
}

/* The whole groups of [0, n), one loop for every build: a group FIRES's
 * cheap test passes over gets zero masks, one it flags gets MASK's exact
 * ones, STEP particles at a time (lo, hi: the axis's walls in the build's
 * form); the tail group after them by the portable code.  A macro, not a
 * function taking the two tests: each build's are compiled for its own
 * target and inlined into its loop. */
#define SCREEN_GROUPS(FIRES, MASK, STEP, L, R, B, T)                                                          \
    uint64_t flags = 0;                                                                                        \
    size_t g = 0, o = 0;                                                                                       \
    for (; o + ISK_WALL_SCREEN <= n && g < ISK_WALL_SCREEN_GROUPS; o += ISK_WALL_SCREEN, g++) {              \
        unsigned mx = 0, my = 0;                                                                               \
        if (FIRES(x + o, y + o, L, R, B, T))                                                                   \
            for (unsigned k = 0; k < ISK_WALL_SCREEN; k += (STEP)) {                                           \
                mx |= MASK(x + o + k, L, R) << k;                                                              \
                my |= MASK(y + o + k, B, T) << k;                                                              \
            }                                                                                                  \
        flags |= store_group(out, g, mx, my);                                                                  \
    }                                                                                                          \
    return flags | screen_tail(n, o, g, x, y, w, out)

/* The portable tests on a whole group. */
static inline int fires16(const double *x, const double *y, double l, double r, double b, double t)
{
    const isk_wall_box w = {l, r, b, t};
    return any_outside(ISK_WALL_SCREEN, x, y, &w);
}
static inline unsigned mask16(const double *p, double lo, double hi)
{
    return outside_mask(ISK_WALL_SCREEN, p, lo, hi);
}

uint64_t isk__wall_screen_portable(size_t n, const double *x, const double *y, const isk_wall_box *w,
                                  isk_wall_outside *out)
{
    SCREEN_GROUPS(fires16, mask16, ISK_WALL_SCREEN, w->left, w->right, w->bottom, w->top);
}

#if ISK__SPAN_AVX2
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

static ISK__AVX2_FN uint64_t screen_avx2(size_t n, const double *x, const double *y, const isk_wall_box *w,
                                         isk_wall_outside *out)
{
    const __m256d L = _mm256_set1_pd(w->left), R = _mm256_set1_pd(w->right);
    const __m256d B = _mm256_set1_pd(w->bottom), T = _mm256_set1_pd(w->top);
    SCREEN_GROUPS(fires4, out4, 4, L, R, B, T);
}
#endif

#if ISK__SPAN_AVX512
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

static ISK__AVX512_FN uint64_t screen_avx512(size_t n, const double *x, const double *y, const isk_wall_box *w,
                                             isk_wall_outside *out)
{
    const __m512d L = _mm512_set1_pd(w->left), R = _mm512_set1_pd(w->right);
    const __m512d B = _mm512_set1_pd(w->bottom), T = _mm512_set1_pd(w->top);
    SCREEN_GROUPS(fires8, out8, 8, L, R, B, T);
}
#endif
#undef SCREEN_GROUPS

isk_wall_screen_fn isk__wall_screen_avx512(void)
{
#if ISK__SPAN_AVX512
    if (isk__have_avx512())
        return screen_avx512;
#endif
    return NULL;
}

isk_wall_screen_fn isk__wall_screen_avx2(void)
{
#if ISK__SPAN_AVX2
    if (isk__have_avx2())
        return screen_avx2;
#endif
    return NULL;
}

isk_wall_screen_fn isk__wall_screen_pick(void)
{
    isk_wall_screen_fn f = isk__wall_screen_avx512();
    if (!f)
        f = isk__wall_screen_avx2();
    return f ? f : isk__wall_screen_portable;
}
