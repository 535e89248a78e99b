/* SPDX-License-Identifier: MIT */
/* Drawing in world units: the thesis's piksel, puniKrug and tekst, plus a
 * world-space polyline.  One call does the transform, so examples never
 * repeat the screen arithmetic. */
#include <limits.h>
#include <stdlib.h>

#include "iskra/draw.h"
#include "iskra/text.h"
#include "iskra/view.h"
#include "raster/clip.h"

void isk_world_dot(isk_canvas *c, const isk_view *v, double x, double y, isk_color color, isk_blend mode)
{
    if (!v)
        return;
    double X, Y;
    isk_view_to_screen(v, x, y, &X, &Y);
    isk_draw_dot(c, X, Y, color, mode);
}

void isk_world_dot_browser(isk_canvas *c, const isk_view *v, double x, double y, isk_color color,
                           isk_blend mode)
{
    if (!v)
        return;
    double X, Y;
    isk_view_to_screen(v, x, y, &X, &Y);
    isk_draw_dot_browser(c, X, Y, color, mode);
}

void isk_world_disc(isk_canvas *c, const isk_view *v, double x, double y, double r, isk_color color,
                    isk_blend mode)
{
    if (!v)
        return;
    double X, Y;
    isk_view_to_screen(v, x, y, &X, &Y);
    double R = v->sx * r;
    if (R < 0) R = -R;
    isk_fill_circle_aa(c, X, Y, R, color, mode);
}

void isk_world_text(isk_canvas *c, const isk_view *v, double x, double y, const char *s, int scale,
                    isk_color color, isk_blend mode)
{
    double X, Y;
    if (!v || scale < 1)
        return;
    isk_view_to_screen(v, x, y, &X, &Y);
    /* Baseline at Y: the 7 rows above the descender row sit above it.  Far
     * positions are clamped (no undefined float->int conversion, no int
     * overflow); text out there is off the canvas either way. */
    long long top = (long long)isk__floor_clamp(Y, -1000000000, 1000000000) - 7LL * scale;
    if (top < INT_MIN)
        top = INT_MIN;
    isk_draw_text(c, isk__floor_clamp(X, -1000000000, 1000000000), (int)top, s, scale, color, mode);
}

/* Transforms the points (on the stack when few) and strokes them. */
static void world_path(isk_canvas *c, const isk_view *v, const double *xy, int n, int closed, isk_color color,
                       isk_blend mode, int hairline)
{
    if (!v || !xy || n < 2)
        return;
    double stack[64];
    double *s = n <= 32 ? stack : malloc(sizeof(double) * 2 * (size_t)n);
    if (!s)
        return;
    for (int i = 0; i < n; i++)
        isk_view_to_screen(v, xy[2 * i], xy[2 * i + 1], &s[2 * i], &s[2 * i + 1]);
    if (hairline)
        isk_stroke_polyline_hairline(c, s, n, closed, color, mode);
    else
        isk_stroke_polyline(c, s, n, closed, color, mode);
    if (s != stack)
        free(s);
}

void isk_world_polyline(isk_canvas *c, const isk_view *v, const double *xy, int n, int closed,
                        isk_color color, isk_blend mode)
{
    world_path(c, v, xy, n, closed, color, mode, 0);
}

void isk_world_polyline_hairline(isk_canvas *c, const isk_view *v, const double *xy, int n, int closed,
                                 isk_color color, isk_blend mode)
{
    world_path(c, v, xy, n, closed, color, mode, 1);
}
