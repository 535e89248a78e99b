/* SPDX-License-Identifier: MIT */
/* iskra bench accuracy [--out DIR] [--quick] [--only STUDY]
 * iskra bench accuracy --scene SCENE [--frames N] [--out DIR]
 * iskra bench stability SCENE [--frames N] [--out DIR]
 * What accuracy costs in time: every study measures error against time on
 * problems with known answers and writes a CSV and a chart per problem;
 * --scene does it for any scene against a reference run of it; stability
 * maps where a scene's step stops being stable (study_stability.c). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cleanup.h"
#include "cmd.h"
#include "outpath.h"
#include "scene_args.h"
#include "stability_map.h"
#include "study.h"

typedef struct study_entry {
    const char *name;
    const char *summary;
    int (*run)(const study_opts *o);
} study_entry;

static const study_entry studies[] = {
    {"integrators", "integrator x step x substeps on five closed-form problems", study_integrators},
    {"longrun", "energy over 10^5 Kepler periods: symplectic bounded, RK4 drifting", study_longrun},
    {"thesis", "fig 29 against a 256-substep reference: pixels off, switch-off frames, seeds", study_thesis},
    {"budget", "error against simulated time at the cost of 16 semi-Euler substeps per frame", study_budget},
    {"invariants", "what each integrator keeps: modified energy, Kepler period, the Euler forms' invariant",
     study_invariants},
    {"knobs", "sine table (and on the campfire), emission modes, ellipse sampler, float vs double", study_knobs},
    {"spring-floor", "a spring on a restitution-1 floor: energy per bounce, every integrator at 1/60 and 1/240",
     study_spring_floor},
};
enum { NSTUDIES = sizeof studies / sizeof studies[0] };

static void help(FILE *f)
{
    fprintf(f, "usage: iskra bench accuracy [--out DIR] [--quick] [--only STUDY]\n"
               "       iskra bench accuracy --scene SCENE [--frames N] [--out DIR]\n"
               "       iskra bench stability SCENE [--frames N] [--out DIR]\n"
               "  Measures error against time per particle-step and writes CSV files and\n"
               "  work-precision charts (PNG) into DIR (default out/accuracy, relative\n"
               "  to the current directory; missing directories are created).\n"
               "  --quick       fewer repetitions and shorter sweeps (a smoke run)\n"
               "  --only STUDY  run one study:");
    for (int i = 0; i < NSTUDIES; i++)
        fprintf(f, " %s", studies[i].name);
    fprintf(f, "\n  studies:\n");
    for (int i = 0; i < NSTUDIES; i++)
        fprintf(f, "    %-12s %s\n", studies[i].name, studies[i].summary);
    fprintf(f, "  --scene SCENE a scene file or built-in name: error in pixels against a\n"
               "                reference run of it, against time per frame, for every\n"
               "                integrator at 1, 2, 4, 8 times its substeps\n"
               "                (scene_NAME.csv, .png, _time.csv, _time.png)\n"
               "  --frames N    frames run (default: the scene's frames, else 120)\n"
               "  stability     a map over step x substeps x integrator, each cell\n"
               "                stable, oscillating, energy growing or removed as\n"
               "                non-finite, with the drag and spring edges iskra knows\n"
               "                (stability_NAME.csv, .png; default --out out/stability)\n"
               "  Timings depend on the machine and its load; read the ratios.\n"
               "  exit status: 0 done, 1 a study failed, 2 usage error\n");
}

int cmd_bench(int argc, char **argv)
{
    if (argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
        help(stdout);
        return 0;
    }
    if (argc >= 2 && !strcmp(argv[1], "stability"))
        return bench_stability(argc - 1, argv + 1);
    if (argc < 2 || strcmp(argv[1], "accuracy") != 0) {
        fprintf(stderr, "iskra bench: expected 'accuracy' or 'stability'%s%s%s\n", argc >= 2 ? ", got '" : "",
                argc >= 2 ? argv[1] : "", argc >= 2 ? "'" : "");
        help(stderr);
        return 2;
    }
    study_opts o = {"out/accuracy", 0};
    const char *only = NULL, *scene = NULL;
    long frames = 0;
    for (int i = 2; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help(stdout);
            return 0;
        } else if (!strcmp(argv[i], "--quick")) {
            o.quick = 1;
        } else if (!strcmp(argv[i], "--out") || !strcmp(argv[i], "--only") || !strcmp(argv[i], "--scene") ||
                   !strcmp(argv[i], "--frames")) {
            if (i + 1 >= argc || !argv[i + 1][0]) {
                fprintf(stderr, "iskra bench: %s needs a value\n", argv[i]);
                return 2;
            }
            if (!strcmp(argv[i], "--out"))
                o.out_dir = argv[++i];
            else if (!strcmp(argv[i], "--scene"))
                scene = argv[++i];
            else if (!strcmp(argv[i], "--frames")) {
                if (!arg_long("bench", "--frames", argv[++i], 1, 100000000, &frames))
                    return 2;
            } else
                only = argv[++i];
        } else {
            fprintf(stderr, "iskra bench: unknown option '%s'\n", argv[i]);
            help(stderr);
            return 2;
        }
    }
    if (scene && only) {
        fprintf(stderr, "iskra bench: --scene and --only do not go together\n");
        return 2;
    }
    if (frames && !scene) {
        fprintf(stderr, "iskra bench: --frames goes with --scene\n");
        return 2;
    }
    if (scene) {
        int rc = study_scene(&o, scene, frames);
        if (rc == 0)
            printf("CSV files and charts in %s/\n", o.out_dir);
        return rc;
    }
    int found = !only;
    for (int i = 0; only && i < NSTUDIES; i++)
        found |= !strcmp(only, studies[i].name);
    if (!found) {
        fprintf(stderr, "iskra bench: no study named '%s'\n", only);
        help(stderr);
        return 2;
    }
    /* Before the first study: a bad --out fails now, not after a long run. */
    if (outpath_make_dirs("bench", o.out_dir))
        return 1;
    cleanup_install("bench");
    int rc = 0;
    for (int i = 0; i < NSTUDIES; i++) {
        if (only && strcmp(only, studies[i].name) != 0)
            continue;
        printf("== %s: %s\n\n", studies[i].name, studies[i].summary);
        fflush(stdout);
        if (studies[i].run(&o) != 0)
            rc = 1;
    }
    if (rc == 0)
        printf("CSV files and charts in %s/\n", o.out_dir);
    return rc;
}
