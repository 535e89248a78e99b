/* SPDX-License-Identifier: MIT */
/* iskra/deflector.h — line segments that particles bounce off, stick to or
 * die on, tested on the whole path of a step so nothing tunnels through.
 *
 * Call it after the integrator has moved the particles: it looks at each
 * particle's path from its old position to its new one, finds the first
 * segment the path crosses, and reacts.  Plain functions over SoA arrays.
 *
 * Example: a particle whose step takes it through a floor bounces off it:
 *
 *     isk_deflector floor = isk_deflector_segment(-1, 0, 1, 0);
 *     floor.restitution = 0.5;                      // c (or epsilon)
 *     double x[1] = {0.5}, y[1] = {0.1}, vx[1] = {0}, vy[1] = {-12}, x_old[1], y_old[1];
 *     double dt = 1.0 / 60;
 *     x_old[0] = x[0];  y_old[0] = y[0];            // integrate: x_old = x; x += vx*dt
 *     x[0] += vx[0] * dt;  y[0] += vy[0] * dt;      // y = -0.1, below the floor
 *     double vx_old[1] = {vx[0]}, vy_old[1] = {vy[0]};  // the step's start state
 *     isk_step_motion mo = {x_old, y_old, vx_old, vy_old, NULL, 0.0, dt, 0, 0, 0};
 *     isk_status st = isk_deflect_step(&floor, 1, x, y, vx, vy, &mo, 1,
 *                                      NULL, NULL, NULL);  // rng/killed/stats optional
 *     printf("y = %g, vy = %g\n", y[0], vy[0]);     // hit at t = dt/2: 0.05, 6
 *     return st != ISK_OK;
 *
 * isk_deflect_step bounces at the time of impact (iskra/impact.h): the hit
 * is found on the chord from the old position to the new one (below), then
 * the time of impact on the particle's flight within the step, the
 * velocity it has there is reflected, and it flies on for the rest of the
 * step; pressed back into the segment with all further hops fitting in
 * the step, it rests on it (and slides along it with normal restitution).
 * isk_deflect(defs, ndef, x, y, vx, vy, x_old, y_old, n, rng, killed,
 * stats), given only the old positions, reflects the end-of-step velocity
 * and the rest of the straight path (adds energy under gravity: kept for
 * callers without a start state).  Segments together with sound walls are
 * met in the order of the path by isk_contacts_step (iskra/contacts.h).
 *
 * Geometry (the fire thesis §5.8, made exact and robust):
 *   - Segment endpoints are put in a canonical order (lexicographic on
 *     (x, y)) before anything is computed, so a segment and its reverse give
 *     bit-identical results.  The normal is n = (-dy, dx)/|d|; its sign never
 *     matters (every formula uses it twice).  Any length works (non-unit).
 *   - Side tests are the 2D cross products o(P) = cross(B - A, P - A).  A path
 *     P0 -> P1 hits segment AB when o(P0) != 0, o(P1) is zero or of the other
 *     sign, and the crossing lies on the closed segment (the path's own cross
 *     products at A and B are not of one strict sign: endpoints count, so a
 *     closed polygon has no gaps, and a shared vertex is classified the same
 *     way for both of its segments because the test at a vertex is literally
 *     the same computation).  The crossing parameter is t = o(P0) /
 *     (o(P0) - o(P1)) in (0, 1].
 *   - Touching convention: a path that ENDS exactly on a segment hits it; a
 *     path that STARTS exactly on a segment (o(P0) = 0) is leaving it and
 *     does not hit it.  Paths collinear with a segment never hit it.  The
 *     library itself never leaves a particle exactly on a segment line.
 *   - Several segments crossed: the smallest t wins; equal t, the lower index.
 *   - Precision: a side test relative to endpoint A would carry the
 *     rounding of |P - A| (a segment reaching to 1e12 would resolve points
 *     near the origin only to 1e-4, and one to 1e150 not at all, so short
 *     paths tunnelled).  Each side test is the direct formula where its
 *     error bound shows it accurate, and otherwise the same determinant in
 *     twice the working precision (exact B - A and cross(A, B), exact
 *     products): a point is then resolved as finely as on a segment through
 *     the origin, wherever the endpoints are.  Endpoint coordinates are
 *     limited to |c| <= ISK_COORD_MAX (1e150, iskra/limits.h) so every product of
 *     coordinates stays finite.
 *
 * Response at the hit point H, for the hit segment's reaction:
 *   BOUNCE  velocity v -> M(v) (isk_deflect_step: the velocity at the time
 *           of impact, and the particle flies on from H for the rest of the
 *           step; isk_deflect: the end-of-step velocity, and the rest of its
 *           straight path, (1 - t)(P1 - P0), is also mapped by M); that new
 *           path is tested again (up to ISK_DEFLECT_MAX_HITS hits per
 *           particle per call).  A restitution above 1 (a bumper) never
 *           leaves a speed above ISK_SPEED_LIMIT (iskra/impact.h).  M is
 *             ISK_RESTITUTION_UNIFORM  M(v) = c (v - 2 (v.n) n)   (fire thesis
 *                                      eq. 5.6 applied to -v, times its damping:
 *                                      both components scaled)
 *             ISK_RESTITUTION_NORMAL   M(v) = v_t - c v_n, v_n = (v.n) n
 *                                      (particle-engine eq. 5.7: only the normal
 *                                      part is scaled; c = 1 is elastic, 0 slides)
 *   KILL    killed[i] = 1, the particle stops at H; velocity unchanged.
 *   STICK   velocity 0, the particle stays at H.
 * "At H" always means H moved back along the incoming path just far enough
 * that every side test puts it strictly on the side it came from (for every
 * segment, not only the hit one), so it ends on the correct side and is never
 * exactly on a line.  When nothing representable lies between the path's
 * start and H (the start is within an ulp or two of the segment, e.g. a
 * particle resting on a floor at c = 0) the start itself is used.
 * Last resort: a particle that would need more than ISK_DEFLECT_MAX_HITS hits
 * in one call (very fast, nearly elastic, in a small enclosure) stops at the
 * last safe point of its path with its current velocity, losing the rest of
 * that step's travel; stats->last_resort counts these.
 *
 * Probability.  Each deflector reacts to a hit with probability p
 * (`probability`, default 1); a particle that fails passes through and its
 * path is tested on against the other segments.  Exactly one uniform draw
 * (isk_rng_uniform) is made per hit on a deflector with 0 < p < 1, and the
 * reaction happens when u < p; p = 0 and p = 1 never draw, so scenes without
 * such deflectors need no rng.  Particles are processed in index order, hits
 * in path order, so the draw sequence is deterministic.
 *
 * Particles with killed[i] already non-zero are skipped.  A particle whose
 * old or new position or velocity is NaN/Inf is left alone (no hits).
 * Nothing allocates; validation of all deflectors runs once per call.
 */
#ifndef ISKRA_DEFLECTOR_H
#define ISKRA_DEFLECTOR_H

#include <stddef.h>
#include <stdint.h>

#include "iskra/impact.h"
#include "iskra/rng.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Most hits handled for one particle in one call (bounces plus passes). */
#define ISK_DEFLECT_MAX_HITS 8

/* Largest restitution (see above; endpoints are within ISK_COORD_MAX of
 * iskra/limits.h; the scene key table's ranges are these). */
#define ISK_DEFLECT_RESTITUTION_MAX 1000.0

typedef enum isk_deflect_reaction {
    ISK_DEFLECT_BOUNCE = 0,
    ISK_DEFLECT_KILL = 1,
    ISK_DEFLECT_STICK = 2,
    ISK_DEFLECT_REACTION_COUNT
} isk_deflect_reaction;

typedef enum isk_restitution_mode {
    ISK_RESTITUTION_UNIFORM = 0, /* fire thesis: c (v - 2 (v.n) n) */
    ISK_RESTITUTION_NORMAL = 1,  /* particle-engine thesis: v_t - c v_n */
    ISK_RESTITUTION_MODE_COUNT
} isk_restitution_mode;

/* Names as scene files spell them, indexed by value. */
extern const char *const isk_deflect_reaction_names[ISK_DEFLECT_REACTION_COUNT]; /* bounce, kill, stick */
extern const char *const isk_restitution_mode_names[ISK_RESTITUTION_MODE_COUNT]; /* uniform, normal */

typedef struct isk_deflector {
    double x0, y0, x1, y1;         /* the segment; order does not matter */
    double restitution;            /* 0 <= c <= 1000 (> 1 gains energy: speeds capped) */
    double probability;            /* p in [0, 1] */
    isk_deflect_reaction reaction;
    isk_restitution_mode mode;
} isk_deflector;

typedef struct isk_deflect_stats {
    size_t hits;        /* crossings found (reacting or passing) */
    size_t bounces, kills, sticks, passes;
    size_t last_resort; /* particles that ran out of hits (see above), or of contacts
                           (ISK_CONTACTS_MAX, iskra/contacts.h) */
    uint8_t *bounced;   /* optional (NULL: not kept): per particle of the call, the bounces it
                           made in it, saturating at 255; written, not added to */
    size_t wall_bounces; /* bounces on walls (isk_contacts_step only; iskra/contacts.h) */
    uint8_t *wall_bounced; /* optional, as `bounced`, for the walls (isk_contacts_step only) */
} isk_deflect_stats;

/* A bouncing segment with c = 1, p = 1, uniform restitution. */
isk_deflector isk_deflector_segment(double x0, double y0, double x1, double y1);

/* ISK_OK, or why the deflector is unusable: ISK_ERR_NULL, ISK_ERR_NAN
 * (non-finite coordinate, restitution or probability), ISK_ERR_RANGE
 * (zero-length segment, a coordinate beyond ISK_COORD_MAX,
 * restitution outside [0, ISK_DEFLECT_RESTITUTION_MAX], p outside [0, 1],
 * bad enum). */
isk_status isk_deflector_check(const isk_deflector *d);

/* Deflects particles 0..n-1 (see above).  x, y, vx, vy are updated in place;
 * x_old, y_old are the positions before the step.  rng may be NULL when no
 * deflector has 0 < p < 1, killed may be NULL when none has reaction KILL,
 * stats may be NULL (it is added to, not reset).  Errors: as
 * isk_deflector_check for any deflector, ISK_ERR_NULL for missing arrays,
 * ISK_ERR_SIZE for ndef < 0.  On error nothing is changed. */
isk_status isk_deflect(const isk_deflector *defs, int ndef, double *x, double *y, double *vx, double *vy,
                       const double *x_old, const double *y_old, size_t n, isk_rng *rng, uint8_t *killed,
                       isk_deflect_stats *stats);

/* The same with the bounce at the time of impact: mo gives the state at the
 * start of the step (its x0, y0 are the old positions), the step and the
 * drag (iskra/impact.h).  Errors: as isk_deflect, ISK_ERR_NULL for a NULL
 * mo or missing start velocities (masses, with drag), ISK_ERR_RANGE for
 * mo->h not > 0 or a negative or non-finite drag. */
isk_status isk_deflect_step(const isk_deflector *defs, int ndef, double *x, double *y, double *vx, double *vy,
                            const isk_step_motion *mo, size_t n, isk_rng *rng, uint8_t *killed,
                            isk_deflect_stats *stats);

/* The velocity map M of one deflector, applied to (vx, vy) (for emitters
 * and tests; no validation). */
void isk_deflector_reflect(const isk_deflector *d, double *vx, double *vy);

#ifdef __cplusplus
}
#endif

#endif
