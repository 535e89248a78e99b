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
#include "sanitized.h"
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

/* Every allocation of one run failing in turn, for the outputs beside a
 * PNG (GIF with a strip and a state, Y4M, a sequence with states) and for
 * the simulator's window: exit 1 with "out of memory" and none of the
 * outputs (the names in `outputs`, under dir), or a run that recovered. */
static void each_allocation_fails(const char *dir, const char *args, const char *const *outputs)
{
    char stderr_path[128];
    snprintf(stderr_path, sizeof stderr_path, "%s/stderr.txt", dir);
    cr_assert_eq(run(dir, "SDL_VIDEODRIVER=dummy ISKRA_ALLOC_COUNT=1", args), 0, "%s without failures", args);
    char *err = cli_slurp(stderr_path);
    const char *a = strstr(err, "allocations: ");
    cr_assert_not_null(a, "%s: %s", args, err);
    const long n = atol(a + 13);
    free(err);
    cr_assert_gt(n, 5, "%s", args);
    for (long k = 1; k <= n; k++) {
        char env[96], rm[256];
        snprintf(rm, sizeof rm, "rm -rf %s/o", dir);
        cr_assert_eq(system(rm), 0);
        snprintf(env, sizeof env, "SDL_VIDEODRIVER=dummy ISKRA_ALLOC_FAIL=%ld", k);
        int rc = run(dir, env, args);
        char *msg = cli_slurp(stderr_path);
        if (rc != 0) {
            cr_assert_eq(rc, 1, "%s, allocation %ld of %ld failing: exit %d: %s", args, k, n, rc, msg);
            cr_assert_not_null(strstr(msg, "out of memory"), "%s, allocation %ld of %ld: %s", args, k, n, msg);
            for (int i = 0; outputs[i]; i++) {
                char path[160];
                snprintf(path, sizeof path, "%s/o/%s", dir, outputs[i]);
                cr_assert_not(cli_exists(path), "%s, allocation %ld: wrote %s anyway", args, k, outputs[i]);
            }
        }
        free(msg);
    }
}

Test(alloc_fail, every_output_and_the_window_fail_cleanly, .timeout = 600)
{
    cli_fresh(OUT "/outputs");
    /* a sequence keeps the frames it finished (--resume goes on from them) */
    static const char *const anim[] = {"x.gif", "s.png", "s.csv", NULL}, *const y4m[] = {"x.y4m", NULL},
                             *const none[] = {NULL};
    each_allocation_fails(OUT "/outputs", "render preset_magic --frames 3 --size 64x64 --every 1 --out "
                          OUT "/outputs/o/x.gif --strip " OUT "/outputs/o/s.png --state " OUT "/outputs/o/s.csv", anim);
    each_allocation_fails(OUT "/outputs", "render scenes/fx_trails.ini --frames 2 --size 48x48 --out "
                          OUT "/outputs/o/x.y4m", y4m);
    each_allocation_fails(OUT "/outputs", "render looks_pinwheel --frames 2 --size 48x48 --out-dir "
                          OUT "/outputs/o/d --state-every 1", none);
    each_allocation_fails(OUT "/outputs", "play preset_rain --size 64x64 --frames 3 --fixed-clock --script wait:2",
                          none);
}

/* The system's own allocator refusing (an address-space limit, as on a
 * small machine): memory the budget allowed is not there when the GIF
 * writer asks for its tables.  Exit 1, "out of memory", no file.  Not
 * under the sanitizers, whose shadow memory needs more than the limit. */
Test(alloc_fail, a_refused_allocation_exits_1_not_2)
{
#if TEST_SANITIZED
    cr_skip_test("AddressSanitizer reserves more address space than the limit");
#endif
    cli_fresh(OUT "/rlimit");
    char cmd[512];
    /* 4096 x 4096 frames: the GIF writer's tables take 400 MiB and more,
     * the effect 70 MiB; the limit leaves room for the effect alone */
    snprintf(cmd, sizeof cmd,
             "ulimit -v 400000 && ISKRA_THREADS=1 %s/bin/iskra render fig09_stationary_particle --size 4096x4096 "
             "--frames 1 --max-memory 2G --out " OUT "/rlimit/x.gif 2>" OUT "/rlimit/stderr.txt",
             refimg_build_dir());
    int st = system(cmd);
    cr_assert(WIFEXITED(st), "killed by a signal");
    char *msg = cli_slurp(OUT "/rlimit/stderr.txt");
    cr_assert_eq(WEXITSTATUS(st), 1, "exit %d: %s", WEXITSTATUS(st), msg);
    cr_assert_not_null(strstr(msg, "out of memory"), "%s", msg);
    cr_assert_not(cli_exists(OUT "/rlimit/x.gif"));
    free(msg);
}
