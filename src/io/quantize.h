/* SPDX-License-Identifier: MIT */
/* src/io/quantize.h — one frame's 256-colour palette, for GIF output.
 *
 *     isk__quant q;
 *     if (isk__quant_init(&q, width * height) != ISK_OK) ...
 *     int n;  uint8_t pal[256 * 3], *idx = malloc(width * height);
 *     isk__quant_frame(&q, &canvas, pal, &n, idx);   // per frame
 *     isk__quant_free(&q);
 *
 * The method, deterministic by construction (integer arithmetic, every
 * tie broken by the packed colour value, so the same frame gives the same
 * bytes on every machine and libc):
 *   - a pixel's colour is its RGB composited over black (r * a / 255,
 *     rounded), since GIF frames here are opaque; opaque canvases are
 *     unchanged;
 *   - a frame with at most 256 distinct colours gets exactly those colours
 *     (sorted by value): the thesis scenes and most drawings are exact;
 *   - otherwise median cut over the distinct colours weighted by their
 *     pixel counts: the box whose longest channel range times pixel count
 *     is largest is split at the weighted median of that channel, until
 *     256 boxes; each box's colour is the count-weighted mean of its
 *     colours, and each pixel takes its box's colour.  No dithering: a
 *     dither pattern would crawl from frame to frame.
 * One palette per frame (GIF local colour tables), so a frame's colours
 * never depend on another frame's. */
#ifndef ISKRA_IO_QUANTIZE_H
#define ISKRA_IO_QUANTIZE_H

#include <stddef.h>
#include <stdint.h>

#include "iskra/canvas.h"
#include "iskra/status.h"

typedef struct isk__quant_entry {
    uint32_t rgb;    /* 0xRRGGBB */
    uint32_t count;  /* pixels of this colour */
    uint32_t index;  /* its palette entry */
} isk__quant_entry;

typedef struct isk__quant {
    size_t max_pixels;
    uint32_t *slots;          /* hash table: entry number + 1, 0 = empty */
    size_t nslots;
    isk__quant_entry *entries; /* distinct colours of the frame */
    size_t nentries;
    uint32_t *rgb;            /* each pixel's composited colour */
} isk__quant;

/* Room for frames of up to max_pixels pixels.  ISK_ERR_SIZE, ISK_ERR_NOMEM. */
isk_status isk__quant_init(isk__quant *q, size_t max_pixels);
void isk__quant_free(isk__quant *q);
/* The most isk__quant_init and isk__quant_frame hold at once for frames of
 * max_pixels pixels: the tables, and a frame's sort (its copy of the
 * colours with their keys). */
size_t isk__quant_bytes(size_t max_pixels);

/* Palette (n RGB triples, 1 <= n <= 256) and one index per pixel, row by
 * row, for a canvas of at most max_pixels pixels. */
isk_status isk__quant_frame(isk__quant *q, const isk_canvas *c, uint8_t palette[256 * 3], int *n, uint8_t *indices);

#endif
