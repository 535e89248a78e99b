/* SPDX-License-Identifier: MIT */
/* Sine lookup table: error bounds for every size and mode, exact table
 * points, wrap-around, huge and non-finite angles, the generated table. */
#include <criterion/criterion.h>
#include <criterion/logging.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "iskra/rng.h"
#include "iskra/sinlut.h"

#define PI 3.14159265358979323846

static const isk_sinlut_mode MODES[3] = {ISK_SINLUT_FLOOR, ISK_SINLUT_ROUND, ISK_SINLUT_LERP};
static const char *MODE_NAME[3] = {"floor", "round", "lerp"};

/* Rounding slack on top of the mathematical bound (see iskra/sinlut.h):
 *   |theta| * 2^-52  forming t = theta * fl(n/2pi): two roundings of 2^-53
 *                    relative each, and sin is 1-Lipschitz;
 *   2^-51            table entry (0.5 ulp <= 2^-54), the lerp's subtract,
 *                    multiply and add (each <= 2^-53 on values <= 1 or on
 *                    much smaller ones), and libm's own sin() (< 1 ulp). */
static double slack(double theta)
{
    return fabs(theta) * 0x1p-52 + 0x1p-51;
}

static double lookup(const isk_sinlut *l, int mode, double th)
{
    switch (mode) {
    case 0: return isk_sinlut_floor(l, th);
    case 1: return isk_sinlut_round(l, th);
    default: return isk_sinlut_lerp(l, th);
    }
}

/* A dense angle sample: uniform near zero, log-spread magnitudes up to 1e6
 * with both signs, and angles just either side of table points of every n
 * (where floor/round are at their worst). */
static size_t make_angles(double **out)
{
    const size_t n_uniform = 120000, n_log = 120000, per_n = 4000;
    size_t cap = n_uniform + n_log + 13 * per_n, k = 0;
    double *a = malloc(cap * sizeof *a);
    cr_assert_not_null(a);
    isk_rng r;
    isk_rng_seed(&r, 20240611);
    for (size_t i = 0; i < n_uniform; i++)
        a[k++] = isk_rng_range(&r, -20.0, 20.0);
    for (size_t i = 0; i < n_log; i++) {
        double m = pow(10.0, isk_rng_range(&r, -3.0, 6.0));
        a[k++] = (isk_rng_uniform(&r) < 0.5) ? -m : m;
    }
    for (int lg = 4; lg <= 16; lg++) {
        double step = 2.0 * PI / (double)(1 << lg);
        for (size_t i = 0; i < per_n; i++) {
            double node = floor(isk_rng_range(&r, -1e5, 1e5)) * step;
            double eps = step * pow(10.0, isk_rng_range(&r, -12.0, 0.0));
            a[k++] = node + ((i & 1u) ? eps : -eps);
        }
    }
    *out = a;
    return k;
}

Test(sinlut, error_bound_every_size_and_mode)
{
    double *th;
    size_t m = make_angles(&th);
    double *ref = malloc(m * sizeof *ref);
    cr_assert_not_null(ref);
    for (size_t i = 0; i < m; i++)
        ref[i] = sin(th[i]);

    for (int lg = 4; lg <= 16; lg++) {
        int n = 1 << lg;
        isk_sinlut l;
        cr_assert_eq(isk_sinlut_init(&l, n), ISK_OK);
        for (int mode = 0; mode < 3; mode++) {
            double bound = isk_sinlut_bound(n, MODES[mode]);
            double worst = 0.0, worst_ratio = 0.0;
            for (size_t i = 0; i < m; i++) {
                double e = fabs(lookup(&l, mode, th[i]) - ref[i]);
                if (!(e <= bound + slack(th[i])))
                    cr_assert_fail("n=%d %s theta=%.17g: error %.3g > bound %.3g + slack %.3g", n,
                             MODE_NAME[mode], th[i], e, bound, slack(th[i]));
                if (e > worst)
                    worst = e;
                if (e / bound > worst_ratio)
                    worst_ratio = e / bound;
            }
            cr_log_info("n=%5d %-5s max error %.4e  bound %.4e  ratio %.4f", n, MODE_NAME[mode], worst,
                        bound, worst_ratio);
        }
    }
    free(ref);
    free(th);
}

/* The fire thesis digest's numbers: N=4096 floor within 2pi/N on
 * [-1e4, 1e4]; the particle-engine digest's N=1024 bounds. */
Test(sinlut, thesis_bounds)
{
    isk_sinlut l4096, l1024;
    cr_assert_eq(isk_sinlut_init(&l4096, 4096), ISK_OK);
    cr_assert_eq(isk_sinlut_init(&l1024, 1024), ISK_OK);
    double e4096 = 0, ef = 0, er = 0, el = 0;
    for (int i = 0; i <= 400000; i++) {
        double th = -1e4 + 2e4 * i / 400000.0 + 1e-7 * (i % 7);
        double s = sin(th);
        e4096 = fmax(e4096, fabs(isk_sinlut_floor(&l4096, th) - s));
        ef = fmax(ef, fabs(isk_sinlut_floor(&l1024, th) - s));
        er = fmax(er, fabs(isk_sinlut_round(&l1024, th) - s));
        el = fmax(el, fabs(isk_sinlut_lerp(&l1024, th) - s));
    }
    cr_expect_leq(e4096, 0.00154);
    cr_expect_leq(ef, 6.14e-3);
    cr_expect_leq(er, 3.07e-3);
    cr_expect_leq(el, 4.71e-6);
    /* The bounds are tight: a dense sample comes close to them. */
    cr_expect_geq(e4096, 0.0015);
    cr_expect_geq(el, 4.6e-6);
}

Test(sinlut, init_validates)
{
    isk_sinlut l;
    int bad[] = {0, 1, 8, 15, 17, 100, 4095, 131072, -16, -65536};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        cr_expect_eq(isk_sinlut_init(&l, bad[i]), ISK_ERR_SIZE, "n=%d", bad[i]);
    cr_expect_eq(isk_sinlut_init(NULL, 64), ISK_ERR_NULL);
    double buf[65];
    cr_expect_eq(isk_sinlut_init_copy(&l, 64, buf, 64), ISK_ERR_SIZE);
    cr_expect_eq(isk_sinlut_init_copy(&l, 64, NULL, 65), ISK_ERR_NULL);
    cr_expect_eq(isk_sinlut_init_copy(&l, 64, buf, 65), ISK_OK);
    cr_expect_eq(isk_sinlut_bound(100, ISK_SINLUT_LERP), 0.0);
}

/* The smallest angle whose t = theta*scale is >= k; returns 1 when t == k
 * exactly (not every integer k is reachable once theta's ulp times scale
 * exceeds k's ulp). */
static int angle_at(const isk_sinlut *l, double k, double *out)
{
    double th = k / l->scale;
    while (th * l->scale < k)
        th = nextafter(th, INFINITY);
    while (nextafter(th, -INFINITY) * l->scale >= k)
        th = nextafter(th, -INFINITY);
    *out = th;
    return th * l->scale == k;
}

Test(sinlut, exact_at_table_points_and_periodic)
{
    int exact = 0, inexact = 0;
    for (int lg = 4; lg <= 16; lg++) {
        int n = 1 << lg;
        isk_sinlut l;
        cr_assert_eq(isk_sinlut_init(&l, n), ISK_OK);
        int step = n >= 4096 ? 7 : 1;
        for (int i = 0; i < n; i += step) {
            double want = isk_sinlut_table[(size_t)i * (size_t)(65536 / n)];
            /* the point itself, one and 1000 periods on, and the negative
             * angle that lands on the same entry */
            double ks[4] = {i, i + (double)n, i + 1000.0 * n, i - 3.0 * n};
            for (int j = 0; j < 4; j++) {
                double th;
                int hit = angle_at(&l, ks[j], &th);
                /* floor always selects entry k; round too, since the fraction
                 * is at most one step of theta's grid (< 0.5) */
                cr_assert_eq(isk_sinlut_floor(&l, th), want, "n=%d i=%d k=%g", n, i, ks[j]);
                cr_assert_eq(isk_sinlut_round(&l, th), want, "n=%d i=%d k=%g", n, i, ks[j]);
                if (hit) {
                    cr_assert_eq(isk_sinlut_lerp(&l, th), want, "n=%d i=%d k=%g", n, i, ks[j]);
                    exact++;
                } else {
                    inexact++;
                }
            }
        }
    }
    cr_log_info("table points: %d hit exactly, %d only from above", exact, inexact);
    cr_expect_gt(exact, 3 * inexact);
}

Test(sinlut, wrap_within_bound)
{
    isk_rng r;
    isk_rng_seed(&r, 7);
    for (int lg = 4; lg <= 16; lg += 2) {
        int n = 1 << lg;
        isk_sinlut l;
        cr_assert_eq(isk_sinlut_init(&l, n), ISK_OK);
        for (int mode = 0; mode < 3; mode++) {
            double bound = isk_sinlut_bound(n, MODES[mode]);
            for (int i = 0; i < 20000; i++) {
                double th = isk_rng_range(&r, -10.0, 10.0);
                double k = floor(isk_rng_range(&r, -150000.0, 150000.0)); /* |th2| < 1e6 */
                double th2 = th + 2.0 * PI * k;
                double d = fabs(lookup(&l, mode, th) - lookup(&l, mode, th2));
                /* both sides within bound of sin; sin(th2) differs from sin(th)
                 * only by th2's rounding, covered by slack(th2) */
                cr_assert_leq(d, 2.0 * bound + slack(th) + 2.0 * slack(th2), "n=%d %s th=%g k=%g", n,
                              MODE_NAME[mode], th, k);
            }
        }
    }
}

Test(sinlut, nonfinite_and_huge)
{
    isk_sinlut l;
    cr_assert_eq(isk_sinlut_init(&l, 65536), ISK_OK);
    double nf[3] = {NAN, INFINITY, -INFINITY};
    for (int i = 0; i < 3; i++)
        for (int mode = 0; mode < 3; mode++) {
            cr_expect(isnan(lookup(&l, mode, nf[i])));
            cr_expect(isnan(isk_sinlut_cos_lerp(&l, nf[i])));
        }
    /* Huge angles: no undefined conversion (UBSan would stop us), a value in
     * [-1, 1], and within bound of sin(fmod(theta, fl(2 pi))), the documented
     * reduction. */
    double huge[] = {4.4e14, 4.5e14, 1e15, -1e15, 1e20, -3e100, 1e300, -1e300, DBL_MAX, -DBL_MAX, 0x1p62, 0x1p63};
    for (size_t i = 0; i < sizeof huge / sizeof huge[0]; i++)
        for (int mode = 0; mode < 3; mode++) {
            double v = lookup(&l, mode, huge[i]);
            cr_expect(v >= -1.0 && v <= 1.0, "theta=%g gives %g", huge[i], v);
            if (fabs(huge[i] * l.scale) >= 0x1p62) {
                double red = fmod(huge[i], 2.0 * PI);
                cr_expect_leq(fabs(v - sin(red)), isk_sinlut_bound(65536, MODES[mode]) + slack(red));
            }
        }
    /* Tiny and signed zero. */
    cr_expect_eq(isk_sinlut_lerp(&l, 0.0), 0.0);
    cr_expect_eq(isk_sinlut_lerp(&l, -0.0), 0.0);
    cr_expect_leq(fabs(isk_sinlut_lerp(&l, -1e-300)), 1e-300);
    cr_expect_leq(fabs(isk_sinlut_lerp(&l, DBL_TRUE_MIN)), DBL_TRUE_MIN);
}

/* pi*j/32768 as x_hi + x_lo (about 100 bits) for 0 <= j <= 16384: pi's top
 * 27 bits times j are exact, and so is the next part. */
static void octant_angle(int j, double *hi, double *lo)
{
    const double pa = 0x1.921fb5p+1;                   /* 25 bits */
    const double pb = 0x1.921fb54442d18p+1 - pa;       /* the rest of fl(pi), 28 bits */
    const double pc = 0x1.1a62633145c07p-53;           /* pi - fl(pi) */
    double a = pa * j, b = pb * j;                      /* exact: <= 42 bits each */
    double s = a + b;
    double e = b - (s - a);                             /* exact: |a| >= |b| */
    *hi = s / 32768.0;
    *lo = (e + pc * j) / 32768.0;
}

/* The generated table equals sin() within 1 ulp.  The argument 2 pi i/65536
 * is folded into the first octant (pi j/32768 with j <= 8192, using sin or
 * cos) and carried as x_hi + x_lo, so the reference is
 * sin(x_hi) + cos(x_hi) x_lo: libm's error plus a term far below an ulp
 * (evaluating sin at the double x_hi alone would be off by up to 2 ulps
 * where the argument sits in a higher binade than the result). */
Test(sinlut, table_matches_libm)
{
    const double *t = isk_sinlut_table;
    cr_assert_eq(t[0], 0.0);
    cr_assert_eq(t[16384], 1.0);
    cr_assert_eq(t[32768], 0.0);
    cr_assert_eq(t[49152], -1.0);
    cr_assert_eq(t[65536], 0.0);
    int off_by_one = 0;
    for (int i = 0; i <= 65536; i++) {
        int q = i % 32768; /* sin(pi + x) = -sin(x) */
        double sign = (i % 65536) >= 32768 ? -1.0 : 1.0;
        int j = q <= 16384 ? q : 32768 - q; /* sin(pi - x) = sin(x) */
        double hi, lo, ref;
        if (j <= 8192) {
            octant_angle(j, &hi, &lo);
            ref = sin(hi) + cos(hi) * lo;
        } else {
            octant_angle(16384 - j, &hi, &lo);
            ref = cos(hi) - sin(hi) * lo;
        }
        ref *= sign;
        if (ref == 0.0)
            ref = 0.0; /* no -0 */
        double ulp = nextafter(fabs(ref), INFINITY) - fabs(ref);
        cr_assert_leq(fabs(t[i] - ref), ulp, "entry %d: %a vs sin %a", i, t[i], ref);
        off_by_one += (t[i] != ref);
        /* exact symmetries of the generated table */
        cr_assert_eq(t[i], -t[(65536 - i) % 65536] + 0.0, "odd symmetry at %d", i);
    }
    /* The one-ulp differences are the reference's own: sin(x_hi) is rounded
     * before the correction is added (the generator proves the table
     * correctly rounded against 113-bit sinq; see tools/gen_sinlut.c). */
    cr_log_info("table vs libm sin: %d of 65537 entries differ by one ulp", off_by_one);

    /* And against sinl on a long double argument (64-bit precision where the
     * platform has it): within 1 ulp, absolute error near the zeros. */
    const long double pi_l = 3.141592653589793238462643383279502884L;
    for (int i = 0; i <= 65536; i++) {
        long double x = (long double)i * (pi_l / 32768.0L);
        double r = (double)sinl(x);
        double ulp = nextafter(fabs(t[i]), INFINITY) - fabs(t[i]);
        double arg = (double)(fabsl(x) * LDBL_EPSILON);
        cr_assert_leq(fabs(r - t[i]), fmax(ulp, arg), "entry %d", i);
    }
}

Test(sinlut, copy_cos_and_eval_agree)
{
    isk_rng r;
    isk_rng_seed(&r, 99);
    static double buf[4097];
    for (int lg = 4; lg <= 12; lg++) {
        int n = 1 << lg;
        isk_sinlut a, b;
        cr_assert_eq(isk_sinlut_init(&a, n), ISK_OK);
        cr_assert_eq(isk_sinlut_init_copy(&b, n, buf, 4097), ISK_OK);
        for (int i = 0; i < 5000; i++) {
            double th = isk_rng_range(&r, -1e3, 1e3);
            for (int mode = 0; mode < 3; mode++) {
                double x = lookup(&a, mode, th);
                cr_assert_eq(x, lookup(&b, mode, th));
                cr_assert_eq(x, isk_sinlut_eval(&a, MODES[mode], th));
            }
            double c = cos(th);
            cr_assert_leq(fabs(isk_sinlut_cos_floor(&a, th) - c), isk_sinlut_bound(n, ISK_SINLUT_FLOOR) + slack(th));
            cr_assert_leq(fabs(isk_sinlut_cos_round(&a, th) - c), isk_sinlut_bound(n, ISK_SINLUT_ROUND) + slack(th));
            cr_assert_leq(fabs(isk_sinlut_cos_lerp(&a, th) - c), isk_sinlut_bound(n, ISK_SINLUT_LERP) + slack(th));
        }
    }
}
