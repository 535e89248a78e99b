/* SPDX-License-Identifier: MIT */
/* Canvas memory: owned, wrapped and view canvases. */
#include "iskra/canvas.h"

#include "raster/blend_px.h" /* isk__fill_span */

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static int valid_dims(int width, int height)
{
    return width > 0 && height > 0 && width <= ISK_CANVAS_MAX_DIM && height <= ISK_CANVAS_MAX_DIM;
}

isk_status isk_canvas_init(isk_canvas *c, int width, int height)
{
    if (!c)
        return ISK_ERR_NULL;
    memset(c, 0, sizeof *c);
    if (!valid_dims(width, height))
        return ISK_ERR_SIZE;
    size_t stride = (size_t)width * 4u;
    uint8_t *p = calloc((size_t)height, stride);
    if (!p)
        return ISK_ERR_NOMEM;
    c->pixels = p;
    c->width = width;
    c->height = height;
    c->stride = stride;
    c->owns_pixels = 1;
    return ISK_OK;
}

isk_status isk_canvas_wrap(isk_canvas *c, void *pixels, int width, int height, size_t stride)
{
    if (!c || !pixels)
        return ISK_ERR_NULL;
    if (!valid_dims(width, height) || stride < (size_t)width * 4u)
        return ISK_ERR_SIZE;
    /* The last row must be addressable: (height-1)*stride + 4*width may
     * neither wrap around size_t nor exceed what a pointer offset holds. */
    size_t last_row = (size_t)(height - 1);
    if (last_row > 0 && stride > ((size_t)PTRDIFF_MAX - (size_t)width * 4u) / last_row)
        return ISK_ERR_SIZE;
    c->pixels = pixels;
    c->width = width;
    c->height = height;
    c->stride = stride;
    c->owns_pixels = 0;
    return ISK_OK;
}

isk_status isk_canvas_view(isk_canvas *view, const isk_canvas *parent, int x, int y, int w, int h)
{
    if (!view || !parent)
        return ISK_ERR_NULL;
    if (w < 0 || h < 0)
        return ISK_ERR_SIZE;
    /* Clip in 64 bits: x + w may overflow int. */
    long long x0 = x, y0 = y, x1 = (long long)x + w, y1 = (long long)y + h;
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > parent->width) x1 = parent->width;
    if (y1 > parent->height) y1 = parent->height;
    view->stride = parent->stride;
    view->owns_pixels = 0;
    if (x0 >= x1 || y0 >= y1 || !parent->pixels) {
        view->pixels = parent->pixels;
        view->width = 0;
        view->height = 0;
        return ISK_OK;
    }
    view->pixels = parent->pixels + (size_t)y0 * parent->stride + (size_t)x0 * 4u;
    view->width = (int)(x1 - x0);
    view->height = (int)(y1 - y0);
    return ISK_OK;
}

void isk_canvas_free(isk_canvas *c)
{
    if (!c)
        return;
    if (c->owns_pixels)
        free(c->pixels);
    memset(c, 0, sizeof *c);
}

void isk_canvas_fill(isk_canvas *c, isk_color color)
{
    if (!c || !c->pixels || c->width <= 0 || c->height <= 0)
        return; /* nothing to fill (a hostile size is not turned into a huge one) */
    uint8_t *const pixels = c->pixels;
    const size_t w = (size_t)c->width, stride = c->stride;
    for (size_t y = 0, h = (size_t)c->height; y < h; y++)
        isk__fill_span(pixels + y * stride, w, color);
}

isk_color isk_canvas_get(const isk_canvas *c, int x, int y)
{
    if (!c || !c->pixels || x < 0 || y < 0 || x >= c->width || y >= c->height)
        return ISK_TRANSPARENT;
    const uint8_t *p = isk_canvas_at(c, x, y);
    return isk_rgba(p[0], p[1], p[2], p[3]);
}

/* A canvas whose fields can be read without going out of bounds: an empty
 * one (0 x 0), or pixels with a positive size and a stride that fits a row. */
static int readable(const isk_canvas *c)
{
    if (!c)
        return 0;
    if (c->width == 0 || c->height == 0)
        return c->width >= 0 && c->height >= 0;
    return c->pixels && c->width > 0 && c->height > 0 && c->stride >= (size_t)c->width * 4u;
}

int isk_canvas_equal(const isk_canvas *a, const isk_canvas *b)
{
    if (!readable(a) || !readable(b) || a->width != b->width || a->height != b->height)
        return 0;
    for (int y = 0; y < a->height; y++)
        if (memcmp(a->pixels + (size_t)y * a->stride, b->pixels + (size_t)y * b->stride,
                   (size_t)a->width * 4u) != 0)
            return 0;
    return 1;
}

/* How far pixel q is from pixel p: the largest difference of one channel
 * (returned; what decides whether two pixels differ, and by how much) and
 * the sum of the four channels' differences (*sum unless NULL, for the mean). */
static int pixel_diff(const uint8_t *p, const uint8_t *q, int *sum)
{
    int m = 0, s = 0;
    for (int k = 0; k < 4; k++) {
        int dd = p[k] > q[k] ? p[k] - q[k] : q[k] - p[k];
        s += dd;
        if (dd > m) m = dd;
    }
    if (sum) *sum = s;
    return m;
}

int isk_canvas_compare(const isk_canvas *a, const isk_canvas *b, isk_canvas_diff *d, isk_canvas *diff_image)
{
    isk_canvas_diff r = {0, 0, 0, 0.0};
    if (!readable(a) || !readable(b)) {
        if (d) *d = r;
        return 0;
    }
    int same_size = a->width == b->width && a->height == b->height;
    double sum = 0.0;
    int w = a->width > b->width ? a->width : b->width, h = a->height > b->height ? a->height : b->height;
    if (diff_image && (!readable(diff_image) || diff_image->width != w || diff_image->height != h))
        diff_image = NULL;
    for (int y = 0; y < h; y++) {
        for (int x = 0; x < w; x++) {
            int inside = x < a->width && y < a->height && x < b->width && y < b->height;
            int m = 0;
            if (inside) {
                int pixel_sum;
                m = pixel_diff(isk_canvas_at(a, x, y), isk_canvas_at(b, x, y), &pixel_sum);
                sum += pixel_sum;
                r.differing += m != 0;
                if (m > r.max_channel) r.max_channel = m;
            }
            if (diff_image) {
                uint8_t *o = isk_canvas_at(diff_image, x, y);
                isk_color c = isk_canvas_get(a, x, y);
                int mark = !inside || m;
                o[0] = mark ? 255 : (uint8_t)(c.r / 3);
                o[1] = mark ? 0 : (uint8_t)(c.g / 3);
                o[2] = mark ? 255 : (uint8_t)(c.b / 3);
                o[3] = 255;
            }
        }
    }
    if (!same_size) {
        if (d) *d = (isk_canvas_diff){0, 0, 0, 0.0};
        return 0;
    }
    r.pixels = (long)a->width * a->height;
    r.mean_abs = r.pixels ? sum / (4.0 * (double)r.pixels) : 0.0;
    if (d) *d = r;
    return 1;
}

long isk_canvas_count_beyond(const isk_canvas *a, const isk_canvas *b, int max_channel_diff)
{
    if (!readable(a) || !readable(b) || a->width != b->width || a->height != b->height || max_channel_diff < 0 ||
        max_channel_diff > 255)
        return -1;
    long n = 0;
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++)
            n += pixel_diff(isk_canvas_at(a, x, y), isk_canvas_at(b, x, y), NULL) > max_channel_diff;
    return n;
}
