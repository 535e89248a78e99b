/* SPDX-License-Identifier: MIT */
/* src/sim/contact_pass.h — the pieces of the contact pass (internal): one
 * pass over walls and segment deflectors in the order each particle's path
 * meets them (iskra/contacts.h; iskra/impact.h documents the model).
 *
 * The pass itself, one particle at a time, is src/sim/contact_pass.c: it
 * finds the next contact, responds to it, and flies the rest of the step,
 * with the pieces below; calls go one way, pass -> pieces -> the exact
 * predicates (src/sim/segment_exact.h):
 *
 *     contact_segments.c  the segments: the nearest hit, the safe point
 *                         before it, the bounce on it
 *     contact_walls.c     the sound walls of the pass
 *     contact_redo.c      the rest of a step flown by the integrator
 *     deflector.c         the velocity map M of one segment
 *
 *     isk__contact_ctx c = ...;                       // the segments, once a call
 *     double t;
 *     int k = isk__segs_nearest(&c, sx, sy, ex, ey, &t);  // -1: no segment hit
 *     if (k >= 0) isk__segs_bounce_flight(&c, k, &defs[k], &f, t, &ex, &ey);
 */
#ifndef ISKRA_SIM_CONTACT_PASS_H
#define ISKRA_SIM_CONTACT_PASS_H

#include <stddef.h>

#include "iskra/bounds.h"
#include "iskra/contacts.h"
#include "iskra/deflector.h"
#include "iskra/integrate.h"
#include "sim/flight.h"
#include "sim/segment_exact.h"

/* ---- what one call of the pass shares ------------------------------------ */

enum { ISK__SEG_CACHE = 64 }; /* more segments than this are put in canonical form on the fly */

/* The segments of one call in canonical form, the integrator that flies
 * the rest of a step (if any), and the segments a particle's current path
 * has passed through (a deflector's probability let it through: it is not
 * hit again on that path). */
typedef struct isk__contact_ctx {
    const isk_deflector *defs;
    int ndef;
    const isk_contact_integrator *redo; /* NULL: the rest of a step after a contact is the fitted flight */
    isk_scratch *scratch;                /* the integrator's working arrays (with redo) */
    isk__seg cache[ISK__SEG_CACHE];
    int passed[ISK_DEFLECT_MAX_HITS];
    int npassed;
} isk__contact_ctx;

/* Segment k in canonical form: from the cache, or made in *tmp. */
static inline const isk__seg *isk__contact_seg(const isk__contact_ctx *c, int k, isk__seg *tmp)
{
    if (k < ISK__SEG_CACHE)
        return &c->cache[k];
    *tmp = isk__seg_canon(&c->defs[k]);
    return tmp;
}

/* The flight since the last bounce (src/sim/flight.h): start S, velocity
 * U, acceleration A, drag rate k, time left s; the integrator's velocity
 * offset (delx, dely). */
typedef struct isk__flight {
    double sx, sy, ux, uy, ax, ay, k, s;
    double delx, dely;
} isk__flight;

/* Where the flight is at time t after its start, and its velocity. */
static inline void isk__flight_at(const isk__flight *f, double t, double *x, double *y, double *vx, double *vy)
{
    double e, d1, d2;
    isk__fl_basis(f->k, t, &e, &d1, &d2);
    *x = f->sx + f->ux * d1 + f->ax * d2;
    *y = f->sy + f->uy * d1 + f->ay * d2;
    *vx = f->ux * e + f->ax * d1;
    *vy = f->uy * e + f->ay * d1;
}

/* ---- deflector.c: the velocity map of one segment ------------------------ */

/* The velocity map M of deflector d (segment s its canonical form). */
void isk__seg_reflect(const isk_deflector *d, const isk__seg *s, double *vx, double *vy);

/* A bumper (c > 1) never leaves a speed above ISK_SPEED_LIMIT. */
void isk__speed_cap(double *vx, double *vy);

/* ---- contact_segments.c: the segments ------------------------------------ */

/* Nearest hit on S -> E among the segments not passed through on this path;
 * returns its index (ties: lowest) and *t, or -1. */
int isk__segs_nearest(const isk__contact_ctx *c, double sx, double sy, double ex, double ey, double *t);

/* A point Q on S -> E just before the hit on segment `hit` at t, strictly
 * on S's side, on no segment's line, reachable from S without a new hit
 * (S itself when none is found). */
void isk__segs_safe_point(const isk__contact_ctx *c, int hit, double sx, double sy, double ex, double ey, double t,
                          double *qx, double *qy);

/* When the flight meets the line of segment s; t_chord: where the chord
 * S -> E crossed it. */
double isk__segs_flight_hit(const isk__flight *f, const isk__seg *s, double t_chord);

/* The bounce of the flight on segment `hit` (deflector d) that its chord
 * to (*ex, *ey) crossed at t_chord; the flight starts afresh after it and
 * (*ex, *ey) is its new end. */
void isk__segs_bounce_flight(const isk__contact_ctx *c, int hit, const isk_deflector *d, isk__flight *f,
                             double t_chord, double *ex, double *ey);

/* The same once the impact is known: at tau, at H = (hx, hy), with the
 * velocity (uix, uiy) there.  Returns 1 when the particle came to rest on
 * the segment. */
int isk__segs_bounce_at(const isk__contact_ctx *c, int hit, const isk_deflector *d, isk__flight *f, double t_chord,
                        double tau, double hx, double hy, double uix, double uiy, double *ex, double *ey);

/* The bounce of a straight path S -> E with the end-of-step velocity U
 * (isk_deflect): all mapped by M from the safe point. */
void isk__segs_bounce_linear(const isk__contact_ctx *c, int hit, const isk_deflector *d, double *sx, double *sy,
                             double *ex, double *ey, double *ux, double *uy, double t);

/* ---- contact_walls.c: the walls ------------------------------------------ */

/* The sound walls of a contact pass, per axis (0: x, 1: y); a missing wall
 * at -inf / +inf. */
typedef struct isk__wall_box {
    double lo[2], hi[2];
    double c;
    int on[2];
} isk__wall_box;

isk__wall_box isk__walls_box(const isk_bounds *b);

static inline int isk__walls_inside(const isk__wall_box *w, double x, double y)
{
    return x >= w->lo[0] && x <= w->hi[0] && y >= w->lo[1] && y <= w->hi[1];
}

/* The first wall the flight meets in the rest of the step: its time (or
 * INFINITY), axis and side (-1: lo, +1: hi); ties go to x.  skip[a]: axis
 * a is not watched (it started outside, or it rests on a wall). */
double isk__walls_first(const isk__flight *f, const isk__wall_box *w, const int skip[2], int *axis, int *side);

/* A flight that starts on a wall it is pressed into rests on it at once.
 * Returns 1 when an axis rested. */
int isk__walls_rest_at_start(isk__flight *f, const isk__wall_box *w, double h, int skip[2]);

/* The bounce on wall (a, side) at tau, at (hx, hy) with velocity (ux, uy);
 * returns 1 when the particle came to rest on the wall. */
int isk__walls_bounce(isk__flight *f, const isk__wall_box *w, int a, int side, double tau, double hx, double hy,
                      double ux, double uy, int skip[2]);

/* The end of the pass on the walls: an axis born outside mirrored in, any
 * residual beyond a wall put on it. */
void isk__walls_finish(const isk__wall_box *w, const int born_out[2], double *x, double *y, double *vx, double *vy);

/* ---- contact_redo.c: the rest of a step flown by the integrator ---------- */

/* A particle's state as the integrator keeps it (its stored velocity). */
typedef struct isk__state {
    double x, y, vx, vy;
} isk__state;

/* The integrator's state at the contact with the line nx x + ny y = off
 * that the flight puts at *tau after st0 (at most s_max); *tau refined. */
isk__state isk__redo_contact(const isk__contact_ctx *c, isk__state st0, double m, double *tau, double s_max,
                             double nx, double ny, double off);

/* At a contact resolved with the integrator, the velocity reflected is the
 * integrator's own: the flight's offset from it is dropped. */
void isk__redo_own_velocity(isk__flight *f);

/* After such a contact: the rest of the step is one step of the
 * integrator from the flight's new start (*start); the flight is fitted to
 * it.  Returns the integrator's end state. */
isk__state isk__redo_rest(const isk__contact_ctx *c, isk__flight *f, double m, isk__state *start);

#endif
