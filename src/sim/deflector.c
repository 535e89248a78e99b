/* Segment deflectors: exact path-crossing tests and the bounce / kill /
 * stick responses.  Conventions are documented in iskra/deflector.h. */
#include "iskra/deflector.h"

#include <math.h>

/* A segment in canonical form: endpoint A first (lexicographic on x, y),
 * d = B - A.  Adding 0.0 turns -0 into +0 so reversed input is bit-identical
 * even there. */
typedef struct seg {
    double ax, ay, bx, by, dx, dy;
} seg;

const char *const isk_deflect_reaction_names[ISK_DEFLECT_REACTION_COUNT] = {"bounce", "kill", "stick"};
const char *const isk_restitution_mode_names[ISK_RESTITUTION_MODE_COUNT] = {"uniform", "normal"};

static seg canon(const isk_deflector *d)
{
    seg s;
    int keep = d->x0 < d->x1 || (d->x0 == d->x1 && d->y0 <= d->y1);
    s.ax = (keep ? d->x0 : d->x1) + 0.0;
    s.ay = (keep ? d->y0 : d->y1) + 0.0;
    s.bx = (keep ? d->x1 : d->x0) + 0.0;
    s.by = (keep ? d->y1 : d->y0) + 0.0;
    s.dx = s.bx - s.ax;
    s.dy = s.by - s.ay;
    return s;
}

/* Side of P relative to the line through the segment: cross(B - A, P - A). */
static inline double side(const seg *s, double px, double py)
{
    return s->dx * (py - s->ay) - s->dy * (px - s->ax);
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
    seg s = canon(d);
    if (!isfinite(s.dx) || !isfinite(s.dy) || !isfinite(hypot(s.dx, s.dy)))
        return ISK_ERR_RANGE; /* endpoints so far apart that d overflows */
    if (d->restitution < 0.0 || d->probability < 0.0 || d->probability > 1.0)
        return ISK_ERR_RANGE;
    if (d->reaction != ISK_DEFLECT_BOUNCE && d->reaction != ISK_DEFLECT_KILL && d->reaction != ISK_DEFLECT_STICK)
        return ISK_ERR_RANGE;
    if (d->mode != ISK_RESTITUTION_UNIFORM && d->mode != ISK_RESTITUTION_NORMAL)
        return ISK_ERR_RANGE;
    return ISK_OK;
}

static void reflect(const isk_deflector *d, const seg *s, double *vx, double *vy)
{
    double len = hypot(s->dx, s->dy);
    double nx = -s->dy / len, ny = s->dx / len;
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

void isk_deflector_reflect(const isk_deflector *d, double *vx, double *vy)
{
    seg s = canon(d);
    reflect(d, &s, vx, vy);
}

typedef struct ctx {
    const isk_deflector *defs;
    int ndef;
    int passed[ISK_DEFLECT_MAX_HITS];
    int npassed;
} ctx;

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
        seg s = canon(&c->defs[k]);
        double tk = crossing(&s, sx, sy, ex, ey);
        if (tk >= 0.0 && tk < bt) {
            bt = tk;
            best = k;
        }
    }
    *t = bt;
    return best;
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
    seg h = canon(&c->defs[hit]);
    int want = sgn(side(&h, sx, sy));
    double dx = ex - sx, dy = ey - sy;
    double delta = t * 0x1p-50;
    for (int iter = 0; iter < 64 && delta < t; iter++, delta *= 2.0) {
        double tau = t - delta;
        double x = sx + tau * dx, y = sy + tau * dy;
        if (sgn(side(&h, x, y)) != want)
            continue;
        int on_line = 0;
        for (int k = 0; k < c->ndef && !on_line; k++) {
            seg s = canon(&c->defs[k]);
            on_line = side(&s, x, y) == 0.0;
        }
        if (on_line)
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

isk_status isk_deflect(const isk_deflector *defs, int ndef, double *x, double *y, double *vx, double *vy,
                       const double *x_old, const double *y_old, size_t n, isk_rng *rng, uint8_t *killed,
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
    if ((need_rng && !rng) || (need_killed && !killed))
        return ISK_ERR_NULL;
    if (ndef == 0)
        return ISK_OK;

    isk_deflect_stats local = {0, 0, 0, 0, 0, 0};
    ctx c;
    c.defs = defs;
    c.ndef = ndef;
    for (size_t i = 0; i < n; i++) {
        if (killed && killed[i])
            continue;
        double sx = x_old[i], sy = y_old[i], ex = x[i], ey = y[i], ux = vx[i], uy = vy[i];
        if (!isfinite(sx) || !isfinite(sy) || !isfinite(ex) || !isfinite(ey) || !isfinite(ux) || !isfinite(uy))
            continue;
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
            double qx, qy;
            safe_point(&c, k, sx, sy, ex, ey, t, &qx, &qy);
            switch (d->reaction) {
            case ISK_DEFLECT_KILL:
                killed[i] = 1;
                local.kills++;
                ex = qx;
                ey = qy;
                done = 1;
                break;
            case ISK_DEFLECT_STICK:
                ux = uy = 0.0;
                local.sticks++;
                ex = qx;
                ey = qy;
                done = 1;
                break;
            default: /* validated: ISK_DEFLECT_BOUNCE */
            case ISK_DEFLECT_BOUNCE: {
                seg s = canon(d);
                double rx = (1.0 - t) * (ex - sx), ry = (1.0 - t) * (ey - sy); /* rest of the path */
                reflect(d, &s, &ux, &uy);
                reflect(d, &s, &rx, &ry);
                local.bounces++;
                sx = qx;
                sy = qy;
                ex = qx + rx;
                ey = qy + ry;
                c.npassed = 0; /* a new path */
                break;
            }
            }
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
