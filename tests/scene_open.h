/* SPDX-License-Identifier: MIT */
/* tests/scene_open.h — an effect from a scene file or a built-in scene's
 * name, stepped and read back (header-only; include it after
 * <criterion/criterion.h>; tests/scene_text.h opens a scene's text).
 *
 *     isk_effect *fx = scene_open_file("docs/from-love-godot/angles.ini");
 *     isk_effect *g = scene_open_builtin("fire_campfire");
 *     scene_steps(fx, 60);                                  // 60 steps, each must succeed
 *     scene_expect_key(fx, "force gravity", "g", "9.81");   // what isk_effect_get prints
 *     isk_effect_destroy(fx);
 *
 * Opening asserts that the scene loads and the effect is created, with the
 * error's message; scene_expect_key is a cr_expect (the test goes on). */
#ifndef ISKRA_TESTS_SCENE_OPEN_H
#define ISKRA_TESTS_SCENE_OPEN_H

#include "iskra/effect.h"
#include "iskra/scene.h"

/* The effect of a loaded definition, which it frees. */
static inline isk_effect *scene_open_def(isk_effect_def *d)
{
    isk_error err = {0};
    isk_effect *fx = NULL;
    cr_assert_eq(isk_effect_create(&fx, d, &err), ISK_OK, "%s", err.message);
    isk_effect_def_free(d);
    return fx;
}

static inline isk_effect *scene_open_file(const char *path)
{
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load_file(&d, path, &err), ISK_OK, "%s", err.message);
    return scene_open_def(&d);
}

static inline isk_effect *scene_open_builtin(const char *name)
{
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load(&d, name, &err), ISK_OK, "%s: %s", name, err.message);
    return scene_open_def(&d);
}

static inline void scene_steps(isk_effect *fx, int n)
{
    for (int i = 0; i < n; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
}

static inline void scene_expect_key(isk_effect *fx, const char *section, const char *key, const char *want)
{
    char v[200];
    isk_error err = {0};
    cr_assert_eq(isk_effect_get(fx, section, key, v, sizeof v, &err), ISK_OK, "%s", err.message);
    cr_expect_str_eq(v, want, "[%s] %s", section, key);
}

#endif
