/* SPDX-License-Identifier: MIT */
/* src/raster/dot_kernel_vector.h — the coverage dot's 2x2 blend of
 * raster/dot_kernel.h, add and over, without a coverage table, in GCC /
 * Clang vector extensions: the twin of dot_kernel_sse2.h for targets
 * without SSE2 (the compiler lowers it to NEON, wasm simd128, ...).
 * Internal; dot_kernel.h includes this where src/core/cpu.h's
 * ISK__CPU_VECTOR is 1 (tests/test_dot_kernels_generic.c forces it on
 * x86-64 with ISK__CPU_NO_SSE2, so it is checked here too).
 *
 *   isk__blend_2x2_vector(p, stride, w, col, mode)   the block at p: the
 *       four a' = div255(sa w) at once, then each row's two pixels in one
 *       vector of 16-bit lanes (a row with a pixel that is not opaque:
 *       the per-pixel rule)
 *
 * isk__px_cov's bytes: div255 is span_vector.h's isk__v_div255, exact for
 * every product of two bytes. */
#ifndef ISKRA_RASTER_DOT_KERNEL_VECTOR_H
#define ISKRA_RASTER_DOT_KERNEL_VECTOR_H

#include "core/cpu.h"

#if ISK__CPU_VECTOR
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "raster/blend_px.h"
#include "raster/span_vector.h" /* the vector types, isk__v_div255, isk__v2_over */

/* One row of the block: two pixels at p with their a' spread over their
 * channels (aa = [a0 x4, a1 x4]) and the colour C = [r g b 255 r g b 255];
 * isk__px_cov's bytes (see blend_px.h). */
static ISK__INLINE void isk__row2_vector(uint8_t *p, isk__u16x8 aa, isk__u16x8 C, isk_color col,
                                         const uint32_t *w, isk_blend mode)
{
    if (mode == ISK_BLEND_ADD) {
        /* the alpha lane: div255(255 a') = a' */
        const isk__u16x8 inc = isk__v_div255(aa * C);
        isk__u8x16 v = {0};
        memcpy(&v, p, 8);
        v = isk__v_sat_add(v, isk__v_pack(inc, inc));
        memcpy(p, &v, 8);
    } else if (p[3] == 255u && p[7] == 255u) {
        const isk__u16x8 x = isk__v2_over(isk__v_widen8(p), aa, C);
        const isk__u8x16 v = isk__v_pack(x, x);
        memcpy(p, &v, 8);
    } else {
        isk__px_cov(p, col, w[0], mode);
        isk__px_cov(p + 4, col, w[1], mode);
    }
}

/* The whole 2x2 block (add or over): a' = div255(sa w) for the four
 * weights at once, then a row of two pixels at a time. */
static ISK__INLINE void isk__blend_2x2_vector(uint8_t *p, size_t stride, const uint32_t w[4], isk_color col,
                                              isk_blend mode)
{
    const isk__u16x8 W = {(uint16_t)w[0], (uint16_t)w[1], (uint16_t)w[2], (uint16_t)w[3], 0, 0, 0, 0};
    const isk__u16x8 A = isk__v_div255(W * (uint16_t)col.a);
    const isk__u16x8 C = {col.r, col.g, col.b, 255, col.r, col.g, col.b, 255};
    isk__row2_vector(p, ISK__SHUF16(A, A, 0, 0, 0, 0, 1, 1, 1, 1), C, col, w, mode);
    isk__row2_vector(p + stride, ISK__SHUF16(A, A, 2, 2, 2, 2, 3, 3, 3, 3), C, col, w + 2, mode);
}
#endif /* ISK__CPU_VECTOR */

#endif
