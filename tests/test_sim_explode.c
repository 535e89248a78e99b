/* SPDX-License-Identifier: MIT */
/* Emitters: counts, validation, the thesis's formulas and draw order, and
 * the multi-Coulomb batch plan and schedule. */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "iskra/explode.h"
#include "iskra/system.h"

#define PI 3.141592653589793

Test(sim_explode, counts_and_validation)
{
    isk_particles p;
    isk_rng r;
    isk_rng_seed(&r, 1);
    isk_particles_init(&p, 0, 0);
    cr_assert_eq(isk_explode_gauss(&p, &r, 0, -3, 0, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_explode_gauss(&p, &r, 0, -3, 10001, ISK_EXPLODE_THESIS_LIMIT), ISK_ERR_RANGE);
    cr_assert_eq(isk_explode_ring(&p, NAN, -3, 10, 0), ISK_ERR_NAN);
    cr_assert_eq(isk_explode_uniform(&p, &r, 0, INFINITY, 10, 0), ISK_ERR_NAN);
    cr_assert_eq(isk_explode_coulomb(&p, NULL, 0, 0, 10, 0, ISK_KICK_NEW), ISK_ERR_NULL);
    cr_assert_eq(isk_explode_coulomb(&p, &r, 0, 0, 10, 0, (isk_kick_target)9), ISK_ERR_RANGE);
    cr_assert_eq(isk_explode_layer(&p, &r, 5, 0, 0, 1, 10, 0), ISK_ERR_RANGE);
    cr_assert_eq(p.count, 0); /* nothing added on error */
    cr_assert_eq(isk_explode_gauss(&p, &r, 0, -3, 10000, 0), ISK_OK);
    cr_assert_eq(p.count, 10000);
    cr_assert_eq(isk_explode_uniform(&p, &r, 0, -3, 25000, 30000), ISK_OK); /* asked for */
    cr_assert_eq(p.count, 35000);
    isk_particles_free(&p);
}

Test(sim_explode, ring_first_particle_at_45_degrees)
{
    isk_particles p;
    isk_particles_init(&p, 0, 0);
    cr_assert_eq(isk_explode_ring(&p, 0, -3, 1000, 0), ISK_OK);
    cr_assert_eq(p.count, 1000);
    cr_assert_eq(p.vx[0], 4.0); /* (0 + 4*cos 0) + 4*(-sin 0) */
    cr_assert_eq(p.vy[0], 4.0);
    for (size_t i = 0; i < p.count; i++) {
        double sp = hypot(p.vx[i], p.vy[i]);
        cr_assert_float_eq(sp, 4 * sqrt(2.0), 1e-13);
        double ang = atan2(p.vy[i], p.vx[i]) * 180 / PI;
        double want = remainder(45.0 + i * 0.36, 360.0);
        cr_assert(fabs(remainder(ang - want, 360.0)) < 1e-9, "i %zu: %g vs %g", i, ang, want);
        cr_assert_eq(p.m[i], 2.0);
        cr_assert_eq(p.x[i], 0.0);
        cr_assert_eq(p.y[i], -3.0);
    }
    /* The thesis's arithmetic: deg = (i*360)/n, rad = deg*(pi/180),
     * x' = (0 + 4cos) + 4(-sin), y' = (0 + 4sin) + 4cos. */
    double deg = (7.0 * 360.0) / 1000.0, rad = deg * (PI / 180.0);
    double vx = (0.0 + 4.0 * cos(rad)) + 4.0 * (-sin(rad));
    double vy = (0.0 + 4.0 * sin(rad)) + 4.0 * cos(rad);
    cr_assert(p.vx[7] == vx && p.vy[7] == vy);
    isk_particles_free(&p);
}

/* Per-particle draw order: replay the generator by hand. */
Test(sim_explode, draw_order_is_the_thesis_order)
{
    isk_particles p;
    isk_particles_init(&p, 0, 0);
    isk_rng r, c;
    isk_rng_seed(&r, 99);
    c = r;
    isk_explode_gauss(&p, &r, 1, 2, 3, 0);
    for (int i = 0; i < 3; i++) {
        double z1, z2;
        isk_rng_normal2(&c, &z1, &z2);
        double m = 2.0 + isk_rng_uniform(&c);
        cr_assert(p.vx[i] == z1 * 3.0 && p.vy[i] == z2 * 3.0 && p.m[i] == m);
    }
    isk_explode_uniform(&p, &r, 1, 2, 2, 0);
    for (int i = 3; i < 5; i++) {
        double ux = isk_rng_uniform(&c), uy = isk_rng_uniform(&c);
        cr_assert(p.vx[i] == ux * 20.0 - 10.0 && p.vy[i] == uy * 20.0 - 10.0 && p.m[i] == 2.0);
    }
    isk_explode_layer(&p, &r, 0, 10, 0, 2, 2, 0);
    for (int i = 5; i < 7; i++) {
        double ux = isk_rng_uniform(&c), uy = isk_rng_uniform(&c);
        cr_assert(p.x[i] == ux * 10.0 + 0.0 && p.y[i] == uy * 2.0 + 0.0);
        cr_assert(p.m[i] == 1.0 && p.vx[i] == 0.0 && p.vy[i] == 0.0);
    }
    isk_explode_coulomb(&p, &r, 1, 2, 1, 0, ISK_KICK_NEW);
    double z1, z2;
    isk_rng_normal2(&c, &z1, &z2);
    double m = 2.0 + isk_rng_uniform(&c);
    cr_assert_eq(p.m[7], m);
    /* Before the kick the particle sat at (z1/50 + 1, z2/50 + 2); the kick
     * moved it by 0.01*v. */
    cr_assert_float_eq(p.x[7] - 0.01 * p.vx[7], z1 / 50.0 + 1.0, 1e-15);
    cr_assert_eq(memcmp(&r, &c, sizeof r), 0); /* nothing else drawn */
    isk_particles_free(&p);
}

Test(sim_explode, uniform_and_gauss_statistics)
{
    isk_particles p;
    isk_rng r;
    isk_rng_seed(&r, 5);
    isk_particles_init(&p, 0, 0);
    isk_explode_uniform(&p, &r, 0, -3, 10000, 0);
    for (size_t i = 0; i < p.count; i++)
        cr_assert(p.vx[i] >= -10 && p.vx[i] < 10 && p.vy[i] >= -10 && p.vy[i] < 10);
    isk_particles_clear(&p);
    isk_explode_gauss(&p, &r, 0, -3, 10000, 0);
    double s2 = 0, mmin = 9, mmax = 0;
    for (size_t i = 0; i < p.count; i++) {
        s2 += p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i];
        mmin = fmin(mmin, p.m[i]);
        mmax = fmax(mmax, p.m[i]);
    }
    cr_assert_float_eq(sqrt(s2 / 20000), 3.0, 0.1);
    cr_assert(mmin >= 2 && mmax < 3);
    isk_particles_free(&p);
}

Test(sim_explode, coulomb_kick_values_and_targets)
{
    isk_particles p;
    isk_rng r;
    isk_rng_seed(&r, 8);
    isk_particles_init(&p, 0, 0);
    /* A mass-1 bystander 0.1 from the centre: dv = 1.5/(m d) = 15 away. */
    isk_particles_add(&p, 5.1, 5, 0, 0, 1, NULL);
    isk_explode_coulomb(&p, &r, 5, 5, 1000, 0, ISK_KICK_ALL);
    cr_assert_float_eq(p.vx[0], 15.0, 1e-12);
    cr_assert_eq(p.vy[0], 0.0);
    cr_assert_float_eq(p.x[0], 5.1 + 0.15, 1e-12);
    for (size_t i = 1; i < p.count; i++) /* max speed 25/m at d = 0.06 */
        cr_assert_leq(hypot(p.vx[i], p.vy[i]), 25.0 / p.m[i] * (1 + 1e-12));
    isk_particles_clear(&p);
    isk_particles_add(&p, 5.1, 5, 0, 0, 1, NULL);
    isk_explode_coulomb(&p, &r, 5, 5, 10, 0, ISK_KICK_NEW);
    cr_assert_eq(p.vx[0], 0.0);
    cr_assert_eq(p.x[0], 5.1);
    isk_particles_free(&p);
}

Test(sim_explode, multi_coulomb_batch_plan)
{
    size_t s, b, last;
    isk_multi_coulomb_plan(1000, &s, &b, &last);
    cr_assert(s == 60 && b == 17 && last == 40);
    isk_multi_coulomb_plan(10000, &s, &b, &last);
    cr_assert(s == 600 && b == 17 && last == 400);
    for (size_t n = 1; n <= 16; n++) {
        isk_multi_coulomb_plan(n, &s, &b, &last);
        cr_assert(s == 1 && b == n && last == 1, "n %zu", n);
    }
    isk_multi_coulomb_plan(120, &s, &b, &last); /* s = 7, 17*7 = 119, rest 1 */
    cr_assert(s == 7 && b == 18 && last == 1);
    isk_multi_coulomb_plan(50, &s, &b, &last); /* s = 3 (3.0000000000000004 floors to 3) */
    cr_assert(s == 3 && b == 17 && last == 2);
    for (size_t n = 1; n <= 3000; n += 7) { /* sizes always add up */
        isk_multi_coulomb_plan(n, &s, &b, &last);
        cr_assert_eq((b - 1) * s + last, n);
    }
    cr_assert_float_eq(isk_multi_coulomb_k(1), 40.0, 1e-13);
    cr_assert_float_eq(isk_multi_coulomb_k(17), 80 * (log(17.0) + 0.5), 1e-13);
    cr_assert_float_eq(isk_multi_coulomb_k(17), 266.66, 0.01);
}

Test(sim_explode, multi_coulomb_release_schedule)
{
    cr_assert_eq(isk_multi_coulomb_release_time(1), 0.0);
    cr_assert_float_eq(isk_multi_coulomb_release_time(2), 0.010, 1e-15);
    cr_assert_float_eq(isk_multi_coulomb_release_time(3), 0.015, 1e-15);
    cr_assert_float_eq(isk_multi_coulomb_release_time(4), 0.010 * (1 + 0.5 + 1.0 / 3), 1e-15);

    /* In a system at 60 frames/s: batch 1 at the click, 2 and 3 before
     * frame 2 (t = 16.7 ms), 4..16 before frame 3 (T16 = 33.2 ms < 33.3 ms), 17
     * (33.8 ms) before frame 4. */
    isk_system s;
    isk_system_init(&s, 1, 0);
    cr_assert_eq(isk_system_explode(&s, ISK_EXPLOSION_MULTI_COULOMB, 5, 5, 1000), ISK_OK);
    cr_assert_eq(s.particles.count, 60);
    size_t want[4] = {60, 180, 960, 1000};
    for (int f = 0; f < 4; f++) {
        cr_assert_eq(isk_system_step(&s, 1.0 / 60), ISK_OK);
        cr_assert_eq(s.particles.count, want[f], "frame %d: %zu", f, s.particles.count);
    }
    cr_assert_eq(s.njobs, 0);
    isk_system_free(&s);
}

/* Only the new batch is kicked, with k_i. */
Test(sim_explode, multi_coulomb_kicks_only_the_new_batch)
{
    isk_particles p;
    isk_rng r;
    isk_rng_seed(&r, 4);
    isk_particles_init(&p, 0, 0);
    isk_multi_coulomb mc;
    cr_assert_eq(isk_multi_coulomb_start(&mc, 0, 0, 100, 0), ISK_OK);
    size_t got;
    isk_multi_coulomb_release(&mc, &p, &r, &got);
    cr_assert_eq(got, 6);
    double vx0 = p.vx[0];
    isk_multi_coulomb_advance(&mc, 0.0125); /* batch 2 is due at 0.010 */
    isk_multi_coulomb_release(&mc, &p, &r, &got);
    cr_assert_eq(got, 6);
    cr_assert_eq(p.vx[0], vx0);
    cr_assert_eq(isk_multi_coulomb_start(&mc, 0, 0, 0, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_multi_coulomb_start(&mc, NAN, 0, 10, 0), ISK_ERR_NAN);
    isk_particles_free(&p);
}
