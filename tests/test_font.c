/* SPDX-License-Identifier: MIT */
/* The built-in bitmap font: metrics, glyph sanity, clipping, reference images. */
#include <criterion/criterion.h>
#include <limits.h>
#include <string.h>

#include "iskra/text.h"
#include "iskra/view.h"
#include <math.h>
#include "font_checks.h"
#include "refimg_scene.h"

Test(font, metrics)
{
    cr_assert_eq(isk_text_width("", 1), 0);
    cr_assert_eq(isk_text_height("", 1), 0);
    cr_assert_eq(isk_text_width(NULL, 1), 0);
    cr_assert_eq(isk_text_height(NULL, 3), 0);
    /* A cell is 6 x 9 at scale 1, trailing spacing included. */
    cr_assert_eq(isk_text_width("A", 1), 6);
    cr_assert_eq(isk_text_height("A", 1), 9);
    cr_assert_eq(isk_text_width("A", 3), 18);
    cr_assert_eq(isk_text_height("A", 3), 27);
    cr_assert_eq(isk_text_width("FPS: 60", 2), 7 * 12);
    /* Multi-line: the widest line, and one cell height per line. */
    cr_assert_eq(isk_text_width("ab\nabcd\nc", 1), 24);
    cr_assert_eq(isk_text_height("ab\nabcd\nc", 1), 27);
    cr_assert_eq(isk_text_height("x\n", 1), 18);
    cr_assert_eq(isk_text_width("x", 0), 0);
    /* Absurd sizes saturate instead of overflowing. */
    cr_assert_eq(isk_text_width("abc", INT_MAX), INT_MAX);
    cr_assert_eq(isk_text_height("abc", INT_MAX / 2), INT_MAX);
}

Test(font, glyphs_fit_their_box_and_differ)
{
    font_check_glyphs(ISK_FONT_5X8);
    /* isk_font_glyph is the 5x8 font's table */
    for (int ch = 0; ch < 256; ch++)
        cr_assert_eq(isk_font_glyph((unsigned char)ch), isk_font_rows(ISK_FONT_5X8, (unsigned char)ch));
}

Test(font, text_stays_inside_its_measured_box)
{
    font_check_inside_box(ISK_FONT_5X8, 200, 80, "Hello, iskra!\nline 2 {}|~", 13, 7, 2, 100);
}

Test(font, clipping_with_extreme_coordinates)
{
    uint8_t mem[40 * 4 * 30];
    memset(mem, 0xAB, sizeof mem);
    isk_canvas big, c;
    cr_assert_eq(isk_canvas_wrap(&big, mem, 40, 30, 40 * 4), ISK_OK);
    cr_assert_eq(isk_canvas_view(&c, &big, 5, 5, 30, 20), ISK_OK);
    const int xs[] = {INT_MIN, -1000, -7, 0, 25, 29, 1000, INT_MAX};
    const int scales[] = {1, 3, 1000, INT_MAX};
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++)
        for (size_t j = 0; j < sizeof xs / sizeof xs[0]; j++)
            for (size_t k = 0; k < sizeof scales / sizeof scales[0]; k++)
                isk_draw_text(&c, xs[i], xs[j], "W@#\n%&", scales[k], ISK_RED, ISK_BLEND_ADD);
    isk_draw_text(&c, 0, 0, NULL, 1, ISK_RED, ISK_BLEND_OVER);
    isk_draw_text(&c, 0, 0, "x", 0, ISK_RED, ISK_BLEND_OVER);
    /* Nothing outside the view changed. */
    for (int y = 0; y < 30; y++)
        for (int x = 0; x < 40; x++) {
            int inside = x >= 5 && x < 35 && y >= 5 && y < 25;
            if (!inside)
                cr_assert_eq(mem[(y * 40 + x) * 4], 0xAB, "(%d,%d) touched", x, y);
        }
}

Test(refimg, text_font_table)
{
    isk_canvas c = refimg_canvas(400, 130, ISK_BLACK);
    char line[33];
    for (int row = 0; row < 3; row++) {
        font_table_line(row, line);
        isk_draw_text(&c, 4, 4 + 11 * row, line, 1, ISK_WHITE, ISK_BLEND_OVER);
        isk_draw_text(&c, 4, 40 + 22 * row, line, 2, ISK_WHITE, ISK_BLEND_OVER);
    }
    refimg_expect("text_font_table", &c);
}

Test(refimg, text_scales)
{
    isk_canvas c = refimg_canvas(520, 110, isk_rgba(20, 40, 90, 255));
    int y = 4;
    for (int s = 1; s <= 4; s++) {
        isk_draw_text(&c, 4, y, "iskra 0.1 (O0 Il1 5S)", s, isk_rgba(255, 220, 0, 200), ISK_BLEND_OVER);
        y += isk_text_height("x", s) + 2;
    }
    refimg_expect("text_scales", &c);
}

Test(font, world_text_with_absurd_positions_and_scales)
{
    isk_canvas c;
    isk_view v;
    cr_assert_eq(isk_canvas_init(&c, 32, 32), ISK_OK);
    cr_assert_eq(isk_view_window(&v, 32, 32, -1, 1, -1, 1), ISK_OK);
    const double pos[] = {0, -1e300, 1e300, NAN, INFINITY, -INFINITY};
    const int scales[] = {1, 1000, INT_MAX};
    for (int i = 0; i < 6; i++)
        for (int k = 0; k < 3; k++)
            isk_world_text(&c, &v, pos[i], pos[(i + 2) % 6], "Ab", scales[k], ISK_WHITE, ISK_BLEND_OVER);
    isk_world_text(&c, &v, 0, 0, "Ab", 0, ISK_WHITE, ISK_BLEND_OVER);
    isk_canvas_free(&c);
}
