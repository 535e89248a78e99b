/* SPDX-License-Identifier: MIT */
/* Moving emitters.  Births are placed on the emitter's path at
 * their exact birth times, position(tb) = position + v*tb computed
 * directly, so 30 and 144 steps per second give the same birth positions
 * (bit for bit); a position set live spreads the next frame's births along
 * the way from the old position to the new; local space carries the
 * particles with the emitter. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "iskra/effect.h"
#include "iskra/png.h"
#include "iskra/scene.h"
#include "refimg.h"
#include "scene_text.h"

static isk_effect *open_text(const char *text) { return scene_text_open(text, 0); }

/* 600 units/s, particles with no speed and no forces, at t = 1 s. */
static isk_effect *fast_emitter(const char *dt)
{
    char text[512];
    snprintf(text, sizeof text,
             "[scene]\ndt = %s\n[emitter e]\nsource = stream\nrate = 90\nposition = -300, 2\n"
             "emitter_velocity = 600, -30\n",
             dt);
    return open_text(text);
}

Test(fx_motion_path, same_birth_positions_at_30_and_144_steps)
{
    isk_effect *a = fast_emitter("1/30"), *b = fast_emitter("1/144");
    for (int i = 0; i < 30; i++)
        cr_assert_eq(isk_effect_step(a), ISK_OK);
    for (int i = 0; i < 144; i++)
        cr_assert_eq(isk_effect_step(b), ISK_OK);
    cr_assert_eq(isk_effect_time(a), 1.0);
    cr_assert_eq(isk_effect_time(b), 1.0);
    const isk_particles *p = isk_effect_particles(a, 0), *q = isk_effect_particles(b, 0);
    cr_assert_eq(p->count, 90);
    cr_assert_eq(q->count, 90);
    for (size_t i = 0; i < p->count; i++) {
        cr_assert(p->x[i] == q->x[i] && p->y[i] == q->y[i], "birth %zu: (%.17g, %.17g) vs (%.17g, %.17g)", i, p->x[i],
                  p->y[i], q->x[i], q->y[i]);
        /* exactly position + v*tb, tb = (k+1)/rate */
        const double tb = 0.0 + (double)(i + 1) / 90.0;
        cr_assert(p->x[i] == -300 + 600 * (tb - 0.0) && p->y[i] == 2 + -30 * (tb - 0.0), "birth %zu off the path", i);
    }
    /* no gaps: evenly spaced along the path, 600/90 units apart */
    for (size_t i = 1; i < p->count; i++)
        cr_assert_float_eq(p->x[i] - p->x[i - 1], 600.0 / 90.0, 1e-9);
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

/* The mouse-follow case: the position set live before each frame; every
 * frame's births lie on the segment from the old position to the new, in
 * birth order, with no gap between frames. */
Test(fx_motion_path, live_position_spreads_births_along_the_way)
{
    isk_effect *fx = open_text("[scene]\ndt = 1/60\n[emitter e]\nsource = stream\nrate = 600\nposition = 0, 0\n");
    isk_error err;
    for (int f = 1; f <= 6; f++) {
        char v[64];
        snprintf(v, sizeof v, "%d, %d", 10 * f, f % 2 ? 3 : -3); /* a zig-zag */
        cr_assert_eq(isk_effect_set(fx, "emitter e", "position", v, &err), ISK_OK, "%s", err.message);
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    }
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_eq(p->count, 60);
    for (size_t i = 0; i < p->count; i++) {
        /* birth k+1 at (k+1)/600 s: frame f = k/10, a tenth of it per birth */
        const int f = (int)(i / 10), k = (int)(i % 10) + 1;
        const double x0 = 10.0 * f, y0 = f == 0 ? 0 : (f % 2 ? 3 : -3), x1 = 10.0 * (f + 1),
                     y1 = (f + 1) % 2 ? 3 : -3;
        cr_assert_float_eq(p->x[i], x0 + (x1 - x0) * k / 10.0, 1e-9, "birth %zu at %.17g", i, p->x[i]);
        cr_assert_float_eq(p->y[i], y0 + (y1 - y0) * k / 10.0, 1e-9, "birth %zu at %.17g", i, p->y[i]);
    }
    char got[64];
    cr_assert_eq(isk_effect_get(fx, "emitter e", "position", got, sizeof got, &err), ISK_OK);
    cr_assert_str_eq(got, "60, -3");
    /* standing still afterwards: births at the last position */
    for (int f = 0; f < 2; f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    for (size_t i = 60; i < p->count; i++)
        cr_assert(p->x[i] == 60 && p->y[i] == -3);
    isk_effect_destroy(fx);
}

/* A live velocity change continues the path from where the emitter is. */
Test(fx_motion_path, live_velocity_change_has_no_jump)
{
    isk_effect *fx = open_text("[scene]\ndt = 1/10\n[emitter e]\nsource = stream\nrate = 10\n"
                               "emitter_velocity = 10, 0\n");
    isk_error err;
    for (int f = 0; f < 5; f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_set(fx, "emitter e", "emitter_velocity", "0, 20", &err), ISK_OK, "%s", err.message);
    for (int f = 0; f < 5; f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_eq(p->count, 10);
    cr_assert_float_eq(p->x[4], 5, 1e-12);
    for (size_t i = 5; i < 10; i++) {
        cr_assert_float_eq(p->x[i], 5, 1e-12, "%zu", i);
        cr_assert_float_eq(p->y[i], 2.0 * (double)(i - 4), 1e-9, "%zu: %.17g", i, p->y[i]);
    }
    isk_effect_destroy(fx);
}

/* Local space: the particles keep their place relative to the emitter
 * (here launched straight up, no forces: x stays the emitter's x); world
 * space leaves them along the path. */
Test(fx_motion_path, local_space_moves_with_the_emitter)
{
    const char *text = "[scene]\ndt = 1/50\nsubsteps = 2\n[emitter e]\nsource = stream\nrate = 100\n"
                       "velocity = 0, 1\nemitter_velocity = 5, 0\nposition = -2, 0\nspace = %s\n";
    char t[512];
    snprintf(t, sizeof t, text, "local");
    isk_effect *loc = open_text(t);
    snprintf(t, sizeof t, text, "world");
    isk_effect *wld = open_text(t);
    for (int f = 0; f < 50; f++) {
        cr_assert_eq(isk_effect_step(loc), ISK_OK);
        cr_assert_eq(isk_effect_step(wld), ISK_OK);
    }
    const isk_particles *p = isk_effect_particles(loc, 0), *q = isk_effect_particles(wld, 0);
    cr_assert_eq(p->count, 100);
    cr_assert_eq(q->count, 100);
    for (size_t i = 0; i < p->count; i++) {
        cr_assert_float_eq(p->x[i], 3.0, 1e-9, "%zu at x %.17g: not carried", i, p->x[i]);
        cr_assert_float_eq(p->y[i], q->y[i], 1e-9); /* the same rise */
        cr_assert_float_eq(q->x[i], -2 + 5 * (i + 1) / 100.0, 1e-9, "%zu: world space stays on the path", i);
    }
    /* a live jump carries them too: the emitter is at 3 and reaches -12 at the frame's end */
    isk_error err;
    cr_assert_eq(isk_effect_set(loc, "emitter e", "position", "-12, 0", &err), ISK_OK, "%s", err.message);
    const double before = p->x[0];
    cr_assert_eq(isk_effect_step(loc), ISK_OK);
    cr_assert_float_eq(p->x[0] - before, -15, 1e-9, "%.17g", p->x[0] - before);
    isk_effect_destroy(loc);
    isk_effect_destroy(wld);
}

/* A local-space emitter riding into a wall: the carry never pushes a
 * particle through a closed wall (it used to, after the walls had run:
 * 1,498 of 1,666 ended beyond the right wall).  It stops them on the wall,
 * an outward velocity turned back as a bounce, on 1 and 3 threads alike. */
Test(fx_motion_path, local_space_never_carries_past_a_wall)
{
    const char *text = "[scene]\ndt = 1/60\nseed = 3\n[bounds]\nwindow = -10, 10, -10, 10\n[emitter e]\n"
                       "source = stream\nrate = 833\nlife = 2\nlaunch = disc\nspeed_max = 3\nposition = -5, 0\n"
                       "emitter_velocity = 7.4, 0\nspace = local\n";
    isk_effect *fx = scene_text_open(text, 1), *fx3 = scene_text_open(text, 3);
    size_t beyond_ever = 0, on_the_wall = 0;
    for (int f = 0; f < 120; f++) {
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        cr_assert_eq(isk_effect_step(fx3), ISK_OK);
        const isk_particles *p = isk_effect_particles(fx, 0);
        size_t beyond = 0;
        on_the_wall = 0;
        for (size_t i = 0; i < p->count; i++) {
            beyond += p->x[i] > 10 || p->x[i] < -10 || p->y[i] > 10 || p->y[i] < -10;
            on_the_wall += p->x[i] == 10;
        }
        beyond_ever = beyond > beyond_ever ? beyond : beyond_ever;
    }
    const isk_particles *p = isk_effect_particles(fx, 0), *q = isk_effect_particles(fx3, 0);
    cr_assert_eq(p->count, 1666);
    cr_assert_eq(beyond_ever, 0, "up to %zu of %zu beyond a wall", beyond_ever, p->count);
    cr_assert_gt(on_the_wall, 100, "the test rides into the wall: %zu on it", on_the_wall);
    cr_assert_eq(q->count, p->count);
    cr_assert_eq(memcmp(p->x, q->x, p->count * sizeof *p->x), 0);
    cr_assert_eq(memcmp(p->vx, q->vx, p->count * sizeof *p->vx), 0);
    isk_effect_destroy(fx);
    isk_effect_destroy(fx3);
}

/* `iskra play --follow`: the emitter goes where the mouse is, and a fast
 * mouse leaves a line of births, not a spot per frame. */
Test(fx_motion_path, play_follow_leaves_no_gaps, .timeout = 60)
{
    cr_assert_eq(system("mkdir -p out/fx_motion"), 0);
    FILE *f = fopen("out/fx_motion/pen.ini", "w");
    cr_assert_not_null(f);
    fputs("[scene]\nwidth = 200\nheight = 100\n[view]\nxmin = 0\nxmax = 200\nymin = 0\nymax = 100\n"
          "[emitter pen]\nsource = stream\nrate = 3000\ncapacity = 100000\nposition = 20, 50\ndraw = pixel\n"
          "color = white\n",
          f);
    fclose(f);
    remove("out/fx_motion/pen.png");
    char cmd[1024];
    snprintf(cmd, sizeof cmd,
             "SDL_VIDEODRIVER=dummy %s/bin/iskra play out/fx_motion/pen.ini --follow pen --fixed-clock --no-panel "
             "--frames 8 --script 'move:20,50 wait:1 move:180,50 wait:2 canvas-shot:out/fx_motion/pen.png' "
             ">/dev/null 2>&1",
             refimg_build_dir());
    cr_assert_eq(system(cmd), 0, "%s", cmd);
    isk_canvas c;
    isk_error err;
    cr_assert_eq(isk_png_read(&c, "out/fx_motion/pen.png", &err), ISK_OK, "%s", err.message);
    /* one frame from x = 20 to 180 at 3000/s: 50 births, 3.2 px apart */
    int lit = 0, last = -1, gap = 0;
    for (int x = 0; x < c.width; x++)
        if (isk_canvas_get(&c, x, 50).r > 128) {
            if (last >= 0 && x - last > gap)
                gap = x - last;
            last = x;
            lit++;
        }
    cr_assert_geq(lit, 45, "%d pixels lit", lit);
    cr_assert_leq(gap, 4, "a gap of %d px", gap);
    isk_canvas_free(&c);
    snprintf(cmd, sizeof cmd, "SDL_VIDEODRIVER=dummy %s/bin/iskra play out/fx_motion/pen.ini --follow nib --frames 1 "
                              ">/dev/null 2>&1", refimg_build_dir());
    int rc = system(cmd);
    cr_assert(WIFEXITED(rc) && WEXITSTATUS(rc) == 2, "an unknown emitter is a usage error");
}
