/* SPDX-License-Identifier: MIT */
/* Compilation: an emitter's definition becomes its group's lists (see
 * effect_internal.h), holding exactly the stages that emitter needs, in the
 * only order they ever run:
 *
 *   frame start:  late walls (draw_before_bounce) -> release (timed explosions)
 *   pipeline:     field (radial, tangential, turbulence) -> remember (deflectors, sound walls; kept by
 *                 the motion stage when there is one) ->
 *                 drift | integrate -> slow ->
 *                 oscillate -> walls -> deflect -> spin -> age
 *                 (a drift with an oscillate after it, and the slow between
 *                 them if any: one drift+sway stage doing them in one pass,
 *                 which describes itself as them)
 *   substep end:  carry (local space) -> hits (bounces as events) ->
 *                 cull (finite lives, killing deflectors) -> spawn (streams)
 *
 * A force no emitter references, a zero-strength force, a disabled
 * potential, or a potential switched off by its maximum distance is in no
 * list.  Recompiling is cheap (no allocation) and happens at create, reset,
 * after a live set, and after a frame in which a potential switched off. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/fast_paths.h"
#include "effect_internal.h"

/* Sums the referenced forces into the group's isk_forces; the live
 * potentials that act are picked by index from the effect's array. */
static void gather_forces(isk_effect *e, fx_group *g)
{
    const isk_effect_def *d = &e->def;
    const isk_emitter_def *em = g->def;
    isk_forces *f = &g->forces;
    memset(f, 0, sizeof *f);
    size_t np = 0;
    for (int i = 0; i < em->motion.nforces; i++) {
        const isk_force_def *fd = &d->forces[em->motion.forces[i]];
        switch (fd->kind) {
        case ISK_FORCE_GRAVITY: f->gravity += fd->g * em->motion.gravity_multiplier; break;
        case ISK_FORCE_DRAG: f->drag += fd->b; break;
        case ISK_FORCE_WIND: f->ax += fd->accel.x; f->ay += fd->accel.y; break;
        case ISK_FORCE_POTENTIAL:
            for (size_t k = 0; k < e->npots; k++) {
                const isk_potential *p = &e->pots[k];
                if (e->pot_force[k] == em->motion.forces[i] && p->enabled && p->k * p->charge != 0.0)
                    g->pick[np++] = k;
            }
            break;
        case ISK_FORCE_TURBULENCE: break; /* the field stage's (gather_field) */
        default: break;
        }
    }
    f->ay += em->motion.weight;
    f->pot = e->pots;
    f->npot = e->npots;
    f->pick = g->pick;
    f->npick = np;
    f->centre = d->centre;
}

/* The field stage's terms : the emitter-centred
 * accelerations and every referenced turbulence of non-zero strength,
 * seeded from the scene's seed and the force's index.  Its clock (time,
 * emitter position) is the frame loop's to set. */
static int gather_field(isk_effect *e, fx_group *g)
{
    const isk_effect_def *d = &e->def;
    const isk_emitter_def *em = g->def;
    isk_field *f = &g->field;
    f->radial = em->motion.radial_accel;
    f->tangential = em->motion.tangential_accel;
    f->own = (isk__fx_ranges_columns(em) & (ISK_PARTICLES_RADIAL | ISK_PARTICLES_TANGENTIAL | ISK_PARTICLES_WIND)) != 0;
    f->nturb = 0;
    for (int i = 0; i < em->motion.nforces && f->nturb < ISK_FIELD_MAX_TURB; i++) {
        const isk_force_def *fd = &d->forces[em->motion.forces[i]];
        if (fd->kind == ISK_FORCE_TURBULENCE && fd->strength != 0)
            f->turb[f->nturb++] =
                isk__field_turbulence(fd->strength, fd->scale, fd->speed, isk__noise_key(d->seed, em->motion.forces[i]));
    }
    return f->radial != 0 || f->tangential != 0 || f->nturb > 0 || f->own;
}

/* The sway's parameters, for the oscillate stage or the drift+sway one. */
static void osc_params(isk_stage_osc *o, isk_effect *e, const isk_emitter_def *em)
{
    o->decay = em->motion.osc_decay;
    o->table = &e->sin_table;
    o->mode = em->motion.osc_table;
    o->faithful = em->motion.osc_faithful;
    o->omega_min = em->motion.osc_omega_min;
    o->omega_max = em->motion.osc_omega_max;
    o->amp_min = em->motion.osc_amplitude_min;
    o->amp_max = em->motion.osc_amplitude_max;
}

#define ADD(kind) ((st = isk__pipeline_add(&g->pipeline, &(kind))) != NULL)

isk_status isk__fx_compile(isk_effect *e, fx_group *g)
{
    const isk_effect_def *d = &e->def;
    const isk_emitter_def *em = g->def;
    isk_forces *f = &g->forces;
    isk_stage *st = NULL;
    isk__pipeline_init(&g->pipeline);
    g->nframe_start = g->nsubstep_end = 0;
    /* A recompiled list may differ in anything: what rested is forgotten. */
    g->rests = 0;
    isk__rest_forget(&g->rest, 0);
    isk__fx_retain_clear(&g->retained);
    gather_forces(e, g);
    g->integrator = em->motion.integrator == ISK_INTEGRATE_INHERIT ? d->integrator : em->motion.integrator;
    g->substeps = em->motion.substeps ? em->motion.substeps : d->substeps;

    if (em->motion.ndeflectors > g->defl_cap) {
        isk_deflector *a = realloc(g->defl, sizeof *a * (size_t)em->motion.ndeflectors);
        if (!a)
            return ISK_ERR_NOMEM;
        g->defl = a;
        g->defl_cap = em->motion.ndeflectors;
    }
    g->ndefl = em->motion.ndeflectors;
    int can_kill = 0;
    for (int k = 0; k < g->ndefl; k++) {
        g->defl[k] = d->deflectors[em->motion.deflectors[k]].seg;
        can_kill |= g->defl[k].reaction == ISK_DEFLECT_KILL;
    }
    const int walls = em->motion.bounded && d->bounds.sides != 0;
    /* Reflect walls (margin 0) leave a resting particle exactly on the floor
     * line, which the view maps to y = height: one pixel outside the canvas.
     * There the drawing moves a screen coordinate in (n - 1, n] to n - 1, so
     * what the walls keep in the world stays in sight.  The thesis's walls
     * keep the thesis's picture (its browser clipped them the same way), and
     * without walls the view is a plain window. */
    g->keep_on_canvas = walls && d->bounds.mode == ISK_BOUNCE_REFLECT;

    if (walls && em->motion.draw_before_bounce)
        g->frame_start[g->nframe_start++] = &isk__fx_step_late_walls;
    if (em->born.source == ISK_SOURCE_EXPLOSION &&
        (em->born.start > 0 || em->born.explosion == ISK_EXPLOSION_MULTI_COULOMB))
        g->frame_start[g->nframe_start++] = &isk__fx_step_release;

    if ((g->has_field = gather_field(e, g)) != 0) {
        if (!ADD(isk__stage_field))
            return ISK_ERR_FULL;
        st->u.field.f = &g->field;
    }
    /* Constant accelerations with the thesis's integrator fold into one
     * drift loop that reads no mass (gravity becomes a = -g). */
    const int fast = g->integrator == ISK_INTEGRATE_SEMI_EULER && f->drag == 0 && f->npick == 0 &&
                     d->fidelity == ISK_FIDELITY_SOUND;
    const int motion_at = g->pipeline.n; /* where the remember stage goes, if the list needs it */
    const int fused_slow = fast && em->motion.slow_faithful && em->motion.slowing > 0;
    /* The thesis's jitter applies the constant part of the acceleration. */
    g->const_ax = f->ax;
    g->const_ay = f->ay - f->gravity;
    /* The sway right after the drift (no stage between them but the sound
     * order's slow): both in one pass, one stage that stands for them all. */
    /* slowing_range: a slow stage of its own, after the drift (the fused
     * drift+sway slows every particle alike) */
    const int slow_each = em->motion.slowing_range > 0;
    const int sway = g->store.osc_amp != NULL, drift_sway = ISK__FAST_FUSED && fast && sway && !slow_each;
    if (drift_sway) {
        if (!ADD(isk__stage_drift_sway))
            return ISK_ERR_FULL;
        st->u.drift_sway.ax = g->const_ax;
        st->u.drift_sway.ay = g->const_ay;
        st->u.drift_sway.slowing = em->motion.slowing > 0 ? em->motion.slowing : 0.0;
        st->u.drift_sway.order = fused_slow ? ISK_DRIFT_THESIS
            : em->motion.slowing > 0        ? ISK_DRIFT_SOUND
                                            : ISK_DRIFT_PLAIN;
        osc_params(&st->u.drift_sway.osc, e, em);
    } else if (fast) {
        if (fused_slow) {
            if (!ADD(isk__stage_drift_slow))
                return ISK_ERR_FULL;
            st->u.drift_slow.ax = g->const_ax;
            st->u.drift_slow.ay = g->const_ay;
            st->u.drift_slow.slowing = em->motion.slowing;
        } else {
            if (!ADD(isk__stage_drift))
                return ISK_ERR_FULL;
            st->u.drift.ax = g->const_ax;
            st->u.drift.ay = g->const_ay;
        }
    } else {
        if (!ADD(isk__stage_motion))
            return ISK_ERR_FULL;
        isk__stage_motion_init(st, g->integrator, f);
    }
    if ((em->motion.slowing > 0 || slow_each) && !fused_slow && !drift_sway) {
        if (!(slow_each ? ADD(isk__stage_slow_each) : ADD(isk__stage_slow)))
            return ISK_ERR_FULL;
        st->u.slow.slowing = em->motion.slowing;
    }
    if (sway && !drift_sway) {
        if (!ADD(isk__stage_oscillate))
            return ISK_ERR_FULL;
        osc_params(&st->u.osc, e, em);
    }
    /* Sound walls and deflectors together are one contact pass, in the
     * order the path meets them (iskra/contacts.h): the deflect stage.
     * When it flies the rest of a step after a contact with the integrator
     * (potentials act: isk__contacts_redo), it takes the walls alone too. */
    const int redo = f->npick > 0 && isk__contacts_redo(f, g->integrator);
    const int sound_walls = walls && !em->motion.draw_before_bounce && d->bounds.mode == ISK_BOUNCE_REFLECT;
    const int walls_in_contacts = sound_walls && (g->ndefl || redo);
    if (walls && !em->motion.draw_before_bounce && !walls_in_contacts) {
        if (!ADD(isk__stage_walls))
            return ISK_ERR_FULL;
        st->u.walls.b = &d->bounds;
        st->u.walls.drag = f->drag;
        /* with potentials the flight is not known from its end alone (iskra/impact.h) */
        st->u.walls.curved = d->bounds.mode == ISK_BOUNCE_REFLECT && f->npick > 0;
        st->u.walls.ax = g->const_ax;
        st->u.walls.ay = g->const_ay;
        st->u.walls.offset = isk_integrator_velocity_offset(g->integrator);
        st->u.walls.hit = em->events.on_hit >= 0;
    }
    if (g->ndefl || walls_in_contacts) {
        if (!ADD(isk__stage_deflect))
            return ISK_ERR_FULL;
        st->u.deflect.segs = g->defl;
        st->u.deflect.n = g->ndefl;
        st->u.deflect.rng = &g->streams[FX_STREAM_CHANCE]; /* a draw only where probability < 1 */
        st->u.deflect.can_kill = can_kill;
        st->u.deflect.drag = f->drag;
        st->u.deflect.hit = em->events.on_hit >= 0;
        st->u.deflect.walls = walls_in_contacts ? &d->bounds : NULL;
        st->u.deflect.redo = (isk_contact_integrator){g->integrator, f};
        st->u.deflect.redo_on = redo;
    }
    if (g->store.angle && isk__fx_looks_spins(em)) {
        const double change = isk__fx_looks_spin_change(em);
        if (!(change != 0.0 ? ADD(isk__stage_spin_life) : ADD(isk__stage_spin)))
            return ISK_ERR_FULL;
        st->u.spin.spin = em->look.spin;
        st->u.spin.spin_range = em->look.spin_range;
        st->u.spin.change = change;
    }
    /* What the stages need, folded: the start state (bounces at the time
     * of impact) kept by the motion stage's own pass, or by a stage of its
     * own before a drift; particle order (a potential that switches itself
     * off, a deflector that draws at random) keeps the list on one thread. */
    const unsigned needs = isk__pipeline_needs(&g->pipeline);
    if (needs & ISK_NEEDS_START) {
        for (int k = 0; k < g->pipeline.n; k++) {
            isk_stage *s = &g->pipeline.stage[k];
            if (s->kind == &isk__stage_motion)
                s->u.motion.remember = 1;
            if (s->kind == &isk__stage_walls)
                s->u.walls.start = 1;
        }
        if (fast && !isk__pipeline_insert(&g->pipeline, motion_at, &isk__stage_remember))
            return ISK_ERR_FULL;
    }
    g->parallel = !(needs & ISK_NEEDS_ORDER);
    /* The dead may be replaced by the last live particles (moving only as
     * many as died) when nothing sees the order: the stages (as for
     * threads) and the drawing (saturating adds commute; no draw). */
    g->cull_unordered = g->parallel && (em->look.draw == ISK_DRAW_NONE || em->look.blend == ISK_BLEND_ADD);
    const int mortal = isfinite(em->life.seconds) || can_kill;
    /* a flipbook played at a rate reads the age of immortal particles too */
    const int flips = g->texture && g->texture->frames > 1 && em->look.texture_fps > 0;
    if ((mortal || flips) && !ADD(isk__stage_age))
        return ISK_ERR_FULL;

    if (em->born.source == ISK_SOURCE_STREAM && em->born.space == ISK_SPACE_LOCAL)
        g->substep_end[g->nsubstep_end++] = &isk__fx_step_carry;
    if (em->events.on_hit >= 0 && (walls || g->ndefl)) /* sub-emitters (effect_events.c) */
        g->substep_end[g->nsubstep_end++] = &isk__fx_step_hits;
    /* The dead leave before the births: a full pool of short lives is full
     * again at every step's end, and a birth never finds the place of a
     * particle that is already dead taken. */
    if (mortal)
        g->substep_end[g->nsubstep_end++] = &isk__fx_step_cull;
    if (em->born.source == ISK_SOURCE_STREAM && em->born.active) /* a stopped stream: none */
        g->substep_end[g->nsubstep_end++] = &isk__fx_step_spawn;
    /* Blocks rest when the pipeline's stages allow it and nothing else moves
     * the group's particles: no step at the frame's start (the late walls,
     * the releases) and no carry with the emitter. */
    g->rests = isk__pipeline_rest_prefix(&g->pipeline) > 0 && g->nframe_start == 0 &&
               !(em->born.source == ISK_SOURCE_STREAM && em->born.space == ISK_SPACE_LOCAL);
    g->draw = isk__fx_choose_draw(g);
    return ISK_OK;
}

isk_status isk__fx_compile_all(isk_effect *e)
{
    for (int i = 0; i < e->ngroups; i++) {
        isk_status s = isk__fx_compile(e, &e->groups[i]);
        if (s != ISK_OK)
            return s;
    }
    return ISK_OK;
}

static void describe_steps(const isk_effect *e, const fx_group *g, const fx_step_kind *const *k, int n, FILE *out)
{
    for (int i = 0; i < n; i++) {
        fprintf(out, "  %-9s ", k[i]->name);
        k[i]->describe(e, g, out);
        fputc('\n', out);
    }
}

void isk__fx_describe_group(const isk_effect *e, const fx_group *g, FILE *out)
{
    const isk_emitter_def *em = g->def;
    fprintf(out, "emitter %s (%s, %zu particles, %d substep%s of %s):\n", em->name, isk_source_names[em->born.source],
            g->store.count, g->substeps, g->substeps == 1 ? "" : "s", isk_integrator_name(g->integrator));
    describe_steps(e, g, g->frame_start, g->nframe_start, out);
    isk__pipeline_describe(&g->pipeline, out);
    describe_steps(e, g, g->substep_end, g->nsubstep_end, out);
    if (g->rests) {
        const int n = isk__pipeline_rest_prefix(&g->pipeline);
        fprintf(out, "  %-9s skips ", "rest");
        for (int k = 0; k < n; k++)
            fprintf(out, "%s%s", k ? (k == n - 1 ? " and " : ", ") : "", g->pipeline.stage[k].kind->name);
        fprintf(out, " for a block %s exactly as it was: a block at rest\n", n == 1 ? "it leaves" : "they leave");
    }
    if (!g->parallel)
        fprintf(out, "  %-9s one thread, in particle order (%s)\n", "order",
                g->forces.npick ? "a potential may switch itself off" : "a deflector draws at random");
    if (em->look.draw != ISK_DRAW_NONE)
        fprintf(out, "  draw      %s, %s%s%s%s%s\n", isk_draw_mode_names[em->look.draw], isk_blend_name(em->look.blend),
                g->has_color_ramp ? ", colour over life" : "", g->has_alpha_ramp ? ", alpha over life" : "",
                g->has_size_ramp ? ", size over life" : "",
                em->look.draw_order == ISK_DRAW_ORDER_OLDEST   ? ", the oldest on top (whole, on one thread)"
                : em->look.draw_order == ISK_DRAW_ORDER_RANDOM ? ", in a random order each frame (whole, on one thread)"
                                                               : "");
    isk__fx_looks_describe(g, out);
    if (em->look.trail > 0)
        fprintf(out, "  trail     the last %d positions, %g px wide, fade %g (drawn first)\n", em->look.trail,
                em->look.trail_width, em->look.trail_fade);
}
