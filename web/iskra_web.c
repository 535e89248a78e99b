/* SPDX-License-Identifier: MIT */
/* The simulator in a web page: the functions web/iskra.js calls in the
 * wasm module (wasm32-wasi, built by `make web`).
 *
 * The page owns nothing of the simulation: it passes the browser's events
 * in, calls iskra_web_frame once per animation frame, and copies the
 * window's canvas (the scene's canvas and the panel, drawn by iskra
 * itself: tools/iskra/play_*.c, the same files as `iskra play`) into an
 * HTML canvas.  Files the user asks for (a saved scene, a screenshot, an
 * animated GIF) are made in memory and left here for the page to offer as
 * downloads.  Strings go both ways as NUL-terminated UTF-8 in the module's
 * memory (iskra_web_alloc / iskra_web_free).
 *
 * The library runs on one thread here (src/sim/pool_serial.c): the bytes
 * of every thread count, so the page's canvas is byte for byte that of
 * `iskra render` on any machine. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/anim.h"
#include "iskra/scene.h"
#include "iskra/sdl.h"
#include "play.h"

#define WEB_EXPORT(name) __attribute__((export_name(#name)))
#define WEB_EVENTS_MAX 256

typedef struct web_file {
    char name[256];
    char *bytes;               /* malloc'd, or NULL: none waiting */
    size_t size;
} web_file;

typedef struct web_gif {
    isk_anim *anim;            /* NULL: not recording */
    FILE *f;                   /* a memory stream into bytes */
    char *bytes;
    size_t size;
    long left;                 /* frames still to add */
    char name[256];
} web_gif;

typedef struct web_page {
    player p;
    int open;                  /* p holds a scene */
    isk_canvas shown;          /* the window's canvas: scene and panel */
    char scene[128];           /* p.args.scene points here */
    char *text;                /* p.args.text points here (an edited scene), or NULL */
    isk_event events[WEB_EVENTS_MAX];
    int nevents;
    char message[2048];        /* the last error, for the page */
    web_file file;             /* a file for the user, until the page takes it */
    web_gif gif;
    isk_canvas still;          /* iskra_web_render's canvas */
    int zoom;                  /* the page shows the window this many times larger */
} web_page;

static web_page page; /* the module's one page (a wasm instance is one page's) */

WEB_EXPORT(iskra_web_alloc) void *iskra_web_alloc(size_t n) { return malloc(n ? n : 1); }
WEB_EXPORT(iskra_web_free) void iskra_web_free(void *ptr) { free(ptr); }
WEB_EXPORT(iskra_web_message) const char *iskra_web_message(void) { return page.message; }

/* ---- the host the player asks things of (play_host) ---------------------- */

/* The player resizes the window's canvas itself (p->shown, which is
 * page.shown); the page follows its size every frame. */
static isk_status host_resize(void *user, int w, int h, isk_error *err)
{
    (void)user, (void)w, (void)h, (void)err;
    return ISK_OK;
}

static isk_status host_push_event(void *user, const isk_event *ev)
{
    web_page *g = user;
    if (g->nevents == WEB_EVENTS_MAX)
        return ISK_ERR_FULL;
    g->events[g->nevents++] = *ev;
    return ISK_OK;
}

static void host_deliver(void *user, const char *name, const void *bytes, size_t n)
{
    web_page *g = user;
    char *copy = malloc(n ? n : 1);
    if (!copy) {
        snprintf(g->message, sizeof g->message, "%s: out of memory", name);
        return;
    }
    memcpy(copy, bytes, n);
    free(g->file.bytes);
    g->file.bytes = copy;
    g->file.size = n;
    snprintf(g->file.name, sizeof g->file.name, "%s", name);
}

/* ---- a scene in the player ------------------------------------------------ */

static void gif_abort(web_gif *r)
{
    if (r->anim)
        isk_anim_abort(r->anim);
    if (r->f)
        fclose(r->f);
    free(r->bytes);
    memset(r, 0, sizeof *r);
}

static void close_player(web_page *g)
{
    if (!g->open)
        return;
    gif_abort(&g->gif);
    isk_canvas_free(&g->p.sim);
    isk_canvas_free(&g->p.chart_cache);
    isk_effect_destroy(g->p.fx);
    play_script_free(&g->p.script);
    memset(&g->p, 0, sizeof g->p);
    g->open = 0;
}

/* The page shows the window magnified by a whole number (iskra_web_zoom),
 * the scene's canvas with the panel: the largest zoom whose layout, made
 * for the viewport divided by it, fits. */
static void choose_zoom(web_page *g, int view_w, int view_h)
{
    player *p = &g->p;
    for (g->zoom = 4; g->zoom >= 1; g->zoom--) {
        p->screen_w = view_w / g->zoom < 320 ? 320 : view_w / g->zoom > 16384 ? 16384 : view_w / g->zoom;
        p->screen_h = view_h / g->zoom < 200 ? 200 : view_h / g->zoom > 16384 ? 16384 : view_h / g->zoom;
        play_choose_layout(p, 0);
        play_layout_compute(p);
        if (p->lay.window.w <= p->screen_w && p->lay.window.h <= p->screen_h)
            return;
    }
    g->zoom = 1; /* nothing fits: the smallest layout, at 1, and the page scrolls */
}

/* Opens `scene` (a built-in scene's name, or with text the name of an
 * edited scene) for a screen of screen_w x screen_h CSS pixels.  On
 * failure (status 2 for a scene error, 1 otherwise) iskra_web_message
 * says why, "FILE:LINE: message" for a scene's mistake, and the running
 * scene keeps running.  fixed_clock: every frame is one step (tests). */
WEB_EXPORT(iskra_web_open)
int iskra_web_open(const char *scene, const char *text, int screen_w, int screen_h, int fixed_clock)
{
    web_page *g = &page;
    g->message[0] = 0;
    if (!scene || !*scene || strlen(scene) >= sizeof g->scene) {
        snprintf(g->message, sizeof g->message, "which scene? (a name of at most %zu bytes)", sizeof g->scene - 1);
        return 2;
    }
    char *copy = NULL;
    if (text && !(copy = malloc(strlen(text) + 1))) {
        snprintf(g->message, sizeof g->message, "out of memory");
        return 1;
    }
    if (copy)
        strcpy(copy, text);
    scene_args args = {.cmd = "web", .scene = scene, .text = copy};
    isk_effect_def def;
    isk_effect *fx;
    int rc = scene_args_load(&args, &def, &fx, g->message, sizeof g->message);
    if (rc) {
        free(copy);
        return rc;
    }
    isk_effect_def_free(&def);
    close_player(g);
    free(g->text);
    g->text = copy;
    snprintf(g->scene, sizeof g->scene, "%s", scene);
    player *p = &g->p;
    p->args = args;
    p->args.scene = g->scene;
    p->args.text = g->text;
    p->fx = fx;
    p->insp.section = -1;
    p->host = (play_host){g, host_resize, host_push_event, host_deliver};
    snprintf(p->name, sizeof p->name, "%.*s", (int)strcspn(scene, "."), scene);
    p->panel = 1;
    p->hud = 1;
    p->fixed_clock = fixed_clock != 0;
    p->borderless = 1; /* the page's room is all the window's */
    const isk_effect_def *d = isk_effect_definition(fx);
    p->panel_kind = play_panel_for(d);
    g->open = 1;
    isk_ui_init(&p->ui, 1);
    choose_zoom(g, screen_w, screen_h);
    play_layout_compute(p);
    isk_canvas_free(&g->shown);
    if (isk_canvas_init(&p->sim, d->width, d->height) != ISK_OK || isk_effect_run(fx, &p->sim, 0) != ISK_OK ||
        isk_canvas_init(&g->shown, p->lay.window.w, p->lay.window.h) != ISK_OK) {
        snprintf(g->message, sizeof g->message, "%s: out of memory", scene);
        close_player(g);
        return 1;
    }
    p->shown = &g->shown;
    play_begin_scene(p);
    return 0;
}

/* Applies edited scene text to the running scene as the simulator's reload
 * does: a mistake leaves the last good scene running and its
 * "FILE:LINE: message" both here (iskra_web_message) and in the window. */
WEB_EXPORT(iskra_web_apply) int iskra_web_apply(const char *name, const char *text)
{
    web_page *g = &page;
    if (!g->open || !text)
        return iskra_web_open(name, text, 1280, 720, 0);
    char *copy = malloc(strlen(text) + 1);
    if (!copy) {
        snprintf(g->message, sizeof g->message, "out of memory");
        return 1;
    }
    strcpy(copy, text);
    const char *old_text = g->p.args.text;
    snprintf(g->scene, sizeof g->scene, "%s", name && *name && strlen(name) < sizeof g->scene ? name : "scene.ini");
    g->p.args.text = copy;
    if (play_reload(&g->p) != 0) {
        g->p.args.text = old_text;
        free(copy);
        snprintf(g->message, sizeof g->message, "%s", g->p.reload_error);
        return 2;
    }
    free(g->text);
    g->text = copy;
    g->message[0] = 0;
    snprintf(g->p.name, sizeof g->p.name, "%.*s", (int)strcspn(g->scene, "."), g->scene);
    return 0;
}

/* ---- frames ------------------------------------------------------------------ */

static void gif_add(web_page *g)
{
    web_gif *r = &g->gif;
    isk_error err;
    if (isk_anim_frame(r->anim, &g->p.sim, &err) != ISK_OK) {
        snprintf(g->message, sizeof g->message, "GIF: %s", err.message);
        gif_abort(r);
        return;
    }
    if (--r->left > 0)
        return;
    isk_status s = isk_anim_end(r->anim, &err);
    r->anim = NULL;
    if (s == ISK_OK && fclose(r->f) == 0) {
        r->f = NULL;
        host_deliver(g, r->name, r->bytes, r->size);
        play_say(&g->p, "saved %s", r->name);
    } else {
        snprintf(g->message, sizeof g->message, "GIF: %s", s == ISK_OK ? "out of memory" : err.message);
    }
    gif_abort(r);
}

/* One shown frame after dt_seconds of real time, with the events given
 * since the last.  Returns 0 to go on, 1 when the simulator stopped (its
 * Quit, or a failure: iskra_web_message). */
WEB_EXPORT(iskra_web_frame) int iskra_web_frame(double dt_seconds)
{
    web_page *g = &page;
    if (!g->open)
        return 1;
    if (!(dt_seconds >= 0.0) || dt_seconds > 1.0)
        dt_seconds = dt_seconds > 1.0 ? 1.0 : 0.0;
    isk_event ev[WEB_EVENTS_MAX];
    const int n = g->nevents;
    memcpy(ev, g->events, sizeof ev[0] * (size_t)n);
    g->nevents = 0;
    int rc = play_frame(&g->p, dt_seconds, ev, n);
    if (g->gif.anim)
        gif_add(g);
    if (g->p.failed)
        snprintf(g->message, sizeof g->message, "the scene stopped: out of memory or a broken state");
    return rc != 0;
}

/* An event from the page; x, y in window-canvas pixels.  type: an
 * isk_event_type; key: an ISK_KEY_* code or lower-case ASCII. */
WEB_EXPORT(iskra_web_event)
void iskra_web_event(int type, int key, int button, int x, int y, int wheel, int mods, int clicks)
{
    isk_event e = {.type = (isk_event_type)type, .key = key, .button = button, .x = x, .y = y,
                   .wheel = wheel, .mods = mods, .clicks = clicks};
    host_push_event(&page, &e);
}

/* Text typed (UTF-8, at most 31 bytes a call). */
WEB_EXPORT(iskra_web_text) void iskra_web_text(const char *utf8)
{
    isk_event e = {.type = ISK_EVENT_TEXT};
    if (!utf8 || !*utf8 || strlen(utf8) >= sizeof e.text)
        return;
    strcpy(e.text, utf8);
    host_push_event(&page, &e);
}

/* The window's canvas (scene and panel): its pixels (RGBA, rows `stride`
 * bytes apart), width and height. */
WEB_EXPORT(iskra_web_pixels) const uint8_t *iskra_web_pixels(void) { return page.shown.pixels; }
WEB_EXPORT(iskra_web_width) int iskra_web_width(void) { return page.shown.width; }
WEB_EXPORT(iskra_web_height) int iskra_web_height(void) { return page.shown.height; }
WEB_EXPORT(iskra_web_zoom) int iskra_web_zoom(void) { return page.zoom < 1 ? 1 : page.zoom; }
WEB_EXPORT(iskra_web_stride) int iskra_web_stride(void) { return (int)page.shown.stride; }
/* The scene's own canvas (without the panel), for tests. */
WEB_EXPORT(iskra_web_scene_pixels) const uint8_t *iskra_web_scene_pixels(void) { return page.p.sim.pixels; }
WEB_EXPORT(iskra_web_scene_width) int iskra_web_scene_width(void) { return page.p.sim.width; }
WEB_EXPORT(iskra_web_scene_height) int iskra_web_scene_height(void) { return page.p.sim.height; }
WEB_EXPORT(iskra_web_scene_stride) int iskra_web_scene_stride(void) { return (int)page.p.sim.stride; }
WEB_EXPORT(iskra_web_scene_frame) long iskra_web_scene_frame(void) { return page.open ? isk_effect_frame(page.p.fx) : 0; }

/* ---- scenes --------------------------------------------------------------- */

WEB_EXPORT(iskra_web_builtin_count) int iskra_web_builtin_count(void) { return isk_scene_builtin_count(); }
WEB_EXPORT(iskra_web_builtin_name) const char *iskra_web_builtin_name(int i) { return isk_scene_builtin_name(i); }
WEB_EXPORT(iskra_web_builtin_text) const char *iskra_web_builtin_text(const char *name)
{
    return isk_scene_builtin_text(name);
}

/* The running scene as scene text (its live values: what Save writes),
 * malloc'd (iskra_web_free), or NULL (iskra_web_message says why). */
WEB_EXPORT(iskra_web_scene_text) char *iskra_web_scene_text(void)
{
    if (!page.open)
        return NULL;
    char *text;
    isk_error err;
    if (isk_scene_write(isk_effect_definition(page.p.fx), &text, &err) != ISK_OK) {
        snprintf(page.message, sizeof page.message, "%s", err.message);
        return NULL;
    }
    return text;
}

/* ---- files for the user ------------------------------------------------------- */

WEB_EXPORT(iskra_web_file_name) const char *iskra_web_file_name(void)
{
    return page.file.bytes ? page.file.name : NULL;
}
WEB_EXPORT(iskra_web_file_bytes) const char *iskra_web_file_bytes(void) { return page.file.bytes; }
WEB_EXPORT(iskra_web_file_size) size_t iskra_web_file_size(void) { return page.file.size; }
WEB_EXPORT(iskra_web_file_taken) void iskra_web_file_taken(void)
{
    free(page.file.bytes);
    memset(&page.file, 0, sizeof page.file);
}

/* Records the next `frames` frames of the scene's canvas (every one) as an
 * animated GIF (iskra/anim.h: a palette per frame, exact up to 256
 * colours); when done it waits as the file for the user. */
WEB_EXPORT(iskra_web_gif) int iskra_web_gif(long frames)
{
    web_page *g = &page;
    if (!g->open || frames < 1 || frames > 3600) {
        snprintf(g->message, sizeof g->message, "GIF: 1 to 3600 frames, not %ld", frames);
        return 2;
    }
    gif_abort(&g->gif);
    web_gif *r = &g->gif;
    r->f = open_memstream(&r->bytes, &r->size);
    const isk_effect_def *d = isk_effect_definition(g->p.fx);
    isk_anim_opts o = {.format = ISK_ANIM_GIF, .width = d->width, .height = d->height,
                       .fps = d->dt >= 0.001 ? 1.0 / d->dt : 1000.0};
    isk_error err;
    if (!r->f || isk_anim_begin(&r->anim, r->f, &o, &err) != ISK_OK) {
        snprintf(g->message, sizeof g->message, "GIF: %s", r->f ? err.message : "out of memory");
        gif_abort(r);
        return 1;
    }
    r->left = frames;
    snprintf(r->name, sizeof r->name, "iskra-%s-%06ld.gif", g->p.name, isk_effect_frame(g->p.fx));
    return 0;
}

/* ---- the same frame as `iskra render` ------------------------------------ */

/* Frame `frames` of a built-in scene, as `iskra render NAME --frames N`
 * draws it, into a canvas of its own (iskra_web_render_pixels ...): what
 * the tests compare with the native build.  0, or as iskra_web_open. */
WEB_EXPORT(iskra_web_render) int iskra_web_render(const char *scene, long frames)
{
    web_page *g = &page;
    scene_args args = {.cmd = "web", .scene = scene};
    isk_effect_def def;
    isk_effect *fx;
    int rc = scene_args_load(&args, &def, &fx, g->message, sizeof g->message);
    if (rc)
        return rc;
    isk_canvas_free(&g->still);
    rc = isk_canvas_init(&g->still, def.width, def.height) == ISK_OK &&
                 isk_effect_run(fx, &g->still, frames < 0 ? 0 : frames) == ISK_OK
             ? 0
             : 1;
    if (rc)
        snprintf(g->message, sizeof g->message, "%s: cannot draw frame %ld", scene, frames);
    isk_effect_destroy(fx);
    isk_effect_def_free(&def);
    return rc;
}
WEB_EXPORT(iskra_web_render_pixels) const uint8_t *iskra_web_render_pixels(void) { return page.still.pixels; }
WEB_EXPORT(iskra_web_render_width) int iskra_web_render_width(void) { return page.still.width; }
WEB_EXPORT(iskra_web_render_height) int iskra_web_render_height(void) { return page.still.height; }
WEB_EXPORT(iskra_web_render_stride) int iskra_web_render_stride(void) { return (int)page.still.stride; }

/* ---- for scripts ----------------------------------------------------------- */

/* Live particles of the running scene. */
WEB_EXPORT(iskra_web_particle_count) double iskra_web_particle_count(void)
{
    return page.open ? (double)isk_effect_particle_count(page.p.fx) : 0.0;
}

/* Where the widget `name` (iskra play --list-widgets) was drawn in the last
 * frame: x, y, w, h in window-canvas pixels into out[4]; 0 if it was not. */
WEB_EXPORT(iskra_web_widget_rect) int iskra_web_widget_rect(const char *name, int *out)
{
    isk_ui_rect r;
    if (!page.open || !name || !out || !isk_ui_find(&page.p.ui, name, &r))
        return 0;
    out[0] = r.x;
    out[1] = r.y;
    out[2] = r.w;
    out[3] = r.h;
    return 1;
}
