/* SPDX-License-Identifier: MIT */
/* iskra play SCENE — the scene in an SDL2 window: the thesis's simulator.
 *
 * The canvas sits at the window's top-left.  The explosion thesis's scenes
 * (a layer or potentials) get the thesis's console beside and below it
 * (play_panel.c: play, pause, stop, reset, reload, step; the speed slider;
 * precision, particles, explosion count, gravity, drag; the walls; click
 * modes; the potentials; the layer), live charts of the energy and the
 * particle count, and the integrators with what they cost; every other
 * scene gets the inspector (play_inspector.c): each section's live keys,
 * each as the widget its row calls for.  Every control edits the running
 * effect through the key table (isk_effect_set), so what it accepts and
 * what it says are the scene format's.  The layout fits the screen with
 * text at least 10 px tall (play_layout.c).  Tab hides the panel for a
 * full-canvas demo.
 *
 * Time: a fixed simulation step (the scene's dt, divided by the speed
 * slider's f) driven by the display's clock through an accumulator
 * (iskra/timestep.h): at most 5 steps per shown frame, the rest of a stall
 * is dropped and the HUD says real time is not kept.  --fixed-clock makes
 * every shown frame one step, so --script sessions give the same pixels
 * every time (the tests' reference images).  With no display (SDL could
 * only start a driver that shows nothing) it says so and exits 1;
 * SDL_VIDEODRIVER=dummy runs it headless on purpose. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cmd.h"
#include "iskra/sdl.h"
#include "outpath.h"
#include "play.h"
#include "scene_args.h"

static void help(FILE *f)
{
    fprintf(f, "usage: iskra play SCENE [--frames N] [--fixed-clock] [--script EVENTS] [--list-widgets]\n"
               "                  [--ui-scale N] [--screen WxH] [--panel console|inspector] [--no-panel]\n"
               "                  [--save PATH] [--shots DIR] [--follow EMITTER] [--seed N] [--size WxH]\n"
               "                  [--dt S] [--substeps N] [--threads N] [--max-memory B]\n"
               "                  [--max-work N]\n"
               "  Runs the scene in a window with a panel beside it: the thesis's simulator console\n"
               "  for the explosion thesis's scenes, the inspector (every section's live keys) for\n"
               "  the others.  Every control changes the running scene (iskra keys lists what each\n"
               "  key accepts).\n"
               "  mouse: a click on the canvas sets off the chosen explosion or adds a potential;\n"
               "        a potential's disc is picked and dragged\n"
               "  fields: a click selects the value, so what is typed replaces it; Ctrl+A and a double\n"
               "        click select all; Return, Tab or a click elsewhere apply, Esc goes back\n"
               "  keys (each button's is written on it; F2 saves to iskra-SCENE.ini or --save,\n"
               "  F12 / F11 write iskra-SCENE-FRAME.png / -window.png):\n");
    play_keys_help(f);
    fprintf(f,
               "  --frames N       quit after N shown frames (for scripts and tests)\n"
               "  --fixed-clock    every shown frame is one step of the scene's dt, as fast as the\n"
               "                   machine can: the same --script gives the same pixels (tests)\n"
               "  --ui-scale N     size of the panel, 1..4 (default: the largest that fits the screen,\n"
               "                   with text at least 10 px tall from 1280x720 up)\n"
               "  --screen WxH     lay the window out for a screen of this size (default: the display's)\n"
               "  --panel KIND     console or inspector (default: console for scenes with a layer or\n"
               "                   potentials, inspector for the others)\n"
               "  --no-panel       start with the panel hidden (Tab shows it)\n"
               "  --list-widgets   print the name of every widget (for press:NAME) and exit; no window\n"
               "  --follow EMITTER the stream emitter goes where the mouse is over the canvas; the\n"
               "                   births of each step spread along its way (no gaps)\n"
               "  --save PATH      where F2 writes the scene (default iskra-SCENE.ini)\n"
               "  --shots DIR      where F12 / F11 screenshots go, created if missing (default:\n"
               "                   the current directory)\n");
    play_script_help(f);
    scene_args_help(f);
    fprintf(f, "  exit status: 0 success, 1 no window (no display) or runtime failure, 2 usage or scene error\n");
}

/* The scene's short name: file name without directory and ".ini". */
static void scene_name(const char *scene, char *out, size_t n)
{
    const char *b = strrchr(scene, '/');
    b = b ? b + 1 : scene;
    snprintf(out, n, "%s", b);
    size_t len = strlen(out);
    if (len > 4 && !strcmp(out + len - 4, ".ini"))
        out[len - 4] = 0;
}

static int frame(void *user, isk_canvas *canvas, double dt_seconds, const isk_event *ev, int nev)
{
    (void)canvas; /* the player's p->shown: the same canvas, resized in place when the panel comes and goes */
    return play_frame(user, dt_seconds, ev, nev);
}

static isk_status window_resize(void *user, int w, int h, isk_error *err)
{
    return isk_window_resize_canvas(user, w, h, err);
}

static isk_status window_push_event(void *user, const isk_event *ev)
{
    return isk_window_push_event(user, ev);
}

/* "WxH" into *w, *h (each 320..16384); 0 and a message when it is not. */
static int parse_screen(const char *v, int *w, int *h)
{
    int used = 0;
    if (sscanf(v, "%dx%d%n", w, h, &used) == 2 && !v[used] && *w >= 320 && *h >= 200 && *w <= 16384 && *h <= 16384)
        return 1;
    fprintf(stderr, "iskra play: --screen: expected WIDTHxHEIGHT, e.g. 1280x720 (320x200 and up), got \"%s\"\n", v);
    return 0;
}

static void print_name(void *user, const char *name)
{
    (void)user;
    printf("%s\n", name);
}

/* --list-widgets: one frame of the panel drawn off screen, then every name. */
static int list_widgets(player *p)
{
    const isk_effect_def *d = isk_effect_definition(p->fx);
    isk_canvas shown;
    play_layout_compute(p);
    if (isk_canvas_init(&shown, p->lay.window.w, p->lay.window.h) != ISK_OK) {
        fprintf(stderr, "iskra play: out of memory\n");
        return 1;
    }
    (void)d;
    p->shown = &shown;
    play_begin_scene(p);
    isk_ui_begin(&p->ui, p->shown);
    play_panel(p);
    play_canvas(p);
    isk_ui_end(&p->ui);
    play_widget_names(p, print_name, NULL);
    isk_canvas_free(&shown);
    return 0;
}

int cmd_play(int argc, char **argv)
{
    static player p; /* large (the widget layer's state): not on the stack */
    memset(&p, 0, sizeof p);
    p.args.cmd = "play";
    long max_frames = 0, ui_scale = 0;
    const char *script = NULL, *panel_kind = NULL;
    int no_panel = 0, rc, list = 0, screen_given = 0;
    p.insp.section = -1; /* none yet: the first emitter once the scene is loaded */
    for (int i = 1; i < argc; i++) {
        const char *v;
        int r;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help(stdout);
            return 0;
        }
        if (!strcmp(argv[i], "--fixed-clock")) {
            p.fixed_clock = 1;
        } else if (!strcmp(argv[i], "--no-panel")) {
            no_panel = 1;
        } else if (!strcmp(argv[i], "--list-widgets")) {
            list = 1;
        } else if ((r = arg_value("play", argc, argv, &i, "--screen", &v)) != 0) {
            if (r < 0 || !parse_screen(v, &p.screen_w, &p.screen_h))
                return 2;
            screen_given = 1;
        } else if ((r = arg_value("play", argc, argv, &i, "--panel", &v)) != 0) {
            if (r < 0)
                return 2;
            if (strcmp(v, "console") && strcmp(v, "inspector")) {
                fprintf(stderr, "iskra play: --panel: expected console or inspector, got \"%s\"\n", v);
                return 2;
            }
            panel_kind = v;
        } else if ((r = arg_value("play", argc, argv, &i, "--frames", &v)) != 0) {
            if (r < 0 || !arg_long("play", "--frames", v, 1, 1000000000, &max_frames))
                return 2;
        } else if ((r = arg_value("play", argc, argv, &i, "--ui-scale", &v)) != 0) {
            if (r < 0 || !arg_long("play", "--ui-scale", v, 1, 4, &ui_scale))
                return 2;
        } else if ((r = arg_value("play", argc, argv, &i, "--save", &v)) != 0) {
            if (r < 0)
                return 2;
            if (!*v) {
                fprintf(stderr, "iskra play: --save needs a file name\n");
                return 2;
            }
            p.save_to = v;
        } else if ((r = arg_value("play", argc, argv, &i, "--shots", &v)) != 0) {
            if (r < 0)
                return 2;
            if (!*v) {
                fprintf(stderr, "iskra play: --shots needs a directory\n");
                return 2;
            }
            if (strlen(v) > 4000) {
                fprintf(stderr, "iskra play: --shots: directory name too long\n");
                return 2;
            }
            p.shots = v;
        } else if ((r = arg_value("play", argc, argv, &i, "--follow", &v)) != 0) {
            if (r < 0)
                return 2;
            p.follow = v;
        } else if ((r = arg_value("play", argc, argv, &i, "--script", &v)) != 0) {
            if (r < 0)
                return 2;
            script = v;
        } else if (scene_args_take(&p.args, argc, argv, &i) < 0) {
            return 2;
        }
    }
    if (!p.args.scene) {
        help(stderr);
        return 2;
    }
    if (script && (rc = play_script_parse(&p.script, script)) != 0) {
        play_script_free(&p.script);
        return rc;
    }
    isk_effect_def def;
    rc = scene_args_open(&p.args, &def, &p.fx);
    if (rc) {
        play_script_free(&p.script);
        return rc;
    }
    /* Save never writes over what the simulator reads (outpath.h). */
    outpath_plan plan = {.cmd = "play"};
    outpath_output(&plan, p.save_to, "--save");
    rc = outpath_refuse(&plan, p.args.text ? NULL : p.args.scene, "the scene") ? 2 : 0;
    for (int i = 0; !rc && i < def.ntextures; i++)
        rc = outpath_refuse(&plan, def.textures[i].name, "a texture of the scene") ? 2 : 0;
    isk_effect_def_free(&def);
    if (rc) {
        isk_effect_destroy(p.fx);
        play_script_free(&p.script);
        return rc;
    }
    if (p.follow) {
        const isk_effect_def *fd = isk_effect_definition(p.fx);
        int k = isk_effect_def_find_emitter(fd, p.follow);
        if (k < 0 || fd->emitters[k].born.source != ISK_SOURCE_STREAM) {
            fprintf(stderr, "iskra play: --follow %s: %s\n", p.follow,
                    k < 0 ? "no emitter of that name" : "not a stream emitter (only a stream's position is live)");
            isk_effect_destroy(p.fx);
            play_script_free(&p.script);
            return 2;
        }
    }
    struct stat st;
    p.path = stat(p.args.scene, &st) == 0 && S_ISREG(st.st_mode) ? p.args.scene : NULL;
    play_remember_file(&p);
    scene_name(p.args.scene, p.name, sizeof p.name);
    p.panel = !no_panel;
    p.hud = 1;
    const isk_effect_def *d = isk_effect_definition(p.fx);
    p.panel_kind = panel_kind ? (!strcmp(panel_kind, "console") ? PLAY_PANEL_CONSOLE : PLAY_PANEL_INSPECTOR)
                              : play_panel_for(d);
    isk_canvas shown = {0};
    isk_error err;
    rc = 1;
    if (isk_canvas_init(&p.sim, d->width, d->height) != ISK_OK || isk_effect_run(p.fx, &p.sim, 0) != ISK_OK) {
        fprintf(stderr, "iskra play: cannot draw the scene (out of memory?)\n");
        goto out;
    }
    isk_ui_init(&p.ui, 1);
    if (list) {
        if (!screen_given) { /* the layout does not change the names; a classroom's screen */
            p.screen_w = 1366;
            p.screen_h = 768;
        }
        p.panel = 1;
        play_choose_layout(&p, (int)ui_scale);
        rc = list_widgets(&p);
        goto out;
    }
    char title[128];
    snprintf(title, sizeof title, "iskra: %s", p.name);
    isk_window *win = NULL;
    if (isk_window_open(&win, title, d->width, d->height, &err) != ISK_OK) {
        fprintf(stderr, "iskra play: cannot open a window: %s\n", err.message);
        goto out;
    }
    char cwd[4096];
    fprintf(stderr, "iskra play: F12 screenshots go to %s\n",
            p.shots ? p.shots : getcwd(cwd, sizeof cwd) ? cwd : "the current directory");
    p.host = (play_host){win, window_resize, window_push_event, NULL};
    isk_window_set_escape_quits(win, 0); /* Escape cancels an edit; outside a field it quits */
    isk_window_set_pacing(win, !p.fixed_clock); /* a fixed clock runs as fast as it can */
    if (!screen_given && isk_window_display_size(win, &p.screen_w, &p.screen_h) != ISK_OK) {
        p.screen_w = 1280; /* SDL cannot tell: the smallest screen a classroom has */
        p.screen_h = 720;
    }
    play_choose_layout(&p, (int)ui_scale);
    play_layout_compute(&p);
    const int w = p.lay.window.w, h = p.lay.window.h;
    if (isk_canvas_init(&shown, w, h) != ISK_OK) {
        fprintf(stderr, "iskra play: out of memory (a %dx%d window)\n", w, h);
        goto out;
    }
    if (isk_window_resize_canvas(win, w, h, &err) != ISK_OK) {
        fprintf(stderr, "iskra play: cannot size the window: %s\n", err.message);
        goto out;
    }
    p.shown = &shown;
    {
        const isk_font_metrics *fm = isk_font_metrics_of(p.ui.font);
        fprintf(stderr, "iskra play: a %dx%d window for a %dx%d screen: the %s, text %d px tall\n", w, h, p.screen_w,
                p.screen_h,
                p.panel_kind == PLAY_PANEL_INSPECTOR ? "inspector"
                : p.arrangement == PLAY_COMPACT      ? "console in columns"
                                                     : "console",
                fm->cap_h * p.ui.scale);
    }
    play_begin_scene(&p);
    if (isk_window_run(win, &shown, frame, &p, max_frames, &err) != ISK_OK)
        fprintf(stderr, "iskra play: window: %s\n", err.message);
    else
        rc = p.failed ? 1 : 0;
out:
    isk_window_close(p.host.user);
    isk_canvas_free(&shown);
    isk_canvas_free(&p.sim);
    isk_canvas_free(&p.chart_cache);
    isk_effect_destroy(p.fx);
    play_script_free(&p.script);
    return rc;
}
