/* The SDL2 window of libiskra-sdl (see iskra/sdl.h).
 *
 * A window shows a canvas 1:1 through a streaming SDL_PIXELFORMAT_RGBA32
 * texture (the canvas's byte order, so no conversion); input comes back as
 * isk_event values.  Works under SDL_VIDEODRIVER=dummy: the renderer then
 * is SDL's software renderer and nothing is shown, which is how the tests
 * drive it. */
#include <SDL.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/sdl.h"

#define MAX_EVENTS 256

struct isk_window {
    SDL_Window *win;
    SDL_Renderer *ren;
    SDL_Texture *tex;
    int width, height;
    int owns_video; /* we initialised the video subsystem */
};

static int map_key(SDL_Keycode k)
{
    if (k >= SDLK_F1 && k <= SDLK_F12)
        return ISK_KEY_F1 + (int)(k - SDLK_F1);
    switch (k) {
    case SDLK_ESCAPE: return ISK_KEY_ESCAPE;
    case SDLK_SPACE: return ISK_KEY_SPACE;
    case SDLK_RETURN: return ISK_KEY_RETURN;
    case SDLK_LEFT: return ISK_KEY_LEFT;
    case SDLK_RIGHT: return ISK_KEY_RIGHT;
    case SDLK_UP: return ISK_KEY_UP;
    case SDLK_DOWN: return ISK_KEY_DOWN;
    case SDLK_KP_PLUS: return ISK_KEY_KP_PLUS;
    case SDLK_KP_MINUS: return ISK_KEY_KP_MINUS;
    default: break;
    }
    if (k >= 32 && k < 127)
        return (k >= 'A' && k <= 'Z') ? (int)k - 'A' + 'a' : (int)k;
    return ISK_KEY_UNKNOWN;
}

/* Our events travel through SDL's queue as SDL_USEREVENT with the isk_event
 * in data1 (freed when read), so injected and real events stay in order. */
static Uint32 user_event_type(void)
{
    static Uint32 type = 0;
    if (!type) {
        Uint32 t = SDL_RegisterEvents(1);
        type = t == (Uint32)-1 ? SDL_USEREVENT : t;
    }
    return type;
}

static int convert(const SDL_Event *e, isk_event *ev)
{
    memset(ev, 0, sizeof *ev);
    switch (e->type) {
    case SDL_QUIT: ev->type = ISK_EVENT_QUIT; return 1;
    case SDL_KEYDOWN:
    case SDL_KEYUP:
        ev->type = e->type == SDL_KEYDOWN ? ISK_EVENT_KEY_DOWN : ISK_EVENT_KEY_UP;
        ev->key = map_key(e->key.keysym.sym);
        return 1;
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
        ev->type = e->type == SDL_MOUSEBUTTONDOWN ? ISK_EVENT_MOUSE_DOWN : ISK_EVENT_MOUSE_UP;
        ev->button = e->button.button == SDL_BUTTON_LEFT ? 1 : e->button.button == SDL_BUTTON_MIDDLE ? 2 : 3;
        ev->x = e->button.x;
        ev->y = e->button.y;
        return 1;
    case SDL_MOUSEMOTION:
        ev->type = ISK_EVENT_MOUSE_MOVE;
        ev->x = e->motion.x;
        ev->y = e->motion.y;
        return 1;
    case SDL_MOUSEWHEEL:
        ev->type = ISK_EVENT_WHEEL;
        ev->wheel = e->wheel.y > 0 ? 1 : e->wheel.y < 0 ? -1 : 0;
        return ev->wheel != 0;
    default:
        if (e->type == user_event_type() && e->user.data1) {
            *ev = *(isk_event *)e->user.data1;
            free(e->user.data1);
            return 1;
        }
        return 0;
    }
}

isk_status isk_window_open(isk_window **out, const char *title, int width, int height, isk_error *err)
{
    if (!out)
        return isk_error_set(err, ISK_ERR_NULL, "window: NULL argument");
    *out = NULL;
    if (width < 1 || height < 1 || width > ISK_CANVAS_MAX_DIM || height > ISK_CANVAS_MAX_DIM)
        return isk_error_set(err, ISK_ERR_SIZE, "window: bad size %dx%d", width, height);
    isk_window *w = calloc(1, sizeof *w);
    if (!w)
        return isk_error_set(err, ISK_ERR_NOMEM, "window: out of memory");
    if (!SDL_WasInit(SDL_INIT_VIDEO)) {
        if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
            isk_error_set(err, ISK_ERR_DISPLAY, "SDL: %s", SDL_GetError());
            free(w);
            return ISK_ERR_DISPLAY;
        }
        w->owns_video = 1;
    }
    w->width = width;
    w->height = height;
    w->win = SDL_CreateWindow(title ? title : "iskra", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height,
                              0);
    if (w->win)
        w->ren = SDL_CreateRenderer(w->win, -1, SDL_RENDERER_PRESENTVSYNC);
    if (!w->ren && w->win)
        w->ren = SDL_CreateRenderer(w->win, -1, SDL_RENDERER_SOFTWARE);
    if (w->ren)
        w->tex = SDL_CreateTexture(w->ren, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STREAMING, width, height);
    if (!w->tex) {
        isk_error_set(err, ISK_ERR_DISPLAY, "SDL: %s", SDL_GetError());
        isk_window_close(w);
        return ISK_ERR_DISPLAY;
    }
    *out = w;
    return ISK_OK;
}

isk_status isk_window_present(isk_window *w, const isk_canvas *c, isk_error *err)
{
    if (!w || !c)
        return isk_error_set(err, ISK_ERR_NULL, "window: NULL argument");
    if (c->width != w->width || c->height != w->height)
        return isk_error_set(err, ISK_ERR_SIZE, "window: canvas %dx%d does not match the window %dx%d", c->width,
                             c->height, w->width, w->height);
    if (c->stride > (size_t)0x7fffffff ||
        SDL_UpdateTexture(w->tex, NULL, c->pixels, (int)c->stride) != 0 || SDL_RenderClear(w->ren) != 0 ||
        SDL_RenderCopy(w->ren, w->tex, NULL, NULL) != 0)
        return isk_error_set(err, ISK_ERR_DISPLAY, "SDL: %s", SDL_GetError());
    SDL_RenderPresent(w->ren);
    return ISK_OK;
}

int isk_window_poll(isk_window *w, isk_event *ev)
{
    if (!w || !ev)
        return 0;
    SDL_Event e;
    while (SDL_PollEvent(&e))
        if (convert(&e, ev))
            return 1;
    return 0;
}

isk_status isk_window_push_event(isk_window *w, const isk_event *ev)
{
    if (!w || !ev)
        return ISK_ERR_NULL;
    isk_event *copy = malloc(sizeof *copy);
    if (!copy)
        return ISK_ERR_NOMEM;
    *copy = *ev;
    SDL_Event e;
    memset(&e, 0, sizeof e);
    e.type = user_event_type();
    e.user.data1 = copy;
    if (SDL_PushEvent(&e) != 1) {
        free(copy);
        return ISK_ERR_DISPLAY;
    }
    return ISK_OK;
}

isk_status isk_window_run(isk_window *w, isk_canvas *canvas, isk_frame_fn frame, void *user, long max_frames,
                          isk_error *err)
{
    if (!w || !canvas || !frame)
        return isk_error_set(err, ISK_ERR_NULL, "window: NULL argument");
    isk_event events[MAX_EVENTS];
    Uint64 freq = SDL_GetPerformanceFrequency(), last = SDL_GetPerformanceCounter();
    for (long n = 0; max_frames <= 0 || n < max_frames; n++) {
        int nev = 0, quit = 0;
        isk_event ev;
        while (nev < MAX_EVENTS && isk_window_poll(w, &ev)) {
            if (ev.type == ISK_EVENT_QUIT || (ev.type == ISK_EVENT_KEY_DOWN && ev.key == ISK_KEY_ESCAPE))
                quit = 1;
            events[nev++] = ev;
        }
        if (quit)
            break;
        Uint64 t = SDL_GetPerformanceCounter();
        double dt = (double)(t - last) / (double)freq;
        last = t;
        if (frame(user, canvas, dt, events, nev))
            break;
        isk_status s = isk_window_present(w, canvas, err);
        if (s != ISK_OK)
            return s;
    }
    return ISK_OK;
}

void isk_window_close(isk_window *w)
{
    if (!w)
        return;
    /* free injected events still queued */
    SDL_Event e;
    while (SDL_PeepEvents(&e, 1, SDL_GETEVENT, user_event_type(), user_event_type()) == 1)
        free(e.user.data1);
    if (w->tex)
        SDL_DestroyTexture(w->tex);
    if (w->ren)
        SDL_DestroyRenderer(w->ren);
    if (w->win)
        SDL_DestroyWindow(w->win);
    if (w->owns_video)
        SDL_QuitSubSystem(SDL_INIT_VIDEO);
    free(w);
}
