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
 * Hot path (called per particle): no allocation, no division, two floors.
 */
#include "iskra/draw.h"

#include "raster/clip.h"

static inline void weights_frac(double fx, double fy, uint8_t w[4])
{
    if (fx == 0.0 && fy == 0.0) { /* integer position: one whole pixel */
        w[0] = 255; w[1] = 0; w[2] = 0; w[3] = 0;
        return;
    }
    double gx = 1.0 - fx, gy = 1.0 - fy;
    double a[4] = {255.0 * gx * gy, 255.0 * fx * gy, 255.0 * gx * fy, 255.0 * fx * fy};
    double frac[4];
    int sum = 0;
    for (int k = 0; k < 4; k++) {
        int f = (int)a[k]; /* a[k] in [0, 255]: truncation is floor */
        w[k] = (uint8_t)f;
        frac[k] = a[k] - f;
        sum += f;
    }
    for (int left = 255 - sum; left > 0; left--) {
        int best = -1;
        for (int k = 0; k < 4; k++)
            if (frac[k] >= 0.0 && (best < 0 || frac[k] > frac[best]))
                best = k;
        if (best < 0)
            break;
        w[best]++;
        frac[best] = -1.0; /* each pixel gets at most one extra unit */
    }
}

int isk_dot_weights(double x, double y, uint8_t w[4])
{
    if (!isk__finite2(x, y)) {
        w[0] = w[1] = w[2] = w[3] = 0;
        return 0;
    }
    weights_frac(x - floor(x), y - floor(y), w);
    return 1;
}

void isk_draw_dot(isk_canvas *c, double x, double y, isk_color color, isk_blend mode)
{
    /* The square [x, x+1) x [y, y+1) touches the canvas only for x in
     * (-1, width) and y in (-1, height); the test also rejects NaN and keeps
     * the conversions below defined. */
    if (!c || !c->pixels || !(x > -1.0 && x < c->width && y > -1.0 && y < c->height))
        return;
    double fx0 = floor(x), fy0 = floor(y);
    int ix = (int)fx0, iy = (int)fy0;
    uint8_t w[4];
    weights_frac(x - fx0, y - fy0, w);
    int left = ix >= 0, right = ix + 1 < c->width;
    int top = iy >= 0, bottom = iy + 1 < c->height;
    if (top) {
        uint8_t *p = c->pixels + (size_t)iy * c->stride;
        if (left) isk_blend_pixel_cov(p + (size_t)ix * 4u, color, w[0], mode);
        if (right) isk_blend_pixel_cov(p + (size_t)(ix + 1) * 4u, color, w[1], mode);
    }
    if (bottom) {
        uint8_t *p = c->pixels + (size_t)(iy + 1) * c->stride;
        if (left) isk_blend_pixel_cov(p + (size_t)ix * 4u, color, w[2], mode);
        if (right) isk_blend_pixel_cov(p + (size_t)(ix + 1) * 4u, color, w[3], mode);
    }
}
