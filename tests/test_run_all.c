/* SPDX-License-Identifier: MIT */
/* The test runner (tests/run_all.sh) says when a binary's tests were
 * skipped, how many and why, instead of reporting "0 tests" as a pass.
 *
 * It runs the runner on a build directory of its own holding only
 * test_thesis_figures (a link to the real one), from a scratch directory
 * where ../shared does not exist, so every thesis-figure test skips.
 * (BXFI_MAP, which Criterion sets in the process running this test, is
 * taken out: a Criterion program that sees it takes itself for a worker.) */
#include <criterion/criterion.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "refimg.h"
#include "tool_cli.h"

#define OUT "out/test_run_all"

Test(run_all, skipped_tests_are_named_with_their_reason, .timeout = 120)
{
    char root[PATH_MAX], build[2 * PATH_MAX + 2], cmd[6 * PATH_MAX];
    cr_assert_not_null(getcwd(root, sizeof root));
    const char *b = refimg_build_dir();
    if (b[0] == '/')
        snprintf(build, sizeof build, "%s", b);
    else
        snprintf(build, sizeof build, "%s/%s", root, b);
    cli_fresh(OUT);
    /* OUT/a/b: its ../shared is OUT/a/shared, which does not exist */
    snprintf(cmd, sizeof cmd,
             "mkdir -p " OUT "/a/b " OUT "/fake/tests && ln -s '%s/tests/test_thesis_figures' " OUT
             "/fake/tests/ && cd " OUT "/a/b && env -u BXFI_MAP ISKRA_TEST_FILTER='*' BUILD='%s/" OUT
             "/fake' sh '%s/tests/run_all.sh' > ../../stdout.txt 2>&1",
             build, root, root);
    int rc = system(cmd);
    char *out = cli_slurp(OUT "/stdout.txt");
    cr_assert_eq(rc, 0, "%s", out);
    cr_assert_not_null(strstr(out, "ok   test_thesis_figures: 0 tests, 9 skipped: no ../shared/reference/thesis-figures/ "
                                   "(the thesis screenshots are not part of the repository) ("),
                       "%s", out);
    cr_assert_not_null(strstr(out, "0 passed, 0 failed"), "%s", out);
    free(out);
}
