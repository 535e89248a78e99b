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

void isk__draw_batch_rows(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                          isk_color col, isk_blend mode, isk__batch_rule rule, int r0, int r1);

#endif
