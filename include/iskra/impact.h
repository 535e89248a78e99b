/* SPDX-License-Identifier: MIT */
/* iskra/impact.h — bounces at the time of impact: what walls and
 * deflectors are told about the motion inside the step they correct.
 *
 * A wall or a deflector runs after the integrator has moved the particles.
 * Reflecting the END-of-step velocity about the wall (the obvious rule)
 * reflects a velocity the particle never had at the wall: falling onto a
 * floor it has gained speed for the rest of the step below the floor, so
 * the rebound carries that gain up again and every bounce adds energy (a
 * ball dropped from 4 m climbed to 9 after 20 bounces with Verlet or RK4).
 * So iskra's sound walls (ISK_BOUNCE_REFLECT) and deflectors instead:
 *
 *   1. describe the particle's motion within the step, per axis, as the
 *      flight p(t) = P + U D1(t) + a D2(t) under a constant acceleration a
 *      and the linear drag k = b/m (D1 = (1 - e^-kt)/k, D2 = (t - D1)/k;
 *      with k = 0 the parabola P + U t + a t^2/2), fitted to the step's two
 *      end states: a from its velocity change, U from its displacement;
 *   2. find the time of impact tau in (0, h] where the flight meets the
 *      wall or segment: exactly (the stable root of a quadratic) without
 *      drag, by safeguarded Halley iteration to full precision with it;
 *   3. reflect the velocity the flight has at tau (restitution scales its
 *      normal part, or all of it for ISK_RESTITUTION_UNIFORM: with c = 1
 *      the speed at the wall is kept exactly, so energy per bounce is
 *      scaled by exactly c^2 of its normal part and c = 1 keeps it);
 *   4. carry on along the reflected flight for the rest of the step, which
 *      may hit again (the other wall, the same one once more).
 * The stored velocity gets back the integrator's own offset from the
 * flight's velocity (zero for Verlet, RK4 and exact drag, whose positions
 * lie on the exact flight; -a h/2 for semi-implicit Euler and +a h/2 for
 * explicit Euler, whose positions lie on the parabola of a velocity half a
 * step away), so after the bounce the integrator continues on the
 * reflected flight and no integrator gains energy at a wall.  For gravity,
 * wind, buoyancy and drag the flight is the integrator's exact motion; for
 * potentials it is the second-order description the step's ends define,
 * and the contact pass of iskra/contacts.h (which the effect runtime and
 * isk_system use then, with every integrator but the Euler forms) takes
 * the integrator's own state at the contact and flies the rest of the
 * step with the integrator, so that a bounce keeps the energy to the
 * integrator's own order there too.
 *
 * Resting contact.  After a bounce, if the acceleration pushes the
 * particle back into the wall and (c < 1) the whole series of ever smaller
 * hops, 2 V / (|a_n| (1 - c)) for a rebound speed V, fits in the rest of
 * the step, the particle comes to rest: on the wall, with normal velocity
 * equal to the integrator's offset (0 for Verlet and RK4; a h/2 away from
 * the wall for semi-implicit Euler, which is the velocity whose next step
 * lands it on the wall again).  A particle within |a| h^2 / 64 of a wall
 * it is pressed into, no faster than |a| h / 64, rests at once (any hops
 * left would be lower than |a| h^2 / 60: 2.7e-7 m at g = 9.81, h = 1/600)
 * when c <= 0.64; above, both bounds shrink with 1 - c so that those hops
 * still fit in the step, and at c = 1 (hops that never shrink) only a
 * particle on the wall at speed 0 rests.  A particle
 * never leaves a wall or a segment by rounding, and a resting one costs a
 * few operations a step, not a root solve.
 *
 * Limits (documented, tested):
 *   - a particle that starts the step outside the walls (born there) is
 *     brought in by mirroring its end position, as before;
 *   - a path that leaves and re-enters within one step, without ending
 *     outside, is not seen: at most |a| h^2 / 8 beyond a wall (3.4e-4 units
 *     at g = 9.81, h = 1/60), e.g. the top of an arc grazing a ceiling;
 *   - more than ISK_BOUNCE_MAX_REFLECTIONS hits on walls in one step (very
 *     fast particles in a small box) fold the rest of the path in closed
 *     form (iskra/bounds.h), except without drag: with restitution 1 the
 *     path repeats from one bounce on a wall to the next on it, and the
 *     whole periods are skipped; hops on one wall that shrink are a
 *     geometric series, skipped too.  With drag, hops on one wall beyond
 *     that count rest.
 *
 * Speeds.  A deflector's restitution may exceed 1 (a pinball bumper); a
 * bounce then never leaves a speed above ISK_SPEED_LIMIT (the velocity is
 * scaled down to it, direction kept; iskra/limits.h).  1e150 is far beyond
 * any scene and keeps v^2, v*dt and b*v finite for every accepted parameter.
 *
 * Example: a ball dropped onto a restitution-1 floor keeps its apex:
 *
 *     double x[1] = {0}, y[1] = {4}, vx[1] = {0}, vy[1] = {0}, m[1] = {1};
 *     isk_bounds b;
 *     if (isk_bounds_reflect(&b, -10, 10, 0, 10, ISK_SIDE_BOTTOM, 0.0, 1.0) != ISK_OK) return 1;
 *     const double g = 9.81, h = 1.0 / 60;
 *     double apex = 0;
 *     for (int i = 0; i < 60 * 20; i++) {           // 20 s: about ten bounces
 *         double x0[1] = {x[0]}, y0[1] = {y[0]}, vx0[1] = {vx[0]}, vy0[1] = {vy[0]};
 *         y[0] += h * vy[0] - 0.5 * g * h * h;      // the exact parabola of the step
 *         vy[0] -= g * h;
 *         isk_step_motion mo = {x0, y0, vx0, vy0, m, 0.0, h, 0, 0, 0};
 *         isk_bounds_apply_step(&b, &mo, 1, x, y, vx, vy);   // bounce at the time of impact
 *         if (i > 60 * 10 && y[0] > apex) apex = y[0];
 *     }
 *     printf("apex after ten seconds: %.6f (dropped from 4)\n", apex);
 *     return !(apex > 3.99 && apex <= 4.0 + 1e-9);
 */
#ifndef ISKRA_IMPACT_H
#define ISKRA_IMPACT_H

#include "iskra/limits.h" /* ISK_SPEED_LIMIT */

#ifdef __cplusplus
extern "C" {
#endif

/* The motion of the step a wall or deflector corrects: the step h > 0 and
 * the linear drag b that acted (F = -b v; 0: none, then m may be NULL), and
 * either
 *   - the state at its start (x0..vy0: arrays of the same n particles as
 *     the end state; the block runner keeps them in L1, stored by the
 *     motion stage as it reads the block):
 *     the flight is fitted to both ends, whatever the forces; or
 *   - (x0..vy0 NULL; walls only) the constant acceleration (ax, ay) that
 *     acted with the drag, and the integrator's velocity offset:
 *     delta = offset * a * h (isk_integrator_velocity_offset, -1/2 for
 *     semi-implicit Euler): the flight is the exact one ending in the end
 *     state, so no start state is needed.  This is what a step under
 *     gravity, wind, buoyancy and drag alone is, and it saves the copy of
 *     the start state (docs/performance.md, "The update against the
 *     memory bandwidth").
 * Deflectors always need the start positions (their hit test is along the
 * path from them). */
typedef struct isk_step_motion {
    const double *x0, *y0;
    const double *vx0, *vy0;
    const double *m;
    double drag;
    double h;
    double ax, ay;  /* used when x0 is NULL */
    double offset;
} isk_step_motion;

#ifdef __cplusplus
}
#endif

#endif
