/* SPDX-License-Identifier: MIT */
/* src/raster/blend_px_sse2.h — the SSE2 twins of the per-pixel kernels
 * of raster/blend_px.h (internal; blend_px.h includes this where
 * src/core/cpu.h's ISK__CPU_SSE2 is 1).
 *
 *   isk__px_sse2(d, s, mode), isk__px_over_sse2(d, s)
 *       iskra/blend_inline.h's isk__px and isk__px_over: on an opaque
 *       destination the four channels' div255(c sa + d (255 - sa)) in one
 *       register, add's four saturating additions in one instruction
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

#include "iskra/blend_inline.h" /* ISK__INLINE, isk__px_over_general */

/* The colour's lanes c sa + 128 (alpha's c = 255: div255(255 sa + 255
 * (255 - sa)) = 255), computed once for a row or a loop of one colour. */
static ISK__INLINE __m128i isk__source_k_sse2(isk_color s)
{
    uint32_t c32; /* x86 is little-endian: memory order r g b a is the value's byte order */
    memcpy(&c32, &s, 4);
    c32 |= 0xFF000000u;
    const __m128i C = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)c32), _mm_setzero_si128());
    return _mm_add_epi16(_mm_mullo_epi16(C, _mm_set1_epi16((short)s.a)), _mm_set1_epi16(128));
}

static ISK__INLINE void isk__px_over_k_sse2(uint8_t *d, isk_color s, __m128i K)
{
    uint32_t sa = s.a;
    uint32_t da = d[3];
    uint32_t inv = 255u - sa;
    if (da == 255u) {
        /* div255(c sa + d inv) in 16-bit lanes: the high half of
         * (x + 128) * 257 */
        uint32_t d32;
        memcpy(&d32, d, 4);
        __m128i x = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)d32), _mm_setzero_si128());
        x = _mm_add_epi16(_mm_mullo_epi16(x, _mm_set1_epi16((short)inv)), K);
        x = _mm_mulhi_epu16(x, _mm_set1_epi16(257));
        d32 = (uint32_t)_mm_cvtsi128_si32(_mm_packus_epi16(x, x));
        memcpy(d, &d32, 4);
        return;
    }
    if (sa - 1u >= 254u) { /* sa 0 or 255 (one test) */
        if (sa)
            memcpy(d, &s, 4); /* r g b 255 */
        return;
    }
    isk__px_over_general(d, s, sa, da, inv);
}

/* increments div255(c a) in 16-bit lanes (alpha: div255(255 a) = a), then
 * saturating byte adds */
static ISK__INLINE void isk__px_add_k_sse2(uint8_t *d, __m128i K)
{
    uint32_t d32;
    memcpy(&d32, d, 4);
    const __m128i x = _mm_mulhi_epu16(K, _mm_set1_epi16(257));
    d32 = (uint32_t)_mm_cvtsi128_si32(_mm_adds_epu8(_mm_cvtsi32_si128((int)d32), _mm_packus_epi16(x, x)));
    memcpy(d, &d32, 4);
}

static ISK__INLINE void isk__px_over_sse2(uint8_t *d, isk_color s)
{
    isk__px_over_k_sse2(d, s, isk__source_k_sse2(s));
}

static ISK__INLINE void isk__px_sse2(uint8_t *d, isk_color s, isk_blend mode)
{
    const __m128i K = isk__source_k_sse2(s);
    switch (mode) {
    case ISK_BLEND_REPLACE:
        d[0] = s.r; d[1] = s.g; d[2] = s.b; d[3] = s.a;
        break;
    case ISK_BLEND_OVER:
        isk__px_over_k_sse2(d, s, K);
        break;
    case ISK_BLEND_ADD:
        isk__px_add_k_sse2(d, K);
        break;
    default: /* not a mode: nothing is drawn */
        break;
    }
}

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
