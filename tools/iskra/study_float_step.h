/* SPDX-License-Identifier: MIT */
/* tools/iskra/study_float_step.h — the float study's fused semi-implicit
 * Euler step (gravity + linear drag), written once for double and float so
 * the two cannot drift apart; tests/test_knobs.c checks that the double one
 * gives the library's bits, which is what makes the float one "the
 * library's formula in float".
 *
 * The library's drag stage first flushes speeds below ISK_FLUSH_TINY to 0
 * (iskra/integrate.h) and sums the forces as fx = 0 + (-b) vx,
 * fy = (0 + m(-g)) + (-b) vy; then isk_k_semi_euler: c = dt/m; v += c F;
 * r += dt v_new.  A float path needs its own flush threshold: 1e-200 is 0
 * in float, and float's subnormals start at 1.2e-38, so 1e-30 plays the
 * same role.  The library's kernels get g and b at run time from another
 * translation unit; here gcc would propagate constant arguments into the
 * loop and then no longer vectorize it, so interprocedural optimisation is
 * switched off for these functions (to measure what a library float path
 * would run). */
#ifndef ISKRA_TOOL_STUDY_FLOAT_STEP_H
#define ISKRA_TOOL_STUDY_FLOAT_STEP_H

#include <math.h>
#include <stddef.h>

#include "iskra/integrate.h"

#if defined(__GNUC__) && !defined(__clang__)
#define STUDY_NOIPA __attribute__((noipa))
#else
#define STUDY_NOIPA __attribute__((noinline))
#endif

#define STUDY_DEFINE_STEP(NAME, T, TINY, ABS)                                                                \
    static STUDY_NOIPA void NAME(size_t n, T *restrict x, T *restrict y, T *restrict vx, T *restrict vy,     \
                                 const T *restrict m, T g, T b, T dt)                                        \
    {                                                                                                        \
        for (size_t i = 0; i < n; i++) {                                                                     \
            T vx0 = vx[i], vy0 = vy[i]; /* loaded first, so the selects if-convert */                       \
            T ux = isless(ABS(vx0), TINY) ? (T)0 : vx0;                                                      \
            T uy = isless(ABS(vy0), TINY) ? (T)0 : vy0;                                                      \
            T fx = (T)0 + (-b) * ux;                                                                         \
            T fy = ((T)0 + m[i] * (-g)) + (-b) * uy;                                                         \
            T c = dt / m[i];                                                                                 \
            T nvx = ux + c * fx, nvy = uy + c * fy;                                                          \
            vx[i] = nvx;                                                                                     \
            vy[i] = nvy;                                                                                     \
            x[i] = x[i] + dt * nvx;                                                                          \
            y[i] = y[i] + dt * nvy;                                                                          \
        }                                                                                                    \
    }
STUDY_DEFINE_STEP(study_step_double, double, ISK_FLUSH_TINY, fabs)
STUDY_DEFINE_STEP(study_step_float, float, 1e-30f, fabsf)

#endif
