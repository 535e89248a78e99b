/* SPDX-License-Identifier: MIT */
/* The sound walls inside the contact pass (src/sim/contact_pass.h): when
 * the flight meets a wall, the bounce there, resting on a wall, and the
 * end of the pass that leaves no particle outside.  The walls alone run
 * src/sim/bounds.c; the rules both need (a wall's time of impact, the
 * mirroring of a particle born outside) live there, in
 * src/sim/wall_contact.h, and the resting distance in rest_screen.h. */
#include <math.h>

#include "sim/contact_pass.h"
#include "sim/rest_screen.h" /* isk__rest_at_once */
#include "sim/wall_contact.h"

isk__wall_box isk__walls_box(const isk_bounds *b)
{
    const unsigned sd = b->sides;
    isk__wall_box w = {{sd & ISK_SIDE_LEFT ? b->xmin + b->margin : -INFINITY,
                        sd & ISK_SIDE_BOTTOM ? b->ymin + b->margin : -INFINITY},
                       {sd & ISK_SIDE_RIGHT ? b->xmax - b->margin : INFINITY,
                        sd & ISK_SIDE_TOP ? b->ymax - b->margin : INFINITY},
                       b->restitution,
                       {(sd & (ISK_SIDE_LEFT | ISK_SIDE_RIGHT)) != 0, (sd & (ISK_SIDE_BOTTOM | ISK_SIDE_TOP)) != 0}};
    return w;
}

/* Which of the flight's axes an axis of the walls watches: those that
 * started the step inside (one born outside is mirrored in at the end)
 * and do not rest on a wall (its normal motion is then held at zero). */
static int watches(const isk__wall_box *w, const int skip[2], int a)
{
    return w->on[a] && !skip[a];
}

/* The first wall the flight meets in the rest of the step: its time (or
 * INFINITY), axis and side (-1: lo, +1: hi); ties go to x. */
double isk__walls_first(const isk__flight *f, const isk__wall_box *w, const int skip[2], int *axis, int *side)
{
    double best = INFINITY;
    *axis = -1;
    for (int a = 0; a < 2; a++) {
        if (!watches(w, skip, a))
            continue;
        int wall;
        const double t = isk__wall_time(a ? f->sy : f->sx, a ? f->uy : f->ux, a ? f->ay : f->ax, f->k, f->s,
                                        w->lo[a], w->hi[a], &wall);
        if (t < best) {
            best = t;
            *axis = a;
            *side = wall;
        }
    }
    return best;
}

/* Holds axis a of the flight on the wall W it is pressed into: the wall
 * takes the normal acceleration, the normal velocity is zero (the stored
 * one gets the integrator's offset back at the end, iskra/impact.h). */
static void rest_on_wall(isk__flight *f, int a, double W, int skip[2])
{
    if (a) {
        f->sy = W;
        f->uy = f->ay = 0.0;
    } else {
        f->sx = W;
        f->ux = f->ax = 0.0;
    }
    skip[a] = 1;
}

/* The start of a flight on a wall it is pressed into: a normal velocity
 * within rounding of zero is zero, and a particle within the resting
 * distance of iskra/impact.h, no faster than its speed, rests at once, as
 * the walls alone do it (else each step would cost a root solve for a hop
 * below what the step resolves).  Returns 1 when an axis rested. */
int isk__walls_rest_at_start(isk__flight *f, const isk__wall_box *w, double h, int skip[2])
{
    int rested = 0;
    for (int a = 0; a < 2; a++) {
        if (!watches(w, skip, a))
            continue;
        const double P = a ? f->sy : f->sx, U = a ? f->uy : f->ux, acc = a ? f->ay : f->ax;
        double near, slow;
        isk__rest_at_once(acc, h, w->c, &near, &slow);
        const double U0 = fabs(U) <= 64 * 2.220446049250313e-16 * fabs(acc) * h ? 0.0 : U;
        const int on_lo = acc < 0.0 && P - w->lo[a] <= near, on_hi = acc > 0.0 && w->hi[a] - P <= near;
        if ((on_lo || on_hi) && fabs(U0) <= slow) {
            rest_on_wall(f, a, on_lo ? w->lo[a] : w->hi[a], skip);
            rested = 1;
        }
    }
    return rested;
}

/* The bounce on a wall at tau (iskra/impact.h), at the point (hx, hy) with
 * the flight's velocity (ux, uy) there (the flight's own, or the
 * integrator's): the point is put exactly on the wall, the normal part of
 * the velocity reflected with the walls' restitution (only an outward
 * one), and the flight starts afresh from there; pressed back into the
 * wall with all further hops fitting in the rest of the step, it rests on
 * it (returns 1). */
int isk__walls_bounce(isk__flight *f, const isk__wall_box *w, int a, int side, double tau, double hx, double hy,
                      double ux, double uy, int skip[2])
{
    const double W = side < 0 ? w->lo[a] : w->hi[a], sigma = side < 0 ? 1.0 : -1.0; /* sigma: into the box */
    double *un = a ? &uy : &ux;
    if (sigma * *un < 0.0)
        *un = -w->c * *un;
    if (a)
        hy = W;
    else
        hx = W;
    f->s = f->s - tau > 0.0 ? f->s - tau : 0.0;
    f->sx = hx;
    f->sy = hy;
    f->ux = ux;
    f->uy = uy;
    const double U = *un, acc = a ? f->ay : f->ax, c = w->c;
    if (sigma * acc < 0.0 &&
        (!(sigma * U > 0.0) || (c < 1.0 && 2.0 * sigma * U <= -sigma * acc * (1.0 - c) * f->s * (1.0 + 1e-9)))) {
        rest_on_wall(f, a, W, skip);
        return 1;
    }
    return 0;
}

/* The end of a contact pass on the walls: an axis that started outside is
 * mirrored in (no crossing to find), and any other residual beyond a wall
 * (rounding at a wall, the top of an arc grazing it unseen, a particle
 * stopped by the cap of contacts) is put on the wall, an outward velocity
 * reflected with the restitution: so no particle ends a step outside. */
void isk__walls_finish(const isk__wall_box *w, const int born_out[2], double *x, double *y, double *vx, double *vy)
{
    double *pos[2] = {x, y}, *vel[2] = {vx, vy};
    for (int a = 0; a < 2; a++) {
        if (!w->on[a])
            continue;
        const double lo = w->lo[a], hi = w->hi[a];
        if (born_out[a]) {
            if (!(*pos[a] >= lo && *pos[a] <= hi))
                isk__wall_settle(pos[a], vel[a], lo, hi, w->c);
        } else if (*pos[a] < lo) {
            *pos[a] = lo;
            if (*vel[a] < 0.0)
                *vel[a] = -w->c * *vel[a];
        } else if (*pos[a] > hi) {
            *pos[a] = hi;
            if (*vel[a] > 0.0)
                *vel[a] = -w->c * *vel[a];
        }
    }
}
