/* SPDX-License-Identifier: MIT */
/* `iskra bench accuracy --scene SCENE`: the work-precision chart of any
 * scene.
 *
 * The scene runs `frames` frames of its own dt under every integrator at
 * substeps 1, 2, 4 and 8 times its own, and once under the reference
 * (scene_sweep.h: Yoshida 4, or RK4 where the forces are not smooth) at 16
 * times its own substeps.  At about 60 frames spread evenly over the run,
 * and at the last, each particle's position is compared with the
 * reference's, in pixels through the scene's view: the error's median and
 * 99th percentile over the particles alive.
 *
 * Pairing: the same seed and births put the same particles in the same
 * slots as long as deaths happen in the same frames (lives are drawn, not
 * integrated).  A deflector kill or a removal of a non-finite particle can
 * differ between a run and the reference; from the first sample where any
 * emitter's count or removals differ, the run is compared no more (its
 * row says until when it was).  Pairing by a birth number would survive
 * that, but the library keeps none, and a run that lost different
 * particles than the reference has already left it.
 *
 * Time: the steps alone, on one thread, the fastest of up to five runs
 * while they took under 50 ms in all; machine dependent, unlike the
 * errors.  Files in the output directory (STEM: the scene's name):
 *   scene_STEM.csv       one row per integrator x substeps
 *   scene_STEM.png       error against milliseconds per frame, log-log,
 *                        the 16.7 ms frame of a 60 Hz display marked
 *   scene_STEM_time.csv  the error at every sample of every run
 *   scene_STEM_time.png  error against simulated time at a fixed cost: each
 *                        integrator at the most substeps whose frame costs
 *                        no more than semi-Euler's at 8 times the scene's */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cleanup.h"
#include "iskra/integrate.h"
#include "iskra/limits.h"
#include "outpath.h"
#include "scene_sweep.h"
#include "study.h"

enum { NI = ISK_INTEGRATOR_COUNT, NSUB = 4, MAX_SAMPLES = 64, MAX_REPS = 5, REF_FACTOR = 16 };
static const int SUB_FACTOR[NSUB] = {1, 2, 4, 8};
static const double REP_BUDGET = 0.05;   /* seconds of timed runs per setting */
static const double FRAME_MS = 1000.0 / 60; /* a 60 Hz display's frame */

/* The particles at one sample frame: per emitter its count, then every
 * live particle's world position, emitters in order. */
typedef struct snapshot {
    long frame;
    size_t removed;
    size_t *count; /* nem */
    double *x, *y; /* sum of count */
} snapshot;

typedef struct run_result {
    double ms;                          /* per frame, fastest run */
    int nsamples;                       /* compared samples */
    double median[MAX_SAMPLES], p99[MAX_SAMPLES], world[MAX_SAMPLES];
    size_t removed;                     /* at the end of the run */
} run_result;

typedef struct scene_study {
    const study_opts *o;
    const char *scene;
    char stem[128];
    isk_effect_def def;
    long frames;
    int nsamples;
    long sample_frame[MAX_SAMPLES];
    snapshot ref[MAX_SAMPLES];
    int nem;
    isk_integrator ref_method;
    int ref_substeps;
    const char *ref_why;
    int budget_substeps;   /* the fixed cost: semi-Euler at these substeps */
    double budget_ms;
    double *err; /* scratch: one error per particle */
    size_t err_cap;
} scene_study;

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void snapshot_free(snapshot *s)
{
    free(s->count);
    free(s->x);
    free(s->y);
    memset(s, 0, sizeof *s);
}

static int snapshot_take(snapshot *s, const isk_effect *fx, long frame)
{
    int nem = isk_effect_emitter_count(fx);
    size_t n = 0;
    s->frame = frame;
    s->removed = sweep_removed(fx);
    s->count = malloc((size_t)(nem > 0 ? nem : 1) * sizeof *s->count);
    for (int e = 0; e < nem; e++)
        n += isk_effect_particles(fx, e)->count;
    s->x = malloc((n ? n : 1) * sizeof *s->x);
    s->y = malloc((n ? n : 1) * sizeof *s->y);
    if (!s->count || !s->x || !s->y)
        return 1;
    size_t k = 0;
    for (int e = 0; e < nem; e++) {
        const isk_particles *p = isk_effect_particles(fx, e);
        s->count[e] = p->count;
        memcpy(s->x + k, p->x, p->count * sizeof *p->x);
        memcpy(s->y + k, p->y, p->count * sizeof *p->y);
        k += p->count;
    }
    return 0;
}

/* Compares fx with the reference at sample j: 1 and the errors when the
 * particles pair, 0 when they do not, -1 out of memory. */
static int compare(scene_study *ss, const isk_effect *fx, int j, double *median, double *p99, double *world)
{
    const snapshot *r = &ss->ref[j];
    if (sweep_removed(fx) != r->removed)
        return 0;
    size_t n = 0;
    for (int e = 0; e < ss->nem; e++) {
        if (isk_effect_particles(fx, e)->count != r->count[e])
            return 0;
        n += r->count[e];
    }
    if (n > ss->err_cap) {
        double *t = realloc(ss->err, n * sizeof *t);
        if (!t)
            return -1;
        ss->err = t;
        ss->err_cap = n;
    }
    const isk_view *v = isk_effect_view(fx);
    size_t k = 0;
    double wmax = 0.0;
    for (int e = 0; e < ss->nem; e++) {
        const isk_particles *p = isk_effect_particles(fx, e);
        for (size_t i = 0; i < p->count; i++, k++) {
            double ax, ay, bx, by;
            isk_view_to_screen(v, p->x[i], p->y[i], &ax, &ay);
            isk_view_to_screen(v, r->x[k], r->y[k], &bx, &by);
            ss->err[k] = hypot(ax - bx, ay - by);
            wmax = fmax(wmax, hypot(p->x[i] - r->x[k], p->y[i] - r->y[k]));
        }
    }
    if (n == 0) {
        *median = *p99 = *world = NAN;
        return 1;
    }
    qsort(ss->err, n, sizeof *ss->err, cmp_double);
    *median = ss->err[n / 2];
    *p99 = ss->err[(size_t)floor(0.99 * (double)(n - 1))];
    *world = wmax;
    return 1;
}

/* One run of the setting: with the reference's snapshots taken (reference
 * = 1) or compared against them (0); *seconds: the steps' time. */
static int run_once(scene_study *ss, const sweep_setting *set, int reference, run_result *out, double *seconds)
{
    isk_effect *fx;
    if (sweep_create("accuracy", &ss->def, set, &fx))
        return 1;
    isk_status st = ISK_OK;
    int j = 0, paired = 1, rc = 0;
    double t = 0.0;
    if (out)
        out->nsamples = 0;
    for (long f = 1; f <= ss->frames && st == ISK_OK && rc == 0; f++) {
        double t0 = study_now();
        st = isk_effect_step(fx);
        t += study_now() - t0;
        if (j >= ss->nsamples || f != ss->sample_frame[j])
            continue;
        if (reference) {
            rc = snapshot_take(&ss->ref[j], fx, f);
        } else if (out && paired) {
            int c = compare(ss, fx, j, &out->median[j], &out->p99[j], &out->world[j]);
            if (c < 0)
                rc = 1;
            else if (c == 0)
                paired = 0;
            else
                out->nsamples = j + 1;
        }
        j++;
    }
    if (out)
        out->removed = sweep_removed(fx);
    isk_effect_destroy(fx);
    if (rc)
        fprintf(stderr, "iskra bench accuracy: out of memory\n");
    else if (st != ISK_OK)
        fprintf(stderr, "iskra bench accuracy: %s with %s: %s\n", ss->scene, isk_integrator_name(set->method),
                isk_status_str(st));
    *seconds = t;
    return rc || st != ISK_OK;
}

/* The errors once, then timing runs while they are cheap. */
static int run_setting(scene_study *ss, const sweep_setting *set, run_result *out)
{
    double t, spent, best;
    if (run_once(ss, set, 0, out, &t))
        return 1;
    spent = best = t;
    for (int r = 1; r < (ss->o->quick ? 1 : MAX_REPS) && spent < REP_BUDGET; r++) {
        if (run_once(ss, set, 0, NULL, &t))
            return 1;
        spent += t;
        best = fmin(best, t);
    }
    out->ms = best * 1000.0 / (double)ss->frames;
    return 0;
}

static double last(const run_result *r, const double *v) { return r->nsamples ? v[r->nsamples - 1] : NAN; }

/* Whole decades around the positive finite values of v. */
static void decades(const double *v, size_t n, double *lo, double *hi)
{
    double a = INFINITY, b = 0.0;
    for (size_t i = 0; i < n; i++)
        if (v[i] > 0 && isfinite(v[i])) {
            a = fmin(a, v[i]);
            b = fmax(b, v[i]);
        }
    if (!(b > 0)) {
        *lo = 1e-3;
        *hi = 1;
        return;
    }
    *lo = pow(10, floor(log10(a)));
    *hi = pow(10, ceil(log10(b)));
    if (*hi <= *lo)
        *hi = *lo * 10;
}

static int write_outputs(scene_study *ss, run_result res[NI][NSUB], int subs[NSUB], int pick[NI])
{
    const study_opts *o = ss->o;
    const double dt = ss->def.dt;
    study_buf csv = {0}, tcsv = {0};
    study_printf(&csv, "scene,integrator,substeps,h,ms_per_frame,frames_compared,time_compared,median_px,p99_px,"
                       "max_world,removed_nonfinite,reference,reference_substeps\n");
    study_printf(&tcsv, "scene,integrator,substeps,fixed_cost,time,median_px,p99_px,max_world\n");
    for (int m = 0; m < NI; m++)
        for (int k = 0; k < NSUB; k++) {
            const run_result *r = &res[m][k];
            if (!subs[k])
                continue;
            long fc = r->nsamples ? ss->sample_frame[r->nsamples - 1] : 0;
            study_printf(&csv, "%s,%s,%d,%.10g,%.6f,%ld,%.10g,%.6e,%.6e,%.6e,%zu,%s,%d\n", ss->stem,
                         isk_integrator_name((isk_integrator)m), subs[k], dt / subs[k], r->ms, fc, (double)fc * dt,
                         last(r, r->median), last(r, r->p99), last(r, r->world), r->removed,
                         isk_integrator_name(ss->ref_method), ss->ref_substeps);
            for (int j = 0; j < r->nsamples; j++)
                study_printf(&tcsv, "%s,%s,%d,%d,%.10g,%.6e,%.6e,%.6e\n", ss->stem,
                             isk_integrator_name((isk_integrator)m), subs[k], pick[m] == k,
                             (double)ss->sample_frame[j] * dt, r->median[j], r->p99[j], r->world[j]);
        }
    char file[192];
    snprintf(file, sizeof file, "scene_%s.csv", ss->stem);
    int rc = study_write_text(o, file, &csv);
    snprintf(file, sizeof file, "scene_%s_time.csv", ss->stem);
    rc |= study_write_text(o, file, &tcsv);
    study_buf_free(&csv);
    study_buf_free(&tcsv);

    /* work-precision: median solid with markers, p99 dotted; the frame line */
    double x[NI][NSUB], ymed[NI][NSUB], yp99[NI][NSUB], all[2 * NI * NSUB], allx[NI * NSUB + 1];
    size_t na = 0, nx = 0;
    for (int m = 0; m < NI; m++)
        for (int k = 0; k < NSUB; k++) {
            const run_result *r = &res[m][k];
            x[m][k] = subs[k] ? r->ms : NAN;
            ymed[m][k] = subs[k] && r->nsamples == ss->nsamples ? last(r, r->median) : NAN;
            yp99[m][k] = subs[k] && r->nsamples == ss->nsamples ? last(r, r->p99) : NAN;
            all[na++] = ymed[m][k];
            all[na++] = yp99[m][k];
            allx[nx++] = x[m][k];
        }
    allx[nx++] = FRAME_MS;
    double ylo, yhi, xlo, xhi;
    decades(all, na, &ylo, &yhi);
    decades(allx, nx, &xlo, &xhi);
    isk_chart_series ser[2 * NI + 1];
    for (int m = 0; m < NI; m++) {
        isk_chart_style st = isk_chart_style_default(m);
        ser[2 * m] = (isk_chart_series){isk_integrator_name((isk_integrator)m), x[m], ymed[m], NSUB, st};
        st.dash = ISK_DASH_DOTTED;
        st.marker = ISK_MARKER_NONE;
        ser[2 * m + 1] = (isk_chart_series){NULL, x[m], yp99[m], NSUB, st};
    }
    double fx[2] = {FRAME_MS, FRAME_MS}, fy[2] = {ylo, yhi};
    ser[2 * NI] = (isk_chart_series){"16.7 ms frame", fx, fy, 2,
                                     {{0x60, 0x60, 0x60, 0xff}, ISK_DASH_DASHED, ISK_MARKER_NONE}};
    char title[256], ylab[128], xlab[160];
    snprintf(title, sizeof title, "%s, %ld frames of %.4g s: error against %s x%d", ss->stem, ss->frames, dt,
             isk_integrator_name(ss->ref_method), ss->ref_substeps);
    snprintf(xlab, sizeof xlab, "time per frame (ms, one thread, this machine); points: substeps x1 x2 x4 x8 of the "
             "scene's %d", ss->def.substeps);
    snprintf(ylab, sizeof ylab, "error at frame %ld (px): median solid, p99 dotted", ss->frames);
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = title;
    ch.x_label = xlab;
    ch.y_label = ylab;
    ch.x_log = ch.y_log = 1;
    ch.x_min = xlo;
    ch.x_max = xhi;
    ch.y_min = ylo;
    ch.y_max = yhi;
    ch.series = ser;
    ch.nseries = 2 * NI + 1;
    ch.legend = ISK_LEGEND_ABOVE;
    snprintf(file, sizeof file, "scene_%s.png", ss->stem);
    rc |= study_write_chart(o, file, &ch, 1400, 900);

    /* error against simulated time at the fixed cost */
    double tt[MAX_SAMPLES], tm[NI][MAX_SAMPLES];
    char names[NI][48];
    isk_chart_series ts[NI];
    for (int j = 0; j < ss->nsamples; j++)
        tt[j] = (double)ss->sample_frame[j] * dt;
    for (int m = 0; m < NI; m++) {
        const run_result *r = &res[m][pick[m]];
        for (int j = 0; j < ss->nsamples; j++)
            tm[m][j] = j < r->nsamples ? r->median[j] : NAN;
        snprintf(names[m], sizeof names[m], "%s x%d", isk_integrator_name((isk_integrator)m), subs[pick[m]]);
        isk_chart_style st = isk_chart_style_default(m);
        if (ss->nsamples > 12)
            st.marker = ISK_MARKER_NONE;
        ts[m] = (isk_chart_series){names[m], tt, tm[m], (size_t)ss->nsamples, st};
    }
    snprintf(title, sizeof title, "%s: median error at the cost of semi-euler x%d per frame (%.3g ms here)", ss->stem,
             ss->budget_substeps, ss->budget_ms);
    isk_chart_defaults(&ch);
    ch.title = title;
    ch.x_label = "simulated time (s)";
    ch.y_label = "median error (px)";
    ch.y_log = 1;
    ch.series = ts;
    ch.nseries = NI;
    ch.legend = ISK_LEGEND_ABOVE;
    snprintf(file, sizeof file, "scene_%s_time.png", ss->stem);
    /* a run with no placeable error (all exact) has nothing to chart */
    int any = 0;
    for (int m = 0; m < NI; m++)
        for (int j = 0; j < ss->nsamples; j++)
            any |= tm[m][j] > 0 && isfinite(tm[m][j]);
    if (any)
        rc |= study_write_chart(o, file, &ch, 1400, 900);
    return rc;
}

int study_scene(const study_opts *o, const char *scene, long frames)
{
    scene_study *ss = calloc(1, sizeof *ss);
    run_result(*res)[NSUB] = calloc(NI, sizeof *res);
    if (!ss || !res) {
        fprintf(stderr, "iskra bench accuracy: out of memory\n");
        free(ss);
        free(res);
        return 1;
    }
    ss->o = o;
    ss->scene = scene;
    sweep_stem(scene, ss->stem, sizeof ss->stem);
    int rc = sweep_load("accuracy", scene, 1, &ss->def);
    if (rc == 0 && outpath_make_dirs("bench", o->out_dir))
        rc = 1;
    if (rc) {
        isk_effect_def_free(&ss->def);
        free(ss);
        free(res);
        return rc;
    }
    cleanup_install("bench");
    ss->frames = frames > 0 ? frames : ss->def.show.frames > 0 ? ss->def.show.frames : 120;
    ss->nem = ss->def.nemitters;
    long every = (ss->frames + MAX_SAMPLES - 2) / (MAX_SAMPLES - 1);
    for (long f = every; f < ss->frames && ss->nsamples < MAX_SAMPLES - 1; f += every)
        ss->sample_frame[ss->nsamples++] = f;
    ss->sample_frame[ss->nsamples++] = ss->frames;

    const int s0 = ss->def.substeps;
    ss->ref_method = sweep_reference(&ss->def, &ss->ref_why);
    ss->ref_substeps = s0 * REF_FACTOR <= ISK_SUBSTEPS_MAX ? s0 * REF_FACTOR : ISK_SUBSTEPS_MAX;
    int subs[NSUB];
    for (int k = 0; k < NSUB; k++)
        subs[k] = s0 * SUB_FACTOR[k] < ss->ref_substeps ? s0 * SUB_FACTOR[k] : 0; /* 0: not run */
    printf("-- %s: %ld frames of %g s; reference %s x%d (%s)\n", ss->stem, ss->frames, ss->def.dt,
           isk_integrator_name(ss->ref_method), ss->ref_substeps, ss->ref_why);
    fflush(stdout);
    double t;
    sweep_setting ref = {ss->ref_method, ss->ref_substeps, ss->def.dt};
    rc = run_once(ss, &ref, 1, NULL, &t);
    size_t seen = 0;
    for (int j = 0; rc == 0 && j < ss->nsamples; j++)
        for (int e = 0; e < ss->nem; e++)
            seen += ss->ref[j].count[e];
    if (rc == 0 && seen == 0) {
        fprintf(stderr, "iskra bench accuracy: %s has no particles in %ld frames (does it wait for a click?): "
                        "nothing to measure\n", scene, ss->frames);
        rc = 1;
    }
    printf("  %-11s %9s %12s %12s %12s %10s %9s\n", "integrator", "substeps", "ms/frame", "median px", "p99 px",
           "compared", "removed");
    for (int m = 0; m < NI && rc == 0; m++)
        for (int k = 0; k < NSUB && rc == 0; k++) {
            if (!subs[k])
                continue;
            sweep_setting set = {(isk_integrator)m, subs[k], ss->def.dt};
            rc = run_setting(ss, &set, &res[m][k]);
            const run_result *r = &res[m][k];
            long fc = r->nsamples ? ss->sample_frame[r->nsamples - 1] : 0;
            printf("  %-11s %9d %12.4f %12.3e %12.3e %6ld/%-3ld %9zu\n", isk_integrator_name((isk_integrator)m),
                   subs[k], r->ms, last(r, r->median), last(r, r->p99), fc, ss->frames, r->removed);
            fflush(stdout);
        }
    if (rc == 0) {
        /* the fixed cost: semi-Euler at the most substeps run */
        int top = 0;
        for (int k = 0; k < NSUB; k++)
            if (subs[k])
                top = k;
        const double budget = res[ISK_INTEGRATE_SEMI_EULER][top].ms;
        ss->budget_substeps = subs[top];
        ss->budget_ms = budget;
        int pick[NI];
        for (int m = 0; m < NI; m++) {
            pick[m] = 0;
            for (int k = 0; k <= top; k++)
                if (res[m][k].ms <= budget)
                    pick[m] = k;
        }
        printf("\n");
        rc = write_outputs(ss, res, subs, pick);
    }
    for (int j = 0; j < MAX_SAMPLES; j++)
        snapshot_free(&ss->ref[j]);
    free(ss->err);
    isk_effect_def_free(&ss->def);
    free(ss);
    free(res);
    return rc;
}
