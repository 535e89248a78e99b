/* SPDX-License-Identifier: MIT */
/* Walls and deflectors in one contact pass (iskra/contacts.h): a fast
 * particle meets them in the order of its path, never ends a step outside a
 * closed box of walls, and a bounce keeps the energy a potential gives to
 * the integrator's own order. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra.h"
#include "scene_text.h"

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
    isk_effect *fx = scene_text_open(text, 0);
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
    cr_assert_eq(isk_contacts_step(&box, &slant, 1, x, y, vx, vy, &mo, NULL, 1, NULL, NULL, &st), ISK_OK);
    cr_assert(fabs(x[0] - 4) < 1e-9 && fabs(y[0] - 3) < 1e-9, "(%.17g, %.17g)", x[0], y[0]);
    cr_assert(fabs(vx[0]) < 1e-9 && fabs(vy[0] + 600) < 1e-9, "(%.17g, %.17g)", vx[0], vy[0]);
    cr_assert_eq(st.wall_bounces, 1);
    cr_assert_eq(st.bounces, 1);
    isk_bounds thesis;
    cr_assert_eq(isk_bounds_thesis(&thesis, -10, 10, -10, 10, ISK_SIDE_ALL), ISK_OK);
    double keep = x[0];
    cr_assert_eq(isk_contacts_step(&thesis, &slant, 1, x, y, vx, vy, &mo, NULL, 1, NULL, NULL, NULL), ISK_ERR_RANGE);
    cr_assert_eq(x[0], keep);
    cr_assert_eq(isk_contacts_step(&box, &slant, 1, x, y, vx, vy, NULL, NULL, 1, NULL, NULL, NULL), ISK_ERR_NULL);
}

/* ---- a spring on a floor ------------------------------------------------- */

/* A particle on a spring (P = 0: F = k (centre - r), k = 4, m = 1: omega =
 * 2) centred at the origin, released from rest at (0.6, 2), bouncing on a
 * restitution-1 floor at y = -1 (a wall, or a segment): it meets the floor
 * once a swing, with the force changing along the step.  Returns the relative change of the
 * energy per bounce, (E_end / E_0)^(1 / bounces) - 1, over `seconds`. */
static double spring_on_floor(const char *integrator, const char *dt, double seconds, int segment, int *bounces)
{
    char text[2000];
    snprintf(text, sizeof text,
             "[scene]\ndt = %s\nintegrator = %s\nseed = 1\n[view]\nxmin = -10\nxmax = 10\nymin = -1\nymax = 10\n"
             "[bounds]\nmode = reflect\nsides = bottom\nrestitution = 1\n"
             "[deflector floor]\nsegment = -10, -1, 10, -1\n"
             "[force spring]\nkind = potential\nk = 4\nposition = 0, 0\nexponent = 0\n"
             "[emitter ball]\nsource = particle\nposition = 0.6, 2\n%s\nforces = spring\ndraw = none\n",
             dt, integrator, segment ? "deflectors = floor" : "bounded = true");
    isk_effect *fx = scene_text_open(text, 0);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_eq(isk_effect_step(fx), ISK_OK); /* born in the first frame */
    cr_assert_eq(p->count, 1);
    const double h = strcmp(dt, "1/60") == 0 ? 1.0 / 60 : 1.0 / 240;
    double e0 = 0;
    int n = 0;
    double vy_before = p->vy[0];
    for (long f = 0; f * h < seconds; f++) {
        if (f == 0)
            e0 = 0.5 * (p->vx[0] * p->vx[0] + p->vy[0] * p->vy[0]) + 2.0 * (p->x[0] * p->x[0] + p->y[0] * p->y[0]);
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        n += vy_before < 0 && p->vy[0] > 0 && p->y[0] < -0.5; /* turned up near the floor */
        vy_before = p->vy[0];
    }
    const double e1 = 0.5 * (p->vx[0] * p->vx[0] + p->vy[0] * p->vy[0]) + 2.0 * (p->x[0] * p->x[0] + p->y[0] * p->y[0]);
    isk_effect_destroy(fx);
    *bounces = n;
    return pow(e1 / e0, 1.0 / n) - 1.0;
}

/* Through a scene (the effect runtime's contact pass), on a wall and on a
 * segment: the integrators of
 * order 2 and 4 whose positions lie on the flight keep the energy per
 * bounce within their own drift (the free spring's, below).  Before the
 * rest of a step after a bounce was flown by the integrator (a constant
 * acceleration fitted to the step's ends), every bounce gained 8.5e-4
 * (Verlet), 5.2e-4 (RK4), 5.4e-4 (Yoshida-4) at 1/60. */
Test(contacts, a_spring_on_a_floor_keeps_its_energy_per_bounce, .timeout = 120)
{
    static const char *const methods[] = {"verlet", "leapfrog", "strang", "rk4", "yoshida4"};
    for (int segment = 0; segment < 2; segment++)
        for (int m = 0; m < 5; m++)
            for (int k = 0; k < 2; k++) {
                int nb;
                const char *dt = k ? "1/240" : "1/60";
                const double d = spring_on_floor(methods[m], dt, 100, segment, &nb);
                const double bound = m < 3 ? (k ? 1e-6 : 1e-5) : (k ? 1e-11 : 1e-8);
                cr_log_info("%s, %-10s dt %-5s: %d bounces, energy per bounce %+.3e (bound %.0e)",
                            segment ? "segment" : "wall", methods[m], dt, nb, d, bound);
                cr_assert(nb >= 45, "%s: %d bounces", methods[m], nb);
                cr_assert(fabs(d) < bound, "%s, %s, dt %s: energy per bounce %+.3e", segment ? "segment" : "wall",
                          methods[m], dt, d);
            }
}

/* ---- a Coulomb gas in a walled box --------------------------------------- */

/* 300 particles in the box [-5, 5]^2 of restitution-1 walls around an
 * attracting Coulomb centre (P = 2, k Q = 20, min_distance 0.5: a spring
 * inside it), thrown out from near the centre: they fall back and forth
 * through the centre and bounce on the walls.  Returns the relative change
 * of the total energy over `frames`, and the wall bounces counted (a
 * normal velocity that turned from outward to inward within one step's
 * travel of a wall). */
static double gas_energy(const isk_particles *p)
{
    const double kq = -20, rmin = 0.5, umin = kq * log(rmin);
    double e = 0;
    for (size_t i = 0; i < p->count; i++) {
        const double d = hypot(p->x[i], p->y[i]);
        const double u = d >= rmin ? kq * log(d) : kq * (d * d - rmin * rmin) / (2 * rmin * rmin) + umin;
        e += p->m[i] * (0.5 * (p->vx[i] * p->vx[i] + p->vy[i] * p->vy[i]) + u);
    }
    return e;
}

static double coulomb_gas(const char *integrator, int frames, int walls, long *bounces)
{
    char text[2000];
    snprintf(text, sizeof text,
             "[scene]\ndt = 1/60\nintegrator = %s\nseed = 7\n[view]\nxmin = -5\nxmax = 5\nymin = -5\nymax = 5\n"
             "[bounds]\nmode = reflect\nrestitution = 1\n"
             "[force centre]\nkind = potential\nk = 20\ncharge = -1\nposition = 0, 0\nexponent = 2\nmin_distance = 0.5\n"
             "[emitter gas]\nsource = stream\nposition = 3, 3\ncount = 300\nlaunch = cone\nspread = 360\n"
             "speed_min = 2\nspeed_max = 6\nbounded = %s\nforces = centre\ndraw = none\n",
             integrator, walls ? "true" : "false");
    isk_effect *fx = scene_text_open(text, 0);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(p->count, 300);
    const double e0 = gas_energy(p);
    double vx[300], vy[300];
    long n = 0;
    for (int f = 0; f < frames; f++) {
        memcpy(vx, p->vx, sizeof vx);
        memcpy(vy, p->vy, sizeof vy);
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        for (size_t i = 0; i < p->count; i++) {
            const double reach = 20.0 / 60; /* faster than any particle's step */
            n += (vx[i] * p->vx[i] < 0 && fabs(p->x[i]) > 5 - reach) + (vy[i] * p->vy[i] < 0 && fabs(p->y[i]) > 5 - reach);
        }
    }
    if (walls)
        cr_assert_eq(outside_box(p, -5, 5), 0);
    const double e1 = gas_energy(p);
    isk_effect_destroy(fx);
    *bounces = n;
    return e1 / e0 - 1;
}

/* The gas stays away from the centre (it starts 4.2 from it at speeds of
 * at most 6, and reaching min_distance would take a speed of 9.1), so the
 * force is smooth along every path and the integrators' own drift is
 * small: what a bounce changes shows.  A bounce's contact is the
 * integrator's own state, so it adds about one step's local error: per
 * bounce at most 1e-8 of the energy for the second-order methods and
 * 1e-11 for RK4 and Yoshida-4 (measured 4e-10, 7e-10 and 2e-13).  Before
 * (the rest of a step after a bounce on a constant acceleration fitted to
 * the step's ends) every bounce lost 1.2e-7 (RK4, Yoshida-4) to 2.4e-7
 * (Verlet): 0.06 to 0.12 % of the energy in these 20 s. */
Test(contacts, a_coulomb_gas_in_a_walled_box_keeps_its_energy_per_bounce, .timeout = 120)
{
    static const char *const methods[] = {"verlet", "rk4", "yoshida4", "leapfrog", "strang"};
    for (int m = 0; m < 5; m++) {
        long nb, none;
        const double d = coulomb_gas(methods[m], 1200, 1, &nb), free = coulomb_gas(methods[m], 1200, 0, &none);
        const double bound = m == 1 || m == 2 ? 1e-11 : 1e-8;
        cr_log_info("%-9s: %ld wall bounces, energy %+.3e in all, %+.3e per bounce (bound %.0e); without walls %+.3e",
                    methods[m], nb, d, d / nb, bound, free);
        cr_assert(nb > 4000, "%s: %ld bounces", methods[m], nb);
        cr_assert(fabs(d / nb) < bound, "%s: energy %+.3e per bounce", methods[m], d / nb);
    }
}

/* The accuracy study's table (iskra/problems.h, docs/accuracy.md): what a
 * bounce itself changes is the energy per bounce with the floor less the
 * integrator's own drift over the same time without it (per as many
 * bounces).  To each integrator's order: at most 1e-6 (1/60) and 1e-8
 * (1/240) for the second-order methods whose positions lie on the flight,
 * 1e-10 and 1e-12 for the fourth-order ones (the contact is the
 * integrator's own state, so a bounce adds about one step's local error);
 * the Euler forms keep the fitted flight with their velocity offset and
 * the exact-drag update freezes the spring over the step: first order,
 * their own drift between bounces dominates (1e-3 and 1e-4 for
 * semi-implicit Euler, 2e-2 and 1e-2 for explicit Euler and exact drag). */
Test(contacts, the_spring_on_a_floor_table, .timeout = 120)
{
    static const double bound[ISK_INTEGRATOR_COUNT][2] = {
        [ISK_INTEGRATE_SEMI_EULER] = {1e-3, 1e-4}, [ISK_INTEGRATE_EULER] = {2e-2, 1e-2},
        [ISK_INTEGRATE_VERLET] = {1e-6, 1e-8},     [ISK_INTEGRATE_RK4] = {1e-10, 1e-12},
        [ISK_INTEGRATE_EXACT_DRAG] = {2e-2, 1e-2}, [ISK_INTEGRATE_LEAPFROG] = {1e-6, 1e-8},
        [ISK_INTEGRATE_YOSHIDA4] = {1e-10, 1e-12}, [ISK_INTEGRATE_STRANG] = {1e-6, 1e-8},
    };
    for (int m = 0; m < ISK_INTEGRATOR_COUNT; m++)
        for (int k = 0; k < 2; k++) {
            const double dt = k ? 1.0 / 240 : 1.0 / 60;
            isk_spring_floor with, without;
            cr_assert_eq(isk_problem_spring_floor(m, dt, 100, 1, &with), ISK_OK);
            cr_assert_eq(isk_problem_spring_floor(m, dt, 100, 0, &without), ISK_OK);
            cr_assert(with.bounces >= 45 && without.bounces == 0, "%d, %d bounces", with.bounces, without.bounces);
            const double per = pow(1 + with.change, 1.0 / with.bounces) - 1;
            const double own = pow(1 + without.change, 1.0 / with.bounces) - 1;
            cr_log_info("%-10s 1/%-3d: %d bounces, per bounce %+.3e, without the floor %+.3e", isk_integrator_names[m],
                        k ? 240 : 60, with.bounces, per, own);
            cr_assert(fabs(per - own) < bound[m][k], "%s, 1/%d: a bounce changes the energy by %+.3e",
                      isk_integrator_names[m], k ? 240 : 60, per - own);
        }
    isk_spring_floor out;
    cr_assert_eq(isk_problem_spring_floor(ISK_INTEGRATOR_COUNT, 0.01, 1, 1, &out), ISK_ERR_RANGE);
    cr_assert_eq(isk_problem_spring_floor(ISK_INTEGRATE_RK4, 0.0, 1, 1, &out), ISK_ERR_RANGE);
    cr_assert_eq(isk_problem_spring_floor(ISK_INTEGRATE_RK4, NAN, 1, 1, &out), ISK_ERR_NAN);
    cr_assert_eq(isk_problem_spring_floor(ISK_INTEGRATE_RK4, 0.01, 1, 1, NULL), ISK_ERR_NULL);
}

/* ---- semi-implicit Euler at a step of 1000 s ------------------------------ */

/* One live frame of dt = 1000 s in a closed box of restitution-1 walls
 * under gravity: semi-implicit Euler's energy, counted from its stored
 * velocities, grows about 4e5 times.  The walls are not the cause: the
 * Euler forms' stored velocity is the flight's shifted by offset * a * h
 * (iskra/integrate.h: -1/2 for semi-implicit Euler, +1/2 for explicit
 * Euler), so a velocity stored by a step of 1/60 is read by a step of
 * 1000 as a flight g h / 2 = 4905 units/s faster, in a box whose speeds
 * are about 14: that is the method's own first-order error at that step.
 * The walls keep that flight's energy exactly (every particle to 1e-12,
 * through hundreds of bounces): checked here, and documented in
 * docs/accuracy.md; a second-order method keeps the energy itself
 * (test_impact's frame of 1000 s). */
Test(contacts, semi_implicit_euler_at_1000_s_is_its_own_first_order_error, .timeout = 60)
{
    static const char *const methods[] = {"semi-euler", "euler"};
    static const double offsets[] = {-0.5, 0.5};
    for (int m = 0; m < 2; m++) {
        char text[2000];
        snprintf(text, sizeof text,
                 "[scene]\ndt = 1/60\nintegrator = %s\nseed = 5\n[view]\nxmin = -6\nxmax = 6\nymin = -1\nymax = 11\n"
                 "[force gravity]\ng = 9.81\n[bounds]\nmode = reflect\nwindow = -5, 5, 0, 10\nrestitution = 1\n"
                 "[emitter box]\nsource = explosion\nexplosion = gauss\nposition = 0, 5\ncount = 500\n"
                 "forces = gravity\ndraw = none\nbounded = true\n",
                 methods[m]);
        isk_effect *fx = scene_text_open(text, 0);
        const isk_particles *p = isk_effect_particles(fx, 0);
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        cr_assert_eq(p->count, 500);
        const double g = 9.81, h = 1000, delta = offsets[m] * -g * h; /* stored = flight + delta */
        static double flight[500];
        double stored0 = 0, stored1 = 0;
        for (size_t i = 0; i < p->count; i++) {
            const double u = p->vy[i] - delta;
            flight[i] = 0.5 * (p->vx[i] * p->vx[i] + u * u) + g * p->y[i];
            stored0 += 0.5 * (p->vx[i] * p->vx[i] + p->vy[i] * p->vy[i]) + g * p->y[i];
        }
        isk_error err;
        cr_assert_eq(isk_effect_set(fx, "scene", "dt", "1000", &err), ISK_OK, "%s", err.message);
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        double worst = 0;
        for (size_t i = 0; i < p->count; i++) {
            const double u = p->vy[i] - delta;
            const double e = 0.5 * (p->vx[i] * p->vx[i] + u * u) + g * p->y[i];
            worst = fmax(worst, fabs(e / flight[i] - 1));
            stored1 += 0.5 * (p->vx[i] * p->vx[i] + p->vy[i] * p->vy[i]) + g * p->y[i];
        }
        cr_log_info("%s: stored energy x%.3g, each flight's energy kept to %.2g", methods[m], stored1 / stored0, worst);
        for (size_t i = 0; i < p->count; i++)
            cr_assert(p->x[i] >= -5 && p->x[i] <= 5 && p->y[i] >= 0 && p->y[i] <= 10, "particle %zu outside", i);
        cr_assert(worst < 1e-12, "%s: a flight's energy changed by %.3g", methods[m], worst);
        cr_assert(stored1 / stored0 > 1e5, "%s: x%.3g", methods[m], stored1 / stored0);
        isk_effect_destroy(fx);
    }
}

/* ---- the same bytes on any number of threads ------------------------------ */

/* The contact pass runs block by block (walls with segments; walls with a
 * potential, flown by the integrator): 1, 2 and 3 threads give the same
 * state, bit for bit, over 4,000 particles (enough blocks to share). */
Test(contacts, the_contact_pass_gives_the_same_bytes_on_any_number_of_threads, .timeout = 120)
{
    static const char *const extras[] = {
        "[deflector slant]\nsegment = -6, -4, 5, 7\n",
        "[force centre]\nkind = potential\nk = 20\ncharge = -1\nposition = 0, 0\nexponent = 2\nmin_distance = 0.5\n",
    };
    static const char *const uses[] = {"deflectors = slant\n", "forces = centre\n"};
    for (int v = 0; v < 2; v++) {
        double *first = NULL;
        size_t n = 0;
        for (int threads = 1; threads <= 3; threads++) {
            char text[3000];
            snprintf(text, sizeof text,
                     "[scene]\ndt = 1/60\nintegrator = verlet\nseed = 3\n[view]\nxmin = -10\nxmax = 10\nymin = -10\n"
                     "ymax = 10\n[bounds]\nmode = reflect\nrestitution = 0.9\n%s"
                     "[emitter fast]\nsource = stream\nposition = 3, 2\ncount = 4000\nlaunch = cone\nspread = 360\n"
                     "speed_min = 20\nspeed_max = 300\nbounded = true\n%sdraw = none\n",
                     extras[v], uses[v]);
            isk_effect *fx = scene_text_open(text, 0);
            cr_assert_eq(isk_effect_set_threads(fx, threads), ISK_OK);
            for (int f = 0; f < 120; f++)
                cr_assert_eq(isk_effect_step(fx), ISK_OK);
            const isk_particles *p = isk_effect_particles(fx, 0);
            cr_assert_eq(p->count, 4000);
            if (!first) {
                n = p->count;
                first = malloc(4 * n * sizeof *first);
                cr_assert_not_null(first);
                memcpy(first, p->x, n * sizeof *first);
                memcpy(first + n, p->y, n * sizeof *first);
                memcpy(first + 2 * n, p->vx, n * sizeof *first);
                memcpy(first + 3 * n, p->vy, n * sizeof *first);
            } else {
                cr_assert(!memcmp(first, p->x, n * sizeof *first) && !memcmp(first + n, p->y, n * sizeof *first) &&
                              !memcmp(first + 2 * n, p->vx, n * sizeof *first) &&
                              !memcmp(first + 3 * n, p->vy, n * sizeof *first),
                          "%s: %d threads differ from 1", v ? "walls + potential" : "walls + segment", threads);
            }
            isk_effect_destroy(fx);
        }
        free(first);
    }
}

/* ---- hit events ------------------------------------------------------------ */

/* A sub-emitter on hit sees every contact of the pass: a particle that
 * bounces off the right wall and then off the slant in the same step (the
 * header's example) fires two events in that step, one for each. */
Test(contacts, on_hit_fires_for_the_wall_and_the_segment_of_one_step)
{
    isk_effect *fx = scene_text_open("[scene]\ndt = 1/60\nintegrator = verlet\n"
                                     "[view]\nxmin = -10\nxmax = 10\nymin = -10\nymax = 10\n"
                                     "[bounds]\nmode = reflect\nrestitution = 1\n"
                                     "[deflector slant]\nsegment = -6, -4, 5, 7\n"
                                     "[emitter ball]\nsource = particle\nposition = 9, 6\n"
                                     "velocity = 600, 0\nbounded = true\n"
                                     "deflectors = slant\non_hit = spark\ndraw = none\n"
                                     "[emitter spark]\nsource = sub\ncount = 1\nlife = 10\ndraw = none\n", 0);
    const isk_effect_def *d = isk_effect_definition(fx);
    const isk_particles *ball = isk_effect_particles(fx, isk_effect_def_find_emitter(d, "ball"));
    const isk_particles *spark = isk_effect_particles(fx, isk_effect_def_find_emitter(d, "spark"));
    size_t before = 0;
    int steps_with_two = 0;
    for (int f = 0; f < 30; f++) {
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        cr_assert_eq(ball->count, 1);
        steps_with_two += spark->count - before == 2;
        cr_assert(spark->count - before <= 2, "frame %d: %zu events", f, spark->count - before);
        before = spark->count;
    }
    cr_log_info("%zu events in 30 frames, %d frames with two", spark->count, steps_with_two);
    cr_assert(steps_with_two >= 1);
    isk_effect_destroy(fx);
}
