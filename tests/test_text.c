/* SPDX-License-Identifier: MIT */
/* tests/test_text.c — isk_draw_text checked pixel by pixel against an
 * independent model of the layout, plus metric edge cases.  Complements
 * tests/test_font.c (metrics basics, glyph sanity, the text_* reference
 * images).
 *
 * The model: canvas pixel (px, py) is inked iff, with dx = px - x and
 * dy = py - y (64-bit), both are >= 0, line dy / (9*scale) and character
 * dx / (6*scale) of that line exist, and the glyph bit at column
 * (dx mod 6*scale) / scale, row (dy mod 9*scale) / scale is set (columns 5
 * and row 8 of a cell are spacing).  Run from the repository root:
 * build/tests/test_text. */
#include <criterion/criterion.h>
#include <limits.h>
#include <string.h>

#include "iskra/text.h"

/* Character `index` of line `line` of s, or -1 if there is none. */
static int char_at(const char *s, long long line, long long index)
{
    while (line > 0) {
        s = strchr(s, '\n');
        if (!s)
            return -1;
        s++;
        line--;
    }
    const char *end = strchr(s, '\n');
    long long len = end ? (long long)(end - s) : (long long)strlen(s);
    return index < len ? (unsigned char)s[index] : -1;
}

static int model_inked(const char *s, long long x, long long y, long long scale, long long px, long long py)
{
    long long dx = px - x, dy = py - y;
    if (dx < 0 || dy < 0)
        return 0;
    long long cw = ISK_FONT_CELL_W * scale, ch = ISK_FONT_CELL_H * scale;
    int c = char_at(s, dy / ch, dx / cw);
    if (c < 0)
        return 0;
    long long col = (dx % cw) / scale, row = (dy % ch) / scale;
    if (col >= ISK_FONT_GLYPH_W || row >= ISK_FONT_GLYPH_H)
        return 0;
    return (isk_font_glyph((unsigned char)c)[row] >> (4 - col)) & 1;
}

/* Draws s on a black w x h canvas and compares every pixel with the model. */
static void check_against_model(const char *s, int x, int y, int scale, int w, int h)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, w, h), ISK_OK);
    isk_canvas_fill(&c, ISK_BLACK);
    isk_draw_text(&c, x, y, s, scale, ISK_WHITE, ISK_BLEND_REPLACE);
    for (int py = 0; py < h; py++)
        for (int px = 0; px < w; px++) {
            int want = model_inked(s, x, y, scale, px, py);
            int got = isk_canvas_get(&c, px, py).r == 255;
            cr_assert_eq(got, want, "\"%s\" at (%d,%d) scale %d: pixel (%d,%d) is %d, model says %d", s, x, y,
                         scale, px, py, got, want);
        }
    isk_canvas_free(&c);
}

Test(text, pixels_match_the_layout_model)
{
    check_against_model("Ag|_j\n0O 1lI", 2, 3, 1, 48, 24);
    check_against_model("Ag|_j\n0O 1lI", 2, 3, 3, 120, 60);
    /* Every printable character and the box glyph at scale 1 and 2. */
    char all[96 + 6 + 1];
    int n = 0;
    for (int ch = 32; ch <= 127; ch++) {
        all[n++] = (char)ch;
        if ((ch - 31) % 16 == 0)
            all[n++] = '\n';
    }
    all[n] = 0;
    check_against_model(all, 1, 1, 1, 100, 60);
    check_against_model(all, 0, 0, 2, 200, 110);
    /* Trailing, leading and doubled newlines. */
    check_against_model("\nab\n\ncd\n", 0, 0, 1, 20, 50);
}

Test(text, clipping_matches_the_model_at_every_edge)
{
    const char *s = "W@#\nq%&";
    const int xs[] = {INT_MIN, -100000, -13, -1, 0, 5, 17, 19, 20, 1000, INT_MAX};
    const int scales[] = {1, 2, 7, 1000, INT_MAX / 9, INT_MAX};
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++)
        for (size_t k = 0; k < sizeof scales / sizeof scales[0]; k++) {
            check_against_model(s, xs[i], -3, scales[k], 20, 14);
            check_against_model(s, 2, xs[i], scales[k], 20, 14);
        }
    /* Huge scale with the glyph origin far to the upper left: one font pixel
     * covers the whole canvas. */
    check_against_model("W", INT_MIN, INT_MIN, INT_MAX, 8, 8);
    check_against_model("W", -INT_MAX / 5, -2, INT_MAX / 5, 8, 8);
}

Test(text, newline_returns_to_the_start_x)
{
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, 60, 60), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 60, 60), ISK_OK);
    isk_draw_text(&a, 7, 2, "xy\nK", 2, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_draw_text(&b, 7, 2, "xy", 2, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_draw_text(&b, 7, 2 + 2 * ISK_FONT_CELL_H, "K", 2, ISK_WHITE, ISK_BLEND_REPLACE);
    cr_assert(isk_canvas_equal(&a, &b));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(text, translucent_text_blends_each_pixel_once)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 40, 20), ISK_OK);
    isk_canvas_fill(&c, ISK_BLACK);
    isk_draw_text(&c, 0, 0, "#M", 2, isk_rgba(255, 255, 255, 128), ISK_BLEND_OVER);
    int lit = 0;
    for (int y = 0; y < c.height; y++)
        for (int x = 0; x < c.width; x++) {
            isk_color p = isk_canvas_get(&c, x, y);
            if (p.r) {
                lit++;
                cr_assert_eq(p.r, 128, "(%d,%d) = %d: blended more than once", x, y, p.r);
                cr_assert_eq(p.a, 255);
            }
        }
    cr_assert_gt(lit, 0);
    isk_canvas_free(&c);
}

Test(text, nothing_drawn_for_bad_arguments)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 16, 16), ISK_OK);
    isk_draw_text(&c, 0, 0, "A", 1, ISK_WHITE, (isk_blend)42);
    isk_draw_text(&c, 0, 0, "A", 0, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_draw_text(&c, 0, 0, "A", INT_MIN, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_draw_text(&c, 0, 0, NULL, 1, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_draw_text(&c, 0, 0, "", 1, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_draw_text(&c, 0, 0, " \n ", 1, ISK_WHITE, ISK_BLEND_REPLACE);
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++)
            cr_assert_eq(isk_canvas_get(&c, x, y).a, 0);
    isk_draw_text(NULL, 0, 0, "A", 1, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_canvas empty;
    memset(&empty, 0, sizeof empty);
    isk_draw_text(&empty, 0, 0, "A", 1, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_canvas_free(&c);
}

Test(text, metric_definitions)
{
    /* Width counts whole cells, the trailing spacing column included, so
     * strings placed side by side at x + width keep the normal gap. */
    cr_assert_eq(isk_text_width("ab", 1), 2 * ISK_FONT_CELL_W);
    cr_assert_eq(isk_text_width("ab", 5), 10 * ISK_FONT_CELL_W);
    /* Every byte except '\n' is one cell, the box-drawn ones too. */
    cr_assert_eq(isk_text_width("\t\x01\xff", 1), 18);
    /* A line is counted after every '\n', even an empty last one. */
    cr_assert_eq(isk_text_height("\n", 1), 18);
    cr_assert_eq(isk_text_width("\n", 1), 0);
    cr_assert_eq(isk_text_height("abc\n", 2), 36);
    cr_assert_eq(isk_text_width("abc\n", 2), 36);
    cr_assert_eq(isk_text_height("a\n\nb", 1), 27);
    cr_assert_eq(isk_text_width("x", -3), 0);
    cr_assert_eq(isk_text_height("x", INT_MIN), 0);
    /* Exact just below the int limit, saturated just above it. */
    cr_assert_eq(isk_text_width("a", INT_MAX / 6), INT_MAX / 6 * 6);
    cr_assert_eq(isk_text_width("a", INT_MAX / 6 + 1), INT_MAX);
    cr_assert_eq(isk_text_height("a", INT_MAX / 9), INT_MAX / 9 * 9);
    cr_assert_eq(isk_text_height("a", INT_MAX / 9 + 1), INT_MAX);
    cr_assert_eq(isk_text_width("a", INT_MAX), INT_MAX);
    cr_assert_eq(isk_text_height("a\nb", INT_MAX), INT_MAX);
}
