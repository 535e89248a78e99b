/* SPDX-License-Identifier: MIT */
/* tests/scene_text.h — an effect from a scene's text, and its stage lists
 * as text (header-only; include it after <criterion/criterion.h>; from a
 * file or a built-in name: tests/scene_open.h, which this includes).
 *
 *     isk_effect *fx = scene_text_open("[emitter e]\nsource = stream\nrate = 10\n", 0);
 *     char *lists = scene_text_describe("[emitter e]\nsource = stream\nrate = 10\n");  // free it
 *     char *now = scene_text_lists(fx);      // a running effect's lists (free it)
 *
 * Both assert that the text parses and the effect is created (threads:
 * 0 for the default, as isk_effect_def.threads). */
#ifndef ISKRA_TESTS_SCENE_TEXT_H
#define ISKRA_TESTS_SCENE_TEXT_H

#include <stdio.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "scene_open.h"

static inline isk_effect *scene_text_open(const char *text, int threads)
{
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load_string(&d, text, "t.ini", &err), ISK_OK, "%s", err.message);
    d.threads = threads;
    return scene_open_def(&d);
}

/* The stage lists of a running effect, as text (free it). */
static inline char *scene_text_lists(const isk_effect *fx)
{
    struct {
        char *text;
        size_t len;
    } out = {NULL, 0}; /* a struct: with two locals, GCC 12 takes the text for a pointer to them */
    FILE *f = open_memstream(&out.text, &out.len);
    cr_assert_not_null(f);
    isk_effect_describe(fx, f);
    fclose(f);
    return out.text;
}

static inline char *scene_text_describe(const char *text)
{
    isk_effect *fx = scene_text_open(text, 0);
    char *buf = scene_text_lists(fx);
    isk_effect_destroy(fx);
    return buf;
}

#endif
