/* SPDX-License-Identifier: MIT */
/* Contact stages: the walls and the deflector segments, with the state
 * before the move that their bounces at the time of impact need (see
 * stage.h and iskra/impact.h). */
#include <math.h>
#include <string.h>

#include "sim/motion_fused.h" /* isk_motion_start: the state the contact stages read */
#include "sim/stage.h"

static void run_remember(const isk_stage *st, isk_block *b, double h)
{
    (void)st;
    (void)h;
    const isk_motion_start start = isk_motion_start_of(b->s);
    isk_motion_start_copy(&start, b->n, b->x, b->y, b->vx, b->vy);
}

static void describe_remember(const isk_stage *st, FILE *out)
{
    (void)st;
    fprintf(out, "positions and velocities (for bounces at the time of impact)");
}

/* The step the block just made, as the contact stages see it: from the
 * remembered start state, or (walls without potentials) from the constant
 * acceleration alone. */
static isk_step_motion motion_of(const isk_block *b, double drag, double h)
{
    const isk_scratch *s = b->s;
    isk_step_motion mo = {s->x_old, s->y_old, s->vx_old, s->vy_old, b->m, drag, h, 0.0, 0.0, 0.0};
    return mo;
}

const isk_stage_kind isk__stage_remember = {
    .name = "remember", .run = run_remember, .describe = describe_remember, .rest = isk__rest_skipped};

/* A particle's hit byte (iskra/particles.h) after a contact stage that
 * touched it `k` times in this substep: the bounces are counted unless it
 * touched the same kind of contact (wall or deflector: `bit`) in the
 * substep before too, which is resting or sliding on it, not bouncing. */
static unsigned char contact_mark(unsigned char h, unsigned bit, size_t k)
{
    if (k == 0)
        return (unsigned char)(h & ~bit);
    size_t n = (h & bit) ? 0 : k;
    size_t c = (h & ISK_HIT_COUNT) + n;
    return (unsigned char)((h & ~(unsigned)ISK_HIT_COUNT) | bit | (c > ISK_HIT_COUNT ? ISK_HIT_COUNT : c));
}

static void run_walls(const isk_stage *st, isk_block *b, double h)
{
    isk_step_motion mo = motion_of(b, st->u.walls.drag, h);
    if (!st->u.walls.start) {
        mo.x0 = mo.y0 = mo.vx0 = mo.vy0 = NULL;
        mo.ax = st->u.walls.ax;
        mo.ay = st->u.walls.ay;
        mo.offset = st->u.walls.offset;
    }
    if (!st->u.walls.hit || !b->p->hit) {
        /* a resting axis's columns are stand-ins: its walls have nothing to do */
        const isk_bounds *w = st->u.walls.b;
        isk_bounds masked;
        if (b->frozen) {
            masked = *w;
            masked.sides &= ~(unsigned)((b->frozen & ISK_REST_X ? ISK_SIDE_LEFT | ISK_SIDE_RIGHT : 0) |
                                        (b->frozen & ISK_REST_Y ? ISK_SIDE_BOTTOM | ISK_SIDE_TOP : 0));
            w = &masked;
        }
        isk_bounds_apply_step(w, &mo, b->n, b->x, b->y, b->vx, b->vy);
        return;
    }
    /* A sub-emitter's on_hit.  The walls touch only particles that end the
     * step beyond them (sound walls) or flip their velocity (the thesis's).
     * A particle resting on a wall touches it at every step: only the first
     * touch after a step without one is a bounce (contact_mark). */
    const isk_bounds *w = st->u.walls.b;
    const unsigned sd = w->sides;
    const double lo[2] = {sd & ISK_SIDE_LEFT ? w->xmin + w->margin : -INFINITY,
                          sd & ISK_SIDE_BOTTOM ? w->ymin + w->margin : -INFINITY};
    const double hi[2] = {sd & ISK_SIDE_RIGHT ? w->xmax - w->margin : INFINITY,
                          sd & ISK_SIDE_TOP ? w->ymax - w->margin : INFINITY};
    const int thesis = w->mode == ISK_BOUNCE_THESIS;
    double pre[2][ISK_SIM_BLOCK];
    double *const pos[2] = {b->x, b->y}, *const vel[2] = {b->vx, b->vy};
    for (int a = 0; a < 2; a++)
        memcpy(pre[a], thesis ? vel[a] : pos[a], b->n * sizeof pre[a][0]);
    isk_bounds_apply_step(w, &mo, b->n, b->x, b->y, b->vx, b->vy);
    unsigned char *hit = b->p->hit + b->first;
    for (size_t i = 0; i < b->n; i++) {
        unsigned k = 0;
        for (int a = 0; a < 2; a++)
            k += thesis ? pre[a][i] * vel[a][i] < 0 : !(pre[a][i] >= lo[a] && pre[a][i] <= hi[a]);
        hit[i] = contact_mark(hit[i], ISK_HIT_WALL, k);
    }
}

static void describe_walls_of(const isk_bounds *w, FILE *out)
{
    fprintf(out, "%s", (unsigned)w->mode < ISK_BOUNCE_MODE_COUNT ? isk_bounce_mode_names[w->mode] : "?");
    if (w->sides != ISK_SIDE_ALL) {
        const char *sep = ": ";
        for (int k = 0; k < ISK_SIDE_COUNT; k++)
            if (w->sides >> k & 1u) {
                fprintf(out, "%s%s", sep, isk_side_names[k]);
                sep = ", ";
            }
    }
    if (w->mode == ISK_BOUNCE_REFLECT)
        fprintf(out, ", restitution %g, at the time of impact", w->restitution);
}

static void describe_walls(const isk_stage *st, FILE *out)
{
    describe_walls_of(st->u.walls.b, out);
}

/* Counting bounces writes the hit column, which a block at rest would stop
 * doing: then no block rests. */
static isk_rest_role rest_walls(const isk_stage *st)
{
    return st->u.walls.hit ? ISK_REST_BREAKS : ISK_REST_SKIPPED;
}

/* At the time of impact, a flight that is not a constant acceleration's
 * is read from its start state (iskra/impact.h). */
static unsigned needs_walls(const isk_stage *st) { return st->u.walls.curved ? ISK_NEEDS_START : 0u; }

const isk_stage_kind isk__stage_walls = {.name = "walls",
                                        .run = run_walls,
                                        .describe = describe_walls,
                                        .rest = rest_walls,
                                        .needs = needs_walls};

static void run_deflect(const isk_stage *st, isk_block *b, double h)
{
    isk_scratch *s = b->s;
    memset(s->killed, 0, b->n);
    const isk_step_motion mo = motion_of(b, st->u.deflect.drag, h);
    const isk_bounds *walls = st->u.deflect.walls;
    const isk_contact_integrator *redo = st->u.deflect.redo_on ? &st->u.deflect.redo : NULL;
    if (st->u.deflect.hit && b->p->hit) {
        /* A sub-emitter's on_hit: each particle's bounces counted
         * (contact_mark: a particle resting on a segment or a wall touches
         * it at every step). */
        uint8_t bounces[ISK_SIM_BLOCK], wall_bounces[ISK_SIM_BLOCK];
        isk_deflect_stats ds = {0, 0, 0, 0, 0, 0, bounces, 0, wall_bounces};
        unsigned char *hit = b->p->hit + b->first;
        for (size_t o = 0; o < b->n; o += ISK_SIM_BLOCK) { /* a block is at most ISK_SIM_BLOCK */
            const size_t m = b->n - o < ISK_SIM_BLOCK ? b->n - o : ISK_SIM_BLOCK;
            isk_step_motion m1 = mo;
            m1.x0 += o;
            m1.y0 += o;
            m1.vx0 += o;
            m1.vy0 += o;
            if (m1.m)
                m1.m += o;
            isk_contacts_step(walls, st->u.deflect.segs, st->u.deflect.n, b->x + o, b->y + o, b->vx + o, b->vy + o,
                              &m1, redo, m, st->u.deflect.rng, s->killed + o, &ds);
            for (size_t i = 0; i < m; i++) {
                hit[o + i] = contact_mark(hit[o + i], ISK_HIT_DEFLECTOR, bounces[i]);
                if (walls)
                    hit[o + i] = contact_mark(hit[o + i], ISK_HIT_WALL, wall_bounces[i]);
            }
        }
    } else {
        isk_contacts_step(walls, st->u.deflect.segs, st->u.deflect.n, b->x, b->y, b->vx, b->vy, &mo, redo, b->n,
                          st->u.deflect.rng, s->killed, NULL);
    }
    if (!st->u.deflect.can_kill)
        return;
    double *life = b->p->life + b->first;
    for (size_t i = 0; i < b->n; i++)
        if (s->killed[i])
            life[i] = -INFINITY; /* culled at the end of the substep */
}

static void describe_deflect(const isk_stage *st, FILE *out)
{
    if (st->u.deflect.n || !st->u.deflect.walls)
        fprintf(out, "%d segment%s", st->u.deflect.n, st->u.deflect.n == 1 ? "" : "s");
    if (st->u.deflect.walls) {
        fprintf(out, "%sthe walls (", st->u.deflect.n ? " and " : "");
        describe_walls_of(st->u.deflect.walls, out);
        fprintf(out, ")%s", st->u.deflect.n ? ", in path order" : "");
    }
    if (st->u.deflect.redo_on)
        fprintf(out, "; the rest of a step after a contact by %s", isk_integrator_name(st->u.deflect.redo.method));
}

/* A crossing test against every segment. */
static double cost_deflect(const isk_stage *st) { return 1.0 + (double)st->u.deflect.n; }

/* The crossings are found from the start state; a segment that lets a
 * particle through by chance draws from the owner's stream, in particle
 * order. */
static unsigned needs_deflect(const isk_stage *st)
{
    unsigned needs = ISK_NEEDS_START;
    for (int k = 0; k < st->u.deflect.n; k++)
        if (st->u.deflect.segs[k].probability > 0.0 && st->u.deflect.segs[k].probability < 1.0)
            needs |= ISK_NEEDS_ORDER;
    return needs;
}

const isk_stage_kind isk__stage_deflect = {.name = "deflect",
                                          .run = run_deflect,
                                          .describe = describe_deflect,
                                          .rest = NULL /* draws from the owner's stream */,
                                          .cost = cost_deflect,
                                          .needs = needs_deflect};

int isk__contacts_redo(const isk_forces *f, isk_integrator method)
{
    const unsigned laws = isk_forces_laws(f);
    return (laws & (ISK_LAW_POWER_2 | ISK_LAW_POWER_1 | ISK_LAW_POWER)) && !(laws & ISK_LAW_CUTOFF) &&
           isk_integrator_velocity_offset(method) == 0.0;
}
