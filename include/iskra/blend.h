/* SPDX-License-Identifier: MIT */
/* iskra/blend.h — how a source colour combines with the pixel underneath.
 *
 * Every drawing primitive takes an isk_blend.  All arithmetic is integer and
 * exactly specified, so buffers are byte-identical on every machine.  The
 * library states these rules once as plain C (src/raster/blend_rule.h) and
 * tests every faster form of them against it.
 * div255(x) below means x/255 rounded to the nearest integer; (x+127)/255 in
 * integers (x/255 is never exactly half-way, so there are no ties).
 *
 *   ISK_BLEND_REPLACE  dst = src (all four channels).
 *   ISK_BLEND_OVER     source-over on straight (non-premultiplied) colour:
 *                        A   = 255*sa + da*(255-sa)             (= 255*out alpha)
 *                        out.a = div255(A)
 *                        out.c = (255*sc*sa + dc*da*(255-sa) + A/2) / A   (rounded to nearest)
 *                      sa = 0 leaves the pixel as it is (A = 0 is only then);
 *                      over an opaque destination out.c = div255(sc*sa + dc*(255-sa))
 *                      and out.a = 255; sa = 255 copies the source.
 *   ISK_BLEND_ADD      saturating add weighted by source alpha:
 *                        out.c = min(255, dc + div255(sc*sa)),  out.a = min(255, da + sa)
 *                      Order-independent: any permutation of the same draws
 *                      gives the same bytes.
 *
 * Anti-aliased primitives first scale the source alpha by the pixel's coverage
 * (0..255): sa' = div255(sa*coverage), then blend as above.  With REPLACE the
 * pixel gets the source colour and alpha sa'.  Coverage 0 leaves the pixel alone.
 *
 * Example: half-transparent blue on opaque red, in each mode:
 *
 *     isk_color blue = isk_rgba(0, 0, 255, 128);
 *     for (int m = 0; m < ISK_BLEND_COUNT; m++) {
 *         uint8_t px[4] = {255, 0, 0, 255};            // R, G, B, A
 *         isk_blend mode = (isk_blend)m;
 *         isk_blend_pixel(px, blue, mode);
 *         printf("%-7s %3d %3d %3d %3d\n", isk_blend_name(mode), px[0], px[1], px[2], px[3]);
 *     }   // replace 0 0 255 128,  over 127 0 128 255,  add 255 0 128 255
 */
#ifndef ISKRA_BLEND_H
#define ISKRA_BLEND_H

#include <stdint.h>

#include "iskra/color.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum isk_blend {
    ISK_BLEND_REPLACE = 0,
    ISK_BLEND_OVER = 1,
    ISK_BLEND_ADD = 2,
    ISK_BLEND_COUNT
} isk_blend;

/* Names as scene files spell them, indexed by mode: "replace", "over", "add". */
extern const char *const isk_blend_names[ISK_BLEND_COUNT];

/* x/255 rounded to nearest, for 0 <= x <= 255*255*255. */
static inline uint32_t isk_div255(uint32_t x)
{
    return (x + 127u) / 255u;
}

/* Blends `src` into the 4 bytes at `dst` with the given mode. */
void isk_blend_pixel(uint8_t *dst, isk_color src, isk_blend mode);

/* Same, with the source alpha first scaled by coverage/255. */
void isk_blend_pixel_cov(uint8_t *dst, isk_color src, uint8_t coverage, isk_blend mode);

/* Name of a blend mode ("replace", "over", "add"), or NULL if invalid. */
const char *isk_blend_name(isk_blend mode);

#ifdef __cplusplus
}
#endif

#endif
