/* SPDX-License-Identifier: MIT */
/* The SDL2 presenter, driven headless (SDL_VIDEODRIVER=dummy): opening,
 * presenting, scripted input, the frame loop, errors. */
#include <criterion/criterion.h>
#include <stdlib.h>

#include "iskra/sdl.h"

static void headless(void)
{
    setenv("SDL_VIDEODRIVER", "dummy", 1);
    setenv("SDL_RENDER_DRIVER", "software", 1);
}

TestSuite(window, .init = headless);

Test(window, open_present_close)
{
    isk_window *w = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_window_open(&w, "test", 64, 48, &err), ISK_OK, "%s", err.message);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 64, 48), ISK_OK);
    isk_canvas_fill(&c, ISK_RED);
    cr_assert_eq(isk_window_present(w, &c, &err), ISK_OK, "%s", err.message);
    isk_canvas wrong;
    cr_assert_eq(isk_canvas_init(&wrong, 32, 48), ISK_OK);
    cr_assert_eq(isk_window_present(w, &wrong, &err), ISK_ERR_SIZE);
    isk_window_close(w);
    /* A second window after the first is closed works too. */
    cr_assert_eq(isk_window_open(&w, "again", 10, 10, &err), ISK_OK, "%s", err.message);
    isk_window_close(w);
    isk_canvas_free(&c);
    isk_canvas_free(&wrong);
}

Test(window, bad_sizes_are_rejected)
{
    isk_window *w = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_window_open(&w, "x", 0, 10, &err), ISK_ERR_SIZE);
    cr_assert_eq(isk_window_open(&w, "x", 10, -5, &err), ISK_ERR_SIZE);
    cr_assert_eq(isk_window_open(&w, "x", ISK_CANVAS_MAX_DIM + 1, 10, &err), ISK_ERR_SIZE);
    cr_assert_eq(isk_window_open(NULL, "x", 10, 10, &err), ISK_ERR_NULL);
}

Test(window, pushed_events_come_back)
{
    isk_window *w = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_window_open(&w, "events", 100, 80, &err), ISK_OK, "%s", err.message);
    isk_event in[3] = {
        {.type = ISK_EVENT_KEY_DOWN, .key = ISK_KEY_F12},
        {.type = ISK_EVENT_KEY_DOWN, .key = 'r'},
        {.type = ISK_EVENT_MOUSE_DOWN, .button = 1, .x = 30, .y = 40},
    };
    for (int i = 0; i < 3; i++)
        cr_assert_eq(isk_window_push_event(w, &in[i]), ISK_OK);
    isk_event ev;
    int seen_f12 = 0, seen_r = 0, seen_click = 0;
    while (isk_window_poll(w, &ev)) {
        seen_f12 |= ev.type == ISK_EVENT_KEY_DOWN && ev.key == ISK_KEY_F12;
        seen_r |= ev.type == ISK_EVENT_KEY_DOWN && ev.key == 'r';
        seen_click |= ev.type == ISK_EVENT_MOUSE_DOWN && ev.button == 1 && ev.x == 30 && ev.y == 40;
    }
    cr_assert(seen_f12 && seen_r && seen_click);
    isk_window_close(w);
}

typedef struct counter {
    int frames, keys;
    int stop_at;
} counter;

static int on_frame(void *user, isk_canvas *c, double dt, const isk_event *ev, int n)
{
    counter *k = user;
    (void)dt;
    for (int i = 0; i < n; i++)
        k->keys += ev[i].type == ISK_EVENT_KEY_DOWN && ev[i].key == ' ';
    isk_canvas_fill(c, k->frames % 2 ? ISK_WHITE : ISK_BLACK);
    return ++k->frames == k->stop_at;
}

Test(window, run_delivers_events_and_stops)
{
    isk_window *w = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_window_open(&w, "run", 32, 32, &err), ISK_OK, "%s", err.message);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 32, 32), ISK_OK);
    /* Stops after max_frames. */
    counter k = {0, 0, -1};
    isk_event space = {.type = ISK_EVENT_KEY_DOWN, .key = ' '};
    cr_assert_eq(isk_window_push_event(w, &space), ISK_OK);
    cr_assert_eq(isk_window_run(w, &c, on_frame, &k, 5, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(k.frames, 5);
    cr_assert_eq(k.keys, 1);
    /* Stops when the callback says so. */
    counter k2 = {0, 0, 3};
    cr_assert_eq(isk_window_run(w, &c, on_frame, &k2, 100, &err), ISK_OK);
    cr_assert_eq(k2.frames, 3);
    /* Stops on Escape. */
    counter k3 = {0, 0, -1};
    isk_event esc = {.type = ISK_EVENT_KEY_DOWN, .key = ISK_KEY_ESCAPE};
    cr_assert_eq(isk_window_push_event(w, &esc), ISK_OK);
    cr_assert_eq(isk_window_run(w, &c, on_frame, &k3, 100, &err), ISK_OK);
    cr_assert_lt(k3.frames, 100);
    isk_window_close(w);
    isk_canvas_free(&c);
}
