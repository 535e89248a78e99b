/* SPDX-License-Identifier: MIT */
/* A scene that draws nothing (an empty file, a [scene] section alone,
 * emitters that all have draw = none) renders its background with exit 0,
 * and the scene commands warn on stderr, naming the file, that nothing is
 * drawn; a scene that draws anything (a particle, a drawing, a drawn
 * potential, a deflector shown) gets no warning. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/png.h"
#include "tool_cli.h"

#define OUT "out/test_cli_nothing_drawn"

/* Renders dir/scene.ini (holding `text`) with `cmd`; returns stderr. */
static char *run(const char *dir, const char *cmd, const char *text, int want)
{
    char path[300], args[700];
    cli_fresh(dir);
    snprintf(path, sizeof path, "%s/scene.ini", dir);
    cli_write_file(path, text);
    snprintf(args, sizeof args, cmd, path, dir);
    cr_assert_eq(cli_run(dir, args), want, "iskra %s", args);
    snprintf(path, sizeof path, "%s/stderr.txt", dir);
    return cli_slurp(path);
}

Test(nothing_drawn, empty_and_scene_only_files_warn_and_render_the_background)
{
    const char *texts[] = {"", "[scene]\nwidth = 40\nheight = 30\nbackground = #102030\n",
                           "[scene]\nwidth = 40\nheight = 30\nbackground = #102030\n[force gravity]\ng = 9.81\n"};
    for (int i = 0; i < 3; i++) {
        char dir[200], want[600];
        snprintf(dir, sizeof dir, OUT "/empty%d", i);
        char *err = run(dir, "render %s --out %s/x.png", texts[i], 0);
        snprintf(want, sizeof want,
                 "iskra render: warning: %s/scene.ini: nothing is drawn: the scene has no [emitter NAME] or "
                 "[drawing NAME] section (the picture is the background alone)\n",
                 dir);
        cr_assert_str_eq(err, want);
        free(err);
        /* the picture is still written: the background */
        snprintf(want, sizeof want, "%s/x.png", dir);
        isk_canvas c;
        cr_assert_eq(isk_png_read(&c, want, NULL), ISK_OK);
        const uint8_t *p = isk_canvas_at(&c, c.width - 1, c.height - 1);
        if (i > 0)
            cr_assert(p[0] == 0x10 && p[1] == 0x20 && p[2] == 0x30 && p[3] == 255);
        isk_canvas_free(&c);
    }
}

Test(nothing_drawn, emitters_that_draw_nothing_warn_too)
{
    char *err = run(OUT "/none", "render %s --out %s/x.png",
                    "[emitter a]\nsource = particle\ndraw = none\n[emitter b]\nsource = particle\ndraw = none\n", 0);
    cr_assert_not_null(strstr(err, "/none/scene.ini: nothing is drawn: every emitter has draw = none"), "%s", err);
    free(err);
    /* describe says it too (the same scene loading) */
    err = run(OUT "/describe", "describe %s", "[scene]\n", 0);
    cr_assert_not_null(strstr(err, "iskra describe: warning: " OUT "/describe/scene.ini: nothing is drawn"), "%s",
                       err);
    free(err);
}

Test(nothing_drawn, a_scene_that_draws_anything_gets_no_warning)
{
    const char *texts[] = {
        "[emitter a]\nsource = particle\n",
        "[drawing d]\nkind = disc\nposition = 0, 0\nradius = 1\n",
        "[emitter a]\nsource = particle\ndraw = none\n[force p]\nkind = potential\nk = 1\nposition = 0, 0\n",
        "[deflector roof]\nsegment = -5, 0, 5, 1\nshow = true\n",
    };
    for (int i = 0; i < 4; i++) {
        char dir[200];
        snprintf(dir, sizeof dir, OUT "/drawn%d", i);
        char *err = run(dir, "render %s --out %s/x.png", texts[i], 0);
        cr_assert_str_eq(err, "", "%s", texts[i]);
        free(err);
    }
}
