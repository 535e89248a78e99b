/* SPDX-License-Identifier: MIT */
/* src/sim/rest_screen.h — the walls' resting screen: which particles of a
 * group the bounces at the time of impact rest at once (internal).
 *
 * A particle lying on a floor ends every step just below it and comes back
 * resting: impact_axis (src/sim/bounds.c) reconstructs its flight from the
 * end state, finds it within rounding of the floor and nearly still, and
 * puts it back on the floor with the integrator's offset velocity.  When
 * the particles have one mass their end states repeat and bounds.c's memo
 * answers them; with many masses (explosions, mass ranges) each needs the
 * reconstruction, a dependent chain of two divisions and the basis series,
 * slow in scalar code (docs/performance.md, "Where the constants come from").  The screen does the same operations
 * for a whole group on vector lanes:
 *
 *     isk_rest_axis ax = {a, delta, h, lo, hi, c};   // one axis, from the end state
 *     isk__rest_screen_pick()(n, y, vy, m, drag, &ax, rest);   // n <= ISK_WALL_SCREEN
 *     // rest[j] == 1: impact_axis rests particle j on lo; 2: on hi;
 *     // 0: it does something else, or the screen cannot tell (the series
 *     // does not cover its drag rate, no drag and a mass 0, ...): ask it
 *
 * m is NULL, or drag 0, for the flight without drag (k = 0 for every mass).
 * The caller makes sure a and delta are finite and a != 0.  A 1 or 2 is a
 * verdict: the same IEEE operations in the same order as impact_axis, so
 * the same doubles and the same comparisons (tests/test_rest_screen.c
 * checks every build against the walls themselves).
 *
 * Three builds of the same C loop: the portable one (what the compiler
 * makes of it for the baseline target, SSE2 on x86-64) and, on x86-64 CPUs
 * that have them, AVX2 and AVX-512, chosen at run time (AVX-512's 32
 * registers and mask registers). */
#ifndef ISKRA_SIM_REST_SCREEN_H
#define ISKRA_SIM_REST_SCREEN_H

#include <math.h>
#include <stddef.h>

typedef struct isk_rest_axis {
    double a, delta; /* the constant acceleration and the integrator's velocity offset (a h offset) */
    double h;        /* the step */
    double lo, hi;   /* the walls (a missing one at -inf / +inf) */
    double c;        /* their restitution */
} isk_rest_axis;

/* The resting contact at once (iskra/impact.h): a particle within *near of
 * a wall it is pressed into, no faster than *slow, rests without a root
 * solve.  That is sound only when all its further hops fit in the step:
 * they start at most at V = 0.178 |a| h (V^2 <= 2 |a| near + slow^2) and
 * last 2 V / (|a| (1 - c)) in all, within h while c <= 0.64; above that
 * both bounds shrink with 1 - c, to nothing at c = 1, where hops do not
 * shrink and only a particle on the wall at speed 0 rests.  One rule for
 * the walls and this screen. */
static inline void isk__rest_at_once(double a, double h, double c, double *near, double *slow)
{
    const double f = c <= 0.64 ? 1.0 : (1.0 - c) / 0.36;
    *near = fabs(a) * h * h / 64.0 * (f * f);
    *slow = fabs(a) * h / 64.0 * f;
}

typedef void (*isk_rest_screen_fn)(size_t n, const double *pos, const double *vel, const double *m, double drag,
                                   const isk_rest_axis *ax, double *rest);

void isk__rest_screen_portable(size_t n, const double *pos, const double *vel, const double *m, double drag,
                              const isk_rest_axis *ax, double *rest);
/* The AVX2 and AVX-512 builds, each NULL when this build or this CPU has
 * none. */
isk_rest_screen_fn isk__rest_screen_avx2(void);
isk_rest_screen_fn isk__rest_screen_avx512(void);
/* The fastest build this CPU runs. */
isk_rest_screen_fn isk__rest_screen_pick(void);

#endif
