/* SPDX-License-Identifier: MIT */
/* iskra/texture_png.h — textures from PNG files and PNG bytes.
 *
 * The texture module (iskra/texture.h, src/raster) reads no file; these
 * readers (src/io) decode the PNG through iskra/png.h and hand it the
 * pixels.  Each checks the PNG's header before decoding anything: at most
 * ISK_TEXTURE_MAX_DIM a side, and a grid that divides the image
 * (isk_texture_check_size's rules), so a file too large is refused
 * unread.  Every message names the file (or `name`) and the problem.
 *
 * Example: a sheet of two frames written as a PNG, then loaded:
 *
 *     isk_canvas img;
 *     if (isk_canvas_init(&img, 32, 16) != ISK_OK) return 1;
 *     isk_canvas_fill(&img, isk_rgba(255, 160, 40, 255));
 *     isk_error err;
 *     isk_status st = isk_png_write(&img, "sheet.png", &err);
 *     isk_canvas_free(&img);
 *     isk_texture tex;
 *     if (st == ISK_OK) st = isk_texture_load(&tex, "sheet.png", 2, 1, &err);
 *     if (st != ISK_OK) { fprintf(stderr, "%s\n", err.message); return 1; }
 *     int frames = tex.frames;                       // 2, each 16 x 16
 *     isk_texture_free(&tex);
 *     return frames != 2;
 */
#ifndef ISKRA_TEXTURE_PNG_H
#define ISKRA_TEXTURE_PNG_H

#include <stddef.h>

#include "iskra/canvas.h"
#include "iskra/png.h"
#include "iskra/status.h"
#include "iskra/texture.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What isk_texture_load would refuse, from the file's header alone (no
 * decoding): ISK_ERR_NULL, ISK_ERR_IO, ISK_ERR_FORMAT (iskra/png.h's),
 * ISK_ERR_SIZE, ISK_ERR_RANGE (a grid out of range or one the image does
 * not divide). */
isk_status isk_texture_check_file(const char *png_path, int cols, int rows, isk_error *err);

/* The pixels a texture is made of: `png_path` decoded into a new canvas
 * (straight RGBA8, free with isk_canvas_free), refused when a side exceeds
 * ISK_TEXTURE_MAX_DIM (from the header, before decoding).  Errors as
 * isk_texture_check_file; on error *out is zeroed. */
isk_status isk_texture_image_read(isk_canvas *out, const char *png_path, isk_error *err);

/* The same from `size` bytes of PNG in memory; `name` labels the messages. */
isk_status isk_texture_image_read_memory(isk_canvas *out, const void *png, size_t size, const char *name,
                                         isk_error *err);

/* Reads `png_path` into *t (which then owns its memory: isk_texture_free);
 * errors as isk_texture_check_file, and ISK_ERR_NOMEM.  On error *t is
 * zeroed. */
isk_status isk_texture_load(isk_texture *t, const char *png_path, int cols, int rows, isk_error *err);

/* The same from `size` bytes of PNG in memory (a texture built into a
 * program); `name` labels the messages. */
isk_status isk_texture_load_memory(isk_texture *t, const void *png, size_t size, const char *name, int cols, int rows,
                                   isk_error *err);

/* The cache's texture of (png_path, cols, rows) (iskra/texture.h), read
 * from the file on the first request: isk_texture_cache_get_canvas with
 * the file's pixels, errors as isk_texture_load's. */
isk_status isk_texture_cache_get(isk_texture_cache *cache, const char *png_path, int cols, int rows,
                                 const isk_texture **out, isk_error *err);

/* The same for a PNG in memory, kept under `name` (a path or any name: a
 * later _get or _get_memory of that name and grid finds it). */
isk_status isk_texture_cache_get_memory(isk_texture_cache *cache, const char *name, const void *png, size_t size,
                                        int cols, int rows, const isk_texture **out, isk_error *err);

#ifdef __cplusplus
}
#endif

#endif
