/* SPDX-License-Identifier: MIT */
/* `iskra bench accuracy --only longrun`: energy over 10^5 periods.
 *
 * One particle on the Kepler ellipse of iskra/problems.h (the P = 3 law,
 * e = 0.6, a = 1: period 1 s) for 10^5 periods (--quick: 10^3) at 128
 * steps per period, every integrator that can run that long; after every
 * step the energy error is tracked (isk_problem_track), and the largest
 * |E - E0| / E0 so far is recorded at 1, 2, 5, 10, 20, ... periods.  The
 * symplectic methods' error stays bounded (it wobbles within each orbit,
 * peaking in a narrow spike at periapsis, and does not grow); tracking
 * only every sixteenth of a period would miss that spike and find it
 * later, as the orbit's phase drifts past the samples, which looks like a
 * slow growth that is not there.  RK4's is smaller
 * at first but grows without bound, in proportion to the time, until it
 * passes every symplectic method of its cost.  longrun.csv, longrun.png. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "iskra/problems.h"
#include "iskra/system.h"
#include "study.h"

enum { STEPS_PER_PERIOD = 128, MAXCHECK = 20 };

static const isk_integrator METHODS[] = {ISK_INTEGRATE_SEMI_EULER, ISK_INTEGRATE_VERLET,  ISK_INTEGRATE_LEAPFROG,
                                         ISK_INTEGRATE_STRANG,     ISK_INTEGRATE_YOSHIDA4, ISK_INTEGRATE_RK4};
enum { NM = sizeof METHODS / sizeof METHODS[0] };

/* 1, 2, 5, 10, 20, 50, ... up to `periods`. */
static int checkpoints(long periods, long *at)
{
    int n = 0;
    for (long d = 1; d <= periods && n < MAXCHECK; d *= 10)
        for (int k = 0; k < 3 && n < MAXCHECK; k++) {
            long v = d * (k == 0 ? 1 : (k == 1 ? 2 : 5));
            if (v <= periods)
                at[n++] = v;
        }
    return n;
}

int study_longrun(const study_opts *o)
{
    const long periods = o->quick ? 1000 : 100000;
    long at[MAXCHECK];
    const int nc = checkpoints(periods, at);
    double err[NM][MAXCHECK], secs[NM];
    isk_problem pb = isk_problem_defaults(ISK_PROBLEM_KEPLER);
    pb.count = 1;
    pb.start_min = pb.start_max = 1.0; /* a = 1: one period per second */
    pb.T = (double)periods;
    isk_system *s = malloc(sizeof *s);
    if (!s) {
        fprintf(stderr, "iskra bench: longrun: out of memory\n");
        return 1;
    }
    int rc = 0;
    printf("-- long run: Kepler ellipse e = %g, a = 1 (period 1 s), %ld periods, %d steps per period\n",
           pb.eccentricity, periods, STEPS_PER_PERIOD);
    printf("  max |E - E0| / E0 up to N periods (tracked after every step)\n  %10s", "periods");
    for (int m = 0; m < NM; m++)
        printf(" %10s", isk_integrator_name(METHODS[m]));
    printf("\n");
    fflush(stdout);
    for (int m = 0; m < NM && rc == 0; m++) {
        isk_status st = isk_system_init(s, 1, 0);
        if (st == ISK_OK)
            st = isk_problem_setup(&pb, s);
        if (st == ISK_OK)
            st = isk_system_set_integrator(s, METHODS[m]);
        isk_problem_error acc = {0};
        const double dt = 1.0 / STEPS_PER_PERIOD;
        double t0 = study_now();
        int c = 0;
        for (long p = 1; p <= periods && st == ISK_OK; p++) {
            for (int f = 0; f < STEPS_PER_PERIOD && st == ISK_OK; f++) {
                st = isk_system_step(s, dt);
                if (st == ISK_OK)
                    st = isk_problem_track(&pb, s, &acc);
            }
            if (c < nc && p == at[c])
                err[m][c++] = acc.energy;
        }
        secs[m] = study_now() - t0;
        isk_system_free(s);
        if (st != ISK_OK) {
            fprintf(stderr, "iskra bench: longrun: %s: %s\n", isk_integrator_name(METHODS[m]), isk_status_str(st));
            rc = 1;
        }
    }
    free(s);
    if (rc)
        return rc;
    study_buf csv = {0};
    study_printf(&csv, "integrator,periods,max_relative_energy_error\n");
    for (int c = 0; c < nc; c++) {
        printf("  %10ld", at[c]);
        for (int m = 0; m < NM; m++)
            printf(" %10.2e", err[m][c]);
        printf("\n");
    }
    for (int m = 0; m < NM; m++)
        for (int c = 0; c < nc; c++)
            study_printf(&csv, "%s,%ld,%.6e\n", isk_integrator_name(METHODS[m]), at[c], err[m][c]);
    printf("  growth from %ld to %ld periods (x%ld in time):", at[nc > 3 ? 3 : 0], at[nc - 1],
           at[nc - 1] / at[nc > 3 ? 3 : 0]);
    for (int m = 0; m < NM; m++)
        printf(" %s x%.3g", isk_integrator_name(METHODS[m]), err[m][nc - 1] / err[m][nc > 3 ? 3 : 0]);
    printf("\n  seconds for the run:");
    for (int m = 0; m < NM; m++)
        printf(" %s %.1f", isk_integrator_name(METHODS[m]), secs[m]);
    printf("\n\n");
    if (study_write_text(o, "longrun.csv", &csv))
        rc = 1;
    study_buf_free(&csv);

    double xs[MAXCHECK], ys[NM][MAXCHECK];
    isk_chart_series ser[NM];
    for (int c = 0; c < nc; c++)
        xs[c] = (double)at[c];
    for (int m = 0; m < NM; m++) {
        for (int c = 0; c < nc; c++)
            ys[m][c] = err[m][c] > 0 ? err[m][c] : NAN;
        ser[m] = (isk_chart_series){isk_integrator_name(METHODS[m]), xs, ys[m], (size_t)nc,
                                    isk_chart_style_default((int)METHODS[m])};
    }
    char title[160];
    snprintf(title, sizeof title, "Energy over %ld Kepler periods (e = 0.6, %d steps per period)", periods,
             STEPS_PER_PERIOD);
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = title;
    ch.x_label = "periods";
    ch.y_label = "max |E - E0| / E0 so far";
    ch.x_log = ch.y_log = 1;
    ch.series = ser;
    ch.nseries = NM;
    ch.legend = ISK_LEGEND_TOP_LEFT;
    if (study_write_chart(o, "longrun.png", &ch, 1200, 800))
        rc = 1;
    return rc;
}
