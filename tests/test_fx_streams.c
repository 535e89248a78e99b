/* SPDX-License-Identifier: MIT */
/* An emitter's random streams (effect_internal.h, fx_stream): positions,
 * launch velocities, lives and the rest of what the theses' scenes draw
 * come from the emitter's main stream; each optional attribute (mass_range,
 * rotation_range, spin_range, size_range, color_pick, a deflector's
 * probability, flipbook_random_start, the motion's ranges) draws from a
 * stream of its own.  So turning such a key on
 * for 20 frames changes the particles born then, and nothing else: once
 * they have died, the canvas is the one of the run that never had it. */
#include <criterion/criterion.h>

#include <stdio.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "key_case.h"
#include "scene_text.h"

/* Lives of 0.3..0.35 s (at most 21 frames): what is born up to frame 30
 * is gone by frame 52.  The "over" blend keeps the cull in particle order
 * whatever the keys, so the particles' arrays can be compared too. */
static const char base[] = "[scene]\nwidth = 64\nheight = 48\nseed = 5\n[view]\nxmin = -4\nxmax = 4\nymin = -3\n"
                           "ymax = 3\n[force drag]\nb = 0.5\n[deflector wall]\nsegment = 0.5, -3, 0.5, 3\n"
                           "[emitter e]\nsource = stream\nrate = 120\nlaunch = disc\nspeed_max = 6\nlife = 0.3\n"
                           "life_range = 0.05\nforces = drag\ndeflectors = wall\nbounded = false\n"
                           "draw = sprite\nsprite = smooth\nsize = 0.4\nalign = velocity\n";

typedef struct toggle {
    const char *section, *key, *on, *off;
    const char *extra; /* lines added to base's emitter, or NULL */
} toggle;

static const toggle toggles[] = {
    {"emitter e", "mass_range", "3", "0", NULL},
    {"emitter e", "rotation_range", "360", "0", NULL},
    {"emitter e", "spin_range", "720", "0", NULL},
    {"emitter e", "size_range", "0.6", "0", NULL},
    {"emitter e", "color_pick", "0:red, 1:blue", "off", NULL},
    {"deflector wall", "probability", "0.5", "1", NULL},
    {"emitter e", "radial_accel_range", "30", "0", NULL},
    {"emitter e", "tangential_accel_range", "30", "0", NULL},
    {"emitter e", "wind_range", "20, -20", "0, 0", NULL},
    {"emitter e", "slowing_range", "8", "0", NULL},
    {"emitter e", "flipbook_random_start", "true", "false",
     "texture = scenes/textures/arrows.png\ntexture_grid = 4, 2\ntexture_fps = 3\n"},
};

static void step_frames(isk_effect *fx, int n)
{
    for (int i = 0; i < n; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
}

static void render(isk_effect *fx, isk_canvas *c)
{
    cr_assert_eq(isk_canvas_init(c, 64, 48), ISK_OK);
    cr_assert_eq(isk_effect_render(fx, c), ISK_OK);
}

Test(fx_streams, an_attribute_on_for_20_frames_leaves_no_trace)
{
    for (size_t k = 0; k < sizeof toggles / sizeof toggles[0]; k++) {
        const toggle *t = &toggles[k];
        char text[2048];
        snprintf(text, sizeof text, "%s%s", base, t->extra ? t->extra : "");
        isk_effect *plain = scene_text_open(text, 1), *tried = scene_text_open(text, 1);
        isk_error err;
        step_frames(plain, 10);
        step_frames(tried, 10);
        cr_assert_eq(isk_effect_set(tried, t->section, t->key, t->on, &err), ISK_OK, "%s", err.message);
        step_frames(plain, 15);
        step_frames(tried, 15);
        isk_canvas a, b;
        render(plain, &a);
        render(tried, &b);
        cr_assert(!key_case_equal(&a, &b), "%s = %s changes nothing while on", t->key, t->on);
        isk_canvas_free(&a);
        isk_canvas_free(&b);
        step_frames(plain, 5);
        step_frames(tried, 5);
        cr_assert_eq(isk_effect_set(tried, t->section, t->key, t->off, &err), ISK_OK, "%s", err.message);
        step_frames(plain, 30); /* frame 60: those born with the key are dead */
        step_frames(tried, 30);
        const isk_particles *p = isk_effect_particles(plain, 0), *q = isk_effect_particles(tried, 0);
        cr_assert_eq(p->count, q->count, "%s", t->key);
        cr_assert_eq(memcmp(p->x, q->x, p->count * sizeof *p->x), 0, "%s moved later particles", t->key);
        cr_assert_eq(memcmp(p->vy, q->vy, p->count * sizeof *p->vy), 0, "%s moved later particles", t->key);
        render(plain, &a);
        render(tried, &b);
        cr_assert(key_case_equal(&a, &b), "%s: the canvas differs after those particles died", t->key);
        isk_canvas_free(&a);
        isk_canvas_free(&b);
        isk_effect_destroy(plain);
        isk_effect_destroy(tried);
    }
}

/* The main stream is the one a C program seeding an isk_rng with the
 * scene's seed gets: the streams of the attributes take nothing from it,
 * whichever are set. */
Test(fx_streams, attributes_take_no_draw_from_the_main_stream)
{
    char text[2048];
    snprintf(text, sizeof text, "%ssize_range = 0.6\ncolor_pick = 0:red, 1:blue\nmass_range = 3\n", base);
    isk_effect *plain = scene_text_open(base, 1), *all = scene_text_open(text, 1);
    step_frames(plain, 12);
    step_frames(all, 12);
    const isk_particles *p = isk_effect_particles(plain, 0), *q = isk_effect_particles(all, 0);
    cr_assert_eq(p->count, q->count);
    /* the same births (positions, launch velocities, lives), drawn from the main stream */
    cr_assert_eq(memcmp(p->life, q->life, p->count * sizeof *p->life), 0);
    isk_effect_destroy(plain);
    isk_effect_destroy(all);
}
