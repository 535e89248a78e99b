/* SPDX-License-Identifier: MIT */
/* src/sim/bounds_sse2.h — the SSE2 twins of two steps of bounds.c's
 * resting screen over a group, two particles at a time (internal;
 * bounds.c includes this where src/core/cpu.h's ISK__CPU_SSE2 is 1):
 *
 *   rested_bits_sse2(rest, n, &bits)    bit j of bits set when rest[j] != 0
 *   rest_on_walls_sse2(p, v, rest, n, rested, lo, hi, delta)
 *       each particle j of `rested` put on its wall (lo where rest[j] is 1,
 *       else hi) with velocity delta, every other one kept: by selects,
 *       where a branch a particle cost 3 cycles
 *
 * Each does the whole pairs of [0, n) and returns how many particles that
 * is; bounds.c's loops do the rest, and the same for every particle in
 * the portable build. */
#ifndef ISKRA_SIM_BOUNDS_SSE2_H
#define ISKRA_SIM_BOUNDS_SSE2_H

#include "core/cpu.h"

#if ISK__CPU_SSE2
#include <emmintrin.h>
#include <stddef.h>
#include <stdint.h>

static inline size_t rested_bits_sse2(const double *rest, size_t n, uint32_t *bits)
{
    const __m128d Z = _mm_setzero_pd();
    size_t j = 0;
    for (; j + 2 <= n; j += 2)
        *bits |= (uint32_t)_mm_movemask_pd(_mm_cmpneq_pd(_mm_loadu_pd(rest + j), Z)) << j;
    return j;
}

static inline size_t rest_on_walls_sse2(double *p, double *v, const double *rest, size_t n, uint32_t rested,
                                        double lo, double hi, double delta)
{
    static const uint64_t lane[4][2] = {{0, 0}, {~0ull, 0}, {0, ~0ull}, {~0ull, ~0ull}};
    const __m128d L = _mm_set1_pd(lo), H = _mm_set1_pd(hi), D = _mm_set1_pd(delta), ONE = _mm_set1_pd(1.0);
    size_t j = 0;
    for (; j + 2 <= n; j += 2) {
        const __m128d M = _mm_loadu_pd((const double *)(const void *)lane[rested >> j & 3u]);
        const __m128d at_lo = _mm_cmpeq_pd(_mm_loadu_pd(rest + j), ONE);
        const __m128d wall = _mm_or_pd(_mm_and_pd(at_lo, L), _mm_andnot_pd(at_lo, H));
        _mm_storeu_pd(p + j, _mm_or_pd(_mm_and_pd(M, wall), _mm_andnot_pd(M, _mm_loadu_pd(p + j))));
        _mm_storeu_pd(v + j, _mm_or_pd(_mm_and_pd(M, D), _mm_andnot_pd(M, _mm_loadu_pd(v + j))));
    }
    return j;
}
#endif /* ISK__CPU_SSE2 */

#endif
