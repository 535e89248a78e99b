/* SPDX-License-Identifier: MIT */
/* The fire's sway over a block, the portable loops, and the one place that
 * picks sway_avx2.c's twins (see sway.h). */
#include "sim/sway.h"

#include <math.h>
#include <stdint.h>

#include "core/cpu.h" /* ISK__CPU_AVX2, isk__have_avx2 */
#include "sim/sway_loops.h"

static inline void sway_loop(size_t n, double *restrict x, double *restrict vx, double *restrict amp,
                             double *restrict ph, const double *restrict om, double *restrict off,
                             const isk_sway *w, const int mode, const int faithful)
{
    for (size_t i = 0; i < n; i++)
        sway_one(i, x, vx, amp, ph, om, off, w, mode, faithful);
}

#define SWAY_AS(name, mode, faithful)                                                                            \
    static void name(size_t n, double *x, double *vx, double *amp, double *ph, const double *om, double *off,   \
                     const isk_sway *w)                                                                          \
    {                                                                                                            \
        sway_loop(n, x, vx, amp, ph, om, off, w, mode, faithful);                                               \
    }
SWAY_AS(sway_00, 0, 0) SWAY_AS(sway_01, 0, 1) SWAY_AS(sway_10, 1, 0) SWAY_AS(sway_11, 1, 1)
SWAY_AS(sway_20, 2, 0) SWAY_AS(sway_21, 2, 1) SWAY_AS(sway_30, 3, 0) SWAY_AS(sway_31, 3, 1)
#undef SWAY_AS
/* [mode][faithful], modes in isk_sinlut_mode order. */
static const sway_fn sway_loops[ISK_SINLUT_MODE_COUNT][2] = {
    {sway_00, sway_01}, {sway_10, sway_11}, {sway_20, sway_21}, {sway_30, sway_31}};

/* 1 when every index*stride of the table, +stride, is an int32 (always,
 * for the tables isk_sinlut_init makes: at most 65536). */
static int gatherable(const isk_sinlut *t)
{
    return t && t->mask < (uint64_t)INT32_MAX && t->stride <= (uint64_t)INT32_MAX / (t->mask + 1u);
}

/* 1 when sway_avx2.c's loops may take this table sine: the caller asks
 * for them (avx2), a table sine (libm's sin has no AVX2 loop), 32-bit
 * offsets, a CPU with AVX2. */
static int fast_sine(int avx2, unsigned mode, const isk_sinlut *t)
{
    return avx2 && mode < ISK_SINLUT_LIBM && gatherable(t) && isk__have_avx2();
}

void isk__sway_build(int avx2, const isk_sway *w, size_t n, double *x, double *vx, double *amp, double *phase,
                    const double *omega, double *offset)
{
    const unsigned mode = (unsigned)w->mode < ISK_SINLUT_MODE_COUNT ? (unsigned)w->mode : ISK_SINLUT_LIBM;
#if ISK__CPU_AVX2
    if (fast_sine(avx2, mode, w->table)) {
        isk__sway_loops_avx2[mode][w->faithful != 0](n, x, vx, amp, phase, omega, offset, w);
        return;
    }
#else
    (void)avx2; /* no AVX2 build to choose */
#endif
    sway_loops[mode][w->faithful != 0](n, x, vx, amp, phase, omega, offset, w);
}

void isk__sway_run(const isk_sway *w, size_t n, double *x, double *vx, double *amp, double *phase,
                  const double *omega, double *offset)
{
    isk__sway_build(1, w, n, x, vx, amp, phase, omega, offset);
}

int isk__sway_drift_build(int avx2, const isk_sway_drift *d, const isk_sway *w, size_t n, double *x, double *y,
                         double *vx, double *vy, double *amp, double *phase, const double *omega, double *offset)
{
    const unsigned order = (unsigned)d->order, mode = (unsigned)w->mode;
    if (order > ISK_DRIFT_SOUND || !fast_sine(avx2, mode, w->table))
        return 0;
#if ISK__CPU_AVX2
    const drift_c c = drift_c_of(d, w->h);
    isk__drift_sway_loops_avx2[order][mode * 2 + (w->faithful != 0)](n, x, y, vx, vy, amp, phase, omega, offset, &c,
                                                                     w);
    return 1;
#else
    (void)n, (void)x, (void)y, (void)vx, (void)vy, (void)amp, (void)phase, (void)omega, (void)offset;
    return 0;
#endif
}
