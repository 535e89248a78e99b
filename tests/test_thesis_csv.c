/* SPDX-License-Identifier: MIT */
/* The --csv output of the single-particle figures (fig10–fig14) must equal,
 * byte for byte, what the thesis's JavaScript computes (IEEE doubles).
 *
 * tests/data/thesis_csv/figNN.csv are golden files made by
 * tests/thesis_js/trajectories.js, a line-by-line transcription of the
 * thesis's classes and loops, run with node:
 *     node tests/thesis_js/trajectories.js fig10 > tests/data/thesis_csv/fig10.csv
 *     node tests/thesis_js/trajectories.js fig14 2000 > tests/data/thesis_csv/fig14.csv
 * Tests here: (1) each example's --csv equals its golden file; (2) when
 * /usr/bin/node exists, the transcription still produces the golden files
 * (so it stays honest) and its %.17g formatter agrees with C's printf on
 * 4000+ values.  Bit equality depends on the build flags (-ffp-contract=off:
 * no fused multiply-add) and on doing the operations in the thesis's order. */
#include <criterion/criterion.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "refimg.h"

#define NODE "/usr/bin/node"
#define GOLDEN "tests/data/thesis_csv/"
#define JS "tests/thesis_js/trajectories.js"

static int run(const char *cmd)
{
    int rc = system(cmd);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    size_t r;
    while (buf && (r = fread(buf + n, 1, cap - n, f)) > 0) {
        n += r;
        if (n == cap) {
            char *nb = realloc(buf, cap *= 2);
            if (!nb) {
                free(buf);
                buf = NULL;
            }
            buf = nb;
        }
    }
    fclose(f);
    *len = n;
    return buf;
}

/* Compares two files; on a difference logs the first differing line. */
static int same_file(const char *a, const char *b)
{
    size_t la, lb;
    char *x = slurp(a, &la), *y = slurp(b, &lb);
    cr_assert_not_null(x, "cannot read %s", a);
    cr_assert_not_null(y, "cannot read %s", b);
    int same = la == lb && memcmp(x, y, la) == 0;
    if (!same) {
        size_t i = 0, line = 1, start = 0;
        while (i < la && i < lb && x[i] == y[i]) {
            if (x[i] == '\n') {
                line++;
                start = i + 1;
            }
            i++;
        }
        cr_log_error("%s and %s differ at line %zu:\n  %.*s\n  %.*s", a, b, line,
                     (int)strcspn(x + start, "\n"), x + start, (int)strcspn(y + start, "\n"), y + start);
    }
    free(x);
    free(y);
    return same;
}

static void example_csv(const char *example, const char *extra, const char *fig)
{
    char cmd[1024], out[256], golden[256];
    mkdir("out", 0777);
    mkdir("out/thesis_csv", 0777);
    snprintf(out, sizeof out, "out/thesis_csv/%s.csv", fig);
    snprintf(golden, sizeof golden, GOLDEN "%s.csv", fig);
    remove(out);
    snprintf(cmd, sizeof cmd, "%s/examples/%s %s --csv %s", refimg_build_dir(), example, extra, out);
    cr_assert_eq(run(cmd), 0, "%s failed", cmd);
    cr_assert(same_file(out, golden), "%s --csv differs from the thesis's JavaScript (%s)", example, golden);
}

Test(thesis_csv, fig10_bit_exact) { example_csv("fig10_trajectory", "", "fig10"); }
Test(thesis_csv, fig11_bit_exact) { example_csv("fig11_drag", "", "fig11"); }
Test(thesis_csv, fig12_bit_exact) { example_csv("fig12_gravity", "", "fig12"); }
Test(thesis_csv, fig13_bit_exact) { example_csv("fig13_drag_gravity", "", "fig13"); }
Test(thesis_csv, fig14_bit_exact) { example_csv("fig14_animation_strip", "--frames 2000", "fig14"); }

Test(thesis_csv, csv_to_stdout_matches_file)
{
    char cmd[1024];
    mkdir("out", 0777);
    mkdir("out/thesis_csv", 0777);
    snprintf(cmd, sizeof cmd, "%s/examples/fig10_trajectory --csv - > out/thesis_csv/stdout10.csv",
             refimg_build_dir());
    cr_assert_eq(run(cmd), 0);
    cr_assert(same_file("out/thesis_csv/stdout10.csv", GOLDEN "fig10.csv"));
}

/* The JavaScript transcription, re-run: it must still produce the golden
 * files (skipped without node). */
static void js_regenerates(const char *fig, const char *arg)
{
    if (access(NODE, X_OK) != 0)
        cr_skip_test("%s not available", NODE);
    char cmd[1024], out[256], golden[256];
    mkdir("out", 0777);
    mkdir("out/thesis_csv", 0777);
    snprintf(out, sizeof out, "out/thesis_csv/%s.js.csv", fig);
    snprintf(golden, sizeof golden, GOLDEN "%s.csv", fig);
    snprintf(cmd, sizeof cmd, NODE " " JS " %s %s > %s", fig, arg, out);
    cr_assert_eq(run(cmd), 0, "%s failed", cmd);
    cr_assert(same_file(out, golden), "node %s no longer gives %s", JS, golden);
}

Test(thesis_js, fig10_regenerates) { js_regenerates("fig10", ""); }
Test(thesis_js, fig11_regenerates) { js_regenerates("fig11", ""); }
Test(thesis_js, fig12_regenerates) { js_regenerates("fig12", ""); }
Test(thesis_js, fig13_regenerates) { js_regenerates("fig13", ""); }
Test(thesis_js, fig14_regenerates) { js_regenerates("fig14", "2000"); }

/* The JS %.17g formatter against C's printf: node prints "hexbits text". */
Test(thesis_js, formatter_matches_printf)
{
    if (access(NODE, X_OK) != 0)
        cr_skip_test("%s not available", NODE);
    FILE *p = popen(NODE " " JS " --selftest", "r");
    cr_assert_not_null(p);
    char hex[32], text[128], ours[128];
    long n = 0, bad = 0;
    while (fscanf(p, "%31s %127s", hex, text) == 2) {
        uint64_t bits = strtoull(hex, NULL, 16);
        double d;
        memcpy(&d, &bits, sizeof d);
        snprintf(ours, sizeof ours, "%.17g", d);
        n++;
        if (strcmp(ours, text)) {
            if (bad++ < 10)
                cr_log_error("%s: js %s, printf %s", hex, text, ours);
        }
    }
    int rc = pclose(p);
    cr_assert(WIFEXITED(rc) && WEXITSTATUS(rc) == 0);
    cr_assert_gt(n, 4000);
    cr_assert_eq(bad, 0, "%ld of %ld values formatted differently", bad, n);
}
