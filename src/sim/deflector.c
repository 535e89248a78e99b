/* SPDX-License-Identifier: MIT */
/* Segment deflectors: exact path-crossing tests, side tests that keep
 * their precision for segments of any length, and the bounce / kill /
 * stick responses, with the bounce at the time of impact when the motion
 * of the step is known.  Conventions are documented in iskra/deflector.h
 * and iskra/impact.h. */
#include "iskra/deflector.h"

#include <math.h>
#include <string.h>

#include "iskra/contacts.h"
#include "iskra/integrate.h"
#include "sim/crossing.h"
#include "sim/flight.h"
#include "sim/rest_screen.h"  /* isk__rest_at_once */
#include "sim/wall_contact.h"

const char *const isk_deflect_reaction_names[ISK_DEFLECT_REACTION_COUNT] = {"bounce", "kill", "stick"};
const char *const isk_restitution_mode_names[ISK_RESTITUTION_MODE_COUNT] = {"uniform", "normal"};

/* ---- error-free transformations (round to nearest, no fused multiply-add:
 * the build uses -ffp-contract=off) ---------------------------------------- */

static inline void two_sum(double a, double b, double *s, double *e)
{
    double x = a + b, bv = x - a, av = x - bv;
    *s = x;
    *e = (a - av) + (b - bv);
}

/* Veltkamp's split: a = hi + lo, each half 26 bits (|a| < 1e300). */
static inline void split(double a, double *hi, double *lo)
{
    double c = 134217729.0 * a; /* 2^27 + 1 */
    double h = c - (c - a);
    *hi = h;
    *lo = a - h;
}

/* Dekker's product: a*b = p + e exactly. */
static inline void two_prod(double a, double b, double *p, double *e)
{
    double ah, al, bh, bl;
    split(a, &ah, &al);
    split(b, &bh, &bl);
    double x = a * b;
    *p = x;
    *e = ((ah * bh - x) + ah * bl + al * bh) + al * bl;
}

/* The sum of four doubles, exactly as a nonoverlapping expansion (Shewchuk's
 * grow-expansion), then added from the smallest part: within an ulp of the
 * exact sum however much it cancels. */
static double sum4(double a, double b, double c, double d)
{
    double e[8], h[8], in[4] = {a, b, c, d};
    int n = 0;
    for (int j = 0; j < 4; j++) {
        double q = in[j];
        int m = 0;
        for (int i = 0; i < n; i++) {
            double s, t;
            two_sum(q, e[i], &s, &t);
            q = s;
            if (t != 0.0)
                h[m++] = t;
        }
        if (q != 0.0 || m == 0)
            h[m++] = q;
        memcpy(e, h, (size_t)m * sizeof *e);
        n = m;
    }
    double s = 0.0;
    for (int i = 0; i < n; i++)
        s += e[i];
    return s;
}

/* ---- segments ------------------------------------------------------------ */

/* A segment in canonical form: endpoint A first (lexicographic on x, y),
 * d = B - A (rounded; dl its exact remainder), K = cross(A, B) rounded
 * from its exact value, and the unit normal n = (-dy, dx)/|d|.  Adding 0.0
 * turns -0 into +0 so reversed input is bit-identical even there. */
typedef struct seg {
    double ax, ay, bx, by, dx, dy;
    double dlx, dly, K;
    double nx, ny, len;
} seg;

static seg canon(const isk_deflector *d)
{
    seg s;
    int keep = d->x0 < d->x1 || (d->x0 == d->x1 && d->y0 <= d->y1);
    s.ax = (keep ? d->x0 : d->x1) + 0.0;
    s.ay = (keep ? d->y0 : d->y1) + 0.0;
    s.bx = (keep ? d->x1 : d->x0) + 0.0;
    s.by = (keep ? d->y1 : d->y0) + 0.0;
    two_sum(s.bx, -s.ax, &s.dx, &s.dlx);
    two_sum(s.by, -s.ay, &s.dy, &s.dly);
    double k1, f1, k2, f2;
    two_prod(s.ax, s.by, &k1, &f1);
    two_prod(s.ay, s.bx, &k2, &f2);
    s.K = sum4(k1, f1, -k2, -f2);
    s.len = hypot(s.dx, s.dy);
    s.nx = -s.dy / s.len;
    s.ny = s.dx / s.len;
    return s;
}

/* Side of P relative to the line through the segment, cross(B - A, P - A).
 * The direct formula relative to A carries the rounding of |P - A|: for a
 * segment reaching to 1e12 a point near the origin is resolved only to
 * 1e-4, and at 1e150 not at all.  So it is used only where its error bound
 * (Shewchuk's orient2d bound) shows it accurate to 2^-32 of its value;
 * otherwise the same determinant is evaluated as cross(B - A, P) + K in
 * twice the working precision (exact products, exact B - A and K), whose
 * error is that of a point at |P| on a segment through the origin: the
 * precision no longer depends on where the endpoints are. */
static double side(const seg *s, double px, double py)
{
    double l = s->dx * (py - s->ay), r = s->dy * (px - s->ax);
    double o = l - r;
    const double bound = 0x1p32 * 3.3306690738754716e-16 * (fabs(l) + fabs(r)); /* (3 + 16 eps) eps */
    if (fabs(o) > bound || !(fabs(px) < 1e300 && fabs(py) < 1e300))
        return o;
    double p1, e1, p2, e2, u, eu, w, ew;
    two_prod(s->dx, py, &p1, &e1);
    two_prod(s->dy, px, &p2, &e2);
    two_sum(p1, -p2, &u, &eu);
    two_sum(u, s->K, &w, &ew);
    return w + (((e1 - e2) + (eu + ew)) + (s->dlx * py - s->dly * px));
}

static inline int sgn(double v)
{
    return (v > 0.0) - (v < 0.0);
}

/* Crossing parameter of path P0 -> P1 with the segment, or -1 for no hit.
 * See the touching convention in the header. */
static double crossing(const seg *s, double x0, double y0, double x1, double y1)
{
    double o1 = side(s, x0, y0);
    int s1 = sgn(o1);
    if (s1 == 0)
        return -1.0; /* starting on the line: leaving it */
    double o2 = side(s, x1, y1);
    if (sgn(o2) == s1)
        return -1.0;
    /* The path's own side tests of A and B: the same expression for a vertex
     * shared by two segments, so shared vertices are watertight. */
    double px = x1 - x0, py = y1 - y0;
    int s3 = sgn(px * (s->ay - y0) - py * (s->ax - x0));
    int s4 = sgn(px * (s->by - y0) - py * (s->bx - x0));
    if (s3 != 0 && s3 == s4)
        return -1.0;
    return o1 / (o1 - o2); /* opposite signs: no cancellation, in (0, 1] */
}

isk_deflector isk_deflector_segment(double x0, double y0, double x1, double y1)
{
    isk_deflector d = {x0, y0, x1, y1, 1.0, 1.0, ISK_DEFLECT_BOUNCE, ISK_RESTITUTION_UNIFORM};
    return d;
}

isk_status isk_deflector_check(const isk_deflector *d)
{
    if (!d)
        return ISK_ERR_NULL;
    if (!isfinite(d->x0) || !isfinite(d->y0) || !isfinite(d->x1) || !isfinite(d->y1) || !isfinite(d->restitution) ||
        !isfinite(d->probability))
        return ISK_ERR_NAN;
    if (d->x0 == d->x1 && d->y0 == d->y1)
        return ISK_ERR_RANGE;
    if (!(fabs(d->x0) <= ISK_COORD_MAX && fabs(d->y0) <= ISK_COORD_MAX &&
          fabs(d->x1) <= ISK_COORD_MAX && fabs(d->y1) <= ISK_COORD_MAX))
        return ISK_ERR_RANGE;
    if (d->restitution < 0.0 || d->restitution > ISK_DEFLECT_RESTITUTION_MAX || d->probability < 0.0 ||
        d->probability > 1.0)
        return ISK_ERR_RANGE;
    if (d->reaction != ISK_DEFLECT_BOUNCE && d->reaction != ISK_DEFLECT_KILL && d->reaction != ISK_DEFLECT_STICK)
        return ISK_ERR_RANGE;
    if (d->mode != ISK_RESTITUTION_UNIFORM && d->mode != ISK_RESTITUTION_NORMAL)
        return ISK_ERR_RANGE;
    return ISK_OK;
}

/* The velocity map M (iskra/deflector.h). */
static void reflect(const isk_deflector *d, const seg *s, double *vx, double *vy)
{
    double nx = s->nx, ny = s->ny;
    double vn = *vx * nx + *vy * ny;
    double c = d->restitution;
    if (d->mode == ISK_RESTITUTION_UNIFORM) {
        *vx = c * (*vx - 2.0 * vn * nx);
        *vy = c * (*vy - 2.0 * vn * ny);
    } else {
        double tx = *vx - vn * nx, ty = *vy - vn * ny; /* v_t */
        *vx = tx - c * (vn * nx);
        *vy = ty - c * (vn * ny);
    }
}

/* A bumper (c > 1) never leaves a speed above ISK_SPEED_LIMIT. */
static void cap_speed(double *vx, double *vy)
{
    double v = hypot(*vx, *vy);
    if (v > ISK_SPEED_LIMIT) {
        double f = ISK_SPEED_LIMIT / v;
        *vx *= f;
        *vy *= f;
    }
}

void isk_deflector_reflect(const isk_deflector *d, double *vx, double *vy)
{
    seg s = canon(d);
    reflect(d, &s, vx, vy);
}

/* ---- one call: the segments in canonical form, the paths ----------------- */

enum { SEG_CACHE = 64 }; /* more segments than this are put in canonical form on the fly */

typedef struct ctx {
    const isk_deflector *defs;
    int ndef;
    const isk_contact_integrator *redo; /* NULL: the rest of a step after a contact is the fitted flight */
    isk_scratch *scratch;                /* the integrator's working arrays (with redo) */
    seg cache[SEG_CACHE];
    int passed[ISK_DEFLECT_MAX_HITS];
    int npassed;
} ctx;

static const seg *get_seg(const ctx *c, int k, seg *tmp)
{
    if (k < SEG_CACHE)
        return &c->cache[k];
    *tmp = canon(&c->defs[k]);
    return tmp;
}

static int was_passed(const ctx *c, int k)
{
    for (int i = 0; i < c->npassed; i++)
        if (c->passed[i] == k)
            return 1;
    return 0;
}

/* Nearest hit on S -> E among the segments not passed through on this path;
 * returns its index (ties: lowest) and *t, or -1. */
static int nearest(const ctx *c, double sx, double sy, double ex, double ey, double *t)
{
    int best = -1;
    double bt = INFINITY;
    for (int k = 0; k < c->ndef; k++) {
        if (c->npassed && was_passed(c, k))
            continue;
        seg tmp;
        double tk = crossing(get_seg(c, k, &tmp), sx, sy, ex, ey);
        if (tk >= 0.0 && tk < bt) {
            bt = tk;
            best = k;
        }
    }
    *t = bt;
    return best;
}

/* 1 when (x, y) is on no segment's line. */
static int off_every_line(const ctx *c, double x, double y)
{
    for (int k = 0; k < c->ndef; k++) {
        seg tmp;
        if (side(get_seg(c, k, &tmp), x, y) == 0.0)
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
static void safe_point(const ctx *c, int hit, double sx, double sy, double ex, double ey, double t, double *qx,
                      double *qy)
{
    seg tmp;
    const seg *h = get_seg(c, hit, &tmp);
    int want = sgn(side(h, sx, sy));
    double dx = ex - sx, dy = ey - sy;
    double delta = t * 0x1p-50;
    for (int iter = 0; iter < 64 && delta < t; iter++, delta *= 2.0) {
        double tau = t - delta;
        double x = sx + tau * dx, y = sy + tau * dy;
        if (sgn(side(h, x, y)) != want || !off_every_line(c, x, y))
            continue;
        double tq;
        if (nearest(c, sx, sy, x, y, &tq) >= 0)
            break; /* rounding put Q past another segment: give up */
        *qx = x;
        *qy = y;
        return;
    }
    *qx = sx;
    *qy = sy;
}

/* ---- the motion of one particle in the step (iskra/impact.h) ------------- */

/* The flight since the last bounce: start S, velocity U, acceleration A,
 * drag rate k, time left s; the integrator's velocity offset (dx, dy). */
typedef struct flight {
    double sx, sy, ux, uy, ax, ay, k, s;
    double delx, dely;
} flight;

static void flight_at(const flight *f, double t, double *x, double *y, double *vx, double *vy)
{
    double e, d1, d2;
    isk__fl_basis(f->k, t, &e, &d1, &d2);
    *x = f->sx + f->ux * d1 + f->ax * d2;
    *y = f->sy + f->uy * d1 + f->ay * d2;
    *vx = f->ux * e + f->ax * d1;
    *vy = f->uy * e + f->ay * d1;
}

/* When the flight meets the line of segment s (S strictly on one side);
 * t_chord: where the chord S -> E crossed it (the answer when the curve and
 * the chord disagree, by rounding or near an end of the segment). */
static double flight_hit(const flight *f, const seg *s, double t_chord)
{
    double o = side(s, f->sx, f->sy) / s->len; /* signed distance of S from the line */
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
static int bounce_at(const ctx *c, int hit, const isk_deflector *d, flight *f, double t_chord, double tau, double hx,
                     double hy, double uix, double uiy, double *ex, double *ey);

static void bounce_flight(const ctx *c, int hit, const isk_deflector *d, flight *f, double t_chord, double *ex,
                          double *ey)
{
    seg tmp;
    const double tau = flight_hit(f, get_seg(c, hit, &tmp), t_chord);
    double hx, hy, uix, uiy;
    flight_at(f, tau, &hx, &hy, &uix, &uiy);
    bounce_at(c, hit, d, f, t_chord, tau, hx, hy, uix, uiy, ex, ey);
}

/* The bounce of bounce_flight once the impact is known: at tau, at the
 * point H = (hx, hy) with the flight's velocity (uix, uiy) there (the
 * flight's own, or the integrator's: iskra/contacts.h).  Returns 1 when
 * the particle came to rest on the segment. */
static int bounce_at(const ctx *c, int hit, const isk_deflector *d, flight *f, double t_chord, double tau, double hx,
                     double hy, double uix, double uiy, double *ex, double *ey)
{
    seg tmp;
    const seg *s = get_seg(c, hit, &tmp);
    double qx, qy;
    double th = crossing(s, f->sx, f->sy, hx, hy);
    if (th >= 0.0)
        safe_point(c, hit, f->sx, f->sy, hx, hy, th, &qx, &qy);
    else if (sgn(side(s, hx, hy)) == sgn(side(s, f->sx, f->sy)) && off_every_line(c, hx, hy) &&
             nearest(c, f->sx, f->sy, hx, hy, &th) < 0) {
        qx = hx; /* the curve met the line a hair off the chord: H itself is safe */
        qy = hy;
    } else
        safe_point(c, hit, f->sx, f->sy, *ex, *ey, t_chord, &qx, &qy);
    /* Reflect the velocity at impact; only one moving into the segment. */
    double nsg = side(s, f->sx, f->sy) > 0.0 ? 1.0 : -1.0; /* n_out = nsg * n points back to the start */
    double nox = nsg * s->nx, noy = nsg * s->ny;
    if (uix * nox + uiy * noy < 0.0) {
        reflect(d, s, &uix, &uiy);
        cap_speed(&uix, &uiy);
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
    flight_at(f, f->s, ex, ey, &vx, &vy);
    return rested;
}

/* Bounce of a straight path with the end-of-step velocity (isk_deflect):
 * the rest of the path, (1 - t)(E - S), and the velocity are both mapped by
 * M from the safe point. */
static void bounce_linear(const ctx *c, int hit, const isk_deflector *d, double *sx, double *sy, double *ex,
                          double *ey, double *ux, double *uy, double t)
{
    seg tmp;
    const seg *s = get_seg(c, hit, &tmp);
    double qx, qy;
    safe_point(c, hit, *sx, *sy, *ex, *ey, t, &qx, &qy);
    double rx = (1.0 - t) * (*ex - *sx), ry = (1.0 - t) * (*ey - *sy); /* rest of the path */
    reflect(d, s, ux, uy);
    cap_speed(ux, uy);
    reflect(d, s, &rx, &ry);
    *sx = qx;
    *sy = qy;
    *ex = qx + rx;
    *ey = qy + ry;
}

/* ---- the rest of a step flown by the integrator (iskra/contacts.h) -------- */

/* A particle's state as the integrator keeps it (its stored velocity). */
typedef struct state {
    double x, y, vx, vy;
} state;

/* One step of the integrator of c->redo over t from st. */
static state redo_step(const ctx *c, state st, double m, double t)
{
    if (t > 0.0)
        isk_integrate_block(c->redo->method, c->redo->forces, c->scratch, 1, &st.x, &st.y, &st.vx, &st.vy, &m, t);
    return st;
}

/* The integrator's state at the contact the flight puts at *tau after the
 * start st0 (at most s_max): one step of the integrator over *tau, its
 * time refined by a Newton step on the signed distance nx x + ny y - off
 * to the wall or the segment's line, so that the contact is where the
 * integrator's own path meets it.  The flight is fitted to the ends of
 * that path, so one step brings the distance down to rounding. */
static state redo_contact(const ctx *c, state st0, double m, double *tau, double s_max, double nx, double ny,
                          double off)
{
    state st = redo_step(c, st0, m, *tau);
    const double g = nx * st.x + ny * st.y - off, gp = nx * st.vx + ny * st.vy;
    const double t1 = gp != 0.0 ? *tau - g / gp : *tau;
    if (t1 != *tau && t1 > 0.0 && t1 <= s_max && isfinite(t1)) {
        st = redo_step(c, st0, m, t1);
        *tau = t1;
    }
    return st;
}

/* At a contact resolved with the integrator, the velocity reflected is the
 * integrator's own (its state at the contact), not the flight's: the
 * flight's offset from it (which a potential makes of the order of the
 * force's change over the step) is dropped, or it would be added to the
 * reflected velocity and change the energy at every bounce. */
static void redo_own_velocity(flight *f)
{
    f->delx = f->dely = 0.0;
}

/* After a contact resolved with the integrator: the rest of the step, from
 * the flight's new start (its velocity plus the offset, the integrator's
 * form: *start), is one step of the integrator; its end becomes the
 * particle's and the flight is fitted to it (to find the next contact).
 * Returns the integrator's end state. */
static state redo_rest(const ctx *c, flight *f, double m, state *start)
{
    const state st0 = {f->sx, f->sy, f->ux + f->delx, f->uy + f->dely};
    *start = st0;
    if (!(f->s > 0.0))
        return st0;
    const state end = redo_step(c, st0, m, f->s);
    flight g = *f;
    isk__fl_fit(st0.x, st0.vx, end.x, end.vx, f->k, f->s, &g.ux, &g.ax, &g.delx);
    isk__fl_fit(st0.y, st0.vy, end.y, end.vy, f->k, f->s, &g.uy, &g.ay, &g.dely);
    if (isfinite(g.ux) && isfinite(g.uy) && isfinite(g.ax) && isfinite(g.ay) && isfinite(g.delx) &&
        isfinite(g.dely))
        *f = g;
    return end;
}

/* ---- walls in the same pass (iskra/contacts.h) ---------------------------- */

/* The sound walls of a contact pass, per axis (0: x, 1: y); a missing wall
 * at -inf / +inf. */
typedef struct wall_box {
    double lo[2], hi[2];
    double c;
    int on[2];
} wall_box;

static wall_box wall_box_of(const isk_bounds *b)
{
    const unsigned sd = b->sides;
    wall_box w = {{sd & ISK_SIDE_LEFT ? b->xmin + b->margin : -INFINITY,
                   sd & ISK_SIDE_BOTTOM ? b->ymin + b->margin : -INFINITY},
                  {sd & ISK_SIDE_RIGHT ? b->xmax - b->margin : INFINITY,
                   sd & ISK_SIDE_TOP ? b->ymax - b->margin : INFINITY},
                  b->restitution,
                  {(sd & (ISK_SIDE_LEFT | ISK_SIDE_RIGHT)) != 0, (sd & (ISK_SIDE_BOTTOM | ISK_SIDE_TOP)) != 0}};
    return w;
}

static int in_box(const wall_box *w, double x, double y)
{
    return x >= w->lo[0] && x <= w->hi[0] && y >= w->lo[1] && y <= w->hi[1];
}

/* Which of the flight's axes an axis of the walls watches: those that
 * started the step inside (one born outside is mirrored in at the end)
 * and do not rest on a wall (its normal motion is then held at zero). */
static int watches(const wall_box *w, const int skip[2], int a)
{
    return w->on[a] && !skip[a];
}

/* The first wall the flight meets in the rest of the step: its time (or
 * INFINITY), axis and side (-1: lo, +1: hi); ties go to x. */
static double first_wall(const flight *f, const wall_box *w, const int skip[2], int *axis, int *side)
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
static void rest_on_wall(flight *f, int a, double W, int skip[2])
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
static int rest_at_start(flight *f, const wall_box *w, double h, int skip[2])
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
static int bounce_wall(flight *f, const wall_box *w, int a, int side, double tau, double hx, double hy, double ux,
                       double uy, int skip[2])
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
    if (sigma * acc < 0.0 && (!(sigma * U > 0.0) || (c < 1.0 && 2.0 * sigma * U <= -sigma * acc * (1.0 - c) * f->s * (1.0 + 1e-9)))) {
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
static void finish_walls(const wall_box *w, const int born_out[2], double *x, double *y, double *vx, double *vy)
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

/* The flight of particle i in the step (iskra/impact.h), fitted to its
 * start (sx, sy and mo's velocities) and its end (ex, ey, ux, uy).  Returns
 * 0 when there is no usable motion (a start velocity not finite). */
static int fit_flight(flight *f, const isk_step_motion *mo, size_t i, double sx, double sy, double ex, double ey,
                      double ux, double uy)
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

static isk_status deflect(const isk_bounds *walls, const isk_deflector *defs, int ndef, double *x, double *y,
                          double *vx, double *vy, const double *x_old, const double *y_old, const isk_step_motion *mo,
                          const isk_contact_integrator *redo, size_t n, isk_rng *rng, uint8_t *killed,
                          isk_deflect_stats *stats)
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
    if (walls && walls->sides == 0)
        walls = NULL; /* no wall: the deflectors alone */
    if (walls) {
        isk_status st = isk_bounds_validate(walls);
        if (st != ISK_OK)
            return st;
        if (walls->mode != ISK_BOUNCE_REFLECT)
            return ISK_ERR_RANGE;
        if (!mo)
            return ISK_ERR_NULL;
    }
    if (redo && (!mo || !redo->forces || (unsigned)redo->method >= ISK_INTEGRATOR_COUNT))
        return redo->forces ? ISK_ERR_RANGE : ISK_ERR_NULL;
    if (ndef == 0 && !walls)
        return ISK_OK;

    isk_deflect_stats local = {0, 0, 0, 0, 0, 0, NULL, 0, NULL};
    uint8_t *per_particle = stats ? stats->bounced : NULL;
    uint8_t *per_particle_walls = walls && stats ? stats->wall_bounced : NULL;
    if (per_particle && n > 0)
        memset(per_particle, 0, n);
    if (per_particle_walls && n > 0)
        memset(per_particle_walls, 0, n);
    const wall_box wb = walls ? wall_box_of(walls) : (wall_box){{0, 0}, {0, 0}, 0, {0, 0}};
    ctx c;
    c.defs = defs;
    c.ndef = ndef;
    c.redo = redo;
    isk_scratch scratch; /* the integrator's arrays for one particle (with redo) */
    c.scratch = &scratch;
    for (int k = 0; k < ndef && k < SEG_CACHE; k++)
        c.cache[k] = canon(&defs[k]);
    for (size_t i = 0; i < n; i++) {
        if (killed && killed[i])
            continue;
        if (ndef == 0 && in_box(&wb, x[i], y[i]))
            continue; /* walls alone, a path that ends inside: nothing to meet (a NaN is not inside) */
        double sx = x_old[i], sy = y_old[i], ex = x[i], ey = y[i], ux = vx[i], uy = vy[i];
        if (!isfinite(sx) || !isfinite(sy) || !isfinite(ex) || !isfinite(ey) || !isfinite(ux) || !isfinite(uy))
            continue;
        flight f;
        int fitted = 0, bounced = 0, linear = mo == NULL;
        /* With the integrator (redo): after each contact the rest of the
         * step is its step, from the contact; `end` is where it ends.  Off
         * once the particle rests on a wall or a segment (the flight holds
         * it there). */
        int redo_on = redo != NULL && mo != NULL;
        const double mass = mo && mo->m ? mo->m[i] : 1.0;
        state end = {ex, ey, ux, uy};
        state from = {sx, sy, mo ? mo->vx0[i] : 0.0, mo ? mo->vy0[i] : 0.0}; /* the integrator's state where the
                                                                               flight starts (redo) */
        c.npassed = 0;
        int hits = 0, done = 0, contacts = 0;
        /* walls: the axes that started outside (mirrored in at the end) or
         * rest on a wall (skip), and those that started outside alone */
        int skip[2] = {0, 0}, born_out[2] = {0, 0};
        if (walls) {
            born_out[0] = wb.on[0] && !(sx >= wb.lo[0] && sx <= wb.hi[0]);
            born_out[1] = wb.on[1] && !(sy >= wb.lo[1] && sy <= wb.hi[1]);
            skip[0] = born_out[0];
            skip[1] = born_out[1];
        }
        while (!done) {
            double t;
            int k = ndef ? nearest(&c, sx, sy, ex, ey, &t) : -1;
            if (walls && !linear) {
                /* The walls and the segments in the order the path meets
                 * them: the flight is needed once the path ends outside
                 * the box or crosses a segment. */
                if (!fitted && (k >= 0 || !in_box(&wb, ex, ey))) {
                    fitted = 1;
                    if (!fit_flight(&f, mo, i, sx, sy, ex, ey, ux, uy) || !(isfinite(f.delx) && isfinite(f.dely))) {
                        linear = 1; /* no usable motion: the segments' path rule, the walls' end rule */
                        continue;
                    }
                    if (rest_at_start(&f, &wb, mo->h, skip)) { /* the flight changed: its new end */
                        double wvx, wvy;
                        flight_at(&f, f.s, &ex, &ey, &wvx, &wvy);
                        sx = f.sx;
                        sy = f.sy;
                        bounced = 1;
                        redo_on = 0;
                        continue;
                    }
                }
                int axis = -1, side = 0;
                const double tw = fitted ? first_wall(&f, &wb, skip, &axis, &side) : INFINITY;
                if (axis >= 0 && k >= 0) {
                    seg tmp;
                    if (flight_hit(&f, get_seg(&c, k, &tmp), t) <= tw)
                        axis = -1; /* the segment first (a tie too: the wall is met next) */
                }
                if (axis >= 0 && ndef) {
                    /* The wall first, unless the chord to the point of
                     * impact crosses a segment that the chord to the end
                     * (beyond the wall) missed: a curved path into a
                     * corner of a wall and a segment.  Then that segment
                     * first, along the chord to the wall. */
                    double hx, hy, hvx, hvy, t2;
                    flight_at(&f, tw, &hx, &hy, &hvx, &hvy);
                    if (axis)
                        hy = side < 0 ? wb.lo[1] : wb.hi[1];
                    else
                        hx = side < 0 ? wb.lo[0] : wb.hi[0];
                    const int k2 = nearest(&c, sx, sy, hx, hy, &t2);
                    if (k2 >= 0) {
                        k = k2;
                        t = t2;
                        ex = hx;
                        ey = hy;
                        axis = -1;
                    }
                }
                if (axis >= 0) {
                    if (contacts == ISK_CONTACTS_MAX) {
                        ex = sx; /* out of contacts: stay at the last contact, with the velocity there */
                        ey = sy;
                        local.last_resort++;
                        ux = f.ux + f.delx;
                        uy = f.uy + f.dely;
                        bounced = 0;
                        break;
                    }
                    contacts++;
                    double tau = tw, hx, hy, hvx, hvy;
                    if (redo_on) { /* the integrator's state at the contact, its velocity reflected */
                        const state at = redo_contact(&c, from, mass, &tau, f.s, axis ? 0.0 : 1.0,
                                                      axis ? 1.0 : 0.0, side < 0 ? wb.lo[axis] : wb.hi[axis]);
                        redo_own_velocity(&f);
                        hx = at.x;
                        hy = at.y;
                        hvx = at.vx;
                        hvy = at.vy;
                    } else {
                        flight_at(&f, tau, &hx, &hy, &hvx, &hvy);
                    }
                    if (bounce_wall(&f, &wb, axis, side, tau, hx, hy, hvx, hvy, skip))
                        redo_on = 0;
                    local.wall_bounces++;
                    if (per_particle_walls && per_particle_walls[i] < 255)
                        per_particle_walls[i]++;
                    if (redo_on) {
                        end = redo_rest(&c, &f, mass, &from);
                        ex = end.x;
                        ey = end.y;
                    } else {
                        double wvx, wvy;
                        flight_at(&f, f.s, &ex, &ey, &wvx, &wvy);
                    }
                    sx = f.sx;
                    sy = f.sy;
                    bounced = 1;
                    c.npassed = 0; /* a new path */
                    continue;
                }
            }
            if (k < 0)
                break; /* E is final */
            if (hits == ISK_DEFLECT_MAX_HITS || contacts == ISK_CONTACTS_MAX) {
                ex = sx; /* out of hits: stay at the last safe point */
                ey = sy;
                local.last_resort++;
                if (bounced) { /* with the velocity the flight has there */
                    ux = f.ux + f.delx;
                    uy = f.uy + f.dely;
                    bounced = 0;
                }
                break;
            }
            hits++;
            local.hits++;
            const isk_deflector *d = &defs[k];
            double p = d->probability;
            int react = p >= 1.0 || (p > 0.0 && isk_rng_uniform(rng) < p);
            if (!react) {
                local.passes++;
                c.passed[c.npassed++] = k;
                continue;
            }
            if (d->reaction != ISK_DEFLECT_BOUNCE) {
                double qx, qy;
                safe_point(&c, k, sx, sy, ex, ey, t, &qx, &qy);
                if (d->reaction == ISK_DEFLECT_KILL) {
                    killed[i] = 1;
                    local.kills++;
                } else {
                    ux = uy = 0.0;
                    bounced = 0;
                    local.sticks++;
                }
                ex = qx;
                ey = qy;
                done = 1;
                break;
            }
            local.bounces++;
            contacts++;
            if (per_particle && per_particle[i] < 255)
                per_particle[i]++;
            c.npassed = 0; /* a new path */
            if (linear) {
                bounce_linear(&c, k, d, &sx, &sy, &ex, &ey, &ux, &uy, t);
                continue;
            }
            if (!fitted) {
                fitted = 1;
                if (!fit_flight(&f, mo, i, sx, sy, ex, ey, ux, uy)) {
                    /* no usable motion (a start velocity not finite): the path rule */
                    bounce_linear(&c, k, d, &sx, &sy, &ex, &ey, &ux, &uy, t);
                    linear = 1;
                    redo_on = 0;
                    continue;
                }
            }
            if (redo_on) { /* the contact where the integrator's path meets the segment's line */
                seg tmp;
                const seg *sg = get_seg(&c, k, &tmp);
                double tau = flight_hit(&f, sg, t);
                const state at = redo_contact(&c, from, mass, &tau,
                                              f.s, sg->nx, sg->ny, sg->nx * sg->ax + sg->ny * sg->ay);
                redo_own_velocity(&f);
                if (bounce_at(&c, k, d, &f, t, tau, at.x, at.y, at.vx, at.vy, &ex, &ey)) {
                    redo_on = 0;
                } else {
                    end = redo_rest(&c, &f, mass, &from);
                    ex = end.x;
                    ey = end.y;
                }
            } else {
                bounce_flight(&c, k, d, &f, t, &ex, &ey);
            }
            sx = f.sx;
            sy = f.sy;
            bounced = 1;
        }
        if (bounced && redo_on) { /* the integrator's own end velocity */
            ux = end.vx;
            uy = end.vy;
        } else if (bounced) {
            double px, py, wx, wy;
            flight_at(&f, f.s, &px, &py, &wx, &wy);
            ux = wx + f.delx;
            uy = wy + f.dely;
        }
        if (walls)
            finish_walls(&wb, born_out, &ex, &ey, &ux, &uy);
        x[i] = ex;
        y[i] = ey;
        vx[i] = ux;
        vy[i] = uy;
    }
    if (stats) {
        stats->wall_bounces += local.wall_bounces;
        stats->hits += local.hits;
        stats->bounces += local.bounces;
        stats->kills += local.kills;
        stats->sticks += local.sticks;
        stats->passes += local.passes;
        stats->last_resort += local.last_resort;
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

/* ---- gates: the same crossing test, counted (sim/crossing.h) -------------- */

void isk__segment_crossings(const isk_deflector *gate, size_t n, const double *x, const double *y,
                            const double *prev, size_t stride, uint64_t *forward, uint64_t *backward)
{
    const seg s = canon(gate);
    /* canon may have swapped the end points: the given direction's left is
     * then the canonical right */
    const int swapped = !(gate->x0 < gate->x1 || (gate->x0 == gate->x1 && gate->y0 <= gate->y1));
    uint64_t f = 0, b = 0;
    for (size_t i = 0; i < n; i++) {
        const double *p = prev + stride * i;
        if (crossing(&s, p[0], p[1], x[i], y[i]) < 0.0)
            continue;
        const int from_left = (side(&s, p[0], p[1]) > 0.0) != swapped;
        f += (uint64_t)from_left;
        b += (uint64_t)!from_left;
    }
    *forward += f;
    *backward += b;
}
