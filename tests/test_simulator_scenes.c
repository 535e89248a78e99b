/* SPDX-License-Identifier: MIT */
/* The thesis's simulator scenes, built in: simulator (figure 21) and
 * fig22..fig25_simulator_* hold the parameters of their thesis pages, start
 * with an empty layer that clicks fill, and the mushroom scenes (26-29) ask
 * `iskra play` to start paused after their first frame (prviFrame). */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "scene_open.h"

typedef struct sim_scene {
    const char *name;
    const char *explosion;
    int click_enabled;
    const char *sides;
} sim_scene;

static const sim_scene scenes[] = {
    {"simulator", "coulomb", 0, "right, bottom, left"},
    {"fig22_simulator_regular", "ring", 1, "none"},
    {"fig23_simulator_gauss", "gauss", 1, "none"},
    {"fig24_simulator_coulomb", "coulomb", 1, "none"},
    {"fig25_simulator_multi_coulomb", "multi-coulomb", 1, "none"},
};

static void expect_value(isk_effect *fx, const char *section, const char *key, const char *want, const char *name)
{
    char v[128];
    isk_error err;
    cr_assert_eq(isk_effect_get(fx, section, key, v, sizeof v, &err), ISK_OK, "%s: %s", name, err.message);
    cr_expect_str_eq(v, want, "%s: [%s] %s", name, section, key);
}

Test(simulator_scenes, hold_the_thesis_pages_parameters)
{
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        const sim_scene *s = &scenes[i];
        isk_effect *fx = scene_open_builtin(s->name);
        const isk_effect_def *d = isk_effect_definition(fx);
        cr_expect_eq(d->width, 600);
        cr_expect_eq(d->height, 600);
        cr_expect(d->xmin == 0 && d->xmax == 10 && d->ymin == 0 && d->ymax == 10, "%s: view 0..10", s->name);
        cr_expect_eq(d->fidelity, ISK_FIDELITY_THESIS, "%s", s->name);
        cr_expect_eq(d->show.start_paused, 0, "%s: prviFrame is false on this page", s->name);
        expect_value(fx, "scene", "dt", "0.016666666666666666", s->name);
        expect_value(fx, "scene", "substeps", "1", s->name);
        expect_value(fx, "scene", "speed_divisor", "1", s->name);
        expect_value(fx, "force gravity", "g", "0", s->name);
        expect_value(fx, "force drag", "b", "0", s->name);
        expect_value(fx, "bounds", "mode", "thesis", s->name);
        expect_value(fx, "bounds", "sides", s->sides, s->name);
        expect_value(fx, "click", "explosion", s->explosion, s->name);
        expect_value(fx, "click", "enabled", s->click_enabled ? "true" : "false", s->name);
        expect_value(fx, "click", "count", "1000", s->name);
        expect_value(fx, "emitter particles", "count", "0", s->name);
        expect_value(fx, "emitter particles", "draw", "dot-browser", s->name);
        cr_expect_eq(isk_effect_particle_count(fx), 0u, "%s: the layer starts empty", s->name);
        isk_effect_destroy(fx);
    }
}

Test(simulator_scenes, the_mushroom_scenes_start_paused)
{
    const char *names[] = {"fig26_mushroom_one_potential", "fig27_mushroom_moving_potential",
                           "fig28_mushroom_three_potentials", "fig29_mushroom_four_potentials"};
    for (int i = 0; i < 4; i++) {
        isk_effect *fx = scene_open_builtin(names[i]);
        cr_expect_eq(isk_effect_definition(fx)->show.start_paused, 1, "%s", names[i]);
        isk_effect_destroy(fx);
    }
}

/* The click of fig 22: a ring of 1000, mass 2, speed 4*sqrt(2); the layer
 * stays what it was (empty) after a reset, unless its count was changed. */
Test(simulator_scenes, clicks_fill_the_empty_layer_and_reset_empties_it)
{
    isk_effect *fx = scene_open_builtin("fig22_simulator_regular");
    cr_assert_eq(isk_effect_click(fx, 5, 5), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 1000u);
    const isk_particles *p = isk_effect_particles(fx, 0);
    for (size_t i = 0; i < p->count; i++) {
        cr_assert_eq(p->m[i], 2.0);
        cr_assert_float_eq(hypot(p->vx[i], p->vy[i]), 4 * sqrt(2.0), 1e-12);
    }
    cr_assert_eq(isk_effect_click(fx, 2, 2), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 2000u);
    cr_assert_eq(isk_effect_reset(fx), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 0u);
    isk_error err;
    cr_assert_eq(isk_effect_set(fx, "emitter particles", "count", "250", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_set(fx, "emitter particles", "rect", "0, 10, 0, 1", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_particle_count(fx), 0u, "a layer's count applies at reset");
    cr_assert_eq(isk_effect_reset(fx), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 250u);
    for (size_t i = 0; i < p->count; i++)
        cr_assert(p->y[i] >= 0 && p->y[i] <= 1);
    cr_assert_eq(isk_effect_set(fx, "emitter particles", "count", "10001", &err), ISK_ERR_RANGE);
    cr_assert(strstr(err.message, "must be 0..10000"), "%s", err.message);
    isk_effect_destroy(fx);
}

Test(simulator_scenes, the_empty_simulator_ignores_clicks_until_a_mode_is_chosen)
{
    isk_effect *fx = scene_open_builtin("simulator");
    cr_assert_eq(isk_effect_click(fx, 5, 5), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 0u);
    isk_error err;
    cr_assert_eq(isk_effect_set(fx, "click", "enabled", "true", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_set(fx, "click", "explosion", "gauss", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_click(fx, 5, 5), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 1000u);
    isk_effect_destroy(fx);
}
