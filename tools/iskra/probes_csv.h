/* SPDX-License-Identifier: MIT */
/* iskra render --probes FILE.csv: the scene's probes (iskra/probes.h), a
 * row per frame stepped (1 .. N), a column per reading, each named
 * PROBE.VALUE (isk_probe_values), values in round-trip precision:
 *
 *     frame,time,door.forward,door.backward,door.rate_forward,...
 *     1,0.016666666666666666,0,0,0,...
 *
 * The file goes through the tool's one output path (cleanup.h,
 * iskra/outfile.h): written into a temporary while the render runs and
 * renamed into place at its end, so a reader never sees half of one.
 * The hooks, so the render command need not know more:
 *
 *     probes_opts po = {0};
 *     ... if ((r = probes_args_take(&po, argc, argv, &i)) != 0) { if (r < 0) return 2; continue; }
 *     ... before frame 0: if (probes_begin(&po, fx)) rc = 1;
 *     ... after frame f: if (probes_after_frame(&po, fx, f)) rc = 1;
 *     ... at the end: if (probes_finish(&po)) rc = 1;   (on an error path: probes_abort(&po))
 */
#ifndef ISKRA_TOOL_PROBES_CSV_H
#define ISKRA_TOOL_PROBES_CSV_H

#include "iskra/effect.h"
#include "iskra/outfile.h"

typedef struct probes_opts {
    const char *path; /* --probes FILE.csv, or NULL */
    isk_outfile out;
    int open;
} probes_opts;

/* --probes at argv[*i]: 1 taken, 0 not ours, -1 error (printed). */
int probes_args_take(probes_opts *o, int argc, char **argv, int *i);
/* Opens the file and writes the header; 0, or 1 after printing why. */
int probes_begin(probes_opts *o, const isk_effect *fx);
/* The row of frame f (f >= 1); 0 or 1 after printing why. */
int probes_after_frame(probes_opts *o, const isk_effect *fx, long f);
int probes_finish(probes_opts *o);
void probes_abort(probes_opts *o);

#endif
