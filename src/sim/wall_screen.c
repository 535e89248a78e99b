/* The walls' screen, portable and AVX2 (see wall_screen.h). */
#include "sim/wall_screen.h"

#include <string.h>


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

isk_wall_screen_fn isk_wall_screen_avx2(void)
{
    return NULL; /* (not written yet) */
}

isk_wall_screen_fn isk_wall_screen_pick(void)
{
    isk_wall_screen_fn f = isk_wall_screen_avx2();
    return f ? f : isk_wall_screen_portable;
}
