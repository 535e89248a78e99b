/* SPDX-License-Identifier: MIT */
/* Drawing textured sprites: the rule of iskra/texture.h (mip level,
 * fixed-point inverse mapping, footprint, bilinear sample, tint, blend of a
 * premultiplied source), in two row walkers that compute the same integers:
 *
 *   general   any angle: per row, the exact span of pixels inside the
 *             footprint (a double estimate widened, then trimmed by the
 *             exact test: the inside set of a row is contiguous), then a
 *             walk stepping U and V by the fixed-point derivatives;
 *   blit      an axis-aligned mapping (DUY = DVX = 0): the columns' taps
 *             and weights are computed once per sprite and the rows' once
 *             per row, so a pixel is two table reads and the sample.
 *
 * The sample and the blends are SSE2 on x86-64, one pixel at a time
 * (16-bit lanes: the horizontal taps are exact products below 2^15, the
 * vertical step a pmaddwd, one rounding), AVX2 where the CPU has it, four
 * pixels at a time (the taps gathered), and portable integer code
 * elsewhere; all are the same integer formula, so the bytes do not depend
 * on the path (tests force each path, texture_rows.h). */
#include "iskra/texture.h"

#include <math.h>
#include <string.h>

#include "raster/blend_px.h"
#include "raster/clip.h"
#include "raster/span_simd.h"
#include "raster/texture_rows.h"

#define TEX_SSE2 ISK__SPAN_SSE2
#define TEX_AVX2 ISK__SPAN_AVX2

#define TWO32 4294967296.0
#define FIX_HALF ((int64_t)1 << 31)
#define CENTRE_MAX 1048576.0 /* |cx|, |cy| < 2^20 */
#define BLIT_CHUNK 256       /* columns whose taps are tabled at once */

/* x in units of 2^-32, rounded to nearest, halves away from zero (exact:
 * the truncation's remainder is exact). */
static inline int64_t fix32(double x)
{
    double v = x * TWO32;
    int64_t r = (int64_t)v;
    double f = v - (double)r;
    return r + (f >= 0.5) - (f <= -0.5);
}

/* Where and how a sprite is drawn: everything the walkers need. */
typedef struct tex_draw {
    const uint8_t *base;    /* the level's padded image: its border texel (-1, -1) */
    size_t ts;              /* bytes per padded row */
    int64_t pu0, pv0;       /* U + 1/2 and V + 1/2 at pixel (i0, j0), in 2^-32 texel */
    int64_t dux, duy, dvx, dvy;
    uint64_t uhi, vhi;      /* footprint: 0 <= pu < uhi and 0 <= pv < vhi */
    int i0, j0;
    int bi0, bi1, bj0, bj1; /* pixels that may be inside, cut to the canvas */
    double rdux, rdvx, rdvy; /* 1 / the derivative (0 for 0): span estimates */
    int tinted;             /* the tint is not white */
    isk_color tint;
} tex_draw;

static int place(tex_draw *d, const isk_canvas *c, const isk_texture *t, int frame, double cx, double cy, double W,
                 double H, double angle, isk_color tint, isk_blend mode)
{
    if (!c || !c->pixels || c->width <= 0 || c->height <= 0 || !t || !t->texels || t->frames < 1 || t->levels < 1)
        return 0;
    if (mode != ISK_BLEND_REPLACE && mode != ISK_BLEND_OVER && mode != ISK_BLEND_ADD)
        return 0;
    /* the comparisons also reject NaN */
    if (!(cx > -CENTRE_MAX && cx < CENTRE_MAX && cy > -CENTRE_MAX && cy < CENTRE_MAX))
        return 0;
    if (!(W >= ISK_TEXTURE_DRAW_MIN && W <= ISK_TEXTURE_DRAW_MAX && H >= ISK_TEXTURE_DRAW_MIN &&
          H <= ISK_TEXTURE_DRAW_MAX) ||
        !isfinite(angle))
        return 0;
    if (tint.a == 0) /* every sample's A is 0 */
        return 0;
    if (frame < 0)
        frame = 0;
    if (frame >= t->frames)
        frame = t->frames - 1;

    double f = t->frame_w / W, fv = t->frame_h / H, p2 = 2.0;
    if (fv > f)
        f = fv;
    int L = 0;
    while (L + 1 < t->levels && f >= p2) {
        L++;
        p2 *= 2.0;
    }
    const isk_texture_level *lv = &t->level[L];
    d->base = t->texels + (size_t)frame * t->frame_bytes + lv->offset;
    d->ts = 4u * (size_t)(lv->w + 2);

    double su = lv->w / W, sv = lv->h / H, cs = 1.0, sn = 0.0;
    if (angle != 0.0) {
        cs = cos(angle);
        sn = sin(angle);
    }
    double m00 = cs * su, m01 = sn * su, m10 = -sn * sv, m11 = cs * sv;
    d->i0 = (int)floor(cx);
    d->j0 = (int)floor(cy);
    double ox = (d->i0 + 0.5) - cx, oy = (d->j0 + 0.5) - cy;
    d->pu0 = fix32(m00 * ox + m01 * oy + 0.5 * lv->w) + FIX_HALF;
    d->pv0 = fix32(m10 * ox + m11 * oy + 0.5 * lv->h) + FIX_HALF;
    d->dux = fix32(m00);
    d->duy = fix32(m01);
    d->dvx = fix32(m10);
    d->dvy = fix32(m11);
    d->uhi = (uint64_t)(lv->w + 1) << 32;
    d->vhi = (uint64_t)(lv->h + 1) << 32;
    d->rdux = d->dux ? 1.0 / (double)d->dux : 0.0;
    d->rdvx = d->dvx ? 1.0 / (double)d->dvx : 0.0;
    d->rdvy = d->dvy ? 1.0 / (double)d->dvy : 0.0;

    /* The footprint's half extents along the image axes (the frame and half
     * a texel of border), turned, plus 2 px for every rounding: no pixel
     * outside this box can pass the exact test. */
    double ex = 0.5 * W * (lv->w + 1) / lv->w, ey = 0.5 * H * (lv->h + 1) / lv->h;
    double bx = fabs(cs) * ex + fabs(sn) * ey + 2.0, by = fabs(sn) * ex + fabs(cs) * ey + 2.0;
    d->bi0 = isk__floor_clamp(cx - bx, 0, c->width);
    d->bi1 = isk__floor_clamp(cx + bx, -1, c->width - 1) + 1;
    d->bj0 = isk__floor_clamp(cy - by, 0, c->height);
    d->bj1 = isk__floor_clamp(cy + by, -1, c->height - 1) + 1;
    if (d->bi0 >= d->bi1 || d->bj0 >= d->bj1)
        return 0;
    d->tint = tint;
    d->tinted = tint.r != 255 || tint.g != 255 || tint.b != 255 || tint.a != 255;
    return 1;
}

/* The k in [*ka, *kb) with 0 <= p + k dp < hi, exactly (the set is an
 * interval).  The estimate (numerators exact in integers, rdp = 1 / dp) is
 * within far less than a pixel of each end wherever that end falls inside
 * the range, so the first pixel inside lies within [floor(lo) - 1,
 * floor(lo) + 2] and three branch-free exact steps find it, likewise the
 * end; the loops after them never run unless that bound failed. */
static ISK__INLINE void cut_span(int64_t p, int64_t dp, uint64_t hi, double rdp, int *ka, int *kb)
{
    int a = *ka, b = *kb;
    if (dp == 0) {
        if (!((uint64_t)p < hi))
            b = a;
    } else {
        double x = (double)(-p) * rdp, y = (double)((int64_t)hi - p) * rdp;
        double lo = x < y ? x : y, up = x < y ? y : x;
        int s = isk__floor_clamp(lo, a - 4, b + 4) - 1;
        s += !((uint64_t)(p + (int64_t)s * dp) < hi);
        s += !((uint64_t)(p + (int64_t)s * dp) < hi);
        s += !((uint64_t)(p + (int64_t)s * dp) < hi);
        int e = isk__floor_clamp(up, a - 4, b + 4) - 1;
        e = e > s ? e : s;
        e += (uint64_t)(p + (int64_t)e * dp) < hi;
        e += (uint64_t)(p + (int64_t)e * dp) < hi;
        e += (uint64_t)(p + (int64_t)e * dp) < hi;
        a = s > a ? s : a;
        b = e < b ? e : b;
        while (a < b && !((uint64_t)(p + (int64_t)a * dp) < hi))
            a++;
        while (b > a && !((uint64_t)(p + (int64_t)(b - 1) * dp) < hi))
            b--;
    }
    *ka = a;
    *kb = b < a ? a : b;
}

/* ---- the blend of a premultiplied sample (iskra/texture.h) ---------------- */

static ISK__INLINE void blend_pm(uint8_t *d, uint32_t pr, uint32_t pg, uint32_t pb, uint32_t A, isk_blend mode)
{
    switch (mode) {
    case ISK_BLEND_ADD:
        d[0] = isk__sat_add(d[0], pr);
        d[1] = isk__sat_add(d[1], pg);
        d[2] = isk__sat_add(d[2], pb);
        d[3] = isk__sat_add(d[3], A);
        break;
    case ISK_BLEND_OVER: {
        if (A == 0u)
            break;
        uint32_t da = d[3], inv = 255u - A;
        if (da == 255u) {
            d[0] = (uint8_t)(pr + isk_div255(d[0] * inv));
            d[1] = (uint8_t)(pg + isk_div255(d[1] * inv));
            d[2] = (uint8_t)(pb + isk_div255(d[2] * inv));
            break;
        }
        uint32_t wd = da * inv, T = 255u * A + wd, half = T / 2u;
        d[0] = (uint8_t)((65025u * pr + d[0] * wd + half) / T);
        d[1] = (uint8_t)((65025u * pg + d[1] * wd + half) / T);
        d[2] = (uint8_t)((65025u * pb + d[2] * wd + half) / T);
        d[3] = (uint8_t)isk_div255(T);
        break;
    }
    case ISK_BLEND_REPLACE:
        if (A == 0u)
            break;
        d[0] = (uint8_t)((255u * pr + A / 2u) / A);
        d[1] = (uint8_t)((255u * pg + A / 2u) / A);
        d[2] = (uint8_t)((255u * pb + A / 2u) / A);
        d[3] = (uint8_t)A;
        break;
    default:
        break;
    }
}

/* ---- portable pixel --------------------------------------------------------- */

static ISK__INLINE void px_scalar(uint8_t *d, const uint8_t *p, size_t ts, uint32_t fx, uint32_t fy, int tinted,
                                  isk_color tint, isk_blend mode)
{
    const uint32_t w00 = (128u - fx) * (128u - fy), w10 = fx * (128u - fy), w01 = (128u - fx) * fy, w11 = fx * fy;
    uint32_t s[4];
    for (int k = 0; k < 4; k++)
        s[k] = (p[k] * w00 + p[4 + k] * w10 + p[ts + k] * w01 + p[ts + 4 + k] * w11 + 8192u) >> 14;
    if (tinted) {
        s[3] = isk_div255(s[3] * tint.a);
        s[0] = isk_div255(tint.r * isk_div255(s[0] * tint.a));
        s[1] = isk_div255(tint.g * isk_div255(s[1] * tint.a));
        s[2] = isk_div255(tint.b * isk_div255(s[2] * tint.a));
    }
    blend_pm(d, s[0], s[1], s[2], s[3], mode);
}

/* ---- SSE2 pixel ------------------------------------------------------------- */

#if TEX_SSE2
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
#endif


/* ---- the blit's rows, filtered vertically first ---------------------------------
 * In the blit every pixel of a row has the same fy, so each texel column
 * the row needs is blended vertically once, V = t0 (128 - fy) + t1 fy
 * (exact, below 2^15), and a pixel is then V0 (128 - fx) + V1 fx: the same
 * sum of four exact products, one rounding.  VROW_MAX texels at most (a
 * wider chunk, possible only far beyond 2 texels per pixel, takes the
 * per-pixel taps). */
#define VROW_MAX 600

/* The column table of the blit: per column its left tap (padded texel
 * index, relative to the chunk's first texel xa) and its weight pair
 * (128 - fx) | fx << 16. */
typedef struct blit_cols {
    int m, xa, nt;              /* columns, first texel, texels the rows need */
    /* 3 more entries repeat the last column, so a row's last group of
     * four reads valid taps in its masked lanes */
    int x[BLIT_CHUNK + 3];      /* left tap - xa */
    uint32_t w[BLIT_CHUNK + 3]; /* (128 - fx) | fx << 16 */
    int64_t fx[BLIT_CHUNK + 3];
} blit_cols;

static ISK__INLINE void blit_columns(const tex_draw *t, int k0, int m, blit_cols *bc)
{
    int lo = INT32_MAX, hi = -1;
    for (int q = 0; q < m; q++) {
        uint64_t x = (uint64_t)(t->pu0 + (int64_t)(t->bi0 + k0 + q - t->i0) * t->dux);
        int tx = (int)(x >> 32);
        uint32_t fx = (uint32_t)(x >> 25) & 127u;
        bc->x[q] = tx;
        bc->fx[q] = (int64_t)fx;
        bc->w[q] = (128u - fx) | fx << 16;
        lo = tx < lo ? tx : lo;
        hi = tx > hi ? tx : hi;
    }
    for (int q = m; q < m + 3; q++) {
        bc->x[q] = bc->x[m - 1];
        bc->fx[q] = bc->fx[m - 1];
        bc->w[q] = bc->w[m - 1];
    }
    bc->m = m;
    bc->xa = lo;
    bc->nt = hi + 2 - lo;
    for (int q = 0; q < m + 3; q++)
        bc->x[q] -= lo;
}

/* The blit's extent: columns [*ka, *kb) of the candidate box, rows [*ra,
 * *rb) of the band [j0, j1); 0 when empty. */
static ISK__INLINE int blit_span(const tex_draw *t, int j0, int j1, int *ka, int *kb, int *ra, int *rb)
{
    *ka = 0;
    *kb = t->bi1 - t->bi0;
    cut_span(t->pu0 + (int64_t)(t->bi0 - t->i0) * t->dux, t->dux, t->uhi, t->rdux, ka, kb);
    *ra = 0;
    *rb = j1 - j0;
    cut_span(t->pv0 + (int64_t)(j0 - t->j0) * t->dvy, t->dvy, t->vhi, t->rdvy, ra, rb);
    return *ka < *kb && *ra < *rb;
}

/* Row j of the blit: its upper texel row and weight fy (the same for the
 * whole row), and *d, the destination of the chunk starting at column k0. */
static ISK__INLINE const uint8_t *blit_row(isk_canvas *c, const tex_draw *t, int j, int k0, uint32_t *fy,
                                           uint8_t **d)
{
    uint64_t y = (uint64_t)(t->pv0 + (int64_t)(j - t->j0) * t->dvy);
    *fy = (uint32_t)(y >> 25) & 127u;
    *d = c->pixels + (size_t)j * c->stride + 4u * (size_t)(t->bi0 + k0);
    return t->base + (size_t)(y >> 32) * t->ts;
}

/* A row of the rotated walker: its exact span [*ka, *kb) and U, V (+ 1/2)
 * at the span's first pixel; 0 when empty. */
static ISK__INLINE int row_span(const tex_draw *t, int j, int64_t *pu, int64_t *pv, int *ka, int *kb)
{
    int64_t u = t->pu0 + (int64_t)(j - t->j0) * t->duy + (int64_t)(t->bi0 - t->i0) * t->dux;
    int64_t v = t->pv0 + (int64_t)(j - t->j0) * t->dvy + (int64_t)(t->bi0 - t->i0) * t->dvx;
    *ka = 0;
    *kb = t->bi1 - t->bi0;
    cut_span(u, t->dux, t->uhi, t->rdux, ka, kb);
    cut_span(v, t->dvx, t->vhi, t->rdvx, ka, kb);
    *pu = u + (int64_t)*ka * t->dux;
    *pv = v + (int64_t)*ka * t->dvx;
    return *ka < *kb;
}

#if TEX_SSE2
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
#endif

/* ---- AVX2: four pixels a step ----------------------------------------------------
 * The samples come out as 16-bit lanes in pixel order (A B | C D), the
 * order of the destination's 16 bytes widened; a row's last one to three
 * pixels are the same step with the missing lanes masked (their taps
 * repeat the first pixel's, so every read stays inside the texture). */
#if TEX_AVX2
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
#endif

/* ---- the walkers of the portable and SSE2 levels --------------------------------- */

/* SIMD level of a walker: the portable arithmetic, SSE2 one pixel at a
 * time, AVX2 four at a time. */
enum { LV_SCALAR, LV_SSE2, LV_AVX2, LV_COUNT };

/* Any angle: per row the exact span, then U and V stepped. */
static ISK__INLINE void walk_general(isk_canvas *c, const tex_draw *t, int j0, int j1, int level, int tinted,
                                     isk_blend mode)
{
    const size_t ts = t->ts;
#if TEX_SSE2
    const __m128i kta = _mm_set1_epi16((short)t->tint.a);
    const __m128i ktc = _mm_set_epi16(255, t->tint.b, t->tint.g, t->tint.r, 255, t->tint.b, t->tint.g, t->tint.r);
#endif
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
#if TEX_SSE2
            if (level != LV_SCALAR) {
                px_sse2(d, p, ts, s_wx(fx), s_wy(fy), tinted, kta, ktc, mode);
                continue;
            }
#else
            (void)level;
#endif
            px_scalar(d, p, ts, fx, fy, tinted, t->tint, mode);
        }
    }
}

/* Axis-aligned: columns tabled per chunk, rows one at a time (the v test
 * holds for a whole row, the u test for a whole column); SSE2 filters each
 * row vertically first. */
static ISK__INLINE void walk_blit(isk_canvas *c, const tex_draw *t, int j0, int j1, int level, int tinted,
                                  isk_blend mode)
{
    int ka, kb, ra, rb;
    if (!blit_span(t, j0, j1, &ka, &kb, &ra, &rb))
        return;
    const size_t ts = t->ts;
    blit_cols bc;
#if TEX_SSE2
    const __m128i kta = _mm_set1_epi16((short)t->tint.a);
    const __m128i ktc = _mm_set_epi16(255, t->tint.b, t->tint.g, t->tint.r, 255, t->tint.b, t->tint.g, t->tint.r);
    uint16_t vrow[4 * (VROW_MAX + 2)];
#endif
    for (int k0 = ka; k0 < kb; k0 += BLIT_CHUNK) {
        blit_columns(t, k0, kb - k0 < BLIT_CHUNK ? kb - k0 : BLIT_CHUNK, &bc);
        for (int r = ra; r < rb; r++) {
            uint32_t fy;
            uint8_t *d;
            const uint8_t *row = blit_row(c, t, j0 + r, k0, &fy, &d);
#if TEX_SSE2
            if (level != LV_SCALAR && bc.nt <= VROW_MAX) {
                s_vrow(vrow, row, ts, bc.xa, bc.nt, fy);
                for (int q = 0; q < bc.m; q++)
                    px_sse2_put(d + 4 * q, s_hsample(vrow + 4 * bc.x[q], bc.w[q]), tinted, kta, ktc, mode);
                continue;
            }
            if (level != LV_SCALAR) {
                for (int q = 0; q < bc.m; q++)
                    px_sse2(d + 4 * q, row + 4u * (size_t)(bc.xa + bc.x[q]), ts, s_wx((uint32_t)bc.fx[q]), s_wy(fy), tinted, kta,
                            ktc, mode);
                continue;
            }
#else
            (void)level;
#endif
            for (int q = 0; q < bc.m; q++)
                px_scalar(d + 4 * q, row + 4u * (size_t)(bc.xa + bc.x[q]), ts, (uint32_t)bc.fx[q], fy, tinted, t->tint, mode);
        }
    }
}

/* ---- one function per (level, mode, tint), the rest constants inside ------- */

typedef void (*walker_fn)(isk_canvas *, const tex_draw *, int, int);

#define BASE_WALKERS(LV, MODE, TINT, SUFFIX)                                                            \
    static void general_##SUFFIX(isk_canvas *c, const tex_draw *t, int j0, int j1)                     \
    {                                                                                                   \
        walk_general(c, t, j0, j1, LV, TINT, MODE);                                                     \
    }                                                                                                   \
    static void blit_##SUFFIX(isk_canvas *c, const tex_draw *t, int j0, int j1)                        \
    {                                                                                                   \
        walk_blit(c, t, j0, j1, LV, TINT, MODE);                                                        \
    }
#define BASE_MODES(LV, NAME)                                                                            \
    BASE_WALKERS(LV, ISK_BLEND_REPLACE, 0, NAME##_replace)                                              \
    BASE_WALKERS(LV, ISK_BLEND_OVER, 0, NAME##_over)                                                    \
    BASE_WALKERS(LV, ISK_BLEND_ADD, 0, NAME##_add)                                                      \
    BASE_WALKERS(LV, ISK_BLEND_REPLACE, 1, NAME##_replace_t)                                            \
    BASE_WALKERS(LV, ISK_BLEND_OVER, 1, NAME##_over_t)                                                  \
    BASE_WALKERS(LV, ISK_BLEND_ADD, 1, NAME##_add_t)
#define TABLE(NAME)                                                                                     \
    {{{general_##NAME##_replace, blit_##NAME##_replace}, {general_##NAME##_replace_t, blit_##NAME##_replace_t}}, \
     {{general_##NAME##_over, blit_##NAME##_over}, {general_##NAME##_over_t, blit_##NAME##_over_t}},             \
     {{general_##NAME##_add, blit_##NAME##_add}, {general_##NAME##_add_t, blit_##NAME##_add_t}}}

BASE_MODES(LV_SCALAR, scalar)
#if TEX_SSE2
BASE_MODES(LV_SSE2, sse2)
#endif
#if TEX_AVX2
#define AVX2_WALKERS(MODE, TINT, SUFFIX)                                                                \
    static ISK__AVX2_FN void general_##SUFFIX(isk_canvas *c, const tex_draw *t, int j0, int j1)        \
    {                                                                                                   \
        walk_general_avx2(c, t, j0, j1, TINT, MODE);                                                    \
    }                                                                                                   \
    static ISK__AVX2_FN void blit_##SUFFIX(isk_canvas *c, const tex_draw *t, int j0, int j1)           \
    {                                                                                                   \
        walk_blit_avx2(c, t, j0, j1, TINT, MODE);                                                       \
    }
AVX2_WALKERS(ISK_BLEND_REPLACE, 0, avx2_replace)
AVX2_WALKERS(ISK_BLEND_OVER, 0, avx2_over)
AVX2_WALKERS(ISK_BLEND_ADD, 0, avx2_add)
AVX2_WALKERS(ISK_BLEND_REPLACE, 1, avx2_replace_t)
AVX2_WALKERS(ISK_BLEND_OVER, 1, avx2_over_t)
AVX2_WALKERS(ISK_BLEND_ADD, 1, avx2_add_t)
#endif

/* [level][mode][tinted][blit]; a level this build lacks falls back to the
 * next lower one. */
static const walker_fn WALKER[LV_COUNT][ISK_BLEND_COUNT][2][2] = {
    TABLE(scalar),
#if TEX_SSE2
    TABLE(sse2),
#else
    TABLE(scalar),
#endif
#if TEX_AVX2
    TABLE(avx2),
#elif TEX_SSE2
    TABLE(sse2),
#else
    TABLE(scalar),
#endif
};

void isk__draw_texture_rows(isk_canvas *c, const isk_texture *t, int frame, double cx, double cy, double width,
                            double height, double angle, isk_color tint, isk_blend mode, int r0, int r1, int paths)
{
    tex_draw d;
    if (!place(&d, c, t, frame, cx, cy, width, height, angle, tint, mode))
        return;
    int j0 = d.bj0 > r0 ? d.bj0 : r0, j1 = d.bj1 < r1 ? d.bj1 : r1;
    if (j0 >= j1)
        return;
    int blit = d.duy == 0 && d.dvx == 0 && !(paths & ISK__TEXTURE_GENERAL);
    int level = LV_SCALAR;
#if TEX_SSE2
    if (!(paths & ISK__TEXTURE_SCALAR))
        level = LV_SSE2;
#endif
#if TEX_AVX2
    if (level == LV_SSE2 && !(paths & ISK__TEXTURE_NO_AVX2) && isk__have_avx2())
        level = LV_AVX2;
#endif
    WALKER[level][mode][d.tinted][blit](c, &d, j0, j1);
}

void isk_draw_texture(isk_canvas *c, const isk_texture *t, int frame, double cx, double cy, double width,
                      double height, double angle, isk_color tint, isk_blend mode)
{
    isk__draw_texture_rows(c, t, frame, cx, cy, width, height, angle, tint, mode, 0, c ? c->height : 0, 0);
}
