/* SPDX-License-Identifier: MIT */
/* src/sim/motion_fused.h — forces + integrator in one pass over a block, for
 * the common cases (internal).
 *
 * The general path of a motion stage makes seven passes over a block
 * (iskra/integrate.h's isk_integrate_block: clear fx and fy, gravity, drag
 * with its flush and saturation, the integrator, then the runner's two
 * non-finite checks), and with potentials four more (clear px and py, a
 * pass per potential, F += P).  When the integrator is semi-implicit or
 * explicit Euler and each potential that acts has the exponent P = 2 or
 * P = 1 and no max distance (at most four of them, all of the forces'
 * potentials or its pick list), the same operations in the same order per
 * particle fit in one loop that reads x, y, vx, vy, m once and writes
 * x, y, vx, vy once: 72 B a particle-step, the bandwidth limit's own count.
 *
 *     int nonfinite;
 *     if (!isk__motion_fused(method, forces, isk_forces_laws(forces), n, x, y, vx, vy, m, dt, NULL,
 *                            &nonfinite))
 *         ... the general path (isk_integrate_block + the checks) ...
 *
 * The bits are the general path's, for every input (tests/test_motion_fused.c):
 * the force sums start from +0.0 and add each force as the general path
 * does (0.0 + m*(-g) is not m*(-g) for a zero mass of negative sign, and
 * vx + c*(+0.0) turns a -0 velocity into +0; with potentials the leading
 * +0.0 goes where it provably changes no bit, motion_fused.c's pot_step),
 * the drag flushes and saturates as forces.c's drag stage, the potentials
 * are summed on their own from +0.0 in their order and added last, and
 * the non-finite check is the same bit test (isk_k_nonfinite_bits).  Under
 * the sound centre rule a block in which some force is not representable
 * (a particle on or very near a potential) is stepped again from its old
 * state by scalar code that replaces and saturates that force as forces.c
 * does (its second pass).
 *
 * Declined (0, nothing touched; the general path runs): other integrators,
 * an exponent other than 2 or 1 (pow()), a max distance (its switch-off
 * depends on the particles' order and changes the potential), a fifth
 * potential, drag with a zero step.  Potentials that do not act (disabled,
 * or k*Q == 0) are skipped as forces.c skips them. */
#ifndef ISKRA_SIM_MOTION_FUSED_H
#define ISKRA_SIM_MOTION_FUSED_H

#include <stddef.h>

#include "iskra/forces.h"
#include "iskra/integrate.h"

/* The force laws the pass knows (iskra/forces.h): it declines any set
 * with another, so a law the library gains is summed by the general path
 * until the pass learns it. */
#define ISK__FUSED_LAWS (ISK_LAW_GRAVITY | ISK_LAW_ACCEL | ISK_LAW_DRAG | ISK_LAW_POWER_2 | ISK_LAW_POWER_1)

/* Where the pass stores the state each particle starts the step from (n
 * entries each), for the contact stages that bounce at the time of impact
 * (iskra/impact.h): what the remember stage copies, stored by the loop as
 * it reads it instead of in a pass of its own (stage.h's motion.remember).
 * Never the same memory as the columns. */
typedef struct isk_motion_start {
    double *x, *y, *vx, *vy;
} isk_motion_start;

/* The block runner's: the scratch's x_old, y_old, vx_old, vy_old. */
static inline isk_motion_start isk_motion_start_of(isk_scratch *s)
{
    return (isk_motion_start){s->x_old, s->y_old, s->vx_old, s->vy_old};
}

/* The start state kept by a copy of its own, where no fused loop stores it
 * on the way (the remember stage, a motion stage on the general path).
 * One loop over the four columns rather than
 * four memcpy: the copy is the first to read a block from memory, and four
 * streams at once keep four misses in flight where a memcpy a column waits
 * for one column's lines after another's (docs/performance.md, "Where the constants come from"). */
static inline void isk_motion_start_copy(const isk_motion_start *s, size_t n, const double *x, const double *y,
                                         const double *vx, const double *vy)
{
    double *restrict sx = s->x, *restrict sy = s->y, *restrict svx = s->vx, *restrict svy = s->vy;
    for (size_t i = 0; i < n; i++) {
        sx[i] = x[i];
        sy[i] = y[i];
        svx[i] = vx[i];
        svy[i] = vy[i];
    }
}

/* Steps the n particles and returns 1 when the fused pass covers this
 * method and these forces (then *nonfinite is 1 when some new x, y, vx or
 * vy is not finite, else 0, and the old state is in *start unless start is
 * NULL); returns 0, touching nothing, otherwise.  laws: isk_forces_laws(f),
 * or a set that holds it (the motion stage keeps it from when its list was
 * made: the laws only shrink until the next compile); a law outside
 * ISK__FUSED_LAWS declines. */
int isk__motion_fused(isk_integrator method, const isk_forces *f, unsigned laws, size_t n, double *x, double *y,
                      double *vx, double *vy, const double *m, double dt, const isk_motion_start *start,
                      int *nonfinite);

/* The same with the widest build it may take: simd = 0 the portable
 * loops, 1 AVX2, 2 AVX-512, each only when the CPU has it
 * (src/core/cpu.h's isk__simd_level).  isk__motion_fused takes the
 * widest; the tests compare them all. */
int isk__motion_fused_build(int simd, isk_integrator method, const isk_forces *f, size_t n, double *x, double *y,
                           double *vx, double *vy, const double *m, double dt, const isk_motion_start *start,
                           int *nonfinite);
/* 1 when some potential of f (its pick, or all of them) is enabled: the
 * test isk_forces_eval_step makes before it evaluates potentials (forces.c). */
int isk__forces_potentials_on(const isk_forces *f);

#endif
