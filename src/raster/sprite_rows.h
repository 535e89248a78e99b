/* SPDX-License-Identifier: MIT */
/* src/raster/sprite_rows.h — a sprite drawn on a band of canvas rows
 * (internal; the renderer's threads each take a band).
 *
 *     isk__draw_sprite_rows(c, s, cx, cy, NULL, mode, r0, r1);   // isk_draw_sprite
 *     isk__draw_sprite_rows(c, s, cx, cy, &tint, mode, r0, r1);  // isk_draw_sprite_tinted
 *
 * draws exactly the pixels of rows [r0, r1) that the whole call would,
 * with the same bytes: the sprite is placed on the whole canvas and only
 * its row range is cut.  Bands covering the canvas therefore give the bytes
 * of one call, in any order. */
#ifndef ISKRA_RASTER_SPRITE_ROWS_H
#define ISKRA_RASTER_SPRITE_ROWS_H

#include "iskra/sprite.h"

void isk__draw_sprite_rows(isk_canvas *c, const isk_sprite *s, double cx, double cy, const isk_color *tint,
                           isk_blend mode, int r0, int r1);

#endif
