/* SPDX-License-Identifier: MIT */
/* Fixed-step accumulator with a cap on steps per frame. */
#include "iskra/timestep.h"

#include <math.h>

isk_status isk_timestep_init(isk_timestep *ts, double dt, int max_steps)
{
    if (!ts)
        return ISK_ERR_NULL;
    if (!isfinite(dt))
        return ISK_ERR_NAN;
    if (!(dt > 0.0) || max_steps < 1)
        return ISK_ERR_RANGE;
    ts->dt = dt;
    ts->max_steps = max_steps;
    ts->accumulated = 0.0;
    ts->dropped = 0.0;
    ts->steps = 0;
    return ISK_OK;
}

/* Usable: initialised (a zeroed struct is not). */
static int ready(const isk_timestep *ts)
{
    return ts && ts->dt > 0.0 && isfinite(ts->dt) && ts->max_steps >= 1;
}

/* Steps handed out one at a time (each subtraction exact as before); more
 * than this are taken in one division, so max_steps = INT_MAX costs no
 * two-billion-iteration loop. */
#define ONE_BY_ONE 64

int isk_timestep_advance(isk_timestep *ts, double frame_seconds)
{
    if (!ready(ts))
        return 0;
    if (!(frame_seconds > 0.0) || !isfinite(frame_seconds))
        frame_seconds = 0.0;
    /* Never let one frame ask for more than max_steps + 1 steps' worth: a
     * 10-minute stall must not turn into a 10-minute loop below.  (In
     * double: max_steps + 1 overflows int for INT_MAX.) */
    double cap = ts->dt * ((double)ts->max_steps + 1.0);
    if (frame_seconds > cap) {
        ts->dropped += frame_seconds - cap;
        frame_seconds = cap;
    }
    ts->accumulated += frame_seconds;
    int n = 0;
    while (ts->accumulated >= ts->dt && n < ts->max_steps && n < ONE_BY_ONE) {
        ts->accumulated -= ts->dt;
        n++;
    }
    if (ts->accumulated >= ts->dt && n < ts->max_steps) {
        double whole = floor(ts->accumulated / ts->dt);
        double room = (double)(ts->max_steps - n);
        if (whole > room)
            whole = room;
        ts->accumulated -= whole * ts->dt;
        n += (int)whole;
        if (ts->accumulated < 0.0)
            ts->accumulated = 0.0;
        while (ts->accumulated >= ts->dt && n < ts->max_steps) { /* the division's rounding */
            ts->accumulated -= ts->dt;
            n++;
        }
    }
    if (ts->accumulated >= ts->dt) {
        /* Could not keep up: keep the fraction, drop the whole steps. */
        double whole = floor(ts->accumulated / ts->dt) * ts->dt;
        ts->dropped += whole;
        ts->accumulated -= whole;
        if (!(ts->accumulated >= 0.0) || ts->accumulated >= ts->dt)
            ts->accumulated = 0.0;
    }
    ts->steps += n;
    return n;
}

double isk_timestep_alpha(const isk_timestep *ts)
{
    if (!ready(ts))
        return 0.0;
    double a = ts->accumulated / ts->dt;
    return a < 0.0 ? 0.0 : (a >= 1.0 ? 0.0 : a);
}

void isk_timestep_reset(isk_timestep *ts)
{
    if (ts)
        ts->accumulated = 0.0;
}
