/* SPDX-License-Identifier: MIT */
/* The motion of one particle within one step (see flight.h). */
#include "sim/flight.h"

#include <math.h>
#include <stddef.h>

double isk__fl_phi2_series(double h)
{
    /* sum_{j>=0} (-h)^j / (j+2)!; 10 terms leave < 1e-18 relative error. */
    static const double inv_fact[10] = {
        1.0 / 2, 1.0 / 6, 1.0 / 24, 1.0 / 120, 1.0 / 720, 1.0 / 5040, 1.0 / 40320,
        1.0 / 362880, 1.0 / 3628800, 1.0 / 39916800,
    };
    double acc = 0.0;
    for (int j = 9; j >= 0; j--)
        acc = inv_fact[j] - h * acc;
    return acc;
}

void isk__fl_basis(double k, double t, double *e, double *d1, double *d2)
{
    isk_fl_basis_inline(k, t, e, d1, d2);
}

void isk__fl_basis_slow(double k, double t, double *e, double *d1, double *d2)
{
    const double z = k * t;
    double em = expm1(-z); /* e^-z - 1, accurate for small z */
    *e = 1.0 + em;
    *d1 = -em / k;
    *d2 = (z < 0.1 ? isk__fl_phi2_series(z) : (z + em) / (z * z)) * (t * t);
}

void isk__fl_fit(double p0, double v0, double p1, double v1, double k, double h, double *U, double *a,
                double *delta)
{
    if (v1 == v0 && !(k > 0.0)) {
        /* No acceleration, no drag: every integrator moves on the straight
         * line at the stored velocity (exactly: a bounce only flips signs). */
        *U = v1;
        *a = 0.0;
        *delta = 0.0;
        return;
    }
    double e, d1, d2;
    isk__fl_basis(k, h, &e, &d1, &d2);
    /* v1 = v0 e + a D1 gives a; p1 = p0 + U D1 + a D2 gives U. */
    double acc = (v1 - v0 * e) / d1;
    double u0 = (p1 - p0 - acc * d2) / d1;
    *a = acc;
    *U = u0;
    *delta = v1 - (u0 * e + acc * d1);
}

void isk__fl_from_end(double p1, double v1, double a, double k, double h, double delta, isk_fl_cache *cache,
                     double *P, double *U)
{
    double e, d1, d2;
    isk_fl_basis_step(cache, k, h, &e, &d1, &d2);
    /* u(h) = U e + a D1 = v1 - delta;  p(h) = P + U D1 + a D2 = p1 */
    double u0 = ((v1 - delta) - a * d1) / e;
    *U = u0;
    *P = p1 - u0 * d1 - a * d2;
}

double isk__fl_turn(double U, double a, double k)
{
    if (!(U * a < 0.0))
        return -1.0;
    if (!(k > 0.0))
        return -U / a;
    /* U e + a (1 - e)/k = 0  <=>  e^{-kt} = a / (a - k U). */
    return log1p(-k * U / a) / k;
}

/* f(t), f'(t) = u(t) and f''(t) = u'(t) = e (a - k U); the basis through
 * the cache c, or (c NULL) computed. */
static double f_at(isk_fl_cache *c, double c0, double U, double a, double k, double t, double *fp, double *fpp)
{
    double e, d1, d2;
    isk_fl_basis_cached(c, k, t, &e, &d1, &d2);
    *fp = U * e + a * d1;
    *fpp = e * (a - k * U);
    return c0 + U * d1 + a * d2;
}

/* The quadratic c0 + U t + (a/2) t^2 = 0: both roots in the stable form
 * (no cancellation), the one inside [t0, t1] (clamped: rounding may put it
 * an ulp outside).  Returns 0 when the formula fails (overflow). */
static int quadratic_root(double c0, double U, double a, double t0, double t1, double *t)
{
    double r;
    if (a == 0.0) {
        if (U == 0.0)
            return 0;
        r = -c0 / U;
    } else {
        double disc = U * U - 2.0 * a * c0;
        if (!isfinite(disc))
            return 0;
        double q = -0.5 * (U + copysign(sqrt(disc > 0.0 ? disc : 0.0), U));
        double r1 = q / (0.5 * a), r2 = q != 0.0 ? c0 / q : r1;
        /* The root nearer the interval (at most one lies inside it). */
        double d1 = r1 < t0 ? t0 - r1 : (r1 > t1 ? r1 - t1 : 0.0);
        double d2 = r2 < t0 ? t0 - r2 : (r2 > t1 ? r2 - t1 : 0.0);
        r = d2 < d1 ? r2 : r1;
    }
    if (!isfinite(r))
        return 0;
    *t = r < t0 ? t0 : (r > t1 ? t1 : r);
    return 1;
}

double isk__fl_root(double c0, double U, double a, double k, double t0, double t1, isk_fl_cache *cache)
{
    if (!(t1 > t0))
        return t0;
    double t;
    if (!(k > 0.0) && quadratic_root(c0, U, a, t0, t1, &t))
        return t;
    double fp, fpp;
    double fa = f_at(cache, c0, U, a, k, t0, &fp, &fpp), fb = f_at(cache, c0, U, a, k, t1, &fp, &fpp);
    if (fa < 0.0)
        return t0;
    if (fb >= 0.0)
        return fabs(fb) < fa ? t1 : t0;
    /* Safeguarded Halley: the bracket [lo, hi] always has f(lo) >= 0 >
     * f(hi); a step that leaves it is replaced by bisection.  f is smooth
     * with a simple root here, so this converges from the root the flight
     * would have without drag (k t is small in every ordinary step: that
     * start is off by about k t / 6 of t), else from the chord's.  Halley's
     * step (f'' costs two operations more than Newton's f') triples the
     * digits: from the quadratic's start one step leaves ~1e-9 of t, and a
     * step of less than 2^-20 of t leaves less than an ulp after it, so the
     * step is taken without evaluating f once more to confirm it.  Two
     * evaluations a root instead of Newton's four. */
    double lo = t0, hi = t1;
    double tq;
    if (quadratic_root(c0, U, a, t0, t1, &tq) && tq > lo && tq < hi)
        t = tq;
    else
        t = lo + (hi - lo) * (fa / (fa - fb)); /* regula falsi start */
    for (int it = 0; it < 200; it++) {
        double f = f_at(NULL, c0, U, a, k, t, &fp, &fpp); /* an iterate: never asked for again */
        if (f == 0.0)
            return t; /* on the root (bisecting on from it cost ~25 more steps) */
        if (f > 0.0)
            lo = t;
        else
            hi = t;
        const double den = 2.0 * fp * fp - f * fpp;
        double tn = den != 0.0 && isfinite(den) ? t - 2.0 * f * fp / den : fp != 0.0 ? t - f / fp : 0.5 * (lo + hi);
        if (tn == t)
            return t;
        if (!(tn > lo && tn < hi)) {
            /* A step of a few ulps out of the bracket is the iteration
             * done, at the rounding of f (the end it crossed is t); a
             * longer one is a bad step, replaced by bisection. */
            if (fabs(tn - t) <= 4.0 * 2.220446049250313e-16 * t)
                return t;
            tn = 0.5 * (lo + hi);
        } else if (fabs(tn - t) <= 0x1p-20 * t) {
            return tn; /* converged (above) */
        }
        if (hi - lo <= 4.0 * 2.220446049250313e-16 * hi)
            return tn;
        t = tn;
    }
    return t;
}
