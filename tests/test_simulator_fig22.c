/* SPDX-License-Identifier: MIT */
/* Thesis figure 22 (the regular explosion in the simulator) reproduced by
 * the simulator.
 *
 * The screenshot's panel shows gravity 10, drag 0.3, the slowest speed
 * (f = 30: each frame 1/1800 s) and the four walls on.  Fitting the ring's
 * centre and size gives the click at canvas pixel (297, 221) and 1521
 * frames after it; there, with the thesis's arithmetic (fidelity thesis)
 * and the browser's dot, the set of lit pixels equals the screenshot's
 * exactly (3292 pixels, outside the FPS text), which is more than the
 * "within 1 px" asked for.
 *
 * 1. The library alone: the scene, the four settings, the click, 1521
 *    frames, compared with ../shared/reference/thesis-figures/ when it is
 *    there (skipped otherwise).
 * 2. The simulator, driven through its panel by a script (the speed slider
 *    down with its key, the fields typed, the walls clicked, the click on
 *    the canvas): its canvas is the library's to the byte, and its window
 *    is refimg/simulator_fig22.png. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "iskra/effect.h"
#include "iskra/png.h"
#include "iskra/scene.h"
#include "refimg.h"
#include "scene_open.h"
#include "tool_cli.h"

#define FIG "../shared/reference/thesis-figures/fig22-PESimulator.png"
#define OUT "out/test_simulator_fig22"
#define CLICK_X 297
#define CLICK_Y 221
#define FRAMES 1521

/* The screenshot's canvas sits at (53, 5) inside its 5 px border. */
#define SHOT_X 53
#define SHOT_Y 5

static void fig22_canvas(isk_canvas *c)
{
    isk_effect *fx = scene_open_builtin("fig22_simulator_regular");
    isk_error err;
    static const char *const sets[][3] = {{"force gravity", "g", "10"},
                                          {"force drag", "b", "0.3"},
                                          {"scene", "speed_divisor", "30"},
                                          {"bounds", "sides", "all"}};
    for (int i = 0; i < 4; i++)
        cr_assert_eq(isk_effect_set(fx, sets[i][0], sets[i][1], sets[i][2], &err), ISK_OK, "%s", err.message);
    /* the thesis: the click's whole pixel, (X - px) / sx and (Y - py) / sy */
    double x, y;
    isk_view_to_world(isk_effect_view(fx), CLICK_X, CLICK_Y, &x, &y);
    cr_assert_eq(isk_effect_click(fx, x, y), ISK_OK);
    cr_assert_eq(isk_canvas_init(c, 600, 600), ISK_OK);
    cr_assert_eq(isk_effect_run(fx, c, FRAMES), ISK_OK);
    isk_effect_destroy(fx);
}

static int lit(const uint8_t *p) { return (p[0] | p[1] | p[2]) != 0; }

/* The FPS text's corner is not the simulation's. */
static int in_fps_text(int x, int y) { return x < 200 && y < 40; }

Test(fig22, the_canvas_lights_exactly_the_screenshots_pixels)
{
    struct stat st;
    if (stat(FIG, &st) != 0)
        cr_skip_test("thesis screenshots not available");
    isk_canvas ours, shot;
    isk_error err;
    fig22_canvas(&ours);
    cr_assert_eq(isk_png_read(&shot, FIG, &err), ISK_OK, "%s", err.message);
    long lit_ours = 0, lit_theirs = 0, only_ours = 0, only_theirs = 0, far = 0;
    double sum = 0;
    int max = 0;
    for (int y = 0; y < 600; y++)
        for (int x = 0; x < 600; x++) {
            if (in_fps_text(x, y))
                continue;
            const uint8_t *a = isk_canvas_at(&ours, x, y), *b = isk_canvas_at(&shot, SHOT_X + x, SHOT_Y + y);
            lit_ours += lit(a);
            lit_theirs += lit(b);
            only_ours += lit(a) && !lit(b);
            only_theirs += lit(b) && !lit(a);
            if (lit(a) || lit(b)) {
                int d = abs(a[0] - b[0]);
                sum += d;
                max = d > max ? d : max;
            }
            /* within 1 px: a lit pixel of ours with no lit neighbour in theirs */
            if (lit(a)) {
                int near = 0;
                for (int dy = -1; dy <= 1 && !near; dy++)
                    for (int dx = -1; dx <= 1 && !near; dx++)
                        if (x + dx >= 0 && y + dy >= 0 && x + dx < 600 && y + dy < 600)
                            near = lit(isk_canvas_at(&shot, SHOT_X + x + dx, SHOT_Y + y + dy));
                far += !near;
            }
        }
    printf("fig22: lit %ld ours, %ld thesis; %ld only ours, %ld only thesis, %ld farther than 1 px; "
           "red channel over lit pixels: mean |d| %.2f, max %d\n",
           lit_ours, lit_theirs, only_ours, only_theirs, far, lit_ours ? sum / (double)lit_ours : 0.0, max);
    cr_expect_eq(far, 0);
    cr_expect_eq(only_ours, 0);
    cr_expect_eq(only_theirs, 0);
    cr_expect_eq(lit_ours, lit_theirs);
    isk_canvas_free(&ours);
    isk_canvas_free(&shot);
}

Test(fig22, the_simulator_gets_there_through_its_panel, .timeout = 300)
{
    cli_fresh(OUT);
    /* ',' ten times: the speed slider from 1000 to 1 (f = 30); the fields
     * typed; the four walls clicked on; the click; the panel hidden while
     * the 1521 frames run (they are cheaper without it) and shown again. */
    char args[2048];
    snprintf(args, sizeof args,
             "play fig22_simulator_regular --fixed-clock --ui-scale 2 --frames 1600 --script '"
             ", , , , , , , , , , press:gravity wait:2 key:backspace type:10 key:return "
             "press:drag wait:2 key:backspace type:0.3 key:return "
             "press:wall-top press:wall-right press:wall-bottom press:wall-left wait:6 "
             "click:%d,%d tab wait:%d tab wait:2 shot:" OUT "/window.png canvas-shot:" OUT "/canvas.png'",
             CLICK_X, CLICK_Y, FRAMES - 2);
    int rc = cli_run(OUT, args);
    cr_assert_eq(rc, 0, "%s", cli_slurp(OUT "/stderr.txt"));
    isk_canvas canvas, window, want;
    isk_error err;
    cr_assert_eq(isk_png_read(&canvas, OUT "/canvas.png", &err), ISK_OK, "%s", err.message);
    fig22_canvas(&want);
    cr_expect(isk_canvas_equal(&canvas, &want), "the simulator's canvas is not the library's");
    cr_assert_eq(isk_png_read(&window, OUT "/window.png", &err), ISK_OK, "%s", err.message);
    cr_expect(refimg_check("simulator_fig22", &window));
    isk_canvas_free(&canvas);
    isk_canvas_free(&window);
    isk_canvas_free(&want);
}
