/* SPDX-License-Identifier: MIT */
/* The system: the thesis simulator's frame bit for bit, determinism,
 * potential ids, substeps, ageing, hard cases. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/system.h"
#include "iskra/teach.h"

static int stores_equal(const isk_particles *a, const isk_particles *b)
{
    size_t n = a->count;
    return n == b->count && !memcmp(a->x, b->x, n * 8) && !memcmp(a->y, b->y, n * 8) &&
           !memcmp(a->vx, b->vx, n * 8) && !memcmp(a->vy, b->vy, n * 8) && !memcmp(a->m, b->m, n * 8);
}

/* A mushroom-like scene: layer + Coulomb click, gravity, drag, two
 * potentials (one with a max distance that trips mid-run), walls R/B/L,
 * precision 2.  The system must equal main.js's per-particle loop:
 *   for j < precision: for i < n: h = dt/precision/f;
 *     P = reduce(+, F_pot) from (0,0); F = (G + D) + P; pomakni(h, F); zarobi
 * then potentials move by pomak(h*precision). */
Test(sim_system, equals_the_thesis_simulator_loop)
{
    isk_system s;
    isk_system_init(&s, 2024, 0);
    isk_system_set_gravity(&s, 9.81);
    isk_system_set_drag(&s, 0.47);
    isk_system_set_substeps(&s, 2);
    s.forces.centre = ISK_FIDELITY_THESIS;
    isk_bounds b;
    isk_bounds_thesis(&b, 0, 10, 0, 10, ISK_SIDE_RIGHT | ISK_SIDE_BOTTOM | ISK_SIDE_LEFT);
    isk_system_set_bounds(&s, &b, 1);
    isk_potential a, c;
    isk_potential_init(&a, 800, isk_vec2_make(5, 5), 1);
    isk_potential_set_law(&a, ISK_COULOMB_LAW_CODE, 4);
    a.min_dist = 0.5;
    a.max_dist = 0.1;
    isk_potential_init(&c, 150, isk_vec2_make(5, 1.8), 1);
    isk_potential_set_law(&c, ISK_COULOMB_LAW_CODE, 2);
    c.x_mult = 0;
    c.min_dist = 0.2;
    c.vel = isk_vec2_make(0, 20);
    int id1, id2;
    cr_assert_eq(isk_system_add_potential(&s, &a, &id1), ISK_OK);
    cr_assert_eq(isk_system_add_potential(&s, &c, &id2), ISK_OK);
    cr_assert(id1 == 1 && id2 == 2);
    cr_assert_eq(isk_system_add_layer(&s, 0, 10, 0, 2, 700), ISK_OK);
    cr_assert_eq(isk_system_explode(&s, ISK_EXPLOSION_COULOMB, 5, 4, 300), ISK_OK);

    /* Reference: a copy of the initial state as thesis objects. */
    size_t n = s.particles.count;
    isk_particle *ref = malloc(n * sizeof *ref);
    for (size_t i = 0; i < n; i++)
        isk_particle_init(&ref[i], s.particles.m[i], isk_vec2_make(s.particles.x[i], s.particles.y[i]),
                          isk_vec2_make(s.particles.vx[i], s.particles.vy[i]));
    isk_potential pots[2] = {s.forces.pot[0], s.forces.pot[1]};

    const double dt = 1.0 / 60;
    int tripped_at = -1;
    for (int frame = 0; frame < 120; frame++) {
        double h = 0;
        for (int j = 0; j < 2; j++)
            for (size_t i = 0; i < n; i++) {
                h = dt / 2 / 1.0;
                isk_vec2 P = isk_vec2_make(0, 0);
                for (int k = 0; k < 2; k++)
                    P = isk_vec2_add(P, isk_potential_force_on(&pots[k], &ref[i].mp, ISK_FIDELITY_THESIS));
                isk_vec2 F = isk_vec2_add(
                    isk_vec2_add(isk_gravity_force(&ref[i].mp, 9.81), isk_drag_force(&ref[i].mp, 0.47)), P);
                isk_mp_move(&ref[i].mp, h, F);
                isk_particle_zarobi_box(&ref[i], 0, 10, 0, 10, 0, 1, 1, 1);
            }
        for (int k = 0; k < 2; k++)
            isk_potential_move(&pots[k], h * 2);
        cr_assert_eq(isk_system_step(&s, dt), ISK_OK);
        for (size_t i = 0; i < n; i++) {
            int same = !memcmp(&ref[i].mp.r.x, &s.particles.x[i], 8) && !memcmp(&ref[i].mp.r.y, &s.particles.y[i], 8) &&
                       !memcmp(&ref[i].mp.v.x, &s.particles.vx[i], 8) && !memcmp(&ref[i].mp.v.y, &s.particles.vy[i], 8);
            if (!same)
                cr_assert_fail("frame %d particle %zu differs", frame, i);
        }
        cr_assert_eq(s.forces.pot[0].enabled, pots[0].enabled);
        cr_assert(s.forces.pot[1].r.y == pots[1].r.y);
        if (tripped_at < 0 && !pots[0].enabled)
            tripped_at = frame;
    }
    cr_assert_geq(tripped_at, 0, "the max-distance switch should trip in this scene");
    free(ref);
    isk_system_free(&s);
}

static void build(isk_system *s, uint64_t seed, isk_integrator m)
{
    isk_system_init(s, seed, 0);
    isk_system_set_gravity(s, 9.81);
    isk_system_set_drag(s, 0.3);
    isk_system_set_integrator(s, m);
    isk_bounds b;
    isk_bounds_reflect(&b, 0, 10, 0, 10, ISK_SIDE_ALL, 0, 0.7);
    isk_system_set_bounds(s, &b, 1);
    isk_potential p;
    isk_potential_init(&p, 50, isk_vec2_make(5, 6), 1);
    p.min_dist = 0.3;
    isk_system_add_potential(s, &p, NULL);
    isk_system_add_layer(s, 0, 10, 0, 1, 500);
    isk_system_explode(s, ISK_EXPLOSION_GAUSS, 5, 5, 500);
    isk_system_explode(s, ISK_EXPLOSION_MULTI_COULOMB, 3, 7, 400);
}

Test(sim_system, same_seed_same_bytes_different_seed_different)
{
    for (int m = 0; m < ISK_INTEGRATOR_COUNT; m++) {
        isk_system a, b, c;
        build(&a, 77, (isk_integrator)m);
        build(&b, 77, (isk_integrator)m);
        build(&c, 78, (isk_integrator)m);
        for (int i = 0; i < 100; i++) {
            isk_system_step(&a, 1.0 / 60);
            isk_system_step(&b, 1.0 / 60);
            isk_system_step(&c, 1.0 / 60);
        }
        cr_assert_eq(a.particles.count, 1400);
        cr_assert(stores_equal(&a.particles, &b.particles));
        cr_assert(!stores_equal(&a.particles, &c.particles));
        for (size_t i = 0; i < a.particles.count; i++)
            cr_assert(isfinite(a.particles.x[i]) && a.particles.x[i] >= 0 && a.particles.x[i] <= 10);
        isk_system_free(&a);
        isk_system_free(&b);
        isk_system_free(&c);
    }
}

Test(sim_system, potential_ids_belong_to_the_system)
{
    isk_system a, b;
    isk_system_init(&a, 1, 0);
    isk_system_init(&b, 1, 0);
    isk_potential p;
    isk_potential_init(&p, 1, isk_vec2_make(0, 0), 1);
    int id;
    isk_system_add_potential(&a, &p, &id);
    cr_assert_eq(id, 1);
    isk_system_add_potential(&a, &p, &id);
    cr_assert_eq(id, 2);
    isk_system_add_potential(&b, &p, &id);
    cr_assert_eq(id, 1);
    cr_assert_not_null(isk_system_potential(&a, 2));
    cr_assert_null(isk_system_potential(&a, 3));
    p.P = NAN;
    cr_assert_eq(isk_system_add_potential(&a, &p, &id), ISK_ERR_NAN);
    isk_system_free(&a);
    isk_system_free(&b);
}

/* N substeps of dt/N per frame == N frames of dt/N. */
Test(sim_system, substeps_are_n_steps_of_dt_over_n)
{
    isk_system a, b;
    build(&a, 5, ISK_INTEGRATE_SEMI_EULER);
    build(&b, 5, ISK_INTEGRATE_SEMI_EULER);
    a.njobs = b.njobs = 0; /* no scheduled releases: compare physics only */
    a.auto_move_potentials = b.auto_move_potentials = 0;
    isk_system_set_substeps(&a, 4);
    for (int i = 0; i < 30; i++) {
        isk_system_step(&a, 0.04);
        for (int j = 0; j < 4; j++)
            isk_system_step(&b, 0.01);
    }
    cr_assert(stores_equal(&a.particles, &b.particles));
    cr_assert_float_eq(a.time, 1.2, 1e-12);
    isk_system_free(&a);
    isk_system_free(&b);
}

Test(sim_system, ageing_culls_in_order)
{
    isk_system s;
    isk_system_init(&s, 1, 0);
    s.ageing = 1;
    for (int i = 0; i < 6; i++) {
        isk_particles_add(&s.particles, i, 0, 0, 0, 1, NULL);
        s.particles.life[i] = (i % 2) ? 0.5 : 10;
    }
    for (int i = 0; i < 3; i++)
        isk_system_step(&s, 0.25);
    cr_assert_eq(s.particles.count, 3);
    cr_assert(s.particles.x[0] == 0 && s.particles.x[1] == 2 && s.particles.x[2] == 4);
    cr_assert_float_eq(s.particles.age[0], 0.75, 1e-15);
    isk_system_free(&s);
}

Test(sim_system, sound_potential_without_min_never_nan)
{
    isk_system s;
    isk_system_init(&s, 1, 0);
    isk_potential p;
    isk_potential_init(&p, 150, isk_vec2_make(5, 1.8), 1);
    isk_potential_set_law(&p, ISK_COULOMB_LAW_CODE, 3);
    p.x_mult = 0;
    isk_system_add_potential(&s, &p, NULL);
    isk_bounds b;
    isk_bounds_reflect(&b, 0, 10, 0, 10, ISK_SIDE_ALL, 0, 0.5);
    isk_system_set_bounds(&s, &b, 1);
    isk_particles_add(&s.particles, 5, 1.8, 0, 0, 1, NULL); /* exactly on it */
    isk_particles_add(&s.particles, 5, 1.8 + 1e-9, 0, 0, 1, NULL);
    for (int m = 0; m < ISK_INTEGRATOR_COUNT; m++) {
        isk_system_set_integrator(&s, (isk_integrator)m);
        for (int i = 0; i < 1000; i++)
            isk_system_step(&s, 1.0 / 60);
        for (size_t i = 0; i < s.particles.count; i++)
            cr_assert(!isnan(s.particles.x[i]) && !isnan(s.particles.y[i]) && !isnan(s.particles.vx[i]) &&
                          !isnan(s.particles.vy[i]),
                      "%s", isk_integrator_name((isk_integrator)m));
    }
    cr_assert_eq(s.particles.vx[0], 0.0);
    isk_system_free(&s);
}

Test(sim_system, validation)
{
    isk_system s;
    isk_system_init(&s, 1, 0);
    cr_assert_eq(isk_system_step(&s, NAN), ISK_ERR_NAN);
    cr_assert_eq(isk_system_step(&s, -1), ISK_ERR_RANGE);
    cr_assert_eq(isk_system_set_substeps(&s, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_system_set_drag(&s, -1), ISK_ERR_RANGE);
    cr_assert_eq(isk_system_set_gravity(&s, INFINITY), ISK_ERR_NAN);
    cr_assert_eq(isk_system_set_integrator(&s, ISK_INTEGRATOR_COUNT), ISK_ERR_RANGE);
    cr_assert_eq(isk_system_explode(&s, ISK_EXPLOSION_COUNT, 0, 0, 10), ISK_ERR_RANGE);
    cr_assert_eq(isk_system_explode(&s, ISK_EXPLOSION_RING, 0, 0, 10001), ISK_ERR_RANGE);
    s.explode_limit = 20000;
    cr_assert_eq(isk_system_explode(&s, ISK_EXPLOSION_RING, 0, 0, 10001), ISK_OK);
    cr_assert_eq(isk_system_step(NULL, 0.1), ISK_ERR_NULL);
    isk_system_free(&s);
}
