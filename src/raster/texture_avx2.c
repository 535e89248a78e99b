/* SPDX-License-Identifier: MIT */
/* The textured sprite's walkers in AVX2 (raster/texture_loops.h), for a CPU
 * that has it: four pixels a step.  The samples come out as 16-bit lanes
 * in pixel order (A B | C D), the order of the destination's 16 bytes
 * widened; a row's last one to three pixels are the same step with the
 * missing lanes masked (their taps repeat the first pixel's, so every read
 * stays inside the texture).  The same integers as texture_draw.c's
 * px_scalar, so the same bytes. */
#include "core/cpu.h"

#if ISK__CPU_AVX2
#include <immintrin.h>
#include <string.h>

#include "raster/span_avx2.h" /* ISK__K128Y, ISK__K257Y */
#include "raster/texture_loops.h"

static ISK__INLINE ISK__AVX2_FN __m256i a_div255(__m256i x)
{
    return _mm256_mulhi_epu16(_mm256_add_epi16(x, ISK__K128Y), ISK__K257Y);
}

static ISK__INLINE ISK__AVX2_FN __m256i a_pair(const void *lo, const void *hi, int bytes8)
{
    __m128i a, b;
    if (bytes8) {
        a = _mm_loadl_epi64((const __m128i *)lo);
        b = _mm_loadl_epi64((const __m128i *)hi);
    } else {
        a = _mm_loadu_si128((const __m128i *)lo);
        b = _mm_loadu_si128((const __m128i *)hi);
    }
    return _mm256_inserti128_si256(_mm256_castsi128_si256(a), b, 1);
}

/* Eight bytes at a and eight at b as one vector (movq + movhps). */
static ISK__INLINE ISK__AVX2_FN __m128i a_two8(const uint8_t *a, const uint8_t *b)
{
    __m128i x = _mm_loadl_epi64((const __m128i *)(const void *)a);
    return _mm_castpd_si128(_mm_loadh_pd(_mm_castsi128_pd(x), (const double *)(const void *)b));
}

/* The samples' one rounding, (sum + 8192) >> 14, of two vectors of 32-bit
 * sums, packed into 16-bit lanes (lo's pixels first in each half). */
static ISK__INLINE ISK__AVX2_FN __m256i a_round_pack(__m256i lo, __m256i hi)
{
    const __m256i rnd = _mm256_set1_epi32(8192);
    lo = _mm256_srli_epi32(_mm256_add_epi32(lo, rnd), 14);
    hi = _mm256_srli_epi32(_mm256_add_epi32(hi, rnd), 14);
    return _mm256_packs_epi32(lo, hi);
}

/* Four samples of the rotated walker: left taps at base + off[0..3] (the
 * next row ts further), weights fx, fy in the low 32 bits of 64-bit lanes. */
static ISK__INLINE ISK__AVX2_FN __m256i a_sample4(const uint8_t *base, const int64_t *off, size_t ts, __m256i fx,
                                                  __m256i fy)
{
    const uint8_t *pa = base + off[0], *pb = base + off[1], *pc = base + off[2], *pd = base + off[3];
    /* a row's taps, lanes [A.t0 A.t1 B.t0 B.t1 | C.t0 C.t1 D.t0 D.t1] */
    __m256i g0 = _mm256_inserti128_si256(_mm256_castsi128_si256(a_two8(pa, pb)), a_two8(pc, pd), 1);
    __m256i g1 = _mm256_inserti128_si256(_mm256_castsi128_si256(a_two8(pa + ts, pb + ts)), a_two8(pc + ts, pd + ts), 1);
    /* each pixel's two taps interleaved by channel: t0.r t1.r t0.g t1.g ... */
    const __m256i il = _mm256_setr_epi8(0, 4, 1, 5, 2, 6, 3, 7, 8, 12, 9, 13, 10, 14, 11, 15, 0, 4, 1, 5, 2, 6, 3, 7, 8,
                                        12, 9, 13, 10, 14, 11, 15);
    const __m256i z = _mm256_setzero_si256();
    g0 = _mm256_shuffle_epi8(g0, il);
    g1 = _mm256_shuffle_epi8(g1, il);
    /* weight pairs (128 - f) | f << 16, spread over a pixel's 4 lanes:
     * ...l for A and C, ...h for B and D */
    const __m256i k128 = _mm256_set1_epi64x(128);
    __m256i wx = _mm256_or_si256(_mm256_slli_epi64(fx, 16), _mm256_sub_epi64(k128, fx));
    __m256i wy = _mm256_or_si256(_mm256_slli_epi64(fy, 16), _mm256_sub_epi64(k128, fy));
    __m256i wxl = _mm256_shuffle_epi32(wx, 0x00), wxh = _mm256_shuffle_epi32(wx, 0xAA);
    __m256i wyl = _mm256_shuffle_epi32(wy, 0x00), wyh = _mm256_shuffle_epi32(wy, 0xAA);
    /* horizontal: (t0.c, t1.c) against (128 - fx, fx), exact, < 2^15 */
    __m256i hl0 = _mm256_madd_epi16(_mm256_unpacklo_epi8(g0, z), wxl);
    __m256i hh0 = _mm256_madd_epi16(_mm256_unpackhi_epi8(g0, z), wxh);
    __m256i hl1 = _mm256_madd_epi16(_mm256_unpacklo_epi8(g1, z), wxl);
    __m256i hh1 = _mm256_madd_epi16(_mm256_unpackhi_epi8(g1, z), wxh);
    /* vertical: (row 0, row 1) per channel against (128 - fy, fy) */
    __m256i vl = _mm256_madd_epi16(_mm256_or_si256(hl0, _mm256_slli_epi32(hl1, 16)), wyl);
    __m256i vh = _mm256_madd_epi16(_mm256_or_si256(hh0, _mm256_slli_epi32(hh1, 16)), wyh);
    return a_round_pack(vl, vh);
}

/* Four samples of the blit from the filtered row v: left taps at v + 4 x[q],
 * weight pairs w[q]. */
static ISK__INLINE ISK__AVX2_FN __m256i a_hsample4(const uint16_t *v, const int *x, const uint32_t *w)
{
    __m256i pl = a_pair(v + 4 * x[0], v + 4 * x[2], 0), ph = a_pair(v + 4 * x[1], v + 4 * x[3], 0);
    __m256i w4 = _mm256_castsi128_si256(_mm_loadu_si128((const __m128i *)(const void *)w));
    __m256i wl = _mm256_permutevar8x32_epi32(w4, _mm256_setr_epi32(0, 0, 0, 0, 2, 2, 2, 2));
    __m256i wh = _mm256_permutevar8x32_epi32(w4, _mm256_setr_epi32(1, 1, 1, 1, 3, 3, 3, 3));
    __m256i sl = _mm256_madd_epi16(_mm256_unpacklo_epi16(pl, _mm256_srli_si256(pl, 8)), wl);
    __m256i sh = _mm256_madd_epi16(_mm256_unpacklo_epi16(ph, _mm256_srli_si256(ph, 8)), wh);
    return a_round_pack(sl, sh);
}

/* The AVX2 blit's vertical pass (4 texels a step; reads up to 3 texels past
 * the end: slack). */
static ISK__INLINE ISK__AVX2_FN void a_vrow(uint16_t *v, const uint8_t *r0, size_t ts, int xa, int nt, uint32_t fy)
{
    const __m256i w0 = _mm256_set1_epi16((short)(128u - fy)), w1 = _mm256_set1_epi16((short)fy);
    const uint8_t *a = r0 + 4u * (size_t)xa, *b = a + ts;
    for (int x = 0; x < nt; x += 4) {
        __m256i ta = _mm256_cvtepu8_epi16(_mm_loadu_si128((const __m128i *)(const void *)(a + 4 * x)));
        __m256i tb = _mm256_cvtepu8_epi16(_mm_loadu_si128((const __m128i *)(const void *)(b + 4 * x)));
        _mm256_storeu_si256((__m256i *)(void *)(v + 4 * x),
                            _mm256_add_epi16(_mm256_mullo_epi16(ta, w0), _mm256_mullo_epi16(tb, w1)));
    }
}

/* Tint and blend n (1..4) samples (16-bit lanes A B | C D) into d. */
static ISK__INLINE ISK__AVX2_FN void a_put4(uint8_t *d, __m256i s, int n, int tinted, __m256i kta, __m256i ktc,
                                            isk_blend mode)
{
    if (tinted) {
        s = a_div255(_mm256_mullo_epi16(s, kta));
        s = a_div255(_mm256_mullo_epi16(s, ktc));
    }
    const __m128i mask = _mm_cmpgt_epi32(_mm_set1_epi32(n), _mm_setr_epi32(0, 1, 2, 3));
    __m128i v = n == 4 ? _mm_loadu_si128((const __m128i *)(const void *)d) : _mm_maskload_epi32((const int *)(const void *)d, mask);
    __m128i out;
    if (mode == ISK_BLEND_ADD) {
        __m256i b = _mm256_permute4x64_epi64(_mm256_packus_epi16(s, s), 0x08);
        out = _mm_adds_epu8(v, _mm256_castsi256_si128(b));
    } else if (mode == ISK_BLEND_OVER &&
               (_mm_movemask_epi8(_mm_cmpeq_epi8(_mm_or_si128(v, _mm_xor_si128(mask, _mm_set1_epi8(-1))),
                                                 _mm_set1_epi8(-1))) & 0x8888) == 0x8888) {
        __m256i D = _mm256_cvtepu8_epi16(v);
        __m256i inv = _mm256_sub_epi16(_mm256_set1_epi16(255), _mm256_shufflehi_epi16(_mm256_shufflelo_epi16(s, 0xFF), 0xFF));
        __m256i x = _mm256_add_epi16(a_div255(_mm256_mullo_epi16(D, inv)), s);
        out = _mm256_castsi256_si128(_mm256_permute4x64_epi64(_mm256_packus_epi16(x, x), 0x08));
    } else {
        /* replace, or over onto a translucent pixel: the exact rule per pixel */
        uint8_t q[16];
        __m256i b = _mm256_permute4x64_epi64(_mm256_packus_epi16(s, s), 0x08);
        _mm_storeu_si128((__m128i *)(void *)q, _mm256_castsi256_si128(b));
        for (int k = 0; k < n; k++)
            blend_pm(d + 4 * k, q[4 * k], q[4 * k + 1], q[4 * k + 2], q[4 * k + 3], mode);
        return;
    }
    if (n == 4)
        _mm_storeu_si128((__m128i *)(void *)d, out);
    else
        _mm_maskstore_epi32((int *)(void *)d, mask, out);
}

#define A_TINT_CONSTANTS(t)                                                                                        \
    const __m256i kta = _mm256_set1_epi16((short)(t)->tint.a);                                                     \
    const __m256i ktc = _mm256_setr_epi16((t)->tint.r, (t)->tint.g, (t)->tint.b, 255, (t)->tint.r, (t)->tint.g,    \
                                          (t)->tint.b, 255, (t)->tint.r, (t)->tint.g, (t)->tint.b, 255,            \
                                          (t)->tint.r, (t)->tint.g, (t)->tint.b, 255)

static ISK__INLINE ISK__AVX2_FN void walk_general_avx2(isk_canvas *c, const tex_draw *t, int j0, int j1, int tinted,
                                                       isk_blend mode)
{
    const size_t ts = t->ts;
    A_TINT_CONSTANTS(t);
    const __m256i m127 = _mm256_set1_epi64x(127);
    const __m256i lane_u = _mm256_setr_epi64x(0, t->dux, 2 * t->dux, 3 * t->dux);
    const __m256i lane_v = _mm256_setr_epi64x(0, t->dvx, 2 * t->dvx, 3 * t->dvx);
    const __m256i step_u = _mm256_set1_epi64x(4 * t->dux), step_v = _mm256_set1_epi64x(4 * t->dvx);
    const __m256i vts = _mm256_set1_epi64x((long long)ts);
    for (int j = j0; j < j1; j++) {
        int64_t pu, pv;
        int ka, kb;
        if (!row_span(t, j, &pu, &pv, &ka, &kb))
            continue;
        uint8_t *d = c->pixels + (size_t)j * c->stride + 4u * (size_t)(t->bi0 + ka);
        __m256i U = _mm256_add_epi64(_mm256_set1_epi64x(pu), lane_u), V = _mm256_add_epi64(_mm256_set1_epi64x(pv), lane_v);
        for (int k = ka; k < kb; k += 4, d += 16) {
            int n = kb - k < 4 ? kb - k : 4;
            __m256i u = U, v = V;
            if (n < 4) { /* the masked lanes take the first pixel's taps */
                __m256i keep = _mm256_cmpgt_epi64(_mm256_set1_epi64x(n), _mm256_setr_epi64x(0, 1, 2, 3));
                u = _mm256_blendv_epi8(_mm256_permute4x64_epi64(U, 0), U, keep);
                v = _mm256_blendv_epi8(_mm256_permute4x64_epi64(V, 0), V, keep);
            }
            /* texel offsets: (V >> 32) ts + 4 (U >> 32) (both below 2^32) */
            int64_t off[4];
            _mm256_storeu_si256((__m256i *)(void *)off,
                                _mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(v, 32), vts),
                                                 _mm256_slli_epi64(_mm256_srli_epi64(u, 32), 2)));
            __m256i fx = _mm256_and_si256(_mm256_srli_epi64(u, 25), m127);
            __m256i fy = _mm256_and_si256(_mm256_srli_epi64(v, 25), m127);
            a_put4(d, a_sample4(t->base, off, ts, fx, fy), n, tinted, kta, ktc, mode);
            U = _mm256_add_epi64(U, step_u);
            V = _mm256_add_epi64(V, step_v);
        }
    }
}

static ISK__INLINE ISK__AVX2_FN void walk_blit_avx2(isk_canvas *c, const tex_draw *t, int j0, int j1, int tinted,
                                                    isk_blend mode)
{
    int ka, kb, ra, rb;
    if (!blit_span(t, j0, j1, &ka, &kb, &ra, &rb))
        return;
    const size_t ts = t->ts;
    A_TINT_CONSTANTS(t);
    blit_cols bc;
    uint16_t vrow[4 * (VROW_MAX + 4)];
    for (int k0 = ka; k0 < kb; k0 += BLIT_CHUNK) {
        blit_columns(t, k0, kb - k0 < BLIT_CHUNK ? kb - k0 : BLIT_CHUNK, &bc);
        for (int r = ra; r < rb; r++) {
            uint32_t fy;
            uint8_t *d;
            const uint8_t *row = blit_row(c, t, j0 + r, k0, &fy, &d);
            int wide = bc.nt > VROW_MAX; /* far beyond 2 texels per pixel: the taps per pixel */
            if (!wide)
                a_vrow(vrow, row, ts, bc.xa, bc.nt, fy);
            for (int q = 0; q < bc.m; q += 4) {
                int n = bc.m - q < 4 ? bc.m - q : 4;
                __m256i s;
                if (!wide) {
                    s = a_hsample4(vrow, bc.x + q, bc.w + q);
                } else {
                    int64_t off[4];
                    for (int e = 0; e < 4; e++)
                        off[e] = 4 * (int64_t)(bc.xa + bc.x[q + e]);
                    s = a_sample4(row, off, ts, _mm256_loadu_si256((const __m256i *)(const void *)(bc.fx + q)),
                                  _mm256_set1_epi64x(fy));
                }
                a_put4(d + 4 * q, s, n, tinted, kta, ktc, mode);
            }
        }
    }
}

TEXTURE_WALKERS(avx2_, ISK__AVX2_FN, walk_general_avx2, walk_blit_avx2)
const isk__texture_walkers isk__texture_walkers_avx2 = TEXTURE_TABLE(avx2_);
#else
typedef int isk__texture_avx2_unused; /* ISO C wants a declaration in every file */
#endif
