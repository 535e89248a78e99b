/* SPDX-License-Identifier: MIT */
/* Every key of the sub-emitters and trails (on_death, on_hit, inherit,
 * count of a sub-emitter, trail, trail_width, trail_fade): with it the bytes
 * differ, at its default they are today's, a bad value is refused with
 * FILE:LINE and the CLI exits 2 (tests/key_case.h). */
#include <criterion/criterion.h>

#include "key_case.h"

/* A parent whose five particles die at 0.2 s; the sub-emitter is kept
 * referenced by an emitter that never bounces, so the scene is valid
 * without the key. */
static const char *deaths = "[scene]\nwidth = 64\nheight = 48\n"
                            "[emitter p]\nsource = stream\ncount = 5\nlife = 0.2\nlaunch = disc\nspeed_max = 3\n%s\n"
                            "[emitter hold]\nsource = particle\non_hit = s\n"
                            "[emitter s]\nsource = sub\ncount = 6\nlaunch = disc\nspeed_max = 4\ncolor = red\n";

Test(fx_events_keys, on_death)
{
    key_case_differs(deaths, "on_death = s", 30);
    key_case_same(deaths, "on_death =", 30);
    key_case_rejects(deaths, "on_death = hold", "not a sub-emitter");
    key_case_rejects(deaths, "on_death = nobody", "on_death");
}

/* Rain on a floor; the sub-emitter is kept referenced by an immortal particle. */
static const char *hits = "[scene]\nwidth = 64\nheight = 48\n[deflector floor]\nsegment = -10, -2, 10, -2\n"
                          "[emitter p]\nsource = stream\ncount = 5\nposition = 0, 3\nshape = segment\nshape_a = 6\n"
                          "velocity = 0, -10\ndeflectors = floor\n%s\n"
                          "[emitter hold]\nsource = particle\non_death = s\n"
                          "[emitter s]\nsource = sub\ncount = 6\nlaunch = disc\nspeed_max = 4\ncolor = red\n";

Test(fx_events_keys, on_hit)
{
    key_case_differs(hits, "on_hit = s", 40);
    key_case_same(hits, "on_hit =", 40);
    key_case_rejects(hits, "on_hit = p", "not a sub-emitter");
}

static const char *sub = "[scene]\nwidth = 64\nheight = 48\n"
                         "[emitter p]\nsource = stream\ncount = 5\nlife = 0.2\nvelocity = 8, 0\non_death = s\n"
                         "[emitter s]\nsource = sub\ncount = 3\nlaunch = disc\nspeed_max = 2\n%s\n";

Test(fx_events_keys, inherit)
{
    key_case_differs(sub, "inherit = 0.5", 40);
    key_case_same(sub, "inherit = 0", 40);
    key_case_rejects(sub, "inherit = 1.5", "inherit");
    key_case_rejects(sub, "inherit = -0.1", "inherit");
}

/* A sub-emitter's count is required: the cases compare two values. */
static const char *sub_nocount = "[scene]\nwidth = 64\nheight = 48\n"
                                 "[emitter p]\nsource = stream\ncount = 5\nlife = 0.2\nvelocity = 8, 0\n"
                                 "on_death = s\n[emitter s]\nsource = sub\nlaunch = disc\nspeed_max = 2\n%s\n";

Test(fx_events_keys, count_of_a_sub_emitter)
{
    isk_canvas a = key_case_render(sub_nocount, "count = 3", 40), b = key_case_render(sub_nocount, "count = 9", 40);
    cr_assert_not(key_case_equal(&a, &b));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    key_case_rejects(sub_nocount, "count = 0", "count");
}

static const char *stream = "[scene]\nwidth = 64\nheight = 48\n"
                            "[emitter p]\nsource = stream\nrate = 40\nlaunch = disc\nspeed_max = 5\nlife = 1\n%s\n";
static const char *trailed = "[scene]\nwidth = 64\nheight = 48\n"
                             "[emitter p]\nsource = stream\nrate = 40\nlaunch = disc\nspeed_max = 5\nlife = 1\n"
                             "trail = 8\n%s\n";

Test(fx_events_keys, trail)
{
    key_case_differs(stream, "trail = 8", 30);
    key_case_same(stream, "trail = 0", 30);
    key_case_rejects(stream, "trail = 65", "trail");
    key_case_rejects(stream, "trail = -1", "trail");
}

Test(fx_events_keys, trail_width)
{
    key_case_differs(trailed, "trail_width = 3", 30);
    key_case_same(trailed, "trail_width = 1", 30);
    key_case_rejects(trailed, "trail_width = 0", "trail_width");
}

Test(fx_events_keys, trail_fade)
{
    key_case_differs(trailed, "trail_fade = 0.3", 30);
    key_case_same(trailed, "trail_fade = 1", 30);
    key_case_rejects(trailed, "trail_fade = 2", "trail_fade");
}
