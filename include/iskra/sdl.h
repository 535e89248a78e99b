/* SPDX-License-Identifier: MIT */
/* iskra/sdl.h — show canvases in an SDL2 window (library libiskra-sdl).
 *
 * Kept out of libiskra so that the core needs no SDL.  The window uploads a
 * canvas each frame through a streaming SDL_PIXELFORMAT_RGBA32 texture (the
 * canvas layout, no conversion) and reports input as plain isk_event values,
 * so callers need not include SDL headers.  Works under
 * SDL_VIDEODRIVER=dummy, which is how the tests drive it without a display.
 *
 * Example: a disc growing for 30 frames:
 *
 *     static int my_frame(void *user, isk_canvas *c, double dt, const isk_event *ev, int nev)
 *     {
 *         int *frames = user;                      // the program's own state
 *         (void)dt; (void)ev; (void)nev;           // real seconds since the last frame; input
 *         isk_canvas_fill(c, ISK_BLACK);
 *         isk_fill_circle_aa(c, 300, 300, 10.0 * *frames, ISK_YELLOW, ISK_BLEND_OVER);
 *         return ++*frames == 30;                  // non-zero: stop
 *     }
 *     // in main():
 *     isk_window *w;
 *     isk_error err;
 *     if (isk_window_open(&w, "demo", 600, 600, &err) != ISK_OK) {
 *         fprintf(stderr, "%s\n", err.message);
 *         return 1;
 *     }
 *     isk_canvas canvas;
 *     int frames = 0;
 *     isk_status s = isk_canvas_init(&canvas, 600, 600);
 *     if (s == ISK_OK) s = isk_window_run(w, &canvas, my_frame, &frames, 0, &err);  // 0: no limit
 *     if (s != ISK_OK) fprintf(stderr, "%s\n", s == ISK_ERR_NOMEM ? "out of memory" : err.message);
 *     isk_canvas_free(&canvas);
 *     isk_window_close(w);
 *     return s != ISK_OK;
 *
 * The frame callback gets the events of this frame and the real time since
 * the previous frame, draws into the canvas and returns 0 to go on, non-zero
 * to stop; closing the window or Escape stops too.
 *
 * Behaviour worth knowing:
 *   - Keys: printable keys give their lower-case ASCII whatever the Shift
 *     state (so '=' and '+' / '-' keys give '=', '+', '-' as the layout
 *     reports them); Escape, Space, Return (also keypad Enter), Backspace,
 *     Tab, Delete, Home, End, F1..F12, the arrows and keypad +/- have
 *     ISK_KEY_* codes; anything else is ISK_KEY_UNKNOWN.  Auto-repeat
 *     arrives as further KEY_DOWN events.
 *   - Text: what a key types (Shift and the layout applied: "A", "_", "+")
 *     arrives as a separate ISK_EVENT_TEXT after its KEY_DOWN; text fields
 *     read these, shortcuts read the keys.
 *   - Modifiers: a key event's `mods` says which of Shift, Ctrl and Alt
 *     were held (ISK_MOD_*), so Ctrl+A can be told from A.
 *   - Mouse: x, y are canvas pixels.  The window is resizable; the canvas is
 *     scaled by the largest whole number that fits (never a fraction, so
 *     pixels stay sharp: 1 when the window is smaller than the canvas) and
 *     centred with black bars, and positions are mapped back to canvas
 *     pixels, so they can lie outside 0..width-1 / 0..height-1 when the
 *     pointer is over a bar.  A press's `clicks` is 2 for the second click
 *     of a double click (the system's timing).  Buttons other than
 *     left/middle/right are not reported.
 *   - Wheel: +1 / -1 per notch, in the physical direction even with
 *     "natural scrolling"; horizontal scrolling is not reported.
 *   - All windows share SDL's one event queue: with two windows open, poll
 *     either of them (closing a window's close button gives ISK_EVENT_QUIT).
 *   - SDL is initialised on open and shut down when the last window closes
 *     (SDL's own subsystem reference count; no global state of ours).
 *   - No display: when SDL could only start a driver that shows nothing
 *     (its "offscreen" or "dummy" video driver) without being asked for it
 *     through SDL_VIDEODRIVER, as happens with a stale DISPLAY over ssh or
 *     in a container, isk_window_open fails with ISK_ERR_DISPLAY and says
 *     so, instead of running invisibly.  SDL_VIDEODRIVER=dummy (how the
 *     tests run) or =offscreen asks for it on purpose and works.
 *   - Nothing prints; failures fill the isk_error with SDL's message.
 */
#ifndef ISKRA_SDL_H
#define ISKRA_SDL_H

#include "iskra/canvas.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct isk_window isk_window;

/* Keys: printable ASCII keys are their lower-case character; others below. */
enum {
    ISK_KEY_UNKNOWN = 0,
    ISK_KEY_BACKSPACE = 8,
    ISK_KEY_TAB = 9,
    ISK_KEY_DELETE = 127,
    ISK_KEY_ESCAPE = 27,
    ISK_KEY_SPACE = ' ',
    ISK_KEY_RETURN = '\r',
    ISK_KEY_F1 = 0x101, ISK_KEY_F2, ISK_KEY_F3, ISK_KEY_F4, ISK_KEY_F5, ISK_KEY_F6,
    ISK_KEY_F7, ISK_KEY_F8, ISK_KEY_F9, ISK_KEY_F10, ISK_KEY_F11, ISK_KEY_F12,
    ISK_KEY_LEFT, ISK_KEY_RIGHT, ISK_KEY_UP, ISK_KEY_DOWN,
    ISK_KEY_KP_PLUS, ISK_KEY_KP_MINUS,
    ISK_KEY_HOME, ISK_KEY_END
};

typedef enum isk_event_type {
    ISK_EVENT_QUIT = 1,
    ISK_EVENT_KEY_DOWN,
    ISK_EVENT_KEY_UP,
    ISK_EVENT_MOUSE_DOWN,
    ISK_EVENT_MOUSE_UP,
    ISK_EVENT_MOUSE_MOVE,
    ISK_EVENT_WHEEL,
    ISK_EVENT_TEXT    /* text typed (after the keyboard layout and Shift): `text` */
} isk_event_type;

/* Modifier keys held with a key (isk_event.mods, a bit set). */
enum { ISK_MOD_SHIFT = 1, ISK_MOD_CTRL = 2, ISK_MOD_ALT = 4 };

typedef struct isk_event {
    isk_event_type type;
    int key;          /* KEY_DOWN/UP: ISK_KEY_* or lower-case ASCII */
    int button;       /* MOUSE_DOWN/UP: 1 left, 2 middle, 3 right */
    int x, y;         /* mouse position in canvas pixels */
    int wheel;        /* WHEEL: +1 away from the user, -1 towards */
    char text[32];    /* TEXT: the characters, UTF-8, NUL-terminated */
    int mods;         /* KEY_DOWN/UP: ISK_MOD_* held */
    int clicks;       /* MOUSE_DOWN/UP: 1, or 2 for a double click's second (0 in a pushed event counts as 1) */
} isk_event;

/* Opens a window of the given size (the canvas size shown 1:1).  Sizes
 * outside 1..ISK_CANVAS_MAX_DIM give ISK_ERR_SIZE, a window-system failure
 * ISK_ERR_DISPLAY (with SDL's message in err). */
isk_status isk_window_open(isk_window **w, const char *title, int width, int height, isk_error *err);

/* Resizes the window on screen (e.g. a 2x zoom); the canvas keeps the size
 * given to isk_window_open and is scaled to fit. */
isk_status isk_window_set_size(isk_window *w, int width, int height);

/* Changes the canvas size the window shows (and resizes the window to it):
 * from then on isk_window_present and isk_window_run take canvases of the
 * new size.  ISK_ERR_SIZE for sizes outside 1..ISK_CANVAS_MAX_DIM,
 * ISK_ERR_DISPLAY if SDL fails (the window then keeps its old size). */
isk_status isk_window_resize_canvas(isk_window *w, int width, int height, isk_error *err);

/* How many screen pixels a canvas pixel is across now: a whole number
 * (1 when the window is smaller than the canvas); 0 for NULL. */
double isk_window_scale(const isk_window *w);

/* The usable size of the display the window is on (without task bars), for
 * choosing how large to lay out; ISK_ERR_DISPLAY if SDL cannot tell. */
isk_status isk_window_display_size(const isk_window *w, int *width, int *height);

/* Whether isk_window_run sleeps out the rest of ~1/60 s after a quick
 * frame (1, the default) or runs frames as fast as they come (0: scripted
 * sessions with their own clock). */
void isk_window_set_pacing(isk_window *w, int on);

/* Whether Escape ends isk_window_run (1, the default) or reaches the frame
 * callback like any key (0: programs whose text fields use Escape to cancel
 * an edit, and quit on Escape themselves). */
void isk_window_set_escape_quits(isk_window *w, int quits);

/* Uploads the canvas and shows it.  The canvas must match the window's
 * canvas size (ISK_ERR_SIZE otherwise); any stride is fine. */
isk_status isk_window_present(isk_window *w, const isk_canvas *c, isk_error *err);

/* Next pending event: returns 1 and fills *ev, or 0 when none is left. */
int isk_window_poll(isk_window *w, isk_event *ev);

typedef int (*isk_frame_fn)(void *user, isk_canvas *canvas, double dt_seconds,
                            const isk_event *events, int nevents);

/* Runs frames until the callback returns non-zero, the window is closed
 * (ISK_EVENT_QUIT or Escape: the loop ends before a callback sees them;
 * see isk_window_set_escape_quits), or
 * max_frames frames ran (0 = no limit, negative = ISK_ERR_RANGE).
 * Each frame: gathers pending events (at most 64; when more are waiting the
 * oldest mouse motions are dropped first, and keys and clicks that still do
 * not fit wait for the next frame), calls the callback with dt = real seconds
 * since the previous frame's start, presents the canvas, then sleeps so an
 * idle loop runs at about 60 frames per second at most.  A canvas of the
 * wrong size gives ISK_ERR_SIZE before any callback. */
isk_status isk_window_run(isk_window *w, isk_canvas *canvas, isk_frame_fn frame, void *user,
                          long max_frames, isk_error *err);

/* Injects an event as if it came from the user (for tests and scripting):
 * pushes the equivalent SDL event, so it travels through the same queue and
 * translation as real input.  Mouse x, y are canvas pixels and arrive
 * unchanged however the window is scaled.  Buttons outside 1..3, wheel values
 * other than +1/-1, text that is empty or does not fit, and unknown types give
 * ISK_ERR_RANGE. */
isk_status isk_window_push_event(isk_window *w, const isk_event *ev);

void isk_window_close(isk_window *w);

#ifdef __cplusplus
}
#endif

#endif
