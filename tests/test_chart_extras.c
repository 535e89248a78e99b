/* SPDX-License-Identifier: MIT */
/* Chart extras (iskra/chart.h): notes at data points and a second x axis
 * along the top, drawn exactly as refimg/chart_notes_top_axis.png; off by
 * default, so every other chart is unchanged; and their checks. */
#include <criterion/criterion.h>
#include <math.h>

#include "iskra/chart.h"
#include "refimg.h"

/* Two work-precision curves, a step size noted at some points, a point
 * singled out with its own marker, and "particles per frame" on the top:
 * 1e9 * T / x with T = 2 (the accuracy study's use). */
static void draw(isk_canvas *c, int w, int h)
{
    static double x1[6] = {20, 40, 80, 160, 320, 640}, y1[6] = {1e-1, 5e-2, 2.5e-2, 1.2e-2, 6e-3, 3e-3};
    static double x2[6] = {60, 120, 240, 480, 960, 1920}, y2[6] = {2e-3, 1.2e-4, 7.5e-6, 4.7e-7, 2.9e-8, 1.8e-9};
    isk_chart_series s[2] = {{"euler", x1, y1, 6, isk_chart_style_default(0)},
                             {"rk4", x2, y2, 6, isk_chart_style_default(3)}};
    isk_chart_note notes[5] = {
        {20, 1e-1, "h 0.4", s[0].style.color, ISK_MARKER_NONE},
        {160, 1.2e-2, "h 0.05", s[0].style.color, ISK_MARKER_NONE},
        {480, 4.7e-7, "h 0.05", s[1].style.color, ISK_MARKER_NONE},
        {300, 2e-2, "dt = 1/60", isk_rgba(0, 0, 0, 255), ISK_MARKER_DIAMOND},
        {1e9, 1, "outside: not drawn", isk_rgba(255, 0, 0, 255), ISK_MARKER_CIRCLE},
    };
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = "notes and a top axis";
    ch.x_label = "ns per particle";
    ch.y_label = "error";
    ch.x_log = ch.y_log = 1;
    ch.series = s;
    ch.nseries = 2;
    ch.notes = notes;
    ch.nnotes = 5;
    ch.x2_label = "particles per 16.7 ms frame";
    ch.x2_scale = 2e9;
    ch.x2_inverse = 1;
    ch.legend = ISK_LEGEND_BOTTOM_LEFT;
    cr_assert_eq(isk_canvas_init(c, w, h), ISK_OK);
    cr_assert_eq(isk_chart_draw(&ch, c), ISK_OK);
}

Test(refimg, chart_notes_top_axis)
{
    isk_canvas c;
    draw(&c, 800, 520);
    cr_assert(refimg_check("chart_notes_top_axis", &c));
    isk_canvas_free(&c);
}

Test(chart_extras, checks)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 400, 300), ISK_OK);
    double x[2] = {1, 10}, y[2] = {1, 10};
    isk_chart_series s = {"a", x, y, 2, isk_chart_style_default(0)};
    isk_chart ch;
    isk_chart_defaults(&ch);
    cr_assert(ch.notes == NULL && ch.nnotes == 0 && ch.x2_label == NULL, "off by default");
    ch.series = &s;
    ch.nseries = 1;
    ch.x_log = 1;
    ch.nnotes = 1;
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_ERR_NULL);
    isk_chart_note n = {2, 2, "x", ISK_BLACK, ISK_MARKER_COUNT};
    ch.notes = &n;
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_ERR_RANGE);
    n.marker = ISK_MARKER_NONE;
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    ch.x2_label = "top";
    ch.x2_scale = 0;
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_ERR_RANGE);
    ch.x2_scale = NAN;
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_ERR_RANGE);
    ch.x2_scale = 10;
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    ch.x_log = 0; /* a top axis only on a log x axis: ignored, not an error */
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    isk_canvas_free(&c);
}
