/* SPDX-License-Identifier: MIT */
/* iskra replay LESSON --check DIR [--update] — a recorded lesson (lesson.h)
 * as a pixel-exact test.
 *
 * The lesson is played headless, with no window and no SDL: the player
 * (play_frame) runs with a host whose event queue is a plain array, one
 * simulation step per frame, so it needs no display and gives the same
 * pixels as `iskra play --replay`.  At each shot:NAME the window (or, for
 * canvas-shot:NAME, the canvas) is compared exactly with DIR/NAME.png
 * through iskra/refimg.h; a mismatch names the shot, the first differing
 * pixel and how many differ, and leaves NAME.actual.png and NAME.diff.png
 * in the --actual directory.  The references are inputs: only --update
 * writes them.  F2, F11 and F12 in a lesson write nothing here. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd.h"
#include "iskra/png.h"
#include "iskra/refimg.h"
#include "lesson.h"
#include "outpath.h"
#include "play.h"
#include "play_cli.h"

#define REPLAY_FRAME_EVENTS 64 /* as the window: at most 64 events reach a frame, the rest the next */
#define REPLAY_DEFAULT_ACTUAL "iskra-replay-actual"

static void help(FILE *f)
{
    fprintf(f, "usage: iskra replay LESSON --check DIR [--update] [--actual DIR] [--frames N]\n"
               "  Replays a lesson recorded by iskra play --record with no window (no display needed)\n"
               "  and compares the window at each shot:NAME with DIR/NAME.png, pixel for pixel (a\n"
               "  canvas-shot:NAME compares the canvas alone).\n"
               "  --check DIR      the reference images\n"
               "  --update         write (or overwrite) the references from this replay instead\n"
               "  --actual DIR     where a mismatch leaves NAME.actual.png and NAME.diff.png\n"
               "                   (default " REPLAY_DEFAULT_ACTUAL ", created when needed)\n"
               "  --frames N       stop after N frames (default: where the lesson ends)\n"
               "  exit status: 0 every shot matches (or was written), 1 a shot differs, has no\n"
               "  reference or cannot be written, 2 usage error or a bad lesson (FILE:LINE)\n");
}

/* The headless host: events wait in a queue until the next frame. */
typedef struct replay_queue {
    isk_event *ev;
    int n, cap;
} replay_queue;

static isk_status queue_push(void *user, const isk_event *ev)
{
    replay_queue *q = user;
    if (q->n == q->cap) {
        int cap = q->cap ? q->cap * 2 : 256;
        isk_event *more = realloc(q->ev, (size_t)cap * sizeof *more);
        if (!more)
            return ISK_ERR_NOMEM;
        q->ev = more;
        q->cap = cap;
    }
    q->ev[q->n++] = *ev;
    return ISK_OK;
}

static isk_status no_resize(void *user, int w, int h, isk_error *err)
{
    (void)user, (void)w, (void)h, (void)err;
    return ISK_OK; /* the player resizes p->shown itself; there is no window to follow it */
}

static void discard_file(void *user, const char *name, const void *bytes, size_t n)
{
    (void)user, (void)name, (void)bytes, (void)n;
}

typedef struct replay_check {
    const char *dir, *actual, *lesson, *scene;
    int update;
    int shots, failed;
} replay_check;

/* The first pixel where a and b (one size) differ: 1 and its x, y. */
static int first_difference(const isk_canvas *a, const isk_canvas *b, int *x, int *y)
{
    for (*y = 0; *y < a->height; ++*y)
        if (memcmp(isk_canvas_at(a, 0, *y), isk_canvas_at(b, 0, *y), (size_t)a->width * 4))
            for (*x = 0; *x < a->width; ++*x)
                if (memcmp(isk_canvas_at(a, *x, *y), isk_canvas_at(b, *x, *y), 4))
                    return 1;
    return 0;
}

static void check_shot(player *p, void *user, const char *name, int whole_window)
{
    replay_check *c = user;
    const isk_canvas *got = whole_window ? p->shown : &p->sim;
    char ref[4200];
    snprintf(ref, sizeof ref, "%s/%s.png", c->dir, name);
    c->shots++;
    if (c->update && (outpath_refuse_input("replay", ref, c->lesson) ||
                      (c->scene && outpath_refuse_input("replay", ref, c->scene)))) {
        c->failed++;
        return;
    }
    isk_refimg_result res;
    isk_refimg_opts opts = {0};
    opts.out_dir = c->actual;
    opts.update = c->update ? ISK_REFIMG_UPDATE_ALWAYS : ISK_REFIMG_UPDATE_NEVER;
    opts.result = &res;
    isk_error err;
    isk_status s = isk_refimg_check(got, ref, &opts, &err);
    if (s == ISK_OK) {
        if (c->update)
            printf("%s: wrote %s (after frame %ld)\n", name, ref, p->frames_shown);
        else
            printf("%s: same pixels as %s (after frame %ld)\n", name, ref, p->frames_shown);
        return;
    }
    c->failed++;
    if (s == ISK_ERR_MISMATCH && res.same_size) {
        isk_canvas want;
        int x = 0, y = 0;
        if (isk_png_read(&want, ref, NULL) == ISK_OK) {
            first_difference(got, &want, &x, &y);
            const uint8_t *g = isk_canvas_at(got, x, y), *w = isk_canvas_at(&want, x, y);
            fprintf(stderr,
                    "iskra replay: shot %s after frame %ld differs from %s: %ld pixels differ, the first at "
                    "(%d, %d): %d,%d,%d,%d instead of %d,%d,%d,%d\n",
                    name, p->frames_shown, ref, res.diff.differing, x, y, g[0], g[1], g[2], g[3], w[0], w[1], w[2],
                    w[3]);
            isk_canvas_free(&want);
        }
    }
    fprintf(stderr, "iskra replay: shot %s: %s\n", name, err.message);
}

int cmd_replay(int argc, char **argv)
{
    static player p; /* large (the widget layer's state): not on the stack */
    memset(&p, 0, sizeof p);
    const char *path = NULL;
    replay_check chk = {0};
    chk.actual = REPLAY_DEFAULT_ACTUAL;
    long max_frames = 0;
    for (int i = 1; i < argc; i++) {
        const char *v;
        int r;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help(stdout);
            return 0;
        }
        if (!strcmp(argv[i], "--update")) {
            chk.update = 1;
        } else if ((r = arg_value("replay", argc, argv, &i, "--check", &v)) != 0) {
            if (r < 0)
                return 2;
            chk.dir = v;
        } else if ((r = arg_value("replay", argc, argv, &i, "--actual", &v)) != 0) {
            if (r < 0)
                return 2;
            chk.actual = v;
        } else if ((r = arg_value("replay", argc, argv, &i, "--frames", &v)) != 0) {
            if (r < 0 || !arg_long("replay", "--frames", v, 1, 1000000000, &max_frames))
                return 2;
        } else if (argv[i][0] == '-' && argv[i][1]) {
            fprintf(stderr, "iskra replay: unknown option %s\n", argv[i]);
            help(stderr);
            return 2;
        } else if (!path) {
            path = argv[i];
        } else {
            fprintf(stderr, "iskra replay: one lesson at a time (got %s and %s)\n", path, argv[i]);
            return 2;
        }
    }
    if (!path || !chk.dir || !*chk.dir || !*chk.actual) {
        fprintf(stderr, "iskra replay: %s\n", !path ? "which lesson?" : "--check needs a directory of references");
        help(stderr);
        return 2;
    }
    if (outpath_same_file(chk.actual, chk.dir)) {
        fprintf(stderr, "iskra replay: --actual %s is the directory of the references: choose another\n",
                chk.actual);
        return 2;
    }
    lesson les;
    play_opts o;
    int rc = play_cli_lesson(&p, &o, &les, path);
    outpath_plan plan = {.cmd = "replay"};
    if (!rc)
        rc = play_cli_open(&p, &o, &plan, path);
    if (rc) {
        play_script_free(&p.script);
        lesson_free(&les);
        return rc;
    }
    chk.lesson = path;
    chk.scene = p.path;
    p.script.shot = check_shot;
    p.script.shot_user = &chk;
    replay_queue q = {0};
    isk_canvas shown = {0};
    p.host = (play_host){&q, no_resize, queue_push, discard_file};
    play_choose_layout(&p, (int)o.ui_scale);
    play_layout_compute(&p);
    rc = 1;
    if (isk_canvas_init(&shown, p.lay.window.w, p.lay.window.h) != ISK_OK) {
        fprintf(stderr, "iskra replay: out of memory\n");
        goto out;
    }
    p.shown = &shown;
    play_begin_scene(&p);
    if (play_script_start(&p) != 0)
        goto out;
    isk_event ev[REPLAY_FRAME_EVENTS];
    for (long f = 0; max_frames == 0 || f < max_frames; f++) {
        const int n = q.n < REPLAY_FRAME_EVENTS ? q.n : REPLAY_FRAME_EVENTS;
        if (n > 0) {
            memcpy(ev, q.ev, (size_t)n * sizeof *ev);
            memmove(q.ev, q.ev + n, (size_t)(q.n - n) * sizeof *ev);
            q.n -= n;
        }
        if (play_frame(&p, p.ts.dt, ev, n) || (play_script_done(&p) && q.n == 0))
            break;
    }
    if (p.failed) {
        fprintf(stderr, "iskra replay: %s: %s\n", path, p.status);
    } else if (chk.failed) {
        fprintf(stderr, "iskra replay: %s: %d of the lesson's shots do not match (iskra replay %s --check %s "
                        "--update writes them, on purpose)\n", path, chk.failed, path, chk.dir);
    } else if (chk.shots == 0) {
        fprintf(stderr, "iskra replay: %s has no shot:NAME: nothing to check (F9 marks one while recording)\n",
                path);
    } else {
        printf("%s: %ld frames, %d shots %s\n", path, p.frames_shown, chk.shots,
               chk.update ? "written" : "the same");
        rc = 0;
    }
out:
    isk_canvas_free(&shown);
    free(q.ev);
    play_cli_close(&p);
    lesson_free(&les);
    return rc;
}
