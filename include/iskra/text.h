/* SPDX-License-Identifier: MIT */
/* iskra/text.h — text from iskra's own built-in bitmap fonts.
 *
 * Two fonts cover printable ASCII 32..126 in fixed-width cells; any other
 * byte is drawn as a hollow box.  '\n' starts a new line.  Glyphs are scaled
 * by integer factors (1 = one font pixel per canvas pixel).  No font files.
 * The 5x8 font (isk_draw_text, isk_text_width, isk_text_height) has
 * capitals 7 pixels tall; the 6x13 font (ISK_FONT_6X13, through the
 * isk_font_* functions) has capitals 10 pixels tall, for panels read from
 * across a room.
 *
 * Example:
 *
 *     isk_canvas c;
 *     if (isk_canvas_init(&c, 200, 60) != ISK_OK) return 1;
 *     isk_draw_text(&c, 15, 30, "FPS: 60", 2, ISK_WHITE, ISK_BLEND_OVER);
 *     int w = isk_text_width("FPS: 60", 2);
 *     printf("%d pixels wide\n", w);
 *     isk_font_draw_text(&c, ISK_FONT_6X13, 15, 4, "rate 420", 1, ISK_WHITE, ISK_BLEND_OVER);
 *     printf("%d pixels wide in 6x13\n", isk_font_text_width(ISK_FONT_6X13, "rate 420", 1));
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

/* ---- either font ----------------------------------------------------------
 * The functions above are the 5x8 font's; these take the font.  Their
 * rules are the same (cells, lines, clipping, saturation); an unknown font
 * measures 0 and draws nothing. */
typedef enum isk_font {
    ISK_FONT_5X8 = 0, /* 5x8 glyphs in 6x9 cells: capitals 7 pixels tall (rows 0..6) */
    ISK_FONT_6X13,    /* 6x13 glyphs in 7x14 cells: capitals 10 pixels tall (rows 0..9) */
    ISK_FONT_COUNT
} isk_font;

typedef struct isk_font_metrics {
    int cell_w, cell_h;   /* a character's advance and a line's height at scale 1, spacing included */
    int glyph_w, glyph_h; /* the glyph box at the cell's top-left */
    int cap_h;            /* rows of capitals and digits from the top: the baseline is row cap_h - 1 */
} isk_font_metrics;

/* The font's metrics at scale 1, or NULL for an unknown font. */
const isk_font_metrics *isk_font_metrics_of(isk_font font);
/* Byte ch's glyph: glyph_h rows, bit glyph_w - 1 of each the leftmost
 * pixel; the font's box glyph for bytes outside 32..126; NULL for an
 * unknown font. */
const uint8_t *isk_font_rows(isk_font font, unsigned char ch);
int isk_font_text_width(isk_font font, const char *s, int scale);
int isk_font_text_height(isk_font font, const char *s, int scale);
void isk_font_draw_text(isk_canvas *c, isk_font font, int x, int y, const char *s, int scale, isk_color color,
                        isk_blend mode);

#ifdef __cplusplus
}
#endif

#endif
