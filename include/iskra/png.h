/* SPDX-License-Identifier: MIT */
/* iskra/png.h — write and read canvases as PNG files (libpng).
 *
 * Example: a canvas written, then read back:
 *
 *     isk_canvas canvas, img;
 *     if (isk_canvas_init(&canvas, 64, 48) != ISK_OK) return 1;
 *     isk_canvas_fill(&canvas, isk_rgba(255, 128, 0, 200));
 *     isk_error err;
 *     if (isk_png_write(&canvas, "frame.png", &err) != ISK_OK
 *             || isk_png_read(&img, "frame.png", &err) != ISK_OK) {
 *         fprintf(stderr, "%s\n", err.message);
 *         return 1;
 *     }
 *     int same = isk_canvas_equal(&canvas, &img);      // 1: the very bytes
 *     isk_canvas_free(&img);
 *     isk_canvas_free(&canvas);
 *     return !same;
 *
 * Writing goes through iskra/outfile.h: to a temporary file renamed over
 * the target only when complete (a failure never leaves a half-written PNG
 * and never destroys an existing file); a symlink is followed, /dev/null or
 * a FIFO is written through, never replaced.  Output is 8-bit RGBA,
 * non-interlaced, the canvas's bytes exactly.
 *
 * Reading accepts every PNG colour type, bit depth and interlacing and
 * gives straight RGBA8, as the PNG specification and common readers
 * (browsers without colour management, GIMP, ImageMagick) do:
 *   - 1, 2 and 4-bit grey is scaled to 0..255 exactly (v * 255 / (2^d - 1));
 *   - 16-bit samples are scaled by 1/257 with rounding, round(v / 257):
 *     no gamma is applied, whatever gAMA, sRGB, cHRM or iCCP say (they are
 *     skipped, as are text and every other ancillary chunk but tRNS);
 *   - a palette gives its colours, tRNS its alpha (opaque otherwise);
 *   - grey and RGB get alpha 255, or 0 for the tRNS colour key.
 * Reading is bounded: width and height at most ISK_CANVAS_MAX_DIM, at most
 * `max_pixels` pixels decoded (checked from the header before anything is
 * allocated), ancillary chunks skipped without being stored, libpng's
 * chunk allocations capped.  A hostile file costs at most the canvas it
 * declares.  Nothing is printed: libpng's messages go into `err`.
 */
#ifndef ISKRA_PNG_H
#define ISKRA_PNG_H

#include <stddef.h>
#include <stdio.h>

#include "iskra/canvas.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* isk_png_read's cap on decoded pixels: 8192 x 8192 = 64 Mpx (256 MiB of
 * RGBA).  isk_png_read_max takes any cap up to ISK_CANVAS_MAX_DIM^2. */
#define ISK_PNG_MAX_PIXELS_DEFAULT (8192LL * 8192LL)

/* Errors: ISK_ERR_NULL, ISK_ERR_SIZE (empty or malformed canvas), ISK_ERR_IO
 * (see iskra/outfile.h), ISK_ERR_NOMEM. */
isk_status isk_png_write(const isk_canvas *c, const char *path, isk_error *err);

/* Writes the PNG to an open stream (left open); `name` labels messages. */
isk_status isk_png_write_stream(const isk_canvas *c, FILE *f, const char *name, isk_error *err);

/* The most memory isk_png_write holds at once for rows `width` pixels
 * wide, in bytes: libpng's row buffers (one row at a time; the filters'
 * trials) and zlib's compressor; the image itself is never copied.  For a
 * program's memory budget (isk_effect_def.host_memory); 0 for width < 1. */
size_t isk_png_write_memory(int width);

/* What a PNG's header says, read without decoding any pixels. */
typedef struct isk_png_info {
    int width, height;
    int bit_depth;     /* 1, 2, 4, 8 or 16 */
    int color_type;    /* PNG's: 0 grey, 2 RGB, 3 palette, 4 grey+alpha, 6 RGBA */
    int interlaced;    /* 1: Adam7 */
} isk_png_info;

/* Errors: ISK_ERR_NULL, ISK_ERR_IO (cannot open or read), ISK_ERR_FORMAT
 * (not a PNG, bad header), ISK_ERR_SIZE (width or height 0 or above
 * ISK_CANVAS_MAX_DIM). */
isk_status isk_png_read_info(const char *path, isk_png_info *info, isk_error *err);

/* Reads `path` into a newly initialised canvas (free with isk_canvas_free),
 * decoding at most ISK_PNG_MAX_PIXELS_DEFAULT pixels.  Errors: as
 * isk_png_read_info, ISK_ERR_SIZE when the image has more pixels than the
 * cap, ISK_ERR_FORMAT for corrupt data, ISK_ERR_NOMEM.  On error the canvas
 * is zeroed. */
isk_status isk_png_read(isk_canvas *out, const char *path, isk_error *err);

/* The same with another cap, 1 .. ISK_CANVAS_MAX_DIM^2 (ISK_ERR_RANGE
 * otherwise). */
isk_status isk_png_read_max(isk_canvas *out, const char *path, long long max_pixels, isk_error *err);

/* The same from `size` bytes in memory (`name` labels messages). */
isk_status isk_png_read_memory(isk_canvas *out, const void *data, size_t size, const char *name,
                               long long max_pixels, isk_error *err);

#ifdef __cplusplus
}
#endif

#endif
