/* SPDX-License-Identifier: MIT */
/* Sub-emitters: the deaths and bounces of one emitter's particles become
 * events of another (source = sub), whose children are born where they
 * happened.
 *
 * Where an event comes from, in the order that makes it deterministic on
 * any number of threads:
 *   deaths   the cull (a substep-end stage, on the caller), in index order,
 *            before the dead are removed;
 *   bounces  the contact stages run in threaded blocks and only count each
 *            particle's bounces in its own hit column (stage_contact.c: a
 *            touch right after a touch of the same kind is resting or
 *            sliding, not a bounce);
 *            the hits stage after the pipeline (substep end, on the caller)
 *            turns them into events in index order and clears them
 *            (a bounce in a back-dated birth's first moments, stream or
 *            child, waits in the column for the next substep's hits).
 * The event is the particle's position and velocity at the end of the
 * substep in which it died or bounced, and that substep's end time.
 *
 * When children are born: at the end of the frame, after every group
 * stepped, each sub-emitter's waiting events in the order they came (group
 * order, then substeps, then index), each child advanced by its age (the
 * frame's end minus the event's time) through its own stages, as a
 * stream's back-dated births are.  So the children are the same whether
 * the sub-emitter steps before or after its parent, and they are in the
 * frame's picture.
 *
 * Bounds: an event adds at most its `count` children and no more than the
 * pool's room; the events waiting in one frame are at most the child's
 * capacity (more could never be born: each gives at least one child).  The
 * rest are dropped and counted (isk_effect_dropped of the sub-emitter).  A
 * chain (a sub-emitter with its own on_death) or a cycle only ever makes
 * events at its next substeps, so no loop here waits on itself.  A child
 * whose age at birth already reaches its life is born all the same and
 * dies at the next cull (its own on_death then fires there, one substep
 * late), so a chain of very short lives still fires every generation. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "effect_internal.h"

isk_status isk__fx_events_columns(fx_group *g)
{
    const isk_emitter_def *em = g->def;
    isk_particles *p = &g->store;
    isk_status s = ISK_OK;
    if (em->events.on_hit >= 0 && !p->hit)
        s = isk_particles_add_columns(p, ISK_PARTICLES_HIT);
    /* a gate probe needs the last positions: one trail point at least */
    const int points = em->look.trail > 0 ? em->look.trail : g->keep_prev;
    if (s == ISK_OK && points != p->trail_len)
        s = isk_particles_set_trail(p, points);
    return s;
}

void isk__fx_events_free(fx_group *g)
{
    free(g->pending.ev);
    g->pending.ev = NULL;
    g->pending.n = g->pending.cap = 0;
}

static void drop_children(fx_group *c, size_t events)
{
    size_t n = c->def->born.count;
    uint64_t lost = events > 0 && n > UINT64_MAX / events ? UINT64_MAX : (uint64_t)events * n;
    c->dropped = lost > UINT64_MAX - c->dropped ? UINT64_MAX : c->dropped + lost;
}

/* One event for the sub-emitter c. */
static isk_status push(fx_group *c, const isk_particles *p, size_t i, double t)
{
    fx_events *q = &c->pending;
    if (q->n >= c->def->born.capacity) {
        drop_children(c, 1);
        return ISK_OK;
    }
    if (q->n == q->cap) {
        size_t cap = q->cap ? 2 * q->cap : 64;
        if (cap > c->def->born.capacity)
            cap = c->def->born.capacity;
        fx_event *a = cap <= SIZE_MAX / sizeof *a ? realloc(q->ev, cap * sizeof *a) : NULL; /* 32-bit size_t */
        if (!a)
            return ISK_ERR_NOMEM;
        q->ev = a;
        q->cap = cap;
    }
    q->ev[q->n++] = (fx_event){p->x[i], p->y[i], p->vx[i], p->vy[i], t};
    return ISK_OK;
}

isk_status isk__fx_events_deaths(isk_effect *e, fx_group *g, double t)
{
    const int to = g->def->events.on_death;
    if (to < 0 || to >= e->ngroups)
        return ISK_OK;
    fx_group *c = &e->groups[to];
    const isk_particles *p = &g->store;
    for (size_t i = 0; i < p->count; i++)
        if (p->age[i] >= p->life[i]) { /* the cull's own test */
            isk_status s = push(c, p, i, t);
            if (s != ISK_OK)
                return s;
        }
    return ISK_OK;
}

static isk_status run_hits(isk_effect *e, fx_group *g, double t0, double h)
{
    const int to = g->def->events.on_hit;
    isk_particles *p = &g->store;
    if (to < 0 || to >= e->ngroups || !p->hit)
        return ISK_OK;
    fx_group *c = &e->groups[to];
    for (size_t i = 0; i < p->count; i++) {
        const unsigned n = p->hit[i] & ISK_HIT_COUNT;
        for (unsigned k = 0; k < n; k++) { /* one event per bounce (at most 63 a substep) */
            isk_status s = push(c, p, i, t0 + h);
            if (s != ISK_OK)
                return s;
        }
        p->hit[i] &= (unsigned char)~ISK_HIT_COUNT; /* the touch bits stay for the next substep */
    }
    return ISK_OK;
}

static void describe_hits(const isk_effect *e, const fx_group *g, FILE *out)
{
    fprintf(out, "bounces -> events of %s", e->def.emitters[g->def->events.on_hit].name);
}

const fx_step_kind isk__fx_step_hits = {"hits", run_hits, describe_hits};

/* The children of one event: `count` of them, launched from the event's
 * position, with inherit times its velocity added to their launch. */
static isk_status release_group(isk_effect *e, fx_group *g)
{
    const isk_emitter_def *em = g->def;
    fx_events *q = &g->pending;
    fx_launcher l = isk__fx_launcher_of(em);
    for (size_t k = 0; k < q->n; k++) {
        const fx_event *ev = &q->ev[k];
        const size_t room = g->store.count < em->born.capacity ? em->born.capacity - g->store.count : 0;
        if (room == 0) {
            drop_children(g, q->n - k);
            break;
        }
        l.shape.cx = ev->x;
        l.shape.cy = ev->y;
        double age = isk__fx_group_time(e, g) - ev->t;
        if (!(age > 0))
            age = 0;
        const double dv[2] = {em->launch.inherit * ev->vx, em->launch.inherit * ev->vy};
        const size_t born = em->born.count < room ? em->born.count : room;
        if (born < em->born.count) /* the rest find no room: counted in one addition */
            g->dropped =
                em->born.count - born > UINT64_MAX - g->dropped ? UINT64_MAX : g->dropped + (em->born.count - born);
        for (size_t j = 0; j < born; j++) {
            isk_status s = isk__fx_birth(e, g, &l, age, ev->t, em->launch.inherit > 0 ? dv : NULL);
            if (s != ISK_OK) {
                q->n = 0;
                return s;
            }
        }
    }
    q->n = 0;
    return ISK_OK;
}

isk_status isk__fx_events_release(isk_effect *e)
{
    for (int i = 0; i < e->ngroups; i++) {
        fx_group *g = &e->groups[i];
        if (g->def->born.source != ISK_SOURCE_SUB || g->pending.n == 0)
            continue;
        if (!g->def->born.active || g->def->motion.paused) {
            g->pending.n = 0; /* nothing is born into it: its events are skipped, not kept for later */
            continue;
        }
        isk_status s = release_group(e, g);
        if (s != ISK_OK)
            return s;
    }
    return ISK_OK;
}
