/* SPDX-License-Identifier: MIT */
/* src/view/dot_block_sse2.h — the SSE2 twins of view/dot_block.h's blends
 * from a coverage table (internal; dot_block.h includes this where
 * src/core/cpu.h's ISK__CPU_SSE2 is 1).
 *
 *   px2_sse2(p, lut, wa, wb, mode)      px2's add, and its over on two opaque
 *                                       pixels, in one register
 *   px4_sse2(p, stride, lut, w, mode)   px4's over on four opaque pixels, in
 *                                       one set of lanes
 *
 * Each returns 1 when it blended, 0 (nothing touched) when the plain code
 * must (another mode, or a pixel that is not opaque).  The same bytes as
 * the table's per-pixel blends (blend_px.h's isk__px_lut). */
#ifndef ISKRA_VIEW_DOT_BLOCK_SSE2_H
#define ISKRA_VIEW_DOT_BLOCK_SSE2_H

#include "core/cpu.h"

#if ISK__CPU_SSE2
#include <emmintrin.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "raster/blend_px.h"
#include "raster/span_sse2.h" /* isk__s_div255 */

/* Source-over on two opaque pixels whose bytes are the low 8 of v, at
 * coverages wa, wb: div255(c a' + d (255 - a')) in their 16-bit lanes, from
 * the coverage table (blend_px.h's isk__over_opaque_lanes, two at once). */
static ISK__INLINE __m128i over2_opaque(__m128i v, const isk__cov_lut *lut, uint32_t wa, uint32_t wb)
{
    const __m128i P = _mm_set_epi64x((long long)lut->over_p[wb], (long long)lut->over_p[wa]);
    const __m128i I = _mm_set_epi64x((long long)lut->over_inv[wb], (long long)lut->over_inv[wa]);
    return isk__s_div255(_mm_add_epi16(_mm_mullo_epi16(_mm_unpacklo_epi8(v, _mm_setzero_si128()), I), P));
}

static ISK__INLINE int px2_sse2(uint8_t *p, const isk__cov_lut *lut, uint32_t wa, uint32_t wb, isk_blend mode)
{
    if (mode == ISK_BLEND_ADD) {
        uint32_t ia, ib;
        memcpy(&ia, lut->add[wa], 4);
        memcpy(&ib, lut->add[wb], 4);
        __m128i inc = _mm_unpacklo_epi32(_mm_cvtsi32_si128((int)ia), _mm_cvtsi32_si128((int)ib));
        __m128i v = _mm_loadl_epi64((const __m128i *)(const void *)p);
        _mm_storel_epi64((__m128i *)(void *)p, _mm_adds_epu8(v, inc));
        return 1;
    }
    if (mode == ISK_BLEND_OVER && p[3] == 255u && p[7] == 255u) {
        const __m128i x = over2_opaque(_mm_loadl_epi64((const __m128i *)(const void *)p), lut, wa, wb);
        _mm_storel_epi64((__m128i *)(void *)p, _mm_packus_epi16(x, x));
        return 1;
    }
    return 0;
}

static ISK__INLINE int px4_sse2(uint8_t *p, size_t stride, const isk__cov_lut *lut, const uint8_t w[4],
                                isk_blend mode)
{
    if (mode == ISK_BLEND_OVER) {
        /* integer loads and stores: the rows are 4-byte aligned, and a
         * double's (_mm_loadh_pd) would claim 8 */
        uint8_t *q = p + stride;
        const __m128i vp = _mm_loadl_epi64((const __m128i *)(const void *)p);
        const __m128i vq = _mm_loadl_epi64((const __m128i *)(const void *)q);
        const __m128i v = _mm_unpacklo_epi64(vp, vq);
        if ((_mm_movemask_epi8(_mm_cmpeq_epi8(v, _mm_set1_epi8(-1))) & 0x8888) == 0x8888) {
            const __m128i r = _mm_packus_epi16(over2_opaque(vp, lut, w[0], w[1]), over2_opaque(vq, lut, w[2], w[3]));
            _mm_storel_epi64((__m128i *)(void *)p, r);
            _mm_storel_epi64((__m128i *)(void *)q, _mm_unpackhi_epi64(r, r));
            return 1;
        }
    }
    return 0;
}
#endif /* ISK__CPU_SSE2 */

#endif
