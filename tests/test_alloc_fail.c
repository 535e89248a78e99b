/* Every shipped scene rendered by the iskra tool with its n-th allocation
 * failing, for every n up to the number it makes: each run must either stop
 * with exit status 1, "out of memory" on stderr and no output file, or
 * recover (a full sprite cache is cleared and baked again) and write
 * exactly the image of a run without failures — no crash, no hang, no other
 * message, and (in the sanitizer build) no leak.  The tool
 * is built with tests/alloc/alloc_fail.c wrapping malloc, calloc, realloc
 * and aligned_alloc (iskra's own allocations; libpng's are its own). */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "iskra/scene.h"
#include "refimg.h"
#include "tool_cli.h"

#define OUT "out/test_alloc_fail"

/* Runs the tool; returns its exit status, stderr in OUT/stderr.txt. */
static int run(const char *env, const char *args)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s %s/tests/iskra_allocfail %s >/dev/null 2>%s/stderr.txt", env, refimg_build_dir(),
             args, OUT);
    int st = system(cmd);
    cr_assert(WIFEXITED(st), "%s: killed by a signal", cmd);
    return WEXITSTATUS(st);
}

Test(alloc_fail, every_allocation_of_every_scene_fails_cleanly, .timeout = 900)
{
    cli_fresh(OUT);
    long total = 0, recovered = 0;
    for (int i = 0; i < isk_scene_builtin_count(); i++) {
        const char *name = isk_scene_builtin_name(i);
        char args[256];
        snprintf(args, sizeof args, "render %s --frames 3 --size 64x64 --out " OUT "/x.png", name);
        cr_assert_eq(run("ISKRA_ALLOC_COUNT=1", args), 0, "%s without failures", name);
        cr_assert_eq(rename(OUT "/x.png", OUT "/want.png"), 0);
        char *err = cli_slurp(OUT "/stderr.txt");
        long n = 0;
        const char *a = strstr(err, "allocations: ");
        cr_assert_not_null(a, "%s: %s", name, err);
        n = atol(a + 13);
        free(err);
        cr_assert_gt(n, 5, "%s", name);
        for (long k = 1; k <= n; k++) {
            char env[64];
            snprintf(env, sizeof env, "ISKRA_ALLOC_FAIL=%ld", k);
            remove(OUT "/x.png");
            int rc = run(env, args);
            char *msg = cli_slurp(OUT "/stderr.txt");
            if (rc == 0) {
                cr_assert_eq(system("cmp -s " OUT "/x.png " OUT "/want.png"), 0,
                             "%s, allocation %ld of %ld: recovered, but the image differs", name, k, n);
                recovered++;
            } else {
                cr_assert_eq(rc, 1, "%s, allocation %ld of %ld failing: exit %d: %s", name, k, n, rc, msg);
                cr_assert_not_null(strstr(msg, "out of memory"), "%s, allocation %ld of %ld: %s", name, k, n, msg);
                cr_assert_not(cli_exists(OUT "/x.png"), "%s, allocation %ld: wrote its output anyway", name, k);
            }
            free(msg);
        }
        total += n;
    }
    cr_assert_gt(total, 300);
    cr_assert_lt(recovered, total / 10, "most failures must stop the run: %ld of %ld recovered", recovered, total);
}
