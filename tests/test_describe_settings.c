/* SPDX-License-Identifier: MIT */
/* isk_effect_describe (and `iskra describe`) says everything the scene
 * holds: after the pipeline and the drawings, every key of [scene],
 * [bounds] (with walls), each [deflector NAME] and [click] (when on) as
 * "key = value" lines: the clicks, a click at the start, start_paused, the
 * seed, a deflector shown, live changes included. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/keys.h"
#include "iskra/scene.h"
#include "scene_text.h"
#include "tool_cli.h"

static const char *const scene =
    "[scene]\nwidth = 200\nheight = 150\nseed = 42\nstart_paused = true\nframes = 31\n"
    "[view]\nxmin = 0\nxmax = 10\nymin = 0\nymax = 10\n"
    "[bounds]\nmode = reflect\nsides = bottom, left\nrestitution = 0.5\n"
    "[deflector roof]\nsegment = 1, 2, 8, 3\nshow = true\ncolor = #ff8020\n"
    "[deflector hidden]\nsegment = 1, 1, 2, 1\nreaction = kill\n"
    "[emitter layer]\nsource = layer\ncount = 100\nrect = 1, 9, 1, 2\ndeflectors = roof, hidden\n"
    "[click]\nexplosion = gauss\ncount = 500\nat_start = 5, 1\nafter_frames = 1\n";

static void contains(const char *text, const char *want)
{
    cr_assert_not_null(strstr(text, want), "expected \"%s\" in:\n%s", want, text);
}

Test(describe_settings, the_click_the_start_and_the_deflectors_are_described)
{
    isk_effect *fx = scene_text_open(scene, 0);
    char *t = scene_text_lists(fx);
    contains(t, "\n[click] enabled = true; explosion = gauss; count = 500; emitter = the first emitter; at_start = 5, 1; "
                "after_frames = 1\n");
    contains(t, "; seed = 42;");
    contains(t, "; frames = 31; start_paused = true;");
    contains(t, "\n[bounds] mode = reflect; sides = bottom, left; margin = 0; restitution = 0.5; window = ");
    contains(t, "\n[deflector roof] segment = 1, 2, 8, 3; restitution = 1; probability = 1; reaction = bounce; "
                "restitution_mode = uniform; show = true; color = #ff8020\n");
    contains(t, "\n[deflector hidden] segment = 1, 1, 2, 1;");
    contains(t, "; reaction = kill;");
    free(t);
    /* a live change is described as it now is */
    isk_error err = {0};
    cr_assert_eq(isk_effect_set(fx, "deflector roof", "segment", "1, 3, 8, 2", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_set(fx, "click", "count", "250", &err), ISK_OK, "%s", err.message);
    t = scene_text_lists(fx);
    contains(t, "[deflector roof] segment = 1, 3, 8, 2;");
    contains(t, "; count = 250;");
    free(t);
    isk_effect_destroy(fx);
}

/* Every key of those sections that applies is there: a new key cannot be
 * left out. */
Test(describe_settings, every_key_of_the_settings_sections_is_there)
{
    isk_effect *fx = scene_text_open(scene, 0);
    char *t = scene_text_lists(fx);
    const isk_section_kind sections[] = {ISK_SECTION_SCENE, ISK_SECTION_DEFLECTOR, ISK_SECTION_CLICK};
    for (int s = 0; s < 3; s++)
        for (int i = 0; i < isk_key_count(); i++) {
            const isk_key *k = isk_key_at(i);
            if (k->section != sections[s])
                continue;
            char want[80];
            snprintf(want, sizeof want, "%s = ", k->name);
            char *line = strstr(t, isk_section_name(sections[s]));
            cr_assert_not_null(line, "no [%s] line:\n%s", isk_section_name(sections[s]), t);
            contains(line, want);
        }
    free(t);
    isk_effect_destroy(fx);
}

/* No clicks and no walls: no [click] or [bounds] line; `iskra describe`
 * prints the same lines. */
Test(describe_settings, off_sections_stay_out_and_the_tool_says_the_same)
{
    isk_effect *fx = scene_text_open("[scene]\nseed = 3\n[emitter e]\nsource = particle\n", 0);
    char *t = scene_text_lists(fx);
    cr_assert_null(strstr(t, "[click]"), "%s", t);
    cr_assert_null(strstr(t, "[bounds]"), "%s", t);
    contains(t, "[scene] width = 600; height = 600;");
    free(t);
    isk_effect_destroy(fx);
    cli_fresh("out/test_describe_settings");
    cr_assert_eq(cli_run("out/test_describe_settings", "describe fig26_mushroom_one_potential"), 0);
    char *out = cli_slurp("out/test_describe_settings/stdout.txt");
    contains(out, "; start_paused = true;");
    contains(out, "\n[click] enabled = true; explosion = coulomb; count = 1000; emitter = layer; at_start = 5, 1; "
                  "after_frames = 1\n");
    free(out);
}
