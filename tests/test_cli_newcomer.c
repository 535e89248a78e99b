/* SPDX-License-Identifier: MIT */
/* What a newcomer meets first: every output of every command creates its
 * missing parent directories and works from any working directory (not
 * only the repository), scene names get a did-you-mean, `iskra list`
 * describes each scene, and fire_campfire's help names all its options. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "refimg.h"
#include "tool_cli.h"

#define OUT "out/test_cli_newcomer"

/* A fresh scratch directory outside the repository. */
static void scratch(char *dir, size_t n, const char *tag)
{
    snprintf(dir, n, "/tmp/iskra-newcomer-%s-XXXXXX", tag);
    cr_assert_not_null(mkdtemp(dir), "mkdtemp");
}

static void remove_tree(const char *dir)
{
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    cr_assert_eq(system(cmd), 0);
}

static int exists_in(const char *dir, const char *rel)
{
    char p[1024];
    snprintf(p, sizeof p, "%s/%s", dir, rel);
    return cli_exists(p);
}

Test(newcomer, every_output_creates_its_parents_from_any_directory, .timeout = 120)
{
    const char *log = OUT "/parents";
    cli_fresh(log);
    char tmp[256];
    scratch(tmp, sizeof tmp, "parents");
    cr_assert_eq(cli_run_in(tmp, log, "render fig09_stationary_particle --out a/b/c.png"), 0, "%s",
                 cli_slurp(OUT "/parents/stderr.txt"));
    cr_assert(exists_in(tmp, "a/b/c.png"));
    cr_assert_eq(cli_run_in(tmp, log, "render fig16_regular --frames 2 --out-dir d/e/f"), 0);
    cr_assert(exists_in(tmp, "d/e/f/frame_000002.png"));
    cr_assert_eq(cli_run_in(tmp, log, "compare a/b/c.png d/e/f/frame_000000.png --diff g/h/diff.png"), 1);
    cr_assert(exists_in(tmp, "g/h/diff.png"));
    cr_assert_eq(cli_run_in(tmp, log, "bench accuracy --quick --only knobs --out x/y/z"), 0, "%s",
                 cli_slurp(OUT "/parents/stderr.txt"));
    cr_assert(exists_in(tmp, "x/y/z/sine.csv"));
    cr_assert(exists_in(tmp, "x/y/z/sine.png"));
    /* the default output directory is relative to where the command runs */
    cr_assert_eq(cli_run_in(tmp, log, "bench accuracy --quick --only knobs"), 0);
    cr_assert(exists_in(tmp, "out/accuracy/ellipse.csv"));
    remove_tree(tmp);
}

Test(newcomer, play_shots_go_where_asked)
{
    const char *log = OUT "/shots";
    cli_fresh(log);
    char tmp[256];
    scratch(tmp, sizeof tmp, "shots");
    int rc = cli_run_in(tmp, log, "play fig16_regular --frames 3 --shots s/t --script f12");
    char *err = cli_slurp(OUT "/shots/stderr.txt");
    if (rc == 1 && strstr(err, "window")) {
        remove_tree(tmp);
        cr_skip("no SDL video available: %s", err);
    }
    cr_assert_eq(rc, 0, "%s", err);
    cr_assert_not_null(strstr(err, "F12 screenshots go to s/t"), "%s", err);
    cr_assert_not_null(strstr(err, "saved s/t/iskra-fig16_regular-"), "%s", err);
    free(err);
    /* without --shots: the current directory, named on stderr */
    cr_assert_eq(cli_run_in(tmp, log, "play fig16_regular --frames 2"), 0);
    err = cli_slurp(OUT "/shots/stderr.txt");
    cr_assert_not_null(strstr(err, "F12 screenshots go to /tmp/iskra-newcomer-shots-"), "%s", err);
    free(err);
    cr_assert_eq(cli_run_in(tmp, log, "play fig16_regular --frames 2 --shots ''"), 2);
    remove_tree(tmp);
}

Test(newcomer, a_parent_that_cannot_be_made_is_exit_1_with_the_reason)
{
    const char *log = OUT "/blocked";
    cli_fresh(log);
    FILE *f = fopen(OUT "/blocked/plain", "w");
    cr_assert_not_null(f);
    fclose(f);
    cr_assert_eq(cli_run(log, "render fig09_stationary_particle --out " OUT "/blocked/plain/sub/x.png"), 1);
    char *err = cli_slurp(OUT "/blocked/stderr.txt");
    cr_assert_not_null(strstr(err, "cannot create directory " OUT "/blocked/plain: Not a directory"), "%s", err);
    free(err);
    cr_assert_eq(cli_run(log, "bench accuracy --quick --only knobs --out " OUT "/blocked/plain/acc"), 1);
    err = cli_slurp(OUT "/blocked/stderr.txt");
    cr_assert_not_null(strstr(err, "cannot create directory"), "%s", err);
    free(err);
}

Test(newcomer, scene_names_get_a_did_you_mean)
{
    const char *log = OUT "/dym";
    cli_fresh(log);
    static const struct {
        const char *given, *hint;
    } cases[] = {
        {"fig19", "did you mean fig19_coulomb?"},
        {"campfire", "did you mean fire_campfire?"},
        {"fig12_gravty", "did you mean fig12_gravity?"},
        {"mushroom", "did you mean fig26_mushroom_one_potential, fig27_mushroom_moving_potential, "
                     "fig28_mushroom_three_potentials or fig29_mushroom_four_potentials?"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char args[256];
        snprintf(args, sizeof args, "render %s --out " OUT "/dym/x.png", cases[i].given);
        cr_assert_eq(cli_run(log, args), 2, "%s", args);
        char *err = cli_slurp(OUT "/dym/stderr.txt");
        cr_assert_not_null(strstr(err, cases[i].hint), "%s: %s", cases[i].given, err);
        free(err);
        cr_assert_not(cli_exists(OUT "/dym/x.png"));
    }
    cr_assert_eq(cli_run(log, "describe zzzz"), 2);
    char *err = cli_slurp(OUT "/dym/stderr.txt");
    cr_assert_not_null(strstr(err, "`iskra list` shows them"), "%s", err);
    free(err);
}

Test(newcomer, list_describes_every_scene_in_one_line)
{
    const char *log = OUT "/list";
    cli_fresh(log);
    cr_assert_eq(cli_run(log, "list"), 0);
    char *out = cli_slurp(OUT "/list/stdout.txt");
    cr_assert_not_null(strstr(out, "fig12_gravity  "), "%s", out);
    cr_assert_not_null(strstr(out, "Thesis figure 12: the trajectory of figure 10 under gravity.\n"), "%s", out);
    int lines = 0;
    for (char *line = out, *nl; (nl = strchr(line, '\n')); line = nl + 1, lines++) {
        cr_assert_leq(nl - line, 100, "line %d is wider than 100 columns", lines + 1);
        char *gap = strstr(line, "  ");
        cr_assert(gap && gap < nl, "line %d has no description", lines + 1);
        while (*gap == ' ')
            gap++;
        cr_assert_gt(nl - gap, 10, "line %d: description too short", lines + 1);
    }
    cr_assert_eq(cli_run(log, "list --names"), 0);
    char *names = cli_slurp(OUT "/list/stdout.txt");
    cr_assert_not_null(strstr(names, "\nfig12_gravity\n"), "%s", names);
    int nnames = 0;
    for (char *p = names; *p; p++)
        nnames += *p == '\n';
    cr_assert_eq(nnames, lines);
    free(names);
    free(out);
}

static int campfire(const char *args, const char *log)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s/examples/fire_campfire %s >%s/stdout.txt 2>%s/stderr.txt", refimg_build_dir(), args,
             log, log);
    int rc = system(cmd);
    cr_assert(WIFEXITED(rc));
    return WEXITSTATUS(rc);
}

Test(newcomer, fire_campfire_help_names_its_own_options)
{
    const char *log = OUT "/campfire";
    cli_fresh(log);
    cr_assert_eq(campfire("--help", log), 0);
    char *out = cli_slurp(OUT "/campfire/stdout.txt");
    cr_assert_not_null(strstr(out, "--wind X"), "%s", out);
    cr_assert_not_null(strstr(out, "--strip PATH"), "%s", out);
    cr_assert_not_null(strstr(out, "--seed N"), "%s", out);
    free(out);
    const char *missing[] = {"--wind", "--strip", "--png " OUT "/campfire/x.png --wind"};
    const char *opt[] = {"--wind", "--strip", "--wind"};
    for (int i = 0; i < 3; i++) {
        cr_assert_eq(campfire(missing[i], log), 2, "%s", missing[i]);
        char *err = cli_slurp(OUT "/campfire/stderr.txt");
        char want[64];
        snprintf(want, sizeof want, "fire_campfire: %s needs a value", opt[i]);
        cr_assert_not_null(strstr(err, want), "%s: %s", missing[i], err);
        cr_assert_null(strstr(err, "unknown option"), "%s: %s", missing[i], err);
        free(err);
    }
    cr_assert_not(cli_exists(OUT "/campfire/x.png"));
}
