/* SPDX-License-Identifier: MIT */
/* iskra/draw.h — the software rasterizer's primitives, in pixel coordinates.
 *
 * Pixel (i, j) is the unit square [i, i+1) x [j, j+1); its centre is
 * (i+0.5, j+0.5).  x grows right, y grows down.  Every primitive takes a
 * colour and a blend mode (iskra/blend.h) and clips to the canvas.
 *
 * Any coordinate is accepted: huge values (±1e300), ±Inf and NaN are clipped
 * or ignored, never undefined behaviour.  A primitive whose geometry contains
 * a NaN or an infinity (including an infinite radius) draws nothing.  Lines
 * and triangles reaching beyond 2^24 px from the canvas are first clipped to
 * that guard box in double (exact results are guaranteed only inside it).
 * Nothing here allocates or fails, so nothing returns a status: bad geometry
 * simply draws nothing.
 *
 * Example:
 *
 *     isk_canvas c;
 *     if (isk_canvas_init(&c, 600, 600) != ISK_OK) return 1;
 *     isk_canvas_fill(&c, ISK_WHITE);
 *     isk_fill_circle(&c, 300, 300, 40, ISK_YELLOW, ISK_BLEND_OVER);
 *     isk_stroke_line(&c, 175, 300, 325, 300, ISK_BLACK, ISK_BLEND_OVER);
 *     isk_draw_dot(&c, 180.4, 420.7, ISK_YELLOW, ISK_BLEND_OVER);
 *     isk_canvas_free(&c);
 *
 * Aliased (1-pixel) primitives:
 *   isk_draw_pixel, isk_fill_rect    integer pixel coordinates (64-bit bounds
 *                                    maths, INT_MIN/INT_MAX are fine); a
 *                                    negative w or h extends left / up, as
 *                                    canvas fillRect(); 0 draws nothing
 *   isk_draw_line                    Bresenham between the pixels containing
 *                                    the two end points (both ends drawn, each
 *                                    pixel once).  Walking the major axis from
 *                                    the end with the smaller major coordinate,
 *                                    step i lights minor offset i*db/da rounded
 *                                    half up, so line(A,B) == line(B,A)
 *   isk_draw_triangle                three isk_draw_line edges, each without
 *                                    the pixel of its end vertex, so every
 *                                    vertex pixel is blended once
 *   isk_fill_triangle                pixels whose centre is inside; centres
 *                                    exactly on an edge follow the top-left rule
 *                                    (shared edges are drawn once); either
 *                                    winding; zero area draws nothing
 *   isk_fill_circle                  pixels whose centre is strictly inside:
 *                                    (i+0.5-cx)^2 + (j+0.5-cy)^2 < r^2
 *                                    (in double; hypot() beyond r = 2^26)
 * Anti-aliased primitives (coverage = exact area, or 16x16 supersampling
 * where stated, then blended with alpha scaled by coverage).  An area a in
 * [0, 1] becomes the byte floor(255*a + 0.5):
 *   isk_draw_dot           a 1x1 square whose top-left corner is (x, y),
 *                          spread over up to 2x2 pixels by exact area: how the
 *                          thesis's browser drew every particle (fillRect).
 *                          The four bytes sum to exactly 255: see
 *                          isk_dot_weights
 *   isk_stroke_line        a width-1 line like HTML canvas stroke(): the
 *                          rectangle of half-width 0.5 around the segment,
 *                          butt caps, coverage by exact area; a zero-length
 *                          line draws nothing.  Same as a 2-point polyline
 *   isk_stroke_polyline    a width-1 path with miter joins (limit 10, as
 *                          canvas: ratio 1/sin(angle/2) > 10 gives a bevel)
 *                          and butt caps, drawn as one shape so joins and
 *                          self-overlaps are not painted twice.  Coverage is
 *                          the exact area of the union (inclusion–exclusion
 *                          of the <= 3 convex pieces at a pixel); pixels
 *                          touched by 4+ pieces (very short segments) use 16x16
 *                          supersampling, round(hits*255/256).  Repeated
 *                          points are skipped.  Cost O(touched pixels * n)
 *   isk_fill_circle_aa     a disc, coverage by exact area (analytic; beyond
 *                          r = 2^16 the edge inside a pixel is taken as its
 *                          tangent, < 1e-5 px off)
 *   isk_stroke_trail       a fading ribbon for particle trails (below)
 *
 * Note on the thesis's figure 1: the browser (Skia) draws width-1 strokes as
 * anti-aliased hairlines (coverage 255 split between the two pixels across
 * the line on each major-axis step, no joins), not as exact-area rectangles,
 * so its diagonal lines are thinner than isk_stroke_line's.  Horizontal and
 * vertical lines agree (two half-intensity rows for integer coordinates).
 */
#ifndef ISKRA_DRAW_H
#define ISKRA_DRAW_H

#include "iskra/blend.h"
#include "iskra/blend_inline.h"
#include "iskra/canvas.h"

#ifdef __cplusplus
extern "C" {
#endif

void isk_draw_pixel(isk_canvas *c, int x, int y, isk_color color, isk_blend mode);

/* Pixel (x, y) of c, or NULL when there is none: unsigned compares reject
 * negative coordinates too, and an empty or pixel-less canvas fails them
 * as well. */
static ISK__INLINE uint8_t *isk__pixel_at(isk_canvas *c, int x, int y)
{
    if (!c || !c->pixels || (unsigned)x >= (unsigned)c->width || (unsigned)y >= (unsigned)c->height)
        return (uint8_t *)0;
    return isk_canvas_at(c, x, y);
}

/* isk_draw_pixel is also a macro over this inline copy of it (C11 7.1.4
 * lets a library function be one): a loop of calls then compiles to a loop
 * of blends, with no call and with the colour's part of the rule left
 * out of the loop by the compiler (the blend is iskra/blend_inline.h's
 * rule, or on x86-64 its SSE2 twin).  The bytes are the same either way;
 * (isk_draw_pixel)(...) or &isk_draw_pixel reach the function. */

static ISK__INLINE void isk__draw_pixel_inline(isk_canvas *c, int x, int y, isk_color color, isk_blend mode)
{
    /* first, unconditionally: a loop of one colour computes it once */
    const isk__px_prep K = isk__px_prepare(color);
    uint8_t *d = isk__pixel_at(c, x, y);
    if (d)
        isk__px_prepared(d, color, K, mode);
}
#define isk_draw_pixel(c, x, y, color, mode) isk__draw_pixel_inline((c), (x), (y), (color), (mode))

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

/* A particle's trail: a ribbon through n screen points xy (x0,y0,x1,y1,...,
 * oldest first, newest last), `width` px wide, anti-aliased, its alpha
 * color.a at the newest point falling linearly along the ribbon's length to
 * color.a * (1 - fade) at the oldest; fade is clamped into [0, 1].
 *
 *     const double xy[8] = {10, 40, 14, 37, 19, 36, 25, 37};
 *     isk_stroke_trail(&c, xy, 4, 2.0, ISK_YELLOW, 1.0, ISK_BLEND_ADD);
 *
 * The shape is every point within width/2 of the polyline: round caps and
 * round joins, one shape (each pixel is blended once, so a trail crossing
 * or doubling back over itself is not painted twice there).  One point, or
 * points all equal, give a disc of diameter `width`.  Per pixel, with p its
 * centre:
 *   nearest   the segment nearest p (squared distance to its nearest point
 *             q; a later, newer segment wins a tie); beyond width/2 +
 *             sqrt(2)/2 nothing is drawn
 *   coverage  the exact area of the pixel inside the straight band of the
 *             ribbon's width through q, perpendicular to p - q (or to the
 *             segment, when p is on it): exact wherever the ribbon is
 *             straight across the pixel; at caps, joins and crossings the
 *             band stands for the curved or broken edge, so thin round ends
 *             come out too bright (measured, tests/test_trail.c: a lone dot
 *             of width 1 gets 1.20-1.40x its area, width 2 1.06-1.11x,
 *             width 4 1.02x; short random trails of width 1 / 2 / 4 get
 *             1.06 / 1.03 / 1.01x the exact shape's area in total)
 *   fade      t = arc length from the oldest point to q over the whole
 *             length (1 for a trail of length 0); alpha factor
 *             1 - fade (1 - t)
 *   byte      floor(255 * area * factor + 0.5), blended as every
 *             anti-aliased primitive (isk_blend_pixel_cov with color)
 * Width: at least 0.5 px is drawn; a thinner trail (width > 0) is drawn
 * 0.5 px wide with its alpha scaled by width / 0.5, so a trail thinning to
 * nothing fades out.  Nothing is drawn for n < 1 or n > 2^28, a NaN or
 * infinite point, width NaN, <= 0 or above 4096, fade NaN, a mode that is
 * not a blend mode.  Segments reaching beyond 2^24 px from the canvas are
 * first clipped to that guard box (arc lengths are those of the clipped
 * segments).  Cost: per segment, the pixels within width/2 + 1 of it, then
 * one pass over the trail's pixels; nothing is allocated.  The texture
 * primitives and trails together: docs/textures.md. */
void isk_stroke_trail(isk_canvas *c, const double *xy, int n, double width, isk_color color, double fade,
                      isk_blend mode);

/* Anti-aliased hairlines, the browser's canvas stroke() at width 1 (faithful
 * mode): Chrome's Skia draws strokes no wider than a pixel as hairlines,
 * one pixel of coverage per step along the major axis split between the two
 * pixels nearest the line's centre (a diagonal stays 2 px wide; the
 * exact-area isk_stroke_line spreads it over 3).  Each polyline segment is
 * drawn on its own: no joins, no caps.  The rule is in src/raster/hairline.c. */
void isk_stroke_hairline(isk_canvas *c, double x0, double y0, double x1, double y1, isk_color color,
                         isk_blend mode);
void isk_stroke_polyline_hairline(isk_canvas *c, const double *xy, int n, int closed, isk_color color,
                                  isk_blend mode);

/* Coverage of the coverage dot at (x, y) for the 2x2 block of pixels whose
 * top-left is (floor(x), floor(y)): w[0] top-left, w[1] top-right,
 * w[2] bottom-left, w[3] bottom-right, each 0..255, summing to exactly 255.
 * Rule: with fx = x - floor(x), fy = y - floor(y), the exact areas times 255
 * a = 255(1-fx)(1-fy), 255fx(1-fy), 255(1-fx)fy, 255fx*fy are floored, and
 * the units still missing from 255 go one each to the largest fractional
 * parts, ties to the lower index.  Integer (x, y) gives {255, 0, 0, 0};
 * (x+0.5, y) gives {128, 127, 0, 0}; (x+0.5, y+0.5) gives {64, 64, 64, 63}.
 * Returns 0 (and zero weights) when x or y is not finite, else 1. */
int isk_dot_weights(double x, double y, uint8_t w[4]);

/* The thesis browser's own rule for the same square (faithful mode): Skia's
 * anti-aliased fillRect snaps the edges to 1/256 px and multiplies row and
 * column coverage with truncation, so slivers under 1/256 px add nothing; the
 * four weights sum to 250..256 (Skia's scale is 1/256, truncated).  With it the thesis's
 * trajectory figures are reproduced pixel for pixel (lit pixels exactly);
 * the exact-area isk_draw_dot is the sound default.
 * isk_dot_weights_browser returns 0 for non-finite or huge coordinates;
 * otherwise *ix, *iy receive the top-left pixel of the 2x2 block. */
void isk_draw_dot_browser(isk_canvas *c, double x, double y, isk_color color, isk_blend mode);
int isk_dot_weights_browser(double x, double y, int *ix, int *iy, uint8_t w[4]);

#ifdef __cplusplus
}
#endif

#endif
