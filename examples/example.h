/* SPDX-License-Identifier: MIT */
/* examples/example.h — the command line every example shares.
 *
 * Each example is one small program; this header keeps the option parsing
 * and the output (PNG file and/or SDL2 window) out of its way:
 *
 *     int main(int argc, char **argv) {
 *         example_opts o = {.seed = 1, .frames = 200};
 *         example_parse(argc, argv, &o, EX_SEED | EX_FRAMES, "fig16_regular",
 *                       "the regular (ring) explosion");
 *         ...set up a canvas and a state...
 *         return example_animate(&canvas, &o, state, step_and_draw);
 *     }
 *
 * Options: --png PATH (write the image), --window (show it in SDL2), and,
 * where the example says so, --seed N, --frames N, --csv PATH.  With neither
 * --png nor --window the example opens a window when a display is available
 * and otherwise writes NAME.png in the current directory.  Bad options print
 * a message and exit with status 2; output failures exit with status 1.
 * Header-only (static functions) so each example stays a single file.
 */
#ifndef ISKRA_EXAMPLE_H
#define ISKRA_EXAMPLE_H

#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra.h"
#include "iskra/sdl.h"

enum { EX_SEED = 1, EX_FRAMES = 2, EX_CSV = 4 };

typedef struct example_opts {
    const char *png;   /* --png PATH */
    const char *csv;   /* --csv PATH */
    int window;        /* --window */
    uint64_t seed;     /* --seed N */
    long frames;       /* --frames N: the frame to render */
    const char *name;  /* program name, for messages */
    char default_png[256];
} example_opts;

static inline void example_usage(FILE *f, const char *name, const char *about, unsigned flags)
{
    fprintf(f, "%s — %s\n\nusage: %s [--png PATH] [--window]%s%s%s\n", name, about, name,
            (flags & EX_SEED) ? " [--seed N]" : "", (flags & EX_FRAMES) ? " [--frames N]" : "",
            (flags & EX_CSV) ? " [--csv PATH]" : "");
    fprintf(f, "  --png PATH   write the image to PATH\n"
               "  --window     show it in a window (Esc closes)\n");
    if (flags & EX_SEED) fprintf(f, "  --seed N     random seed (0..2^64-1)\n");
    if (flags & EX_FRAMES) fprintf(f, "  --frames N   render frame N (N >= 0)\n");
    if (flags & EX_CSV) fprintf(f, "  --csv PATH   write the trajectory as CSV ('-' for stdout)\n");
}

static inline int example_parse_u64(const char *s, uint64_t *out)
{
    if (!s || !*s || *s == '-' || *s == '+')
        return 0;
    char *end;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    if (errno || *end)
        return 0;
    *out = (uint64_t)v;
    return 1;
}

/* Parses argv into o (defaults already set by the caller); exits on error. */
static inline void example_parse(int argc, char **argv, example_opts *o, unsigned flags, const char *name,
                          const char *about)
{
    o->name = name;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *val = (i + 1 < argc) ? argv[i + 1] : NULL;
        uint64_t u;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            example_usage(stdout, name, about, flags);
            exit(0);
        } else if (!strcmp(a, "--window")) {
            o->window = 1;
        } else if (!strcmp(a, "--png") && val) {
            o->png = val; i++;
        } else if (!strcmp(a, "--csv") && (flags & EX_CSV) && val) {
            o->csv = val; i++;
        } else if (!strcmp(a, "--seed") && (flags & EX_SEED) && val) {
            if (!example_parse_u64(val, &u)) {
                fprintf(stderr, "%s: --seed expects a whole number 0..2^64-1, got '%s'\n", name, val);
                exit(2);
            }
            o->seed = u; i++;
        } else if (!strcmp(a, "--frames") && (flags & EX_FRAMES) && val) {
            if (!example_parse_u64(val, &u) || u > 100000000u) {
                fprintf(stderr, "%s: --frames expects a whole number 0..100000000, got '%s'\n", name, val);
                exit(2);
            }
            o->frames = (long)u; i++;
        } else {
            int known = !strcmp(a, "--png") || !strcmp(a, "--csv") || !strcmp(a, "--seed") ||
                        !strcmp(a, "--frames");
            if (known && !val)
                fprintf(stderr, "%s: %s needs a value\n", name, a);
            else
                fprintf(stderr, "%s: unknown option '%s'\n", name, a);
            example_usage(stderr, name, about, flags);
            exit(2);
        }
    }
    if (!o->png && !o->window && !o->csv) {
        if (getenv("DISPLAY") || getenv("WAYLAND_DISPLAY")) {
            o->window = 1;
        } else {
            snprintf(o->default_png, sizeof o->default_png, "%s.png", name);
            o->png = o->default_png;
            fprintf(stderr, "%s: no display; writing %s (use --png PATH or --window)\n", name, o->png);
        }
    }
}

static inline int example_write_png(const isk_canvas *c, const example_opts *o)
{
    if (!o->png)
        return 0;
    isk_error err;
    if (isk_png_write(c, o->png, &err) != ISK_OK) {
        fprintf(stderr, "%s: %s\n", o->name, err.message);
        return 1;
    }
    return 0;
}

typedef void (*example_frame_fn)(void *state, isk_canvas *c);

typedef struct example_loop {
    void *state;
    example_frame_fn frame;
} example_loop;

static inline int example_window_frame(void *user, isk_canvas *c, double dt, const isk_event *ev, int n)
{
    (void)dt; (void)ev; (void)n;
    example_loop *l = user;
    if (l->frame)
        l->frame(l->state, c);
    return 0;
}

static inline int example_window(isk_canvas *c, const example_opts *o, void *state, example_frame_fn frame)
{
    isk_window *w;
    isk_error err;
    if (isk_window_open(&w, o->name, c->width, c->height, &err) != ISK_OK) {
        fprintf(stderr, "%s: cannot open a window: %s\n", o->name, err.message);
        return 1;
    }
    example_loop l = {state, frame};
    isk_status s = isk_window_run(w, c, example_window_frame, &l, 0, &err);
    isk_window_close(w);
    if (s != ISK_OK) {
        fprintf(stderr, "%s: %s\n", o->name, err.message);
        return 1;
    }
    return 0;
}

/* A still image: write it and/or show it until the window is closed. */
static inline int example_show(isk_canvas *c, const example_opts *o)
{
    int rc = example_write_png(c, o);
    if (!rc && o->window)
        rc = example_window(c, o, NULL, NULL);
    return rc;
}

/* An animation: `frame` advances the state one frame and draws it.  The PNG
 * gets frame o->frames (frame 0 = before any call); the window then keeps
 * animating from there. */
static inline int example_animate(isk_canvas *c, const example_opts *o, void *state, example_frame_fn frame)
{
    if (o->png) {
        for (long i = 0; i < o->frames; i++)
            frame(state, c);
        if (example_write_png(c, o))
            return 1;
    }
    return o->window ? example_window(c, o, state, frame) : 0;
}

#endif
