/* SPDX-License-Identifier: MIT */
/* Public functions of the particle store, the explosions, spawn shapes, the
 * teaching API, effects, scenes, presets and the key table keep their
 * contract on hostile arguments: NULL, zero, negative and overflowing sizes
 * give a status (or nothing happens), never a crash (run under ASan+UBSan in
 * CI).  One block per function. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/explode.h"
#include "iskra/keys.h"
#include "iskra/presets.h"
#include "iskra/scene.h"
#include "iskra/shape.h"
#include "iskra/teach.h"

Test(contracts, particles)
{
    isk_particles p;
    cr_assert_eq(isk_particles_init(NULL, 4, 0), ISK_ERR_NULL);
    cr_assert_eq(isk_particles_init(&p, SIZE_MAX, 0), ISK_ERR_SIZE);
    cr_assert_eq(isk_particles_init(&p, 0, 1u << 20), ISK_ERR_SIZE);
    cr_assert_eq(isk_particles_init(&p, 0, 0), ISK_OK);
    cr_assert_eq(isk_particles_reserve(NULL, 4), ISK_ERR_NULL);
    cr_assert_eq(isk_particles_reserve(&p, SIZE_MAX), ISK_ERR_SIZE);
    cr_assert_eq(isk_particles_reserve(&p, ISK_PARTICLES_MAX + 1), ISK_ERR_SIZE);
    cr_assert_eq(isk_particles_add_columns(NULL, ISK_PARTICLES_OSC), ISK_ERR_NULL);
    cr_assert_eq(isk_particles_add_columns(&p, 1u << 20), ISK_ERR_SIZE);
    cr_assert_eq(isk_particles_add(NULL, 0, 0, 0, 0, 1, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_particles_add(&p, NAN, 0, 0, 0, 1, NULL), ISK_ERR_NAN);
    cr_assert_eq(isk_particles_add(&p, 0, 0, INFINITY, 0, 1, NULL), ISK_ERR_NAN);
    cr_assert_eq(isk_particles_add(&p, 0, 0, 0, 0, 0, NULL), ISK_ERR_RANGE);
    cr_assert_eq(isk_particles_add(&p, 0, 0, 0, 0, -1, NULL), ISK_ERR_RANGE);
    cr_assert_eq(isk_particles_add(&p, 1, 2, 3, 4, 5, NULL), ISK_OK);
    isk_particles_age(NULL, 0, 10, 1.0);
    isk_particles_age(&p, 0, SIZE_MAX, 1.0); /* clamped to the one particle */
    isk_particles_age(&p, 5, 2, 1.0);        /* an empty range */
    cr_assert_eq(p.age[0], 1.0);
    isk_particles_remove(NULL, 0);
    isk_particles_remove(&p, SIZE_MAX);
    cr_assert_eq(isk_particles_cull(NULL), 0);
    isk_particles_clear(NULL);
    cr_assert_eq(isk_particles_bytes(SIZE_MAX, 0), 0);
    isk_particles_free(NULL);
    isk_particles_free(&p);
    isk_particles_free(&p); /* twice is fine */
}

Test(contracts, explosions)
{
    isk_particles p;
    isk_rng r;
    isk_rng_seed(&r, 1);
    cr_assert_eq(isk_particles_init(&p, 0, 0), ISK_OK);
    cr_assert_eq(isk_explode_ring(NULL, 0, 0, 10, 0), ISK_ERR_NULL);
    cr_assert_eq(isk_explode_ring(&p, NAN, 0, 10, 0), ISK_ERR_NAN);
    cr_assert_eq(isk_explode_ring(&p, 0, 0, 0, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_explode_ring(&p, 0, 0, SIZE_MAX, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_explode_uniform(&p, NULL, 0, 0, 10, 0), ISK_ERR_NULL);
    cr_assert_eq(isk_explode_gauss(NULL, &r, 0, 0, 10, 0), ISK_ERR_NULL);
    cr_assert_eq(isk_explode_coulomb(&p, &r, 0, 0, 10, 0, (isk_kick_target)7), ISK_ERR_RANGE);
    cr_assert_eq(isk_explode_coulomb(&p, &r, 0, INFINITY, 10, 0, ISK_KICK_ALL), ISK_ERR_NAN);
    cr_assert_eq(isk_explode_layer(&p, &r, 1, 0, 0, 1, 10, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_explode_layer(&p, &r, 0, 1, 0, NAN, 10, 0), ISK_ERR_NAN);
    cr_assert_eq(isk_explode_layer(&p, &r, 0, 1, 0, 1, SIZE_MAX, SIZE_MAX), ISK_ERR_SIZE);
    isk_coulomb_kick(NULL, 0, 10, 0, 0, 150);
    isk_coulomb_kick(&p, 0, SIZE_MAX, 0, 0, 150);
    isk_multi_coulomb mc;
    cr_assert_eq(isk_multi_coulomb_start(NULL, 0, 0, 10, 0), ISK_ERR_NULL);
    cr_assert_eq(isk_multi_coulomb_start(&mc, NAN, 0, 10, 0), ISK_ERR_NAN);
    cr_assert_eq(isk_multi_coulomb_start(&mc, 0, 0, 0, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_multi_coulomb_release(NULL, &p, &r, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_multi_coulomb_due(NULL), 0);
    isk_multi_coulomb_advance(NULL, 1);
    cr_assert(isk_multi_coulomb_done(NULL));
    isk_particles_free(&p);
}

Test(contracts, shapes_and_launches)
{
    isk_rng r;
    isk_rng_seed(&r, 1);
    double x = 7, y = 7;
    cr_assert_eq(isk_shape_check(NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_velgen_check(NULL), ISK_ERR_NULL);
    isk_shape s = isk_shape_disc(0, 0, 1);
    isk_shape_sample(NULL, &r, &x, &y);
    cr_assert(x == 0 && y == 0);
    isk_shape_sample(&s, NULL, &x, &y);
    isk_shape_sample(&s, &r, NULL, NULL);
    cr_assert_eq(isk_shape_sample_n(NULL, &r, 4, &x, &y), ISK_ERR_NULL);
    cr_assert_eq(isk_shape_sample_n(&s, &r, 4, NULL, &y), ISK_ERR_NULL);
    s.kind = (isk_shape_kind)99;
    cr_assert_eq(isk_shape_check(&s), ISK_ERR_RANGE);
    isk_velgen v = isk_velgen_cone(0, 1, 1, 2);
    isk_velgen_sample(NULL, &r, &x, &y);
    isk_velgen_sample(&v, &r, NULL, &y);
    cr_assert_eq(isk_velgen_sample_n(&v, NULL, 4, &x, &y), ISK_ERR_NULL);
    v.kind = (isk_velgen_kind)-3;
    cr_assert_eq(isk_velgen_check(&v), ISK_ERR_RANGE);
}

Test(contracts, teaching_api)
{
    isk_mp_move(NULL, 0.1, isk_vec2_make(1, 1));
    isk_mp_move_explicit(NULL, 0.1, isk_vec2_make(1, 1));
    isk_vec2 f = isk_gravity_force(NULL, 9.81);
    cr_assert(f.x == 0 && f.y == 0);
    f = isk_drag_force(NULL, 1);
    cr_assert(f.x == 0 && f.y == 0);
    f = isk_potential_force_on(NULL, NULL, ISK_FIDELITY_SOUND);
    cr_assert(f.x == 0 && f.y == 0);
    isk_particle_init(NULL, 1, isk_vec2_make(0, 0), isk_vec2_make(0, 0));
    isk_particle c;
    isk_particle_init(&c, 1, isk_vec2_make(0, 0), isk_vec2_make(0, 0));
    isk_particle_draw(&c, NULL, NULL);
    isk_particle_draw(NULL, NULL, NULL);
    isk_particle_zarobi(&c, NULL, 1, 1, 1, 1);
    isk_particle_zarobi_box(NULL, 0, 1, 0, 1, 1, 1, 1, 1);
}

Test(contracts, effect_definitions)
{
    isk_effect_def_init(NULL);
    isk_effect_def_free(NULL);
    cr_assert_eq(isk_effect_def_add_force(NULL, "g", ISK_FORCE_GRAVITY), -1);
    cr_assert_null(isk_effect_def_add_emitter(NULL, "e"));
    cr_assert_null(isk_effect_def_add_drawing(NULL, "d", ISK_DRAWING_TEXT));
    cr_assert_eq(isk_effect_def_add_deflector(NULL, "s", isk_deflector_segment(0, 0, 1, 0)), -1);
    isk_effect_def d;
    isk_effect_def_init(&d);
    cr_assert_eq(isk_effect_def_add_force(&d, "g", (isk_force_kind)99), -1);
    cr_assert_eq(isk_effect_def_add_force(&d, "g", (isk_force_kind)-1), -1);
    cr_assert_null(isk_effect_def_add_drawing(&d, "d", (isk_drawing_kind)99));
    cr_assert_eq(isk_effect_def_find_force(NULL, "g"), -1);
    cr_assert_eq(isk_effect_def_find_force(&d, NULL), -1);
    cr_assert_eq(isk_effect_def_find_emitter(&d, "nobody"), -1);
    cr_assert_eq(isk_effect_def_find_deflector(NULL, NULL), -1);
    cr_assert_eq(isk_emitter_use_force(NULL, 0), ISK_ERR_NULL);
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, NULL); /* a NULL name is an empty one */
    cr_assert_not_null(e);
    cr_assert_eq(isk_emitter_use_force(e, -1), ISK_ERR_RANGE);
    cr_assert_eq(isk_emitter_use_force(e, ISK_EFFECT_MAX_FORCES), ISK_ERR_RANGE);
    cr_assert_eq(isk_emitter_use_deflector(e, -5), ISK_ERR_RANGE);
    cr_assert_eq(isk_effect_def_memory(NULL), 0);
    /* a hand-broken definition is refused, not followed */
    isk_effect *fx = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_effect_create(NULL, &d, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_create(&fx, NULL, &err), ISK_ERR_NULL);
    d.nforces = 3; /* a count without its array */
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_NULL);
    d.nforces = -1;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_SIZE);
    d.nforces = 0;
    e->motion.forces[0] = 9;
    e->motion.nforces = 1; /* a reference to nothing */
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    cr_assert_not_null(strstr(err.message, "force reference 9 does not exist"), "%s", err.message);
    e->motion.nforces = -4;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    e->motion.nforces = 0;
    e->born.source = (isk_source_kind)42;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    e->born.source = ISK_SOURCE_PARTICLE;
    e->look.color_over_life.n = 99;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    e->look.color_over_life.n = 0;
    d.width = 0;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    d.width = INT32_MAX;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    cr_assert_null(fx);
    isk_effect_def_free(&d);
}

Test(contracts, running_effects)
{
    cr_assert_eq(isk_effect_reset(NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_step(NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_render(NULL, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_run(NULL, NULL, 5), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_step_render(NULL, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_click(NULL, 0, 0), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_set_substeps(NULL, 2), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_add_potential(NULL, "p", NULL, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_remove_force(NULL, "p", NULL), ISK_ERR_NULL);
    char buf[8];
    cr_assert_eq(isk_effect_get(NULL, "scene", "dt", buf, sizeof buf, NULL), ISK_ERR_NULL);
    isk_effect_describe(NULL, NULL);
    isk_effect_destroy(NULL);
    cr_assert_eq(isk_effect_particle_count(NULL), 0);
    cr_assert_eq(isk_effect_frame(NULL), 0);
    cr_assert_null(isk_effect_view(NULL));
    cr_assert_null(isk_effect_definition(NULL));
    cr_assert_null(isk_effect_particles(NULL, 0));
    cr_assert_eq(isk_effect_dropped(NULL, 0), 0);
    size_t n = 99;
    cr_assert_null(isk_effect_potentials(NULL, &n));
    cr_assert_eq(n, 0);

    isk_effect_def d;
    isk_effect_def_init(&d);
    d.width = d.height = 16;
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "p");
    e->born.source = ISK_SOURCE_PARTICLE;
    isk_effect *fx = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_canvas small;
    cr_assert_eq(isk_canvas_init(&small, 8, 8), ISK_OK);
    cr_assert_eq(isk_effect_render(fx, &small), ISK_ERR_SIZE);
    cr_assert_eq(isk_effect_run(fx, &small, 1), ISK_ERR_SIZE);
    cr_assert_eq(isk_effect_run(fx, NULL, 1), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_click(fx, NAN, 0), ISK_ERR_NAN);
    cr_assert_eq(isk_effect_click(fx, 0, INFINITY), ISK_ERR_NAN);
    cr_assert_eq(isk_effect_set_substeps(fx, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_effect_set_substeps(fx, INT32_MAX), ISK_ERR_RANGE);
    cr_assert_eq(isk_effect_set_substeps(fx, -7), ISK_ERR_RANGE);
    cr_assert_eq(isk_effect_get(fx, "scene", "dt", NULL, 8, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_get(fx, "scene", "dt", buf, 0, NULL), ISK_ERR_SIZE);
    cr_assert_eq(isk_effect_get(fx, "scene", "dt", buf, 1, NULL), ISK_ERR_SIZE);
    cr_assert_eq(isk_effect_set(fx, "", "", "", NULL), ISK_ERR_RANGE);
    cr_assert_eq(isk_effect_set(fx, "emitter", "rate", "1", NULL), ISK_ERR_RANGE);
    cr_assert_eq(isk_effect_set(fx, "scene x", "dt", "1", NULL), ISK_ERR_RANGE);
    cr_assert_null(isk_effect_particles(fx, -1));
    cr_assert_null(isk_effect_particles(fx, 1));
    cr_assert_eq(isk_effect_dropped(fx, 99), 0);
    isk_canvas_free(&small);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

Test(contracts, scenes_presets_and_keys)
{
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load(NULL, "fig12_gravity", &err), ISK_ERR_NULL);
    cr_assert_eq(isk_scene_load(&d, NULL, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_scene_load_file(&d, NULL, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_scene_load_string(&d, NULL, "x", &err), ISK_ERR_NULL);
    cr_assert_eq(isk_scene_load_string(NULL, "", "x", &err), ISK_ERR_NULL);
    cr_assert_eq(isk_scene_load_string(&d, "", NULL, NULL), ISK_OK); /* NULL name and err are fine */
    isk_effect_def_free(&d);
    cr_assert_null(isk_scene_builtin_name(-1));
    cr_assert_null(isk_scene_builtin_name(isk_scene_builtin_count()));
    cr_assert_null(isk_scene_builtin_text(NULL));
    cr_assert_eq(isk_preset_fire(NULL, NULL, isk_vec2_make(0, 0), 1), -1);
    isk_effect_def_init(&d);
    cr_assert_eq(isk_preset_smoke(&d, NULL, isk_vec2_make(NAN, 0), 1), -1);
    cr_assert_eq(isk_preset_sparks(&d, NULL, isk_vec2_make(0, 0), 0), -1);
    cr_assert_eq(isk_preset_snow(&d, NULL, isk_vec2_make(0, 0), -INFINITY), -1);
    cr_assert_eq(d.nemitters, 0);
    isk_effect_def_free(&d);
    cr_assert_null(isk_key_find((isk_section_kind)-1, "dt"));
    cr_assert_null(isk_key_find(ISK_SECTION_SCENE, NULL));
    cr_assert_null(isk_section_name(ISK_SECTION_COUNT));
    cr_assert_eq(isk_section_named((isk_section_kind)77), 0);
    cr_assert_eq(isk_section_find(NULL), -1);
    cr_assert_null(isk_section_kind_key((isk_section_kind)-2));
    int n = 5;
    cr_assert_null(isk_section_kind_names((isk_section_kind)99, &n));
    cr_assert_eq(n, 0);
    cr_assert_str_eq(isk_key_type_name((isk_key_type)-1), "?");
    char buf[4] = "xyz";
    isk_key_range_text(NULL, buf, sizeof buf);
    cr_assert_str_eq(buf, "");
    isk_key_range_text(isk_key_find(ISK_SECTION_SCENE, "dt"), NULL, 10);
    isk_key_range_text(isk_key_find(ISK_SECTION_SCENE, "dt"), buf, 0);
    isk_key_kinds_text(NULL, 1, buf, sizeof buf);
    isk_key_default_text(NULL, buf, sizeof buf);
    isk_key_live_text(NULL, buf, sizeof buf);
    isk_key_range_text(isk_key_find(ISK_SECTION_EMITTER, "draw"), buf, sizeof buf); /* truncated, terminated */
    cr_assert_eq(strlen(buf), 3);
    cr_assert_eq(isk_key_choices(NULL, NULL, 5), 0);
    const char *c[2];
    cr_assert_eq(isk_key_choices(isk_key_find(ISK_SECTION_EMITTER, "draw"), c, 2), 2);
    cr_assert_eq(isk_key_choices(isk_key_find(ISK_SECTION_EMITTER, "draw"), c, -1), 0);
}
