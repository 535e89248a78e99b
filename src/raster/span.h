/* SPDX-License-Identifier: MIT */
/* src/raster/span.h — row ("span") kernels: one colour blended along a row
 * of pixels with per-pixel coverage bytes (internal).
 *
 *   isk__span_cov(d, cov, n, col, mode)    pixel i: isk__px_cov(d + 4i, col, cov[i], mode)
 *   isk__span_add_bytes(d, q, nbytes)      d[k] = min(255, d[k] + q[k])  (premade increments)
 *   isk__span_add_bytes16(d, q, nbytes)    the same, nbytes a multiple of 16
 *
 * Each is the plain loop below, after a fast twin that takes the first
 * whole groups of pixels where this build has one (src/core/cpu.h):
 * span_sse2.h on x86-64 (4 pixels a step), span_vector.h on other GCC /
 * Clang targets (8 pixels a step), none in the reference build; the AVX2
 * twins, chosen at run time by their callers, are in span_avx2.h.
 *
 * The twins give the plain loop's bytes, by construction:
 *   a' = div255(sa * cov) and div255(c * a') are computed in 16-bit lanes
 *   as (t + (t >> 8)) >> 8 with t = x + 128, or as the high half of t * 257
 *   (the same value), which equals (x + 127) / 255 for every x <= 255*255
 *   (checked exhaustively in tests/test_raster_fast.c and
 *   tests/raster_kernels_body.h);
 *   source-over uses the opaque-destination formula only for groups whose
 *   alpha bytes are all 255, and the exact per-pixel rule otherwise;
 * tests/test_raster_kernels*.c compare every twin with the rule. */
#ifndef ISKRA_RASTER_SPAN_H
#define ISKRA_RASTER_SPAN_H

#include <stdint.h>
#include <string.h>

#include "core/cpu.h"
#include "raster/blend_px.h"
#if ISK__CPU_SSE2
#include "raster/span_sse2.h"
#elif ISK__CPU_VECTOR
#include "raster/span_vector.h"
#endif

/* Pixel i of the row at d gets coverage cov[i] (a mask byte).  Fastest
 * when n is a multiple of 4 (the sprites' padded spans). */
static ISK__INLINE void isk__span_cov(uint8_t *d, const uint8_t *cov, int n, isk_color col, isk_blend mode)
{
    int i = 0; /* the pixels a fast twin did */
#if ISK__CPU_SSE2
    i = isk__span_cov_sse2(d, cov, n, col, mode);
#elif ISK__CPU_VECTOR
    i = isk__span_cov_vector(d, cov, n, col, mode);
#endif
    for (; i < n; i++)
        isk__px_cov(d + 4 * i, col, cov[i], mode);
}

/* Saturating byte add of premade increments (a sprite's baked colour):
 * four bytes a step in one uint32, then byte by byte. */
static ISK__INLINE void isk__span_add_bytes(uint8_t *d, const uint8_t *q, int nbytes)
{
    int k = 0; /* the bytes a fast twin did */
#if ISK__CPU_SSE2
    k = isk__span_add_bytes_sse2(d, q, nbytes);
#elif ISK__CPU_VECTOR
    k = isk__span_add_bytes_vector(d, q, nbytes);
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
 * 4-pixel steps), so the SSE2 twin needs no tail loops. */
static ISK__INLINE void isk__span_add_bytes16(uint8_t *d, const uint8_t *q, int nbytes)
{
#if ISK__CPU_SSE2
    isk__span_add_bytes16_sse2(d, q, nbytes);
#else
    isk__span_add_bytes(d, q, nbytes);
#endif
}

#endif
