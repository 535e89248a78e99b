/* SPDX-License-Identifier: MIT */
/* tools/iskra/study.h — shared pieces of `iskra bench accuracy`: options,
 * the clock, a growing text buffer for CSV, and output files written to a
 * temporary name and renamed (a failed or interrupted run never leaves a
 * half-written CSV or PNG behind).
 *
 * Each study is one function `int study_X(const study_opts *o)` returning
 * 0 on success, 1 on a runtime failure (already reported on stderr); it
 * prints its tables to stdout and writes o->out_dir/<name>.csv and .png.
 *
 * Timing lives here, in the tool, never in the library (the library has
 * no clock): library calls compute the errors, the tool times them. */
#ifndef ISKRA_TOOL_STUDY_H
#define ISKRA_TOOL_STUDY_H

#include <stddef.h>

#include "iskra/chart.h"

typedef struct study_opts {
    const char *out_dir; /* created if missing */
    int quick;           /* 1: fewer repetitions and smaller sweeps (CI smoke run) */
} study_opts;

/* Monotonic seconds. */
double study_now(void);
/* Median of n values (sorts v in place); n >= 1. */
double study_median(double *v, int n);

typedef struct study_buf {
    char *text;
    size_t len, cap;
    int failed; /* an allocation failed; the text is incomplete */
} study_buf;

/* Appends printf-style text (sets failed on allocation failure). */
void study_printf(study_buf *b, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void study_buf_free(study_buf *b);

/* Writes b to out_dir/name atomically.  Returns 0, or 1 after printing
 * "iskra bench: <path>: <reason>" to stderr. */
int study_write_text(const study_opts *o, const char *name, const study_buf *b);

/* Draws the chart on a w x h canvas and writes out_dir/name as PNG.
 * Returns 0, or 1 after printing the reason. */
int study_write_chart(const study_opts *o, const char *name, const isk_chart *ch, int w, int h);

/* The studies (one file each). */
int study_integrators(const study_opts *o); /* study_integrators.c */
int study_longrun(const study_opts *o);     /* study_longrun.c */
int study_thesis(const study_opts *o);      /* study_thesis.c */
int study_knobs(const study_opts *o);       /* study_knobs.c */
int study_invariants(const study_opts *o);   /* study_invariants.c */
int study_budget(const study_opts *o);       /* study_budget.c */
int study_spring_floor(const study_opts *o); /* study_spring_floor.c */
/* `--scene SCENE [--frames N]` (study_scene.c): returns 0, 1 on a runtime
 * failure, 2 on a scene error (printed). */
int study_scene(const study_opts *o, const char *scene, long frames);

#endif
