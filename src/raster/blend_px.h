/* src/raster/blend_px.h — the blend rules of iskra/blend.h as inline kernels,
 * one per mode, for the primitives' inner loops.
 *
 * The rule lives here once: isk_blend_pixel / isk_blend_pixel_cov
 * (blend.c) are thin wrappers, and every primitive calls these with the
 * mode as a compile-time constant, so the switch below folds away and each
 * primitive gets one loop per mode (AGG's "blender as template argument",
 * in C).  The usual shape is
 *
 *     static ISK__INLINE void fill_row(uint8_t *d, int n, isk_color s, isk_blend mode)
 *     { for (...) isk__px(d, s, mode); }           // generic in mode
 *     ISK__BLEND_DISPATCH(mode, fill_row, d, n, s); // one call per mode
 *
 * Nothing here allocates, fails or keeps state.
 */
#ifndef ISKRA_RASTER_BLEND_PX_H
#define ISKRA_RASTER_BLEND_PX_H

#include <stdint.h>
#include <string.h>

#include "iskra/blend.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#if defined(__GNUC__)
#define ISK__INLINE inline __attribute__((always_inline))
#else
#define ISK__INLINE inline
#endif

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
static ISK__INLINE void isk__px_over(uint8_t *d, isk_color s)
{
    uint32_t sa = s.a;
    uint32_t da = d[3];
    uint32_t inv = 255u - sa;
    if (da == 255u) {
        /* Opaque destination: the common case, no division by A, and no
         * test of the source alpha either: the rule gives sa 0 and 255
         * their bytes (div255(255 d) = d, div255(255 c) = c). */
#if defined(__SSE2__)
        /* the three channels (and alpha: div255(255 sa + 255 inv) = 255) in
         * one set of 16-bit lanes; div255(x) = high half of (x + 128) * 257 */
        uint32_t c32, d32; /* x86 is little-endian: memory order r g b a is the value's byte order */
        memcpy(&c32, &s, 4);
        c32 |= 0xFF000000u;
        memcpy(&d32, d, 4);
        const __m128i z = _mm_setzero_si128();
        __m128i C = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)c32), z);
        __m128i D = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)d32), z);
        __m128i x = _mm_add_epi16(_mm_mullo_epi16(C, _mm_set1_epi16((short)sa)),
                                  _mm_mullo_epi16(D, _mm_set1_epi16((short)inv)));
        x = _mm_mulhi_epu16(_mm_add_epi16(x, _mm_set1_epi16(128)), _mm_set1_epi16(257));
        d32 = (uint32_t)_mm_cvtsi128_si32(_mm_packus_epi16(x, x));
        memcpy(d, &d32, 4);
#else
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

static ISK__INLINE void isk__px_add(uint8_t *d, isk_color s)
{
#if defined(__SSE2__)
    /* increments div255(c a) in 16-bit lanes (alpha: div255(255 a) = a),
     * then saturating byte adds */
    uint32_t c32, d32; /* x86 is little-endian: memory order r g b a is the value's byte order */
    memcpy(&c32, &s, 4);
    c32 |= 0xFF000000u;
    memcpy(&d32, d, 4);
    __m128i C = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)c32), _mm_setzero_si128());
    __m128i x = _mm_mullo_epi16(C, _mm_set1_epi16((short)s.a));
    x = _mm_mulhi_epu16(_mm_add_epi16(x, _mm_set1_epi16(128)), _mm_set1_epi16(257));
    d32 = (uint32_t)_mm_cvtsi128_si32(_mm_adds_epu8(_mm_cvtsi32_si128((int)d32), _mm_packus_epi16(x, x)));
    memcpy(d, &d32, 4);
#else
    d[0] = isk__sat_add(d[0], isk_div255((uint32_t)s.r * s.a));
    d[1] = isk__sat_add(d[1], isk_div255((uint32_t)s.g * s.a));
    d[2] = isk__sat_add(d[2], isk_div255((uint32_t)s.b * s.a));
    d[3] = isk__sat_add(d[3], s.a);
#endif
}

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

/* The source alpha scaled by coverage first; coverage 0 leaves the pixel
 * alone in every mode. */
static ISK__INLINE void isk__px_cov(uint8_t *d, isk_color s, uint32_t coverage, isk_blend mode)
{
    if (coverage == 0u)
        return;
    s.a = (uint8_t)isk_div255((uint32_t)s.a * coverage);
    isk__px(d, s, mode);
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
#if defined(__SSE2__)
    /* the same lanes in SSE2 (x86: the u64's 16-bit lanes are r g b a in
     * order); div255 as the high half of (x + 128) * 257 */
    uint32_t d32;
    memcpy(&d32, d, 4);
    __m128i D = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)d32), _mm_setzero_si128());
    __m128i x = _mm_add_epi16(_mm_mullo_epi16(D, _mm_set1_epi16((short)inv)), _mm_cvtsi64_si128((long long)p));
    x = _mm_mulhi_epu16(_mm_add_epi16(x, _mm_set1_epi16(128)), _mm_set1_epi16(257));
    d32 = (uint32_t)_mm_cvtsi128_si32(_mm_packus_epi16(x, x));
    memcpy(d, &d32, 4);
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
            isk__px_over(d, s);
        }
        break;
    case ISK_BLEND_ADD: {
        /* coverage 0 adds 0: no test needed */
        uint32_t v, inc;
        memcpy(&v, d, 4);
        memcpy(&inc, t->add[cov], 4);
#if defined(__SSE2__)
        v = (uint32_t)_mm_cvtsi128_si32(_mm_adds_epu8(_mm_cvtsi32_si128((int)v), _mm_cvtsi32_si128((int)inc)));
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
