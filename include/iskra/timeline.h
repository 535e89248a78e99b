/* SPDX-License-Identifier: MIT */
/* iskra/timeline.h — rewind: a run's frames kept as snapshots every K
 * frames (iskra/snapshot.h), within a memory budget, and any of them
 * brought back.
 *
 * Example:
 *
 *     isk_effect_def d;
 *     isk_effect *fx;
 *     isk_error err;
 *     if (isk_scene_load(&d, "fire_campfire", &err) != ISK_OK) return 2;
 *     isk_status s = isk_effect_create(&fx, &d, &err);
 *     isk_effect_def_free(&d);
 *     if (s != ISK_OK) return 2;
 *     isk_timeline *t = isk_timeline_create(64u << 20);   // at most 64 MB of checkpoints
 *     if (!t) return 1;
 *     isk_timeline_restart(t, fx, NULL);                 // after create, reset, a new scene
 *     for (int f = 0; f < 600; f++) {
 *         isk_timeline_watch(t, fx, NULL);               // after your edits, before the step
 *         isk_effect_step(fx);
 *         isk_timeline_stepped(t, fx, NULL);
 *     }
 *     isk_timeline_seek(t, fx, NULL, 250);               // frame 250, as it was
 *     isk_timeline_destroy(t);
 *     isk_effect_destroy(fx);
 *
 * A seek restores the newest checkpoint at or before the frame and steps
 * on from it, so it costs at most K frames, and gives the bytes the run
 * had there (a run is deterministic).  Stepping on from the past without
 * an edit follows the same timeline.  An edit (isk_effect_edits moved:
 * a set, a click, a potential, a birth by hand, a move) forks it: the
 * frames after now are forgotten and now becomes a checkpoint, since the
 * future will differ.
 *
 * Memory stays under the budget: when the checkpoints pass it, every other
 * one goes and K doubles (K starts at ISK_TIMELINE_EVERY); an edit's
 * checkpoint stays, since the frames after it come from it alone, so when
 * edits alone fill the budget (an emitter dragged for minutes) the oldest
 * checkpoints go and the timeline starts later.  A scene whose one frame
 * takes more than a quarter of the budget is not kept at all
 * (isk_timeline_is_off).
 *
 * `canvas` (may be NULL) is the canvas you render into.  A scene that
 * draws trails over its canvas (clear = false) keeps a copy of it with
 * each checkpoint, and a seek puts the trails of that frame back; for the
 * other scenes a seek renders the frame into it.
 */
#ifndef ISKRA_TIMELINE_H
#define ISKRA_TIMELINE_H

#include <stddef.h>

#include "iskra/canvas.h"
#include "iskra/effect.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A checkpoint every this many frames to begin with. */
#define ISK_TIMELINE_EVERY 8

typedef struct isk_timeline isk_timeline;

/* NULL when out of memory. */
isk_timeline *isk_timeline_create(size_t budget);
void isk_timeline_destroy(isk_timeline *t);

/* Forgets everything: the effect's frame now is the first checkpoint. */
isk_status isk_timeline_restart(isk_timeline *t, isk_effect *fx, const isk_canvas *canvas);
/* An edit since the last look forks the timeline at the effect's frame. */
isk_status isk_timeline_watch(isk_timeline *t, isk_effect *fx, const isk_canvas *canvas);
/* After each step: the timeline grows; a checkpoint every K frames. */
isk_status isk_timeline_stepped(isk_timeline *t, isk_effect *fx, const isk_canvas *canvas);
/* The effect at `frame`, clamped to the frames kept (the canvas too). */
isk_status isk_timeline_seek(isk_timeline *t, isk_effect *fx, isk_canvas *canvas, long frame);

/* The first and last frames a seek reaches; the checkpoints (their frames,
 * whether an edit made them); the memory they take; K now. */
long isk_timeline_first(const isk_timeline *t);
long isk_timeline_last(const isk_timeline *t);
int isk_timeline_checkpoints(const isk_timeline *t);
long isk_timeline_checkpoint_frame(const isk_timeline *t, int i);
int isk_timeline_checkpoint_edit(const isk_timeline *t, int i);
size_t isk_timeline_bytes(const isk_timeline *t);
size_t isk_timeline_budget(const isk_timeline *t);
int isk_timeline_every(const isk_timeline *t);
/* 1: one frame of this scene needs more than a quarter of the budget. */
int isk_timeline_is_off(const isk_timeline *t);

#ifdef __cplusplus
}
#endif

#endif
