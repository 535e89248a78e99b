/* SPDX-License-Identifier: MIT */
/* src/raster/font_bitmaps.h — what a built-in font's file gives text.c.
 *
 * A font file (font.c, font_6x13.c) holds its glyph table and box glyph and
 * describes them, with its metrics, in one isk__font_bitmaps; text.c looks
 * glyphs up, measures and draws every font with the same code.  To add a
 * font: a file with its table and its isk__font_bitmaps, a constant in
 * isk_font (iskra/text.h) and a row in text.c's table of fonts.
 */
#ifndef ISKRA_FONT_BITMAPS_H
#define ISKRA_FONT_BITMAPS_H

#include <stdint.h>

#include "iskra/text.h"

/* The bytes every built-in font has a glyph for (printable ASCII); the
 * others are drawn as the font's box glyph. */
#define ISK__FONT_FIRST 32
#define ISK__FONT_LAST 126
#define ISK__FONT_GLYPHS (ISK__FONT_LAST - ISK__FONT_FIRST + 1)

typedef struct isk__font_bitmaps {
    isk_font_metrics metrics; /* at scale 1 */
    const uint8_t *glyphs;    /* ISK__FONT_GLYPHS glyphs from ISK__FONT_FIRST on, metrics.glyph_h rows each */
    const uint8_t *box;       /* metrics.glyph_h rows: the glyph of every other byte */
} isk__font_bitmaps;

extern const isk__font_bitmaps isk__font_5x8;  /* src/raster/font.c */
extern const isk__font_bitmaps isk__font_6x13; /* src/raster/font_6x13.c */

#endif
