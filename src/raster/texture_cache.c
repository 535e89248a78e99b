/* SPDX-License-Identifier: MIT */
/* The texture cache (iskra/texture.h): textures kept by (name, grid), each
 * made once.  It reads no file: what a miss makes a texture from is the
 * caller's (a canvas here, a PNG in src/io/texture_png.c), through a maker
 * (raster/texture_cache.h).  A handful of textures per scene: a linear
 * search. */
#include <stdlib.h>
#include <string.h>

#include "raster/texture_cache.h"

typedef struct entry {
    char *name;
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
        free(c->items[i].name);
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

isk_status isk__texture_cache_get(isk_texture_cache *c, const char *name, int cols, int rows,
                                  isk__texture_maker make, void *ctx, const isk_texture **out, isk_error *err)
{
    if (!c || !name || !out)
        return isk_error_set(err, ISK_ERR_NULL, "texture cache: NULL %s", !c ? "cache" : !name ? "name" : "out");
    for (int i = 0; i < c->count; i++)
        if (c->items[i].cols == cols && c->items[i].rows == rows && strcmp(c->items[i].name, name) == 0) {
            *out = c->items[i].tex;
            return ISK_OK;
        }
    if (c->count >= c->capacity)
        return isk_error_set(err, ISK_ERR_FULL, "texture %s: the cache already holds its %d textures", name,
                             c->capacity);
    size_t len = strlen(name);
    entry e = {malloc(len + 1), cols, rows, malloc(sizeof(isk_texture))};
    if (!e.name || !e.tex) {
        free(e.name);
        free(e.tex);
        return isk_error_set(err, ISK_ERR_NOMEM, "texture %s: out of memory", name);
    }
    memcpy(e.name, name, len + 1);
    isk_status st = make(ctx, e.tex, name, cols, rows, err);
    if (st != ISK_OK) {
        free(e.name);
        free(e.tex);
        return st;
    }
    c->loads++;
    c->items[c->count++] = e;
    *out = e.tex;
    return ISK_OK;
}

/* The maker of isk_texture_cache_get_canvas: a copy of the canvas. */
static isk_status from_canvas(void *img, isk_texture *t, const char *name, int cols, int rows, isk_error *err)
{
    return isk__texture_from_image(t, img, name, cols, rows, err);
}

isk_status isk_texture_cache_get_canvas(isk_texture_cache *c, const char *name, const isk_canvas *img, int cols,
                                        int rows, const isk_texture **out, isk_error *err)
{
    if (!img)
        return isk_error_set(err, ISK_ERR_NULL, "texture cache: NULL image");
    return isk__texture_cache_get(c, name, cols, rows, from_canvas, (void *)img, out, err);
}

int isk_texture_cache_count(const isk_texture_cache *c)
{
    return c ? c->count : 0;
}

long isk_texture_cache_loads(const isk_texture_cache *c)
{
    return c ? c->loads : 0;
}
