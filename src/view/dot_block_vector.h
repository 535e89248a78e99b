/* SPDX-License-Identifier: MIT */
/* src/view/dot_block_vector.h — view/dot_block.h's blends from a coverage
 * table in GCC / Clang vector extensions: the twins of dot_block_sse2.h
 * for targets without SSE2 (the compiler lowers them to NEON, wasm
 * simd128, ...).  Internal; dot_block.h includes this where
 * src/core/cpu.h's ISK__CPU_VECTOR is 1 (tests/test_dot_kernels_generic.c
 * forces it on x86-64 with ISK__CPU_NO_SSE2, so it is checked here too).
 *
 *   px2_vector(p, lut, wa, wb, mode)      px2's add, and its over on two
 *                                         opaque pixels, in one vector
 *   px4_vector(p, stride, lut, w, mode)   px4's over on four opaque
 *                                         pixels, in one set of lanes
 *
 * Each returns 1 when it blended, 0 (nothing touched) when the plain code
 * must (another mode, or a pixel that is not opaque).  The same bytes as
 * the table's per-pixel blends (blend_px.h's isk__px_lut). */
#ifndef ISKRA_VIEW_DOT_BLOCK_VECTOR_H
#define ISKRA_VIEW_DOT_BLOCK_VECTOR_H

#include "core/cpu.h"

#if ISK__CPU_VECTOR
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "raster/blend_px.h"
#include "raster/span_vector.h" /* the vector types, isk__v_div255 */

/* Source-over on the two opaque pixels at p, at coverages wa, wb:
 * div255(c a' + d (255 - a')) in their 16-bit lanes, from the coverage
 * table (blend_px.h's isk__over_opaque_lanes, two at once; the table's
 * 64-bit entries are four 16-bit lanes in memory order on the
 * little-endian targets cpu.h allows). */
static ISK__INLINE isk__u16x8 over2_opaque_vector(const uint8_t *p, const isk__cov_lut *lut, uint32_t wa,
                                                  uint32_t wb)
{
    const uint64_t pp[2] = {lut->over_p[wa], lut->over_p[wb]}, ii[2] = {lut->over_inv[wa], lut->over_inv[wb]};
    isk__u16x8 P, I;
    memcpy(&P, pp, 16);
    memcpy(&I, ii, 16);
    return isk__v_div255(isk__v_widen8(p) * I + P);
}

static ISK__INLINE int px2_vector(uint8_t *p, const isk__cov_lut *lut, uint32_t wa, uint32_t wb, isk_blend mode)
{
    if (mode == ISK_BLEND_ADD) {
        isk__u8x16 v = {0}, inc = {0};
        memcpy(&v, p, 8);
        memcpy(&inc, lut->add[wa], 4);
        memcpy((uint8_t *)&inc + 4, lut->add[wb], 4);
        v = isk__v_sat_add(v, inc);
        memcpy(p, &v, 8);
        return 1;
    }
    if (mode == ISK_BLEND_OVER && p[3] == 255u && p[7] == 255u) {
        const isk__u16x8 x = over2_opaque_vector(p, lut, wa, wb);
        const isk__u8x16 v = isk__v_pack(x, x);
        memcpy(p, &v, 8);
        return 1;
    }
    return 0;
}

static ISK__INLINE int px4_vector(uint8_t *p, size_t stride, const isk__cov_lut *lut, const uint8_t w[4],
                                  isk_blend mode)
{
    uint8_t *q = p + stride;
    if (mode == ISK_BLEND_OVER && (p[3] & p[7] & q[3] & q[7]) == 255u) {
        const isk__u8x16 r =
            isk__v_pack(over2_opaque_vector(p, lut, w[0], w[1]), over2_opaque_vector(q, lut, w[2], w[3]));
        memcpy(p, &r, 8);
        memcpy(q, (const uint8_t *)&r + 8, 8);
        return 1;
    }
    return 0;
}
#endif /* ISK__CPU_VECTOR */

#endif
