/* SPDX-License-Identifier: MIT */
/* Textures from PNG files and PNG bytes (iskra/texture_png.h): the header
 * checked by the texture module's rules, then the pixels decoded by the
 * bounded reader of iskra/png.h and handed to the texture module. */
#include "iskra/texture_png.h"

#include <string.h>

#include "raster/texture_cache.h"

/* Decoding never goes past the largest image a texture takes. */
#define MAX_PIXELS ((long long)ISK_TEXTURE_MAX_DIM * ISK_TEXTURE_MAX_DIM)

/* The grid's own rule (an image of cols x rows pixels meets every other). */
static isk_status check_grid(const char *name, int cols, int rows, isk_error *err)
{
    return isk_texture_check_size(name, cols, rows, cols, rows, err);
}

isk_status isk_texture_check_file(const char *png_path, int cols, int rows, isk_error *err)
{
    if (!png_path)
        return isk_error_set(err, ISK_ERR_NULL, "texture: NULL path");
    /* the grid first: no file is opened for a grid that cannot be */
    isk_status st = check_grid(png_path, cols, rows, err);
    if (st != ISK_OK)
        return st;
    isk_png_info info;
    if ((st = isk_png_read_info(png_path, &info, err)) != ISK_OK)
        return st;
    return isk_texture_check_size(png_path, info.width, info.height, cols, rows, err);
}

isk_status isk_texture_image_read(isk_canvas *out, const char *png_path, isk_error *err)
{
    if (out)
        memset(out, 0, sizeof *out);
    if (!out || !png_path)
        return isk_error_set(err, ISK_ERR_NULL, "texture: NULL %s", out ? "path" : "image");
    /* the header first: a file too large is refused before it is decoded */
    isk_status st = isk_texture_check_file(png_path, 1, 1, err);
    return st != ISK_OK ? st : isk_png_read_max(out, png_path, MAX_PIXELS, err);
}

isk_status isk_texture_image_read_memory(isk_canvas *out, const void *png, size_t size, const char *name,
                                         isk_error *err)
{
    if (out)
        memset(out, 0, sizeof *out);
    if (!out || !png || !name)
        return isk_error_set(err, ISK_ERR_NULL, "texture: NULL %s", !out ? "image" : !png ? "data" : "name");
    isk_status st = isk_png_read_memory(out, png, size, name, MAX_PIXELS, err);
    if (st == ISK_OK && (st = isk_texture_check_size(name, out->width, out->height, 1, 1, err)) != ISK_OK)
        isk_canvas_free(out);
    return st;
}

/* A PNG for a texture: a file (png == NULL) or bytes. */
typedef struct png_source {
    const void *png;
    size_t size;
} png_source;

static isk_status load(void *ctx, isk_texture *t, const char *name, int cols, int rows, isk_error *err)
{
    const png_source *src = ctx;
    memset(t, 0, sizeof *t);
    /* the grid, and a file's header, before any pixel is decoded */
    isk_status st = src->png ? check_grid(name, cols, rows, err) : isk_texture_check_file(name, cols, rows, err);
    if (st != ISK_OK)
        return st;
    isk_canvas img;
    st = src->png ? isk_png_read_memory(&img, src->png, src->size, name, MAX_PIXELS, err)
                  : isk_png_read_max(&img, name, MAX_PIXELS, err);
    if (st != ISK_OK)
        return st;
    st = isk__texture_from_image(t, &img, name, cols, rows, err);
    isk_canvas_free(&img);
    return st;
}

isk_status isk_texture_load(isk_texture *t, const char *png_path, int cols, int rows, isk_error *err)
{
    if (t)
        memset(t, 0, sizeof *t);
    if (!t || !png_path)
        return isk_error_set(err, ISK_ERR_NULL, "texture: NULL %s", t ? "path" : "texture");
    png_source file = {NULL, 0};
    return load(&file, t, png_path, cols, rows, err);
}

isk_status isk_texture_load_memory(isk_texture *t, const void *png, size_t size, const char *name, int cols, int rows,
                                   isk_error *err)
{
    if (t)
        memset(t, 0, sizeof *t);
    if (!t || !png || !name)
        return isk_error_set(err, ISK_ERR_NULL, "texture: NULL %s", !t ? "texture" : !png ? "data" : "name");
    png_source bytes = {png, size};
    return load(&bytes, t, name, cols, rows, err);
}

isk_status isk_texture_cache_get(isk_texture_cache *c, const char *png_path, int cols, int rows,
                                 const isk_texture **out, isk_error *err)
{
    png_source file = {NULL, 0};
    return isk__texture_cache_get(c, png_path, cols, rows, load, &file, out, err);
}

isk_status isk_texture_cache_get_memory(isk_texture_cache *c, const char *name, const void *png, size_t size, int cols,
                                        int rows, const isk_texture **out, isk_error *err)
{
    if (!png)
        return isk_error_set(err, ISK_ERR_NULL, "texture cache: NULL data");
    png_source bytes = {png, size};
    return isk__texture_cache_get(c, name, cols, rows, load, &bytes, out, err);
}
