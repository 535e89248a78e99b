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
 * SDL_VIDEODRIVER=dummy runs it headless on purpose.
 *
 * Lessons (lesson.h): --record writes the session's input, frame by frame,
 * as it reaches the simulator (the recorder sits between the window's
 * events and play_frame); --replay plays a lesson back through the
 * window's queue, as --script does. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cmd.h"
#include "iskra/limits.h"
#include "iskra/png.h"
#include "iskra/sdl.h"
#include "lesson.h"
#include "outpath.h"
#include "play.h"
#include "play_cli.h"
#include "play_shadow.h"
#include "scene_args.h"

void play_cli_help(FILE *f)
{
    fprintf(f, "usage: iskra play SCENE [--frames N] [--fixed-clock] [--script EVENTS] [--list-widgets]\n"
               "                  [--ui-scale N] [--screen WxH] [--panel console|inspector] [--no-panel]\n"
               "                  [--save PATH] [--shots DIR] [--follow EMITTER] [--seed N] [--size WxH]\n"
               "                  [--dt S] [--substeps N] [--threads N] [--max-memory B]\n"
               "                  [--max-work N] [--record LESSON] [--shadow] [--shadow-factor N]\n"
               "       iskra play --replay LESSON [--frames N] [--fixed-clock] [--shots DIR]\n"
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
               "                   the current directory); with --replay, the lesson's shots too\n"
               "  --record LESSON  write every input with its frame number to LESSON (the --script\n"
               "                   format; written whole at each checkpoint, every 600 frames and at\n"
               "                   the end); one step per shown frame, as with --fixed-clock but at\n"
               "                   about 60 frames a second; F9 marks a checkpoint (shot:checkpoint-N)\n"
               "  --replay LESSON  show a recorded lesson again, frame by frame; its shots are\n"
               "                   written as DIR/NAME.png with --shots DIR (iskra replay checks them)\n"
               "  --shadow         start with the shadow run on (G toggles it): a copy of the scene\n"
               "                   stepped with yoshida4 (rk4 where forces are not smooth) at 16x the\n"
               "                   substeps; each particle's error shows as a ghost, with a chart\n"
               "  --shadow-factor N the shadow's substeps per the scene's, 1..1000 (default 16)\n");
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

/* The window's session: the player and, with --record, the recorder. */
typedef struct play_session {
    player *p;
    lesson_recorder *rec;
} play_session;

static int frame(void *user, isk_canvas *canvas, double dt_seconds, const isk_event *ev, int nev)
{
    play_session *ses = user;
    (void)canvas; /* the player's p->shown: the same canvas, resized in place when the panel comes and goes */
    if (!ses->rec)
        return play_frame(ses->p, dt_seconds, ev, nev);
    isk_event mine[64];
    int n = nev < 64 ? nev : 64; /* the window gives at most 64 a frame */
    memcpy(mine, ev, (size_t)n * sizeof *ev);
    lesson_record_frame(ses->rec, ses->p->frames_shown, mine, &n);
    return play_frame(ses->p, dt_seconds, mine, n);
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

/* Marks argv[from..to] (an option and its value) as not for a lesson. */
static void skip_args(int *skip, int from, int to)
{
    for (int k = from; skip && k <= to; k++)
        skip[k] = 1;
}

int play_cli_options(player *p, play_opts *o, int argc, char **argv, int *skip)
{
    memset(o, 0, sizeof *o);
    p->args.cmd = "play";
    p->insp.section = -1; /* none yet: the first emitter once the scene is loaded */
    for (int i = 1; i < argc; i++) {
        const char *v;
        const int at = i;
        int r;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            play_cli_help(stdout);
            return -1;
        }
        if (!strcmp(argv[i], "--fixed-clock")) {
            o->fixed_clock = 1;
            skip_args(skip, at, i);
        } else if (!strcmp(argv[i], "--shadow")) {
            p->shadow_wanted = 1;
        } else if ((r = arg_value("play", argc, argv, &i, "--shadow-factor", &v)) != 0) {
            long factor;
            if (r < 0 || !arg_long("play", "--shadow-factor", v, 1, ISK_SUBSTEPS_MAX, &factor))
                return 2;
            p->shadow_factor = (int)factor;
        } else if (!strcmp(argv[i], "--no-panel")) {
            o->no_panel = 1;
        } else if (!strcmp(argv[i], "--list-widgets")) {
            o->list = 1;
        } else if ((r = arg_value("play", argc, argv, &i, "--screen", &v)) != 0) {
            if (r < 0 || !parse_screen(v, &p->screen_w, &p->screen_h))
                return 2;
            o->screen_given = 1;
        } else if ((r = arg_value("play", argc, argv, &i, "--panel", &v)) != 0) {
            if (r < 0)
                return 2;
            if (strcmp(v, "console") && strcmp(v, "inspector")) {
                fprintf(stderr, "iskra play: --panel: expected console or inspector, got \"%s\"\n", v);
                return 2;
            }
            o->panel_kind = v;
        } else if ((r = arg_value("play", argc, argv, &i, "--frames", &v)) != 0) {
            if (r < 0 || !arg_long("play", "--frames", v, 1, 1000000000, &o->max_frames))
                return 2;
            skip_args(skip, at, i);
        } else if ((r = arg_value("play", argc, argv, &i, "--ui-scale", &v)) != 0) {
            if (r < 0 || !arg_long("play", "--ui-scale", v, 1, 4, &o->ui_scale))
                return 2;
        } else if ((r = arg_value("play", argc, argv, &i, "--save", &v)) != 0) {
            if (r < 0)
                return 2;
            if (!*v) {
                fprintf(stderr, "iskra play: --save needs a file name\n");
                return 2;
            }
            p->save_to = v;
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
            p->shots = v;
        } else if ((r = arg_value("play", argc, argv, &i, "--follow", &v)) != 0) {
            if (r < 0)
                return 2;
            p->follow = v;
        } else if ((r = arg_value("play", argc, argv, &i, "--script", &v)) != 0) {
            if (r < 0)
                return 2;
            o->script = v;
            skip_args(skip, at, i);
        } else if ((r = arg_value("play", argc, argv, &i, "--record", &v)) != 0) {
            if (r < 0)
                return 2;
            if (!*v) {
                fprintf(stderr, "iskra play: --record needs a file name\n");
                return 2;
            }
            o->record = v;
            skip_args(skip, at, i);
        } else if ((r = arg_value("play", argc, argv, &i, "--replay", &v)) != 0) {
            if (r < 0)
                return 2;
            o->replay = v;
        } else if (scene_args_take(&p->args, argc, argv, &i) < 0) {
            return 2;
        }
    }
    return 0;
}

int play_cli_lesson(player *p, play_opts *o, lesson *l, const char *path)
{
    int rc = lesson_load(l, path);
    if (rc)
        return rc;
    rc = play_cli_options(p, o, l->argc, l->argv, NULL);
    if (rc) {
        if (rc < 0) /* --help in a lesson */
            fprintf(stderr, "%s:%d: --help is not a lesson's option\n", path, l->args_line);
        else
            fprintf(stderr, "%s:%d: in the play: line (iskra play --help lists the options)\n", path, l->args_line);
        return 2;
    }
    const char *bad = o->record   ? "--record"
                    : o->replay ? "--replay"
                    : o->script ? "--script"
                    : o->list   ? "--list-widgets"
                    : !p->args.scene ? "no scene"
                                     : NULL;
    if (bad) {
        fprintf(stderr, "%s:%d: a lesson's play: line cannot have %s\n", path, l->args_line, bad);
        return 2;
    }
    if (!o->screen_given) {
        p->screen_w = PLAY_LESSON_SCREEN_W;
        p->screen_h = PLAY_LESSON_SCREEN_H;
        o->screen_given = 1;
    }
    o->fixed_clock = 1; /* one step per shown frame, as recorded */
    return play_script_parse_lesson(&p->script, l->events, path, l->events_line);
}

int play_cli_open(player *p, const play_opts *o, outpath_plan *plan, const char *lesson_path)
{
    if (o->script && !p->script.text) {
        int rc = play_script_parse(&p->script, o->script);
        if (rc) {
            play_script_free(&p->script);
            return rc;
        }
    }
    isk_effect_def def;
    int rc = scene_args_open(&p->args, &def, &p->fx);
    if (rc) {
        play_script_free(&p->script);
        return rc;
    }
    /* Nothing is written over what the simulator reads (outpath.h). */
    rc = outpath_clash(plan) ? 2 : 0;
    if (!rc)
        rc = outpath_refuse(plan, p->args.text ? NULL : p->args.scene, "the scene") ? 2 : 0;
    if (!rc && lesson_path)
        rc = outpath_refuse(plan, lesson_path, "the lesson") ? 2 : 0;
    for (int i = 0; !rc && i < def.ntextures; i++)
        rc = outpath_refuse(plan, def.textures[i].name, "a texture of the scene") ? 2 : 0;
    isk_effect_def_free(&def);
    if (!rc && p->follow) {
        const isk_effect_def *fd = isk_effect_definition(p->fx);
        int k = isk_effect_def_find_emitter(fd, p->follow);
        if (k < 0 || fd->emitters[k].born.source != ISK_SOURCE_STREAM) {
            fprintf(stderr, "iskra play: --follow %s: %s\n", p->follow,
                    k < 0 ? "no emitter of that name" : "not a stream emitter (only a stream's position is live)");
            rc = 2;
        }
    }
    if (rc) {
        play_cli_close(p);
        return rc;
    }
    struct stat st;
    p->path = p->args.text == NULL && stat(p->args.scene, &st) == 0 && S_ISREG(st.st_mode) ? p->args.scene : NULL;
    play_remember_file(p);
    scene_name(p->args.scene, p->name, sizeof p->name);
    p->panel = !o->no_panel;
    p->hud = 1;
    p->fixed_clock = o->fixed_clock;
    const isk_effect_def *d = isk_effect_definition(p->fx);
    p->panel_kind = o->panel_kind ? (!strcmp(o->panel_kind, "console") ? PLAY_PANEL_CONSOLE : PLAY_PANEL_INSPECTOR)
                                  : play_panel_for(d);
    if (isk_canvas_init(&p->sim, d->width, d->height) != ISK_OK || isk_effect_run(p->fx, &p->sim, 0) != ISK_OK) {
        fprintf(stderr, "iskra play: cannot draw the scene (out of memory?)\n");
        play_cli_close(p);
        return 1;
    }
    isk_ui_init(&p->ui, 1);
    return 0;
}

void play_cli_close(player *p)
{
    play_shadow_report(p, stderr); /* while the scene is there to say its frame */
    isk_canvas_free(&p->sim);
    isk_canvas_free(&p->chart_cache);
    isk_effect_destroy(p->fx);
    p->fx = NULL;
    play_script_free(&p->script);
    isk_timeline_destroy(p->timeline);
    p->timeline = NULL;
    play_shadow_free(p);
}

/* --replay: a lesson's shot:NAME into --shots DIR as NAME.png, saying
 * nothing in the window (the recording showed nothing there either). */
static void replay_shot(player *p, void *user, const char *name, int whole_window)
{
    const char *lesson_path = user;
    if (!p->shots)
        return;
    char path[4200];
    snprintf(path, sizeof path, "%s/%s.png", p->shots, name);
    isk_error err;
    if (outpath_refuse_input("play", path, lesson_path) || outpath_make_dirs("play", p->shots))
        return;
    if (isk_png_write(whole_window ? p->shown : &p->sim, path, &err) != ISK_OK)
        fprintf(stderr, "iskra play: %s\n", err.message);
    else
        fprintf(stderr, "iskra play: %s after frame %ld\n", path, p->frames_shown);
}

/* --replay LESSON: only --frames, --fixed-clock and --shots beside it; the
 * rest comes from the lesson. */
static int replay_options(player *p, play_opts *o, lesson *l, int argc, char **argv, int *unpaced)
{
    long max_frames = 0;
    int fixed = 0;
    const char *shots = NULL, *path = NULL;
    for (int i = 1; i < argc; i++) {
        const char *v;
        int r;
        if (!strcmp(argv[i], "--fixed-clock")) {
            fixed = 1;
        } else if ((r = arg_value("play", argc, argv, &i, "--frames", &v)) != 0) {
            if (r < 0 || !arg_long("play", "--frames", v, 1, 1000000000, &max_frames))
                return 2;
        } else if ((r = arg_value("play", argc, argv, &i, "--shots", &v)) != 0) {
            if (r < 0)
                return 2;
            if (!*v || strlen(v) > 4000) {
                fprintf(stderr, "iskra play: --shots needs a directory (of a sensible length)\n");
                return 2;
            }
            shots = v;
        } else if ((r = arg_value("play", argc, argv, &i, "--replay", &v)) != 0) {
            if (r < 0)
                return 2;
            path = v;
        } else {
            fprintf(stderr, "iskra play: --replay takes the scene and its options from the lesson; beside it "
                            "only --frames, --fixed-clock and --shots (got \"%s\")\n", argv[i]);
            return 2;
        }
    }
    int rc = play_cli_lesson(p, o, l, path);
    if (rc)
        return rc;
    o->max_frames = max_frames;
    o->replay = path;
    p->shots = shots;
    p->script.shot = replay_shot;
    p->script.shot_user = (void *)path;
    *unpaced = fixed;
    return 0;
}

int cmd_play(int argc, char **argv)
{
    static player p; /* large (the widget layer's state): not on the stack */
    memset(&p, 0, sizeof p);
    play_opts o;
    lesson les = {0};
    lesson_recorder rec = {0};
    int *skip = calloc((size_t)argc + 1, sizeof *skip);
    if (!skip) {
        fprintf(stderr, "iskra play: out of memory\n");
        return 1;
    }
    int rc = play_cli_options(&p, &o, argc, argv, skip);
    int unpaced = rc == 0 && o.fixed_clock;
    if (rc == 0 && o.replay) {
        memset(&p, 0, sizeof p);
        rc = replay_options(&p, &o, &les, argc, argv, &unpaced);
    }
    if (rc) {
        free(skip);
        lesson_free(&les);
        play_script_free(&p.script);
        return rc < 0 ? 0 : rc;
    }
    if (!p.args.scene) {
        play_cli_help(stderr);
        free(skip);
        return 2;
    }
    if (o.record && (o.list || o.replay)) {
        fprintf(stderr, "iskra play: --record cannot go with %s\n", o.list ? "--list-widgets" : "--replay");
        free(skip);
        return 2;
    }
    if (o.record)
        o.fixed_clock = 1; /* one step per shown frame: the lesson replays to the same pixels */
    outpath_plan plan = {.cmd = "play"};
    outpath_output(&plan, p.save_to, "--save");
    outpath_output(&plan, o.record, "--record");
    rc = play_cli_open(&p, &o, &plan, o.replay);
    if (rc) {
        free(skip);
        lesson_free(&les);
        return rc;
    }
    isk_canvas shown = {0};
    isk_error err;
    const isk_effect_def *d = isk_effect_definition(p.fx);
    rc = 1;
    if (o.list) {
        if (!o.screen_given) { /* the layout does not change the names; a classroom's screen */
            p.screen_w = 1366;
            p.screen_h = 768;
        }
        p.panel = 1;
        play_choose_layout(&p, (int)o.ui_scale);
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
    /* A fixed clock runs as fast as it can; a lesson keeps about 60 frames a second. */
    isk_window_set_pacing(win, !unpaced);
    if (!o.screen_given && isk_window_display_size(win, &p.screen_w, &p.screen_h) != ISK_OK) {
        p.screen_w = 1280; /* SDL cannot tell: the smallest screen a classroom has */
        p.screen_h = 720;
    }
    if (o.record) {
        int r = lesson_record_begin(&rec, o.record, argc, argv, skip, p.screen_w, p.screen_h, o.screen_given);
        if (r) {
            rc = r;
            goto out;
        }
        fprintf(stderr, "iskra play: recording to %s (F9 marks a checkpoint)\n", o.record);
    }
    play_choose_layout(&p, (int)o.ui_scale);
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
    play_session ses = {&p, o.record ? &rec : NULL};
    if (play_script_start(&p) != 0)
        rc = 1;
    else if (isk_window_run(win, &shown, frame, &ses, o.max_frames, &err) != ISK_OK)
        fprintf(stderr, "iskra play: window: %s\n", err.message);
    else
        rc = p.failed ? 1 : 0;
    if (o.record) {
        if (lesson_record_save(&rec, p.frames_shown) != 0 || rec.failed)
            rc = 1;
        else
            fprintf(stderr, "iskra play: recorded %ld frames and %d checkpoint%s to %s\n", p.frames_shown,
                    rec.checkpoints, rec.checkpoints == 1 ? "" : "s", o.record);
    }
out:
    isk_window_close(p.host.user);
    isk_canvas_free(&shown);
    play_cli_close(&p);
    lesson_record_free(&rec);
    lesson_free(&les);
    free(skip);
    return rc;
}
