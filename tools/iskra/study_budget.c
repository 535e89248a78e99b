/* SPDX-License-Identifier: MIT */
/* `iskra bench accuracy --only budget`: error against simulated time at a
 * fixed cost per frame.
 *
 * A game or a demo has a fixed budget: so many particles in a 16.7 ms
 * frame.  Here every integrator gets the same time per particle and frame
 * (a frame simulates 1/60 s): the time of BUDGET semi-Euler substeps,
 * measured in the same run (the control), so each method runs as many
 * substeps as fit, at least one.  Then the position error against the
 * closed form is followed through simulated time.  A cheap low-order
 * method takes small steps; a costly high-order one takes few: which wins
 * depends on the problem and on how long it runs.
 *
 * The problems are rows of PROBLEMS: a problem of iskra/problems.h with
 * a closed-form position (its error: the largest distance from it), or
 * the spring on a floor (no closed form: its error is the energy's
 * relative change, which a bounce must give back).  Per problem:
 * budget_<name>.csv (the substeps each integrator got, its measured cost
 * against the control, and the error at about 80 times spread evenly on
 * a log scale) and budget_<name>.png (error against time, log-log).
 * The substeps chosen move with the machine's timings; the errors for
 * given substeps do not.  --quick: a tenth of T, 32 particles, one timing
 * run. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "iskra/integrate.h"
#include "iskra/limits.h"
#include "iskra/problems.h"
#include "iskra/system.h"
#include "study.h"

/* A problem's row: `kind`, or SPRING_FLOOR (iskra/problems.h's spring on a
 * floor, whose error is its energy's). */
enum { SPRING_FLOOR = -1 };
static const struct {
    int kind;     /* an isk_problem_kind, or SPRING_FLOOR */
    double T;     /* seconds simulated */
    size_t count; /* particles */
} PROBLEMS[] = {
    {ISK_PROBLEM_PROJECTILE, 10.0, 256},
    {ISK_PROBLEM_KEPLER, 100.0, 256},
    {SPRING_FLOOR, 100.0, 256},
};
enum { NPROB = sizeof PROBLEMS / sizeof PROBLEMS[0], NI = ISK_INTEGRATOR_COUNT, MAXS = 256 };
enum { BUDGET = 16 };                    /* semi-Euler substeps per frame: the budget */
static const double FRAME = 1.0 / 60;    /* simulated seconds per frame */
static const double DIVERGED = 1e3;      /* errors above: left out of the chart */

/* The row's system at time 0: its particles, forces and walls. */
static isk_status setup(int pi, const isk_problem *pb, isk_system *s)
{
    return PROBLEMS[pi].kind == SPRING_FLOOR ? isk_problem_spring_floor_setup(s, pb->count, 1)
                                             : isk_problem_setup(pb, s);
}

/* The row's error now: the largest distance from the closed form, or the
 * spring's largest relative energy change (e0: its energy at time 0). */
static isk_status error_now(int pi, const isk_problem *pb, const isk_system *s, double e0, double *err)
{
    if (PROBLEMS[pi].kind != SPRING_FLOOR) {
        isk_problem_error e;
        isk_status st = isk_problem_measure(pb, s, &e);
        *err = e.position;
        return st;
    }
    double worst = 0;
    for (size_t i = 0; i < s->particles.count; i++)
        worst = fmax(worst, fabs(isk_problem_spring_floor_energy(&s->particles, i) / e0 - 1.0));
    *err = s->particles.count == pb->count ? worst : INFINITY; /* (one removed as non-finite) */
    return ISK_OK;
}

/* Fastest of `reps` timed runs of `frames` frames (ns per particle-step). */
static isk_status time_steps(isk_system *s, int pi, const isk_problem *pb, isk_integrator m, int frames, int reps,
                             double *ns)
{
    isk_status st = ISK_OK;
    *ns = INFINITY;
    for (int r = -1; r < reps && st == ISK_OK; r++) { /* r = -1 warms up, untimed */
        st = setup(pi, pb, s);
        if (st == ISK_OK)
            st = isk_system_set_integrator(s, m);
        if (st == ISK_OK)
            st = isk_system_set_substeps(s, 1);
        double t0 = study_now();
        for (int f = 0; f < frames && st == ISK_OK; f++)
            st = isk_system_step(s, FRAME);
        double t = (study_now() - t0) * 1e9 / ((double)frames * (double)pb->count);
        if (r >= 0 && t < *ns)
            *ns = t;
    }
    return st;
}

typedef struct curve {
    int substeps;
    double ns, fraction; /* ns per particle-step; frame cost / budget */
    size_t n;
    double t[MAXS], err[MAXS], shown[MAXS];
} curve;

static int study_problem(const study_opts *o, isk_system *s, int pi)
{
    const int spring = PROBLEMS[pi].kind == SPRING_FLOOR;
    isk_problem pb = isk_problem_defaults(spring ? ISK_PROBLEM_PROJECTILE : (isk_problem_kind)PROBLEMS[pi].kind);
    pb.count = o->quick ? 32 : PROBLEMS[pi].count;
    pb.T = o->quick ? PROBLEMS[pi].T / 10 : PROBLEMS[pi].T;
    const char *name = spring ? "spring_floor" : isk_problem_name(pb.kind);
    const long frames = lround(pb.T / FRAME);
    curve *c = calloc(NI, sizeof *c);
    if (!c) {
        fprintf(stderr, "iskra bench: budget: out of memory\n");
        return 1;
    }
    isk_status st = ISK_OK;
    for (int m = 0; m < NI && st == ISK_OK; m++)
        st = time_steps(s, pi, &pb, (isk_integrator)m, 60, o->quick ? 1 : 7, &c[m].ns);
    const double budget = BUDGET * c[ISK_INTEGRATE_SEMI_EULER].ns;
    for (int m = 0; m < NI && st == ISK_OK; m++) {
        int sub = (int)floor(budget / c[m].ns);
        c[m].substeps = sub < 1 ? 1 : sub > ISK_SUBSTEPS_MAX ? ISK_SUBSTEPS_MAX : sub;
        c[m].fraction = c[m].substeps * c[m].ns / budget;
        st = setup(pi, &pb, s);
        const double e0 = spring && st == ISK_OK ? isk_problem_spring_floor_energy(&s->particles, 0) : 0.0;
        if (st == ISK_OK)
            st = isk_system_set_integrator(s, (isk_integrator)m);
        if (st == ISK_OK)
            st = isk_system_set_substeps(s, c[m].substeps);
        long next = 1;
        for (long f = 1; f <= frames && st == ISK_OK; f++) {
            st = isk_system_step(s, FRAME);
            if (st != ISK_OK || (f != next && f != frames) || c[m].n == MAXS)
                continue;
            double err;
            st = error_now(pi, &pb, s, e0, &err);
            c[m].t[c[m].n] = (double)f * FRAME;
            c[m].err[c[m].n] = err;
            c[m].shown[c[m].n] = err > 0 && err < DIVERGED ? err : NAN;
            c[m].n++;
            next = (long)ceil((double)f * 1.09); /* about 80 samples over 4 decades */
            if (next == f)
                next++;
        }
    }
    if (st != ISK_OK) {
        fprintf(stderr, "iskra bench: budget: %s: %s\n", name, isk_status_str(st));
        free(c);
        return 1;
    }

    printf("-- budget: %s, %zu particles, frames of 1/60 s for %g s; every integrator gets the time of\n"
           "   %d semi-Euler substeps per particle and frame (%.1f ns measured here)\n"
           "  %-11s %9s %13s %12s %12s %12s %12s\n",
           name, pb.count, pb.T, BUDGET, budget, "integrator", "substeps", "of budget", "error 1 s", "error 10 s",
           "error T", "max error");
    study_buf csv = {0};
    study_printf(&csv, "problem,integrator,substeps,h,ns_per_particle_step,budget_fraction,time,%s\n",
                 spring ? "energy_error" : "position_error");
    for (int m = 0; m < NI; m++) {
        double at1 = NAN, at10 = NAN, worst = 0;
        for (size_t k = 0; k < c[m].n; k++) {
            if (c[m].t[k] <= 1 + 1e-9)
                at1 = c[m].err[k];
            if (c[m].t[k] <= 10 + 1e-9)
                at10 = c[m].err[k];
            worst = fmax(worst, c[m].err[k]);
            study_printf(&csv, "%s,%s,%d,%.10g,%.3f,%.3f,%.10g,%.6e\n", name, isk_integrator_name((isk_integrator)m),
                         c[m].substeps, FRAME / c[m].substeps, c[m].ns, c[m].fraction, c[m].t[k], c[m].err[k]);
        }
        printf("  %-11s %9d %12.0f%% %12.3e %12.3e %12.3e %12.3e\n", isk_integrator_name((isk_integrator)m),
               c[m].substeps, 100 * c[m].fraction, at1, at10, c[m].err[c[m].n - 1], worst);
    }
    printf("\n");
    char file[64];
    snprintf(file, sizeof file, "budget_%s.csv", name);
    int rc = study_write_text(o, file, &csv);
    study_buf_free(&csv);

    char names[NI][48], title[160];
    isk_chart_series ser[NI];
    for (int m = 0; m < NI; m++) {
        snprintf(names[m], sizeof names[m], "%s x%d", isk_integrator_name((isk_integrator)m), c[m].substeps);
        ser[m] = (isk_chart_series){names[m], c[m].t, c[m].shown, c[m].n, isk_chart_style_default(m)};
    }
    snprintf(title, sizeof title, "%s: error at the cost of %d semi-Euler substeps per 1/60 s frame", name, BUDGET);
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = title;
    ch.x_label = "simulated time (s)";
    ch.y_label = spring ? "max |E / E0 - 1| over the particles" : "max |r - r_exact| (m)";
    ch.x_log = ch.y_log = 1;
    ch.series = ser;
    ch.nseries = NI;
    ch.legend = ISK_LEGEND_ABOVE;
    snprintf(file, sizeof file, "budget_%s.png", name);
    rc |= study_write_chart(o, file, &ch, 1200, 800);
    free(c);
    return rc;
}

int study_budget(const study_opts *o)
{
    isk_system *s = malloc(sizeof *s);
    if (!s || isk_system_init(s, 1, 0) != ISK_OK) {
        fprintf(stderr, "iskra bench: budget: out of memory\n");
        free(s);
        return 1;
    }
    int rc = 0;
    for (int p = 0; p < NPROB; p++)
        rc |= study_problem(o, s, p);
    isk_system_free(s);
    free(s);
    return rc;
}
