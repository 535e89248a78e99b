/* SPDX-License-Identifier: MIT */
/* The one rule every source's new particles follow (isk__fx_adopt): explosions
 * (effect_group.c), stream births (effect_stream.c) and sub-emitters'
 * children (effect_events.c) all end here, so lifetimes, oscillation state
 * and looks are drawn the same way, in the same order. */
#include <math.h>

#include "effect_internal.h"

/* Lifetime life + U*range (one uniform, only with a finite life and a
 * range), then the oscillation state: omega, amplitude, and with
 * osc_random_phase the phase (the offset starts where the sine is, so the
 * first step moves the particle by the change only); last the looks
 * (angle, spin, size, colour: effect_looks.c). */
void isk__fx_adopt(isk_effect *e, fx_group *g, size_t from)
{
    const isk_emitter_def *em = g->def;
    isk_particles *p = &g->store;
    const int ranged = isfinite(em->life.seconds) && em->life.range > 0;
    for (size_t i = from; i < p->count; i++)
        p->life[i] = em->life.seconds + (ranged ? em->life.range * isk_rng_uniform(&g->rng) : 0.0);
    for (size_t i = from; p->osc_amp && i < p->count; i++) {
        p->osc_omega[i] = isk_rng_range(&g->rng, em->motion.osc_omega_min, em->motion.osc_omega_max);
        p->osc_amp[i] = isk_rng_range(&g->rng, em->motion.osc_amplitude_min, em->motion.osc_amplitude_max);
        p->osc_phase[i] = 0.0;
        p->osc_offset[i] = 0.0;
        if (em->motion.osc_random_phase) {
            double ph = isk_rng_range(&g->rng, 0.0, 6.283185307179586);
            p->osc_phase[i] = ph;
            p->osc_offset[i] = p->osc_amp[i] * isk_sinlut_eval(&e->sin_table, em->motion.osc_table, ph);
        }
    }
    /* last: the looks' draws come after every draw above (effect_looks.c),
     * then the motion's ranges (effect_ranges.c), each from its own stream */
    isk__fx_looks_adopt(g, from);
    isk__fx_ranges_adopt(g, from);
}
