/* SPDX-License-Identifier: MIT */
/* The key-case checks themselves (tests/key_case.h), on keys that exist:
 * each check must be able to fail. */
#include <criterion/criterion.h>

#include "key_case.h"

static const char *base = "[scene]\nwidth = 48\nheight = 32\nseed = 3\n"
                          "[emitter e]\nsource = stream\nrate = 300\nlaunch = disc\nspeed_max = 4\n%s\n";

Test(key_case, an_existing_key_shows_each_outcome)
{
    key_case_differs(base, "color = red", 20);
    key_case_same(base, "color = yellow", 20);
    key_case_rejects(base, "life = -1", "life");
}

Test(key_case, the_render_is_the_scene_after_its_frames)
{
    isk_canvas a = key_case_render(base, "", 0), b = key_case_render(base, "", 20);
    cr_assert_eq(a.width, 48);
    cr_assert_eq(a.height, 32);
    cr_assert_not(key_case_equal(&a, &b), "20 frames of a stream drew nothing");
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}
