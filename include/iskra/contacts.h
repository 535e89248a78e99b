/* SPDX-License-Identifier: MIT */
/* iskra/contacts.h — walls and deflector segments in one contact pass, in
 * the order a particle's path meets them.
 *
 * Walls alone (iskra/bounds.h) and segments alone (iskra/deflector.h) each
 * resolve every contact of a step at its time of impact.  Together they
 * must be one pass: resolved one after the other, a particle that a
 * deflector turns back towards a wall it has already crossed in the same
 * step would end outside the box and fly away for good (at 300 units/s in
 * a box of 20 with one slanted segment, a fifth of the particles did).  So
 * isk_contacts_step, for each particle:
 *
 *   1. describes its motion in the step as the flight of iskra/impact.h,
 *      fitted to the step's two end states (a particle whose path ends
 *      inside the box and crosses no segment is not looked at further);
 *   2. finds the earliest contact along the rest of the flight among the
 *      walls (the time of impact of each axis, iskra/bounds.h) and the
 *      segments (the first segment the chord crosses, then the time the
 *      flight meets it, iskra/deflector.h); a tie goes to the segment;
 *   3. responds as the walls or the segment would alone: a wall reflects
 *      the normal part of the velocity at impact with its restitution; a
 *      segment bounces, kills, sticks or lets the particle pass (its
 *      probability, one draw per hit, in path order);
 *   4. carries on from the contact for the rest of the step, repeating in
 *      time order, at most ISK_CONTACTS_MAX contacts (bounces on walls and
 *      segments) per particle and step; a particle that would need more
 *      stops at its last contact with the velocity it has there (losing the
 *      rest of that step's travel; stats->last_resort counts it), as the
 *      deflectors' own cap does.
 * Resting contact, the velocity offset of the Euler integrators, and the
 * exact bounce under gravity, wind and drag are those of iskra/impact.h.
 *
 * The integrator's own flight (redo).  Under a force that changes along
 * the step (potentials) the fitted flight is only second order, and the
 * rest of a step after a bounce flown on it gained energy at every bounce
 * (a spring on a restitution-1 floor: 8.5e-4 a bounce with Verlet at
 * 1/60, 5.2e-4 with RK4).  Given the integrator that made the step, the
 * pass instead takes the integrator's own state at the contact (one step
 * of it from the start of the flight to the time of impact, that time
 * refined by a Newton step on the distance to the wall or segment line),
 * reflects that state's velocity, and flies the rest of the step with one
 * step of the integrator; the flight is fitted to that step to find the
 * next contact.  A bounce then adds about one step's local error: the
 * energy per bounce is c^2 to the integrator's own order (1e-7 at 1/60
 * for the second-order methods, 1e-11 for the fourth-order ones;
 * docs/accuracy.md, "A spring on a floor").  The effect runtime and
 * isk_system pass it when potentials act, none of them switches itself
 * off, and the integrator's velocity offset is 0 (the Euler forms keep
 * the flight and their offset: first order either way); a particle that
 * comes to rest on a wall or segment finishes its step on the flight.
 * Every finite particle ends the step inside the walls: an axis that
 * started the step outside (a particle born there) is mirrored in, and any
 * residual beyond a wall (rounding, an arc grazing it unseen, the cap) is
 * put on the wall with an outward velocity reflected.
 *
 * The effect runtime uses this pass when an emitter has both sound walls
 * and deflectors, or either with potentials (the redo above); otherwise
 * walls alone keep their own faster stage (its screens, memo and skipped
 * periods give the same bounces), segments alone theirs.
 *
 * Example: in one step, off a wall, then off a slanted segment:
 *
 *     isk_bounds box;
 *     if (isk_bounds_reflect(&box, -10, 10, -10, 10, ISK_SIDE_ALL, 0.0, 1.0) != ISK_OK) return 1;
 *     isk_deflector slant = isk_deflector_segment(-6, -4, 5, 7);
 *     double x0[1] = {9}, y0[1] = {6}, vx0[1] = {600}, vy0[1] = {0}, h = 1.0 / 60;
 *     double x[1] = {9 + 600 * h}, y[1] = {6}, vx[1] = {600}, vy[1] = {0};  // 9 beyond the right wall
 *     isk_step_motion mo = {x0, y0, vx0, vy0, NULL, 0.0, h, 0, 0, 0};
 *     isk_status st = isk_contacts_step(&box, &slant, 1, x, y, vx, vy, &mo, NULL, 1, NULL, NULL, NULL);
 *     printf("(%g, %g) (%g, %g)\n", x[0], y[0], vx[0], vy[0]);
 *     // off the wall at t = h/10, the slant at (4, 6) at 7h/10, then down: (4, 3) (0, -600)
 *     return st != ISK_OK;
 *
 * Errors: those of isk_deflect_step; the walls' (isk_bounds_validate),
 * ISK_ERR_RANGE for walls that are not ISK_BOUNCE_REFLECT (the thesis's
 * walls have their own arithmetic, iskra/bounds.h).  walls may be NULL or
 * have no side (then it is isk_deflect_step).  On error nothing is changed.
 */
#ifndef ISKRA_CONTACTS_H
#define ISKRA_CONTACTS_H

#include <stddef.h>
#include <stdint.h>

#include "iskra/bounds.h"
#include "iskra/deflector.h"
#include "iskra/impact.h"
#include "iskra/integrate.h"
#include "iskra/rng.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Most contacts (wall and segment bounces) resolved for one particle in one
 * step; segment hits (bounces plus passes) are also bounded by
 * ISK_DEFLECT_MAX_HITS. */
#define ISK_CONTACTS_MAX 32

/* The integrator that made the step, to fly the rest of it after a contact
 * (see above).  Its forces are evaluated at extra states: no potential in
 * them may switch itself off (a max_distance), or the switch would trip
 * at states the particle never had. */
typedef struct isk_contact_integrator {
    isk_integrator method;
    isk_forces *forces;
} isk_contact_integrator;

/* The contact pass over particles 0..n-1 (see above).  redo: NULL (the
 * rest of a step after a contact is the fitted flight: exact under
 * gravity, wind and drag), or the integrator that made the step.  stats,
 * when given, also counts the wall bounces (wall_bounces, and per particle
 * in wall_bounced when that is not NULL). */
isk_status isk_contacts_step(const isk_bounds *walls, const isk_deflector *defs, int ndef, double *x, double *y,
                             double *vx, double *vy, const isk_step_motion *mo, const isk_contact_integrator *redo,
                             size_t n, isk_rng *rng, uint8_t *killed, isk_deflect_stats *stats);

#ifdef __cplusplus
}
#endif

#endif
