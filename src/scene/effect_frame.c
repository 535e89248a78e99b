/* SPDX-License-Identifier: MIT */
/* The frame loop: what one isk_effect_step does, and the clocks.
 *
 * A frame, every group that has started in definition order: its
 * frame-start stages, then `substeps` times the block runner over its
 * store (src/sim/stage.h) followed by its substep-end stages (births, the
 * cull).  Then, after every group: the children of sub-emitters' events,
 * the probes' measures, the trails' newest points.  The block runner is the one isk_system_step
 * uses, so a thesis scene and the C example that drives an isk_system give
 * identical bits by construction.  A prewarm runs the same frames before
 * frame 0.  The frame's entry points are here too: step, render, run and
 * a click's explosion. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "effect_internal.h"
#include "sim/store_internal.h"

static isk_status advance(isk_effect *e);

/* Every clock at frame 0 of a frame length of `step`. */
void isk__fx_start_clocks(isk_effect *e, double step)
{
    e->clock = (fx_clock){0.0, 0, step};
    for (int gi = 0; gi < e->ngroups; gi++)
        e->groups[gi].clock = e->clock;
    e->frame = 0;
    e->time = 0.0;
}

/* The frame's simulated time changed (a live dt or speed_divisor): every
 * clock goes on from where it is now at the new rate. */
static void rebase_clocks(isk_effect *e, double step)
{
    e->clock = (fx_clock){isk__fx_clock_at(&e->clock, e->frame), e->frame, step};
    for (int gi = 0; gi < e->ngroups; gi++) {
        fx_group *g = &e->groups[gi];
        const long f = e->frame + g->frame_offset;
        g->clock = (fx_clock){isk__fx_clock_at(&g->clock, f), f, step};
    }
}

/* prewarm: the whole effect, every group built, runs the frames before
 * frame 0 that its prewarmed emitters ask for.  An emitter prewarmed by n
 * frames starts n frames before frame 0 (its clock at 0 then), a
 * sub-emitter with the emitters that feed it (isk__fx_prewarm_offsets); every
 * other group, and the potentials, start at frame 0, so they stand still
 * meanwhile.  The children of events are released and the trails recorded
 * after each of these frames, as after any other, so frame 0 of an effect
 * prewarmed by T holds what frame T/dt holds without it. */
isk_status isk__fx_prewarm(isk_effect *e)
{
    const isk_effect_def *d = &e->def;
    double *frames = calloc((size_t)(e->ngroups ? e->ngroups : 1), sizeof *frames);
    if (!frames)
        return ISK_ERR_NOMEM;
    long most = 0;
    isk__fx_prewarm_offsets(d, frames); /* each bounded by the check (iskra/limits.h) */
    for (int gi = 0; gi < e->ngroups; gi++) {
        e->groups[gi].frame_offset = (long)frames[gi];
        if ((long)frames[gi] > most)
            most = (long)frames[gi];
    }
    free(frames);
    isk_status s = ISK_OK;
    e->frame = -most;
    e->time = isk__fx_clock_at(&e->clock, e->frame);
    while (s == ISK_OK && e->frame < 0)
        s = advance(e);
    return s;
}

/* ---- the frame loop --------------------------------------------------------- */

static isk_status run_steps(isk_effect *e, fx_group *g, const fx_step_kind *const *k, int n, double t0, double h)
{
    for (int i = 0; i < n; i++) {
        isk_status s = k[i]->run(e, g, t0, h);
        if (s != ISK_OK)
            return s;
    }
    return ISK_OK;
}

/* Whether a group's update goes to the workers, from counts alone (no
 * clock: the same decision on every run): its particles times what its
 * stages declare they cost, a block at rest counting only the stages it
 * does not skip, against FX_UPDATE_MIN_WORK.  The bytes are the same
 * either way. */
static double update_work(const fx_group *g)
{
    const size_t n = g->store.count;
    const isk_pipeline *pl = &g->pipeline;
    const int prefix = g->rests ? isk__pipeline_rest_prefix(pl) : 0;
    size_t resting = prefix ? isk__rest_blocks(&g->rest, n, ISK_REST_X | ISK_REST_Y) * ISK_SIM_BLOCK : 0;
    resting = resting < n ? resting : n;
    return (double)(n - resting) * isk__pipeline_cost(pl, 0) + (double)resting * isk__pipeline_cost(pl, prefix);
}

static isk_status step_group(isk_effect *e, fx_group *g)
{
    const isk_effect_def *d = &e->def;
    const int N = g->substeps;
    const double h = d->dt / (double)N / d->speed_divisor;
    const double time = isk__fx_group_time(e, g); /* e->time unless a prewarm ran */
    isk_status s = run_steps(e, g, g->frame_start, g->nframe_start, time, h * (double)N);
    for (int j = 0; s == ISK_OK && j < N; j++) {
        if (g->has_field)
            isk__fx_field_clock(g, time + h * j);
        /* a multi-Coulomb explosion releases particles of the store as it goes */
        isk_rest *rest = g->rests && !g->mc_active && !e->no_rest ? &g->rest : NULL;
        if (!rest) /* every block steps: the states describe nothing after it */
            isk__rest_forget(&g->rest, 0);
        const int shared = g->parallel && isk__workers_count(&e->workers) > 1 && update_work(g) >= e->update_min_work;
        const isk_run_context ctx = {shared ? &e->workers : NULL, rest};
        g->shared_updates += shared;
        isk__pipeline_run(&g->pipeline, &g->store, 0, g->store.count, h, &e->scratch, &ctx);
        s = run_steps(e, g, g->substep_end, g->nsubstep_end, time + h * j, h);
        if (e->scratch.nonfinite) { /* never kept or drawn: removed and counted (iskra/limits.h) */
            size_t first;
            g->removed_nonfinite += isk__store_remove_nonfinite(&g->store, &first);
            isk__rest_forget(&g->rest, first);
            e->scratch.nonfinite = 0;
        }
    }
    if (g->mc_active)
        isk_multi_coulomb_advance(&g->mc, h * (double)N);
    return s;
}

/* A potential that switched itself off (its maximum distance) acts as zero
 * from that particle on; after the frame it leaves the lists. */
static int lost_a_potential(const isk_effect *e, const fx_group *g)
{
    for (size_t k = 0; k < g->forces.npick; k++)
        if (!e->pots[g->forces.pick[k]].enabled)
            return 1;
    return 0;
}

/* One frame of every group that has started (effect.c's prewarm runs the
 * frames before 0; isk_effect_step the others). */
static isk_status advance(isk_effect *e)
{
    const isk_effect_def *d = &e->def;
    const double frame_time = d->dt / d->speed_divisor;
    if (frame_time != e->clock.step)
        rebase_clocks(e, frame_time);
    /* The potentials start at frame 0, as every group not prewarmed. */
    const long stepped = e->frame;
    const int started = stepped >= 0;
    /* The thesis draws the potentials, then moves them: the move of the
     * previous frame happens now, after that frame was rendered. */
    if (started && e->last_frame_time != 0)
        for (size_t k = 0; k < e->npots; k++)
            isk_potential_move(&e->pots[k], e->last_frame_time);
    size_t total = 0;
    for (int gi = 0; gi < e->ngroups; gi++) {
        fx_group *g = &e->groups[gi];
        if (!isk__fx_group_runs(e, g))
            continue;
        isk_status s = step_group(e, g);
        if (s != ISK_OK)
            return s;
        total += g->store.count;
    }
    for (int gi = 0; gi < e->ngroups; gi++)
        if (lost_a_potential(e, &e->groups[gi])) {
            isk_status s = isk__fx_compile(e, &e->groups[gi]);
            if (s != ISK_OK)
                return s;
        }
    e->frame++;
    e->time = isk__fx_clock_at(&e->clock, e->frame);
    /* The thesis's h stays unassigned when there are no particles: then its
     * potentials do not move. */
    if (started)
        e->last_frame_time = total ? frame_time : 0.0;
    /* sub-emitters' children, then the trails' newest points */
    isk_status se = isk__fx_events_release(e);
    if (se != ISK_OK)
        return se;
    if (e->probes) /* before the trails' record: a gate reads where each particle was */
        isk__fx_probes_measure(e, stepped);
    isk__fx_trail_record(e, stepped);
    if (d->click.at_start && d->click.after_frames > 0 && e->frame == d->click.after_frames)
        return isk__fx_click(e, d->click.x, d->click.y);
    return ISK_OK;
}

isk_status isk_effect_step(isk_effect *e)
{
    return e ? advance(e) : ISK_ERR_NULL;
}

isk_status isk_effect_step_render(isk_effect *e, isk_canvas *c)
{
    isk_status s = isk_effect_step(e);
    return s != ISK_OK ? s : isk_effect_render(e, c);
}

isk_status isk_effect_run(isk_effect *e, isk_canvas *c, long frames)
{
    if (!e || !c)
        return ISK_ERR_NULL;
    if (frames < 0)
        return ISK_ERR_RANGE;
    if (c->width != e->def.width || c->height != e->def.height)
        return ISK_ERR_SIZE;
    isk_status s = ISK_OK;
    if (e->def.clear) {
        for (long i = 0; i < frames && s == ISK_OK; i++)
            s = isk_effect_step(e);
        return s != ISK_OK ? s : isk_effect_render(e, c);
    }
    isk_canvas_fill(c, e->def.background);
    for (long i = 0; i < frames && s == ISK_OK; i++)
        s = isk_effect_step_render(e, c);
    return s;
}

isk_status isk_effect_render(isk_effect *e, isk_canvas *c)
{
    if (!e || !c)
        return ISK_ERR_NULL;
    if (c->width != e->def.width || c->height != e->def.height)
        return ISK_ERR_SIZE;
    return isk__fx_render(e, c);
}

isk_status isk_effect_click(isk_effect *e, double x, double y)
{
    if (!e)
        return ISK_ERR_NULL;
    if (!isfinite(x) || !isfinite(y))
        return ISK_ERR_NAN;
    e->edits++;
    return isk__fx_click(e, x, y);
}

unsigned long isk_effect_edits(const isk_effect *e) { return e ? e->edits : 0; }

isk_status isk__fx_click(isk_effect *e, double x, double y)
{
    const isk_effect_def *d = &e->def;
    if (!(d->click.enabled || d->click.at_start) || e->ngroups == 0)
        return ISK_OK;
    int gi = d->click.emitter >= 0 ? d->click.emitter : 0;
    fx_group *g = &e->groups[gi];
    return isk__fx_fire_explosion(e, g, d->click.explosion, x, y, d->click.count, g->def->born.kick);
}
