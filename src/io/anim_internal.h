/* SPDX-License-Identifier: MIT */
/* src/io/anim_internal.h — what the animation formats share (anim.c holds
 * the table of formats, gif.c and y4m.c the writers). */
#ifndef ISKRA_IO_ANIM_INTERNAL_H
#define ISKRA_IO_ANIM_INTERNAL_H

#include "iskra/anim.h"

typedef struct anim_format {
    const char *name;   /* "gif" */
    const char *ext;    /* ".gif", or NULL: never chosen by a file name */
    int needs_fps;      /* 1: begin refuses a missing or bad fps */
    isk_status (*begin)(isk_anim *a, isk_error *err);
    isk_status (*frame)(isk_anim *a, const isk_canvas *c, isk_error *err);
    isk_status (*end)(isk_anim *a, isk_error *err); /* finishes the stream */
    void (*release)(isk_anim *a);                   /* frees a->state */
    size_t (*memory)(const isk_anim_opts *o);       /* the most it holds at once (isk_anim_memory) */
} anim_format;

struct isk_anim {
    const anim_format *fmt;
    FILE *f;
    isk_anim_opts o;
    long frames;
    void *state;        /* the format's own */
};

/* The writers (gif.c, y4m.c). */
isk_status isk__gif_begin(isk_anim *a, isk_error *err);
isk_status isk__gif_frame(isk_anim *a, const isk_canvas *c, isk_error *err);
isk_status isk__gif_end(isk_anim *a, isk_error *err);
void isk__gif_release(isk_anim *a);
size_t isk__gif_memory(const isk_anim_opts *o);
isk_status isk__y4m_begin(isk_anim *a, isk_error *err);
isk_status isk__y4m_frame(isk_anim *a, const isk_canvas *c, isk_error *err);
isk_status isk__raw_frame(isk_anim *a, const isk_canvas *c, isk_error *err);
isk_status isk__stream_end(isk_anim *a, isk_error *err); /* fflush + error check */
void isk__stream_release(isk_anim *a);
size_t isk__y4m_memory(const isk_anim_opts *o);
size_t isk__raw_memory(const isk_anim_opts *o);

#endif
