/* SPDX-License-Identifier: MIT */
/* Gravity, drag and the thesis's Coulomb potential against hand-computed
 * values; the store stages against the single-particle function. */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "iskra/forces.h"
#include "iskra/rng.h"
#include "iskra/teach.h"

static isk_potential pot_at(double k, double x, double y, double q)
{
    isk_potential p;
    isk_potential_init(&p, k, isk_vec2_make(x, y), q);
    return p;
}

Test(sim_forces, gravity_and_drag_are_the_thesis_formulas)
{
    isk_material_point mp = {3.0, {1, 2}, {4, -5}};
    isk_vec2 g = isk_gravity_force(&mp, 9.81);
    cr_assert_eq(g.x, 0.0);
    cr_assert_eq(g.y, 3.0 * -9.81);
    isk_vec2 d = isk_drag_force(&mp, 0.47);
    cr_assert_eq(d.x, -0.47 * 4);
    cr_assert_eq(d.y, -0.47 * -5);

    double m[2] = {3.0, 2.5}, vx[2] = {4, 1}, vy[2] = {-5, 2}, fx[2] = {0, 0}, fy[2] = {0, 0};
    isk_force_gravity(2, m, 9.81, fy);
    isk_force_drag(2, vx, vy, 0.47, fx, fy);
    cr_assert_eq(fx[0], 0.0 + d.x);
    cr_assert_eq(fy[0], g.y + d.y);
    cr_assert_eq(fy[1], 2.5 * -9.81 + -0.47 * 2);
}

Test(sim_forces, coulomb_outside_min_p2_attracts_with_1_over_d)
{
    /* k = 2, Q = +1 at the origin, particle at (3,4): d = 5,
     * F = n * kQ/d^2 = (-3,-4) * 2/25 = (-0.24, -0.32), |F| = 2/5. */
    isk_potential p = pot_at(2, 0, 0, 1);
    isk_vec2 F = isk_potential_force(&p, 3, 4, ISK_FIDELITY_THESIS);
    cr_assert_float_eq(F.x, -0.24, 1e-15);
    cr_assert_float_eq(F.y, -0.32, 1e-15);
    cr_assert_float_eq(isk_vec2_len(F), 0.4, 1e-15);
    /* Repulsion with Q = -1. */
    p = pot_at(2, 0, 0, -1);
    F = isk_potential_force(&p, 3, 4, ISK_FIDELITY_THESIS);
    cr_assert_float_eq(F.x, 0.24, 1e-15);
    cr_assert_float_eq(F.y, 0.32, 1e-15);
}

Test(sim_forces, coulomb_exponent_laws_code_and_text)
{
    isk_potential p = pot_at(2, 0, 0, 1);
    cr_assert_eq(isk_potential_set_law(&p, ISK_COULOMB_LAW_CODE, 3), ISK_OK);
    cr_assert_eq(p.P, 3.0);
    isk_vec2 F = isk_potential_force(&p, 3, 4, ISK_FIDELITY_SOUND);
    /* |F| = k|Q| d^(1-P) = 2/25 = 0.08 */
    cr_assert_float_eq(isk_vec2_len(F), 0.08, 1e-15);
    cr_assert_float_eq(F.x, -3 * 2.0 / 125, 1e-15);
    /* text's p = 1 is the code's P = 3: same force */
    isk_potential q = pot_at(2, 0, 0, 1);
    cr_assert_eq(isk_potential_set_law(&q, ISK_COULOMB_LAW_TEXT, 1), ISK_OK);
    cr_assert_eq(q.P, 3.0);
    isk_vec2 G = isk_potential_force(&q, 3, 4, ISK_FIDELITY_SOUND);
    cr_assert_eq(F.x, G.x);
    cr_assert_eq(F.y, G.y);
    /* P = 1: constant magnitude k|Q| */
    isk_potential_set_law(&q, ISK_COULOMB_LAW_CODE, 1);
    cr_assert_float_eq(isk_vec2_len(isk_potential_force(&q, 30, 40, ISK_FIDELITY_SOUND)), 2.0, 1e-14);
    cr_assert_eq(isk_potential_set_law(&q, ISK_COULOMB_LAW_TEXT, NAN), ISK_ERR_NAN);
    cr_assert_eq(isk_potential_set_law(&q, (isk_coulomb_law)7, 1), ISK_ERR_RANGE);
}

Test(sim_forces, coulomb_inside_min_clamps_only_the_denominator)
{
    isk_potential p = pot_at(2, 0, 0, 1);
    p.min_dist = 10; /* d = 5 < 10: F = n * 2/100 */
    isk_vec2 F = isk_potential_force(&p, 3, 4, ISK_FIDELITY_THESIS);
    cr_assert_float_eq(F.x, -0.06, 1e-15);
    cr_assert_float_eq(F.y, -0.08, 1e-15);
    /* min below d: no effect */
    p.min_dist = 4.9;
    F = isk_potential_force(&p, 3, 4, ISK_FIDELITY_THESIS);
    cr_assert_float_eq(F.x, -0.24, 1e-15);
}

Test(sim_forces, coulomb_max_distance_switches_off_for_good)
{
    isk_potential p = pot_at(2, 0, 0, 1);
    p.max_dist = 6;
    isk_vec2 F = isk_potential_force(&p, 30, 40, ISK_FIDELITY_THESIS); /* d = 50: on */
    cr_assert_neq(F.x, 0.0);
    cr_assert_eq(p.enabled, 1);
    F = isk_potential_force(&p, 3, 4, ISK_FIDELITY_THESIS); /* d = 5 < 6: trips */
    cr_assert_eq(F.x, 0.0);
    cr_assert_eq(F.y, 0.0);
    cr_assert_eq(p.enabled, 0);
    F = isk_potential_force(&p, 30, 40, ISK_FIDELITY_THESIS); /* stays off */
    cr_assert_eq(F.x, 0.0);
    cr_assert_eq(F.y, 0.0);
}

Test(sim_forces, coulomb_x_multiplier_scales_only_numerator_x)
{
    isk_potential p = pot_at(2, 0, 0, 1);
    p.x_mult = 0;
    isk_vec2 F = isk_potential_force(&p, 3, 4, ISK_FIDELITY_THESIS);
    cr_assert_eq(F.x, 0.0);
    cr_assert_float_eq(F.y, -0.32, 1e-15); /* d stays 5, not 4 */
    p.x_mult = 0.5;
    F = isk_potential_force(&p, 3, 4, ISK_FIDELITY_THESIS);
    cr_assert_float_eq(F.x, -0.12, 1e-15);
}

Test(sim_forces, particle_on_potential_centre)
{
    isk_potential p = pot_at(150, 1, 2, -1);
    p.min_dist = 0.06;
    isk_vec2 F = isk_potential_force(&p, 1, 2, ISK_FIDELITY_THESIS);
    cr_assert_eq(F.x, 0.0);
    cr_assert_eq(F.y, 0.0);
    F = isk_potential_force(&p, 1, 2, ISK_FIDELITY_SOUND);
    cr_assert_eq(F.x, 0.0);
    cr_assert_eq(F.y, 0.0);
    /* No min distance: the thesis code gives NaN, ours zero. */
    p.min_dist = ISK_DIST_OFF;
    F = isk_potential_force(&p, 1, 2, ISK_FIDELITY_THESIS);
    cr_assert(isnan(F.x) && isnan(F.y));
    F = isk_potential_force(&p, 1, 2, ISK_FIDELITY_SOUND);
    cr_assert_eq(F.x, 0.0);
    cr_assert_eq(F.y, 0.0);
    /* P = 3 and x_mult 0 (the fig-27 potential) too. */
    isk_potential_set_law(&p, ISK_COULOMB_LAW_CODE, 3);
    p.x_mult = 0;
    F = isk_potential_force(&p, 1, 2, ISK_FIDELITY_SOUND);
    cr_assert(!isnan(F.x) && !isnan(F.y));
    /* The store stage agrees. */
    double x = 1, y = 2, px = 0, py = 0;
    isk_force_potential(&p, 1, &x, &y, &px, &py, ISK_FIDELITY_SOUND);
    cr_assert(px == 0.0 && py == 0.0);
}

/* The store stage reproduces the single-particle function bit for bit,
 * including the potential-sum order and the mid-loop sticky switch. */
Test(sim_forces, store_stage_matches_single_particle_thesis_order)
{
    enum { N = 700 };
    static double x[N], y[N], vx[N], vy[N], m[N], fx[N], fy[N], px[N], py[N];
    isk_rng r;
    isk_rng_seed(&r, 7);
    for (int i = 0; i < N; i++) {
        x[i] = isk_rng_range(&r, 0, 10);
        y[i] = isk_rng_range(&r, 0, 10);
        vx[i] = isk_rng_range(&r, -5, 5);
        vy[i] = isk_rng_range(&r, -5, 5);
        m[i] = 2 + isk_rng_uniform(&r);
    }
    x[400] = 5.01; /* trips pot 1's max distance at index 400 */
    y[400] = 5.0;
    isk_potential a[3], b[3];
    a[0] = pot_at(800, 5, 5, 1);
    isk_potential_set_law(&a[0], ISK_COULOMB_LAW_CODE, 4);
    a[0].min_dist = 0.5;
    a[0].max_dist = 0.1;
    a[1] = pot_at(150, 2, 8, -1);
    a[2] = pot_at(2, 20, 45, -1);
    isk_potential_set_law(&a[2], ISK_COULOMB_LAW_CODE, 1);
    a[2].min_dist = 3;
    a[1].x_mult = 0.3;
    memcpy(b, a, sizeof a);
    isk_forces f = {.gravity = 9.81, .drag = 0.47, .pot = a, .npot = 3, .centre = ISK_FIDELITY_THESIS};
    isk_forces_eval(&f, N, x, y, vx, vy, m, fx, fy, px, py, 1);
    cr_assert_eq(a[0].enabled, 0);
    int differs_if_reassociated = 0;
    for (int i = 0; i < N; i++) {
        isk_material_point mp = {m[i], {x[i], y[i]}, {vx[i], vy[i]}};
        isk_vec2 P = {0, 0};
        isk_vec2 Pk[3];
        for (int k = 0; k < 3; k++) {
            Pk[k] = isk_potential_force_on(&b[k], &mp, ISK_FIDELITY_THESIS);
            P = isk_vec2_add(P, Pk[k]);
        }
        isk_vec2 F = isk_vec2_add(isk_vec2_add(isk_gravity_force(&mp, 9.81), isk_drag_force(&mp, 0.47)), P);
        cr_assert(memcmp(&F.x, &fx[i], 8) == 0 && memcmp(&F.y, &fy[i], 8) == 0, "particle %d", i);
        if (i < 400)
            cr_assert_neq(Pk[0].x, 0.0);
        else
            cr_assert(Pk[0].x == 0.0 && Pk[0].y == 0.0);
        /* The order matters: ((G + D) + P1) + P2 ... is not the same sum. */
        isk_vec2 alt = isk_vec2_add(isk_gravity_force(&mp, 9.81), isk_drag_force(&mp, 0.47));
        for (int k = 0; k < 3; k++)
            alt = isk_vec2_add(alt, Pk[k]);
        differs_if_reassociated += alt.x != F.x || alt.y != F.y;
    }
    cr_assert_gt(differs_if_reassociated, 0);
}

Test(sim_forces, zero_strength_stages_cost_nothing_and_change_nothing)
{
    double x[3] = {1, 2, 3}, y[3] = {0, 1, 0}, vx[3] = {1, -1, 0}, vy[3] = {0, 2, -3}, m[3] = {1, 2, 3};
    double fx[3], fy[3], px[3], py[3], gx[3], gy[3];
    isk_potential off[2] = {pot_at(0, 1, 1, 1), pot_at(5, 1, 1, 1)};
    off[1].enabled = 0;
    isk_forces with = {.gravity = 1.5, .drag = 0.2, .pot = off, .npot = 2};
    isk_forces without = {.gravity = 1.5, .drag = 0.2};
    isk_forces_eval(&with, 3, x, y, vx, vy, m, fx, fy, px, py, 1);
    isk_forces_eval(&without, 3, x, y, vx, vy, m, gx, gy, px, py, 1);
    cr_assert(memcmp(fx, gx, sizeof fx) == 0 && memcmp(fy, gy, sizeof fy) == 0);
}

Test(sim_forces, potential_motion_velocity_and_callback)
{
    isk_potential p = pot_at(150, 5, 1.8, 1);
    p.vel = isk_vec2_make(0, 20); /* the thesis's pomak(p) = (0, 20p) */
    isk_potential_move(&p, 1.0 / 60);
    cr_assert_eq(p.r.x, 5.0);
    cr_assert_eq(p.r.y, 1.8 + 20 * (1.0 / 60));
    cr_assert_eq(isk_potential_validate(&p), ISK_OK);
    p.k = NAN;
    cr_assert_eq(isk_potential_validate(&p), ISK_ERR_NAN);
}
