/* SPDX-License-Identifier: MIT */
/* The coverage dot: how the thesis's browser drew every particle (a 1x1
 * fillRect whose top-left corner is the particle), spread over up to 2x2
 * pixels by exact area.
 *
 * Rounding rule (so the four bytes always sum to exactly 255 and a dot never
 * gains or loses brightness with its sub-pixel position):
 *   with fx = x - floor(x), fy = y - floor(y), gx = 1 - fx, gy = 1 - fy,
 *   a = 255*gx*gy, 255*fx*gy, 255*gx*fy, 255*fx*fy   (TL, TR, BL, BR; doubles,
 *                                                     multiplied left to right)
 *   w_k = floor(a_k), then the remainder 255 - sum(w) (0..3, at most 4 after
 *   rounding) goes one unit each to the largest fractional parts a_k - w_k,
 *   ties to the lower index (TL, TR, BL, BR).
 * So (x+0.5, y) gives TL 128, TR 127 and (x+0.5, y+0.5) gives 64, 64, 64, 63.
 *
 * The arithmetic is in raster/dot_kernel.h, shared with the batched draws
 * (isk_draw_dots); here are the public single-dot entry points.  Hot path:
 * no allocation, no division, no libm call, one mode switch per dot.
 */
#include "iskra/draw.h"

#include <stddef.h>

#include "raster/clip.h"
#include "raster/dot_kernel.h"

int isk_dot_weights(double x, double y, uint8_t w[4])
{
    if (!w)
        return 0;
    if (!isk__finite2(x, y)) {
        w[0] = w[1] = w[2] = w[3] = 0;
        return 0;
    }
    uint32_t u[4];
    isk__dot_weights_frac(x - floor(x), y - floor(y), u);
    for (int k = 0; k < 4; k++)
        w[k] = (uint8_t)u[k];
    return 1;
}

void isk_draw_dot(isk_canvas *c, double x, double y, isk_color color, isk_blend mode)
{
    if (!c || !c->pixels)
        return;
    ISK__BLEND_DISPATCH(mode, isk__dot, c, x, y, color, NULL);
}

/* The browser's rule (Skia's anti-aliased rectangle fill, which Chrome's
 * canvas used for the thesis's fillRect(x, y, 1, 1)): the edges go through
 * float and 16.16 fixed point and are rounded to 1/256 px; a partly covered
 * row gets 256 - frac(top) (top) or frac(bottom) (bottom) of 256, a whole row
 * 255; columns likewise with 256 for a whole column; a pixel's coverage is
 * row * column >> 8 (truncated), or the row alone when the column is whole.
 * Slivers thinner than 1/256 px therefore contribute nothing, and a dot's
 * four weights may sum to a little less than 255. */
int isk_dot_weights_browser(double x, double y, int *ix, int *iy, uint8_t w[4])
{
    if (!ix || !iy || !w)
        return 0;
    uint32_t u[4];
    int ok = isk__dot_weights_browser(x, y, ix, iy, u);
    for (int k = 0; k < 4; k++)
        w[k] = (uint8_t)u[k];
    return ok;
}

void isk_draw_dot_browser(isk_canvas *c, double x, double y, isk_color color, isk_blend mode)
{
    if (!c || !c->pixels)
        return;
    ISK__BLEND_DISPATCH(mode, isk__dot_browser, c, x, y, color, NULL);
}
