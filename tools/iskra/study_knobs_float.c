/* SPDX-License-Identifier: MIT */
/* Knob study "float": what a float particle state would buy.  AN
 * EXPERIMENT, NOT A LIBRARY PATH: iskra keeps doubles (the thesis's
 * JavaScript is doubles and its trajectories are reproduced bit for bit),
 * so this file carries its own float copy of the semi-implicit Euler step.
 *
 * Problem (as the integrator study, iskra/problems.h): a projectile under gravity g and
 * linear drag b, mass m, with a closed form
 *     r(t) = r0 + v_inf t + (v0 - v_inf)(1 - e^{-kt})/k,  k = b/m,  v_inf = (0, -g/k),
 * NP particles with different launch velocities, error = the largest
 * |r - r_exact| at T.  Three cases: near the origin for T = 2 s; the same
 * launched from x0 = 1e4 (a float's 24-bit mantissa leaves steps of
 * 2^-10 ~ 1e-3 there); and a long run, T = 60 s (the particles fall ~700
 * units at the terminal speed g/k).
 *
 * Three implementations, each timed per particle-step (median):
 *   double (library)  isk_integrate_range(ISK_INTEGRATE_SEMI_EULER): forces
 *                     into block scratch, then the integrator, per block
 *   double (loop)     the study's fused loop in double: the same operations
 *                     in the same order (isk_forces_eval's sum, then
 *                     isk_k_semi_euler), checked to give the library's bits
 *   float (loop)      that loop with every double replaced by float
 * so "float (loop)" against "double (loop)" is the price of the type alone,
 * and against the library the price of what the library does today. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/integrate.h"
#include "iskra/particles.h"
#include "study.h"
#include "study_float_step.h"

static const double G = 9.81, B = 0.8, M = 1.0;

enum { NCASES = 3, NIMPL = 3, MAXSTEPS = 9, LIB = 0, DBL = 1, FLT = 2 };
static const char *const IMPL_NAME[NIMPL] = {"double (library)", "double (loop)", "float (loop)"};
static const char *const IMPL_KEY[NIMPL] = {"double-library", "double-loop", "float-loop"}; /* CSV */
static const struct {
    const char *name, *key; /* key: the CSV's name, without commas */
    double x0, T;
    int nsteps, nsteps_quick; /* how many of STEPS_PER_S to use */
} CASES[NCASES] = {{"origin, T = 2 s", "origin-2s", 0, 2, 9, 6},
                   {"x0 = 1e4, T = 2 s", "x1e4-2s", 1e4, 2, 9, 6},
                   {"origin, T = 60 s", "origin-60s", 0, 60, 6, 3}};
static const int STEPS_PER_S[MAXSTEPS] = {30, 60, 120, 240, 480, 960, 1920, 3840, 7680};

/* The fused steps: study_float_step.h. */

static void launch(size_t i, size_t np, double *vx, double *vy)
{
    double ang = 0.2 + 1.2 * (double)i / (double)np;
    double sp = 5.0 + 10.0 * (double)((i * 7919) % np) / (double)np;
    *vx = sp * cos(ang);
    *vy = sp * sin(ang);
}

static void exact(double x0, double vx0, double vy0, double t, double *x, double *y)
{
    double k = B / M, vinf = -G / k, f = -expm1(-k * t) / k;
    *x = x0 + vx0 * f;
    *y = vinf * t + (vy0 - vinf) * f;
}

typedef struct state {
    size_t np;
    isk_particles p;  /* the library's store */
    isk_scratch *scr;
    double *d[5];     /* x, y, vx, vy, m */
    float *f[5];
} state;

static void load(state *s, int impl, double x0)
{
    if (impl == LIB)
        isk_particles_clear(&s->p);
    for (size_t i = 0; i < s->np; i++) {
        double vx, vy;
        launch(i, s->np, &vx, &vy);
        if (impl == LIB) {
            isk_particles_add(&s->p, x0, 0, vx, vy, M, NULL);
        } else {
            const double v[5] = {x0, 0, vx, vy, M};
            for (int k = 0; k < 5; k++) {
                if (impl == DBL)
                    s->d[k][i] = v[k];
                else
                    s->f[k][i] = (float)v[k];
            }
        }
    }
}

/* Runs impl for `steps` steps of dt; returns seconds. */
static double run(state *s, int impl, long steps, double dt)
{
    isk_forces fo = {0};
    fo.gravity = G;
    fo.drag = B;
    const float gf = (float)G, bf = (float)B, dtf = (float)dt;
    double t0 = study_now();
    for (long k = 0; k < steps; k++)
        switch (impl) {
        case LIB: isk_integrate_range(ISK_INTEGRATE_SEMI_EULER, &fo, s->scr, &s->p, 0, s->p.count, dt); break;
        case DBL: study_step_double(s->np, s->d[0], s->d[1], s->d[2], s->d[3], s->d[4], G, B, dt); break;
        default: study_step_float(s->np, s->f[0], s->f[1], s->f[2], s->f[3], s->f[4], gf, bf, dtf); break;
        }
    return study_now() - t0;
}

static double max_error(const state *s, int impl, double x0, double T)
{
    double worst = 0;
    for (size_t i = 0; i < s->np; i++) {
        double vx, vy, x, y;
        launch(i, s->np, &vx, &vy);
        exact(x0, vx, vy, T, &x, &y);
        double px = impl == LIB ? s->p.x[i] : impl == DBL ? s->d[0][i] : (double)s->f[0][i];
        double py = impl == LIB ? s->p.y[i] : impl == DBL ? s->d[1][i] : (double)s->f[1][i];
        worst = fmax(worst, hypot(px - x, py - y));
    }
    return worst;
}

/* The study's double loop must be the library's arithmetic, bit for bit. */
static int same_bits(const state *s)
{
    const double *lib[4] = {s->p.x, s->p.y, s->p.vx, s->p.vy};
    for (int k = 0; k < 4; k++)
        if (memcmp(lib[k], s->d[k], s->np * sizeof(double)) != 0)
            return 0;
    return 1;
}

int study_knobs_float(const study_opts *o)
{
    const size_t np = o->quick ? 128 : 2000;
    const int reps = o->quick ? 1 : 3;
    state s = {np, {0}, NULL, {NULL}, {NULL}};
    int rc = 0;
    int ok = isk_particles_init(&s.p, np, 0) == ISK_OK;
    s.scr = malloc(sizeof *s.scr);
    for (int k = 0; k < 5; k++) {
        s.d[k] = malloc(np * sizeof(double));
        s.f[k] = malloc(np * sizeof(float));
        ok = ok && s.d[k] && s.f[k];
    }
    study_buf csv = {0};
    if (!ok || !s.scr) {
        fprintf(stderr, "iskra bench: float: out of memory\n");
        rc = 1;
        goto done;
    }
    study_printf(&csv, "case,x0,T,steps_per_s,impl,max_position_error,ns_per_particle_step,ns_per_particle_run\n");
    printf("float vs double: AN EXPERIMENT, NOT A LIBRARY PATH (iskra's state is double; the float\n"
           "step is the study's own copy of semi-implicit Euler).  Projectile, g = %g, drag b = %g, m = %g,\n"
           "%zu particles; error = max |r - r_exact| at T; ns per particle-step (median of %d)\n",
           G, B, M, np, reps);

    double err[NCASES][NIMPL][MAXSTEPS], cost[NCASES][NIMPL][MAXSTEPS];
    int nst[NCASES];
    for (int c = 0; c < NCASES; c++) {
        nst[c] = o->quick ? CASES[c].nsteps_quick : CASES[c].nsteps;
        printf("\n%s (x0 = %g)\n%8s", CASES[c].name, CASES[c].x0, "steps/s");
        for (int im = 0; im < NIMPL; im++)
            printf(" | %-24s", IMPL_NAME[im]);
        printf(" | float/double error\n");
        for (int j = 0; j < nst[c]; j++) {
            const long steps = (long)(STEPS_PER_S[j] * CASES[c].T + 0.5);
            const double dt = 1.0 / STEPS_PER_S[j];
            double t[NIMPL][8];
            for (int r = 0; r < reps; r++)
                for (int im = 0; im < NIMPL; im++) { /* interleaved: drift hits all alike */
                    load(&s, im, CASES[c].x0);
                    t[im][r] = run(&s, im, steps, dt);
                    if (r == 0)
                        err[c][im][j] = max_error(&s, im, CASES[c].x0, CASES[c].T);
                }
            if (!same_bits(&s)) {
                fprintf(stderr, "iskra bench: float: the study's double loop differs from the library "
                                "(%s, %d steps/s)\n", CASES[c].name, STEPS_PER_S[j]);
                rc = 1;
            }
            printf("%8d", STEPS_PER_S[j]);
            for (int im = 0; im < NIMPL; im++) {
                cost[c][im][j] = study_median(t[im], reps) / ((double)np * (double)steps) * 1e9;
                printf(" | %9.3e %6.2f ns/step", err[c][im][j], cost[c][im][j]);
                study_printf(&csv, "%s,%g,%g,%d,%s,%.6e,%.4f,%.2f\n", CASES[c].key, CASES[c].x0, CASES[c].T,
                             STEPS_PER_S[j], IMPL_KEY[im], err[c][im][j], cost[c][im][j],
                             cost[c][im][j] * (double)steps);
            }
            printf(" | %8.2f\n", err[c][FLT][j] / err[c][LIB][j]);
        }
        /* Where float stops improving: its smallest error, and the double's
         * error at the same step. */
        int best = 0;
        for (int j = 1; j < nst[c]; j++)
            if (err[c][FLT][j] < err[c][FLT][best])
                best = j;
        printf("  float's smallest error %.3e at %d steps/s (double there: %.3e; at %d steps/s: float %.3e, double "
               "%.3e)\n", err[c][FLT][best], STEPS_PER_S[best], err[c][LIB][best], STEPS_PER_S[nst[c] - 1],
               err[c][FLT][nst[c] - 1], err[c][LIB][nst[c] - 1]);
    }
    /* Speed: medians over every setting (the cost does not depend on dt). */
    double med[NIMPL];
    for (int im = 0; im < NIMPL; im++) {
        double all[NCASES * MAXSTEPS];
        int k = 0;
        for (int c = 0; c < NCASES; c++)
            for (int j = 0; j < nst[c]; j++)
                all[k++] = cost[c][im][j];
        med[im] = study_median(all, k);
    }
    printf("\nns per particle-step, median over every setting: double (library) %.2f, double (loop) %.2f, "
           "float (loop) %.2f\nfloat saves %.0f%% against the same loop in double, %.0f%% against the library's path%s\n\n",
           med[LIB], med[DBL], med[FLT], (1 - med[FLT] / med[DBL]) * 100, (1 - med[FLT] / med[LIB]) * 100,
           rc ? "" : "\n(the double loop reproduced the library's bits in every run)");
    if (study_write_text(o, "float.csv", &csv))
        rc = 1;

    /* Chart: error against the cost of the whole run per particle; double
     * (the library's path) and float per case, points in order of step. */
    double xs[NCASES][2][MAXSTEPS], ys[NCASES][2][MAXSTEPS];
    char names[NCASES][2][64];
    isk_chart_series ser[NCASES * 2];
    for (int c = 0; c < NCASES; c++)
        for (int k = 0; k < 2; k++) {
            int im = k ? FLT : LIB;
            for (int j = 0; j < nst[c]; j++) {
                xs[c][k][j] = cost[c][im][j] * STEPS_PER_S[j] * CASES[c].T;
                ys[c][k][j] = err[c][im][j];
            }
            snprintf(names[c][k], sizeof names[c][k], "%s, %s", k ? "float" : "double", CASES[c].name);
            ser[c * 2 + k] = (isk_chart_series){names[c][k], xs[c][k], ys[c][k], (size_t)nst[c],
                                                isk_chart_style_default(c * 2 + k)};
        }
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = "Experiment: float vs double semi-implicit Euler, projectile with drag";
    ch.x_label = "ns per particle for the whole run (smaller steps: further right)";
    ch.y_label = "max |r - r_exact| at T";
    ch.x_log = ch.y_log = 1;
    ch.series = ser;
    ch.nseries = NCASES * 2;
    ch.legend = ISK_LEGEND_TOP_RIGHT;
    if (study_write_chart(o, "float.png", &ch, 960, 640))
        rc = 1;
done:
    study_buf_free(&csv);
    isk_particles_free(&s.p);
    free(s.scr);
    for (int k = 0; k < 5; k++) {
        free(s.d[k]);
        free(s.f[k]);
    }
    return rc;
}
