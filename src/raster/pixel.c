/* Integer-coordinate primitives: a single pixel and a filled rectangle.
 * All bounds arithmetic is 64-bit so INT_MIN/INT_MAX arguments are safe. */
#include "iskra/draw.h"

#include "raster/clip.h"

void isk_draw_pixel(isk_canvas *c, int x, int y, isk_color color, isk_blend mode)
{
    if (!isk__canvas_ok(c) || x < 0 || y < 0 || x >= c->width || y >= c->height)
        return;
    isk_blend_pixel(isk_canvas_at(c, x, y), color, mode);
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
    for (long long j = y0; j < y1; j++) {
        uint8_t *p = isk_canvas_at(c, (int)x0, (int)j);
        for (long long i = x0; i < x1; i++, p += 4)
            isk_blend_pixel(p, color, mode);
    }
}
