/* SPDX-License-Identifier: MIT */
/* The 6x13 bitmap font (ISK_FONT_6X13): its metrics, capitals at least 10
 * pixels tall (what a class reads from across the room), glyphs inside their
 * box and all different, the 5x8 font unchanged through the font-taking
 * functions, and the whole table as a reference image. */
#include <criterion/criterion.h>
#include <limits.h>

#include "iskra/text.h"
#include "font_checks.h"
#include "refimg_scene.h"

Test(font_6x13, metrics)
{
    const isk_font_metrics *m = isk_font_metrics_of(ISK_FONT_6X13);
    cr_assert_not_null(m);
    cr_assert_eq(m->cell_w, 7);
    cr_assert_eq(m->cell_h, 14);
    cr_assert_eq(m->glyph_w, 6);
    cr_assert_eq(m->glyph_h, 13);
    cr_assert_eq(m->cap_h, 10);
    cr_assert_eq(isk_font_text_width(ISK_FONT_6X13, "rate", 1), 28);
    cr_assert_eq(isk_font_text_height(ISK_FONT_6X13, "a\nb", 2), 56);
    cr_assert_eq(isk_font_text_width(ISK_FONT_6X13, "abc", INT_MAX), INT_MAX);
    /* The 5x8 font through the same functions is the old one. */
    cr_assert_eq(isk_font_text_width(ISK_FONT_5X8, "FPS: 60", 2), isk_text_width("FPS: 60", 2));
    cr_assert_eq(isk_font_metrics_of(ISK_FONT_5X8)->cap_h, 7);
    cr_assert_eq(isk_font_rows(ISK_FONT_5X8, 'A'), isk_font_glyph('A'));
    /* An unknown font measures nothing and draws nothing. */
    cr_assert_null(isk_font_metrics_of(ISK_FONT_COUNT));
    cr_assert_null(isk_font_rows((isk_font)-1, 'A'));
    cr_assert_eq(isk_font_text_width(ISK_FONT_COUNT, "abc", 1), 0);
    isk_canvas c = refimg_canvas(20, 20, ISK_BLACK);
    isk_font_draw_text(&c, ISK_FONT_COUNT, 0, 0, "A", 1, ISK_WHITE, ISK_BLEND_OVER);
    for (int i = 0; i < 20 * 20 * 4; i += 4)
        cr_assert_eq(c.pixels[i], 0);
    isk_canvas_free(&c);
}

/* Rows of ink of a glyph: its first and last. */
static void ink_rows(const uint8_t *g, int h, int *top, int *bottom)
{
    *top = -1;
    *bottom = -1;
    for (int r = 0; r < h; r++)
        if (g[r]) {
            if (*top < 0)
                *top = r;
            *bottom = r;
        }
}

Test(font_6x13, capitals_and_digits_are_ten_pixels_tall)
{
    const char *tall = "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789bdfhklt";
    for (const char *p = tall; *p; p++) {
        int top, bottom;
        ink_rows(isk_font_rows(ISK_FONT_6X13, (unsigned char)*p), 13, &top, &bottom);
        if (*p == 't') /* its top is shorter, as in most fonts */
            top = 0;
        cr_expect_eq(top, 0, "'%c' starts at row %d", *p, top);
        cr_expect_eq(bottom, 9, "'%c' ends at row %d", *p, bottom);
    }
    const char *x_height = "acemnorsuvwxz";
    for (const char *p = x_height; *p; p++) {
        int top, bottom;
        ink_rows(isk_font_rows(ISK_FONT_6X13, (unsigned char)*p), 13, &top, &bottom);
        cr_expect_eq(top, 3, "'%c' starts at row %d", *p, top);
        cr_expect_eq(bottom, 9, "'%c' ends at row %d", *p, bottom);
    }
    const char *descenders = "gjpqy";
    for (const char *p = descenders; *p; p++) {
        int top, bottom;
        ink_rows(isk_font_rows(ISK_FONT_6X13, (unsigned char)*p), 13, &top, &bottom);
        cr_expect_eq(bottom, 12, "'%c' ends at row %d", *p, bottom);
    }
    /* Drawn at scale 1, "H" lights exactly 10 rows. */
    isk_canvas c = refimg_canvas(10, 20, ISK_BLACK);
    isk_font_draw_text(&c, ISK_FONT_6X13, 0, 0, "H", 1, ISK_WHITE, ISK_BLEND_OVER);
    int rows = 0;
    for (int y = 0; y < 20; y++) {
        int lit = 0;
        for (int x = 0; x < 10; x++)
            lit |= isk_canvas_get(&c, x, y).r != 0;
        rows += lit;
    }
    cr_expect_eq(rows, 10);
    isk_canvas_free(&c);
}

Test(font_6x13, glyphs_fit_their_box_and_differ)
{
    font_check_glyphs(ISK_FONT_6X13);
    /* the sixth column is spacing, except for the one glyph that needs it */
    for (int ch = 33; ch <= 126; ch++) {
        const uint8_t *g = isk_font_rows(ISK_FONT_6X13, (unsigned char)ch);
        if (ch != '&')
            for (int r = 0; r < 13; r++)
                cr_assert_eq(g[r] & 1u, 0, "glyph '%c' row %d uses the sixth column", ch, r);
    }
}

Test(font_6x13, text_stays_inside_its_measured_box)
{
    font_check_inside_box(ISK_FONT_6X13, 260, 90, "Hello, iskra!\ngjpqy_ {}|~", 9, 5, 2, 200);
}

Test(refimg, text_font_table_6x13)
{
    isk_canvas c = refimg_canvas(460, 150, ISK_BLACK);
    char line[33];
    for (int row = 0; row < 3; row++) {
        font_table_line(row, line);
        isk_font_draw_text(&c, ISK_FONT_6X13, 4, 4 + 16 * row, line, 1, ISK_WHITE, ISK_BLEND_OVER);
    }
    isk_font_draw_text(&c, ISK_FONT_6X13, 4, 56, "The quick brown fox jumps over the lazy dog.\n"
                       "rate 420  color_over_life 0:#ffdc6e3c  spin -90\n"
                       "Il1| O0o 5S 8B DO gqpy ,;:. \"q\" `t` ~^@&%$!?",
                       1, isk_rgba(0xe6, 0xe0, 0xf0, 255), ISK_BLEND_OVER);
    isk_font_draw_text(&c, ISK_FONT_6X13, 4, 104, "Gravity 9.81", 2, isk_rgba(0xb3, 0x88, 0xeb, 255),
                       ISK_BLEND_OVER);
    refimg_expect("text_font_table_6x13", &c);
}
