/* SPDX-License-Identifier: MIT */
/* tests/test_sdl.c — value tests of the SDL2 presenter's input and frame loop,
 * headless under SDL_VIDEODRIVER=dummy.  Complements tests/test_window.c
 * (open/present/close, bad sizes, basic scripted input, run stopping) with
 * the full key table, every mouse/wheel field, window scaling, two windows at
 * once, the per-frame event cap and argument checks.
 *
 * Run from the repository root: build/tests/test_sdl.  SDL.h is included only
 * to inject raw window-system events the public API cannot express (a click
 * in a resized window, the close button). */
#include <criterion/criterion.h>
#include <SDL.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/sdl.h"

static void headless(void)
{
    setenv("SDL_VIDEODRIVER", "dummy", 1);
    setenv("SDL_RENDER_DRIVER", "software", 1);
}

TestSuite(sdl, .init = headless);

static isk_window *open_or_fail(int w, int h)
{
    isk_window *win = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_window_open(&win, "test_sdl", w, h, &err), ISK_OK, "%s", err.message);
    return win;
}

/* Pushes `in` and returns the one event that comes back. */
static isk_event round_trip(isk_window *w, isk_event in)
{
    cr_assert_eq(isk_window_push_event(w, &in), ISK_OK);
    isk_event out, extra;
    cr_assert_eq(isk_window_poll(w, &out), 1, "pushed event type %d did not come back", in.type);
    cr_assert_eq(isk_window_poll(w, &extra), 0, "more than one event came back");
    return out;
}

Test(sdl, every_key_round_trips)
{
    isk_window *w = open_or_fail(16, 16);
    int keys[128], n = 0;
    for (int k = ISK_KEY_F1; k <= ISK_KEY_KP_MINUS; k++)
        keys[n++] = k;
    keys[n++] = ISK_KEY_ESCAPE;
    keys[n++] = ISK_KEY_RETURN;
    for (int k = 32; k < 127; k++)
        if (k < 'A' || k > 'Z')
            keys[n++] = k;
    for (int i = 0; i < n; i++) {
        isk_event down = round_trip(w, (isk_event){.type = ISK_EVENT_KEY_DOWN, .key = keys[i]});
        cr_assert_eq(down.type, ISK_EVENT_KEY_DOWN);
        cr_assert_eq(down.key, keys[i], "key %d came back as %d", keys[i], down.key);
        isk_event up = round_trip(w, (isk_event){.type = ISK_EVENT_KEY_UP, .key = keys[i]});
        cr_assert_eq(up.type, ISK_EVENT_KEY_UP);
        cr_assert_eq(up.key, keys[i]);
    }
    /* Upper case is folded: keys are reported as lower-case ASCII. */
    cr_assert_eq(round_trip(w, (isk_event){.type = ISK_EVENT_KEY_DOWN, .key = 'Q'}).key, 'q');
    cr_assert_eq(round_trip(w, (isk_event){.type = ISK_EVENT_KEY_DOWN, .key = 0x7777}).key, ISK_KEY_UNKNOWN);
    isk_window_close(w);
}

Test(sdl, mouse_wheel_and_quit_fields)
{
    isk_window *w = open_or_fail(100, 80);
    for (int b = 1; b <= 3; b++) {
        isk_event e = round_trip(w, (isk_event){.type = ISK_EVENT_MOUSE_DOWN, .button = b, .x = 10 * b, .y = 79});
        cr_assert_eq(e.type, ISK_EVENT_MOUSE_DOWN);
        cr_assert(e.button == b && e.x == 10 * b && e.y == 79);
        e = round_trip(w, (isk_event){.type = ISK_EVENT_MOUSE_UP, .button = b, .x = 0, .y = 1});
        cr_assert(e.type == ISK_EVENT_MOUSE_UP && e.button == b && e.x == 0 && e.y == 1);
    }
    isk_event m = round_trip(w, (isk_event){.type = ISK_EVENT_MOUSE_MOVE, .x = 99, .y = 5});
    cr_assert(m.type == ISK_EVENT_MOUSE_MOVE && m.x == 99 && m.y == 5);
    cr_assert_eq(round_trip(w, (isk_event){.type = ISK_EVENT_WHEEL, .wheel = 1}).wheel, 1);
    cr_assert_eq(round_trip(w, (isk_event){.type = ISK_EVENT_WHEEL, .wheel = -1}).wheel, -1);
    cr_assert_eq(round_trip(w, (isk_event){.type = ISK_EVENT_QUIT}).type, ISK_EVENT_QUIT);

    /* Values the event model cannot express are refused, not guessed. */
    isk_event bad[] = {
        {.type = ISK_EVENT_MOUSE_DOWN, .button = 0},
        {.type = ISK_EVENT_MOUSE_UP, .button = 4},
        {.type = ISK_EVENT_WHEEL, .wheel = 0},
        {.type = ISK_EVENT_WHEEL, .wheel = 7},
        {.type = (isk_event_type)99},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        cr_assert_eq(isk_window_push_event(w, &bad[i]), ISK_ERR_RANGE, "bad event %zu accepted", i);
    isk_event ev;
    cr_assert_eq(isk_window_poll(w, &ev), 0);
    cr_assert_eq(isk_window_push_event(NULL, &ev), ISK_ERR_NULL);
    cr_assert_eq(isk_window_push_event(w, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_window_poll(NULL, &ev), 0);
    cr_assert_eq(isk_window_poll(w, NULL), 0);
    isk_window_close(w);
    isk_window_close(NULL);
}

/* The SDL window of the only open window (IDs are small integers). */
static SDL_Window *only_sdl_window(void)
{
    for (Uint32 id = 1; id < 10000; id++) {
        SDL_Window *win = SDL_GetWindowFromID(id);
        if (win)
            return win;
    }
    cr_assert_fail("no SDL window found");
    return NULL;
}

static void push_raw_click(SDL_Window *win, int x, int y)
{
    SDL_Event e;
    memset(&e, 0, sizeof e);
    e.type = SDL_MOUSEBUTTONDOWN;
    e.button.windowID = SDL_GetWindowID(win);
    e.button.button = SDL_BUTTON_LEFT;
    e.button.state = SDL_PRESSED;
    e.button.x = x;
    e.button.y = y;
    cr_assert_eq(SDL_PushEvent(&e), 1);
}

Test(sdl, clicks_in_a_resized_window_map_to_canvas_pixels)
{
    isk_window *w = open_or_fail(100, 80);
    SDL_Window *win = only_sdl_window();
    isk_event ev;
    /* 1:1 at first. */
    push_raw_click(win, 37, 21);
    cr_assert_eq(isk_window_poll(w, &ev), 1);
    cr_assert(ev.x == 37 && ev.y == 21, "got (%d,%d)", ev.x, ev.y);

    cr_assert_eq(isk_window_set_size(w, 200, 160), ISK_OK);
    cr_assert_eq(isk_window_set_size(w, 0, 160), ISK_ERR_SIZE);
    int ww, wh;
    SDL_GetWindowSize(win, &ww, &wh);
    cr_assert(ww == 200 && wh == 160, "window is %dx%d", ww, wh);
    while (isk_window_poll(w, &ev)) /* the resize notifications */
        ;
    push_raw_click(win, 75, 43);
    cr_assert_eq(isk_window_poll(w, &ev), 1);
    cr_assert_eq(ev.type, ISK_EVENT_MOUSE_DOWN);
    cr_assert(ev.x == 37 && ev.y == 21, "2x window: got (%d,%d), expected (37,21)", ev.x, ev.y);
    /* Scripted clicks are canvas pixels already and are not rescaled. */
    isk_event click = {.type = ISK_EVENT_MOUSE_DOWN, .button = 1, .x = 37, .y = 21};
    isk_event back = round_trip(w, click);
    cr_assert(back.x == 37 && back.y == 21, "scripted click moved to (%d,%d)", back.x, back.y);

    /* Presenting still works at the new size. */
    isk_canvas c;
    isk_error err = {0};
    cr_assert_eq(isk_canvas_init(&c, 100, 80), ISK_OK);
    cr_assert_eq(isk_window_present(w, &c, &err), ISK_OK, "%s", err.message);
    isk_canvas_free(&c);
    isk_window_close(w);
}

Test(sdl, close_button_is_quit)
{
    isk_window *w = open_or_fail(20, 20);
    SDL_Event e;
    memset(&e, 0, sizeof e);
    e.type = SDL_WINDOWEVENT;
    e.window.event = SDL_WINDOWEVENT_CLOSE;
    e.window.windowID = SDL_GetWindowID(only_sdl_window());
    cr_assert_eq(SDL_PushEvent(&e), 1);
    isk_event ev;
    int quit = 0;
    while (isk_window_poll(w, &ev))
        quit |= ev.type == ISK_EVENT_QUIT;
    cr_assert(quit);
    isk_window_close(w);
}

Test(sdl, two_windows_at_once)
{
    isk_window *a = open_or_fail(30, 20), *b = open_or_fail(40, 10);
    isk_canvas ca, cb;
    isk_error err = {0};
    cr_assert_eq(isk_canvas_init(&ca, 30, 20), ISK_OK);
    cr_assert_eq(isk_canvas_init(&cb, 40, 10), ISK_OK);
    cr_assert_eq(isk_window_present(a, &ca, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_window_present(b, &cb, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_window_present(a, &cb, &err), ISK_ERR_SIZE);
    cr_assert(strstr(err.message, "does not match") != NULL, "%s", err.message);
    /* Closing one must not shut SDL down under the other. */
    isk_window_close(a);
    cr_assert_eq(isk_window_present(b, &cb, &err), ISK_OK, "%s", err.message);
    isk_event ev = round_trip(b, (isk_event){.type = ISK_EVENT_KEY_DOWN, .key = 'x'});
    cr_assert_eq(ev.key, 'x');
    isk_window_close(b);
    cr_assert_eq(SDL_WasInit(SDL_INIT_VIDEO), 0u, "video left initialised after the last close");
    isk_canvas_free(&ca);
    isk_canvas_free(&cb);
}

typedef struct recorder {
    int frames, calls_with_events, max_per_frame;
    int keys_seen[256];
    int last_x;
    double dt_sum, dt_min;
} recorder;

static int record(void *user, isk_canvas *c, double dt, const isk_event *ev, int n)
{
    recorder *r = user;
    (void)c;
    r->frames++;
    r->dt_sum += dt;
    if (r->frames == 1 || dt < r->dt_min)
        r->dt_min = dt;
    if (n > r->max_per_frame)
        r->max_per_frame = n;
    r->calls_with_events += n > 0;
    for (int i = 0; i < n; i++) {
        if (ev[i].type == ISK_EVENT_KEY_DOWN && ev[i].key >= 0 && ev[i].key < 256)
            r->keys_seen[ev[i].key]++;
        if (ev[i].type == ISK_EVENT_MOUSE_MOVE)
            r->last_x = ev[i].x;
    }
    return 0;
}

Test(sdl, run_caps_events_per_frame_and_loses_no_keys)
{
    isk_window *w = open_or_fail(32, 32);
    isk_canvas c;
    isk_error err = {0};
    cr_assert_eq(isk_canvas_init(&c, 32, 32), ISK_OK);
    /* 300 motions, then 100 key presses: more than one frame can take. */
    for (int i = 0; i < 300; i++)
        cr_assert_eq(isk_window_push_event(w, &(isk_event){.type = ISK_EVENT_MOUSE_MOVE, .x = i}), ISK_OK);
    const char *letters = "abcdefghijklmnopqrstuvwxyz0123456789";
    for (int i = 0; i < 100; i++)
        cr_assert_eq(isk_window_push_event(w, &(isk_event){.type = ISK_EVENT_KEY_DOWN, .key = letters[i % 36]}),
                     ISK_OK);
    recorder r;
    memset(&r, 0, sizeof r);
    cr_assert_eq(isk_window_run(w, &c, record, &r, 6, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(r.frames, 6);
    cr_assert_leq(r.max_per_frame, 64);
    int keys = 0;
    for (int k = 0; k < 256; k++)
        keys += r.keys_seen[k];
    cr_assert_eq(keys, 100, "keys delivered: %d of 100", keys);
    cr_assert_eq(r.last_x, 299, "the latest pointer position must survive the cap");
    /* dt is real time; the loop sleeps to ~60 fps, so 6 frames take a while. */
    cr_assert_gt(r.dt_min, 0.0);
    cr_assert_gt(r.dt_sum, 0.05, "6 frames in %.4f s: the idle loop does not sleep", r.dt_sum);
    isk_canvas_free(&c);
    isk_window_close(w);
}

static int must_not_run(void *user, isk_canvas *c, double dt, const isk_event *ev, int n)
{
    (void)user; (void)c; (void)dt; (void)ev; (void)n;
    cr_assert_fail("frame callback ran");
    return 1;
}

Test(sdl, run_refuses_bad_arguments_and_stops_on_quit)
{
    isk_window *w = open_or_fail(32, 32);
    isk_canvas c, wrong;
    isk_error err = {0};
    cr_assert_eq(isk_canvas_init(&c, 32, 32), ISK_OK);
    cr_assert_eq(isk_canvas_init(&wrong, 33, 32), ISK_OK);
    cr_assert_eq(isk_window_run(w, &wrong, must_not_run, NULL, 3, &err), ISK_ERR_SIZE);
    cr_assert_eq(err.status, ISK_ERR_SIZE);
    cr_assert_eq(isk_window_run(w, &c, must_not_run, NULL, -1, &err), ISK_ERR_RANGE);
    cr_assert_eq(isk_window_run(w, &c, NULL, NULL, 3, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_window_run(NULL, &c, must_not_run, NULL, 3, &err), ISK_ERR_NULL);
    /* QUIT ends the loop before the callback sees it. */
    cr_assert_eq(isk_window_push_event(w, &(isk_event){.type = ISK_EVENT_QUIT}), ISK_OK);
    cr_assert_eq(isk_window_run(w, &c, must_not_run, NULL, 0, &err), ISK_OK, "%s", err.message);
    isk_canvas_free(&c);
    isk_canvas_free(&wrong);
    isk_window_close(w);
}

Test(sdl, open_reports_errors_without_leaving_state)
{
    isk_window *w = (isk_window *)&w; /* must be reset to NULL on failure */
    isk_error err = {0};
    cr_assert_eq(isk_window_open(&w, "x", 10, ISK_CANVAS_MAX_DIM + 1, &err), ISK_ERR_SIZE);
    cr_assert_null(w);
    cr_assert_eq(err.status, ISK_ERR_SIZE);
    cr_assert_eq(isk_window_open(&w, "x", -2147483647 - 1, 10, NULL), ISK_ERR_SIZE);
    cr_assert_eq(SDL_WasInit(SDL_INIT_VIDEO), 0u);
    /* A NULL title is allowed. */
    cr_assert_eq(isk_window_open(&w, NULL, 8, 8, &err), ISK_OK, "%s", err.message);
    isk_window_close(w);
}
