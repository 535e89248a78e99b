/* SPDX-License-Identifier: MIT */
/* iskra/bounds.h — walls that keep particles in the view: the thesis's
 * zarobi, and a physically sound reflection.
 *
 * Each side (top, right, bottom, left) is switched on or off.  Walls sit
 * `margin` inside the view: left = xmin+margin, right = xmax-margin,
 * bottom = ymin+margin, top = ymax-margin (each computed once, in double).
 *
 * ISK_BOUNCE_THESIS — Cestica.zarobi exactly (catalogue §1.4), margin 0.1
 * (the particle's "diameter").  Per particle, in this order, each check
 * independent and strict:
 *     1. left   and x < left   -> vx = -vx
 *     2. right  and x > right  -> vx = -vx
 *     3. bottom and y < bottom -> vy = -vy
 *     4. top    and y > top    -> vy = -vy
 *     5. bottom and y < bottom -> y = bottom      (only the floor clamps)
 *   Restitution 1, unconditional flip: a particle still beyond a left/right/top
 *   wall next step flips again (it can jitter or stay out, as in the thesis).
 *
 * ISK_BOUNCE_REFLECT — sound: walls with restitution c in [0, 1] that bounce
 * a particle at the time of impact (iskra/impact.h): the block runner tells
 * the stage how each particle moved in the step (isk_bounds_apply_step), the
 * stage finds when the particle met the wall, reflects the velocity it had
 * THEN (its normal part scaled by c, so c = 1 keeps the energy exactly),
 * and carries it on for the rest of the step along its reflected flight,
 * which may meet the other wall or the same one again; a particle pressed
 * into a wall whose hops would all fit in the step comes to rest on it.
 * The axes are independent (a corner is two bounces).  Nothing is touched
 * for a particle that ends the step inside.
 *
 * Without the motion (isk_bounds_apply, isk_bounds_apply_arrays: the end
 * state alone, e.g. the thesis examples' draw-before-bounce order, or a
 * particle that starts the step outside) a particle beyond a wall is
 * mirrored about it: position x' = wall + c*(wall - x), velocity v' = -c*v
 * but only if v points outward (an inward-moving particle is never turned
 * around, so it never sticks).  That reflects the END-of-step velocity,
 * which the particle had below the wall, not at it: under gravity it adds
 * energy at every bounce, which is why the block runner never uses it.
 * Both forms share the fast-particle rule: a particle still beyond the
 * opposite wall is reflected again, one reflection at a time up to 16
 * times; beyond that (10^6 units per step in a box of 10 needs 10^5) the
 * rest of the path between the two walls is folded in closed form, with the
 * same result the reflections would give (exact fmod fold for c = 1, a
 * geometric series for c < 1), so a fast particle lands where it should
 * instead of sitting on a wall.  The end-state form clamps a NaN or
 * infinite position onto the wall (a velocity that is not finite becomes 0)
 * as a last safety net; the step form
 * leaves a non-finite particle alone for the runner to remove and count.
 * After the stage every finite particle is inside [left, right] x
 * [bottom, top] for the enabled sides.
 *
 * Walls together with deflector segments, or under potentials (with the
 * integrators of iskra/contacts.h's rule), are met in one contact pass in
 * the order of the path (iskra/contacts.h), which the effect runtime and
 * isk_system use then.
 *
 * The bounce is its own stage so callers choose the order: the thesis's
 * examples draw BEFORE zarobi, its simulator AFTER (isk_system has
 * bounce_in_step; isk_system_bounce() runs the stage alone).
 *
 * Example: a particle below the thesis's floor, then outside a sound box:
 *
 *     isk_particles store;
 *     if (isk_particles_init(&store, 16, 0) != ISK_OK) return 1;
 *     isk_status s = isk_particles_add(&store, 0, -10.5, 1, -3, 1.0, NULL);   // x, y, vx, vy, m
 *     isk_bounds b;
 *     if (s == ISK_OK) s = isk_bounds_thesis(&b, -10, 10, -10, 10, ISK_SIDE_BOTTOM);  // floor only
 *     if (s == ISK_OK) isk_bounds_apply(&b, &store, 0, store.count);           // y = -9.9, vy = 3
 *     if (s == ISK_OK)                                                         // margin 0, c = 0.5
 *         s = isk_bounds_reflect(&b, 0, 10, 0, 10, ISK_SIDE_ALL, 0.0, 0.5);
 *     if (s == ISK_OK) isk_bounds_apply(&b, &store, 0, store.count);           // y = 0.5 * 9.9
 *     printf("y = %g, vy = %g\n", store.y[0], store.vy[0]);                   // 4.95, 3
 *     isk_particles_free(&store);
 *     // the step form: a particle that left y = 0.1 at vy = -12 for h = 1/60
 *     double x0[1] = {5}, y0[1] = {0.1}, vx0[1] = {0}, vy0[1] = {-12};
 *     double x[1] = {5}, y[1] = {0.1 - 12.0 / 60}, vx[1] = {0}, vy[1] = {-12};
 *     isk_step_motion mo = {x0, y0, vx0, vy0, NULL, 0.0, 1.0 / 60, 0, 0, 0};  // the step's start
 *     if (s == ISK_OK) isk_bounds_apply_step(&b, &mo, 1, x, y, vx, vy);
 *     printf("y = %g, vy = %g\n", y[0], vy[0]);     // hit at t = 1/120: 0.05, 6
 *     return s != ISK_OK;
 */
#ifndef ISKRA_BOUNDS_H
#define ISKRA_BOUNDS_H

#include <stddef.h>

#include "iskra/impact.h"
#include "iskra/particles.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
    ISK_SIDE_TOP = 1u << 0,
    ISK_SIDE_RIGHT = 1u << 1,
    ISK_SIDE_BOTTOM = 1u << 2,
    ISK_SIDE_LEFT = 1u << 3,
    ISK_SIDE_ALL = 15u,
    ISK_SIDE_COUNT = 4 /* bits */
};

typedef enum isk_bounce_mode { ISK_BOUNCE_THESIS = 0, ISK_BOUNCE_REFLECT = 1, ISK_BOUNCE_MODE_COUNT } isk_bounce_mode;

/* Names as scene files spell them: isk_bounce_mode_names[mode] ("thesis",
 * "reflect"); isk_side_names[k] names the side of bit 1 << k ("top",
 * "right", "bottom", "left"). */
extern const char *const isk_bounce_mode_names[ISK_BOUNCE_MODE_COUNT];
extern const char *const isk_side_names[ISK_SIDE_COUNT];

#define ISK_BOUNCE_MAX_REFLECTIONS 16

typedef struct isk_bounds {
    isk_bounce_mode mode;
    unsigned sides;             /* ISK_SIDE_* bits */
    double xmin, xmax, ymin, ymax;
    double margin;              /* thesis: 0.1 */
    double restitution;         /* reflect mode only, [0, 1] */
} isk_bounds;

/* The thesis's zarobi with margin 0.1 on the view xmin..ymax.  Errors:
 * ISK_ERR_NULL, ISK_ERR_NAN, ISK_ERR_RANGE (min >= max, unknown side bits). */
isk_status isk_bounds_thesis(isk_bounds *b, double xmin, double xmax, double ymin, double ymax,
                             unsigned sides);

/* Sound reflection.  Errors: ISK_ERR_NULL, ISK_ERR_NAN, ISK_ERR_RANGE
 * (restitution outside [0,1], margin < 0, walls not strictly ordered, a
 * width or height that overflows a double). */
isk_status isk_bounds_reflect(isk_bounds *b, double xmin, double xmax, double ymin, double ymax,
                              unsigned sides, double margin, double restitution);

/* Validates a hand-filled isk_bounds (same rules as the constructors). */
isk_status isk_bounds_validate(const isk_bounds *b);

/* The bounce stage on particles [begin, end) (clamped to the store). */
void isk_bounds_apply(const isk_bounds *b, isk_particles *p, size_t begin, size_t end);

/* The same on raw arrays of n particles. */
void isk_bounds_apply_arrays(const isk_bounds *b, size_t n, double *x, double *y, double *vx, double *vy);

/* The bounce at the time of impact on raw arrays: (x, y, vx, vy) is the
 * state at the end of the step mo describes (iskra/impact.h: from its
 * start state, or, without one, from the constant acceleration and the
 * integrator's velocity offset).  The thesis mode ignores mo (its
 * arithmetic is the thesis's); a NULL or incomplete mo (h not > 0, drag
 * without masses, no start state and no finite acceleration) falls back to
 * the end-state rule of isk_bounds_apply_arrays. */
void isk_bounds_apply_step(const isk_bounds *b, const isk_step_motion *mo, size_t n, double *x, double *y,
                           double *vx, double *vy);

#ifdef __cplusplus
}
#endif

#endif
