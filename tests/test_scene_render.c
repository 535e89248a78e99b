/* SPDX-License-Identifier: MIT */
/* Scenes rendered through the runtime: every scenes/NAME.ini gives the same
 * bytes as its C example's reference image refimg/NAME.png, and a scene pays
 * only for what it uses (unreferenced, zero-strength and disabled forces
 * change no pixel and are not in the pipeline). */
#include <criterion/criterion.h>
#include <criterion/logging.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/png.h"
#include "iskra/scene.h"
#include "refimg.h"
#include "scene_text.h"

/* Renders frame `frames` (-1: the scene's default) of a definition. */
static void render_def(const isk_effect_def *d, long frames, isk_canvas *c)
{
    isk_effect *fx;
    isk_error err;
    cr_assert_eq(isk_effect_create(&fx, d, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_canvas_init(c, d->width, d->height), ISK_OK);
    cr_assert_eq(isk_effect_run(fx, c, frames < 0 ? d->show.frames : frames), ISK_OK);
    isk_effect_destroy(fx);
}

static void render_text(const char *text, long frames, isk_canvas *c)
{
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load_string(&d, text, "t.ini", &err), ISK_OK, "%s", err.message);
    render_def(&d, frames, c);
    isk_effect_def_free(&d);
}

static char *describe_text(const char *text) { return scene_text_describe(text); }

/* Every built-in scene with a reference image of its name is that image:
 * the thesis figures' (made by their C examples) and the effect scenes'
 * (refimg_check: ISKRA_REFIMG_UPDATE=1 rewrites them, as for any refimg). */
Test(scene_render, every_scene_matches_its_example, .timeout = 240)
{
    int checked = 0, failed = 0;
    for (int i = 0; i < isk_scene_builtin_count(); i++) {
        const char *name = isk_scene_builtin_name(i);
        char ref_path[256];
        snprintf(ref_path, sizeof ref_path, "refimg/%s.png", name);
        /* fig14's reference is its example's strip of six frames; its scene is
         * one frame of the animation (tested below against --frames). */
        if (!strcmp(name, "fig14_animation_strip"))
            continue;
        FILE *ref = fopen(ref_path, "rb");
        if (!ref)
            continue; /* a scene with no image (the simulator's, the strips' scenes) */
        fclose(ref);
        isk_effect_def d;
        isk_error err;
        cr_assert_eq(isk_scene_load(&d, name, &err), ISK_OK, "%s", err.message);
        isk_canvas c;
        render_def(&d, -1, &c);
        if (!refimg_check(name, &c)) {
            cr_log_error("scenes/%s.ini differs from refimg/%s.png", name, name);
            failed++;
        }
        checked++;
        isk_canvas_free(&c);
        isk_effect_def_free(&d);
    }
    cr_assert_eq(failed, 0);
    cr_assert_geq(checked, 13, "expected the thesis figure scenes to be compared");
}

/* ---- only what is used ----------------------------------------------------------- */

#define BASE                                                                                                 \
    "[scene]\nseed = 7\ndt = 1/60\n[view]\nxmin = -10\nxmax = 10\nymin = -10\nymax = 10\n"                   \
    "[force gravity]\ng = 9.81\n"                                                                            \
    "[emitter sparks]\nsource = explosion\nexplosion = gauss\nposition = 0, 0\ncount = 2000\n"              \
    "forces = gravity\ncolor = yellow\n"

/* Potentials are drawn as discs by default (the thesis shows them), which is
 * part of the picture, not of the simulation: the extra ones here say
 * draw = false so the comparison is about what they cost to simulate. */
Test(scene_render, fig14_scene_is_a_frame_of_its_example)
{
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load(&d, "fig14_animation_strip", &err), ISK_OK, "%s", err.message);
    long frames = d.show.frames;
    cr_assert_gt(frames, 0);
    isk_canvas c, ex;
    render_def(&d, -1, &c);
    char cmd[512];
    (void)system("mkdir -p out/scenes");
    snprintf(cmd, sizeof cmd, "%s/examples/fig14_animation_strip --frames %ld --png out/scenes/fig14_frame.png",
             refimg_build_dir(), frames);
    cr_assert_eq(system(cmd), 0, "%s failed", cmd);
    cr_assert_eq(isk_png_read(&ex, "out/scenes/fig14_frame.png", &err), ISK_OK, "%s", err.message);
    isk_canvas_diff diff;
    cr_assert(isk_canvas_compare(&c, &ex, &diff, NULL));
    cr_assert_eq(diff.differing, 0, "scenes/fig14_animation_strip.ini frame %ld: %ld pixels differ from the example",
                 frames, diff.differing);
    isk_canvas_free(&c);
    isk_canvas_free(&ex);
    isk_effect_def_free(&d);
}

Test(scene_pipeline, unreferenced_force_changes_nothing)
{
    const char *plain = BASE;
    const char *extra = BASE "[force coulomb]\nkind = potential\nk = 500\nposition = 1, 1\nmin_distance = 0.2\ndraw = false\n"
                             "[force air]\nkind = drag\nb = 3\n";
    isk_canvas a, b;
    render_text(plain, 40, &a);
    render_text(extra, 40, &b);
    cr_assert(isk_canvas_equal(&a, &b), "an unreferenced force changed the image");
    char *da = describe_text(plain), *db = describe_text(extra);
    cr_assert_str_eq(da, db, "describe lists an unreferenced force");
    cr_assert_null(strstr(db, "coulomb"));
    cr_assert_null(strstr(db, "potential"));
    cr_assert_null(strstr(db, "drag"));
    free(da);
    free(db);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(scene_pipeline, zero_strength_stage_changes_no_pixel)
{
    const char *plain = BASE;
    const char *zero = "[scene]\nseed = 7\ndt = 1/60\n[view]\nxmin = -10\nxmax = 10\nymin = -10\nymax = 10\n"
                       "[force gravity]\ng = 9.81\n[force air]\nkind = drag\nb = 0\n"
                       "[force nothing]\nkind = potential\nk = 0\nposition = 2, 2\ndraw = false\n"
                       "[emitter sparks]\nsource = explosion\nexplosion = gauss\nposition = 0, 0\ncount = 2000\n"
                       "forces = gravity, air, nothing\ncolor = yellow\n";
    isk_canvas a, b;
    render_text(plain, 40, &a);
    render_text(zero, 40, &b);
    cr_assert(isk_canvas_equal(&a, &b), "a zero-strength force changed the image");
    char *dz = describe_text(zero);
    cr_assert_null(strstr(dz, "drag"), "zero drag listed:\n%s", dz);
    cr_assert_null(strstr(dz, "potential"), "zero potential listed:\n%s", dz);
    free(dz);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(scene_pipeline, disabled_potential_not_described)
{
    const char *text = "[scene]\nseed = 7\ndt = 1/60\n[view]\nxmin = -10\nxmax = 10\nymin = -10\nymax = 10\n"
                       "[force gravity]\ng = 9.81\n"
                       "[force P]\nkind = potential\nk = 500\nposition = 1, 1\nenabled = false\n"
                       "[emitter sparks]\nsource = explosion\nexplosion = gauss\nposition = 0, 0\ncount = 2000\n"
                       "forces = gravity, P\ncolor = yellow\n";
    char *d = describe_text(text);
    cr_assert_null(strstr(d, "potential"), "a disabled potential is in the pipeline:\n%s", d);
    free(d);
    isk_canvas a, b;
    render_text(BASE, 40, &a);
    render_text(text, 40, &b);
    cr_assert(isk_canvas_equal(&a, &b), "a disabled potential changed the image");
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(scene_pipeline, referenced_potential_is_described)
{
    /* the converse, so the tests above cannot pass vacuously */
    const char *on = "[force gravity]\ng = 9.81\n[force P]\nkind = potential\nk = 500\nposition = 1, 1\n"
                     "[emitter sparks]\nsource = explosion\nexplosion = gauss\ncount = 100\nforces = gravity, P\n";
    char *d = describe_text(on);
    cr_assert_not_null(strstr(d, "potential"), "describe output:\n%s", d);
    free(d);
}
