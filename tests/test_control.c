/* SPDX-License-Identifier: MIT */
/* Driving an emitter by hand (iskra/effect.h): isk_effect_emit,
 * isk_effect_set_active, isk_effect_set_paused and isk_effect_move, each
 * against what LÖVE's ParticleSystem does with emit, stop/start, pause and
 * moveTo (docs/from-love-godot.md, "Driving an emitter by hand"), the keys
 * behind them saved and read back, and their refusals. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "scene_text.h"

/* A stream of 60/s at one point (frames of 1/60 s: one birth a frame), an
 * explosion emitter, a sub-emitter fed by the stream's deaths. */
static const char *const SCENE = "[scene]\nwidth = 120\nheight = 90\ndt = 1/60\nseed = 9\n"
                                 "[view]\nxmin = -10\nxmax = 10\nymin = -5\nymax = 10\n"
                                 "[force gravity]\ng = 9.81\n"
                                 "[emitter sparks]\nsource = stream\nposition = 1, 2\nlaunch = cone\nangle = 90\n"
                                 "spread = 40\nspeed_min = 3\nspeed_max = 5\nrate = 60\nlife = 1\ncapacity = 500\n"
                                 "forces = gravity\non_death = pops\n"
                                 "[emitter pops]\nsource = sub\ncount = 2\nlife = 0.5\ncapacity = 400\n"
                                 "[emitter boom]\nsource = explosion\nexplosion = ring\ncount = 10\nactive = false\nposition = -3, 4\n"
                                 "limit = 1000\ncapacity = 100\n";

static isk_effect *load(const char *text) { return scene_text_open(text, 0); }

static size_t count_of(const isk_effect *fx, int emitter) { return isk_effect_particles(fx, emitter)->count; }

static void steps(isk_effect *fx, int n)
{
    for (int i = 0; i < n; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
}

static void ok(isk_status s, const isk_error *err) { cr_assert_eq(s, ISK_OK, "%s", err->message); }

/* LÖVE's emit(n): n particles at once, where the emitter is, whatever its
 * rate; a full system takes what fits. */
Test(control, emit_adds_n_now_where_the_emitter_is)
{
    isk_effect *fx = load(SCENE);
    isk_error err = {0};
    steps(fx, 10);
    const size_t before = count_of(fx, 0);
    ok(isk_effect_emit(fx, "emitter sparks", 25, &err), &err);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_eq(p->count, before + 25);
    for (size_t i = before; i < p->count; i++) {
        cr_assert_eq(p->x[i], 1.0);
        cr_assert_eq(p->y[i], 2.0);
        cr_assert_eq(p->age[i], 0.0);
        const double speed = hypot(p->vx[i], p->vy[i]);
        cr_assert(speed >= 3.0 && speed <= 5.0, "launch speed %g", speed);
    }
    /* beyond the pool: what fits, the rest counted as dropped */
    const uint64_t dropped = isk_effect_dropped(fx, 0);
    ok(isk_effect_emit(fx, "emitter sparks", 1000, &err), &err);
    cr_assert_eq(count_of(fx, 0), 500);
    cr_assert_eq(isk_effect_dropped(fx, 0), dropped + 1000 - (500 - before - 25));
    isk_effect_destroy(fx);
}

Test(control, emit_fires_an_explosion_of_n)
{
    isk_effect *fx = load(SCENE);
    isk_error err = {0};
    cr_assert_eq(count_of(fx, 2), 0);
    ok(isk_effect_emit(fx, "emitter boom", 40, &err), &err);
    const isk_particles *p = isk_effect_particles(fx, 2);
    cr_assert_eq(p->count, 40);
    for (size_t i = 0; i < p->count; i++) { /* a ring: every particle at the centre */
        cr_assert_eq(p->x[i], -3.0);
        cr_assert_eq(p->y[i], 4.0);
    }
    cr_assert_eq(isk_effect_emit(fx, "emitter boom", 1001, &err), ISK_ERR_RANGE);
    cr_assert_str_eq(err.message, "isk_effect_emit: [emitter boom]: 1001 particles, over its limit 1000");
    cr_assert_eq(count_of(fx, 2), 40);
    isk_effect_destroy(fx);
}

Test(control, refusals_name_the_problem)
{
    isk_effect *fx = load(SCENE);
    isk_error err = {0};
    cr_assert_eq(isk_effect_emit(fx, "emitter pops", 3, &err), ISK_ERR_RANGE);
    cr_assert_str_eq(err.message,
                     "isk_effect_emit: [emitter pops] is a sub source: only stream and explosion emitters emit");
    cr_assert_eq(isk_effect_emit(fx, "force gravity", 3, &err), ISK_ERR_RANGE);
    cr_assert_str_eq(err.message, "isk_effect_emit: [force gravity] is not an emitter (write \"emitter NAME\")");
    cr_assert_eq(isk_effect_emit(fx, "emitter spark", 3, &err), ISK_ERR_RANGE);
    cr_assert_str_eq(err.message, "no emitter named 'spark'; did you mean 'sparks'?");
    cr_assert_eq(isk_effect_emit(NULL, "emitter sparks", 3, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_move(fx, NULL, 0, 0, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_move(fx, "emitter sparks", NAN, 0, &err), ISK_ERR_NAN);
    cr_assert_eq(isk_effect_move(fx, "emitter sparks", 0, 1e151, &err), ISK_ERR_RANGE);
    cr_assert_eq(isk_effect_move(fx, "emitter pops", 0, 0, &err), ISK_ERR_RANGE);
    cr_assert_str_eq(err.message, "isk_effect_move: [emitter pops] is a sub source: it has no position");
    cr_assert_eq(isk_effect_set_active(fx, "emitter pops", 0, &err), ISK_OK, "%s", err.message);
    const isk_emitter_def *em = &isk_effect_definition(fx)->emitters[0];
    cr_assert_eq(em->born.position.x, 1.0, "a refused move changed the position");
    cr_assert_eq(em->born.position.y, 2.0);
    isk_effect_destroy(fx);
}

/* LÖVE's stop(): no new particles, the old ones live out their lives;
 * start(): emission again from now, without the births it missed. */
Test(control, stopped_streams_skip_births_and_start_without_catching_up)
{
    isk_effect *fx = load(SCENE);
    isk_error err = {0};
    steps(fx, 30);
    cr_assert_eq(count_of(fx, 0), 30);
    ok(isk_effect_set_active(fx, "emitter sparks", 0, &err), &err);
    steps(fx, 1);
    cr_assert_eq(count_of(fx, 0), 30, "a stopped stream gave birth");
    steps(fx, 59); /* their life is 1 s: every one has died */
    cr_assert_eq(count_of(fx, 0), 0);
    steps(fx, 60);
    cr_assert_eq(count_of(fx, 0), 0);
    ok(isk_effect_set_active(fx, "emitter sparks", 1, &err), &err);
    steps(fx, 1);
    cr_assert_eq(count_of(fx, 0), 1, "started again: one birth a frame, no catch-up of the 120 missed");
    steps(fx, 9);
    cr_assert_eq(count_of(fx, 0), 10);
    isk_effect_destroy(fx);
}

/* A stopped emitter costs nothing: its lists lose the births. */
Test(control, a_stopped_stream_has_no_spawn_stage)
{
    char *running = scene_text_describe(SCENE);
    isk_effect *fx = load(SCENE);
    isk_error err = {0};
    ok(isk_effect_set_active(fx, "emitter sparks", 0, &err), &err);
    char *stopped = scene_text_lists(fx);
    cr_assert_not_null(strstr(running, "spawn"), "%s", running);
    const char *sparks = strstr(stopped, "sparks"), *pops = strstr(stopped, "pops");
    cr_assert(sparks && pops && pops > sparks);
    char *own = strndup(sparks, (size_t)(pops - sparks));
    cr_assert_null(strstr(own, "spawn"), "%s", stopped);
    free(own);
    free(running);
    free(stopped);
    isk_effect_destroy(fx);
}

Test(control, stopped_sub_emitters_and_timed_explosions_skip_what_falls_due)
{
    isk_effect *fx = load(SCENE);
    isk_error err = {0};
    ok(isk_effect_set_active(fx, "emitter pops", 0, &err), &err);
    steps(fx, 120); /* the first sparks die after 60 frames: their pops are skipped */
    cr_assert_eq(count_of(fx, 1), 0);
    ok(isk_effect_set_active(fx, "emitter pops", 1, &err), &err);
    steps(fx, 1);
    cr_assert_eq(count_of(fx, 1), 2, "one spark died this frame: its two pops, nothing of the skipped ones");
    isk_effect_destroy(fx);

    char text[2048];
    snprintf(text, sizeof text, "%s%s", SCENE, "[emitter late]\nsource = explosion\nexplosion = ring\ncount = 20\n"
                                               "start = 0.5\nactive = false\n");
    fx = load(text);
    steps(fx, 40);
    cr_assert_eq(count_of(fx, 3), 0, "a stopped explosion fired");
    ok(isk_effect_set_active(fx, "emitter late", 1, &err), &err);
    steps(fx, 40);
    cr_assert_eq(count_of(fx, 3), 0, "an explosion due while stopped fired later");
    ok(isk_effect_emit(fx, "emitter late", 20, &err), &err);
    cr_assert_eq(count_of(fx, 3), 20, "emit works on a stopped emitter");
    isk_effect_destroy(fx);
}

/* LÖVE's pause(): the particles stand still, nothing is born. */
Test(control, a_paused_emitter_stands_still)
{
    isk_effect *fx = load(SCENE);
    isk_error err = {0};
    steps(fx, 20);
    ok(isk_effect_set_paused(fx, "emitter sparks", 1, &err), &err);
    const isk_particles *p = isk_effect_particles(fx, 0);
    const size_t n = p->count;
    double *was = malloc(sizeof *was * 3 * n);
    for (size_t i = 0; i < n; i++) {
        was[3 * i] = p->x[i];
        was[3 * i + 1] = p->y[i];
        was[3 * i + 2] = p->age[i];
    }
    steps(fx, 100);
    p = isk_effect_particles(fx, 0);
    cr_assert_eq(p->count, n, "paused, yet born or died");
    for (size_t i = 0; i < n; i++)
        cr_assert(p->x[i] == was[3 * i] && p->y[i] == was[3 * i + 1] && p->age[i] == was[3 * i + 2],
                  "particle %zu moved or aged", i);
    cr_assert_eq(count_of(fx, 1), 0, "nothing was born into the pops");
    ok(isk_effect_set_paused(fx, "emitter sparks", 0, &err), &err);
    steps(fx, 1);
    p = isk_effect_particles(fx, 0);
    cr_assert_eq(p->count, n + 1, "unpaused: one birth a frame again, no catch-up");
    cr_assert_neq(p->y[0], was[1]);
    free(was);
    isk_effect_destroy(fx);
}

/* The typed setter gives the bytes of the text one; LÖVE's moveTo spreads
 * the births along the way (setPosition would bunch them). */
Test(control, move_is_the_position_key_without_text)
{
    isk_effect *a = load(SCENE), *b = load(SCENE);
    isk_canvas ca, cb;
    cr_assert_eq(isk_canvas_init(&ca, 120, 90), ISK_OK);
    cr_assert_eq(isk_canvas_init(&cb, 120, 90), ISK_OK);
    isk_error err = {0};
    for (int f = 0; f < 90; f++) {
        const double x = 6.0 * sin(0.1 * f) + 0.1234567890123, y = 2.0 + 0.05 * f;
        char v[80], w[80];
        snprintf(v, sizeof v, "%.17g, %.17g", x, y);
        snprintf(w, sizeof w, "%.17g, %.17g", -x, y);
        ok(isk_effect_move(a, "emitter sparks", x, y, &err), &err);
        ok(isk_effect_set(b, "emitter sparks", "position", v, &err), &err);
        ok(isk_effect_move(a, "emitter boom", -x, y, &err), &err);
        ok(isk_effect_set(b, "emitter boom", "position", w, &err), &err);
        if (f % 30 == 0) {
            ok(isk_effect_emit(a, "emitter boom", 5, &err), &err);
            ok(isk_effect_emit(b, "emitter boom", 5, &err), &err);
        }
        cr_assert_eq(isk_effect_step_render(a, &ca), ISK_OK);
        cr_assert_eq(isk_effect_step_render(b, &cb), ISK_OK);
    }
    cr_assert_eq(memcmp(ca.pixels, cb.pixels, ca.stride * (size_t)ca.height), 0);
    isk_canvas_free(&ca);
    isk_canvas_free(&cb);
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

/* The keys behind them are part of the definition: saved, read back, and a
 * scene that writes out their defaults is the scene without them. */
Test(control, the_keys_save_and_load)
{
    isk_effect *fx = load(SCENE);
    isk_error err = {0};
    ok(isk_effect_set_active(fx, "emitter sparks", 0, &err), &err);
    ok(isk_effect_set_paused(fx, "emitter boom", 1, &err), &err);
    char *text = NULL;
    ok(isk_scene_write(isk_effect_definition(fx), &text, &err), &err);
    cr_assert_not_null(strstr(text, "active = false"), "%s", text);
    cr_assert_not_null(strstr(text, "paused = true"), "%s", text);
    isk_effect_def d;
    ok(isk_scene_load_string(&d, text, "saved.ini", &err), &err);
    cr_assert_eq(d.emitters[0].born.active, 0);
    cr_assert_eq(d.emitters[2].motion.paused, 1);
    cr_assert_eq(d.emitters[1].born.active, 1);
    isk_effect_def_free(&d);
    free(text);
    isk_effect_destroy(fx);

    char with[2048];
    snprintf(with, sizeof with, "%s", SCENE);
    char *at = strstr(with, "on_death = pops\n");
    memmove(at + strlen("on_death = pops\nactive = true\npaused = false\n"), at + strlen("on_death = pops\n"),
            strlen(at + strlen("on_death = pops\n")) + 1);
    memcpy(at, "on_death = pops\nactive = true\npaused = false\n", strlen("on_death = pops\nactive = true\npaused = false\n"));
    char *plain = scene_text_describe(SCENE), *written = scene_text_describe(with);
    cr_assert_str_eq(plain, written);
    free(plain);
    free(written);
    isk_effect *x = load(SCENE), *y = load(with);
    isk_canvas cx, cy;
    cr_assert_eq(isk_canvas_init(&cx, 120, 90), ISK_OK);
    cr_assert_eq(isk_canvas_init(&cy, 120, 90), ISK_OK);
    cr_assert_eq(isk_effect_run(x, &cx, 100), ISK_OK);
    cr_assert_eq(isk_effect_run(y, &cy, 100), ISK_OK);
    cr_assert_eq(memcmp(cx.pixels, cy.pixels, cx.stride * (size_t)cx.height), 0);
    isk_canvas_free(&cx);
    isk_canvas_free(&cy);
    isk_effect_destroy(x);
    isk_effect_destroy(y);
}
