/* SPDX-License-Identifier: MIT */
/* The fire thesis's stages: slowing (in both orders), the horizontal
 * oscillation, and the drift and the oscillation in one pass (see stage.h
 * and sway.h). */
#include <string.h>

#include "sim/kernels.h"
#include "sim/stage.h"
#include "sim/sway.h"

/* The fire thesis's 1 - slowing*dt, clamped so a long frame can stop a
 * particle but never reverse it. */
static double slow_factor(double slowing, double h)
{
    double f = 1.0 - slowing * h;
    return f > 0.0 ? f : 0.0;
}

static void run_slow(const isk_stage *st, isk_block *b, double h)
{
    const double f = slow_factor(st->u.slow.slowing, h);
    double *restrict vx = b->vx, *restrict vy = b->vy;
    for (size_t i = 0; i < b->n; i++) {
        vx[i] = isk_k_flush(vx[i] * f);
        vy[i] = isk_k_flush(vy[i] * f);
    }
}

/* slowing_range: each particle's own slowing, slowing + slowing_extra. */
static void run_slow_each(const isk_stage *st, isk_block *b, double h)
{
    const double *restrict extra = b->p->slowing_extra + b->first;
    double *restrict vx = b->vx, *restrict vy = b->vy;
    for (size_t i = 0; i < b->n; i++) {
        const double f = slow_factor(st->u.slow.slowing + extra[i], h);
        vx[i] = isk_k_flush(vx[i] * f);
        vy[i] = isk_k_flush(vy[i] * f);
    }
}

static void describe_slow_each(const isk_stage *st, FILE *out)
{
    fprintf(out, "v *= max(0, 1 - (%g + its own U*range)*dt)", st->u.slow.slowing);
}

const isk_stage_kind isk__stage_slow_each = {
    .name = "slow", .run = run_slow_each, .describe = describe_slow_each, .rest = isk__rest_skipped};

static void describe_slow(const isk_stage *st, FILE *out)
{
    fprintf(out, "v *= max(0, 1 - %g*dt)", st->u.slow.slowing);
}

const isk_stage_kind isk__stage_slow = {
    .name = "slow", .run = run_slow, .describe = describe_slow, .rest = isk__rest_skipped};

/* The fire thesis's Emitter::Advance: v -= F*dt; v *= slow; p += v*dt (F in
 * its sign is -a), slow clamped at 0. */
static void run_drift_slow(const isk_stage *st, isk_block *b, double h)
{
    const double dvx = st->u.drift_slow.ax * h, dvy = st->u.drift_slow.ay * h;
    const double f = slow_factor(st->u.drift_slow.slowing, h);
    double *restrict x = b->x, *restrict y = b->y, *restrict vx = b->vx, *restrict vy = b->vy;
    for (size_t i = 0; i < b->n; i++) {
        double nvx = isk_k_flush((vx[i] + dvx) * f), nvy = isk_k_flush((vy[i] + dvy) * f);
        vx[i] = nvx;
        vy[i] = nvy;
        x[i] = x[i] + h * nvx;
        y[i] = y[i] + h * nvy;
    }
}

static void describe_drift_slow(const isk_stage *st, FILE *out)
{
    fprintf(out, "thesis order: v += (%g, %g)*dt; v *= max(0, 1 - %g*dt); p += v*dt", st->u.drift_slow.ax,
            st->u.drift_slow.ay, st->u.drift_slow.slowing);
}

const isk_stage_kind isk__stage_drift_slow = {
    .name = "drift", .run = run_drift_slow, .describe = describe_drift_slow, .rest = isk__rest_skipped};

/* The sway of step h as sim/sway.h takes it. */
static isk_sway sway_of(const isk_stage_osc *o, double h)
{
    double decay = 1.0 - o->decay * h;
    if (!(decay > 0.0))
        decay = 0.0;
    const isk_sway w = {o->table, o->mode, o->faithful, decay, h};
    return w;
}

/* The sway's loops are sim/sway.h's (portable, and AVX2 at run time). */
static void run_oscillate(const isk_stage *st, isk_block *b, double h)
{
    isk_particles *p = b->p;
    const size_t o = b->first;
    const isk_sway w = sway_of(&st->u.osc, h);
    isk__sway_run(&w, b->n, b->x, b->vx, p->osc_amp + o, p->osc_phase + o, p->osc_omega + o, p->osc_offset + o);
}

static void describe_oscillate(const isk_stage *st, FILE *out)
{
    const unsigned mode = (unsigned)st->u.osc.mode < ISK_SINLUT_MODE_COUNT ? (unsigned)st->u.osc.mode : ISK_SINLUT_LIBM;
    fprintf(out, "x, omega %g..%g rad/s, amplitude %g..%g, decay %g/s%s, sine %s%s", st->u.osc.omega_min,
            st->u.osc.omega_max, st->u.osc.amp_min, st->u.osc.amp_max, st->u.osc.decay,
            st->u.osc.faithful ? ", thesis vx coupling" : "", isk_sinlut_mode_names[mode],
            mode == ISK_SINLUT_LIBM ? "" : " (4096-entry table)");
}

const isk_stage_kind isk__stage_oscillate = {
    .name = "oscillate", .run = run_oscillate, .describe = describe_oscillate,
    .rest = NULL /* a phase that moves on */};

/* The stages a drift+sway stage stands for, in list order: the drift (or
 * the thesis-order drift), the slow stage for the sound order, the sway.
 * Returns how many. */
static int drift_sway_parts(const isk_stage *st, isk_stage part[3])
{
    memset(part, 0, 3 * sizeof *part);
    int n = 0;
    if (st->u.drift_sway.order == ISK_DRIFT_THESIS) {
        part[n].kind = &isk__stage_drift_slow;
        part[n].u.drift_slow.ax = st->u.drift_sway.ax;
        part[n].u.drift_slow.ay = st->u.drift_sway.ay;
        part[n++].u.drift_slow.slowing = st->u.drift_sway.slowing;
    } else {
        part[n].kind = &isk__stage_drift;
        part[n].u.drift.ax = st->u.drift_sway.ax;
        part[n++].u.drift.ay = st->u.drift_sway.ay;
        if (st->u.drift_sway.order == ISK_DRIFT_SOUND) {
            part[n].kind = &isk__stage_slow;
            part[n++].u.slow.slowing = st->u.drift_sway.slowing;
        }
    }
    part[n].kind = &isk__stage_oscillate;
    part[n++].u.osc = st->u.drift_sway.osc;
    return n;
}

/* One pass where the AVX2 build takes it (sim/sway.h), else the stages it
 * stands for one after the other: the same bits either way. */
static void run_drift_sway(const isk_stage *st, isk_block *b, double h)
{
    isk_particles *p = b->p;
    const size_t o = b->first;
    const isk_sway w = sway_of(&st->u.drift_sway.osc, h);
    const isk_sway_drift d = {st->u.drift_sway.ax, st->u.drift_sway.ay, slow_factor(st->u.drift_sway.slowing, h),
                              st->u.drift_sway.order};
    if (isk__sway_drift_build(1, &d, &w, b->n, b->x, b->y, b->vx, b->vy, p->osc_amp + o, p->osc_phase + o,
                             p->osc_omega + o, p->osc_offset + o))
        return;
    isk_stage part[3];
    const int n = drift_sway_parts(st, part);
    for (int k = 0; k < n; k++)
        part[k].kind->run(&part[k], b, h);
}

/* As the stages it stands for, a line each: `iskra describe` reads the
 * same whether the list fused them or not. */
static void describe_drift_sway(const isk_stage *st, FILE *out)
{
    isk_stage part[3];
    const int n = drift_sway_parts(st, part);
    part[0].kind->describe(&part[0], out);
    for (int k = 1; k < n; k++) {
        fputc('\n', out);
        isk__stage_describe_line(&part[k], out);
    }
}

const isk_stage_kind isk__stage_drift_sway = {
    .name = "drift", .run = run_drift_sway, .describe = describe_drift_sway, .rest = NULL /* the sway's phase */};

