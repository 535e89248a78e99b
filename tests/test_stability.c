/* SPDX-License-Identifier: MIT */
/* The hard cases that must stay numerically stable, one test per case, each
 * asserting the documented behaviour (docs/accuracy.md, "Hard cases"):
 * a particle on a potential's centre, tiny distances with large exponents,
 * stiff drag, 10^6 units per step against walls and segments, extreme
 * world coordinates in the view and rasterizer, a 10^7-step run with drag,
 * and bad inputs.  The suite also runs under ASan + UBSan in CI. */
#include <criterion/criterion.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "iskra/bounds.h"
#include "iskra/deflector.h"
#include "iskra/draw.h"
#include "iskra/effect.h"
#include "iskra/scene.h"
#include "iskra/system.h"
#include "iskra/text.h"
#include "iskra/view.h"

static const double thesis_exponents[] = {1, 2, 3, 4, 9};
static const double PI = 3.14159265358979323846;

static int store_finite(const isk_particles *p)
{
    for (size_t i = 0; i < p->count; i++)
        if (!isfinite(p->x[i]) || !isfinite(p->y[i]) || !isfinite(p->vx[i]) || !isfinite(p->vy[i]))
            return 0;
    return 1;
}

/* ---- a particle exactly on a potential ---------------------------------- */

Test(stability, centre_of_every_thesis_exponent_is_zero_force)
{
    for (int k = 0; k < 5; k++)
        for (int with_min = 0; with_min < 2; with_min++) {
            isk_potential pot;
            isk_potential_init(&pot, 800, isk_vec2_make(5, 5), 1);
            pot.P = thesis_exponents[k];
            pot.min_dist = with_min ? 0.5 : ISK_DIST_OFF;
            isk_vec2 F = isk_potential_force(&pot, 5, 5, ISK_FIDELITY_SOUND);
            /* Defined: no direction exists at the centre, the force is zero
             * (both signs of zero compare equal to 0). */
            cr_assert(F.x == 0 && F.y == 0, "P=%g min=%d: (%g, %g)", pot.P, with_min, F.x, F.y);
        }
}

Test(stability, thesis_fidelity_keeps_its_documented_nan_at_the_centre)
{
    isk_potential pot;
    isk_potential_init(&pot, 800, isk_vec2_make(5, 5), 1);
    isk_vec2 F = isk_potential_force(&pot, 5, 5, ISK_FIDELITY_THESIS);
    cr_assert(isnan(F.x) && isnan(F.y)); /* 0 * (kQ / 0): what the JavaScript computes */
    pot.min_dist = 0.5;
    F = isk_potential_force(&pot, 5, 5, ISK_FIDELITY_THESIS);
    cr_assert(F.x == 0 && F.y == 0); /* with a min distance even the thesis is fine */
}

Test(stability, particles_on_the_centre_stay_finite_with_every_integrator)
{
    for (int method = 0; method < ISK_INTEGRATOR_COUNT; method++)
        for (int k = 0; k < 5; k++)
            for (int with_min = 0; with_min < 2; with_min++) {
                isk_system s;
                cr_assert_eq(isk_system_init(&s, 1, 0), ISK_OK);
                isk_system_set_integrator(&s, (isk_integrator)method);
                isk_potential pot;
                isk_potential_init(&pot, 800, isk_vec2_make(0, 0), 1);
                pot.P = thesis_exponents[k];
                pot.min_dist = with_min ? 0.5 : ISK_DIST_OFF;
                cr_assert_eq(isk_system_add_potential(&s, &pot, NULL), ISK_OK);
                s.forces.drag = 0.1;
                isk_particles_add(&s.particles, 0, 0, 0, 0, 1, NULL);    /* exactly on it */
                isk_particles_add(&s.particles, 1e-3, 0, 0, 0, 1, NULL); /* falls through it */
                for (int step = 0; step < 500; step++)
                    cr_assert_eq(isk_system_step(&s, 1.0 / 60), ISK_OK);
                cr_assert(store_finite(&s.particles), "%s P=%g min=%d",
                          isk_integrator_name((isk_integrator)method), pot.P, with_min);
                cr_assert(s.particles.x[0] == 0 && s.particles.y[0] == 0); /* zero force: it stays */
                isk_system_free(&s);
            }
}

/* ---- tiny distances, large exponents: saturation ------------------------- */

Test(stability, tiny_distance_with_exponent_9_saturates_along_the_law)
{
    isk_potential pot;
    isk_potential_init(&pot, 1, isk_vec2_make(0, 0), 1);
    pot.P = 9;
    /* d = 1e-150: the law's |F| = d^-8 = 1e1200 overflows; d^9 underflows. */
    isk_vec2 F = isk_potential_force(&pot, 1e-150, 0, ISK_FIDELITY_SOUND);
    cr_assert(F.x == -ISK_FORCE_LIMIT && F.y == 0, "(%g, %g)", F.x, F.y); /* attracts: towards 0 */
    F = isk_potential_force(&pot, 1e-150, 2e-150, ISK_FIDELITY_SOUND);
    cr_assert(F.x == -0.5 * ISK_FORCE_LIMIT && F.y == -ISK_FORCE_LIMIT, "(%g, %g)", F.x, F.y);
    /* d^2 itself underflows here, so d computes as 0: still saturated along n. */
    F = isk_potential_force(&pot, -3e-170, 1e-170, ISK_FIDELITY_SOUND);
    cr_assert(F.x == ISK_FORCE_LIMIT && fabs(F.y + ISK_FORCE_LIMIT / 3) <= 1e-15 * ISK_FORCE_LIMIT);
    /* Repulsive: the other way. */
    pot.charge = -1;
    F = isk_potential_force(&pot, 1e-150, 0, ISK_FIDELITY_SOUND);
    cr_assert(F.x == ISK_FORCE_LIMIT && F.y == 0);
    /* The thesis mode reproduces the overflow it would have. */
    pot.charge = 1;
    F = isk_potential_force(&pot, 1e-150, 0, ISK_FIDELITY_THESIS);
    cr_assert(isinf(F.x) || isnan(F.x));
}

Test(stability, forces_below_the_limit_are_the_thesis_bits)
{
    isk_potential pot;
    isk_potential_init(&pot, 1, isk_vec2_make(0.25, -0.5), 1);
    for (int k = 0; k < 5; k++) {
        pot.P = thesis_exponents[k];
        for (double d = 1e-12; d < 1e3; d *= 3.7) {
            isk_vec2 a = isk_potential_force(&pot, 0.25 + d * 0.6, -0.5 - d * 0.8, ISK_FIDELITY_SOUND);
            isk_vec2 b = isk_potential_force(&pot, 0.25 + d * 0.6, -0.5 - d * 0.8, ISK_FIDELITY_THESIS);
            if (fabs(b.x) <= ISK_FORCE_LIMIT && fabs(b.y) <= ISK_FORCE_LIMIT)
                cr_assert(!memcmp(&a, &b, sizeof a), "P=%g d=%g", pot.P, d);
            else
                cr_assert(fmax(fabs(a.x), fabs(a.y)) == ISK_FORCE_LIMIT, "P=%g d=%g", pot.P, d);
        }
    }
}

Test(stability, saturated_kicks_stay_finite_downstream)
{
    /* The vector pass and the scalar fix-up together: a block where one
     * particle saturates and its neighbours do not. */
    isk_system s;
    cr_assert_eq(isk_system_init(&s, 1, 0), ISK_OK);
    isk_potential pot;
    isk_potential_init(&pot, 1, isk_vec2_make(0, 0), 1);
    pot.P = 9;
    cr_assert_eq(isk_system_add_potential(&s, &pot, NULL), ISK_OK);
    for (int i = 0; i < 300; i++)
        isk_particles_add(&s.particles, i == 137 ? 1e-150 : 1 + i * 0.01, 0, 0, 0, 1, NULL);
    isk_potential pot_alone = pot;
    isk_vec2 expect = isk_potential_force(&pot_alone, 1 + 5 * 0.01, 0, ISK_FIDELITY_SOUND);
    cr_assert_eq(isk_system_step(&s, 1.0 / 60), ISK_OK);
    cr_assert(store_finite(&s.particles));
    cr_assert(s.particles.vx[137] == -ISK_FORCE_LIMIT / 60);
    cr_assert(s.particles.vx[5] == expect.x / 60); /* unsaturated neighbours: the law */
    for (int step = 0; step < 100; step++)
        cr_assert_eq(isk_system_step(&s, 1.0 / 60), ISK_OK);
    cr_assert(store_finite(&s.particles));
    isk_system_free(&s);
}

/* ---- stiff drag: b*dt/m = 10 -------------------------------------------- */

static double stiff_run(isk_integrator method, int steps, double *v_out, int *sign_flips, int *monotone)
{
    isk_system s;
    cr_assert_eq(isk_system_init(&s, 1, 0), ISK_OK);
    isk_system_set_integrator(&s, method);
    isk_system_set_drag(&s, 600); /* m = 1, dt = 1/60: b*dt/m = 10 */
    isk_particles_add(&s.particles, 0, 0, 1, 0, 1, NULL);
    double prev = 1;
    *sign_flips = 0;
    *monotone = 1;
    for (int i = 0; i < steps; i++) {
        isk_system_step(&s, 1.0 / 60);
        double v = s.particles.vx[0];
        if (v * prev < 0)
            (*sign_flips)++;
        if (fabs(v) > fabs(prev))
            *monotone = 0;
        prev = v;
    }
    *v_out = prev;
    double x = s.particles.x[0];
    isk_system_free(&s);
    return x;
}

/* The explicit forms used to multiply v by 1 - b*dt/m = -9 every step and
 * overflow (dt = 1000 with an ordinary drag did it in a hundred frames).
 * The drag now saturates at m/h (iskra/limits.h): it stops the particle
 * within the step and never reverses it. */
Test(stability, stiff_drag_saturates_explicit_methods_exact_decays)
{
    double v;
    int flips, mono;
    /* Explicit and semi-implicit Euler: 1 - min(b dt/m, 1) = 0, at once. */
    double x = stiff_run(ISK_INTEGRATE_EULER, 20, &v, &flips, &mono);
    cr_assert(v == 0 && flips == 0 && mono, "v = %g", v);
    cr_assert(x == 1.0 / 60, "x = %.17g", x); /* the old velocity for one step, then at rest */
    x = stiff_run(ISK_INTEGRATE_SEMI_EULER, 20, &v, &flips, &mono);
    cr_assert(v == 0 && flips == 0 && mono && x == 0, "v = %g x = %g", v, x);
    /* RK4's amplification at the saturation (z = 1): 1 - 1 + 1/2 - 1/6 + 1/24. */
    stiff_run(ISK_INTEGRATE_RK4, 10, &v, &flips, &mono);
    cr_assert(fabs(v / pow(0.375, 10) - 1) < 1e-12, "v = %g", v);
    cr_assert(flips == 0 && mono);
    /* Verlet: two half kicks, (1 - 1/2)^2 a step. */
    stiff_run(ISK_INTEGRATE_VERLET, 10, &v, &flips, &mono);
    cr_assert(fabs(v / pow(0.25, 10) - 1) < 1e-12 && flips == 0 && mono, "v = %g", v);
    /* The exponential update needs no cap: e^-10 per step, monotone, never
     * a sign flip, and after enough steps exactly 0 (flushed, never
     * subnormal). */
    x = stiff_run(ISK_INTEGRATE_EXACT_DRAG, 200, &v, &flips, &mono);
    cr_assert_eq(flips, 0);
    cr_assert(mono);
    cr_assert(v == 0);
    /* Travelled v0*m/b*(1 - e^{-10 n}) -> 1/600. */
    cr_assert(fabs(x - 1.0 / 600) < 1e-15, "x = %.17g", x);
    stiff_run(ISK_INTEGRATE_EXACT_DRAG, 3, &v, &flips, &mono);
    cr_assert(fabs(v / exp(-30) - 1) < 1e-12);
}

/* The case: dt = 1000 with drag and semi-implicit Euler, every
 * integrator, and the drag's largest value: finite, at rest. */
Test(stability, a_long_step_with_drag_stays_finite)
{
    const double bs[2] = {0.47, ISK_STRENGTH_MAX};
    for (int m = 0; m < ISK_INTEGRATOR_COUNT; m++)
        for (int k = 0; k < 2; k++) {
            isk_system s;
            cr_assert_eq(isk_system_init(&s, 1, 0), ISK_OK);
            isk_system_set_integrator(&s, (isk_integrator)m);
            cr_assert_eq(isk_system_set_drag(&s, bs[k]), ISK_OK);
            cr_assert_eq(isk_system_set_gravity(&s, 9.81), ISK_OK);
            isk_particles_add(&s.particles, 0, 0, 3, 4, 1, NULL);
            for (int i = 0; i < 1000; i++)
                cr_assert_eq(isk_system_step(&s, ISK_DT_MAX), ISK_OK);
            cr_assert(store_finite(&s.particles), "%s b=%g", isk_integrator_name((isk_integrator)m), bs[k]);
            cr_assert_eq(s.removed_nonfinite, 0);
            isk_system_free(&s);
        }
}

Test(stability, slowing_factor_never_goes_negative)
{
    /* slowing 100/s at dt = 1/60: 1 - slowing*dt = -0.67, clamped to 0. */
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load_string(&d,
                                       "[scene]\ndt = 1/60\n[emitter a]\nsource = particle\nvelocity = 3, -2\n"
                                       "slowing = 100\n",
                                       "slow", &err),
                 ISK_OK, "%s", err.message);
    isk_effect *e;
    cr_assert_eq(isk_effect_create(&e, &d, &err), ISK_OK, "%s", err.message);
    for (int i = 0; i < 10; i++) {
        cr_assert_eq(isk_effect_step(e), ISK_OK);
        const isk_particles *p = isk_effect_particles(e, 0);
        cr_assert_eq(p->count, 1);
        cr_assert(p->vx[0] == 0 && p->vy[0] == 0 && !signbit(p->vx[0]) == !signbit(3.0 * 0),
                  "v = (%g, %g)", p->vx[0], p->vy[0]);
    }
    isk_effect_destroy(e);
    isk_effect_def_free(&d);
}

/* ---- 10^6 units per step against walls and segments ---------------------- */

Test(stability, million_units_per_step_against_walls)
{
    isk_system s;
    cr_assert_eq(isk_system_init(&s, 7, 0), ISK_OK);
    isk_bounds b;
    cr_assert_eq(isk_bounds_reflect(&b, 0, 10, 0, 10, ISK_SIDE_ALL, 0, 1), ISK_OK);
    cr_assert_eq(isk_system_set_bounds(&s, &b, 1), ISK_OK);
    const double speed = 6e7; /* dt = 1/60: 10^6 units per step, 10^5 boxes */
    for (int k = 0; k < 64; k++) {
        double a = 2 * PI * k / 64 + 0.01;
        isk_particles_add(&s.particles, 5, 5, speed * cos(a), speed * sin(a), 1, NULL);
    }
    double prev_x[64];
    int moved[64] = {0};
    for (int step = 0; step < 1000; step++) {
        memcpy(prev_x, s.particles.x, sizeof prev_x);
        cr_assert_eq(isk_system_step(&s, 1.0 / 60), ISK_OK);
        for (int i = 0; i < 64; i++) {
            double x = s.particles.x[i], y = s.particles.y[i];
            cr_assert(x >= 0 && x <= 10 && y >= 0 && y <= 10, "outside at step %d: (%g, %g)", step, x, y);
            /* Restitution 1: the speed is kept exactly (signs flip only). */
            cr_assert(hypot(s.particles.vx[i], s.particles.vy[i]) == hypot(speed * cos(2 * PI * i / 64 + 0.01),
                                                                          speed * sin(2 * PI * i / 64 + 0.01)));
            moved[i] += x != prev_x[i];
        }
    }
    for (int i = 0; i < 64; i++)
        cr_assert(moved[i] > 900, "particle %d stuck: moved in %d of 1000 steps", i, moved[i]);
    isk_system_free(&s);
}

/* The closed-form fold against reflecting one wall at a time (in test code),
 * for overshoots of up to 300 box widths: same place, same velocity. */
Test(stability, fold_equals_one_reflection_at_a_time)
{
    const double cs[] = {1.0, 0.97, 0.5};
    for (int ci = 0; ci < 3; ci++)
        for (int k = 1; k < 3000; k += 7) {
            double c = cs[ci], x0 = 10 + k * 1.0137, v0 = 60.0 * k; /* beyond the right wall */
            double p = x0, u = v0;
            for (int guard = 0; guard < 100000 && (p < 0 || p > 10); guard++) {
                if (p > 10) { p = 10 - c * (p - 10); u = -c * u; }
                else { p = c * (0 - p); u = -c * u; }
            }
            isk_bounds b;
            cr_assert_eq(isk_bounds_reflect(&b, 0, 10, 0, 10, ISK_SIDE_ALL, 0, c), ISK_OK);
            double x = x0, y = 5, vx = v0, vy = 0;
            isk_bounds_apply_arrays(&b, 1, &x, &y, &vx, &vy);
            cr_assert(fabs(x - p) <= 1e-9 && fabs(vx - u) <= 1e-9 * fabs(v0), "c=%g k=%d: x %.17g vs %.17g, v %g vs %g",
                      c, k, x, p, vx, u);
        }
}

Test(stability, million_units_per_step_against_segments)
{
    /* A closed square of four segments; particles inside at 10^6 units per
     * step with restitution 1 must never leave it, never stop. */
    isk_deflector sq[4] = {isk_deflector_segment(0, 0, 10, 0), isk_deflector_segment(10, 0, 10, 10),
                           isk_deflector_segment(10, 10, 0, 10), isk_deflector_segment(0, 10, 0, 0)};
    enum { N = 64 };
    double x[N], y[N], vx[N], vy[N], ox[N], oy[N];
    const double dt = 1.0 / 60, speed = 6e7;
    for (int i = 0; i < N; i++) {
        double a = 2 * PI * i / N + 0.013;
        x[i] = 5 + 0.01 * i;
        y[i] = 5 - 0.007 * i;
        vx[i] = speed * cos(a);
        vy[i] = speed * sin(a);
    }
    isk_deflect_stats st = {0};
    size_t stopped = 0;
    for (int step = 0; step < 500; step++) {
        for (int i = 0; i < N; i++) {
            ox[i] = x[i];
            oy[i] = y[i];
            x[i] += dt * vx[i];
            y[i] += dt * vy[i];
        }
        cr_assert_eq(isk_deflect(sq, 4, x, y, vx, vy, ox, oy, N, NULL, NULL, &st), ISK_OK);
        for (int i = 0; i < N; i++) {
            cr_assert(x[i] > 0 && x[i] < 10 && y[i] > 0 && y[i] < 10, "escaped at step %d: (%g, %g)", step,
                      x[i], y[i]);
            cr_assert(hypot(vx[i], vy[i]) > 0.99 * speed);
            stopped += x[i] == ox[i] && y[i] == oy[i];
        }
    }
    /* A path needing more than ISK_DEFLECT_MAX_HITS bounces stops at its
     * last safe point for that step (documented last resort): at 10^5 box
     * widths per step that is every step, yet the particle is never stuck:
     * its velocity is kept, so the next step moves it again. */
    cr_assert(st.bounces > 0);
    cr_assert(stopped < (size_t)N * 500, "every particle stuck");
}

/* ---- extreme world coordinates through the view and the rasterizer ------- */

Test(stability, extreme_world_coordinates_are_clipped_or_skipped)
{
    isk_canvas big, c;
    cr_assert_eq(isk_canvas_init(&big, 120, 120), ISK_OK);
    isk_canvas_fill(&big, ISK_BLACK);
    cr_assert_eq(isk_canvas_view(&c, &big, 10, 10, 100, 100), ISK_OK);
    isk_view v;
    cr_assert_eq(isk_view_window(&v, 100, 100, -10, 10, -10, 10), ISK_OK);
    const double bad[] = {1e300, -1e300, INFINITY, -INFINITY, NAN, DBL_MAX, -DBL_MAX, 1e15, 4.9e-324};
    const int nb = sizeof bad / sizeof bad[0];
    for (int i = 0; i < nb; i++)
        for (int j = 0; j < nb; j++) {
            double wx = bad[i], wy = bad[j];
            isk_world_dot(&c, &v, wx, wy, ISK_WHITE, ISK_BLEND_OVER);
            isk_world_dot_browser(&c, &v, wx, wy, ISK_WHITE, ISK_BLEND_ADD);
            isk_world_disc(&c, &v, wx, wy, 1e300, ISK_WHITE, ISK_BLEND_OVER);
            isk_world_disc(&c, &v, 0, 0, bad[i], ISK_WHITE, ISK_BLEND_OVER);
            isk_world_text(&c, &v, wx, wy, "x", 3, ISK_WHITE, ISK_BLEND_OVER);
            double xy[6] = {wx, wy, 0, 0, bad[j], bad[i]};
            isk_world_polyline(&c, &v, xy, 3, 1, ISK_WHITE, ISK_BLEND_OVER);
            isk_world_polyline_hairline(&c, &v, xy, 3, 0, ISK_WHITE, ISK_BLEND_OVER);
        }
    /* Nothing outside the view rectangle changed. */
    for (int y = 0; y < 120; y++)
        for (int x = 0; x < 120; x++)
            if (x < 10 || x >= 110 || y < 10 || y >= 110) {
                isk_color p = isk_canvas_get(&big, x, y);
                cr_assert(p.r == 0 && p.g == 0 && p.b == 0, "(%d, %d) written", x, y);
            }
    isk_canvas_free(&big);
}

Test(stability, a_scene_whose_particles_fly_off_to_infinity_renders)
{
    /* Particles with positions of 1e300, Inf and NaN (put straight into the
     * store, as a broken integration would) are skipped by the renderer. */
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load_string(&d,
                                       "[scene]\nwidth = 64\nheight = 64\n[emitter a]\nsource = layer\n"
                                       "count = 6\nrect = -1, 1, -1, 1\ndraw = disc\nsize = 0.5\n",
                                       "inf", &err),
                 ISK_OK, "%s", err.message);
    isk_effect *e;
    cr_assert_eq(isk_effect_create(&e, &d, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_step(e), ISK_OK);
    isk_particles *p = (isk_particles *)isk_effect_particles(e, 0);
    const double bad[] = {1e300, -INFINITY, NAN, 1e300, INFINITY, -1e300};
    for (int i = 0; i < 5; i++) {
        p->x[i] = bad[i];
        p->y[i] = bad[5 - i];
    }
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 64, 64), ISK_OK);
    cr_assert_eq(isk_effect_render(e, &c), ISK_OK);
    isk_canvas_free(&c);
    isk_effect_destroy(e);
    isk_effect_def_free(&d);
}

/* ---- long runs ----------------------------------------------------------- */

Test(stability, ten_million_steps_with_drag_end_at_rest_never_subnormal, .timeout = 120)
{
    /* Drag alone makes v decay geometrically: without the flush it would
     * sink into subnormals and stay there (see iskra/integrate.h). */
    isk_particles p;
    cr_assert_eq(isk_particles_init(&p, 4, 0), ISK_OK);
    const double v0[4] = {3, -1e-3, 1e5, -2};
    for (int i = 0; i < 4; i++)
        isk_particles_add(&p, 0, 0, v0[i], 0.5 * v0[i], 1, NULL);
    isk_forces f = {.drag = 0.8};
    isk_scratch s;
    const double dt = 1.0 / 60;
    for (long k = 0; k < 10000000; k++) {
        isk_integrate_range(ISK_INTEGRATE_SEMI_EULER, &f, &s, &p, 0, 4, dt);
        if (k % 100000 == 0)
            for (int i = 0; i < 4; i++) {
                cr_assert(fpclassify(p.vx[i]) != FP_SUBNORMAL && fpclassify(p.vy[i]) != FP_SUBNORMAL);
                cr_assert(isfinite(p.x[i]) && isfinite(p.vx[i]));
            }
    }
    for (int i = 0; i < 4; i++) {
        cr_assert(p.vx[i] == 0 && p.vy[i] == 0);
        /* Semi-implicit Euler's discrete limit: x = v0 * dt * q / (1 - q)
         * with q = 1 - b*dt/m, i.e. v0 * (m/b) * q. */
        double q = 1 - 0.8 * dt, lim = v0[i] * dt * q / (1 - q);
        cr_assert(fabs(p.x[i] - lim) <= 1e-12 * fabs(lim), "x = %.17g, limit %.17g", p.x[i], lim);
    }
    isk_particles_free(&p);
}

/* ---- bad inputs ----------------------------------------------------------- */

Test(stability, bad_inputs_get_a_status_not_a_crash)
{
    isk_particles p;
    cr_assert_eq(isk_particles_init(&p, 2, 0), ISK_OK);
    cr_assert_eq(isk_particles_add(&p, 0, 0, 0, 0, 0, NULL), ISK_ERR_RANGE);  /* zero mass */
    cr_assert_eq(isk_particles_add(&p, 0, 0, 0, 0, -1, NULL), ISK_ERR_RANGE); /* negative mass */
    cr_assert_eq(isk_particles_add(&p, 0, 0, 0, 0, NAN, NULL), ISK_ERR_NAN);
    cr_assert_eq(isk_particles_add(&p, NAN, 0, 0, 0, 1, NULL), ISK_ERR_NAN);
    cr_assert_eq(isk_particles_add(&p, 0, 0, INFINITY, 0, 1, NULL), ISK_ERR_NAN);
    cr_assert_eq(p.count, 0);
    isk_particles_free(&p);

    isk_system s;
    cr_assert_eq(isk_system_init(&s, 1, 0), ISK_OK);
    isk_particles_add(&s.particles, 1, 2, 3, 4, 1, NULL);
    cr_assert_eq(isk_system_step(&s, -1.0 / 60), ISK_ERR_RANGE);
    cr_assert_eq(isk_system_step(&s, NAN), ISK_ERR_NAN);
    cr_assert_eq(isk_system_step(&s, INFINITY), ISK_ERR_NAN);
    cr_assert_eq(isk_system_set_gravity(&s, NAN), ISK_ERR_NAN);
    cr_assert_eq(isk_system_set_drag(&s, -1), ISK_ERR_RANGE);
    cr_assert_eq(isk_system_set_substeps(&s, 0), ISK_ERR_RANGE);
    isk_potential pot;
    isk_potential_init(&pot, NAN, isk_vec2_make(0, 0), 1);
    cr_assert_eq(isk_system_add_potential(&s, &pot, NULL), ISK_ERR_NAN);
    /* dt = 0 is a valid, empty step: nothing moves. */
    cr_assert_eq(isk_system_step(&s, 0), ISK_OK);
    cr_assert(s.particles.x[0] == 1 && s.particles.y[0] == 2 && s.particles.vx[0] == 3);
    cr_assert(s.time == 0);
    isk_system_free(&s);

    /* Scene-level: zero lifetime and non-finite values are refused by name. */
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load_string(&d, "[emitter a]\nsource = particle\nlife = 0\n", "zero_life", &err),
                 ISK_ERR_FORMAT);
    cr_assert(!strcmp(err.message, "zero_life:3: [emitter a] life: expected a number of seconds > 0 or forever, "
                                   "got \"0\""),
              "%s", err.message);
    cr_assert_eq(isk_scene_load_string(&d, "[emitter a]\nsource = particle\nmass = -1\n", "neg_mass", &err),
                 ISK_ERR_FORMAT);
    cr_assert(!strcmp(err.message, "neg_mass:3: [emitter a] mass: expected a number between 1e-12 and 1e12, got \"-1\""), "%s",
              err.message);
    cr_assert_eq(isk_scene_load_string(&d, "[scene]\ndt = 0\n", "zero_dt", &err), ISK_ERR_FORMAT);
    cr_assert(strstr(err.message, "zero_dt:2: [scene] dt: expected a number > 0"), "%s", err.message);
    /* The C API refuses a zero lifetime too (a stored particle with life 0
     * is simply culled at the end of its first step). */
    isk_effect_def_init(&d);
    isk_emitter_def *em = isk_effect_def_add_emitter(&d, "a");
    em->born.source = ISK_SOURCE_PARTICLE;
    em->life.seconds = 0;
    isk_effect *e = NULL;
    cr_assert_eq(isk_effect_create(&e, &d, &err), ISK_ERR_RANGE);
    cr_assert(!strcmp(err.message, "emitter 'a': life: expected a number of seconds > 0 or forever, got \"0\""), "%s",
              err.message);
    cr_assert_null(e);
    isk_effect_def_free(&d);
}

Test(stability, a_full_pool_drops_and_counts)
{
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load_string(&d,
                                       "[scene]\ndt = 1/60\n[emitter a]\nsource = stream\nrate = 600\n"
                                       "capacity = 5\n",
                                       "pool", &err),
                 ISK_OK, "%s", err.message);
    isk_effect *e;
    cr_assert_eq(isk_effect_create(&e, &d, &err), ISK_OK, "%s", err.message);
    for (int i = 0; i < 60; i++)
        cr_assert_eq(isk_effect_step(e), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(e), 5);
    cr_assert_eq(isk_effect_dropped(e, 0), 600 - 5);
    isk_effect_destroy(e);
    isk_effect_def_free(&d);
}

/* ---- accepted inputs never give a non-finite state (iskra/limits.h) ------- */

/* The C API validates what scene files validate (dt = 1e300 used to return
 * success with y = -inf). */
Test(stability, the_c_api_refuses_what_scene_files_refuse)
{
    isk_system s;
    cr_assert_eq(isk_system_init(&s, 1, 0), ISK_OK);
    isk_particles_add(&s.particles, 0, 0, 1, 1, 1, NULL);
    cr_assert_eq(isk_system_step(&s, 1e300), ISK_ERR_RANGE);
    cr_assert_eq(isk_system_step(&s, ISK_DT_MAX * 1.001), ISK_ERR_RANGE);
    cr_assert_eq(isk_system_step(&s, ISK_DT_MAX), ISK_OK);
    cr_assert_eq(isk_system_set_gravity(&s, 1e13), ISK_ERR_RANGE);
    cr_assert_eq(isk_system_set_gravity(&s, -ISK_STRENGTH_MAX), ISK_OK);
    cr_assert_eq(isk_system_set_drag(&s, 1e13), ISK_ERR_RANGE);
    cr_assert_eq(isk_system_set_substeps(&s, ISK_SUBSTEPS_MAX + 1), ISK_ERR_RANGE);
    /* plain data set directly is checked by the step */
    s.forces.gravity = 1e308;
    cr_assert_eq(isk_system_step(&s, 0.01), ISK_ERR_RANGE);
    s.forces.gravity = 9.81;
    s.forces.ax = 1e308;
    cr_assert_eq(isk_system_step(&s, 0.01), ISK_ERR_RANGE);
    s.forces.ax = 0;
    s.speed_divisor = 1e-300;
    cr_assert_eq(isk_system_step(&s, 0.01), ISK_ERR_RANGE);
    s.speed_divisor = 1;
    isk_potential pot;
    isk_potential_init(&pot, 1, isk_vec2_make(0, 0), 1);
    pot.P = 1000;
    cr_assert_eq(isk_system_add_potential(&s, &pot, NULL), ISK_ERR_RANGE);
    pot.P = -15; /* |F| ~ d^16: flung out to 1e146 in three frames before the range was narrowed */
    cr_assert_eq(isk_system_add_potential(&s, &pot, NULL), ISK_ERR_RANGE);
    pot.P = ISK_P_MIN - 1e-9;
    cr_assert_eq(isk_system_add_potential(&s, &pot, NULL), ISK_ERR_RANGE);
    pot.P = ISK_P_MAX;
    cr_assert_eq(isk_system_add_potential(&s, &pot, NULL), ISK_OK);
    s.forces.pot[0].P = -1000; /* edited in place: the step refuses it */
    cr_assert_eq(isk_system_step(&s, 0.01), ISK_ERR_RANGE);
    isk_system_free(&s);

    isk_scratch sc;
    isk_particles p;
    isk_particles_init(&p, 1, 0);
    isk_particles_add(&p, 0, 0, 0, 0, 1, NULL);
    isk_forces f = {.gravity = 9.81};
    cr_assert_eq(isk_integrate_range(ISK_INTEGRATE_RK4, &f, &sc, &p, 0, 1, 1e300), ISK_ERR_RANGE);
    isk_particles_free(&p);
    isk_bounds b;
    cr_assert_eq(isk_bounds_reflect(&b, -1e308, 1e308, 0, 1, ISK_SIDE_ALL, 0, 1), ISK_ERR_RANGE);
}

/* The thesis's centre rule makes a particle exactly on a potential NaN (the
 * JavaScript does): the step removes it and counts it, nothing else. */
Test(stability, the_system_removes_and_counts_a_non_finite_state)
{
    isk_system s;
    cr_assert_eq(isk_system_init(&s, 1, 0), ISK_OK);
    s.forces.centre = ISK_FIDELITY_THESIS;
    isk_potential pot;
    isk_potential_init(&pot, 800, isk_vec2_make(0, 0), 1);
    cr_assert_eq(isk_system_add_potential(&s, &pot, NULL), ISK_OK);
    isk_particles_add(&s.particles, 1, 1, 0, 0, 1, NULL);
    isk_particles_add(&s.particles, 0, 0, 0, 0, 1, NULL); /* on it */
    isk_particles_add(&s.particles, -1, 2, 0, 0, 1, NULL);
    cr_assert_eq(isk_system_step(&s, 1.0 / 60), ISK_OK);
    cr_assert_eq(s.removed_nonfinite, 1);
    cr_assert_eq(s.particles.count, 2);
    cr_assert(s.particles.x[0] > 0 && s.particles.x[1] < 0, "the order of the others is kept");
    cr_assert(store_finite(&s.particles));
    isk_system_free(&s);
}

/* A deflector restitution above 1 (a pinball bumper) in a closed box: the
 * speed grows by c at every bounce until ISK_SPEED_LIMIT, where it is
 * capped; nothing goes non-finite (c = 1.5 gave NaN by frame 333). */
Test(stability, bumpers_in_a_closed_box_cap_the_speed, .timeout = 60)
{
    const double cs[2] = {1.5, 1000};
    for (int k = 0; k < 2; k++) {
        char text[1200];
        snprintf(text, sizeof text,
                 "[scene]\ndt = 1/60\n[force gravity]\ng = 9.81\n"
                 "[deflector a]\nsegment = -5, -5, 5, -5\nrestitution = %g\n"
                 "[deflector b]\nsegment = 5, -5, 5, 5\nrestitution = %g\n"
                 "[deflector c]\nsegment = 5, 5, -5, 5\nrestitution = %g\n"
                 "[deflector d]\nsegment = -5, 5, -5, -5\nrestitution = %g\n"
                 "[emitter e]\nsource = explosion\nexplosion = gauss\ncount = 200\nforces = gravity\n"
                 "deflectors = a, b, c, d\nbounded = false\ndraw = none\n",
                 cs[k], cs[k], cs[k], cs[k]);
        isk_effect_def d;
        isk_error err;
        isk_effect *fx = NULL;
        cr_assert_eq(isk_scene_load_string(&d, text, "bumper", &err), ISK_OK, "%s", err.message);
        cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
        isk_effect_def_free(&d);
        const isk_particles *p = isk_effect_particles(fx, 0);
        double top = 0;
        for (int f = 0; f < 2000; f++) {
            cr_assert_eq(isk_effect_step(fx), ISK_OK);
            cr_assert(store_finite(p), "c = %g, frame %d", cs[k], f);
        }
        for (size_t i = 0; i < p->count; i++)
            top = fmax(top, hypot(p->vx[i], p->vy[i]));
        cr_assert_eq(isk_effect_removed_nonfinite(fx, 0), 0);
        cr_assert_eq(p->count, 200);
        /* the speed rose to the cap (plus at most the last step's gravity) */
        cr_assert(top > 1e100 && top <= ISK_SPEED_LIMIT * (1 + 1e-12), "c = %g: top speed %g", cs[k], top);
        isk_effect_destroy(fx);
    }
}

/* The exponent's range is where the law means something, P in
 * 0..17 (iskra/limits.h).  P = -15 (|F| ~ d^16), which flung every particle
 * to 1e146 within three frames, is refused with its line; at the range's
 * ends the motion is bounded: a spring (P = 0) keeps a particle oscillating
 * within its amplitude, and d^-16 (P = 17) stays finite. */
Test(stability, exponent_range_is_where_the_law_means_something)
{
    static const char *const scene = "[force well]\nkind = potential\nk = 1\nposition = 0, 0\nexponent = %s\n"
                                     "[emitter p]\nsource = particle\nposition = 1, 0\nvelocity = 0, 0\n"
                                     "forces = well\n";
    char text[400];
    isk_effect_def d;
    isk_error err = {0};
    snprintf(text, sizeof text, scene, "-15");
    cr_assert_eq(isk_scene_load_string(&d, text, "steep", &err), ISK_ERR_FORMAT);
    cr_expect(strstr(err.message, "steep:5: [force well] exponent:") != NULL, "%s", err.message);
    snprintf(text, sizeof text, scene, "1e-9"); /* just above a spring: still fine */
    cr_assert_eq(isk_scene_load_string(&d, text, "s", &err), ISK_OK, "%s", err.message);
    isk_effect_def_free(&d);
    snprintf(text, sizeof text, scene, "-1e-9");
    cr_assert_eq(isk_scene_load_string(&d, text, "s", &err), ISK_ERR_FORMAT);
    const char *const ends[] = {"0", "17"};
    for (int k = 0; k < 2; k++) {
        snprintf(text, sizeof text, scene, ends[k]);
        cr_assert_eq(isk_scene_load_string(&d, text, "edge", &err), ISK_OK, "%s", err.message);
        isk_effect *fx = NULL;
        cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
        double reach = 0;
        for (int f = 0; f < 2000; f++) {
            cr_assert_eq(isk_effect_step(fx), ISK_OK);
            const isk_particles *p = isk_effect_particles(fx, 0);
            cr_assert_eq(p->count, 1);
            cr_assert(isfinite(p->x[0]) && isfinite(p->y[0]) && isfinite(p->vx[0]) && isfinite(p->vy[0]));
            reach = fmax(reach, hypot(p->x[0], p->y[0]));
        }
        if (k == 0) /* a spring of k = 1 at 60 steps a second: within 2 % of its amplitude */
            cr_expect(reach < 1.02, "the spring's particle reached %g", reach);
        isk_effect_destroy(fx);
        isk_effect_def_free(&d);
    }
}
