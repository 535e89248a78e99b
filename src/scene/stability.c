/* SPDX-License-Identifier: MIT */
/* The drag edges of the integrators, and where a scene sits against them
 * (iskra/stability.h: the amplifications and their edges). */
#include "iskra/stability.h"

#include <math.h>

/* Indexed by method; INFINITY: no edge. */
static const double DRAG_EDGE[ISK_INTEGRATOR_COUNT] = {
    [ISK_INTEGRATE_SEMI_EULER] = 2.0,
    [ISK_INTEGRATE_EULER] = 2.0,
    [ISK_INTEGRATE_VERLET] = 4.0,
    [ISK_INTEGRATE_RK4] = 2.785293563405282,
    [ISK_INTEGRATE_EXACT_DRAG] = INFINITY,
    [ISK_INTEGRATE_LEAPFROG] = INFINITY,
    [ISK_INTEGRATE_YOSHIDA4] = 1.134424004107524,
    [ISK_INTEGRATE_STRANG] = INFINITY,
};

/* Indexed by method; 0: every step grows. */
static const double SPRING_EDGE[ISK_INTEGRATOR_COUNT] = {
    [ISK_INTEGRATE_SEMI_EULER] = 2.0,
    [ISK_INTEGRATE_EULER] = 0.0,
    [ISK_INTEGRATE_VERLET] = 2.0,
    [ISK_INTEGRATE_RK4] = 2.8284271247461903, /* 2 sqrt 2 */
    [ISK_INTEGRATE_EXACT_DRAG] = 0.0,
    [ISK_INTEGRATE_LEAPFROG] = 2.0,
    [ISK_INTEGRATE_YOSHIDA4] = 1.5734019474345398,
    [ISK_INTEGRATE_STRANG] = 2.0,
};

double isk_integrator_spring_edge(isk_integrator method)
{
    if (method < 0 || method >= ISK_INTEGRATOR_COUNT)
        return NAN;
    return SPRING_EDGE[method];
}

double isk_integrator_drag_edge(isk_integrator method)
{
    if (method < 0 || method >= ISK_INTEGRATOR_COUNT)
        return NAN;
    return DRAG_EDGE[method];
}

isk_integrator isk_effect_def_emitter_integrator(const isk_effect_def *d, int i)
{
    if (!d || i < 0 || i >= d->nemitters)
        return ISK_INTEGRATE_INHERIT;
    isk_integrator m = d->emitters[i].motion.integrator;
    return m == ISK_INTEGRATE_INHERIT ? d->integrator : m;
}

int isk_effect_def_emitter_substeps(const isk_effect_def *d, int i)
{
    if (!d || i < 0 || i >= d->nemitters)
        return 0;
    int n = d->emitters[i].motion.substeps;
    return n > 0 ? n : d->substeps;
}

double isk_effect_def_drag_ratio(const isk_effect_def *d, int i)
{
    int n = isk_effect_def_emitter_substeps(d, i);
    if (n <= 0)
        return 0.0;
    const isk_emitter_def *em = &d->emitters[i];
    double b = 0.0;
    for (int k = 0; k < em->motion.nforces; k++) {
        int f = em->motion.forces[k];
        if (f >= 0 && f < d->nforces && d->forces[f].kind == ISK_FORCE_DRAG)
            b += d->forces[f].b;
    }
    if (!(b > 0.0) || !(em->launch.mass > 0.0) || !(d->speed_divisor > 0.0))
        return 0.0;
    return b * (d->dt / (double)n / d->speed_divisor) / em->launch.mass;
}

double isk_effect_def_spring_ratio(const isk_effect_def *d, int i)
{
    int n = isk_effect_def_emitter_substeps(d, i);
    if (n <= 0)
        return 0.0;
    const isk_emitter_def *em = &d->emitters[i];
    double w2 = 0.0;
    for (int k = 0; k < em->motion.nforces; k++) {
        int f = em->motion.forces[k];
        if (f < 0 || f >= d->nforces || d->forces[f].kind != ISK_FORCE_POTENTIAL)
            continue;
        isk_potential p = d->forces[f].pot;
        if (isk_potential_set_law(&p, d->forces[f].law, d->forces[f].exponent) != ISK_OK || !p.enabled)
            continue;
        const double kq = p.k * p.charge;
        const double core = p.P == 0 ? 1.0 : p.min_dist > 0 ? pow(p.min_dist, p.P) : 0.0;
        if (kq > 0 && core > 0)
            w2 = fmax(w2, kq * fmax(1.0, fabs(p.x_mult)) / core);
    }
    if (!(w2 > 0.0) || !(em->launch.mass > 0.0) || !(d->speed_divisor > 0.0))
        return 0.0;
    return sqrt(w2 / em->launch.mass) * (d->dt / (double)n / d->speed_divisor);
}
