/* SPDX-License-Identifier: MIT */
/* The everyday settings people know from LÖVE's ParticleSystem and Godot's
 * CPUParticles2D: the gaussian and border emission areas, launch_outward,
 * spin_end, texture_origin, draw_order and flipbook_random_start.  Each does what it says (a measured
 * number), costs and changes nothing at its default (the same describe,
 * the same bytes), gives the same bytes on 1, 2 and 3 threads, and has a
 * reference image. */
#include <criterion/criterion.h>
#include <criterion/logging.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "refimg_scene.h"
#include "scene_text.h"

#define PI 3.14159265358979323846

static isk_effect *open_def(const char *text, int threads, int *w, int *h)
{
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load_string(&d, text, "scenes/settings.ini", &err), ISK_OK, "%s", err.message);
    d.threads = threads;
    if (w)
        *w = d.width, *h = d.height;
    isk_effect *fx;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_def_free(&d);
    return fx;
}

static isk_effect *open_scene(const char *text, int threads) { return open_def(text, threads, NULL, NULL); }

static isk_canvas render(const char *text, int threads, long frames)
{
    int w, h;
    isk_effect *fx = open_def(text, threads, &w, &h);
    isk_canvas c = refimg_canvas(w, h, ISK_BLACK);
    cr_assert_eq(isk_effect_run(fx, &c, frames), ISK_OK);
    isk_effect_destroy(fx);
    return c;
}

/* isk_effect_describe's text (free it). */
static char *describe(const char *text)
{
    isk_effect *fx = open_scene(text, 1);
    char *t = scene_text_lists(fx);
    isk_effect_destroy(fx);
    return t;
}

/* ---- the scenes of the reference images ---------------------------------- */

/* Four streams side by side, no forces: a gaussian area (sigma 0.6, 0.3),
 * the border of a rect turned 20 degrees, the border of an ellipse, and a
 * circle launched outward (angle 0, speeds 1..3), drawn as streaks along
 * their velocities: rays from its centre. */
static const char areas_scene[] =
    "[scene]\nwidth = 320\nheight = 96\nbackground = #101018\nseed = 5\n"
    "[view]\nxmin = 0\nxmax = 20\nymin = 0\nymax = 6\n"
    "[emitter gauss]\nsource = stream\nposition = 2.5, 3\nrate = 600\nlife = 1\nshape = gaussian\n"
    "shape_a = 0.6\nshape_b = 0.3\ncolor = #ffd080\n"
    "[emitter box]\nsource = stream\nposition = 7.5, 3\nrate = 600\nlife = 1\nshape = rect_border\n"
    "shape_a = 1.6\nshape_b = 0.9\nshape_angle = 20\ncolor = #80ff80\n"
    "[emitter oval]\nsource = stream\nposition = 12.5, 3\nrate = 600\nlife = 1\nshape = ellipse_border\n"
    "shape_a = 2\nshape_b = 1\ncolor = #80c0ff\n"
    "[emitter out]\nsource = stream\nposition = 17.5, 3\nrate = 300\nlife = 0.6\nshape = circle\nshape_a = 0.4\n"
    "launch = direction\nangle = 0\nspeed_min = 1\nspeed_max = 3\nlaunch_outward = true\n"
    "draw = sprite\nsprite = smooth\nsize = 0.15\nalign = velocity\nblend = add\ncolor = #ff80c0\n";

/* Arrows (scenes/textures/arrows.png, frame 0 points right) of life 2 s
 * born at rest: the top row with texture_origin 0, 0.5 (the arrow's tail)
 * turning about it, the bottom row about their centres; each column an
 * age: spin 0 rising to spin_end 180 deg/s at the end of the life, so at
 * age a the angle is 45 a^2 degrees (ages 0, 0.45, 0.9, 1.35, 1.8: 0,
 * 9.1, 36.5, 82 and 145.8 degrees). */
static void spin_origin_scene(char *text, size_t size)
{
    int n = snprintf(text, size,
                     "[scene]\nwidth = 320\nheight = 128\ndt = 1/4\nbackground = #202028\n"
                     "[view]\nxmin = 0\nxmax = 20\nymin = 0\nymax = 8\n");
    for (int row = 0; row < 2; row++)
        for (int k = 0; k < 5; k++)
            n += snprintf(text + n, size - (size_t)n,
                          "[emitter a%d%d]\nsource = stream\nposition = %d, %d\nrate = 0\ncount = 1\nstart = %g\n"
                          "life = 2\ndraw = sprite\nsize = 2\ntexture = textures/arrows.png\ntexture_grid = 4, 2\n"
                          "texture_fps = 0.001\nspin = 0\nspin_end = 180\ntexture_origin = %s\ncolor = %s\n",
                          row, k, 2 + 4 * k, row ? 2 : 6, 2.0 - 0.45 * k, row ? "0.5, 0.5" : "0, 0.5",
                          row ? "#80c0ff" : "#ffc060");
    cr_assert_lt((size_t)n, size);
}

/* Which particles are on top: three fans of the same stream, each
 * particle turning from red (born) to blue (dying), discs with the newest
 * on top (the default), sprites with the oldest on top, textures in a
 * random order. */
static const char order_scene[] =
    "[scene]\nwidth = 240\nheight = 96\nbackground = #101018\nseed = 8\n"
    "[view]\nxmin = 0\nxmax = 15\nymin = 0\nymax = 6\n"
    "[emitter newest]\nsource = stream\nposition = 2.5, 1\nrate = 20\nlife = 1\nlaunch = cone\nangle = 90\n"
    "spread = 60\nspeed_min = 3\nspeed_max = 4\ndraw = disc\nsize = 1.2\n"
    "color_over_life = 0:#ff4040, 1:#4040ff\n"
    "[emitter oldest]\nsource = stream\nposition = 7.5, 1\nrate = 20\nlife = 1\nlaunch = cone\nangle = 90\n"
    "spread = 60\nspeed_min = 3\nspeed_max = 4\ndraw = sprite\nsprite = disc\nsize = 1.6\n"
    "color_over_life = 0:#ff4040, 1:#4040ff\ndraw_order = oldest\n"
    "[emitter random]\nsource = stream\nposition = 12.5, 1\nrate = 20\nlife = 1\nlaunch = cone\nangle = 90\n"
    "spread = 60\nspeed_min = 3\nspeed_max = 4\ndraw = sprite\nsize = 2.6\ntexture = textures/sparkle.png\n"
    "color_over_life = 0:#ff4040, 1:#4040ff\ndraw_order = random\n";

Test(refimg, settings_draw_order)
{
    isk_canvas c = render(order_scene, 1, 50);
    refimg_expect("settings_draw_order", &c);
}

/* flipbook_random_start: a sheet of 8 frames drawn here, frame k a bar
 * k + 1 texels high (a level meter), on sixteen single particles: the top
 * row immortal, so each shows the frame it starts at; the bottom row plays
 * on at 4 frames a second from its own first frame (one frame on at
 * 3/8 s). */
static void flipbook_scene(char *text, size_t size)
{
    int n = snprintf(text, size,
                     "[scene]\nwidth = 256\nheight = 64\ndt = 1/8\nbackground = #202028\nseed = 12\n"
                     "[view]\nxmin = 0\nxmax = 16\nymin = 0\nymax = 4\n");
    for (int row = 0; row < 2; row++)
        for (int k = 0; k < 8; k++)
            n += snprintf(text + n, size - (size_t)n,
                          "[emitter m%d%d]\nsource = particle\nposition = %d, %d\ndraw = sprite\nsize = 1.5\n"
                          "flipbook_random_start = true\ntexture_fps = %d\ncolor = %s\n",
                          row, k, 1 + 2 * k, row ? 1 : 3, row ? 4 : 0, row ? "#80c0ff" : "#ffc060");
    cr_assert_lt((size_t)n, size);
}

/* The scene's emitters drawn as the level-meter sheet (texture_grid 8, 1),
 * run for `frames` frames on `threads` threads. */
static isk_canvas render_flipbook(int threads, long frames)
{
    char text[8192];
    flipbook_scene(text, sizeof text);
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load_string(&d, text, "flipbook.ini", &err), ISK_OK, "%s", err.message);
    isk_canvas sheet = refimg_canvas(64, 8, isk_rgba(0, 0, 0, 0));
    for (int k = 0; k < 8; k++)
        for (int y = 7 - k; y < 8; y++)
            for (int x = 8 * k + 1; x < 8 * k + 7; x++)
                memset(sheet.pixels + (size_t)y * sheet.stride + 4 * (size_t)x, 255, 4);
    cr_assert_eq(isk_effect_def_add_texture(&d, "meter", &sheet, &err), ISK_OK, "%s", err.message);
    isk_canvas_free(&sheet);
    for (int i = 0; i < d.nemitters; i++) {
        snprintf(d.emitters[i].look.texture, sizeof d.emitters[i].look.texture, "meter");
        d.emitters[i].look.texture_grid = (isk_vec2){8, 1};
    }
    d.threads = threads;
    isk_effect *fx;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_canvas c = refimg_canvas(d.width, d.height, ISK_BLACK);
    isk_effect_def_free(&d);
    cr_assert_eq(isk_effect_run(fx, &c, frames), ISK_OK);
    isk_effect_destroy(fx);
    return c;
}

Test(refimg, settings_flipbook)
{
    isk_canvas c = render_flipbook(1, 3);
    refimg_expect("settings_flipbook", &c);
}

/* The motion's ranges: a swirl whose particles each orbit by their own
 * radial and tangential accelerations (a band, not a line); a fountain
 * blown by a wind force of (-3, 0) plus wind_range 6, 0 (LÖVE's linear
 * acceleration from -3 to 3); a jet whose particles each stop at their own
 * slowing (1 + U*3): 1.5 to 6 units from the nozzle. */
static const char ranges_scene[] =
    "[scene]\nwidth = 300\nheight = 120\nbackground = #101018\nseed = 3\n"
    "[view]\nxmin = 0\nxmax = 25\nymin = 0\nymax = 10\n"
    "[force gravity]\ng = 9.81\n[force wind]\nacceleration = -3, 0\n"
    "[emitter swirl]\nsource = stream\nposition = 5, 5\nrate = 120\nlife = 2\nshape = circle\nshape_a = 2\n"
    "launch = direction\nangle = 90\nspeed_min = 2\nspeed_max = 2\nlaunch_outward = true\n"
    "radial_accel = -2\nradial_accel_range = 1\ntangential_accel = 0\ntangential_accel_range = 3\n"
    "color = #80c0ff\n"
    "[emitter fountain]\nsource = stream\nposition = 13, 1\nrate = 150\nlife = 1.5\nlaunch = cone\nangle = 90\n"
    "spread = 10\nspeed_min = 9\nspeed_max = 10\nforces = gravity, wind\nwind_range = 6, 0\ncolor = #ffd080\n"
    "[emitter jet]\nsource = stream\nposition = 17.5, 5\nrate = 150\nlife = 3\nlaunch = cone\nangle = 0\n"
    "spread = 30\nspeed_min = 6\nspeed_max = 6\nslowing = 1\nslowing_range = 3\ncolor = #80ff80\n";

Test(refimg, settings_ranges)
{
    isk_canvas c = render(ranges_scene, 1, 120);
    refimg_expect("settings_ranges", &c);
}

Test(refimg, settings_areas)
{
    isk_canvas c = render(areas_scene, 1, 60);
    refimg_expect("settings_areas", &c);
}

Test(refimg, settings_spin_origin)
{
    char text[8192];
    spin_origin_scene(text, sizeof text);
    isk_canvas c = render(text, 1, 8); /* 2 s */
    refimg_expect("settings_spin_origin", &c);
}

/* The same bytes on 1, 2 and 3 threads, for every scene. */
Test(settings, threads_give_the_same_bytes)
{
    char text[8192];
    spin_origin_scene(text, sizeof text);
    const char *scenes[4] = {areas_scene, text, order_scene, ranges_scene};
    const long frames[4] = {60, 8, 50, 120};
    for (int s = 0; s < 4; s++) {
        isk_canvas one = render(scenes[s], 1, frames[s]);
        for (int t = 2; t <= 3; t++) {
            isk_canvas more = render(scenes[s], t, frames[s]);
            cr_assert_eq(memcmp(one.pixels, more.pixels, one.stride * (size_t)one.height), 0,
                         "scene %d on %d threads", s, t);
            isk_canvas_free(&more);
        }
        isk_canvas_free(&one);
    }
    isk_canvas one = render_flipbook(1, 3);
    for (int t = 2; t <= 3; t++) {
        isk_canvas more = render_flipbook(t, 3);
        cr_assert_eq(memcmp(one.pixels, more.pixels, one.stride * (size_t)one.height), 0, "flipbook, %d threads", t);
        isk_canvas_free(&more);
    }
    isk_canvas_free(&one);
}

/* ---- what each does ----------------------------------------------------------- */

/* launch_outward: a circle of radius 1 launching along angle 0 at speed 2
 * sends every particle straight away from the centre: its velocity is
 * parallel to its offset (cross product below 1e-9 of the product of
 * lengths) and points outward, at speed 2.  Without the key, every
 * velocity is (2, 0). */
Test(settings, launch_outward_points_away_from_the_centre)
{
    static const char text[] = "[scene]\nseed = 9\n[emitter e]\nsource = stream\nposition = 3, -2\nrate = 600\n"
                               "shape = circle\nshape_a = 1\nlaunch = direction\nangle = 0\nspeed_min = 2\n"
                               "speed_max = 2\nlaunch_outward = true\n";
    isk_effect *fx = open_scene(text, 1);
    for (int i = 0; i < 20; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_geq(p->count, 190u);
    for (size_t i = 0; i < p->count; i++) {
        const double dx = p->x[i] - 3, dy = p->y[i] + 2, r = hypot(dx, dy), v = hypot(p->vx[i], p->vy[i]);
        cr_assert_lt(fabs(dx * p->vy[i] - dy * p->vx[i]), 1e-9 * r * v, "particle %zu", i);
        cr_assert_gt(dx * p->vx[i] + dy * p->vy[i], 0.0);
        cr_assert_lt(fabs(v - 2), 1e-12);
    }
    isk_effect_destroy(fx);
}

/* The angle at age a of a particle born at rest with angle 0, spin w and
 * spin_end W over a life L: the speed w + (W - w) a/L integrated, w a +
 * (W - w) a^2 / (2L), wrapped into [-pi, pi).  Its derivative at a = L is
 * W: the particle ends its life turning at spin_end.  Measured at ages
 * 0.25 .. 1.75 of a life of 2 with spin 30, spin_end 300 deg/s, to 1e-12,
 * with 1 and with 7 substeps (the step size changes nothing). */
Test(settings, spin_end_is_the_speed_at_the_end_of_the_life)
{
    const double w = 30 * PI / 180, W = 300 * PI / 180, L = 2;
    for (int sub = 1; sub <= 7; sub += 6) {
        char text[1024];
        snprintf(text, sizeof text,
                 "[scene]\ndt = 1/4\nsubsteps = %d\n[emitter e]\nsource = stream\nrate = 0\ncount = 1\nlife = 2\n"
                 "draw = sprite\nalign = velocity\nspin = 30\nspin_end = 300\n",
                 sub);
        isk_effect *fx = open_scene(text, 1);
        for (int f = 1; f <= 7; f++) {
            cr_assert_eq(isk_effect_step(fx), ISK_OK);
            const isk_particles *p = isk_effect_particles(fx, 0);
            cr_assert_eq(p->count, 1u);
            const double a = p->age[0];
            cr_assert_lt(fabs(a - 0.25 * f), 1e-12);
            double want = w * a + (W - w) * a * a / (2 * L);
            want -= 2 * PI * floor((want + PI) / (2 * PI));
            cr_assert_lt(fabs(p->angle[0] - want), 1e-12, "substeps %d age %g: %.17g, want %.17g", sub, a,
                         p->angle[0], want);
        }
        isk_effect_destroy(fx);
    }
}

/* spin_end changes only the speed's course: with spin_range each particle
 * keeps its own start w_i (the same draws as without spin_end) and ends at
 * w_i + spin_end - spin. */
Test(settings, spin_end_keeps_each_particles_own_start)
{
    static const char base[] = "[scene]\ndt = 1/4\nseed = 3\n[emitter e]\nsource = stream\nrate = 0\ncount = 50\n"
                               "life = 2\ndraw = sprite\nalign = velocity\nspin = 30\nspin_range = 90\n";
    char with[1024];
    snprintf(with, sizeof with, "%sspin_end = -60\n", base);
    isk_effect *a = open_scene(base, 1), *b = open_scene(with, 1);
    for (int f = 0; f < 4; f++) {
        cr_assert_eq(isk_effect_step(a), ISK_OK);
        cr_assert_eq(isk_effect_step(b), ISK_OK);
    }
    const isk_particles *pa = isk_effect_particles(a, 0), *pb = isk_effect_particles(b, 0);
    cr_assert_eq(pa->count, 50u);
    cr_assert_eq(pb->count, 50u);
    const double change = -90 * PI / 180, age = 1.0;
    for (size_t i = 0; i < 50; i++) {
        cr_assert_eq(pa->spin[i], pb->spin[i], "the same start speed");
        double want = pa->angle[i] + change * age * age / (2 * 2.0);
        want -= 2 * PI * floor((want + PI) / (2 * PI));
        double d = fabs(pb->angle[i] - want);
        cr_assert(d < 1e-12 || fabs(d - 2 * PI) < 1e-12, "particle %zu: %.17g, want %.17g", i, pb->angle[i], want);
    }
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

/* The box of the pixels that differ from the background. */
static void drawn_box(const isk_canvas *c, int box[4])
{
    box[0] = c->width, box[1] = c->height, box[2] = -1, box[3] = -1;
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++) {
            const uint8_t *px = c->pixels + (size_t)y * c->stride + 4 * (size_t)x;
            if (px[0] || px[1] || px[2]) {
                box[0] = x < box[0] ? x : box[0];
                box[1] = y < box[1] ? y : box[1];
                box[2] = x > box[2] ? x : box[2];
                box[3] = y > box[3] ? y : box[3];
            }
        }
}

/* texture_origin: an 8 x 8 white texture drawn 32 pixels wide on a
 * particle at the screen point (50, 40).  The default centres it there:
 * the pixels it covers (2 more each way: the bilinear magnification's
 * fringe) are centred on (50, 40).  Origin 0, 0 puts the image's top-left
 * corner on the point: the same pixels moved by (+16, +16); origin 1, 1 by
 * (-16, -16); turned by 90 degrees (counter-clockwise in the world) about
 * the corner 0, 0 the square swings up, by (+16, -16). */
Test(settings, texture_origin_is_the_point_placed_and_turned_about)
{
    static const struct {
        isk_vec2 origin;
        double degrees;
        int dx, dy; /* the move from the centred box */
    } cases[] = {
        {{0.5, 0.5}, 0, 0, 0},
        {{0, 0}, 0, 16, 16},
        {{1, 1}, 0, -16, -16},
        {{0, 0}, 90, 16, -16},
    };
    int centred[4] = {0};
    isk_canvas square;
    cr_assert_eq(isk_canvas_init(&square, 8, 8), ISK_OK);
    isk_canvas_fill(&square, ISK_WHITE);
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        isk_effect_def d;
        isk_effect_def_init(&d);
        d.width = 100;
        d.height = 80;
        d.xmin = 0, d.xmax = 100, d.ymin = 0, d.ymax = 80;
        isk_error err = {0};
        cr_assert_eq(isk_effect_def_add_texture(&d, "square", &square, &err), ISK_OK, "%s", err.message);
        isk_emitter_def *e = isk_effect_def_add_emitter(&d, "e");
        cr_assert_not_null(e);
        e->born.position = (isk_vec2){50, 40};
        e->look.draw = ISK_DRAW_SPRITE;
        e->look.size = 32;
        snprintf(e->look.texture, sizeof e->look.texture, "square");
        e->look.texture_origin = cases[k].origin;
        e->look.rotation = cases[k].degrees * (PI / 180);
        isk_effect *fx;
        cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
        isk_effect_def_free(&d);
        isk_canvas c = refimg_canvas(100, 80, ISK_BLACK);
        cr_assert_eq(isk_effect_render(fx, &c), ISK_OK);
        int box[4];
        drawn_box(&c, box);
        cr_log_info("origin %g, %g rotation %g: box %d, %d .. %d, %d", cases[k].origin.x, cases[k].origin.y,
                    cases[k].degrees, box[0], box[1], box[2], box[3]);
        if (k == 0) {
            memcpy(centred, box, sizeof centred);
            cr_assert_eq(box[0] + box[2] + 1, 2 * 50, "centred on x = 50: %d .. %d", box[0], box[2]);
            cr_assert_eq(box[1] + box[3] + 1, 2 * 40, "centred on y = 40: %d .. %d", box[1], box[3]);
            cr_assert_eq(box[2] - box[0] + 1, 32 + 4);
        }
        for (int q = 0; q < 4; q++)
            cr_assert_eq(box[q], centred[q] + (q & 1 ? cases[k].dy : cases[k].dx), "case %zu: box[%d] = %d", k, q,
                         box[q]);
        isk_canvas_free(&c);
        isk_effect_destroy(fx);
    }
    isk_canvas_free(&square);
}

/* draw_order, pixel by pixel: opaque discs born 10 a second at one point,
 * at rest, turning from red (born) to blue (at the end of their life of
 * 1 s).  At 0.95 s the centre pixel is the newest particle's colour (red,
 * with less than 1/8 blue) by default, the oldest's (more blue than red)
 * with draw_order = oldest; random shows one of the particles, neither of
 * those two in at least one of 8 frames, and the same bytes on 1, 2 and 3
 * threads. */
static isk_color centre_after(const char *order, long frames, int threads)
{
    char text[1024];
    snprintf(text, sizeof text,
             "[scene]\nwidth = 21\nheight = 21\ndt = 1/20\n[view]\nxmin = -1\nxmax = 1\nymin = -1\nymax = 1\n"
             "[emitter e]\nsource = stream\nrate = 10\nlife = 1\ndraw = disc\nsize = 1\n"
             "color_over_life = 0:#ff0000, 1:#0000ff\ndraw_order = %s\n",
             order);
    isk_canvas c = render(text, threads, frames);
    const uint8_t *px = c.pixels + 10 * c.stride + 4 * 10;
    isk_color col = isk_rgba(px[0], px[1], px[2], px[3]);
    isk_canvas_free(&c);
    return col;
}

Test(settings, draw_order_decides_which_particle_is_on_top)
{
    const isk_color newest = centre_after("newest", 19, 1), oldest = centre_after("oldest", 19, 1);
    cr_log_info("centre: newest on top %d,%d,%d; oldest on top %d,%d,%d", newest.r, newest.g, newest.b, oldest.r,
                oldest.g, oldest.b);
    cr_assert_gt(newest.r, 200);
    cr_assert_lt(newest.b, 32);
    cr_assert_gt(oldest.b, oldest.r);
    int other = 0;
    for (long f = 12; f < 20; f++) {
        const isk_color r1 = centre_after("random", f, 1);
        for (int t = 2; t <= 3; t++) {
            const isk_color rt = centre_after("random", f, t);
            cr_assert(r1.r == rt.r && r1.g == rt.g && r1.b == rt.b && r1.a == rt.a, "frame %ld, %d threads", f, t);
        }
        const isk_color n = centre_after("newest", f, 1), o = centre_after("oldest", f, 1);
        other += (r1.r != n.r || r1.b != n.b) && (r1.r != o.r || r1.b != o.b);
    }
    cr_assert_gt(other, 0, "random never differs from both fixed orders");
}

/* flipbook_random_start: 8000 particles of an 8-frame flipbook start at
 * each frame 1000 +- 100 times (a standard error of 3%); without the key
 * every one starts at frame 0 and the store has no such column. */
Test(settings, flipbook_random_start_spreads_the_first_frames)
{
    static const char base[] = "[scene]\nseed = 6\n[emitter e]\nsource = stream\nrate = 0\ncount = 8000\n"
                               "draw = sprite\ntexture = textures/arrows.png\ntexture_grid = 4, 2\n";
    char with[1024];
    snprintf(with, sizeof with, "%sflipbook_random_start = true\n", base);
    isk_effect *fx = open_scene(with, 1), *plain = open_scene(base, 1);
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_step(plain), ISK_OK);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_eq(p->count, 8000u);
    cr_assert_not_null(p->frame0);
    long seen[8] = {0};
    for (size_t i = 0; i < p->count; i++) {
        cr_assert_lt(p->frame0[i], 8);
        seen[p->frame0[i]]++;
    }
    for (int k = 0; k < 8; k++)
        cr_assert(seen[k] > 900 && seen[k] < 1100, "frame %d: %ld", k, seen[k]);
    cr_assert_null(isk_effect_particles(plain, 0)->frame0);
    isk_effect_destroy(fx);
    isk_effect_destroy(plain);
}

/* The motion's ranges: 500 particles at rest on a circle of radius 1
 * around (0, 0), born by a burst at t = 0 and advanced to the end of the
 * first step h = 1/60 (the field kicks, then the particle moves), so each
 * one's velocity is its own acceleration times h: radially outwards at
 * (2 + its radial_extra) h; counter-clockwise along the circle at
 * (1 + its tangential_extra) h; (wind_x, wind_y) h; and for particles
 * launched at (2, 0), 2 (1 - (0.5 + slowing_extra) h).  All to 1e-12.
 * Each part is U*range: in [0, range) with a mean of range/2 within 5%
 * (a standard error of 1.3%). */
static void check_part(const double *v, size_t n, double range, const char *what)
{
    cr_assert_not_null(v, "%s: no column", what);
    double sum = 0;
    for (size_t i = 0; i < n; i++) {
        cr_assert(range > 0 ? v[i] >= 0 && v[i] < range : v[i] <= 0 && v[i] > range, "%s: %g", what, v[i]);
        sum += v[i];
    }
    cr_log_info("%s: mean %.4f of range %g over %zu", what, sum / (double)n, range, n);
    cr_assert_lt(fabs(sum / (double)n / range - 0.5), 0.05, "%s: mean %g", what, sum / (double)n);
}

Test(settings, each_particle_has_its_own_part_of_each_range)
{
    static const char text[] =
        "[scene]\nseed = 21\ndt = 1/60\n"
        "[emitter radial]\nsource = stream\ncount = 500\nshape = circle\nshape_a = 1\nradial_accel = 2\n"
        "radial_accel_range = 6\n"
        "[emitter swirl]\nsource = stream\ncount = 500\nshape = circle\nshape_a = 1\ntangential_accel = 1\n"
        "tangential_accel_range = 6\n"
        "[emitter wind]\nsource = stream\ncount = 500\nshape = circle\nshape_a = 1\nwind_range = 3, -5\n"
        "[emitter slowed]\nsource = stream\ncount = 500\nvelocity = 2, 0\nslowing = 0.5\nslowing_range = 4\n";
    isk_effect *fx = open_scene(text, 1);
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    const double h = 1.0 / 60;
    const isk_particles *r = isk_effect_particles(fx, 0), *t = isk_effect_particles(fx, 1);
    const isk_particles *w = isk_effect_particles(fx, 2), *s = isk_effect_particles(fx, 3);
    cr_assert_eq(r->count, 500u);
    check_part(r->radial_extra, r->count, 6, "radial_extra");
    check_part(t->tangential_extra, t->count, 6, "tangential_extra");
    check_part(w->wind_x, w->count, 3, "wind_x");
    check_part(w->wind_y, w->count, -5, "wind_y");
    check_part(s->slowing_extra, s->count, 4, "slowing_extra");
    cr_assert_null(r->tangential_extra);
    cr_assert_null(r->wind_x);
    cr_assert_null(t->radial_extra);
    for (size_t i = 0; i < 500; i++) {
        /* the birth point: where the particle is now, less its step */
        double x = r->x[i] - r->vx[i] * h, y = r->y[i] - r->vy[i] * h, d = hypot(x, y);
        double a = (2 + r->radial_extra[i]) * h;
        cr_assert_lt(hypot(r->vx[i] - a * x / d, r->vy[i] - a * y / d), 1e-12, "radial %zu", i);
        x = t->x[i] - t->vx[i] * h, y = t->y[i] - t->vy[i] * h, d = hypot(x, y);
        a = (1 + t->tangential_extra[i]) * h;
        cr_assert_lt(hypot(t->vx[i] + a * y / d, t->vy[i] - a * x / d), 1e-12, "tangential %zu", i);
        cr_assert_lt(hypot(w->vx[i] - w->wind_x[i] * h, w->vy[i] - w->wind_y[i] * h), 1e-12, "wind %zu", i);
        cr_assert_lt(fabs(s->vx[i] - 2 * (1 - (0.5 + s->slowing_extra[i]) * h)), 1e-12, "slowing %zu", i);
    }
    isk_effect_destroy(fx);
}

/* A live change of the emitter's value reaches every particle at once:
 * the parts are kept apart from it. */
Test(settings, a_live_radial_accel_still_reaches_every_particle)
{
    static const char text[] = "[scene]\nseed = 2\n[emitter e]\nsource = stream\ncount = 50\nshape = circle\n"
                               "shape_a = 1\nradial_accel_range = 1\n";
    isk_effect *fx = open_scene(text, 1);
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    isk_error err = {0};
    cr_assert_eq(isk_effect_set(fx, "emitter e", "radial_accel", "100", &err), ISK_OK, "%s", err.message);
    const isk_particles *p = isk_effect_particles(fx, 0);
    double before[50];
    for (size_t i = 0; i < 50; i++)
        before[i] = hypot(p->vx[i], p->vy[i]);
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    p = isk_effect_particles(fx, 0);
    for (size_t i = 0; i < 50; i++) /* at least 100/60 faster: the new value, plus its own part */
        cr_assert_gt(hypot(p->vx[i], p->vy[i]) - before[i], 100.0 / 60 - 1e-9, "particle %zu", i);
    isk_effect_destroy(fx);
}

/* ---- unused, they cost and change nothing -------------------------------------- */

/* Every new key written at its default gives the describe of the scene
 * without them, and the same bytes. */
Test(settings, defaults_change_nothing)
{
    static const char base[] =
        "[scene]\nwidth = 160\nheight = 96\nseed = 4\n"
        "[emitter e]\nsource = stream\nrate = 200\nlife = 1\nshape = ellipse\nshape_a = 1\nshape_b = 0.5\n"
        "launch = cone\nangle = 90\nspread = 40\nspeed_min = 2\nspeed_max = 4\ndraw = sprite\nsize = 1\n"
        "texture = textures/arrows.png\ntexture_grid = 4, 2\nspin = 90\nspin_range = 30\n";
    char with[2048];
    snprintf(with, sizeof with, "%slaunch_outward = false\nspin_end = none\ntexture_origin = 0.5, 0.5\ndraw_order = newest\n"
             "flipbook_random_start = false\nradial_accel_range = 0\ntangential_accel_range = 0\n"
             "wind_range = 0, 0\nslowing_range = 0\n", base);
    char *da = describe(base), *db = describe(with);
    cr_assert_str_eq(da, db);
    free(da);
    free(db);
    isk_canvas a = render(base, 1, 30), b = render(with, 1, 30);
    cr_assert_eq(memcmp(a.pixels, b.pixels, a.stride * (size_t)a.height), 0);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

/* ---- bad values: FILE:LINE and what is wrong ------------------------------------ */

Test(settings, bad_values_are_refused_with_their_line)
{
    static const struct {
        const char *line;
        const char *says;
    } bad[] = {
        {"shape = gaussian_blur", "shape"},
        {"spin_end = fast", "spin_end"},
        {"spin_end = 1e9", "spin_end"},
        {"texture_origin = 0.5", "texture_origin"},
        {"texture_origin = 20, 0", "texture_origin"},
        {"launch_outward = maybe", "launch_outward"},
        {"draw_order = lifetime", "draw_order"},
        {"radial_accel_range = -1", "radial_accel_range"},
        {"wind_range = 1", "wind_range"},
        {"slowing_range = -2", "slowing_range"},
        {"slowing_range = 2\nslowing = 1\nslow_faithful = true", "not with slow_faithful"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        char text[256];
        snprintf(text, sizeof text, "[emitter e]\nsource = stream\n%s\n", bad[k].line);
        isk_effect_def d;
        isk_error err = {0};
        cr_assert_neq(isk_scene_load_string(&d, text, "bad.ini", &err), ISK_OK, "%s", bad[k].line);
        cr_assert_not_null(strstr(err.message, "bad.ini:3"), "%s: %s", bad[k].line, err.message);
        cr_assert_not_null(strstr(err.message, bad[k].says), "%s: %s", bad[k].line, err.message);
    }
}
