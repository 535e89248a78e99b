/* SPDX-License-Identifier: MIT */
/* Walls and deflectors in one contact pass (iskra/contacts.h): a fast
 * particle meets them in the order of its path, never ends a step outside a
 * closed box of walls, and a bounce keeps the energy a potential gives to
 * the integrator's own order. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>

#include "iskra.h"

static isk_effect *scene(const char *text)
{
    isk_effect_def d;
    isk_error err;
    isk_effect *fx = NULL;
    cr_assert_eq(isk_scene_load_string(&d, text, "test", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_def_free(&d);
    return fx;
}

static size_t outside_box(const isk_particles *p, double lo, double hi)
{
    size_t n = 0;
    for (size_t i = 0; i < p->count; i++)
        n += !(p->x[i] >= lo && p->x[i] <= hi && p->y[i] >= lo && p->y[i] <= hi);
    return n;
}

/* Reflect walls around [-10, 10]^2 with deflectors inside, 1,200 particles
 * thrown every way at 300 units/s from the centre: each step crosses a
 * third of the box, so a particle that a deflector turns back towards a
 * wall it has already passed in the same step (walls first, then the
 * deflectors, as it was) left the box for good.  None may, at any step. */
static void box_with(const char *deflectors, const char *names, const char *dt, const char *integrator, int frames)
{
    char text[3000];
    snprintf(text, sizeof text,
             "[scene]\ndt = %s\nintegrator = %s\nseed = 3\n[view]\nxmin = -10\nxmax = 10\nymin = -10\nymax = 10\n"
             "[bounds]\nmode = reflect\nrestitution = 1\n%s"
             "[emitter fast]\nsource = stream\nposition = 0.3, 0.2\ncount = 1200\nlaunch = cone\nspread = 360\n"
             "speed_min = 300\nspeed_max = 300\nbounded = true\ndeflectors = %s\ndraw = none\n",
             dt, integrator, deflectors, names);
    isk_effect *fx = scene(text);
    const isk_particles *p = isk_effect_particles(fx, 0);
    size_t worst = 0;
    for (int f = 0; f < frames; f++) {
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        size_t out = outside_box(p, -10, 10);
        worst = out > worst ? out : worst;
    }
    /* Restitution 1 everywhere and no force: every bounce keeps the speed,
     * so a particle put back by the last safety net instead of bounced
     * (or stopped by the cap of contacts) would show here. */
    double worst_speed = 0;
    for (size_t i = 0; i < p->count; i++) {
        const double v = hypot(p->vx[i], p->vy[i]);
        worst_speed = fabs(v / 300 - 1) > worst_speed ? fabs(v / 300 - 1) : worst_speed;
    }
    cr_log_info("dt %s, %s: %zu particles, at most %zu outside, speed within %.3g", dt, integrator, p->count, worst,
                worst_speed);
    cr_assert(worst_speed < 1e-12, "dt %s, %s: a speed changed by %.3g", dt, integrator, worst_speed);
    cr_assert_eq(p->count, 1200);
    cr_assert_eq(worst, 0, "dt %s, %s: %zu of 1200 particles outside the walls", dt, integrator, worst);
    isk_effect_destroy(fx);
}

Test(contacts, a_slanted_deflector_in_a_walled_box_lets_no_particle_out, .timeout = 120)
{
    static const char *const dts[] = {"1/60", "1/30", "1/240"};
    for (int k = 0; k < 3; k++)
        box_with("[deflector slant]\nsegment = -6, -4, 5, 7\n", "slant", dts[k], "verlet", 300);
    box_with("[deflector slant]\nsegment = -6, -4, 5, 7\n", "slant", "1/60", "semi-euler", 300);
}

/* A chain of segments meeting at corners (a V open towards a wall, and a
 * segment ending on the wall itself): paths that hit a segment, a wall and
 * the next segment within one step stay in the box. */
Test(contacts, a_chain_of_deflectors_against_the_walls_lets_no_particle_out, .timeout = 120)
{
    box_with("[deflector a]\nsegment = -8, 8, 0, 0\n[deflector b]\nsegment = 0, 0, 8, 8\n"
             "[deflector c]\nsegment = 10, -3, 2, -9\n",
             "a, b, c", "1/60", "rk4", 300);
}

/* The header's example (iskra/contacts.h): off the right wall, then the
 * slant, then down, in one step; thesis walls are refused. */
Test(contacts, the_header_example_meets_the_wall_then_the_slant)
{
    isk_bounds box;
    cr_assert_eq(isk_bounds_reflect(&box, -10, 10, -10, 10, ISK_SIDE_ALL, 0.0, 1.0), ISK_OK);
    isk_deflector slant = isk_deflector_segment(-6, -4, 5, 7);
    double x0[1] = {9}, y0[1] = {6}, vx0[1] = {600}, vy0[1] = {0}, h = 1.0 / 60;
    double x[1] = {9 + 600 * h}, y[1] = {6}, vx[1] = {600}, vy[1] = {0};
    isk_step_motion mo = {x0, y0, vx0, vy0, NULL, 0.0, h, 0, 0, 0};
    isk_deflect_stats st = {0};
    cr_assert_eq(isk_contacts_step(&box, &slant, 1, x, y, vx, vy, &mo, 1, NULL, NULL, &st), ISK_OK);
    cr_assert(fabs(x[0] - 4) < 1e-9 && fabs(y[0] - 3) < 1e-9, "(%.17g, %.17g)", x[0], y[0]);
    cr_assert(fabs(vx[0]) < 1e-9 && fabs(vy[0] + 600) < 1e-9, "(%.17g, %.17g)", vx[0], vy[0]);
    cr_assert_eq(st.wall_bounces, 1);
    cr_assert_eq(st.bounces, 1);
    isk_bounds thesis;
    cr_assert_eq(isk_bounds_thesis(&thesis, -10, 10, -10, 10, ISK_SIDE_ALL), ISK_OK);
    double keep = x[0];
    cr_assert_eq(isk_contacts_step(&thesis, &slant, 1, x, y, vx, vy, &mo, 1, NULL, NULL, NULL), ISK_ERR_RANGE);
    cr_assert_eq(x[0], keep);
    cr_assert_eq(isk_contacts_step(&box, &slant, 1, x, y, vx, vy, NULL, 1, NULL, NULL, NULL), ISK_ERR_NULL);
}
