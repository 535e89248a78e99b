/* SPDX-License-Identifier: MIT */
/* iskra/blend_inline.h — the blend rules of iskra/blend.h for one pixel,
 * as inline code (included by iskra/draw.h; not called directly).
 *
 * isk_draw_pixel (iskra/draw.h) is also a macro over an inline copy of
 * itself, as the C library's functions may be (C11 7.1.4), so that a loop
 * of calls compiles to a loop of blends: the call, the choice of the mode
 * and the colour's set-up leave the loop.  It needs the rule here, and the
 * library's own kernels (src/raster/blend_px.h) take it from here too, so
 * the rule is written once.  Everything named isk__ is internal: it may
 * change between versions; use isk_blend_pixel and isk_draw_pixel.
 *
 * Nothing here allocates, fails or keeps state.
 *
 * Example: the macro, the function and isk_blend_pixel give the same bytes:
 *
 *     isk_canvas a, b;
 *     if (isk_canvas_init(&a, 4, 4) != ISK_OK) return 1;
 *     if (isk_canvas_init(&b, 4, 4) != ISK_OK) { isk_canvas_free(&a); return 1; }
 *     isk_canvas_fill(&a, ISK_BLACK);
 *     isk_canvas_fill(&b, ISK_BLACK);
 *     isk_color c = isk_rgba(255, 128, 0, 200);
 *     isk_draw_pixel(&a, 1, 2, c, ISK_BLEND_OVER);      // inlined here
 *     (isk_draw_pixel)(&b, 1, 2, c, ISK_BLEND_OVER);    // the library's function
 *     uint8_t px[4] = {0, 0, 0, 255};
 *     isk_blend_pixel(px, c, ISK_BLEND_OVER);
 *     int same = memcmp(a.pixels, b.pixels, (size_t)a.stride * 4) == 0 &&
 *                memcmp(isk_canvas_at(&a, 1, 2), px, 4) == 0;
 *     printf("%s\n", same ? "same bytes" : "different");
 *     isk_canvas_free(&a);
 *     isk_canvas_free(&b);
 *     if (!same) return 1; */
#ifndef ISKRA_BLEND_INLINE_H
#define ISKRA_BLEND_INLINE_H

#include <stdint.h>
#include <string.h>

#include "iskra/blend.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#ifndef ISK__INLINE
#if defined(__GNUC__)
#define ISK__INLINE inline __attribute__((always_inline))
#else
#define ISK__INLINE inline
#endif
#endif

static ISK__INLINE uint8_t isk__sat_add(uint32_t a, uint32_t b)
{
    uint32_t s = a + b;
    return (uint8_t)(s > 255u ? 255u : s);
}

/* Source-over onto a translucent pixel: the division by the output alpha.
 * Out of line (and marked cold) so the common opaque path stays short. */
#if defined(__GNUC__)
__attribute__((noinline, cold, unused))
#endif
static void isk__px_over_general(uint8_t *d, isk_color s, uint32_t sa, uint32_t da, uint32_t inv)
{
    uint32_t wd = da * inv;              /* destination weight, scaled by 255 */
    uint32_t A = 255u * sa + wd;         /* 255 * output alpha */
    uint32_t half = A / 2u;
    d[0] = (uint8_t)((255u * s.r * sa + d[0] * wd + half) / A);
    d[1] = (uint8_t)((255u * s.g * sa + d[1] * wd + half) / A);
    d[2] = (uint8_t)((255u * s.b * sa + d[2] * wd + half) / A);
    d[3] = (uint8_t)isk_div255(A);
}

/* Source-over on straight colour (iskra/blend.h). */
/* The part of source-over and of add that depends on the colour only
 * (isk__px_over_k, isk__px_add_k): with SSE2 the lanes c sa + 128 (alpha's
 * c = 255), else nothing.  Computed before the mode is chosen, both modes
 * use it, so a loop of one colour computes it once whatever its mode. */
#if defined(__SSE2__)
typedef __m128i isk__src_k;
static ISK__INLINE isk__src_k isk__source_k(isk_color s)
{
    uint32_t c32; /* x86 is little-endian: memory order r g b a is the value's byte order */
    memcpy(&c32, &s, 4);
    c32 |= 0xFF000000u; /* alpha: div255(255 sa + 255 inv) = 255 */
    const __m128i C = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)c32), _mm_setzero_si128());
    return _mm_add_epi16(_mm_mullo_epi16(C, _mm_set1_epi16((short)s.a)), _mm_set1_epi16(128));
}
#else
typedef int isk__src_k;
static ISK__INLINE isk__src_k isk__source_k(isk_color s)
{
    (void)s;
    return 0;
}
#endif

/* Source-over on straight colour (iskra/blend.h), given
 * K = isk__source_k(s): a loop of one colour computes K once, and an
 * opaque pixel's chain is only d inv + K. */
static ISK__INLINE void isk__px_over_k(uint8_t *d, isk_color s, isk__src_k K)
{
    uint32_t sa = s.a;
    uint32_t da = d[3];
    uint32_t inv = 255u - sa;
    if (da == 255u) {
        /* Opaque destination: the common case, no division by A, and no
         * test of the source alpha either: the rule gives sa 0 and 255
         * their bytes (div255(255 d) = d, div255(255 c) = c). */
#if defined(__SSE2__)
        /* div255(c sa + d inv) in 16-bit lanes, div255(x) the high half
         * of (x + 128) * 257 */
        uint32_t d32;
        memcpy(&d32, d, 4);
        __m128i x = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)d32), _mm_setzero_si128());
        x = _mm_add_epi16(_mm_mullo_epi16(x, _mm_set1_epi16((short)inv)), K);
        x = _mm_mulhi_epu16(x, _mm_set1_epi16(257));
        d32 = (uint32_t)_mm_cvtsi128_si32(_mm_packus_epi16(x, x));
        memcpy(d, &d32, 4);
#else
        (void)K;
        d[0] = (uint8_t)isk_div255(s.r * sa + d[0] * inv);
        d[1] = (uint8_t)isk_div255(s.g * sa + d[1] * inv);
        d[2] = (uint8_t)isk_div255(s.b * sa + d[2] * inv);
#endif
        return;
    }
    if (sa - 1u >= 254u) { /* sa 0 or 255 (one test) */
        if (sa)
            memcpy(d, &s, 4); /* r g b 255 */
        return;
    }
    isk__px_over_general(d, s, sa, da, inv);
}

static ISK__INLINE void isk__px_over(uint8_t *d, isk_color s)
{
    isk__px_over_k(d, s, isk__source_k(s));
}

/* Add (iskra/blend.h), given K = isk__source_k(s). */
static ISK__INLINE void isk__px_add_k(uint8_t *d, isk_color s, isk__src_k K)
{
#if defined(__SSE2__)
    /* increments div255(c a) in 16-bit lanes (alpha: div255(255 a) = a),
     * then saturating byte adds */
    (void)s;
    uint32_t d32;
    memcpy(&d32, d, 4);
    const __m128i x = _mm_mulhi_epu16(K, _mm_set1_epi16(257));
    d32 = (uint32_t)_mm_cvtsi128_si32(_mm_adds_epu8(_mm_cvtsi32_si128((int)d32), _mm_packus_epi16(x, x)));
    memcpy(d, &d32, 4);
#else
    (void)K;
    d[0] = isk__sat_add(d[0], isk_div255((uint32_t)s.r * s.a));
    d[1] = isk__sat_add(d[1], isk_div255((uint32_t)s.g * s.a));
    d[2] = isk__sat_add(d[2], isk_div255((uint32_t)s.b * s.a));
    d[3] = isk__sat_add(d[3], s.a);
#endif
}

/* One pixel in any mode, given K = isk__source_k(s) (a caller drawing
 * many pixels of one colour prepares it once). */
static ISK__INLINE void isk__px_k(uint8_t *d, isk_color s, isk__src_k K, isk_blend mode)
{
    switch (mode) {
    case ISK_BLEND_REPLACE:
        d[0] = s.r; d[1] = s.g; d[2] = s.b; d[3] = s.a;
        break;
    case ISK_BLEND_OVER:
        isk__px_over_k(d, s, K);
        break;
    case ISK_BLEND_ADD:
        isk__px_add_k(d, s, K);
        break;
    default: /* not a mode: nothing is drawn */
        break;
    }
}

static ISK__INLINE void isk__px(uint8_t *d, isk_color s, isk_blend mode)
{
    isk__px_k(d, s, isk__source_k(s), mode);
}

#endif
