/* SPDX-License-Identifier: MIT */
/* The walls' resting screen, portable (rest_screen_loops.h's loop), and
 * the one place that picks its AVX2 and AVX-512 builds (see
 * rest_screen.h). */
#include "sim/rest_screen.h"

#include "core/cpu.h" /* ISK__CPU_AVX2, isk__have_avx2 */
#include "sim/rest_screen_loops.h"

void isk__rest_screen_portable(size_t n, const double *pos, const double *vel, const double *m, double drag,
                              const isk_rest_axis *ax, double *rest)
{
    rest_screen_run(n, pos, vel, m, drag, ax, rest);
}

isk_rest_screen_fn isk__rest_screen_avx512(void)
{
#if ISK__CPU_AVX512
    if (isk__have_avx512())
        return isk__rest_screen_in_avx512;
#endif
    return NULL;
}

isk_rest_screen_fn isk__rest_screen_avx2(void)
{
#if ISK__CPU_AVX2
    if (isk__have_avx2())
        return isk__rest_screen_in_avx2;
#endif
    return NULL;
}

isk_rest_screen_fn isk__rest_screen_pick(void)
{
    isk_rest_screen_fn f = isk__rest_screen_avx512();
    if (!f)
        f = isk__rest_screen_avx2();
    return f ? f : isk__rest_screen_portable;
}
