/* SPDX-License-Identifier: MIT */
/* Bounce stages: the thesis's zarobi and a sound reflection. */
#include "iskra/bounds.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "core/cpu.h"
#include "sim/flight.h"
#include "sim/kernels.h"
#include "sim/rest_screen.h"
#include "sim/wall_contact.h"
#include "sim/wall_screen.h"

#if ISK__CPU_SSE2
#include "sim/bounds_sse2.h"
#endif

const char *const isk_bounce_mode_names[ISK_BOUNCE_MODE_COUNT] = {"thesis", "reflect"};
const char *const isk_side_names[ISK_SIDE_COUNT] = {"top", "right", "bottom", "left"};

isk_status isk_bounds_validate(const isk_bounds *b)
{
    if (!b)
        return ISK_ERR_NULL;
    if (!isfinite(b->xmin) || !isfinite(b->xmax) || !isfinite(b->ymin) || !isfinite(b->ymax) ||
        !isfinite(b->margin) || !isfinite(b->restitution))
        return ISK_ERR_NAN;
    if (b->sides & ~(unsigned)ISK_SIDE_ALL)
        return ISK_ERR_RANGE;
    if (!(b->xmin < b->xmax) || !(b->ymin < b->ymax) || !isfinite(b->xmax - b->xmin) ||
        !isfinite(b->ymax - b->ymin))
        return ISK_ERR_RANGE; /* (a width that overflows would make the fold meaningless) */
    if (b->mode == ISK_BOUNCE_THESIS)
        return ISK_OK; /* the thesis accepts any margin */
    if (b->mode != ISK_BOUNCE_REFLECT)
        return ISK_ERR_RANGE;
    if (!(b->restitution >= 0.0 && b->restitution <= 1.0) || b->margin < 0.0)
        return ISK_ERR_RANGE;
    if (!(b->xmin + b->margin < b->xmax - b->margin) || !(b->ymin + b->margin < b->ymax - b->margin))
        return ISK_ERR_RANGE;
    return ISK_OK;
}

isk_status isk_bounds_thesis(isk_bounds *b, double xmin, double xmax, double ymin, double ymax,
                             unsigned sides)
{
    if (!b)
        return ISK_ERR_NULL;
    isk_bounds t = {ISK_BOUNCE_THESIS, sides, xmin, xmax, ymin, ymax, 0.1, 1.0};
    isk_status s = isk_bounds_validate(&t);
    if (s == ISK_OK)
        *b = t;
    return s;
}

isk_status isk_bounds_reflect(isk_bounds *b, double xmin, double xmax, double ymin, double ymax,
                              unsigned sides, double margin, double restitution)
{
    if (!b)
        return ISK_ERR_NULL;
    isk_bounds t = {ISK_BOUNCE_REFLECT, sides, xmin, xmax, ymin, ymax, margin, restitution};
    isk_status s = isk_bounds_validate(&t);
    if (s == ISK_OK)
        *b = t;
    return s;
}

/* ---- thesis: one loop per enabled side (no per-particle side test) ---- */

static void flip_below(size_t n, const double *restrict pos, double *restrict v, double wall)
{
    for (size_t i = 0; i < n; i++)
        v[i] = isk_k_flip_below(pos[i], wall, v[i]);
}

static void flip_above(size_t n, const double *restrict pos, double *restrict v, double wall)
{
    for (size_t i = 0; i < n; i++)
        v[i] = isk_k_flip_above(pos[i], wall, v[i]);
}

/* Floor: steps 3 and 5 fused (step 4, the top, only reads y, which step 5
 * has not yet changed, and both flips negate vy, so they commute). */
static void floor_flip_clamp(size_t n, double *restrict y, double *restrict vy, double wall)
{
    for (size_t i = 0; i < n; i++) {
        double p = y[i], u = vy[i];
        double nu = isk_k_flip_below(p, wall, u), np = isk_k_clamp_below(p, wall);
        vy[i] = nu; /* loads, selects, then stores: vectorizes */
        y[i] = np;
    }
}

static void thesis_apply(const isk_bounds *b, size_t n, double *x, double *y, double *vx, double *vy)
{
    double left = b->xmin + b->margin, right = b->xmax - b->margin;
    double bottom = b->ymin + b->margin, top = b->ymax - b->margin;
    if (b->sides & ISK_SIDE_LEFT)
        flip_below(n, x, vx, left);
    if (b->sides & ISK_SIDE_RIGHT)
        flip_above(n, x, vx, right);
    if (b->sides & ISK_SIDE_TOP)
        flip_above(n, y, vy, top);
    if (b->sides & ISK_SIDE_BOTTOM)
        floor_flip_clamp(n, y, vy, bottom);
}

/* ---- sound reflection ---- */

/* One pass per axis and chunk: candidates first into small stack buffers
 * (arithmetic only), then the selects; both loops vectorize (see kernels.h
 * for why it is split).  A disabled wall is at -inf/+inf: never crossed. */
enum { CHUNK = 256 };

static void reflect_pass(size_t n, double *restrict pos, double *restrict v, double lo, double hi,
                         double c)
{
    double ml[CHUNK], mh[CHUNK], rv[CHUNK];
    for (size_t o = 0; o < n; o += CHUNK) {
        size_t m = n - o < CHUNK ? n - o : CHUNK;
        double *restrict p = pos + o, *restrict u = v + o;
        for (size_t i = 0; i < m; i++) {
            ml[i] = isk_k_mirror_lo(p[i], lo, c);
            mh[i] = isk_k_mirror_hi(p[i], hi, c);
            rv[i] = isk_k_rebound(u[i], c);
        }
        for (size_t i = 0; i < m; i++) {
            isk_k_select_box(&p[i], &u[i], lo, hi, ml[i], mh[i], rv[i]);
        }
    }
}

/* Rare path: a particle still outside after one reflection per wall. */
/* Where a particle still outside after ISK_BOUNCE_MAX_REFLECTIONS
 * reflections ends up, in closed form (only between two walls, W = hi - lo
 * > 0; a single wall always takes one reflection).  With a first overshoot
 * o_0 beyond a wall, each reflection leaves o_{k+1} = c o_k - W beyond the
 * other one.
 *   c = 1: the path folds like a triangle wave of period 2W: fmod is exact,
 *          and the parity of the number of reflections flips v or not.
 *   c < 1: o_k = c^k (o_0 + S) - S with S = W / (1 - c), so the count is
 *          K = ceil(log1p(o_0 / S) / -log(c)); the particle ends c o_{K-1}
 *          inside the wall it hit last, with velocity v (-c)^K.
 * So a particle at any speed (10^6 units per step in a box of 10: 10^5
 * reflections) ends inside at the right place instead of clamped onto a
 * wall step after step, which would look stuck. */
static void fold_between(double *pos, double *vel, double lo, double hi, double c)
{
    double p = *pos, u = *vel, W = hi - lo;
    if (c == 1.0) {
        double m = fmod(p - lo, 2.0 * W);
        if (m < 0.0)
            m += 2.0 * W;
        int odd = m > W;
        *pos = odd ? lo + (2.0 * W - m) : lo + m;
        *vel = odd ? -u : u;
        return;
    }
    int above = p > hi;
    double o0 = above ? p - hi : lo - p;
    double S = W / (1.0 - c);
    double K = ceil(log1p(o0 / S) / -log(c));
    if (!(K >= 1.0))
        K = 1.0;
    double ck = pow(c, K);
    double inside = ck * (o0 + S) - S + W; /* c o_{K-1}: distance inside the last wall */
    inside = inside < 0.0 ? 0.0 : (inside > W ? W : inside);
    int last_is_first = fmod(K, 2.0) == 1.0;
    int last_hi = last_is_first ? above : !above;
    *pos = last_hi ? hi - inside : lo + inside;
    *vel = isk_k_flush(last_is_first ? -u * ck : u * ck);
}

/* One particle still outside after the vector pass: reflections one at a
 * time, then the closed-form fold, then the clamp of the last safety net
 * (a NaN or infinite coordinate lands on a wall). */
static void settle_one(double *pos, double *vel, double lo, double hi, double c)
{
    double p = *pos, u = *vel;
    for (int k = 0; k < ISK_BOUNCE_MAX_REFLECTIONS && !(p >= lo && p <= hi); k++) {
        if (p < lo)
            isk_k_reflect_lo(&p, &u, lo, c);
        else if (p > hi)
            isk_k_reflect_hi(&p, &u, hi, c);
        else
            break; /* NaN: handled by the clamp below */
    }
    if ((p < lo || p > hi) && isfinite(p) && isfinite(lo) && isfinite(hi) && isfinite(u))
        fold_between(&p, &u, lo, hi, c);
    if (!(p >= lo)) { /* also catches NaN */
        p = lo;
        if (!(u >= 0.0))
            u = u < 0.0 ? -c * u : 0.0;
    } else if (p > hi) {
        p = hi;
        if (u > 0.0)
            u = -c * u;
    }
    if (!isfinite(u))
        u = 0.0; /* an infinite velocity would throw it out again (and to NaN) at the next step */
    *pos = p;
    *vel = u;
}

void isk__wall_settle(double *pos, double *vel, double lo, double hi, double c)
{
    settle_one(pos, vel, lo, hi, c);
}

static void settle_axis(size_t n, double *restrict pos, double *restrict v, double lo, double hi,
                        double c)
{
    for (size_t i = 0; i < n; i++) {
        double p = pos[i];
        if (islessequal(p, hi) & isgreaterequal(p, lo) & (fabs(v[i]) <= DBL_MAX)) /* inside; NaN falls through */
            continue;
        settle_one(&pos[i], &v[i], lo, hi, c);
    }
}

static void reflect_axis(size_t n, double *pos, double *v, int lo_on, int hi_on, double lo, double hi,
                         double c)
{
    if (!lo_on && !hi_on)
        return;
    lo = lo_on ? lo : -INFINITY;
    hi = hi_on ? hi : INFINITY;
    reflect_pass(n, pos, v, lo, hi, c);
    settle_axis(n, pos, v, lo, hi, c);
}

static void reflect_apply(const isk_bounds *b, size_t n, double *x, double *y, double *vx, double *vy)
{
    double left = b->xmin + b->margin, right = b->xmax - b->margin;
    double bottom = b->ymin + b->margin, top = b->ymax - b->margin;
    double c = b->restitution;
    reflect_axis(n, x, vx, (b->sides & ISK_SIDE_LEFT) != 0, (b->sides & ISK_SIDE_RIGHT) != 0, left,
                 right, c);
    reflect_axis(n, y, vy, (b->sides & ISK_SIDE_BOTTOM) != 0, (b->sides & ISK_SIDE_TOP) != 0, bottom,
                 top, c);
}

/* ---- sound reflection at the time of impact (iskra/impact.h) ---- */

/* When a flight on the inside of a wall (f = signed distance, > 0 inside:
 * f(t) = c0 + U D1(t) + a D2(t)) meets it within (0, s], given that it does
 * (its end f_end or its turning point f_turn at t_turn is outside). */
static double hit_time(double c0, double U, double a, double k, double s, double t_turn, int turn_in,
                       double f_turn, double f_end, isk_fl_cache *cache)
{
    if (!(c0 > 0.0)) {
        if (U < 0.0 || (U == 0.0 && a <= 0.0))
            return 0.0; /* on the wall and leaving (or pressed into it) at once */
        /* on the wall moving in: it meets it again after turning back */
        return turn_in && f_end < 0.0 ? isk__fl_root(c0, U, a, k, t_turn, s, cache) : s;
    }
    if (turn_in && f_turn < 0.0)
        return isk__fl_root(c0, U, a, k, 0.0, t_turn, cache);
    return isk__fl_root(c0, U, a, k, 0.0, s, cache);
}

/* Whether the turning point of the flight (P, U, a) may lie outside
 * [lo, hi]: 0 only when it surely lies inside, so that a step whose end
 * is inside needs neither the turning time (a log1p) nor the point (a
 * basis) to know that it hit nothing.  A turning point exists only when U
 * and a have opposite signs (isk__fl_turn), and lies on a's side of P at
 * a distance between U^2 / (2 (|a| + k|U|)) (the deceleration is at most
 * that) and U^2 / (2|a|) (drag only shortens the flight): the first, when
 * it is well above the rounding of P + U D1 + a D2, keeps the computed
 * point off P's other side, and the second plus the same margin bounds it
 * on a's side.  Where either is not clear, the caller computes the point
 * as it always did: the bits are the same either way. */
static int turn_may_leave(double P, double U, double a, double k, double lo, double hi)
{
    if (!(U * a < 0.0))
        return 0; /* no turning point: isk__fl_turn's -1 */
    const double reach = U * U / (2.0 * fabs(a)), least = U * U / (2.0 * (fabs(a) + k * fabs(U)));
    const double margin = 0x1p-30 * (fabs(P) + reach);
    if (!(least > margin))
        return 1;
    return a < 0.0 ? !(P + reach + margin < hi) : !(P - reach - margin > lo);
}

double isk__wall_time(double P, double U, double a, double k, double s, double lo, double hi, int *wall)
{
    double e, d1, d2;
    isk__fl_basis(k, s, &e, &d1, &d2);
    const double end = P + U * d1 + a * d2;
    const double t_turn = isk__fl_turn(U, a, k);
    const int turn_in = t_turn > 0.0 && t_turn < s;
    double p_turn = P;
    if (turn_in) {
        isk__fl_basis(k, t_turn, &e, &d1, &d2);
        p_turn = P + U * d1 + a * d2;
    }
    double tau = INFINITY;
    *wall = 0;
    if (end < lo || (turn_in && p_turn < lo)) {
        tau = hit_time(P - lo, U, a, k, s, t_turn, turn_in, p_turn - lo, end - lo, NULL);
        *wall = -1;
    }
    if (end > hi || (turn_in && p_turn > hi)) {
        const double t = hit_time(hi - P, -U, -a, k, s, t_turn, turn_in, hi - p_turn, hi - end, NULL);
        if (t < tau) {
            tau = t;
            *wall = 1;
        }
    }
    return tau;
}

/* How an axis's flight in the step is known (iskra/impact.h): from the
 * start state (p0, v0), or (start == NULL) from the end state with the
 * constant acceleration a and the integrator's velocity offset delta. */
typedef struct axis_motion {
    const double *p0, *v0;
    double a, delta;
} axis_motion;

/* Restitution 1 without drag: the path from a bounce on a wall repeats
 * from the next bounce on it, `period` later.  Flies the whole periods
 * that fit in the rest s of the step.  Returns 0 when none fits. */
static int skip_periods(double *s, double period)
{
    if (!(period > 0.0 && *s >= period))
        return 0;
    *s -= period * floor(*s / period);
    if (*s < 0.0)
        *s = 0.0; /* rounding: the bounce itself */
    return 1;
}

/* Hops on one wall without drag, from it at speed |U| for the rest s of
 * the step: each lasts 2 |U| / |a|, c times the one before.  Flies the
 * whole ones that fit in s (c = 1: they repeat; c < 1: fewer than all, or
 * the fitting rule would have rested it) in closed form, leaving U and s
 * for the last, partial one.  Returns 0 when there is nothing to skip. */
static int skip_hops(double *U, double *s, double a, double c)
{
    const double T0 = 2.0 * fabs(*U) / fabs(a);
    if (!(T0 > 0.0 && isfinite(T0) && *s > T0))
        return 0;
    double N, span;
    if (c == 1.0) {
        N = floor(*s / T0);
        span = N * T0;
    } else {
        const double q = 1.0 - *s * (1.0 - c) / T0; /* in (0, 1): all of them do not fit */
        if (!(q > 0.0 && c > 0.0))
            return 0;
        N = floor(log(q) / log(c));
        span = T0 * (1.0 - pow(c, N)) / (1.0 - c);
    }
    while (N >= 1.0 && span > *s) { /* rounding: never past the step's end */
        N -= 1.0;
        span = c == 1.0 ? N * T0 : T0 * (1.0 - pow(c, N)) / (1.0 - c);
    }
    if (!(N >= 1.0))
        return 0;
    *U *= c == 1.0 ? 1.0 : pow(c, N);
    *s -= span;
    return 1;
}

/* One axis of one particle whose step ended outside [lo, hi] (a disabled
 * wall is at -inf / +inf): the bounces of iskra/impact.h.  (*pos, *vel) is
 * the integrator's end state, k the drag rate b/m. */
/* What impact_axis did: RESTED_AT_ONCE is the resting contact at the start
 * of the step (the answer rest_memo keeps), BOUNCED anything else. */
enum { BOUNCED, RESTED_AT_ONCE };

static int impact_axis(double *pos, double *vel, const axis_motion *am, size_t i, double k, double h, double lo,
                       double hi, double c, isk_fl_cache *cache)
{
    const double p1 = *pos, v1 = *vel;
    if (!(isfinite(p1) && isfinite(v1)))
        return BOUNCED; /* not finite: the runner removes and counts it */
    double P, U, a, delta;
    if (am->p0) {
        P = am->p0[i];
        if (!(isfinite(P) && isfinite(am->v0[i])))
            return BOUNCED;
        isk__fl_fit(P, am->v0[i], p1, v1, k, h, &U, &a, &delta);
    } else {
        a = am->a;
        delta = am->delta;
        isk__fl_from_end(p1, v1, a, k, h, delta, cache, &P, &U);
        /* A start reconstructed within rounding of a wall is on it (a
         * particle resting on the floor comes back 1e-19 below it). */
        const double tol = 64 * 2.220446049250313e-16 * (fabs(p1) + fabs(U) * h + fabs(a) * h * h);
        if (P < lo && lo - P <= tol)
            P = lo;
        else if (P > hi && P - hi <= tol)
            P = hi;
    }
    if (!(P >= lo && P <= hi) || !(isfinite(U) && isfinite(a) && isfinite(delta))) {
        settle_one(pos, vel, lo, hi, c); /* started outside (born there): no crossing to find */
        return BOUNCED;
    }
    /* A start velocity within rounding of zero is zero: a particle resting
     * on a wall then meets it at once and rests again in a few operations
     * (else its 1e-18 "upward" speed costs a root solve every step). */
    if (fabs(U) <= 64 * 2.220446049250313e-16 * (fabs(v1) + fabs(a) * h))
        U = 0.0;
    /* Resting contact at once: within |a| h^2 / 64 of a wall it is pressed
     * into, no faster than |a| h / 64: whatever hops remain are lower than
     * |a| h^2 / 60 (2.7e-7 m at g = 9.81, h = 1/600), below what the step
     * resolves, so it rests without a root solve.  (With drag and the
     * Euler forms the flight is not exactly theirs: a resting particle
     * comes back with a speed of ~ (b h/m) |a| h and would otherwise make a
     * real hop, with Newton, every step.  A ball in flight is never this
     * slow this close to the floor, whatever the step.)  Only while every
     * further hop fits in the step: the bounds shrink as c nears 1. */
    double near, slow;
    isk__rest_at_once(a, h, c, &near, &slow);
    if (a < 0.0 && P - lo <= near && fabs(U) <= slow) {
        *pos = lo;
        *vel = delta;
        return RESTED_AT_ONCE;
    }
    if (a > 0.0 && hi - P <= near && fabs(U) <= slow) {
        *pos = hi;
        *vel = delta;
        return RESTED_AT_ONCE;
    }
    double s = h, end = p1, uend = v1 - delta;
    int last = 0, same = 0, skipped = 0;
    /* the rest of the step at the last bounce on each wall, and the time
     * between the last two bounces on the wall `last` */
    double s_lo = NAN, s_hi = NAN, period = NAN;
    for (int n = 0;; n++) {
        if (end >= lo && end <= hi && !turn_may_leave(P, U, a, k, lo, hi))
            break; /* what the tests below would find, without the turning point */
        double t_turn = isk__fl_turn(U, a, k), p_turn = P;
        const int turn_in = t_turn > 0.0 && t_turn < s;
        if (turn_in) {
            double e, d1, d2;
            isk_fl_basis_cached(cache, k, t_turn, &e, &d1, &d2);
            p_turn = P + U * d1 + a * d2;
        }
        const int out_lo = end < lo || (turn_in && p_turn < lo);
        const int out_hi = end > hi || (turn_in && p_turn > hi);
        if (!out_lo && !out_hi)
            break;
        /* Without drag, restitution 1 repeats the path from one bounce on
         * a wall to the next on it (one wall or two): whole periods are
         * skipped.  Hops on one wall that shrink: skip_hops. */
        if (n == ISK_BOUNCE_MAX_REFLECTIONS && k == 0.0 && !skipped &&
            ((c == 1.0 && skip_periods(&s, period)) || (same >= 2 && skip_hops(&U, &s, a, c)))) {
            skipped = 1; /* the whole hops on the wall `last` are flown: the last ones, afresh */
            n = 0;
            double e, d1, d2;
            isk_fl_basis_cached(cache, k, s, &e, &d1, &d2);
            end = P + U * d1 + a * d2;
            uend = U * e + a * d1;
            continue;
        }
        if (n >= ISK_BOUNCE_MAX_REFLECTIONS) {
            if (same >= 2) { /* hopping on one wall ever more often (with drag): it rests there */
                *pos = last < 0 ? lo : hi;
                *vel = delta;
                return BOUNCED;
            }
            settle_one(&end, &uend, lo, hi, c); /* wall to wall, fast: fold the rest */
            break;
        }
        double tau = INFINITY;
        int wall = 0;
        if (out_lo) {
            tau = hit_time(P - lo, U, a, k, s, t_turn, turn_in, p_turn - lo, end - lo, cache);
            wall = -1;
        }
        if (out_hi) {
            double t = hit_time(hi - P, -U, -a, k, s, t_turn, turn_in, hi - p_turn, hi - end, cache);
            if (t < tau) {
                tau = t;
                wall = 1;
            }
        }
        const double W = wall < 0 ? lo : hi, sigma = wall < 0 ? 1.0 : -1.0; /* sigma: into the box */
        double e, d1, d2;
        isk_fl_basis_cached(cache, k, tau, &e, &d1, &d2);
        const double ui = U * e + a * d1;
        P = W;
        U = sigma * ui < 0.0 ? -c * ui : ui; /* only an outward velocity is turned */
        s = s - tau > 0.0 ? s - tau : 0.0;
        /* Pressed back into the wall, with all further hops fitting in the
         * rest of the step (2 V / (|a| (1 - c)) for rebound speed V): rest.
         * A series that ends at the step's very end (a particle already at
         * rest, under semi-implicit Euler's offset) rests too: rounding must
         * not decide it, or it would hop 16 times a step. */
        if (sigma * a < 0.0 &&
            (!(sigma * U > 0.0) || (c < 1.0 && 2.0 * sigma * U <= -sigma * a * (1.0 - c) * s * (1.0 + 1e-9)))) {
            *pos = W;
            *vel = delta;
            return BOUNCED;
        }
        double *s_wall = wall < 0 ? &s_lo : &s_hi;
        period = *s_wall - s; /* NaN at a wall's first bounce */
        *s_wall = s;
        same = wall == last ? same + 1 : 0;
        last = wall;
        isk_fl_basis_cached(cache, k, s, &e, &d1, &d2);
        end = P + U * d1 + a * d2;
        uend = U * e + a * d1;
    }
    if (!(end >= lo && end <= hi)) /* rounding at a wall: it is on it */
        end = end < lo ? lo : hi;
    *pos = end;
    *vel = uend + delta;
    return BOUNCED;
}

/* What the walls of a block need beyond the box: which axes have walls,
 * the flights of both axes, and the drag for the rate k = b / m. */
typedef struct impact_walls {
    isk_wall_box box; /* a missing wall at -inf / +inf */
    int x_on, y_on;
    axis_motion mx, my;
    const double *m;  /* the masses for the drag rate k = b / m; NULL without drag (k = 0 for every mass,
                         and the memo's mass key is 0) */
    double drag, h, c;
    isk_wall_screen_fn screen;
    isk_rest_screen_fn rest_screen;
} impact_walls;

/* One answer of impact_axis for an axis whose flight is known from the end
 * state: then the answer depends only on (p1, v1) and the mass (through
 * k = b/m), everything else being the call's constants, so an input equal
 * bit for bit gets the same answer without the work.  Particles resting on
 * a floor all end their step in the same state (the one their integrator
 * makes of (floor, offset) for their mass), step after step: a scene that
 * has settled is mostly this one input.  Only a resting answer is kept,
 * so the few particles still hopping between them do not evict it. */
typedef struct rest_memo {
    uint64_t p1, v1, m; /* the input's bits (m: 0 without drag, where k = 0 for every mass) */
    double pos, vel;    /* the answer */
    int valid;
} rest_memo;

static uint64_t bits_of(double v)
{
    uint64_t u;
    memcpy(&u, &v, sizeof u);
    return u;
}

/* The memo's mass key of particle i: its mass's bits, or 0 without drag
 * (m NULL), where k = 0 for every mass. */
static uint64_t mass_key(const double *m, size_t i)
{
    return m ? bits_of(m[i]) : 0;
}

/* Whether the memo holds the answer for (p1, v1) of mass key m. */
static int memo_has(const rest_memo *memo, double p1, double v1, uint64_t m)
{
    return memo->valid & (bits_of(p1) == memo->p1) & (bits_of(v1) == memo->v1) & (m == memo->m);
}

/* impact_axis for particle i, through the memo when the flight is known
 * from the end state. */
static void impact_axis_memo(double *pos, double *vel, const axis_motion *am, size_t i, const impact_walls *iw,
                             double lo, double hi, rest_memo *memo, isk_fl_cache *cache)
{
    const double k = iw->m ? iw->drag / iw->m[i] : 0.0;
    if (am->p0) { /* the start state is an input too: nothing to reuse */
        impact_axis(pos, vel, am, i, k, iw->h, lo, hi, iw->c, cache);
        return;
    }
    const double p1 = *pos, v1 = *vel;
    const uint64_t m = mass_key(iw->m, i);
    if (memo_has(memo, p1, v1, m)) {
        *pos = memo->pos;
        *vel = memo->vel;
        return;
    }
    if (impact_axis(pos, vel, am, i, k, iw->h, lo, hi, iw->c, cache) == RESTED_AT_ONCE)
        *memo = (rest_memo){bits_of(p1), bits_of(v1), m, *pos, *vel, 1};
}

/* Below this many particles of a group left to look at on an axis, the
 * resting screen costs more than it saves: a settled scene of one mass
 * leaves one or two hoppers a group after the memo, one of many masses all
 * sixteen. */
#define REST_SCREEN_MIN 4

/* 1 when v has at least k bits set (k small): k - 1 lowest bits cleared
 * leave some.  Without -mpopcnt (the baseline target) __builtin_popcount
 * is a call into libgcc. */
static int has_bits(uint32_t v, int k)
{
    for (int i = 1; i < k && v; i++)
        v &= v - 1;
    return v != 0;
}

/* The index of v's lowest set bit (v != 0). */
static unsigned lowest_bit(uint32_t v)
{
#if defined(__GNUC__)
    return (unsigned)__builtin_ctz(v);
#else
    unsigned j = 0;
    while (!(v >> j & 1u))
        j++;
    return j;
#endif
}

/* The index of v's highest set bit (v != 0). */
static unsigned highest_bit(uint32_t v)
{
#if defined(__GNUC__)
    return 31u - (unsigned)__builtin_clz(v);
#else
    unsigned j = 31;
    while (!(v >> j & 1u))
        j--;
    return j;
#endif
}

/* The resting screen (rest_screen.h) over a group [o, o + n) for one axis
 * whose flight is known from the end state: the particles of `need` it
 * rests get impact_axis's answer (the last of them goes to the memo);
 * returns those left. */
static uint32_t screen_rests(size_t o, size_t n, double *pos, double *vel, const axis_motion *am,
                             const impact_walls *iw, double lo, double hi, uint32_t need, rest_memo *memo)
{
    if (am->p0 || am->a == 0.0 || !(isfinite(am->a) && isfinite(am->delta)) || !has_bits(need, REST_SCREEN_MIN))
        return need;
    const isk_rest_axis ax = {am->a, am->delta, iw->h, lo, hi, iw->c};
    const double *m = iw->m;
    double rest[ISK_WALL_SCREEN];
    iw->rest_screen(n, pos + o, vel + o, m ? m + o : NULL, iw->drag, &ax, rest);
    uint32_t rested = 0;
    size_t j = 0; /* the particles a fast twin did */
#if ISK__CPU_SSE2
    j = rested_bits_sse2(rest, n, &rested);
#endif
    for (; j < n; j++)
        rested |= (uint32_t)(rest[j] != 0.0) << j;
    rested &= need;
    if (!rested)
        return need;
    /* the last particle rested: its input and answer go to the memo */
    const size_t last = o + highest_bit(rested);
    const double last_p1 = pos[last], last_v1 = vel[last];
    /* the group rewritten: each particle that rests put on its wall (the
     * SSE2 twin two at a time, by selects) */
    const double delta = am->delta;
    double *p = pos + o, *v = vel + o;
    j = 0;
#if ISK__CPU_SSE2
    j = rest_on_walls_sse2(p, v, rest, n, rested, lo, hi, delta);
#endif
    for (; j < n; j++)
        if (rested >> j & 1u) {
            p[j] = rest[j] == 1.0 ? lo : hi;
            v[j] = delta;
        }
    *memo = (rest_memo){bits_of(last_p1), bits_of(last_v1), mass_key(m, last), pos[last], vel[last], 1};
    return need & ~rested;
}

/* Of the particles of [o, o + n) (n <= ISK_WALL_SCREEN) outside on this
 * axis (bit j of `out`, the screen's exact mask: particle o + j), which
 * the memo answers (*hits); returns the others.
 * The memo is asked about every particle only when it answers the first or
 * the last one outside: on a floor of many masses it answers no one, and
 * the resting screen does their work anyway.  It is a cache of
 * impact_axis's answers, so whom it is asked about changes only the time.
 * (Who is outside is found two particles at a time with SSE2: a loop over
 * both axes with the memo tests made gcc spill its masks through the
 * stack at every particle; docs/performance.md, "Where the constants come from".) */
static uint32_t split_by_memo(size_t o, size_t n, const double *pos, const double *vel, const double *m,
                              uint32_t out, const rest_memo *memo, uint32_t *hits)
{
    *hits = 0;
    if (!out || !memo->valid)
        return out;
    const size_t first = o + lowest_bit(out), last = o + highest_bit(out);
    if (!memo_has(memo, pos[first], vel[first], mass_key(m, first)) &&
        !memo_has(memo, pos[last], vel[last], mass_key(m, last)))
        return out;
    uint32_t hit = 0;
    for (size_t j = 0; j < n; j++)
        hit |= (uint32_t)memo_has(memo, pos[o + j], vel[o + j], mass_key(m, o + j)) << j;
    *hits = hit & out;
    return out & ~hit;
}

/* The memo's answer to the particles of `hits`. */
static void apply_memo(size_t o, uint32_t hits, double *pos, double *vel, const rest_memo *memo)
{
    for (uint32_t b = hits; b; b &= b - 1) {
        const size_t i = o + lowest_bit(b);
        pos[i] = memo->pos;
        vel[i] = memo->vel;
    }
}

/* The particles [o, o + n) of a group the screen flagged: each axis of each
 * particle that ended outside gets its bounces (the axes are independent:
 * x's touch x and vx, y's y and vy, so the order between them is free).
 * The screen's masks (out_x, out_y) say who is outside; the memo answers
 * those it can (in a settled scene almost everyone, among a few hoppers),
 * the resting screen takes the rest when there are many (many masses), and
 * impact_axis whatever is left, one by one. */
static void impact_group(size_t o, size_t n, double *restrict x, double *restrict y, double *restrict vx,
                         double *restrict vy, const impact_walls *iw, rest_memo memo[2], uint32_t out_x,
                         uint32_t out_y)
{
    const isk_wall_box *w = &iw->box;
    const double *m = iw->m;
    uint32_t need_x = 0, need_y = 0, hit_x = 0, hit_y = 0; /* bit j: particle o + j, n <= ISK_WALL_SCREEN */
    if (iw->x_on)
        need_x = split_by_memo(o, n, x, vx, m, out_x, &memo[0], &hit_x);
    if (iw->y_on)
        need_y = split_by_memo(o, n, y, vy, m, out_y, &memo[1], &hit_y);
    apply_memo(o, hit_x, x, vx, &memo[0]);
    apply_memo(o, hit_y, y, vy, &memo[1]);
    need_x = screen_rests(o, n, x, vx, &iw->mx, iw, w->left, w->right, need_x, &memo[0]);
    need_y = screen_rests(o, n, y, vy, &iw->my, iw, w->bottom, w->top, need_y, &memo[1]);
    isk_fl_cache cache; /* the group's basis values (flight.h) */
    isk_fl_cache_clear(&cache);
    for (uint32_t b = need_x | need_y; b; b &= b - 1) {
        const unsigned j = lowest_bit(b);
        const size_t i = o + j;
        if (need_x >> j & 1u)
            impact_axis_memo(&x[i], &vx[i], &iw->mx, i, iw, w->left, w->right, &memo[0], &cache);
        if (need_y >> j & 1u)
            impact_axis_memo(&y[i], &vy[i], &iw->my, i, iw, w->bottom, w->top, &memo[1], &cache);
    }
}

/* One screening pass over both axes, then the particles of the flagged
 * groups. */
static void impact_block(size_t n, double *restrict x, double *restrict y, double *restrict vx, double *restrict vy,
                         const impact_walls *iw)
{
    rest_memo memo[2] = {{0}}; /* per axis */
    for (size_t o = 0; o < n; o += ISK_WALL_SCREEN_SPAN) {
        const size_t span = n - o < ISK_WALL_SCREEN_SPAN ? n - o : ISK_WALL_SCREEN_SPAN;
        isk_wall_outside out;
        const uint64_t flags = iw->screen(span, x + o, y + o, &iw->box, &out);
        for (size_t g = 0; g < ISK_WALL_SCREEN_GROUPS && (flags >> g) != 0; g++)
            if (flags >> g & 1u) {
                const size_t first = o + g * ISK_WALL_SCREEN, rest = n - first;
                impact_group(first, rest < ISK_WALL_SCREEN ? rest : ISK_WALL_SCREEN, x, y, vx, vy, iw, memo,
                             out.x[g], out.y[g]);
            }
    }
}

void isk_bounds_apply_step(const isk_bounds *b, const isk_step_motion *mo, size_t n, double *x, double *y,
                           double *vx, double *vy)
{
    if (!b || !x || !y || !vx || !vy || b->sides == 0)
        return;
    if (b->mode == ISK_BOUNCE_THESIS) {
        thesis_apply(b, n, x, y, vx, vy); /* the thesis's arithmetic, whatever the motion */
        return;
    }
    const int start = mo && mo->x0 && mo->y0 && mo->vx0 && mo->vy0;
    if (!mo || !(mo->h > 0.0) || !isfinite(mo->h) || (mo->drag != 0.0 && !mo->m) ||
        (!start && !(isfinite(mo->ax) && isfinite(mo->ay) && isfinite(mo->offset)))) {
        reflect_apply(b, n, x, y, vx, vy); /* no motion to solve: the end-of-step rule */
        return;
    }
    const unsigned sd = b->sides;
    const impact_walls iw = {
        {sd & ISK_SIDE_LEFT ? b->xmin + b->margin : -INFINITY, sd & ISK_SIDE_RIGHT ? b->xmax - b->margin : INFINITY,
         sd & ISK_SIDE_BOTTOM ? b->ymin + b->margin : -INFINITY, sd & ISK_SIDE_TOP ? b->ymax - b->margin : INFINITY},
        (sd & (ISK_SIDE_LEFT | ISK_SIDE_RIGHT)) != 0,
        (sd & (ISK_SIDE_BOTTOM | ISK_SIDE_TOP)) != 0,
        {start ? mo->x0 : NULL, start ? mo->vx0 : NULL, mo->ax, mo->offset * mo->ax * mo->h},
        {start ? mo->y0 : NULL, start ? mo->vy0 : NULL, mo->ay, mo->offset * mo->ay * mo->h},
        mo->drag > 0.0 ? mo->m : NULL,
        mo->drag > 0.0 ? mo->drag : 0.0,
        mo->h,
        b->restitution,
        isk__wall_screen_pick(),
        isk__rest_screen_pick(),
    };
    impact_block(n, x, y, vx, vy, &iw);
}

void isk_bounds_apply_arrays(const isk_bounds *b, size_t n, double *x, double *y, double *vx, double *vy)
{
    if (!b || !x || !y || !vx || !vy || b->sides == 0)
        return;
    if (b->mode == ISK_BOUNCE_THESIS)
        thesis_apply(b, n, x, y, vx, vy);
    else
        reflect_apply(b, n, x, y, vx, vy);
}

void isk_bounds_apply(const isk_bounds *b, isk_particles *p, size_t begin, size_t end)
{
    if (!b || !p)
        return;
    if (end > p->count)
        end = p->count;
    if (begin >= end)
        return;
    isk_bounds_apply_arrays(b, end - begin, p->x + begin, p->y + begin, p->vx + begin, p->vy + begin);
}
