/* SPDX-License-Identifier: MIT */
/* src/raster/blend_rule.h — the blend rules of iskra/blend.h as a student
 * reads them: one pixel, the formulas as written, no shortcut (internal).
 *
 *   isk__rule_over(d, s)                  source-over on straight colour
 *   isk__rule_add(d, s)                   saturating add weighted by alpha
 *   isk__rule_pixel(d, s, mode)           any mode
 *   isk__rule_pixel_cov(d, s, cov, mode)  the source alpha scaled by the
 *                                         pixel's coverage first
 *
 * This is the definition.  Every fast form in the library gives its bytes
 * and is tested against it: the one-pixel rule the drawing calls inline
 * (iskra/blend_inline.h's isk__px, which takes the opaque destination and
 * the source alphas 0 and 255 first) for every alpha, colour and
 * destination value (tests/test_raster_fast.c); the coverage tables
 * (raster/blend_px.h) for every coverage; the row kernels and their SSE2,
 * AVX2 and vector twins (tests/raster_kernels_body.h); and every
 * primitive drawn on random canvases (tests/raster_ref.h, built on these
 * functions). */
#ifndef ISKRA_RASTER_BLEND_RULE_H
#define ISKRA_RASTER_BLEND_RULE_H

#include <stdint.h>

#include "iskra/blend.h"

/* Source-over: A = 255 sa + da (255 - sa) is 255 times the output alpha;
 * each colour channel is the alphas' weighted mean, rounded to nearest
 * (+ A/2 before the division), the alpha div255(A).  A source alpha of 0
 * draws nothing (the pixel stays as it is, even a transparent one). */
static inline void isk__rule_over(uint8_t *d, isk_color s)
{
    const uint32_t sa = s.a, da = d[3];
    if (sa == 0u)
        return;
    const uint32_t A = 255u * sa + da * (255u - sa); /* > 0 */
    const uint32_t sc[3] = {s.r, s.g, s.b};
    for (int k = 0; k < 3; k++)
        d[k] = (uint8_t)((255u * sc[k] * sa + d[k] * da * (255u - sa) + A / 2u) / A);
    d[3] = (uint8_t)isk_div255(A);
}

/* Add: each colour channel gains div255(sc sa), the alpha sa, each
 * saturating at 255 (so any order of the same draws gives the same bytes). */
static inline void isk__rule_add(uint8_t *d, isk_color s)
{
    const uint32_t sc[3] = {s.r, s.g, s.b};
    for (int k = 0; k < 3; k++) {
        const uint32_t v = d[k] + isk_div255(sc[k] * s.a);
        d[k] = (uint8_t)(v > 255u ? 255u : v);
    }
    const uint32_t a = d[3] + (uint32_t)s.a;
    d[3] = (uint8_t)(a > 255u ? 255u : a);
}

static inline void isk__rule_pixel(uint8_t *d, isk_color s, isk_blend mode)
{
    switch (mode) {
    case ISK_BLEND_REPLACE:
        d[0] = s.r;
        d[1] = s.g;
        d[2] = s.b;
        d[3] = s.a;
        break;
    case ISK_BLEND_OVER:
        isk__rule_over(d, s);
        break;
    case ISK_BLEND_ADD:
        isk__rule_add(d, s);
        break;
    default: /* not a mode: nothing is drawn */
        break;
    }
}

/* Anti-aliased primitives: the source alpha becomes div255(sa coverage);
 * coverage 0 leaves the pixel alone in every mode. */
static inline void isk__rule_pixel_cov(uint8_t *d, isk_color s, uint8_t coverage, isk_blend mode)
{
    if (coverage == 0u)
        return;
    s.a = (uint8_t)isk_div255((uint32_t)s.a * coverage);
    isk__rule_pixel(d, s, mode);
}

#endif
