/* SPDX-License-Identifier: MIT */
/* docs/from-love-godot.md's claims, on the scene files it quotes
 * (docs/from-love-godot/ *.ini): every file loads and runs, and each
 * behaviour the page states is measured on its file: angle 90 launches
 * up within the whole opening `spread`, rotation 90 is +pi/2, positive
 * tangential accelerations turn counter-clockwise, the radial origin is
 * the emitter's current position, the damping laws' figures, pixel
 * units, draw order by `order`, and the everyday settings (a gaussian
 * area's spread, a launch outward from the centre). */
#include <criterion/criterion.h>
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "scene_text.h"

#define FROM_DIR "docs/from-love-godot"
#define PI 3.14159265358979323846

/* The page's file `name` (in FROM_DIR), opened. */
static isk_effect *open_file(const char *name)
{
    char path[256];
    snprintf(path, sizeof path, FROM_DIR "/%s", name);
    return scene_open_file(path);
}

Test(from_engines, every_file_loads_runs_and_draws)
{
    DIR *d = opendir(FROM_DIR);
    cr_assert_not_null(d);
    struct dirent *e;
    int files = 0;
    while ((e = readdir(d))) {
        size_t n = strlen(e->d_name);
        if (n < 5 || strcmp(e->d_name + n - 4, ".ini"))
            continue;
        isk_effect *fx = open_file(e->d_name);
        const isk_effect_def *def = isk_effect_definition(fx);
        isk_canvas c;
        cr_assert_eq(isk_canvas_init(&c, def->width, def->height), ISK_OK);
        cr_assert_eq(isk_effect_run(fx, &c, 30), ISK_OK, "%s", e->d_name);
        cr_assert_gt(isk_effect_particle_count(fx), 0, "%s has no particle after 30 frames", e->d_name);
        isk_canvas_free(&c);
        isk_effect_destroy(fx);
        files++;
    }
    closedir(d);
    cr_assert_eq(files, 7, "expected the page's seven scene files, found %d", files);
}

/* angle = 90 is up; spread = 45 is the whole opening: directions fill
 * 67.5..112.5 degrees; rotation = 90 is +pi/2 (counter-clockwise). */
Test(from_engines, angles_go_counter_clockwise_and_spread_is_the_whole_opening)
{
    isk_effect *fx = open_file("angles.ini");
    scene_steps(fx, 60);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_gt(p->count, 40);
    cr_assert_not_null(p->angle, "rotation keeps no angle column");
    double lo = 180, hi = 0;
    for (size_t i = 0; i < p->count; i++) {
        double deg = atan2(p->vy[i], p->vx[i]) * 180 / PI;
        lo = deg < lo ? deg : lo;
        hi = deg > hi ? deg : hi;
    }
    cr_expect_geq(lo, 67.5 - 1e-9);
    cr_expect_leq(hi, 112.5 + 1e-9);
    cr_expect_lt(lo, 70, "the opening reaches only %g degrees: spread is not the whole opening", lo);
    cr_expect_gt(hi, 110, "the opening reaches only %g degrees: spread is not the whole opening", hi);
    isk_effect_destroy(fx);

    /* rotation = 90 with no spin: every angle is +pi/2 */
    fx = scene_text_open("[emitter a]\nsource = stream\nrate = 10\nrotation = 90\n"
                         "texture = docs/from-love-godot/../../scenes/textures/arrows.png\ntexture_grid = 4, 2\n",
                         0);
    scene_steps(fx, 30);
    p = isk_effect_particles(fx, 0);
    cr_assert_gt(p->count, 0);
    for (size_t i = 0; i < p->count; i++)
        cr_expect_float_eq(p->angle[i], PI / 2, 1e-12);
    isk_effect_destroy(fx);
}

/* A particle at rest right of a still emitter, pushed only by a positive
 * tangential acceleration, starts moving up: counter-clockwise. */
Test(from_engines, positive_tangential_turns_counter_clockwise)
{
    isk_effect *fx = scene_text_open("[emitter e]\nsource = stream\nposition = 0, 0\nshape = circle\nshape_a = 1\n"
                                     "count = 1\nlife = 10\ntangential_accel = 6\n",
                                     0);
    scene_steps(fx, 60); /* one particle, born at the start on a circle of radius 1, 1 s old */
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_eq(p->count, 1);
    /* its velocity turned counter-clockwise from where it sits: cross(pos, v) > 0 */
    double cross = p->x[0] * p->vy[0] - p->y[0] * p->vx[0];
    cr_expect_gt(cross, 0, "pos (%g, %g) v (%g, %g): not counter-clockwise", p->x[0], p->y[0], p->vx[0], p->vy[0]);
    isk_effect_destroy(fx);
}

/* The radial origin is the emitter now: a particle born at rest on a
 * moving emitter and pulled towards "the emitter" follows it; pulled
 * towards its birth point (LÖVE's rule) it would never move. */
Test(from_engines, radial_origin_is_the_emitter_now)
{
    isk_effect *fx = scene_text_open("[emitter e]\nsource = stream\nposition = 0, 0\nemitter_velocity = 4, 0\n"
                                     "count = 1\nlife = 10\nradial_accel = -8\n",
                                     0);
    scene_steps(fx, 61); /* the first particle, born at t = 0 at x = 0, is 1 s old */
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_geq(p->count, 1);
    cr_expect_gt(p->x[0], 1.0, "the particle stayed at x = %g: pulled towards its birth point", p->x[0]);
    cr_expect_float_eq(p->y[0], 0.0, 1e-12);
    isk_effect_destroy(fx);
}

/* damping.ini after 1 s at 60 frames a second: slowing 2 leaves
 * (1 - 2/60)^60 = 0.1308 of the speed, drag b = 2 with exact-drag
 * e^-2 = 0.1353; LÖVE's law, (1 / (1 + 2/60))^60, would leave 0.1398. */
Test(from_engines, damping_laws_figures)
{
    cr_expect_float_eq(pow(1 - 2.0 / 60, 60), 0.1308, 5e-5);
    cr_expect_float_eq(exp(-2.0), 0.1353, 5e-5);
    cr_expect_float_eq(pow(1 / (1 + 2.0 / 60), 60), 0.1398, 5e-5);
    isk_effect *fx = open_file("damping.ini");
    scene_steps(fx, 60);
    const isk_particles *slowed = isk_effect_particles(fx, 0), *dragged = isk_effect_particles(fx, 1);
    cr_assert_eq(slowed->count, 1);
    cr_assert_eq(dragged->count, 1);
    cr_expect_float_eq(slowed->vx[0] / 10, pow(1 - 2.0 / 60, 60), 1e-12, "slowed: %.17g", slowed->vx[0] / 10);
    cr_expect_float_eq(dragged->vx[0] / 10, exp(-2.0), 1e-9, "dragged: %.17g", dragged->vx[0] / 10);
    isk_effect_destroy(fx);
}

/* pixels.ini: world (x, y) is pixel (x, 600 - y); LÖVE's (400, 500) is
 * the emitter's (400, 100). */
Test(from_engines, pixel_units)
{
    isk_effect *fx = open_file("pixels.ini");
    const isk_view *v = isk_effect_view(fx);
    double X, Y;
    isk_view_to_screen(v, 400, 100, &X, &Y);
    cr_expect_float_eq(X, 400, 1e-9);
    cr_expect_float_eq(Y, 500, 1e-9);
    isk_view_to_screen(v, 123, 456, &X, &Y);
    cr_expect_float_eq(X, 123, 1e-9);
    cr_expect_float_eq(Y, 600 - 456, 1e-9);
    const isk_effect_def *d = isk_effect_definition(fx);
    cr_expect_float_eq(d->forces[0].g, 980, 0);
    isk_effect_destroy(fx);
}

/* draw_order.ini: the fire (order 1, first in the file) covers the smoke
 * (order 0) where both stand: the emitters' centre is the fire's colour. */
Test(from_engines, order_puts_the_fire_over_the_smoke)
{
    isk_effect *fx = open_file("draw_order.ini");
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 400, 400), ISK_OK);
    cr_assert_eq(isk_effect_run(fx, &c, 60), ISK_OK);
    isk_color px = isk_canvas_get(&c, 200, 195); /* just above the emitters at the centre */
    cr_expect(px.r == 255 && px.g == 165 && px.b == 0, "the centre is %d %d %d, not the fire's orange", px.r, px.g,
              px.b);
    isk_canvas_free(&c);
    isk_effect_destroy(fx);

    /* the same file with the orders swapped: the smoke covers the fire */
    char *text = NULL;
    {
        FILE *f = fopen(FROM_DIR "/draw_order.ini", "rb");
        cr_assert_not_null(f);
        static char buf[8192];
        size_t n = fread(buf, 1, sizeof buf - 1, f);
        fclose(f);
        buf[n] = 0;
        char *a = strstr(buf, "order = 1"), *b = strstr(buf, "order = 0");
        cr_assert(a && b);
        a[8] = '0';
        b[8] = '1';
        text = buf;
    }
    fx = scene_text_open(text, 0);
    cr_assert_eq(isk_canvas_init(&c, 400, 400), ISK_OK);
    cr_assert_eq(isk_effect_run(fx, &c, 60), ISK_OK);
    px = isk_canvas_get(&c, 200, 195);
    cr_expect(px.r == 128 && px.g == 128 && px.b == 128, "swapped, the centre is %d %d %d, not the smoke's gray", px.r,
              px.g, px.b);
    isk_canvas_free(&c);
    isk_effect_destroy(fx);
}

/* settings.ini: the gaussian area's particles (at rest where they were
 * born) spread with standard deviations 1.5 and 0.5 (within 15%: about
 * 200 births, a standard error of 5%); the border ellipse's launch
 * outward moves every particle straight away from its centre (4, 4). */
Test(from_engines, everyday_settings)
{
    isk_effect *fx = open_file("settings.ini");
    scene_steps(fx, 60);
    const isk_particles *mist = isk_effect_particles(fx, 0);
    cr_assert_gt(mist->count, 150u);
    double sx = 0, sy = 0;
    for (size_t i = 0; i < mist->count; i++) {
        sx += (mist->x[i] + 5) * (mist->x[i] + 5);
        sy += mist->y[i] * mist->y[i];
    }
    sx = sqrt(sx / (double)mist->count);
    sy = sqrt(sy / (double)mist->count);
    cr_log_info("gaussian area: standard deviations %.3f, %.3f over %zu births", sx, sy, mist->count);
    cr_assert_lt(fabs(sx / 1.5 - 1), 0.15);
    cr_assert_lt(fabs(sy / 0.5 - 1), 0.15);
    const isk_particles *halo = isk_effect_particles(fx, 1);
    cr_assert_gt(halo->count, 30u);
    for (size_t i = 0; i < halo->count; i++) {
        const double dx = halo->x[i] - 4, dy = halo->y[i] - 4;
        cr_assert_lt(fabs(dx * halo->vy[i] - dy * halo->vx[i]), 1e-9 * hypot(dx, dy) * 2);
        cr_assert_gt(dx * halo->vx[i] + dy * halo->vy[i], 0.0);
    }
    isk_effect_destroy(fx);
}
