/* SPDX-License-Identifier: MIT */
/* src/sim/wall_screen_loops.h — what every build of the walls' screen
 * shares (internal): the portable tests on a group, the flags and masks
 * stored, and SCREEN_GROUPS, the loop over a block's groups that
 * wall_screen.c compiles with the portable tests and wall_screen_avx2.c,
 * wall_screen_avx512.c with four and eight lanes.
 *
 *     uint64_t screen(size_t n, const double *x, const double *y, const isk_wall_box *w, isk_wall_outside *out)
 *     {
 *         SCREEN_GROUPS(fires16, mask16, ISK_WALL_SCREEN, w->left, w->right, w->bottom, w->top);
 *     }
 */
#ifndef ISKRA_SIM_WALL_SCREEN_LOOPS_H
#define ISKRA_SIM_WALL_SCREEN_LOOPS_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "core/cpu.h"
#include "sim/wall_screen.h"

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

#if ISK__CPU_AVX2
/* wall_screen_avx2.c, for a CPU that has AVX2 */
uint64_t isk__wall_screen_in_avx2(size_t n, const double *x, const double *y, const isk_wall_box *w,
                                 isk_wall_outside *out);
#endif
#if ISK__CPU_AVX512
/* wall_screen_avx512.c, for a CPU that has AVX-512 */
uint64_t isk__wall_screen_in_avx512(size_t n, const double *x, const double *y, const isk_wall_box *w,
                                   isk_wall_outside *out);
#endif

#endif
