/* SPDX-License-Identifier: MIT */
/* Particle store: growth, O(1) removal, stable cull, iteration order, checks. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>
#include <stdint.h>

#include "iskra/particles.h"
#include "iskra/rng.h"

Test(sim_store, grows_from_empty_and_keeps_insertion_order)
{
    isk_particles p;
    cr_assert_eq(isk_particles_init(&p, 0, 0), ISK_OK);
    for (int i = 0; i < 5000; i++) {
        size_t idx = 99;
        cr_assert_eq(isk_particles_add(&p, i, -i, 2.0 * i, 0.5, 1.0 + i, &idx), ISK_OK);
        cr_assert_eq(idx, (size_t)i);
    }
    cr_assert_eq(p.count, 5000);
    cr_assert_geq(p.capacity, 5000);
    cr_assert_eq((uintptr_t)p.x % 64, 0);
    cr_assert_eq((uintptr_t)p.vy % 64, 0);
    for (int i = 0; i < 5000; i++) {
        cr_assert_eq(p.x[i], (double)i);
        cr_assert_eq(p.y[i], (double)-i);
        cr_assert_eq(p.vx[i], 2.0 * i);
        cr_assert_eq(p.m[i], 1.0 + i);
        cr_assert_eq(p.age[i], 0.0);
        cr_assert(isinf(p.life[i]));
    }
    cr_assert_null(p.color);
    cr_assert_null(p.size);
    isk_particles_free(&p);
}

Test(sim_store, optional_arrays_only_when_asked)
{
    isk_particles p;
    cr_assert_eq(isk_particles_init(&p, 3, ISK_PARTICLES_COLOR | ISK_PARTICLES_SIZE), ISK_OK);
    cr_assert_eq(isk_particles_add(&p, 0, 0, 0, 0, 1, NULL), ISK_OK);
    cr_assert_not_null(p.color);
    cr_assert_not_null(p.size);
    cr_assert_eq(p.size[0], 0.1);
    cr_assert_eq(p.color[0].r, 255);
    cr_assert_eq(p.color[0].g, 255);
    cr_assert_eq(p.color[0].b, 0);
    isk_particles_free(&p);
    cr_assert_eq(isk_particles_init(&p, 3, 1u << 11), ISK_ERR_SIZE); /* a bit no column takes */
    isk_particles_free(&p);
}

Test(sim_store, remove_is_swap_with_last)
{
    isk_particles p;
    isk_particles_init(&p, 0, 0);
    for (int i = 0; i < 5; i++)
        isk_particles_add(&p, i, 0, 0, 0, 1, NULL);
    isk_particles_remove(&p, 1); /* 0 4 2 3 */
    cr_assert_eq(p.count, 4);
    double want[] = {0, 4, 2, 3};
    for (int i = 0; i < 4; i++)
        cr_assert_eq(p.x[i], want[i]);
    isk_particles_remove(&p, 3); /* last: 0 4 2 */
    cr_assert_eq(p.count, 3);
    cr_assert_eq(p.x[2], 2.0);
    isk_particles_remove(&p, 17); /* out of range: no-op */
    cr_assert_eq(p.count, 3);
    isk_particles_free(&p);
}

Test(sim_store, cull_is_stable)
{
    isk_particles p;
    isk_particles_init(&p, 0, 0);
    for (int i = 0; i < 10; i++) {
        isk_particles_add(&p, i, 0, 0, 0, 1, NULL);
        p.life[i] = (i % 3 == 0) ? 1.0 : INFINITY;
    }
    isk_particles_age(&p, 0, p.count, 1.0);
    cr_assert_eq(isk_particles_cull(&p), 4); /* 0 3 6 9 die */
    double want[] = {1, 2, 4, 5, 7, 8};
    cr_assert_eq(p.count, 6);
    for (int i = 0; i < 6; i++)
        cr_assert_eq(p.x[i], want[i]);
    isk_particles_free(&p);
}

/* Every optional column travels with its particle through growth, swap
 * removal and the stable cull (one table of columns drives all three). */
Test(sim_store, every_column_moves_with_its_particle)
{
    isk_particles p;
    cr_assert_eq(isk_particles_init(&p, 0, ISK_PARTICLES_FLAGS), ISK_OK);
    for (int i = 0; i < 300; i++) { /* grows 64 -> 128 -> 256 -> 512 */
        cr_assert_eq(isk_particles_add(&p, i, -i, 2 * i, 3 * i, 1 + i, NULL), ISK_OK);
        cr_assert_eq(p.osc_amp[i], 0.0);
        p.size[i] = 0.5 * i;
        p.color[i] = isk_rgba((uint8_t)i, (uint8_t)(i >> 8), 7, 255);
        p.osc_amp[i] = 10.0 * i;
        p.osc_phase[i] = 11.0 * i;
        p.osc_omega[i] = 12.0 * i;
        p.osc_offset[i] = 13.0 * i;
        p.life[i] = i % 7 == 0 ? 0.5 : INFINITY;
    }
    isk_particles_remove(&p, 2); /* 299 takes slot 2 */
    isk_particles_age(&p, 0, p.count, 1.0);
    cr_assert_eq(isk_particles_cull(&p), 43); /* the multiples of 7 in 0..298 */
    for (size_t k = 0; k < p.count; k++) {
        double i = p.x[k];
        const int n = (int)i; /* 0..299: an int first, so the byte conversions are defined */
        cr_assert(fmod(i, 7) != 0, "%g survived", i);
        cr_assert(p.y[k] == -i && p.vx[k] == 2 * i && p.vy[k] == 3 * i && p.m[k] == 1 + i);
        cr_assert(p.size[k] == 0.5 * i && p.color[k].r == (uint8_t)n && p.color[k].g == (uint8_t)(n >> 8));
        cr_assert(p.osc_amp[k] == 10 * i && p.osc_phase[k] == 11 * i && p.osc_omega[k] == 12 * i &&
                  p.osc_offset[k] == 13 * i);
        cr_assert(p.age[k] == 1.0 && isinf(p.life[k]));
        if (k > 2)
            cr_assert_gt(p.x[k], p.x[k - 1], "order kept");
    }
    cr_assert_eq(p.x[1], 299); /* slot 0 (x = 0) died, so 299 moved up to slot 1 */
    isk_particles_free(&p);
}

/* The unordered cull keeps exactly the particles the stable cull keeps,
 * each whole (every column), moves at most as many as died, and keeps NaN
 * ages as live; random patterns of deaths, including none and all. */
Test(sim_store, unordered_cull_keeps_the_same_particles_moving_few)
{
    isk_rng r;
    isk_rng_seed(&r, 3);
    for (int trial = 0; trial < 400; trial++) {
        isk_particles a, b;
        cr_assert_eq(isk_particles_init(&a, 0, ISK_PARTICLES_FLAGS), ISK_OK);
        cr_assert_eq(isk_particles_init(&b, 0, ISK_PARTICLES_FLAGS), ISK_OK);
        const int n = (int)isk_rng_below(&r, 200);
        const uint32_t odds = isk_rng_below(&r, 5); /* 0: nobody dies, 4: everybody */
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < 2; k++) {
                isk_particles *p = k ? &b : &a;
                cr_assert_eq(isk_particles_add(p, i, -i, 2 * i, 3 * i, 1 + i, NULL), ISK_OK);
                p->size[i] = 0.5 * i;
                p->color[i] = isk_rgba((uint8_t)i, 1, 2, 3);
                p->osc_amp[i] = 10.0 * i;
                p->osc_offset[i] = 13.0 * i;
            }
            const uint32_t u = isk_rng_below(&r, 4);
            const double life = u < odds ? 0.5 : i % 11 == 0 ? NAN : INFINITY;
            a.life[i] = b.life[i] = life;
        }
        isk_particles_age(&a, 0, a.count, 1.0);
        isk_particles_age(&b, 0, b.count, 1.0);
        size_t dead = isk_particles_cull(&a);
        /* count the moves: a slot below the new count whose particle changed */
        size_t removed = isk_particles_cull_unordered(&b);
        cr_assert_eq(removed, dead);
        cr_assert_eq(b.count, a.count);
        size_t moved = 0;
        char *seen = calloc((size_t)n + 1, 1);
        for (size_t k = 0; k < b.count; k++) {
            const double i = b.x[k];
            const int m = (int)i;
            moved += i != (double)k;
            cr_assert(b.y[k] == -i && b.vx[k] == 2 * i && b.vy[k] == 3 * i && b.m[k] == 1 + i);
            cr_assert(b.size[k] == 0.5 * i && b.color[k].r == (uint8_t)m && b.osc_amp[k] == 10 * i &&
                      b.osc_offset[k] == 13 * i);
            seen[m] = 1;
        }
        for (size_t k = 0; k < a.count; k++)
            cr_assert(seen[(int)a.x[k]], "particle %g kept by the stable cull only", a.x[k]);
        cr_assert_leq(moved, dead, "%zu moved for %zu dead", moved, dead);
        free(seen);
        isk_particles_free(&a);
        isk_particles_free(&b);
    }
    cr_assert_eq(isk_particles_cull_unordered(NULL), 0u);
}

Test(sim_store, validates_inputs_without_partial_state)
{
    isk_particles p;
    cr_assert_eq(isk_particles_init(NULL, 0, 0), ISK_ERR_NULL);
    cr_assert_eq(isk_particles_init(&p, ISK_PARTICLES_MAX + 1, 0), ISK_ERR_SIZE);
    isk_particles_free(&p);
    isk_particles_init(&p, 0, 0);
    cr_assert_eq(isk_particles_add(&p, NAN, 0, 0, 0, 1, NULL), ISK_ERR_NAN);
    cr_assert_eq(isk_particles_add(&p, 0, 0, INFINITY, 0, 1, NULL), ISK_ERR_NAN);
    cr_assert_eq(isk_particles_add(&p, 0, 0, 0, 0, 0.0, NULL), ISK_ERR_RANGE);
    cr_assert_eq(isk_particles_add(&p, 0, 0, 0, 0, -1.0, NULL), ISK_ERR_RANGE);
    cr_assert_eq(isk_particles_add(NULL, 0, 0, 0, 0, 1, NULL), ISK_ERR_NULL);
    cr_assert_eq(p.count, 0);
    cr_assert_eq(isk_particles_reserve(&p, ISK_PARTICLES_MAX + 1), ISK_ERR_SIZE);
    isk_particles_free(&p);
}
