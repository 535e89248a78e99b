/* SPDX-License-Identifier: MIT */
/* iskra render SCENE [--frames N] --out FILE.png
 * iskra render SCENE [--frames N] [--every K] [--fps F] --out FILE.gif|FILE.y4m
 * iskra render SCENE [--frames N] [--every K] --raw --out FILE|-
 * iskra render SCENE [--frames N] [--every K] --out-dir DIR [--resume]
 * iskra render SCENE --frames N --every K --strip FILE.png
 * iskra render SCENE --frames N --snapshot FILE.snap, then
 * iskra render SCENE --from FILE.snap --frames M ...
 * Renders frame N (frame 0 = the initial state, frame N = after N steps) to
 * a PNG, and/or frames 0, K, 2K, ... <= N as a numbered PNG sequence, an
 * animated GIF, a YUV4MPEG2 video or raw RGBA frames (render_out.h);
 * --state / --state-every write the particles as CSV (state_csv.h),
 * --probes the scene's probes, a row per frame (probes_csv.h);
 * --snapshot the exact state of frame N (iskra/snapshot.h), which --from
 * goes on from in another run: the same bytes as one run.
 * Everything is validated before anything is written, and no output may
 * be an input (the scene, its textures) or another output (outpath.h); a
 * signal removes the temporaries and says what was written (cleanup.h). */
#include <ctype.h>
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cleanup.h"
#include "cmd.h"
#include "iskra/anim.h"
#include "iskra/effect.h"
#include "iskra/png.h"
#include "iskra/scene.h"
#include "iskra/snapshot.h"
#include "outpath.h"
#include "probes_csv.h"
#include "progress.h"
#include "render_out.h"
#include "render_strip.h"
#include "scene_args.h"
#include "state_csv.h"

static void help(FILE *f)
{
    fprintf(f, "usage: iskra render SCENE [--frames N] --out FILE.png\n"
               "       iskra render SCENE [--frames N] [--every K] [--fps F] --out FILE.gif\n"
               "                    (or --out FILE.y4m)\n"
               "       iskra render SCENE [--frames N] [--every K] --raw --out FILE|-\n"
               "       iskra render SCENE [--frames N] [--every K] --out-dir DIR [--resume]\n"
               "       iskra render SCENE --frames N --every K --strip FILE.png\n"
               "       iskra render SCENE --frames N --snapshot FILE.snap\n"
               "       iskra render SCENE --from FILE.snap [--frames M] (any output above)\n"
               "  Renders frame N of the scene (0 = the initial state; N steps of dt).\n"
               "  --frames N       the last frame, 0..100000000 (default: the scene's\n"
               "                   [scene] frames, else 0)\n"
               "  --out FILE.png   write frame N there (any name but .gif/.y4m is a PNG)\n"
               "  --out FILE.gif   an animated GIF of frames 0, K, 2K, ... <= N (a palette\n"
               "                   per frame: exact up to 256 colours, else median cut)\n"
               "  --out FILE.y4m   the same frames as YUV4MPEG2 (ffmpeg, mpv, VLC)\n"
               "  --raw            the same frames as raw RGBA bytes, W*H*4 per frame, to\n"
               "                   --out FILE, or to stdout with --out - (for a pipe), e.g.\n"
               "                   iskra render fire_campfire --frames 600 --raw --out - |\n"
               "                     ffmpeg -f rawvideo -pixel_format rgba -video_size 480x400\n"
               "                     -framerate 60 -i - fire.mp4\n"
               "  --fps F          frames per second of a GIF or Y4M, 0.001..1000 (default\n"
               "                   1 / (dt * K): real time)\n"
               "  --out-dir DIR    write frames 0, K, 2K, ... <= N as DIR/frame_000000.png ...\n"
               "  --resume         with --out-dir: keep the frames already there (after an\n"
               "                   interrupted render; the simulation still runs from 0)\n"
               "  --strip FILE.png frames K, 2K, ... <= N side by side at half size, each\n"
               "                   labelled with its time (1..12 panels: frame 0 is left out)\n"
               "  --every K        sequence, animation and strip step, >= 1 (default 1)\n"
               "  --state FILE.csv every live particle at frame N: emitter,index,x,y,vx,vy,\n"
               "                   mass,age,life, values in round-trip precision (%%.17g)\n"
               "  --state-every K  with --out-dir: DIR/state_000000.csv ... every K frames\n"
               "  --probes FILE.csv the scene's probes ([probe NAME]) after every frame 1..N:\n"
               "                   frame,time, then PROBE.VALUE columns (%%.17g)\n"
               "  --snapshot FILE.snap  the whole running state at frame N, exact\n"
               "  --from FILE.snap the run goes on from a snapshot of the same SCENE and\n"
               "                   overrides (--snapshot) instead of frame 0: every output\n"
               "                   from its frame on has the bytes of one run (not with\n"
               "                   --strip, nor a scene that draws over its last frame)\n"
               "  Missing directories of every output are created.  An output that is an\n"
               "  input (the scene, a texture) or another output is refused.  Particles\n"
               "  removed because their state went non-finite are reported.\n");
    scene_args_help(f);
    fprintf(f, "  A progress bar appears on stderr when it is a terminal and the render\n"
               "  takes a while.  SIGINT, SIGTERM, SIGHUP or SIGPIPE removes the temporary\n"
               "  files, says which frames and states were written (or streamed) and exits\n"
               "  with 128 + the signal; a file size limit (ulimit -f) is a failed write.\n"
               "  A later run removes the temporaries that a killed one left.\n"
               "  exit status: 0 success, 1 cannot write, 2 usage or scene error\n");
}

typedef struct render_args {
    scene_args scene;
    const char *out;
    const char *strip;
    const char *snap_out; /* --snapshot */
    const char *from;     /* --from */
    long frames;     /* -1: the scene's */
    double fps;      /* 0: 1 / (dt * every) */
    int raw, have_every;
    render_out o;
    state_opts so;
    probes_opts po;
} render_args;

/* 0, or 2 after printing the usage error. */
static int parse(render_args *r, int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        const char *v;
        int k;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help(stdout);
            exit(0);
        }
        if (!strcmp(argv[i], "--raw")) {
            r->raw = 1;
        } else if (!strcmp(argv[i], "--resume")) {
            r->o.resume = 1;
        } else if ((k = arg_value("render", argc, argv, &i, "--frames", &v)) != 0) {
            if (k < 0 || !arg_long("render", "--frames", v, 0, 100000000, &r->frames))
                return 2;
        } else if ((k = arg_value("render", argc, argv, &i, "--every", &v)) != 0) {
            if (k < 0 || !arg_long("render", "--every", v, 1, 100000000, &r->o.every))
                return 2;
            r->have_every = 1;
        } else if ((k = arg_value("render", argc, argv, &i, "--fps", &v)) != 0) {
            if (k < 0 || !arg_double_pos("render", "--fps", v, &r->fps))
                return 2;
        } else if ((k = arg_value("render", argc, argv, &i, "--out-dir", &v)) != 0) {
            if (k < 0)
                return 2;
            r->o.dir = v;
        } else if ((k = arg_value("render", argc, argv, &i, "--strip", &v)) != 0) {
            if (k < 0)
                return 2;
            r->strip = v;
        } else if ((k = arg_value("render", argc, argv, &i, "--snapshot", &v)) != 0) {
            if (k < 0)
                return 2;
            r->snap_out = v;
        } else if ((k = arg_value("render", argc, argv, &i, "--from", &v)) != 0) {
            if (k < 0)
                return 2;
            r->from = v;
        } else if ((k = arg_value("render", argc, argv, &i, "--out", &v)) != 0) {
            if (k < 0)
                return 2;
            r->out = v;
        } else if ((k = state_args_take(&r->so, argc, argv, &i)) != 0) {
            if (k < 0)
                return 2;
        } else if ((k = probes_args_take(&r->po, argc, argv, &i)) != 0) {
            if (k < 0)
                return 2;
        } else if (scene_args_take(&r->scene, argc, argv, &i) < 0) {
            return 2;
        }
    }
    return 0;
}

/* The combinations; 0 or 2 after printing why. */
static int check(render_args *r)
{
    const char *why = NULL;
    if (!r->scene.scene)
        why = "which scene?";
    else if (!r->out && !r->o.dir && !r->so.path && !r->strip && !r->po.path && !r->snap_out)
        why = "say where: --out FILE (.png, .gif, .y4m; --raw), --out-dir DIR, --strip FILE.png, --state FILE.csv, "
              "--probes FILE.csv or --snapshot FILE.snap";
    else if ((r->out && !*r->out) || (r->o.dir && !*r->o.dir) || (r->strip && !*r->strip) ||
             (r->snap_out && !*r->snap_out) || (r->from && !*r->from))
        why = "empty file name";
    if (why) {
        fprintf(stderr, "iskra render: %s\n", why);
        help(stderr);
        return 2;
    }
    if (r->out && r->raw) {
        r->o.anim_path = r->out;
        r->o.anim_format = ISK_ANIM_RAW;
    } else if (r->out && isk_anim_format_of_path(r->out, &r->o.anim_format)) {
        r->o.anim_path = r->out;
    } else if (r->out && !strcmp(r->out, "-")) {
        why = "--out -: standard output takes raw frames (add --raw), or name a .png, .gif or .y4m file";
    } else {
        r->o.png = r->out;
    }
    if (!why && ((r->snap_out && !strcmp(r->snap_out, "-")) || (r->from && !strcmp(r->from, "-"))))
        why = "a snapshot is a file (--snapshot, --from), not standard input or output";
    else if (!why && r->raw && !r->out)
        why = "--raw needs --out FILE or --out -";
    else if (!why && r->have_every && !r->o.dir && !r->o.anim_path && !r->strip)
        why = "--every needs --out-dir, an animation (--out FILE.gif, FILE.y4m), --raw or --strip";
    else if (!why && r->fps > 0 && !(r->o.anim_path && r->o.anim_format != ISK_ANIM_RAW))
        why = "--fps is for --out FILE.gif or FILE.y4m (raw frames carry no rate)";
    else if (!why && r->o.resume && !r->o.dir)
        why = "--resume needs --out-dir";
    else if (!why && r->from && r->strip)
        why = "--from: a strip's panels start at frame 0; render the strip without --from";
    else if (!why && r->o.anim_path && !strcmp(r->o.anim_path, "-") && isatty(STDOUT_FILENO))
        why = "refusing to write raw frames to a terminal (pipe them, or --out FILE)";
    if (why) {
        fprintf(stderr, "iskra render: %s\n", why);
        return 2;
    }
    if (state_args_check(&r->so, r->o.dir))
        return 2;
    return 0;
}

/* Every output against the others, and against every input: the scene
 * file and the textures it names (as the loader resolved them).  0 or 2
 * after printing which.  Then the temporaries a killed run left beside
 * the outputs are removed. */
static int check_files(const render_args *r, const isk_effect_def *def, long frames)
{
    if (r->po.path && def->nprobes == 0) {
        fprintf(stderr, "iskra render: --probes: %s has no [probe NAME] section to write\n", r->scene.scene);
        return 2;
    }
    outpath_plan plan = {.cmd = "render"};
    outpath_output(&plan, r->out, "--out");
    outpath_output(&plan, r->strip, "--strip");
    outpath_output(&plan, r->so.path, "--state");
    outpath_output(&plan, r->po.path, "--probes");
    outpath_output(&plan, r->snap_out, "--snapshot");
    outpath_series(&plan, r->o.dir, RENDER_FRAME_PREFIX, RENDER_FRAME_SUFFIX, r->o.every, frames, "--out-dir");
    outpath_series(&plan, r->o.dir, STATE_PREFIX, STATE_SUFFIX, r->so.every, frames, "--state-every");
    if (outpath_clash(&plan) || outpath_refuse(&plan, r->scene.text ? NULL : r->scene.scene, "the scene") ||
        outpath_refuse(&plan, r->from, "the snapshot (--from)"))
        return 2;
    for (int i = 0; i < def->ntextures; i++)
        if (outpath_refuse(&plan, def->textures[i].name, "a texture of the scene"))
            return 2;
    outpath_remove_stale(&plan);
    return 0;
}

/* Frames per second for the animation: --fps, or real time.  0 or 2. */
static int choose_fps(render_args *r, double dt, double *fps)
{
    *fps = r->fps > 0 ? r->fps : 1.0 / (dt * (double)r->o.every);
    if (r->o.anim_path && r->o.anim_format != ISK_ANIM_RAW && !(*fps >= 0.001 && *fps <= 1000.0)) {
        if (r->fps > 0)
            fprintf(stderr, "iskra render: --fps: expected 0.001..1000, got %g\n", *fps);
        else
            fprintf(stderr, "iskra render: 1 / (dt * every) = %g frames per second is outside 0.001..1000; "
                            "give --fps\n", *fps);
        return 2;
    }
    return 0;
}

/* What this command holds beside the effect, counted in the memory budget
 * before anything is written (scene_args.host_needs): the animation's
 * encoder, the strip's canvas and the PNG writer of every PNG it writes. */
static void host_needs(isk_effect_def *def, const void *ctx)
{
    const render_args *r = ctx;
    const long frames = r->frames >= 0 ? r->frames : def->show.frames;
    double bytes = 0;
    char *what = def->host_memory_for;
    const size_t n = sizeof def->host_memory_for;
    size_t used = (size_t)snprintf(what, n, "iskra render's");
    int parts = 0;
    if (r->snap_out) {
        /* a copy of the state and its file's bytes: at most twice what
         * the effect holds */
        def->host_memory = 0;
        bytes += 2.0 * (double)isk_effect_def_memory(def);
        used += (size_t)snprintf(what + used, used < n ? n - used : 0, " snapshot");
        parts++;
    }
    if (r->o.anim_path) {
        isk_anim_opts ao = {r->o.anim_format, def->width, def->height, 1.0};
        bytes += (double)isk_anim_memory(&ao);
        char name[8];
        snprintf(name, sizeof name, "%s", isk_anim_format_name(r->o.anim_format));
        for (char *c = name; *c; c++)
            *c = (char)toupper((unsigned char)*c);
        used += (size_t)snprintf(what + used, used < n ? n - used : 0, "%s %s writer (%d x %d frames)",
                                 parts ? "," : "", name, def->width, def->height);
        parts++;
    }
    int sw, sh;
    if (r->strip && render_strip_size(def->width, def->height, frames, r->o.every, &sw, &sh)) {
        bytes += 4.0 * (double)sw * (double)sh + (double)isk_png_write_memory(sw);
        used += (size_t)snprintf(what + used, used < n ? n - used : 0, "%s strip (%d x %d)", parts ? "," : "", sw,
                                 sh);
        parts++;
    }
    if (r->o.png || r->o.dir) {
        bytes += (double)isk_png_write_memory(def->width);
        used += (size_t)snprintf(what + used, used < n ? n - used : 0, "%s PNG writer", parts ? "," : "");
        parts++;
    }
    def->host_memory = parts ? (bytes < (double)SIZE_MAX ? (size_t)bytes : SIZE_MAX) : 0;
    if (!parts)
        what[0] = 0;
}

/* The scene as text (free it), or NULL after printing why. */
static char *scene_text(const isk_effect_def *d)
{
    isk_error err = {0};
    char *text = NULL;
    if (isk_scene_write(d, &text, &err) != ISK_OK)
        fprintf(stderr, "iskra render: --from: %s\n", err.message);
    return text;
}

/* --from: the effect goes on from the snapshot, which must be of this
 * scene with these overrides (the definition it holds, written as scene
 * text, is the one SCENE gives): its frame becomes the first.  0, or the
 * exit status after printing why. */
static int resume_from(const render_args *r, const isk_effect_def *def, isk_effect *fx, long frames, long *first)
{
    *first = 0;
    if (!r->from)
        return 0;
    if (!def->clear) {
        fprintf(stderr, "iskra render: --from: %s draws each frame over the last (clear = false), and a snapshot "
                        "holds no canvas: render it from frame 0\n", r->scene.scene);
        return 2;
    }
    isk_error err = {0};
    isk_snapshot *snap = NULL;
    isk_status s = isk_snapshot_load(&snap, r->from, &err);
    if (s != ISK_OK) {
        fprintf(stderr, "iskra render: --from: %s\n", err.message);
        return s == ISK_ERR_NOMEM ? 1 : 2;
    }
    char *ours = scene_text(def), *theirs = NULL;
    int rc = ours ? 0 : 1;
    if (!rc && (s = isk_effect_restore(fx, snap, &err)) != ISK_OK) {
        fprintf(stderr, "iskra render: --from: %s: %s\n", r->from, err.message);
        rc = s == ISK_ERR_NOMEM ? 1 : 2;
    }
    if (!rc && !(theirs = scene_text(isk_effect_definition(fx))))
        rc = 1;
    if (!rc && strcmp(ours, theirs) != 0) {
        fprintf(stderr, "iskra render: --from: %s is a snapshot of another scene, or of other overrides (--seed, "
                        "--size, --dt, --substeps), than %s gives\n", r->from, r->scene.scene);
        rc = 2;
    }
    if (!rc && isk_snapshot_frame(snap) > frames) {
        fprintf(stderr, "iskra render: --from: %s is at frame %ld, after the last frame %ld (--frames)\n", r->from,
                isk_snapshot_frame(snap), frames);
        rc = 2;
    }
    if (!rc)
        *first = isk_snapshot_frame(snap);
    free(ours);
    free(theirs);
    isk_snapshot_free(snap);
    return rc;
}

/* --snapshot: the state of the last frame, whole or not at all.  0, or 1
 * after printing why. */
static int snapshot_write(const char *path, const isk_effect *fx)
{
    if (!path)
        return 0;
    isk_error err = {0};
    isk_snapshot *snap = NULL;
    unsigned char *bytes = NULL;
    size_t n = 0;
    if (isk_effect_snapshot(fx, &snap, &err) != ISK_OK || isk_snapshot_encode(snap, &bytes, &n, &err) != ISK_OK) {
        fprintf(stderr, "iskra render: --snapshot %s: %s\n", path, err.message);
        isk_snapshot_free(snap);
        return 1;
    }
    isk_snapshot_free(snap);
    isk_outfile o;
    int rc = outpath_make_parents("render", path) || cleanup_outfile_open(&o, path);
    if (!rc && fwrite(bytes, 1, n, o.f) != n) {
        const int e = errno ? errno : EIO;
        cleanup_outfile_abort(&o);
        fprintf(stderr, "iskra render: %s: write failed: %s\n", path, strerror(e));
        rc = 1;
    } else if (!rc) {
        rc = cleanup_outfile_commit(&o);
    }
    free(bytes);
    return rc;
}

int cmd_render(int argc, char **argv)
{
    render_args r;
    memset(&r, 0, sizeof r);
    r.scene.cmd = "render";
    r.frames = -1;
    r.o.every = 1;
    int rc = parse(&r, argc, argv);
    if (!rc)
        rc = check(&r);
    if (rc)
        return rc;

    isk_effect_def def;
    isk_effect *fx;
    r.scene.host_needs = host_needs;
    r.scene.host_ctx = &r;
    if ((rc = scene_args_open(&r.scene, &def, &fx)) != 0)
        return rc;
    long frames = r.frames >= 0 ? r.frames : def.show.frames;
    long first = 0;
    double fps;
    isk_canvas canvas = {0};
    render_strip strip = {0};
    if ((rc = check_files(&r, &def, frames)) != 0 || (rc = choose_fps(&r, def.dt, &fps)) != 0 ||
        (rc = resume_from(&r, &def, fx, frames, &first)) != 0)
        goto done;
    if (isk_canvas_init(&canvas, def.width, def.height) != ISK_OK) {
        fprintf(stderr, "iskra render: out of memory (a %dx%d canvas)\n", def.width, def.height);
        rc = 1;
        goto done;
    }
    if ((rc = render_strip_begin(&strip, r.strip, def.width, def.height, frames, r.o.every)) != 0 ||
        (r.strip && (rc = outpath_make_parents("render", r.strip)) != 0))
        goto done;
    cleanup_install("render");
    if ((rc = render_out_begin(&r.o, def.width, def.height, fps)) != 0 || (rc = probes_begin(&r.po, fx)) != 0)
        goto done;

    progress pg;
    progress_start(&pg, frames);
    /* Frame 0 is the initial state (with trails: the bare background); with
     * --from the snapshot's frame is the first.  A scene that clears is
     * drawn only when a frame is written; a trail scene is drawn after
     * every step, as isk_effect_run does. */
    int trails = !def.clear;
    isk_status s = isk_effect_run(fx, &canvas, 0);
    int drawn = 1;
    for (long f = first; s == ISK_OK; f++) {
        if (render_out_wants(&r.o, f) || render_strip_wants(&strip, f)) {
            if (!drawn && (s = isk_effect_render(fx, &canvas)) != ISK_OK)
                break;
            drawn = 1;
            if (render_strip_wants(&strip, f))
                render_strip_frame(&strip, &canvas, f, isk_effect_time(fx));
            if (render_out_frame(&r.o, &canvas, f)) {
                rc = 1;
                goto done;
            }
        }
        if (state_after_frame(&r.so, fx, r.o.dir, f) || probes_after_frame(&r.po, fx, f)) {
            rc = 1;
            goto done;
        }
        progress_update(&pg, f);
        if (f == frames)
            break;
        s = trails ? isk_effect_step_render(fx, &canvas) : isk_effect_step(fx);
        drawn = trails;
    }
    if (s == ISK_OK && !drawn)
        s = isk_effect_render(fx, &canvas);
    if (s != ISK_OK) {
        fprintf(stderr, "iskra render: %s: frame %ld: %s\n", r.scene.scene, isk_effect_frame(fx), isk_status_str(s));
        rc = 1;
        goto done;
    }
    progress_end(&pg);
    /* The files last, each whole; one that cannot be written (a full
     * disk, no memory) takes back those written before it, so a failed
     * run leaves none of them. */
    rc = render_strip_end(&strip);
    const int strip_written = !rc && r.strip;
    if (!rc)
        rc = state_finish(&r.so, fx);
    const int state_written = !rc && r.so.path;
    if (!rc)
        rc = probes_finish(&r.po);
    const int probes_written = !rc && r.po.path;
    if (!rc)
        rc = snapshot_write(r.snap_out, fx);
    const int snapshot_written = !rc && r.snap_out;
    if (!rc)
        rc = render_out_end(&r.o, &canvas);
    if (rc && strip_written)
        remove(r.strip);
    if (rc && state_written)
        remove(r.so.path);
    if (rc && probes_written)
        remove(r.po.path);
    if (rc && snapshot_written)
        remove(r.snap_out);
done:
    probes_abort(&r.po);
    isk_canvas_free(&strip.out);
    render_out_abort(&r.o);
    isk_canvas_free(&canvas);
    isk_effect_destroy(fx);
    isk_effect_def_free(&def);
    return rc;
}
