/* SPDX-License-Identifier: MIT */
/* The thesis's single-particle figures through the teaching API, checked
 * against the catalogue (§5.4–5.8), and the same runs through a one-particle
 * system (same kernels: identical bits). */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "iskra/system.h"
#include "iskra/teach.h"

typedef struct run_result {
    int bounces;     /* steps on which the floor check fired */
    int first_bounce; /* 1-based step of the first one */
    isk_particle c;
} run_result;

/* Figures 10–13: mass 1, r0 (-4,-4), v0 (1,-2), dt 0.25, 1000 steps;
 * force -> pomakni -> (draw) -> zarobi(bottom only) at ymin = -10. */
static run_result thesis_run(double g, double o)
{
    run_result res = {0, 0, {0}};
    isk_particle_init(&res.c, 1, isk_vec2_make(-4, -4), isk_vec2_make(1, -2));
    for (int i = 1; i <= 1000; i++) {
        isk_vec2 F = isk_vec2_make(0, 0);
        if (g != 0 && o != 0)
            F = isk_vec2_add(isk_gravity_force(&res.c.mp, g), isk_drag_force(&res.c.mp, o));
        else if (g != 0)
            F = isk_gravity_force(&res.c.mp, g);
        else if (o != 0)
            F = isk_drag_force(&res.c.mp, o);
        isk_mp_move(&res.c.mp, 0.25, F);
        if (res.c.mp.r.y < -10 + res.c.diameter) {
            res.bounces++;
            if (!res.first_bounce)
                res.first_bounce = i;
        }
        isk_particle_zarobi_box(&res.c, -10, 10, -10, 10, 0, 0, 1, 0);
    }
    return res;
}

Test(sim_thesis, fig10_one_bounce_at_step_12)
{
    run_result r = thesis_run(0, 0);
    cr_assert_eq(r.bounces, 1);
    cr_assert_eq(r.first_bounce, 12);
    cr_assert_eq(r.c.mp.v.y, 2.0);
    cr_assert_eq(r.c.mp.v.x, 1.0);
}

Test(sim_thesis, fig11_drag_comes_to_rest)
{
    run_result r = thesis_run(0, 0.1);
    cr_assert_eq(r.bounces, 1);
    cr_assert_float_eq(r.c.mp.r.x, 5.75, 1e-3);
    cr_assert_float_eq(r.c.mp.r.y, 3.4384, 1e-4);
}

Test(sim_thesis, fig12_gravity_twelve_bounces)
{
    run_result r = thesis_run(0.25, 0);
    cr_assert_eq(r.bounces, 12);
}

Test(sim_thesis, fig13_drag_and_gravity_788_bounces)
{
    run_result r = thesis_run(0.25, 0.1);
    cr_assert_eq(r.bounces, 788);
    /* ends in the 2-cycle jitter on the floor, |vy| ~ 0.03165 */
    cr_assert_float_eq(fabs(r.c.mp.v.y), 0.03165, 1e-4);
}

/* Fig 13 through a one-particle system, examples' order: step (no bounce
 * inside), draw, isk_system_bounce.  Bit-identical to the teaching loop. */
Test(sim_thesis, fig13_system_equals_teaching_api)
{
    isk_system s;
    isk_system_init(&s, 0, 1);
    isk_system_set_gravity(&s, 0.25);
    isk_system_set_drag(&s, 0.1);
    isk_bounds b;
    isk_bounds_thesis(&b, -10, 10, -10, 10, ISK_SIDE_BOTTOM);
    isk_system_set_bounds(&s, &b, 0);
    isk_particles_add(&s.particles, -4, -4, 1, -2, 1, NULL);
    isk_particle c;
    isk_particle_init(&c, 1, isk_vec2_make(-4, -4), isk_vec2_make(1, -2));
    for (int i = 0; i < 1000; i++) {
        isk_vec2 F = isk_vec2_add(isk_gravity_force(&c.mp, 0.25), isk_drag_force(&c.mp, 0.1));
        isk_mp_move(&c.mp, 0.25, F);
        isk_system_step(&s, 0.25);
        /* the drawn (pre-bounce) position agrees too */
        cr_assert(memcmp(&c.mp.r.y, &s.particles.y[0], 8) == 0, "step %d", i);
        isk_particle_zarobi_box(&c, -10, 10, -10, 10, 0, 0, 1, 0);
        isk_system_bounce(&s);
        cr_assert(memcmp(&c.mp.r, (double[2]){s.particles.x[0], s.particles.y[0]}, 16) == 0);
        cr_assert(memcmp(&c.mp.v, (double[2]){s.particles.vx[0], s.particles.vy[0]}, 16) == 0);
    }
    isk_system_free(&s);
}

Test(sim_thesis, fig9_particle_draws_at_pixel_180_420)
{
    isk_canvas cv;
    cr_assert_eq(isk_canvas_init(&cv, 600, 600), ISK_OK);
    isk_view v;
    cr_assert_eq(isk_view_window(&v, 600, 600, -10, 10, -10, 10), ISK_OK);
    isk_particle c;
    isk_particle_init(&c, 1, isk_vec2_make(-4, -4), isk_vec2_make(0, 0));
    isk_particle_draw(&c, &cv, &v);
    isk_color px = isk_canvas_get(&cv, 180, 420);
    cr_assert(px.r == 255 && px.g == 255 && px.b == 0 && px.a == 255);
    int lit = 0;
    for (int y = 0; y < 600; y++)
        for (int x = 0; x < 600; x++)
            lit += isk_canvas_get(&cv, x, y).a != 0;
    cr_assert_eq(lit, 1);
    /* zarobi through the view uses the same walls */
    isk_particle d;
    isk_particle_init(&d, 1, isk_vec2_make(0, -12), isk_vec2_make(0, -1));
    isk_particle_zarobi(&d, &v, 0, 0, 1, 0);
    cr_assert_eq(d.mp.r.y, -10 + 0.1);
    cr_assert_eq(d.mp.v.y, 1.0);
    isk_canvas_free(&cv);
}
