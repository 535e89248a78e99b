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

static void blend_2x2(isk_canvas *c, int ix, int iy, const uint8_t w[4], isk_color color, isk_blend mode)
{
    int left = ix >= 0 && ix < c->width, right = ix + 1 >= 0 && ix + 1 < c->width;
    int top = iy >= 0 && iy < c->height, bottom = iy + 1 >= 0 && iy + 1 < c->height;
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

void isk_draw_dot(isk_canvas *c, double x, double y, isk_color color, isk_blend mode)
{
    /* The square [x, x+1) x [y, y+1) touches the canvas only for x in
     * (-1, width) and y in (-1, height); the test also rejects NaN and keeps
     * the conversions below defined. */
    if (!c || !c->pixels || !(x > -1.0 && x < c->width && y > -1.0 && y < c->height))
        return;
    double fx0 = floor(x), fy0 = floor(y);
    uint8_t w[4];
    weights_frac(x - fx0, y - fy0, w);
    blend_2x2(c, (int)fx0, (int)fy0, w, color, mode);
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
    w[0] = w[1] = w[2] = w[3] = 0;
    /* |x| < 16400 keeps x * 65536 inside int (and rejects NaN). */
    if (!(x > -16400.0 && x < 16400.0 && y > -16400.0 && y < 16400.0))
        return 0;
    float xf = (float)x, yf = (float)y;
    int L = (((int)(xf * 65536.0f)) + 0x80) >> 8;
    int T = (((int)(yf * 65536.0f)) + 0x80) >> 8;
    int l = L & 255, t = T & 255;
    int col[2] = {l ? 256 - l : 256, l};
    int row[2] = {t ? 256 - t : 255, t};
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++)
            w[2 * j + i] = (uint8_t)(col[i] == 256 ? row[j] : (row[j] * col[i]) >> 8);
    *ix = L >> 8; /* arithmetic shift: floor for negative values too */
    *iy = T >> 8;
    return 1;
}

void isk_draw_dot_browser(isk_canvas *c, double x, double y, isk_color color, isk_blend mode)
{
    if (!c || !c->pixels || !(x > -2.0 && x < c->width + 1.0 && y > -2.0 && y < c->height + 1.0))
        return;
    int ix, iy;
    uint8_t w[4];
    if (isk_dot_weights_browser(x, y, &ix, &iy, w))
        blend_2x2(c, ix, iy, w, color, mode);
}
