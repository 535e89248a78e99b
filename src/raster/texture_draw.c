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
 * The walkers here are the portable ones, per channel in integers.  Their
 * twins (raster/texture_loops.h) are texture_sse2.c on x86-64, one pixel at
 * a time, and texture_avx2.c where the CPU has AVX2, four pixels at a
 * time; all are the same integer formula, so the bytes do not depend on
 * the build (tests force each one, texture_rows.h). */
#include "iskra/texture.h"

#include <math.h>
#include <string.h>

#include "raster/blend_px.h"
#include "raster/clip.h"
#include "raster/texture_rows.h"
#include "raster/texture_loops.h"

#define TWO32 4294967296.0
#define FIX_HALF ((int64_t)1 << 31)
#define CENTRE_MAX 1048576.0 /* |cx|, |cy| < 2^20 */

/* x in units of 2^-32, rounded to nearest, halves away from zero (exact:
 * the truncation's remainder is exact). */
static inline int64_t fix32(double x)
{
    double v = x * TWO32;
    int64_t r = (int64_t)v;
    double f = v - (double)r;
    return r + (f >= 0.5) - (f <= -0.5);
}

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

/* ---- the portable walkers ---------------------------------------------------- */

/* Any angle: per row the exact span, then U and V stepped. */
static ISK__INLINE void walk_general(isk_canvas *c, const tex_draw *t, int j0, int j1, int tinted, isk_blend mode)
{
    const size_t ts = t->ts;
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
            px_scalar(d, p, ts, fx, fy, tinted, t->tint, mode);
        }
    }
}

/* Axis-aligned: columns tabled per chunk, rows one at a time (the v test
 * holds for a whole row, the u test for a whole column). */
static ISK__INLINE void walk_blit(isk_canvas *c, const tex_draw *t, int j0, int j1, int tinted, isk_blend mode)
{
    int ka, kb, ra, rb;
    if (!blit_span(t, j0, j1, &ka, &kb, &ra, &rb))
        return;
    const size_t ts = t->ts;
    blit_cols bc;
    for (int k0 = ka; k0 < kb; k0 += BLIT_CHUNK) {
        blit_columns(t, k0, kb - k0 < BLIT_CHUNK ? kb - k0 : BLIT_CHUNK, &bc);
        for (int r = ra; r < rb; r++) {
            uint32_t fy;
            uint8_t *d;
            const uint8_t *row = blit_row(c, t, j0 + r, k0, &fy, &d);
            for (int q = 0; q < bc.m; q++)
                px_scalar(d + 4 * q, row + 4u * (size_t)(bc.xa + bc.x[q]), ts, (uint32_t)bc.fx[q], fy, tinted, t->tint,
                          mode);
        }
    }
}

TEXTURE_WALKERS(scalar_, , walk_general, walk_blit)
static const isk__texture_walkers scalar_walkers = TEXTURE_TABLE(scalar_);

/* The build a sprite is drawn with: the widest this CPU runs, or a
 * narrower one the tests ask for (texture_rows.h's paths). */
static const isk__texture_walkers *pick_walkers(int paths)
{
    const isk__texture_walkers *w = &scalar_walkers;
    (void)paths; /* a build without twins has nothing to choose */
#if ISK__CPU_SSE2
    if (!(paths & ISK__TEXTURE_SCALAR))
        w = &isk__texture_walkers_sse2;
#endif
#if ISK__CPU_AVX2
    if (w == &isk__texture_walkers_sse2 && !(paths & ISK__TEXTURE_NO_AVX2) && isk__have_avx2())
        w = &isk__texture_walkers_avx2;
#endif
    return w;
}

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
    (*pick_walkers(paths))[mode][d.tinted][blit](c, &d, j0, j1);
}

void isk_draw_texture(isk_canvas *c, const isk_texture *t, int frame, double cx, double cy, double width,
                      double height, double angle, isk_color tint, isk_blend mode)
{
    isk__draw_texture_rows(c, t, frame, cx, cy, width, height, angle, tint, mode, 0, c ? c->height : 0, 0);
}
