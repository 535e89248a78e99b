/* iskra/draw.h — the software rasterizer's primitives, in pixel coordinates.
 *
 * Pixel (i, j) is the unit square [i, i+1) x [j, j+1); its centre is
 * (i+0.5, j+0.5).  x grows right, y grows down.  Every primitive takes a
 * colour and a blend mode (iskra/blend.h) and clips to the canvas.
 *
 * Any coordinate is accepted: huge values (±1e300), ±Inf and NaN are clipped
 * or ignored, never undefined behaviour.  A primitive whose geometry contains
 * a NaN draws nothing.  Nothing here allocates or fails, so nothing returns a
 * status: bad geometry simply draws nothing.
 *
 *     isk_fill_circle(&c, 300, 300, 40, ISK_YELLOW, ISK_BLEND_OVER);
 *     isk_stroke_line(&c, 175, 300, 325, 300, ISK_BLACK, ISK_BLEND_OVER);
 *     isk_draw_dot(&c, 180.4, 420.7, ISK_YELLOW, ISK_BLEND_OVER);
 *
 * Aliased (1-pixel) primitives:
 *   isk_draw_pixel, isk_fill_rect    integer pixel coordinates
 *   isk_draw_line                    Bresenham between the pixels containing
 *                                    the two end points (both ends drawn)
 *   isk_draw_triangle                three isk_draw_line edges
 *   isk_fill_triangle                pixels whose centre is inside; centres
 *                                    exactly on an edge follow the top-left rule
 *                                    (shared edges are drawn once)
 *   isk_fill_circle                  pixels whose centre is strictly inside:
 *                                    (i+0.5-cx)^2 + (j+0.5-cy)^2 < r^2
 * Anti-aliased primitives (coverage = exact area, or 16x16 supersampling
 * where stated, then blended with alpha scaled by coverage):
 *   isk_draw_dot           a 1x1 square whose top-left corner is (x, y),
 *                          spread over up to 2x2 pixels by exact area: how the
 *                          thesis's browser drew every particle (fillRect)
 *   isk_stroke_line        a width-1 line like HTML canvas stroke(): the
 *                          rectangle of half-width 0.5 around the segment,
 *                          butt caps, coverage by exact area
 *   isk_stroke_polyline    a width-1 path with miter joins (limit 10, as
 *                          canvas) and butt caps, drawn as one shape so joins
 *                          are not painted twice
 *   isk_fill_circle_aa     a disc, coverage by exact area
 */
#ifndef ISKRA_DRAW_H
#define ISKRA_DRAW_H

#include "iskra/blend.h"
#include "iskra/canvas.h"

void isk_draw_pixel(isk_canvas *c, int x, int y, isk_color color, isk_blend mode);
void isk_fill_rect(isk_canvas *c, int x, int y, int w, int h, isk_color color, isk_blend mode);

void isk_draw_line(isk_canvas *c, double x0, double y0, double x1, double y1,
                   isk_color color, isk_blend mode);
void isk_draw_triangle(isk_canvas *c, double x0, double y0, double x1, double y1,
                       double x2, double y2, isk_color color, isk_blend mode);
void isk_fill_triangle(isk_canvas *c, double x0, double y0, double x1, double y1,
                       double x2, double y2, isk_color color, isk_blend mode);
void isk_fill_circle(isk_canvas *c, double cx, double cy, double r, isk_color color, isk_blend mode);

void isk_draw_dot(isk_canvas *c, double x, double y, isk_color color, isk_blend mode);
void isk_stroke_line(isk_canvas *c, double x0, double y0, double x1, double y1,
                     isk_color color, isk_blend mode);
/* xy holds n points as x0,y0,x1,y1,...; closed != 0 joins the last point to
 * the first with a miter join (canvas closePath()). */
void isk_stroke_polyline(isk_canvas *c, const double *xy, int n, int closed,
                         isk_color color, isk_blend mode);
void isk_fill_circle_aa(isk_canvas *c, double cx, double cy, double r, isk_color color, isk_blend mode);

/* Coverage of the coverage dot at (x, y) for the 2x2 block of pixels whose
 * top-left is (floor(x), floor(y)): w[0] top-left, w[1] top-right,
 * w[2] bottom-left, w[3] bottom-right, each 0..255, summing to exactly 255.
 * Returns 0 (and zero weights) when x or y is not finite. */
int isk_dot_weights(double x, double y, uint8_t w[4]);

#endif
