/* SPDX-License-Identifier: MIT */
/* The simulator's files: reload (the button, F5, and by itself when the
 * scene file changes, so a scene can be edited in any editor and watched;
 * a file that does not load leaves the last good scene running and its
 * "FILE:LINE: message" in the window until it loads), save (the parameters
 * as they are now, as a scene file that reproduces them: isk_scene_save),
 * screenshots of the canvas or of the whole window. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "iskra/png.h"
#include "iskra/scene.h"
#include "outpath.h"
#include "play.h"

void play_remember_file(player *p)
{
    struct stat st;
    if (p->path && stat(p->path, &st) == 0) {
        p->stamp = (long long)st.st_mtime * 1000000000LL + (long long)st.st_mtim.tv_nsec;
        p->stamp_size = (long long)st.st_size;
    }
}

void play_watch(player *p)
{
    /* About twice a second; by frames, so a scripted run is the same. */
    if (!p->path || p->frames_shown % 30 != 0)
        return;
    struct stat st;
    if (stat(p->path, &st) != 0)
        return;
    long long stamp = (long long)st.st_mtime * 1000000000LL + (long long)st.st_mtim.tv_nsec;
    if (stamp == p->stamp && (long long)st.st_size == p->stamp_size)
        return;
    if (play_reload(p) == 0)
        play_say(p, "%s changed: reloaded", p->path);
}

static int resize_for(player *p, int width, int height)
{
    isk_canvas sim;
    if (isk_canvas_init(&sim, width, height) != ISK_OK)
        return -1;
    play_layout l;
    play_layout_plan(p, width, height, p->panel, &l);
    const int w = l.window.w, h = l.window.h;
    isk_canvas shown;
    if (isk_canvas_init(&shown, w, h) != ISK_OK) {
        isk_canvas_free(&sim);
        return -1;
    }
    isk_error err;
    if (p->host.resize && p->host.resize(p->host.user, w, h, &err) != ISK_OK) {
        play_say(p, "reload: cannot resize the window: %s", err.message);
        isk_canvas_free(&sim);
        isk_canvas_free(&shown);
        return -1;
    }
    isk_canvas_free(&p->sim);
    p->sim = sim;
    isk_canvas_free(p->shown);
    *p->shown = shown;
    return 0;
}

int play_reload(player *p)
{
    isk_effect_def def;
    isk_effect *fx;
    /* A file that does not load is not tried again until it changes. */
    play_remember_file(p);
    if (scene_args_load(&p->args, &def, &fx, p->reload_error, sizeof p->reload_error) != 0) {
        /* The class watches the window, not the terminal: the whole message
         * stays on the canvas until the file loads (play_hud.c). */
        fprintf(stderr, "%s\n", p->reload_error);
        play_say(p, "reload: the last version keeps running");
        return -1;
    }
    p->reload_error[0] = 0;
    const isk_effect_def *old = isk_effect_definition(p->fx);
    if ((def.width != old->width || def.height != old->height) && resize_for(p, def.width, def.height) != 0) {
        isk_effect_destroy(fx);
        isk_effect_def_free(&def);
        return -1;
    }
    isk_effect_destroy(p->fx);
    p->fx = fx;
    isk_effect_def_free(&def);
    play_layout_compute(p);
    if (isk_effect_run(p->fx, &p->sim, 0) != ISK_OK)
        p->failed = 1;
    play_begin_scene(p);
    return 0;
}

/* A file for the host to hand over (play_host.deliver): a scene's text or
 * a PNG, made in memory. */
static void deliver_scene(player *p, const char *name)
{
    char *text;
    isk_error err;
    if (isk_scene_write(isk_effect_definition(p->fx), &text, &err) != ISK_OK) {
        play_say(p, "save failed: %s", err.message);
        return;
    }
    p->host.deliver(p->host.user, name, text, strlen(text));
    play_say(p, "saved %s", name);
    free(text);
}

static void deliver_png(player *p, const isk_canvas *c, const char *name)
{
    char *bytes = NULL;
    size_t n = 0;
    FILE *f = open_memstream(&bytes, &n);
    isk_error err;
    isk_status s = f ? isk_png_write_stream(c, f, name, &err) : ISK_ERR_NOMEM;
    if (f && fclose(f) != 0 && s == ISK_OK)
        s = ISK_ERR_NOMEM;
    if (s == ISK_OK) {
        p->host.deliver(p->host.user, name, bytes, n);
        play_say(p, "saved %s", name);
    } else {
        play_say(p, "screenshot failed: %s", s == ISK_ERR_NOMEM ? "out of memory" : err.message);
    }
    free(bytes);
}

void play_save(player *p)
{
    char path[4200];
    if (p->save_to)
        snprintf(path, sizeof path, "%s", p->save_to);
    else
        snprintf(path, sizeof path, "iskra-%s.ini", p->name);
    if (p->host.deliver) {
        deliver_scene(p, path);
        return;
    }
    isk_error err;
    if (isk_scene_save(isk_effect_definition(p->fx), path, &err) != ISK_OK)
        play_say(p, "save failed: %s", err.message);
    else
        play_say(p, "saved %s (iskra play runs it again)", path);
}

void play_screenshot(player *p, int whole_window, const char *path)
{
    char name[4200];
    const isk_canvas *c = whole_window ? p->shown : &p->sim;
    if (!path) {
        if (p->host.deliver) {
            snprintf(name, sizeof name, "iskra-%s-%06ld%s.png", p->name, isk_effect_frame(p->fx),
                     whole_window ? "-window" : "");
            deliver_png(p, c, name);
            return;
        }
        snprintf(name, sizeof name, "%s%siskra-%s-%06ld%s.png", p->shots ? p->shots : "", p->shots ? "/" : "",
                 p->name, isk_effect_frame(p->fx), whole_window ? "-window" : "");
        path = name;
        if (p->shots && outpath_make_dirs("play", p->shots))
            return;
    }
    isk_error err;
    if (isk_png_write(c, path, &err) == ISK_OK)
        play_say(p, "saved %s", path);
    else
        play_say(p, "screenshot failed: %s", err.message);
}
