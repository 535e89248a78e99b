/* SPDX-License-Identifier: MIT */
/* `preset = NAME[, SCALE]` in scene files: the same emitter as the C
 * function, keys after it override it, and every misuse named at its line. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/presets.h"
#include "iskra/scene.h"
#include "key_case.h"

static const char *base = "[scene]\nwidth = 80\nheight = 80\nseed = 4\n[view]\nxmin = -3\nxmax = 3\nymin = -1\nymax = 5\n"
                          "[emitter e]\n%s\n";

static isk_canvas render_def(isk_effect_def *d, int frames)
{
    isk_effect *fx;
    isk_error err = {0};
    cr_assert_eq(isk_effect_create(&fx, d, &err), ISK_OK, "%s", err.message);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, d->width, d->height), ISK_OK);
    for (int i = 0; i < frames; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_render(fx, &c), ISK_OK);
    isk_effect_destroy(fx);
    return c;
}

/* Every preset by name, at a scale, is the C function's emitter: same
 * bytes after a second of simulation. */
Test(preset_key, each_preset_is_the_c_functions_emitter)
{
    cr_assert_geq(isk_preset_count(), 6);
    for (int p = 0; p < isk_preset_count(); p++) {
        const char *name = isk_preset_name(p);
        char line[80];
        snprintf(line, sizeof line, "preset = %s, 1.5", name);
        isk_canvas a = key_case_render(base, line, 60);
        isk_effect_def d;
        isk_effect_def_init(&d);
        d.width = d.height = 80;
        d.seed = 4;
        d.xmin = -3, d.xmax = 3, d.ymin = -1, d.ymax = 5;
        cr_assert_eq(isk_preset_add(&d, name, "e", isk_vec2_make(0, 0), 1.5), 0, "%s", name);
        cr_assert_str_eq(d.emitters[0].preset, name);
        isk_canvas b = render_def(&d, 60);
        isk_effect_def_free(&d);
        cr_assert(key_case_equal(&a, &b), "preset %s in a scene file is not isk_preset_add's", name);
        isk_canvas_free(&a);
        isk_canvas_free(&b);
    }
}

Test(preset_key, keys_after_it_override_it)
{
    isk_effect_def d;
    isk_error err = {0};
    const char *text = "[emitter e]\npreset = sparks, 2\nrate = 7\nposition = 1, 2\n";
    cr_assert_eq(isk_scene_load_string(&d, text, "p.ini", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(d.emitters[0].born.rate, 7);
    cr_assert(d.emitters[0].born.position.x == 1 && d.emitters[0].born.position.y == 2);
    cr_assert_float_eq(d.emitters[0].launch.speed_max, 6.0, 1e-12); /* the preset's 300 points at scale 2 */
    cr_assert_eq(d.nforces, 1);                                     /* its own gravity, e_gravity */
    cr_assert_str_eq(d.forces[0].name, "e_gravity");
    cr_assert_float_eq(d.forces[0].g, 6.0, 1e-12);
    cr_assert_eq(d.emitters[0].motion.nforces, 1);
    isk_effect_def_free(&d);
    key_case_differs(base, "preset = fire, 2\nsize = 3", 30);
    key_case_differs(base, "preset = fire, 2", 30);
}

/* A written scene holds the preset's values, each as its own key, and
 * reads back to the same bytes (the directive itself is not written: it
 * would overwrite the forces written before it). */
Test(preset_key, written_scenes_keep_the_values_not_the_directive)
{
    isk_effect_def d, back;
    isk_error err = {0};
    char *text = malloc(strlen(base) + 40);
    cr_assert_not_null(text);
    /* A section named as the preset's own force, after it, changes that
     * force (it is not a second one). */
    sprintf(text, "[scene]\nwidth = 80\nheight = 80\n[emitter e]\npreset = sparks, 2\n[force e_gravity]\ng = 1\n");
    cr_assert_eq(isk_scene_load_string(&d, text, "p.ini", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(d.nforces, 1);
    cr_assert_eq(d.forces[0].g, 1.0);
    cr_assert_eq(d.forces[0].kind, ISK_FORCE_GRAVITY);
    isk_effect_def_free(&d);
    /* Its keys are checked as any section's. */
    sprintf(text, "[scene]\nwidth = 80\nheight = 80\n[emitter e]\npreset = sparks, 2\n[force e_gravity]\ng = -1\n");
    cr_assert_neq(isk_scene_load_string(&d, text, "p.ini", &err), ISK_OK);
    cr_assert(strstr(err.message, "p.ini:7:"), "%s", err.message);
    sprintf(text, "[scene]\nwidth = 80\nheight = 80\n[emitter e]\npreset = sparks, 2\n");
    cr_assert_eq(isk_scene_load_string(&d, text, "p.ini", &err), ISK_OK, "%s", err.message);
    free(text);
    char *written;
    cr_assert_eq(isk_scene_write(&d, &written, &err), ISK_OK, "%s", err.message);
    cr_assert_null(strstr(written, "preset"), "%s", written);
    cr_assert_eq(isk_scene_load_string(&back, written, "w.ini", &err), ISK_OK, "%s", err.message);
    free(written);
    isk_canvas a = render_def(&d, 40), b = render_def(&back, 40);
    cr_assert(key_case_equal(&a, &b));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_effect_def_free(&d);
    isk_effect_def_free(&back);
}

Test(preset_key, misuse_is_named_at_its_line)
{
    key_case_rejects(base, "preset = campfire", "no preset 'campfire' (the presets: fire, smoke, sparks");
    key_case_rejects(base, "preset = fire, 0", "the scale after the name must be a number in (0, 1e+06]");
    key_case_rejects(base, "preset = fire, big", "not ' big'");
    key_case_rejects(base, "preset = fire, 1e7", "(0, 1e+06]");
    static const char *late = "[emitter e]\nrate = 5\n%s\n";
    key_case_rejects(late, "preset = fire", "must be the section's first key (line 2 sets rate before it");
}

Test(preset_key, the_c_side_checks_its_arguments)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    cr_assert_eq(isk_preset_find("smoke"), 1);
    cr_assert_eq(isk_preset_find("Smoke"), -1);
    cr_assert_eq(isk_preset_find(NULL), -1);
    cr_assert_null(isk_preset_name(-1));
    cr_assert_null(isk_preset_name(isk_preset_count()));
    cr_assert_eq(isk_preset_apply(&d, 0, "fire", 1), ISK_ERR_RANGE); /* no emitter 0 */
    cr_assert_eq(isk_preset_add(&d, "nope", NULL, isk_vec2_make(0, 0), 1), -1);
    cr_assert_eq(isk_preset_add(&d, "fire", NULL, isk_vec2_make(0, 0), 2e6), -1);
    cr_assert_eq(isk_preset_apply(NULL, 0, "fire", 1), ISK_ERR_NULL);
    int i = isk_preset_add(&d, "fire", "flame", isk_vec2_make(1, 2), 1);
    cr_assert_eq(i, 0);
    d.emitters[0].look.order = 5;
    cr_assert_eq(isk_preset_apply(&d, 0, "snow", 2), ISK_OK);
    cr_assert_str_eq(d.emitters[0].name, "flame");
    cr_assert_str_eq(d.emitters[0].preset, "snow");
    cr_assert_eq(d.emitters[0].look.order, 5);
    cr_assert(d.emitters[0].born.position.x == 1 && d.emitters[0].born.position.y == 2);
    cr_assert_eq(d.emitters[0].born.rate, 10); /* snow's, not fire's */
    cr_assert_eq(isk_preset_apply(&d, 0, "snow", NAN), ISK_ERR_RANGE);
    isk_effect_def_free(&d);
}
