/* SPDX-License-Identifier: MIT */
/* The effect runtime: thesis bit-exactness, only-what-is-used, frame-rate
 * independent emission, validation. */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/teach.h"

static isk_effect *make(const isk_effect_def *d)
{
    isk_effect *e = NULL;
    isk_error err = {0};
    isk_status s = isk_effect_create(&e, d, &err);
    cr_assert_eq(s, ISK_OK, "create: %s", err.message);
    return e;
}

/* Figure 13 as a definition: one particle, gravity 0.25 + drag 0.1, floor
 * only, drawn before the bounce, trails. */
static void fig13_def(isk_effect_def *d)
{
    isk_effect_def_init(d);
    d->dt = 0.25;
    d->clear = 0;
    d->fidelity = ISK_FIDELITY_THESIS;
    cr_assert_eq(isk_bounds_thesis(&d->bounds, -10, 10, -10, 10, ISK_SIDE_BOTTOM), ISK_OK);
    int g = isk_effect_def_add_force(d, "gravity", ISK_FORCE_GRAVITY);
    int b = isk_effect_def_add_force(d, "drag", ISK_FORCE_DRAG);
    d->forces[g].g = 0.25;
    d->forces[b].b = 0.1;
    isk_emitter_def *e = isk_effect_def_add_emitter(d, "particle");
    e->born.source = ISK_SOURCE_PARTICLE;
    e->born.position = isk_vec2_make(-4, -4);
    e->launch.velocity = isk_vec2_make(1, -2);
    e->motion.bounded = 1;
    e->motion.draw_before_bounce = 1;
    e->look.draw = ISK_DRAW_DOT_BROWSER; /* as the teaching API's particle */
    isk_emitter_use_force(e, g);
    isk_emitter_use_force(e, b);
}

Test(effect, fig13_bit_identical_to_teaching_api)
{
    isk_effect_def d;
    fig13_def(&d);
    isk_effect *fx = make(&d);
    isk_effect_def_free(&d);

    isk_view v;
    cr_assert_eq(isk_view_window(&v, 600, 600, -10, 10, -10, 10), ISK_OK);
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, 600, 600), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 600, 600), ISK_OK);
    isk_canvas_fill(&a, ISK_BLACK);
    isk_particle c;
    isk_particle_init(&c, 1, isk_vec2_make(-4, -4), isk_vec2_make(1, -2));
    for (int i = 0; i < 1000; i++) {
        isk_vec2 F = isk_vec2_add(isk_gravity_force(&c.mp, 0.25), isk_drag_force(&c.mp, 0.1));
        isk_mp_move(&c.mp, 0.25, F);
        isk_particle_draw(&c, &a, &v);
        isk_particle_zarobi(&c, &v, 0, 0, 1, 0);
    }
    cr_assert_eq(isk_effect_run(fx, &b, 1000), ISK_OK);
    cr_assert(isk_canvas_equal(&a, &b), "trail images differ");
    /* The runtime's state is the one drawn last: before the 1000th bounce,
     * which it applies at the start of the next step. */
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_eq(p->count, 1u);
    isk_effect_step(fx);
    isk_vec2 F = isk_vec2_add(isk_gravity_force(&c.mp, 0.25), isk_drag_force(&c.mp, 0.1));
    isk_mp_move(&c.mp, 0.25, F);
    cr_assert(p->x[0] == c.mp.r.x && p->y[0] == c.mp.r.y && p->vx[0] == c.mp.v.x && p->vy[0] == c.mp.v.y);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_effect_destroy(fx);
}

static void gauss_def(isk_effect_def *d, int extra_force, double gravity)
{
    isk_effect_def_init(d);
    d->dt = 0.001;
    d->seed = 7;
    int g = isk_effect_def_add_force(d, "gravity", ISK_FORCE_GRAVITY);
    d->forces[g].g = gravity;
    if (extra_force) {
        int p = isk_effect_def_add_force(d, "unused", ISK_FORCE_POTENTIAL);
        d->forces[p].pot.k = 500;
        d->forces[p].draw = 0;
        int w = isk_effect_def_add_force(d, "wind", ISK_FORCE_WIND);
        d->forces[w].accel = isk_vec2_make(3, 0);
    }
    isk_emitter_def *e = isk_effect_def_add_emitter(d, "boom");
    e->born.source = ISK_SOURCE_EXPLOSION;
    e->born.explosion = ISK_EXPLOSION_GAUSS;
    e->born.position = isk_vec2_make(0, -3);
    e->born.count = 3000;
    isk_emitter_use_force(e, g);
}

static void render_frames(const isk_effect_def *d, long frames, isk_canvas *out, char *describe, size_t n)
{
    isk_effect *fx = make(d);
    cr_assert_eq(isk_canvas_init(out, d->width, d->height), ISK_OK);
    cr_assert_eq(isk_effect_run(fx, out, frames), ISK_OK);
    if (describe) {
        FILE *f = fmemopen(describe, n, "w");
        isk_effect_describe(fx, f);
        fclose(f);
    }
    isk_effect_destroy(fx);
}

Test(effect, unreferenced_forces_change_nothing_and_are_not_described)
{
    isk_effect_def a, b;
    gauss_def(&a, 0, 2.0);
    gauss_def(&b, 1, 2.0);
    isk_canvas ca, cb;
    char da[2048] = {0}, db[2048] = {0};
    render_frames(&a, 300, &ca, da, sizeof da);
    render_frames(&b, 300, &cb, db, sizeof db);
    cr_assert(isk_canvas_equal(&ca, &cb));
    cr_assert_str_eq(da, db);
    cr_assert(strstr(db, "potential") == NULL && strstr(db, "wind") == NULL, "%s", db);
    isk_canvas_free(&ca);
    isk_canvas_free(&cb);
    isk_effect_def_free(&a);
    isk_effect_def_free(&b);
}

Test(effect, zero_strength_stage_changes_no_pixel)
{
    isk_effect_def a, b;
    gauss_def(&a, 0, 0.0);
    gauss_def(&b, 0, 0.0);
    /* b: no reference to the (zero) gravity at all. */
    b.emitters[0].motion.nforces = 0;
    isk_canvas ca, cb;
    char da[2048] = {0}, db[2048] = {0};
    render_frames(&a, 200, &ca, da, sizeof da);
    render_frames(&b, 200, &cb, db, sizeof db);
    cr_assert(isk_canvas_equal(&ca, &cb));
    cr_assert_str_eq(da, db);
    isk_canvas_free(&ca);
    isk_canvas_free(&cb);
    isk_effect_def_free(&a);
    isk_effect_def_free(&b);
}

Test(effect, disabled_potential_not_in_pipeline)
{
    isk_effect_def d;
    gauss_def(&d, 0, 1.0);
    int p = isk_effect_def_add_force(&d, "pot", ISK_FORCE_POTENTIAL);
    d.forces[p].pot.k = 100;
    d.forces[p].pot.enabled = 0;
    isk_emitter_use_force(&d.emitters[0], p);
    isk_effect *fx = make(&d);
    char buf[2048] = {0};
    FILE *f = fmemopen(buf, sizeof buf, "w");
    isk_effect_describe(fx, f);
    fclose(f);
    cr_assert(strstr(buf, "potential") == NULL, "%s", buf);
    isk_effect_destroy(fx);
    d.forces[p].pot.enabled = 1;
    fx = make(&d);
    memset(buf, 0, sizeof buf);
    f = fmemopen(buf, sizeof buf, "w");
    isk_effect_describe(fx, f);
    fclose(f);
    cr_assert(strstr(buf, "potential 1") != NULL, "%s", buf);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

static void stream_def(isk_effect_def *d, double dt)
{
    isk_effect_def_init(d);
    d->dt = dt;
    d->seed = 3;
    int g = isk_effect_def_add_force(d, "gravity", ISK_FORCE_GRAVITY);
    d->forces[g].g = 9.81;
    isk_emitter_def *e = isk_effect_def_add_emitter(d, "fountain");
    e->born.source = ISK_SOURCE_STREAM;
    e->born.rate = 200;
    /* Not 0.6: births fall on multiples of 1/200 s, and a particle born at
     * 0.4 s with life 0.6 s dies exactly at t = 1 s, a tie that rounding
     * (of accumulated ages) decides differently for different step sizes. */
    e->life.seconds = 0.6025;
    e->launch.kind = ISK_VELGEN_CONE;
    e->launch.angle = 1.5707963267948966; /* up */
    e->launch.spread = 0.5;
    e->launch.speed_min = 4;
    e->launch.speed_max = 6;
    isk_emitter_use_force(e, g);
}

Test(effect, stream_is_frame_rate_independent)
{
    isk_effect_def a, b;
    stream_def(&a, 1.0 / 30);
    stream_def(&b, 1.0 / 144);
    isk_effect *fa = make(&a), *fb = make(&b);
    for (int i = 0; i < 30; i++)
        isk_effect_step(fa);
    for (int i = 0; i < 144; i++)
        isk_effect_step(fb);
    const isk_particles *pa = isk_effect_particles(fa, 0), *pb = isk_effect_particles(fb, 0);
    /* Rate 200/s, life 0.6 s: the births of the last 0.6 s are alive. */
    cr_assert_eq(pa->count, pb->count, "%zu vs %zu", pa->count, pb->count);
    cr_assert(pa->count >= 119 && pa->count <= 121, "%zu", pa->count);
    /* Same particles in the same order; positions differ only by the
     * integrator's error for the two step sizes: semi-implicit Euler under
     * gravity is off by g*t*dt/2 <= 9.81*0.6*(1/30)/2 ~ 0.1 at most. */
    double worst = 0;
    for (size_t i = 0; i < pa->count; i++) {
        double d = hypot(pa->x[i] - pb->x[i], pa->y[i] - pb->y[i]);
        if (d > worst) worst = d;
    }
    cr_assert_lt(worst, 0.1, "worst %g", worst);
    isk_effect_destroy(fa);
    isk_effect_destroy(fb);
    isk_effect_def_free(&a);
    isk_effect_def_free(&b);
}

Test(effect, thesis_rounding_emits_nothing_at_20_per_s_and_60_fps)
{
    isk_effect_def d;
    stream_def(&d, 1.0 / 60);
    d.emitters[0].born.rate = 20;
    d.emitters[0].born.rate_mode = ISK_RATE_THESIS;
    isk_effect *fx = make(&d);
    for (int i = 0; i < 600; i++)
        isk_effect_step(fx);
    cr_assert_eq(isk_effect_particle_count(fx), 0u);
    isk_effect_destroy(fx);
    d.emitters[0].born.rate_mode = ISK_RATE_ACCUMULATE;
    d.emitters[0].life.seconds = INFINITY;
    fx = make(&d);
    for (int i = 0; i < 600; i++)
        isk_effect_step(fx);
    cr_assert_eq(isk_effect_particle_count(fx), 200u); /* 20/s for 10 s */
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

Test(effect, full_pool_drops_and_counts)
{
    isk_effect_def d;
    stream_def(&d, 1.0 / 60);
    d.emitters[0].born.capacity = 50;
    d.emitters[0].life.seconds = INFINITY;
    isk_effect *fx = make(&d);
    for (int i = 0; i < 60; i++)
        isk_effect_step(fx);
    cr_assert_eq(isk_effect_particle_count(fx), 50u);
    cr_assert_eq(isk_effect_dropped(fx, 0), 150u);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

Test(effect, same_seed_same_bytes_other_seed_differs)
{
    isk_effect_def d;
    gauss_def(&d, 0, 1.0);
    isk_canvas a, b, c;
    render_frames(&d, 100, &a, NULL, 0);
    render_frames(&d, 100, &b, NULL, 0);
    d.seed = 8;
    render_frames(&d, 100, &c, NULL, 0);
    cr_assert(isk_canvas_equal(&a, &b));
    cr_assert(!isk_canvas_equal(&a, &c));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_canvas_free(&c);
    isk_effect_def_free(&d);
}

Test(effect, reset_replays_the_same_run)
{
    isk_effect_def d;
    stream_def(&d, 1.0 / 60);
    isk_effect *fx = make(&d);
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, 600, 600), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 600, 600), ISK_OK);
    cr_assert_eq(isk_effect_run(fx, &a, 90), ISK_OK);
    cr_assert_eq(isk_effect_reset(fx), ISK_OK);
    cr_assert_eq(isk_effect_run(fx, &b, 90), ISK_OK);
    cr_assert(isk_canvas_equal(&a, &b));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

Test(effect, validation_messages_name_the_item)
{
    isk_effect_def d;
    stream_def(&d, 1.0 / 60);
    isk_effect *fx = NULL;
    isk_error err = {0};
    d.emitters[0].life.seconds = -1;
    d.emitters[0].line = 12;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    cr_assert_null(fx);
    cr_assert(strstr(err.message, "emitter 'fountain' (line 12): life") != NULL, "%s", err.message);
    d.emitters[0].life.seconds = 1;
    d.dt = NAN;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    cr_assert(strstr(err.message, "dt") != NULL, "%s", err.message);
    d.dt = 0.01;
    d.emitters[0].motion.forces[0] = 7; /* no such force */
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    d.emitters[0].motion.forces[0] = 0;
    d.xmin = 5;
    d.xmax = 5;
    cr_assert_neq(isk_effect_create(&fx, &d, &err), ISK_OK);
    cr_assert(strstr(err.message, "view") != NULL, "%s", err.message);
    cr_assert_eq(isk_effect_create(NULL, &d, &err), ISK_ERR_NULL);
    isk_effect_def_free(&d);
}

Test(effect, oscillation_random_phase_starts_without_a_jump)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    d.dt = 0.001;
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "flame");
    e->born.source = ISK_SOURCE_LAYER;
    e->born.rect[0] = 0; e->born.rect[1] = 0; e->born.rect[2] = 0; e->born.rect[3] = 0; /* all at the origin, at rest */
    e->born.count = 2000;
    e->motion.osc_omega_min = 6;
    e->motion.osc_omega_max = 6;
    e->motion.osc_amplitude_min = 0.5;
    e->motion.osc_amplitude_max = 0.5;
    e->motion.osc_table = ISK_SINLUT_LIBM;
    for (int random = 0; random < 2; random++) {
        e->motion.osc_random_phase = random;
        isk_effect *fx = make(&d);
        isk_effect_step(fx);
        const isk_particles *p = isk_effect_particles(fx, 0);
        int left = 0, right = 0;
        for (size_t i = 0; i < p->count; i++) {
            /* One step moves by A*(sin(ph + w*dt) - sin(ph)) <= A*w*dt = 0.003. */
            cr_assert_leq(fabs(p->x[i]), 0.5 * 6 * 0.001 + 1e-12, "particle %zu jumped to %g", i, p->x[i]);
            left += p->x[i] < 0;
            right += p->x[i] > 0;
        }
        if (random)
            cr_assert(left > 800 && right > 800, "sway directions %d left, %d right", left, right);
        else
            cr_assert(left == 0 && right == 2000, "phase 0: all sway right first (%d, %d)", left, right);
        isk_effect_destroy(fx);
    }
    isk_effect_def_free(&d);
}

Test(effect, every_dot_rule_draws_with_a_colour_ramp)
{
    /* The same particles with and without a (constant) colour ramp give the
     * same picture, for both dot rules: the per-particle colour path must
     * draw what the constant-colour path draws. */
    const isk_draw_mode modes[2] = {ISK_DRAW_DOT, ISK_DRAW_DOT_BROWSER};
    for (int k = 0; k < 2; k++) {
        isk_canvas a, b;
        for (int ramp = 0; ramp < 2; ramp++) {
            isk_effect_def d;
            gauss_def(&d, 0, 1.0);
            d.emitters[0].look.draw = modes[k];
            d.emitters[0].life.seconds = 100;
            if (ramp) {
                d.emitters[0].look.color_over_life.n = 2;
                d.emitters[0].look.color_over_life.stops[0] = (isk_color_stop){0.0, ISK_YELLOW};
                d.emitters[0].look.color_over_life.stops[1] = (isk_color_stop){1.0, ISK_YELLOW};
            }
            render_frames(&d, 50, ramp ? &b : &a, NULL, 0);
            isk_effect_def_free(&d);
        }
        cr_assert(isk_canvas_equal(&a, &b), "draw mode %d", (int)modes[k]);
        isk_canvas_free(&a);
        isk_canvas_free(&b);
    }
}

Test(effect, every_source_honours_the_life_range)
{
    const isk_source_kind sources[2] = {ISK_SOURCE_LAYER, ISK_SOURCE_EXPLOSION};
    for (int k = 0; k < 2; k++) {
        isk_effect_def d;
        isk_effect_def_init(&d);
        isk_emitter_def *e = isk_effect_def_add_emitter(&d, "src");
        e->born.source = sources[k];
        e->born.explosion = ISK_EXPLOSION_MULTI_COULOMB; /* batches: the scheduled path */
        e->born.rect[1] = 1;
        e->born.rect[3] = 1;
        e->born.count = 500;
        e->life.seconds = 2.0;
        e->life.range = 1.0;
        isk_effect *fx = make(&d);
        for (int i = 0; i < 10; i++)
            isk_effect_step(fx);
        const isk_particles *p = isk_effect_particles(fx, 0);
        cr_assert_eq(p->count, 500u);
        double lo = 10, hi = 0;
        for (size_t i = 0; i < p->count; i++) {
            lo = fmin(lo, p->life[i]);
            hi = fmax(hi, p->life[i]);
        }
        cr_assert(lo >= 2.0 && hi < 3.0 && hi - lo > 0.9, "source %d: lives %g..%g", k, lo, hi);
        isk_effect_destroy(fx);
        isk_effect_def_free(&d);
    }
}
