/* SPDX-License-Identifier: MIT */
/* src/raster/dot_kernel_sse2.h — the SSE2 twin of the coverage dot's 2x2
 * blend of raster/dot_kernel.h, add and over, without a coverage table
 * (internal; dot_kernel.h includes this where src/core/cpu.h's
 * ISK__CPU_SSE2 is 1).
 *
 *   isk__blend_2x2_sse2(p, stride, w, col, mode)   the block at p: the
 *       four a' = div255(sa w) at once, then each row's two pixels in one
 *       set of 16-bit lanes (a row with a pixel that is not opaque: the
 *       per-pixel rule)
 *
 * isk__px_cov's bytes (div255 as the high half of (x + 128) * 257). */
#ifndef ISKRA_RASTER_DOT_KERNEL_SSE2_H
#define ISKRA_RASTER_DOT_KERNEL_SSE2_H

#include "core/cpu.h"

#if ISK__CPU_SSE2
#include <emmintrin.h>
#include <stddef.h>
#include <stdint.h>

#include "raster/blend_px.h"

/* One row of the block: two pixels at p with their a' spread over their
 * channels (aa = [a0 x4, a1 x4]); isk__px_cov's bytes (see blend_px.h). */
static ISK__INLINE void isk__row2_sse2(uint8_t *p, __m128i aa, __m128i C, isk_color col, const uint32_t *w,
                                       isk_blend mode)
{
    const __m128i z = _mm_setzero_si128(), k128 = _mm_set1_epi16(128), k257 = _mm_set1_epi16(257);
    __m128i v = _mm_loadl_epi64((const __m128i *)(const void *)p);
    if (mode == ISK_BLEND_ADD) {
        __m128i inc = _mm_mulhi_epu16(_mm_add_epi16(_mm_mullo_epi16(aa, C), k128), k257);
        _mm_storel_epi64((__m128i *)(void *)p, _mm_adds_epu8(v, _mm_packus_epi16(inc, inc)));
    } else if (p[3] == 255u && p[7] == 255u) {
        __m128i x = _mm_add_epi16(_mm_mullo_epi16(_mm_unpacklo_epi8(v, z), _mm_sub_epi16(_mm_set1_epi16(255), aa)),
                                  _mm_mullo_epi16(C, aa));
        x = _mm_mulhi_epu16(_mm_add_epi16(x, k128), k257);
        _mm_storel_epi64((__m128i *)(void *)p, _mm_packus_epi16(x, x));
    } else {
        isk__px_cov(p, col, w[0], mode);
        isk__px_cov(p + 4, col, w[1], mode);
    }
}

/* The whole 2x2 block (add or over): a' = div255(sa w) for the four
 * weights at once, then a row of two pixels at a time. */
static ISK__INLINE void isk__blend_2x2_sse2(uint8_t *p, size_t stride, const uint32_t w[4], isk_color col,
                                            isk_blend mode)
{
    __m128i A = _mm_setr_epi16((short)w[0], (short)w[1], (short)w[2], (short)w[3], 0, 0, 0, 0);
    A = _mm_mulhi_epu16(_mm_add_epi16(_mm_mullo_epi16(A, _mm_set1_epi16((short)col.a)), _mm_set1_epi16(128)),
                        _mm_set1_epi16(257));
    __m128i t = _mm_unpacklo_epi16(A, A);
    uint32_t c32 = (uint32_t)col.r | (uint32_t)col.g << 8 | (uint32_t)col.b << 16 | 0xFF000000u;
    __m128i C = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)c32), _mm_setzero_si128());
    C = _mm_unpacklo_epi64(C, C);
    isk__row2_sse2(p, _mm_unpacklo_epi32(t, t), C, col, w, mode);
    isk__row2_sse2(p + stride, _mm_unpackhi_epi32(t, t), C, col, w + 2, mode);
}
#endif /* ISK__CPU_SSE2 */

#endif
