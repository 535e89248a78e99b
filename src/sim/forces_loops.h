/* SPDX-License-Identifier: MIT */
/* src/sim/forces_loops.h — the Coulomb potential's loop over a block
 * (internal), which forces.c compiles for every CPU and forces_avx2.c for
 * AVX2 (twice the lanes for the sqrt and the divisions; the same IEEE
 * operations in the same order, no FMA: -ffp-contract=off, so the same
 * bits).
 *
 *     COULOMB_AS(coulomb_21, static, 2, 1)   // P = 2, the sound centre rule
 *
 * defines a coulomb_fn for one (power kind, centre rule); a table of six
 * is indexed [power kind * 2 + sound]. */
#ifndef ISKRA_SIM_FORCES_LOOPS_H
#define ISKRA_SIM_FORCES_LOOPS_H

#include <stddef.h>
#include <stdint.h>

#include "core/cpu.h"
#include "sim/kernels.h"

/* One specialised loop per (power kind, centre rule): both are constants
 * here, so the loop body has no scene-level branch.  Every loop vectorizes
 * but the pow() variants, which call libm: the sound-mode loops reduce
 * their "all forces representable" flag as an integer or of the kernel's
 * keep masks (isk_k_force_keep).  The rare particles whose force saturates
 * get 0 in the first pass and their saturated force in a second one, which
 * runs only when the first saw any. */
static inline void coulomb_loop(size_t n, const double *restrict x, const double *restrict y,
                                double *restrict px, double *restrict py, double cx, double cy,
                                double s, double xm, double minv, double P, const int kind,
                                const int sound)
{
    uint64_t all_ok = 1;
    for (size_t i = 0; i < n; i++) {
        double fx, fy;
        all_ok &= (uint64_t)isk_k_coulomb(cx, cy, x[i], y[i], s, xm, minv, P, kind, sound, &fx, &fy);
        double ax = px[i] + fx, ay = py[i] + fy;
        px[i] = ax;
        py[i] = ay;
    }
    if (!sound || all_ok)
        return;
    for (size_t i = 0; i < n; i++) {
        double fx, fy;
        if (isk_k_coulomb(cx, cy, x[i], y[i], s, xm, minv, P, kind, sound, &fx, &fy))
            continue;
        isk_k_coulomb_saturated(cx, cy, x[i], y[i], s, xm, &fx, &fy);
        px[i] = px[i] + fx;
        py[i] = py[i] + fy;
    }
}

typedef void (*coulomb_fn)(size_t n, const double *restrict x, const double *restrict y, double *restrict px,
                           double *restrict py, double cx, double cy, double s, double xm, double minv, double P);

#define COULOMB_AS(name, attr, kind, sound)                                                                      \
    attr void name(size_t n, const double *restrict x, const double *restrict y, double *restrict px,           \
                   double *restrict py, double cx, double cy, double s, double xm, double minv, double P)         \
    {                                                                                                            \
        coulomb_loop(n, x, y, px, py, cx, cy, s, xm, minv, P, kind, sound);                                     \
    }
#define COULOMB_ROW(p) {p##00, p##01, p##10, p##11, p##20, p##21}

#if ISK__CPU_AVX2
/* forces_avx2.c's loops, for a CPU that has AVX2 */
extern const coulomb_fn isk__coulomb_loops_avx2[6];
#endif

#endif
