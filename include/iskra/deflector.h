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
 *     isk_status st = isk_deflect(&floor, 1, x, y, vx, vy, x_old, y_old, 1,
 *                                 NULL, NULL, NULL);  // rng/killed/stats optional
 *     printf("y = %g, vy = %g\n", y[0], vy[0]);     // above the floor again, moving up
 *     return st != ISK_OK;
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
 *   - Precision: side tests are taken relative to endpoint A, so they carry
 *     the rounding of coordinates of the size of |P - A|; keep segments
 *     within a sane range of the particles (a segment with an endpoint at
 *     1e12 resolves positions near the origin only to about 1e-4).
 *
 * Response at the hit point H, for the hit segment's reaction:
 *   BOUNCE  velocity v -> M(v); the particle continues from H with the rest of
 *           its path, (1 - t)(P1 - P0), also mapped by M; that new path is
 *           tested again (up to ISK_DEFLECT_MAX_HITS hits per particle per
 *           call).  M is
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

#include "iskra/rng.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Most hits handled for one particle in one call (bounces plus passes). */
#define ISK_DEFLECT_MAX_HITS 8

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
    double restitution;            /* c >= 0, finite (> 1 gains energy) */
    double probability;            /* p in [0, 1] */
    isk_deflect_reaction reaction;
    isk_restitution_mode mode;
} isk_deflector;

typedef struct isk_deflect_stats {
    size_t hits;        /* crossings found (reacting or passing) */
    size_t bounces, kills, sticks, passes;
    size_t last_resort; /* particles that ran out of hits (see above) */
} isk_deflect_stats;

/* A bouncing segment with c = 1, p = 1, uniform restitution. */
isk_deflector isk_deflector_segment(double x0, double y0, double x1, double y1);

/* ISK_OK, or why the deflector is unusable: ISK_ERR_NULL, ISK_ERR_NAN
 * (non-finite coordinate, restitution or probability), ISK_ERR_RANGE
 * (zero-length segment, restitution < 0, p outside [0, 1], bad enum). */
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

/* The velocity map M of one deflector, applied to (vx, vy) (for emitters
 * and tests; no validation). */
void isk_deflector_reflect(const isk_deflector *d, double *vx, double *vy);

#ifdef __cplusplus
}
#endif

#endif
