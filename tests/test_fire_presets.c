/* SPDX-License-Identifier: MIT */
/* The presets (iskra/presets.h): their numbers, their validation, and one
 * reference image each (suite "refimg"). */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/presets.h"
#include "refimg.h"

typedef int (*preset_fn)(isk_effect_def *, const char *, isk_vec2, double);

typedef struct preset_case {
    const char *name;
    preset_fn fn;
    double x, y, scale;
    double xmin, xmax, ymin, ymax;
    int w, h;
    long frames;
} preset_case;

/* Each preset as its C function makes it (preset_magic_round: the magic
 * preset without the texture its scene adds, so its sparkles are round). */
static const preset_case cases[] = {
    {"preset_fire", isk_preset_fire, 0, 0, 1, -1.5, 1.5, -0.5, 2.5, 200, 200, 240},
    {"preset_smoke", isk_preset_smoke, 0, 0, 1, -1.5, 1.5, -0.5, 2.5, 200, 200, 300},
    {"preset_sparks", isk_preset_sparks, 0, 0, 1, -1.5, 1.5, -0.5, 2.5, 200, 200, 120},
    {"preset_fountain", isk_preset_fountain, 0, 0, 1, -3.5, 3.5, -3.5, 3.5, 200, 200, 300},
    {"preset_snow", isk_preset_snow, 0, 1.6, 1, -2.4, 2.4, -1.6, 1.6, 240, 160, 3600},
    {"preset_explosion", isk_preset_explosion, 0, 0, 1, -4, 4, -4, 4, 200, 200, 90},
    {"preset_galaxy", isk_preset_galaxy, 0, 0, 1, -2, 2, -2, 2, 240, 240, 400},
    {"preset_fireworks", isk_preset_fireworks, 0, 0, 1, -2.4, 2.4, -0.4, 4, 320, 294, 200},
    {"preset_rain", isk_preset_rain, 0, 0, 1, -2.4, 2.4, -3.5, 0.1, 320, 240, 150},
    {"preset_magic_round", isk_preset_magic, -2, 0, 1, -2.4, 2.4, -1.5, 1.5, 320, 200, 150},
};

static void render_case(const preset_case *pc, isk_canvas *c, isk_effect **keep)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    d.width = pc->w;
    d.height = pc->h;
    d.xmin = pc->xmin;
    d.xmax = pc->xmax;
    d.ymin = pc->ymin;
    d.ymax = pc->ymax;
    d.seed = 4;
    int i = pc->fn(&d, NULL, isk_vec2_make(pc->x, pc->y), pc->scale);
    cr_assert_eq(i, 0, "%s", pc->name);
    isk_effect *fx = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s: %s", pc->name, err.message);
    isk_effect_def_free(&d);
    cr_assert_eq(isk_canvas_init(c, pc->w, pc->h), ISK_OK);
    cr_assert_eq(isk_effect_run(fx, c, pc->frames), ISK_OK);
    if (keep)
        *keep = fx;
    else
        isk_effect_destroy(fx);
}

Test(refimg, presets)
{
    int failures = 0;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        isk_canvas c;
        render_case(&cases[k], &c, NULL);
        failures += !refimg_check(cases[k].name, &c);
        isk_canvas_free(&c);
    }
    cr_assert_eq(failures, 0);
}

/* Every preset is drawn: a good share of its canvas is lit. */
Test(fire_presets, each_preset_draws_something)
{
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        isk_canvas c;
        isk_effect *fx;
        render_case(&cases[k], &c, &fx);
        long lit = 0;
        for (int y = 0; y < c.height; y++)
            for (int x = 0; x < c.width; x++) {
                const uint8_t *p = isk_canvas_at(&c, x, y);
                lit += p[0] + p[1] + p[2] > 30;
            }
        cr_assert_gt(lit, (long)c.width * c.height / 200, "%s: %ld lit pixels", cases[k].name, lit);
        cr_assert_gt(isk_effect_particle_count(fx), 50u, "%s", cases[k].name);
        isk_effect_destroy(fx);
        isk_canvas_free(&c);
    }
}

Test(fire_presets, cocos_numbers_in_world_units)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    int f = isk_preset_fire(&d, NULL, isk_vec2_make(1, 2), 2.0);
    cr_assert_eq(f, 0);
    const isk_emitter_def *e = &d.emitters[f];
    cr_assert_str_eq(e->name, "fire");
    /* scale 2: 2 world units per 100 points, so posVar (40, 20) -> (0.8, 0.4). */
    cr_assert_float_eq(e->born.shape_a, 0.8, 1e-12);
    cr_assert_float_eq(e->born.shape_b, 0.4, 1e-12);
    cr_assert_float_eq(e->launch.speed_min, 0.8, 1e-12);
    cr_assert_float_eq(e->launch.speed_max, 1.6, 1e-12);
    cr_assert_float_eq(e->look.size, 1.08, 1e-12);
    cr_assert_float_eq(e->born.rate, 250.0 / 3.0, 1e-12);
    cr_assert_eq(e->born.capacity, 250u);
    cr_assert_eq(e->look.blend, ISK_BLEND_ADD);
    cr_assert(e->born.position.x == 1 && e->born.position.y == 2);
    cr_assert_eq(d.nforces, 0); /* fire needs no force */

    int s = isk_preset_sparks(&d, "embers", isk_vec2_make(0, 0), 1.0);
    cr_assert_eq(s, 1);
    cr_assert_eq(d.nforces, 1);
    cr_assert_str_eq(d.forces[0].name, "embers_gravity");
    cr_assert_float_eq(d.forces[0].g, 3.0, 1e-12);
    cr_assert_eq(d.emitters[s].motion.nforces, 1);
    /* Calling again with the same name reuses (and updates) the force. */
    cr_assert_eq(isk_preset_sparks(&d, "embers", isk_vec2_make(0, 0), 2.0), 2);
    cr_assert_eq(d.nforces, 1);
    cr_assert_float_eq(d.forces[0].g, 6.0, 1e-12);

    int w = isk_preset_fountain(&d, NULL, isk_vec2_make(0, 0), 1.0);
    cr_assert_float_eq(d.forces[d.emitters[w].motion.forces[0]].g, 0.9, 1e-12); /* cocos gravity -90 */
    int x = isk_preset_explosion(&d, NULL, isk_vec2_make(0, 0), 1.0);
    cr_assert_eq(d.emitters[x].born.count, 700u);
    cr_assert_float_eq(d.emitters[x].launch.spread, 2 * 3.14159265358979323846, 1e-12);
    isk_effect_def_free(&d);
}

Test(fire_presets, bad_arguments_add_nothing)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    cr_assert_eq(isk_preset_fire(NULL, NULL, isk_vec2_make(0, 0), 1), -1);
    cr_assert_eq(isk_preset_smoke(&d, NULL, isk_vec2_make(NAN, 0), 1), -1);
    cr_assert_eq(isk_preset_snow(&d, NULL, isk_vec2_make(0, 0), 0), -1);
    cr_assert_eq(isk_preset_sparks(&d, NULL, isk_vec2_make(0, 0), -1), -1);
    cr_assert_eq(isk_preset_explosion(&d, NULL, isk_vec2_make(0, 0), INFINITY), -1);
    cr_assert_eq(d.nemitters, 0);
    cr_assert_eq(d.nforces, 0);
    isk_effect_def_free(&d);
}

/* The fire preset's pool is cocos2d's 250: the steady state is at the cap
 * and the excess is counted, never written. */
Test(fire_presets, fire_pool_caps_at_250_and_counts_drops)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    isk_preset_fire(&d, NULL, isk_vec2_make(0, 0), 1.0);
    isk_effect *fx = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    for (int i = 0; i < 600; i++) {
        isk_effect_step(fx);
        cr_assert_leq(isk_effect_particle_count(fx), 250u);
    }
    cr_assert_gt(isk_effect_particle_count(fx), 230u);
    cr_assert_gt(isk_effect_dropped(fx, 0), 0u);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}
