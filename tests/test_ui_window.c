/* SPDX-License-Identifier: MIT */
/* What the widget layer and the simulator need from the SDL window
 * (iskra/sdl.h): text and editing-key events, Escape left to the program,
 * a canvas that changes size, events into the widget layer
 * (iskra/ui_sdl.h), and the refusal to run invisibly when SDL could only
 * start a driver that shows nothing. */
#include <criterion/criterion.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/ui_sdl.h"

static void headless(void)
{
    setenv("SDL_VIDEODRIVER", "dummy", 1);
    setenv("SDL_RENDER_DRIVER", "software", 1);
}

TestSuite(ui_window, .init = headless);

Test(ui_window, text_and_editing_keys_come_back)
{
    isk_window *w = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_window_open(&w, "text", 40, 30, &err), ISK_OK, "%s", err.message);
    isk_event text = {.type = ISK_EVENT_TEXT};
    strcpy(text.text, "Ab_+");
    cr_assert_eq(isk_window_push_event(w, &text), ISK_OK);
    const int keys[] = {ISK_KEY_BACKSPACE, ISK_KEY_TAB, ISK_KEY_DELETE, ISK_KEY_HOME, ISK_KEY_END};
    for (int i = 0; i < 5; i++) {
        isk_event k = {.type = ISK_EVENT_KEY_DOWN, .key = keys[i]};
        cr_assert_eq(isk_window_push_event(w, &k), ISK_OK);
    }
    isk_event empty = {.type = ISK_EVENT_TEXT};
    cr_assert_eq(isk_window_push_event(w, &empty), ISK_ERR_RANGE);
    isk_event ev;
    int seen_text = 0, seen = 0;
    while (isk_window_poll(w, &ev)) {
        if (ev.type == ISK_EVENT_TEXT)
            seen_text = !strcmp(ev.text, "Ab_+");
        if (ev.type == ISK_EVENT_KEY_DOWN)
            for (int i = 0; i < 5; i++)
                seen += ev.key == keys[i];
    }
    cr_assert(seen_text);
    cr_assert_eq(seen, 5);
    isk_window_close(w);
}

typedef struct escapes {
    int frames, escapes;
} escapes;

static int count_escapes(void *user, isk_canvas *c, double dt, const isk_event *ev, int n)
{
    (void)c;
    (void)dt;
    escapes *e = user;
    for (int i = 0; i < n; i++)
        e->escapes += ev[i].type == ISK_EVENT_KEY_DOWN && ev[i].key == ISK_KEY_ESCAPE;
    return ++e->frames == 3;
}

Test(ui_window, escape_can_be_left_to_the_program)
{
    isk_window *w = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_window_open(&w, "esc", 20, 20, &err), ISK_OK, "%s", err.message);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 20, 20), ISK_OK);
    isk_window_set_escape_quits(w, 0);
    isk_event esc = {.type = ISK_EVENT_KEY_DOWN, .key = ISK_KEY_ESCAPE};
    cr_assert_eq(isk_window_push_event(w, &esc), ISK_OK);
    escapes e = {0, 0};
    cr_assert_eq(isk_window_run(w, &c, count_escapes, &e, 10, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(e.frames, 3);
    cr_assert_eq(e.escapes, 1);
    isk_window_set_escape_quits(w, 1);
    cr_assert_eq(isk_window_push_event(w, &esc), ISK_OK);
    escapes e2 = {0, 0};
    cr_assert_eq(isk_window_run(w, &c, count_escapes, &e2, 10, &err), ISK_OK);
    cr_assert_eq(e2.frames, 0, "the loop ends before the callback sees it");
    isk_canvas_free(&c);
    isk_window_close(w);
}

Test(ui_window, the_canvas_size_can_change)
{
    isk_window *w = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_window_open(&w, "resize", 30, 20, &err), ISK_OK, "%s", err.message);
    isk_canvas small, big;
    cr_assert_eq(isk_canvas_init(&small, 30, 20), ISK_OK);
    cr_assert_eq(isk_canvas_init(&big, 50, 40), ISK_OK);
    cr_assert_eq(isk_window_present(w, &small, &err), ISK_OK);
    cr_assert_eq(isk_window_resize_canvas(w, 50, 40, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_window_present(w, &small, &err), ISK_ERR_SIZE);
    cr_assert_eq(isk_window_present(w, &big, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_window_resize_canvas(w, 0, 40, &err), ISK_ERR_SIZE);
    cr_assert_eq(isk_window_resize_canvas(NULL, 10, 10, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_window_present(w, &big, &err), ISK_OK, "a refused size changes nothing");
    isk_canvas_free(&small);
    isk_canvas_free(&big);
    isk_window_close(w);
}

Test(ui_window, window_events_drive_the_widgets)
{
    isk_ui ui;
    isk_ui_init(&ui, 1);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 100, 40), ISK_OK);
    const isk_ui_rect r = {10, 10, 80, 20};
    isk_ui_begin(&ui, &c);
    isk_ui_field(&ui, "f", r, "1", 0, NULL, 0);
    isk_ui_end(&ui);
    const isk_event evs[] = {
        {.type = ISK_EVENT_MOUSE_MOVE, .x = 20, .y = 15},
        {.type = ISK_EVENT_MOUSE_DOWN, .button = 1, .x = 20, .y = 15},
        {.type = ISK_EVENT_MOUSE_UP, .button = 1, .x = 20, .y = 15},
        {.type = ISK_EVENT_MOUSE_DOWN, .button = 3, .x = 1, .y = 1}, /* right button: not for widgets */
        {.type = ISK_EVENT_KEY_DOWN, .key = ISK_KEY_END},
        {.type = ISK_EVENT_TEXT, .text = "2x"},
        {.type = ISK_EVENT_KEY_DOWN, .key = ISK_KEY_BACKSPACE},
        {.type = ISK_EVENT_KEY_DOWN, .key = ISK_KEY_KP_PLUS},
        {.type = ISK_EVENT_TEXT, .text = "+"},
        {.type = ISK_EVENT_KEY_DOWN, .key = ISK_KEY_RETURN},
    };
    for (size_t i = 0; i < sizeof evs / sizeof evs[0]; i++)
        isk_ui_feed_event(&ui, &evs[i]);
    char out[32] = "";
    int applied = 0;
    for (int f = 0; f < 6; f++) {
        isk_ui_begin(&ui, &c);
        applied |= isk_ui_field(&ui, "f", r, "1", 0, out, sizeof out) == ISK_UI_FIELD_APPLY;
        isk_ui_end(&ui);
    }
    cr_assert(applied);
    cr_assert_str_eq(out, "12+");
    cr_assert_eq(isk_ui_key_from_window(ISK_KEY_F12), ISK_UI_KEY_F12);
    cr_assert_eq(isk_ui_key_from_window('r'), 'r');
    cr_assert_eq(isk_ui_key_from_window(ISK_KEY_UNKNOWN), 0);
    isk_canvas_free(&c);
}

/* No display: SDL falls back to its "offscreen" driver when DISPLAY points
 * nowhere; opening a window must then fail and say why. */
Test(ui_window, a_display_that_does_not_answer_is_refused)
{
    unsetenv("SDL_VIDEODRIVER");
    unsetenv("WAYLAND_DISPLAY");
    setenv("DISPLAY", ":4093", 1); /* no X server listens there */
    isk_window *w = NULL;
    isk_error err = {0};
    isk_status s = isk_window_open(&w, "nowhere", 20, 20, &err);
    if (s == ISK_OK) {
        isk_window_close(w);
        cr_skip_test("a real video driver opened a window without a display here");
    }
    cr_assert_eq(s, ISK_ERR_DISPLAY);
    cr_assert_eq(w, NULL);
    cr_assert(strstr(err.message, "no display") || strstr(err.message, "SDL"), "%s", err.message);
    if (strstr(err.message, "no display")) {
        cr_assert(strstr(err.message, "DISPLAY=:4093 did not answer"), "%s", err.message);
        cr_assert(strstr(err.message, "SDL_VIDEODRIVER="), "%s", err.message);
    }
    /* asking for the driver on purpose works */
    setenv("SDL_VIDEODRIVER", "offscreen", 1);
    cr_assert_eq(isk_window_open(&w, "on purpose", 20, 20, &err), ISK_OK, "%s", err.message);
    isk_window_close(w);
}

/* A window made larger than its canvas scales the canvas by the largest
 * whole number that fits, never by a fraction (which blurs pixels); a
 * window smaller than the canvas shows it 1:1. */
Test(ui_window, the_canvas_is_scaled_by_whole_numbers_only)
{
    isk_window *w = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_window_open(&w, "scale", 100, 80, &err), ISK_OK, "%s", err.message);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 100, 80), ISK_OK);
    static const struct {
        int w, h;
        double scale;
    } sizes[] = {{100, 80, 1}, {250, 250, 2}, {299, 239, 2}, {300, 240, 3}, {199, 500, 1}, {60, 40, 1}};
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        cr_assert_eq(isk_window_set_size(w, sizes[i].w, sizes[i].h), ISK_OK);
        isk_event ev;
        while (isk_window_poll(w, &ev)) /* the resize reaches the renderer through SDL's events */
            ;
        cr_assert_eq(isk_window_present(w, &c, &err), ISK_OK, "%s", err.message);
        cr_expect_eq(isk_window_scale(w), sizes[i].scale, "a %dx%d window: scale %g", sizes[i].w, sizes[i].h,
                     isk_window_scale(w));
    }
    cr_assert_eq(isk_window_scale(NULL), 0);
    isk_canvas_free(&c);
    isk_window_close(w);
}

/* Modifiers and double clicks come through the window: Ctrl+A reaches
 * the widget layer as ISK_UI_MOD_CTRL | 'a', a double click's second
 * press with clicks = 2, and a field takes both as "select all". */
Test(ui_window, ctrl_a_and_double_clicks_reach_the_widgets)
{
    isk_window *w = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_window_open(&w, "keys", 100, 40, &err), ISK_OK, "%s", err.message);
    const isk_event evs[] = {
        {.type = ISK_EVENT_KEY_DOWN, .key = 'a', .mods = ISK_MOD_CTRL},
        {.type = ISK_EVENT_MOUSE_DOWN, .button = 1, .x = 20, .y = 15, .clicks = 2},
    };
    for (size_t i = 0; i < 2; i++)
        cr_assert_eq(isk_window_push_event(w, &evs[i]), ISK_OK);
    isk_event ev;
    int ctrl_a = 0, twice = 0;
    while (isk_window_poll(w, &ev)) {
        ctrl_a |= ev.type == ISK_EVENT_KEY_DOWN && ev.key == 'a' && (ev.mods & ISK_MOD_CTRL);
        twice |= ev.type == ISK_EVENT_MOUSE_DOWN && ev.clicks == 2;
    }
    cr_expect(ctrl_a, "Ctrl+A came back as 'a' with ISK_MOD_CTRL");
    cr_expect(twice, "the double click came back with clicks = 2");
    isk_window_close(w);

    /* the widgets: a field's text, its selection ended by End, then Ctrl+A and typing */
    isk_ui ui;
    isk_ui_init(&ui, 1);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 100, 40), ISK_OK);
    const isk_ui_rect r = {10, 10, 80, 20};
    char out[32] = "";
    const isk_event session[] = {
        {.type = ISK_EVENT_MOUSE_DOWN, .button = 1, .x = 20, .y = 15, .clicks = 1},
        {.type = ISK_EVENT_MOUSE_UP, .button = 1, .x = 20, .y = 15, .clicks = 1},
        {.type = ISK_EVENT_KEY_DOWN, .key = ISK_KEY_END},
        {.type = ISK_EVENT_KEY_DOWN, .key = 'a', .mods = ISK_MOD_CTRL},
        {.type = ISK_EVENT_TEXT, .text = "7"},
        {.type = ISK_EVENT_KEY_DOWN, .key = ISK_KEY_RETURN},
    };
    int applied = 0;
    for (size_t i = 0; i < sizeof session / sizeof session[0]; i++)
        isk_ui_feed_event(&ui, &session[i]);
    for (int f = 0; f < 6; f++) {
        isk_ui_begin(&ui, &c);
        applied |= isk_ui_field(&ui, "f", r, "9.81", 0, out, sizeof out) == ISK_UI_FIELD_APPLY;
        isk_ui_end(&ui);
    }
    cr_assert(applied);
    cr_expect_str_eq(out, "7", "Ctrl+A selected the whole value, so 7 replaced it");
    isk_canvas_free(&c);
}
