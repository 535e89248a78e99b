/* SPDX-License-Identifier: MIT */
/* `iskra bench accuracy`: usage errors exit 2 with a clear message, --help
 * exits 0, and a quick run of the integrator study writes well-formed CSV
 * files (one row per setting) and readable charts.  Timings are machine
 * dependent and never asserted. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include "iskra/png.h"
#include "iskra/problems.h"
#include "refimg.h"
#include "tool_cli.h"

/* Criterion runs tests in parallel: each test has its own directory. */
#define OUT "out/test_bench_cli"
#define USAGE OUT "/usage"
#define HELP OUT "/help"
#define QUICK OUT "/quick"

/* Exit status 2 and `needle` on stderr, nothing on stdout's place. */
static void usage_error(const char *args, const char *needle)
{
    cr_assert_eq(cli_run(USAGE, args), 2, "iskra %s", args);
    char *err = cli_slurp(USAGE "/stderr.txt");
    cr_assert_not_null(strstr(err, needle), "iskra %s: stderr lacks \"%s\":\n%s", args, needle, err);
    free(err);
}

Test(bench_cli, usage_errors)
{
    cli_fresh(USAGE);
    usage_error("bench", "expected 'accuracy'");
    usage_error("bench speed", "expected 'accuracy', got 'speed'");
    usage_error("bench accuracy --bogus", "unknown option '--bogus'");
    usage_error("bench accuracy --only", "--only needs a value");
    usage_error("bench accuracy --out", "--out needs a value");
    usage_error("bench accuracy --quick --only nope --out " USAGE "/none", "no study named 'nope'");
    cr_assert_not(cli_exists(USAGE "/none"), "nothing is written on a usage error");
}

Test(bench_cli, help)
{
    cli_fresh(HELP);
    const char *forms[3] = {"bench --help", "bench accuracy --help", "bench accuracy --quick -h"};
    for (int i = 0; i < 3; i++) {
        cr_assert_eq(cli_run(HELP, forms[i]), 0, "%s", forms[i]);
        char *out = cli_slurp(HELP "/stdout.txt");
        cr_assert_not_null(strstr(out, "usage: iskra bench accuracy"), "%s", forms[i]);
        cr_assert_not_null(strstr(out, "integrators"), "the help names the studies");
        free(out);
    }
}

/* ---- the quick run's files -------------------------------------------------- */

enum { MAX_ROWS = 4096, MAX_COLS = 16 };

typedef struct csv {
    char *text;
    int ncols, nrows;
    char *head[MAX_COLS];
    char *cell[MAX_ROWS][MAX_COLS];
} csv;

/* Splits the file in place into header and rows; every row must have the
 * header's number of fields. */
static void csv_read(csv *c, const char *path)
{
    memset(c, 0, sizeof *c);
    c->text = cli_slurp(path);
    char *line = c->text, *next;
    int row = -1;
    for (; *line; line = next) {
        next = strchr(line, '\n');
        cr_assert_not_null(next, "%s: the last line is not terminated", path);
        *next++ = 0;
        char **dst = row < 0 ? c->head : c->cell[row];
        int n = 0;
        for (char *f = line;; n++) {
            cr_assert_lt(n, MAX_COLS, "%s: too many fields", path);
            dst[n] = f;
            char *comma = strchr(f, ',');
            if (!comma) {
                n++;
                break;
            }
            *comma = 0;
            f = comma + 1;
        }
        if (row < 0)
            c->ncols = n;
        else
            cr_assert_eq(n, c->ncols, "%s row %d: %d fields, the header has %d", path, row + 1, n, c->ncols);
        row++;
        cr_assert_lt(row, MAX_ROWS);
    }
    c->nrows = row;
}

static int col(const csv *c, const char *name)
{
    for (int i = 0; i < c->ncols; i++)
        if (!strcmp(c->head[i], name))
            return i;
    cr_assert_fail("no column %s", name);
    return -1;
}

static double num(const char *s)
{
    char *end;
    double v = strtod(s, &end);
    cr_assert(end != s && *end == 0, "not a number: '%s'", s);
    return v;
}

static int integrator_index(const char *name)
{
    for (int m = 0; m < ISK_INTEGRATOR_COUNT; m++)
        if (!strcmp(name, isk_integrator_name((isk_integrator)m)))
            return m;
    cr_assert_fail("unknown integrator '%s'", name);
    return -1;
}

static void check_csv(isk_problem_kind kind, const char *errors, int nsub)
{
    char path[256], header[512];
    snprintf(path, sizeof path, QUICK "/acc/%s.csv", isk_problem_name(kind));
    csv *c = malloc(sizeof *c);
    csv_read(c, path);
    snprintf(header, sizeof header,
             "problem,integrator,substeps,dt,steps,%s,diverged,ns_per_particle_step,ns_per_particle_run,timing_runs,"
             "timing_spread",
             errors);
    char joined[512] = "";
    for (int i = 0; i < c->ncols; i++)
        snprintf(joined + strlen(joined), sizeof joined - strlen(joined), "%s%s", i ? "," : "", c->head[i]);
    cr_assert_str_eq(joined, header);

    const double T = isk_problem_defaults(kind).T;
    const int ci = col(c, "integrator"), cs = col(c, "substeps"), cdt = col(c, "dt"), cn = col(c, "steps"),
              cdv = col(c, "diverged"), cps = col(c, "ns_per_particle_step"), cpr = col(c, "ns_per_particle_run");
    /* steps seen per (integrator, substeps): every group sweeps the same steps */
    long seen[ISK_INTEGRATOR_COUNT][3][64];
    int nseen[ISK_INTEGRATOR_COUNT][3] = {{0}};
    for (int r = 0; r < c->nrows; r++) {
        char **row = c->cell[r];
        cr_assert_str_eq(row[0], isk_problem_name(kind));
        int m = integrator_index(row[ci]);
        int sub = (int)num(row[cs]);
        cr_assert(sub == 1 || (nsub == 3 && (sub == 2 || sub == 4)), "substeps %d", sub);
        int j = sub == 1 ? 0 : sub == 2 ? 1 : 2;
        double dt = num(row[cdt]), steps = num(row[cn]);
        cr_assert(steps >= 1 && steps == floor(steps));
        cr_assert(fabs(dt * steps - T) < 1e-12 * T, "%s row %d: dt %g x %g steps != T %g", path, r + 1, dt, steps, T);
        for (int k = 0; k < nseen[m][j]; k++)
            cr_assert_neq(seen[m][j][k], (long)steps, "%s row %d repeats a setting", path, r + 1);
        cr_assert_lt(nseen[m][j], 64);
        seen[m][j][nseen[m][j]++] = (long)steps;
        int diverged = (int)num(row[cdv]);
        cr_assert(diverged == 0 || diverged == 1);
        for (int e = 5; e < cdv; e++) {
            double v = num(row[e]); /* strtod reads "inf" and "nan" too */
            if (!diverged)
                cr_assert(isfinite(v) && v >= 0, "%s row %d: %s = %s", path, r + 1, c->head[e], row[e]);
        }
        double ps = num(row[cps]), pr = num(row[cpr]);
        cr_assert(isfinite(ps) && ps > 0 && isfinite(pr) && pr > 0, "%s row %d: timings %g %g", path, r + 1, ps, pr);
        /* the run's cost is the step's cost times the integrator steps (CSV rounding aside) */
        cr_assert(fabs(pr / (ps * steps * sub) - 1) < 0.01, "%s row %d", path, r + 1);
        if (kind == ISK_PROBLEM_PROJECTILE && m == ISK_INTEGRATE_EXACT_DRAG)
            cr_assert_lt(num(row[col(c, "position_error")]), 1e-10, "exact drag is exact");
    }
    int per = nseen[0][0];
    cr_assert_geq(per, 6, "%s: %d step sizes", path, per);
    for (int m = 0; m < ISK_INTEGRATOR_COUNT; m++)
        for (int j = 0; j < nsub; j++) {
            cr_assert_eq(nseen[m][j], per, "%s: %s substeps group %d has %d rows, not %d", path,
                         isk_integrator_name((isk_integrator)m), j, nseen[m][j], per);
            for (int k = 0; k < per; k++)
                cr_assert_eq(seen[m][j][k], seen[0][0][k]);
        }
    cr_assert_eq(c->nrows, ISK_INTEGRATOR_COUNT * nsub * per);
    free(c->text);
    free(c);
}

static void check_png(const char *name)
{
    char path[256];
    snprintf(path, sizeof path, QUICK "/acc/%s", name);
    cli_check_chart(path, 1200, 800);
}

Test(bench_cli, quick_integrator_study_writes_csv_and_charts, .timeout = 120)
{
    cli_fresh(QUICK);
    int rc = cli_run(QUICK, "bench accuracy --quick --only integrators --out " QUICK "/acc");
    char *err = cli_slurp(QUICK "/stderr.txt");
    cr_assert_eq(rc, 0, "exit %d, stderr:\n%s", rc, err);
    free(err);
    char *out = cli_slurp(QUICK "/stdout.txt");
    cr_assert_not_null(strstr(out, "observed order"), "%s", out);
    cr_assert_not_null(strstr(out, "cheapest setting"));
    cr_assert_not_null(strstr(out, "bit-identical"));
    cr_assert_null(strstr(out, "== knobs"), "--only ran one study");
    free(out);
    check_csv(ISK_PROBLEM_PROJECTILE, "position_error,velocity_error", 3);
    check_csv(ISK_PROBLEM_OSCILLATOR, "position_error,velocity_error,energy_error,phase_error", 3);
    check_csv(ISK_PROBLEM_RADIAL, "energy_error", 3);
    check_csv(ISK_PROBLEM_BOUNCE, "position_error,velocity_error,energy_error", 1);
    check_csv(ISK_PROBLEM_KEPLER, "position_error,velocity_error,energy_error,angular_momentum_error,period_error", 1);
    const char *charts[9] = {"projectile.png", "oscillator.png", "oscillator_phase.png", "radial.png", "substeps.png",
                             "bounce.png",     "bounce_energy.png", "kepler.png",        "kepler_period.png"};
    for (int i = 0; i < 9; i++)
        check_png(charts[i]);
}

/* The long run: 10^3 Kepler periods in the quick run.  The symplectic
 * methods' energy error stays bounded; RK4's grows with the time. */
Test(bench_cli, quick_long_run_shows_bounded_against_drifting, .timeout = 120)
{
    cli_fresh(OUT "/longrun");
    cr_assert_eq(cli_run(OUT "/longrun", "bench accuracy --quick --only longrun --out " OUT "/longrun/acc"), 0);
    csv *c = malloc(sizeof *c);
    csv_read(c, OUT "/longrun/acc/longrun.csv");
    const int ci = col(c, "integrator"), cp = col(c, "periods"), ce = col(c, "max_relative_energy_error");
    double first[ISK_INTEGRATOR_COUNT] = {0}, last[ISK_INTEGRATOR_COUNT] = {0};
    for (int r = 0; r < c->nrows; r++) {
        int m = integrator_index(c->cell[r][ci]);
        double p = num(c->cell[r][cp]), e = num(c->cell[r][ce]);
        if (p == 10)
            first[m] = e;
        if (p == 1000)
            last[m] = e;
    }
    const isk_integrator bounded[4] = {ISK_INTEGRATE_VERLET, ISK_INTEGRATE_LEAPFROG, ISK_INTEGRATE_YOSHIDA4,
                                       ISK_INTEGRATE_SEMI_EULER};
    for (int i = 0; i < 4; i++)
        cr_assert(last[bounded[i]] < 2 * first[bounded[i]], "%s: %g -> %g", isk_integrator_name(bounded[i]),
                  first[bounded[i]], last[bounded[i]]);
    cr_assert(last[ISK_INTEGRATE_RK4] > 50 * first[ISK_INTEGRATE_RK4], "rk4: %g -> %g", first[ISK_INTEGRATE_RK4],
              last[ISK_INTEGRATE_RK4]);
    free(c->text);
    free(c);
    cli_check_chart(OUT "/longrun/acc/longrun.png", 1200, 800);
}

/* The thesis's figure 29 against its reference: the files, a row per
 * setting, fractions in [0, 1], the switch-off frames in the scene. */
Test(bench_cli, quick_thesis_scene_study, .timeout = 300)
{
    cli_fresh(OUT "/thesis");
    cr_assert_eq(cli_run(OUT "/thesis", "bench accuracy --quick --only thesis --out " OUT "/thesis/acc"), 0);
    csv *c = malloc(sizeof *c);
    csv_read(c, OUT "/thesis/acc/thesis_fig29.csv");
    cr_assert_eq(c->nrows, 5, "4 substep settings and the reference");
    const int cf = col(c, "fraction_over_1px"), cs = col(c, "substeps");
    for (int r = 0; r < 4; r++) {
        double f = num(c->cell[r][cf]);
        cr_assert(f >= 0 && f <= 1, "row %d: %g", r, f);
    }
    cr_assert_eq(num(c->cell[4][cs]), 32);
    for (int k = 0; k < c->ncols; k++)
        if (strstr(c->head[k], "switch_off_frame"))
            for (int r = 0; r < c->nrows; r++) {
                double v = num(c->cell[r][k]);
                cr_assert(v == -2 || v == -1 || (v >= 1 && v <= 121), "%s = %g", c->head[k], v);
            }
    free(c->text);
    free(c);
    const char *charts[3] = {"thesis_fig29.png", "thesis_fig29_time.png", "thesis_fig29_switch.png"};
    for (int i = 0; i < 3; i++) {
        char path[256];
        snprintf(path, sizeof path, OUT "/thesis/acc/%s", charts[i]);
        cli_check_chart(path, 1200, 800);
    }
}
