/* SPDX-License-Identifier: MIT */
/* The textured sprite's walkers in SSE2 (raster/texture_loops.h), one pixel
 * at a time: the bilinear sample in 16-bit lanes (the horizontal taps are
 * exact products below 2^15, the vertical step a pmaddwd, one rounding),
 * then the tint and the blend in the same lanes; the blit filters each row
 * vertically first (V = t0 (128 - fy) + t1 fy, exact, then V0 (128 - fx)
 * + V1 fx: the same sum of four exact products).  The same integers as
 * texture_draw.c's px_scalar, so the same bytes. */
#include "core/cpu.h"

#if ISK__CPU_SSE2
#include <emmintrin.h>
#include <string.h>

#include "raster/texture_loops.h"

/* Weights as lanes: wx = [128 - fx] x 4, [fx] x 4 (the two taps of a row),
 * wy = pairs (128 - fy, fy) for pmaddwd. */
static ISK__INLINE __m128i s_wx(uint32_t fx)
{
    __m128i f = _mm_set1_epi16((short)fx);
    return _mm_unpacklo_epi64(_mm_sub_epi16(_mm_set1_epi16(128), f), f);
}

static ISK__INLINE __m128i s_wy(uint32_t fy)
{
    return _mm_set1_epi32((int)(fy << 16 | (128u - fy)));
}

static ISK__INLINE __m128i s_div255(__m128i x)
{
    return _mm_mulhi_epu16(_mm_add_epi16(x, _mm_set1_epi16(128)), _mm_set1_epi16(257));
}

/* The sample in 16-bit lanes r g b a (low half). */
static ISK__INLINE __m128i s_sample(const uint8_t *p, size_t ts, __m128i wx, __m128i wy)
{
    const __m128i z = _mm_setzero_si128();
    __m128i r0 = _mm_mullo_epi16(_mm_unpacklo_epi8(_mm_loadl_epi64((const __m128i *)(const void *)p), z), wx);
    __m128i r1 = _mm_mullo_epi16(_mm_unpacklo_epi8(_mm_loadl_epi64((const __m128i *)(const void *)(p + ts)), z), wx);
    __m128i h0 = _mm_add_epi16(r0, _mm_srli_si128(r0, 8)); /* t00 wx0 + t10 wx1 < 2^15 */
    __m128i h1 = _mm_add_epi16(r1, _mm_srli_si128(r1, 8));
    __m128i s = _mm_madd_epi16(_mm_unpacklo_epi16(h0, h1), wy);
    s = _mm_srli_epi32(_mm_add_epi32(s, _mm_set1_epi32(8192)), 14);
    return _mm_packs_epi32(s, s);
}

/* Tint the sample s (16-bit lanes r g b a) and blend it into d. */
static ISK__INLINE void px_sse2_put(uint8_t *d, __m128i s, int tinted, __m128i kta, __m128i ktc, isk_blend mode)
{
    if (tinted) {
        s = s_div255(_mm_mullo_epi16(s, kta)); /* all four: div255(S * tint.a) */
        s = s_div255(_mm_mullo_epi16(s, ktc)); /* r g b: times tint.c; a: times 255, unchanged */
    }
    switch (mode) {
    case ISK_BLEND_ADD: {
        uint32_t v;
        memcpy(&v, d, 4);
        v = (uint32_t)_mm_cvtsi128_si32(_mm_adds_epu8(_mm_cvtsi32_si128((int)v), _mm_packus_epi16(s, s)));
        memcpy(d, &v, 4);
        break;
    }
    case ISK_BLEND_OVER:
        if (d[3] != 255u) { /* a translucent destination: the exact division */
            uint32_t q = (uint32_t)_mm_cvtsi128_si32(_mm_packus_epi16(s, s)); /* little-endian: r g b a */
            blend_pm(d, q & 0xFFu, q >> 8 & 0xFFu, q >> 16 & 0xFFu, q >> 24, mode);
        } else {
            /* P + div255(d (255 - A)) in all four lanes (alpha: A + 255 - A) */
            uint32_t v;
            memcpy(&v, d, 4);
            __m128i D = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)v), _mm_setzero_si128());
            __m128i inv = _mm_sub_epi16(_mm_set1_epi16(255), _mm_shufflelo_epi16(s, 0xFF));
            __m128i x = _mm_add_epi16(s_div255(_mm_mullo_epi16(D, inv)), s);
            v = (uint32_t)_mm_cvtsi128_si32(_mm_packus_epi16(x, x));
            memcpy(d, &v, 4);
        }
        break;
    default: {
        uint32_t q = (uint32_t)_mm_cvtsi128_si32(_mm_packus_epi16(s, s)); /* little-endian: r g b a */
        blend_pm(d, q & 0xFFu, q >> 8 & 0xFFu, q >> 16 & 0xFFu, q >> 24, mode);
        break;
    }
    }
}

static ISK__INLINE void px_sse2(uint8_t *d, const uint8_t *p, size_t ts, __m128i wx, __m128i wy, int tinted,
                                __m128i kta, __m128i ktc, isk_blend mode)
{
    px_sse2_put(d, s_sample(p, ts, wx, wy), tinted, kta, ktc, mode);
}

/* The SSE2 blit's vertical pass: texels [xa, xa + nt) of rows r0, r0 + ts
 * into v (4 lanes each).  Reads up to one texel past the end (slack). */
static ISK__INLINE void s_vrow(uint16_t *v, const uint8_t *r0, size_t ts, int xa, int nt, uint32_t fy)
{
    const __m128i z = _mm_setzero_si128(), w0 = _mm_set1_epi16((short)(128u - fy)), w1 = _mm_set1_epi16((short)fy);
    const uint8_t *a = r0 + 4u * (size_t)xa, *b = a + ts;
    for (int x = 0; x < nt; x += 2) {
        __m128i ta = _mm_unpacklo_epi8(_mm_loadl_epi64((const __m128i *)(const void *)(a + 4 * x)), z);
        __m128i tb = _mm_unpacklo_epi8(_mm_loadl_epi64((const __m128i *)(const void *)(b + 4 * x)), z);
        _mm_storeu_si128((__m128i *)(void *)(v + 4 * x), _mm_add_epi16(_mm_mullo_epi16(ta, w0), _mm_mullo_epi16(tb, w1)));
    }
}

/* One pixel from the filtered row: V at its left tap, the weight pair. */
static ISK__INLINE __m128i s_hsample(const uint16_t *v, uint32_t w)
{
    __m128i x = _mm_loadu_si128((const __m128i *)(const void *)v);
    __m128i s = _mm_madd_epi16(_mm_unpacklo_epi16(x, _mm_srli_si128(x, 8)), _mm_set1_epi32((int)w));
    s = _mm_srli_epi32(_mm_add_epi32(s, _mm_set1_epi32(8192)), 14);
    return _mm_packs_epi32(s, s);
}

/* The tint's lanes: tint.a in all four, and r g b 255. */
#define S_TINT_CONSTANTS(t)                                                                                        \
    const __m128i kta = _mm_set1_epi16((short)(t)->tint.a);                                                       \
    const __m128i ktc = _mm_set_epi16(255, (t)->tint.b, (t)->tint.g, (t)->tint.r, 255, (t)->tint.b, (t)->tint.g,  \
                                      (t)->tint.r)

/* texture_draw.c's walk_general, each pixel in SSE2. */
static ISK__INLINE void walk_general_sse2(isk_canvas *c, const tex_draw *t, int j0, int j1, int tinted, isk_blend mode)
{
    const size_t ts = t->ts;
    S_TINT_CONSTANTS(t);
    for (int j = j0; j < j1; j++) {
        int64_t pu, pv;
        int ka, kb;
        if (!row_span(t, j, &pu, &pv, &ka, &kb))
            continue;
        uint8_t *d = c->pixels + (size_t)j * c->stride + 4u * (size_t)(t->bi0 + ka);
        for (int k = ka; k < kb; k++, d += 4, pu += t->dux, pv += t->dvx) {
            uint64_t x = (uint64_t)pu, y = (uint64_t)pv;
            const uint8_t *p = t->base + (size_t)(y >> 32) * ts + 4u * (size_t)(x >> 32);
            uint32_t fx = (uint32_t)(x >> 25) & 127u, fy = (uint32_t)(y >> 25) & 127u;
            px_sse2(d, p, ts, s_wx(fx), s_wy(fy), tinted, kta, ktc, mode);
        }
    }
}

/* texture_draw.c's walk_blit, each row filtered vertically first (a
 * chunk wider than VROW_MAX texels: each pixel's own taps). */
static ISK__INLINE void walk_blit_sse2(isk_canvas *c, const tex_draw *t, int j0, int j1, int tinted, isk_blend mode)
{
    int ka, kb, ra, rb;
    if (!blit_span(t, j0, j1, &ka, &kb, &ra, &rb))
        return;
    const size_t ts = t->ts;
    blit_cols bc;
    S_TINT_CONSTANTS(t);
    uint16_t vrow[4 * (VROW_MAX + 2)];
    for (int k0 = ka; k0 < kb; k0 += BLIT_CHUNK) {
        blit_columns(t, k0, kb - k0 < BLIT_CHUNK ? kb - k0 : BLIT_CHUNK, &bc);
        for (int r = ra; r < rb; r++) {
            uint32_t fy;
            uint8_t *d;
            const uint8_t *row = blit_row(c, t, j0 + r, k0, &fy, &d);
            if (bc.nt <= VROW_MAX) {
                s_vrow(vrow, row, ts, bc.xa, bc.nt, fy);
                for (int q = 0; q < bc.m; q++)
                    px_sse2_put(d + 4 * q, s_hsample(vrow + 4 * bc.x[q], bc.w[q]), tinted, kta, ktc, mode);
            } else {
                for (int q = 0; q < bc.m; q++)
                    px_sse2(d + 4 * q, row + 4u * (size_t)(bc.xa + bc.x[q]), ts, s_wx((uint32_t)bc.fx[q]), s_wy(fy),
                            tinted, kta, ktc, mode);
            }
        }
    }
}

TEXTURE_WALKERS(sse2_, , walk_general_sse2, walk_blit_sse2)
const isk__texture_walkers isk__texture_walkers_sse2 = TEXTURE_TABLE(sse2_);
#else
typedef int isk__texture_sse2_unused; /* ISO C wants a declaration in every file */
#endif
