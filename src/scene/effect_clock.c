/* SPDX-License-Identifier: MIT */
/* The effect's clocks (fx_clock, effect_internal.h): the time of a frame,
 * and a group's time at the effect's frame.  Every file that needs a time
 * reads it here, so none of them calls back into the frame loop. */
#include "effect_internal.h"

double isk__fx_clock_at(const fx_clock *c, long frame) { return c->t0 + (double)(frame - c->f0) * c->step; }

double isk__fx_group_time(const isk_effect *e, const fx_group *g)
{
    return isk__fx_clock_at(&g->clock, e->frame + g->frame_offset);
}

int isk__fx_group_started(const isk_effect *e, const fx_group *g) { return e->frame + g->frame_offset >= 0; }

int isk__fx_group_runs(const isk_effect *e, const fx_group *g)
{
    return isk__fx_group_started(e, g) && !g->def->motion.paused;
}
