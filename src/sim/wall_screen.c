/* SPDX-License-Identifier: MIT */
/* The walls' screen, portable, and the one place that picks its AVX2 and
 * AVX-512 twins (see wall_screen.h). */
#include "sim/wall_screen.h"

#include <math.h>
#include <string.h>

#include "core/cpu.h" /* ISK__CPU_AVX2, isk__have_avx2 */
#include "sim/wall_screen_loops.h"

_Static_assert(ISK_WALL_SCREEN_SPAN == ISK_WALL_SCREEN * ISK_WALL_SCREEN_GROUPS, "one bit per group");
_Static_assert(ISK_WALL_SCREEN_GROUPS <= 64, "the flags are one 64-bit word");
_Static_assert(ISK_WALL_SCREEN <= 16, "a group's mask is 16 bits");

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

isk_wall_screen_fn isk__wall_screen_avx512(void)
{
#if ISK__CPU_AVX512
    if (isk__have_avx512())
        return isk__wall_screen_in_avx512;
#endif
    return NULL;
}

isk_wall_screen_fn isk__wall_screen_avx2(void)
{
#if ISK__CPU_AVX2
    if (isk__have_avx2())
        return isk__wall_screen_in_avx2;
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
