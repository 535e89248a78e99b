/* src/view/world_batch.h — the batched store drawing of iskra/view.h,
 * restricted to a band of canvas rows (internal).
 *
 *     isk__draw_batch_rows(c, v, n, x, y, col, mode, ISK__BATCH_DOT, r0, r1);
 *
 * draws exactly the pixels of rows [r0, r1) that the whole batch would
 * draw, with the same bytes: every point is placed on the whole canvas and
 * only the blend is cut to the band.  Bands that cover the canvas, drawn
 * in any order or at the same time, therefore give the bytes of one call
 * (each pixel sees the same points in the same order): the renderer's
 * threads each take a band.  r0 and r1 are clamped to the canvas. */
#ifndef ISKRA_VIEW_WORLD_BATCH_H
#define ISKRA_VIEW_WORLD_BATCH_H

#include "iskra/view.h"

typedef enum isk__batch_rule {
    ISK__BATCH_DOT,         /* isk_draw_dots */
    ISK__BATCH_DOT_BROWSER, /* isk_draw_dots_browser */
    ISK__BATCH_PIXEL        /* isk_draw_pixels */
} isk__batch_rule;

/* Or-ed into the rule: a screen coordinate in (n - 1, n] (n the canvas's
 * width or height) is moved to n - 1 first, so a particle exactly on the
 * right or bottom edge is drawn in the last column or row instead of just
 * outside (isk__keep_on_canvas; the effects' particles use it). */
#define ISK__BATCH_KEEP_ON_CANVAS 0x100u

/* What ISK__BATCH_KEEP_ON_CANVAS does to one coordinate. */
static inline double isk__keep_on_canvas(double v, int n)
{
    return v > n - 1.0 && v <= (double)n ? n - 1.0 : v;
}

void isk__draw_batch_rows(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                          isk_color col, isk_blend mode, unsigned rule, int r0, int r1);

#endif
