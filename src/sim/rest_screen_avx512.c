/* SPDX-License-Identifier: MIT */
/* The walls' resting screen (rest_screen_loops.h's loop) compiled for AVX-512,
 * for a CPU that has it. */
#include "core/cpu.h"

#if ISK__CPU_AVX512
#include "sim/rest_screen_loops.h"

ISK__AVX512_FN void isk__rest_screen_in_avx512(size_t n, const double *pos, const double *vel, const double *m,
                                         double drag, const isk_rest_axis *ax, double *rest)
{
    rest_screen_run(n, pos, vel, m, drag, ax, rest);
}
#else
typedef int isk__rest_screen_avx512_unused; /* ISO C wants a declaration in every file */
#endif
