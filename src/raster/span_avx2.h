/* SPDX-License-Identifier: MIT */
/* src/raster/span_avx2.h — the row kernels of raster/span.h in AVX2, 8
 * pixels a step, and the baked sprite's source-over rows (internal).
 * Included only by the AVX2 builds (sprite_avx2.c, circle_avx2.c,
 * texture_avx2.c) and their tests: every function here is compiled for
 * AVX2 by a target attribute (ISK__AVX2_FN, src/core/cpu.h) and runs only
 * where isk__have_avx2() says the CPU has it.
 *
 *   isk__span_cov_avx2(d, cov, n, col, mode)     isk__span_cov
 *   isk__span_add_bytes_avx2(d, q, nbytes)       isk__span_add_bytes
 *   isk__span_add_bytes16_avx2(d, q, nbytes)     isk__span_add_bytes16
 *   isk__span_over_inc_avx2(d, inc, n, col)      source-over of a baked
 *       sprite row from its increments (byte 3 of each pixel's is its a')
 *   isk__rows_over_inc_avx2(...)                 every row of such a sprite
 *
 * The SSE2 kernels' arithmetic (span_sse2.h) in twice the lanes: integer
 * arithmetic, so the bytes do not depend on the path. */
#ifndef ISKRA_RASTER_SPAN_AVX2_H
#define ISKRA_RASTER_SPAN_AVX2_H

#include "core/cpu.h"

#if ISK__CPU_AVX2
#include <immintrin.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "raster/span.h"
#include "raster/span_sse2.h"

/* The kernels' constants kept in registers (isk__s_keep, span_sse2.h). */
static ISK__INLINE ISK__AVX2_FN __m256i isk__a_keep(__m256i v)
{
    __asm__("" : "+x"(v));
    return v;
}
#define ISK__K128Y isk__a_keep(_mm256_set1_epi16(128))
#define ISK__K257Y isk__a_keep(_mm256_set1_epi16(257))
#define ISK__K255Y isk__a_keep(_mm256_set1_epi16(255))

static ISK__INLINE ISK__AVX2_FN __m256i isk__a_div255(__m256i x)
{
    return _mm256_mulhi_epu16(_mm256_add_epi16(x, ISK__K128Y), ISK__K257Y);
}

/* a' of 8 pixels spread over their channels: lo = [a0 x4 a1 x4 | a4 x4 a5 x4],
 * hi = [a2 x4 a3 x4 | a6 x4 a7 x4], matching the in-lane unpack of 8 pixels. */
static ISK__INLINE ISK__AVX2_FN void isk__a_alpha8(const uint8_t *cov, uint32_t ca, __m256i *lo, __m256i *hi)
{
    __m128i A = _mm_unpacklo_epi8(_mm_loadl_epi64((const __m128i *)(const void *)cov), _mm_setzero_si128());
    if (ca != 255u)
        A = _mm_mulhi_epu16(_mm_add_epi16(_mm_mullo_epi16(A, _mm_set1_epi16((short)ca)), ISK__K128), ISK__K257);
    __m128i t = _mm_unpacklo_epi16(A, A), u = _mm_unpackhi_epi16(A, A);
    __m256i T = _mm256_inserti128_si256(_mm256_castsi128_si256(t), u, 1);
    *lo = _mm256_unpacklo_epi32(T, T);
    *hi = _mm256_unpackhi_epi32(T, T);
}

static ISK__INLINE ISK__AVX2_FN void isk__a8_add(uint8_t *d, __m256i lo, __m256i hi, __m256i Cadd)
{
    __m256i inc = _mm256_packus_epi16(isk__a_div255(_mm256_mullo_epi16(lo, Cadd)),
                                      isk__a_div255(_mm256_mullo_epi16(hi, Cadd)));
    __m256i v = _mm256_loadu_si256((const __m256i *)(const void *)d);
    _mm256_storeu_si256((__m256i *)(void *)d, _mm256_adds_epu8(v, inc));
}

static ISK__INLINE ISK__AVX2_FN int isk__a8_over_opaque(uint8_t *d, __m256i lo, __m256i hi, __m256i C)
{
    __m256i v = _mm256_loadu_si256((const __m256i *)(const void *)d);
    if (((unsigned)_mm256_movemask_epi8(_mm256_cmpeq_epi8(v, _mm256_set1_epi8(-1))) & 0x88888888u) != 0x88888888u)
        return 0;
    const __m256i z = _mm256_setzero_si256(), k255 = ISK__K255Y;
    __m256i xl = _mm256_add_epi16(_mm256_mullo_epi16(_mm256_unpacklo_epi8(v, z), _mm256_sub_epi16(k255, lo)),
                                  _mm256_mullo_epi16(C, lo));
    __m256i xh = _mm256_add_epi16(_mm256_mullo_epi16(_mm256_unpackhi_epi8(v, z), _mm256_sub_epi16(k255, hi)),
                                  _mm256_mullo_epi16(C, hi));
    _mm256_storeu_si256((__m256i *)(void *)d, _mm256_packus_epi16(isk__a_div255(xl), isk__a_div255(xh)));
    return 1;
}

/* isk__span_cov, 8 pixels a step (then the SSE2 step for a 4-pixel rest). */
static ISK__INLINE ISK__AVX2_FN void isk__span_cov_avx2(uint8_t *d, const uint8_t *cov, int n, isk_color col,
                                                        isk_blend mode)
{
    int i = 0;
    if (mode == ISK_BLEND_ADD || mode == ISK_BLEND_OVER) {
        const __m256i C = _mm256_setr_epi16(col.r, col.g, col.b, 255, col.r, col.g, col.b, 255, col.r, col.g, col.b,
                                            255, col.r, col.g, col.b, 255);
        for (; i + 8 <= n; i += 8) {
            uint64_t m;
            memcpy(&m, cov + i, 8);
            if (m == 0u)
                continue;
            __m256i lo, hi;
            isk__a_alpha8(cov + i, col.a, &lo, &hi);
            if (mode == ISK_BLEND_ADD)
                isk__a8_add(d + 4 * i, lo, hi, C);
            else if (!isk__a8_over_opaque(d + 4 * i, lo, hi, C))
                for (int k = i; k < i + 8; k++)
                    isk__px_cov(d + 4 * k, col, cov[k], mode);
        }
    }
    isk__span_cov(d + 4 * i, cov + i, n - i, col, mode);
}

/* isk__span_add_bytes16, 32 bytes a step and one 16-byte step for the rest. */
static ISK__INLINE ISK__AVX2_FN void isk__span_add_bytes16_avx2(uint8_t *d, const uint8_t *q, int nbytes)
{
    int k = 0;
    for (; k + 32 <= nbytes; k += 32) {
        __m256i a = _mm256_loadu_si256((const __m256i *)(const void *)(d + k));
        __m256i b = _mm256_loadu_si256((const __m256i *)(const void *)(q + k));
        _mm256_storeu_si256((__m256i *)(void *)(d + k), _mm256_adds_epu8(a, b));
    }
    if (k < nbytes) {
        __m128i a = _mm_loadu_si128((const __m128i *)(const void *)(d + k));
        __m128i b = _mm_loadu_si128((const __m128i *)(const void *)(q + k));
        _mm_storeu_si128((__m128i *)(void *)(d + k), _mm_adds_epu8(a, b));
    }
}

static ISK__INLINE ISK__AVX2_FN void isk__span_add_bytes_avx2(uint8_t *d, const uint8_t *q, int nbytes)
{
    int k = 0;
    for (; k + 32 <= nbytes; k += 32) {
        __m256i a = _mm256_loadu_si256((const __m256i *)(const void *)(d + k));
        __m256i b = _mm256_loadu_si256((const __m256i *)(const void *)(q + k));
        _mm256_storeu_si256((__m256i *)(void *)(d + k), _mm256_adds_epu8(a, b));
    }
    isk__span_add_bytes(d + k, q + k, nbytes - k);
}
/* Source-over of a baked sprite row from its additive increments: byte 3
 * of each pixel's increments is its a' (iskra/sprite.h), spread over the
 * four channels by one byte shuffle; out = div255(c a' + d (255 - a')) on
 * opaque destinations, isk__blend_px_over with alpha a' elsewhere (the same as
 * isk__px_cov with the mask byte, whose a' this is).  The constants are
 * built once per sprite (isk__over_k) and passed down. */
typedef struct isk__over_k {
    __m256i C, spread, z, k128, k257, k255;
} isk__over_k;

static ISK__INLINE ISK__AVX2_FN void isk__over_k_init(isk__over_k *k, isk_color col)
{
    k->C = isk__a_keep(_mm256_setr_epi16(col.r, col.g, col.b, 255, col.r, col.g, col.b, 255, col.r, col.g, col.b, 255,
                                         col.r, col.g, col.b, 255));
    k->spread = isk__a_keep(_mm256_setr_epi8(3, 3, 3, 3, 7, 7, 7, 7, 11, 11, 11, 11, 15, 15, 15, 15, 3, 3, 3, 3, 7, 7,
                                             7, 7, 11, 11, 11, 11, 15, 15, 15, 15));
    k->z = _mm256_setzero_si256();
    k->k128 = ISK__K128Y;
    k->k257 = ISK__K257Y;
    k->k255 = ISK__K255Y;
}

/* 16 lanes of 16-bit x <= 255*255 -> div255, with the kept constants */
#define ISK__A_DIV255K(x, k) _mm256_mulhi_epu16(_mm256_add_epi16((x), (k)->k128), (k)->k257)
#define ISK__S_DIV255K(x, k) \
    _mm_mulhi_epu16(_mm_add_epi16((x), _mm256_castsi256_si128((k)->k128)), _mm256_castsi256_si128((k)->k257))

static ISK__INLINE ISK__AVX2_FN void isk__over_inc_fallback(uint8_t *d, const uint8_t *inc, int n, isk_color col)
{
    for (int i = 0; i < n; i++) {
        isk_color s = col;
        s.a = inc[4 * i + 3];
        isk__blend_px_over(d + 4 * i, s);
    }
}

static ISK__INLINE ISK__AVX2_FN void isk__over_inc_row_k(uint8_t *d, const uint8_t *inc, int n, isk_color col,
                                                         const isk__over_k *k)
{
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        __m256i v = _mm256_loadu_si256((const __m256i *)(const void *)(d + 4 * i));
        if (((unsigned)_mm256_movemask_epi8(_mm256_cmpeq_epi8(v, _mm256_cmpeq_epi8(k->z, k->z))) & 0x88888888u) !=
            0x88888888u) {
            isk__over_inc_fallback(d + 4 * i, inc + 4 * i, 8, col);
            continue;
        }
        __m256i aa = _mm256_shuffle_epi8(_mm256_loadu_si256((const __m256i *)(const void *)(inc + 4 * i)), k->spread);
        __m256i lo = _mm256_unpacklo_epi8(aa, k->z), hi = _mm256_unpackhi_epi8(aa, k->z);
        __m256i xl = _mm256_add_epi16(_mm256_mullo_epi16(_mm256_unpacklo_epi8(v, k->z), _mm256_sub_epi16(k->k255, lo)),
                                      _mm256_mullo_epi16(k->C, lo));
        __m256i xh = _mm256_add_epi16(_mm256_mullo_epi16(_mm256_unpackhi_epi8(v, k->z), _mm256_sub_epi16(k->k255, hi)),
                                      _mm256_mullo_epi16(k->C, hi));
        _mm256_storeu_si256((__m256i *)(void *)(d + 4 * i),
                            _mm256_packus_epi16(ISK__A_DIV255K(xl, k), ISK__A_DIV255K(xh, k)));
    }
    if (i + 4 <= n) { /* the same for one 4-pixel step, in the low halves */
        const __m128i z = _mm256_castsi256_si128(k->z);
        __m128i v = _mm_loadu_si128((const __m128i *)(const void *)(d + 4 * i));
        if ((_mm_movemask_epi8(_mm_cmpeq_epi8(v, _mm_cmpeq_epi8(z, z))) & 0x8888) != 0x8888) {
            isk__over_inc_fallback(d + 4 * i, inc + 4 * i, 4, col);
        } else {
            __m128i aa = _mm_shuffle_epi8(_mm_loadu_si128((const __m128i *)(const void *)(inc + 4 * i)),
                                          _mm256_castsi256_si128(k->spread));
            __m128i lo = _mm_unpacklo_epi8(aa, z), hi = _mm_unpackhi_epi8(aa, z);
            const __m128i C = _mm256_castsi256_si128(k->C), k255 = _mm256_castsi256_si128(k->k255);
            __m128i xl = _mm_add_epi16(_mm_mullo_epi16(_mm_unpacklo_epi8(v, z), _mm_sub_epi16(k255, lo)),
                                       _mm_mullo_epi16(C, lo));
            __m128i xh = _mm_add_epi16(_mm_mullo_epi16(_mm_unpackhi_epi8(v, z), _mm_sub_epi16(k255, hi)),
                                       _mm_mullo_epi16(C, hi));
            _mm_storeu_si128((__m128i *)(void *)(d + 4 * i),
                             _mm_packus_epi16(ISK__S_DIV255K(xl, k), ISK__S_DIV255K(xh, k)));
        }
        i += 4;
    }
    isk__over_inc_fallback(d + 4 * i, inc + 4 * i, n - i, col);
}

static ISK__INLINE ISK__AVX2_FN void isk__span_over_inc_avx2(uint8_t *d, const uint8_t *inc, int n, isk_color col)
{
    isk__over_k k;
    isk__over_k_init(&k, col);
    isk__over_inc_row_k(d, inc, n, col, &k);
}

/* `rows` whole rows of n pixels (n a constant where it can be). */
static ISK__INLINE ISK__AVX2_FN void isk__rows_over_whole_avx2(uint8_t *drow, size_t stride, const uint8_t *inc,
                                                               size_t inc_stride, int rows, int n, isk_color col,
                                                               const isk__over_k *k)
{
    for (int j = 0; j < rows; j++, drow += stride, inc += inc_stride)
        isk__over_inc_row_k(drow, inc, n, col, k);
}

/* Every row of a baked sprite wholly on the canvas, over: row j is at
 * drow + j * stride, its increments at inc + j * inc_stride, its span
 * [span[2j], span[2j+1]), or the whole row [0, S) when span is NULL (a'
 * = 0 leaves a pixel as it is: div255(255 d) = d). */
static ISK__INLINE ISK__AVX2_FN void isk__rows_over_inc_avx2(uint8_t *drow, size_t stride, const uint8_t *inc,
                                                             size_t inc_stride, const uint16_t *span, int S,
                                                             isk_color col)
{
    isk__over_k k;
    isk__over_k_init(&k, col);
    if (!span) {
        /* the small sizes with a constant row length: a row's steps
         * unrolled, no length test in it */
        if (S == 8)
            isk__rows_over_whole_avx2(drow, stride, inc, inc_stride, 8, 8, col, &k);
        else if (S == 12)
            isk__rows_over_whole_avx2(drow, stride, inc, inc_stride, 12, 12, col, &k);
        else if (S == 16)
            isk__rows_over_whole_avx2(drow, stride, inc, inc_stride, 16, 16, col, &k);
        else
            isk__rows_over_whole_avx2(drow, stride, inc, inc_stride, S, S, col, &k);
        return;
    }
    for (int j = 0; j < S; j++, drow += stride, inc += inc_stride) {
        int b = span[2 * j];
        isk__over_inc_row_k(drow + 4 * b, inc + 4 * b, span[2 * j + 1] - b, col, &k);
    }
}
#endif /* ISK__CPU_AVX2 */

#endif
