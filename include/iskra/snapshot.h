/* SPDX-License-Identifier: MIT */
/* iskra/snapshot.h — an effect's whole running state, kept and put back.
 *
 * Example:
 *
 *     isk_effect_def d;
 *     isk_effect *fx;
 *     isk_snapshot *at20;
 *     isk_error err;
 *     if (isk_scene_load(&d, "fire_campfire", &err) != ISK_OK) return 2;
 *     isk_status s = isk_effect_create(&fx, &d, &err);
 *     isk_effect_def_free(&d);
 *     if (s != ISK_OK) return 2;
 *     for (int f = 0; f < 20; f++) isk_effect_step(fx);
 *     if (isk_effect_snapshot(fx, &at20, &err) != ISK_OK) return 1;   // frame 20, all of it
 *     for (int f = 20; f < 90; f++) isk_effect_step(fx);
 *     isk_effect_restore(fx, at20, &err);              // back at frame 20, as it was
 *     isk_snapshot_save(at20, "at20.snap", &err);      // for another process
 *     isk_snapshot_free(at20);
 *     isk_effect_destroy(fx);
 *
 * A snapshot holds everything a run depends on: the live definition (every
 * isk_effect_set, add and remove so far), the live potentials, each
 * emitter's particles with every column and trail, its random stream and
 * the state of its births (the stream's schedule, bursts, cycles,
 * explosions under way, the emitter's path, sub-emitters' pending events),
 * the counts of dropped and removed particles, the probes' counts and
 * windows (iskra/probes.h), and the clocks.  Restoring
 * the snapshot of frame k and stepping to frame n gives the bytes of a
 * straight run to n, on any number of threads.  What it does not hold is
 * what no result depends on: the threads (the effect keeps its own), the
 * caches (blocks at rest, recorded draws, baked sprites), and a canvas
 * (render after a restore; a scene with clear = false draws over
 * whatever canvas it is given).
 *
 * isk_effect_restore works on any effect: the snapshot's definition
 * replaces the effect's, so an effect created from another scene becomes
 * the snapshot's.  It is all-or-nothing: on error the effect is as it was.
 *
 * The file (isk_snapshot_save / isk_snapshot_load, or the bytes of
 * isk_snapshot_encode / isk_snapshot_decode) is exact: a header line, the
 * definition as scene text (iskra/scene.h: it loads back to the same
 * bits), then the state as little-endian numbers, and a checksum.  A
 * snapshot of a potential moved by a C function, which scene text cannot
 * hold, cannot be saved (ISK_ERR_FORMAT).  Textures are read again from
 * the files the scene names, relative to the current directory or as
 * absolute paths.  Reading checks everything: a damaged or hostile file is
 * refused with a message (ISK_ERR_FORMAT), never half-loaded, and its
 * numbers are checked as a scene's are (no NaN, counts within the pools).
 * `iskra render --state` writes what an analysis wants (CSV); this is what
 * a run needs to go on (`iskra render --snapshot FILE`, then `--from FILE`).
 */
#ifndef ISKRA_SNAPSHOT_H
#define ISKRA_SNAPSHOT_H

#include <stddef.h>

#include "iskra/effect.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct isk_snapshot isk_snapshot;

/* *out receives a new snapshot of e (free it).  ISK_ERR_NULL, ISK_ERR_NOMEM. */
isk_status isk_effect_snapshot(const isk_effect *e, isk_snapshot **out, isk_error *err);
/* e becomes the snapshot's state.  ISK_ERR_NULL, ISK_ERR_NOMEM, and what
 * isk_effect_create refuses (a snapshot read from a file is checked again). */
isk_status isk_effect_restore(isk_effect *e, const isk_snapshot *snap, isk_error *err);
void isk_snapshot_free(isk_snapshot *snap);

/* The frame it was taken at (isk_effect_frame), and the memory it holds. */
long isk_snapshot_frame(const isk_snapshot *snap);
size_t isk_snapshot_bytes(const isk_snapshot *snap);

/* The exact file, as bytes (*bytes is malloc'd: free it) and back (`name`
 * names it in messages).  ISK_ERR_NULL, ISK_ERR_NOMEM, ISK_ERR_FORMAT. */
isk_status isk_snapshot_encode(const isk_snapshot *snap, unsigned char **bytes, size_t *size, isk_error *err);
isk_status isk_snapshot_decode(isk_snapshot **out, const unsigned char *bytes, size_t size, const char *name,
                               isk_error *err);
/* The same through a file (written through iskra/outfile.h: whole or not
 * at all).  ISK_ERR_IO besides. */
isk_status isk_snapshot_save(const isk_snapshot *snap, const char *path, isk_error *err);
isk_status isk_snapshot_load(isk_snapshot **out, const char *path, isk_error *err);

#ifdef __cplusplus
}
#endif

#endif
