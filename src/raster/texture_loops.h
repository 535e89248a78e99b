/* SPDX-License-Identifier: MIT */
/* src/raster/texture_loops.h — what every build of the textured sprite's
 * walkers shares (internal): the placement (tex_draw), the exact spans of
 * a row, the blit's column table, the blend of a premultiplied sample, and
 * the macros that compile one build's walkers into a table.
 *
 * texture_draw.c has the portable walkers (and picks a build), and
 * texture_sse2.c and texture_avx2.c have their twins, one pixel at a time
 * in SSE2 registers and four pixels at a time in AVX2 ones:
 *
 *     TEXTURE_WALKERS(sse2_, , walk_general_sse2, walk_blit_sse2)
 *     const isk__texture_walkers isk__texture_walkers_sse2 = TEXTURE_TABLE(sse2_);
 *
 * A table is indexed [mode][tinted][blit].  All builds compute the same
 * integers (iskra/texture.h's rule), so the bytes do not depend on the
 * build; tests force each one (texture_rows.h's paths). */
#ifndef ISKRA_RASTER_TEXTURE_LOOPS_H
#define ISKRA_RASTER_TEXTURE_LOOPS_H

#include <stddef.h>
#include <stdint.h>

#include "core/cpu.h"
#include "iskra/texture.h"
#include "raster/blend_px.h"
#include "raster/clip.h"

#define BLIT_CHUNK 256 /* columns whose taps are tabled at once */

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

/* ---- one function per (mode, tint), the rest constants inside ------------- */

typedef void (*walker_fn)(isk_canvas *, const tex_draw *, int, int);
typedef walker_fn isk__texture_walkers[ISK_BLEND_COUNT][2][2];

/* GENERAL and BLIT: static ISK__INLINE walkers taking (c, t, j0, j1,
 * tinted, mode), compiled with ATTR (a target attribute, or nothing). */
#define TEXTURE_WALKER(P, ATTR, GENERAL, BLIT, MODE, TINT, SUFFIX)                                        \
    static ATTR void P##general_##SUFFIX(isk_canvas *c, const tex_draw *t, int j0, int j1)              \
    {                                                                                                   \
        GENERAL(c, t, j0, j1, TINT, MODE);                                                              \
    }                                                                                                   \
    static ATTR void P##blit_##SUFFIX(isk_canvas *c, const tex_draw *t, int j0, int j1)                 \
    {                                                                                                   \
        BLIT(c, t, j0, j1, TINT, MODE);                                                                 \
    }
#define TEXTURE_WALKERS(P, ATTR, GENERAL, BLIT)                                                          \
    TEXTURE_WALKER(P, ATTR, GENERAL, BLIT, ISK_BLEND_REPLACE, 0, replace)                               \
    TEXTURE_WALKER(P, ATTR, GENERAL, BLIT, ISK_BLEND_OVER, 0, over)                                     \
    TEXTURE_WALKER(P, ATTR, GENERAL, BLIT, ISK_BLEND_ADD, 0, add)                                       \
    TEXTURE_WALKER(P, ATTR, GENERAL, BLIT, ISK_BLEND_REPLACE, 1, replace_t)                             \
    TEXTURE_WALKER(P, ATTR, GENERAL, BLIT, ISK_BLEND_OVER, 1, over_t)                                   \
    TEXTURE_WALKER(P, ATTR, GENERAL, BLIT, ISK_BLEND_ADD, 1, add_t)
#define TEXTURE_TABLE(P)                                                                                 \
    {{{P##general_replace, P##blit_replace}, {P##general_replace_t, P##blit_replace_t}},               \
     {{P##general_over, P##blit_over}, {P##general_over_t, P##blit_over_t}},                           \
     {{P##general_add, P##blit_add}, {P##general_add_t, P##blit_add_t}}}

#if ISK__CPU_SSE2
extern const isk__texture_walkers isk__texture_walkers_sse2; /* texture_sse2.c */
#endif
#if ISK__CPU_AVX2
extern const isk__texture_walkers isk__texture_walkers_avx2; /* texture_avx2.c, for a CPU that has AVX2 */
#endif

#endif
