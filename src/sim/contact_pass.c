/* SPDX-License-Identifier: MIT */
/* The contact pass: walls and segment deflectors met in the order of each
 * particle's path (iskra/contacts.h), and the segments alone
 * (isk_deflect, isk_deflect_step: iskra/deflector.h).  Read
 * follow_particle first: one particle through one step.
 *
 *     start      its path S -> E in the step (start of step -> where the
 *                integrator put it), its velocity at E
 *     repeat     find the next contact on the rest of the path: the
 *                nearest segment the chord S -> E crosses, and (with walls)
 *                the first wall the flight meets;
 *                respond to it: a wall reflects, a segment bounces, kills,
 *                sticks or lets it pass; after a bounce the path starts
 *                afresh at the contact and E is the end of the rest of the
 *                step (flown on the flight, or by the integrator)
 *     finish     the velocity at the end, the walls' last word, write back
 *
 * The pieces live in contact_segments.c, contact_walls.c and
 * contact_redo.c (src/sim/contact_pass.h); the exact predicates in
 * src/sim/segment_exact.h.  Determinism: one random draw per hit on a
 * segment whose probability is strictly between 0 and 1, in path order,
 * particle after particle. */
#include "iskra/contacts.h"

#include <math.h>
#include <string.h>

#include "iskra/deflector.h"
#include "sim/contact_pass.h"

/* ---- one call ------------------------------------------------------------- */

/* What every particle of one call shares. */
typedef struct pass {
    const isk_bounds *walls;   /* NULL: the segments alone */
    isk__wall_box wb;          /* the walls as the pass uses them */
    const isk_deflector *defs; /* the segments, c.cache their canonical form */
    int ndef;
    const isk_step_motion *mo; /* NULL: straight paths with the end velocity (isk_deflect) */
    isk_rng *rng;
    uint8_t *killed;
    uint8_t *bounced, *wall_bounced; /* per particle counts, or NULL */
    isk_deflect_stats local;         /* the call's counts, added to the caller's at the end */
    isk__contact_ctx c;
} pass;

/* One particle on its way through the step. */
typedef struct particle {
    size_t i;
    double sx, sy, ex, ey; /* the current path S -> E: E is where the step ends so far */
    double ux, uy;         /* the velocity at E (once it bounced: see finish_particle) */
    isk__flight f;         /* the flight from S, once fitted */
    int fitted;            /* f has been fitted to the step */
    int linear;            /* no usable flight: straight paths (the segments' path rule, the walls' end rule) */
    int bounced;           /* the velocity at the end comes from the flight (or the integrator) */
    /* With the integrator (redo): after each contact the rest of the step
     * is its step, from the contact; `end` is where it ends, `from` its
     * state where the flight starts.  Off once the particle rests on a
     * wall or a segment (the flight holds it there). */
    int redo_on;
    double mass;
    isk__state end, from;
    int hits, contacts; /* segments hit, contacts responded to (bounces) */
    /* the axes that started outside the walls (mirrored in at the end) or
     * rest on a wall (skip), and those that started outside alone */
    int skip[2], born_out[2];
} particle;

/* The flight of particle i in the step (iskra/impact.h), fitted to its
 * start (sx, sy and mo's velocities) and its end (ex, ey, ux, uy).  Returns
 * 0 when there is no usable motion (a start velocity not finite). */
static int fit_flight(isk__flight *f, const isk_step_motion *mo, size_t i, double sx, double sy, double ex,
                      double ey, double ux, double uy)
{
    const double kk = mo->drag > 0.0 ? mo->drag / mo->m[i] : 0.0;
    f->sx = sx;
    f->sy = sy;
    f->k = kk;
    f->s = mo->h;
    isk__fl_fit(sx, mo->vx0[i], ex, ux, kk, mo->h, &f->ux, &f->ax, &f->delx);
    isk__fl_fit(sy, mo->vy0[i], ey, uy, kk, mo->h, &f->uy, &f->ay, &f->dely);
    return isfinite(f->ux) && isfinite(f->uy) && isfinite(f->ax) && isfinite(f->ay);
}

/* ---- one particle: start --------------------------------------------------- */

static void start_particle(const pass *ps, particle *p, size_t i, double sx, double sy, double ex, double ey,
                           double ux, double uy)
{
    const isk_step_motion *mo = ps->mo;
    p->i = i;
    p->sx = sx;
    p->sy = sy;
    p->ex = ex;
    p->ey = ey;
    p->ux = ux;
    p->uy = uy;
    p->fitted = 0;
    p->bounced = 0;
    p->linear = mo == NULL;
    p->redo_on = ps->c.redo != NULL && mo != NULL;
    p->mass = mo && mo->m ? mo->m[i] : 1.0;
    p->end = (isk__state){ex, ey, ux, uy};
    p->from = (isk__state){sx, sy, mo ? mo->vx0[i] : 0.0, mo ? mo->vy0[i] : 0.0};
    p->hits = p->contacts = 0;
    p->skip[0] = p->skip[1] = p->born_out[0] = p->born_out[1] = 0;
    if (ps->walls) {
        const isk__wall_box *wb = &ps->wb;
        p->born_out[0] = wb->on[0] && !(sx >= wb->lo[0] && sx <= wb->hi[0]);
        p->born_out[1] = wb->on[1] && !(sy >= wb->lo[1] && sy <= wb->hi[1]);
        p->skip[0] = p->born_out[0];
        p->skip[1] = p->born_out[1];
    }
}

/* ---- one particle: find the next contact ----------------------------------- */

/* The next contact on the path: a segment k hit at t along the chord S -> E
 * (k -1: none), and with the walls the first wall the flight meets, at tw
 * on axis `axis` (-1: none), side -1 (lo) or +1 (hi). */
typedef struct contact {
    int k;
    double t;
    int axis, side;
    double tw;
} contact;

enum next {
    NEXT_NONE,    /* no contact: E is final */
    NEXT_AGAIN,   /* the path changed without a contact: look again */
    NEXT_WALL,    /* a wall first */
    NEXT_SEGMENT, /* a segment first */
};

/* With the walls, the flight is needed once the path ends outside the box
 * or crosses a segment (segment k, -1: none).  Fitted here the first time;
 * a flight that starts pressed into a wall rests on it at once.  Returns 1
 * when the path changed (no usable flight, or it rested): look again. */
static int fit_for_walls(const pass *ps, particle *p, int k)
{
    if (p->fitted || (k < 0 && isk__walls_inside(&ps->wb, p->ex, p->ey)))
        return 0;
    p->fitted = 1;
    if (!fit_flight(&p->f, ps->mo, p->i, p->sx, p->sy, p->ex, p->ey, p->ux, p->uy) ||
        !(isfinite(p->f.delx) && isfinite(p->f.dely))) {
        p->linear = 1; /* no usable motion: the segments' path rule, the walls' end rule */
        return 1;
    }
    if (isk__walls_rest_at_start(&p->f, &ps->wb, ps->mo->h, p->skip)) { /* the flight changed: its new end */
        double wvx, wvy;
        isk__flight_at(&p->f, p->f.s, &p->ex, &p->ey, &wvx, &wvy);
        p->sx = p->f.sx;
        p->sy = p->f.sy;
        p->bounced = 1;
        p->redo_on = 0;
        return 1;
    }
    return 0;
}

/* The walls and the segments in the order the path meets them. */
static enum next find_next_contact(const pass *ps, particle *p, contact *ct)
{
    ct->t = INFINITY;
    ct->k = ps->ndef ? isk__segs_nearest(&ps->c, p->sx, p->sy, p->ex, p->ey, &ct->t) : -1;
    ct->axis = -1;
    ct->side = 0;
    ct->tw = INFINITY;
    if (ps->walls && !p->linear) {
        if (fit_for_walls(ps, p, ct->k))
            return NEXT_AGAIN;
        ct->tw = p->fitted ? isk__walls_first(&p->f, &ps->wb, p->skip, &ct->axis, &ct->side) : INFINITY;
        if (ct->axis >= 0 && ct->k >= 0) {
            isk__seg tmp;
            if (isk__segs_flight_hit(&p->f, isk__contact_seg(&ps->c, ct->k, &tmp), ct->t) <= ct->tw)
                ct->axis = -1; /* the segment first (a tie too: the wall is met next) */
        }
        if (ct->axis >= 0 && ps->ndef) {
            /* The wall first, unless the chord to the point of impact
             * crosses a segment that the chord to the end (beyond the
             * wall) missed: a curved path into a corner of a wall and a
             * segment.  Then that segment first, along the chord to the
             * wall. */
            double hx, hy, hvx, hvy, t2;
            isk__flight_at(&p->f, ct->tw, &hx, &hy, &hvx, &hvy);
            if (ct->axis)
                hy = ct->side < 0 ? ps->wb.lo[1] : ps->wb.hi[1];
            else
                hx = ct->side < 0 ? ps->wb.lo[0] : ps->wb.hi[0];
            const int k2 = isk__segs_nearest(&ps->c, p->sx, p->sy, hx, hy, &t2);
            if (k2 >= 0) {
                ct->k = k2;
                ct->t = t2;
                p->ex = hx;
                p->ey = hy;
                ct->axis = -1;
            }
        }
        if (ct->axis >= 0)
            return NEXT_WALL;
    }
    return ct->k >= 0 ? NEXT_SEGMENT : NEXT_NONE;
}

/* ---- one particle: respond to a wall --------------------------------------- */

/* The rest of the step after a contact: on the integrator's step (redo) or
 * on the flight, from the contact; a new path. */
static void fly_rest_of_step(pass *ps, particle *p)
{
    if (p->redo_on) {
        p->end = isk__redo_rest(&ps->c, &p->f, p->mass, &p->from);
        p->ex = p->end.x;
        p->ey = p->end.y;
    } else {
        double wvx, wvy;
        isk__flight_at(&p->f, p->f.s, &p->ex, &p->ey, &wvx, &wvy);
    }
}

/* The bounce on the wall ct names.  Returns 0 when the particle is out of
 * contacts: it stays at its last contact, with the velocity there. */
static int respond_to_wall(pass *ps, particle *p, const contact *ct)
{
    if (p->contacts == ISK_CONTACTS_MAX) {
        p->ex = p->sx; /* out of contacts: stay at the last contact, with the velocity there */
        p->ey = p->sy;
        ps->local.last_resort++;
        p->ux = p->f.ux + p->f.delx;
        p->uy = p->f.uy + p->f.dely;
        p->bounced = 0;
        return 0;
    }
    p->contacts++;
    const int axis = ct->axis;
    double tau = ct->tw, hx, hy, hvx, hvy;
    if (p->redo_on) { /* the integrator's state at the contact, its velocity reflected */
        const isk__state at = isk__redo_contact(&ps->c, p->from, p->mass, &tau, p->f.s, axis ? 0.0 : 1.0,
                                                axis ? 1.0 : 0.0, ct->side < 0 ? ps->wb.lo[axis] : ps->wb.hi[axis]);
        isk__redo_own_velocity(&p->f);
        hx = at.x;
        hy = at.y;
        hvx = at.vx;
        hvy = at.vy;
    } else {
        isk__flight_at(&p->f, tau, &hx, &hy, &hvx, &hvy);
    }
    if (isk__walls_bounce(&p->f, &ps->wb, axis, ct->side, tau, hx, hy, hvx, hvy, p->skip))
        p->redo_on = 0;
    ps->local.wall_bounces++;
    if (ps->wall_bounced && ps->wall_bounced[p->i] < 255)
        ps->wall_bounced[p->i]++;
    fly_rest_of_step(ps, p);
    p->sx = p->f.sx;
    p->sy = p->f.sy;
    p->bounced = 1;
    ps->c.npassed = 0; /* a new path */
    return 1;
}

/* ---- one particle: respond to a segment ------------------------------------ */

/* The bounce on segment k, hit at t along the chord S -> E, on the flight
 * or (redo) where the integrator's path meets the segment's line. */
static void bounce_on_segment(pass *ps, particle *p, int k, double t)
{
    const isk_deflector *d = &ps->defs[k];
    if (p->linear) {
        isk__segs_bounce_linear(&ps->c, k, d, &p->sx, &p->sy, &p->ex, &p->ey, &p->ux, &p->uy, t);
        return;
    }
    if (!p->fitted) {
        p->fitted = 1;
        if (!fit_flight(&p->f, ps->mo, p->i, p->sx, p->sy, p->ex, p->ey, p->ux, p->uy)) {
            /* no usable motion (a start velocity not finite): the path rule */
            isk__segs_bounce_linear(&ps->c, k, d, &p->sx, &p->sy, &p->ex, &p->ey, &p->ux, &p->uy, t);
            p->linear = 1;
            p->redo_on = 0;
            return;
        }
    }
    if (p->redo_on) { /* the contact where the integrator's path meets the segment's line */
        isk__seg tmp;
        const isk__seg *sg = isk__contact_seg(&ps->c, k, &tmp);
        double tau = isk__segs_flight_hit(&p->f, sg, t);
        const isk__state at = isk__redo_contact(&ps->c, p->from, p->mass, &tau, p->f.s, sg->nx, sg->ny,
                                                sg->nx * sg->ax + sg->ny * sg->ay);
        isk__redo_own_velocity(&p->f);
        if (isk__segs_bounce_at(&ps->c, k, d, &p->f, t, tau, at.x, at.y, at.vx, at.vy, &p->ex, &p->ey))
            p->redo_on = 0;
        else
            fly_rest_of_step(ps, p);
    } else {
        isk__segs_bounce_flight(&ps->c, k, d, &p->f, t, &p->ex, &p->ey);
    }
    p->sx = p->f.sx;
    p->sy = p->f.sy;
    p->bounced = 1;
}

/* The segment ct names: a hit, then the deflector's probability decides
 * whether it reacts (one draw, only when 0 < p < 1); it bounces, kills or
 * sticks.  Returns 0 when the particle's step is over (killed, stuck, or
 * out of hits or contacts: it stays at the last safe point). */
static int respond_to_segment(pass *ps, particle *p, const contact *ct)
{
    const int k = ct->k;
    if (p->hits == ISK_DEFLECT_MAX_HITS || p->contacts == ISK_CONTACTS_MAX) {
        p->ex = p->sx; /* out of hits: stay at the last safe point */
        p->ey = p->sy;
        ps->local.last_resort++;
        if (p->bounced) { /* with the velocity the flight has there */
            p->ux = p->f.ux + p->f.delx;
            p->uy = p->f.uy + p->f.dely;
            p->bounced = 0;
        }
        return 0;
    }
    p->hits++;
    ps->local.hits++;
    const isk_deflector *d = &ps->defs[k];
    double prob = d->probability;
    int react = prob >= 1.0 || (prob > 0.0 && isk_rng_uniform(ps->rng) < prob);
    if (!react) {
        ps->local.passes++;
        ps->c.passed[ps->c.npassed++] = k; /* not met again on this path */
        return 1;
    }
    if (d->reaction != ISK_DEFLECT_BOUNCE) {
        double qx, qy;
        isk__segs_safe_point(&ps->c, k, p->sx, p->sy, p->ex, p->ey, ct->t, &qx, &qy);
        if (d->reaction == ISK_DEFLECT_KILL) {
            ps->killed[p->i] = 1;
            ps->local.kills++;
        } else {
            p->ux = p->uy = 0.0;
            p->bounced = 0;
            ps->local.sticks++;
        }
        p->ex = qx;
        p->ey = qy;
        return 0;
    }
    ps->local.bounces++;
    p->contacts++;
    if (ps->bounced && ps->bounced[p->i] < 255)
        ps->bounced[p->i]++;
    ps->c.npassed = 0; /* a new path */
    bounce_on_segment(ps, p, k, ct->t);
    return 1;
}

/* ---- one particle: finish --------------------------------------------------- */

/* The velocity at the end (the integrator's own, or the flight's with its
 * offset), then the walls' last word: no particle ends outside them. */
static void finish_particle(const pass *ps, particle *p, double *x, double *y, double *vx, double *vy)
{
    if (p->bounced && p->redo_on) { /* the integrator's own end velocity */
        p->ux = p->end.vx;
        p->uy = p->end.vy;
    } else if (p->bounced) {
        double px, py, wx, wy;
        isk__flight_at(&p->f, p->f.s, &px, &py, &wx, &wy);
        p->ux = wx + p->f.delx;
        p->uy = wy + p->f.dely;
    }
    if (ps->walls)
        isk__walls_finish(&ps->wb, p->born_out, &p->ex, &p->ey, &p->ux, &p->uy);
    *x = p->ex;
    *y = p->ey;
    *vx = p->ux;
    *vy = p->uy;
}

/* One particle through one step: contact after contact, in path order. */
static void follow_particle(pass *ps, particle *p, double *x, double *y, double *vx, double *vy)
{
    ps->c.npassed = 0;
    for (;;) {
        contact ct;
        const enum next next = find_next_contact(ps, p, &ct);
        if (next == NEXT_AGAIN)
            continue;
        if (next == NEXT_NONE)
            break; /* E is final */
        const int go_on = next == NEXT_WALL ? respond_to_wall(ps, p, &ct) : respond_to_segment(ps, p, &ct);
        if (!go_on)
            break;
    }
    finish_particle(ps, p, x, y, vx, vy);
}

/* ---- the call --------------------------------------------------------------- */

/* The arguments of a call, checked before anything changes (the errors of
 * iskra/deflector.h and iskra/contacts.h, in this order).  Walls with no
 * side are no walls: *walls becomes NULL. */
static isk_status check_call(const isk_bounds **walls, const isk_deflector *defs, int ndef, const double *x,
                             const double *y, const double *vx, const double *vy, const double *x_old,
                             const double *y_old, const isk_step_motion *mo, const isk_contact_integrator *redo,
                             size_t n, const isk_rng *rng, const uint8_t *killed)
{
    if (ndef < 0)
        return ISK_ERR_SIZE;
    if (ndef > 0 && !defs)
        return ISK_ERR_NULL;
    int need_rng = 0, need_killed = 0;
    for (int k = 0; k < ndef; k++) {
        isk_status st = isk_deflector_check(&defs[k]);
        if (st != ISK_OK)
            return st;
        need_rng |= defs[k].probability > 0.0 && defs[k].probability < 1.0;
        need_killed |= defs[k].reaction == ISK_DEFLECT_KILL;
    }
    if (n > 0 && (!x || !y || !vx || !vy || !x_old || !y_old))
        return ISK_ERR_NULL;
    if (mo && n > 0 && (!mo->vx0 || !mo->vy0 || (mo->drag != 0.0 && !mo->m)))
        return ISK_ERR_NULL;
    if (mo && (!isfinite(mo->h) || !(mo->h > 0.0) || !isfinite(mo->drag) || mo->drag < 0.0))
        return ISK_ERR_RANGE;
    if ((need_rng && !rng) || (need_killed && !killed))
        return ISK_ERR_NULL;
    if (*walls && (*walls)->sides == 0)
        *walls = NULL; /* no wall: the deflectors alone */
    if (*walls) {
        isk_status st = isk_bounds_validate(*walls);
        if (st != ISK_OK)
            return st;
        if ((*walls)->mode != ISK_BOUNCE_REFLECT)
            return ISK_ERR_RANGE;
        if (!mo)
            return ISK_ERR_NULL;
    }
    if (redo && (!mo || !redo->forces || (unsigned)redo->method >= ISK_INTEGRATOR_COUNT))
        return redo->forces ? ISK_ERR_RANGE : ISK_ERR_NULL;
    return ISK_OK;
}

static isk_status deflect(const isk_bounds *walls, const isk_deflector *defs, int ndef, double *x, double *y,
                          double *vx, double *vy, const double *x_old, const double *y_old, const isk_step_motion *mo,
                          const isk_contact_integrator *redo, size_t n, isk_rng *rng, uint8_t *killed,
                          isk_deflect_stats *stats)
{
    isk_status st = check_call(&walls, defs, ndef, x, y, vx, vy, x_old, y_old, mo, redo, n, rng, killed);
    if (st != ISK_OK)
        return st;
    if (ndef == 0 && !walls)
        return ISK_OK;

    pass ps;
    ps.walls = walls;
    ps.wb = walls ? isk__walls_box(walls) : (isk__wall_box){{0, 0}, {0, 0}, 0, {0, 0}};
    ps.defs = defs;
    ps.ndef = ndef;
    ps.mo = mo;
    ps.rng = rng;
    ps.killed = killed;
    ps.local = (isk_deflect_stats){0, 0, 0, 0, 0, 0, NULL, 0, NULL};
    ps.bounced = stats ? stats->bounced : NULL;
    ps.wall_bounced = walls && stats ? stats->wall_bounced : NULL;
    if (ps.bounced && n > 0)
        memset(ps.bounced, 0, n);
    if (ps.wall_bounced && n > 0)
        memset(ps.wall_bounced, 0, n);
    isk_scratch scratch; /* the integrator's arrays for one particle (with redo) */
    ps.c.defs = defs;
    ps.c.ndef = ndef;
    ps.c.redo = redo;
    ps.c.scratch = &scratch;
    for (int k = 0; k < ndef && k < ISK__SEG_CACHE; k++)
        ps.c.cache[k] = isk__seg_canon(&defs[k]);
    for (size_t i = 0; i < n; i++) {
        if (killed && killed[i])
            continue;
        if (ndef == 0 && isk__walls_inside(&ps.wb, x[i], y[i]))
            continue; /* walls alone, a path that ends inside: nothing to meet (a NaN is not inside) */
        const double sx = x_old[i], sy = y_old[i], ex = x[i], ey = y[i], ux = vx[i], uy = vy[i];
        if (!isfinite(sx) || !isfinite(sy) || !isfinite(ex) || !isfinite(ey) || !isfinite(ux) || !isfinite(uy))
            continue;
        particle p;
        start_particle(&ps, &p, i, sx, sy, ex, ey, ux, uy);
        follow_particle(&ps, &p, &x[i], &y[i], &vx[i], &vy[i]);
    }
    if (stats) {
        stats->wall_bounces += ps.local.wall_bounces;
        stats->hits += ps.local.hits;
        stats->bounces += ps.local.bounces;
        stats->kills += ps.local.kills;
        stats->sticks += ps.local.sticks;
        stats->passes += ps.local.passes;
        stats->last_resort += ps.local.last_resort;
    }
    return ISK_OK;
}

isk_status isk_deflect(const isk_deflector *defs, int ndef, double *x, double *y, double *vx, double *vy,
                       const double *x_old, const double *y_old, size_t n, isk_rng *rng, uint8_t *killed,
                       isk_deflect_stats *stats)
{
    return deflect(NULL, defs, ndef, x, y, vx, vy, x_old, y_old, NULL, NULL, n, rng, killed, stats);
}

isk_status isk_deflect_step(const isk_deflector *defs, int ndef, double *x, double *y, double *vx, double *vy,
                            const isk_step_motion *mo, size_t n, isk_rng *rng, uint8_t *killed,
                            isk_deflect_stats *stats)
{
    if (!mo)
        return ISK_ERR_NULL;
    return deflect(NULL, defs, ndef, x, y, vx, vy, mo->x0, mo->y0, mo, NULL, n, rng, killed, stats);
}

isk_status isk_contacts_step(const isk_bounds *walls, const isk_deflector *defs, int ndef, double *x, double *y,
                             double *vx, double *vy, const isk_step_motion *mo, const isk_contact_integrator *redo,
                             size_t n, isk_rng *rng, uint8_t *killed, isk_deflect_stats *stats)
{
    if (!mo)
        return ISK_ERR_NULL;
    return deflect(walls, defs, ndef, x, y, vx, vy, mo->x0, mo->y0, mo, redo, n, rng, killed, stats);
}
