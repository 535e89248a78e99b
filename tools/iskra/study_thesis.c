/* SPDX-License-Identifier: MIT */
/* `iskra bench accuracy --only thesis`: error against step on the
 * thesis's own scene, figure 29 (the mushroom with four potentials: a
 * layer of 15,000 particles and a click of 1,000, drag, three P = 9
 * potentials that switch themselves off when a particle comes within
 * their max distance, a repelling P = 1 one, the thesis floor).
 *
 * The scene runs its 121 frames at substeps 1, 2, 4, ... 64 and at 256
 * (the reference), for several seeds (3; --quick: 1 seed, up to 8 against
 * 32).  Measured against the reference of the same seed, particle by
 * particle (the same seed makes the same particles in the same order):
 *   - the fraction of particles more than 1 pixel (600 px over 40 units)
 *     from where the reference puts them at the last frame;
 *   - the frame at which each self-switching potential switched off;
 *   - the time per frame (the fastest of up to 3 runs while they take less
 *     than a second, with the spread).
 * thesis_fig29.csv, thesis_fig29.png (fraction against substeps and
 * against time per frame, one line per seed: the spread of the seeds is
 * the distribution), thesis_fig29_switch.png (switch-off frames against
 * substeps). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "study.h"

#define SCENE "fig29_mushroom_four_potentials"
enum { MAXN = 8, MAXSEEDS = 3, MAXPOT = 8, MAXREPS = 3 };
static const int SUBSTEPS_FULL[] = {1, 2, 4, 8, 16, 32, 64}, SUBSTEPS_QUICK[] = {1, 2, 4, 8};
static const uint64_t SEEDS[MAXSEEDS] = {1, 2, 3};

typedef struct run_out {
    size_t n;
    double *sx, *sy;    /* screen positions at the last frame */
    long off[MAXPOT];   /* frame at which potential k switched off (-1: never) */
    int npot;
    double ms_frame;    /* fastest run */
    double spread;
} run_out;

static void run_free(run_out *r)
{
    free(r->sx);
    free(r->sy);
    r->sx = r->sy = NULL;
}

/* One run of the scene with this seed and substeps; `reps` > 1 repeats it
 * (only the first run's state is kept: every repetition is identical). */
static int run_scene(uint64_t seed, int substeps, int reps, run_out *out)
{
    memset(out, 0, sizeof *out);
    double best = INFINITY, worst = 0;
    for (int r = 0; r < reps; r++) {
        isk_effect_def def;
        isk_error err;
        isk_effect *fx = NULL;
        if (isk_scene_load(&def, SCENE, &err) != ISK_OK) {
            fprintf(stderr, "iskra bench: thesis: %s\n", err.message);
            return 1;
        }
        def.seed = seed;
        def.substeps = substeps;
        const long frames = def.show.frames;
        isk_status st = isk_effect_create(&fx, &def, &err);
        isk_effect_def_free(&def);
        if (st != ISK_OK) {
            fprintf(stderr, "iskra bench: thesis: %s\n", err.message);
            return 1;
        }
        size_t np;
        const isk_potential *pots = isk_effect_potentials(fx, &np);
        int npot = np < MAXPOT ? (int)np : MAXPOT;
        long off[MAXPOT];
        for (int k = 0; k < npot; k++)
            off[k] = pots[k].max_dist > 0 && pots[k].enabled ? -1 : -2; /* -2: not a switching one */
        double t = 0;
        for (long f = 1; f <= frames && st == ISK_OK; f++) {
            double t0 = study_now();
            st = isk_effect_step(fx);
            t += study_now() - t0;
            pots = isk_effect_potentials(fx, &np);
            for (int k = 0; k < npot && (size_t)k < np; k++)
                if (off[k] == -1 && !pots[k].enabled)
                    off[k] = f;
        }
        if (st != ISK_OK) {
            fprintf(stderr, "iskra bench: thesis: seed %llu substeps %d: %s\n", (unsigned long long)seed, substeps,
                    isk_status_str(st));
            isk_effect_destroy(fx);
            return 1;
        }
        best = fmin(best, t / (double)frames);
        worst = fmax(worst, t / (double)frames);
        if (r == 0) {
            const isk_particles *p = isk_effect_particles(fx, 0);
            out->n = p->count;
            out->sx = malloc(p->count * sizeof *out->sx);
            out->sy = malloc(p->count * sizeof *out->sy);
            if (!out->sx || !out->sy) {
                isk_effect_destroy(fx);
                run_free(out);
                fprintf(stderr, "iskra bench: thesis: out of memory\n");
                return 1;
            }
            const isk_view *v = isk_effect_view(fx);
            for (size_t i = 0; i < p->count; i++)
                isk_view_to_screen(v, p->x[i], p->y[i], &out->sx[i], &out->sy[i]);
            out->npot = npot;
            memcpy(out->off, off, sizeof off);
        }
        isk_effect_destroy(fx);
        if (t * (double)(r + 1) > 1.0)
            break; /* long runs are not noisy: one is enough */
    }
    out->ms_frame = best * 1e3;
    out->spread = best > 0 ? (worst - best) / best : 0;
    return 0;
}

/* Fraction of particles more than 1 px from the reference (a particle the
 * other run does not have counts as off). */
static double off_fraction(const run_out *a, const run_out *ref)
{
    size_t n = ref->n, bad = 0;
    for (size_t i = 0; i < n; i++)
        bad += i >= a->n || !(hypot(a->sx[i] - ref->sx[i], a->sy[i] - ref->sy[i]) <= 1.0);
    return n ? (double)bad / (double)n : 0.0;
}

int study_thesis(const study_opts *o)
{
    const int *subs = o->quick ? SUBSTEPS_QUICK : SUBSTEPS_FULL;
    const int nn = o->quick ? 4 : 7, ref_sub = o->quick ? 32 : 256, nseeds = o->quick ? 1 : MAXSEEDS;
    double frac[MAXSEEDS][MAXN], ms[MAXSEEDS][MAXN], spread[MAXSEEDS][MAXN];
    long off[MAXSEEDS][MAXN + 1][MAXPOT];
    int npot = 0, rc = 0;
    printf("-- thesis figure 29 (%s): substeps against a %d-substep reference, %d seed%s\n", SCENE, ref_sub, nseeds,
           nseeds == 1 ? "" : "s");
    fflush(stdout);
    double t_all = study_now();
    for (int sd = 0; sd < nseeds && rc == 0; sd++) {
        run_out ref;
        if (run_scene(SEEDS[sd], ref_sub, 1, &ref)) {
            rc = 1;
            break;
        }
        npot = ref.npot;
        memcpy(off[sd][nn], ref.off, sizeof ref.off);
        for (int j = 0; j < nn; j++) {
            run_out r;
            if (run_scene(SEEDS[sd], subs[j], MAXREPS, &r)) {
                rc = 1;
                break;
            }
            frac[sd][j] = off_fraction(&r, &ref);
            ms[sd][j] = r.ms_frame;
            spread[sd][j] = r.spread;
            memcpy(off[sd][j], r.off, sizeof r.off);
            run_free(&r);
        }
        run_free(&ref);
    }
    if (rc)
        return rc;

    printf("  fraction of particles > 1 px from the reference at frame 121 (per seed), ms per frame:\n");
    printf("  %8s", "substeps");
    for (int sd = 0; sd < nseeds; sd++)
        printf("  seed %llu: %8s %8s", (unsigned long long)SEEDS[sd], "> 1 px", "ms");
    printf("\n");
    for (int j = 0; j < nn; j++) {
        printf("  %8d", subs[j]);
        for (int sd = 0; sd < nseeds; sd++)
            printf("          %7.3f%% %8.2f", 100 * frac[sd][j], ms[sd][j]);
        printf("\n");
    }
    printf("  frame at which each self-switching potential switched off (-: never; last row: the reference):\n");
    for (int sd = 0; sd < nseeds; sd++) {
        printf("  seed %llu:", (unsigned long long)SEEDS[sd]);
        for (int j = 0; j <= nn; j++) {
            printf(" %s%d:", j == nn ? "ref " : "", j == nn ? ref_sub : subs[j]);
            for (int k = 0; k < npot; k++)
                if (off[sd][j][k] != -2) {
                    if (off[sd][j][k] < 0)
                        printf(" -");
                    else
                        printf(" %ld", off[sd][j][k]);
                }
        }
        printf("\n");
    }
    printf("  (%.1f s)\n\n", study_now() - t_all);

    study_buf csv = {0};
    study_printf(&csv, "scene,seed,substeps,reference_substeps,fraction_over_1px,ms_per_frame,timing_spread");
    for (int k = 0; k < npot; k++)
        study_printf(&csv, ",switch_off_frame_potential_%d", k + 1);
    study_printf(&csv, "\n");
    for (int sd = 0; sd < nseeds; sd++)
        for (int j = 0; j <= nn; j++) {
            study_printf(&csv, "fig29,%llu,%d,%d,", (unsigned long long)SEEDS[sd], j == nn ? ref_sub : subs[j], ref_sub);
            if (j == nn)
                study_printf(&csv, "0,,");
            else
                study_printf(&csv, "%.6g,%.4f,%.4f", frac[sd][j], ms[sd][j], spread[sd][j]);
            for (int k = 0; k < npot; k++)
                study_printf(&csv, ",%ld", off[sd][j][k]);
            study_printf(&csv, "\n");
        }
    if (study_write_text(o, "thesis_fig29.csv", &csv))
        rc = 1;
    study_buf_free(&csv);

    /* The fraction against substeps and against ms per frame, a line per
     * seed (two charts side by side would need a canvas of their own: two
     * files). */
    double xs[MAXN], ys[MAXSEEDS][MAXN], xm[MAXSEEDS][MAXN];
    char names[MAXSEEDS][24];
    isk_chart_series ser[MAXSEEDS], ser2[MAXSEEDS];
    for (int j = 0; j < nn; j++)
        xs[j] = subs[j];
    for (int sd = 0; sd < nseeds; sd++) {
        snprintf(names[sd], sizeof names[sd], "seed %llu", (unsigned long long)SEEDS[sd]);
        for (int j = 0; j < nn; j++) {
            ys[sd][j] = frac[sd][j] > 0 ? frac[sd][j] : NAN;
            xm[sd][j] = ms[sd][j];
        }
        ser[sd] = (isk_chart_series){names[sd], xs, ys[sd], (size_t)nn, isk_chart_style_default(sd)};
        ser2[sd] = (isk_chart_series){names[sd], xm[sd], ys[sd], (size_t)nn, isk_chart_style_default(sd)};
    }
    char title[160];
    snprintf(title, sizeof title, "Figure 29: particles > 1 px from the %d-substep reference at frame 121", ref_sub);
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = title;
    ch.x_label = "substeps per frame (dt = 1/60)";
    ch.y_label = "fraction of the 16,000 particles";
    ch.x_log = ch.y_log = 1;
    ch.series = ser;
    ch.nseries = (size_t)nseeds;
    ch.legend = ISK_LEGEND_BOTTOM_LEFT;
    if (study_write_chart(o, "thesis_fig29.png", &ch, 1200, 800))
        rc = 1;
    ch.series = ser2;
    ch.x_label = "ms per frame (fastest run)";
    if (study_write_chart(o, "thesis_fig29_time.png", &ch, 1200, 800))
        rc = 1;

    /* Switch-off frames against substeps, a line per (potential, seed). */
    double sy[MAXSEEDS * MAXPOT][MAXN + 1], sx[MAXN + 1];
    char snames[MAXSEEDS * MAXPOT][40];
    isk_chart_series ss[MAXSEEDS * MAXPOT];
    size_t ns = 0;
    for (int j = 0; j <= nn; j++)
        sx[j] = j == nn ? ref_sub : subs[j];
    for (int k = 0; k < npot; k++)
        for (int sd = 0; sd < nseeds; sd++) {
            if (off[sd][0][k] == -2)
                continue;
            for (int j = 0; j <= nn; j++)
                sy[ns][j] = off[sd][j][k] >= 0 ? (double)off[sd][j][k] : NAN;
            snprintf(snames[ns], sizeof snames[ns], "potential %d, seed %llu", k + 1, (unsigned long long)SEEDS[sd]);
            isk_chart_style st = isk_chart_style_default(k);
            st.marker = (isk_chart_marker)(1 + sd % (ISK_MARKER_COUNT - 1));
            ss[ns] = (isk_chart_series){snames[ns], sx, sy[ns], (size_t)nn + 1, st};
            ns++;
        }
    if (ns) {
        isk_chart cs;
        isk_chart_defaults(&cs);
        cs.title = "Figure 29: the frame at which each potential switches itself off";
        cs.x_label = "substeps per frame (the last point: the reference)";
        cs.y_label = "frame";
        cs.x_log = 1;
        cs.series = ss;
        cs.nseries = ns;
        cs.legend = ISK_LEGEND_TOP_RIGHT;
        if (study_write_chart(o, "thesis_fig29_switch.png", &cs, 1200, 800))
            rc = 1;
    }
    return rc;
}
