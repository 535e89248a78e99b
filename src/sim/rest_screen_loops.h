/* SPDX-License-Identifier: MIT */
/* src/sim/rest_screen_loops.h — the walls' resting screen as one C loop
 * (internal), which rest_screen.c compiles for every CPU and
 * rest_screen_avx2.c, rest_screen_avx512.c for AVX2 and AVX-512 (gcc
 * vectorizes it four and eight lanes wide there; the same IEEE operations
 * in the same order, so the same verdicts).
 *
 * Written so that gcc vectorizes it: the tests as isless.. combined with
 * `&` (no short circuit), no `a ? b : c ? d : e` chain (gcc sinks the
 * second test's subtraction under a branch and then cannot speculate it),
 * tests on the raw values rather than on selects of them, and the answer
 * as a double (baseline SSE2 cannot pack a double's mask into an integer).
 * Each line names the step of impact_axis it is. */
#ifndef ISKRA_SIM_REST_SCREEN_LOOPS_H
#define ISKRA_SIM_REST_SCREEN_LOOPS_H

#include <float.h>
#include <math.h>

#include "core/cpu.h"
#include "sim/flight.h"
#include "sim/rest_screen.h"

static const double EPS = 2.220446049250313e-16;

static inline void rest_screen_loop(size_t n, const double *restrict pos, const double *restrict vel,
                          const double *restrict m, double drag, const isk_rest_axis *ax, double *restrict rest,
                          const int with_drag)
{
    const double a = ax->a, delta = ax->delta, h = ax->h, lo = ax->lo, hi = ax->hi;
    double near, slow;
    isk__rest_at_once(a, h, ax->c, &near, &slow);
    const double lo_side = a < 0.0 ? 1.0 : 0.0, hi_side = a > 0.0 ? 1.0 : 0.0;
    for (size_t i = 0; i < n; i++) {
        const double p1 = pos[i], v1 = vel[i];
        /* the basis over the step: isk__fl_basis (k = 0: no drag) */
        double e = 1.0, d1 = h, d2 = 0.5 * h * h;
        int covered = 1;
        if (with_drag) {
            const double k = drag / m[i], z = k * h;
            isk_fl_basis_series(z, h, &e, &d1, &d2);
            covered = isgreater(k, 0.0) & isless(z, ISK_FL_SERIES_MAX); /* else isk__fl_basis takes another branch */
        }
        /* isk__fl_from_end */
        const double U = ((v1 - delta) - a * d1) / e;
        double P = p1 - U * d1 - a * d2;
        /* a start within rounding of a wall is on it: P < lo as lo - P > 0,
         * the same test (a difference of doubles is 0 only for equal ones) */
        const double tol = 64 * EPS * (fabs(p1) + fabs(U) * h + fabs(a) * h * h);
        const double below = lo - P, above = P - hi;
        const int to_lo = isgreater(below, 0.0) & islessequal(below, tol);
        const int to_hi = isgreater(above, 0.0) & islessequal(above, tol); /* never both: lo < hi */
        P = to_lo ? lo : P;
        P = to_hi ? hi : P;
        /* a start velocity within rounding of zero is zero */
        const double U0 = islessequal(fabs(U), 64 * EPS * (fabs(v1) + fabs(a) * h)) ? 0.0 : U;
        /* finite input, a start between the walls, a finite U (U0 is
         * finite when U is: the test on U keeps gcc's masks simple) */
        const int ok = covered & islessequal(fabs(p1), DBL_MAX) & islessequal(fabs(v1), DBL_MAX) &
                       isgreaterequal(P, lo) & islessequal(P, hi) & islessequal(fabs(U), DBL_MAX);
        /* the resting contact at once */
        const int on_lo = islessequal(P - lo, near) & islessequal(fabs(U0), slow);
        const int on_hi = islessequal(hi - P, near) & islessequal(fabs(U0), slow);
        rest[i] = (ok & on_lo ? lo_side : 0.0) + (ok & on_hi ? 2.0 * hi_side : 0.0);
    }
}

/* The loop for one call: with drag (a mass per particle) or without,
 * each a constant of its copy of the loop. */
static ISK__INLINE void rest_screen_run(size_t n, const double *pos, const double *vel, const double *m, double drag,
                                        const isk_rest_axis *ax, double *rest)
{
    if (m && drag > 0.0)
        rest_screen_loop(n, pos, vel, m, drag, ax, rest, 1);
    else
        rest_screen_loop(n, pos, vel, m, drag, ax, rest, 0);
}

#if ISK__CPU_AVX2
/* rest_screen_avx2.c, for a CPU that has AVX2 */
void isk__rest_screen_in_avx2(size_t n, const double *pos, const double *vel, const double *m, double drag,
                             const isk_rest_axis *ax, double *rest);
#endif
#if ISK__CPU_AVX512
/* rest_screen_avx512.c, for a CPU that has AVX-512 */
void isk__rest_screen_in_avx512(size_t n, const double *pos, const double *vel, const double *m, double drag,
                               const isk_rest_axis *ax, double *rest);
#endif

#endif
