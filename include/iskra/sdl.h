/* iskra/sdl.h — show canvases in an SDL2 window (library libiskra-sdl).
 *
 * Kept out of libiskra so that the core needs no SDL.  The window uploads a
 * canvas each frame through a streaming SDL_PIXELFORMAT_RGBA32 texture (the
 * canvas layout, no conversion) and reports input as plain isk_event values,
 * so callers need not include SDL headers.  Works under
 * SDL_VIDEODRIVER=dummy, which is how the tests drive it without a display.
 *
 *     isk_window *w;
 *     isk_error err;
 *     if (isk_window_open(&w, "demo", 600, 600, &err) != ISK_OK) { ... }
 *     isk_window_run(w, &canvas, my_frame, &state, 0);   // until closed
 *     isk_window_close(w);
 *
 * The frame callback gets the events of this frame and the real time since
 * the previous frame, draws into the canvas and returns 0 to go on, non-zero
 * to stop.
 */
#ifndef ISKRA_SDL_H
#define ISKRA_SDL_H

#include "iskra/canvas.h"
#include "iskra/status.h"

typedef struct isk_window isk_window;

/* Keys: printable ASCII keys are their lower-case character; others below. */
enum {
    ISK_KEY_UNKNOWN = 0,
    ISK_KEY_ESCAPE = 27,
    ISK_KEY_SPACE = ' ',
    ISK_KEY_RETURN = '\r',
    ISK_KEY_F1 = 0x101, ISK_KEY_F2, ISK_KEY_F3, ISK_KEY_F4, ISK_KEY_F5, ISK_KEY_F6,
    ISK_KEY_F7, ISK_KEY_F8, ISK_KEY_F9, ISK_KEY_F10, ISK_KEY_F11, ISK_KEY_F12,
    ISK_KEY_LEFT, ISK_KEY_RIGHT, ISK_KEY_UP, ISK_KEY_DOWN,
    ISK_KEY_KP_PLUS, ISK_KEY_KP_MINUS
};

typedef enum isk_event_type {
    ISK_EVENT_QUIT = 1,
    ISK_EVENT_KEY_DOWN,
    ISK_EVENT_KEY_UP,
    ISK_EVENT_MOUSE_DOWN,
    ISK_EVENT_MOUSE_UP,
    ISK_EVENT_MOUSE_MOVE,
    ISK_EVENT_WHEEL
} isk_event_type;

typedef struct isk_event {
    isk_event_type type;
    int key;          /* KEY_DOWN/UP: ISK_KEY_* or lower-case ASCII */
    int button;       /* MOUSE_DOWN/UP: 1 left, 2 middle, 3 right */
    int x, y;         /* mouse position in canvas pixels */
    int wheel;        /* WHEEL: +1 away from the user, -1 towards */
} isk_event;

/* Opens a window of the given size (the canvas size shown 1:1). */
isk_status isk_window_open(isk_window **w, const char *title, int width, int height, isk_error *err);

/* Uploads the canvas and shows it.  The canvas must match the window size. */
isk_status isk_window_present(isk_window *w, const isk_canvas *c, isk_error *err);

/* Next pending event: returns 1 and fills *ev, or 0 when none is left. */
int isk_window_poll(isk_window *w, isk_event *ev);

typedef int (*isk_frame_fn)(void *user, isk_canvas *canvas, double dt_seconds,
                            const isk_event *events, int nevents);

/* Runs frames until the callback returns non-zero, the window is closed
 * (ISK_EVENT_QUIT or Escape), or max_frames frames ran (0 = no limit).
 * Presents the canvas after every callback. */
isk_status isk_window_run(isk_window *w, isk_canvas *canvas, isk_frame_fn frame, void *user,
                          long max_frames, isk_error *err);

/* Injects an event as if it came from the user (for tests and scripting). */
isk_status isk_window_push_event(isk_window *w, const isk_event *ev);

void isk_window_close(isk_window *w);

#endif
