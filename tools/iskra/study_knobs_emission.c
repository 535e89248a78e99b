/* SPDX-License-Identifier: MIT */
/* Knob studies "emission_rate" and "emission_birth": the stream emitter's
 * two fidelity choices (iskra/effect.h), run through the real effect
 * runtime (isk_effect_create / isk_effect_step), at 24 .. 240 steps per
 * second.
 *
 * emission_rate: how many particles are emitted in the first second.  The
 * fire thesis rounds dt*rate per frame with no carry (ISK_RATE_THESIS), so
 * the count is steps * round(rate/steps), off by up to half a particle per
 * frame, in a direction that depends on the frame rate; the accumulator
 * (ISK_RATE_ACCUMULATE) emits the k-th particle at k/rate.  Error: the
 * emitted count against rate * t, after 1 s (signed, % of rate) and the
 * largest |N(t) - rate t| over every step of that second (particles).
 * Both modes do the same work per emitted particle, so the chart plots the
 * error against the frame rate, the knob that sets the cost.
 *
 * emission_birth: where a particle born between two steps is.  With the
 * accumulator the k-th particle is due at k/rate; a point source with a
 * constant launch velocity uses no random draws, so the k-th particle of
 * every run has the same initial conditions and a closed-form position at
 * t = 1 s (age tau = 1 - k/rate):  r = v0 tau + a tau^2 / 2.
 * Modes: back-dated (ISK_BIRTH_BACKDATE, advanced by its age through the
 * emitter's stages), the fire thesis's whole-millisecond jitter
 * (ISK_BIRTH_THESIS_JITTER, here paired with the accumulator so that
 * particle k is the same particle in every run; the thesis pairs it with
 * its rounding) and end-of-frame birth (ISK_BIRTH_FRAME).  Error: mean and
 * largest distance to the closed form, without forces (only the birth time
 * matters: semi-implicit Euler is exact for constant velocity) and under
 * gravity (adds the integrator's error, at most |a| tau h / 2 for a
 * back-dated particle, docs/fire.md).  Cost: time per simulated second. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "iskra/effect.h"
#include "study.h"

enum { NFPS = 8, NRATES = 3, NBIRTH = 3, NSCEN = 2 };
static const int FPS[NFPS] = {24, 30, 48, 60, 90, 120, 144, 240};
static const int FPS_QUICK[] = {24, 60, 144, 240};
static const double RATES[NRATES] = {20, 90, 1000};
static const isk_birth_mode BIRTH[NBIRTH] = {ISK_BIRTH_BACKDATE, ISK_BIRTH_THESIS_JITTER, ISK_BIRTH_FRAME};

/* The birth study's two cases: launch velocity and gravity. */
static const struct {
    const char *name, *key; /* key: the CSV's name */
    double vx, vy, g;
} SCEN[NSCEN] = {{"no force", "no-force", 3, 4, 0}, {"gravity", "gravity", 3, 8, 9.81}};
static const double BIRTH_RATE = 1000; /* particles per second */

static isk_effect *make(int fps, double rate, isk_rate_mode rm, isk_birth_mode bm, double vx, double vy, double g)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    d.dt = 1.0 / fps;
    d.seed = 7;
    int gi = -1;
    if (g > 0) {
        gi = isk_effect_def_add_force(&d, "gravity", ISK_FORCE_GRAVITY);
        if (gi >= 0)
            d.forces[gi].g = g;
    }
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "stream");
    isk_effect *fx = NULL;
    if (e && (g <= 0 || gi >= 0)) {
        e->born.source = ISK_SOURCE_STREAM;
        e->born.rate = rate;
        e->born.rate_mode = rm;
        e->born.birth = bm;
        e->launch.velocity = isk_vec2_make(vx, vy);
        e->life.seconds = INFINITY;
        e->born.capacity = 4 * (size_t)rate + 1024; /* never full: the thesis mode over-emits by < 1 per step */
        e->look.draw = ISK_DRAW_NONE;
        if (gi >= 0)
            isk_emitter_use_force(e, gi);
        isk_error err;
        if (isk_effect_create(&fx, &d, &err) != ISK_OK) {
            fprintf(stderr, "iskra bench: emission: %s\n", err.message);
            fx = NULL;
        }
    } else {
        fprintf(stderr, "iskra bench: emission: out of memory\n");
    }
    isk_effect_def_free(&d);
    return fx;
}

/* Median seconds for `steps` steps from the state after create. */
static double time_run(isk_effect *fx, int steps, int reps)
{
    double t[16];
    for (int r = -1; r < reps; r++) { /* r = -1 warms the caches and the allocator, untimed */
        isk_effect_reset(fx);
        double t0 = study_now();
        for (int i = 0; i < steps; i++)
            isk_effect_step(fx);
        if (r >= 0)
            t[r] = study_now() - t0;
    }
    return study_median(t, reps);
}

/* ---- count per frame ----------------------------------------------------- */

static int rate_study(const study_opts *o, const int *fps, int nfps, int reps)
{
    int rc = 0;
    study_buf csv = {0};
    study_printf(&csv, "rate,steps_per_s,mode,count_at_1s,expected_at_1s,error_at_1s_percent,"
                       "max_abs_count_error,ns_per_step,ns_per_particle\n");
    /* err_pct[mode][rate][fps] */
    double err_pct[2][NRATES][NFPS], max_err[2][NRATES][NFPS], ns[2][NRATES][NFPS];
    size_t count[2][NRATES][NFPS];
    for (int ri = 0; ri < NRATES; ri++)
        for (int fi = 0; fi < nfps; fi++)
            for (int m = 0; m < 2; m++) {
                isk_effect *fx = make(fps[fi], RATES[ri], m ? ISK_RATE_THESIS : ISK_RATE_ACCUMULATE,
                                      ISK_BIRTH_BACKDATE, 0, 1, 0);
                if (!fx) {
                    rc = 1;
                    goto done;
                }
                double worst = 0;
                for (int n = 1; n <= fps[fi]; n++) {
                    if (isk_effect_step(fx) != ISK_OK) {
                        fprintf(stderr, "iskra bench: emission_rate: a step failed\n");
                        isk_effect_destroy(fx);
                        rc = 1;
                        goto done;
                    }
                    /* rate * n / fps, not rate * time: the ideal count of
                     * whole frames, free of the clock's rounding */
                    double ideal = RATES[ri] * n / fps[fi];
                    worst = fmax(worst, fabs((double)isk_effect_particle_count(fx) - ideal));
                }
                size_t c = isk_effect_particle_count(fx);
                double sec = time_run(fx, fps[fi], reps);
                isk_effect_destroy(fx);
                count[m][ri][fi] = c;
                err_pct[m][ri][fi] = ((double)c - RATES[ri]) / RATES[ri] * 100;
                max_err[m][ri][fi] = worst;
                ns[m][ri][fi] = sec / fps[fi] * 1e9;
                study_printf(&csv, "%g,%d,%s,%zu,%g,%.4f,%.6f,%.1f,", RATES[ri], fps[fi], isk_rate_mode_names[m], c, RATES[ri],
                             err_pct[m][ri][fi], worst, ns[m][ri][fi]);
                if (c > 0) /* nothing emitted: no cost per particle (empty field) */
                    study_printf(&csv, "%.1f", sec / (double)c * 1e9);
                study_printf(&csv, "\n");
            }

    printf("emission_rate: particles emitted in the first second (point source, immortal particles)\n");
    printf("thesis = (unsigned)(dt*rate + 0.5) per step, no carry; accumulate = the k-th particle at k/rate\n");
    printf("N = count at 1 s, err = (N - rate)/rate, max = largest |N(t) - rate t| over the steps (particles)\n\n");
    printf("%6s %7s | %6s %8s %7s %8s | %6s %8s %7s %8s\n", "rate/s", "steps/s", "thesis", "err", "max", "ns/step",
           "accum", "err", "max", "ns/step");
    double acc_worst = 0;
    for (int ri = 0; ri < NRATES; ri++)
        for (int fi = 0; fi < nfps; fi++) {
            printf("%6g %7d", RATES[ri], fps[fi]);
            for (int m = 1; m >= 0; m--)
                printf(" | %6zu %7.1f%% %7.2f %8.0f", count[m][ri][fi], err_pct[m][ri][fi], max_err[m][ri][fi],
                       ns[m][ri][fi]);
            printf("\n");
            acc_worst = fmax(acc_worst, max_err[0][ri][fi]);
        }
    printf("\naccumulator: largest |N(t) - rate t| over every step and setting: %.3f particles%s\n", acc_worst,
           acc_worst < 1 ? " (< 1: never a whole particle off)" : "  ** a whole particle off **");
    if (!(acc_worst < 1)) {
        fprintf(stderr, "iskra bench: emission_rate: the accumulator is off by %.3f particles\n", acc_worst);
        rc = 1;
    }
    for (int ri = 0; ri < NRATES; ri++) {
        int lo = 0, hi = 0;
        for (int fi = 1; fi < nfps; fi++) {
            if (err_pct[1][ri][fi] < err_pct[1][ri][lo]) lo = fi;
            if (err_pct[1][ri][fi] > err_pct[1][ri][hi]) hi = fi;
        }
        printf("thesis at %g/s emits from %zu/s (at %d steps/s) to %zu/s (at %d steps/s)\n", RATES[ri], count[1][ri][lo],
               fps[lo], count[1][ri][hi], fps[hi]);
    }
    printf("\n");
    if (study_write_text(o, "emission_rate.csv", &csv))
        rc = 1;

    /* Chart: the thesis's error per rate, and the accumulator's (the
     * largest over the rates, which all coincide at 0 after 1 s). */
    double xs[NFPS], ys[NRATES + 1][NFPS];
    char names[NRATES][48];
    isk_chart_series ser[NRATES + 1];
    for (int fi = 0; fi < nfps; fi++) {
        xs[fi] = fps[fi];
        ys[NRATES][fi] = 0;
        for (int ri = 0; ri < NRATES; ri++) {
            ys[ri][fi] = err_pct[1][ri][fi];
            if (fabs(err_pct[0][ri][fi]) > fabs(ys[NRATES][fi]))
                ys[NRATES][fi] = err_pct[0][ri][fi];
        }
    }
    for (int ri = 0; ri < NRATES; ri++) {
        snprintf(names[ri], sizeof names[ri], "thesis rounding, %g/s", RATES[ri]);
        ser[ri] = (isk_chart_series){names[ri], xs, ys[ri], (size_t)nfps, isk_chart_style_default(ri)};
    }
    ser[NRATES] = (isk_chart_series){"accumulator, every rate", xs, ys[NRATES], (size_t)nfps,
                                     isk_chart_style_default(NRATES)};
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = "Emitted count after 1 s: thesis per-step rounding vs accumulator";
    ch.x_label = "steps per second (the cost grows in proportion)";
    ch.y_label = "(N(1 s) - rate * 1 s) / (rate * 1 s), %";
    /* Room above the data for the legend: whole 20 % steps, a fifth of
     * the plot left free at the top. */
    double lo = 0, hi = 0;
    for (int k = 0; k <= NRATES; k++)
        for (int fi = 0; fi < nfps; fi++) {
            lo = fmin(lo, ys[k][fi]);
            hi = fmax(hi, ys[k][fi]);
        }
    ch.y_min = 20 * floor(lo / 20 - 0.25);
    ch.y_max = 20 * ceil((hi + (hi - ch.y_min) * 0.25) / 20);
    ch.series = ser;
    ch.nseries = NRATES + 1;
    ch.legend = ISK_LEGEND_TOP_RIGHT;
    if (study_write_chart(o, "emission_rate.png", &ch, 960, 640))
        rc = 1;
done:
    study_buf_free(&csv);
    return rc;
}

/* ---- birth time -------------------------------------------------------------- */

static int birth_study(const study_opts *o, const int *fps, int nfps, int reps)
{
    int rc = 0;
    study_buf csv = {0};
    study_printf(&csv, "scenario,mode,steps_per_s,particles,mean_position_error,max_position_error,ns_per_step,"
                       "us_per_sim_second\n");
    double mean[NSCEN][NBIRTH][NFPS], worst[NSCEN][NBIRTH][NFPS], us[NSCEN][NBIRTH][NFPS];
    double bound_ratio = 0; /* back-dated under gravity: error / (|a| tau h / 2), worst case */
    for (int sc = 0; sc < NSCEN; sc++)
        for (int b = 0; b < NBIRTH; b++)
            for (int fi = 0; fi < nfps; fi++) {
                isk_effect *fx = make(fps[fi], BIRTH_RATE, ISK_RATE_ACCUMULATE, BIRTH[b], SCEN[sc].vx, SCEN[sc].vy,
                                      SCEN[sc].g);
                if (!fx) {
                    rc = 1;
                    goto done;
                }
                isk_status st = ISK_OK;
                for (int n = 0; n < fps[fi] && st == ISK_OK; n++)
                    st = isk_effect_step(fx);
                const isk_particles *p = isk_effect_particles(fx, 0);
                const size_t want = (size_t)BIRTH_RATE;
                if (st != ISK_OK || p->count != want) {
                    fprintf(stderr, "iskra bench: emission_birth: %s %s at %d steps/s: %s, %zu particles at 1 s, "
                                    "expected %zu\n", SCEN[sc].name, isk_birth_mode_names[BIRTH[b]], fps[fi], isk_status_str(st),
                            p->count, want);
                    rc = 1;
                    isk_effect_destroy(fx);
                    mean[sc][b][fi] = worst[sc][b][fi] = us[sc][b][fi] = NAN; /* a gap in table and chart */
                    continue;
                }
                const double h = 1.0 / fps[fi];
                double sum = 0, big = 0;
                for (size_t i = 0; i < p->count; i++) {
                    double tau = 1.0 - (double)(i + 1) / BIRTH_RATE;
                    double ex = SCEN[sc].vx * tau, ey = SCEN[sc].vy * tau - SCEN[sc].g * tau * tau / 2;
                    double e = hypot(p->x[i] - ex, p->y[i] - ey);
                    sum += e;
                    big = fmax(big, e);
                    if (BIRTH[b] == ISK_BIRTH_BACKDATE && SCEN[sc].g > 0 && tau > 0)
                        bound_ratio = fmax(bound_ratio, (e - 1e-12) / (SCEN[sc].g * tau * h / 2));
                }
                double sec = time_run(fx, fps[fi], reps);
                isk_effect_destroy(fx);
                mean[sc][b][fi] = sum / (double)want;
                worst[sc][b][fi] = big;
                us[sc][b][fi] = sec * 1e6;
                study_printf(&csv, "%s,%s,%d,%zu,%.6e,%.6e,%.1f,%.3f\n", SCEN[sc].key, isk_birth_mode_names[BIRTH[b]], fps[fi], want,
                             mean[sc][b][fi], big, sec / fps[fi] * 1e9, us[sc][b][fi]);
            }

    printf("emission_birth: where the k-th particle is at t = 1 s (rate %g/s, accumulator, point source,\n"
           "launch velocity fixed); error = distance to r = v0 tau + a tau^2/2, tau = 1 - k/rate\n",
           BIRTH_RATE);
    for (int sc = 0; sc < NSCEN; sc++) {
        printf("\n%s (v0 = (%g, %g), g = %g): mean / max position error, us per simulated second\n", SCEN[sc].name,
               SCEN[sc].vx, SCEN[sc].vy, SCEN[sc].g);
        printf("%7s", "steps/s");
        for (int b = 0; b < NBIRTH; b++)
            printf(" | %-29s", isk_birth_mode_names[BIRTH[b]]);
        printf("\n");
        for (int fi = 0; fi < nfps; fi++) {
            printf("%7d", fps[fi]);
            for (int b = 0; b < NBIRTH; b++)
                printf(" | %9.2e %9.2e %7.1f us", mean[sc][b][fi], worst[sc][b][fi], us[sc][b][fi]);
            printf("\n");
        }
    }
    /* Without forces a particle's error is its speed times its birth-time
     * error: for end-of-frame births the true age, about uniform in [0, h)
     * (mean h/2); for the jitter |U - age| with U an independent whole-ms
     * draw in [0, h) (mean h/3). */
    printf("\nno force, mean error / (speed h), per steps/s:");
    for (int b = 1; b < NBIRTH; b++) {
        printf("  %s", isk_birth_mode_names[BIRTH[b]]);
        for (int fi = 0; fi < nfps; fi++)
            printf(" %.3f", mean[0][b][fi] / (hypot(SCEN[0].vx, SCEN[0].vy) / fps[fi]));
    }
    printf("\n(independent uniforms in [0, h): E|U - V| = h/3, E V = h/2)\n");
    printf("back-dated under gravity: largest error / (g tau h / 2) = %.4f%s\n", bound_ratio,
           bound_ratio <= 1 ? " (within the documented bound)" : "  ** exceeds the documented bound **");
    if (!(bound_ratio <= 1)) {
        fprintf(stderr, "iskra bench: emission_birth: back-dated error exceeds |a| tau h / 2\n");
        rc = 1;
    }
    printf("\n");
    if (study_write_text(o, "emission_birth.csv", &csv))
        rc = 1;

    /* Chart: mean error against the cost of a simulated second, one line
     * per (mode, case), points in order of frame rate.  Back-dated births
     * without forces are exact up to rounding; drawn, they would stretch
     * the error axis over 14 decades and squeeze the other five lines
     * together, so the title gives their largest error instead. */
    double xs[NSCEN][NBIRTH][NFPS], exact_worst = 0;
    char names[NSCEN][NBIRTH][48], title[160];
    isk_chart_series ser[NSCEN * NBIRTH];
    size_t ns = 0;
    for (int sc = 0; sc < NSCEN; sc++)
        for (int b = 0; b < NBIRTH; b++) {
            if (SCEN[sc].g == 0 && BIRTH[b] == ISK_BIRTH_BACKDATE) {
                for (int fi = 0; fi < nfps; fi++)
                    exact_worst = fmax(exact_worst, worst[sc][b][fi]);
                continue;
            }
            for (int fi = 0; fi < nfps; fi++)
                xs[sc][b][fi] = us[sc][b][fi];
            snprintf(names[sc][b], sizeof names[sc][b], "%s, %s", isk_birth_mode_names[BIRTH[b]], SCEN[sc].name);
            ser[ns] = (isk_chart_series){names[sc][b], xs[sc][b], mean[sc][b], (size_t)nfps,
                                         isk_chart_style_default(sc * NBIRTH + b)};
            ns++;
        }
    snprintf(title, sizeof title,
             "Sub-step births: position error at 1 s, 24 .. 240 steps/s (backdate, no force: max %.0e, not drawn)",
             exact_worst);
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = title;
    ch.x_label = "us per simulated second (1000 particles/s)";
    ch.y_label = "mean |r - r_exact| (world units)";
    ch.x_log = ch.y_log = 1;
    ch.series = ser;
    ch.nseries = ns;
    ch.legend = ISK_LEGEND_BOTTOM_LEFT;
    if (study_write_chart(o, "emission_birth.png", &ch, 960, 640))
        rc = 1;
done:
    study_buf_free(&csv);
    return rc;
}

int study_knobs_emission(const study_opts *o)
{
    const int *fps = o->quick ? FPS_QUICK : FPS;
    const int nfps = o->quick ? (int)(sizeof FPS_QUICK / sizeof FPS_QUICK[0]) : NFPS;
    const int reps = o->quick ? 3 : 7;
    int rc = rate_study(o, fps, nfps, reps);
    if (birth_study(o, fps, nfps, reps))
        rc = 1;
    return rc;
}
