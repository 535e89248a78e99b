/* SPDX-License-Identifier: MIT */
/* Reference images of the looks, byte for byte: a still scene
 * of textured particles at known angles and flipbook frames (the example
 * scene scenes/looks_pinwheel.ini is compared with its image by
 * tests/test_scene_render.c, with every scene that has one). */
#include <criterion/criterion.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "refimg_scene.h"

static void render_scene(const char *name, const char *text, const char *label, long frames)
{
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load_string(&d, text, label, &err), ISK_OK, "%s", err.message);
    isk_effect *fx;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_canvas c = refimg_canvas(d.width, d.height, ISK_BLACK);
    isk_effect_def_free(&d);
    cr_assert_eq(isk_effect_run(fx, &c, frames), ISK_OK);
    isk_effect_destroy(fx);
    refimg_expect(name, &c);
}

/* Eight arrows at rotations 0, 45, ..., 315 degrees (counter-clockwise:
 * the second points up-right), arrow k showing frame k of the sheet (k + 1
 * ticks: texture_fps = 8k after one step of 1/8 s), in a colour of its
 * own; below, a streak per direction (align = velocity). */
Test(refimg, looks_rotations)
{
    static const char *const colors[8] = {"white", "#ff8080", "#ffc060", "#ffff80",
                                          "#80ff80", "#80ffff", "#8080ff", "#ff80ff"};
    char text[8192];
    int n = snprintf(text, sizeof text,
                     "[scene]\nwidth = 256\nheight = 96\ndt = 1/8\nbackground = #202028\n"
                     "[view]\nxmin = 0\nxmax = 16\nymin = 0\nymax = 6\n");
    for (int k = 0; k < 8; k++)
        n += snprintf(text + n, sizeof text - (size_t)n,
                      "[emitter a%d]\nsource = particle\nposition = %d, 4\nsize = 1.6\ndraw = sprite\n"
                      "texture = textures/arrows.png\ntexture_grid = 4, 2\ntexture_fps = %d\nrotation = %d\n"
                      "color = %s\n"
                      "[emitter s%d]\nsource = particle\nposition = %d, 1.5\nvelocity = %g, %g\nforces = none\n"
                      "draw = sprite\nsprite = smooth\nsize = 0.5\nalign = velocity\ncolor = %s\nblend = add\n",
                      k, 1 + 2 * k, 8 * k, 45 * k, colors[k], k, 1 + 2 * k, k == 2 || k == 6 ? 0.0 : (k < 2 || k > 6 ? 1e-3 : -1e-3),
                      k == 0 || k == 4 ? 0.0 : (k < 4 ? 1e-3 : -1e-3), colors[k]);
    cr_assert_lt((size_t)n, sizeof text);
    /* one step of 1/8 s: arrow k at 8k frames per second shows frame k */
    render_scene("looks_rotations", text, "scenes/looks_rotations.ini", 1);
}
