/* SPDX-License-Identifier: MIT */
/* src/raster/circle_loops.h — the anti-aliased disc's row walk with cached
 * integrals (internal): compiled by circle.c for every CPU, with the row
 * kernels of raster/span.h, and by circle_avx2.c for AVX2, with the
 * coverage of four pixels a step and span_avx2.h's kernels.
 *
 *     AA_ROWS_FN(aa_rows_small, static, ROW_SMALL, isk__span_cov, NULL)
 *
 * defines a function drawing the disc's rows [r0, r1) whose columns fit
 * CAP (ROW_SMALL or ROW_CACHE), blending each row with SPAN and, when ROW
 * is not NULL, computing its coverage with ROW instead of pixel by pixel
 * (row_cov_fn: the same doubles, lane by lane).  circle.c's
 * isk__fill_circle_aa_rows picks one. */
#ifndef ISKRA_RASTER_CIRCLE_LOOPS_H
#define ISKRA_RASTER_CIRCLE_LOOPS_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "core/cpu.h"
#include "iskra/draw.h"
#include "raster/blend_px.h"
#include "raster/clip.h"

/* asin(1): the double nearest pi/2, which is what asin(+-1) returns
 * (tests/test_raster_kernels.c pins it against this libm). */
#define ASIN_ONE 1.5707963267948966

/* Integral of h over [0, x], |x| <= r.  At x = +-r (every column edge a
 * small disc clamps) q is 0 and x / r is +-1: the same operations with
 * asin's value written in, so no libm call (a quarter of an r = 1 disc's
 * time went to them). */
static double h_integral(double x, double r)
{
    if (r > 0.0 && (x == r || x == -r))
        return 0.5 * (x * 0.0 + r * r * (x > 0.0 ? ASIN_ONE : -ASIN_ONE));
    double q = r * r - x * x;
    return 0.5 * (x * sqrt(q > 0.0 ? q : 0.0) + r * r * asin(x / r));
}

/* ---- the row walk with cached integrals ----------------------------------
 * The exact area of a pixel needs h_integral at its two (clamped) column
 * edges and, for its two row edges y, w(y) = sqrt(r^2 - y^2) and
 * h_integral(w): values that depend on the column alone or on the row
 * alone.  They are computed once per column and once per row (a pixel edge
 * shared by two neighbours, when its two computations give the same
 * double, once for both) instead of up to 16 times per pixel, and each
 * pixel's area is then min_antideriv's arithmetic on them in the same order,
 * so every double, hence every coverage byte, is the one the per-pixel walk
 * computes.  Coverage is collected per row and blended by the span kernel. */
#define ROW_CACHE 512    /* columns; wider discs take the per-pixel walk */
#define ROW_SMALL 32     /* columns of the small discs' scratch (below) */
#define PREFETCH_ROWS 16 /* rows requested ahead of the one being drawn */

typedef struct edge_y {
    double y, cl, w, hw; /* row edge, |y|, w(|y|) (0 beyond r), h_integral(w) */
    double cw;           /* cl * w */
} edge_y;

static void edge_y_make(edge_y *e, double y, double r)
{
    e->y = y;
    e->cl = fabs(y);
    e->w = e->cl < r ? sqrt((r - e->cl) * (r + e->cl)) : 0.0;
    /* h_integral(+0) is +0 (C's asin(+0) is +0): no libm call for the
     * edges beyond the disc */
    e->hw = e->w == 0.0 ? 0.0 : h_integral(e->w, r);
    e->cw = e->cl * e->w;
}

/* min_antideriv(x, cl, r) given h_integral(x) and the row edge's values;
 * the three cases are all computed and one selected (no branch to
 * mispredict; (-cl)*w is -(cl*w) exactly). */
static inline double min_antideriv_cached(double x, double hx, const edge_y *e)
{
    double t1 = e->cw + hx - e->hw, t2 = -e->cw + hx + e->hw, t3 = e->cl * x;
    double t = x < -e->w ? t2 : t3;
    return x > e->w ? t1 : t;
}

/* strip_integral(a, b, y, r) for clamped a, b */
static inline double strip_cached(double a, double ha, double b, double hb, const edge_y *e)
{
    double v = min_antideriv_cached(b, hb, e) - min_antideriv_cached(a, ha, e);
    return e->y < 0.0 ? -v : v;
}

/* Coverage of the pixel in column k of the row (edges e0, e1), or -1 when
 * it is wholly inside the disc.  fx2[k], nx2[k] are the column's squared
 * far and near distances (fx*fx, nx*nx of the per-pixel walk, computed once
 * per column), fy2, ny2 the row's. */
static ISK__INLINE int pixel_cov(int k, double r2, double fy2, double ny2, int shared, int j, const double *fx2,
                                 const double *nx2, const double *ca, const double *ha, const double *cb,
                                 const double *hb, const edge_y *e0, const edge_y *e1, double *sprev, int *srow)
{
    if (fx2[k] + fy2 <= r2)
        return -1;
    if (nx2[k] + ny2 >= r2)
        return 0;
    double s1 = strip_cached(ca[k], ha[k], cb[k], hb[k], e1);
    double s0 = shared && srow[k] == j - 1 ? sprev[k] : strip_cached(ca[k], ha[k], cb[k], hb[k], e0);
    sprev[k] = s1;
    srow[k] = j;
    return isk__coverage(s1 - s0);
}

/* The row kernel, a parameter so the walk is compiled once per SIMD level. */
typedef void (*span_cov_fn)(uint8_t *, const uint8_t *, int, isk_color, isk_blend);

/* Coverage of the row's pixels in columns kb .. kb+n-1 (rounded up to a
 * multiple of 4: the scratch has room), four a step: pixel_cov's
 * arithmetic lane by lane, its two tests as selects.  Every pixel of the
 * row is computed: the strips of full pixels are thrown away (the full
 * ones are a run, so pixel_cov's walk from both ends gives the same
 * bytes), and the bottom strip of the row above is computed again from e0
 * instead of being kept (the same double: e0 is that row's e1). */
typedef void (*row_cov_fn)(uint8_t *, int, int, const double *, const double *, const double *, const double *,
                           const double *, const double *, double, double, double, const edge_y *, const edge_y *);

/* The row walk's per-column scratch: cap columns of each array, carved
 * from one block the caller sizes (see AA_ROWS_FN). */
typedef struct aa_scratch {
    double *ca, *cb, *ha, *hb, *fx2, *nx2, *sprev; /* cap + 3 each */
    int *srow;
    uint8_t *cov; /* cap + 16 bytes: room for 16-byte stores past the row */
} aa_scratch;

static ISK__INLINE void fill_circle_aa_rows(isk_canvas *c, double cx, double cy, double r, isk_color color,
                                            int i0g, int i1g, int r0, int r1, const aa_scratch *sc, int cap,
                                            span_cov_fn span_cov, row_cov_fn row_cov, isk_blend mode)
{
    double r2 = r * r;
    int j0 = isk__floor_clamp(cy - r, -1, c->height);
    int j1 = isk__floor_clamp(cy + r, -1, c->height);
    if (j0 < r0) j0 = r0;
    if (j1 > r1 - 1) j1 = r1 - 1;
    /* The disc's rows are random accesses a stride apart: ask for the first
     * ones now, so the loads overlap the integrals computed below. */
#if defined(__GNUC__)
    for (int j = j0; j <= j1 && j < j0 + PREFETCH_ROWS; j++) {
        __builtin_prefetch(isk_canvas_at(c, i0g, j), 1);
        __builtin_prefetch(isk_canvas_at(c, i1g, j), 1);
    }
#endif
    /* per column: clamped edges and their integrals */
    const int ncol = i1g - i0g + 1;
    double *ca = sc->ca, *cb = sc->cb, *ha = sc->ha, *hb = sc->hb, *fx2 = sc->fx2, *nx2 = sc->nx2;
    for (int k = 0; k < ncol; k++) {
        double x0 = (i0g + k) - cx, x1 = x0 + 1.0;
        double ax0 = fabs(x0), ax1 = fabs(x1); /* fmin/fmax without NaN: no libm call */
        double nx = (x0 <= 0.0 && x1 >= 0.0) ? 0.0 : (ax0 < ax1 ? ax0 : ax1);
        double fx = ax0 > ax1 ? ax0 : ax1;
        fx2[k] = fx * fx;
        nx2[k] = nx * nx;
        ca[k] = isk__clampd(x0, -r, r);
        cb[k] = isk__clampd(x1, -r, r);
        ha[k] = k > 0 && ca[k] == cb[k - 1] ? hb[k - 1] : h_integral(ca[k], r);
        hb[k] = h_integral(cb[k], r);
    }
    if (row_cov) /* it reads up to 3 columns past the last: zeros */
        for (int k = ncol; k < ncol + 3; k++)
            ca[k] = cb[k] = ha[k] = hb[k] = fx2[k] = nx2[k] = 0.0;
    uint8_t *cov = sc->cov;
    /* a pixel's bottom strip is the top strip of the pixel below when the
     * two rows share their edge: kept per column with the row it came from */
    double *sprev = sc->sprev;
    int *srow = sc->srow;
    for (int k = 0; k < ncol; k++)
        srow[k] = -2;
    edge_y e0, e1;
    int have_e1 = 0, shared;
    for (int j = j0; j <= j1; j++) {
        double y0 = j - cy, y1 = y0 + 1.0;
        double ay0 = fabs(y0), ay1 = fabs(y1); /* fmin/fmax without NaN: no libm call */
        double ny = (y0 <= 0.0 && y1 >= 0.0) ? 0.0 : (ay0 < ay1 ? ay0 : ay1);
        double fy = ay0 > ay1 ? ay0 : ay1;
        if (!(ny < r))
            continue;
        /* the previous row's bottom edge is this row's top when equal */
        shared = have_e1 && e1.y == y0;
        if (shared)
            e0 = e1;
        else
            edge_y_make(&e0, y0, r);
        edge_y_make(&e1, y1, r);
        have_e1 = 1;
        double hw = sqrt((r - ny) * (r + ny));
        int i0 = isk__floor_clamp(cx - hw, -1, c->width);
        int i1 = isk__floor_clamp(cx + hw, -1, c->width);
        if (i0 < 0) i0 = 0;
        if (i1 > c->width - 1) i1 = c->width - 1;
        if (i0 > i1)
            continue;
#if defined(__GNUC__)
        if (j + PREFETCH_ROWS <= j1) {
            __builtin_prefetch(isk_canvas_at(c, i0g, j + PREFETCH_ROWS), 1);
            __builtin_prefetch(isk_canvas_at(c, i1g, j + PREFETCH_ROWS), 1);
        }
#endif
        /* fx grows away from the centre on both sides (max of a falling
         * and a rising function), so the full pixels of a row are one run:
         * the edge pixels are classified from each end inward until a full
         * one, and the run between is set at once. */
        const double fy2 = fy * fy, ny2 = ny * ny;
        int i = i0;
        if (row_cov) {
            row_cov(cov, i0 - i0g, i1 - i0 + 1, ca, ha, cb, hb, fx2, nx2, r2, fy2, ny2, &e0, &e1);
            i = i1 + 1;
        }
        for (; i <= i1; i++) {
            int v = pixel_cov(i - i0g, r2, fy2, ny2, shared, j, fx2, nx2, ca, ha, cb, hb, &e0, &e1, sprev, srow);
            if (v < 0)
                break;
            cov[i - i0] = (uint8_t)v;
        }
        if (i <= i1) {
            /* isk__coverage(1.0) = 255 from the first full pixel on, 16
             * bytes a store (the buffer has room past the row; a memset
             * call costs more for these short runs), then the right end's
             * edge pixels over it */
            static const uint8_t full16[16] = {255, 255, 255, 255, 255, 255, 255, 255,
                                               255, 255, 255, 255, 255, 255, 255, 255};
            for (int k = i - i0; k <= i1 - i0; k += 16)
                memcpy(cov + k, full16, 16);
            for (int b = i1; b > i; b--) {
                int v = pixel_cov(b - i0g, r2, fy2, ny2, shared, j, fx2, nx2, ca, ha, cb, hb, &e0, &e1, sprev, srow);
                if (v < 0)
                    break;
                cov[b - i0] = (uint8_t)v;
            }
        }
        /* Padded to whole 4-pixel steps of the span kernel with coverage 0
         * (no change in any mode) where the canvas row allows. */
        int n = i1 - i0 + 1, n4 = (n + 3) & ~3, start = i0;
        if (i0 + n4 <= c->width) {
            cov[n] = cov[n + 1] = cov[n + 2] = 0; /* up to 3 bytes of padding (room is there) */
            n = n4;
        } else if (i1 + 1 - n4 >= 0 && n4 <= cap) {
            int pad = n4 - n; /* 1..3: the row moves right, zeros before it */
            memmove(cov + pad, cov, (size_t)n);
            cov[0] = 0;
            if (pad > 1) cov[1] = 0;
            if (pad > 2) cov[2] = 0;
            start = i1 + 1 - n4;
            n = n4;
        }
        span_cov(isk_canvas_at(c, start, j), cov, n, color, mode);
    }
}

/* One function per scratch size, each with the three modes inlined.  A
 * small disc's scratch is a few hundred contiguous bytes: with the big
 * one's arrays 4 KiB apart, their first elements (all a small disc uses)
 * would share one L1 set, and its frame would span 36 KiB of stack. */
#define AA_ROWS_FN(NAME, ATTR, CAP, SPAN, ROW)                                                             \
    ATTR void NAME(isk_canvas *c, double cx, double cy, double r, isk_color color, int i0g, int i1g, \
                          int r0, int r1, isk_blend mode)                                                  \
    {                                                                                                      \
        double d[7][CAP + 3];                                                                              \
        int srow[CAP];                                                                                     \
        uint8_t cov[CAP + 16];                                                                             \
        const aa_scratch sc = {d[0], d[1], d[2], d[3], d[4], d[5], d[6], srow, cov};                       \
        ISK__BLEND_DISPATCH(mode, fill_circle_aa_rows, c, cx, cy, r, color, i0g, i1g, r0, r1, &sc, CAP, SPAN, \
                            ROW);                                                                          \
    }

#if ISK__CPU_AVX2
/* The small discs' walk for AVX2 (circle_avx2.c), for a CPU that has it. */
void isk__circle_aa_rows_small_avx2(isk_canvas *c, double cx, double cy, double r, isk_color color, int i0g, int i1g,
                                    int r0, int r1, isk_blend mode);
#endif

#endif
