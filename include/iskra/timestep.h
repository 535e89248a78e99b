/* SPDX-License-Identifier: MIT */
/* iskra/timestep.h — a fixed simulation step driven by a variable frame clock.
 *
 * Interactive programs get frames at whatever rate the display allows, but
 * the simulation must advance in equal steps of dt so that it is the same
 * simulation as an offline render ("Fix Your Timestep!").  The accumulator
 * collects real time and hands out whole steps; when the machine cannot keep
 * up it drops time instead of queueing ever more steps (no spiral of death).
 *
 * Example: three frames, the last one late:
 *
 *     isk_timestep ts;
 *     if (isk_timestep_init(&ts, 1.0 / 60.0, 5) != ISK_OK) return 1;   // dt, at most 5 steps/frame
 *     double frame_seconds[3] = {0.016, 0.018, 0.5};    // measured by the caller's clock
 *     long steps = 0;
 *     for (int f = 0; f < 3; f++) {                     // each frame:
 *         int n = isk_timestep_advance(&ts, frame_seconds[f]);
 *         for (int i = 0; i < n; i++) steps++;          // step(ts.dt): isk_effect_step, ...
 *     }
 *     printf("%ld steps, %.3f s dropped\n", steps, ts.dropped);   // 7 steps, 0.417 s
 *
 * Plain data, no clock inside: the caller measures real time, so tests can
 * drive it with any sequence of frame times.
 */
#ifndef ISKRA_TIMESTEP_H
#define ISKRA_TIMESTEP_H

#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct isk_timestep {
    double dt;          /* simulation step, seconds (> 0) */
    double accumulated; /* real time not yet simulated, 0 <= accumulated < dt after advance */
    int max_steps;      /* most steps handed out per frame (>= 1) */
    double dropped;     /* total real time discarded because of max_steps */
    long long steps;    /* total steps handed out */
} isk_timestep;

/* Errors: ISK_ERR_NULL, ISK_ERR_NAN (dt not finite), ISK_ERR_RANGE (dt <= 0,
 * max_steps < 1).  Any max_steps up to INT_MAX works: many steps due at
 * once are counted arithmetically, not one by one. */
isk_status isk_timestep_init(isk_timestep *ts, double dt, int max_steps);

/* Adds frame_seconds of real time (negative or non-finite counts as 0) and
 * returns how many steps of dt to run now, at most max_steps.  When more are
 * due, the excess is dropped (counted in `dropped`) and the remainder kept
 * below one dt, so a stall is followed by normal frames, not a catch-up. */
int isk_timestep_advance(isk_timestep *ts, double frame_seconds);
/* (NULL, or an accumulator never initialised: 0 steps; alpha 0.) */

/* Fraction of a step accumulated but not simulated, in [0, 1): for
 * interpolating what is drawn between two simulation states. */
double isk_timestep_alpha(const isk_timestep *ts);

/* Forgets accumulated time (after a pause or a reset). */
void isk_timestep_reset(isk_timestep *ts);

#ifdef __cplusplus
}
#endif

#endif
