/* SPDX-License-Identifier: MIT */
/* tests/font_checks.h — what every built-in font's tests check, for any
 * font (header-only; include it after <criterion/criterion.h>).
 *
 *     font_check_glyphs(ISK_FONT_6X13);             // the table's sanity
 *     font_check_inside_box(ISK_FONT_6X13, 260, 90, "Hello\nyes", 9, 5, 2, 200);
 *     char line[33];
 *     font_table_line(1, line);                     // "@AB...^_": bytes 64..95
 *
 * font_check_glyphs: the space is blank; every other printable byte has
 * ink, all of it inside the glyph box (glyph_w x glyph_h), and no two
 * glyphs are equal; every byte outside 32..126 is drawn as one box glyph,
 * which has ink and is none of the printable ones.
 * font_check_inside_box: text drawn at (x, y) inks only pixels inside
 * [x, x + width) x [y, y + height) as isk_font_text_width/height measure
 * it, and more than min_lit of them. */
#ifndef ISKRA_TESTS_FONT_CHECKS_H
#define ISKRA_TESTS_FONT_CHECKS_H

#include <string.h>

#include "iskra/text.h"

static inline int font_glyph_ink(const isk_font_metrics *m, const uint8_t *g)
{
    int n = 0;
    for (int r = 0; r < m->glyph_h; r++)
        for (int b = 0; b < 8; b++)
            n += (g[r] >> b) & 1;
    return n;
}

static inline void font_check_glyphs(isk_font font)
{
    const isk_font_metrics *m = isk_font_metrics_of(font);
    cr_assert_not_null(m);
    const size_t h = (size_t)m->glyph_h;
    const unsigned outside_box = ~((1u << m->glyph_w) - 1u);
    cr_assert_eq(font_glyph_ink(m, isk_font_rows(font, ' ')), 0, "the space has ink");
    const uint8_t *box = isk_font_rows(font, 127);
    cr_assert_gt(font_glyph_ink(m, box), 0, "the box glyph is empty");
    const unsigned char others[] = {0, 1, 31, 128, 200, 255};
    for (size_t i = 0; i < sizeof others; i++)
        cr_assert(memcmp(box, isk_font_rows(font, others[i]), h) == 0, "byte %d is not the box", others[i]);
    for (int ch = 33; ch <= 126; ch++) {
        const uint8_t *g = isk_font_rows(font, (unsigned char)ch);
        cr_assert_gt(font_glyph_ink(m, g), 0, "glyph %d is empty", ch);
        for (int r = 0; r < m->glyph_h; r++)
            cr_assert_eq(g[r] & outside_box, 0, "glyph %d row %d outside the %d-pixel box", ch, r, m->glyph_w);
        cr_assert(memcmp(g, box, h) != 0, "glyph %d is the box", ch);
        for (int other = 33; other < ch; other++)
            cr_assert(memcmp(g, isk_font_rows(font, (unsigned char)other), h) != 0, "glyphs %d and %d are identical",
                      ch, other);
    }
}

static inline void font_check_inside_box(isk_font font, int canvas_w, int canvas_h, const char *s, int x, int y,
                                         int scale, int min_lit)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, canvas_w, canvas_h), ISK_OK);
    isk_canvas_fill(&c, ISK_BLACK);
    isk_font_draw_text(&c, font, x, y, s, scale, ISK_WHITE, ISK_BLEND_OVER);
    int w = isk_font_text_width(font, s, scale), h = isk_font_text_height(font, s, scale), lit = 0;
    for (int py = 0; py < c.height; py++)
        for (int px = 0; px < c.width; px++)
            if (isk_canvas_get(&c, px, py).r) {
                lit++;
                cr_assert(px >= x && px < x + w && py >= y && py < y + h, "pixel (%d,%d) outside", px, py);
            }
    cr_assert_gt(lit, min_lit);
    isk_canvas_free(&c);
}

/* Row `row` (0..2) of the table pictures: the printable bytes from
 * 32 + 32 * row, at most 32 of them (the last row ends at 126). */
static inline void font_table_line(int row, char line[33])
{
    int n = 0;
    for (int ch = 32 + 32 * row; ch < 32 + 32 * (row + 1) && ch < 127; ch++)
        line[n++] = (char)ch;
    line[n] = 0;
}

#endif
