/* SPDX-License-Identifier: MIT */
/* src/raster/blend_px_sse2.h — the SSE2 twins of the per-pixel kernels
 * of raster/blend_px.h (internal; blend_px.h includes this where
 * src/core/cpu.h's ISK__CPU_SSE2 is 1).
 *
 *   isk__px_sse2(d, s, mode), isk__px_over_sse2(d, s)
 *       iskra/blend_inline.h's isk__px and isk__px_over: the public twins
 *       of iskra/blend_inline_sse2.h (the inlined isk_draw_pixel runs
 *       them too), written once there
 *   isk__over_opaque_lanes_sse2(d, p, inv)   isk__over_opaque_lanes
 *   isk__sat_add_u8x4_sse2(a, b)             isk__sat_add_u8x4
 *
 * Same bytes: div255(x) for x <= 255*255 is the high half of
 * (x + 128) * 257 (checked for every x in tests/raster_kernels_body.h;
 * tests/test_raster_fast.c checks the one-pixel twin against the rule for
 * every pair of alphas). */
#ifndef ISKRA_RASTER_BLEND_PX_SSE2_H
#define ISKRA_RASTER_BLEND_PX_SSE2_H

#include "core/cpu.h"

#if ISK__CPU_SSE2
#include <emmintrin.h>
#include <stdint.h>
#include <string.h>

#include "iskra/blend_inline_sse2.h" /* isk__px_sse2, isk__px_over_sse2: the public twins */

/* p: the 16-bit lanes r a', g a', b a', 255 a' of a coverage table (x86
 * is little-endian: a uint64's lanes are r g b a in memory order). */
static ISK__INLINE void isk__over_opaque_lanes_sse2(uint8_t *d, uint64_t p, uint32_t inv)
{
    uint32_t d32;
    memcpy(&d32, d, 4);
    __m128i D = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)d32), _mm_setzero_si128());
    __m128i x = _mm_add_epi16(_mm_mullo_epi16(D, _mm_set1_epi16((short)inv)), _mm_cvtsi64_si128((long long)p));
    x = _mm_mulhi_epu16(_mm_add_epi16(x, _mm_set1_epi16(128)), _mm_set1_epi16(257));
    d32 = (uint32_t)_mm_cvtsi128_si32(_mm_packus_epi16(x, x));
    memcpy(d, &d32, 4);
}

static ISK__INLINE uint32_t isk__sat_add_u8x4_sse2(uint32_t a, uint32_t b)
{
    return (uint32_t)_mm_cvtsi128_si32(_mm_adds_epu8(_mm_cvtsi32_si128((int)a), _mm_cvtsi32_si128((int)b)));
}
#endif /* ISK__CPU_SSE2 */

#endif
