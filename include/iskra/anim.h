/* SPDX-License-Identifier: MIT */
/* iskra/anim.h — animations written frame by frame: animated GIF (giflib),
 * YUV4MPEG2 (what ffmpeg, mpv and VLC read) and raw RGBA frames (for a
 * pipe into ffmpeg or anything else).
 *
 * Example: a disc growing for 60 frames, as an animated GIF:
 *
 *     isk_canvas c;
 *     if (isk_canvas_init(&c, 120, 100) != ISK_OK) return 1;
 *     isk_error err;
 *     isk_outfile o;                                   // iskra/outfile.h
 *     if (isk_outfile_open(&o, "disc.gif", &err) != ISK_OK) {
 *         fprintf(stderr, "%s\n", err.message);
 *         return 1;
 *     }
 *     isk_anim_opts ao = {ISK_ANIM_GIF, c.width, c.height, 30.0};   // format, size, fps
 *     isk_anim *a;
 *     isk_status s = isk_anim_begin(&a, o.f, &ao, &err);
 *     for (int i = 0; i < 60 && s == ISK_OK; i++) {
 *         isk_canvas_fill(&c, ISK_BLACK);
 *         isk_fill_circle_aa(&c, 60, 50, 0.75 * i, ISK_YELLOW, ISK_BLEND_OVER);
 *         s = isk_anim_frame(a, &c, &err);
 *     }
 *     if (s == ISK_OK) s = isk_anim_end(a, &err); else isk_anim_abort(a);
 *     if (s == ISK_OK) s = isk_outfile_commit(&o, &err); else isk_outfile_abort(&o);
 *     if (s != ISK_OK) fprintf(stderr, "%s\n", err.message);
 *     isk_canvas_free(&c);
 *     return s != ISK_OK;
 *
 * The writer only writes to the stream it is given (a file, a pipe,
 * stdout) and never closes it.  Every frame has the size given at begin.
 * Same frames, same bytes: nothing depends on time or the machine.
 *
 *   GIF   GIF89a, looping forever.  Each frame gets its own palette
 *         (src/io/quantize.h): exact when the frame has at most 256
 *         colours, else median cut over its colours weighted by pixel
 *         count, no dithering (a dither would crawl between frames).
 *         Delays are whole centiseconds: frame i ends at
 *         round(100 (i+1) / fps) cs, at least 2 cs after it started
 *         (browsers slow 0 and 1 cs down to 10), so above 50 fps a GIF
 *         plays at 50.  Alpha is composited over black.
 *   Y4M   "YUV4MPEG2 Wn Hn Fnum:den Ip A1:1 C444", then FRAME + the Y, Cb
 *         and Cr planes: BT.601 limited range, integer arithmetic, no
 *         chroma subsampling (ffmpeg's -pix_fmt yuv420p makes 4:2:0 for
 *         players that need it).  fps is written as a fraction in
 *         thousandths (29.97 -> 2997:100).  Alpha is composited over black.
 *   RAW   width x height x 4 bytes per frame, R G B A, top row first, no
 *         header, straight alpha: the canvas bytes, row padding removed.
 *         fps is not recorded (tell the reader, e.g. ffmpeg -framerate).
 */
#ifndef ISKRA_ANIM_H
#define ISKRA_ANIM_H

#include <stdio.h>

#include "iskra/canvas.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum isk_anim_format { ISK_ANIM_GIF = 0, ISK_ANIM_Y4M, ISK_ANIM_RAW, ISK_ANIM_FORMAT_COUNT } isk_anim_format;

typedef struct isk_anim_opts {
    isk_anim_format format;
    int width, height;  /* every frame's size, 1..ISK_CANVAS_MAX_DIM */
    double fps;         /* frames per second, 0.001..1000 (RAW: ignored, may be 0) */
} isk_anim_opts;

typedef struct isk_anim isk_anim;

/* Writes the stream's header.  Errors: ISK_ERR_NULL, ISK_ERR_SIZE,
 * ISK_ERR_RANGE (format, fps), ISK_ERR_NAN (fps), ISK_ERR_NOMEM,
 * ISK_ERR_IO. */
isk_status isk_anim_begin(isk_anim **out, FILE *f, const isk_anim_opts *o, isk_error *err);

/* Appends one frame (its size must be the animation's: ISK_ERR_SIZE). */
isk_status isk_anim_frame(isk_anim *a, const isk_canvas *frame, isk_error *err);

/* Finishes the stream (GIF's trailer), flushes it and frees the writer. */
isk_status isk_anim_end(isk_anim *a, isk_error *err);

/* Frees the writer without finishing the stream (after a failure). */
void isk_anim_abort(isk_anim *a);

/* The most memory a writer with these options holds at once, in bytes
 * (isk_anim_begin's tables and every isk_anim_frame's scratch together:
 * GIF's palette tables grow with the frame's pixels, Y4M keeps a row, raw
 * nothing), so a program can count it in its budget before it writes
 * anything (isk_effect_def.host_memory).  0 for NULL options or a frame
 * size isk_anim_begin refuses. */
size_t isk_anim_memory(const isk_anim_opts *o);

/* Frames written so far (0 for NULL). */
long isk_anim_count(const isk_anim *a);

/* The format a file name asks for by its extension (".gif", ".y4m",
 * case-insensitive): 1 and *f set, or 0 for any other name. */
int isk_anim_format_of_path(const char *path, isk_anim_format *f);

/* "gif", "y4m", "raw"; NULL for an unknown format. */
const char *isk_anim_format_name(isk_anim_format f);

#ifdef __cplusplus
}
#endif

#endif
