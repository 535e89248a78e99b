/* SPDX-License-Identifier: MIT */
/* src/scene/effect_style.h — a particle's colour and size as its group
 * draws it (internal, header-only: every draw inlines it in its loop).
 *
 *     const int vary = fx_varies(g);                 // once per draw
 *     double mult;
 *     isk_color col = fx_style(g, &g->store, i, vary, &mult);   // per particle
 *
 * The colour: the emitter's, or the particle's own (color_pick), or its
 * colour over life at its normalised age, times its alpha over life; the
 * size multiplier: its size over life (the ramps are baked at create,
 * effect_draws.c). */
#ifndef ISKRA_SCENE_EFFECT_STYLE_H
#define ISKRA_SCENE_EFFECT_STYLE_H

#include <math.h>

#include "effect_internal.h"

/* The colour, alpha and size multiplier of particle i at normalised age t. */
static inline isk_color fx_style_at(const fx_group *g, const isk_particles *p, size_t i, double t, double *size_mult)
{
    isk_color col = p->color ? p->color[i] : g->def->look.color;
    if (g->has_color_ramp) {
        isk_color ramp = isk_color_gradient_at(&g->color_ramp, t);
        /* a picked base colour (color_pick) is multiplied, channel by
         * channel, div255(base * ramp); otherwise the ramp is the colour */
        if (g->def->look.color_pick.n && p->color)
            ramp = isk_rgba((uint8_t)((col.r * ramp.r + 127) / 255), (uint8_t)((col.g * ramp.g + 127) / 255),
                            (uint8_t)((col.b * ramp.b + 127) / 255), (uint8_t)((col.a * ramp.a + 127) / 255));
        col = ramp;
    }
    if (g->has_alpha_ramp) {
        double a = col.a * isk_scalar_gradient_at(&g->alpha_ramp, t);
        col.a = (uint8_t)(a >= 255.0 ? 255 : (a > 0 ? (int)(a + 0.5) : 0));
    }
    *size_mult = g->has_size_ramp ? isk_scalar_gradient_at(&g->size_ramp, t) : 1.0;
    return col;
}

/* Whether anything varies per particle: a group-level fact, so the
 * branch in fx_style always goes the same way. */
static inline int fx_varies(const fx_group *g)
{
    return g->has_color_ramp || g->has_alpha_ramp || g->has_size_ramp || g->store.color;
}

/* Particle i's colour and size multiplier (vary: fx_varies(g)). */
static inline isk_color fx_style(const fx_group *g, const isk_particles *p, size_t i, int vary, double *mult)
{
    *mult = 1.0;
    if (!vary)
        return g->def->look.color;
    double t = isfinite(p->life[i]) && p->life[i] > 0 ? p->age[i] / p->life[i] : 0.0;
    return fx_style_at(g, p, i, t, mult);
}

#endif
