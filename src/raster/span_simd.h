/* SPDX-License-Identifier: MIT */
/* src/raster/span_simd.h — row ("span") kernels: one colour blended along a
 * row of pixels with per-pixel coverage bytes, several pixels per step.
 * Three builds of the same arithmetic, chosen at compile time, all portable
 * -O3 without -march:
 *   x86-64: SSE2 intrinsics (SSE2 is part of x86-64), 4 pixels a step;
 *   other GCC / Clang targets: vector extensions, 8 pixels a step (the
 *     compiler lowers them to NEON, AltiVec, ... or scalar code);
 *   anything else: the per-pixel rule.
 * tests/test_raster_fast.c checks the first two against the per-pixel
 * reference (the vector-extension build by compiling this header with
 * ISK__SPAN_NO_SSE2 defined).
 *
 *   isk__span_cov(d, cov, n, col, mode)   pixel i: isk__px_cov(d + 4i, col, cov[i], mode)
 *   isk__span_add_bytes(d, q, nbytes)     d[k] = min(255, d[k] + q[k])  (premade increments)
 *
 * Same bytes as the per-pixel rule (iskra/blend.h), by construction:
 *   a' = div255(sa * cov) and div255(c * a') are computed in 16-bit lanes
 *   as (t + (t >> 8)) >> 8 with t = x + 128, or as the high half of t * 257
 *   (the same value), which equals (x + 127) / 255 for every x <= 255*255
 *   (checked exhaustively in tests/test_raster_fast.c);
 *   OVER uses the opaque-destination formula only for groups of 8 pixels
 *   whose alpha bytes are all 255, and the exact per-pixel rule otherwise.
 * Lane order is memory order; the byte-packing trick (r | g << 8) needs a
 * little-endian machine, so big-endian builds take the per-pixel loop.
 */
#ifndef ISKRA_RASTER_SPAN_SIMD_H
#define ISKRA_RASTER_SPAN_SIMD_H

#include <stdint.h>
#include <string.h>

#include "raster/blend_px.h"

#if defined(__SSE2__) && !defined(ISK__SPAN_NO_SSE2)
#define ISK__SPAN_SSE2 1
#define ISK__SPAN_VECTOR 0
#include <emmintrin.h>
#elif defined(__GNUC__) && defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ && \
    (defined(__clang__) || __GNUC__ >= 9)
#define ISK__SPAN_SSE2 0
#define ISK__SPAN_VECTOR 1
#else
#define ISK__SPAN_SSE2 0
#define ISK__SPAN_VECTOR 0
#endif

#if ISK__SPAN_SSE2
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
#endif /* ISK__SPAN_SSE2 */

/* ---- AVX2, chosen at run time --------------------------------------------
 * The same arithmetic 8 pixels a step, in functions compiled for AVX2 by a
 * target attribute (the rest of the build stays baseline x86-64); callers
 * pick them per primitive when isk__have_avx2() says the CPU and the OS
 * support them.  Integer arithmetic: the bytes do not depend on the path. */
#if ISK__SPAN_SSE2 && defined(__GNUC__) && !defined(ISK__SPAN_NO_AVX2) && (defined(__clang__) || __GNUC__ >= 6)
#define ISK__SPAN_AVX2 1
#include <immintrin.h>
#define ISK__AVX2_FN __attribute__((target("avx2")))

/* 1 or 0 (a table index), whatever __builtin_cpu_supports returns. */
static inline int isk__have_avx2(void)
{
    return __builtin_cpu_supports("avx2") != 0;
}

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
#else
#define ISK__SPAN_AVX2 0
/* No AVX2 build: callers that index tables by it need no #if. */
static inline int isk__have_avx2(void) { return 0; }
#endif

/* AVX-512 (F, VL, BW, DQ), chosen at run time the same way: for kernels of
 * doubles that gain from 8 lanes and mask registers (the dot's weights).
 * The bits are the same: IEEE operations lane by lane, no FMA
 * (-ffp-contract=off holds in these functions too). */
#if ISK__SPAN_AVX2 && !defined(ISK__SPAN_NO_AVX512) && (defined(__clang__) || __GNUC__ >= 8)
#define ISK__SPAN_AVX512 1
#define ISK__AVX512_FN __attribute__((target("avx512f,avx512vl,avx512bw,avx512dq")))
static inline int isk__have_avx512(void)
{
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
           __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq");
}
#else
#define ISK__SPAN_AVX512 0
static inline int isk__have_avx512(void) { return 0; }
#endif

/* Its arguments where this build has AVX2 (AVX-512), else nothing: one
 * list of a kernel's builds, and one table row per build, without an #if
 * for each combination of the two. */
#if ISK__SPAN_AVX2
#define ISK__IF_AVX2(...) __VA_ARGS__
#else
#define ISK__IF_AVX2(...)
#endif
#if ISK__SPAN_AVX512
#define ISK__IF_AVX512(...) __VA_ARGS__
#else
#define ISK__IF_AVX512(...)
#endif

/* The widest build a caller may take, at most `most` (0 baseline x86-64,
 * 1 AVX2, 2 AVX-512) and what this CPU runs: the index of a table with a
 * row per build (1 + ISK__SPAN_AVX2 + ISK__SPAN_AVX512 rows).  Tests pass
 * each `most` in turn to compare the builds' bits. */
static inline int isk__simd_level(int most)
{
    if (most >= 2 && isk__have_avx512())
        return 2;
    return most >= 1 && isk__have_avx2();
}

#if ISK__SPAN_VECTOR
typedef uint8_t isk__u8x8 __attribute__((vector_size(8)));
typedef uint8_t isk__u8x16 __attribute__((vector_size(16)));
typedef uint16_t isk__u16x8 __attribute__((vector_size(16)));

/* Two-vector shuffles with constant lane lists, written only in patterns
 * SSE2 has single instructions for (unpack, pack), so GCC and Clang emit
 * those rather than lane-by-lane moves. */
#if defined(__clang__)
#define ISK__SHUF16(a, b, ...) __builtin_shufflevector(a, b, __VA_ARGS__)
#define ISK__SHUF8(a, b, ...) __builtin_shufflevector(a, b, __VA_ARGS__)
#else
#define ISK__SHUF16(a, b, ...) __builtin_shuffle(a, b, (isk__u16x8){__VA_ARGS__})
#define ISK__SHUF8(a, b, ...) __builtin_shuffle(a, b, (isk__u8x16){__VA_ARGS__})
#endif

static ISK__INLINE isk__u16x8 isk__v_div255(isk__u16x8 x)
{
    isk__u16x8 t = x + 128;
    return (t + (t >> 8)) >> 8;
}

static ISK__INLINE isk__u8x16 isk__v_sat_add(isk__u8x16 a, isk__u8x16 b)
{
    isk__u8x16 s = a + b;
    return s | (isk__u8x16)(s < a); /* wrapped lanes become 255 */
}

/* Two vectors of 16-bit values <= 255 packed into one of bytes (the low
 * byte of each lane: little-endian). */
static ISK__INLINE isk__u8x16 isk__v_pack(isk__u16x8 lo, isk__u16x8 hi)
{
    return ISK__SHUF8((isk__u8x16)lo, (isk__u8x16)hi, 0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
}

/* Bytes 0..7 / 8..15 of v as 16-bit lanes. */
static ISK__INLINE isk__u16x8 isk__v_widen_lo(isk__u8x16 v)
{
    const isk__u8x16 z = {0};
    return (isk__u16x8)ISK__SHUF8(v, z, 0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23);
}

static ISK__INLINE isk__u16x8 isk__v_widen_hi(isk__u8x16 v)
{
    const isk__u8x16 z = {0};
    return (isk__u16x8)ISK__SHUF8(v, z, 8, 24, 9, 25, 10, 26, 11, 27, 12, 28, 13, 29, 14, 30, 15, 31);
}

static ISK__INLINE isk__u16x8 isk__v_widen8(const uint8_t *p)
{
    isk__u8x8 b;
    memcpy(&b, p, 8);
    return __builtin_convertvector(b, isk__u16x8);
}

/* 8 pixels, additive: dst += (div255(r a'), div255(g a'), div255(b a'), a'). */
static ISK__INLINE void isk__v8_add(uint8_t *d, isk__u16x8 A, isk_color col)
{
    isk__u16x8 R = isk__v_div255(A * (uint16_t)col.r), G = isk__v_div255(A * (uint16_t)col.g),
               B = isk__v_div255(A * (uint16_t)col.b);
    isk__u16x8 rg = R | (isk__u16x8)(G << 8), ba = B | (isk__u16x8)(A << 8);
    isk__u16x8 lo = ISK__SHUF16(rg, ba, 0, 8, 1, 9, 2, 10, 3, 11);
    isk__u16x8 hi = ISK__SHUF16(rg, ba, 4, 12, 5, 13, 6, 14, 7, 15);
    isk__u8x16 d0, d1;
    memcpy(&d0, d, 16);
    memcpy(&d1, d + 16, 16);
    d0 = isk__v_sat_add(d0, (isk__u8x16)lo);
    d1 = isk__v_sat_add(d1, (isk__u8x16)hi);
    memcpy(d, &d0, 16);
    memcpy(d + 16, &d1, 16);
}

/* 2 pixels over an opaque destination, given their a' in every lane of
 * their 4 channels (AA) and the colour as [r g b 255 r g b 255]. */
static ISK__INLINE isk__u16x8 isk__v2_over(isk__u16x8 D, isk__u16x8 AA, isk__u16x8 C)
{
    return isk__v_div255(D * (isk__u16x8)(255 - AA) + C * AA);
}

/* 8 pixels over opaque destinations (alpha stays 255: the alpha lane
 * computes div255(255 a' + 255 (255 - a')) = 255). */
static ISK__INLINE void isk__v8_over_opaque(uint8_t *d, isk__u16x8 A, isk__u16x8 C)
{
    /* a' of pixels 0..7 spread over their four channels, two pixels a vector */
    isk__u16x8 lo = ISK__SHUF16(A, A, 0, 8, 1, 9, 2, 10, 3, 11);   /* a0 a0 a1 a1 a2 a2 a3 a3 */
    isk__u16x8 hi = ISK__SHUF16(A, A, 4, 12, 5, 13, 6, 14, 7, 15); /* a4 a4 ... a7 a7 */
    isk__u16x8 a01 = ISK__SHUF16(lo, lo, 0, 8, 1, 9, 2, 10, 3, 11);
    isk__u16x8 a23 = ISK__SHUF16(lo, lo, 4, 12, 5, 13, 6, 14, 7, 15);
    isk__u16x8 a45 = ISK__SHUF16(hi, hi, 0, 8, 1, 9, 2, 10, 3, 11);
    isk__u16x8 a67 = ISK__SHUF16(hi, hi, 4, 12, 5, 13, 6, 14, 7, 15);
    isk__u8x16 d0, d1;
    memcpy(&d0, d, 16);
    memcpy(&d1, d + 16, 16);
    d0 = isk__v_pack(isk__v2_over(isk__v_widen_lo(d0), a01, C), isk__v2_over(isk__v_widen_hi(d0), a23, C));
    d1 = isk__v_pack(isk__v2_over(isk__v_widen_lo(d1), a45, C), isk__v2_over(isk__v_widen_hi(d1), a67, C));
    memcpy(d, &d0, 16);
    memcpy(d + 16, &d1, 16);
}

static ISK__INLINE int isk__opaque8(const uint8_t *d)
{
    return (d[3] & d[7] & d[11] & d[15] & d[19] & d[23] & d[27] & d[31]) == 255u;
}
#endif /* ISK__SPAN_VECTOR */

#if ISK__SPAN_VECTOR
/* 8 pixels at p with coverage cov[0..8). */
static ISK__INLINE void isk__v8_cov(uint8_t *p, const uint8_t *cov, isk_color col, isk__u16x8 C, isk_blend mode)
{
    isk__u16x8 A = isk__v_div255(isk__v_widen8(cov) * (uint16_t)col.a);
    if (mode == ISK_BLEND_ADD) {
        isk__v8_add(p, A, col);
    } else if (isk__opaque8(p)) {
        isk__v8_over_opaque(p, A, C);
    } else {
        for (int k = 0; k < 8; k++)
            isk__px_cov(p + 4 * k, col, cov[k], mode);
    }
}
#endif

/* Pixel i of the row at d gets coverage cov[i] (a mask byte).  Fastest
 * when n is a multiple of 4 (the sprites' padded spans). */
static ISK__INLINE void isk__span_cov(uint8_t *d, const uint8_t *cov, int n, isk_color col, isk_blend mode)
{
    int i = 0;
#if ISK__SPAN_SSE2
    if (mode == ISK_BLEND_ADD || mode == ISK_BLEND_OVER) {
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
    }
#elif ISK__SPAN_VECTOR
    if (mode == ISK_BLEND_ADD || mode == ISK_BLEND_OVER) {
        const isk__u16x8 C = {col.r, col.g, col.b, 255, col.r, col.g, col.b, 255};
        for (; i + 8 <= n; i += 8)
            isk__v8_cov(d + 4 * i, cov + i, col, C, mode);
        int t = n - i;
        if (t >= 2) {
            /* The tail through a scratch group: missing pixels get
             * coverage 0 (no change in either mode) and an opaque alpha
             * (so they do not spoil the opaque test). */
            uint8_t px[32], cv[8] = {0};
            memset(px, 255, sizeof px);
            memcpy(px, d + 4 * i, 4u * (unsigned)t);
            memcpy(cv, cov + i, (unsigned)t);
            isk__v8_cov(px, cv, col, C, mode);
            memcpy(d + 4 * i, px, 4u * (unsigned)t);
            return;
        }
    }
#endif
    for (; i < n; i++)
        isk__px_cov(d + 4 * i, col, cov[i], mode);
}

/* Saturating byte add of premade increments (a sprite's baked colour). */
static ISK__INLINE void isk__span_add_bytes(uint8_t *d, const uint8_t *q, int nbytes)
{
    int k = 0;
#if ISK__SPAN_SSE2
    for (; k + 16 <= nbytes; k += 16) {
        __m128i a = _mm_loadu_si128((const __m128i *)(const void *)(d + k));
        __m128i b = _mm_loadu_si128((const __m128i *)(const void *)(q + k));
        _mm_storeu_si128((__m128i *)(void *)(d + k), _mm_adds_epu8(a, b));
    }
#elif ISK__SPAN_VECTOR
    for (; k + 16 <= nbytes; k += 16) {
        isk__u8x16 a, b;
        memcpy(&a, d + k, 16);
        memcpy(&b, q + k, 16);
        a = isk__v_sat_add(a, b);
        memcpy(d + k, &a, 16);
    }
#endif
    for (; k + 4 <= nbytes; k += 4) {
        uint32_t a, b;
        memcpy(&a, d + k, 4);
        memcpy(&b, q + k, 4);
        a = isk__sat_add_u8x4(a, b);
        memcpy(d + k, &a, 4);
    }
    for (; k < nbytes; k++)
        d[k] = isk__sat_add(d[k], q[k]);
}


/* isk__span_add_bytes for a padded span: nbytes a multiple of 16 (whole
 * 4-pixel steps), so no tail loops. */
static ISK__INLINE void isk__span_add_bytes16(uint8_t *d, const uint8_t *q, int nbytes)
{
#if ISK__SPAN_SSE2
    for (int k = 0; k < nbytes; k += 16) {
        __m128i a = _mm_loadu_si128((const __m128i *)(const void *)(d + k));
        __m128i b = _mm_loadu_si128((const __m128i *)(const void *)(q + k));
        _mm_storeu_si128((__m128i *)(void *)(d + k), _mm_adds_epu8(a, b));
    }
#else
    isk__span_add_bytes(d, q, nbytes);
#endif
}

#if ISK__SPAN_AVX2
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
 * opaque destinations, isk__px_over with alpha a' elsewhere (the same as
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
        isk__px_over(d + 4 * i, s);
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
#endif


#endif
