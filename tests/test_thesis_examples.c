/* SPDX-License-Identifier: MIT */
/* Facts about the thesis-figure examples, checked on their output:
 * the trajectories' bounces and resting point (from --csv, catalogue
 * §5.5–5.8), and the determinism of the random animated examples (same
 * seed -> byte-identical PNG, different seed -> a different one). */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include "refimg.h"

typedef struct row {
    long step;
    double dx, dy, x, y, vx, vy;
} row;

static int run(const char *cmd)
{
    int rc = system(cmd);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

/* Runs `example --csv` and reads every row; returns the row count. */
static long read_csv(const char *example, row *rows, long max)
{
    char cmd[1024], path[256];
    mkdir("out", 0777);
    mkdir("out/thesis_csv", 0777);
    snprintf(path, sizeof path, "out/thesis_csv/%s.facts.csv", example);
    snprintf(cmd, sizeof cmd, "%s/examples/%s --csv %s", refimg_build_dir(), example, path);
    cr_assert_eq(run(cmd), 0, "%s failed", cmd);
    FILE *f = fopen(path, "r");
    cr_assert_not_null(f);
    char line[1024];
    cr_assert_not_null(fgets(line, sizeof line, f));
    cr_assert_str_eq(line, "step,drawn_x,drawn_y,x,y,vx,vy\n");
    long n = 0;
    while (n < max && fgets(line, sizeof line, f)) {
        row *r = &rows[n];
        cr_assert_eq(sscanf(line, "%ld,%lf,%lf,%lf,%lf,%lf,%lf", &r->step, &r->dx, &r->dy, &r->x, &r->y,
                            &r->vx, &r->vy), 7, "bad line %s", line);
        cr_assert_eq(r->step, n + 1);
        n++;
    }
    fclose(f);
    return n;
}

/* Steps whose drawn position is below the floor y = -10 + 0.1: exactly the
 * steps on which zarobi flips and clamps. */
static long floor_bounces(const row *r, long n, long *first)
{
    const double floor_y = -10.0 + 0.1;
    long k = 0;
    *first = -1;
    for (long i = 0; i < n; i++)
        if (r[i].dy < floor_y) {
            if (*first < 0)
                *first = r[i].step;
            k++;
            cr_assert_eq(r[i].y, floor_y, "step %ld: bounce must clamp to the floor", r[i].step);
        }
    return k;
}

static row rows[1000];

Test(thesis_facts, fig10_one_bounce_at_step_12)
{
    long n = read_csv("fig10_trajectory", rows, 1000), first;
    cr_assert_eq(n, 1000);
    cr_assert_eq(floor_bounces(rows, n, &first), 1);
    cr_assert_eq(first, 12);
    /* no force: the velocity only ever changes sign */
    for (long i = 0; i < n; i++)
        cr_assert(rows[i].vx == 1.0 && fabs(rows[i].vy) == 2.0);
}

Test(thesis_facts, fig11_one_bounce_and_rest)
{
    long n = read_csv("fig11_drag", rows, 1000), first;
    cr_assert_eq(n, 1000);
    cr_assert_eq(floor_bounces(rows, n, &first), 1);
    const row *last = &rows[n - 1];
    cr_assert(fabs(last->x - 5.75) < 1e-4 && fabs(last->y - 3.4384) < 1e-4, "rests at (%.6f, %.6f)",
              last->x, last->y);
    cr_assert_lt(hypot(last->vx, last->vy), 1e-9);
}

Test(thesis_facts, fig12_twelve_bounces)
{
    long n = read_csv("fig12_gravity", rows, 1000), first;
    cr_assert_eq(n, 1000);
    cr_assert_eq(floor_bounces(rows, n, &first), 12);
}

Test(thesis_facts, fig13_788_bounces_and_jitter)
{
    long n = read_csv("fig13_drag_gravity", rows, 1000), first;
    cr_assert_eq(n, 1000);
    cr_assert_eq(floor_bounces(rows, n, &first), 788);
    /* at the end: drawn just below the floor every other step (the 2-cycle) */
    const row *a = &rows[n - 1], *b = &rows[n - 2];
    double lowest = a->dy < b->dy ? a->dy : b->dy;
    cr_assert(fabs(lowest - -9.9079) < 1e-3, "lowest drawn y %.6f", lowest);
    cr_assert(fabs(fabs(a->vy) - 0.03165) < 1e-4, "|vy| %.6f", fabs(a->vy));
}

/* ---- determinism of the random animated examples ------------------------ */

static int files_equal(const char *a, const char *b)
{
    FILE *f = fopen(a, "rb"), *g = fopen(b, "rb");
    cr_assert(f && g);
    int same = 1, c, d;
    do {
        c = fgetc(f);
        d = fgetc(g);
        if (c != d)
            same = 0;
    } while (same && c != EOF);
    fclose(f);
    fclose(g);
    return same;
}

static void render_seed(const char *example, const char *seed, const char *tag, char *png, size_t len)
{
    char cmd[1024];
    mkdir("out", 0777);
    mkdir("out/determinism", 0777);
    snprintf(png, len, "out/determinism/%s.%s.png", example, tag);
    remove(png);
    /* a short run: determinism does not need the default frame */
    snprintf(cmd, sizeof cmd, "%s/examples/%s --frames 60 --seed %s --png %s", refimg_build_dir(), example,
             seed, png);
    cr_assert_eq(run(cmd), 0, "%s failed", cmd);
}

static void deterministic(const char *example)
{
    char a[256], b[256], c[256];
    render_seed(example, "7", "a", a, sizeof a);
    render_seed(example, "7", "b", b, sizeof b);
    render_seed(example, "8", "c", c, sizeof c);
    cr_assert(files_equal(a, b), "%s: the same seed gave different images", example);
    cr_assert_not(files_equal(a, c), "%s: different seeds gave the same image", example);
}

Test(determinism, fig17_uniform) { deterministic("fig17_uniform"); }
Test(determinism, fig18_gauss) { deterministic("fig18_gauss"); }
Test(determinism, fig19_coulomb) { deterministic("fig19_coulomb"); }
Test(determinism, fig20_multi_coulomb) { deterministic("fig20_multi_coulomb"); }
Test(determinism, fig26_mushroom_one_potential) { deterministic("fig26_mushroom_one_potential"); }
Test(determinism, fig27_mushroom_moving_potential) { deterministic("fig27_mushroom_moving_potential"); }
Test(determinism, fig28_mushroom_three_potentials) { deterministic("fig28_mushroom_three_potentials"); }
Test(determinism, fig29_mushroom_four_potentials) { deterministic("fig29_mushroom_four_potentials"); }

/* The ring has no randomness: no --seed option, and the same image twice. */
Test(determinism, fig16_regular_has_no_seed)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s/examples/fig16_regular --seed 3 --png out/x.png 2>/dev/null",
             refimg_build_dir());
    cr_assert_eq(run(cmd), 2);
}

/* Every new example: --help exits 0, a bad option exits 2. */
Test(thesis_facts, options)
{
    static const char *names[] = {"fig09_stationary_particle", "fig10_trajectory", "fig14_animation_strip",
                                  "fig16_regular", "fig20_multi_coulomb", "fig29_mushroom_four_potentials"};
    char cmd[1024];
    for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
        snprintf(cmd, sizeof cmd, "%s/examples/%s --help >/dev/null", refimg_build_dir(), names[i]);
        cr_assert_eq(run(cmd), 0, "%s --help", names[i]);
        snprintf(cmd, sizeof cmd, "%s/examples/%s --frames x 2>/dev/null", refimg_build_dir(), names[i]);
        cr_assert_eq(run(cmd), 2, "%s --frames x", names[i]);
    }
}
