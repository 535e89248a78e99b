/* SPDX-License-Identifier: MIT */
/* The particle system: stage pipeline per frame (see iskra/system.h). */
#include "iskra/system.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sim/stage.h"

isk_status isk_system_init(isk_system *s, uint64_t seed, size_t capacity)
{
    if (!s)
        return ISK_ERR_NULL;
    memset(s, 0, sizeof *s);
    isk_rng_seed(&s->rng, seed);
    s->integrator = ISK_INTEGRATE_SEMI_EULER;
    s->substeps = 1;
    s->speed_divisor = 1.0;
    s->bounds.sides = 0;
    s->bounds.xmin = 0.0;
    s->bounds.xmax = 1.0;
    s->bounds.ymin = 0.0;
    s->bounds.ymax = 1.0;
    s->bounce_in_step = 0;
    s->ageing = 0;
    s->auto_move_potentials = 1;
    s->coulomb_kick = ISK_KICK_ALL;
    s->explode_limit = ISK_EXPLODE_THESIS_LIMIT;
    s->forces.centre = ISK_FIDELITY_SOUND;
    return isk_particles_init(&s->particles, capacity, 0);
}

void isk_system_free(isk_system *s)
{
    if (!s)
        return;
    isk_particles_free(&s->particles);
    free(s->forces.pot);
    free(s->jobs);
    s->forces.pot = NULL;
    s->forces.npot = 0;
    s->pot_capacity = 0;
    s->jobs = NULL;
    s->njobs = s->job_capacity = 0;
}

/* A strength within [lo, ISK_STRENGTH_MAX] (iskra/limits.h). */
static isk_status check_strength(double v, double lo)
{
    if (!isfinite(v))
        return ISK_ERR_NAN;
    return v >= lo && v <= ISK_STRENGTH_MAX ? ISK_OK : ISK_ERR_RANGE;
}

isk_status isk_system_set_gravity(isk_system *s, double g)
{
    if (!s)
        return ISK_ERR_NULL;
    /* Negative gravity (upwards) is a legitimate scene. */
    isk_status st = check_strength(g, -ISK_STRENGTH_MAX);
    if (st == ISK_OK)
        s->forces.gravity = g;
    return st;
}

isk_status isk_system_set_drag(isk_system *s, double b)
{
    if (!s)
        return ISK_ERR_NULL;
    isk_status st = check_strength(b, 0.0);
    if (st == ISK_OK)
        s->forces.drag = b;
    return st;
}

isk_status isk_system_set_integrator(isk_system *s, isk_integrator method)
{
    if (!s)
        return ISK_ERR_NULL;
    if ((unsigned)method >= ISK_INTEGRATOR_COUNT)
        return ISK_ERR_RANGE;
    s->integrator = method;
    return ISK_OK;
}

isk_status isk_system_set_substeps(isk_system *s, int substeps)
{
    if (!s)
        return ISK_ERR_NULL;
    if (substeps < 1 || substeps > ISK_SUBSTEPS_MAX)
        return ISK_ERR_RANGE;
    s->substeps = substeps;
    return ISK_OK;
}

isk_status isk_system_set_bounds(isk_system *s, const isk_bounds *b, int bounce_in_step)
{
    if (!s || !b)
        return ISK_ERR_NULL;
    isk_status st = isk_bounds_validate(b);
    if (st != ISK_OK)
        return st;
    s->bounds = *b;
    s->bounce_in_step = bounce_in_step != 0;
    return ISK_OK;
}

isk_status isk_system_add_potential(isk_system *s, const isk_potential *pot, int *id)
{
    if (!s || !pot)
        return ISK_ERR_NULL;
    isk_status st = isk_potential_validate(pot);
    if (st != ISK_OK)
        return st;
    if (s->forces.npot == s->pot_capacity) {
        size_t cap = s->pot_capacity ? s->pot_capacity * 2 : 4;
        isk_potential *np = realloc(s->forces.pot, cap * sizeof *np);
        if (!np)
            return ISK_ERR_NOMEM;
        s->forces.pot = np;
        s->pot_capacity = cap;
    }
    isk_potential *dst = &s->forces.pot[s->forces.npot++];
    *dst = *pot;
    dst->id = ++s->next_potential_id;
    if (id)
        *id = dst->id;
    return ISK_OK;
}

isk_potential *isk_system_potential(isk_system *s, int id)
{
    if (!s)
        return NULL;
    for (size_t k = 0; k < s->forces.npot; k++)
        if (s->forces.pot[k].id == id)
            return &s->forces.pot[k];
    return NULL;
}

void isk_system_move_potentials(isk_system *s, double param)
{
    if (!s)
        return;
    for (size_t k = 0; k < s->forces.npot; k++)
        isk_potential_move(&s->forces.pot[k], param);
}

static isk_status push_job(isk_system *s, const isk_multi_coulomb *mc)
{
    if (s->njobs == s->job_capacity) {
        size_t cap = s->job_capacity ? s->job_capacity * 2 : 4;
        isk_multi_coulomb *nj = realloc(s->jobs, cap * sizeof *nj);
        if (!nj)
            return ISK_ERR_NOMEM;
        s->jobs = nj;
        s->job_capacity = cap;
    }
    s->jobs[s->njobs++] = *mc;
    return ISK_OK;
}

isk_status isk_system_explode(isk_system *s, isk_explosion kind, double cx, double cy, size_t count)
{
    if (!s)
        return ISK_ERR_NULL;
    isk_particles *p = &s->particles;
    size_t lim = s->explode_limit;
    switch (kind) {
    case ISK_EXPLOSION_RING: return isk_explode_ring(p, cx, cy, count, lim);
    case ISK_EXPLOSION_UNIFORM: return isk_explode_uniform(p, &s->rng, cx, cy, count, lim);
    case ISK_EXPLOSION_GAUSS: return isk_explode_gauss(p, &s->rng, cx, cy, count, lim);
    case ISK_EXPLOSION_COULOMB:
        return isk_explode_coulomb(p, &s->rng, cx, cy, count, lim, s->coulomb_kick);
    case ISK_EXPLOSION_MULTI_COULOMB: {
        isk_multi_coulomb mc;
        isk_status st = isk_multi_coulomb_start(&mc, cx, cy, count, lim);
        if (st != ISK_OK)
            return st;
        /* Batch 1 lands now (the thesis pushes it synchronously). */
        st = isk_multi_coulomb_release(&mc, p, &s->rng, NULL);
        if (st != ISK_OK)
            return st;
        return isk_multi_coulomb_done(&mc) ? ISK_OK : push_job(s, &mc);
    }
    default: return ISK_ERR_RANGE;
    }
}

isk_status isk_system_add_layer(isk_system *s, double xmin, double xmax, double ymin, double ymax,
                                size_t count)
{
    if (!s)
        return ISK_ERR_NULL;
    return isk_explode_layer(&s->particles, &s->rng, xmin, xmax, ymin, ymax, count, s->explode_limit);
}

static isk_status release_jobs(isk_system *s)
{
    size_t w = 0;
    isk_status st = ISK_OK;
    for (size_t k = 0; k < s->njobs; k++) {
        if (st == ISK_OK)
            st = isk_multi_coulomb_release(&s->jobs[k], &s->particles, &s->rng, NULL);
        if (!isk_multi_coulomb_done(&s->jobs[k]))
            s->jobs[w++] = s->jobs[k];
    }
    s->njobs = w;
    return st;
}

/* The fields a step reads, against what scene files accept (iskra/limits.h):
 * the system is plain data, so they are checked where they are used. */
static isk_status check_fields(const isk_system *s)
{
    const isk_forces *f = &s->forces;
    if (!isfinite(s->speed_divisor) || !isfinite(f->gravity) || !isfinite(f->ax) || !isfinite(f->ay) ||
        !isfinite(f->drag))
        return ISK_ERR_NAN;
    if (s->substeps < 1 || s->substeps > ISK_SUBSTEPS_MAX || !(s->speed_divisor >= ISK_SPEED_DIVISOR_MIN) ||
        !(s->speed_divisor <= ISK_SPEED_DIVISOR_MAX) || (unsigned)s->integrator >= ISK_INTEGRATOR_COUNT)
        return ISK_ERR_RANGE;
    if (check_strength(f->gravity, -ISK_STRENGTH_MAX) != ISK_OK || check_strength(f->ax, -ISK_STRENGTH_MAX) != ISK_OK ||
        check_strength(f->ay, -ISK_STRENGTH_MAX) != ISK_OK || check_strength(f->drag, 0.0) != ISK_OK)
        return ISK_ERR_RANGE;
    if (f->npot && !f->pot)
        return ISK_ERR_NULL;
    for (size_t k = 0; k < f->npot; k++) {
        isk_status st = isk_potential_validate(&f->pot[k]);
        if (st != ISK_OK)
            return st;
    }
    return ISK_OK;
}

isk_status isk_system_step(isk_system *s, double dt)
{
    if (!s)
        return ISK_ERR_NULL;
    if (!isfinite(dt))
        return ISK_ERR_NAN;
    if (dt < 0.0 || dt > ISK_DT_MAX)
        return ISK_ERR_RANGE;
    isk_status fs = check_fields(s);
    if (fs != ISK_OK)
        return fs;
    int bounce = s->bounce_in_step && s->bounds.sides != 0;
    if (bounce && isk_bounds_validate(&s->bounds) != ISK_OK)
        return ISK_ERR_RANGE;

    isk_status st = release_jobs(s);
    if (st != ISK_OK)
        return st;

    /* The system's fields compile into the block runner's list (the same
     * runner the effect steps through): motion (remembering the start state),
     * walls, ageing.
     * Sound walls bounce at the time of impact, from the state before the
     * move (iskra/impact.h). */
    isk_pipeline pl;
    isk__pipeline_init(&pl);
    int potentials = 0;
    for (size_t k = 0; k < s->forces.npot; k++)
        potentials |= s->forces.pot[k].enabled;
    const int start = bounce && s->bounds.mode == ISK_BOUNCE_REFLECT && potentials;
    isk_stage *motion = isk__pipeline_add(&pl, &isk__stage_motion);
    isk__stage_motion_init(motion, s->integrator, &s->forces);
    motion->u.motion.remember = start;
    if (bounce && start && isk__contacts_redo(&s->forces, s->integrator)) {
        /* the contact pass flies the rest of a step after a bounce with the
         * integrator: a bounce keeps the energy to its order (iskra/contacts.h) */
        isk_stage *c = isk__pipeline_add(&pl, &isk__stage_deflect);
        c->u.deflect.walls = &s->bounds;
        c->u.deflect.drag = s->forces.drag;
        c->u.deflect.redo = (isk_contact_integrator){s->integrator, &s->forces};
        c->u.deflect.redo_on = 1;
    } else if (bounce) {
        isk_stage *w = isk__pipeline_add(&pl, &isk__stage_walls);
        w->u.walls.b = &s->bounds;
        w->u.walls.drag = s->forces.drag;
        w->u.walls.start = start;
        w->u.walls.ax = s->forces.ax;
        w->u.walls.ay = s->forces.ay - s->forces.gravity;
        w->u.walls.offset = isk_integrator_velocity_offset(s->integrator);
    }
    if (s->ageing)
        isk__pipeline_add(&pl, &isk__stage_age);

    isk_particles *p = &s->particles;
    const int N = s->substeps;
    const double h = dt / (double)N / s->speed_divisor;
    /* Substeps outer, particles inner, like the thesis: a potential switched
     * off by particle i in substep j is off for every particle in substep
     * j+1.  A state gone non-finite is removed and counted (limits.h). */
    for (int j = 0; j < N; j++) {
        isk__pipeline_run(&pl, p, 0, p->count, h, &s->scratch, NULL);
        if (s->scratch.nonfinite) {
            s->removed_nonfinite += isk_particles_remove_nonfinite(p);
            s->scratch.nonfinite = 0;
        }
    }
    const double frame = h * (double)N; /* the thesis's vremenskiPomak*preciznost */
    s->time += frame;
    for (size_t k = 0; k < s->njobs; k++)
        isk_multi_coulomb_advance(&s->jobs[k], frame);
    if (s->ageing)
        isk_particles_cull(p);
    if (s->auto_move_potentials)
        isk_system_move_potentials(s, frame);
    return ISK_OK;
}

void isk_system_bounce(isk_system *s)
{
    if (!s || s->bounds.sides == 0 || isk_bounds_validate(&s->bounds) != ISK_OK)
        return;
    isk_bounds_apply(&s->bounds, &s->particles, 0, s->particles.count);
}
