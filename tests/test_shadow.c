/* SPDX-License-Identifier: MIT */
/* The shadow run of `iskra play` (--shadow, G; tools/iskra/play_shadow.c),
 * through scripted sessions under SDL's dummy driver: a reference copy of
 * the scene integrated finer beside it.  The sessions end with one line
 * on stderr ("iskra play: shadow at frame N (METHOD at Fx the substeps):
 * median ... px, p99 ... px, max ... px; C of T particles compared from
 * frame K"), which these tests read.  What they check: identical settings
 * give an error of exactly 0, also after live edits; an edit of the
 * integrator leaves the reference its own; semi-Euler's error halves as
 * the substeps double (first order); a rewind starts the reference again
 * there; the scene's own run, its saved scene and its describe are the
 * same with or without the shadow; the window with the shadow on matches
 * refimg/simulator_shadow.png. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/canvas.h"
#include "play_session.h"
#include "refimg.h"
#include "sanitized.h"
#include "tool_cli.h"

#define OUT "out/test_shadow/"

/* Smooth forces (gravity, drag, a potential without limits), no walls:
 * the shadow's rule picks yoshida4, as the scene has. */
#define SMOOTH_SCENE(INTEGRATOR)                                                                                       \
    "[scene]\nwidth = 320\nheight = 240\nseed = 5\nintegrator = " INTEGRATOR "\n[view]\nxmin = -8\nxmax = 8\n"         \
    "ymin = -6\nymax = 6\n[force gravity]\ng = 9.81\n[force drag]\nb = 0.4\n[force well]\nkind = potential\n"         \
    "k = 30\nposition = 0, 0\n[emitter sparks]\nsource = stream\nrate = 400\nposition = 0, -4\n"                       \
    "forces = gravity, drag, well\n[click]\nexplosion = gauss\ncount = 200\nemitter = sparks\n"

/* A floor: not smooth, so the rule picks rk4. */
#define FLOOR_SCENE(INTEGRATOR)                                                                                        \
    "[scene]\nseed = 3\nintegrator = " INTEGRATOR "\n[view]\nxmin = 0\nxmax = 10\nymin = 0\nymax = 10\n"               \
    "[force gravity]\ng = 9.81\n[force drag]\nb = 0.1\n[bounds]\nsides = bottom\n"                                     \
    "[emitter p]\nsource = layer\ncount = 200\nrect = 0, 10, 0, 2\nforces = gravity, drag\n"                           \
    "[click]\nexplosion = gauss\ncount = 300\nemitter = p\n"

typedef struct shadow_line {
    long frame, since;
    char method[16];
    int factor;
    double median, p99, max;
    size_t compared, total;
} shadow_line;

/* The session's last line about the shadow; 0 when there is none. */
static int read_shadow(const char *dir, shadow_line *o)
{
    char *e = play_stderr(dir);
    const char *at = e ? strstr(e, "iskra play: shadow at frame ") : NULL;
    const char *numbers = at ? strstr(at, "): median ") : NULL; /* after "the substeps" and a cap, if any */
    int ok = numbers &&
             sscanf(at, "iskra play: shadow at frame %ld (%15s at %dx the substeps", &o->frame, o->method,
                    &o->factor) == 3 &&
             sscanf(numbers, "): median %lf px, p99 %lf px, max %lf px; %zu of %zu particles compared from frame %ld",
                    &o->median, &o->p99, &o->max, &o->compared, &o->total, &o->since) == 6;
    free(e);
    return ok;
}

static void scene_file(const char *name, const char *text)
{
    (void)system("mkdir -p " OUT);
    cli_write_file(name, text);
}

static shadow_line session(const char *dir, const char *args)
{
    shadow_line s;
    cr_assert_eq(play_session(dir, args), 0, "%s", play_stderr(dir));
    cr_assert(read_shadow(dir, &s), "no shadow line: %s", play_stderr(dir));
    return s;
}

Test(shadow, identical_settings_give_an_error_of_exactly_zero)
{
    scene_file(OUT "smooth.ini", SMOOTH_SCENE("yoshida4"));
    shadow_line s = session(OUT "same", OUT "smooth.ini --shadow --shadow-factor 1 --frames 60");
    cr_expect_str_eq(s.method, "yoshida4");
    cr_expect_eq(s.factor, 1);
    cr_expect_eq(s.frame, 60);
    cr_expect_eq(s.compared, 400);
    cr_expect_eq(s.total, 400);
    cr_expect(s.median == 0 && s.p99 == 0 && s.max == 0, "%g %g %g", s.median, s.p99, s.max);
    /* with a wall the rule picks rk4: a scene at rk4 is its own reference too */
    scene_file(OUT "floor.ini", FLOOR_SCENE("rk4"));
    s = session(OUT "same-rk4", OUT "floor.ini --shadow --shadow-factor 1 --frames 60 --script 'wait:5 click:200,200'");
    cr_expect_str_eq(s.method, "rk4");
    cr_expect_eq(s.compared, 500);
    cr_expect(s.max == 0, "%g", s.max);
    /* and 16x the substeps is a different run: not zero, far below a pixel */
    s = session(OUT "finer", OUT "smooth.ini --shadow --frames 60");
    cr_expect_eq(s.factor, 16);
    cr_expect(s.max > 0 && s.max < 1e-4, "%g", s.max);
    /* 16 x 100 substeps passes the limit: the reference runs 1000 and says so */
    cr_assert_eq(play_session(OUT "capped", OUT "smooth.ini --shadow --substeps 100 --frames 2"), 0);
    char *e = play_stderr(OUT "capped");
    cr_expect(strstr(e, "(yoshida4 at 16x the substeps, capped at 1000)"), "%s", e);
    free(e);
}

/* A click, the drag, a potential's k, the substeps and a potential dragged
 * reach both runs: with identical settings the error stays exactly 0 and
 * the reference never had to start again (from frame 0). */
Test(shadow, live_edits_reach_both_runs)
{
    scene_file(OUT "smooth-edits.ini", SMOOTH_SCENE("yoshida4"));
    shadow_line s = session(OUT "edits", OUT "smooth-edits.ini --shadow --shadow-factor 1 --frames 80 --script 'wait:5 "
                                             "click:100,60 wait:5 press:drag wait:2 key:backspace key:backspace "
                                             "key:backspace type:0.9 key:return wait:5 press:pot-k wait:2 "
                                             "key:backspace key:backspace type:50 key:return wait:5 press:precision "
                                             "wait:2 key:backspace type:3 key:return wait:5 "
                                             "drag:160,120,200,100 wait:5'");
    cr_expect_eq(s.since, 0);
    cr_expect_eq(s.compared, s.total);
    cr_expect_gt(s.total, 600); /* the click's 200 are there */
    cr_expect(s.max == 0, "%g", s.max);
}

/* The scene switched to semi-Euler: the reference keeps yoshida4, so the
 * error is no longer 0. */
Test(shadow, an_integrator_edit_leaves_the_reference_its_own)
{
    scene_file(OUT "smooth-integrator.ini", SMOOTH_SCENE("yoshida4"));
    shadow_line s = session(OUT "integrator", OUT "smooth-integrator.ini --shadow --shadow-factor 1 --frames 40 "
                                                  "--script 'wait:5 press:integrator/semi-euler'");
    cr_expect_str_eq(s.method, "yoshida4");
    cr_expect_eq(s.since, 0);
    cr_expect(s.median > 0.1 && s.max > s.median, "%g %g", s.median, s.max);
}

/* Semi-Euler is first order: doubling the substeps halves the error the
 * shadow shows (60 frames, 400 particles). */
Test(shadow, semi_euler_error_halves_as_substeps_double)
{
    scene_file(OUT "semi-halves.ini", SMOOTH_SCENE("semi-euler"));
    shadow_line s[3];
    for (int i = 0; i < 3; i++) {
        char dir[64], args[200];
        snprintf(dir, sizeof dir, OUT "semi%d", 1 << i);
        snprintf(args, sizeof args, OUT "semi-halves.ini --substeps %d --shadow --frames 60", 1 << i);
        s[i] = session(dir, args);
        cr_expect_eq(s[i].compared, 400);
    }
    static const double median[3] = {0.204, 0.102, 0.051}; /* docs/simulator.md, "The shadow run" */
    for (int i = 0; i < 3; i++)
        cr_expect(fabs(s[i].median - median[i]) < 0.0005, "%g", s[i].median);
    for (int i = 0; i < 2; i++) {
        const double rm = s[i].median / s[i + 1].median, rp = s[i].p99 / s[i + 1].p99;
        cr_expect(rm > 1.8 && rm < 2.2, "median %g / %g", s[i].median, s[i + 1].median);
        cr_expect(rp > 1.8 && rp < 2.2, "p99 %g / %g", s[i].p99, s[i + 1].p99);
    }
}

/* The figure of docs/simulator.md, "The shadow run": fig 29 at 1 and 4
 * substeps, 60 frames after its start (frame 61): the median falls, the
 * 99th percentile of the jet's chaotic paths barely moves.  Instrumented
 * builds (sanitizers: ten times slower) check the same fall over 10
 * frames; the figures are the plain build's. */
Test(shadow, fig29_the_median_falls_the_tail_does_not, .timeout = 120)
{
#if TEST_SANITIZED
#define FIG29_FRAMES "11"
#else
#define FIG29_FRAMES "61"
#endif
    shadow_line s1 =
        session(OUT "fig29-1", "fig29_mushroom_four_potentials --shadow --frames " FIG29_FRAMES " --script 'key:p'");
    shadow_line s4 = session(OUT "fig29-4", "fig29_mushroom_four_potentials --shadow --substeps 4 --frames " FIG29_FRAMES
                                            " --script 'key:p'");
    cr_expect_str_eq(s1.method, "rk4");
    cr_expect_eq(s1.frame, atol(FIG29_FRAMES));
    cr_expect_eq(s1.compared, 16000);
    cr_expect_eq(s4.compared, 16000);
    cr_expect_lt(s4.median, s1.median, "more substeps, a smaller median");
#if !TEST_SANITIZED
    cr_expect(fabs(s1.median - 0.198) < 0.0005 && fabs(s4.median - 0.117) < 0.0005, "%g %g", s1.median, s4.median);
    cr_expect(fabs(s1.p99 - 27.0) < 0.05 && fabs(s4.p99 - 24.1) < 0.05, "%g %g", s1.p99, s4.p99);
#endif
#undef FIG29_FRAMES
}

/* A killing deflector takes a particle in one run and not in the other:
 * from then on the slots pair different particles, so that emitter is not
 * compared, and the canvas says so. */
Test(shadow, an_emitter_whose_counts_differ_is_not_compared)
{
    scene_file(OUT "kill.ini", "[scene]\nwidth = 320\nheight = 240\nseed = 5\n[view]\nxmin = -8\nxmax = 8\n"
                               "ymin = -6\nymax = 6\n[force gravity]\ng = 9.81\n[force well]\nkind = potential\n"
                               "k = 30\nposition = 0, 0\n[deflector catch]\nsegment = -1, -3, 1, -3\n"
                               "reaction = kill\n[emitter sparks]\nsource = stream\nrate = 400\nshape = disc\n"
                               "shape_a = 2\nposition = 0, 4\nforces = gravity, well\ndeflectors = catch\n");
    shadow_line s = session(OUT "kill", OUT "kill.ini --shadow --frames 90");
    cr_expect_str_eq(s.method, "rk4"); /* a deflector: not smooth */
    cr_expect_gt(s.total, 400);
    cr_expect_eq(s.compared, 0);
    cr_expect(s.max == 0, "%g", s.max);
    /* before the first particle reaches the deflector, every one is compared */
    shadow_line t = session(OUT "kill-40", OUT "kill.ini --shadow --frames 40");
    cr_expect_eq(t.compared, t.total);
}

/* B goes back: the reference starts again from the frame the run went to. */
Test(shadow, a_rewind_starts_it_again_there)
{
    scene_file(OUT "semi-rewind.ini", SMOOTH_SCENE("semi-euler"));
    shadow_line s =
        session(OUT "rewind", OUT "semi-rewind.ini --shadow --frames 30 --script 'wait:20 key:b key:b key:p'");
    /* the keys arrive after 21 steps (a script's events reach the frame
     * after the wait): two back is frame 19; then the frames left run on */
    cr_expect_eq(s.since, 19, "%ld", s.since);
    cr_expect_gt(s.frame, s.since);
    cr_expect_gt(s.max, 0);
}

/* G turns it on and off; its line is there only while it is on. */
Test(shadow, g_toggles_it)
{
    scene_file(OUT "semi-g.ini", SMOOTH_SCENE("semi-euler"));
    shadow_line s = session(OUT "g", OUT "semi-g.ini --frames 30 --script 'wait:10 key:g'");
    cr_expect_eq(s.since, 11, "%ld", s.since); /* G arrives after 11 steps */
    cr_expect_eq(s.factor, 16);
    cr_assert_eq(play_session(OUT "g2", OUT "semi-g.ini --frames 30 --script 'wait:10 key:g wait:5 key:g'"), 0);
    cr_expect_not(read_shadow(OUT "g2", &s));
    char *e = play_stderr(OUT "g2");
    cr_expect(strstr(e, "shadow off"), "%s", e);
    free(e);
    cr_expect_eq(play_session(OUT "bad", OUT "semi-g.ini --frames 3 --shadow-factor 0"), 2);
    cr_expect_eq(play_session(OUT "bad", OUT "semi-g.ini --frames 3 --shadow-factor x"), 2);
}

/* The shadow is beside the scene, never in it: the canvas, the saved
 * scene and its describe are the same with it on as without. */
Test(shadow, the_scene_is_the_same_with_or_without_it)
{
    scene_file(OUT "semi.ini", SMOOTH_SCENE("semi-euler"));
    const char *script = "--script 'wait:5 click:100,60 wait:5 press:drag wait:2 key:backspace key:backspace "
                         "key:backspace type:0.9 key:return wait:20 f12 f2 wait:2'";
    char args[600];
    for (int on = 0; on < 2; on++) {
        const char *dir = on ? OUT "with" : OUT "without";
        snprintf(args, sizeof args, OUT "semi.ini %s --frames 40 --shots %s --save %s/s.ini %s", on ? "--shadow" : "",
                 dir, dir, script);
        cr_assert_eq(play_session(dir, args), 0, "%s", play_stderr(dir));
    }
    shadow_line s;
    cr_expect(read_shadow(OUT "with", &s) && s.max > 0);
    isk_canvas a, b;
    play_read_png(OUT "with/iskra-semi-000034.png", &a);
    play_read_png(OUT "without/iskra-semi-000034.png", &b);
    cr_expect(isk_canvas_equal(&a, &b), "the shadow changed the scene's canvas");
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    char *sa = cli_slurp(OUT "with/s.ini"), *sb = cli_slurp(OUT "without/s.ini");
    cr_expect_str_eq(sa, sb);
    free(sa);
    free(sb);
    cr_assert_eq(cli_run(OUT "with", "describe " OUT "with/s.ini"), 0);
    cr_assert_eq(cli_run(OUT "without", "describe " OUT "without/s.ini"), 0);
    sa = cli_slurp(OUT "with/stdout.txt");
    sb = cli_slurp(OUT "without/stdout.txt");
    cr_expect_str_eq(sa, sb);
    cr_expect(strstr(sa, "semi-euler") && !strstr(sa, "yoshida4"), "%s", sa);
    free(sa);
    free(sb);
}

/* The window with the shadow on: ghosts over the floor scene after a
 * click, the text and the chart at the canvas's top right. */
Test(shadow, the_window_with_the_shadow_on)
{
    scene_file(OUT "floor-semi.ini", FLOOR_SCENE("semi-euler"));
    const char *args = OUT "floor-semi.ini --shadow --substeps 1 --ui-scale 1 --screen 1280x720 --frames 70 "
                           "--script 'wait:5 click:300,250 wait:60 shot:" OUT "window/w.png'";
    cr_assert_eq(play_session(OUT "window", args), 0, "%s", play_stderr(OUT "window"));
    isk_canvas c;
    play_read_png(OUT "window/w.png", &c);
    cr_expect(refimg_check("simulator_shadow", &c));
    isk_canvas_free(&c);
}
