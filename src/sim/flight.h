/* SPDX-License-Identifier: MIT */
/* src/sim/flight.h — the motion of one particle within one step, for
 * bounces at the time of impact (internal; iskra/impact.h documents the
 * model for users).
 *
 * Per axis, a particle that moved from (p0, v0) to (p1, v1) over the step h
 * under a linear drag k = b/m (0: none) is described by the flight
 *
 *     p(t) = P + U D1(t) + a D2(t),      u(t) = U e(t) + a D1(t)
 *     e(t) = e^{-kt},  D1(t) = (1 - e^{-kt})/k,  D2(t) = (t - D1(t))/k
 *
 * (k = 0: D1 = t, D2 = t^2/2, the parabola).  This is the exact motion
 * under a constant acceleration a and the drag, started at P with velocity
 * U.  isk__fl_fit chooses a from the step's velocity change and U from its
 * displacement, so the flight passes through both positions; for gravity,
 * wind and drag that is the exact motion with every integrator whose
 * positions lie on it (Verlet, RK4, exact drag: then U = v0), and for the
 * Euler forms it is the parabola their positions lie on, whose velocity is
 * the stored one shifted by -+a h/2 (`delta`, the integrator's own offset,
 * kept across a bounce).  With other forces (potentials) it is the
 * second-order approximation the step's two end states define.
 *
 * Nothing here allocates or branches on scene-level choices; everything
 * runs only for the few particles that hit something in a step. */
#ifndef ISKRA_SIM_FLIGHT_H
#define ISKRA_SIM_FLIGHT_H

/* e(t), D1(t), D2(t) for drag k >= 0 and time t >= 0. */
void isk__fl_basis(double k, double t, double *e, double *d1, double *d2);

/* isk__fl_basis for 0 < z = k t < ISK_FL_SERIES_MAX: every ordinary step
 * (k t = 0.005 for b/m = 0.3 over 1/60 s).  The series phi1 = (1 - e^-z)/z
 * and phi2 = (z - 1 + e^-z)/z^2, eight terms each (the first left out is
 * below 3e-18 of the sum), in Estrin's form (pairs, then pairs of pairs: a
 * short dependency chain, since the root solve's steps wait for each
 * other), no expm1 and no division: a bounce asks for this eight times
 * (five through isk_fl_cache), and the series costs about half of expm1
 * and its divisions (docs/performance.md, "Where the constants come
 * from").  Inline,
 * and branch-free, so the walls' resting screen (rest_screen.h) runs it
 * on vector lanes with the same bits. */
#define ISK_FL_SERIES_MAX 0.03125
static inline void isk_fl_basis_series(double z, double t, double *e, double *d1, double *d2)
{
    /* 1 / i! */
    const double c1 = 1.0, c2 = 1.0 / 2, c3 = 1.0 / 6, c4 = 1.0 / 24, c5 = 1.0 / 120, c6 = 1.0 / 720,
                 c7 = 1.0 / 5040, c8 = 1.0 / 40320, c9 = 1.0 / 362880;
    const double w = -z, w2 = w * w, w4 = w2 * w2;
    const double p1 = ((c1 + c2 * w) + (c3 + c4 * w) * w2) + ((c5 + c6 * w) + (c7 + c8 * w) * w2) * w4;
    const double p2 = ((c2 + c3 * w) + (c4 + c5 * w) * w2) + ((c6 + c7 * w) + (c8 + c9 * w) * w2) * w4;
    *e = 1.0 - z * p1;
    *d1 = t * p1;
    *d2 = p2 * (t * t);
}

/* (h - 1 + e^-h)/h^2 for 0 <= h < 0.1 by its Taylor series (the exact-drag
 * update uses it too: one series, one place). */
double isk__fl_phi2_series(double h);

/* The flight of one axis through (p0, v0) -> (p1, v1) over h with drag k:
 * its start velocity U, acceleration a, and the integrator's velocity
 * offset delta = v1 - u(h).  Without acceleration or drag (v1 == v0, k = 0)
 * the flight is the straight line at v1 itself (U = v1, delta = 0). */
void isk__fl_fit(double p0, double v0, double p1, double v1, double k, double h, double *U, double *a,
                double *delta);

/* isk__fl_basis, inline but for the expm1 branch (k t >= ISK_FL_SERIES_MAX):
 * the same branches and operations, so the same bits.  The walls' bounce
 * solve asks for a basis ten times a hopping particle: as calls, every
 * double it keeps live was spilled around each (the SysV ABI saves no xmm
 * register). */
void isk__fl_basis_slow(double k, double t, double *e, double *d1, double *d2);
static inline void isk_fl_basis_inline(double k, double t, double *e, double *d1, double *d2)
{
    if (!(k > 0.0) || t == 0.0) {
        *e = 1.0;
        *d1 = t;
        *d2 = 0.5 * t * t;
        return;
    }
    const double z = k * t;
    if (z < ISK_FL_SERIES_MAX)
        isk_fl_basis_series(z, t, e, d1, d2);
    else
        isk__fl_basis_slow(k, t, e, d1, d2);
}

/* The last few isk__fl_basis(k, t) asked for, for the walls of one group of
 * particles: a bounce asks for the same time more than once (the turning
 * point, then the root solve's bracket end there; the rest of the step
 * after a hit, for the end state and then as the next root solve's
 * bracket end).  Beside them, pinned, the basis over the whole step
 * (isk__fl_from_end's): the particles of a group mostly share one mass, so
 * their flights over the step need one basis, not one each, and the four
 * times each bounce brings would otherwise evict it before the next
 * particle.  t = 0 and the root solve's own iterates are never looked up
 * nor kept: the first is free, the others never asked for again.  A pure
 * function, so the values are the ones a new call would give.  Empty:
 * isk_fl_cache_clear (the arrays need no clearing). */
enum { ISK_FL_CACHE = 4 };
typedef struct isk_fl_cache {
    double k[ISK_FL_CACHE], t[ISK_FL_CACHE], e[ISK_FL_CACHE], d1[ISK_FL_CACHE], d2[ISK_FL_CACHE];
    int n, next;
    double step_k, step_t, step_e, step_d1, step_d2; /* the pinned entry, when step_set */
    int step_set;
} isk_fl_cache;

static inline void isk_fl_cache_clear(isk_fl_cache *c)
{
    c->n = c->next = 0;
    c->step_set = 0;
}

/* Whether the pinned entry holds (k, t). */
static inline int isk_fl_cache_step_is(const isk_fl_cache *c, double k, double t)
{
    return c->step_set && c->step_t == t && c->step_k == k;
}

/* isk__fl_basis through the cache (NULL: none), kept in the ring.
 * Inline: a bounce asks seven or eight times, and as calls the lookups
 * cost a tenth of a settled floor's update. */
static inline void isk_fl_basis_cached(isk_fl_cache *c, double k, double t, double *e, double *d1, double *d2)
{
    if (!c || t == 0.0) {
        isk_fl_basis_inline(k, t, e, d1, d2);
        return;
    }
    if (isk_fl_cache_step_is(c, k, t)) {
        *e = c->step_e;
        *d1 = c->step_d1;
        *d2 = c->step_d2;
        return;
    }
    for (int i = 0; i < c->n; i++)
        if (c->t[i] == t && c->k[i] == k) {
            *e = c->e[i];
            *d1 = c->d1[i];
            *d2 = c->d2[i];
            return;
        }
    isk_fl_basis_inline(k, t, e, d1, d2);
    const int i = c->next;
    c->k[i] = k;
    c->t[i] = t;
    c->e[i] = *e;
    c->d1[i] = *d1;
    c->d2[i] = *d2;
    c->next = (i + 1) % ISK_FL_CACHE;
    if (c->n < ISK_FL_CACHE)
        c->n++;
}

/* isk__fl_basis through the cache's pinned entry (the step's), which it
 * replaces when (k, t) is another. */
static inline void isk_fl_basis_step(isk_fl_cache *c, double k, double t, double *e, double *d1, double *d2)
{
    if (!c) {
        isk_fl_basis_inline(k, t, e, d1, d2);
        return;
    }
    if (!isk_fl_cache_step_is(c, k, t)) {
        isk_fl_basis_inline(k, t, &c->step_e, &c->step_d1, &c->step_d2);
        c->step_k = k;
        c->step_t = t;
        c->step_set = 1;
    }
    *e = c->step_e;
    *d1 = c->step_d1;
    *d2 = c->step_d2;
}

/* The flight of one axis that ends at (p1, v1) after h with acceleration
 * a, drag k and the integrator's velocity offset delta (v1 = u(h) +
 * delta): its start P and start velocity U.  `cache` may be NULL. */
void isk__fl_from_end(double p1, double v1, double a, double k, double h, double delta, isk_fl_cache *cache,
                     double *P, double *U);

/* The time in (0, +inf) at which u(t) = 0 (the flight's turning point), or
 * -1 when it has none (U and a not of opposite signs). */
double isk__fl_turn(double U, double a, double k);

/* A root of f(t) = c0 + U D1(t) + a D2(t) in [t0, t1], given f(t0) >= 0 and
 * f(t1) < 0 (the flight leaves the side where f > 0 in that interval, and f
 * has no other root there).  Exact for k = 0 (the quadratic's stable root),
 * safeguarded Halley iteration for k > 0 (within a few ulps of the root:
 * tests/test_flight_root.c); when rounding has put no sign change in the
 * interval it returns the end where |f| is smaller.  cache may be NULL. */
double isk__fl_root(double c0, double U, double a, double k, double t0, double t1, isk_fl_cache *cache);

#endif
