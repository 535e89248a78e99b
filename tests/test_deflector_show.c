/* SPDX-License-Identifier: MIT */
/* A deflector can be shown: `show = true` (with `color`) in its section
 * draws the segment as a line 1 px wide, after the drawings and before the
 * particles, from where the segment is at each render, so a live change
 * (isk_effect_set) moves the line with the segment.
 *
 * refimg/deflector_show.png: rain on a shown roof, under a drawn moon, at
 * frame 40; refimg/deflector_show_tilted.png: the same after the roof is
 * tilted live at frame 40 and 20 more frames (the line where the roof now
 * is, none where it was; the drops slide the new way).  Also: a shown
 * deflector draws the bytes a [drawing] of the same two points draws, and
 * show = false (or turned off live) draws nothing. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "refimg_scene.h"
#include "scene_text.h"

/* %s: the roof's extra keys. */
static const char *const rain = "[scene]\nwidth = 96\nheight = 72\nbackground = #0b1020\nseed = 7\n"
                                "[view]\nxmin = -4\nxmax = 4\nymin = -3\nymax = 3\n"
                                "[force gravity]\ng = 9.81\n"
                                "[deflector roof]\nsegment = -3, -1, 2, 0.5\nrestitution = 0.2\n%s\n"
                                "[emitter rain]\nsource = stream\nposition = -4, 3\nshape = segment\nshape_a = 8\n"
                                "rate = 60\nvelocity = 0.5, -3\nlife = 2\nforces = gravity\ndeflectors = roof\n"
                                "color = #a0c8ff\n"
                                "[drawing moon]\nkind = disc\nposition = 2.5, 2\nradius = 0.6\ncolor = #f0e8c0\n";

static isk_effect *create(const char *roof_keys)
{
    char text[2000];
    snprintf(text, sizeof text, rain, roof_keys);
    return scene_text_open(text, 0);
}

static isk_canvas render(isk_effect *fx)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 96, 72), ISK_OK);
    cr_assert_eq(isk_effect_render(fx, &c), ISK_OK);
    return c;
}

static int same(const isk_canvas *a, const isk_canvas *b)
{
    isk_canvas_diff d;
    return isk_canvas_compare(a, b, &d, NULL) && d.differing == 0;
}

/* The roof's line crosses column 42 (world x = -0.5, where the roof is at
 * y = -0.25: rows 38 and 39 share it): a pixel there has the colour's red
 * (at least half of it) and no more blue than the background's. */
static int line_at_42(const isk_canvas *c, int rgb_red)
{
    for (int y = 37; y <= 40; y++) {
        const uint8_t *p = isk_canvas_at(c, 42, y);
        if (p[0] >= rgb_red / 2 && p[2] <= 0x40)
            return 1;
    }
    return 0;
}

Test(deflector_show, a_shown_roof_follows_a_live_tilt)
{
    isk_effect *fx = create("show = true\ncolor = #ff8020");
    scene_steps(fx, 40);
    isk_canvas c = render(fx);
    /* the roof's middle, (-0.5, -0.25): pixel (42, 38) */
    cr_assert(line_at_42(&c, 0xff));
    refimg_expect("deflector_show", &c);
    isk_error err = {0};
    cr_assert_eq(isk_effect_set(fx, "deflector roof", "segment", "-3, 0.5, 2, -1", &err), ISK_OK, "%s",
                 err.message);
    scene_steps(fx, 20);
    c = render(fx);
    cr_assert(!line_at_42(&c, 0xff), "the line stayed where the roof was");
    refimg_expect("deflector_show_tilted", &c);
    isk_effect_destroy(fx);
}

Test(deflector_show, a_shown_deflector_is_a_drawing_of_its_segment)
{
    /* the same segment as a [drawing] after the moon: the same bytes */
    isk_effect *shown = create("show = true\ncolor = #ff8020");
    char text[2000];
    snprintf(text, sizeof text, rain, "");
    strcat(text, "[drawing roof]\npoints = -3, -1, 2, 0.5\ncolor = #ff8020\n");
    isk_effect *drawn = scene_text_open(text, 0);
    for (int f = 0; f < 3; f++) {
        scene_steps(shown, 15);
        scene_steps(drawn, 15);
        isk_canvas a = render(shown), b = render(drawn);
        cr_assert(same(&a, &b), "frame %d", 15 * (f + 1));
        isk_canvas_free(&a);
        isk_canvas_free(&b);
    }
    isk_effect_destroy(shown);
    isk_effect_destroy(drawn);
}

Test(deflector_show, hidden_by_default_and_when_turned_off)
{
    isk_effect *plain = create(""), *off = create("show = false\ncolor = red"), *on = create("show = true");
    scene_steps(plain, 30);
    scene_steps(off, 30);
    scene_steps(on, 30);
    isk_canvas a = render(plain), b = render(off), c = render(on);
    cr_assert(same(&a, &b));
    cr_assert(!same(&a, &c));
    const uint8_t *p = isk_canvas_at(&c, 42, 38), *q = isk_canvas_at(&c, 42, 39);
    /* the line's two halves: white over the background in every channel */
    for (int k = 0; k < 3; k++)
        cr_assert_gt(p[k] + q[k], 220, "the default colour is white: (%d %d %d), (%d %d %d)", p[0], p[1], p[2],
                     q[0], q[1], q[2]);
    isk_error err = {0};
    cr_assert_eq(isk_effect_set(on, "deflector roof", "show", "false", &err), ISK_OK, "%s", err.message);
    isk_canvas_free(&c);
    c = render(on);
    cr_assert(same(&a, &c), "turned off live, the line is gone");
    char v[64];
    cr_assert_eq(isk_effect_get(on, "deflector roof", "color", v, sizeof v, &err), ISK_OK);
    cr_assert_str_eq(v, "white");
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_canvas_free(&c);
    isk_effect_destroy(plain);
    isk_effect_destroy(off);
    isk_effect_destroy(on);
}

/* A deflector added in C has the key table's defaults: hidden, white. */
Test(deflector_show, c_definitions_get_the_defaults)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    int i = isk_effect_def_add_deflector(&d, "floor", isk_deflector_segment(-1, 0, 1, 0));
    cr_assert_eq(i, 0);
    cr_assert_eq(d.deflectors[0].show, 0);
    cr_assert(d.deflectors[0].color.r == 255 && d.deflectors[0].color.g == 255 && d.deflectors[0].color.b == 255 &&
              d.deflectors[0].color.a == 255);
    cr_assert_eq(d.deflectors[0].seg.x1, 1.0);
    isk_effect_def_free(&d);
}
