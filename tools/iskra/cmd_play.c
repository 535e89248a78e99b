/* iskra play SCENE — the scene in an SDL2 window, in real time.
 *
 * A fixed simulation step (the scene's dt) driven by the display's frame
 * clock through an accumulator (iskra/timestep.h): at most 5 steps per
 * displayed frame, the rest of a stall is dropped (no spiral of death).
 * Keys: space pause, R reset, + / - (also keypad, '=') substeps, F12
 * screenshot, H overlay; a left click runs the scene's [click] action at the
 * clicked world point.  The simulation draws into its own canvas (trail
 * scenes accumulate there); the window shows a copy with the overlay on top.
 * --frames N stops after N displayed frames (for tests, with
 * SDL_VIDEODRIVER=dummy no display is needed).  --shots DIR says where F12
 * screenshots go (default: the current directory; said on stderr). */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cmd.h"
#include "iskra/draw.h"
#include "iskra/effect.h"
#include "iskra/png.h"
#include "iskra/sdl.h"
#include "iskra/text.h"
#include "iskra/timestep.h"
#include "outpath.h"
#include "progress.h"
#include "scene_args.h"

#define MAX_STEPS_PER_FRAME 5
#define MAX_SUBSTEPS 1000

typedef struct player {
    isk_effect *fx;
    const isk_effect_def *def;
    isk_canvas sim;          /* what the effect draws (trails live here) */
    isk_timestep ts;
    int trails;
    int paused, overlay, substeps;
    int said_no_click;
    char name[64];           /* scene name for screenshots */
    const char *shots;       /* screenshot directory (NULL: the current one) */
    double fps, update_ms;   /* smoothed */
    long frames_shown;
    int failed;              /* 1: runtime failure */
} player;

static void help(FILE *f)
{
    fprintf(f, "usage: iskra play SCENE [--frames N] [--shots DIR] [--seed N] [--size WxH]\n"
               "                  [--dt S] [--substeps N]\n"
               "  Runs the scene in a window in real time (fixed time step).\n"
               "  keys: space pause/resume   R reset   + / - substeps   F12 screenshot\n"
               "        (iskra-SCENE-FRAME.png, see --shots)   H overlay   Esc quit\n"
               "  mouse: left click runs the scene's [click] action at that point\n"
               "  --frames N       quit after N displayed frames (for scripts and tests)\n"
               "  --shots DIR      where F12 screenshots go, created if missing (default:\n"
               "                   the current directory)\n"
               "  --script EVENTS  inject events at the start (for tests), space-separated:\n"
               "                   space r + - = kp+ kp- h f12 esc click:X,Y (canvas pixels)\n");
    scene_args_help(f);
    fprintf(f, "  exit status: 0 success, 1 no window or runtime failure, 2 usage or scene error\n");
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

static void screenshot(player *p)
{
    char path[4200];
    snprintf(path, sizeof path, "%s%siskra-%s-%06ld.png", p->shots ? p->shots : "", p->shots ? "/" : "",
             p->name, isk_effect_frame(p->fx));
    if (p->shots && outpath_make_dirs("play", p->shots))
        return;
    isk_error err;
    if (isk_png_write(&p->sim, path, &err) == ISK_OK)
        fprintf(stderr, "iskra play: saved %s\n", path);
    else
        fprintf(stderr, "iskra play: screenshot failed: %s\n", err.message);
}

static void reset(player *p)
{
    if (isk_effect_reset(p->fx) != ISK_OK || isk_effect_run(p->fx, &p->sim, 0) != ISK_OK)
        p->failed = 1;
    isk_timestep_reset(&p->ts);
}

static void set_substeps(player *p, int n)
{
    if (n < 1 || n > MAX_SUBSTEPS)
        return;
    if (isk_effect_set_substeps(p->fx, n) == ISK_OK)
        p->substeps = n;
}

static void draw_overlay(player *p, isk_canvas *c)
{
    char text[256];
    snprintf(text, sizeof text,
             "FPS %.0f  particles %zu  update %.2f ms/frame\nframe %ld  substeps %d%s\n"
             "space pause  R reset  +/- substeps  F12 shot  H hide",
             p->fps, isk_effect_particle_count(p->fx), p->update_ms, isk_effect_frame(p->fx), p->substeps,
             p->paused ? "  PAUSED" : "");
    int scale = c->width >= 640 ? 2 : 1;
    int w = isk_text_width(text, scale), h = isk_text_height(text, scale);
    isk_fill_rect(c, 4, 4, w + 8, h + 6, isk_rgba(0, 0, 0, 160), ISK_BLEND_OVER);
    isk_draw_text(c, 8, 7, text, scale, ISK_WHITE, ISK_BLEND_OVER);
}

/* Pushes the --script events; 0 on success, 2 on a bad script. */
static int push_script(isk_window *w, const char *script)
{
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", script);
    for (char *tok = strtok(buf, " "); tok; tok = strtok(NULL, " ")) {
        isk_event ev;
        memset(&ev, 0, sizeof ev);
        ev.type = ISK_EVENT_KEY_DOWN;
        int x, y, used = 0;
        if (sscanf(tok, "click:%d,%d%n", &x, &y, &used) == 2 && !tok[used]) {
            ev.type = ISK_EVENT_MOUSE_DOWN;
            ev.button = 1;
            ev.x = x;
            ev.y = y;
        } else if (!strcmp(tok, "space")) ev.key = ' ';
        else if (!strcmp(tok, "kp+")) ev.key = ISK_KEY_KP_PLUS;
        else if (!strcmp(tok, "kp-")) ev.key = ISK_KEY_KP_MINUS;
        else if (!strcmp(tok, "f12")) ev.key = ISK_KEY_F12;
        else if (!strcmp(tok, "esc")) ev.key = ISK_KEY_ESCAPE;
        else if (strlen(tok) == 1 && strchr("rh+-=", tok[0])) ev.key = tok[0];
        else {
            fprintf(stderr, "iskra play: --script: unknown event '%s'\n", tok);
            return 2;
        }
        if (isk_window_push_event(w, &ev) != ISK_OK) {
            fprintf(stderr, "iskra play: --script: cannot queue '%s'\n", tok);
            return 1;
        }
    }
    return 0;
}

static int frame(void *user, isk_canvas *canvas, double dt_seconds, const isk_event *ev, int nev)
{
    player *p = user;
    for (int i = 0; i < nev; i++) {
        if (ev[i].type == ISK_EVENT_KEY_DOWN) {
            switch (ev[i].key) {
            case ' ':
                p->paused = !p->paused;
                isk_timestep_reset(&p->ts);
                break;
            case 'r': reset(p); break;
            case '+': case '=': case ISK_KEY_KP_PLUS: set_substeps(p, p->substeps + 1); break;
            case '-': case ISK_KEY_KP_MINUS: set_substeps(p, p->substeps - 1); break;
            case 'h': p->overlay = !p->overlay; break;
            case ISK_KEY_F12: screenshot(p); break;
            default: break;
            }
        } else if (ev[i].type == ISK_EVENT_MOUSE_DOWN && ev[i].button == 1) {
            if (!p->def->click.enabled) {
                if (!p->said_no_click)
                    fprintf(stderr, "iskra play: this scene has no [click] action\n");
                p->said_no_click = 1;
                continue;
            }
            double x, y;
            isk_view_to_world(isk_effect_view(p->fx), ev[i].x + 0.5, ev[i].y + 0.5, &x, &y);
            isk_status s = isk_effect_click(p->fx, x, y);
            if (s != ISK_OK)
                fprintf(stderr, "iskra play: click: %s\n", isk_status_str(s));
        }
    }
    if (p->failed)
        return 1;

    int steps = p->paused ? 0 : isk_timestep_advance(&p->ts, dt_seconds);
    double t0 = progress_now();
    for (int i = 0; i < steps; i++) {
        isk_status s = p->trails ? isk_effect_step_render(p->fx, &p->sim) : isk_effect_step(p->fx);
        if (s != ISK_OK) {
            fprintf(stderr, "iskra play: frame %ld: %s\n", isk_effect_frame(p->fx), isk_status_str(s));
            p->failed = 1;
            return 1;
        }
    }
    double t1 = progress_now();
    if (steps > 0)
        p->update_ms = 0.9 * p->update_ms + 0.1 * (t1 - t0) * 1000.0 / steps;
    if (!p->trails && isk_effect_render(p->fx, &p->sim) != ISK_OK) {
        p->failed = 1;
        return 1;
    }
    if (dt_seconds > 0)
        p->fps = p->fps > 0 ? 0.9 * p->fps + 0.1 / dt_seconds : 1.0 / dt_seconds;

    /* the window shows a copy: the overlay never lands in the simulation's canvas */
    for (int y = 0; y < canvas->height; y++)
        memcpy(canvas->pixels + (size_t)y * canvas->stride, p->sim.pixels + (size_t)y * p->sim.stride,
               (size_t)canvas->width * 4);
    if (p->overlay)
        draw_overlay(p, canvas);
    p->frames_shown++;
    return 0;
}

int cmd_play(int argc, char **argv)
{
    scene_args a = {.cmd = "play"};
    long max_frames = 0;
    const char *script = NULL, *shots = NULL;
    for (int i = 1; i < argc; i++) {
        const char *v;
        int r;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help(stdout);
            return 0;
        }
        if ((r = arg_value("play", argc, argv, &i, "--frames", &v)) != 0) {
            if (r < 0 || !arg_long("play", "--frames", v, 1, 1000000000, &max_frames))
                return 2;
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
            shots = v;
        } else if ((r = arg_value("play", argc, argv, &i, "--script", &v)) != 0) {
            if (r < 0)
                return 2;
            script = v;
        } else if (scene_args_take(&a, argc, argv, &i) < 0) {
            return 2;
        }
    }
    if (!a.scene) {
        help(stderr);
        return 2;
    }
    isk_effect_def def;
    player p;
    memset(&p, 0, sizeof p);
    int rc = scene_args_open(&a, &def, &p.fx);
    if (rc)
        return rc;
    p.def = isk_effect_definition(p.fx);
    p.trails = !def.clear;
    p.overlay = 1;
    p.substeps = def.substeps;
    scene_name(a.scene, p.name, sizeof p.name);
    p.shots = shots;
    isk_canvas shown;
    isk_window *w = NULL;
    isk_error err;
    rc = 1;
    if (isk_timestep_init(&p.ts, def.dt, MAX_STEPS_PER_FRAME) != ISK_OK ||
        isk_canvas_init(&p.sim, def.width, def.height) != ISK_OK) {
        fprintf(stderr, "iskra play: out of memory\n");
        goto out_fx;
    }
    if (isk_canvas_init(&shown, def.width, def.height) != ISK_OK) {
        fprintf(stderr, "iskra play: out of memory\n");
        goto out_sim;
    }
    if (isk_effect_run(p.fx, &p.sim, 0) != ISK_OK) {
        fprintf(stderr, "iskra play: cannot draw the scene\n");
        goto out_shown;
    }
    char title[128];
    snprintf(title, sizeof title, "iskra: %s", p.name);
    if (isk_window_open(&w, title, def.width, def.height, &err) != ISK_OK) {
        fprintf(stderr, "iskra play: cannot open a window: %s\n", err.message);
        goto out_shown;
    }
    char cwd[4096];
    fprintf(stderr, "iskra play: F12 screenshots go to %s\n",
            shots ? shots : getcwd(cwd, sizeof cwd) ? cwd : "the current directory");
    if (script && (rc = push_script(w, script)) != 0) {
        isk_window_close(w);
        goto out_shown;
    }
    rc = 1;
    if (isk_window_run(w, &shown, frame, &p, max_frames, &err) != ISK_OK) {
        fprintf(stderr, "iskra play: window: %s\n", err.message);
    } else {
        rc = p.failed ? 1 : 0;
    }
    isk_window_close(w);
out_shown:
    isk_canvas_free(&shown);
out_sim:
    isk_canvas_free(&p.sim);
out_fx:
    isk_effect_destroy(p.fx);
    isk_effect_def_free(&def);
    return rc;
}
