/* SPDX-License-Identifier: MIT */
/* `iskra bench accuracy --scene` and `iskra bench stability`: on the
 * accuracy study's projectile written as a scene, the error at each step
 * is the study's figure at that step; the stability map finds explicit
 * Euler's drag edge at exactly b*h/m = 2 (where iskra's cap keeps it
 * stable) and semi-implicit Euler's and RK4's spring edges where the
 * theory puts them; the same scene gives the same map, byte for byte.
 * Timings are machine dependent and never asserted. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/integrate.h"
#include "iskra/problems.h"
#include "iskra/stability.h"
#include "iskra/system.h"
#include "tool_cli.h"
#include "csv_table.h"

#define OUT "out/test_bench_scene"
#define DATA "tests/data/accuracy/"


/* The accuracy study's figure: the projectile problem with one particle,
 * `steps` steps of h under `m`, its position error at the end. */
static double study_figure(isk_integrator m, double h, int steps)
{
    isk_problem p = isk_problem_defaults(ISK_PROBLEM_PROJECTILE);
    p.count = 1;
    isk_system s;
    cr_assert_eq(isk_system_init(&s, 1, 0), ISK_OK);
    cr_assert_eq(isk_problem_setup(&p, &s), ISK_OK);
    cr_assert_eq(isk_system_set_integrator(&s, m), ISK_OK);
    for (int k = 0; k < steps; k++)
        cr_assert_eq(isk_system_step(&s, h), ISK_OK);
    isk_problem_error e;
    cr_assert_eq(isk_problem_measure(&p, &s, &e), ISK_OK);
    isk_system_free(&s);
    return e.position;
}

Test(bench_scene, the_projectile_scene_finds_the_studys_error_at_each_step)
{
    cli_fresh(OUT "/projectile");
    cr_assert_eq(cli_run(OUT "/projectile",
                         "bench accuracy --scene " DATA "projectile.ini --out " OUT "/projectile/acc"),
                 0, "%s", cli_slurp(OUT "/projectile/stderr.txt"));
    csv *c = csv_load(OUT "/projectile/acc/scene_projectile.csv");
    const int cm = csv_col(c, "integrator"), cs = csv_col(c, "substeps"), cw = csv_col(c, "max_world");
    const int cmed = csv_col(c, "median_px"), cp = csv_col(c, "p99_px"), cf = csv_col(c, "frames_compared");
    cr_assert_eq(c->nrows, ISK_INTEGRATOR_COUNT * 4, "every integrator at substeps 1, 2, 4, 8");
    /* The reference (Yoshida 4 at 16 substeps) has an error of its own:
     * exact drag is exact on this problem up to rounding, so its row
     * measures the reference's.  Every run is compared with the
     * reference, not the closed form: it may differ from the study's
     * figure by that much, plus the rounding of one particle's sums. */
    double ref_error = NAN;
    for (int r = 0; r < c->nrows; r++)
        if (!strcmp(c->cell[r][cm], "exact-drag") && !strcmp(c->cell[r][cs], "1"))
            ref_error = csv_num(c->cell[r][cw]);
    cr_assert(ref_error < 1e-9, "the reference is far better than any swept run: %g", ref_error);
    for (int r = 0; r < c->nrows; r++) {
        const int m = csv_integrator(c->cell[r][cm]), sub = (int)csv_num(c->cell[r][cs]);
        const double mine = csv_num(c->cell[r][cw]);
        const double study = study_figure((isk_integrator)m, 0.05 / sub, 40 * sub);
        cr_assert_eq(csv_num(c->cell[r][cf]), 40, "%s x%d compared to the end", c->cell[r][cm], sub);
        cr_assert_leq(fabs(mine - study), 2 * ref_error + 1e-6 * study, "%s x%d: scene %.9e, study %.9e",
                      c->cell[r][cm], sub, mine, study);
        /* one particle: median = p99 = max; one pixel is one metre */
        cr_assert_eq(csv_num(c->cell[r][cmed]), csv_num(c->cell[r][cp]));
        cr_assert_leq(fabs(csv_num(c->cell[r][cmed]) - mine), 1e-9 * (1 + mine), "%s x%d: pixels are metres",
                      c->cell[r][cm], sub);
    }
    csv_free(c);
    c = csv_load(OUT "/projectile/acc/scene_projectile_time.csv");
    cr_assert_eq(c->nrows, ISK_INTEGRATOR_COUNT * 4 * 40, "40 samples (every frame) of every run");
    csv_free(c);
    cli_check_chart(OUT "/projectile/acc/scene_projectile.png", 1400, 900);
    cli_check_chart(OUT "/projectile/acc/scene_projectile_time.png", 1400, 900);
}

/* The map of a scene: runs it into dir and reads the CSV. */
static csv *map_of(const char *dir, const char *scene, const char *stem)
{
    char args[512], path[512];
    cli_fresh(dir);
    snprintf(args, sizeof args, "bench stability " DATA "%s --out %s/map", scene, dir);
    cr_assert_eq(cli_run(dir, args), 0, "%s", args);
    snprintf(path, sizeof path, "%s/map/stability_%s.png", dir, stem);
    cli_check_chart(path, 1600, 800);
    snprintf(path, sizeof path, "%s/map/stability_%s.csv", dir, stem);
    csv *c = csv_load(path);
    cr_assert_eq(c->nrows, ISK_INTEGRATOR_COUNT * 4 * 15, "8 integrators x 4 substeps x 15 steps");
    return c;
}

Test(bench_scene, explicit_eulers_drag_edge_is_exactly_two_and_iskras_cap_keeps_it_stable)
{
    csv *c = map_of(OUT "/drag", "drag_alone.ini", "drag_alone");
    const int cm = csv_col(c, "integrator"), cs = csv_col(c, "substeps"), cd = csv_col(c, "dt"), ch = csv_col(c, "h");
    const int cc = csv_col(c, "class"), cr = csv_col(c, "drag_ratio"), ce = csv_col(c, "drag_edge");
    int below = 0, above = 0, at = 0;
    for (int r = 0; r < c->nrows; r++) {
        if (strcmp(c->cell[r][cm], "euler") != 0)
            continue;
        const double h = csv_num(c->cell[r][ch]), x = csv_num(c->cell[r][cr]);
        cr_assert_eq(csv_num(c->cell[r][ce]), 2.0, "explicit Euler's drag edge is b*h/m = 2 exactly");
        cr_assert_eq(h, csv_num(c->cell[r][cd]) / csv_num(c->cell[r][cs]));
        cr_assert_leq(fabs(x - 120 * h), 1e-13 * x, "b*h/m = 120 h for b = 120, m = 1");
        /* the scene's own cell: b*dt/m = 2, the edge through its middle */
        if (csv_num(c->cell[r][cs]) == 1 && fabs(csv_num(c->cell[r][cd]) - 1.0 / 60) < 1e-15)
            at += fabs(x - 2) < 1e-15;
        below += x < 2 && x > 1.4;
        above += x > 2 && x < 2.9;
        /* iskra caps the drag at b*h/m = 1: on both sides of the textbook
         * edge explicit Euler stops the particle and stays stable */
        cr_assert_str_eq(c->cell[r][cc], "stable", "euler x%s at dt %s (b*h/m %g)", c->cell[r][cs], c->cell[r][cd],
                         x);
    }
    cr_assert_eq(at, 1, "the scene's cell has b*dt/m = 2");
    cr_assert_geq(below, 4, "cells just below the edge");
    cr_assert_geq(above, 4, "cells just above the edge");
    csv_free(c);
}

Test(bench_scene, the_spring_edges_are_where_the_theory_puts_them)
{
    /* omega = 120 * 2^(1/4); semi-implicit Euler is stable for omega h < 2, RK4 for omega h < 2 sqrt 2 */
    const double omega = 120 * pow(2, 0.25);
    csv *c = map_of(OUT "/spring", "spring.ini", "spring");
    const int cm = csv_col(c, "integrator"), ch = csv_col(c, "h"), cc = csv_col(c, "class"), cw = csv_col(c, "spring_ratio");
    const int ce = csv_col(c, "spring_edge");
    int checked[2][2] = {{0}};
    for (int r = 0; r < c->nrows; r++) {
        const char *m = c->cell[r][cm], *cls = c->cell[r][cc];
        /* the line the map draws: w*h from the scene's definition */
        cr_assert_float_eq(csv_num(c->cell[r][cw]), omega * csv_num(c->cell[r][ch]), 1e-12 * omega * csv_num(c->cell[r][ch]));
        cr_assert_eq(csv_num(c->cell[r][ce]), isk_integrator_spring_edge((isk_integrator)csv_integrator(m)));
        const int which = !strcmp(m, "semi-euler") ? 0 : !strcmp(m, "rk4") ? 1 : -1;
        if (which < 0)
            continue;
        const double edge = which == 0 ? 2 : 2 * sqrt(2), wh = omega * csv_num(c->cell[r][ch]);
        const int bad = !strcmp(cls, "growing") || !strcmp(cls, "removed");
        if (wh < 0.97 * edge) {
            cr_assert_not(bad, "%s at omega h = %.3f < %.3f: %s", m, wh, edge, cls);
            checked[which][0]++;
        } else if (wh > 1.03 * edge) {
            cr_assert(bad, "%s at omega h = %.3f > %.3f: %s", m, wh, edge, cls);
            checked[which][1]++;
        }
    }
    for (int i = 0; i < 2; i++)
        cr_assert(checked[i][0] >= 8 && checked[i][1] >= 8, "cells on both sides");
    csv_free(c);
}

Test(bench_scene, the_same_scene_gives_the_same_map)
{
    csv *a = map_of(OUT "/same1", "spring.ini", "spring");
    csv *b = map_of(OUT "/same2", "spring.ini", "spring");
    csv_free(a);
    csv_free(b);
    const char *names[2] = {"stability_spring.csv", "stability_spring.png"};
    for (int i = 0; i < 2; i++) {
        char pa[256], pb[256];
        snprintf(pa, sizeof pa, OUT "/same1/map/%s", names[i]);
        snprintf(pb, sizeof pb, OUT "/same2/map/%s", names[i]);
        FILE *fa = fopen(pa, "rb"), *fb = fopen(pb, "rb");
        cr_assert(fa && fb);
        int x, y;
        long at = 0;
        do {
            x = fgetc(fa);
            y = fgetc(fb);
            cr_assert_eq(x, y, "%s differs at byte %ld", names[i], at);
            at++;
        } while (x != EOF);
        fclose(fa);
        fclose(fb);
    }
}

static void usage_error(const char *args, const char *needle)
{
    cr_assert_eq(cli_run(OUT "/usage", args), 2, "iskra %s", args);
    char *err = cli_slurp(OUT "/usage/stderr.txt");
    cr_assert_not_null(strstr(err, needle), "iskra %s: stderr lacks \"%s\":\n%s", args, needle, err);
    free(err);
}

Test(bench_scene, usage_errors)
{
    cli_fresh(OUT "/usage");
    usage_error("bench stability", "which scene?");
    usage_error("bench stability --out " OUT "/usage/none", "which scene?");
    usage_error("bench stability " DATA "spring.ini " DATA "drag_alone.ini", "one scene only");
    usage_error("bench stability " DATA "spring.ini --frames 0", "--frames");
    usage_error("bench stability " DATA "spring.ini --bogus", "unknown option '--bogus'");
    usage_error("bench stability " DATA "nope.ini --out " OUT "/usage/none", "nope.ini");
    usage_error("bench accuracy --scene " DATA "nope.ini --out " OUT "/usage/none", "nope.ini");
    usage_error("bench accuracy --scene " DATA "spring.ini --only budget", "--scene and --only");
    usage_error("bench accuracy --frames 10", "--frames goes with --scene");
    usage_error("bench accuracy --scene", "--scene needs a value");
    cr_assert_not(cli_exists(OUT "/usage/none"), "nothing is written on a usage or scene error");
    /* a scene that waits for a click has nothing to measure: a failure, said */
    const char *empty[2] = {"bench accuracy --scene fig24_simulator_coulomb --frames 3 --out " OUT "/usage/e1",
                            "bench stability fig24_simulator_coulomb --frames 1 --out " OUT "/usage/e2"};
    for (int i = 0; i < 2; i++) {
        cr_assert_eq(cli_run(OUT "/usage", empty[i]), 1, "%s", empty[i]);
        char *err = cli_slurp(OUT "/usage/stderr.txt");
        cr_assert_not_null(strstr(err, "has no particles in"), "%s", err);
        free(err);
    }
    cr_assert_eq(cli_run(OUT "/usage", "bench stability --help"), 0);
    char *out = cli_slurp(OUT "/usage/stdout.txt");
    cr_assert_not_null(strstr(out, "usage: iskra bench stability SCENE"));
    free(out);
}

Test(bench_scene, a_run_that_loses_other_particles_is_compared_until_then)
{
    /* semi-Euler's first-order error moves some impacts on the killing
     * floor into other frames than the reference's: from the first frame
     * where the counts differ the run is compared no more; RK4's impacts
     * fall in the reference's frames to the end */
    cli_fresh(OUT "/kill");
    cr_assert_eq(cli_run(OUT "/kill", "bench accuracy --scene " DATA "kill_floor.ini --out " OUT "/kill/acc"), 0);
    csv *c = csv_load(OUT "/kill/acc/scene_kill_floor.csv");
    const int cm = csv_col(c, "integrator"), cs = csv_col(c, "substeps"), cf = csv_col(c, "frames_compared");
    long semi = -1, rk4 = -1;
    for (int r = 0; r < c->nrows; r++) {
        if (strcmp(c->cell[r][cs], "1") != 0)
            continue;
        if (!strcmp(c->cell[r][cm], "semi-euler"))
            semi = (long)csv_num(c->cell[r][cf]);
        if (!strcmp(c->cell[r][cm], "rk4"))
            rk4 = (long)csv_num(c->cell[r][cf]);
    }
    cr_assert(semi > 0 && semi < 60, "semi-euler x1 compared until frame %ld", semi);
    cr_assert_eq(rk4, 60);
    csv_free(c);
    /* the time CSV has the compared samples only (every frame is one here) */
    c = csv_load(OUT "/kill/acc/scene_kill_floor_time.csv");
    const int tm = csv_col(c, "integrator"), ts = csv_col(c, "substeps"), tt = csv_col(c, "time");
    long n = 0;
    double last = 0;
    for (int r = 0; r < c->nrows; r++)
        if (!strcmp(c->cell[r][tm], "semi-euler") && !strcmp(c->cell[r][ts], "1")) {
            n++;
            last = csv_num(c->cell[r][tt]);
        }
    cr_assert_eq(n, semi);
    cr_assert_float_eq(last, semi / 30.0, 1e-9); /* the CSV has 10 digits */
    csv_free(c);
}
