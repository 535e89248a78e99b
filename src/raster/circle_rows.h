/* SPDX-License-Identifier: MIT */
/* src/raster/circle_rows.h — an anti-aliased disc (isk_fill_circle_aa,
 * iskra/draw.h) drawn on a band of canvas rows (internal; the renderer's
 * threads each take a band).
 *
 *     isk__fill_circle_aa_rows(c, cx, cy, r, color, mode, r0, r1);
 *
 * draws exactly the pixels of rows [r0, r1) that the whole call would, with
 * the same bytes: a pixel's coverage is the exact area of the disc in its
 * square, the same doubles whichever row the walk starts from (the row
 * walk shares an edge's integrals between two rows only when the two
 * computations would give the same double), so bands covering the canvas,
 * in any order, give the bytes of one call.  r0 and r1 are clamped to the
 * canvas. */
#ifndef ISKRA_RASTER_CIRCLE_ROWS_H
#define ISKRA_RASTER_CIRCLE_ROWS_H

#include "iskra/draw.h"

void isk__fill_circle_aa_rows(isk_canvas *c, double cx, double cy, double r, isk_color color, isk_blend mode, int r0,
                              int r1);

#endif
