/* iskra/text.h — text from iskra's own built-in bitmap font.
 *
 * The font covers printable ASCII 32..126 in fixed-width cells; any other
 * byte is drawn as a hollow box.  '\n' starts a new line.  Glyphs are scaled
 * by integer factors (1 = one font pixel per canvas pixel).  No font files.
 *
 *     isk_draw_text(&c, 15, 30, "FPS: 60", 2, ISK_WHITE, ISK_BLEND_OVER);
 *     int w = isk_text_width("FPS: 60", 2);
 *
 * (x, y) is the top-left corner of the first character cell.  Coordinates
 * and scale are clipped; scale < 1 draws nothing.
 */
#ifndef ISKRA_TEXT_H
#define ISKRA_TEXT_H

#include "iskra/blend.h"
#include "iskra/canvas.h"

/* Cell size at scale 1, including the one-pixel spacing column/row. */
#define ISK_FONT_CELL_W 6
#define ISK_FONT_CELL_H 9
/* Glyph box inside the cell (the rest is spacing). */
#define ISK_FONT_GLYPH_W 5
#define ISK_FONT_GLYPH_H 8

/* Width in pixels of the widest line of `s` (0 for empty or NULL). */
int isk_text_width(const char *s, int scale);
/* Height in pixels of `s`: number of lines times cell height. */
int isk_text_height(const char *s, int scale);

void isk_draw_text(isk_canvas *c, int x, int y, const char *s, int scale,
                   isk_color color, isk_blend mode);

/* The 5x8 bitmap of byte `ch`: 8 rows, bit 4 of each row is the leftmost
 * pixel.  Returns the box glyph for bytes outside 32..126. */
const uint8_t *isk_font_glyph(unsigned char ch);

#endif
