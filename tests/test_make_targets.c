/* SPDX-License-Identifier: MIT */
/* What the Makefile's user-facing targets build, read from `make -n` (the
 * commands make would run, none of them run) on an empty build directory:
 * `make run` builds the iskra tool and the libraries it links, never the
 * tests, examples or benchmarks (the demo needs none of them). */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tool_cli.h"

#define OUT "out/test_make_targets"

/* `make -n TARGET` with BUILD=OUT/build (never built: every command shows),
 * outside any make running this test (its jobserver is not ours). */
static char *dry_run(const char *target)
{
    char cmd[512];
    snprintf(cmd, sizeof cmd,
             "env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -n --no-print-directory %s BUILD=" OUT
             "/build > " OUT "/%s.txt 2>&1",
             target, target);
    cr_assert_eq(system(cmd), 0, "%s failed", cmd);
    char path[256];
    snprintf(path, sizeof path, OUT "/%s.txt", target);
    return cli_slurp(path);
}

Test(make_targets, run_builds_the_tool_and_nothing_else, .timeout = 120)
{
    cli_fresh(OUT);
    char *out = dry_run("run");
    cr_assert_not_null(strstr(out, "-o " OUT "/build/bin/iskra "), "make run does not build the tool:\n%s", out);
    cr_assert_not_null(strstr(out, "tools/run_demo.sh"), "%s", out);
    const char *never[] = {" tests/", " bench/", " examples/", "/tests/", "/bench/", "/examples/"};
    for (size_t i = 0; i < sizeof never / sizeof never[0]; i++) {
        const char *hit = strstr(out, never[i]);
        cr_assert_null(hit, "make run builds '%s' (the demo needs only the tool): %.200s", never[i], hit);
    }
    free(out);
}
