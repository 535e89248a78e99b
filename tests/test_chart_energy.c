/* SPDX-License-Identifier: MIT */
/* The simulator's energy chart: its numbers (play_energy_of, compiled in
 * here from tools/iskra/play_energy.c, as play_charts.c samples them) are
 * the library's potential energy of the forces the effect applies
 * (isk_forces_potential_energy of isk_effect_forces).  An emitter's weight
 * counts as the gravity it equals; without friction the total energy under
 * gravity and weight changes only by the integrator's own error. */
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>

#include "scene_text.h"

#include "../tools/iskra/play_energy.c"

/* Forty particles of an explosion falling at 3 units/s^2, no walls: by a
 * gravity force, or by the emitter's weight. */
#define BURST "[emitter e]\nsource = explosion\nexplosion = gauss\nposition = 1, 5\ncount = 40\n"
static const char *const by_gravity = "[force down]\nkind = gravity\ng = 3\n" BURST "forces = down\n";
static const char *const by_weight = BURST "weight = -3\n";

Test(chart_energy, a_weight_shows_the_energy_of_the_equal_gravity)
{
    isk_effect *a = scene_text_open(by_gravity, 1), *b = scene_text_open(by_weight, 1);
    const isk_forces *fa = isk_effect_forces(a, 0), *fb = isk_effect_forces(b, 0);
    cr_assert(fa && fb);
    cr_expect_eq(fa->gravity, 3.0);
    cr_expect_eq(fb->ay, -3.0, "the weight is in the forces the effect applies");
    cr_expect_null(isk_effect_forces(a, 1));
    cr_expect_null(isk_effect_forces(NULL, 0));
    double first = NAN;
    for (int frame = 0; frame < 120; frame++) {
        cr_assert_eq(isk_effect_step(a), ISK_OK);
        cr_assert_eq(isk_effect_step(b), ISK_OK);
        play_energy ea = play_energy_of(a), eb = play_energy_of(b);
        cr_assert_eq(isk_effect_particle_count(a), 40);
        /* the same motion and the same sums: the same bits */
        cr_assert_eq(ea.kinetic, eb.kinetic, "frame %d: kinetic %.17g vs %.17g", frame, ea.kinetic, eb.kinetic);
        cr_assert_eq(ea.potential, eb.potential, "frame %d: potential %.17g by gravity, %.17g by weight", frame,
                     ea.potential, eb.potential);
        if (frame == 0)
            first = ea.potential;
    }
    play_energy e = play_energy_of(b);
    cr_expect_lt(e.potential, first - 1.0, "the fall shows: %g after %g", e.potential, first);
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

/* One particle of mass 2 thrown at (3, 4) from (0, 5) under gravity 9.81
 * and weight 3 (a = -6.81), no drag, no walls, dt 1/60, for two seconds.
 * With a constant acceleration a and step h, semi-implicit Euler (v += a
 * h, then x += v h) loses exactly 1/2 m a h dv of total energy as the
 * vertical velocity changes by dv, explicit Euler (x first) gains it, and
 * every other integrator is exact (second order or higher, or the
 * closed form): so the chart's total must move by that and by rounding
 * alone.  Left without the weight, it would move by m w dy, some 30 units. */
static const char *const thrown = "[scene]\ndt = 1/60\n[force down]\nkind = gravity\ng = 9.81\n"
                                  "[emitter ball]\nsource = particle\nposition = 0, 5\nvelocity = 3, 4\nmass = 2\n"
                                  "weight = 3\nforces = down\n";

Test(chart_energy, the_total_under_gravity_and_weight_keeps_to_the_integrators_error)
{
    const double m = 2.0, a = -6.81, h = 1.0 / 60.0;
    for (int k = 0; k < ISK_INTEGRATOR_COUNT; k++) {
        const char *name = isk_integrator_names[k];
        isk_effect *fx = scene_text_open(thrown, 1);
        isk_error err;
        cr_assert_eq(isk_effect_set(fx, "scene", "integrator", name, &err), ISK_OK, "%s", err.message);
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        const isk_particles *p = isk_effect_particles(fx, 0);
        cr_assert_eq(p->count, 1);
        const double vy0 = p->vy[0], y0 = p->y[0];
        play_energy e0 = play_energy_of(fx);
        for (int frame = 0; frame < 120; frame++)
            cr_assert_eq(isk_effect_step(fx), ISK_OK);
        play_energy e1 = play_energy_of(fx);
        const double dv = p->vy[0] - vy0, dy = p->y[0] - y0;
        const double change = (e1.kinetic + e1.potential) - (e0.kinetic + e0.potential);
        const double size = e0.kinetic + fabs(e0.potential);
        double want = 0.0;
        if (!strcmp(name, "semi-euler"))
            want = -0.5 * m * a * h * dv;
        else if (!strcmp(name, "euler"))
            want = 0.5 * m * a * h * dv;
        cr_log_info("%s: total %.12g -> %.12g, change %.3e (integrator's %.3e); dy %.3f", name,
                    e0.kinetic + e0.potential, e1.kinetic + e1.potential, change, want, dy);
        cr_expect_lt(dy, -4.0, "%s: it fell (dy %g)", name, dy);
        cr_expect_leq(fabs(change - want), 1e-11 * size, "%s: the total changed by %.6e, the integrator's error is %.6e",
                      name, change, want);
        isk_effect_destroy(fx);
    }
}
