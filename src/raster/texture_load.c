/* SPDX-License-Identifier: MIT */
/* Textures from PNG files (isk_texture_load) and the cache that loads each
 * file once (iskra/texture.h).  The one part of the texture module that
 * reads files: it uses the bounded PNG reader of iskra/png.h (src/io). */
#include "iskra/texture.h"

#include <stdlib.h>
#include <string.h>

#include "iskra/png.h"

/* The checks every load makes: a grid of 1..ISK_TEXTURE_MAX_GRID, an image
 * of at most ISK_TEXTURE_MAX_DIM a side that the grid divides. */
static isk_status check_grid(const char *name, int cols, int rows, isk_error *err)
{
    if (cols < 1 || cols > ISK_TEXTURE_MAX_GRID || rows < 1 || rows > ISK_TEXTURE_MAX_GRID)
        return isk_error_set(err, ISK_ERR_RANGE, "texture %s: a grid of %d x %d frames (cols and rows must be 1..%d)",
                             name, cols, rows, ISK_TEXTURE_MAX_GRID);
    return ISK_OK;
}

static isk_status check_image(const char *name, int width, int height, int cols, int rows, isk_error *err)
{
    if (width > ISK_TEXTURE_MAX_DIM || height > ISK_TEXTURE_MAX_DIM)
        return isk_error_set(err, ISK_ERR_SIZE, "texture %s: %d x %d pixels, larger than %d a side", name, width,
                             height, ISK_TEXTURE_MAX_DIM);
    if (width % cols != 0 || height % rows != 0)
        return isk_error_set(err, ISK_ERR_RANGE,
                             "texture %s: %d x %d pixels do not divide into %d x %d frames (cols must divide the "
                             "width, rows the height)",
                             name, width, height, cols, rows);
    return ISK_OK;
}

static isk_status from_image(isk_texture *t, isk_canvas *img, const char *name, int cols, int rows, isk_error *err)
{
    isk_status st = check_image(name, img->width, img->height, cols, rows, err);
    if (st == ISK_OK && (st = isk_texture_from_canvas(t, img, cols, rows)) != ISK_OK)
        isk_error_set(err, st, "texture %s: %s", name, isk_status_str(st));
    isk_canvas_free(img);
    return st;
}

isk_status isk_texture_check_file(const char *png_path, int cols, int rows, isk_error *err)
{
    if (!png_path)
        return isk_error_set(err, ISK_ERR_NULL, "texture: NULL path");
    isk_status st = check_grid(png_path, cols, rows, err);
    if (st != ISK_OK)
        return st;
    isk_png_info info;
    if ((st = isk_png_read_info(png_path, &info, err)) != ISK_OK)
        return st;
    return check_image(png_path, info.width, info.height, cols, rows, err);
}

isk_status isk_texture_load(isk_texture *t, const char *png_path, int cols, int rows, isk_error *err)
{
    if (t)
        memset(t, 0, sizeof *t);
    if (!t || !png_path)
        return isk_error_set(err, ISK_ERR_NULL, "texture: NULL %s", t ? "path" : "texture");
    /* the header first: a file too large is refused before it is decoded */
    isk_status st = isk_texture_check_file(png_path, cols, rows, err);
    if (st != ISK_OK)
        return st;
    isk_canvas img;
    st = isk_png_read_max(&img, png_path, (long long)ISK_TEXTURE_MAX_DIM * ISK_TEXTURE_MAX_DIM, err);
    return st != ISK_OK ? st : from_image(t, &img, png_path, cols, rows, err);
}

isk_status isk_texture_load_memory(isk_texture *t, const void *png, size_t size, const char *name, int cols, int rows,
                                   isk_error *err)
{
    if (t)
        memset(t, 0, sizeof *t);
    if (!t || !png || !name)
        return isk_error_set(err, ISK_ERR_NULL, "texture: NULL %s", !t ? "texture" : !png ? "data" : "name");
    isk_status st = check_grid(name, cols, rows, err);
    if (st != ISK_OK)
        return st;
    isk_canvas img;
    st = isk_png_read_memory(&img, png, size, name, (long long)ISK_TEXTURE_MAX_DIM * ISK_TEXTURE_MAX_DIM, err);
    return st != ISK_OK ? st : from_image(t, &img, name, cols, rows, err);
}

/* ---- cache --------------------------------------------------------------
 * A handful of textures per scene: a linear search over (path, grid). */

typedef struct entry {
    char *path;
    int cols, rows;
    isk_texture *tex;
} entry;

struct isk_texture_cache {
    int capacity, count;
    long loads;
    entry *items;
};

isk_status isk_texture_cache_create(isk_texture_cache **out, int capacity)
{
    if (!out)
        return ISK_ERR_NULL;
    *out = NULL;
    if (capacity < 1 || capacity > ISK_TEXTURE_CACHE_MAX)
        return ISK_ERR_SIZE;
    isk_texture_cache *c = calloc(1, sizeof *c);
    if (!c)
        return ISK_ERR_NOMEM;
    c->items = calloc((size_t)capacity, sizeof *c->items);
    if (!c->items) {
        free(c);
        return ISK_ERR_NOMEM;
    }
    c->capacity = capacity;
    *out = c;
    return ISK_OK;
}

void isk_texture_cache_clear(isk_texture_cache *c)
{
    if (!c)
        return;
    for (int i = 0; i < c->count; i++) {
        isk_texture_free(c->items[i].tex);
        free(c->items[i].tex);
        free(c->items[i].path);
    }
    memset(c->items, 0, (size_t)c->capacity * sizeof *c->items);
    c->count = 0;
}

void isk_texture_cache_destroy(isk_texture_cache *c)
{
    if (!c)
        return;
    isk_texture_cache_clear(c);
    free(c->items);
    free(c);
}

/* The cache's one lookup: (key, cols, rows), loaded from the file `key`
 * or, with png != NULL, from those bytes. */
static isk_status cache_get(isk_texture_cache *c, const char *key, const void *png, size_t size, int cols, int rows,
                            const isk_texture **out, isk_error *err)
{
    if (!c || !key || !out)
        return isk_error_set(err, ISK_ERR_NULL, "texture cache: NULL %s", !c ? "cache" : !key ? "path" : "out");
    for (int i = 0; i < c->count; i++)
        if (c->items[i].cols == cols && c->items[i].rows == rows && strcmp(c->items[i].path, key) == 0) {
            *out = c->items[i].tex;
            return ISK_OK;
        }
    if (c->count >= c->capacity)
        return isk_error_set(err, ISK_ERR_FULL, "texture %s: the cache already holds its %d textures", key,
                             c->capacity);
    size_t len = strlen(key);
    entry e = {malloc(len + 1), cols, rows, malloc(sizeof(isk_texture))};
    if (!e.path || !e.tex) {
        free(e.path);
        free(e.tex);
        return isk_error_set(err, ISK_ERR_NOMEM, "texture %s: out of memory", key);
    }
    memcpy(e.path, key, len + 1);
    isk_status st = png ? isk_texture_load_memory(e.tex, png, size, key, cols, rows, err)
                        : isk_texture_load(e.tex, key, cols, rows, err);
    if (st != ISK_OK) {
        free(e.path);
        free(e.tex);
        return st;
    }
    c->loads++;
    c->items[c->count++] = e;
    *out = e.tex;
    return ISK_OK;
}

isk_status isk_texture_cache_get(isk_texture_cache *c, const char *png_path, int cols, int rows,
                                 const isk_texture **out, isk_error *err)
{
    return cache_get(c, png_path, NULL, 0, cols, rows, out, err);
}

isk_status isk_texture_cache_get_memory(isk_texture_cache *c, const char *name, const void *png, size_t size, int cols,
                                        int rows, const isk_texture **out, isk_error *err)
{
    if (!png)
        return isk_error_set(err, ISK_ERR_NULL, "texture cache: NULL data");
    return cache_get(c, name, png, size, cols, rows, out, err);
}

int isk_texture_cache_count(const isk_texture_cache *c)
{
    return c ? c->count : 0;
}

long isk_texture_cache_loads(const isk_texture_cache *c)
{
    return c ? c->loads : 0;
}
