/* SPDX-License-Identifier: MIT */
/* `iskra bench accuracy --only integrators`: what accuracy costs in time.
 *
 * Every integrator x time step x substeps {1, 2, 4} on the problems of
 * iskra/problems.h (projectile with drag, harmonic oscillator, radial
 * motion through the Coulomb core; the bouncing ball and the Kepler
 * ellipse with substeps 1 only), run through the library's own pipeline
 * (isk_problem_setup, isk_system_step) and measured against the closed
 * forms.  Conserved quantities (energy, angular momentum, period) are
 * tracked after every step and their largest error over [0, T] is
 * reported, not their value at T.  Per problem: a table on stdout, the
 * observed convergence orders, the cheapest setting for a few target
 * errors, <problem>.csv (one row per setting) and a work-precision chart
 * <problem>.png: error against the time per particle for the whole run,
 * log-log; at a given error the leftmost curve is the cheapest.  The top
 * axis says the same cost as particles per 16.7 ms frame (a frame
 * simulating 1/60 s), step sizes are written at some points, and a diamond
 * on each curve marks dt = 1/60 (interpolated between the neighbouring
 * steps).  substeps.png shows what substeps do on the projectile.
 *
 * Step sizes: frames over T grow by sqrt(2) per index k (k = 0..20, 6.6 per
 * decade over 3 decades), with the odd ones rounded once and then doubled,
 * so k and k + 2 are exact halvings: the observed order is
 * log2(e_k / e_{k+2}) with no interpolation, and N substeps of dt use the
 * very step dt/N of substeps 1 at k + 2 log2 N: the final states must be
 * bit-identical, which we check (the errors differ in their last digits,
 * because the system clock sums frames, not substeps).
 *
 * Timing: the fastest of up to 5 runs of one setting (the least disturbed
 * by the other work on the machine), repeated only while the runs so far
 * took < 50 ms in total; the spread (slowest - fastest) / fastest goes to
 * the CSV and the tables, so noise is not read as cost.  Only the steps are
 * timed, not the tracking.  --quick: 1 run, every other step up to k = 12,
 * 32 particles. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/integrate.h"
#include "iskra/problems.h"
#include "iskra/system.h"
#include "study.h"

enum { NI = ISK_INTEGRATOR_COUNT, NSUB = 3, NK = 21, MAX_REPS = 5 };
static const int SUBSTEPS[NSUB] = {1, 2, 4};
static const double REP_BUDGET = 0.05; /* seconds */
/* An error above this (a thousand times the problem's own size) is called
 * diverged: it is kept in the CSV but left out of charts and summaries. */
static const double DIVERGED = 1e3;
/* Errors in this window are mostly past the pre-asymptotic regime and
 * above rounding, so the median of their ratios shows the order (the
 * printed list of every ratio shows where that holds). */
static const double ORDER_LO = 1e-10, ORDER_HI = 1e-1;

typedef enum metric { M_POSITION, M_VELOCITY, M_ENERGY, M_PHASE, M_ANGMOM, M_PERIOD, M_COUNT } metric;

static const struct {
    const char *csv;  /* CSV column */
    const char *tag;  /* chart file suffix */
    const char *what; /* axis label */
} METRIC[M_COUNT] = {
    {"position_error", "position", "max |r - r_exact| at T (m)"},
    {"velocity_error", "velocity", "max |v - v_exact| at T (m/s)"},
    {"energy_error", "energy", "max |E - E0| / E0 over [0, T] (relative)"},
    {"phase_error", "phase", "max |phase error| at T (rad)"},
    {"angular_momentum_error", "angular_momentum", "max |L - L0| / L0 over [0, T] (relative)"},
    {"period_error", "period", "max |P - P0| / P0 over [0, T] (relative, from the energy)"},
};

static double metric_of(const isk_problem_error *e, metric m)
{
    switch (m) {
    case M_POSITION: return e->position;
    case M_VELOCITY: return e->velocity;
    case M_ENERGY: return e->energy;
    case M_ANGMOM: return e->angular_momentum;
    case M_PERIOD: return e->period;
    default: return e->phase;
    }
}

/* What to run for one problem. */
typedef struct plan {
    isk_problem_kind kind;
    size_t count;      /* particles: enough that the per-frame overhead is small */
    long n0;           /* frames over T at k = 0 (the coarsest step) */
    metric shown[2];   /* charted and summarised; shown[0] decides divergence */
    int nshown;
    isk_chart_legend legend; /* the corner the curves leave empty */
    int nsub;          /* substep settings run: 3 (1, 2, 4) or 1 */
} plan;

/* Ranges: the coarsest step is about where the first methods go unstable
 * (w dt ~ 2 for the oscillator and the radial core), the finest where RK4
 * reaches rounding.  Particle counts: the per-frame overhead (~0.1 us)
 * stays a few per cent of a frame, and the whole study under a minute on
 * two cores. */
static const plan PLANS[] = {
    {ISK_PROBLEM_PROJECTILE, 1024, 5, {M_POSITION, M_POSITION}, 1, ISK_LEGEND_TOP_RIGHT, NSUB},
    {ISK_PROBLEM_OSCILLATOR, 256, 30, {M_ENERGY, M_PHASE}, 2, ISK_LEGEND_BOTTOM_LEFT, NSUB},
    {ISK_PROBLEM_RADIAL, 256, 25, {M_ENERGY, M_ENERGY}, 1, ISK_LEGEND_BOTTOM_LEFT, NSUB},
    /* The ball's exact-flight integrators sit at rounding (they bounce
     * exactly): its chart is the Euler forms' error against the others'. */
    {ISK_PROBLEM_BOUNCE, 256, 20, {M_POSITION, M_ENERGY}, 2, ISK_LEGEND_BOTTOM_LEFT, 1},
    {ISK_PROBLEM_KEPLER, 32, 80, {M_ENERGY, M_PERIOD}, 2, ISK_LEGEND_BOTTOM_LEFT, 1},
};
enum { NPLANS = sizeof PLANS / sizeof PLANS[0] };

typedef struct cell {
    int ran;
    long frames;
    double dt;
    isk_problem_error err;
    int diverged, nondeterministic;
    uint64_t state;  /* hash of the final particle state's bits */
    double ns_step; /* per particle and integrator step (substep): the fastest run */
    double ns_run;  /* per particle for the whole run to T: the fastest run */
    double spread;  /* (slowest - fastest) / fastest of the runs */
    int reps;
} cell;

typedef struct results {
    const plan *pl;
    isk_problem pb;
    cell c[NI][NSUB][NK];
} results;

/* Frames at index k: n0 * 2^(k/2), the odd ones from round(n0 sqrt 2). */
static long frames_at(long n0, int k)
{
    long base = k % 2 ? lround((double)n0 * sqrt(2.0)) : n0;
    return base << (k / 2);
}

/* FNV-1a over the bits of every position and velocity. */
static uint64_t state_hash(const isk_particles *p)
{
    uint64_t h = 14695981039346656037u;
    const double *arr[4] = {p->x, p->y, p->vx, p->vy};
    for (int a = 0; a < 4; a++)
        for (size_t i = 0; i < p->count; i++) {
            uint64_t bits;
            memcpy(&bits, &arr[a][i], sizeof bits);
            for (int b = 0; b < 8; b++) {
                h ^= (bits >> (8 * b)) & 0xffu;
                h *= 1099511628211u;
            }
        }
    return h;
}

static int tracked(isk_problem_kind kind) { return kind != ISK_PROBLEM_PROJECTILE; }

static int run_setting(const isk_problem *pb, isk_system *s, isk_integrator m, int sub, long frames,
                       int max_reps, cell *c)
{
    double times[MAX_REPS], spent = 0.0;
    int reps = 0;
    const double dt = pb->T / (double)frames;
    do {
        isk_status st = isk_problem_setup(pb, s);
        if (st == ISK_OK)
            st = isk_system_set_integrator(s, m);
        if (st == ISK_OK)
            st = isk_system_set_substeps(s, sub);
        isk_problem_error acc = {0};
        double t = 0.0;
        if (!tracked(pb->kind)) {
            double t0 = study_now();
            for (long f = 0; f < frames && st == ISK_OK; f++)
                st = isk_system_step(s, dt);
            t = study_now() - t0;
        } else {
            /* the steps timed, the tracking of conserved quantities not */
            for (long f = 0; f < frames && st == ISK_OK; f++) {
                double t0 = study_now();
                st = isk_system_step(s, dt);
                t += study_now() - t0;
                if (st == ISK_OK)
                    st = isk_problem_track(pb, s, &acc);
            }
        }
        isk_problem_error e;
        if (st == ISK_OK)
            st = isk_problem_measure(pb, s, &e);
        if (st == ISK_OK && tracked(pb->kind)) { /* maxima over [0, T] replace the values at T */
            e.energy = acc.energy;
            if (pb->kind == ISK_PROBLEM_KEPLER) {
                e.angular_momentum = acc.angular_momentum;
                e.period = acc.period;
            }
        }
        if (st != ISK_OK) {
            fprintf(stderr, "iskra bench: %s, %s, substeps %d, %ld steps: %s\n", isk_problem_name(pb->kind),
                    isk_integrator_name(m), sub, frames, isk_status_str(st));
            return 1;
        }
        uint64_t h = state_hash(&s->particles);
        if (reps == 0) {
            c->err = e;
            c->state = h;
        } else if (h != c->state) {
            c->nondeterministic = 1;
        }
        times[reps++] = t;
        spent += t;
    } while (reps < max_reps && spent < REP_BUDGET);
    double fast = times[0], slow = times[0];
    for (int r = 1; r < reps; r++) {
        fast = fmin(fast, times[r]);
        slow = fmax(slow, times[r]);
    }
    c->ran = 1;
    c->frames = frames;
    c->dt = dt;
    c->reps = reps;
    c->ns_run = fast * 1e9 / (double)pb->count;
    c->ns_step = c->ns_run / ((double)frames * sub);
    c->spread = fast > 0 ? (slow - fast) / fast : 0.0;
    return 0;
}

/* Diverged: a state went non-finite, or a charted error is beyond
 * DIVERGED or infinite (an orbit that escaped has no period). */
static void mark_diverged(const plan *pl, cell *c)
{
    c->diverged = c->err.nonfinite > 0;
    for (int i = 0; i < pl->nshown; i++)
        c->diverged |= !(metric_of(&c->err, pl->shown[i]) <= DIVERGED);
}

/* The k indices a run uses. */
static int k_list(const study_opts *o, int *ks)
{
    int n = 0;
    for (int k = 0; k < NK; k++)
        if (!o->quick || (k % 2 == 0 && k <= 12))
            ks[n++] = k;
    return n;
}

static int sweep(const study_opts *o, results *R, isk_system *s)
{
    int ks[NK], nk = k_list(o, ks);
    int max_reps = o->quick ? 1 : MAX_REPS;
    for (int m = 0; m < NI; m++)
        for (int j = 0; j < R->pl->nsub; j++)
            for (int a = 0; a < nk; a++) {
                cell *c = &R->c[m][j][ks[a]];
                if (run_setting(&R->pb, s, (isk_integrator)m, SUBSTEPS[j], frames_at(R->pl->n0, ks[a]),
                                max_reps, c))
                    return 1;
                mark_diverged(R->pl, c);
            }
    return 0;
}

/* ---- stdout ---------------------------------------------------------------- */

static void print_table(const results *R, metric mt)
{
    printf("  %s, substeps 1\n  %6s %9s", METRIC[mt].what, "steps", "dt");
    for (int m = 0; m < NI; m++)
        printf(" %10s", isk_integrator_name((isk_integrator)m));
    printf("\n");
    for (int k = 0; k < NK; k++) {
        const cell *c0 = &R->c[0][0][k];
        if (!c0->ran)
            continue;
        printf("  %6ld %9.3g", c0->frames, c0->dt);
        for (int m = 0; m < NI; m++) {
            const cell *c = &R->c[m][0][k];
            if (c->diverged)
                printf(" %10s", "diverged");
            else
                printf(" %10.2e", metric_of(&c->err, mt));
        }
        printf("\n");
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void print_costs(const results *R)
{
    printf("  ns per particle-step (fastest of the runs, median over the steps, substeps 1;\n"
           "  in brackets the median spread (slowest - fastest) / fastest):\n   ");
    for (int m = 0; m < NI; m++) {
        double v[NK], w[NK];
        int n = 0;
        for (int k = 0; k < NK; k++)
            if (R->c[m][0][k].ran) {
                w[n] = R->c[m][0][k].spread;
                v[n++] = R->c[m][0][k].ns_step;
            }
        qsort(v, (size_t)n, sizeof *v, cmp_double);
        qsort(w, (size_t)n, sizeof *w, cmp_double);
        printf(" %s %.2f (%.0f%%)", isk_integrator_name((isk_integrator)m), n ? v[n / 2] : NAN, n ? 100 * w[n / 2] : NAN);
    }
    printf("\n");
}

static int in_window(const cell *c, metric mt)
{
    double e = metric_of(&c->err, mt);
    return c->ran && !c->diverged && e >= ORDER_LO && e <= ORDER_HI;
}

static void print_orders(const results *R, metric mt)
{
    printf("  observed order of the %s (log2 of the error ratio when dt halves, substeps 1,\n"
           "  halvings with both errors in [%.0e, %.0e]: median, range, count | each halving\n"
           "  from the coarsest step, '.' where a run diverged):\n",
           METRIC[mt].tag, ORDER_LO, ORDER_HI);
    for (int m = 0; m < NI; m++) {
        double v[NK];
        int n = 0;
        char all[NK * 8] = "";
        size_t len = 0;
        for (int k = 0; k + 2 < NK; k++) {
            const cell *a = &R->c[m][0][k], *b = &R->c[m][0][k + 2];
            if (!a->ran || !b->ran)
                continue;
            double q = log2(metric_of(&a->err, mt) / metric_of(&b->err, mt));
            if (in_window(a, mt) && in_window(b, mt))
                v[n++] = q;
            if (k % 2 || len + 8 >= sizeof all)
                continue; /* the display lists the even chain: steps n0, 2 n0, 4 n0, ... */
            if (!a->diverged && !b->diverged && isfinite(q))
                len += (size_t)snprintf(all + len, sizeof all - len, " %.1f", q);
            else
                len += (size_t)snprintf(all + len, sizeof all - len, " .");
        }
        qsort(v, (size_t)n, sizeof *v, cmp_double);
        if (n)
            printf("    %-10s %5.2f  (%.2f..%.2f, %2d)  |%s\n", isk_integrator_name((isk_integrator)m),
                   v[n / 2], v[0], v[n - 1], n, all);
        else
            printf("    %-10s  none in the window     |%s\n", isk_integrator_name((isk_integrator)m), all);
    }
}

static void print_cheapest(const results *R, metric mt)
{
    static const double targets[] = {1e-1, 1e-3, 1e-6, 1e-9};
    printf("  cheapest setting reaching a %s error (ns per particle for the whole run):\n", METRIC[mt].tag);
    for (int t = 0; t < 4; t++) {
        const cell *best = NULL;
        int bm = 0, bj = 0;
        for (int m = 0; m < NI; m++)
            for (int j = 0; j < R->pl->nsub; j++)
                for (int k = 0; k < NK; k++) {
                    const cell *c = &R->c[m][j][k];
                    if (c->ran && !c->diverged && metric_of(&c->err, mt) <= targets[t] &&
                        (!best || c->ns_run < best->ns_run)) {
                        best = c;
                        bm = m;
                        bj = j;
                    }
                }
        if (!best)
            printf("    <= %.0e: not reached by any setting here\n", targets[t]);
        else
            printf("    <= %.0e: %-10s %6ld steps x %d substeps (h %.3g): %9.0f ns  (error %.1e)\n", targets[t],
                   isk_integrator_name((isk_integrator)bm), best->frames, SUBSTEPS[bj], best->dt / SUBSTEPS[bj],
                   best->ns_run, metric_of(&best->err, mt));
    }
}

/* N substeps of dt against 1 substep of dt/N: same errors?  same time? */
static void print_substeps(const results *R)
{
    for (int j = 1; j < R->pl->nsub; j++) {
        int shift = j * 2; /* 2 log2(SUBSTEPS[j]) */
        int same = 0, total = 0, n = 0;
        double ratio[NI * NK];
        for (int m = 0; m < NI; m++)
            for (int k = 0; k + shift < NK; k++) {
                const cell *a = &R->c[m][j][k], *b = &R->c[m][0][k + shift];
                if (!a->ran || !b->ran)
                    continue;
                total++;
                same += a->state == b->state;
                ratio[n++] = a->ns_run / b->ns_run;
            }
        if (!total) {
            printf("  substeps %d: no step of substeps 1 to compare with in this run\n", SUBSTEPS[j]);
            continue;
        }
        qsort(ratio, (size_t)n, sizeof *ratio, cmp_double);
        printf("  substeps %d at dt vs substeps 1 at dt/%d: final states bit-identical in %d of %d;\n"
               "    time ratio median %.2f (range %.2f..%.2f); per integrator:",
               SUBSTEPS[j], SUBSTEPS[j], same, total, ratio[n / 2], ratio[0], ratio[n - 1]);
        /* the median per integrator: a shared machine's noise shows up here
         * as ratios far from 1 for single integrators */
        for (int m = 0; m < NI; m++) {
            double own[NK];
            int nown = 0;
            for (int k = 0; k + shift < NK; k++) {
                const cell *a = &R->c[m][j][k], *b = &R->c[m][0][k + shift];
                if (a->ran && b->ran)
                    own[nown++] = a->ns_run / b->ns_run;
            }
            if (nown) {
                qsort(own, (size_t)nown, sizeof *own, cmp_double);
                printf(" %s %.2f", isk_integrator_name((isk_integrator)m), own[nown / 2]);
            }
        }
        printf("\n");
    }
    int nondet = 0;
    for (int m = 0; m < NI; m++)
        for (int j = 0; j < NSUB; j++)
            for (int k = 0; k < NK; k++)
                nondet += R->c[m][j][k].nondeterministic;
    if (nondet)
        printf("  WARNING: %d settings gave different errors on repeated runs\n", nondet);
}

/* ---- files ------------------------------------------------------------------- */

static int applies(isk_problem_kind kind, metric m)
{
    switch (kind) {
    case ISK_PROBLEM_PROJECTILE: return m == M_POSITION || m == M_VELOCITY;
    case ISK_PROBLEM_OSCILLATOR: return m != M_ANGMOM && m != M_PERIOD;
    case ISK_PROBLEM_BOUNCE: return m == M_POSITION || m == M_VELOCITY || m == M_ENERGY;
    case ISK_PROBLEM_KEPLER: return m != M_PHASE;
    default: return m == M_ENERGY;
    }
}

static int write_csv(const study_opts *o, const results *R)
{
    const char *name = isk_problem_name(R->pb.kind);
    study_buf b = {0};
    study_printf(&b, "problem,integrator,substeps,dt,steps");
    for (int m = 0; m < M_COUNT; m++)
        if (applies(R->pb.kind, (metric)m))
            study_printf(&b, ",%s", METRIC[m].csv);
    study_printf(&b, ",diverged,ns_per_particle_step,ns_per_particle_run,timing_runs,timing_spread\n");
    for (int m = 0; m < NI; m++)
        for (int j = 0; j < R->pl->nsub; j++)
            for (int k = 0; k < NK; k++) {
                const cell *c = &R->c[m][j][k];
                if (!c->ran)
                    continue;
                study_printf(&b, "%s,%s,%d,%.17g,%ld", name, isk_integrator_name((isk_integrator)m), SUBSTEPS[j],
                             c->dt, c->frames);
                for (int e = 0; e < M_COUNT; e++)
                    if (applies(R->pb.kind, (metric)e))
                        study_printf(&b, ",%.6e", metric_of(&c->err, (metric)e));
                study_printf(&b, ",%d,%.6g,%.6g,%d,%.4f\n", c->diverged, c->ns_step, c->ns_run, c->reps, c->spread);
            }
    char file[64];
    snprintf(file, sizeof file, "%s.csv", name);
    int rc = study_write_text(o, file, &b);
    study_buf_free(&b);
    return rc;
}

enum { CHART_W = 1200, CHART_H = 800 };

/* Points of one (integrator, substeps) curve: x = ns per particle for the
 * run, y = error; a diverged setting is a NaN point, a visible gap. */
static size_t curve(const results *R, int m, int j, metric mt, double *x, double *y)
{
    size_t n = 0;
    for (int k = 0; k < NK; k++) {
        const cell *c = &R->c[m][j][k];
        if (!c->ran)
            continue;
        x[n] = c->ns_run;
        y[n] = c->diverged ? NAN : metric_of(&c->err, mt);
        n++;
    }
    return n;
}

static void describe(const isk_problem *pb, char *out, size_t cap)
{
    switch (pb->kind) {
    case ISK_PROBLEM_PROJECTILE:
        snprintf(out, cap, "projectile: gravity %g, linear drag %g, m %g, T %g s, %zu particles", pb->gravity,
                 pb->drag, pb->mass, pb->T, pb->count);
        break;
    case ISK_PROBLEM_OSCILLATOR:
        snprintf(out, cap, "harmonic oscillator (P = 0 spring): omega %.3g rad/s, T %g s = %.4g periods, %zu particles",
                 sqrt(pb->kq / pb->mass), pb->T, pb->T * sqrt(pb->kq / pb->mass) / 6.283185307179586, pb->count);
        break;
    case ISK_PROBLEM_BOUNCE:
        snprintf(out, cap, "bouncing ball: gravity %g onto a floor of restitution %g, drops %g..%g m, T %g s, %zu particles",
                 pb->gravity, pb->restitution, pb->start_min, pb->start_max, pb->T, pb->count);
        break;
    case ISK_PROBLEM_KEPLER:
        snprintf(out, cap, "Kepler ellipse (P = 3 law): e %g, a %g..%g, T %g s (~10 orbits), %zu particles",
                 pb->eccentricity, pb->start_min, pb->start_max, pb->T, pb->count);
        break;
    default:
        snprintf(out, cap, "radial Coulomb (P = 2): kQ %g, core %g, release at %g..%g, T %g s, %zu particles", pb->kq,
                 pb->min_dist, pb->start_min, pb->start_max, pb->T, pb->count);
        break;
    }
}

/* Where the curve of (m, substeps 1) passes dt = 1/60, interpolated in
 * log-log between the two steps around it; 0 when it does not. */
static int at_sixtieth(const results *R, int m, metric mt, double *x, double *y)
{
    const double want = 1.0 / 60.0;
    const cell *a = NULL;
    for (int k = 0; k < NK; k++) {
        const cell *b = &R->c[m][0][k];
        if (!b->ran)
            continue;
        if (a && a->dt >= want && b->dt <= want && !a->diverged && !b->diverged) {
            double ea = metric_of(&a->err, mt), eb = metric_of(&b->err, mt);
            if (!(ea > 0 && eb > 0 && a->ns_run > 0 && b->ns_run > 0))
                return 0;
            double f = (log(a->dt) - log(want)) / (log(a->dt) - log(b->dt));
            *x = exp(log(a->ns_run) + f * (log(b->ns_run) - log(a->ns_run)));
            *y = exp(log(ea) + f * (log(eb) - log(ea)));
            return 1;
        }
        a = b;
    }
    return 0;
}

enum { LABEL_EVERY = 8 }; /* step sizes written at k = 0, 8, 16 */

static int write_chart(const study_opts *o, const results *R, metric mt, const char *file)
{
    double x[NI][NK], y[NI][NK];
    isk_chart_series s[NI];
    isk_chart_note notes[NI * (NK / LABEL_EVERY + 2)];
    char texts[NI * (NK / LABEL_EVERY + 2)][24];
    size_t nn = 0;
    for (int m = 0; m < NI; m++) {
        size_t n = curve(R, m, 0, mt, x[m], y[m]);
        isk_chart_series one = {isk_integrator_name((isk_integrator)m), x[m], y[m], n, isk_chart_style_default(m)};
        s[m] = one;
        /* step sizes at a few points, in the series' colour */
        for (int k = 0; k < NK; k += LABEL_EVERY) {
            const cell *c = &R->c[m][0][k];
            if (!c->ran || c->diverged)
                continue;
            snprintf(texts[nn], sizeof texts[nn], "h %.2g", c->dt);
            notes[nn] = (isk_chart_note){c->ns_run, metric_of(&c->err, mt), texts[nn], one.style.color,
                                         ISK_MARKER_NONE};
            nn++;
        }
        double px, py;
        if (at_sixtieth(R, m, mt, &px, &py))
            notes[nn++] = (isk_chart_note){px, py, NULL, one.style.color, ISK_MARKER_DIAMOND};
    }
    char title[200];
    describe(&R->pb, title, sizeof title);
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = title;
    ch.x_label = "ns per particle for the whole run to T (substeps 1)";
    ch.y_label = METRIC[mt].what;
    ch.x_log = ch.y_log = 1;
    ch.series = s;
    ch.nseries = NI;
    ch.legend = R->pl->legend;
    ch.notes = notes;
    ch.nnotes = nn;
    /* cost per particle for the run to T -> particles a 16.7 ms frame
     * (simulating 1/60 s) can take: 16.7e6 ns / (ns_run / (60 T)) */
    ch.x2_label = "particles per 16.7 ms frame (diamonds: dt = 1/60; labels: step h in s)";
    ch.x2_scale = 1e9 * R->pb.T;
    ch.x2_inverse = 1;
    return study_write_chart(o, file, &ch, CHART_W, CHART_H);
}

/* Semi-Euler and RK4 at substeps 1, 2, 4: one colour per integrator, one
 * dash and marker per substep count. */
static int write_substeps_chart(const study_opts *o, const results *R)
{
    static const int which[2] = {ISK_INTEGRATE_SEMI_EULER, ISK_INTEGRATE_RK4};
    static const isk_chart_dash dash[NSUB] = {ISK_DASH_SOLID, ISK_DASH_DASHED, ISK_DASH_DOTTED};
    static const isk_chart_marker mark[NSUB] = {ISK_MARKER_CIRCLE, ISK_MARKER_SQUARE, ISK_MARKER_TRIANGLE};
    double x[2 * NSUB][NK], y[2 * NSUB][NK];
    char names[2 * NSUB][40];
    isk_chart_series s[2 * NSUB];
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < NSUB; j++) {
            int q = i * NSUB + j;
            size_t n = curve(R, which[i], j, R->pl->shown[0], x[q], y[q]);
            snprintf(names[q], sizeof names[q], "%s, substeps %d", isk_integrator_name((isk_integrator)which[i]),
                     SUBSTEPS[j]);
            isk_chart_style st = isk_chart_style_default(which[i]);
            st.dash = dash[j];
            st.marker = mark[j];
            isk_chart_series one = {names[q], x[q], y[q], n, st};
            s[q] = one;
        }
    char title[240];
    snprintf(title, sizeof title, "substeps: %s - N substeps of dt vs 1 step of dt/N",
             isk_problem_name(R->pb.kind));
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = title;
    ch.x_label = "ns per particle for the whole run to T";
    ch.y_label = METRIC[R->pl->shown[0]].what;
    ch.x_log = ch.y_log = 1;
    ch.series = s;
    ch.nseries = 2 * NSUB;
    ch.legend = ISK_LEGEND_BOTTOM_LEFT; /* the corner the curves leave empty */
    return study_write_chart(o, "substeps.png", &ch, CHART_W, CHART_H);
}

/* ---- one problem, all problems ---------------------------------------------- */

static int study_problem(const study_opts *o, const plan *pl, results *R, isk_system *s)
{
    memset(R, 0, sizeof *R);
    R->pl = pl;
    R->pb = isk_problem_defaults(pl->kind);
    R->pb.count = o->quick ? 32 : pl->count;
    char title[200];
    describe(&R->pb, title, sizeof title);
    printf("-- %s\n", title);
    fflush(stdout);
    double t0 = study_now();
    if (sweep(o, R, s))
        return 1;
    for (int i = 0; i < pl->nshown; i++)
        print_table(R, pl->shown[i]);
    print_costs(R);
    for (int i = 0; i < pl->nshown; i++)
        print_orders(R, pl->shown[i]);
    for (int i = 0; i < pl->nshown; i++)
        print_cheapest(R, pl->shown[i]);
    print_substeps(R);
    int rc = write_csv(o, R);
    const char *name = isk_problem_name(pl->kind);
    for (int i = 0; i < pl->nshown; i++) {
        char file[64];
        if (i == 0)
            snprintf(file, sizeof file, "%s.png", name);
        else
            snprintf(file, sizeof file, "%s_%s.png", name, METRIC[pl->shown[i]].tag);
        rc |= write_chart(o, R, pl->shown[i], file);
    }
    if (pl->kind == ISK_PROBLEM_PROJECTILE)
        rc |= write_substeps_chart(o, R);
    printf("  (%.1f s)\n\n", study_now() - t0);
    fflush(stdout);
    return rc;
}

int study_integrators(const study_opts *o)
{
    isk_system *s = malloc(sizeof *s);
    results *R = malloc(sizeof *R);
    int rc = 1;
    if (!s || !R) {
        fprintf(stderr, "iskra bench: out of memory\n");
        goto done;
    }
    isk_status st = isk_system_init(s, 1, 0);
    if (st != ISK_OK) {
        fprintf(stderr, "iskra bench: %s\n", isk_status_str(st));
        isk_system_free(s);
        goto done;
    }
    rc = 0;
    for (int i = 0; i < NPLANS; i++)
        rc |= study_problem(o, &PLANS[i], R, s);
    isk_system_free(s);
done:
    free(s);
    free(R);
    return rc;
}
