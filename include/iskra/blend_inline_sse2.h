/* SPDX-License-Identifier: MIT */
/* iskra/blend_inline_sse2.h — the SSE2 twin of iskra/blend_inline.h's
 * one-pixel rule, for the inlined isk_draw_pixel on x86-64 (included by
 * iskra/blend_inline.h; not used directly).
 *
 * The same bytes as isk__px in blend_inline.h, which is the form to read:
 * tests/test_raster_fast.c compares the two for every source and
 * destination alpha and every channel value.  It exists only because a
 * program's loop of isk_draw_pixel calls, inlined, runs 1.4 to 1.7 times
 * as long with the plain form under gcc (docs/performance.md, "Drawing
 * primitives").  Defining ISKRA_REFERENCE before including iskra.h (the
 * library's reference build does) keeps the plain form.
 *
 * Example: a loop of one colour, as a program writes it:
 *
 *     isk_canvas c;
 *     if (isk_canvas_init(&c, 64, 64) != ISK_OK) return 1;
 *     isk_canvas_fill(&c, ISK_BLACK);
 *     for (int y = 0; y < 64; y++)
 *         for (int x = 0; x < 64; x++)
 *             isk_draw_pixel(&c, x, y, isk_rgba(255, 128, 0, 100), ISK_BLEND_OVER);
 *     printf("%d\n", isk_canvas_at(&c, 10, 10)[0]);
 *     isk_canvas_free(&c);
 */
/* blend_inline.h first: it includes this file in turn, after the plain
 * rule this twin falls back on (isk__px_over_general). */
#include "iskra/blend_inline.h"

#ifndef ISKRA_BLEND_INLINE_SSE2_H
#define ISKRA_BLEND_INLINE_SSE2_H
#if defined(__SSE2__) /* on any other target this file holds nothing */

#include <emmintrin.h>
#include <stdint.h>
#include <string.h>

/* The part of over and add that depends on the colour only: the lanes
 * c sa + 128 (the alpha's c is 255).  Computed first, so a loop of one
 * colour computes it once, whatever its mode. */
static ISK__INLINE __m128i isk__source_k_sse2(isk_color s)
{
    uint32_t c32; /* x86 is little-endian: memory order r g b a is the value's byte order */
    memcpy(&c32, &s, 4);
    c32 |= 0xFF000000u; /* alpha: div255(255 sa + 255 inv) = 255 */
    const __m128i C = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)c32), _mm_setzero_si128());
    return _mm_add_epi16(_mm_mullo_epi16(C, _mm_set1_epi16((short)s.a)), _mm_set1_epi16(128));
}

/* isk__px_over given K = isk__source_k_sse2(s): an opaque destination's
 * div255(c sa + d inv) in 16-bit lanes, div255(x) the high half of
 * (x + 128) * 257; the rest as there. */
static ISK__INLINE void isk__px_over_k_sse2(uint8_t *d, isk_color s, __m128i K)
{
    const uint32_t sa = s.a, da = d[3], inv = 255u - sa;
    if (da == 255u) {
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

/* isk__px_add given K: the increments div255(c a) in 16-bit lanes
 * (alpha: div255(255 a) = a), then saturating byte adds. */
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

/* isk__px's twin given K = isk__source_k_sse2(s): one pixel in any mode. */
static ISK__INLINE void isk__px_k_sse2(uint8_t *d, isk_color s, __m128i K, isk_blend mode)
{
    switch (mode) {
    case ISK_BLEND_REPLACE:
        d[0] = s.r;
        d[1] = s.g;
        d[2] = s.b;
        d[3] = s.a;
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

static ISK__INLINE void isk__px_sse2(uint8_t *d, isk_color s, isk_blend mode)
{
    isk__px_k_sse2(d, s, isk__source_k_sse2(s), mode);
}

#endif /* __SSE2__ */
#endif
