/* Contact stages: the walls and the deflector segments, with the state
 * before the move that their bounces at the time of impact need (see
 * stage.h and iskra/impact.h). */
#include <math.h>
#include <string.h>

#include "sim/stage.h"

static void run_remember(const isk_stage *st, isk_block *b, double h)
{
    (void)st;
    (void)h;
    memcpy(b->s->x_old, b->x, b->n * sizeof *b->x);
    memcpy(b->s->y_old, b->y, b->n * sizeof *b->y);
    memcpy(b->s->vx_old, b->vx, b->n * sizeof *b->vx);
    memcpy(b->s->vy_old, b->vy, b->n * sizeof *b->vy);
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

const isk_stage_kind isk_stage_remember = {"remember", run_remember, describe_remember};

static void run_walls(const isk_stage *st, isk_block *b, double h)
{
    isk_step_motion mo = motion_of(b, st->u.walls.drag, h);
    if (!st->u.walls.start) {
        mo.x0 = mo.y0 = mo.vx0 = mo.vy0 = NULL;
        mo.ax = st->u.walls.ax;
        mo.ay = st->u.walls.ay;
        mo.offset = st->u.walls.offset;
    }
    isk_bounds_apply_step(st->u.walls.b, &mo, b->n, b->x, b->y, b->vx, b->vy);
}

static void describe_walls(const isk_stage *st, FILE *out)
{
    const isk_bounds *w = st->u.walls.b;
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

const isk_stage_kind isk_stage_walls = {"walls", run_walls, describe_walls};

static void run_deflect(const isk_stage *st, isk_block *b, double h)
{
    isk_scratch *s = b->s;
    memset(s->killed, 0, b->n);
    const isk_step_motion mo = motion_of(b, st->u.deflect.drag, h);
    isk_deflect_step(st->u.deflect.segs, st->u.deflect.n, b->x, b->y, b->vx, b->vy, &mo, b->n, st->u.deflect.rng,
                     s->killed, NULL);
    if (!st->u.deflect.can_kill)
        return;
    double *life = b->p->life + b->first;
    for (size_t i = 0; i < b->n; i++)
        if (s->killed[i])
            life[i] = -INFINITY; /* culled at the end of the substep */
}

static void describe_deflect(const isk_stage *st, FILE *out)
{
    fprintf(out, "%d segment%s", st->u.deflect.n, st->u.deflect.n == 1 ? "" : "s");
}

const isk_stage_kind isk_stage_deflect = {"deflect", run_deflect, describe_deflect};
