/* SPDX-License-Identifier: MIT */
/* Motion stages: the constant-acceleration drift, forces + integrator, and
 * ageing (see stage.h). */
#include <math.h>

#include "core/fast_paths.h"
#include "sim/kernels.h"
#include "sim/motion_fused.h"
#include "sim/stage.h"

/* v += a*h; r += h*v: semi-implicit Euler with a constant acceleration.
 * With a = (0, -g) this is the hand-written gravity loop, operation for
 * operation (vy + (-g*h) == vy - g*h in IEEE arithmetic). */
static void drift_loop(size_t n, double *restrict x, double *restrict y, double *restrict vx,
                       double *restrict vy, double ax, double ay, double h)
{
    const double dvx = ax * h, dvy = ay * h;
    if (ax == 0.0) {
        /* Gravity alone (the common case): vx does not change, so it is only
         * read; skipping its store saves an eighth of the memory traffic.
         * vx + 0 == vx for every vx but -0, and -0 + 0 = +0 would only
         * change the sign of a zero velocity, never a position. */
        for (size_t i = 0; i < n; i++) {
            double nvy = vy[i] + dvy;
            vy[i] = nvy;
            x[i] = x[i] + h * vx[i];
            y[i] = y[i] + h * nvy;
        }
        return;
    }
    for (size_t i = 0; i < n; i++) {
        double nvx = vx[i] + dvx, nvy = vy[i] + dvy;
        vx[i] = nvx;
        vy[i] = nvy;
        x[i] = x[i] + h * nvx;
        y[i] = y[i] + h * nvy;
    }
}

static void run_drift(const isk_stage *st, isk_block *b, double h)
{
    drift_loop(b->n, b->x, b->y, b->vx, b->vy, st->u.drift.ax, st->u.drift.ay, h);
}

static void describe_drift(const isk_stage *st, FILE *out)
{
    if (st->u.drift.ax != 0 || st->u.drift.ay != 0)
        fprintf(out, "semi-euler, constant acceleration (%g, %g)", st->u.drift.ax, st->u.drift.ay);
    else
        fprintf(out, "semi-euler, no forces");
}

const isk_stage_kind isk__stage_drift = {
    .name = "drift", .run = run_drift, .describe = describe_drift, .rest = isk__rest_skipped};

/* Forces are where a finite state can turn non-finite (the thesis's centre
 * rule gives NaN on a potential, iskra/limits.h): the block is checked
 * after the step, in L1, and the runner's owner removes and counts.  The
 * drift above needs no check: with the accepted accelerations and steps it
 * cannot leave the finite numbers. */
static void run_motion(const isk_stage *st, isk_block *b, double h)
{
    const isk_motion_start start = isk_motion_start_of(b->s);
    int nonfinite;
    const unsigned laws = st->u.motion.laws_known ? st->u.motion.laws : isk_forces_laws(st->u.motion.forces);
    if (ISK__FAST_FUSED && isk__motion_fused(st->u.motion.method, st->u.motion.forces, laws, b->n, b->x, b->y,
                                             b->vx, b->vy, b->m, h, st->u.motion.remember ? &start : NULL,
                                             &nonfinite)) {
        b->s->nonfinite |= nonfinite; /* the common case in one pass: the same bits (motion_fused.h) */
        return;
    }
    if (st->u.motion.remember)
        isk_motion_start_copy(&start, b->n, b->x, b->y, b->vx, b->vy);
    isk_integrate_block(st->u.motion.method, st->u.motion.forces, b->s, b->n, b->x, b->y, b->vx, b->vy,
                        b->m, h);
    b->s->nonfinite |= isk_k_any_nonfinite2(b->n, b->x, b->y) | isk_k_any_nonfinite2(b->n, b->vx, b->vy);
}

/* Names only what acts, and the start state kept for the contact stages. */
static void describe_motion(const isk_stage *st, FILE *out)
{
    const isk_forces *f = st->u.motion.forces;
    fprintf(out, "%s, forces: ", isk_integrator_name(st->u.motion.method));
    int any = 0;
    if (f->gravity != 0)
        fprintf(out, "%sgravity g=%g", any++ ? ", " : "", f->gravity);
    if (f->ax != 0 || f->ay != 0)
        fprintf(out, "%saccel (%g, %g)", any++ ? ", " : "", f->ax, f->ay);
    if (f->drag != 0)
        fprintf(out, "%sdrag b=%g", any++ ? ", " : "", f->drag);
    size_t n = f->pick ? f->npick : f->npot;
    for (size_t k = 0; k < n; k++)
        fprintf(out, "%spotential %d", any++ ? ", " : "", f->pot[f->pick ? f->pick[k] : k].id);
    if (!any)
        fprintf(out, "none");
    if (st->u.motion.remember)
        fprintf(out, "; keeps the start state (bounces at the time of impact)");
}

/* Potentials move and switch themselves off: a block under one never rests. */
static isk_rest_role rest_motion(const isk_stage *st)
{
    const isk_forces *f = st->u.motion.forces;
    return (f->pick ? f->npick : f->npot) ? ISK_REST_BREAKS : ISK_REST_SKIPPED;
}

/* The integrator's force sums and update, and a pass per potential. */
static double cost_motion(const isk_stage *st)
{
    const isk_forces *f = st->u.motion.forces;
    return 2.0 + 4.0 * (double)(f->pick ? f->npick : f->npot);
}

/* A potential that switches itself off at its max distance does so at the
 * first particle that comes near, for every later one: particle order. */
static unsigned needs_motion(const isk_stage *st)
{
    return isk_forces_laws(st->u.motion.forces) & ISK_LAW_CUTOFF ? ISK_NEEDS_ORDER : 0u;
}

void isk__stage_motion_init(isk_stage *st, isk_integrator method, isk_forces *f)
{
    st->u.motion.method = method;
    st->u.motion.forces = f;
    st->u.motion.laws = isk_forces_laws(f);
    st->u.motion.laws_known = 1;
}

const isk_stage_kind isk__stage_motion = {.name = "integrate",
                                         .run = run_motion,
                                         .describe = describe_motion,
                                         .rest = rest_motion,
                                         .cost = cost_motion,
                                         .needs = needs_motion};

static void run_age(const isk_stage *st, isk_block *b, double h)
{
    (void)st;
    isk_particles_age(b->p, b->first, b->first + b->n, h);
}

static void describe_age(const isk_stage *st, FILE *out)
{
    (void)st;
    fprintf(out, "age += dt");
}

const isk_stage_kind isk__stage_age = {
    .name = "age", .run = run_age, .describe = describe_age, .rest = isk__rest_beside};
