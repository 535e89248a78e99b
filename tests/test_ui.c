/* SPDX-License-Identifier: MIT */
/* The widget layer (iskra/ui.h) driven by scripted input, without SDL:
 * what each widget returns, focus and editing, the input queue, layout,
 * and reference images of every widget in every state. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>

#include "iskra/ui.h"
#include "refimg.h"

/* ---- a small panel used by most tests ------------------------------------------- */

typedef struct panel {
    isk_ui ui;
    isk_canvas c;
    int clicks, flips, radio, row, scroll, on, bar;
    double slider;
    char a[64], b[64];     /* the values fields a and b show */
    char applied[64];      /* the last text applied, and where */
    const char *applied_to;
    int cancels;
    const char *refuse;    /* refuse applies in this field, with a message */
    isk_ui_area_state area;
    int disabled_clicks;
} panel;

static const char *const options[] = {"one", "two words", "three"};
static const char *const rows[] = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta"};

static void field(panel *p, const char *id, isk_ui_rect r, char *value, unsigned flags)
{
    char typed[64];
    isk_ui_field_result res = isk_ui_field(&p->ui, id, r, value, flags, typed, sizeof typed);
    if (res == ISK_UI_FIELD_APPLY) {
        if (p->refuse && !strcmp(p->refuse, id)) {
            isk_ui_field_error(&p->ui, id, "refused: expected 1..9");
        } else {
            snprintf(p->applied, sizeof p->applied, "%s", typed);
            p->applied_to = id;
            memcpy(value, typed, sizeof typed);
        }
    } else if (res == ISK_UI_FIELD_CANCEL) {
        p->cancels++;
    }
}

/* One frame of the panel: 320 x 240 at scale 1 (sizes in units of the scale). */
static void frame(panel *p)
{
    isk_ui *ui = &p->ui;
#define U(n) isk_ui_px(ui, n)
    isk_ui_begin(ui, &p->c);
    isk_ui_clear(ui);
    isk_ui_rect all = isk_ui_inset((isk_ui_rect){0, 0, p->c.width, p->c.height}, U(4)), line;
    isk_ui_panel(ui, all);
    all = isk_ui_inset(all, U(6));
    const int row = isk_ui_row_height(ui);
    line = isk_ui_cut_top(&all, row);
    if (isk_ui_button(ui, "button", isk_ui_cut_left(&line, U(80)), "Button"))
        p->clicks++;
    isk_ui_cut_left(&line, U(6));
    if (isk_ui_toggle(ui, "toggle", isk_ui_cut_left(&line, U(80)), "toggle", &p->on))
        p->flips++;
    isk_ui_cut_left(&line, U(6));
    isk_ui_icon_button(ui, "play", isk_ui_cut_left(&line, U(30)), ISK_UI_ICON_PLAY, isk_rgba(0x44, 0x8e, 0x44, 255),
                       NULL);
    isk_ui_cut_left(&line, U(4));
    isk_ui_icon_button(ui, "reload", isk_ui_cut_left(&line, U(30)), ISK_UI_ICON_RELOAD,
                       isk_rgba(0xd8, 0x2a, 0x1e, 255), NULL);
    isk_ui_cut_top(&all, U(4));
    line = isk_ui_cut_top(&all, row);
    isk_ui_slider(ui, "slider", line, &p->slider, 0, 100, 5);
    isk_ui_cut_top(&all, U(4));
    line = isk_ui_cut_top(&all, row);
    isk_ui_label(ui, isk_ui_cut_left(&line, U(20)), "a", ISK_UI_LEFT);
    field(p, "a", isk_ui_cut_left(&line, U(100)), p->a, ISK_UI_FIELD_NUMBER);
    isk_ui_cut_left(&line, U(6));
    isk_ui_label(ui, isk_ui_cut_left(&line, U(20)), "b", ISK_UI_LEFT);
    field(p, "b", line, p->b, 0);
    isk_ui_cut_top(&all, U(4));
    line = isk_ui_cut_top(&all, row);
    isk_ui_radio(ui, "radio", line, options, 3, 0, &p->radio);
    isk_ui_cut_top(&all, U(4));
    line = isk_ui_cut_top(&all, 3 * row + U(2));
    isk_ui_list(ui, "list", isk_ui_cut_left(&line, U(140)), rows, 6, &p->row, &p->scroll);
    isk_ui_cut_left(&line, U(6));
    isk_ui_rect bars = isk_ui_cut_left(&line, U(40));
    isk_ui_toggle_bar(ui, "bar", isk_ui_cut_top(&bars, U(8)), &p->bar);
    isk_ui_cut_left(&line, U(6));
    p->area = isk_ui_area(ui, "area", line);
    isk_ui_box(ui, line);
    isk_ui_cut_top(&all, U(4));
    line = isk_ui_cut_top(&all, row);
    isk_ui_set_disabled(ui, 1);
    if (isk_ui_button(ui, "disabled", isk_ui_cut_left(&line, U(80)), "Disabled"))
        p->disabled_clicks++;
    isk_ui_set_disabled(ui, 0);
    isk_ui_cut_left(&line, U(6));
    isk_ui_field(ui, "readonly", isk_ui_cut_left(&line, U(80)), "1000", ISK_UI_FIELD_READONLY, NULL, 0);
    isk_ui_end(ui);
#undef U
}

static void setup(panel *p)
{
    memset(p, 0, sizeof *p);
    isk_ui_init(&p->ui, 1);
    cr_assert_eq(isk_canvas_init(&p->c, 320, 240), ISK_OK);
    snprintf(p->a, sizeof p->a, "9.81");
    snprintf(p->b, sizeof p->b, "text");
    p->slider = 50;
    frame(p); /* lays the widgets out: isk_ui_find works from here */
}

static void teardown(panel *p) { isk_canvas_free(&p->c); }

static isk_ui_rect where(panel *p, const char *id)
{
    isk_ui_rect r;
    cr_assert(isk_ui_find(&p->ui, id, &r), "no widget '%s'", id);
    return r;
}

static void click_at(panel *p, int x, int y)
{
    isk_ui_input_mouse(&p->ui, x, y);
    isk_ui_input_button(&p->ui, x, y, 1);
    isk_ui_input_button(&p->ui, x, y, 0);
}

static void click(panel *p, const char *id)
{
    isk_ui_rect r = where(p, id);
    click_at(p, r.x + r.w / 2, r.y + r.h / 2);
}

/* Frames until every queued event is taken, then one more. */
static void settle(panel *p)
{
    for (int i = 0; i < 100 && isk_ui_pending(&p->ui); i++)
        frame(p);
    frame(p);
}

/* ---- buttons, toggles, names ------------------------------------------------- */

Test(ui, button_clicks_once_per_press_and_release_over_it)
{
    panel p;
    setup(&p);
    click(&p, "button");
    settle(&p);
    cr_assert_eq(p.clicks, 1);
    /* pressed over it, released elsewhere: no click */
    isk_ui_rect r = where(&p, "button");
    isk_ui_input_button(&p.ui, r.x + 5, r.y + 5, 1);
    isk_ui_input_mouse(&p.ui, 300, 230);
    isk_ui_input_button(&p.ui, 300, 230, 0);
    settle(&p);
    cr_assert_eq(p.clicks, 1);
    /* pressed elsewhere, released over it: no click */
    isk_ui_input_button(&p.ui, 300, 230, 1);
    isk_ui_input_mouse(&p.ui, r.x + 5, r.y + 5);
    isk_ui_input_button(&p.ui, r.x + 5, r.y + 5, 0);
    settle(&p);
    cr_assert_eq(p.clicks, 1);
    /* a disabled button never clicks */
    click(&p, "disabled");
    settle(&p);
    cr_assert_eq(p.disabled_clicks, 0);
    teardown(&p);
}

Test(ui, two_clicks_between_frames_are_two_frames_of_input)
{
    panel p;
    setup(&p);
    click(&p, "button");
    click(&p, "toggle");
    cr_assert_eq(isk_ui_pending(&p.ui), 6); /* a move, a press and a release each */
    frame(&p);
    cr_assert_eq(p.clicks, 1);
    cr_assert_eq(p.flips, 0);
    frame(&p);
    cr_assert_eq(p.flips, 1);
    cr_assert_eq(p.on, 1);
    cr_assert_eq(isk_ui_pending(&p.ui), 0);
    teardown(&p);
}

Test(ui, toggles_flip_and_radio_and_list_choose)
{
    panel p;
    setup(&p);
    click(&p, "toggle");
    click(&p, "bar");
    click(&p, "radio/two-words");
    click(&p, "list/2");
    settle(&p);
    cr_assert_eq(p.on, 1);
    cr_assert_eq(p.bar, 1);
    cr_assert_eq(p.radio, 1);
    cr_assert_eq(p.row, 2);
    click(&p, "radio/three");
    click(&p, "toggle");
    settle(&p);
    cr_assert_eq(p.radio, 2);
    cr_assert_eq(p.on, 0);
    cr_assert_eq(p.flips, 2);
    teardown(&p);
}

Test(ui, list_scrolls_with_the_wheel_and_names_its_rows)
{
    panel p;
    setup(&p);
    isk_ui_rect r = where(&p, "list");
    cr_assert(isk_ui_find(&p.ui, "list/0", NULL));
    cr_assert(!isk_ui_find(&p.ui, "list/3", NULL)); /* three rows fit */
    isk_ui_input_mouse(&p.ui, r.x + 10, r.y + 10);
    isk_ui_input_wheel(&p.ui, -1);
    isk_ui_input_wheel(&p.ui, -1);
    settle(&p);
    cr_assert_eq(p.scroll, 2);
    cr_assert(isk_ui_find(&p.ui, "list/4", NULL));
    cr_assert(!isk_ui_find(&p.ui, "list/0", NULL));
    for (int i = 0; i < 10; i++)
        isk_ui_input_wheel(&p.ui, -1);
    settle(&p);
    cr_assert_eq(p.scroll, 3, "scrolls no further than the last row");
    click(&p, "list/5");
    settle(&p);
    cr_assert_eq(p.row, 5);
    teardown(&p);
}

Test(ui, slider_follows_a_drag_in_steps_and_the_wheel)
{
    panel p;
    setup(&p);
    isk_ui_rect r = where(&p, "slider");
    const int knob = 7, x0 = r.x + knob, w = r.w - 2 * knob;
    isk_ui_input_mouse(&p.ui, x0 + w / 2, r.y + 5);
    isk_ui_input_button(&p.ui, x0 + w / 2, r.y + 5, 1);
    frame(&p);
    isk_ui_input_mouse(&p.ui, x0 + w * 23 / 100, r.y + 5); /* 23 % of the way: the step 5 gives 25 */
    frame(&p);
    cr_assert_float_eq(p.slider, 25.0, 1e-12);
    isk_ui_input_mouse(&p.ui, x0 + w + 40, r.y + 5); /* beyond the end: clamped */
    isk_ui_input_button(&p.ui, x0 + w + 40, r.y + 5, 0);
    settle(&p);
    cr_assert_float_eq(p.slider, 100.0, 1e-12);
    isk_ui_input_mouse(&p.ui, x0 + 3, r.y + 5);
    isk_ui_input_wheel(&p.ui, -1);
    settle(&p);
    cr_assert_float_eq(p.slider, 95.0, 1e-12);
    teardown(&p);
}

Test(ui, area_reports_press_drag_and_release_in_its_coordinates)
{
    panel p;
    setup(&p);
    isk_ui_rect r = where(&p, "area");
    isk_ui_input_button(&p.ui, r.x + 3, r.y + 4, 1);
    frame(&p);
    cr_assert(p.area.pressed && p.area.down && p.area.hover);
    cr_assert_eq(p.area.x, 3);
    cr_assert_eq(p.area.y, 4);
    isk_ui_input_mouse(&p.ui, r.x + 30, r.y + 20);
    frame(&p);
    cr_assert(!p.area.pressed && p.area.down);
    cr_assert_eq(p.area.x, 30);
    isk_ui_input_button(&p.ui, 2, 2, 0); /* released outside: still its release */
    frame(&p);
    cr_assert(p.area.released && !p.area.down && !p.area.hover);
    teardown(&p);
}

/* ---- fields ------------------------------------------------------------------- */

Test(ui, a_field_edits_with_a_cursor_and_applies_on_return)
{
    panel p;
    setup(&p);
    click(&p, "a");
    settle(&p);
    cr_assert(isk_ui_editing(&p.ui));
    cr_assert_str_eq(p.ui.edit, "9.81");
    cr_assert_eq(p.ui.cursor, 4);
    cr_assert_eq(p.ui.anchor, 0, "the focus selects the whole value");
    isk_ui_input_key(&p.ui, ISK_UI_KEY_END); /* the selection ends; the cursor after the text */
    isk_ui_input_key(&p.ui, ISK_UI_KEY_BACKSPACE);
    isk_ui_input_key(&p.ui, ISK_UI_KEY_HOME);
    isk_ui_input_key(&p.ui, ISK_UI_KEY_DELETE);
    isk_ui_input_text(&p.ui, "1x2"); /* a number field drops the x */
    isk_ui_input_key(&p.ui, ISK_UI_KEY_END);
    isk_ui_input_key(&p.ui, ISK_UI_KEY_LEFT);
    isk_ui_input_text(&p.ui, "5");
    frame(&p);
    cr_assert_str_eq(p.ui.edit, "12.58");
    cr_assert_str_eq(p.a, "9.81", "nothing applies before Return");
    isk_ui_input_key(&p.ui, ISK_UI_KEY_RETURN);
    settle(&p);
    cr_assert_str_eq(p.applied, "12.58");
    cr_assert_str_eq(p.applied_to, "a");
    cr_assert_str_eq(p.a, "12.58");
    cr_assert(!isk_ui_editing(&p.ui));
    teardown(&p);
}

Test(ui, escape_cancels_and_tab_moves_on)
{
    panel p;
    setup(&p);
    click(&p, "a");
    settle(&p);
    isk_ui_input_text(&p.ui, "77");
    isk_ui_input_key(&p.ui, ISK_UI_KEY_ESCAPE);
    settle(&p);
    cr_assert_eq(p.cancels, 1);
    cr_assert_str_eq(p.a, "9.81");
    cr_assert(!isk_ui_editing(&p.ui));
    cr_assert_eq(p.applied_to, NULL);
    /* Tab applies a and gives b the focus, with b's text selected */
    click(&p, "a");
    settle(&p);
    isk_ui_input_text(&p.ui, "1");
    isk_ui_input_key(&p.ui, ISK_UI_KEY_TAB);
    isk_ui_input_text(&p.ui, "!");
    isk_ui_input_key(&p.ui, ISK_UI_KEY_RETURN);
    settle(&p);
    cr_assert_str_eq(p.a, "1");
    cr_assert_str_eq(p.b, "!");
    teardown(&p);
}

Test(ui, a_click_elsewhere_applies_and_the_clicked_field_edits_next)
{
    panel p;
    setup(&p);
    click(&p, "a");
    settle(&p);
    isk_ui_input_text(&p.ui, "9");
    click(&p, "b");
    settle(&p);
    cr_assert_str_eq(p.a, "9");
    cr_assert(isk_ui_editing(&p.ui));
    cr_assert_str_eq(p.ui.edit, "text");
    click(&p, "area");
    settle(&p);
    cr_assert(!isk_ui_editing(&p.ui));
    cr_assert_str_eq(p.applied_to, "b");
    teardown(&p);
}

Test(ui, a_refused_value_keeps_the_text_and_says_why)
{
    panel p;
    setup(&p);
    p.refuse = "a";
    click(&p, "a");
    settle(&p);
    isk_ui_input_key(&p.ui, ISK_UI_KEY_END);
    isk_ui_input_text(&p.ui, "0");
    isk_ui_input_key(&p.ui, ISK_UI_KEY_RETURN);
    settle(&p);
    cr_assert_str_eq(p.a, "9.81");
    cr_assert(isk_ui_editing(&p.ui), "still in the field");
    cr_assert_str_eq(p.ui.edit, "9.810");
    cr_assert_str_eq(p.ui.error, "refused: expected 1..9");
    cr_assert(refimg_check("ui_field_error", &p.c));
    isk_ui_input_key(&p.ui, ISK_UI_KEY_ESCAPE);
    settle(&p);
    cr_assert_eq(p.ui.error_id, 0u);
    cr_assert_str_eq(p.a, "9.81");
    teardown(&p);
}

Test(ui, shortcuts_reach_the_program_only_outside_fields)
{
    panel p;
    setup(&p);
    isk_ui_input_key(&p.ui, 'r');
    frame(&p);
    cr_assert(isk_ui_key(&p.ui, 'r'));
    cr_assert(!isk_ui_key(&p.ui, 's'));
    click(&p, "b");
    settle(&p);
    isk_ui_input_key(&p.ui, 'r');
    isk_ui_input_text(&p.ui, "r");
    isk_ui_input_key(&p.ui, ISK_UI_KEY_F1 + 11);
    frame(&p);
    cr_assert(!isk_ui_key(&p.ui, 'r'), "typed into the field");
    cr_assert(isk_ui_key(&p.ui, ISK_UI_KEY_F12), "function keys always reach the program");
    cr_assert_str_eq(p.ui.edit, "r", "the typing replaced the selected text");
    teardown(&p);
}

Test(ui, focus_can_be_given_and_a_field_not_drawn_loses_it)
{
    panel p;
    setup(&p);
    isk_ui_focus(&p.ui, "b");
    frame(&p);
    cr_assert(isk_ui_editing(&p.ui));
    cr_assert_str_eq(p.ui.edit, "text");
    /* a frame without the field */
    isk_ui_begin(&p.ui, &p.c);
    isk_ui_end(&p.ui);
    cr_assert(!isk_ui_editing(&p.ui));
    teardown(&p);
}

/* ---- pictures ------------------------------------------------------------------- */

Test(ui, every_widget_at_rest)
{
    panel p;
    setup(&p);
    cr_assert(refimg_check("ui_widgets", &p.c));
    teardown(&p);
}

Test(ui, hover_and_focused_states)
{
    panel p;
    setup(&p);
    p.on = p.bar = 1;
    p.radio = 2;
    p.row = 1;
    click(&p, "a");
    settle(&p);
    isk_ui_input_key(&p.ui, ISK_UI_KEY_END);
    isk_ui_input_text(&p.ui, "2");
    isk_ui_input_key(&p.ui, ISK_UI_KEY_LEFT);
    isk_ui_rect b = where(&p, "button");
    isk_ui_input_mouse(&p.ui, b.x + 10, b.y + 5); /* hovered */
    settle(&p);
    cr_assert_str_eq(p.ui.edit, "9.812");
    cr_assert_eq(p.ui.cursor, 4);
    cr_assert(isk_ui_hovering(&p.ui));
    cr_assert(refimg_check("ui_states", &p.c));
    teardown(&p);
}

Test(ui, pressed_state)
{
    panel p;
    setup(&p);
    isk_ui_rect b = where(&p, "button"), t = where(&p, "play");
    isk_ui_input_mouse(&p.ui, t.x + 3, t.y + 3);
    frame(&p);
    isk_ui_input_button(&p.ui, b.x + 10, b.y + 5, 1); /* held down over the button */
    settle(&p);
    cr_assert_eq(p.clicks, 0, "not a click until released");
    cr_assert(refimg_check("ui_pressed", &p.c));
    isk_ui_input_button(&p.ui, b.x + 10, b.y + 5, 0);
    settle(&p);
    cr_assert_eq(p.clicks, 1);
    teardown(&p);
}

Test(ui, scale_two_doubles_every_metric)
{
    panel p;
    memset(&p, 0, sizeof p);
    isk_ui_init(&p.ui, 2);
    cr_assert_eq(isk_ui_row_height(&p.ui), 30);
    cr_assert_eq(isk_ui_px(&p.ui, 7), 14);
    cr_assert_eq(isk_ui_text_width(&p.ui, "abc"), 34);
    cr_assert_eq(isk_canvas_init(&p.c, 640, 480), ISK_OK);
    snprintf(p.a, sizeof p.a, "9.81");
    snprintf(p.b, sizeof p.b, "text");
    p.slider = 50;
    frame(&p); /* the same panel, every size doubled */
    cr_assert(refimg_check("ui_scale2", &p.c));
    teardown(&p);
}

Test(ui, the_same_session_gives_the_same_bytes)
{
    panel p, q;
    setup(&p);
    setup(&q);
    panel *both[2] = {&p, &q};
    for (int k = 0; k < 2; k++) {
        panel *x = both[k];
        click(x, "toggle");
        click(x, "a");
        isk_ui_input_text(&x->ui, "5");
        isk_ui_input_key(&x->ui, ISK_UI_KEY_RETURN);
        click(x, "list/1");
        settle(x);
    }
    cr_assert(isk_canvas_equal(&p.c, &q.c));
    cr_assert_str_eq(p.a, "5");
    teardown(&p);
    teardown(&q);
}

/* ---- layout and robustness ------------------------------------------------------ */

Test(ui, cutting_rectangles)
{
    isk_ui_rect r = {10, 20, 100, 50};
    isk_ui_rect t = isk_ui_cut_top(&r, 15);
    cr_assert(t.x == 10 && t.y == 20 && t.w == 100 && t.h == 15);
    cr_assert(r.y == 35 && r.h == 35);
    isk_ui_rect l = isk_ui_cut_left(&r, 30);
    cr_assert(l.w == 30 && r.x == 40 && r.w == 70);
    isk_ui_rect b = isk_ui_cut_bottom(&r, 500); /* more than there is: all of it */
    cr_assert(b.h == 35 && r.h == 0);
    isk_ui_rect in = isk_ui_inset((isk_ui_rect){0, 0, 4, 4}, 5);
    cr_assert(in.w == 0 && in.h == 0);
    /* cells tile the rectangle exactly */
    isk_ui_rect whole = {0, 0, 101, 10};
    int x = 0;
    for (int i = 0; i < 3; i++) {
        isk_ui_rect c = isk_ui_cell(whole, 3, 1, i, 0, 2);
        cr_assert_eq(c.x, x);
        x = c.x + c.w + 2;
    }
    cr_assert_eq(x - 2, 101);
    cr_assert_eq(isk_ui_fit_scale(1400, 950, 660, 450, 4), 2);
    cr_assert_eq(isk_ui_fit_scale(600, 400, 660, 450, 4), 1);
}

Test(ui, null_and_empty_arguments_are_harmless)
{
    isk_ui ui;
    isk_ui_init(&ui, 0);
    cr_assert_eq(ui.scale, 1);
    isk_ui_begin(&ui, NULL); /* no canvas: widgets work, nothing is drawn */
    int on = 0, sel = 0, scroll = 0;
    double v = 0.5;
    cr_assert_eq(isk_ui_button(&ui, "b", (isk_ui_rect){0, 0, 10, 10}, NULL), 0);
    cr_assert_eq(isk_ui_toggle(&ui, "t", (isk_ui_rect){0, 0, 10, 10}, NULL, NULL), 0);
    cr_assert_eq(isk_ui_slider(&ui, "s", (isk_ui_rect){0, 0, 10, 10}, &v, 1, 1, 0), 0);
    cr_assert_eq(isk_ui_radio(&ui, "r", (isk_ui_rect){0, 0, 10, 10}, NULL, 3, 0, &sel), 0);
    cr_assert_eq(isk_ui_list(&ui, "l", (isk_ui_rect){0, 0, 10, 10}, NULL, 0, &sel, &scroll), 0);
    cr_assert_eq(isk_ui_field(&ui, "f", (isk_ui_rect){-50, -50, 10, 10}, NULL, 0, NULL, 0), ISK_UI_FIELD_IDLE);
    isk_ui_label(&ui, (isk_ui_rect){0, 0, 10, 10}, NULL, ISK_UI_LEFT);
    isk_ui_end(&ui);
    cr_assert_eq(on, 0);
    isk_ui_begin(NULL, NULL);
    isk_ui_end(NULL);
    isk_ui_input_text(NULL, "x");
    cr_assert_eq(isk_ui_button(NULL, "b", (isk_ui_rect){0, 0, 1, 1}, "x"), 0);
    cr_assert(!isk_ui_find(NULL, "b", NULL));
    /* a long queue of motion never overflows; clicks in it survive */
    isk_ui_input_button(&ui, 1, 1, 1);
    for (int i = 0; i < 2 * ISK_UI_QUEUE_MAX; i++)
        isk_ui_input_mouse(&ui, i, i);
    cr_assert_eq(isk_ui_pending(&ui), ISK_UI_QUEUE_MAX);
    cr_assert_eq(ui.queue[0].type, 2); /* the press is still first */
    /* drawing at or beyond the canvas's edges is clipped */
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 20, 20), ISK_OK);
    isk_ui_begin(&ui, &c);
    isk_ui_panel(&ui, (isk_ui_rect){-30, -30, 100, 100});
    isk_ui_button(&ui, "edge", (isk_ui_rect){15, 15, 40, 40}, "a long label");
    isk_ui_field(&ui, "f2", (isk_ui_rect){-5, 5, 40, 12}, "a long value", 0, NULL, 0);
    isk_ui_end(&ui);
    isk_canvas_free(&c);
}
