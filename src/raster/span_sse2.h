/* SPDX-License-Identifier: MIT */
/* src/raster/span_sse2.h — the SSE2 twins of the row kernels of
 * raster/span.h, 4 pixels a step (internal; span.h includes this where
 * src/core/cpu.h's ISK__CPU_SSE2 is 1, i.e. on every x86-64 build).
 *
 *   isk__span_cov_sse2(d, cov, n, col, mode)    the whole 4-pixel groups of
 *                                               isk__span_cov; returns how
 *                                               many pixels it did
 *   isk__span_add_bytes_sse2(d, q, nbytes)      the whole 16-byte steps of
 *                                               isk__span_add_bytes; returns
 *                                               how many bytes it did
 *   isk__span_add_bytes16_sse2(d, q, nbytes)    isk__span_add_bytes16
 *
 * The same bytes as the per-pixel rule (span.h says why); the helpers
 * below (isk__s_div255, ISK__K128, ...) are also the AVX2 kernels' and
 * the dots' (span_avx2.h, view/dot_block_sse2.h). */
#ifndef ISKRA_RASTER_SPAN_SSE2_H
#define ISKRA_RASTER_SPAN_SSE2_H

#include "core/cpu.h"

#if ISK__CPU_SSE2
#include <emmintrin.h>
#include <stdint.h>
#include <string.h>

#include "raster/blend_px.h"

/* The kernels' constants made opaque to the compiler (an empty asm that
 * "changes" them): GCC would otherwise rebuild each broadcast (move, movd,
 * broadcast: a shuffle-port operation) inside every loop step; this way it
 * builds them once and keeps them in registers. */
static ISK__INLINE __m128i isk__s_keep(__m128i v)
{
    __asm__("" : "+x"(v));
    return v;
}
#define ISK__K128 isk__s_keep(_mm_set1_epi16(128))
#define ISK__K257 isk__s_keep(_mm_set1_epi16(257))
#define ISK__K255 isk__s_keep(_mm_set1_epi16(255))

/* div255 in each 16-bit lane (x <= 255*255): high half of (x + 128) * 257. */
static ISK__INLINE __m128i isk__s_div255(__m128i x)
{
    return _mm_mulhi_epu16(_mm_add_epi16(x, ISK__K128), ISK__K257);
}

/* a' = div255(ca * cov) of 4 pixels in lanes 0..3 (ca = 255: a' = cov). */
static ISK__INLINE __m128i isk__s_alpha4(const uint8_t *cov, uint32_t ca)
{
    uint32_t m;
    memcpy(&m, cov, 4);
    __m128i A = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)m), _mm_setzero_si128());
    return ca == 255u ? A : isk__s_div255(_mm_mullo_epi16(A, _mm_set1_epi16((short)ca)));
}

/* lanes a0..a3 -> [a0 a0 a0 a0 a1 a1 a1 a1] and [a2 x4, a3 x4] */
static ISK__INLINE void isk__s_spread(__m128i A, __m128i *a01, __m128i *a23)
{
    __m128i t = _mm_unpacklo_epi16(A, A);
    *a01 = _mm_unpacklo_epi32(t, t);
    *a23 = _mm_unpackhi_epi32(t, t);
}

/* 4 pixels, additive: increments div255(c a') per channel (Cadd = [r g b 255]
 * twice: div255(255 a') = a' for alpha), saturating byte adds. */
static ISK__INLINE void isk__s4_add(uint8_t *d, __m128i A, __m128i Cadd)
{
    __m128i a01, a23;
    isk__s_spread(A, &a01, &a23);
    __m128i inc = _mm_packus_epi16(isk__s_div255(_mm_mullo_epi16(a01, Cadd)),
                                   isk__s_div255(_mm_mullo_epi16(a23, Cadd)));
    __m128i v = _mm_loadu_si128((const __m128i *)(const void *)d);
    _mm_storeu_si128((__m128i *)(void *)d, _mm_adds_epu8(v, inc));
}

/* 4 pixels over opaque destinations: div255(c a' + d (255 - a')) per
 * channel; the alpha lane (c = 255) gives 255.  0 when some destination is
 * not opaque (nothing written: the caller uses the exact rule). */
static ISK__INLINE int isk__s4_over_opaque_aa(uint8_t *d, __m128i a01, __m128i a23, __m128i C)
{
    __m128i v = _mm_loadu_si128((const __m128i *)(const void *)d);
    if ((_mm_movemask_epi8(_mm_cmpeq_epi8(v, _mm_set1_epi8(-1))) & 0x8888) != 0x8888)
        return 0;
    const __m128i z = _mm_setzero_si128(), k255 = ISK__K255;
    __m128i lo = _mm_add_epi16(_mm_mullo_epi16(_mm_unpacklo_epi8(v, z), _mm_sub_epi16(k255, a01)),
                               _mm_mullo_epi16(C, a01));
    __m128i hi = _mm_add_epi16(_mm_mullo_epi16(_mm_unpackhi_epi8(v, z), _mm_sub_epi16(k255, a23)),
                               _mm_mullo_epi16(C, a23));
    _mm_storeu_si128((__m128i *)(void *)d, _mm_packus_epi16(isk__s_div255(lo), isk__s_div255(hi)));
    return 1;
}

static ISK__INLINE int isk__s4_over_opaque(uint8_t *d, __m128i A, __m128i C)
{
    __m128i a01, a23;
    isk__s_spread(A, &a01, &a23);
    return isk__s4_over_opaque_aa(d, a01, a23, C);
}

/* Pixels [0, 4 * (n / 4)) of isk__span_cov in add and over (coverage 0
 * leaves a group alone in both; a group over a destination that is not
 * all opaque takes the exact rule per pixel); replace is left to the
 * caller's loop.  Returns how many pixels it did. */
static ISK__INLINE int isk__span_cov_sse2(uint8_t *d, const uint8_t *cov, int n, isk_color col, isk_blend mode)
{
    int i = 0;
    if (mode != ISK_BLEND_ADD && mode != ISK_BLEND_OVER)
        return 0;
    const uint32_t ca = col.a;
    const __m128i C = _mm_setr_epi16(col.r, col.g, col.b, 255, col.r, col.g, col.b, 255);
    for (; i + 4 <= n; i += 4) {
        uint32_t m;
        memcpy(&m, cov + i, 4);
        if (m == 0u) /* coverage 0 changes nothing in either mode */
            continue;
        __m128i A = isk__s_alpha4(cov + i, ca);
        if (mode == ISK_BLEND_ADD)
            isk__s4_add(d + 4 * i, A, C);
        else if (!isk__s4_over_opaque(d + 4 * i, A, C))
            for (int k = i; k < i + 4; k++)
                isk__px_cov(d + 4 * k, col, cov[k], mode);
    }
    return i;
}

/* Bytes [0, 16 * (nbytes / 16)): saturating byte adds. */
static ISK__INLINE int isk__span_add_bytes_sse2(uint8_t *d, const uint8_t *q, int nbytes)
{
    int k = 0;
    for (; k + 16 <= nbytes; k += 16) {
        __m128i a = _mm_loadu_si128((const __m128i *)(const void *)(d + k));
        __m128i b = _mm_loadu_si128((const __m128i *)(const void *)(q + k));
        _mm_storeu_si128((__m128i *)(void *)(d + k), _mm_adds_epu8(a, b));
    }
    return k;
}

/* nbytes a multiple of 16: no tail. */
static ISK__INLINE void isk__span_add_bytes16_sse2(uint8_t *d, const uint8_t *q, int nbytes)
{
    for (int k = 0; k < nbytes; k += 16) {
        __m128i a = _mm_loadu_si128((const __m128i *)(const void *)(d + k));
        __m128i b = _mm_loadu_si128((const __m128i *)(const void *)(q + k));
        _mm_storeu_si128((__m128i *)(void *)(d + k), _mm_adds_epu8(a, b));
    }
}
#endif /* ISK__CPU_SSE2 */

#endif
