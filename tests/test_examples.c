/* SPDX-License-Identifier: MIT */
/* Every example program, run headless with --png, must reproduce its
 * reference image refimg/<example>.png exactly.  The list of examples comes
 * from the build ($BUILD/gen/examples.txt, one name per line).
 * ISKRA_EXAMPLE_FILTER=substring limits the run (tools/refimg uses it). */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include "iskra/png.h"
#include "refimg.h"

static int run_example(const char *name, const char *png)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s/examples/%s --png %s", refimg_build_dir(), name, png);
    int rc = system(cmd);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

Test(examples, every_example_matches_its_reference, .timeout = 600)
{
    char list[512];
    snprintf(list, sizeof list, "%s/gen/examples.txt", refimg_build_dir());
    FILE *f = fopen(list, "r");
    cr_assert_not_null(f, "cannot open %s (run make first)", list);
    mkdir("out", 0777);
    mkdir("out/examples", 0777);
    const char *filter = getenv("ISKRA_EXAMPLE_FILTER");
    char name[256];
    int n = 0, failures = 0;
    while (fgets(name, sizeof name, f)) {
        name[strcspn(name, "\r\n")] = 0;
        if (!*name || (filter && *filter && !strstr(name, filter)))
            continue;
        n++;
        char png[512];
        snprintf(png, sizeof png, "out/examples/%s.png", name);
        remove(png);
        int rc = run_example(name, png);
        if (rc != 0) {
            cr_log_error("example %s exited with status %d", name, rc);
            failures++;
            continue;
        }
        isk_canvas c;
        isk_error err;
        if (isk_png_read(&c, png, &err) != ISK_OK) {
            cr_log_error("example %s: %s", name, err.message);
            failures++;
            continue;
        }
        if (!refimg_check(name, &c))
            failures++;
        isk_canvas_free(&c);
    }
    fclose(f);
    cr_expect(n > 0 || (filter && *filter), "no examples found in %s", list);
    cr_assert_eq(failures, 0, "%d of %d examples differ from their reference images", failures, n);
}

Test(examples, bad_options_exit_with_status_2)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s/examples/fig01_triangle --no-such-option 2>/dev/null",
             refimg_build_dir());
    int rc = system(cmd);
    cr_assert(WIFEXITED(rc) && WEXITSTATUS(rc) == 2);
    snprintf(cmd, sizeof cmd, "%s/examples/fig01_triangle --png 2>/dev/null", refimg_build_dir());
    rc = system(cmd);
    cr_assert(WIFEXITED(rc) && WEXITSTATUS(rc) == 2);
}

Test(examples, unwritable_output_exits_with_status_1_and_leaves_nothing)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s/examples/fig01_triangle --png out/no/such/dir/x.png 2>/dev/null",
             refimg_build_dir());
    int rc = system(cmd);
    cr_assert(WIFEXITED(rc) && WEXITSTATUS(rc) == 1);
    struct stat st;
    cr_assert_neq(stat("out/no/such/dir/x.png", &st), 0);
}
