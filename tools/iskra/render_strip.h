/* SPDX-License-Identifier: MIT */
/* `iskra render --strip FILE.png`: frames K, 2K, ... <= N side by side at
 * half size, each labelled with its simulated time, in one PNG (the gallery strips of
 * the README).  Frame 0, the empty start, is left out.
 *
 *     render_strip s;
 *     if ((rc = render_strip_begin(&s, path, w, h, last, every))) return rc;   // 2: too many panels
 *     for each frame f: if (render_strip_wants(&s, f)) render_strip_frame(&s, &canvas, f, isk_effect_time(fx));
 *     rc = render_strip_end(&s);          // writes the PNG (0 or 1); always frees
 *
 * Messages go to stderr as "iskra render: ..." */
#ifndef ISKRA_TOOL_RENDER_STRIP_H
#define ISKRA_TOOL_RENDER_STRIP_H

#include "iskra/canvas.h"

/* More panels than a README page shows legibly: say so, and which --every. */
#define RENDER_STRIP_MAX_PANELS 12

typedef struct render_strip {
    const char *path;    /* NULL: no strip asked for */
    long every;
    int panels, pw, ph;
    isk_canvas out;
} render_strip;

/* The strip's size for frames every, 2 every, ... <= last of a width x
 * height canvas: its panels (*w x *h set), or 0 when there would be none
 * or too many, or it would be wider than a canvas can be
 * (render_strip_begin says so). */
int render_strip_size(int width, int height, long last, long every, int *w, int *h);
/* 0, 1 (out of memory) or 2 (no frame or too many frames for a strip). */
int render_strip_begin(render_strip *s, const char *path, int width, int height, long last, long every);
int render_strip_wants(const render_strip *s, long f);
void render_strip_frame(render_strip *s, const isk_canvas *c, long f, double time);
int render_strip_end(render_strip *s);

#endif
