/* SPDX-License-Identifier: MIT */
/* iskra render's particle state: --state FILE.csv writes every live
 * particle at the last frame, --state-every K (with --out-dir) writes
 * DIR/state_NNNNNN.csv beside every K-th frame, and the report of
 * particles removed because their state went non-finite.
 *
 * One row per live particle, emitters in definition order, particles in
 * store order, values in round-trip precision (%.17g: read back to the same
 * bits; an immortal particle's life is "inf"):
 *
 *     emitter,index,x,y,vx,vy,mass,age,life
 *     sparks,0,0.123...,0.5...,...
 *
 * Files go through the tool's one output path (cleanup.h, iskra/outfile.h):
 * a temporary renamed into place, so a reader never sees half of one, a
 * device or FIFO written through, an existing file's mode kept.  The hooks are three calls, so the rest of the render
 * command does not need to know about any of this:
 *
 *     state_opts so = {0};
 *     ... if ((r = state_args_take(&so, argc, argv, &i)) != 0) { if (r < 0) return 2; continue; }
 *     if (state_args_check(&so, out_dir)) return 2;
 *     ... after frame f is done: if (state_after_frame(&so, fx, out_dir, f)) rc = 1;
 *     ... at the end: if (state_finish(&so, fx)) rc = 1;   (also reports removals)
 */
#ifndef ISKRA_TOOL_STATE_CSV_H
#define ISKRA_TOOL_STATE_CSV_H

#include "iskra/effect.h"

typedef struct state_opts {
    const char *path; /* --state FILE.csv, or NULL */
    long every;       /* --state-every K, 0: none */
    long first, count; /* --state-every files written so far */
} state_opts;

/* --state / --state-every at argv[*i]: 1 taken, 0 not ours, -1 error
 * (printed). */
int state_args_take(state_opts *o, int argc, char **argv, int *i);

/* The combination with --out-dir: 0, or 2 after printing why. */
int state_args_check(const state_opts *o, const char *out_dir);

/* The CSV of the effect's live particles now; 0 or 1 after printing why. */
int state_csv_write(const isk_effect *fx, const char *path);

/* After frame f: DIR/STATE_PREFIX%06ldSTATE_SUFFIX when f is a multiple
 * of K. 0 or 1. */
#define STATE_PREFIX "state_"
#define STATE_SUFFIX ".csv"
int state_after_frame(state_opts *o, const isk_effect *fx, const char *out_dir, long f);

/* At the end of the render: --state FILE, then the report of removed
 * particles on stderr.  0 or 1. */
int state_finish(const state_opts *o, const isk_effect *fx);

/* "iskra render: emitter 'a': 3 particles removed: their state went
 * non-finite" for every emitter that lost any; returns how many in all. */
size_t state_report_removed(const isk_effect *fx);

#endif
