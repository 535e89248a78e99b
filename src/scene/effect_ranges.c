/* SPDX-License-Identifier: MIT */
/* Per-particle ranges of the motion: radial_accel_range,
 * tangential_accel_range, wind_range and slowing_range (LÖVE's and Godot's
 * random radial, tangential and linear accelerations and damping).
 *
 * Each particle draws its own part U*range at birth, from the range's own
 * random stream (fx_stream), and keeps it in a column of its own
 * (ISK_PARTICLES_RADIAL, ...): the field stage (src/sim/stage_field.c)
 * adds the accelerations' parts to the emitter's values, the slow stage
 * its slowing's (src/sim/stage_fire.c).  A range at 0 has no column, no
 * draw and no stage, so it costs and changes nothing; the parts are kept
 * apart from the emitter's values, so a live change of radial_accel or
 * slowing reaches every particle at once, as without a range. */
#include "effect_internal.h"

unsigned isk__fx_ranges_columns(const isk_emitter_def *em)
{
    const isk_emitter_motion *m = &em->motion;
    return (m->radial_accel_range > 0 ? ISK_PARTICLES_RADIAL : 0u) |
           (m->tangential_accel_range > 0 ? ISK_PARTICLES_TANGENTIAL : 0u) |
           (m->wind_range.x != 0 || m->wind_range.y != 0 ? ISK_PARTICLES_WIND : 0u) |
           (m->slowing_range > 0 ? ISK_PARTICLES_SLOWING : 0u);
}

/* New particles [from, count): one draw per range that asks, x then y
 * for the wind.  A column kept after its range went back to 0 (a live
 * change) gets 0, with no draw. */
void isk__fx_ranges_adopt(fx_group *g, size_t from)
{
    const isk_emitter_motion *m = &g->def->motion;
    isk_particles *p = &g->store;
    isk_rng *rng = g->streams;
    for (size_t i = from; p->radial_extra && i < p->count; i++)
        p->radial_extra[i] =
            m->radial_accel_range > 0 ? m->radial_accel_range * isk_rng_uniform(&rng[FX_STREAM_RADIAL]) : 0.0;
    for (size_t i = from; p->tangential_extra && i < p->count; i++)
        p->tangential_extra[i] = m->tangential_accel_range > 0
                                     ? m->tangential_accel_range * isk_rng_uniform(&rng[FX_STREAM_TANGENTIAL])
                                     : 0.0;
    for (size_t i = from; p->wind_x && i < p->count; i++) {
        const int on = m->wind_range.x != 0 || m->wind_range.y != 0;
        p->wind_x[i] = on ? m->wind_range.x * isk_rng_uniform(&rng[FX_STREAM_WIND]) : 0.0;
        p->wind_y[i] = on ? m->wind_range.y * isk_rng_uniform(&rng[FX_STREAM_WIND]) : 0.0;
    }
    for (size_t i = from; p->slowing_extra && i < p->count; i++)
        p->slowing_extra[i] = m->slowing_range > 0 ? m->slowing_range * isk_rng_uniform(&rng[FX_STREAM_SLOWING]) : 0.0;
}

isk_status isk__fx_ranges_live(fx_group *g)
{
    const unsigned want = isk__fx_ranges_columns(g->def);
    return want & ~g->store.flags ? isk_particles_add_columns(&g->store, want) : ISK_OK;
}
