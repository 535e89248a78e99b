/* SPDX-License-Identifier: MIT */
/* src/raster/span_vector.h — the row kernels of raster/span.h in GCC /
 * Clang vector extensions, 8 pixels a step: what targets without SSE2
 * build (the compiler lowers them to NEON, AltiVec, ... or scalar code).
 * Internal; span.h includes this where src/core/cpu.h's ISK__CPU_VECTOR is
 * 1 (tests/test_raster_kernels_generic.c forces it on x86-64 with
 * ISK__CPU_NO_SSE2, so it is checked here too).
 *
 *   isk__span_cov_vector(d, cov, n, col, mode)   isk__span_cov in add and
 *                                                over, tail included;
 *                                                returns how many pixels
 *                                                it did (0 for replace)
 *   isk__span_add_bytes_vector(d, q, nbytes)     the whole 16-byte steps of
 *                                                isk__span_add_bytes
 *
 * Lane order is memory order; the byte-packing (r | g << 8) needs a
 * little-endian machine, which cpu.h requires for ISK__CPU_VECTOR. */
#ifndef ISKRA_RASTER_SPAN_VECTOR_H
#define ISKRA_RASTER_SPAN_VECTOR_H

#include "core/cpu.h"

#if ISK__CPU_VECTOR
#include <stdint.h>
#include <string.h>

#include "raster/blend_px.h"

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

static ISK__INLINE int isk__span_cov_vector(uint8_t *d, const uint8_t *cov, int n, isk_color col, isk_blend mode)
{
    int i = 0;
    if (mode != ISK_BLEND_ADD && mode != ISK_BLEND_OVER)
        return 0;
    const isk__u16x8 C = {col.r, col.g, col.b, 255, col.r, col.g, col.b, 255};
    for (; i + 8 <= n; i += 8)
        isk__v8_cov(d + 4 * i, cov + i, col, C, mode);
    int t = n - i;
    if (t >= 2) {
        /* The tail through a scratch group: missing pixels get coverage 0
         * (no change in either mode) and an opaque alpha (so they do not
         * spoil the opaque test). */
        uint8_t px[32], cv[8] = {0};
        memset(px, 255, sizeof px);
        memcpy(px, d + 4 * i, 4u * (unsigned)t);
        memcpy(cv, cov + i, (unsigned)t);
        isk__v8_cov(px, cv, col, C, mode);
        memcpy(d + 4 * i, px, 4u * (unsigned)t);
        return n;
    }
    return i;
}

static ISK__INLINE int isk__span_add_bytes_vector(uint8_t *d, const uint8_t *q, int nbytes)
{
    int k = 0;
    for (; k + 16 <= nbytes; k += 16) {
        isk__u8x16 a, b;
        memcpy(&a, d + k, 16);
        memcpy(&b, q + k, 16);
        a = isk__v_sat_add(a, b);
        memcpy(d + k, &a, 16);
    }
    return k;
}
#endif /* ISK__CPU_VECTOR */

#endif
