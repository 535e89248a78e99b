/* SPDX-License-Identifier: MIT */
/* Rewind: checkpoints of a run, and seeking among them (iskra/timeline.h). */
#include <stdlib.h>
#include <string.h>

#include "iskra/snapshot.h"
#include "iskra/timeline.h"

typedef struct checkpoint {
    long frame;
    isk_snapshot *snap;
    isk_canvas canvas; /* trails: the canvas at that frame (pixels NULL otherwise) */
    size_t bytes;
    int edit;          /* taken at a restart or an edit: never thinned out */
} checkpoint;

struct isk_timeline {
    checkpoint *cp;    /* ascending frames; cp[0] the first frame kept */
    int n, cap;
    int every;         /* K */
    long newest;       /* the furthest frame this timeline has reached */
    size_t bytes, budget;
    unsigned long edits; /* isk_effect_edits when last seen */
    int off;           /* one frame alone needs more than a quarter of the budget */
};

isk_timeline *isk_timeline_create(size_t budget)
{
    isk_timeline *t = calloc(1, sizeof *t);
    if (t) {
        t->budget = budget;
        t->every = ISK_TIMELINE_EVERY;
    }
    return t;
}

static void drop(checkpoint *c)
{
    isk_snapshot_free(c->snap);
    isk_canvas_free(&c->canvas);
    memset(c, 0, sizeof *c);
}

static void forget_from(isk_timeline *t, int first)
{
    for (int i = first; i < t->n; i++) {
        t->bytes -= t->cp[i].bytes;
        drop(&t->cp[i]);
    }
    if (first < t->n)
        t->n = first;
}

void isk_timeline_destroy(isk_timeline *t)
{
    if (!t)
        return;
    forget_from(t, 0);
    free(t->cp);
    free(t);
}

/* Within the budget: every other checkpoint after the first goes and K
 * doubles, as long as that frees something; an edit's checkpoint stays
 * there (before it the definition was another, so the frames after it
 * come from it alone).  If edits still fill the budget (an emitter dragged
 * for minutes), the oldest checkpoints go: the timeline starts later. */
static void thin(isk_timeline *t)
{
    int dropped = 1;
    while (t->bytes > t->budget && t->n > 2 && dropped) {
        int k = 1;
        dropped = 0;
        for (int i = 1; i < t->n; i++) {
            if (i % 2 && !t->cp[i].edit && i < t->n - 1) {
                t->bytes -= t->cp[i].bytes;
                drop(&t->cp[i]);
                dropped++;
            } else {
                t->cp[k++] = t->cp[i];
            }
        }
        t->n = k;
        if (dropped)
            t->every *= 2;
    }
    while (t->bytes > t->budget && t->n > 1) {
        t->bytes -= t->cp[0].bytes;
        drop(&t->cp[0]);
        memmove(t->cp, t->cp + 1, sizeof *t->cp * (size_t)(t->n - 1));
        t->n--;
    }
}

/* The effect's state now as the last checkpoint (one of the same frame is
 * replaced). */
static isk_status take(isk_timeline *t, isk_effect *fx, const isk_canvas *canvas, int edit)
{
    if (t->off)
        return ISK_OK;
    const long frame = isk_effect_frame(fx);
    checkpoint c = {frame, NULL, {0}, 0, edit};
    isk_status s = isk_effect_snapshot(fx, &c.snap, NULL);
    if (s != ISK_OK)
        return s;
    c.bytes = isk_snapshot_bytes(c.snap);
    if (!isk_effect_definition(fx)->clear && canvas) { /* trails: the canvas is part of the picture */
        if ((s = isk_canvas_init(&c.canvas, canvas->width, canvas->height)) != ISK_OK) {
            drop(&c);
            return s;
        }
        for (int y = 0; y < canvas->height; y++)
            memcpy(c.canvas.pixels + (size_t)y * c.canvas.stride, canvas->pixels + (size_t)y * canvas->stride,
                   (size_t)canvas->width * 4);
        c.bytes += c.canvas.stride * (size_t)c.canvas.height;
    }
    if (c.bytes > t->budget / 4) { /* a few of them would not fit: no rewind for this scene */
        drop(&c);
        forget_from(t, 0);
        t->off = 1;
        return ISK_OK;
    }
    if (t->n && t->cp[t->n - 1].frame >= frame) {
        int i = t->n - 1;
        while (i > 0 && t->cp[i - 1].frame >= frame)
            i--;
        forget_from(t, i);
    }
    if (t->n == t->cap) {
        int cap = t->cap ? 2 * t->cap : 64;
        checkpoint *a = realloc(t->cp, sizeof *a * (size_t)cap);
        if (!a) {
            drop(&c);
            return ISK_ERR_NOMEM;
        }
        t->cp = a;
        t->cap = cap;
    }
    t->cp[t->n++] = c;
    t->bytes += c.bytes;
    thin(t);
    return ISK_OK;
}

/* The timeline goes on from now: what came after it was another future
 * (forgotten by take), and now is a checkpoint of its own. */
static isk_status go_on_from_now(isk_timeline *t, isk_effect *fx, const isk_canvas *canvas)
{
    t->newest = isk_effect_frame(fx);
    t->edits = isk_effect_edits(fx);
    return take(t, fx, canvas, 1);
}

isk_status isk_timeline_restart(isk_timeline *t, isk_effect *fx, const isk_canvas *canvas)
{
    if (!t || !fx)
        return ISK_ERR_NULL;
    forget_from(t, 0);
    t->off = 0;
    t->every = ISK_TIMELINE_EVERY;
    return go_on_from_now(t, fx, canvas);
}

isk_status isk_timeline_watch(isk_timeline *t, isk_effect *fx, const isk_canvas *canvas)
{
    if (!t || !fx)
        return ISK_ERR_NULL;
    return isk_effect_edits(fx) == t->edits ? ISK_OK : go_on_from_now(t, fx, canvas);
}

isk_status isk_timeline_stepped(isk_timeline *t, isk_effect *fx, const isk_canvas *canvas)
{
    if (!t || !fx)
        return ISK_ERR_NULL;
    const long frame = isk_effect_frame(fx);
    if (frame > t->newest)
        t->newest = frame;
    if (t->off || !t->n || frame <= t->cp[t->n - 1].frame || (frame - t->cp[0].frame) % t->every)
        return ISK_OK;
    return take(t, fx, canvas, 0);
}

long isk_timeline_first(const isk_timeline *t) { return !t ? 0 : t->n ? t->cp[0].frame : t->newest; }
long isk_timeline_last(const isk_timeline *t) { return t ? t->newest : 0; }
int isk_timeline_checkpoints(const isk_timeline *t) { return t ? t->n : 0; }
long isk_timeline_checkpoint_frame(const isk_timeline *t, int i) { return t && i >= 0 && i < t->n ? t->cp[i].frame : -1; }
int isk_timeline_checkpoint_edit(const isk_timeline *t, int i) { return t && i >= 0 && i < t->n && t->cp[i].edit; }
size_t isk_timeline_bytes(const isk_timeline *t) { return t ? t->bytes : 0; }
size_t isk_timeline_budget(const isk_timeline *t) { return t ? t->budget : 0; }
int isk_timeline_every(const isk_timeline *t) { return t ? t->every : 0; }
int isk_timeline_is_off(const isk_timeline *t) { return t ? t->off : 1; }

isk_status isk_timeline_seek(isk_timeline *t, isk_effect *fx, isk_canvas *canvas, long frame)
{
    if (!t || !fx)
        return ISK_ERR_NULL;
    if (t->off || !t->n)
        return ISK_OK;
    if (frame < t->cp[0].frame)
        frame = t->cp[0].frame;
    if (frame > t->newest)
        frame = t->newest;
    int i = t->n - 1;
    while (i > 0 && t->cp[i].frame > frame)
        i--;
    const checkpoint *c = &t->cp[i];
    isk_status s = isk_effect_restore(fx, c->snap, NULL);
    if (s != ISK_OK)
        return s;
    const int trails = !isk_effect_definition(fx)->clear;
    if (trails && c->canvas.pixels && canvas)
        for (int y = 0; y < canvas->height && y < c->canvas.height; y++)
            memcpy(canvas->pixels + (size_t)y * canvas->stride, c->canvas.pixels + (size_t)y * c->canvas.stride,
                   (size_t)canvas->width * 4);
    for (long f = c->frame; f < frame && s == ISK_OK; f++)
        s = trails && canvas ? isk_effect_step_render(fx, canvas) : isk_effect_step(fx);
    if (s == ISK_OK && !trails && canvas)
        s = isk_effect_render(fx, canvas);
    return s;
}
