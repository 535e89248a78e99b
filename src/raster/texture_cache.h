/* SPDX-License-Identifier: MIT */
/* src/raster/texture_cache.h — what the texture readers of other modules
 * share with the texture module (internal).
 *
 *     isk__texture_from_image(&t, &img, "spark.png", 4, 2, &err);
 *
 * makes a texture as isk_texture_from_canvas does, with a message naming
 * the texture (isk_texture_check_size's); and
 *
 *     isk__texture_cache_get(cache, "spark.png", 4, 2, make, ctx, &out, &err);
 *
 * is the cache's one lookup: the texture held under (name, cols, rows), or
 * on a miss the one `make` writes into *t, kept.  The cache knows no file
 * format: iskra/texture_png.h (src/io) passes a maker that decodes a PNG,
 * isk_texture_cache_get_canvas one that copies a canvas. */
#ifndef ISKRA_RASTER_TEXTURE_CACHE_H
#define ISKRA_RASTER_TEXTURE_CACHE_H

#include "iskra/texture.h"

isk_status isk__texture_from_image(isk_texture *t, const isk_canvas *img, const char *name, int cols, int rows,
                                   isk_error *err);

/* Makes the texture of (name, cols, rows) into *t (zeroed on error), with
 * a message in err. */
typedef isk_status (*isk__texture_maker)(void *ctx, isk_texture *t, const char *name, int cols, int rows,
                                         isk_error *err);

isk_status isk__texture_cache_get(isk_texture_cache *cache, const char *name, int cols, int rows,
                                  isk__texture_maker make, void *ctx, const isk_texture **out, isk_error *err);

#endif
