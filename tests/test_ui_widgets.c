/* SPDX-License-Identifier: MIT */
/* The widgets an inspector is built from (iskra/ui.h): the choice (a
 * drop-down whose list is drawn over everything and takes the press over
 * it), the logarithmic slider for ranges of many decades, the scroll bar
 * and the wheel over a region, selectable rows, colour swatches; and the
 * whole set in the 6x13 font, as reference images. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "iskra/ui.h"
#include "refimg.h"

static const char *const blends[] = {"replace", "over", "add"};

typedef struct board {
    isk_ui ui;
    isk_canvas c;
    int blend, chosen, under_clicks, row, first, toggled;
    double rate, spin;
    int rate_changes;
} board;

static void frame(board *b)
{
    isk_ui *ui = &b->ui;
    isk_ui_begin(ui, &b->c);
    isk_ui_clear(ui);
    isk_ui_rect all = isk_ui_inset((isk_ui_rect){0, 0, b->c.width, b->c.height}, isk_ui_px(ui, 4));
    isk_ui_panel(ui, all);
    isk_ui_rect a = isk_ui_inset(all, isk_ui_px(ui, 6));
    const int rh = isk_ui_row_height(ui), gap = isk_ui_px(ui, 4);
    isk_ui_rect line = isk_ui_cut_top(&a, rh);
    isk_ui_cut_top(&a, gap);
    isk_ui_label(ui, isk_ui_cut_left(&line, isk_ui_px(ui, 60)), "blend", ISK_UI_LEFT);
    b->chosen += isk_ui_choice(ui, "blend", line, blends, 3, &b->blend);
    /* a button the open list covers: a press on the list must not click it */
    line = isk_ui_cut_top(&a, rh);
    isk_ui_cut_top(&a, gap);
    isk_ui_label(ui, isk_ui_cut_left(&line, isk_ui_px(ui, 60)), "under", ISK_UI_LEFT);
    b->under_clicks += isk_ui_button(ui, "under", line, "Under");
    line = isk_ui_cut_top(&a, rh);
    isk_ui_cut_top(&a, gap);
    isk_ui_label(ui, isk_ui_cut_left(&line, isk_ui_px(ui, 60)), "rate", ISK_UI_LEFT);
    b->rate_changes += isk_ui_slider_log(ui, "rate", line, &b->rate, 0, 1e7, 0.01, 0);
    line = isk_ui_cut_top(&a, rh);
    isk_ui_cut_top(&a, gap);
    isk_ui_label(ui, isk_ui_cut_left(&line, isk_ui_px(ui, 60)), "spin", ISK_UI_LEFT);
    isk_ui_slider_log(ui, "spin", line, &b->spin, -360000, 360000, 1, 1);
    line = isk_ui_cut_top(&a, rh);
    isk_ui_cut_top(&a, gap);
    isk_ui_label(ui, isk_ui_cut_left(&line, isk_ui_px(ui, 60)), "colours", ISK_UI_LEFT);
    const isk_color ramp[4] = {isk_rgba(255, 220, 110, 255), isk_rgba(255, 140, 30, 200), isk_rgba(220, 50, 10, 120),
                               isk_rgba(90, 0, 0, 0)};
    isk_ui_rect sw = isk_ui_cut_left(&line, 2 * rh);
    isk_ui_swatches(ui, sw, ramp, 1);
    isk_ui_cut_left(&line, gap);
    isk_ui_swatches(ui, line, ramp, 4);
    /* six rows of which three show, with a scroll bar and the wheel */
    isk_ui_rect rows = isk_ui_cut_top(&a, 3 * rh);
    isk_ui_rect bar = isk_ui_cut_right(&rows, isk_ui_px(ui, 8));
    b->first -= isk_ui_wheel(ui, rows);
    isk_ui_scrollbar(ui, "rows-scroll", bar, &b->first, 6, 3);
    static const char *const names[] = {"emitter smoke", "emitter flame", "emitter core", "emitter sparks",
                                        "force gravity", "force wind"};
    for (int i = 0; i < 3; i++) {
        char id[32];
        snprintf(id, sizeof id, "row/%d", b->first + i);
        if (isk_ui_selectable(ui, id, (isk_ui_rect){rows.x, rows.y + i * rh, rows.w, rh}, names[b->first + i],
                              b->row == b->first + i))
            b->row = b->first + i;
    }
    isk_ui_cut_top(&a, gap);
    line = isk_ui_cut_top(&a, rh);
    isk_ui_toggle(ui, "bounded", line, "on", &b->toggled);
    isk_ui_end(ui);
}

static void setup(board *b, isk_font font)
{
    memset(b, 0, sizeof *b);
    isk_ui_init(&b->ui, 1);
    b->ui.font = font;
    b->blend = 2;
    b->rate = 420;
    b->spin = -90;
    cr_assert_eq(isk_canvas_init(&b->c, 320, 260), ISK_OK);
    frame(b);
}

static void settle(board *b)
{
    for (int i = 0; i < 100 && isk_ui_pending(&b->ui); i++)
        frame(b);
    frame(b);
}

static isk_ui_rect where(board *b, const char *id)
{
    isk_ui_rect r;
    cr_assert(isk_ui_find(&b->ui, id, &r), "no widget '%s'", id);
    return r;
}

static void click(board *b, const char *id)
{
    isk_ui_rect r = where(b, id);
    isk_ui_input_mouse(&b->ui, r.x + r.w / 2, r.y + r.h / 2);
    isk_ui_input_button(&b->ui, r.x + r.w / 2, r.y + r.h / 2, 1);
    isk_ui_input_button(&b->ui, r.x + r.w / 2, r.y + r.h / 2, 0);
}

Test(ui_widgets, a_choice_opens_its_list_and_picks)
{
    board b;
    setup(&b, ISK_FONT_5X8);
    cr_assert(!isk_ui_find(&b.ui, "blend/over", NULL), "closed: no options");
    click(&b, "blend");
    settle(&b);
    cr_assert(isk_ui_find(&b.ui, "blend/over", NULL), "open: each option has its name");
    /* the list covers the button under it: the press is the list's */
    isk_ui_rect over = where(&b, "blend/over"), under = where(&b, "under");
    cr_assert(over.y < under.y + under.h && over.y + over.h > under.y, "the test needs the option over the button");
    click(&b, "blend/over");
    settle(&b);
    cr_assert_eq(b.blend, 1);
    cr_assert_eq(b.chosen, 1);
    cr_assert_eq(b.under_clicks, 0, "the button under the list saw nothing");
    cr_assert(!isk_ui_find(&b.ui, "blend/over", NULL), "the list closed");
    /* Escape closes it without a choice; so does a press elsewhere, which
     * then reaches what it pressed */
    click(&b, "blend");
    settle(&b);
    isk_ui_input_key(&b.ui, ISK_UI_KEY_ESCAPE);
    settle(&b);
    cr_assert(!isk_ui_find(&b.ui, "blend/add", NULL));
    cr_assert(!isk_ui_key(&b.ui, ISK_UI_KEY_ESCAPE));
    click(&b, "blend");
    settle(&b);
    click(&b, "bounded");
    settle(&b);
    cr_assert(!isk_ui_find(&b.ui, "blend/add", NULL));
    cr_assert_eq(b.toggled, 1);
    cr_assert_eq(b.blend, 1);
    /* a press on the open choice itself closes it */
    click(&b, "blend");
    settle(&b);
    click(&b, "blend");
    settle(&b);
    cr_assert(!isk_ui_find(&b.ui, "blend/add", NULL));
    isk_canvas_free(&b.c);
}

/* Equal lengths per decade: 10x the value is the same distance along. */
Test(ui_widgets, the_log_slider_gives_every_decade_the_same_length)
{
    board b;
    setup(&b, ISK_FONT_5X8);
    isk_ui_rect r = where(&b, "rate");
    const int knob = 7, x0 = r.x + knob, w = r.w - 2 * knob;
    double at[3];
    const double fraction[3] = {0.5, 0.5 + 1 / 9.0, 0.5 + 2 / 9.0};
    for (int k = 0; k < 3; k++) {
        const int x = x0 + (int)lround(fraction[k] * w);
        isk_ui_input_mouse(&b.ui, x, r.y + 5);
        isk_ui_input_button(&b.ui, x, r.y + 5, 1);
        isk_ui_input_button(&b.ui, x, r.y + 5, 0);
        settle(&b);
        at[k] = b.rate;
        /* three significant digits */
        char t[32];
        snprintf(t, sizeof t, "%.3g", b.rate);
        cr_expect_eq(strtod(t, NULL), b.rate, "%.17g has more than 3 digits", b.rate);
    }
    /* 0..1e7 with 0.01 linear: 9 decades over the track, so 1/9 of it is about 10x */
    cr_expect(at[1] / at[0] > 8 && at[1] / at[0] < 12.5, "%g -> %g", at[0], at[1]);
    cr_expect(at[2] / at[1] > 8 && at[2] / at[1] < 12.5, "%g -> %g", at[1], at[2]);
    /* the ends are the range's */
    isk_ui_input_mouse(&b.ui, r.x + 1, r.y + 5); /* on the slider, before the track's start */
    isk_ui_input_button(&b.ui, r.x + 1, r.y + 5, 1);
    isk_ui_input_button(&b.ui, r.x + 1, r.y + 5, 0);
    settle(&b);
    cr_expect_eq(b.rate, 0);
    isk_ui_input_mouse(&b.ui, r.x + r.w - 1, r.y + 5);
    isk_ui_input_button(&b.ui, r.x + r.w - 1, r.y + 5, 1);
    isk_ui_input_button(&b.ui, r.x + r.w - 1, r.y + 5, 0);
    settle(&b);
    cr_expect_eq(b.rate, 1e7);
    /* the symmetric one: its middle is 0, whole numbers only */
    isk_ui_rect s = where(&b, "spin");
    isk_ui_input_mouse(&b.ui, s.x + s.w / 2, s.y + 5);
    isk_ui_input_button(&b.ui, s.x + s.w / 2, s.y + 5, 1);
    isk_ui_input_button(&b.ui, s.x + s.w / 2, s.y + 5, 0);
    settle(&b);
    cr_expect(fabs(b.spin) < 3, "the middle: %g", b.spin);
    isk_ui_input_mouse(&b.ui, s.x + s.w * 3 / 4, s.y + 5);
    isk_ui_input_wheel(&b.ui, 1);
    settle(&b);
    cr_expect_gt(b.spin, 0);
    cr_expect_eq(b.spin, floor(b.spin));
    double v = 5;
    cr_assert_eq(isk_ui_slider_log(&b.ui, "bad", r, &v, 0, 1, 0, 0), 0, "linear must be > 0");
    isk_canvas_free(&b.c);
}

Test(ui_widgets, the_scroll_bar_the_wheel_and_selectable_rows)
{
    board b;
    setup(&b, ISK_FONT_5X8);
    cr_assert(isk_ui_find(&b.ui, "row/0", NULL) && !isk_ui_find(&b.ui, "row/3", NULL));
    isk_ui_rect r = where(&b, "row/1");
    isk_ui_input_mouse(&b.ui, r.x + 5, r.y + 5);
    isk_ui_input_wheel(&b.ui, -1);
    isk_ui_input_wheel(&b.ui, -1);
    settle(&b);
    cr_assert_eq(b.first, 2);
    for (int i = 0; i < 5; i++)
        isk_ui_input_wheel(&b.ui, -1);
    settle(&b);
    cr_assert_eq(b.first, 3, "no further than the last row");
    click(&b, "row/4");
    settle(&b);
    cr_assert_eq(b.row, 4);
    /* a click at the bar's top scrolls back to the first row */
    isk_ui_rect bar = where(&b, "rows-scroll");
    isk_ui_input_mouse(&b.ui, bar.x + 2, bar.y + 1);
    isk_ui_input_button(&b.ui, bar.x + 2, bar.y + 1, 1);
    isk_ui_input_button(&b.ui, bar.x + 2, bar.y + 1, 0);
    settle(&b);
    cr_assert_eq(b.first, 0);
    /* the wheel elsewhere does nothing to it */
    isk_ui_input_mouse(&b.ui, 2, 2);
    isk_ui_input_wheel(&b.ui, -1);
    settle(&b);
    cr_assert_eq(b.first, 0);
    isk_canvas_free(&b.c);
}

/* Every one of these widgets at rest, then with the choice open, in the
 * 6x13 font (capitals 10 px tall). */
Test(refimg, ui_inspector_widgets)
{
    board b;
    setup(&b, ISK_FONT_6X13);
    b.row = 1;
    settle(&b);
    cr_assert(refimg_check("ui_inspector_widgets", &b.c));
    click(&b, "blend");
    settle(&b);
    cr_assert(refimg_check("ui_choice_open", &b.c));
    isk_canvas_free(&b.c);
}
