/* SPDX-License-Identifier: MIT */
/* The tutorial's images are what its files draw (docs/tutorial.md): each
 * docs/tutorial/stepN.ini, rendered by the library and by the command the
 * page shows (`iskra render docs/tutorial/stepN.ini --out stepN.png`), is
 * refimg/tutorial_stepN.png byte for byte; docs/tutorial/fountain.c, run
 * as it is, writes fountain.png with step 4's bytes and
 * fountain_tilted.png with refimg/tutorial_tilted.png's.  (That the page
 * quotes these files as they are is test_docs_snippets' job;
 * tests/header_examples.sh builds fountain.c as a user would.) */
#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "iskra/effect.h"
#include "iskra/png.h"
#include "iskra/scene.h"
#include "refimg.h"
#include "tool_cli.h"

/* The tutorial's C program, compiled here as it is, its main renamed. */
#define main tutorial_fountain_main
#include "../docs/tutorial/fountain.c"
#undef main

#define OUT "out/test_tutorial"
#define STEPS 4

/* The image `iskra render FILE` draws: the scene's own frame. */
static void render_file(const char *path, isk_canvas *c)
{
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load_file(&d, path, &err), ISK_OK, "%s", err.message);
    isk_effect *fx;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_canvas_init(c, d.width, d.height), ISK_OK);
    cr_assert_gt(d.show.frames, 0, "%s sets no frame to show", path);
    cr_assert_eq(isk_effect_run(fx, c, d.show.frames), ISK_OK);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

static void expect_png(const char *path, const char *ref)
{
    isk_canvas c;
    isk_error err;
    cr_assert_eq(isk_png_read(&c, path, &err), ISK_OK, "%s", err.message);
    cr_expect(refimg_check(ref, &c), "%s differs from refimg/%s.png", path, ref);
    isk_canvas_free(&c);
}

Test(tutorial, every_step_draws_its_image)
{
    for (int i = 1; i <= STEPS; i++) {
        char path[64], ref[64];
        snprintf(path, sizeof path, "docs/tutorial/step%d.ini", i);
        snprintf(ref, sizeof ref, "tutorial_step%d", i);
        isk_canvas c;
        render_file(path, &c);
        cr_expect(refimg_check(ref, &c), "%s differs from refimg/%s.png", path, ref);
        isk_canvas_free(&c);
    }
}

/* The command the page shows, word for word but for the output folder. */
Test(tutorial, the_pages_command_draws_the_same, .timeout = 120)
{
    cli_fresh(OUT "/cli");
    for (int i = 1; i <= STEPS; i++) {
        char args[128], png[64], ref[64];
        snprintf(args, sizeof args, "render docs/tutorial/step%d.ini --out " OUT "/cli/step%d.png", i, i);
        snprintf(png, sizeof png, OUT "/cli/step%d.png", i);
        snprintf(ref, sizeof ref, "tutorial_step%d", i);
        cr_assert_eq(cli_run(OUT "/cli", args), 0, "iskra %s failed", args);
        expect_png(png, ref);
    }
}

/* Each step differs from the one before: every step shows something. */
Test(tutorial, each_step_changes_the_picture)
{
    isk_canvas prev, c;
    render_file("docs/tutorial/step1.ini", &prev);
    for (int i = 2; i <= STEPS; i++) {
        char path[64];
        snprintf(path, sizeof path, "docs/tutorial/step%d.ini", i);
        render_file(path, &c);
        isk_canvas_diff diff;
        cr_assert(isk_canvas_compare(&prev, &c, &diff, NULL));
        cr_expect_gt(diff.differing, 1000, "step %d changes only %ld pixels of step %d", i, diff.differing, i - 1);
        isk_canvas_free(&prev);
        prev = c;
    }
    isk_canvas_free(&prev);
}

Test(tutorial, the_c_program_draws_step_4_then_the_tilted_fountain)
{
    char top[4096];
    cr_assert_not_null(getcwd(top, sizeof top));
    cli_fresh(OUT "/c");
    cr_assert_eq(chdir(OUT "/c"), 0);
    int rc = tutorial_fountain_main();
    cr_assert_eq(chdir(top), 0);
    cr_assert_eq(rc, 0, "docs/tutorial/fountain.c exited with %d", rc);
    /* the same effect from C structs and from the scene file: the same bytes */
    expect_png(OUT "/c/fountain.png", "tutorial_step4");
    expect_png(OUT "/c/fountain_tilted.png", "tutorial_tilted");
}
