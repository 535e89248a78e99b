/* SPDX-License-Identifier: MIT */
/* src/io/sdl_window.c — the SDL2 window of libiskra-sdl (see iskra/sdl.h).
 *
 * A window shows a canvas through a streaming SDL_PIXELFORMAT_RGBA32 texture
 * (the canvas's byte order R,G,B,A, so no conversion) and reports input as
 * isk_event values.  Works under SDL_VIDEODRIVER=dummy: nothing is shown and
 * SDL's software renderer is used, which is how tests/test_window.c and
 * tests/test_sdl.c drive it.
 *
 *     isk_window *w;
 *     if (isk_window_open(&w, "demo", 600, 600, &err) != ISK_OK) ...
 *     isk_window_run(w, &canvas, frame_fn, &state, 0, &err);
 *     isk_window_close(w);
 *
 * Global state: none of ours.  Every open calls SDL_InitSubSystem(VIDEO) and
 * every close SDL_QuitSubSystem(VIDEO); SDL keeps a per-subsystem reference
 * count, so two windows (at once or in turn) work and video is shut down when
 * the last one closes.  A caller that initialised SDL itself keeps its own
 * reference, so we never shut SDL down under it.
 *
 * Scaling: the window is resizable; SDL_RenderSetLogicalSize keeps the canvas
 * at its aspect ratio (letterboxed) and makes SDL translate mouse coordinates
 * of our window into canvas pixels before we see them, and
 * SDL_RenderSetIntegerScale keeps the scale a whole number, so a pixel of
 * the canvas is always a square of whole screen pixels (never blurred).
 */
#include <SDL.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/sdl.h"

/* Events handed to one frame callback.  Bounded so a flood of mouse motion
 * cannot grow a frame without limit; see collect_events for what gives way. */
#define FRAME_EVENTS 64
/* Frame pacing when nothing else (vsync) limits the loop: at most ~60 fps. */
#define MIN_FRAME_MS 16

struct isk_window {
    SDL_Window *win;
    SDL_Renderer *ren;
    SDL_Texture *tex;
    Uint32 id;           /* SDL window ID, to recognise our window's events */
    int width, height;   /* canvas size */
    int video_ref;       /* 1 while we hold a reference on SDL's video subsystem */
    int has_carry;       /* an event polled but not yet delivered (full frame) */
    isk_event carry;
    int escape_keeps;    /* 1: Escape reaches the frame callback instead of ending the loop */
    int unpaced;         /* 1: no sleep after a quick frame */
};

static isk_status display_error(isk_error *err, const char *what)
{
    return isk_error_set(err, ISK_ERR_DISPLAY, "SDL: %s: %s", what, SDL_GetError());
}

/* ---- key codes ------------------------------------------------------------ */

static int key_from_sdl(SDL_Keycode k)
{
    if (k >= SDLK_F1 && k <= SDLK_F12)
        return ISK_KEY_F1 + (int)(k - SDLK_F1);
    switch (k) {
    case SDLK_LEFT: return ISK_KEY_LEFT;
    case SDLK_RIGHT: return ISK_KEY_RIGHT;
    case SDLK_UP: return ISK_KEY_UP;
    case SDLK_DOWN: return ISK_KEY_DOWN;
    case SDLK_KP_PLUS: return ISK_KEY_KP_PLUS;
    case SDLK_KP_MINUS: return ISK_KEY_KP_MINUS;
    case SDLK_KP_ENTER: return ISK_KEY_RETURN;
    case SDLK_HOME: return ISK_KEY_HOME;
    case SDLK_END: return ISK_KEY_END;
    default: break;
    }
    /* SDL's keycodes for printable keys, Escape, Space, Return, Backspace,
     * Tab and Delete are their ASCII codes already (and lower case whatever
     * the Shift state). */
    if (k == SDLK_ESCAPE || k == SDLK_RETURN || k == SDLK_BACKSPACE || k == SDLK_TAB || k == SDLK_DELETE ||
        (k >= 32 && k < 127))
        return (k >= 'A' && k <= 'Z') ? (int)(k - 'A' + 'a') : (int)k;
    return ISK_KEY_UNKNOWN;
}

static SDL_Keycode key_to_sdl(int key)
{
    if (key >= ISK_KEY_F1 && key <= ISK_KEY_F12)
        return SDLK_F1 + (key - ISK_KEY_F1);
    switch (key) {
    case ISK_KEY_LEFT: return SDLK_LEFT;
    case ISK_KEY_RIGHT: return SDLK_RIGHT;
    case ISK_KEY_UP: return SDLK_UP;
    case ISK_KEY_DOWN: return SDLK_DOWN;
    case ISK_KEY_KP_PLUS: return SDLK_KP_PLUS;
    case ISK_KEY_KP_MINUS: return SDLK_KP_MINUS;
    case ISK_KEY_ESCAPE: return SDLK_ESCAPE;
    case ISK_KEY_RETURN: return SDLK_RETURN;
    case ISK_KEY_BACKSPACE: return SDLK_BACKSPACE;
    case ISK_KEY_TAB: return SDLK_TAB;
    case ISK_KEY_DELETE: return SDLK_DELETE;
    case ISK_KEY_HOME: return SDLK_HOME;
    case ISK_KEY_END: return SDLK_END;
    default: break;
    }
    if (key >= 32 && key < 127)
        return (key >= 'A' && key <= 'Z') ? key - 'A' + 'a' : key;
    return SDLK_UNKNOWN;
}

/* ---- event translation --------------------------------------------------- */

/* 1 and fills *ev when `e` is something we report, else 0. */
static int convert(const isk_window *w, const SDL_Event *e, isk_event *ev)
{
    memset(ev, 0, sizeof *ev);
    switch (e->type) {
    case SDL_QUIT:
        ev->type = ISK_EVENT_QUIT;
        return 1;
    case SDL_WINDOWEVENT:
        /* With several windows SDL sends SDL_QUIT only when the last one
         * closes; closing ours must still end its loop. */
        if (e->window.event != SDL_WINDOWEVENT_CLOSE || e->window.windowID != w->id)
            return 0;
        ev->type = ISK_EVENT_QUIT;
        return 1;
    case SDL_KEYDOWN:
    case SDL_KEYUP:
        ev->type = e->type == SDL_KEYDOWN ? ISK_EVENT_KEY_DOWN : ISK_EVENT_KEY_UP;
        ev->key = key_from_sdl(e->key.keysym.sym);
        ev->mods = (e->key.keysym.mod & KMOD_SHIFT ? ISK_MOD_SHIFT : 0) |
                   (e->key.keysym.mod & KMOD_CTRL ? ISK_MOD_CTRL : 0) | (e->key.keysym.mod & KMOD_ALT ? ISK_MOD_ALT : 0);
        return 1;
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
        switch (e->button.button) {
        case SDL_BUTTON_LEFT: ev->button = 1; break;
        case SDL_BUTTON_MIDDLE: ev->button = 2; break;
        case SDL_BUTTON_RIGHT: ev->button = 3; break;
        default: return 0; /* side buttons: not part of our model */
        }
        ev->type = e->type == SDL_MOUSEBUTTONDOWN ? ISK_EVENT_MOUSE_DOWN : ISK_EVENT_MOUSE_UP;
        ev->x = e->button.x; /* already canvas pixels: see the logical size */
        ev->y = e->button.y;
        ev->clicks = e->button.clicks > 1 ? 2 : 1;
        return 1;
    case SDL_MOUSEMOTION:
        ev->type = ISK_EVENT_MOUSE_MOVE;
        ev->x = e->motion.x;
        ev->y = e->motion.y;
        return 1;
    case SDL_TEXTINPUT:
        ev->type = ISK_EVENT_TEXT;
        memcpy(ev->text, e->text.text, sizeof ev->text < sizeof e->text.text ? sizeof ev->text : sizeof e->text.text);
        ev->text[sizeof ev->text - 1] = 0;
        return ev->text[0] != 0;
    case SDL_MOUSEWHEEL: {
        Sint32 dy = e->wheel.y;
        if (e->wheel.direction == SDL_MOUSEWHEEL_FLIPPED)
            dy = -dy; /* "natural scrolling": report the physical direction */
        if (dy == 0)
            return 0; /* horizontal-only scroll */
        ev->type = ISK_EVENT_WHEEL;
        ev->wheel = dy > 0 ? 1 : -1;
        return 1;
    }
    default:
        return 0;
    }
}

/* ---- open / close --------------------------------------------------------- */

/* 1 when `list` (SDL_VIDEODRIVER: a name or a comma-separated list) names
 * the driver. */
static int names_driver(const char *list, const char *driver)
{
    size_t n = strlen(driver);
    for (const char *p = list; p && *p;) {
        const char *end = strchr(p, ',');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        if (len == n && SDL_strncasecmp(p, driver, n) == 0)
            return 1;
        p = end ? end + 1 : NULL;
    }
    return 0;
}

/* SDL falls back to its "offscreen" driver when no window system answers
 * (a stale DISPLAY over ssh, a container): a window would then run
 * invisibly.  Refused unless SDL_VIDEODRIVER asked for that driver. */
static int headless_driver(isk_error *err)
{
    static const char *const shows_nothing[] = {"offscreen", "dummy"};
    const char *driver = SDL_GetCurrentVideoDriver();
    const char *asked = SDL_GetHint(SDL_HINT_VIDEODRIVER);
    for (size_t i = 0; driver && i < sizeof shows_nothing / sizeof shows_nothing[0]; i++) {
        if (SDL_strcasecmp(driver, shows_nothing[i]) != 0 || names_driver(asked, driver))
            continue;
        const char *x11 = SDL_getenv("DISPLAY"), *wl = SDL_getenv("WAYLAND_DISPLAY");
        char where[160];
        if (x11 && *x11)
            SDL_snprintf(where, sizeof where, "DISPLAY=%s did not answer", x11);
        else if (wl && *wl)
            SDL_snprintf(where, sizeof where, "WAYLAND_DISPLAY=%s did not answer", wl);
        else
            SDL_snprintf(where, sizeof where, "DISPLAY and WAYLAND_DISPLAY are not set");
        isk_error_set(err, ISK_ERR_DISPLAY,
                      "no display: %s, and SDL could only start its '%s' video driver, which shows nothing "
                      "(set SDL_VIDEODRIVER=%s to run without a display on purpose)",
                      where, driver, driver);
        return 1;
    }
    return 0;
}

void isk_window_close(isk_window *w)
{
    if (!w)
        return;
    if (w->tex)
        SDL_DestroyTexture(w->tex);
    if (w->ren)
        SDL_DestroyRenderer(w->ren);
    if (w->win)
        SDL_DestroyWindow(w->win);
    if (w->video_ref)
        SDL_QuitSubSystem(SDL_INIT_VIDEO);
    free(w);
}

isk_status isk_window_open(isk_window **out, const char *title, int width, int height, isk_error *err)
{
    if (!out)
        return isk_error_set(err, ISK_ERR_NULL, "window: NULL argument");
    *out = NULL;
    if (width < 1 || height < 1 || width > ISK_CANVAS_MAX_DIM || height > ISK_CANVAS_MAX_DIM)
        return isk_error_set(err, ISK_ERR_SIZE, "window: bad size %dx%d (1..%d each)", width, height,
                             ISK_CANVAS_MAX_DIM);
    isk_window *w = calloc(1, sizeof *w);
    if (!w)
        return isk_error_set(err, ISK_ERR_NOMEM, "window: out of memory");
    w->width = width;
    w->height = height;
    if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
        display_error(err, "cannot initialise video");
        free(w);
        return ISK_ERR_DISPLAY;
    }
    w->video_ref = 1;
    if (headless_driver(err)) {
        isk_window_close(w);
        return ISK_ERR_DISPLAY;
    }

    w->win = SDL_CreateWindow(title ? title : "iskra", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width,
                              height, SDL_WINDOW_RESIZABLE);
    if (!w->win) {
        display_error(err, "cannot create the window");
        isk_window_close(w);
        return ISK_ERR_DISPLAY;
    }
    w->id = SDL_GetWindowID(w->win);
    w->ren = SDL_CreateRenderer(w->win, -1, SDL_RENDERER_ACCELERATED | SDL_RENDERER_PRESENTVSYNC);
    if (!w->ren)
        w->ren = SDL_CreateRenderer(w->win, -1, SDL_RENDERER_SOFTWARE);
    if (!w->ren) {
        display_error(err, "cannot create a renderer");
        isk_window_close(w);
        return ISK_ERR_DISPLAY;
    }
    if (SDL_RenderSetLogicalSize(w->ren, width, height) != 0 || SDL_RenderSetIntegerScale(w->ren, SDL_TRUE) != 0) {
        display_error(err, "cannot set the logical size");
        isk_window_close(w);
        return ISK_ERR_DISPLAY;
    }
    w->tex = SDL_CreateTexture(w->ren, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STREAMING, width, height);
    if (!w->tex) {
        display_error(err, "cannot create the texture");
        isk_window_close(w);
        return ISK_ERR_DISPLAY;
    }
    *out = w;
    return ISK_OK;
}

isk_status isk_window_set_size(isk_window *w, int width, int height)
{
    if (!w)
        return ISK_ERR_NULL;
    if (width < 1 || height < 1 || width > ISK_CANVAS_MAX_DIM || height > ISK_CANVAS_MAX_DIM)
        return ISK_ERR_SIZE;
    SDL_SetWindowSize(w->win, width, height);
    return ISK_OK;
}

isk_status isk_window_resize_canvas(isk_window *w, int width, int height, isk_error *err)
{
    if (!w)
        return isk_error_set(err, ISK_ERR_NULL, "window: NULL argument");
    if (width < 1 || height < 1 || width > ISK_CANVAS_MAX_DIM || height > ISK_CANVAS_MAX_DIM)
        return isk_error_set(err, ISK_ERR_SIZE, "window: bad size %dx%d (1..%d each)", width, height,
                             ISK_CANVAS_MAX_DIM);
    if (width == w->width && height == w->height)
        return ISK_OK;
    SDL_Texture *tex = SDL_CreateTexture(w->ren, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STREAMING, width, height);
    if (!tex)
        return display_error(err, "cannot create the texture");
    if (SDL_RenderSetLogicalSize(w->ren, width, height) != 0) {
        SDL_DestroyTexture(tex);
        SDL_RenderSetLogicalSize(w->ren, w->width, w->height);
        return display_error(err, "cannot set the logical size");
    }
    SDL_DestroyTexture(w->tex);
    w->tex = tex;
    w->width = width;
    w->height = height;
    SDL_SetWindowSize(w->win, width, height);
    /* Grown past the screen's edge: back onto it (the top-left stays put
     * otherwise, so a canvas at the window's corner does not move). */
    SDL_Rect r;
    int x, y, display = SDL_GetWindowDisplayIndex(w->win);
    SDL_GetWindowPosition(w->win, &x, &y);
    if (display >= 0 && SDL_GetDisplayUsableBounds(display, &r) == 0) {
        int nx = x + width > r.x + r.w ? r.x + r.w - width : x, ny = y + height > r.y + r.h ? r.y + r.h - height : y;
        nx = nx < r.x ? r.x : nx;
        ny = ny < r.y ? r.y : ny;
        if (nx != x || ny != y)
            SDL_SetWindowPosition(w->win, nx, ny);
    }
    return ISK_OK;
}

double isk_window_scale(const isk_window *w)
{
    if (!w)
        return 0;
    float sx = 1, sy = 1;
    SDL_RenderGetScale(w->ren, &sx, &sy);
    return sx < sy ? sx : sy;
}

isk_status isk_window_display_size(const isk_window *w, int *width, int *height)
{
    if (!w || !width || !height)
        return ISK_ERR_NULL;
    SDL_Rect r;
    int display = SDL_GetWindowDisplayIndex(w->win);
    if (display < 0 || SDL_GetDisplayUsableBounds(display, &r) != 0 || r.w <= 0 || r.h <= 0)
        return ISK_ERR_DISPLAY;
    *width = r.w;
    *height = r.h;
    return ISK_OK;
}

void isk_window_set_pacing(isk_window *w, int on)
{
    if (w)
        w->unpaced = !on;
}

void isk_window_set_escape_quits(isk_window *w, int quits)
{
    if (w)
        w->escape_keeps = !quits;
}

/* ---- present ---------------------------------------------------------------- */

isk_status isk_window_present(isk_window *w, const isk_canvas *c, isk_error *err)
{
    if (!w || !c || !c->pixels)
        return isk_error_set(err, ISK_ERR_NULL, "window: NULL argument");
    if (c->width != w->width || c->height != w->height)
        return isk_error_set(err, ISK_ERR_SIZE, "window: canvas %dx%d does not match the window %dx%d",
                             c->width, c->height, w->width, w->height);
    if (c->stride > (size_t)INT_MAX) /* SDL takes the pitch as int */
        return isk_error_set(err, ISK_ERR_SIZE, "window: canvas stride %zu too large", c->stride);
    /* SDL_UpdateTexture honours both the canvas stride and the texture's own
     * pitch, so views and padded canvases upload correctly. */
    if (SDL_UpdateTexture(w->tex, NULL, c->pixels, (int)c->stride) != 0)
        return display_error(err, "cannot upload the canvas");
    /* Clear first: the letterbox bars around a resized window are black. */
    if (SDL_SetRenderDrawColor(w->ren, 0, 0, 0, 255) != 0 || SDL_RenderClear(w->ren) != 0 ||
        SDL_RenderCopy(w->ren, w->tex, NULL, NULL) != 0)
        return display_error(err, "cannot draw the canvas");
    SDL_RenderPresent(w->ren);
    return ISK_OK;
}

/* ---- input ------------------------------------------------------------------ */

int isk_window_poll(isk_window *w, isk_event *ev)
{
    if (!w || !ev)
        return 0;
    if (w->has_carry) {
        *ev = w->carry;
        w->has_carry = 0;
        return 1;
    }
    /* SDL (>= 2.0.22) marks the end of each pump with a sentinel and
     * SDL_PollEvent returns 0 once on reaching it, even when events pushed
     * after the pump are still queued; a second pass picks those up.  Two
     * passes at most, so a flood of new input cannot keep us here. */
    SDL_Event e;
    for (int pass = 0; pass < 2; pass++)
        while (SDL_PollEvent(&e))
            if (convert(w, &e, ev))
                return 1;
    return 0;
}

isk_status isk_window_push_event(isk_window *w, const isk_event *ev)
{
    if (!w || !ev)
        return ISK_ERR_NULL;
    SDL_Event e;
    memset(&e, 0, sizeof e);
    /* Mouse events carry windowID 0: SDL's renderer then leaves their
     * coordinates alone, so the caller's canvas pixels arrive unchanged even
     * when the window is scaled. */
    switch (ev->type) {
    case ISK_EVENT_QUIT:
        e.type = SDL_QUIT;
        break;
    case ISK_EVENT_KEY_DOWN:
    case ISK_EVENT_KEY_UP:
        e.type = ev->type == ISK_EVENT_KEY_DOWN ? SDL_KEYDOWN : SDL_KEYUP;
        e.key.state = ev->type == ISK_EVENT_KEY_DOWN ? SDL_PRESSED : SDL_RELEASED;
        e.key.keysym.sym = key_to_sdl(ev->key);
        e.key.keysym.scancode = SDL_GetScancodeFromKey(e.key.keysym.sym);
        e.key.keysym.mod = (Uint16)((ev->mods & ISK_MOD_SHIFT ? KMOD_LSHIFT : 0) |
                                    (ev->mods & ISK_MOD_CTRL ? KMOD_LCTRL : 0) | (ev->mods & ISK_MOD_ALT ? KMOD_LALT : 0));
        break;
    case ISK_EVENT_MOUSE_DOWN:
    case ISK_EVENT_MOUSE_UP:
        if (ev->button < 1 || ev->button > 3)
            return ISK_ERR_RANGE;
        e.type = ev->type == ISK_EVENT_MOUSE_DOWN ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
        e.button.state = ev->type == ISK_EVENT_MOUSE_DOWN ? SDL_PRESSED : SDL_RELEASED;
        e.button.button = (Uint8)(ev->button == 1 ? SDL_BUTTON_LEFT
                                  : ev->button == 2 ? SDL_BUTTON_MIDDLE : SDL_BUTTON_RIGHT);
        e.button.clicks = (Uint8)(ev->clicks > 1 ? 2 : 1);
        e.button.x = ev->x;
        e.button.y = ev->y;
        break;
    case ISK_EVENT_MOUSE_MOVE:
        e.type = SDL_MOUSEMOTION;
        e.motion.x = ev->x;
        e.motion.y = ev->y;
        break;
    case ISK_EVENT_WHEEL:
        if (ev->wheel != 1 && ev->wheel != -1)
            return ISK_ERR_RANGE;
        e.type = SDL_MOUSEWHEEL;
        e.wheel.y = ev->wheel;
        e.wheel.direction = SDL_MOUSEWHEEL_NORMAL;
        break;
    case ISK_EVENT_TEXT: {
        size_t n = strnlen(ev->text, sizeof ev->text);
        if (n == 0 || n >= sizeof ev->text || n >= sizeof e.text.text)
            return ISK_ERR_RANGE;
        e.type = SDL_TEXTINPUT;
        e.text.windowID = w->id;
        memcpy(e.text.text, ev->text, n + 1);
        break;
    }
    default:
        return ISK_ERR_RANGE;
    }
    /* 1 = queued, 0 = filtered out by an application filter, < 0 = error. */
    return SDL_PushEvent(&e) < 0 ? ISK_ERR_DISPLAY : ISK_OK;
}

/* Moves every pending event into ev[0..FRAME_EVENTS) and returns the count.
 * When the frame is full, the oldest mouse motion gives way, but only while
 * a later motion (kept or arriving) still says where the pointer is; an event
 * that does not fit waits in w->carry for the next frame, so clicks, keys
 * and the latest pointer position are never lost. */
static int collect_events(isk_window *w, isk_event *ev)
{
    int n = 0;
    isk_event e;
    /* Bounded even if motion kept arriving as fast as we drop it. */
    for (int polls = 0; polls < 16 * FRAME_EVENTS && isk_window_poll(w, &e); polls++) {
        if (n < FRAME_EVENTS) {
            ev[n++] = e;
            continue;
        }
        int oldest_motion = -1, motions = 0;
        for (int i = 0; i < n; i++)
            if (ev[i].type == ISK_EVENT_MOUSE_MOVE && motions++ == 0)
                oldest_motion = i;
        if (motions >= 2 || (motions == 1 && e.type == ISK_EVENT_MOUSE_MOVE)) {
            memmove(&ev[oldest_motion], &ev[oldest_motion + 1],
                    (size_t)(n - 1 - oldest_motion) * sizeof *ev);
            ev[n - 1] = e;
            continue;
        }
        w->carry = e;
        w->has_carry = 1;
        break;
    }
    return n;
}

static int ends_loop(const isk_window *w, const isk_event *e)
{
    return e->type == ISK_EVENT_QUIT || (!w->escape_keeps && e->type == ISK_EVENT_KEY_DOWN && e->key == ISK_KEY_ESCAPE);
}

isk_status isk_window_run(isk_window *w, isk_canvas *canvas, isk_frame_fn frame, void *user, long max_frames,
                          isk_error *err)
{
    if (!w || !canvas || !frame || !canvas->pixels)
        return isk_error_set(err, ISK_ERR_NULL, "window: NULL argument");
    if (max_frames < 0)
        return isk_error_set(err, ISK_ERR_RANGE, "window: max_frames %ld is negative", max_frames);
    /* Refuse before the first callback rather than after it. */
    if (canvas->width != w->width || canvas->height != w->height)
        return isk_error_set(err, ISK_ERR_SIZE, "window: canvas %dx%d does not match the window %dx%d",
                             canvas->width, canvas->height, w->width, w->height);
    isk_event events[FRAME_EVENTS];
    const double freq = (double)SDL_GetPerformanceFrequency();
    Uint64 last = SDL_GetPerformanceCounter();
    for (long n = 0; max_frames == 0 || n < max_frames; n++) {
        int nev = collect_events(w, events);
        for (int i = 0; i < nev; i++)
            if (ends_loop(w, &events[i]))
                return ISK_OK;
        Uint64 now = SDL_GetPerformanceCounter();
        double dt = (double)(now - last) / freq;
        last = now;
        if (frame(user, canvas, dt, events, nev))
            return ISK_OK;
        isk_status s = isk_window_present(w, canvas, err);
        if (s != ISK_OK)
            return s;
        /* Without vsync (software or dummy renderer) nothing else would stop
         * an idle loop from spinning a core: sleep out the rest of ~1/60 s. */
        double spent_ms = (double)(SDL_GetPerformanceCounter() - now) * 1000.0 / freq;
        if (spent_ms < MIN_FRAME_MS && !w->unpaced)
            SDL_Delay((Uint32)(MIN_FRAME_MS - spent_ms));
    }
    return ISK_OK;
}
