/* SPDX-License-Identifier: MIT */
/* `iskra bench stability SCENE`: where a scene's step stops being stable.
 *
 * A map over the frame step dt (15 values, dt/2 .. 64 dt of the scene's,
 * sqrt 2 apart) x substeps (1, 2, 4, 8) x the eight integrators.  Every
 * cell runs the scene for the simulated time of its own frames at its own
 * dt (at least MIN_FRAMES frames), and is classed by the first of these
 * tests that holds (docs/accuracy.md, "Stability classes"):
 *
 *   removed      a particle went NaN or infinite and was removed
 *                (isk_effect_removed_nonfinite of any emitter > 0);
 *   growing      energy growing: the largest kinetic energy of all live
 *                particles in the run's second half exceeds GROWTH times
 *                both its largest in the first half and the largest the
 *                reference reaches (it grows, and past what the scene
 *                ever does), or any frame exceeds BLOWN times the
 *                reference's (it blew up at once).  The reference: the
 *                scene's dt under scene_sweep.h's method at REF_FACTOR
 *                times its substeps, over the longest cell's time, seen
 *                at its frames; it sets the scale only.  A trend, not a
 *                level: near its edge a stable method's orbit is bounded
 *                but distorted (semi-implicit Euler's kinetic energy
 *                peaks at 1/(1 - (w h/2)^2) times the true one), which
 *                is not growth;
 *   oscillating  at least 1 % of the particles (and at least one) reversed
 *                their velocity (v . v_before < 0) at ZIGZAG frames in a
 *                row: they zigzag from frame to frame, which no motion
 *                slower than half a frame rate does;
 *   stable       none of these.
 *
 * Kinetic energy, not the total: births, potentials that switch
 * themselves off and moving forces make a scene's total energy jump for
 * reasons that are not the integrator's, and the reference has the same
 * births and switches.  The analytic drag and spring edges
 * (iskra/stability.h) are drawn on the map; the map is deterministic
 * (same scene, same CSV and PNG bytes), and no time is measured.
 * Output: stability_STEM.csv (one row per cell) and stability_STEM.png. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cleanup.h"
#include "iskra/integrate.h"
#include "iskra/limits.h"
#include "iskra/stability.h"
#include "outpath.h"
#include "scene_args.h"
#include "scene_sweep.h"
#include "stability_map.h"
#include "study.h"

enum { MIN_FRAMES = 8, ZIGZAG = 4, REF_FACTOR = 4 };
static const double GROWTH = 2.0, BLOWN = 1e3;
static const double ZIGZAG_SHARE = 0.01;

const char *const stability_class_names[STABILITY_CLASS_COUNT] = {"stable", "oscillating", "growing", "removed"};

/* Per particle slot of one emitter: its last velocity and its run of
 * reversals.  Slots, not particles: a death that moves another particle
 * into a slot can count one false reversal there, and a zigzag needs
 * ZIGZAG in a row. */
typedef struct slots {
    double *vx, *vy;
    int *run;
    unsigned char *zig;
    size_t n;
} slots;

static void slots_free(slots *s)
{
    free(s->vx);
    free(s->vy);
    free(s->run);
    free(s->zig);
    memset(s, 0, sizeof *s);
}

static int slots_grow(slots *s, size_t n)
{
    if (n <= s->n)
        return 0;
    double *vx = realloc(s->vx, n * sizeof *vx), *vy = vx ? realloc(s->vy, n * sizeof *vy) : NULL;
    if (vx)
        s->vx = vx;
    if (vy)
        s->vy = vy;
    int *run = vy ? realloc(s->run, n * sizeof *run) : NULL;
    if (run)
        s->run = run;
    unsigned char *zig = run ? realloc(s->zig, n) : NULL;
    if (!zig)
        return 1;
    s->zig = zig;
    for (size_t i = s->n; i < n; i++) {
        s->vx[i] = s->vy[i] = 0.0;
        s->run[i] = 0;
        s->zig[i] = 0;
    }
    s->n = n;
    return 0;
}

/* The reference's largest kinetic energy at any of its frames over T. */
static int run_reference(isk_effect_def *def, double T, double *kmax, const char *scene)
{
    const char *why;
    int sub = def->substeps * REF_FACTOR;
    sweep_setting set = {sweep_reference(def, &why), sub < ISK_SUBSTEPS_MAX ? sub : ISK_SUBSTEPS_MAX, def->dt};
    const long frames = (long)ceil(T / def->dt - 1e-9);
    isk_effect *fx;
    if (sweep_create("stability", def, &set, &fx))
        return 1;
    isk_status st = ISK_OK;
    size_t seen = sweep_live(fx);
    *kmax = sweep_kinetic(fx);
    for (long f = 1; f <= frames && st == ISK_OK; f++) {
        st = isk_effect_step(fx);
        *kmax = fmax(*kmax, sweep_kinetic(fx));
        seen += sweep_live(fx);
    }
    isk_effect_destroy(fx);
    if (st != ISK_OK) {
        fprintf(stderr, "iskra bench stability: the reference run: %s\n", isk_status_str(st));
        return 1;
    }
    if (seen == 0) {
        fprintf(stderr, "iskra bench stability: %s has no particles in %ld frames (does it wait for a click?): "
                        "nothing to map\n", scene, frames);
        return 1;
    }
    printf("-- reference: %s x%d (%s) at dt %g for %ld frames; its largest kinetic energy %.6g\n",
           isk_integrator_name(set.method), set.substeps, why, set.dt, frames, *kmax);
    return 0;
}

/* Runs one cell and classes it. */
static int run_cell(isk_effect_def *def, double kref, stability_cell *c)
{
    sweep_setting set = {c->method, c->substeps, c->dt};
    isk_effect *fx;
    if (sweep_create("stability", def, &set, &fx))
        return 1;
    const int nem = isk_effect_emitter_count(fx);
    slots *sl = calloc((size_t)(nem > 0 ? nem : 1), sizeof *sl);
    isk_status st = sl ? ISK_OK : ISK_ERR_NOMEM;
    size_t most = sweep_live(fx);
    c->kinetic_ratio = 0.0;
    for (int e = 0; e < nem && st == ISK_OK; e++) {
        const isk_particles *p = isk_effect_particles(fx, e);
        if (slots_grow(&sl[e], p->count))
            st = ISK_ERR_NOMEM;
        for (size_t i = 0; st == ISK_OK && i < p->count; i++) {
            sl[e].vx[i] = p->vx[i];
            sl[e].vy[i] = p->vy[i];
        }
    }
    double early = 0.0, late = 0.0;
    for (long f = 1; f <= c->frames && st == ISK_OK; f++) {
        st = isk_effect_step(fx);
        if (st != ISK_OK)
            break;
        const double k = sweep_kinetic(fx);
        const double ratio = kref > 0 ? k / kref : k > 0 ? INFINITY : 0.0;
        c->kinetic_ratio = fmax(c->kinetic_ratio, isnan(ratio) ? INFINITY : ratio);
        if (2 * f <= c->frames)
            early = fmax(early, k);
        else
            late = fmax(late, k);
        size_t live = sweep_live(fx);
        most = live > most ? live : most;
        for (int e = 0; e < nem && st == ISK_OK; e++) {
            const isk_particles *p = isk_effect_particles(fx, e);
            slots *s = &sl[e];
            size_t old = s->n;
            if (slots_grow(s, p->count)) {
                st = ISK_ERR_NOMEM;
                break;
            }
            for (size_t i = 0; i < p->count; i++) {
                if (i >= old) { /* a new slot: its first velocity */
                    s->vx[i] = p->vx[i];
                    s->vy[i] = p->vy[i];
                    continue;
                }
                int reversed = p->vx[i] * s->vx[i] + p->vy[i] * s->vy[i] < 0;
                s->run[i] = reversed ? s->run[i] + 1 : 0;
                if (s->run[i] >= ZIGZAG)
                    s->zig[i] = 1;
                s->vx[i] = p->vx[i];
                s->vy[i] = p->vy[i];
            }
        }
    }
    c->removed = sweep_removed(fx);
    c->zigzag = 0;
    for (int e = 0; sl && e < nem; e++) {
        for (size_t i = 0; i < sl[e].n; i++)
            c->zigzag += sl[e].zig[i];
        slots_free(&sl[e]);
    }
    free(sl);
    isk_effect_destroy(fx);
    if (st != ISK_OK) {
        fprintf(stderr, "iskra bench stability: %s x%d at dt %g: %s\n", isk_integrator_name(c->method), c->substeps,
                c->dt, isk_status_str(st));
        return 1;
    }
    const int growing = (late > GROWTH * early && late > GROWTH * kref) || !(c->kinetic_ratio <= BLOWN);
    double share = ZIGZAG_SHARE * (double)most;
    c->cls = c->removed > 0                                      ? STABILITY_REMOVED
             : growing                                           ? STABILITY_GROWING
             : c->zigzag > 0 && (double)c->zigzag >= share       ? STABILITY_OSCILLATING
                                                                 : STABILITY_STABLE;
    return 0;
}

static void help(FILE *f)
{
    fprintf(f, "usage: iskra bench stability SCENE [--frames N] [--out DIR]\n"
               "  Runs SCENE (a file or a built-in name) at 15 frame steps from half its\n"
               "  dt to 64 times it, at 1, 2, 4 and 8 substeps, under every\n"
               "  integrator, and classes each cell: stable, oscillating (particles\n"
               "  zigzag frame to frame), growing (kinetic energy past twice the\n"
               "  reference's) or removed (particles went non-finite).  Writes\n"
               "  DIR/stability_NAME.csv and DIR/stability_NAME.png (default DIR\n"
               "  out/stability; missing directories are created), with the drag and\n"
               "  spring edges iskra knows drawn on the map (docs/accuracy.md,\n"
               "  \"Stability map\").\n"
               "  --frames N  each cell simulates N frames of the scene's dt (default:\n"
               "              the scene's frames, else 120), at least %d of its own\n"
               "  exit status: 0 done, 1 a run failed, 2 usage or scene error\n",
            MIN_FRAMES);
}

int bench_stability(int argc, char **argv)
{
    const char *scene = NULL, *out_dir = "out/stability";
    long frames = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help(stdout);
            return 0;
        } else if (!strcmp(argv[i], "--out") || !strcmp(argv[i], "--frames")) {
            if (i + 1 >= argc || !argv[i + 1][0]) {
                fprintf(stderr, "iskra bench stability: %s needs a value\n", argv[i]);
                return 2;
            }
            if (!strcmp(argv[i], "--out"))
                out_dir = argv[++i];
            else if (!arg_long("bench stability", "--frames", argv[++i], 1, 100000000, &frames))
                return 2;
        } else if (argv[i][0] == '-' && argv[i][1]) {
            fprintf(stderr, "iskra bench stability: unknown option '%s'\n", argv[i]);
            help(stderr);
            return 2;
        } else if (scene) {
            fprintf(stderr, "iskra bench stability: one scene only ('%s' and '%s')\n", scene, argv[i]);
            return 2;
        } else {
            scene = argv[i];
        }
    }
    if (!scene) {
        fprintf(stderr, "iskra bench stability: which scene?\n");
        help(stderr);
        return 2;
    }
    stability_map *map = calloc(1, sizeof *map);
    if (!map) {
        fprintf(stderr, "iskra bench stability: out of memory\n");
        return 1;
    }
    int rc = sweep_load("stability", scene, 0, &map->def);
    if (rc) {
        isk_effect_def_free(&map->def);
        free(map);
        return rc;
    }
    if (outpath_make_dirs("bench", out_dir)) {
        isk_effect_def_free(&map->def);
        free(map);
        return 1;
    }
    cleanup_install("bench");
    sweep_stem(scene, map->stem, sizeof map->stem);
    isk_effect_def *def = &map->def;
    const long nframes = frames > 0 ? frames : def->show.frames > 0 ? def->show.frames : 120;
    const double T = (double)nframes * def->dt;
    map->scene_dt = def->dt;
    map->scene_substeps = def->substeps;
    map->scene_method = def->integrator;
    double Tmax = T;
    for (int j = 0; j < STABILITY_NDT; j++) {
        map->dt[j] = def->dt * pow(2.0, (double)(j + STABILITY_DT_FIRST) / 2);
        map->frames[j] = (long)ceil(T / map->dt[j] - 1e-9);
        if (map->frames[j] < MIN_FRAMES)
            map->frames[j] = MIN_FRAMES;
        Tmax = fmax(Tmax, (double)map->frames[j] * map->dt[j]);
    }
    for (int k = 0; k < STABILITY_NSUB; k++)
        map->substeps[k] = 1 << k;
    printf("== stability: %s, %g s simulated per cell (%ld frames of the scene's %g s)\n", map->stem, T, nframes,
           def->dt);
    fflush(stdout);
    double kref = 0.0;
    rc = run_reference(def, Tmax, &kref, scene);
    study_buf csv = {0};
    study_printf(&csv, "scene,integrator,substeps,dt,h,frames,class,removed_nonfinite,kinetic_ratio,"
                       "zigzag_particles,drag_ratio,drag_edge,spring_ratio,spring_edge\n");
    for (int m = 0; m < ISK_INTEGRATOR_COUNT && rc == 0; m++) {
        printf("  %-11s", isk_integrator_name((isk_integrator)m));
        for (int k = 0; k < STABILITY_NSUB && rc == 0; k++) {
            for (int j = 0; j < STABILITY_NDT && rc == 0; j++) {
                stability_cell *c = &map->cell[m][k][j];
                c->method = (isk_integrator)m;
                c->substeps = map->substeps[k];
                c->dt = map->dt[j];
                c->frames = map->frames[j];
                sweep_setting set = {c->method, c->substeps, c->dt};
                c->drag_ratio = sweep_ratio(def, &set, isk_effect_def_drag_ratio);
                c->spring_ratio = sweep_ratio(def, &set, isk_effect_def_spring_ratio);
                rc = run_cell(def, kref, c);
                if (rc)
                    break;
                putchar("sogr"[c->cls]);
                study_printf(&csv, "%s,%s,%d,%.17g,%.17g,%ld,%s,%zu,%.6e,%zu,%.17g,%.17g,%.17g,%.17g\n",
                             map->stem, isk_integrator_name(c->method), c->substeps, c->dt, c->dt / c->substeps,
                             c->frames, stability_class_names[c->cls], c->removed, c->kinetic_ratio, c->zigzag,
                             c->drag_ratio, isk_integrator_drag_edge(c->method), c->spring_ratio,
                             isk_integrator_spring_edge(c->method));
            }
            putchar(' ');
            fflush(stdout);
        }
        putchar('\n');
    }
    if (rc == 0) {
        printf("  (per integrator, substeps 1 2 4 8; per cell: s stable, o oscillating, g growing, r removed)\n");
        study_opts o = {out_dir, 0};
        char file[192];
        snprintf(file, sizeof file, "stability_%s.csv", map->stem);
        rc = study_write_text(&o, file, &csv);
        snprintf(file, sizeof file, "stability_%s.png", map->stem);
        rc |= stability_map_write(&o, file, map);
        if (rc == 0)
            printf("CSV file and map in %s/\n", out_dir);
    }
    study_buf_free(&csv);
    isk_effect_def_free(def);
    free(map);
    return rc;
}
