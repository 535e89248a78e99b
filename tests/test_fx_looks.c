/* SPDX-License-Identifier: MIT */
/* The looks of a particle: rotation, spin, align, size_range,
 * color_pick, texture, texture_grid, texture_fps.  Per key: bytes differ
 * with it, equal at its default, bad values refused with FILE:LINE and
 * exit 2 (tests/key_case.h); then what each key means, in numbers: a
 * rotation of 0 is the unrotated blit, a particle's texture is exactly
 * isk_draw_texture's with the documented angle, size and frame, flipbook
 * frames, picked colours on their gradient, sizes in their range, angles
 * bounded, the stages and columns only where used, the same bytes on any
 * number of threads. */
#include <criterion/criterion.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../tools/looks_texture.h"
#include "iskra/effect.h"
#include "iskra/png.h"
#include "iskra/scene.h"
#include "scene/effect_internal.h" /* band_min_work */
#include "iskra/texture.h"
#include "iskra/texture_png.h"
#include "key_case.h"
#include "scene_text.h"
#include "tool_cli.h"

#define PI 3.14159265358979323846
#define TEX "scenes/textures/arrows.png"

/* The absolute path of a file of the repository (the tests' cwd), so a
 * scene written anywhere finds it. */
static const char *abs_path(const char *rel)
{
    static char buf[4][1024];
    static int k;
    char cwd[700];
    cr_assert_not_null(getcwd(cwd, sizeof cwd));
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", cwd, rel);
    return buf[k];
}

static const char *stream_base(const char *extra)
{
    static char buf[2][2048];
    static int k;
    k = (k + 1) % 2;
    snprintf(buf[k], sizeof buf[k],
             "[scene]\nwidth = 64\nheight = 48\nseed = 5\n[view]\nxmin = -4\nxmax = 4\nymin = -3\nymax = 3\n"
             "[emitter e]\nsource = stream\nrate = 40\nlaunch = disc\nspeed_max = 2\nlife = 2\nsize = 0.8\n"
             "%s%%s\n",
             extra);
    return buf[k];
}

/* A stream of textured particles: one image, and the 4 x 2 sheet. */
static const char *tex_base(void)
{
    static char extra[1200];
    snprintf(extra, sizeof extra, "draw = sprite\ncolor = white\ntexture = %s\n", abs_path(TEX));
    return stream_base(extra);
}

static const char *sheet_base(void)
{
    static char extra[1200];
    snprintf(extra, sizeof extra, "draw = sprite\ncolor = white\ntexture = %s\ntexture_grid = 4, 2\n", abs_path(TEX));
    return stream_base(extra);
}

Test(looks_keys, rotation)
{
    key_case_differs(tex_base(), "rotation = 30", 20);
    key_case_same(tex_base(), "rotation = 0", 20);
    key_case_same(tex_base(), "rotation = 360", 20); /* wraps to exactly 0 */
    key_case_rejects(tex_base(), "rotation = fast", "rotation");
    key_case_rejects(tex_base(), "rotation = 4000", "rotation");
}

Test(looks_keys, rotation_range)
{
    key_case_differs(tex_base(), "rotation_range = 90", 20);
    key_case_same(tex_base(), "rotation_range = 0", 20);
    key_case_rejects(tex_base(), "rotation_range = -5", "rotation_range");
}

Test(looks_keys, spin)
{
    key_case_differs(tex_base(), "spin = 90", 20);
    key_case_same(tex_base(), "spin = 0", 20);
    key_case_rejects(tex_base(), "spin = 1e9", "spin");
}

Test(looks_keys, spin_range)
{
    key_case_differs(tex_base(), "spin_range = 90", 20);
    key_case_same(tex_base(), "spin_range = 0", 20);
    key_case_rejects(tex_base(), "spin_range = -1", "spin_range");
}

Test(looks_keys, align)
{
    key_case_differs(tex_base(), "align = velocity", 20);
    key_case_differs(stream_base("draw = sprite\n"), "align = velocity", 20); /* a sprite kind: streaks */
    key_case_same(tex_base(), "align = none", 20);
    key_case_rejects(tex_base(), "align = sideways", "align");
}

Test(looks_keys, size_range)
{
    key_case_differs(tex_base(), "size_range = 0.5", 20);
    key_case_differs(stream_base("draw = disc\n"), "size_range = 0.5", 20);
    key_case_differs(stream_base("draw = sprite\n"), "size_range = 0.5", 20);
    key_case_same(tex_base(), "size_range = 0", 20);
    key_case_rejects(tex_base(), "size_range = -1", "size_range");
}

Test(looks_keys, color_pick)
{
    key_case_differs(tex_base(), "color_pick = 0:red, 1:blue", 20);
    key_case_differs(stream_base("draw = sprite\n"), "color_pick = 0:red, 1:blue", 20);
    key_case_same(tex_base(), "color_pick = off", 20);
    key_case_rejects(tex_base(), "color_pick = 0:red, 2:blue", "color_pick");
}

Test(looks_keys, texture)
{
    char line[1200];
    snprintf(line, sizeof line, "texture = %s", abs_path(TEX));
    key_case_differs(stream_base("draw = sprite\n"), line, 20);
    key_case_rejects(stream_base("draw = sprite\n"), "texture = no_such_texture.png", "no_such_texture.png");
    snprintf(line, sizeof line, "texture = %s", abs_path("scenes/looks_pinwheel.ini"));
    key_case_rejects(stream_base("draw = sprite\n"), line, "looks_pinwheel.ini"); /* not a PNG */
}

Test(looks_keys, texture_grid)
{
    key_case_differs(tex_base(), "texture_grid = 4, 2", 20);
    key_case_same(tex_base(), "texture_grid = 1, 1", 20);
    key_case_rejects(tex_base(), "texture_grid = 3, 2", "arrows.png"); /* 64 px in 3 columns */
    key_case_rejects(tex_base(), "texture_grid = 1.5, 1", "texture_grid");
    key_case_rejects(tex_base(), "texture_grid = 0, 1", "texture_grid");
}

Test(looks_keys, texture_fps)
{
    key_case_differs(sheet_base(), "texture_fps = 10", 20);
    key_case_same(sheet_base(), "texture_fps = 0", 20);
    key_case_rejects(sheet_base(), "texture_fps = -1", "texture_fps");
}

/* ---- what the keys mean ------------------------------------------------------ */

static isk_effect *make(const char *text) { return scene_text_open(text, 0); }
static char *describe(const isk_effect *fx) { return scene_text_lists(fx); }

/* One resting particle at the origin of a 64x64 canvas (view -4..4, 8 px
 * a unit), drawn as the sheet's texture with `extra` keys. */
static isk_effect *one_in(const char *color, const char *extra)
{
    char text[2048];
    snprintf(text, sizeof text,
             "[scene]\nwidth = 64\nheight = 64\ndt = 1/64\n[view]\nxmin = -4\nxmax = 4\nymin = -4\nymax = 4\n"
             "[emitter e]\nsource = particle\nposition = 0.25, -0.5\nsize = 3\ncolor = %s\nblend = over\n"
             "draw = sprite\ntexture = " TEX "\n%s\n",
             color, extra);
    return make(text);
}

static isk_effect *one(const char *extra)
{
    return one_in("#ffc080", extra);
}

static isk_texture sheet(int cols, int rows)
{
    isk_texture t;
    isk_error err;
    cr_assert_eq(isk_texture_load(&t, TEX, cols, rows, &err), ISK_OK, "%s", err.message);
    return t;
}

/* The effect's canvas against isk_draw_texture of the documented
 * arguments on the background. */
static void expect_draw(isk_effect *fx, const isk_texture *t, int frame, double angle, const char *what)
{
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, 64, 64), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 64, 64), ISK_OK);
    cr_assert_eq(isk_effect_render(fx, &a), ISK_OK);
    isk_canvas_fill(&b, ISK_BLACK);
    /* (0.25, -0.5) is pixel (34, 36); size 3 is 24 px wide, frames keep their aspect */
    isk_draw_texture(&b, t, frame, 34.0, 36.0, 24.0, 24.0 * t->frame_h / t->frame_w, angle, isk_rgba(255, 192, 128, 255),
                     ISK_BLEND_OVER);
    cr_assert(key_case_equal(&a, &b), "%s: not isk_draw_texture's bytes", what);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(looks, a_particle_is_isk_draw_texture_with_the_documented_angle)
{
    isk_texture t = sheet(1, 1);
    isk_effect *fx = one("");
    expect_draw(fx, &t, 0, 0.0, "no rotation");
    isk_effect_destroy(fx);
    fx = one("rotation = 0");
    expect_draw(fx, &t, 0, 0.0, "rotation 0"); /* the unrotated blit, byte for byte */
    isk_effect_destroy(fx);
    /* counter-clockwise in the world (y up) is clockwise-negative on the screen (y down) */
    fx = one("rotation = 30");
    expect_draw(fx, &t, 0, -30 * (PI / 180), "rotation 30");
    isk_effect_destroy(fx);
    fx = one("rotation = 90");
    expect_draw(fx, &t, 0, -90 * (PI / 180), "rotation 90");
    isk_effect_destroy(fx);
    isk_texture_free(&t);
}

Test(looks, align_velocity_turns_by_atan2_of_the_screen_velocity)
{
    isk_texture t = sheet(1, 1);
    /* dt is 1/64 s but the particle is drawn before any step: at rest where it was put */
    isk_effect *fx = one("velocity = -1, 1\nalign = velocity");
    expect_draw(fx, &t, 0, atan2(1.0 * -8.0, -1.0 * 8.0), "velocity (-1, 1)");
    isk_effect_destroy(fx);
    fx = one("velocity = 2, 0\nalign = velocity\nrotation = 45");
    expect_draw(fx, &t, 0, -45 * (PI / 180) + atan2(0.0 * -8.0, 2.0 * 8.0), "velocity (2, 0) + 45");
    isk_effect_destroy(fx);
    isk_texture_free(&t);
}

/* Frame k of a flipbook over a life of 1 s at dt = 1/64 (ages exact in
 * binary): floor(t * 8) after n frames, t = n / 64; with texture_fps,
 * floor(age * fps) mod 8. */
Test(looks, flipbook_frame_numbers)
{
    isk_texture t = sheet(4, 2);
    const int steps[] = {0, 5, 8, 20, 47, 63};
    for (size_t k = 0; k < sizeof steps / sizeof steps[0]; k++) {
        isk_effect *fx = one("texture_grid = 4, 2\nlife = 1");
        for (int i = 0; i < steps[k]; i++)
            cr_assert_eq(isk_effect_step(fx), ISK_OK);
        char what[64];
        snprintf(what, sizeof what, "life, %d steps", steps[k]);
        expect_draw(fx, &t, steps[k] / 8, 0.0, what);
        isk_effect_destroy(fx);
    }
    const int fps_steps[] = {0, 7, 13, 100, 1000};
    for (size_t k = 0; k < sizeof fps_steps / sizeof fps_steps[0]; k++) {
        isk_effect *fx = one("texture_grid = 4, 2\ntexture_fps = 10");
        for (int i = 0; i < fps_steps[k]; i++)
            cr_assert_eq(isk_effect_step(fx), ISK_OK);
        char what[64];
        snprintf(what, sizeof what, "10 fps, %d steps", fps_steps[k]);
        expect_draw(fx, &t, (fps_steps[k] * 10 / 64) % 8, 0.0, what);
        isk_effect_destroy(fx);
    }
    isk_texture_free(&t);
}

/* Every picked colour is the gradient's at some t: with red -> blue, r + b
 * is 255 (each channel rounded half up: 256 at a tie), g = 0, a = 255; and
 * the picks cover the gradient. */
Test(looks, picked_colours_lie_on_the_gradient)
{
    isk_effect *fx = make("[scene]\nseed = 9\n[emitter e]\nsource = stream\nrate = 2000\nlaunch = disc\n"
                          "speed_max = 1\ncolor_pick = 0:#ff0000, 1:#0000ff\n");
    for (int i = 0; i < 30; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_gt(p->count, 900);
    cr_assert_not_null(p->color);
    int rmin = 255, rmax = 0;
    for (size_t i = 0; i < p->count; i++) {
        isk_color c = p->color[i];
        cr_assert(c.r + c.b == 255 || c.r + c.b == 256, "particle %zu: %d %d %d %d", i, c.r, c.g, c.b, c.a);
        cr_assert_eq(c.g, 0);
        cr_assert_eq(c.a, 255);
        rmin = c.r < rmin ? c.r : rmin;
        rmax = c.r > rmax ? c.r : rmax;
    }
    cr_assert_lt(rmin, 5);
    cr_assert_gt(rmax, 250);
    isk_effect_destroy(fx);
}

/* Picked colour times the colour ramp, per channel div255(a * b). */
Test(looks, color_over_life_multiplies_the_picked_colour)
{
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, 64, 64), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 64, 64), ISK_OK);
    /* one stop: the picked colour is that colour; the ramp is constant */
    isk_effect *fx = one("color_pick = 0:#c08040\ncolor_over_life = 0:#8080ff, 1:#8080ff\nlife = 10");
    cr_assert_eq(isk_effect_render(fx, &a), ISK_OK);
    isk_effect_destroy(fx);
    fx = one_in("#604040", "life = 10"); /* div255(192*128), div255(128*128), div255(64*255) */
    cr_assert_eq(isk_effect_render(fx, &b), ISK_OK);
    isk_effect_destroy(fx);
    cr_assert(key_case_equal(&a, &b));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(looks, sizes_lie_in_their_range)
{
    isk_effect *fx = make("[scene]\nseed = 2\n[emitter e]\nsource = stream\nrate = 2000\nlaunch = disc\n"
                          "speed_max = 1\ndraw = disc\nsize = 0.5\nsize_range = 0.25\n");
    for (int i = 0; i < 30; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_not_null(p->size);
    double lo = 1, hi = 0;
    for (size_t i = 0; i < p->count; i++) {
        cr_assert(p->size[i] >= 0.5 && p->size[i] < 0.75, "size %.17g", p->size[i]);
        lo = fmin(lo, p->size[i]);
        hi = fmax(hi, p->size[i]);
    }
    /* 1,000 uniform draws: the least below 0.01 and the largest above
     * 0.99 but for a chance of e^-10 each */
    cr_assert_eq(p->count, 1000);
    cr_assert_lt(lo, 0.5 + 0.25 * 0.01, "lo %.6g", lo);
    cr_assert_gt(hi, 0.5 + 0.25 * 0.99, "hi %.6g", hi);
    isk_effect_destroy(fx);
}

/* Angles: the spin's sum, wrapped into [-pi, pi), bounded and precise over
 * a long run at the fastest spin. */
Test(looks, angles_wrap_and_stay_precise)
{
    isk_effect *fx = make("[scene]\ndt = 1/64\n[emitter e]\nsource = particle\nrotation = 10\nspin = 90\n"
                          "draw = sprite\ntexture = " TEX "\n");
    for (int i = 0; i < 64 * 5; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    /* 10 + 450 degrees = 100 degrees */
    cr_assert(fabs(isk_effect_particles(fx, 0)->angle[0] - 100 * (PI / 180)) < 1e-12, "%.17g",
              isk_effect_particles(fx, 0)->angle[0]);
    isk_effect_destroy(fx);
    fx = make("[scene]\ndt = 1000\n[emitter e]\nsource = particle\nspin = -360000\nspin_range = 0\n"
              "align = velocity\n");
    for (int i = 0; i < 2000; i++) {
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        double a = isk_effect_particles(fx, 0)->angle[0];
        cr_assert(a >= -PI && a < PI, "angle %.17g after %d steps", a, i + 1);
    }
    isk_effect_destroy(fx);
}

/* The phase at the fastest spin: each step's turn (6.3e6 rad at a step of
 * 1000 s) is rounded at its own size and wrapped with a rounded 2 pi, so
 * the angle drifts from the exact spin x time by up to 1.4e-9 rad a step
 * at 1000 s and 2.3e-14 at 1/60 s (limits.h), never more.  The reference:
 * the same turns in long double (64-bit mantissa; where long double is a
 * double, nothing to compare with). */
Test(looks, the_phase_drifts_no_more_than_limits_h_says)
{
#if LDBL_MANT_DIG >= 64
    const struct {
        const char *dt;
        long double h;
        double per_step;
    } cases[2] = {{"1000", 1000.0L, 1.4e-9}, {"1/60", 1.0L / 60, 2.3e-14}};
    for (int c = 0; c < 2; c++) {
        char text[300];
        snprintf(text, sizeof text,
                 "[scene]\ndt = %s\n[emitter e]\nsource = particle\nspin = -360000\nspin_range = 0\n"
                 "align = velocity\n",
                 cases[c].dt);
        isk_effect *fx = make(text);
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        const isk_particles *p = isk_effect_particles(fx, 0);
        cr_assert_eq(p->count, 1);
        const long double two_pi = 6.283185307179586476925286766559L;
        /* the step's h as the scene has it (1/60 rounded to a double) */
        const long double turn = (long double)p->spin[0] * (long double)(double)cases[c].h;
        const double a0 = p->angle[0];
        double worst = 0;
        for (int n = 1; n <= 2000; n++) {
            cr_assert_eq(isk_effect_step(fx), ISK_OK);
            const long double exact = remainderl((long double)a0 + n * turn, two_pi);
            const double e = (double)fabsl(remainderl((long double)p->angle[0] - exact, two_pi));
            worst = e > worst ? e : worst;
            cr_assert(e <= cases[c].per_step * n, "dt = %s, step %d: %.3g rad from the exact phase", cases[c].dt,
                      n, e);
        }
        cr_log_info("dt = %s: drift after 2000 steps %.3g rad", cases[c].dt, worst);
        isk_effect_destroy(fx);
    }
#endif
}

/* The angle column and the spin stage only where used; no draw without a
 * range (the particle's other values are today's). */
Test(looks, columns_and_stages_only_where_used)
{
    isk_effect *fx = make("[emitter e]\nsource = stream\nrate = 100\nlaunch = disc\nspeed_max = 1\n");
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_null(p->angle);
    cr_assert_null(p->size);
    cr_assert_null(p->color);
    char *d = describe(fx);
    cr_assert_null(strstr(d, "spin"), "%s", d);
    cr_assert_null(strstr(d, "looks"), "%s", d);
    free(d);
    isk_effect_destroy(fx);

    fx = make("[emitter e]\nsource = stream\nrate = 100\nlaunch = disc\nspeed_max = 1\nrotation = 20\n");
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_null(isk_effect_particles(fx, 0)->angle, "dots look the same at every angle");
    isk_effect_destroy(fx);
    fx = make("[emitter e]\nsource = stream\nrate = 100\nlaunch = disc\nspeed_max = 1\nrotation = 20\n"
              "draw = sprite\ntexture = " TEX "\n");
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_not_null(isk_effect_particles(fx, 0)->angle);
    d = describe(fx);
    cr_assert_null(strstr(d, "  spin "), "a rotation without spin needs no stage:\n%s", d);
    free(d);
    isk_effect_destroy(fx);

    fx = make("[emitter e]\nsource = stream\nrate = 100\nlaunch = disc\nspeed_max = 1\nspin_range = 20\n"
              "draw = sprite\nalign = velocity\n");
    d = describe(fx);
    cr_assert_not_null(strstr(d, "  spin "), "%s", d);
    free(d);
    isk_effect_destroy(fx);
}

/* A round sprite without a texture looks the same at every angle. */
Test(looks, rotation_of_a_round_sprite_changes_nothing)
{
    const char *base = stream_base("draw = sprite\nsprite = smooth\n");
    key_case_same(base, "rotation = 45", 20);
    key_case_same(base, "spin = 300\nrotation_range = 180", 20);
}

/* Set while running: the columns appear, old particles keep today's looks. */
Test(looks, set_live)
{
    isk_effect *fx = make("[emitter e]\nsource = stream\nrate = 100\nlaunch = disc\nspeed_max = 1\ndraw = sprite\n"
                          "align = velocity\n");
    for (int i = 0; i < 5; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    isk_error err;
    cr_assert_eq(isk_effect_set(fx, "emitter e", "size_range", "0.5", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_set(fx, "emitter e", "spin", "90", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_set(fx, "emitter e", "color_pick", "0:red, 1:blue", &err), ISK_OK, "%s", err.message);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_not_null(p->size);
    cr_assert_not_null(p->angle);
    cr_assert_eq(p->size[0], 0.1);
    { isk_color y = ISK_YELLOW; cr_assert(!memcmp(&p->color[0], &y, sizeof y)); }
    for (int i = 0; i < 5; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    char *d = describe(fx);
    cr_assert_not_null(strstr(d, "  spin "), "%s", d);
    free(d);
    cr_assert_neq(isk_effect_set(fx, "emitter e", "texture", TEX, &err), ISK_OK);
    isk_effect_destroy(fx);

    /* a sprite kind becomes a streak when align is set, and round again */
    fx = make("[emitter e]\nsource = stream\nrate = 100\nlaunch = disc\nspeed_max = 1\ndraw = sprite\n");
    cr_assert_eq(isk_effect_set(fx, "emitter e", "align", "velocity", &err), ISK_OK, "%s", err.message);
    d = describe(fx);
    cr_assert_not_null(strstr(d, "streak"), "%s", d);
    free(d);
    cr_assert_eq(isk_effect_set(fx, "emitter e", "align", "none", &err), ISK_OK, "%s", err.message);
    d = describe(fx);
    cr_assert_null(strstr(d, "streak"), "%s", d);
    free(d);
    isk_effect_destroy(fx);
}

/* The threaded draw (bands of rows) gives the bytes of the whole call. */
Test(looks, the_same_bytes_on_any_number_of_threads, .timeout = 120)
{
    char text[2048];
    snprintf(text, sizeof text,
             "[scene]\nwidth = 160\nheight = 120\nseed = 4\n[emitter e]\nsource = stream\nrate = 0\ncount = 20000\n"
             "shape = disc\nshape_a = 9\nlaunch = disc\nspeed_max = 3\nlife = 5\nsize = 0.4\nsize_range = 0.3\n"
             "rotation_range = 360\nspin = 200\ntexture = %s\ntexture_grid = 4, 2\ncolor_pick = 0:red, 1:cyan\n"
             "blend = over\n"
             "[emitter s]\nsource = stream\nrate = 0\ncount = 20000\nshape = disc\nshape_a = 9\nlaunch = disc\n"
             "speed_max = 3\ndraw = sprite\nalign = velocity\nsize = 0.3\nblend = over\n",
             TEX);
    isk_canvas c[3];
    const int threads[] = {1, 2, 3};
    for (int k = 0; k < 3; k++) {
        isk_effect *fx = make(text);
        cr_assert_eq(isk_effect_set_threads(fx, threads[k]), ISK_OK);
        fx->band_min_work = 0; /* in bands at any size, as a bigger scene's draw would be */
        cr_assert_eq(isk_canvas_init(&c[k], 160, 120), ISK_OK);
        cr_assert_eq(isk_effect_run(fx, &c[k], 10), ISK_OK);
        cr_assert_geq(isk_effect_particle_count(fx), 16384 * 2);
        isk_effect_destroy(fx);
    }
    cr_assert(key_case_equal(&c[0], &c[1]), "2 threads");
    cr_assert(key_case_equal(&c[0], &c[2]), "3 threads");
    for (int k = 0; k < 3; k++)
        isk_canvas_free(&c[k]);
}

/* The path is the scene file's directory's. */
Test(looks, texture_paths_are_relative_to_the_scene_file)
{
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load_string(&d, "[emitter e]\nsource = particle\ntexture = textures/arrows.png\n",
                                       "scenes/x.ini", &err),
                 ISK_OK, "%s", err.message);
    cr_assert_str_eq(d.emitters[0].look.texture, TEX);
    isk_effect_def_free(&d);
    cr_assert_neq(isk_scene_load_string(&d, "[emitter e]\nsource = particle\ntexture = textures/arrows.png\n",
                                        "x.ini", &err),
                  ISK_OK);
    cr_assert(strstr(err.message, "x.ini:3: ") == err.message, "%s", err.message);
    cr_assert_not_null(strstr(err.message, "textures/arrows.png"), "%s", err.message);

    /* a C definition's paths: tests/test_texture_def.c */
}

/* The committed sheet is tools/looks_texture.h's drawing. */
Test(looks, the_committed_texture_is_the_tools_drawing)
{
    isk_canvas want, got;
    isk_error err;
    cr_assert_eq(looks_texture_draw(&want), ISK_OK);
    cr_assert_eq(isk_png_read(&got, TEX, &err), ISK_OK, "%s", err.message);
    cr_assert(key_case_equal(&want, &got), TEX " differs from tools/looks_texture.h: run tools/gen_looks_texture.c");
    isk_canvas_free(&want);
    isk_canvas_free(&got);
}

Test(looks, the_committed_sparkle_is_the_tools_drawing)
{
    isk_canvas want, got;
    isk_error err;
    cr_assert_eq(looks_sparkle_draw(&want), ISK_OK);
    cr_assert_eq(isk_png_read(&got, "scenes/textures/sparkle.png", &err), ISK_OK, "%s", err.message);
    cr_assert(key_case_equal(&want, &got), "sparkle.png differs from tools/looks_texture.h: run tools/gen_looks_texture.c");
    isk_canvas_free(&want);
    isk_canvas_free(&got);
}

/* A PNG in memory is the same texture as the file, through the cache too
 * (kept under its name). */
Test(looks, a_texture_from_memory_is_the_files)
{
    FILE *f = fopen(TEX, "rb");
    cr_assert_not_null(f);
    static unsigned char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    isk_texture a, b;
    isk_error err;
    cr_assert_eq(isk_texture_load(&a, TEX, 4, 2, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_texture_load_memory(&b, buf, n, "arrows", 4, 2, &err), ISK_OK, "%s", err.message);
    isk_canvas ca, cb;
    cr_assert_eq(isk_canvas_init(&ca, 64, 64), ISK_OK);
    cr_assert_eq(isk_canvas_init(&cb, 64, 64), ISK_OK);
    isk_canvas_fill(&ca, ISK_BLACK);
    isk_canvas_fill(&cb, ISK_BLACK);
    for (int k = 0; k < 8; k++) {
        isk_draw_texture(&ca, &a, k, 8 + 7 * k, 30, 20, 14, 0.4 * k, ISK_WHITE, ISK_BLEND_OVER);
        isk_draw_texture(&cb, &b, k, 8 + 7 * k, 30, 20, 14, 0.4 * k, ISK_WHITE, ISK_BLEND_OVER);
    }
    cr_assert(key_case_equal(&ca, &cb));
    cr_assert_neq(isk_texture_load_memory(&b, buf, n / 2, "half", 1, 1, &err), ISK_OK);
    cr_assert(strstr(err.message, "half"), "%s", err.message);
    cr_assert_neq(isk_texture_load_memory(&b, buf, n, "arrows", 3, 1, &err), ISK_OK); /* 64 is not 3 frames */
    isk_texture_cache *cache;
    cr_assert_eq(isk_texture_cache_create(&cache, 4), ISK_OK);
    const isk_texture *t1, *t2;
    cr_assert_eq(isk_texture_cache_get_memory(cache, "arrows", buf, n, 4, 2, &t1, &err), ISK_OK);
    cr_assert_eq(isk_texture_cache_get(cache, "arrows", 4, 2, &t2, &err), ISK_OK); /* found by its name */
    cr_assert_eq(t1, t2);
    cr_assert_eq(isk_texture_cache_loads(cache), 1);
    cr_assert_neq(isk_texture_cache_get_memory(cache, "x", NULL, 1, 1, 1, &t1, &err), ISK_OK);
    isk_texture_cache_destroy(cache);
    isk_texture_free(&a);
    isk_texture_free(&b);
    isk_canvas_free(&ca);
    isk_canvas_free(&cb);
}

/* Built-in scenes carry their textures: run from any directory, the
 * pinwheel is its reference image. */
Test(looks, a_built_in_scene_draws_its_texture_anywhere)
{
    char cwd[4096];
    cr_assert_not_null(getcwd(cwd, sizeof cwd));
    char dir[4200], args[4400], out[4300];
    snprintf(dir, sizeof dir, "%s/out/test_fx_looks/anywhere", cwd);
    cli_fresh("out/test_fx_looks/anywhere");
    snprintf(out, sizeof out, "%s/p.png", dir);
    snprintf(args, sizeof args, "render looks_pinwheel --out %s", out);
    cr_assert_eq(cli_run_in("/", "out/test_fx_looks/anywhere", args), 0, "iskra %s", args);
    isk_canvas got, want;
    cr_assert_eq(isk_png_read(&got, out, NULL), ISK_OK);
    cr_assert_eq(isk_png_read(&want, "refimg/looks_pinwheel.png", NULL), ISK_OK);
    cr_assert(key_case_equal(&got, &want));
    isk_canvas_free(&got);
    isk_canvas_free(&want);
}
