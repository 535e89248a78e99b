/* SPDX-License-Identifier: MIT */
/* The fire runtime: stream emission, births, lifetime, pool,
 * forces (wind, buoyancy, slowing, gravity multiplier), flame oscillation
 * and the slowing order, with the numbers of the fire thesis's checks
 * (reference/fire-thesis.md section 5) and the particle-engine thesis's
 * worked example. */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/sinlut.h"
#include "scene/effect_internal.h"

#define PI 3.14159265358979323846

static isk_effect *make(const isk_effect_def *d)
{
    isk_effect *e = NULL;
    isk_error err = {0};
    isk_status s = isk_effect_create(&e, d, &err);
    cr_assert_eq(s, ISK_OK, "create: %s", err.message);
    return e;
}

static void steps(isk_effect *fx, int n)
{
    for (int i = 0; i < n; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
}

/* One stream emitter, no forces, point source, constant velocity. */
static isk_emitter_def *stream(isk_effect_def *d, double dt, double rate)
{
    isk_effect_def_init(d);
    d->dt = dt;
    d->seed = 11;
    isk_emitter_def *e = isk_effect_def_add_emitter(d, "s");
    e->born.source = ISK_SOURCE_STREAM;
    e->born.rate = rate;
    e->launch.velocity = isk_vec2_make(0, 1);
    return e;
}

/* One particle at the origin, at rest. */
static isk_emitter_def *single(isk_effect_def *d, double dt)
{
    isk_effect_def_init(d);
    d->dt = dt;
    isk_emitter_def *e = isk_effect_def_add_emitter(d, "p");
    e->born.source = ISK_SOURCE_PARTICLE;
    return e;
}

/* ---- sub-frame birth ------------------------------------------------------ */

static void cone_stream(isk_effect_def *d, double dt, int with_wind)
{
    isk_emitter_def *e = stream(d, dt, 200);
    e->life.seconds = 0.6025; /* no death exactly at t = 1 s (births are on a 1/200 s grid) */
    e->launch.kind = ISK_VELGEN_CONE;
    e->launch.angle = PI / 2;
    e->launch.spread = 0.5;
    e->launch.speed_min = 4;
    e->launch.speed_max = 6;
    e->born.shape = ISK_SHAPE_DISC;
    e->born.shape_a = 0.5;
    if (with_wind) {
        int w = isk_effect_def_add_force(d, "wind", ISK_FORCE_WIND);
        d->forces[w].accel = isk_vec2_make(0, -9.81);
        isk_emitter_use_force(&d->emitters[0], w);
    }
}

/* 30 and 144 steps per second: the same particles at t = 1 s.  Without
 * forces the positions agree to rounding (1e-12); under a constant
 * acceleration a, semi-implicit Euler puts a particle of age T at
 * x0 + v0 T + a (T^2 + sum h_j^2)/2, so the two runs differ by at most
 * |a| T h30 / 2 (<= 9.81 * 0.6025 / 30 / 2 = 0.0985). */
Test(fire, subframe_birth_30_vs_144_steps)
{
    for (int wind = 0; wind <= 1; wind++) {
        isk_effect_def a, b;
        cone_stream(&a, 1.0 / 30, wind);
        cone_stream(&b, 1.0 / 144, wind);
        isk_effect *fa = make(&a), *fb = make(&b);
        steps(fa, 30);
        steps(fb, 144);
        cr_assert_float_eq(isk_effect_time(fa), 1.0, 1e-15);
        cr_assert_float_eq(isk_effect_time(fb), 1.0, 1e-15);
        const isk_particles *pa = isk_effect_particles(fa, 0), *pb = isk_effect_particles(fb, 0);
        /* Births at k/200 s, alive if 1 - k/200 < 0.6025: k = 80..200. */
        cr_assert_eq(pa->count, 121u);
        cr_assert_eq(pb->count, 121u);
        for (size_t i = 0; i < pa->count; i++) {
            cr_assert_float_eq(pa->age[i], pb->age[i], 1e-12);
            double tol = wind ? 9.81 * pa->age[i] * (1.0 / 30) / 2 + 1e-12 : 1e-12;
            cr_assert_float_eq(pa->x[i], pb->x[i], 1e-12, "x %zu", i);
            cr_assert(fabs(pa->y[i] - pb->y[i]) <= tol, "wind %d, particle %zu: %g vs %g (tol %g)", wind, i,
                      pa->y[i], pb->y[i], tol);
        }
        isk_effect_destroy(fa);
        isk_effect_destroy(fb);
        isk_effect_def_free(&a);
        isk_effect_def_free(&b);
    }
}

/* The particle-engine thesis's worked example (section 1.4): rate 5/s,
 * life 300 ms, updates at t = 300 ms and t = 750 ms -> one particle of age
 * 100 ms, then one of age 150 ms, and exactly two allocations (the birth
 * at 400 ms would be 350 ms old: never created).  Driven through the
 * runtime's spawn stage with those two uneven steps. */
static size_t allocations;

Test(fire, backdated_birth_worked_example)
{
    isk_effect_def d;
    isk_emitter_def *em = stream(&d, 0.01, 5);
    em->life.seconds = 0.3;
    isk_effect *fx = make(&d);
    fx_group *g = &fx->groups[0];
    allocations = 0;
    double t = 0;
    const double h[2] = {0.3, 0.45};
    const double want_age[2] = {0.1, 0.15};
    for (int k = 0; k < 2; k++) {
        isk__pipeline_run(&g->pipeline, &g->store, 0, g->store.count, h[k], &fx->scratch, NULL);
        size_t before = g->store.count;
        cr_assert_eq(isk__fx_step_spawn.run(fx, g, t, h[k]), ISK_OK);
        allocations += g->store.count - before;
        isk_particles_cull(&g->store);
        t += h[k];
        cr_assert_eq(g->store.count, 1u, "update %d", k);
        cr_assert_float_eq(g->store.age[0], want_age[k], 1e-12);
        cr_assert_float_eq(g->store.y[0], want_age[k], 1e-12); /* v = (0, 1): moved by its age */
    }
    cr_assert_eq(allocations, 2);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* ---- rates ------------------------------------------------------------------ */

/* Fire thesis check 7: at dt = 1/60 the per-frame rounding gives
 * 20/s -> 0, 45/s -> 1, 100/s -> 2 per frame; the accumulator gives
 * rate * 10 s over 600 frames. */
Test(fire, thesis_rounding_and_accumulator)
{
    const double rates[3] = {20, 45, 100};
    const size_t per_frame[3] = {0, 1, 2};
    for (int k = 0; k < 3; k++) {
        isk_effect_def d;
        isk_emitter_def *e = stream(&d, 1.0 / 60, rates[k]);
        e->born.rate_mode = ISK_RATE_THESIS;
        isk_effect *fx = make(&d);
        steps(fx, 600);
        cr_assert_eq(isk_effect_particle_count(fx), 600 * per_frame[k], "rate %g", rates[k]);
        isk_effect_destroy(fx);
        d.emitters[0].born.rate_mode = ISK_RATE_ACCUMULATE;
        fx = make(&d);
        steps(fx, 600);
        cr_assert_eq(isk_effect_particle_count(fx), (size_t)(rates[k] * 10), "rate %g", rates[k]);
        isk_effect_destroy(fx);
        isk_effect_def_free(&d);
    }
}

/* Fire thesis check 8: the thesis's jitter pre-advances a new particle by
 * (rand() % msec) / 1000 s of the external force and one position step
 * only: with v0 = (0, 1), F = 0, dt = 0.1 the y values are multiples of
 * 0.001 in [0, 0.099] with mean 0.0495.  Slowing and oscillation are not
 * applied in the pre-advance; an acceleration is (v = v0 + a s, y = v s). */
Test(fire, thesis_jitter_whole_ms_force_and_position_only)
{
    isk_effect_def d;
    isk_emitter_def *e = stream(&d, 0.1, 100000); /* 10,000 per frame */
    e->born.rate_mode = ISK_RATE_THESIS;
    e->born.birth = ISK_BIRTH_THESIS_JITTER;
    e->born.capacity = 10000;
    isk_effect *fx = make(&d);
    steps(fx, 1);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_eq(p->count, 10000u);
    double sum = 0;
    for (size_t i = 0; i < p->count; i++) {
        double ms = p->y[i] * 1000;
        cr_assert_float_eq(ms, round(ms), 1e-9, "y = %g", p->y[i]);
        cr_assert(p->y[i] >= 0 && p->y[i] <= 0.099 + 1e-12);
        cr_assert_eq(p->age[i], 0.0); /* the thesis does not shift the end time */
        sum += p->y[i];
    }
    cr_assert_float_eq(sum / (double)p->count, 0.0495, 0.003);
    isk_effect_destroy(fx);

    /* With weight 2 (upward acceleration), slowing 5/s and oscillation. */
    d.emitters[0].motion.weight = 2;
    d.emitters[0].motion.slowing = 5;
    d.emitters[0].motion.osc_omega_min = d.emitters[0].motion.osc_omega_max = 10;
    d.emitters[0].motion.osc_amplitude_min = d.emitters[0].motion.osc_amplitude_max = 1;
    fx = make(&d);
    steps(fx, 1);
    p = isk_effect_particles(fx, 0);
    for (size_t i = 0; i < p->count; i++) {
        double s = (p->vy[i] - 1.0) / 2.0; /* the jitter, from v = 1 + 2 s */
        cr_assert_float_eq(s * 1000, round(s * 1000), 1e-9);
        cr_assert_float_eq(p->y[i], p->vy[i] * s, 1e-15);
        cr_assert_eq(p->x[i], 0.0); /* no oscillation */
        cr_assert_eq(p->vx[i], 0.0);
    }
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* Fire thesis check 19 (Little's law): rate R, life uniform in
 * [L, L + D]: the mean live count is R (L + D/2) = 125 within 5 %. */
Test(fire, steady_state_population)
{
    isk_effect_def d;
    isk_emitter_def *e = stream(&d, 1.0 / 60, 100);
    e->life.seconds = 1.0;
    e->life.range = 0.5;
    isk_effect *fx = make(&d);
    steps(fx, 270); /* 3 (L + D) */
    double sum = 0;
    for (int i = 0; i < 100; i++) {
        steps(fx, 1);
        sum += (double)isk_effect_particle_count(fx);
    }
    cr_assert_float_eq(sum / 100, 125.0, 125 * 0.05);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* ---- lifetime and pool -------------------------------------------------------- */

/* Life 1 s at dt = 1/8 (exact in binary): alive after 7 steps (age
 * 0.875), gone after the 8th (age 1.0: a particle lives while age < life).
 * The thesis's strict "now > end" on whole milliseconds keeps it 1 ms more. */
Test(fire, dies_when_age_reaches_life)
{
    isk_effect_def d;
    isk_emitter_def *e = single(&d, 0.125);
    e->life.seconds = 1.0;
    isk_effect *fx = make(&d);
    steps(fx, 7);
    cr_assert_eq(isk_effect_particle_count(fx), 1u);
    cr_assert_eq(isk_effect_particles(fx, 0)->age[0], 0.875);
    steps(fx, 1);
    cr_assert_eq(isk_effect_particle_count(fx), 0u);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* Lifetime = min + U * range: every life in [1, 1.5), both ends reached. */
Test(fire, lifetime_min_plus_range)
{
    isk_effect_def d;
    isk_emitter_def *e = stream(&d, 1.0 / 60, 6000);
    e->life.seconds = 1.0;
    e->life.range = 0.5;
    isk_effect *fx = make(&d);
    steps(fx, 30);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_eq(p->count, 3000u);
    double lo = 9, hi = 0, sum = 0;
    for (size_t i = 0; i < p->count; i++) {
        lo = fmin(lo, p->life[i]);
        hi = fmax(hi, p->life[i]);
        sum += p->life[i];
    }
    cr_assert(lo >= 1.0 && lo < 1.002, "%g", lo);
    cr_assert(hi < 1.5 && hi > 1.498, "%g", hi);
    cr_assert_float_eq(sum / 3000, 1.25, 0.01);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* Bursts of 60 every 0.5 s into a pool of 100: t = 0, 0.5, 1.0 -> 180
 * spawns, 100 kept, 80 dropped and counted; nothing written past the pool
 * (ASan would see it). */
Test(fire, pool_overflow_counted)
{
    isk_effect_def d;
    isk_emitter_def *e = stream(&d, 0.125, 0);
    e->born.count = 60;
    e->born.burst_every = 0.5;
    e->born.capacity = 100;
    isk_effect *fx = make(&d);
    steps(fx, 8); /* to t = 1.0 */
    cr_assert_eq(isk_effect_particle_count(fx), 100u);
    cr_assert_eq(isk_effect_dropped(fx, 0), 80u);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* ---- forces -------------------------------------------------------------------- */

/* Wind is a constant acceleration: with semi-implicit Euler x_n =
 * a h^2 n(n+1)/2, so the drift grows as t^2 (x(2t)/x(t) -> 4). */
Test(fire, wind_is_an_acceleration)
{
    isk_effect_def d;
    single(&d, 0.01);
    int w = isk_effect_def_add_force(&d, "wind", ISK_FORCE_WIND);
    d.forces[w].accel = isk_vec2_make(2, 0);
    isk_emitter_use_force(&d.emitters[0], w);
    isk_effect *fx = make(&d);
    const isk_particles *p = isk_effect_particles(fx, 0);
    steps(fx, 100);
    double x1 = p->x[0];
    cr_assert_float_eq(x1, 2 * 0.01 * 0.01 * 100 * 101 / 2, 1e-12);
    steps(fx, 100);
    cr_assert_float_eq(p->x[0], 2 * 0.01 * 0.01 * 200 * 201 / 2, 1e-12);
    cr_assert_float_eq(p->x[0] / x1, 4.0, 0.05);
    cr_assert_eq(p->y[0], 0.0);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* Weight against gravity (the fire thesis's buoyancy): weight 12 > g 9.81
 * and the particles rise, the mean vy growing by 2.19 per second; a gravity
 * multiplier of 2 doubles the fall. */
Test(fire, buoyancy_and_gravity_multiplier)
{
    isk_effect_def d;
    isk_emitter_def *e = stream(&d, 1.0 / 64, 100);
    e->launch.velocity = isk_vec2_make(0, 0);
    e->motion.weight = 12;
    int g = isk_effect_def_add_force(&d, "gravity", ISK_FORCE_GRAVITY);
    d.forces[g].g = 9.81;
    isk_emitter_use_force(&d.emitters[0], g);
    isk_effect *fx = make(&d);
    const isk_particles *p = isk_effect_particles(fx, 0);
    double prev = -1;
    for (int k = 0; k < 4; k++) {
        steps(fx, 32);
        double mean = 0, ymin = INFINITY;
        for (size_t i = 0; i < p->count; i++) {
            mean += p->vy[i];
            ymin = fmin(ymin, p->y[i]);
        }
        mean /= (double)p->count;
        cr_assert_gt(mean, prev);
        cr_assert_geq(ymin, 0.0); /* smoke rises: nothing goes below the source */
        prev = mean;
    }
    /* The oldest particle (born at 0.01 s) has vy = 2.19 * age (immortal
     * particles have no age stage: the age is t - 0.01). */
    cr_assert_float_eq(p->vy[0], 2.19 * (isk_effect_time(fx) - 0.01), 1e-9);
    isk_effect_destroy(fx);

    isk_effect_def_free(&d);
    isk_effect_def_init(&d);
    d.dt = 0.01;
    g = isk_effect_def_add_force(&d, "gravity", ISK_FORCE_GRAVITY);
    d.forces[g].g = 9.81;
    for (int k = 0; k < 2; k++) {
        isk_emitter_def *pe = isk_effect_def_add_emitter(&d, k ? "double" : "single");
        pe->motion.gravity_multiplier = k ? 2.0 : 1.0;
        isk_emitter_use_force(pe, g);
    }
    fx = make(&d);
    steps(fx, 50);
    double v1 = isk_effect_particles(fx, 0)->vy[0], v2 = isk_effect_particles(fx, 1)->vy[0];
    cr_assert_float_eq(v1, -9.81 * 0.5, 1e-12);
    cr_assert_float_eq(v2, -2 * 9.81 * 0.5, 1e-12);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* ---- slowing and its order ------------------------------------------------------ */

/* Fire thesis check 13: F = (0, -10) in the thesis's sign (an upward
 * acceleration 10), v0 = 0, dt = 0.1: y = 0.1 after one step, 0.3 after
 * two, in both orders.  With slowing 20/s the factor 1 - 20*0.1 = -1 is
 * clamped to 0: the velocity stops, never reverses.  The sound order moves
 * the particle with the unslowed velocity first (y = 0.1), the thesis order
 * does not move it. */
Test(fire, slowing_clamped_and_both_orders)
{
    for (int faithful = 0; faithful <= 1; faithful++) {
        isk_effect_def d;
        isk_emitter_def *e = single(&d, 0.1);
        e->motion.weight = 10;
        e->motion.slow_faithful = faithful;
        isk_effect *fx = make(&d);
        const isk_particles *p = isk_effect_particles(fx, 0);
        steps(fx, 1);
        cr_assert_float_eq(p->y[0], 0.1, 1e-12);
        steps(fx, 1);
        cr_assert_float_eq(p->y[0], 0.3, 1e-12);
        isk_effect_destroy(fx);

        d.emitters[0].motion.slowing = 20;
        d.emitters[0].launch.velocity = isk_vec2_make(3, 0);
        fx = make(&d);
        p = isk_effect_particles(fx, 0);
        for (int k = 0; k < 5; k++) {
            steps(fx, 1);
            cr_assert_eq(p->vx[0], 0.0);
            cr_assert_eq(p->vy[0], 0.0);
        }
        cr_assert_float_eq(p->x[0], faithful ? 0.0 : 0.3, 1e-12);
        cr_assert_float_eq(p->y[0], faithful ? 0.0 : 5 * 0.1 * 0.1 * 10, 1e-12);
        isk_effect_destroy(fx);
        isk_effect_def_free(&d);
    }
}

/* The difference in numbers: acceleration a = 10 up, slowing k = 2/s,
 * dt = 1/60.  The terminal drift of the sound order is exactly a/k = 5 at
 * any dt; the thesis order drifts at a (1 - k dt)/k = 4.8333 (3.3 % slow at
 * 60 steps/s, 1.4 % at 144).  Transients differ by O(dt) too. */
Test(fire, slowing_order_terminal_drift)
{
    const double dts[2] = {1.0 / 60, 1.0 / 144};
    for (int k = 0; k < 2; k++)
        for (int faithful = 0; faithful <= 1; faithful++) {
            isk_effect_def d;
            isk_emitter_def *e = single(&d, dts[k]);
            e->motion.weight = 10;
            e->motion.slowing = 2;
            e->motion.slow_faithful = faithful;
            isk_effect *fx = make(&d);
            const isk_particles *p = isk_effect_particles(fx, 0);
            steps(fx, (int)(20 / dts[k])); /* 20 s: 40 time constants */
            double y0 = p->y[0];
            steps(fx, 1);
            double drift = (p->y[0] - y0) / dts[k];
            double want = faithful ? 10 * (1 - 2 * dts[k]) / 2 : 5.0;
            cr_assert_float_eq(drift, want, 1e-9, "dt %g faithful %d: %.12g", dts[k], faithful, drift);
            isk_effect_destroy(fx);
            isk_effect_def_free(&d);
        }
}

/* The thesis order is a fused constant-acceleration kernel: with drag it is
 * refused with a message naming the emitter. */
Test(fire, thesis_slowing_order_needs_constant_forces)
{
    isk_effect_def d;
    isk_emitter_def *e = single(&d, 0.01);
    e->motion.slowing = 1;
    e->motion.slow_faithful = 1;
    int b = isk_effect_def_add_force(&d, "drag", ISK_FORCE_DRAG);
    d.forces[b].b = 0.5;
    isk_emitter_use_force(e, b);
    isk_effect *fx = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    cr_assert(strstr(err.message, "emitter 'p'") && strstr(err.message, "thesis slowing order"), "%s",
              err.message);
    d.forces[b].b = 0; /* a zero drag is no drag */
    fx = make(&d);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* ---- oscillation ------------------------------------------------------------------ */

static void osc_run(int faithful, int table, double out[4])
{
    isk_effect_def d;
    isk_emitter_def *e = single(&d, 0.25);
    e->motion.osc_omega_min = e->motion.osc_omega_max = 2 * PI;
    e->motion.osc_amplitude_min = e->motion.osc_amplitude_max = 1;
    e->motion.osc_faithful = faithful;
    e->motion.osc_table = table ? ISK_SINLUT_FLOOR : ISK_SINLUT_LIBM;
    isk_effect *fx = make(&d);
    for (int k = 0; k < 4; k++) {
        steps(fx, 1);
        out[k] = isk_effect_particles(fx, 0)->x[0];
    }
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* The issue's numbers: A = 1, omega = 2 pi, dt = 0.25 from rest.  Faithful
 * (offset change also added to vx): 1, 0.25, -0.75, 0; pure: 1, 0, -1, 0.
 * libm: to rounding (sin(pi) is 1.2e-16, not 0).  Sine table (N = 4096,
 * floor lookup): within 2e-3 (the fire thesis's check; the table's bound is
 * 2 pi/N = 1.53e-3 per lookup). */
Test(fire, oscillation_issue_numbers)
{
    const double faithful[4] = {1, 0.25, -0.75, 0}, pure[4] = {1, 0, -1, 0};
    for (int table = 0; table <= 1; table++) {
        double x[4];
        double tol = table ? 2e-3 : 1e-12;
        osc_run(1, table, x);
        for (int k = 0; k < 4; k++)
            cr_assert_float_eq(x[k], faithful[k], tol, "faithful table=%d step %d: %.17g", table, k + 1, x[k]);
        osc_run(0, table, x);
        for (int k = 0; k < 4; k++)
            cr_assert_float_eq(x[k], pure[k], tol, "pure table=%d step %d: %.17g", table, k + 1, x[k]);
    }
}

/* Amplitude decay k = 0.5/s: after 10 steps of 0.1 s, A = 0.95^10 =
 * 0.5987.  Observed in pure mode: x = A_10 sin(theta_11) with omega chosen
 * so theta_11 = pi/2. */
Test(fire, oscillation_amplitude_decay)
{
    isk_effect_def d;
    isk_emitter_def *e = single(&d, 0.1);
    e->motion.osc_omega_min = e->motion.osc_omega_max = (PI / 2) / 1.1;
    e->motion.osc_amplitude_min = e->motion.osc_amplitude_max = 1;
    e->motion.osc_decay = 0.5;
    e->motion.osc_table = ISK_SINLUT_LIBM;
    isk_effect *fx = make(&d);
    steps(fx, 10);
    cr_assert_float_eq(fx->groups[0].store.osc_amp[0], pow(0.95, 10), 1e-12);
    cr_assert_float_eq(fx->groups[0].store.osc_amp[0], 0.5987, 1e-4);
    steps(fx, 1);
    cr_assert_float_eq(isk_effect_particles(fx, 0)->x[0], pow(0.95, 10), 1e-12);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* At dt = 1/600 the faithful mode follows A sin(theta) + (A/omega)(1 -
 * cos(theta)) (the fire thesis's analysis, theta0 = 0): x(0.25 s) = 1.1592
 * within 1e-3; the pure mode follows A sin(theta). */
Test(fire, oscillation_faithful_drift_term)
{
    for (int faithful = 0; faithful <= 1; faithful++) {
        isk_effect_def d;
        isk_emitter_def *e = single(&d, 1.0 / 600);
        e->motion.osc_omega_min = e->motion.osc_omega_max = 2 * PI;
        e->motion.osc_amplitude_min = e->motion.osc_amplitude_max = 1;
        e->motion.osc_faithful = faithful;
        e->motion.osc_table = ISK_SINLUT_LIBM;
        isk_effect *fx = make(&d);
        steps(fx, 150);
        double want = sin(PI / 2) + (faithful ? (1 - cos(PI / 2)) / (2 * PI) : 0);
        cr_assert_float_eq(isk_effect_particles(fx, 0)->x[0], want, 1e-3);
        isk_effect_destroy(fx);
        isk_effect_def_free(&d);
    }
}

/* ---- deflectors ---------------------------------------------------------------- */

/* Sparks under gravity over a floor segment: no particle ever ends below
 * it, and some bounce (move up after having fallen). */
Test(fire, sparks_bounce_off_the_ground)
{
    isk_effect_def d;
    isk_emitter_def *e = stream(&d, 1.0 / 60, 100);
    e->born.position = isk_vec2_make(0, 0.5);
    e->launch.kind = ISK_VELGEN_CONE;
    e->launch.angle = PI / 2;
    e->launch.spread = 1.5;
    e->launch.speed_min = 1;
    e->launch.speed_max = 4;
    e->life.seconds = 3;
    int g = isk_effect_def_add_force(&d, "gravity", ISK_FORCE_GRAVITY);
    d.forces[g].g = 9.81;
    isk_deflector floor = isk_deflector_segment(5, 0, -5, 0);
    floor.restitution = 0.5;
    int f = isk_effect_def_add_deflector(&d, "floor", floor);
    isk_emitter_use_force(&d.emitters[0], g);
    isk_emitter_use_deflector(&d.emitters[0], f);
    isk_effect *fx = make(&d);
    const isk_particles *p = isk_effect_particles(fx, 0);
    int rising_low = 0;
    for (int k = 0; k < 240; k++) {
        steps(fx, 1);
        for (size_t i = 0; i < p->count; i++) {
            if (fabs(p->x[i]) < 5)
                cr_assert_geq(p->y[i], 0.0, "frame %d particle %zu", k, i);
            rising_low += p->y[i] < 0.05 && p->vy[i] > 0 && p->age[i] > 0.3;
        }
    }
    cr_assert_gt(rising_low, 10);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* The describe output names the fire stages. */
Test(fire, describe_lists_fire_stages)
{
    isk_effect_def d;
    isk_emitter_def *e = stream(&d, 1.0 / 60, 20);
    e->motion.weight = 1;
    e->motion.slowing = 0.5;
    e->motion.slow_faithful = 1;
    e->motion.osc_omega_min = e->motion.osc_omega_max = 3;
    e->motion.osc_amplitude_min = e->motion.osc_amplitude_max = 0.1;
    e->life.seconds = 2;
    e->born.rate_mode = ISK_RATE_THESIS;
    e->born.birth = ISK_BIRTH_THESIS_JITTER;
    isk_effect *fx = make(&d);
    char buf[2048] = {0};
    FILE *f = fmemopen(buf, sizeof buf, "w");
    isk_effect_describe(fx, f);
    fclose(f);
    cr_assert(strstr(buf, "thesis order") && strstr(buf, "oscillate") && strstr(buf, "rate_mode thesis") &&
                  strstr(buf, "birth thesis-jitter"),
              "%s", buf);
    cr_assert(strstr(buf, "slow      v") == NULL, "%s", buf); /* fused into the drift */
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}
