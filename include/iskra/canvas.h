/* SPDX-License-Identifier: MIT */
/* iskra/canvas.h — the RGBA8 pixel buffer every drawing call writes into.
 *
 * Memory layout: bytes R,G,B,A per pixel, rows `stride` bytes apart, top row
 * first — the layout of PNG and of SDL_PIXELFORMAT_RGBA32, so a canvas can be
 * written or uploaded without conversion.
 *
 * Example:
 *
 *     isk_canvas c;
 *     if (isk_canvas_init(&c, 600, 600) != ISK_OK) return 1;   // owns memory
 *     isk_canvas_fill(&c, ISK_BLACK);
 *     isk_fill_rect(&c, 100, 100, 50, 50, ISK_YELLOW, ISK_BLEND_OVER);   // iskra/draw.h
 *     isk_color p = isk_canvas_get(&c, 120, 120);              // 255 255 0 255
 *     printf("%d %d %d %d\n", p.r, p.g, p.b, p.a);
 *     isk_canvas_free(&c);
 *
 * isk_canvas_wrap() draws into memory the caller owns (olive.c style);
 * isk_canvas_view() makes a clipped sub-rectangle sharing the parent's pixels.
 * Colours are straight (non-premultiplied) RGBA.  Blend modes are documented
 * in iskra/blend.h.
 */
#ifndef ISKRA_CANVAS_H
#define ISKRA_CANVAS_H

#include <stddef.h>
#include <stdint.h>

#include "iskra/color.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest accepted width or height. */
#define ISK_CANVAS_MAX_DIM 16384

typedef struct isk_canvas {
    uint8_t *pixels;   /* top-left pixel; R,G,B,A bytes */
    int width;
    int height;
    size_t stride;     /* bytes from one row to the next (>= 4*width) */
    int owns_pixels;   /* 1 when isk_canvas_free must release `pixels` */
} isk_canvas;

/* Allocates a width x height canvas, all bytes 0 (transparent black). */
isk_status isk_canvas_init(isk_canvas *c, int width, int height);

/* Wraps caller memory; stride in bytes must be >= 4*width, and small enough
 * that the last row's end, (height-1)*stride + 4*width, fits in a pointer
 * offset (ISK_ERR_SIZE otherwise).  Never freed by us. */
isk_status isk_canvas_wrap(isk_canvas *c, void *pixels, int width, int height, size_t stride);

/* A view of the rectangle (x, y, w, h) of `parent`, clipped to the parent.
 * The view shares the parent's pixels and must not outlive it.  A rectangle
 * that lies wholly outside gives a 0x0 view (drawing into it does nothing). */
isk_status isk_canvas_view(isk_canvas *view, const isk_canvas *parent, int x, int y, int w, int h);

/* Releases owned pixels (safe on wrapped canvases, views and zeroed structs). */
void isk_canvas_free(isk_canvas *c);

/* Sets every pixel to `color` (no blending). */
void isk_canvas_fill(isk_canvas *c, isk_color color);

/* Address of pixel (x, y); the caller guarantees 0 <= x < width, 0 <= y < height. */
static inline uint8_t *isk_canvas_at(const isk_canvas *c, int x, int y)
{
    return c->pixels + (size_t)y * c->stride + (size_t)x * 4u;
}

/* Reads pixel (x, y); out-of-range coordinates give ISK_TRANSPARENT. */
isk_color isk_canvas_get(const isk_canvas *c, int x, int y);

/* 1 when both canvases have equal size and identical pixel bytes (0 when
 * either is NULL or malformed: NULL pixels with a size, a negative size, a
 * stride shorter than a row). */
int isk_canvas_equal(const isk_canvas *a, const isk_canvas *b);

/* How two canvases differ, over all four channels. */
typedef struct isk_canvas_diff {
    long pixels;        /* pixels compared (width x height) */
    long differing;     /* pixels with any channel different */
    int max_channel;    /* largest difference in one channel, 0..255 */
    double mean_abs;    /* mean absolute difference per channel */
} isk_canvas_diff;

/* Compares a with b pixel by pixel; returns 1 and fills *d (may be NULL)
 * when the sizes match, 0 (and a zeroed *d) when they do not.  If
 * diff_image is not NULL it must be max(width) x max(height) of the two:
 * it receives differing pixels (and pixels outside either canvas) in
 * opaque magenta and the others as a dimmed opaque copy of a, the
 * picture tests write next to a failing comparison. */
int isk_canvas_compare(const isk_canvas *a, const isk_canvas *b, isk_canvas_diff *d, isk_canvas *diff_image);

/* How many pixels of a and b (one size) have a channel that differs by more
 * than max_channel_diff (0..255; 0 counts every differing pixel): the rule
 * of a reference check's tolerance (iskra/refimg.h) and of `iskra compare
 * --max-channel-diff`.  -1 when either canvas is NULL or malformed, the
 * sizes differ, or max_channel_diff is outside 0..255. */
long isk_canvas_count_beyond(const isk_canvas *a, const isk_canvas *b, int max_channel_diff);

#ifdef __cplusplus
}
#endif

#endif
