/* SPDX-License-Identifier: MIT */
/* Editing in the widget layer's fields, as a spin box edits (iskra/ui.h):
 * the focus selects the whole value so what is typed replaces it ("10"
 * typed into 9.81 is 10, not 9.8110); Ctrl+A and a double click select
 * all; the arrows end a selection.  And messages: a refused value's
 * message is shown whole, wrapped, in the program's layout or inside the
 * panel that holds its field, never wider than that panel. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>

#include "iskra/ui.h"
#include "refimg.h"

typedef struct form {
    isk_ui ui;
    isk_canvas c;
    char value[64];    /* what field "g" shows */
    char applied[64];  /* the last text applied */
    int applies;
    const char *refusal; /* refuse every apply with this message (NULL: accept) */
    int in_flow;         /* 1: the message goes under the field, in the layout */
    isk_ui_rect panel, field, after; /* where the panel, the field and the widget after it were */
} form;

static void frame(form *f)
{
    isk_ui *ui = &f->ui;
    isk_ui_begin(ui, &f->c);
    isk_ui_clear(ui);
    f->panel = (isk_ui_rect){10, 10, 150, f->c.height - 20};
    isk_ui_panel(ui, f->panel);
    isk_ui_rect a = isk_ui_inset(f->panel, isk_ui_px(ui, 6));
    f->field = isk_ui_cut_top(&a, isk_ui_row_height(ui));
    isk_ui_cut_top(&a, isk_ui_px(ui, 4));
    char typed[64];
    if (isk_ui_field(ui, "g", f->field, f->value, ISK_UI_FIELD_NUMBER, typed, sizeof typed) == ISK_UI_FIELD_APPLY) {
        f->applies++;
        if (f->refusal) {
            isk_ui_field_error(ui, "g", f->refusal);
        } else {
            snprintf(f->applied, sizeof f->applied, "%s", typed);
            snprintf(f->value, sizeof f->value, "%s", typed);
        }
    }
    if (f->in_flow)
        isk_ui_field_message(ui, "g", &a);
    f->after = isk_ui_cut_top(&a, isk_ui_row_height(ui));
    isk_ui_button(ui, "after", f->after, "After");
    isk_ui_end(ui);
}

static void setup(form *f, int scale, isk_font font)
{
    memset(f, 0, sizeof *f);
    isk_ui_init(&f->ui, scale);
    f->ui.font = font;
    cr_assert_eq(isk_canvas_init(&f->c, 240 * scale, 190 * scale), ISK_OK);
    snprintf(f->value, sizeof f->value, "9.81");
    frame(f);
}

static void settle(form *f)
{
    for (int i = 0; i < 100 && isk_ui_pending(&f->ui); i++)
        frame(f);
    frame(f);
}

static void click(form *f, int x, int y, int clicks)
{
    isk_ui_input_mouse(&f->ui, x, y);
    isk_ui_input_button_clicks(&f->ui, x, y, 1, clicks);
    isk_ui_input_button_clicks(&f->ui, x, y, 0, clicks);
}

static void click_field(form *f) { click(f, f->field.x + f->field.w / 2, f->field.y + f->field.h / 2, 1); }

/* ---- selection ---------------------------------------------------------------------- */

/* The reviewers' case: "type 10 into Gravity" gave 9.811. */
Test(ui_fields, typing_into_a_field_replaces_its_value)
{
    form f;
    setup(&f, 1, ISK_FONT_5X8);
    click_field(&f);
    settle(&f);
    cr_assert_str_eq(f.ui.edit, "9.81");
    cr_assert_eq(f.ui.anchor, 0);
    cr_assert_eq(f.ui.cursor, 4, "the whole value is selected");
    isk_ui_input_text(&f.ui, "10");
    isk_ui_input_key(&f.ui, ISK_UI_KEY_RETURN);
    settle(&f);
    cr_assert_str_eq(f.applied, "10");
    /* Tab into it (no click): selected too */
    isk_ui_focus(&f.ui, "g");
    settle(&f);
    isk_ui_input_text(&f.ui, "3");
    isk_ui_input_key(&f.ui, ISK_UI_KEY_RETURN);
    settle(&f);
    cr_assert_str_eq(f.applied, "3");
    /* Backspace and Delete remove the selection */
    click_field(&f);
    settle(&f);
    isk_ui_input_key(&f.ui, ISK_UI_KEY_DELETE);
    frame(&f);
    cr_assert_str_eq(f.ui.edit, "");
    isk_ui_input_key(&f.ui, ISK_UI_KEY_ESCAPE);
    settle(&f);
    cr_assert_str_eq(f.value, "3");
    isk_canvas_free(&f.c);
}

Test(ui_fields, arrows_end_the_selection_and_a_click_places_the_cursor)
{
    form f;
    setup(&f, 1, ISK_FONT_5X8);
    click_field(&f);
    settle(&f);
    isk_ui_input_key(&f.ui, ISK_UI_KEY_LEFT); /* to the selection's start */
    isk_ui_input_text(&f.ui, "1");
    frame(&f);
    cr_assert_str_eq(f.ui.edit, "19.81");
    isk_ui_input_key(&f.ui, ISK_UI_MOD_CTRL | 'a');
    isk_ui_input_key(&f.ui, ISK_UI_KEY_RIGHT); /* to its end */
    isk_ui_input_text(&f.ui, "2");
    frame(&f);
    cr_assert_str_eq(f.ui.edit, "19.812");
    /* a click inside the focused field puts the cursor there: no selection */
    const int cell = isk_font_metrics_of(ISK_FONT_5X8)->cell_w, tw = isk_ui_text_width(&f.ui, "19.812");
    const int inner_x = f.field.x + 4, inner_w = f.field.w - 8, x0 = inner_x + (inner_w - tw) / 2;
    click(&f, x0 + 2 * cell, f.field.y + 5, 1);
    settle(&f);
    cr_assert_eq(f.ui.cursor, 2);
    cr_assert_eq(f.ui.anchor, 2);
    isk_ui_input_text(&f.ui, "5");
    frame(&f);
    cr_assert_str_eq(f.ui.edit, "195.812");
    isk_canvas_free(&f.c);
}

Test(ui_fields, ctrl_a_and_a_double_click_select_all)
{
    form f;
    setup(&f, 1, ISK_FONT_5X8);
    click_field(&f);
    settle(&f);
    isk_ui_input_key(&f.ui, ISK_UI_KEY_END);
    isk_ui_input_key(&f.ui, ISK_UI_MOD_CTRL | 'a');
    isk_ui_input_text(&f.ui, "7");
    frame(&f);
    cr_assert_str_eq(f.ui.edit, "7");
    cr_assert(!isk_ui_key(&f.ui, ISK_UI_MOD_CTRL | 'a'), "the field took Ctrl+A: it is no shortcut");
    /* a single click deselects, the double click's second press selects all */
    click_field(&f);
    settle(&f);
    cr_assert_eq(f.ui.anchor, f.ui.cursor);
    click(&f, f.field.x + 5, f.field.y + 5, 2);
    settle(&f);
    cr_assert_eq(f.ui.anchor, 0);
    cr_assert_eq(f.ui.cursor, 1);
    isk_ui_input_text(&f.ui, "8");
    isk_ui_input_key(&f.ui, ISK_UI_KEY_RETURN);
    settle(&f);
    cr_assert_str_eq(f.applied, "8");
    isk_canvas_free(&f.c);
}

/* The selection drawn: the 6x13 font, the value highlighted. */
Test(refimg, ui_field_selected)
{
    form f;
    setup(&f, 1, ISK_FONT_6X13);
    click_field(&f);
    settle(&f);
    cr_assert(isk_ui_focused(&f.ui, "g"));
    cr_assert(refimg_check("ui_field_selected", &f.c));
    isk_canvas_free(&f.c);
}

/* ---- messages --------------------------------------------------------------------------- */

static const char *const long_message =
    "[force gravity] g: expected a number between 0 and 1e12, got \"-5\" (the key's row in iskra keys)";

/* The pixels in the error colour under the field (its outline is in it
 * too): how many, and their bounding box. */
static int error_pixels(const form *f, int *x0, int *y0, int *x1, int *y1)
{
    const isk_color e = f->ui.style.error;
    int n = 0;
    *x0 = *y0 = 1 << 30;
    *x1 = *y1 = -1;
    for (int y = f->field.y + f->field.h; y < f->c.height; y++)
        for (int x = 0; x < f->c.width; x++) {
            isk_color c = isk_canvas_get(&f->c, x, y);
            if (c.r == e.r && c.g == e.g && c.b == e.b) {
                n++;
                *x0 = x < *x0 ? x : *x0;
                *y0 = y < *y0 ? y : *y0;
                *x1 = x > *x1 ? x : *x1;
                *y1 = y > *y1 ? y : *y1;
            }
        }
    return n;
}

static void refuse(form *f)
{
    click_field(f);
    settle(f);
    isk_ui_input_text(&f->ui, "-5");
    isk_ui_input_key(&f->ui, ISK_UI_KEY_RETURN);
    settle(f);
}

/* Not placed by the program: a box under the field, wrapped inside the
 * panel that holds the field (the reviewers saw it centred, wider than the
 * column and cut at both edges). */
Test(ui_fields, a_floating_message_wraps_inside_its_panel)
{
    form f;
    setup(&f, 1, ISK_FONT_6X13);
    f.refusal = long_message;
    refuse(&f);
    const char *id;
    cr_assert_str_eq(isk_ui_field_message_text(&f.ui, &id), long_message);
    cr_assert_str_eq(id, "g");
    int x0, y0, x1, y1;
    cr_assert_gt(error_pixels(&f, &x0, &y0, &x1, &y1), 0);
    cr_expect(x0 >= f.panel.x && x1 < f.panel.x + f.panel.w, "the message spans %d..%d, the panel %d..%d", x0, x1,
              f.panel.x, f.panel.x + f.panel.w - 1);
    cr_expect(y1 < f.panel.y + f.panel.h);
    /* whole: as many lines as wrapping the message to the panel gives */
    char lines[400];
    int n = isk_ui_wrap(&f.ui, long_message, f.panel.w - 6, lines, sizeof lines);
    cr_expect_geq(n, 5);
    cr_expect_geq(y1 - f.field.y - f.field.h, (n - 1) * isk_ui_line_height(&f.ui), "all %d lines are drawn", n);
    cr_assert(refimg_check("ui_message_floating", &f.c));
    isk_canvas_free(&f.c);
}

/* Placed by the program under its field: the layout makes room, so the
 * button after the field moves down and nothing is covered. */
Test(ui_fields, a_message_in_the_layout_pushes_what_follows_down)
{
    form f;
    setup(&f, 1, ISK_FONT_6X13);
    f.in_flow = 1;
    const isk_ui_rect before = f.after;
    f.refusal = long_message;
    refuse(&f);
    int x0, y0, x1, y1;
    cr_assert_gt(error_pixels(&f, &x0, &y0, &x1, &y1), 0);
    cr_expect_gt(f.after.y, before.y, "the button moved down");
    cr_expect_lt(y1, f.after.y, "the message ends above the button");
    cr_expect_lt(y0, f.field.y + f.field.h + isk_ui_row_height(&f.ui), "and starts right under the field");
    cr_assert(refimg_check("ui_message_in_flow", &f.c));
    /* Escape: the message goes, the button comes back */
    isk_ui_input_key(&f.ui, ISK_UI_KEY_ESCAPE);
    settle(&f);
    cr_expect_eq(f.after.y, before.y);
    cr_expect_null(isk_ui_field_message_text(&f.ui, NULL));
    isk_canvas_free(&f.c);
}

Test(ui_fields, wrapping_breaks_at_spaces_and_inside_long_words)
{
    isk_ui ui;
    isk_ui_init(&ui, 1);
    char out[200];
    /* 60 px of 6-px cells: 10 characters a line */
    cr_assert_eq(isk_ui_wrap(&ui, "the quick brown fox jumps", 60, out, sizeof out), 3);
    cr_assert_str_eq(out, "the quick\nbrown fox\njumps");
    cr_assert_eq(isk_ui_wrap(&ui, "a/very/long/path/name.ini ok", 60, out, sizeof out), 3);
    cr_assert_str_eq(out, "a/very/lon\ng/path/nam\ne.ini ok");
    cr_assert_eq(isk_ui_wrap(&ui, "two\nlines", 60, out, sizeof out), 2);
    cr_assert_str_eq(out, "two\nlines");
    cr_assert_eq(isk_ui_wrap(&ui, "", 60, out, sizeof out), 0);
    cr_assert_eq(isk_ui_wrap(&ui, "too narrow", 24, out, sizeof out), 0, "under five characters a line");
    ui.font = ISK_FONT_6X13; /* 7-px cells: 8 characters in 60 px */
    cr_assert_eq(isk_ui_wrap(&ui, "the quick brown", 60, out, sizeof out), 3);
    cr_assert_eq(isk_ui_line_height(&ui), 14);
    cr_assert_eq(isk_ui_row_height(&ui), 20);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 100, 100), ISK_OK);
    isk_ui_begin(&ui, &c);
    cr_assert_eq(isk_ui_text_wrapped(&ui, (isk_ui_rect){0, 0, 60, 100}, "the quick brown", ui.style.text), 42);
    isk_ui_end(&ui);
    isk_canvas_free(&c);
}
