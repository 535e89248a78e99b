/* SPDX-License-Identifier: MIT */
/* Knob study "sine": the sine table (iskra/sinlut.h) at every size from 64
 * to 65536 entries, with each lookup (floor, round, linear interpolation),
 * against libm sin: the largest |error| over many angles, and nanoseconds
 * per call.
 *
 * The angles are uniform random in [-1e4, 1e4] rad, drawn once and used in
 * that (random) order, so neither the table's cache lines nor the branch
 * predictor see a friendly pattern: a large table costs what it costs when
 * particles' phases are unrelated.  Every lookup is timed in its own tight
 * loop (the mode is chosen outside the loop, as a hot loop would), the
 * configurations are interleaved repetition by repetition so a change in
 * the machine's speed hits all of them alike, and the median is reported.
 *
 * The measured errors are checked against the documented bounds 2 pi/N,
 * pi/N and (2 pi/N)^2/8, plus the rounding slack the header states
 * (|theta| 2^-52 + 2^-52); a violation fails the study (exit status 1). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "iskra/rng.h"
#include "iskra/sinlut.h"
#include "study.h"

enum { NSIZES = 11, NMODES = 3, LIBM = NMODES };
static const int SIZES[NSIZES] = {64, 128, 256, 512, 1024, 2048, 4096, 8192, 16384, 32768, 65536};
static const isk_sinlut_mode MODES[NMODES] = {ISK_SINLUT_FLOOR, ISK_SINLUT_ROUND, ISK_SINLUT_LERP};
#define MODE_NAME isk_sinlut_mode_names /* indexed by mode: the first three are the table's */
static const double RANGE = 1e4; /* angles in [-RANGE, RANGE] rad */

/* Seconds for one pass of `mode` (or libm sin) over the angles. */
static double run(const isk_sinlut *lut, int mode, const double *th, double *out, size_t n)
{
    double t0 = study_now();
    switch (mode) {
    case 0:
        for (size_t i = 0; i < n; i++)
            out[i] = isk_sinlut_floor(lut, th[i]);
        break;
    case 1:
        for (size_t i = 0; i < n; i++)
            out[i] = isk_sinlut_round(lut, th[i]);
        break;
    case 2:
        for (size_t i = 0; i < n; i++)
            out[i] = isk_sinlut_lerp(lut, th[i]);
        break;
    default:
        for (size_t i = 0; i < n; i++)
            out[i] = sin(th[i]);
        break;
    }
    return study_now() - t0;
}

static double decade_below(double v) { return pow(10.0, floor(log10(v))); }
static double decade_above(double v) { return pow(10.0, ceil(log10(v))); }

int study_knobs_sine(const study_opts *o)
{
    const size_t n = o->quick ? (size_t)1 << 16 : (size_t)1 << 20;
    const int reps = o->quick ? 3 : 7;
    enum { NCONF = NSIZES * NMODES + 1 }; /* + libm, the last */
    double *th = malloc(n * sizeof *th), *ref = malloc(n * sizeof *ref), *out = malloc(n * sizeof *out);
    double *times = malloc((size_t)NCONF * (size_t)reps * sizeof *times);
    isk_sinlut lut[NSIZES];
    double err[NSIZES][NMODES], ns[NSIZES][NMODES], ns_libm = 0;
    study_buf csv = {0};
    int rc = 0;
    if (!th || !ref || !out || !times) {
        fprintf(stderr, "iskra bench: sine: out of memory\n");
        rc = 1;
        goto done;
    }
    isk_rng rng;
    isk_rng_seed(&rng, 1);
    double max_abs = 0;
    for (size_t i = 0; i < n; i++) {
        th[i] = isk_rng_range(&rng, -RANGE, RANGE);
        ref[i] = sin(th[i]);
        max_abs = fmax(max_abs, fabs(th[i]));
    }
    for (int s = 0; s < NSIZES; s++)
        if (isk_sinlut_init(&lut[s], SIZES[s]) != ISK_OK) {
            fprintf(stderr, "iskra bench: sine: cannot build a table of %d\n", SIZES[s]);
            rc = 1;
            goto done;
        }

    for (int r = 0; r < reps; r++)
        for (int c = 0; c < NCONF; c++) {
            int s = c / NMODES, mode = c == NCONF - 1 ? LIBM : c % NMODES;
            times[c * reps + r] = run(&lut[c == NCONF - 1 ? 0 : s], mode, th, out, n);
            if (r == 0 && mode != LIBM) { /* the errors do not change between repetitions */
                double worst = 0;
                for (size_t i = 0; i < n; i++)
                    worst = fmax(worst, fabs(out[i] - ref[i]));
                err[s][mode] = worst;
            }
        }
    for (int c = 0; c < NCONF; c++) {
        double t = study_median(times + c * reps, reps) / (double)n * 1e9;
        if (c == NCONF - 1)
            ns_libm = t;
        else
            ns[c / NMODES][c % NMODES] = t;
    }

    /* The header's rounding slack for the largest angle used. */
    const double slack = max_abs * 0x1p-52 + 0x1p-52;
    printf("sine table against libm sin: %zu random angles in [-%g, %g] rad, random order; median of %d runs\n", n,
           RANGE, RANGE, reps);
    printf("bounds (iskra/sinlut.h): floor 2pi/N, round pi/N, lerp (2pi/N)^2/8, each + rounding slack %.1e\n",
           slack);
    printf("libm sin: %.2f ns per call (error 0 by definition: it is the reference)\n\n", ns_libm);
    printf("%6s", "N");
    for (int m = 0; m < NMODES; m++)
        printf(" | %5s: %9s %7s %6s", MODE_NAME[m], "max err", "/bound", "ns");
    printf("\n");
    study_printf(&csv, "mode,size,max_abs_error,bound,error_over_bound,ns_per_call,libm_ns_per_call\n");
    double lo = INFINITY, hi = 0, worst_ratio = 0, least_ratio = INFINITY;
    for (int s = 0; s < NSIZES; s++) {
        printf("%6d", SIZES[s]);
        for (int m = 0; m < NMODES; m++) {
            double bound = isk_sinlut_bound(SIZES[s], MODES[m]), ratio = err[s][m] / bound;
            printf(" | %5s  %9.3e %7.4f %6.2f", "", err[s][m], ratio, ns[s][m]);
            study_printf(&csv, "%s,%d,%.6e,%.6e,%.6f,%.4f,%.4f\n", MODE_NAME[m], SIZES[s], err[s][m], bound, ratio,
                         ns[s][m], ns_libm);
            if (!(err[s][m] <= bound + slack)) {
                fprintf(stderr, "iskra bench: sine: N = %d %s: max error %.6e exceeds its bound %.6e + %.1e\n",
                        SIZES[s], MODE_NAME[m], err[s][m], bound, slack);
                rc = 1;
            }
            worst_ratio = fmax(worst_ratio, ratio);
            least_ratio = fmin(least_ratio, ratio);
            lo = fmin(lo, err[s][m]);
            hi = fmax(hi, err[s][m]);
        }
        printf("\n");
    }
    printf("\n%s: error / bound from %.4f to %.6f%s\n", rc ? "FAILED, see above" : "every error is within its bound",
           least_ratio, worst_ratio, least_ratio >= 0.99 ? " (the bounds are tight)" : "");
    printf("cost relative to libm sin: ");
    for (int m = 0; m < NMODES; m++)
        printf("%s %.2f..%.2f%s", MODE_NAME[m], ns[0][m] / ns_libm, ns[NSIZES - 1][m] / ns_libm,
               m + 1 < NMODES ? ", " : " (N = 64 .. 65536)\n");
    /* Per lookup, the smallest table reaching an error: chosen by the
     * (deterministic) errors, not by timings that differ by noise. */
    printf("smallest table reaching an error, per lookup (ns per call):\n");
    const double targets[] = {1e-2, 1e-4, 1e-6, 1e-8};
    for (size_t t = 0; t < sizeof targets / sizeof targets[0]; t++) {
        printf("  error <= %.0e:", targets[t]);
        for (int m = 0; m < NMODES; m++) {
            int s = 0;
            while (s < NSIZES && !(err[s][m] <= targets[t]))
                s++;
            if (s < NSIZES)
                printf("  %s N = %d (%.2f ns)", MODE_NAME[m], SIZES[s], ns[s][m]);
            else
                printf("  %s: none up to %d", MODE_NAME[m], SIZES[NSIZES - 1]);
        }
        printf("\n");
    }
    printf("\n");
    if (study_write_text(o, "sine.csv", &csv))
        rc = 1;

    /* Chart: one series per lookup, its points in order of table size (the
     * error falls along each series); libm as a vertical line at its cost. */
    double xs[NMODES][NSIZES], ys[NMODES][NSIZES];
    isk_chart_series ser[NMODES + 1];
    for (int m = 0; m < NMODES; m++) {
        for (int s = 0; s < NSIZES; s++) {
            xs[m][s] = ns[s][m];
            ys[m][s] = err[s][m];
        }
        ser[m] = (isk_chart_series){MODE_NAME[m], xs[m], ys[m], NSIZES, isk_chart_style_default(m)};
    }
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.y_min = decade_below(lo);
    ch.y_max = decade_above(hi);
    double lx[2] = {ns_libm, ns_libm}, ly[2] = {ch.y_min, ch.y_max};
    ser[NMODES] = (isk_chart_series){"libm sin (its cost)", lx, ly, 2, isk_chart_style_default(NMODES)};
    ser[NMODES].style.marker = ISK_MARKER_NONE;
    ch.title = "Sine table (N = 64 .. 65536 along each line) against libm sin";
    ch.x_label = "ns per call (median, random angles in [-1e4, 1e4])";
    ch.y_label = "max |table - sin|";
    ch.x_log = ch.y_log = 1;
    ch.series = ser;
    ch.nseries = NMODES + 1;
    ch.legend = ISK_LEGEND_TOP_RIGHT;
    if (study_write_chart(o, "sine.png", &ch, 960, 640))
        rc = 1;
done:
    study_buf_free(&csv);
    free(th);
    free(ref);
    free(out);
    free(times);
    return rc;
}
