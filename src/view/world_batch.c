/* Batched drawing of a particle store through a view (isk_draw_dots,
 * isk_draw_dots_browser, isk_draw_pixels in iskra/view.h).
 *
 * One loop per (view kind, dot rule, blend mode), chosen once per batch:
 * the transform is isk_view_to_screen's arithmetic inlined (same operations,
 * same order, so the same doubles), the dot is raster/dot_kernel.h's, the
 * blend raster/blend_px.h's with the mode a constant.  The result is
 * byte-identical to calling the single-dot functions in index order. */
#include "iskra/view.h"

#include <stddef.h>

#include "raster/blend_px.h"
#include "raster/dot_kernel.h"

typedef enum batch_rule { RULE_DOT, RULE_DOT_BROWSER, RULE_PIXEL } batch_rule;

/* How many points ahead the pixels are prefetched: a dot's 2x2 block is a
 * random access into the canvas, so the loads are started early enough to
 * overlap (the hardware cannot guess the address). */
#define PREFETCH_AHEAD 8

static ISK__INLINE void run_batch(const isk_canvas *c, const isk_view *v, size_t n, const double *x,
                                  const double *y, isk_color col, const isk__cov_lut *lut, int camera,
                                  batch_rule rule, isk_blend mode)
{
    /* isk_view_to_screen: camera  X = w/2 + a*(x + tx),  Y = h/2 - a*(y + ty);
     *                     window  X = sx*x + px,          Y = sy*y + py. */
    const double hw = v->width / 2.0, hh = v->height / 2.0, a = v->a, tx = v->tx, ty = v->ty;
    const double sx = v->sx, sy = v->sy, px = v->px, py = v->py;
    const double W = c->width, H = c->height;
    for (size_t i = 0; i < n; i++) {
        double X, Y;
#if defined(__GNUC__)
        if (i + PREFETCH_AHEAD < n) {
            size_t k = i + PREFETCH_AHEAD;
            double PX = camera ? hw + a * (x[k] + tx) : sx * x[k] + px;
            double PY = camera ? hh - a * (y[k] + ty) : sy * y[k] + py;
            if (PX >= 0.0 && PX < W && PY >= 0.0 && PY < H) {
                const uint8_t *q = isk_canvas_at(c, (int)PX, (int)PY);
                __builtin_prefetch(q, 1);
                if (rule != RULE_PIXEL)
                    __builtin_prefetch(q + c->stride, 1);
            }
        }
#endif
        if (camera) {
            X = hw + a * (x[i] + tx);
            Y = hh - a * (y[i] + ty);
        } else {
            X = sx * x[i] + px;
            Y = sy * y[i] + py;
        }
        switch (rule) {
        case RULE_DOT:
            isk__dot(c, X, Y, col, lut, mode);
            break;
        case RULE_DOT_BROWSER:
            isk__dot_browser(c, X, Y, col, lut, mode);
            break;
        case RULE_PIXEL:
            if (X >= 0 && Y >= 0 && X < W && Y < H)
                isk__px(isk_canvas_at(c, (int)X, (int)Y), col, mode);
            break;
        }
    }
}

/* The exact-area dot over a batch, in blocks: a first pass computes, for
 * each point of the block, its pixel offset and four weights (pure
 * arithmetic, independent from point to point, so the processor overlaps
 * it freely) and prefetches the two pixel rows; a second pass blends in
 * index order.  A point whose 2x2 block is not wholly inside the canvas is
 * left to the single-dot kernel (clipping), in its turn. */
#define BLOCK 32

static ISK__INLINE void run_dots_blocked(const isk_canvas *c, const isk_view *v, size_t n, const double *x,
                                         const double *y, isk_color col, const isk__cov_lut *lut, int camera,
                                         isk_blend mode)
{
    const double hw = v->width / 2.0, hh = v->height / 2.0, a = v->a, tx = v->tx, ty = v->ty;
    const double sx = v->sx, sy = v->sy, px = v->px, py = v->py;
    const double W1 = c->width - 1.0, H1 = c->height - 1.0;
    const size_t stride = c->stride;
    uint8_t *const pixels = c->pixels;
    size_t off[BLOCK];
    uint32_t wt[BLOCK][4];
    double bx[BLOCK], by[BLOCK];
    unsigned char fast[BLOCK];
    for (size_t i0 = 0; i0 < n; i0 += BLOCK) {
        const size_t m = n - i0 < BLOCK ? n - i0 : BLOCK;
        for (size_t k = 0; k < m; k++) {
            double X, Y;
            if (camera) {
                X = hw + a * (x[i0 + k] + tx);
                Y = hh - a * (y[i0 + k] + ty);
            } else {
                X = sx * x[i0 + k] + px;
                Y = sy * y[i0 + k] + py;
            }
            bx[k] = X;
            by[k] = Y;
            /* the whole 2x2 block on the canvas: floor(X) in [0, width-2] */
            fast[k] = X >= 0.0 && X < W1 && Y >= 0.0 && Y < H1;
            if (!fast[k])
                continue;
            int ix = (int)X, iy = (int)Y; /* >= 0: truncation is floor */
            isk__dot_weights_frac(X - ix, Y - iy, wt[k]);
            off[k] = (size_t)iy * stride + (size_t)ix * 4u;
#if defined(__GNUC__)
            __builtin_prefetch(pixels + off[k], 1);
            __builtin_prefetch(pixels + off[k] + stride, 1);
#endif
        }
        for (size_t k = 0; k < m; k++) {
            if (fast[k]) {
                uint8_t *p = pixels + off[k];
                isk__px_w(p, col, lut, wt[k][0], mode);
                isk__px_w(p + 4, col, lut, wt[k][1], mode);
                isk__px_w(p + stride, col, lut, wt[k][2], mode);
                isk__px_w(p + stride + 4, col, lut, wt[k][3], mode);
            } else {
                isk__dot(c, bx[k], by[k], col, lut, mode);
            }
        }
    }
}

static ISK__INLINE void run_kind(const isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                                 isk_color col, const isk__cov_lut *lut, batch_rule rule, isk_blend mode)
{
    if (rule == RULE_DOT && v->kind == ISK_VIEW_CAMERA)
        run_dots_blocked(c, v, n, x, y, col, lut, 1, mode);
    else if (rule == RULE_DOT)
        run_dots_blocked(c, v, n, x, y, col, lut, 0, mode);
    else if (v->kind == ISK_VIEW_CAMERA)
        run_batch(c, v, n, x, y, col, lut, 1, rule, mode);
    else
        run_batch(c, v, n, x, y, col, lut, 0, rule, mode);
}

/* Batches this short skip the 256-entry table: building it would cost
 * more than it saves. */
#define LUT_MIN_BATCH 64

static ISK__INLINE void run_rule(const isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                                 isk_color col, batch_rule rule, isk_blend mode)
{
    isk__cov_lut lut;
    switch (rule) {
    case RULE_DOT:
    case RULE_DOT_BROWSER:
        if (n >= LUT_MIN_BATCH) {
            isk__cov_lut_init(&lut, col);
            if (rule == RULE_DOT)
                run_kind(c, v, n, x, y, col, &lut, RULE_DOT, mode);
            else
                run_kind(c, v, n, x, y, col, &lut, RULE_DOT_BROWSER, mode);
        } else if (rule == RULE_DOT) {
            run_kind(c, v, n, x, y, col, NULL, RULE_DOT, mode);
        } else {
            run_kind(c, v, n, x, y, col, NULL, RULE_DOT_BROWSER, mode);
        }
        break;
    case RULE_PIXEL:
        run_kind(c, v, n, x, y, col, NULL, RULE_PIXEL, mode);
        break;
    }
}

static void draw_batch(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                       isk_color col, isk_blend mode, batch_rule rule)
{
    if (!c || !c->pixels || !v || !x || !y || n == 0)
        return;
    ISK__BLEND_DISPATCH(mode, run_rule, c, v, n, x, y, col, rule);
}

void isk_draw_dots(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                   isk_color color, isk_blend mode)
{
    draw_batch(c, v, n, x, y, color, mode, RULE_DOT);
}

void isk_draw_dots_browser(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                           isk_color color, isk_blend mode)
{
    draw_batch(c, v, n, x, y, color, mode, RULE_DOT_BROWSER);
}

void isk_draw_pixels(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                     isk_color color, isk_blend mode)
{
    draw_batch(c, v, n, x, y, color, mode, RULE_PIXEL);
}
