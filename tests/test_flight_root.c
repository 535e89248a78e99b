/* SPDX-License-Identifier: MIT */
/* The hit-time solver of the bounces at the time of impact (src/sim/flight.h's
 * isk__fl_root) against a long-double bisection of the same flight: on
 * random drag flights of the sizes a step has, and on the flights where
 * Newton found the root exactly and the old loop then bisected away from
 * it for ~25 steps, the root it returns is within a few ulps of the
 * reference (its early exits, on f == 0 and on a step within rounding, do
 * not cost accuracy); and the flight's basis e, D1, D2 against long
 * double (the series range within 2 ulps). */
#include <criterion/criterion.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "sim/flight.h"

/* p(t) - wall for the flight (c0, U, a, k): c0 + U (1 - e^-kt)/k + a (kt + e^-kt - 1)/k^2. */
static long double f_ref(long double c0, long double U, long double a, long double k, long double t)
{
    const long double em = expm1l(-k * t);
    return c0 - U * em / k + a * (k * t + em) / (k * k);
}

/* The root in [t0, t1] by bisection in long double (f(t0) >= 0 > f(t1)). */
static double root_ref(double c0, double U, double a, double k, double t0, double t1)
{
    long double lo = t0, hi = t1;
    for (int i = 0; i < 200 && hi - lo > 0; i++) {
        const long double mid = 0.5L * (lo + hi);
        if (mid == lo || mid == hi)
            break;
        if (f_ref(c0, U, a, k, mid) >= 0)
            lo = mid;
        else
            hi = mid;
    }
    return (double)(0.5L * (lo + hi));
}

static void check(double c0, double U, double a, double k, double t0, double t1, const char *what)
{
    const double t = isk__fl_root(c0, U, a, k, t0, t1, NULL), want = root_ref(c0, U, a, k, t0, t1);
    cr_assert(t >= t0 && t <= t1, "%s: %a outside [%a, %a]", what, t, t0, t1);
    isk_fl_cache cache;
    isk_fl_cache_clear(&cache); /* through the cache, seeded with an end's basis as bounds.c does: the same bits */
    double e, d1, d2;
    isk_fl_basis_cached(&cache, k, t1, &e, &d1, &d2);
    const double tc = isk__fl_root(c0, U, a, k, t0, t1, &cache);
    cr_assert(memcmp(&tc, &t, sizeof t) == 0, "%s: %a through the cache, %a without", what, tc, t);
    /* f's three terms round to ~1e-19 of a millisecond's flight: the root
     * is known to a few ulps of t, no better */
    cr_assert(fabs(t - want) <= 8 * 2.220446049250313e-16 * want, "%s: %.17g, reference %.17g (%g ulps)", what, t,
              want, fabs(t - want) / (2.220446049250313e-16 * want));
}

Test(flight_root, exact_roots_found_on_the_way)
{
    /* from bench_walls' box (g = 9.81, drag 0.47 / m, dt = 1/600): Newton's
     * second or third step lands on f == 0 */
    check(0x1.21b8a704a0b4fp-9, -0x1.58b3a7ddea8e6p+1, -0x1.39eb851eb851fp+3, 0x1.0464e18876fdep-2, 0.0,
          0x1.b4e81b4e81b4fp-10, "floor, falling");
    check(0x1.9dc7abf8448p-8, -0x1.30da99c502c94p+2, 0x1.39eb851eb851fp+3, 0x1.d53b27b410bbp-2, 0.0,
          0x1.b4e81b4e81b4fp-10, "ceiling, rising");
    check(0x1.902195d4288p-8, -0x1.f1b19bb916b0ap+1, -0x0p+0, 0x1.9a62e4bff7882p-2, 0.0, 0x1.b4e81b4e81b4fp-10,
          "side wall, no acceleration");
}

Test(flight_root, random_drag_flights)
{
    uint64_t s = 0x9e3779b97f4a7c15u;
    int done = 0;
    for (int i = 0; i < 20000; i++) {
        double r[5];
        for (int j = 0; j < 5; j++) {
            s ^= s << 13, s ^= s >> 7, s ^= s << 17;
            r[j] = (double)(s >> 11) / 9007199254740992.0;
        }
        const double h = r[0] < 0.5 ? 1.0 / 600 : 1.0 / 60;
        const double U = -(0.1 + 20 * r[1]), a = -40 + 80 * r[2], k = 0.01 + 5 * r[3];
        const double c0 = r[4] * -U * h; /* a start that reaches the wall within the step, or nearly */
        if (!(f_ref(c0, U, a, k, h) < 0))
            continue; /* no crossing in the step */
        char what[64];
        snprintf(what, sizeof what, "flight %d", i);
        check(c0, U, a, k, 0.0, h, what);
        done++;
    }
    cr_assert_gt(done, 5000, "only %d flights crossed", done);
}

/* e = e^-kt, D1 = (1 - e)/k and D2 = (t - D1)/k within 2 ulps of long
 * double on both sides of the series' range (k t < 1/32: no expm1), and
 * continuous across its edge. */
Test(flight_root, basis_against_long_double)
{
    uint64_t s = 12345;
    for (int i = 0; i < 100000; i++) {
        s ^= s << 13, s ^= s >> 7, s ^= s << 17;
        const double u = (double)(s >> 11) / 9007199254740992.0;
        const double k = i % 2 ? 0.3 : 0.01 + 10 * u, t = i % 2 ? u * 0.25 : (1.0 / 60) * (0.01 + u);
        double e, d1, d2;
        isk__fl_basis(k, t, &e, &d1, &d2);
        const long double K = k, T = t, em = expm1l(-K * T), E = 1 + em, D1 = -em / K;
        long double phi2 = 0, term = 0.5L; /* (z - 1 + e^-z) / z^2 by its series: no cancellation */
        for (int j = 0; j < 40; j++) {
            phi2 += term;
            term *= -K * T / (j + 3);
        }
        const long double D2 = phi2 * T * T;
        const long double ulp = 2.220446049250313e-16L;
        /* beyond the series, D2 = (z + expm1(-z)) / z^2 cancels two bits or so near z = 0.1 */
        const long double d2_ulps = k * t < 0.03125 ? 2 : 8;
        cr_assert(fabsl(e - E) <= 2 * ulp * E && fabsl(d1 - D1) <= 2 * ulp * D1 && fabsl(d2 - D2) <= d2_ulps * ulp * D2,
                  "k %a t %a (z %g): e %g d1 %g d2 %g ulps off", k, t, k * t, (double)(fabsl(e - E) / (ulp * E)),
                  (double)(fabsl(d1 - D1) / (ulp * D1)), (double)(fabsl(d2 - D2) / (ulp * D2)));
    }
}
