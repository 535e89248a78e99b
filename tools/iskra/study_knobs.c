/* SPDX-License-Identifier: MIT */
/* `iskra bench accuracy --only knobs`: what the library's accuracy knobs
 * cost and buy, each measured against a known answer:
 *
 *   sine            the sine table's sizes and lookups against libm sin
 *   campfire        the same lookups on the campfire's picture
 *   emission_rate   the fire thesis's per-frame count rounding against the
 *                   fractional accumulator
 *   emission_birth  back-dated births against the thesis's jitter and
 *                   end-of-frame births
 *   ellipse         the area-uniform ellipse sampler against the
 *                   particle-engine thesis's
 *   float           a float copy of the semi-implicit Euler kernel against
 *                   the library's double path (an experiment: the library
 *                   has no float state)
 *
 * Each part lives in its own file (study_knobs_<part>.c), prints its table,
 * writes <name>.csv and <name>.png, and returns 0, or 1 when a measurement
 * contradicts a documented claim or an output cannot be written.  Every part
 * runs even if an earlier one failed, so one failure does not hide others. */
#include <stdio.h>

#include "study.h"

/* Defined in the part files.  Declared here rather than in study.h, which
 * is shared by every study and names only their entry points. */
int study_knobs_sine(const study_opts *o);
int study_knobs_campfire(const study_opts *o);
int study_knobs_emission(const study_opts *o);
int study_knobs_ellipse(const study_opts *o);
int study_knobs_float(const study_opts *o);

int study_knobs(const study_opts *o)
{
    int (*const parts[])(const study_opts *) = {study_knobs_sine, study_knobs_campfire, study_knobs_emission,
                                                 study_knobs_ellipse, study_knobs_float};
    int rc = 0;
    for (size_t i = 0; i < sizeof parts / sizeof parts[0]; i++) {
        if (parts[i](o) != 0)
            rc = 1;
        fflush(stdout);
    }
    return rc;
}
