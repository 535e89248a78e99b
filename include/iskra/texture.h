/* SPDX-License-Identifier: MIT */
/* iskra/texture.h — RGBA images drawn as particle sprites: scaled, rotated,
 * tinted, optionally one frame of a sprite sheet (a flipbook).
 *
 * A texture is made once from a canvas (isk_texture_from_canvas) or a round
 * sprite kind (isk_texture_from_sprite, for streaks), and drawn any number
 * of times (docs/textures.md: the API together, memory, costs).  This
 * module reads no file: textures from PNG files or PNG bytes are
 * iskra/texture_png.h's (src/io), which decodes them and hands the pixels
 * here.
 *
 * Example (a sheet of two frames, the second drawn stretched and turned):
 *
 *     isk_canvas img, c;
 *     if (isk_canvas_init(&img, 32, 16) != ISK_OK) return 1;
 *     isk_canvas_fill(&img, isk_rgba(255, 160, 40, 255));  // two 16x16 frames
 *     isk_texture tex;
 *     isk_status st = isk_texture_from_canvas(&tex, &img, 2, 1);
 *     isk_canvas_free(&img);  // the texture holds its own copy
 *     if (st != ISK_OK) return 1;
 *     if (isk_canvas_init(&c, 64, 64) != ISK_OK) { isk_texture_free(&tex); return 1; }
 *     isk_canvas_fill(&c, ISK_BLACK);
 *     isk_draw_texture(&c, &tex, 1, 32.0, 32.0, 24.0, 8.0, 0.5, ISK_WHITE, ISK_BLEND_ADD);
 *     isk_texture_free(&tex);
 *     isk_canvas_free(&c);
 *
 * A sprite sheet of cols x rows frames: frame k (row-major, 0 = top-left)
 * is the image's cell (k % cols, k / cols), frame_w = width / cols by
 * frame_h = height / rows texels; cols and rows must divide the image
 * exactly (ISK_ERR_RANGE otherwise: nothing is guessed or cropped).
 *
 * What is kept (memory).  Each frame separately, premultiplied
 * (p = div255(c * a), iskra/blend.h), with a one-texel transparent border
 * and its mip levels: level 0 is the frame, level l + 1 halves level l
 * (sides (w + 1) / 2, each texel the rounded average (sum + 2) / 4 of a
 * 2x2 block of premultiplied texels, an odd side repeating its last one),
 * down to 1 x 1.  Frames never share a texel, so neighbouring frames never
 * bleed into each other.  Memory: the sum over frames and levels of
 * 4 (w_l + 2)(h_l + 2) bytes, plus 64 bytes and sizeof(isk_texture): the
 * image's 4 w h bytes times 4/3 for the levels, plus the borders (a 64x64
 * image: 24 KB, 1.46x; 512x512: 1.35x; a 256x256 sheet of 8x8 frames of
 * 32x32: 420 KB, 1.60x).
 *
 * Drawing (isk_draw_texture).  Frame `frame` (clamped into 0 .. frames-1,
 * so a flipbook index floor(t * frames) may reach `frames` at t = 1) is
 * centred at the screen point (cx, cy), scaled to width x height pixels and
 * turned by `angle` radians: the image's x axis (left to right) points along
 * (cos angle, sin angle) on screen.  Screen y grows down, so a positive
 * angle turns the image clockwise as seen; a particle moving with screen
 * velocity (vx, vy) is aligned by angle = atan2(vy, vx) (its length along
 * `width`).  The rule (integer and exact from the fixed-point step on):
 *
 *   level    f = max(frame_w / width, frame_h / height) texels per pixel;
 *            L = the largest l < levels with 2^l <= f (0 when f < 2), so
 *            the level drawn has 1 to 2 texels per pixel (more only when
 *            the 1x1 level is reached); wL x hL its size
 *   mapping  su = wL / width, sv = hL / height, c = cos angle, s = sin angle
 *            (libm; angle 0 uses c = 1, s = 0 without a call);
 *            u = c su dx + s su dy + wL / 2,  v = -s sv dx + c sv dy + hL / 2
 *            for the offset (dx, dy) of a pixel centre from (cx, cy), in
 *            double, products formed as written, left to right
 *   fixed    in units of 2^-32 texel, Q(x) = x * 2^32 rounded to nearest,
 *            halves away from zero (llround):
 *            DUX = Q(c su), DUY = Q(s su), DVX = Q(-s sv), DVY = Q(c sv);
 *            with i0 = floor(cx), j0 = floor(cy), o = (i0 + 0.5 - cx,
 *            j0 + 0.5 - cy): U0 = Q(c su ox + s su oy + wL / 2), V0 alike;
 *            pixel (i, j): U = U0 + (i - i0) DUX + (j - j0) DUY, V alike
 *   footprint  the pixel is drawn when -1/2 <= U < wL + 1/2 and
 *            -1/2 <= V < hL + 1/2 (texels, exactly in fixed point): the
 *            frame plus half a texel of its transparent border, so edges
 *            fade over half a texel (at 1 texel per pixel that is the
 *            texels' area coverage, to the weights' 1/128); pixels
 *            outside are not touched
 *   sample   bilinear on texel centres with 7-bit weights: x = U + 1/2
 *            (the border is index 0), tap columns floor(x) and floor(x)+1,
 *            fx = the first 7 bits of the fraction of x (truncated), wx =
 *            (128 - fx, fx); the same for y; each premultiplied channel
 *            S = (sum of tap * wx * wy + 8192) >> 14, one rounding, so the
 *            rule is the same along both axes
 *   tint     A = div255(S.a * tint.a); P = div255(tint.c * div255(S.c *
 *            tint.a)) for r, g, b (ISK_WHITE changes nothing)
 *   blend    a pixel with A = 0 is left alone (as coverage 0 is by every
 *            primitive); otherwise, for the premultiplied (P, A), the rules
 *            of iskra/blend.h written for a premultiplied source:
 *              ADD      d.c = min(255, d.c + P), d.a = min(255, d.a + A)
 *              OVER     T = 255 A + d.a (255 - A);  d.a = div255(T),
 *                       d.c = (65025 P + d.c d.a (255 - A) + T / 2) / T
 *                       (onto an opaque pixel: d.c = P + div255(d.c (255 - A)))
 *              REPLACE  d.a = A, d.c = (255 P + A / 2) / A  (<= 255: P <= A)
 *
 * So the bytes depend only on the arguments (never on the canvas size, a
 * view's offset or the band of rows drawn).  When the fixed-point matrix is
 * axis-aligned (DUY = DVX = 0: angle 0, and pi, whose sine rounds to 0) a
 * faster blit computes the same integers (a rotation of 0 is byte for byte
 * the unrotated blit).  A quarter turn of a square frame drawn at its own
 * size, its texels on pixels (cx - w/2 and cy - h/2 whole) or shifted from
 * there by multiples of 1/128 px (the weights' resolution), gives exactly
 * the frame rotated in memory and drawn unrotated; at other offsets the
 * truncated weights of the two axes round differently.
 *
 * Not drawn (no pixel touched): a NULL or empty canvas or texture, a mode
 * that is not a blend mode, any NaN or infinity, |cx| or |cy| >= 2^20,
 * width or height outside [1/1024, 32768], a tint of alpha 0.
 *
 * A pixel counts as in the footprint by its centre, so the footprint's own
 * edge is not anti-aliased: textures with a transparent rim (every particle
 * texture, and isk_texture_from_sprite's) have soft edges from the border
 * fade; an opaque square drawn rotated shows stepped edges.
 *
 * The cache keeps textures by name (a path, or any label) and grid: each
 * is made once, from the pixels given on its first request
 * (isk_texture_cache_get_canvas, or from a PNG through iskra/texture_png.h's
 * isk_texture_cache_get), and never evicted.  It is not thread-safe, but
 * the textures it returns are read-only and may be drawn from many threads
 * at once.
 */
#ifndef ISKRA_TEXTURE_H
#define ISKRA_TEXTURE_H

#include <stddef.h>
#include <stdint.h>

#include "iskra/blend.h"
#include "iskra/canvas.h"
#include "iskra/sprite.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ISK_TEXTURE_MAX_DIM 4096   /* image width and height, pixels */
#define ISK_TEXTURE_MAX_GRID 256   /* cols and rows of a sprite sheet */
#define ISK_TEXTURE_MAX_LEVELS 13  /* 4096 -> 1 */
#define ISK_TEXTURE_CACHE_MAX 1024
/* Drawn width and height, pixels (outside: nothing is drawn). */
#define ISK_TEXTURE_DRAW_MIN (1.0 / 1024.0)
#define ISK_TEXTURE_DRAW_MAX 32768.0

typedef struct isk_texture_level {
    int w, h;        /* texels of one frame at this level */
    size_t offset;   /* bytes from a frame's first byte to this level's padded image */
} isk_texture_level;

/* Read-only after creation; the fields are for inspection. */
typedef struct isk_texture {
    int width, height;      /* the image, pixels */
    int cols, rows, frames; /* grid, frames = cols * rows */
    int frame_w, frame_h;   /* width / cols, height / rows */
    int levels;             /* mip levels, 1 + ceil(log2(max(frame_w, frame_h))) */
    isk_texture_level level[ISK_TEXTURE_MAX_LEVELS];
    size_t frame_bytes;     /* one frame's levels */
    size_t bytes;           /* frames * frame_bytes */
    /* Frame f, level l, texel (x, y), x in -1 .. w, y in -1 .. h (the
     * border is 0): texels + f * frame_bytes + level[l].offset
     * + 4 ((y + 1)(w + 2) + x + 1), bytes r g b a premultiplied. */
    uint8_t *texels;
} isk_texture;

/* Copies `img` into *t (which then owns its memory: isk_texture_free).
 * ISK_ERR_NULL; ISK_ERR_SIZE for a malformed canvas or a side outside
 * 1..ISK_TEXTURE_MAX_DIM; ISK_ERR_RANGE when cols or rows is outside
 * 1..ISK_TEXTURE_MAX_GRID or does not divide the width / height exactly;
 * ISK_ERR_NOMEM.  On error *t is zeroed. */
isk_status isk_texture_from_canvas(isk_texture *t, const isk_canvas *img, int cols, int rows);

/* What isk_texture_from_canvas would refuse in an image of width x height
 * pixels cut into cols x rows frames, with a message in err (may be NULL)
 * naming the texture `name`: ISK_ERR_RANGE for a grid outside
 * 1..ISK_TEXTURE_MAX_GRID or one that does not divide the image exactly,
 * ISK_ERR_SIZE for a side outside 1..ISK_TEXTURE_MAX_DIM; ISK_ERR_NULL.
 * Readers check a file's header with it before decoding the pixels. */
isk_status isk_texture_check_size(const char *name, int width, int height, int cols, int rows, isk_error *err);

/* The bytes isk_texture_from_canvas takes for an image of width x height
 * cut into cols x rows frames (the layout above: every frame's levels with
 * their borders, and the struct), without making it; 0 for what it would
 * refuse.  What a program budgets before making a texture. */
size_t isk_texture_bytes(int width, int height, int cols, int rows);

/* A white texture of one frame, size x size, whose alpha is the sprite
 * kind's mask (iskra/sprite.h, the phase centred on the image): tinted by a
 * colour it is that sprite, and drawn with width != height and an angle it
 * is the sprite stretched along a direction (sparks, rain: align =
 * velocity).  Drawn at size x size pixels, angle 0, additively, at a
 * centre where the sprite's phase-0 mask lies on the pixel grid (cx - size/2
 * and cy - size/2 whole numbers), it gives the bytes of
 * isk_draw_sprite_tinted in that colour; source-over differs from the
 * sprite's straight-colour rule by at most 1 per channel (the texels are
 * premultiplied).
 * ISK_ERR_NULL, ISK_ERR_RANGE (kind), ISK_ERR_SIZE (size outside
 * 1..ISK_SPRITE_MAX_SIZE), ISK_ERR_NOMEM. */
isk_status isk_texture_from_sprite(isk_texture *t, isk_sprite_kind kind, int size);

/* Releases the texels (safe on a zeroed struct); *t is zeroed. */
void isk_texture_free(isk_texture *t);

/* Draws frame `frame` of `t` (the rule above). */
void isk_draw_texture(isk_canvas *c, const isk_texture *t, int frame, double cx, double cy, double width,
                      double height, double angle, isk_color tint, isk_blend mode);

typedef struct isk_texture_cache isk_texture_cache;

/* capacity: most textures held, 1..ISK_TEXTURE_CACHE_MAX. */
isk_status isk_texture_cache_create(isk_texture_cache **out, int capacity);
void isk_texture_cache_destroy(isk_texture_cache *cache);

/* The texture of (name, cols, rows): the one held, else made from `img`
 * (a copy, as isk_texture_from_canvas) and kept.  A texture that cannot be
 * made is reported (err names `name`, isk_texture_check_size's messages)
 * and not kept; ISK_ERR_FULL when a new texture would exceed the capacity;
 * ISK_ERR_NULL.  *out is set only on success and stays valid until _clear
 * or _destroy. */
isk_status isk_texture_cache_get_canvas(isk_texture_cache *cache, const char *name, const isk_canvas *img, int cols,
                                        int rows, const isk_texture **out, isk_error *err);

/* Frees every texture; earlier pointers become invalid. */
void isk_texture_cache_clear(isk_texture_cache *cache);

/* Textures held, and textures made since creation (for tests and stats). */
int isk_texture_cache_count(const isk_texture_cache *cache);
long isk_texture_cache_loads(const isk_texture_cache *cache);

#ifdef __cplusplus
}
#endif

#endif
