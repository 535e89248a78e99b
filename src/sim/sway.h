/* SPDX-License-Identifier: MIT */
/* src/sim/sway.h — the fire thesis's horizontal sway over a block of the
 * store (internal; the oscillate stage of stage_fire.c runs it).
 *
 * Per particle, in this order (the thesis's operations, with h the step):
 *
 *     phase += omega*h;  s = amp*sine(phase);  dx = s - offset;
 *     x += dx;  vx += dx (faithful only);  offset = s;  amp = flush(amp*decay)
 *
 * where sine is one of iskra/sinlut.h's lookups (floor, round, lerp) or
 * libm's sin, and flush is kernels.h's isk_k_flush.
 *
 *     isk_sway w = {&table, ISK_SINLUT_LERP, 1, decay_factor, h};
 *     isk__sway_run(&w, n, x, vx, amp, phase, omega, offset);
 *
 * Two builds of every (sine, faithful) loop, the same bits for every input
 * (tests/test_sway.c checks them against a frozen copy of the scalar code):
 *   portable: the lookups of iskra/sinlut.h one particle at a time (not
 *     vectorized: the huge-angle branch, the 64-bit index, the table
 *     reads; libm's floor is a call on baseline x86-64, but glibc runs
 *     roundsd where the CPU has SSE4.1, and an inline exact floor measured
 *     no faster);
 *   AVX2, chosen at run time: four particles a step for the three table
 *     sines.  floor by vroundpd (exact, as floor()); the index from a 32-bit
 *     conversion, whose bits mod N are the 64-bit conversion's while every
 *     |t| < 2^31 (t the angle in table steps); the entries by gathers.  A
 *     group of four with a larger, infinite or NaN angle runs the portable
 *     code (huge angles take isk_sinlut_reduce_slow there).  libm's sin
 *     stays one particle at a time (gcc offers a vector sin only under the
 *     value-changing flags the Makefile refuses).
 * The same IEEE operations in the same order either way (no FMA:
 * -ffp-contract=off, and the avx2 target has none).
 *
 * In a fire's list the sway follows the drift (the constant acceleration
 * with semi-implicit Euler, maybe slowed), and isk__sway_drift_build runs
 * both in one pass: the block's x and vx stay in registers from the one
 * to the other, and the eight columns stream together.  AVX2 only; where
 * it declines, the caller runs the stages one after the other, which
 * gives the same bits (tests/test_sway.c checks both against the frozen
 * scalar code). */
#ifndef ISKRA_SIM_SWAY_H
#define ISKRA_SIM_SWAY_H

#include <stddef.h>

#include "iskra/sinlut.h"

typedef struct isk_sway {
    const isk_sinlut *table; /* for the table sines (not read for ISK_SINLUT_LIBM) */
    isk_sinlut_mode mode;    /* an invalid mode reads libm's sin */
    int faithful;            /* 1: vx += dx too (the thesis's code) */
    double decay;            /* the amplitude's factor a step, max(0, 1 - decay*h) */
    double h;                /* the step */
} isk_sway;

/* Sways the n particles (columns offset to the first). */
void isk__sway_run(const isk_sway *w, size_t n, double *x, double *vx, double *amp, double *phase,
                  const double *omega, double *offset);

/* The drift before the sway (what isk__stage_drift_sway fuses). */
typedef enum isk_drift_order {
    ISK_DRIFT_PLAIN = 0,  /* isk__stage_drift: v += a*h; p += h*v (vx kept as it is when ax == 0) */
    ISK_DRIFT_THESIS = 1, /* isk__stage_drift_slow: v = flush((v + a*h)*f); p += h*v */
    ISK_DRIFT_SOUND = 2   /* isk__stage_drift, then isk__stage_slow: v += a*h; p += h*v; v = flush(v*f) */
} isk_drift_order;

typedef struct isk_sway_drift {
    double ax, ay;         /* the constant acceleration */
    double f;              /* the slowing factor max(0, 1 - slowing*h) (THESIS, SOUND) */
    isk_drift_order order;
} isk_sway_drift;

/* The drift d with step w->h, then the sway w, of the n particles in one
 * pass: 1 when the AVX2 build ran (avx2 != 0, the CPU has it, a table sine
 * and a table whose offsets fit 32 bits); else 0, touching nothing. */
int isk__sway_drift_build(int avx2, const isk_sway_drift *d, const isk_sway *w, size_t n, double *x, double *y,
                         double *vx, double *vy, double *amp, double *phase, const double *omega, double *offset);

/* The same with the build chosen: avx2 = 0 the portable loops, 1 the AVX2
 * ones when isk__have_avx2() (src/core/cpu.h), else the portable ones
 * too.  isk__sway_run takes the fastest; the tests compare both. */
void isk__sway_build(int avx2, const isk_sway *w, size_t n, double *x, double *vx, double *amp, double *phase,
                    const double *omega, double *offset);

#endif
