/* SPDX-License-Identifier: MIT */
/* The campfire example: its strip of the first second matches
 * refimg/fire_campfire_strip.png exactly, the same seed gives the same
 * bytes, and the wind leans the fire and smoke.  (The default frame is
 * checked by tests/test_examples.c with every other example.) */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include "iskra/png.h"
#include "refimg.h"

static int run(const char *args)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s/examples/fire_campfire %s", refimg_build_dir(), args);
    int rc = system(cmd);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

static void load(isk_canvas *c, const char *path)
{
    isk_error err;
    cr_assert_eq(isk_png_read(c, path, &err), ISK_OK, "%s", err.message);
}

Test(refimg, fire_campfire_strip, .timeout = 120)
{
    mkdir("out", 0777);
    mkdir("out/examples", 0777);
    cr_assert_eq(run("--strip out/examples/fire_campfire_strip.png"), 0);
    isk_canvas c;
    load(&c, "out/examples/fire_campfire_strip.png");
    cr_assert_eq(c.width, 6 * 240 + 5 * 4);
    cr_assert_eq(c.height, 200);
    cr_assert(refimg_check("fire_campfire_strip", &c));
    isk_canvas_free(&c);
}

/* Brightness-weighted x centroid of the pixels brighter than the night
 * sky, in the upper part of the image (flames and smoke, not the logs). */
static double centroid_x(const isk_canvas *c)
{
    double sw = 0, sx = 0;
    for (int y = 0; y < c->height * 3 / 4; y++)
        for (int x = 0; x < c->width; x++) {
            const uint8_t *p = isk_canvas_at(c, x, y);
            double w = p[0] + p[1] + p[2] - 60.0;
            if (w > 0) {
                sw += w;
                sx += w * x;
            }
        }
    return sw > 0 ? sx / sw : -1;
}

Test(fire_campfire, deterministic_and_wind_leans_it, .timeout = 120)
{
    mkdir("out", 0777);
    mkdir("out/examples", 0777);
    cr_assert_eq(run("--png out/examples/fire_campfire_a.png --seed 7 --frames 120"), 0);
    cr_assert_eq(run("--png out/examples/fire_campfire_b.png --seed 7 --frames 120"), 0);
    cr_assert_eq(run("--png out/examples/fire_campfire_w.png --seed 7 --frames 120 --wind 3"), 0);
    cr_assert_eq(run("--wind nonsense --png out/examples/x.png 2>/dev/null"), 2);
    isk_canvas a, b, w;
    load(&a, "out/examples/fire_campfire_a.png");
    load(&b, "out/examples/fire_campfire_b.png");
    load(&w, "out/examples/fire_campfire_w.png");
    cr_assert(isk_canvas_equal(&a, &b));
    double ca = centroid_x(&a), cw = centroid_x(&w);
    /* Calm: centred on the fire (x = 240 of 480); wind 3 to the right. */
    cr_assert(ca > 225 && ca < 255, "calm centroid %g", ca);
    cr_assert_gt(cw, ca + 20, "wind centroid %g vs calm %g", cw, ca);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_canvas_free(&w);
}
