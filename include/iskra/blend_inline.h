/* SPDX-License-Identifier: MIT */
/* iskra/blend_inline.h — the blend rules of iskra/blend.h for one pixel,
 * as inline code (included by iskra/draw.h; not called directly).
 *
 * isk_draw_pixel (iskra/draw.h) is also a macro over an inline copy of
 * itself, as the C library's functions may be (C11 7.1.4), so that a loop
 * of calls compiles to a loop of blends: the call, the choice of the mode
 * and the colour's set-up leave the loop.  It needs the rule here, in
 * plain C (any C11 compiler, any target).  The rule as a student reads it,
 * the one these forms are tested against, is the library's
 * src/raster/blend_rule.h; the library's own kernels (src/raster/
 * blend_px.h) run these forms, or an SSE2 twin of them where the build
 * has one.  Everything named isk__ is internal: it may change between
 * versions; use isk_blend_pixel and isk_draw_pixel.
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
 *     if (!same) return 1;
 */
#ifndef ISKRA_BLEND_INLINE_H
#define ISKRA_BLEND_INLINE_H

#include <stdint.h>
#include <string.h>

#include "iskra/blend.h"

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

/* Source-over (iskra/blend.h): the rule with two shortcuts that give its
 * bytes.  An opaque destination first, the common case: each channel
 * div255(c sa + d (255 - sa)), no division by the output alpha and no test
 * of the source alpha either (the rule gives sa 0 and 255 their bytes
 * there: div255(255 d) = d, div255(255 c) = c), the alpha staying 255.
 * Then the source alphas 0 and 255 (nothing drawn, the source copied). */
static ISK__INLINE void isk__px_over(uint8_t *d, isk_color s)
{
    const uint32_t sa = s.a, da = d[3], inv = 255u - sa;
    if (da == 255u) {
        const uint32_t c[3] = {s.r, s.g, s.b};
        for (int k = 0; k < 3; k++)
            d[k] = (uint8_t)isk_div255(c[k] * sa + d[k] * inv);
        return;
    }
    if (sa - 1u >= 254u) { /* sa 0 or 255 (one test) */
        if (sa)
            memcpy(d, &s, 4); /* r g b 255 */
        return;
    }
    isk__px_over_general(d, s, sa, da, inv);
}

/* Add (iskra/blend.h): each channel gains div255(c sa), the alpha sa, each
 * saturating at 255 (a byte sum that wraps below its first term passed
 * 255). */
static ISK__INLINE void isk__px_add(uint8_t *d, isk_color s)
{
    const uint8_t inc[4] = {(uint8_t)isk_div255((uint32_t)s.r * s.a), (uint8_t)isk_div255((uint32_t)s.g * s.a),
                            (uint8_t)isk_div255((uint32_t)s.b * s.a), s.a};
    for (int k = 0; k < 4; k++) {
        const uint8_t sum = (uint8_t)(d[k] + inc[k]);
        d[k] = sum < d[k] ? 255u : sum;
    }
}

/* One pixel in any mode. */
static ISK__INLINE void isk__px(uint8_t *d, isk_color s, isk_blend mode)
{
    switch (mode) {
    case ISK_BLEND_REPLACE:
        d[0] = s.r; d[1] = s.g; d[2] = s.b; d[3] = s.a;
        break;
    case ISK_BLEND_OVER:
        isk__px_over(d, s);
        break;
    case ISK_BLEND_ADD:
        isk__px_add(d, s);
        break;
    default: /* not a mode: nothing is drawn */
        break;
    }
}

/* The one-pixel rule a program's inlined isk_draw_pixel runs: isk__px,
 * or on x86-64 its SSE2 twin (iskra/blend_inline_sse2.h, the same bytes),
 * unless ISKRA_REFERENCE asks for the plain form.  In two steps: the
 * colour's part first (isk__px_prepare: computed unconditionally, a loop
 * of one colour computes it once, before the loop), then the pixel. */
#if defined(__SSE2__) && defined(__x86_64__) && !defined(ISKRA_REFERENCE)
#include "iskra/blend_inline_sse2.h"
typedef __m128i isk__px_prep;
static ISK__INLINE isk__px_prep isk__px_prepare(isk_color s) { return isk__source_k_sse2(s); }
static ISK__INLINE void isk__px_prepared(uint8_t *d, isk_color s, isk__px_prep K, isk_blend mode)
{
    isk__px_k_sse2(d, s, K, mode);
}
#else
typedef int isk__px_prep; /* the plain rule has no colour part to keep */
static ISK__INLINE isk__px_prep isk__px_prepare(isk_color s)
{
    (void)s;
    return 0;
}
static ISK__INLINE void isk__px_prepared(uint8_t *d, isk_color s, isk__px_prep K, isk_blend mode)
{
    (void)K;
    isk__px(d, s, mode);
}
#endif

#endif
