/* SPDX-License-Identifier: MIT */
/* Every shipped scene rendered by the iskra tool with its n-th allocation
 * failing, for every n up to the number it makes: each run must either stop
 * with exit status 1, "out of memory" on stderr and no output file, or
 * recover (a full sprite cache is cleared and baked again) and write
 * exactly the image of a run without failures — no crash, no hang, no other
 * message, and (in the sanitizer build) no leak.  The tool
 * is built with tests/alloc/alloc_fail.c wrapping malloc, calloc, realloc
 * and aligned_alloc (iskra's own allocations; libpng's are its own). */
#include <criterion/criterion.h>
#include <criterion/parameterized.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "iskra/scene.h"
#include "refimg.h"
#include "tool_cli.h"

#define OUT "out/test_alloc_fail"

/* The scenes are shared out (scene i to share i % SHARES), each share in
 * its own directory, so Criterion runs the shares on every core at once. */
enum { SHARES = 4 };

/* Runs the tool; returns its exit status, stderr in dir/stderr.txt. */
static int run(const char *dir, const char *env, const char *args)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s %s/tests/iskra_allocfail %s >/dev/null 2>%s/stderr.txt", env, refimg_build_dir(),
             args, dir);
    int st = system(cmd);
    cr_assert(WIFEXITED(st), "%s: killed by a signal", cmd);
    return WEXITSTATUS(st);
}

ParameterizedTestParameters(alloc_fail, every_allocation_of_every_scene_fails_cleanly)
{
    static int share[SHARES];
    for (int i = 0; i < SHARES; i++)
        share[i] = i;
    return cr_make_param_array(int, share, SHARES);
}

ParameterizedTest(int *share, alloc_fail, every_allocation_of_every_scene_fails_cleanly, .timeout = 900)
{
    char dir[64], path[96], want[96], stderr_path[96];
    snprintf(dir, sizeof dir, OUT "/share%d", *share);
    snprintf(path, sizeof path, "%s/x.png", dir);
    snprintf(want, sizeof want, "%s/want.png", dir);
    snprintf(stderr_path, sizeof stderr_path, "%s/stderr.txt", dir);
    cli_fresh(dir);
    long total = 0, recovered = 0;
    for (int i = *share; i < isk_scene_builtin_count(); i += SHARES) {
        const char *name = isk_scene_builtin_name(i);
        char args[256];
        snprintf(args, sizeof args, "render %s --frames 3 --size 64x64 --out %s", name, path);
        cr_assert_eq(run(dir, "ISKRA_ALLOC_COUNT=1", args), 0, "%s without failures", name);
        cr_assert_eq(rename(path, want), 0);
        char *err = cli_slurp(stderr_path);
        long n = 0;
        const char *a = strstr(err, "allocations: ");
        cr_assert_not_null(a, "%s: %s", name, err);
        n = atol(a + 13);
        free(err);
        cr_assert_gt(n, 5, "%s", name);
        for (long k = 1; k <= n; k++) {
            char env[64];
            snprintf(env, sizeof env, "ISKRA_ALLOC_FAIL=%ld", k);
            remove(path);
            int rc = run(dir, env, args);
            char *msg = cli_slurp(stderr_path);
            if (rc == 0) {
                char cmp[256];
                snprintf(cmp, sizeof cmp, "cmp -s %s %s", path, want);
                cr_assert_eq(system(cmp), 0,
                             "%s, allocation %ld of %ld: recovered, but the image differs", name, k, n);
                recovered++;
            } else {
                cr_assert_eq(rc, 1, "%s, allocation %ld of %ld failing: exit %d: %s", name, k, n, rc, msg);
                cr_assert_not_null(strstr(msg, "out of memory"), "%s, allocation %ld of %ld: %s", name, k, n, msg);
                cr_assert_not(cli_exists(path), "%s, allocation %ld: wrote its output anyway", name, k);
            }
            free(msg);
        }
        total += n;
    }
    cr_assert_gt(total, 300 / SHARES);
    cr_assert_lt(recovered, total / 10, "most failures must stop the run: %ld of %ld recovered", recovered, total);
}
