/* SPDX-License-Identifier: MIT */
/* iskra/text.h — text from iskra's own built-in bitmap font.
 *
 * The font covers printable ASCII 32..126 in fixed-width cells; any other
 * byte is drawn as a hollow box.  '\n' starts a new line.  Glyphs are scaled
 * by integer factors (1 = one font pixel per canvas pixel).  No font files.
 *
 * Example:
 *
 *     isk_canvas c;
 *     if (isk_canvas_init(&c, 200, 60) != ISK_OK) return 1;
 *     isk_draw_text(&c, 15, 30, "FPS: 60", 2, ISK_WHITE, ISK_BLEND_OVER);
 *     int w = isk_text_width("FPS: 60", 2);
 *     printf("%d pixels wide\n", w);
 *     isk_canvas_free(&c);
 *
 * (x, y) is the top-left corner of the first character cell.  Coordinates
 * and scale are clipped; scale < 1 draws nothing.
 */
#ifndef ISKRA_TEXT_H
#define ISKRA_TEXT_H

#include "iskra/blend.h"
#include "iskra/canvas.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Cell size at scale 1, including the one-pixel spacing column/row. */
#define ISK_FONT_CELL_W 6
#define ISK_FONT_CELL_H 9
/* Glyph box inside the cell (the rest is spacing). */
#define ISK_FONT_GLYPH_W 5
#define ISK_FONT_GLYPH_H 8

/* Metrics count whole cells, spacing included: every byte other than '\n'
 * (box-drawn ones too) is one cell of ISK_FONT_CELL_W x ISK_FONT_CELL_H
 * pixels times scale, so text drawn at x + isk_text_width(...) keeps the
 * normal one-column gap, and all ink lies inside the box
 * [x, x + width) x [y, y + height) (the last column and row of it are the
 * spacing of the last cells, never inked).
 *
 * Width: characters in the widest line times ISK_FONT_CELL_W * scale.
 * Height: lines times ISK_FONT_CELL_H * scale, where a non-empty string has
 * one line plus one per '\n' (so "a\n" is two lines, the second empty).
 * NULL, "" or scale < 1 give 0; results too large for an int give INT_MAX. */
int isk_text_width(const char *s, int scale);
int isk_text_height(const char *s, int scale);

/* Draws `s` with the top-left of its first cell at (x, y): each set font
 * pixel becomes a scale x scale block blended with `mode`, every canvas
 * pixel at most once per call (so translucent text is even).  Any int x, y
 * and scale are safe (64-bit layout arithmetic, clipped to the canvas);
 * NULL canvas or string, scale < 1 or an unknown blend mode draw nothing. */
void isk_draw_text(isk_canvas *c, int x, int y, const char *s, int scale,
                   isk_color color, isk_blend mode);

/* The 5x8 bitmap of byte `ch`: 8 rows, bit 4 of each row is the leftmost
 * pixel.  Returns the box glyph for bytes outside 32..126. */
const uint8_t *isk_font_glyph(unsigned char ch);

#ifdef __cplusplus
}
#endif

#endif
