/* SPDX-License-Identifier: MIT */
/* src/raster/dot_kernel.h — the coverage dot's weights and its 2x2 blend as
 * inline kernels, shared by the single-dot calls (dot.c) and the batched
 * draws over a particle store (src/view/world_draw.c, isk_draw_dots).
 *
 * The rules (documented in iskra/draw.h and dot.c) are stated once here;
 * both the single call and the batch run exactly this code, so a batch is
 * byte-identical to the loop of single calls.  Every kernel takes the blend
 * mode as its last argument and is meant to be called with a constant one
 * (ISK__BLEND_DISPATCH in raster/blend_px.h), so no per-pixel mode switch is
 * left and no per-pixel function call.
 */
#ifndef ISKRA_RASTER_DOT_KERNEL_H
#define ISKRA_RASTER_DOT_KERNEL_H

#include <stdint.h>
#include <string.h>

#include "core/cpu.h"
#include "iskra/canvas.h"
#include "raster/blend_px.h"
#if ISK__CPU_SSE2
#include "raster/dot_kernel_sse2.h"
#elif ISK__CPU_VECTOR
#include "raster/dot_kernel_vector.h"
#endif

/* Exact-area weights of the dot for fractional parts fx, fy in [0, 1).
 * a_k = 255*gx*gy, 255*fx*gy, 255*gx*fy, 255*fx*fy (left to right, no
 * contraction); w_k = floor(a_k); the 255 - sum(w) missing units go one
 * each to the largest a_k - w_k, ties to the lower index.  The selection
 * is written as ranks (how many weights come before k in that order, from
 * the six pairwise comparisons) so it has no branches: k gets a unit when
 * its rank is below the number missing.  The fractions are never NaN. */
static ISK__INLINE void isk__dot_weights_frac(double fx, double fy, uint32_t w[4])
{
    double gx = 1.0 - fx, gy = 1.0 - fy;
    double a0 = 255.0 * gx * gy, a1 = 255.0 * fx * gy, a2 = 255.0 * gx * fy, a3 = 255.0 * fx * fy;
    /* a_k in [0, 255]: truncation is floor */
    int i0 = (int)a0, i1 = (int)a1, i2 = (int)a2, i3 = (int)a3;
    double f0 = a0 - i0, f1 = a1 - i1, f2 = a2 - i2, f3 = a3 - i3;
    int left = 255 - (i0 + i1 + i2 + i3);
    /* c_jk = (f_j >= f_k) for j < k: j comes first; the rank of k counts
     * the j < k with c_jk and the j > k with f_j > f_k, i.e. !c_kj. */
    int c01 = f0 >= f1, c02 = f0 >= f2, c03 = f0 >= f3, c12 = f1 >= f2, c13 = f1 >= f3, c23 = f2 >= f3;
    int r0 = 3 - c01 - c02 - c03;
    int r1 = 2 + c01 - c12 - c13;
    int r2 = 1 + c02 + c12 - c23;
    int r3 = c03 + c13 + c23;
    w[0] = (uint32_t)(i0 + (r0 < left));
    w[1] = (uint32_t)(i1 + (r1 < left));
    w[2] = (uint32_t)(i2 + (r2 < left));
    w[3] = (uint32_t)(i3 + (r3 < left));
}

/* floor(v) for v in (-2^31, 2^31), exactly (so v - floor(v) is exact too)
 * and without a libm call. */
static ISK__INLINE int isk__ifloor(double v)
{
    int i = (int)v;
    return i - ((double)i > v);
}

/* One pixel at coverage w: from the batch's table when there is one
 * (lut is a constant NULL for single dots, so this folds away). */
static ISK__INLINE void isk__px_w(uint8_t *d, isk_color col, const isk__cov_lut *lut, uint32_t w, isk_blend mode)
{
    if (lut)
        isk__px_lut(d, lut, w, mode);
    else
        isk__px_cov(d, col, w, mode);
}

/* Blends the weights into the 2x2 block whose top-left pixel is (ix, iy),
 * skipping pixels outside the canvas. */
static ISK__INLINE void isk__blend_2x2(const isk_canvas *c, int ix, int iy, const uint32_t w[4], isk_color col,
                                       const isk__cov_lut *lut, isk_blend mode)
{
    const size_t stride = c->stride;
    if ((unsigned)ix < (unsigned)(c->width - 1) && (unsigned)iy < (unsigned)(c->height - 1)) {
        uint8_t *p = c->pixels + (size_t)iy * stride + (size_t)ix * 4u;
#if ISK__CPU_SSE2
        if (!lut && mode != ISK_BLEND_REPLACE) { /* the whole block in SSE2 registers */
            isk__blend_2x2_sse2(p, stride, w, col, mode);
            return;
        }
#elif ISK__CPU_VECTOR
        if (!lut && mode != ISK_BLEND_REPLACE) { /* the same in vector-extension lanes */
            isk__blend_2x2_vector(p, stride, w, col, mode);
            return;
        }
#endif
        isk__px_w(p, col, lut, w[0], mode);
        isk__px_w(p + 4, col, lut, w[1], mode);
        isk__px_w(p + stride, col, lut, w[2], mode);
        isk__px_w(p + stride + 4, col, lut, w[3], mode);
        return;
    }
    int left = ix >= 0 && ix < c->width, right = ix + 1 >= 0 && ix + 1 < c->width;
    int top = iy >= 0 && iy < c->height, bottom = iy + 1 >= 0 && iy + 1 < c->height;
    if (top) {
        uint8_t *p = c->pixels + (size_t)iy * stride;
        if (left) isk__px_w(p + (size_t)ix * 4u, col, lut, w[0], mode);
        if (right) isk__px_w(p + (size_t)(ix + 1) * 4u, col, lut, w[1], mode);
    }
    if (bottom) {
        uint8_t *p = c->pixels + (size_t)(iy + 1) * stride;
        if (left) isk__px_w(p + (size_t)ix * 4u, col, lut, w[2], mode);
        if (right) isk__px_w(p + (size_t)(ix + 1) * 4u, col, lut, w[3], mode);
    }
}

/* The 2x2 block cut to the rows [r0, r1) and the columns [c0, c1) of c
 * (ix, iy in canvas columns and rows): a tile of a threaded draw. */
static ISK__INLINE void isk__blend_2x2_tile(const isk_canvas *c, int r0, int r1, int c0, int c1, int ix, int iy,
                                            const uint32_t w[4], isk_color col, const isk__cov_lut *lut,
                                            isk_blend mode)
{
    const isk_canvas tile = {c->pixels + (size_t)r0 * c->stride + (size_t)c0 * 4u, c1 - c0, r1 - r0, c->stride, 0};
    isk__blend_2x2(&tile, ix - c0, iy - r0, w, col, lut, mode);
}

/* isk_draw_dot for a canvas known to have pixels, its blend cut to the
 * rows [r0, r1) and the columns [c0, c1) (the whole canvas: 0 and the
 * height, 0 and the width). */
static ISK__INLINE void isk__dot_tile(const isk_canvas *c, int r0, int r1, int c0, int c1, double x, double y,
                                      isk_color col, const isk__cov_lut *lut, isk_blend mode)
{
    /* The square [x, x+1) x [y, y+1) touches the tile only for x in
     * (c0 - 1, c1) and y in (r0 - 1, r1); the test also rejects NaN and
     * keeps the conversions below defined. */
    if (!(x > c0 - 1.0 && x < c1 && y > r0 - 1.0 && y < r1))
        return;
    int ix = isk__ifloor(x), iy = isk__ifloor(y);
    uint32_t w[4];
    isk__dot_weights_frac(x - ix, y - iy, w);
    isk__blend_2x2_tile(c, r0, r1, c0, c1, ix, iy, w, col, lut, mode);
}

/* isk__dot_tile over whole rows. */
static ISK__INLINE void isk__dot_rows(const isk_canvas *c, int r0, int r1, double x, double y, isk_color col,
                                      const isk__cov_lut *lut, isk_blend mode)
{
    isk__dot_tile(c, r0, r1, 0, c->width, x, y, col, lut, mode);
}

static ISK__INLINE void isk__dot(const isk_canvas *c, double x, double y, isk_color col, const isk__cov_lut *lut,
                                 isk_blend mode)
{
    isk__dot_rows(c, 0, c->height, x, y, col, lut, mode);
}

/* The browser's weights (see dot.c); 0 for non-finite or huge input. */
static ISK__INLINE int isk__dot_weights_browser(double x, double y, int *ix, int *iy, uint32_t w[4])
{
    /* |x| < 16400 keeps x * 65536 inside int (and rejects NaN). */
    if (!(x > -16400.0 && x < 16400.0 && y > -16400.0 && y < 16400.0)) {
        w[0] = w[1] = w[2] = w[3] = 0;
        return 0;
    }
    float xf = (float)x, yf = (float)y;
    int L = (((int)(xf * 65536.0f)) + 0x80) >> 8;
    int T = (((int)(yf * 65536.0f)) + 0x80) >> 8;
    int l = L & 255, t = T & 255;
    uint32_t c0 = l ? 256u - (uint32_t)l : 256u, c1 = (uint32_t)l;
    uint32_t r0 = t ? 256u - (uint32_t)t : 255u, r1 = (uint32_t)t;
    w[0] = c0 == 256u ? r0 : (r0 * c0) >> 8;
    w[1] = (r0 * c1) >> 8;
    w[2] = c0 == 256u ? r1 : (r1 * c0) >> 8;
    w[3] = (r1 * c1) >> 8;
    *ix = L >> 8; /* arithmetic shift: floor for negative values too */
    *iy = T >> 8;
    return 1;
}

/* isk_draw_dot_browser for a canvas known to have pixels, cut to the rows
 * [r0, r1) and the columns [c0, c1). */
static ISK__INLINE void isk__dot_browser_tile(const isk_canvas *c, int r0, int r1, int c0, int c1, double x,
                                              double y, isk_color col, const isk__cov_lut *lut, isk_blend mode)
{
    if (!(x > c0 - 2.0 && x < c1 + 1.0 && y > r0 - 2.0 && y < r1 + 1.0))
        return;
    int ix, iy;
    uint32_t w[4];
    if (isk__dot_weights_browser(x, y, &ix, &iy, w))
        isk__blend_2x2_tile(c, r0, r1, c0, c1, ix, iy, w, col, lut, mode);
}

/* isk__dot_browser_tile over whole rows. */
static ISK__INLINE void isk__dot_browser_rows(const isk_canvas *c, int r0, int r1, double x, double y,
                                              isk_color col, const isk__cov_lut *lut, isk_blend mode)
{
    isk__dot_browser_tile(c, r0, r1, 0, c->width, x, y, col, lut, mode);
}

static ISK__INLINE void isk__dot_browser(const isk_canvas *c, double x, double y, isk_color col,
                                         const isk__cov_lut *lut, isk_blend mode)
{
    isk__dot_browser_rows(c, 0, c->height, x, y, col, lut, mode);
}

#endif
