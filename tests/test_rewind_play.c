/* SPDX-License-Identifier: MIT */
/* Rewind in `iskra play` (scripted sessions, one step a shown frame): B
 * steps back one frame, the timeline bar scrubs, and a session that went
 * back and forth ends on the canvas of one that never did; the bar is
 * drawn only when shown, so sessions without it keep their pixels. */
#include <criterion/criterion.h>
#include <stdlib.h>
#include <string.h>

#include "play_session.h"

#define OUT "out/test_rewind_play/"

static int same_png(const char *a, const char *b)
{
    isk_canvas x, y;
    play_read_png(a, &x);
    play_read_png(b, &y);
    int same = x.width == y.width && x.height == y.height;
    for (int r = 0; same && r < x.height; r++)
        same = !memcmp(x.pixels + (size_t)r * x.stride, y.pixels + (size_t)r * y.stride, (size_t)x.width * 4);
    isk_canvas_free(&x);
    isk_canvas_free(&y);
    return same;
}

/* Held at frame F + 10 then ten times B: the canvas of frame F. */
Test(rewind_play, b_steps_back_one_frame)
{
    cr_assert_eq(play_session(OUT "straight", "fire_campfire --ui-scale 1 --frames 60 --script "
                                              "'wait:30 space wait:2 canvas-shot:" OUT "straight/c.png'"),
                 0, "%s", play_stderr(OUT "straight"));
    cr_assert_eq(play_session(OUT "back", "fire_campfire --ui-scale 1 --frames 80 --script "
                                          "'wait:40 space wait:2 b b b b b b b b b b wait:2 canvas-shot:" OUT
                                          "back/c.png'"),
                 0, "%s", play_stderr(OUT "back"));
    cr_assert(same_png(OUT "straight/c.png", OUT "back/c.png"), "ten frames back is not the frame ten back");
}

/* Scrubbing on the bar, back and forth, then on to the end (the bar's
 * right end is the furthest frame): the canvas of a session that only ran. */
Test(rewind_play, scrubbing_then_running_on_is_the_straight_run)
{
    cr_assert_eq(play_session(OUT "run", "fire_campfire --ui-scale 1 --frames 90 --script "
                                         "'wait:40 space wait:2 space wait:20 space wait:2 canvas-shot:" OUT
                                         "run/c.png'"),
                 0, "%s", play_stderr(OUT "run"));
    /* the campfire's canvas is 480 x 400: the bar's track lies along y 394..399 */
    cr_assert_eq(play_session(OUT "scrub", "fire_campfire --ui-scale 1 --frames 120 --script "
                                           "'wait:40 space wait:2 t wait:1 click:100,397 wait:1 click:450,397 wait:1 "
                                           "drag:20,397,300,397 wait:2 b b wait:1 click:479,397 wait:2 space wait:20 "
                                           "space wait:2 canvas-shot:" OUT "scrub/c.png'"),
                 0, "%s", play_stderr(OUT "scrub"));
    cr_assert(same_png(OUT "run/c.png", OUT "scrub/c.png"), "scrubbing changed where the run went");
}
