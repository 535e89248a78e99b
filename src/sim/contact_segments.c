/* SPDX-License-Identifier: MIT */
/* The segments of the contact pass (src/sim/contact_pass.h): which segment
 * a path meets first, a safe point just before it, and the bounce on it —
 * at the time of impact on the flight's curve (iskra/impact.h), or on a
 * straight path with the end-of-step velocity (isk_deflect).  Only
 * particles whose path crosses a segment get past isk__segs_nearest. */
#include <math.h>

#include "sim/contact_pass.h"

static int was_passed(const isk__contact_ctx *c, int k)
{
    for (int i = 0; i < c->npassed; i++)
        if (c->passed[i] == k)
            return 1;
    return 0;
}

int isk__segs_nearest(const isk__contact_ctx *c, double sx, double sy, double ex, double ey, double *t)
{
    int best = -1;
    double bt = INFINITY;
    for (int k = 0; k < c->ndef; k++) {
        if (c->npassed && was_passed(c, k))
            continue;
        isk__seg tmp;
        double tk = isk__seg_crossing(isk__contact_seg(c, k, &tmp), sx, sy, ex, ey);
        if (tk >= 0.0 && tk < bt) {
            bt = tk;
            best = k;
        }
    }
    *t = bt;
    return best;
}

/* 1 when (x, y) is on no segment's line. */
static int off_every_line(const isk__contact_ctx *c, double x, double y)
{
    for (int k = 0; k < c->ndef; k++) {
        isk__seg tmp;
        if (isk__seg_side(isk__contact_seg(c, k, &tmp), x, y) == 0.0)
            return 0;
    }
    return 1;
}

/* A point Q = S + tau (E - S), tau just below t, strictly on S's side of the
 * hit segment, on no segment line, and reachable from S without a new hit.
 * When no such tau is found — typically because S is within an ulp or two of
 * the segment, so nothing representable lies between — Q is S itself, which
 * is always valid: S is the start of a path that hit, so it is strictly on
 * the incoming side. */
void isk__segs_safe_point(const isk__contact_ctx *c, int hit, double sx, double sy, double ex, double ey, double t,
                          double *qx, double *qy)
{
    isk__seg tmp;
    const isk__seg *h = isk__contact_seg(c, hit, &tmp);
    int want = isk__sgn(isk__seg_side(h, sx, sy));
    double dx = ex - sx, dy = ey - sy;
    double delta = t * 0x1p-50;
    for (int iter = 0; iter < 64 && delta < t; iter++, delta *= 2.0) {
        double tau = t - delta;
        double x = sx + tau * dx, y = sy + tau * dy;
        if (isk__sgn(isk__seg_side(h, x, y)) != want || !off_every_line(c, x, y))
            continue;
        double tq;
        if (isk__segs_nearest(c, sx, sy, x, y, &tq) >= 0)
            break; /* rounding put Q past another segment: give up */
        *qx = x;
        *qy = y;
        return;
    }
    *qx = sx;
    *qy = sy;
}

/* When the flight meets the line of segment s (S strictly on one side);
 * t_chord: where the chord S -> E crossed it (the answer when the curve and
 * the chord disagree, by rounding or near an end of the segment). */
double isk__segs_flight_hit(const isk__flight *f, const isk__seg *s, double t_chord)
{
    double o = isk__seg_side(s, f->sx, f->sy) / s->len; /* signed distance of S from the line */
    double sg = o > 0.0 ? 1.0 : -1.0;
    double c0 = sg * o;
    double un = sg * (s->nx * f->ux + s->ny * f->uy), an = sg * (s->nx * f->ax + s->ny * f->ay);
    double e, d1, d2;
    isk_fl_cache cache; /* the root solve asks for f_end's and t_turn's times again */
    isk_fl_cache_clear(&cache);
    isk_fl_basis_cached(&cache, f->k, f->s, &e, &d1, &d2);
    double f_end = c0 + un * d1 + an * d2;
    double t_turn = isk__fl_turn(un, an, f->k);
    if (t_turn > 0.0 && t_turn < f->s) {
        isk_fl_basis_cached(&cache, f->k, t_turn, &e, &d1, &d2);
        if (c0 + un * d1 + an * d2 < 0.0)
            return isk__fl_root(c0, un, an, f->k, 0.0, t_turn, &cache);
    }
    if (f_end < 0.0)
        return isk__fl_root(c0, un, an, f->k, 0.0, f->s, &cache);
    return t_chord * f->s;
}

/* Bounce of a flight on segment `hit` (deflector d): the impact point on the
 * curve, the safe point Q before it, the reflected velocity, the rest of
 * the flight from Q; resting contact per iskra/impact.h.  Returns the new
 * chord end in (*ex, *ey). */
void isk__segs_bounce_flight(const isk__contact_ctx *c, int hit, const isk_deflector *d, isk__flight *f,
                             double t_chord, double *ex, double *ey)
{
    isk__seg tmp;
    const double tau = isk__segs_flight_hit(f, isk__contact_seg(c, hit, &tmp), t_chord);
    double hx, hy, uix, uiy;
    isk__flight_at(f, tau, &hx, &hy, &uix, &uiy);
    isk__segs_bounce_at(c, hit, d, f, t_chord, tau, hx, hy, uix, uiy, ex, ey);
}

/* The bounce of isk__segs_bounce_flight once the impact is known: at tau,
 * at the point H = (hx, hy) with the flight's velocity (uix, uiy) there
 * (the flight's own, or the integrator's: iskra/contacts.h).  Returns 1
 * when the particle came to rest on the segment. */
int isk__segs_bounce_at(const isk__contact_ctx *c, int hit, const isk_deflector *d, isk__flight *f, double t_chord,
                        double tau, double hx, double hy, double uix, double uiy, double *ex, double *ey)
{
    isk__seg tmp;
    const isk__seg *s = isk__contact_seg(c, hit, &tmp);
    double qx, qy;
    double th = isk__seg_crossing(s, f->sx, f->sy, hx, hy);
    if (th >= 0.0)
        isk__segs_safe_point(c, hit, f->sx, f->sy, hx, hy, th, &qx, &qy);
    else if (isk__sgn(isk__seg_side(s, hx, hy)) == isk__sgn(isk__seg_side(s, f->sx, f->sy)) &&
             off_every_line(c, hx, hy) && isk__segs_nearest(c, f->sx, f->sy, hx, hy, &th) < 0) {
        qx = hx; /* the curve met the line a hair off the chord: H itself is safe */
        qy = hy;
    } else
        isk__segs_safe_point(c, hit, f->sx, f->sy, *ex, *ey, t_chord, &qx, &qy);
    /* Reflect the velocity at impact; only one moving into the segment. */
    double nsg = isk__seg_side(s, f->sx, f->sy) > 0.0 ? 1.0 : -1.0; /* n_out = nsg * n points back to the start */
    double nox = nsg * s->nx, noy = nsg * s->ny;
    if (uix * nox + uiy * noy < 0.0) {
        isk__seg_reflect(d, s, &uix, &uiy);
        isk__speed_cap(&uix, &uiy);
    }
    f->s = f->s - tau > 0.0 ? f->s - tau : 0.0;
    f->sx = qx;
    f->sy = qy;
    f->ux = uix;
    f->uy = uiy;
    /* Pressed back into the segment with every further hop fitting in the
     * step: it rests on it (uniform restitution scales the tangential part
     * at every hop too, so it stops; normal restitution lets it slide) and
     * the segment holds it against the normal acceleration. */
    const double V = f->ux * nox + f->uy * noy, an = f->ax * nox + f->ay * noy, cr = d->restitution;
    int rested = 0;
    if (an < 0.0 && (!(V > 0.0) || (cr < 1.0 && 2.0 * V <= -an * (1.0 - cr) * f->s * (1.0 + 1e-9)))) {
        if (d->mode == ISK_RESTITUTION_UNIFORM && cr < 1.0) {
            f->ux = f->uy = 0.0;
        } else {
            f->ux -= V * nox;
            f->uy -= V * noy;
        }
        f->ax -= an * nox;
        f->ay -= an * noy;
        rested = 1;
    }
    double vx, vy;
    isk__flight_at(f, f->s, ex, ey, &vx, &vy);
    return rested;
}

/* Bounce of a straight path with the end-of-step velocity (isk_deflect):
 * the rest of the path, (1 - t)(E - S), and the velocity are both mapped by
 * M from the safe point. */
void isk__segs_bounce_linear(const isk__contact_ctx *c, int hit, const isk_deflector *d, double *sx, double *sy,
                             double *ex, double *ey, double *ux, double *uy, double t)
{
    isk__seg tmp;
    const isk__seg *s = isk__contact_seg(c, hit, &tmp);
    double qx, qy;
    isk__segs_safe_point(c, hit, *sx, *sy, *ex, *ey, t, &qx, &qy);
    double rx = (1.0 - t) * (*ex - *sx), ry = (1.0 - t) * (*ey - *sy); /* rest of the path */
    isk__seg_reflect(d, s, ux, uy);
    isk__speed_cap(ux, uy);
    isk__seg_reflect(d, s, &rx, &ry);
    *sx = qx;
    *sy = qy;
    *ex = qx + rx;
    *ey = qy + ry;
}
