/* SPDX-License-Identifier: MIT */
/* examples/trajectory_csv.h — the --csv output of the single-particle figures
 * (fig10–fig14).
 *
 * One header line, then one line per loop iteration (or animation frame):
 *
 *     step,drawn_x,drawn_y,x,y,vx,vy
 *
 * step counts from 1; drawn_x, drawn_y are the world position passed to the
 * draw call (after the move, before the bounce); x, y, vx, vy are the state
 * at the end of the iteration (after zarobi).  Every number is printed with
 * "%.17g", which round-trips a double, so the file shows the exact bits; in
 * faithful mode they equal what the thesis's JavaScript computes
 * (tests/thesis_js/trajectories.js, tests/test_thesis_csv.c).
 */
#ifndef ISKRA_EXAMPLES_TRAJECTORY_CSV_H
#define ISKRA_EXAMPLES_TRAJECTORY_CSV_H

#include <stdio.h>
#include <string.h>

#include "iskra/teach.h"

/* Opens PATH ("-" = stdout) and writes the header; NULL path: no CSV.
 * Returns 0 on success, 1 (after a message) when the file cannot be opened. */
static inline int csv_open(FILE **f, const char *path, const char *prog)
{
    *f = NULL;
    if (!path)
        return 0;
    *f = strcmp(path, "-") ? fopen(path, "w") : stdout;
    if (!*f) {
        fprintf(stderr, "%s: cannot write %s\n", prog, path);
        return 1;
    }
    fputs("step,drawn_x,drawn_y,x,y,vx,vy\n", *f);
    return 0;
}

static inline void csv_row(FILE *f, long step, isk_vec2 drawn, const isk_particle *c)
{
    if (f)
        fprintf(f, "%ld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", step, drawn.x, drawn.y, c->mp.r.x,
                c->mp.r.y, c->mp.v.x, c->mp.v.y);
}

/* Closes the file; returns 1 (after a message) if anything failed to write. */
static inline int csv_close(FILE *f, const char *path, const char *prog)
{
    if (!f)
        return 0;
    int bad = ferror(f) != 0;
    if (f == stdout)
        bad |= fflush(f) != 0;
    else
        bad |= fclose(f) != 0;
    if (bad)
        fprintf(stderr, "%s: error writing %s\n", prog, path);
    return bad;
}

#endif
