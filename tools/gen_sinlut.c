/* SPDX-License-Identifier: MIT */
/* gen_sinlut.c — writes src/core/sinlut_table.c, the 65536-entry sine table.
 *
 * Not built by the Makefile: the table is generated once and committed, so
 * the library's sine lookups never depend on the platform's libm.  To
 * regenerate (only needed if the format or size ever changes):
 *
 *     cc -std=c11 -O2 -ffp-contract=off tools/gen_sinlut.c -o /tmp/gen_sinlut -lm
 *     /tmp/gen_sinlut > src/core/sinlut_table.c
 *
 * Optional third cross-check against libquadmath's 113-bit sinq (GCC):
 *     cc -std=c11 -O2 -ffp-contract=off -DGEN_SINLUT_QUADMATH tools/gen_sinlut.c \
 *        -o /tmp/gen_sinlut -lquadmath -lm
 *
 * Entry i is sin(2*pi*i/65536), correctly rounded to the nearest double, for
 * i = 0..65536 (the extra last entry equals entry 0 so linear interpolation
 * never needs to wrap its second index).
 *
 * Method.  By symmetry only the first quadrant q[j] = sin(pi*j/32768),
 * j = 0..16384, is computed; the rest is q mirrored and negated, which is
 * exact.  Each q[j] is evaluated in double-double arithmetic (about 104 bits):
 * the argument y = pi*j/32768 from a two-double pi, then a Taylor series for
 * sin(y) when y <= pi/4, or for cos(pi/2 - y) above (so the series argument
 * never exceeds pi/4 and the terms shrink fast).  The double-double sum
 * hi + lo is rounded to nearest by keeping hi; if hi + lo lies within
 * 2^-96 relative of a rounding midpoint the program refuses to guess and
 * fails (it never happens for this table, but it is what "correctly
 * rounded" needs).
 *
 * Cross-checks, all fatal on failure (messages on stderr):
 *   - every entry against sinl() on a long double argument: must agree
 *     within 1 ulp (the count of entries where sinl's rounding differs is
 *     reported; on x86-64 it is a handful of near-midpoint cases);
 *   - with GEN_SINLUT_QUADMATH, every entry must equal sinq() rounded to
 *     double exactly;
 *   - exact symmetry points: q[0] = 0, q[16384] = 1.
 */
/* No fused multiply-add: it would break the exact-product error terms.
 * -std=c11 (or -ffp-contract=off) does this for GCC; clang reads the pragma. */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#ifdef GEN_SINLUT_QUADMATH
#include <quadmath.h>
#endif

#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "double-double arithmetic needs FLT_EVAL_METHOD == 0 (no x87 excess precision)"
#endif

#define N 65536
#define QUARTER (N / 4)

typedef struct dd { double hi, lo; } dd;

static dd two_sum(double a, double b)
{
    double s = a + b;
    double bb = s - a;
    double e = (a - (s - bb)) + (b - bb);
    return (dd){s, e};
}

static dd quick_two_sum(double a, double b)
{
    double s = a + b;
    return (dd){s, b - (s - a)};
}

/* Dekker's split and exact product (no fma, so no reliance on hardware). */
static void split(double a, double *hi, double *lo)
{
    double t = 134217729.0 * a; /* 2^27 + 1 */
    *hi = t - (t - a);
    *lo = a - *hi;
}

static dd two_prod(double a, double b)
{
    double p = a * b, ah, al, bh, bl;
    split(a, &ah, &al);
    split(b, &bh, &bl);
    double e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    return (dd){p, e};
}

static dd dd_add(dd a, dd b)
{
    dd s = two_sum(a.hi, b.hi);
    dd t = two_sum(a.lo, b.lo);
    s.lo += t.hi;
    s = quick_two_sum(s.hi, s.lo);
    s.lo += t.lo;
    return quick_two_sum(s.hi, s.lo);
}

static dd dd_mul(dd a, dd b)
{
    dd p = two_prod(a.hi, b.hi);
    p.lo += a.hi * b.lo + a.lo * b.hi;
    return quick_two_sum(p.hi, p.lo);
}

static dd dd_div_d(dd a, double b)
{
    double q1 = a.hi / b;
    dd p = two_prod(q1, b);
    dd r = two_sum(a.hi, -p.hi);
    r.lo -= p.lo;
    r.lo += a.lo;
    double q2 = (r.hi + r.lo) / b;
    return quick_two_sum(q1, q2);
}

/* pi = PI_HI + PI_LO to about 107 bits. */
static const double PI_HI = 0x1.921fb54442d18p+1;
static const double PI_LO = 0x1.1a62633145c07p-53;

/* y = pi * j / 32768 in double-double (the division is by a power of two). */
static dd angle(int j)
{
    dd p = two_prod((double)j, PI_HI);
    p = dd_add(p, two_prod((double)j, PI_LO));
    return (dd){ldexp(p.hi, -15), ldexp(p.lo, -15)};
}

/* Taylor series of sin (odd = 1) or cos (odd = 0) for |y| <= pi/4. */
static dd taylor(dd y, int odd)
{
    dd y2 = dd_mul(y, y);
    dd term = odd ? y : (dd){1.0, 0.0};
    dd sum = term;
    for (int k = odd ? 2 : 1; k < 60; k += 2) {
        /* term *= -y^2 / (k (k+1)) */
        term = dd_div_d(dd_mul(term, y2), -(double)k * (double)(k + 1));
        sum = dd_add(sum, term);
        if (fabs(term.hi) < 0x1p-120)
            break;
    }
    return sum;
}

/* Fails when hi + lo is too close to a midpoint between doubles to round. */
static int near_midpoint(dd v)
{
    if (v.lo == 0.0 || v.hi == 0.0)
        return 0;
    double toward = nextafter(v.hi, v.lo > 0 ? INFINITY : -INFINITY);
    double half = (toward - v.hi) / 2.0; /* exact */
    return fabs(v.lo - half) < ldexp(fabs(v.hi), -96);
}

static double q[QUARTER + 1];
static double table[N + 1];

int main(void)
{
    for (int j = 0; j <= QUARTER; j++) {
        dd v = (2 * j <= QUARTER) ? taylor(angle(j), 1) : taylor(angle(QUARTER - j), 0);
        if (near_midpoint(v)) {
            fprintf(stderr, "gen_sinlut: entry %d is too close to a rounding midpoint\n", j);
            return 1;
        }
        q[j] = v.hi + v.lo; /* v is normalised, so this is v.hi: round to nearest */
    }
    if (q[0] != 0.0 || q[QUARTER] != 1.0) {
        fprintf(stderr, "gen_sinlut: symmetry points wrong (%a, %a)\n", q[0], q[QUARTER]);
        return 1;
    }
    for (int j = 0; j <= QUARTER; j++) {
        double s = q[j], m = (s == 0.0) ? 0.0 : -s; /* no negative zeros */
        table[j] = s;
        table[2 * QUARTER - j] = s;
        table[2 * QUARTER + j] = m;
        table[N - j] = (j == 0) ? 0.0 : m;
    }

    /* Cross-check with sinl on a long double argument. */
    const long double pi_l = 3.141592653589793238462643383279502884L;
    int sinl_differs = 0;
    for (int i = 0; i <= N; i++) {
        long double x = (long double)i * (pi_l / 32768.0L);
        double r = (double)sinl(x);
        if (r != table[i]) {
            sinl_differs++;
            double ulp = nextafter(fabs(table[i]), INFINITY) - fabs(table[i]);
            /* Near sin(pi k) sinl also sees its argument's error, |x| * 2^-63 at most. */
            double arg_err = (double)(fabsl(x) * LDBL_EPSILON);
            if (fabs(r - table[i]) > (ulp > arg_err ? ulp : arg_err)) {
                fprintf(stderr, "gen_sinlut: entry %d: table %a, sinl %a\n", i, table[i], r);
                return 1;
            }
        }
    }
#ifdef GEN_SINLUT_QUADMATH
    for (int j = 0; j <= QUARTER; j++) {
        __float128 x = (__float128)j * (M_PIq / 32768.0Q);
        double r = (double)sinq(x);
        if (r != q[j]) {
            fprintf(stderr, "gen_sinlut: entry %d: table %a, sinq %a\n", j, q[j], r);
            return 1;
        }
    }
    fprintf(stderr, "gen_sinlut: all %d quadrant entries equal sinq rounded to double\n", QUARTER + 1);
#endif
    fprintf(stderr, "gen_sinlut: %d entries; sinl rounds differently at %d (all within 1 ulp)\n", N + 1,
            sinl_differs);

    printf("/* SPDX-License-Identifier: MIT */\n"
           "/* sinlut_table.c — GENERATED by tools/gen_sinlut.c; do not edit.\n"
           " * Entry i = sin(2*pi*i/%d) correctly rounded to double, i = 0..%d\n"
           " * (the last entry repeats entry 0).  See tools/gen_sinlut.c to regenerate. */\n"
           "#include \"iskra/sinlut.h\"\n\n"
           "const double isk_sinlut_table[ISK_SINLUT_MAX_N + 1] = {\n",
           N, N);
    for (int i = 0; i <= N; i++) {
        if (i % 4 == 0)
            printf("   ");
        printf(" %a,", table[i]);
        if (i % 4 == 3 || i == N)
            printf("\n");
    }
    printf("};\n");
    return 0;
}
