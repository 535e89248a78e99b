/* SPDX-License-Identifier: MIT */
/* Integer-coordinate primitives: a single pixel and a filled rectangle.
 * All bounds arithmetic is 64-bit so INT_MIN/INT_MAX arguments are safe.
 * The blend mode is chosen once per call (raster/blend_px.h); the pixel's
 * own code is also inline in iskra/draw.h. */
#include "iskra/draw.h"

#include "raster/blend_px.h"
#include "raster/clip.h"

/* The function behind the macro of iskra/draw.h (the name in parentheses
 * is not expanded): for function pointers, other languages' bindings and
 * callers that ask for it.  The macro's pixel, blended as the library's
 * kernels blend (isk__blend_px: its SSE2 twin where the build has one). */
void (isk_draw_pixel)(isk_canvas *c, int x, int y, isk_color color, isk_blend mode)
{
    uint8_t *d = isk__pixel_at(c, x, y);
    if (d)
        isk__blend_px(d, color, mode);
}

static ISK__INLINE void fill_rows(isk_canvas *c, int x0, int y0, int x1, int y1, isk_color color,
                                  isk_blend mode)
{
    for (int j = y0; j < y1; j++) {
        uint8_t *p = isk_canvas_at(c, x0, j);
        if (mode == ISK_BLEND_REPLACE) { /* a constant: the copies of the other modes keep the loop */
            isk__fill_span(p, (size_t)(x1 - x0), color);
            continue;
        }
        for (int i = x0; i < x1; i++, p += 4)
            isk__blend_px(p, color, mode);
    }
}

void isk_fill_rect(isk_canvas *c, int x, int y, int w, int h, isk_color color, isk_blend mode)
{
    if (!isk__canvas_ok(c))
        return;
    /* A negative size extends to the left / upwards, as canvas fillRect(). */
    long long x0 = x, y0 = y, x1 = (long long)x + w, y1 = (long long)y + h;
    if (x1 < x0) { long long t = x0; x0 = x1; x1 = t; }
    if (y1 < y0) { long long t = y0; y0 = y1; y1 = t; }
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > c->width) x1 = c->width;
    if (y1 > c->height) y1 = c->height;
    if (x0 >= x1 || y0 >= y1)
        return;
    ISK__BLEND_DISPATCH(mode, fill_rows, c, (int)x0, (int)y0, (int)x1, (int)y1, color);
}
