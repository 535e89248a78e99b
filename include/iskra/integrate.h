/* SPDX-License-Identifier: MIT */
/* iskra/integrate.h — time integrators over the particle arrays.
 *
 * Eight methods, selectable per system (isk_system.integrator) and per scene
 * (`integrator = ...`):
 *
 *   ISK_INTEGRATE_SEMI_EULER  the thesis CODE (MaterijalnaTocka.pomakni):
 *                             c = dt/m; v += c*F; r += dt*v (new v).  1st order,
 *                             symplectic.  Bit-exact with the JavaScript.
 *   ISK_INTEGRATE_EULER       explicit Euler as the thesis TEXT derives it:
 *                             r += dt*v_old; v += (dt/m)*F.  Energy grows.
 *   ISK_INTEGRATE_VERLET      velocity Verlet: r += dt*v + (dt^2/2)*a(r,v);
 *                             v_half = v + (dt/2)*a; v = v_half + (dt/2)*a(r', v_half).
 *                             Two force evaluations per step (the first is not
 *                             cached between steps, so emitters, removals and
 *                             parameter edits between steps need no bookkeeping).
 *   ISK_INTEGRATE_RK4         classic Runge–Kutta on (r, v) with the forces
 *                             re-evaluated at every stage (F = F(r, v)); 4 evals.
 *   ISK_INTEGRATE_EXACT_DRAG  exact solution of dv/dt = -(b/m) v + a, with b the
 *                             linear drag and a = (all other forces)/m held
 *                             constant over the step (gravity is constant, so it
 *                             is exact for gravity + drag; potentials are frozen
 *                             at the start of the step).  With h = b*dt/m:
 *                               v' = v e^{-h} + a dt phi1(h)
 *                               r' = r + v dt phi1(h) + a dt^2 phi2(h)
 *                             phi1 = (1 - e^{-h})/h = -expm1(-h)/h,
 *                             phi2 = (h - 1 + e^{-h})/h^2 (Taylor series for
 *                             h < 0.1, where the direct form cancels).
 *                             Stable and monotone for every b*dt/m >= 0.
 *                             Not vectorized (expm1 is a libm call).
 *   ISK_INTEGRATE_LEAPFROG    Stormer-Verlet, kick-drift-kick: v += (dt/2) a(r);
 *                             r += dt v; v += (dt/2) a(r').  The linear drag is split
 *                             symmetrically (explicit in the first half kick, solved
 *                             for the new velocity in the second), so it is second
 *                             order with drag too, and time-reversible; symplectic
 *                             without drag.  The force at r' is kept for the next
 *                             stage: one evaluation per step plus one.
 *   ISK_INTEGRATE_YOSHIDA4    Yoshida's fourth-order composition of three leapfrog
 *                             steps of w1 dt, w0 dt, w1 dt (w1 = 1/(2 - 2^(1/3)),
 *                             w0 = 1 - 2 w1 < 0): fourth order, symplectic without
 *                             drag, four force evaluations.
 *   ISK_INTEGRATE_STRANG      Strang splitting: the exact flight under the linear drag
 *                             alone for dt/2 (v e^-kt, r + v (1 - e^-kt)/k), a kick
 *                             v += dt F(r)/m by every other force, the flight for dt/2
 *                             again: drift-kick-drift with the drift solved exactly.
 *                             Second order with drag, symmetric, symplectic without
 *                             it, one force evaluation per step (e^-kt by its series
 *                             for k t < 0.1: no libm call, it vectorizes; expm1 beyond).
 *
 * Decaying speeds and subnormal numbers: linear drag shrinks a velocity by
 * a factor each step, so without gravity it sinks through the subnormal
 * range (below 2.2e-308), where this machine's floating-point unit is about
 * 100x slower, and round-to-nearest then keeps it there for good (at 5e-322,
 * v*(1 - b*dt/m) rounds back to v).  So every stage whose only effect is to
 * make a speed decay flushes components below ISK_FLUSH_TINY (1e-200) to
 * exactly zero: the drag stage (before it computes -b*v), the exact-drag
 * update, the effect runtime's slowing and its oscillation-amplitude decay.
 * 1e-200 is hundreds of orders below any visible motion and far enough above
 * the subnormal range that v*dt, b*v and dt/m*F stay normal for any sane dt
 * and b.  bench/bench_long_run.c measures the effect (10^7 steps).
 *
 * Forces come from an isk_forces (iskra/forces.h).  Verlet and RK4 evaluate
 * them at intermediate states; a potential's sticky max-distance switch can
 * then trip at an intermediate state (documented, deterministic).
 *
 * The step runs in blocks of ISK_SIM_BLOCK particles so the force
 * accumulators and RK4 stage copies stay in L1 cache: every stage is still a
 * tight loop, just over 128 particles at a time.  128, not more: a block's
 * five columns (5 KiB), the next block's, asked for ahead (5 KiB), and the
 * start state the walls keep when potentials act (4 KiB) fit a 32 KiB L1
 * with room to spare; at 256 they fill 28 KiB of it and the copy of the
 * start state slows by several times (docs/performance.md, "Where the
 * constants come from").
 *
 * Example: one RK4 step of a thrown particle under gravity:
 *
 *     isk_particles store;
 *     if (isk_particles_init(&store, 16, 0) != ISK_OK) return 1;
 *     isk_status st = isk_particles_add(&store, 0, 0, 1, 5, 1.0, NULL);   // x, y, vx, vy, m
 *     isk_forces forces = { .gravity = 9.81 };
 *     double dt = 1.0 / 60;
 *     isk_scratch s;                               // 16 KiB, no allocation
 *     if (st == ISK_OK)
 *         st = isk_integrate_range(ISK_INTEGRATE_RK4, &forces, &s, &store, 0, store.count, dt);
 *     if (st == ISK_OK) printf("(%.6f, %.6f)\n", store.x[0], store.y[0]);
 *     isk_particles_free(&store);
 *     return st != ISK_OK;
 */
#ifndef ISKRA_INTEGRATE_H
#define ISKRA_INTEGRATE_H

#include <stddef.h>

#include "iskra/forces.h"
#include "iskra/limits.h"
#include "iskra/particles.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum isk_integrator {
    ISK_INTEGRATE_INHERIT = -1, /* definitions only (an emitter of iskra/effect.h): use the
                                   enclosing scene's integrator; never valid for a step */
    ISK_INTEGRATE_SEMI_EULER = 0,
    ISK_INTEGRATE_EULER,
    ISK_INTEGRATE_VERLET,
    ISK_INTEGRATE_RK4,
    ISK_INTEGRATE_EXACT_DRAG,
    ISK_INTEGRATE_LEAPFROG,
    ISK_INTEGRATE_YOSHIDA4,
    ISK_INTEGRATE_STRANG,
    ISK_INTEGRATOR_COUNT
} isk_integrator;

#define ISK_SIM_BLOCK 128

/* Decaying speeds are flushed to 0 below this (see the top). */
#define ISK_FLUSH_TINY 1e-200

/* Per-block working arrays of every stage of the block runner: force
 * accumulators, potential sum, RK4 copies, the state before the move (for
 * bounces at the time of impact, iskra/impact.h) with the deflectors' kill
 * flags.  No alignment beyond double's is asked of it: it sits inside
 * structs a program may malloc (isk_system), and a declared 64-byte
 * alignment let the compiler use aligned vector loads that crashed on
 * malloc's 16-byte-aligned storage (a -march=native build with AVX-512).
 * The effect's threads get theirs 64-byte aligned all the same. */
typedef struct isk_scratch {
    double fx[ISK_SIM_BLOCK];
    double fy[ISK_SIM_BLOCK];
    double px[ISK_SIM_BLOCK];
    double py[ISK_SIM_BLOCK];
    double x0[ISK_SIM_BLOCK];
    double y0[ISK_SIM_BLOCK];
    double vx0[ISK_SIM_BLOCK];
    double vy0[ISK_SIM_BLOCK];
    double sx[ISK_SIM_BLOCK];
    double sy[ISK_SIM_BLOCK];
    double svx[ISK_SIM_BLOCK];
    double svy[ISK_SIM_BLOCK];
    double x_old[ISK_SIM_BLOCK];
    double y_old[ISK_SIM_BLOCK];
    double vx_old[ISK_SIM_BLOCK];
    double vy_old[ISK_SIM_BLOCK];
    unsigned char killed[ISK_SIM_BLOCK];
    int nonfinite; /* set by a motion stage whose block came out with a NaN or an infinity; the
                      runner's owner removes and counts those particles and clears it */
} isk_scratch;

/* Stage kernels given precomputed forces (n particles, any n). */
void isk_integrate_semi_euler(size_t n, double *x, double *y, double *vx, double *vy, const double *m,
                              const double *fx, const double *fy, double dt);
void isk_integrate_euler(size_t n, double *x, double *y, double *vx, double *vy, const double *m,
                         const double *fx, const double *fy, double dt);
/* fx, fy: every force EXCEPT the drag b (held constant over the step). */
void isk_integrate_exact_drag(size_t n, double *x, double *y, double *vx, double *vy, const double *m,
                              const double *fx, const double *fy, double b, double dt);

/* One step of `method` for at most ISK_SIM_BLOCK particles. */
void isk_integrate_block(isk_integrator method, isk_forces *f, isk_scratch *s, size_t n, double *x,
                         double *y, double *vx, double *vy, const double *m, double dt);

/* One step of `method` for particles [begin, end) of a store, block by block
 * in index order.  Errors: ISK_ERR_NULL, ISK_ERR_RANGE (bad method or range,
 * |dt| > ISK_DT_MAX), ISK_ERR_NAN (non-finite dt). */
isk_status isk_integrate_range(isk_integrator method, isk_forces *f, isk_scratch *s, isk_particles *p,
                               size_t begin, size_t end, double dt);

/* Names as scene files spell them, indexed by method: "semi-euler", "euler",
 * "verlet", "rk4", "exact-drag", "leapfrog", "yoshida4", "strang". */
extern const char *const isk_integrator_names[ISK_INTEGRATOR_COUNT];
/* isk_integrator_names[method], or "?" if unknown. */
const char *isk_integrator_name(isk_integrator method);

/* How far the method's stored velocity is from the velocity of the curve
 * its positions lie on, under a constant acceleration a, in units of a*dt:
 * semi-implicit Euler -1/2 (its velocity is the curve's half a step
 * later), explicit Euler +1/2, every other method 0 (their positions lie
 * on the exact flight).  The walls use it to bounce from the end state
 * alone (iskra/impact.h).  0 for an unknown method. */
double isk_integrator_velocity_offset(isk_integrator method);

#ifdef __cplusplus
}
#endif

#endif
