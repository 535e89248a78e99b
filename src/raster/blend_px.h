/* SPDX-License-Identifier: MIT */
/* src/raster/blend_px.h — the blend rules of iskra/blend.h as inline kernels,
 * one per mode, for the primitives' inner loops.
 *
 * The rule for one pixel is raster/blend_rule.h's; its fast form isk__px
 * is in iskra/blend_inline.h (public, so that isk_draw_pixel can be inlined
 * into its callers' loops), and the library's kernels run isk__blend_px,
 * that form or its SSE2 twin; the coverage and table forms built on it
 * are here.  isk_blend_pixel /
 * isk_blend_pixel_cov (blend.c) are thin wrappers, and every primitive calls these with the
 * mode as a compile-time constant, so the switch below folds away and each
 * primitive gets one loop per mode (AGG's "blender as template argument",
 * in C).  The usual shape is
 *
 *     static ISK__INLINE void fill_row(uint8_t *d, int n, isk_color s, isk_blend mode)
 *     { for (...) isk__blend_px(d, s, mode); }     // generic in mode
 *     ISK__BLEND_DISPATCH(mode, fill_row, d, n, s); // one call per mode
 *
 * Nothing here allocates, fails or keeps state.
 */
#ifndef ISKRA_RASTER_BLEND_PX_H
#define ISKRA_RASTER_BLEND_PX_H

#include <stdint.h>
#include <string.h>

#include "iskra/blend.h"
#include "core/cpu.h"
#include "iskra/blend_inline.h" /* ISK__INLINE, isk__px: the rule for one pixel */
#if ISK__CPU_SSE2
#include "raster/blend_px_sse2.h"
#endif

/* n pixels from d set to s (ISK_BLEND_REPLACE, whatever the source alpha):
 * 32-bit words through locals, which the compiler vectorizes (stores
 * through bytes may alias the caller's fields and kept it from doing so;
 * docs/performance.md, "Where the constants come from"). */
static ISK__INLINE void isk__fill_span(uint8_t *d, size_t n, isk_color s)
{
    const uint8_t px[4] = {s.r, s.g, s.b, s.a};
    uint32_t word;
    memcpy(&word, px, 4);
    for (size_t x = 0; x < n; x++)
        memcpy(d + 4 * x, &word, 4);
}

/* Calls FN(args..., mode) with mode as a literal constant for each valid
 * mode (an invalid mode draws nothing, as before). */
#define ISK__BLEND_DISPATCH(mode, FN, ...)                  \
    do {                                                    \
        switch (mode) {                                     \
        case ISK_BLEND_REPLACE:                             \
            FN(__VA_ARGS__, ISK_BLEND_REPLACE);             \
            break;                                          \
        case ISK_BLEND_OVER:                                \
            FN(__VA_ARGS__, ISK_BLEND_OVER);                \
            break;                                          \
        case ISK_BLEND_ADD:                                 \
            FN(__VA_ARGS__, ISK_BLEND_ADD);                 \
            break;                                          \
        default:                                            \
            break;                                          \
        }                                                   \
    } while (0)

/* One pixel, as the library's kernels blend it: iskra/blend_inline.h's
 * isk__px (plain C, what a program's inlined isk_draw_pixel runs), or
 * where the build has SSE2 its twin (blend_px_sse2.h), which does the four
 * channels in one register: the same bytes, the rule of
 * raster/blend_rule.h. */
static ISK__INLINE void isk__blend_px(uint8_t *d, isk_color s, isk_blend mode)
{
#if ISK__CPU_SSE2
    isk__px_sse2(d, s, mode);
#else
    isk__px(d, s, mode);
#endif
}

static ISK__INLINE void isk__blend_px_over(uint8_t *d, isk_color s)
{
#if ISK__CPU_SSE2
    isk__px_over_sse2(d, s);
#else
    isk__px_over(d, s);
#endif
}

/* The source alpha scaled by coverage first; coverage 0 leaves the pixel
 * alone in every mode. */
static ISK__INLINE void isk__px_cov(uint8_t *d, isk_color s, uint32_t coverage, isk_blend mode)
{
    if (coverage == 0u)
        return;
    s.a = (uint8_t)isk_div255((uint32_t)s.a * coverage);
    isk__blend_px(d, s, mode);
}

/* ---- a colour prepared for many coverage values --------------------------
 * For a batch of one colour, everything that depends only on the coverage
 * byte is tabled once (256 entries): the scaled alpha a' = div255(sa*cov),
 * the additive increments div255(c*a'), and for source-over onto an opaque
 * pixel the products c*a' and the weight 255 - a'.  Per pixel that leaves
 * one table read and a few integer operations on all four channels at
 * once (SWAR: bytes of a uint32 for add, 16-bit lanes of a uint64 for
 * over), the same bytes as isk__px_cov. */
typedef struct isk__cov_lut {
    isk_color col;
    uint8_t alpha[256];      /* a' */
    uint8_t add[256][4];     /* r, g, b increments and a' (ISK_BLEND_ADD) */
    uint64_t over_p[256];    /* lanes r*a', g*a', b*a', 255*a' (ISK_BLEND_OVER, opaque dst) */
    uint64_t over_inv[256];  /* lanes 255 - a', four times */
} isk__cov_lut;

#define ISK__LANES_LO 0x00FF00FF00FF00FFull

/* Fills the table's entry for coverage w (a batch that only ever uses
 * coverage 255, i.e. plain pixels, fills just that one). */
static inline void isk__cov_lut_entry(isk__cov_lut *t, isk_color col, uint32_t w)
{
    t->col = col;
    uint32_t a = isk_div255((uint32_t)col.a * w);
    t->alpha[w] = (uint8_t)a;
    t->add[w][0] = (uint8_t)isk_div255((uint32_t)col.r * a);
    t->add[w][1] = (uint8_t)isk_div255((uint32_t)col.g * a);
    t->add[w][2] = (uint8_t)isk_div255((uint32_t)col.b * a);
    t->add[w][3] = (uint8_t)a;
    t->over_p[w] = (uint64_t)(col.r * a) | (uint64_t)(col.g * a) << 16 | (uint64_t)(col.b * a) << 32 |
                   (uint64_t)(255u * a) << 48;
    t->over_inv[w] = (uint64_t)(255u - a) * 0x0001000100010001ull;
}

static inline void isk__cov_lut_init(isk__cov_lut *t, isk_color col)
{
    for (uint32_t w = 0; w < 256u; w++)
        isk__cov_lut_entry(t, col, w);
}

/* Four saturating byte additions in one uint32 (no carry crosses a byte). */
static ISK__INLINE uint32_t isk__sat_add_u8x4(uint32_t a, uint32_t b)
{
    uint32_t s = (a & 0x7F7F7F7Fu) + (b & 0x7F7F7F7Fu);
    uint32_t top = (a ^ b) & 0x80808080u;
    uint32_t carry = ((a & b) | (s & top)) & 0x80808080u;
    return (s ^ top) | ((carry >> 7) * 0xFFu);
}

/* div255 (x+127)/255 in each 16-bit lane, for lanes <= 255*255:
 * (t + (t >> 8)) >> 8 with t = x + 128 (checked for every lane value by
 * tests/test_raster_fast.c). */
static ISK__INLINE uint64_t isk__div255_lanes(uint64_t x)
{
    uint64_t t = x + 0x0080008000800080ull;
    return ((t + ((t >> 8) & ISK__LANES_LO)) >> 8) & ISK__LANES_LO;
}

/* Source-over of a' onto an opaque pixel: out = div255(c*a' + d*(255-a'))
 * on all four channels (alpha: div255(255*255) = 255), given the tabled
 * lanes p and the weight inv = 255 - a'. */
static ISK__INLINE void isk__over_opaque_lanes(uint8_t *d, uint64_t p, uint32_t inv)
{
#if ISK__CPU_SSE2
    isk__over_opaque_lanes_sse2(d, p, inv); /* the same lanes in one SSE2 register */
#else
    uint64_t x = (uint64_t)d[0] | (uint64_t)d[1] << 16 | (uint64_t)d[2] << 32 | (uint64_t)255u << 48;
    x = isk__div255_lanes(x * inv + p);
    d[0] = (uint8_t)x;
    d[1] = (uint8_t)(x >> 16);
    d[2] = (uint8_t)(x >> 32);
#endif
}

/* isk__px_cov(d, t->col, cov, mode), through the table. */
static ISK__INLINE void isk__px_lut(uint8_t *d, const isk__cov_lut *t, uint32_t cov, isk_blend mode)
{
    switch (mode) {
    case ISK_BLEND_REPLACE:
        if (cov) {
            d[0] = t->col.r; d[1] = t->col.g; d[2] = t->col.b; d[3] = t->alpha[cov];
        }
        break;
    case ISK_BLEND_OVER:
        if (d[3] == 255u) {
            isk__over_opaque_lanes(d, t->over_p[cov], 255u - t->alpha[cov]);
        } else {
            isk_color s = t->col;
            s.a = t->alpha[cov];
            isk__blend_px_over(d, s);
        }
        break;
    case ISK_BLEND_ADD: {
        /* coverage 0 adds 0: no test needed */
        uint32_t v, inc;
        memcpy(&v, d, 4);
        memcpy(&inc, t->add[cov], 4);
#if ISK__CPU_SSE2
        v = isk__sat_add_u8x4_sse2(v, inc);
#else
        v = isk__sat_add_u8x4(v, inc);
#endif
        memcpy(d, &v, 4);
        break;
    }
    default:
        break;
    }
}

#endif
