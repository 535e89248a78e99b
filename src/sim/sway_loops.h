/* SPDX-License-Identifier: MIT */
/* src/sim/sway_loops.h — one particle's sway and drift, the operations
 * every build of the fire's loops follows (internal): sway.c's portable
 * loops and sway_avx2.c's four particles a step, whose groups that cannot
 * take the vector path (huge angles) and whose last particles run these.
 *
 *     sway_one(i, x, vx, amp, ph, om, off, w, mode, faithful);   // sway.h's rule
 *     drift_one(i, x, y, vx, vy, &c, order);                      // the drift stages'
 */
#ifndef ISKRA_SIM_SWAY_LOOPS_H
#define ISKRA_SIM_SWAY_LOOPS_H

#include <math.h>
#include <stddef.h>

#include "core/cpu.h"
#include "sim/kernels.h"
#include "sim/sway.h"

/* The sine of the sway, read as the emitter asks: `mode` is a constant at
 * every call below, so the loops have no per-particle branch on it. */
static inline double sway_sine(const isk_sinlut *t, const int mode, double ph)
{
    switch (mode) {
    case ISK_SINLUT_FLOOR: return isk_sinlut_floor(t, ph);
    case ISK_SINLUT_ROUND: return isk_sinlut_round(t, ph);
    case ISK_SINLUT_LERP: return isk_sinlut_lerp(t, ph);
    default: return sin(ph);
    }
}

/* Particle i, sway.h's operations in their order. */
static inline void sway_one(size_t i, double *restrict x, double *restrict vx, double *restrict amp,
                            double *restrict ph, const double *restrict om, double *restrict off,
                            const isk_sway *w, const int mode, const int faithful)
{
    ph[i] += om[i] * w->h;
    double s = amp[i] * sway_sine(w->table, mode, ph[i]);
    double dx = s - off[i];
    x[i] += dx;
    if (faithful)
        vx[i] += dx;
    off[i] = s;
    amp[i] = isk_k_flush(amp[i] * w->decay);
}

/* The drift's constants for a block: dvx = ax*h and dvy = ay*h as the
 * drift stages form them; keep_vx where vx is left as it is (the plain
 * drift with ax == 0, whose loop does not store vx: v + 0 would turn a
 * -0 into +0). */
typedef struct drift_c {
    double dvx, dvy, f, h;
    int keep_vx;
} drift_c;

static inline drift_c drift_c_of(const isk_sway_drift *d, double h)
{
    drift_c c = {d->ax * h, d->ay * h, d->f, h, d->order != ISK_DRIFT_THESIS && d->ax == 0.0};
    return c;
}

/* Particle i's drift, the drift stages' operations (stage_motion.c's
 * drift_loop, stage_fire.c's run_drift_slow and run_slow) in their order. */
static inline void drift_one(size_t i, double *restrict x, double *restrict y, double *restrict vx,
                             double *restrict vy, const drift_c *c, const int order)
{
    double wx, wy;
    if (order == ISK_DRIFT_THESIS) {
        wx = isk_k_flush((vx[i] + c->dvx) * c->f);
        wy = isk_k_flush((vy[i] + c->dvy) * c->f);
    } else {
        wx = c->keep_vx ? vx[i] : vx[i] + c->dvx;
        wy = vy[i] + c->dvy;
    }
    x[i] = x[i] + c->h * wx;
    y[i] = y[i] + c->h * wy;
    if (order == ISK_DRIFT_SOUND) {
        wx = isk_k_flush(wx * c->f);
        wy = isk_k_flush(wy * c->f);
    }
    vx[i] = wx;
    vy[i] = wy;
}

typedef void (*sway_fn)(size_t, double *, double *, double *, double *, const double *, double *, const isk_sway *);
typedef void (*drift_sway_fn)(size_t, double *, double *, double *, double *, double *, double *, const double *,
                              double *, const drift_c *, const isk_sway *);

#if ISK__CPU_AVX2
/* sway_avx2.c's loops, for a CPU that has AVX2 and a table whose offsets
 * fit 32 bits: the sway [mode][faithful] and the drift then the sway
 * [order][mode * 2 + faithful], for the three table sines. */
extern const sway_fn isk__sway_loops_avx2[ISK_SINLUT_LIBM][2];
extern const drift_sway_fn isk__drift_sway_loops_avx2[3][2 * ISK_SINLUT_LIBM];
#endif

#endif
