/* SPDX-License-Identifier: MIT */
/* src/raster/trail_rows.h — a trail (isk_stroke_trail, iskra/draw.h) drawn
 * on a band of canvas rows (internal; the renderer's threads each take a
 * band).
 *
 *     isk__stroke_trail_rows(c, xy, n, width, color, fade, mode, r0, r1);
 *
 * draws exactly the pixels of rows [r0, r1) that the whole call would, with
 * the same bytes: every pixel's nearest segment, coverage and fade are
 * functions of the pixel and the whole trail only, so bands covering the
 * canvas, in any order, give the bytes of one call.  r0 and r1 are clamped
 * to the canvas.
 *
 * The coverage rule's area, for tests:
 *   isk__trail_band_area(d, nx, ny, w)   the part of the unit pixel square
 *       whose centre lies d from a straight band's centre line, in the
 *       direction of the unit normal (nx, ny), inside the band of width w;
 *   isk__trail_pixel_area(dx, dy, hw, ex, ey, len)   the area a pixel gets
 *       whose centre is (dx, dy) from its nearest point on the trail, the
 *       nearest segment being (ex, ey) long len (the band across (dx, dy),
 *       or across the segment when the offset is 0), for half width hw. */
#ifndef ISKRA_RASTER_TRAIL_ROWS_H
#define ISKRA_RASTER_TRAIL_ROWS_H

#include "iskra/draw.h"

void isk__stroke_trail_rows(isk_canvas *c, const double *xy, int n, double width, isk_color color, double fade,
                            isk_blend mode, int r0, int r1);

double isk__trail_band_area(double d, double nx, double ny, double w);
double isk__trail_pixel_area(double dx, double dy, double hw, double ex, double ey, double len);

#endif
