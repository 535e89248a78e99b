/* SPDX-License-Identifier: MIT */
/* Segment deflectors: exact path-crossing tests, side tests that keep
 * their precision for segments of any length, and the bounce / kill /
 * stick responses, with the bounce at the time of impact when the motion
 * of the step is known.  Conventions are documented in iskra/deflector.h
 * and iskra/impact.h. */
#include "iskra/deflector.h"

#include <math.h>
#include <string.h>

#include "sim/crossing.h"
#include "sim/flight.h"

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
static void bounce_flight(const ctx *c, int hit, const isk_deflector *d, flight *f, double t_chord, double *ex,
                          double *ey)
{
    seg tmp;
    const seg *s = get_seg(c, hit, &tmp);
    const double tau = flight_hit(f, s, t_chord);
    double hx, hy, uix, uiy;
    flight_at(f, tau, &hx, &hy, &uix, &uiy);
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
    if (an < 0.0 && (!(V > 0.0) || (cr < 1.0 && 2.0 * V <= -an * (1.0 - cr) * f->s * (1.0 + 1e-9)))) {
        if (d->mode == ISK_RESTITUTION_UNIFORM && cr < 1.0) {
            f->ux = f->uy = 0.0;
        } else {
            f->ux -= V * nox;
            f->uy -= V * noy;
        }
        f->ax -= an * nox;
        f->ay -= an * noy;
    }
    double vx, vy;
    flight_at(f, f->s, ex, ey, &vx, &vy);
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

static isk_status deflect(const isk_deflector *defs, int ndef, double *x, double *y, double *vx, double *vy,
                          const double *x_old, const double *y_old, const isk_step_motion *mo, size_t n,
                          isk_rng *rng, uint8_t *killed, isk_deflect_stats *stats)
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
    if (ndef == 0)
        return ISK_OK;

    isk_deflect_stats local = {0, 0, 0, 0, 0, 0, NULL};
    uint8_t *per_particle = stats ? stats->bounced : NULL;
    if (per_particle && n > 0)
        memset(per_particle, 0, n);
    ctx c;
    c.defs = defs;
    c.ndef = ndef;
    for (int k = 0; k < ndef && k < SEG_CACHE; k++)
        c.cache[k] = canon(&defs[k]);
    for (size_t i = 0; i < n; i++) {
        if (killed && killed[i])
            continue;
        double sx = x_old[i], sy = y_old[i], ex = x[i], ey = y[i], ux = vx[i], uy = vy[i];
        if (!isfinite(sx) || !isfinite(sy) || !isfinite(ex) || !isfinite(ey) || !isfinite(ux) || !isfinite(uy))
            continue;
        flight f;
        int fitted = 0, bounced = 0, linear = mo == NULL;
        c.npassed = 0;
        int hits = 0, done = 0;
        while (!done) {
            double t;
            int k = nearest(&c, sx, sy, ex, ey, &t);
            if (k < 0)
                break; /* E is final */
            if (hits == ISK_DEFLECT_MAX_HITS) {
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
            if (per_particle && per_particle[i] < 255)
                per_particle[i]++;
            c.npassed = 0; /* a new path */
            if (linear) {
                bounce_linear(&c, k, d, &sx, &sy, &ex, &ey, &ux, &uy, t);
                continue;
            }
            if (!fitted) {
                const double kk = mo->drag > 0.0 ? mo->drag / mo->m[i] : 0.0;
                f.sx = sx;
                f.sy = sy;
                f.k = kk;
                f.s = mo->h;
                isk__fl_fit(sx, mo->vx0[i], ex, ux, kk, mo->h, &f.ux, &f.ax, &f.delx);
                isk__fl_fit(sy, mo->vy0[i], ey, uy, kk, mo->h, &f.uy, &f.ay, &f.dely);
                fitted = 1;
                if (!(isfinite(f.ux) && isfinite(f.uy) && isfinite(f.ax) && isfinite(f.ay))) {
                    /* no usable motion (a start velocity not finite): the path rule */
                    bounce_linear(&c, k, d, &sx, &sy, &ex, &ey, &ux, &uy, t);
                    linear = 1;
                    continue;
                }
            }
            bounce_flight(&c, k, d, &f, t, &ex, &ey);
            sx = f.sx;
            sy = f.sy;
            bounced = 1;
        }
        if (bounced) {
            double px, py, wx, wy;
            flight_at(&f, f.s, &px, &py, &wx, &wy);
            ux = wx + f.delx;
            uy = wy + f.dely;
        }
        x[i] = ex;
        y[i] = ey;
        vx[i] = ux;
        vy[i] = uy;
    }
    if (stats) {
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
    return deflect(defs, ndef, x, y, vx, vy, x_old, y_old, NULL, n, rng, killed, stats);
}

isk_status isk_deflect_step(const isk_deflector *defs, int ndef, double *x, double *y, double *vx, double *vy,
                            const isk_step_motion *mo, size_t n, isk_rng *rng, uint8_t *killed,
                            isk_deflect_stats *stats)
{
    if (!mo)
        return ISK_ERR_NULL;
    return deflect(defs, ndef, x, y, vx, vy, mo->x0, mo->y0, mo, n, rng, killed, stats);
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
