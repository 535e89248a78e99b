/* SPDX-License-Identifier: MIT */
/* iskra/view.h — world coordinates to canvas pixels, and back.
 *
 * Two ways to set up a view, both from the theses:
 *
 * 1. The explosion thesis's global coordinate system: a world window
 *    xmin..xmax, ymin..ymax mapped onto a W x H canvas, y pointing up:
 *        sx = W/(xmax-xmin)   sy = -H/(ymax-ymin)
 *        px = -sx*xmin        py = -sy*ymax
 *        screen = (sx*x + px, sy*y + py)        (computed in exactly this order)
 *    e.g. -10..10 on 600x600: X = 30x + 300, Y = 300 - 30y.
 *
 * 2. The fire thesis's camera: zoom z > 0 (smaller = closer) and pan (tx, ty):
 *        a = (w+h)/(2z) pixels per world unit
 *        screen = (w/2 + a*(x+tx), h/2 - a*(y+ty))
 *    e.g. 800x600, z = 10: world (1,1) -> pixel (470, 230).
 *
 * Both are affine; isk_view_to_world() inverts either (for mouse clicks).
 *
 * Example:
 *
 *     isk_view v;
 *     if (isk_view_window(&v, 600, 600, -10, 10, -10, 10) != ISK_OK) return 1;
 *     isk_canvas canvas;
 *     if (isk_canvas_init(&canvas, 600, 600) != ISK_OK) return 1;
 *     isk_world_dot(&canvas, &v, -4, -4, ISK_YELLOW, ISK_BLEND_OVER);
 *     double px, py, wx, wy;
 *     isk_view_to_screen(&v, -4, -4, &px, &py);         // (180, 420)
 *     isk_view_to_world(&v, px, py, &wx, &wy);          // (-4, -4) again: a mouse click's point
 *     printf("(%g, %g) -> (%g, %g)\n", wx, wy, px, py);
 *     isk_canvas_free(&canvas);
 *
 * The isk_world_* helpers are the thesis's drawing methods in world units:
 * piksel -> isk_world_dot, puniKrug -> isk_world_disc, tekst -> isk_world_text.
 */
#ifndef ISKRA_VIEW_H
#define ISKRA_VIEW_H

#include <stddef.h>

#include "iskra/blend.h"
#include "iskra/canvas.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum isk_view_kind { ISK_VIEW_WINDOW = 0, ISK_VIEW_CAMERA = 1 } isk_view_kind;

typedef struct isk_view {
    isk_view_kind kind;
    int width, height;                 /* canvas size in pixels */
    double xmin, xmax, ymin, ymax;     /* visible world window (both kinds) */
    double sx, sy, px, py;             /* screen = (sx*x + px, sy*y + py) */
    double zoom, tx, ty, a;            /* camera parameters (ISK_VIEW_CAMERA) */
} isk_view;

/* World window -> canvas.  Errors: ISK_ERR_SIZE for a bad canvas size,
 * ISK_ERR_NAN for non-finite bounds, ISK_ERR_RANGE when min >= max. */
isk_status isk_view_window(isk_view *v, int width, int height,
                           double xmin, double xmax, double ymin, double ymax);

/* Fire-thesis camera.  Errors: ISK_ERR_SIZE, ISK_ERR_NAN, ISK_ERR_RANGE (zoom <= 0). */
isk_status isk_view_camera(isk_view *v, int width, int height, double zoom, double tx, double ty);

/* A NULL view converts every point to (0, 0), and the isk_world_* calls
 * below draw nothing with it. */

/* World -> screen (fractional pixels). */
void isk_view_to_screen(const isk_view *v, double x, double y, double *sx, double *sy);
/* Screen -> world, the exact inverse formulas of the view's kind. */
void isk_view_to_world(const isk_view *v, double sx, double sy, double *x, double *y);

/* The thesis's `piksel`: a coverage dot (isk_draw_dot) at the transformed point. */
void isk_world_dot(isk_canvas *c, const isk_view *v, double x, double y, isk_color color, isk_blend mode);
/* The same dot by the thesis browser's rule (isk_draw_dot_browser): what
 * the faithful thesis figures use. */
void isk_world_dot_browser(isk_canvas *c, const isk_view *v, double x, double y, isk_color color,
                           isk_blend mode);
/* Batched particle drawing over a store's SoA position arrays: point i is
 * (x[i], y[i]) in world units, taken through the view exactly as
 * isk_view_to_screen, and drawn in index order.  Each is byte-identical to
 * the loop of single calls it replaces, and much faster (one blend-mode
 * choice per batch, the transform fused into the kernel):
 *   isk_draw_dots          isk_world_dot for every i (exact-area dot)
 *   isk_draw_dots_browser  isk_world_dot_browser for every i
 *   isk_draw_pixels        the pixel containing the screen point: when
 *                          0 <= X < width and 0 <= Y < height (so NaN is
 *                          skipped), isk_draw_pixel(c, (int)X, (int)Y, ...)
 * NULL arguments or n = 0 draw nothing.  One colour for the whole batch;
 * a store whose colour varies per particle keeps the single calls.
 *
 *     isk_draw_dots(&canvas, &view, p->count, p->x, p->y, colour, ISK_BLEND_ADD);
 */
void isk_draw_dots(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                   isk_color color, isk_blend mode);
void isk_draw_dots_browser(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                           isk_color color, isk_blend mode);
void isk_draw_pixels(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                     isk_color color, isk_blend mode);
/* The thesis's `puniKrug`: an anti-aliased disc at the transformed centre with
 * radius |sx|*r pixels (x scale only, as the thesis). */
void isk_world_disc(isk_canvas *c, const isk_view *v, double x, double y, double r,
                    isk_color color, isk_blend mode);
/* The thesis's `tekst`: bitmap-font text whose baseline-left corner is the
 * transformed point (the glyph box sits above it, like canvas fillText). */
void isk_world_text(isk_canvas *c, const isk_view *v, double x, double y, const char *s,
                    int scale, isk_color color, isk_blend mode);
/* Anti-aliased width-1 path through world points (xy = x0,y0,x1,y1,...). */
void isk_world_polyline(isk_canvas *c, const isk_view *v, const double *xy, int n, int closed,
                        isk_color color, isk_blend mode);
/* The same path as the browser's hairlines (isk_stroke_polyline_hairline). */
void isk_world_polyline_hairline(isk_canvas *c, const isk_view *v, const double *xy, int n, int closed,
                                 isk_color color, isk_blend mode);

#ifdef __cplusplus
}
#endif

#endif
