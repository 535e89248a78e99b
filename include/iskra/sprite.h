/* SPDX-License-Identifier: MIT */
/* iskra/sprite.h — round particle sprites, baked once per kind/size/colour.
 *
 * The fire thesis draws each particle as a GL point sprite of S x S pixels,
 * either a flat "circle" or a "glowing" linear radial gradient (§5.9).  Here a
 * sprite is an alpha mask (uint8, 0..255) plus a colour, computed once and
 * reused, so drawing is table reads and integer blends.  Kinds, with d the
 * distance from a pixel centre to the sprite centre and S the size in pixels:
 *
 *   ISK_SPRITE_DISC    alpha = 1 if d < S/2 else 0 (strict, like
 *                      isk_fill_circle): the thesis's solid circle
 *   ISK_SPRITE_LINEAR  alpha = max(0, 1 - 2d/S): the thesis's gradient
 *                      shader (Listing 5.4) with GL's clamp made explicit, so
 *                      the square's corners contribute nothing
 *   ISK_SPRITE_SMOOTH  alpha = max(0, 1 - (2d/S)^2)^2: a soft falloff with
 *                      zero slope at the rim (no visible edge when many
 *                      overlap) and a rounder core than LINEAR
 *
 * mask = round(255 * alpha) (halves up); SMOOTH is exact integer arithmetic,
 * LINEAR uses one correctly rounded sqrt, so masks are identical everywhere.
 * Drawing scales the colour's alpha by the mask exactly like
 * isk_blend_pixel_cov(dst, colour, mask, mode) (iskra/blend.h), byte for byte.
 * With ISK_BLEND_ADD the result does not depend on draw order.
 *
 * Placement (snapping rule).  The centre (cx, cy) snaps to the nearest half
 * pixel: sx = the nearest multiple of 1/2 to cx, halves going up (computed
 * exactly, as floor(2 cx) plus one if 2 cx - floor(2 cx) >= 1/2), same for
 * y.  So a centre on a pixel centre (i + 0.5) or on a pixel corner (i) is used
 * exactly, and any other centre moves by at most 1/4 pixel.  Each sprite
 * holds four masks, one per phase (sx - S/2 whole or half, and the same for
 * y), all S x S; the mask's top-
 * left pixel is (floor(sx - S/2), floor(sy - S/2)).  Every pixel whose centre
 * lies within S/2 of (sx, sy) is in the mask.  Any coordinates are accepted:
 * the sprite is clipped to the canvas; NaN, +-Inf and huge values draw
 * nothing (never an out-of-range float->int conversion).
 *
 * Example: three glowing sprites, added:
 *
 *     isk_canvas canvas;
 *     if (isk_canvas_init(&canvas, 200, 100) != ISK_OK) return 1;
 *     isk_canvas_fill(&canvas, ISK_BLACK);
 *     double sx[] = {50, 90, 150.25}, sy[] = {50, 50, 49.5};
 *     size_t n = 3;
 *     isk_sprite_cache *cache;
 *     isk_status st = isk_sprite_cache_create(&cache, 64);
 *     const isk_sprite *spr;
 *     if (st == ISK_OK) st = isk_sprite_cache_get(cache, ISK_SPRITE_LINEAR, 32,
 *                                                 isk_rgba(255, 128, 0, 255), &spr);
 *     if (st == ISK_OK)
 *         for (size_t i = 0; i < n; i++)
 *             isk_draw_sprite(&canvas, spr, sx[i], sy[i], ISK_BLEND_ADD);
 *     isk_sprite_cache_destroy(cache);
 *     isk_canvas_free(&canvas);
 *     return st != ISK_OK;
 *
 * The cache holds at most `capacity` sprites (1..4096).  It never evicts: a
 * pointer it returned stays valid until isk_sprite_cache_clear() or _destroy(),
 * so a frame can hold many.  When full, get() returns ISK_ERR_FULL and bakes
 * nothing; call clear() (e.g. between frames after a zoom change) and retry.
 * Memory per sprite is 20 S^2 + 32 S bytes (four phase masks, their
 * additive increment images and row spans) plus about 1.1 KB.
 * No global state: caches are independent.
 */
#ifndef ISKRA_SPRITE_H
#define ISKRA_SPRITE_H

#include <stddef.h>
#include <stdint.h>

#include "iskra/blend.h"
#include "iskra/canvas.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ISK_SPRITE_MAX_SIZE 256
#define ISK_SPRITE_CACHE_MAX 4096

typedef enum isk_sprite_kind {
    ISK_SPRITE_DISC = 0,
    ISK_SPRITE_LINEAR = 1,
    ISK_SPRITE_SMOOTH = 2,
    ISK_SPRITE_KIND_COUNT
} isk_sprite_kind;

/* Names as scene files spell them, indexed by kind: "disc", "linear", "smooth". */
extern const char *const isk_sprite_kind_names[ISK_SPRITE_KIND_COUNT];

typedef struct isk_sprite {
    isk_sprite_kind kind;
    int size;                 /* S, 1..256 */
    isk_color color;
    /* mask[p]: S*S bytes, row-major, p = (sx - S/2 is not whole)
     * + 2 (sy - S/2 is not whole): phase 0 is centred on a pixel centre for
     * odd S and on a pixel corner for even S. */
    uint8_t *mask[4];
    /* span[p][2*row], span[p][2*row+1]: first and one-past-last column with a
     * non-zero mask in that row (equal when the row is empty). */
    uint16_t *span[4];
    /* vspan[p]: the same spans grown over zero-mask pixels of the row to a
     * multiple of 4 pixels where the row allows (the row kernels' step). */
    uint16_t *vspan[4];
    /* For mask value m: the source alpha a' = div255(color.a * m) and the
     * additive increments div255(c * a') — what isk_blend_pixel_cov computes. */
    uint8_t lut[256][4];      /* r, g, b increments, a' */
    /* inc[p]: S*S*4 bytes, lut[mask[p][k]] for every pixel k: the baked
     * colour's additive increments, so an additive draw is a byte add. */
    uint8_t *inc[4];
} isk_sprite;

/* Bakes a sprite into memory it owns (release with isk_sprite_free).
 * ISK_ERR_NULL, ISK_ERR_RANGE (kind), ISK_ERR_SIZE (size outside 1..256),
 * ISK_ERR_NOMEM. */
isk_status isk_sprite_init(isk_sprite *s, isk_sprite_kind kind, int size, isk_color color);
void isk_sprite_free(isk_sprite *s);

/* The analytic alpha (0..1) of a kind at distance d for size S, the value the
 * masks round; 0 for an invalid kind. */
double isk_sprite_alpha(isk_sprite_kind kind, double d, int size);

/* Draws the sprite centred at (cx, cy) (see the snapping rule above). */
void isk_draw_sprite(isk_canvas *c, const isk_sprite *s, double cx, double cy, isk_blend mode);

/* Draws the sprite's mask in another colour: every covered pixel gets
 * isk_blend_pixel_cov(dst, color, mask, mode), byte for byte, whatever
 * colour the sprite was baked with.  So one baked mask per (kind, size)
 * serves every colour of an over-life colour ramp (no bake per colour).
 * With the sprite's own colour it gives exactly what isk_draw_sprite gives.
 * Placement and clipping as isk_draw_sprite. */
void isk_draw_sprite_tinted(isk_canvas *c, const isk_sprite *s, double cx, double cy, isk_color color,
                            isk_blend mode);

typedef struct isk_sprite_cache isk_sprite_cache;

/* capacity: most sprites held at once, 1..ISK_SPRITE_CACHE_MAX. */
isk_status isk_sprite_cache_create(isk_sprite_cache **out, int capacity);
void isk_sprite_cache_destroy(isk_sprite_cache *cache);

/* The sprite for (kind, size, colour), baked on first request.  Errors as
 * isk_sprite_init, plus ISK_ERR_FULL when a new sprite would exceed the
 * capacity.  *out is set only on success. */
isk_status isk_sprite_cache_get(isk_sprite_cache *cache, isk_sprite_kind kind, int size, isk_color color,
                                const isk_sprite **out);

/* Frees every sprite; earlier pointers become invalid. */
void isk_sprite_cache_clear(isk_sprite_cache *cache);

/* Sprites held, and sprites baked since creation (for tests and stats). */
int isk_sprite_cache_count(const isk_sprite_cache *cache);
long isk_sprite_cache_bakes(const isk_sprite_cache *cache);

#ifdef __cplusplus
}
#endif

#endif
