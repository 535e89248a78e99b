/* SPDX-License-Identifier: MIT */
/* Knob study "ellipse": the spawn ellipse's two samplers (iskra/shape.h),
 * ISK_ELLIPSE_UNIFORM (the unit disc sample scaled: area-uniform) and
 * ISK_ELLIPSE_THESIS (the particle-engine thesis's x = a(2u1 - 1),
 * y = b(2u2 - 1) sqrt(1 - (x/a)^2)), for 10^3 .. 10^6 samples.
 *
 * How far a sample is from the area-uniform density, three ways:
 *   - KS: the Kolmogorov-Smirnov distance of s = (x/a)^2 + (y/b)^2 from
 *     U(0, 1).  For an area-uniform sample s is uniform (the area inside
 *     the scaled ellipse s <= r is r times the whole), so the distance falls
 *     like 0.87/sqrt(n) (the mean of Kolmogorov's distribution,
 *     sqrt(pi/2) ln 2); the thesis sampler's s has the CDF
 *         F(r) = r * integral_0^{pi/2} cos^2 t / sqrt(1 - r sin^2 t) dt
 *     (|x/a| = xi uniform, then s <= r iff |2u2 - 1| <= sqrt((r - xi^2)/(1 - xi^2));
 *     substitute xi = sqrt(r) sin t), so its distance tends to
 *     D = max_r |F(r) - r| > 0, computed here by quadrature.
 *   - tip: the fraction with |x| > 0.9a, against the area-uniform value
 *     (2/pi)(acos 0.9 - 0.9 sqrt(0.19)) = 0.0374 (the thesis's x is uniform,
 *     so its fraction tends to 0.1).
 *   - bins: the largest relative deviation of the count in 128 equal-area
 *     bins (8 rings of equal s-width x 16 equal angles of (x/a, y/b)) from
 *     n/128.  Sampling noise alone gives about 3 sqrt(128/n).
 * Cost: nanoseconds per sample through isk_shape_sample_n (median). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "iskra/rng.h"
#include "iskra/shape.h"
#include "study.h"

#define PI 3.14159265358979323846
enum { NSIZES = 4, NMODES = 2, RINGS = 8, SECTORS = 16 };
static const size_t SIZES[NSIZES] = {1000, 10000, 100000, 1000000};
static const isk_ellipse_mode MODES[NMODES] = {ISK_ELLIPSE_UNIFORM, ISK_ELLIPSE_THESIS};
static const char *const MODE_NAME[NMODES] = {"uniform", "thesis"};
static const double A = 2, B = 1; /* semi-axes (x, y) */

/* The thesis sampler's CDF of s = (x/a)^2 + (y/b)^2, by Simpson's rule on
 * a smooth integrand (r < 1; F(1) = 1). */
static double thesis_cdf(double r)
{
    if (r >= 1)
        return 1;
    enum { K = 256 }; /* even */
    double h = (PI / 2) / K, sum = 0;
    for (int i = 0; i <= K; i++) {
        double t = i * h, c = cos(t), s = sin(t);
        double f = c * c / sqrt(1 - r * s * s);
        sum += f * (i == 0 || i == K ? 1 : (i % 2 ? 4 : 2));
    }
    return r * sum * h / 3;
}

/* The thesis sampler's limiting KS distance: max |F(r) - r| on a fine grid. */
static double thesis_ks_limit(void)
{
    double d = 0;
    for (int i = 1; i < 4000; i++) {
        double r = i / 4000.0;
        d = fmax(d, fabs(thesis_cdf(r) - r));
    }
    return d;
}

/* Kolmogorov's limiting distribution of sqrt(n) D_n:
 * K(x) = 1 - 2 sum_k (-1)^(k-1) exp(-2 k^2 x^2), and its p-quantile. */
static double kolmogorov_cdf(double x)
{
    double sum = 0;
    for (int k = 1; k <= 100; k++)
        sum += (k % 2 ? 1 : -1) * exp(-2.0 * k * k * x * x);
    return 1 - 2 * sum;
}

static double kolmogorov_quantile(double p)
{
    double lo = 0.2, hi = 3;
    for (int i = 0; i < 60; i++) {
        double mid = (lo + hi) / 2;
        if (kolmogorov_cdf(mid) < p)
            lo = mid;
        else
            hi = mid;
    }
    return (lo + hi) / 2;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

typedef struct measures {
    double ks, tip_frac, tip, bins; /* tip: |tip_frac - area-uniform value| */
} measures;

static measures measure(const double *x, const double *y, size_t n, double *s)
{
    long bin[RINGS * SECTORS] = {0};
    size_t tip = 0;
    for (size_t i = 0; i < n; i++) {
        double u = x[i] / A, v = y[i] / B;
        s[i] = u * u + v * v;
        tip += fabs(x[i]) > 0.9 * A;
        int ring = (int)(s[i] * RINGS), sector = (int)((atan2(v, u) + PI) / (2 * PI) * SECTORS);
        ring = ring < 0 ? 0 : (ring >= RINGS ? RINGS - 1 : ring);
        sector = sector < 0 ? 0 : (sector >= SECTORS ? SECTORS - 1 : sector);
        bin[ring * SECTORS + sector]++;
    }
    qsort(s, n, sizeof *s, cmp_double);
    double ks = 0;
    for (size_t i = 0; i < n; i++)
        ks = fmax(ks, fmax((double)(i + 1) / (double)n - s[i], s[i] - (double)i / (double)n));
    const double expect = (double)n / (RINGS * SECTORS);
    double dev = 0;
    for (int k = 0; k < RINGS * SECTORS; k++)
        dev = fmax(dev, fabs((double)bin[k] / expect - 1));
    const double tip_exact = 2 / PI * (acos(0.9) - 0.9 * sqrt(1 - 0.81));
    double frac = (double)tip / (double)n;
    return (measures){ks, frac, fabs(frac - tip_exact), dev};
}

int study_knobs_ellipse(const study_opts *o)
{
    const int nsizes = o->quick ? NSIZES - 1 : NSIZES;
    const int reps = o->quick ? 3 : 5;
    const size_t nmax = SIZES[nsizes - 1];
    double *x = malloc(nmax * sizeof *x), *y = malloc(nmax * sizeof *y), *s = malloc(nmax * sizeof *s);
    int rc = 0;
    if (!x || !y || !s) {
        fprintf(stderr, "iskra bench: ellipse: out of memory\n");
        free(x);
        free(y);
        free(s);
        return 1;
    }
    const double tip_exact = 2 / PI * (acos(0.9) - 0.9 * sqrt(1 - 0.81));
    const double ks_limit = thesis_ks_limit(), kolmogorov_mean = sqrt(PI / 2) * log(2.0);
    measures m[NMODES][NSIZES];
    double ns[NMODES][NSIZES];
    study_buf csv = {0};
    study_printf(&csv, "mode,samples,ks_distance,tip_fraction,tip_fraction_error,max_bin_deviation,ns_per_sample,"
                       "us_total\n");
    for (int k = 0; k < nsizes; k++)
        for (int md = 0; md < NMODES; md++) {
            const size_t n = SIZES[k];
            isk_shape sh = isk_shape_ellipse(0, 0, A, B, MODES[md]);
            double t[8];
            isk_rng rng;
            for (int r = 0; r < reps; r++) {
                isk_rng_seed(&rng, 1000 + (uint64_t)k); /* the same draws for both modes */
                double t0 = study_now();
                isk_status st = isk_shape_sample_n(&sh, &rng, n, x, y);
                t[r] = study_now() - t0;
                if (st != ISK_OK) {
                    fprintf(stderr, "iskra bench: ellipse: %s\n", isk_status_str(st));
                    rc = 1;
                    goto done;
                }
            }
            ns[md][k] = study_median(t, reps) / (double)n * 1e9;
            m[md][k] = measure(x, y, n, s);
            study_printf(&csv, "%s,%zu,%.6e,%.6f,%.6e,%.6e,%.3f,%.3f\n", MODE_NAME[md], n, m[md][k].ks,
                         m[md][k].tip_frac, m[md][k].tip, m[md][k].bins, ns[md][k], ns[md][k] * (double)n * 1e-3);
        }

    printf("ellipse a = %g, b = %g: area-uniform sampler vs the particle-engine thesis's (seed per size)\n", A, B);
    printf("KS = Kolmogorov-Smirnov distance of (x/a)^2 + (y/b)^2 from U(0,1); tip = fraction with |x| > 0.9a;\n"
           "bins = largest |count/expected - 1| over %d equal-area bins\n", RINGS * SECTORS);
    printf("expected: area-uniform KS ~ %.3f/sqrt(n), tip %.4f; thesis KS -> %.4f (quadrature), tip -> 0.1\n\n",
           kolmogorov_mean, tip_exact, ks_limit);
    printf("%8s | %-8s %8s %8s %8s %7s | %-8s %8s %8s %8s %7s\n", "samples", "uniform", "KS", "tip", "bins", "ns",
           "thesis", "KS", "tip", "bins", "ns");
    for (int k = 0; k < nsizes; k++) {
        printf("%8zu", SIZES[k]);
        for (int md = 0; md < NMODES; md++)
            printf(" | %-8s %8.5f %8.5f %8.4f %7.2f", "", m[md][k].ks, m[md][k].tip_frac, m[md][k].bins, ns[md][k]);
        printf("\n");
    }
    const int last = nsizes - 1;
    printf("\nuniform KS * sqrt(n):");
    for (int k = 0; k < nsizes; k++)
        printf(" %.3f", m[0][k].ks * sqrt((double)SIZES[k]));
    printf(" (Kolmogorov's distribution: mean %.3f, 95%% below %.3f)\n", kolmogorov_mean, kolmogorov_quantile(0.95));
    printf("at %zu samples: thesis KS %.4f vs its limit %.4f;\n"
           "thesis tip fraction %.4f (%.2fx the area-uniform %.4f); thesis costs %.2fx the uniform sampler's time\n\n",
           SIZES[last], m[1][last].ks, ks_limit,
           m[1][last].tip_frac, m[1][last].tip_frac / tip_exact, tip_exact, ns[1][last] / ns[0][last]);
    if (study_write_text(o, "ellipse.csv", &csv))
        rc = 1;

    /* Chart: error against the total sampling time, so more samples move
     * a point right; the uniform sampler's errors keep falling, the
     * thesis's level off at their limits. */
    double xs[NMODES][NSIZES], ks[NMODES][NSIZES], tip[NMODES][NSIZES];
    isk_chart_series ser[2 * NMODES];
    static const char *const names[2 * NMODES] = {"uniform: KS distance", "thesis: KS distance",
                                                  "uniform: |tip fraction - 0.0374|", "thesis: |tip fraction - 0.0374|"};
    for (int md = 0; md < NMODES; md++) {
        for (int k = 0; k < nsizes; k++) {
            xs[md][k] = ns[md][k] * (double)SIZES[k] * 1e-3;
            ks[md][k] = m[md][k].ks;
            tip[md][k] = m[md][k].tip;
        }
        ser[md] = (isk_chart_series){names[md], xs[md], ks[md], (size_t)nsizes, isk_chart_style_default(md)};
        ser[NMODES + md] =
            (isk_chart_series){names[NMODES + md], xs[md], tip[md], (size_t)nsizes, isk_chart_style_default(NMODES + md)};
    }
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = "Ellipse sampler: distance from area-uniform (10^3 .. 10^6 samples along each line)";
    ch.x_label = "us to draw all samples (isk_shape_sample_n, median)";
    ch.y_label = "error";
    ch.x_log = ch.y_log = 1;
    ch.series = ser;
    ch.nseries = 2 * NMODES;
    ch.legend = ISK_LEGEND_BOTTOM_LEFT;
    if (study_write_chart(o, "ellipse.png", &ch, 960, 640))
        rc = 1;
done:
    study_buf_free(&csv);
    free(x);
    free(y);
    free(s);
    return rc;
}
