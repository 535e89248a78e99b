/* SPDX-License-Identifier: MIT */
/* src/raster/texture_rows.h — a textured sprite drawn on a band of canvas
 * rows (internal; the renderer's threads each take a band).
 *
 *     isk__draw_texture_rows(c, t, frame, cx, cy, w, h, angle, tint, mode, r0, r1, 0);
 *
 * draws exactly the pixels of rows [r0, r1) that isk_draw_texture with the
 * same arguments would, with the same bytes: the sprite is placed on the
 * whole canvas (the fixed-point mapping of iskra/texture.h never depends on
 * the rows drawn) and only its row range is cut.  Bands covering the canvas
 * therefore give the bytes of one call, in any order.  r0 and r1 are
 * clamped to the canvas.
 *
 * `paths` forces slower code paths for tests (0 in real use), which must
 * give the same bytes: ISK__TEXTURE_GENERAL draws an axis-aligned sprite
 * with the rotated code instead of the blit, ISK__TEXTURE_SCALAR uses the
 * portable per-channel arithmetic instead of the SIMD kernels,
 * ISK__TEXTURE_NO_AVX2 the SSE2 kernels where the CPU has AVX2. */
#ifndef ISKRA_RASTER_TEXTURE_ROWS_H
#define ISKRA_RASTER_TEXTURE_ROWS_H

#include "iskra/texture.h"

/* Zeroed bytes after a texture's last texel (a vector read at a row's end
 * stays inside the allocation). */
#define ISK__TEXTURE_SLACK 64

enum { ISK__TEXTURE_GENERAL = 1, ISK__TEXTURE_SCALAR = 2, ISK__TEXTURE_NO_AVX2 = 4 };

void isk__draw_texture_rows(isk_canvas *c, const isk_texture *t, int frame, double cx, double cy, double width,
                            double height, double angle, isk_color tint, isk_blend mode, int r0, int r1, int paths);

#endif
