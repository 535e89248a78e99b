/* SPDX-License-Identifier: MIT */
/* Filled circles: aliased (pixel centres strictly inside) and anti-aliased
 * (exact area of disc ∩ pixel square, computed analytically).
 *
 * Analytic area: with the centre at the origin and h(x) = sqrt(r^2 - x^2),
 *   area(disc ∩ [x0,x1]x[y0,y1]) = I(y1) - I(y0),
 *   I(y) = sign(y) * integral over [x0,x1] of min(|y|, h(x)) dx,
 * and min(c, h) integrates in closed form with H(x) = (x h(x) + r^2 asin(x/r))/2.
 * Only pixels the circle's edge crosses use it; whole pixels are 0 or 255.
 * The formula subtracts values of size r^2, so above r = 2^16 (where it would
 * lose digits) the edge is treated as its tangent line at the point nearest
 * the pixel: the arc deviates from that line by < 1e-5 px across a pixel.
 */
#include "iskra/draw.h"

#include <string.h>

#include "raster/circle_rows.h"
#include "raster/clip.h"
#include "raster/span_simd.h"

#define BIG_R_ALIASED 67108864.0 /* 2^26: d^2 and r^2 stay exact enough below */
#define BIG_R_AA 65536.0         /* 2^16, see above */

static int disc_misses_rect(double cx, double cy, double r, double x0, double y0,
                            double x1, double y1)
{
    double dx = cx < x0 ? x0 - cx : (cx > x1 ? cx - x1 : 0.0);
    double dy = cy < y0 ? y0 - cy : (cy > y1 ? cy - y1 : 0.0);
    return dx >= r || dy >= r;
}

void isk_fill_circle(isk_canvas *c, double cx, double cy, double r, isk_color color, isk_blend mode)
{
    if (!isk__canvas_ok(c) || !isk__finite2(cx, cy) || !isfinite(r) || !(r > 0.0))
        return;
    /* No pixel centre can be strictly inside: nothing to do.  This also
     * bounds |cx|, |cy| by r + canvas size for the arithmetic below. */
    if (disc_misses_rect(cx, cy, r, 0.5, 0.5, c->width - 0.5, c->height - 0.5))
        return;
    int big = r > BIG_R_ALIASED;
    double r2 = r * r;
    int j0 = isk__floor_clamp(cy - r - 0.5, -1, c->height);
    int j1 = isk__floor_clamp(cy + r - 0.5, -1, c->height) + 1;
    if (j0 < 0) j0 = 0;
    if (j1 > c->height - 1) j1 = c->height - 1;
    for (int j = j0; j <= j1; j++) {
        double dy = (j + 0.5) - cy;
        double ady = fabs(dy);
        if (!(ady < r))
            continue;
        double hw = big ? sqrt((r - ady) * (r + ady)) : sqrt(r2 - dy * dy);
        int i0 = isk__floor_clamp(cx - hw - 0.5, -2, c->width) - 1;
        int i1 = isk__floor_clamp(cx + hw - 0.5, -2, c->width) + 1;
        if (i0 < 0) i0 = 0;
        if (i1 > c->width - 1) i1 = c->width - 1;
        for (int i = i0; i <= i1; i++) {
            double dx = (i + 0.5) - cx;
            int in = big ? hypot(dx, dy) < r : dx * dx + dy * dy < r2;
            if (in)
                isk_blend_pixel(isk_canvas_at(c, i, j), color, mode);
        }
    }
}

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

/* Antiderivative of min(cl, h(x)) (cl >= 0), for x in [-r, r]. */
static double min_antideriv(double x, double cl, double r)
{
    double w = cl < r ? sqrt((r - cl) * (r + cl)) : 0.0;
    if (x > w)
        return cl * w + h_integral(x, r) - h_integral(w, r);
    if (x < -w)
        return -cl * w + h_integral(x, r) + h_integral(w, r);
    return cl * x;
}

static double strip_integral(double a, double b, double y, double r)
{
    a = isk__clampd(a, -r, r);
    b = isk__clampd(b, -r, r);
    double cl = fabs(y);
    double v = min_antideriv(b, cl, r) - min_antideriv(a, cl, r);
    return y < 0.0 ? -v : v;
}

/* Exact area of the disc of radius r at the origin ∩ [x0,x1]x[y0,y1]. */
static double disc_rect_area(double x0, double x1, double y0, double y1, double r)
{
    return strip_integral(x0, x1, y1, r) - strip_integral(x0, x1, y0, r);
}

/* Area of the unit pixel with top-left (x0, y0) (relative to the centre) on
 * the inner side of the tangent at the point of the circle nearest to it. */
static double tangent_area(double x0, double y0, double r)
{
    double pcx = x0 + 0.5, pcy = y0 + 0.5;
    double d = hypot(pcx, pcy);
    if (!(d > 0.0))
        return 1.0;
    double nx = pcx / d, ny = pcy / d;
    double off = (r - d) + 0.5 * (nx + ny);
    isk__poly sq, out;
    isk__poly_pixel(&sq, 0.0, 0.0);
    isk__poly_clip_halfplane(&sq, &out, nx, ny, off);
    return out.n >= 3 ? 0.5 * isk__poly_area2(&out) : 0.0;
}

/* The tangent rule for big discs and the plain per-pixel walk for discs
 * wider than the row caches below (the original per-pixel code). */
static void fill_circle_aa_pixels(isk_canvas *c, double cx, double cy, double r, isk_color color, isk_blend mode,
                                  int r0, int r1)
{
    int big = r > BIG_R_AA;
    double r2 = r * r;
    int j0 = isk__floor_clamp(cy - r, -1, c->height);
    int j1 = isk__floor_clamp(cy + r, -1, c->height);
    if (j0 < r0) j0 = r0;
    if (j1 > r1 - 1) j1 = r1 - 1;
    for (int j = j0; j <= j1; j++) {
        double y0 = j - cy, y1 = y0 + 1.0;
        double ny = (y0 <= 0.0 && y1 >= 0.0) ? 0.0 : fmin(fabs(y0), fabs(y1));
        double fy = fmax(fabs(y0), fabs(y1));
        if (!(ny < r))
            continue;
        double hw = sqrt((r - ny) * (r + ny));
        int i0 = isk__floor_clamp(cx - hw, -1, c->width);
        int i1 = isk__floor_clamp(cx + hw, -1, c->width);
        if (i0 < 0) i0 = 0;
        if (i1 > c->width - 1) i1 = c->width - 1;
        for (int i = i0; i <= i1; i++) {
            double x0 = i - cx, x1 = x0 + 1.0;
            double nx = (x0 <= 0.0 && x1 >= 0.0) ? 0.0 : fmin(fabs(x0), fabs(x1));
            double fx = fmax(fabs(x0), fabs(x1));
            double area;
            if (!big) {
                if (fx * fx + fy * fy <= r2)
                    area = 1.0;
                else if (nx * nx + ny * ny >= r2)
                    continue;
                else
                    area = disc_rect_area(x0, x1, y0, y1, r);
            } else {
                if (hypot(fx, fy) <= r)
                    area = 1.0;
                else if (hypot(nx, ny) >= r)
                    continue;
                else
                    area = tangent_area(x0, y0, r);
            }
            isk_blend_pixel_cov(isk_canvas_at(c, i, j), color, isk__coverage(area), mode);
        }
    }
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

#if ISK__SPAN_AVX2
/* min_antideriv_cached on four lanes */
static ISK__INLINE ISK__AVX2_FN __m256d mac4(__m256d x, __m256d hx, const edge_y *e)
{
    const __m256d cw = _mm256_set1_pd(e->cw), hw = _mm256_set1_pd(e->hw), w = _mm256_set1_pd(e->w);
    __m256d t1 = _mm256_sub_pd(_mm256_add_pd(cw, hx), hw);
    __m256d t2 = _mm256_add_pd(_mm256_add_pd(_mm256_set1_pd(-e->cw), hx), hw);
    __m256d t3 = _mm256_mul_pd(_mm256_set1_pd(e->cl), x);
    __m256d t = _mm256_blendv_pd(t3, t2, _mm256_cmp_pd(x, _mm256_set1_pd(-e->w), _CMP_LT_OQ));
    return _mm256_blendv_pd(t, t1, _mm256_cmp_pd(x, w, _CMP_GT_OQ));
}

/* strip_cached on four lanes */
static ISK__INLINE ISK__AVX2_FN __m256d strip4(__m256d a, __m256d ha, __m256d b, __m256d hb, const edge_y *e)
{
    __m256d v = _mm256_sub_pd(mac4(b, hb, e), mac4(a, ha, e));
    return e->y < 0.0 ? _mm256_xor_pd(v, _mm256_set1_pd(-0.0)) : v;
}

static ISK__INLINE ISK__AVX2_FN void row_cov_avx2(uint8_t *cov, int kb, int n, const double *ca, const double *ha,
                                                  const double *cb, const double *hb, const double *fx2,
                                                  const double *nx2, double r2, double fy2, double ny2,
                                                  const edge_y *e0, const edge_y *e1)
{
    const __m256d R2 = _mm256_set1_pd(r2), FY2 = _mm256_set1_pd(fy2), NY2 = _mm256_set1_pd(ny2);
    const __m256d one = _mm256_set1_pd(1.0), k255 = _mm256_set1_pd(255.0), half = _mm256_set1_pd(0.5);
    for (int i = 0; i < n; i += 4) {
        const int k = kb + i;
        /* four pixels wholly inside (the middle of a wide row): 255 each,
         * what the selects below give them, without the strips */
        const __m256d full = _mm256_cmp_pd(_mm256_add_pd(_mm256_loadu_pd(fx2 + k), FY2), R2, _CMP_LE_OQ);
        if (_mm256_movemask_pd(full) == 15) {
            memset(cov + i, 255, 4);
            continue;
        }
        __m256d a = _mm256_loadu_pd(ca + k), b = _mm256_loadu_pd(cb + k);
        __m256d hav = _mm256_loadu_pd(ha + k), hbv = _mm256_loadu_pd(hb + k);
        __m256d area = _mm256_sub_pd(strip4(a, hav, b, hbv, e1), strip4(a, hav, b, hbv, e0));
        /* isk__coverage: floor(255 area + 0.5), below 1 -> 0, from 255 on -> 255 */
        __m256d v = _mm256_add_pd(_mm256_mul_pd(k255, area), half);
        v = _mm256_and_pd(v, _mm256_cmp_pd(v, one, _CMP_GE_OQ));
        v = _mm256_blendv_pd(v, k255, _mm256_cmp_pd(v, k255, _CMP_GE_OQ));
        /* outside the disc: 0; wholly inside: 255 (tested in that order last) */
        v = _mm256_andnot_pd(_mm256_cmp_pd(_mm256_add_pd(_mm256_loadu_pd(nx2 + k), NY2), R2, _CMP_GE_OQ), v);
        v = _mm256_blendv_pd(v, k255, full);
        __m128i q = _mm256_cvttpd_epi32(v);
        q = _mm_packus_epi16(_mm_packs_epi32(q, q), q);
        int32_t w4 = _mm_cvtsi128_si32(q);
        memcpy(cov + i, &w4, 4);
    }
}
#endif

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
    static ATTR void NAME(isk_canvas *c, double cx, double cy, double r, isk_color color, int i0g, int i1g, \
                          int r0, int r1, isk_blend mode)                                                  \
    {                                                                                                      \
        double d[7][CAP + 3];                                                                              \
        int srow[CAP];                                                                                     \
        uint8_t cov[CAP + 16];                                                                             \
        const aa_scratch sc = {d[0], d[1], d[2], d[3], d[4], d[5], d[6], srow, cov};                       \
        ISK__BLEND_DISPATCH(mode, fill_circle_aa_rows, c, cx, cy, r, color, i0g, i1g, r0, r1, &sc, CAP, SPAN, \
                            ROW);                                                                          \
    }
AA_ROWS_FN(aa_rows_small, , ROW_SMALL, isk__span_cov, NULL)
AA_ROWS_FN(aa_rows_big, , ROW_CACHE, isk__span_cov, NULL)
#if ISK__SPAN_AVX2
/* small discs where the CPU has AVX2: coverage 4 pixels a step
 * (row_cov_avx2), blending 8 (the same bytes: integer blending; the
 * doubles are the same IEEE operations lane by lane, no FMA) */
AA_ROWS_FN(aa_rows_small_avx2, ISK__AVX2_FN, ROW_SMALL, isk__span_cov_avx2, row_cov_avx2)
#endif

void isk__fill_circle_aa_rows(isk_canvas *c, double cx, double cy, double r, isk_color color, isk_blend mode, int r0,
                              int r1)
{
    if (!isk__canvas_ok(c) || !isk__finite2(cx, cy) || !isfinite(r) || !(r > 0.0))
        return;
    r0 = r0 < 0 ? 0 : r0;
    r1 = r1 > c->height ? c->height : r1;
    if (r0 >= r1 || disc_misses_rect(cx, cy, r, 0.0, r0, c->width, r1))
        return;
    /* every row's columns lie in the disc's column range */
    int i0g = isk__floor_clamp(cx - r, -1, c->width), i1g = isk__floor_clamp(cx + r, -1, c->width);
    if (i0g < 0) i0g = 0;
    if (i1g > c->width - 1) i1g = c->width - 1;
    if (r > BIG_R_AA || i1g - i0g + 1 > ROW_CACHE) {
        fill_circle_aa_pixels(c, cx, cy, r, color, mode, r0, r1);
        return;
    }
    if (i1g - i0g + 1 <= ROW_SMALL) {
#if ISK__SPAN_AVX2
        if (isk__have_avx2()) {
            aa_rows_small_avx2(c, cx, cy, r, color, i0g, i1g, r0, r1, mode);
            return;
        }
#endif
        aa_rows_small(c, cx, cy, r, color, i0g, i1g, r0, r1, mode);
        return;
    }
    aa_rows_big(c, cx, cy, r, color, i0g, i1g, r0, r1, mode);
}

void isk_fill_circle_aa(isk_canvas *c, double cx, double cy, double r, isk_color color, isk_blend mode)
{
    isk__fill_circle_aa_rows(c, cx, cy, r, color, mode, 0, c ? c->height : 0);
}
