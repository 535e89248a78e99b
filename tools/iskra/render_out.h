/* SPDX-License-Identifier: MIT */
/* The outputs of `iskra render`, written as the frames come:
 *
 *   png        --out FILE: the last frame (frame N) as a PNG
 *   sequence   --out-dir DIR: frames 0, K, 2K, ... <= N as DIR/frame_%06ld.png,
 *              each complete or absent (--resume keeps those already there)
 *   animation  --out FILE.gif | FILE.y4m, or --raw --out FILE | - (stdout):
 *              frames 0, K, 2K, ... <= N in one stream (iskra/anim.h)
 *
 *     render_out o = {.png = ..., .dir = ..., .every = K, ...};
 *     if ((rc = render_out_begin(&o, w, h, fps))) return rc;
 *     for each frame f: if (render_out_wants(&o, f)) { draw; render_out_frame(&o, &c, f); }
 *     render_out_end(&o, &c);          // or render_out_abort(&o) on failure
 *
 * Every file goes through iskra/outfile.h (a temporary renamed into place,
 * devices and FIFOs written through) and the tool's cleanup registry, so an
 * interrupted render leaves no temporary behind (cleanup.h).  Messages go
 * to stderr as "iskra render: ..."; functions return 0 or the exit status. */
#ifndef ISKRA_TOOL_RENDER_OUT_H
#define ISKRA_TOOL_RENDER_OUT_H

#include "iskra/anim.h"
#include "iskra/canvas.h"
#include "iskra/outfile.h"

typedef struct render_out {
    /* what was asked */
    const char *png;          /* a single PNG of the last frame, or NULL */
    const char *dir;          /* a PNG sequence, or NULL */
    int resume;               /* keep sequence frames that already exist */
    const char *anim_path;    /* an animation ("-": stdout), or NULL */
    isk_anim_format anim_format;
    long every;               /* sequence and animation step, >= 1 */
    /* progress, for messages */
    long seq_written, seq_kept;
    long seq_first, seq_last; /* sequence frames written (-1: none yet) */
    /* the animation stream */
    isk_outfile anim_file;
    int anim_stdout;
    int streaming;            /* stdout, a pipe, FIFO or device: nothing to take back */
    FILE *stream;             /* what the animation is written to */
    long anim_first, anim_count;
    isk_anim *anim;
    int width, height;
} render_out;

/* Creates directories and opens the animation stream.  0, or the exit
 * status after printing why. */
int render_out_begin(render_out *o, int width, int height, double fps);

/* 1 when frame f goes to the sequence or the animation. */
int render_out_wants(const render_out *o, long f);

/* Writes frame f where it goes.  0 or 1 (printed). */
int render_out_frame(render_out *o, const isk_canvas *c, long f);

/* Writes the single PNG and finishes the animation.  0 or 1 (printed). */
int render_out_end(render_out *o, const isk_canvas *last);

/* Drops an unfinished animation (its temporary is removed). */
void render_out_abort(render_out *o);

/* Path of sequence frame f in dir (the one naming rule):
 * DIR/RENDER_FRAME_PREFIX%06ldRENDER_FRAME_SUFFIX. */
#define RENDER_FRAME_PREFIX "frame_"
#define RENDER_FRAME_SUFFIX ".png"
void render_out_frame_path(const char *dir, long f, char *path, size_t n);

#endif
