/* SPDX-License-Identifier: MIT */
/* A progress bar on stderr for long renders: drawn only when stderr is a
 * terminal and the work has run for more than half a second, so scripted
 * and quick runs stay silent. */
#ifndef ISKRA_TOOL_PROGRESS_H
#define ISKRA_TOOL_PROGRESS_H

typedef struct progress {
    long total;
    double start;     /* seconds (monotonic clock) */
    double last_draw;
    int enabled;      /* stderr is a terminal */
    int shown;        /* something was drawn (needs a final newline) */
} progress;

/* Monotonic seconds. */
double progress_now(void);
void progress_start(progress *p, long total);
void progress_update(progress *p, long done);
/* Completes the bar (if it was shown) with a newline. */
void progress_end(progress *p);

#endif
