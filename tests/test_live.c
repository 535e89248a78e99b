/* SPDX-License-Identifier: MIT */
/* Changing a running effect: isk_effect_set / isk_effect_get through the key
 * table, the stage lists following every change, refused values changing
 * nothing, the same sets at the same frames giving the same bytes, keys
 * that apply at reset or only at creation, and potentials added and
 * removed while running. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/keys.h"
#include "iskra/scene.h"
#include "scene_text.h"

/* A fountain with gravity and (zero) drag over a floor, a potential that is
 * off, a deflector, a label: something for every section. */
static const char *const SCENE =
    "[scene]\nwidth = 160\nheight = 120\ndt = 1/60\nseed = 5\n"
    "[view]\nxmin = -8\nxmax = 8\nymin = 0\nymax = 12\n"
    "[force gravity]\ng = 9.81\n"
    "[force air]\nkind = drag\nb = 0\n"
    "[force magnet]\nkind = potential\nk = 40\nposition = 3, 6\nmin_distance = 0.5\nenabled = false\n"
    "[deflector ramp]\nsegment = -6, 2, -2, 1\nrestitution = 0.6\n"
    "[bounds]\nsides = left, right, bottom\nrestitution = 0.5\n"
    "[emitter sparks]\nsource = stream\nposition = 0, 0.5\nlaunch = cone\nangle = 90\nspread = 30\n"
    "speed_min = 6\nspeed_max = 9\nrate = 200\nlife = 2.5\ncapacity = 2000\nforces = gravity, air, magnet\n"
    "deflectors = ramp\n"
    "[emitter cloud]\nsource = explosion\nexplosion = gauss\ncount = 300\nposition = 0, 6\nforces = gravity\n"
    "[drawing label]\nkind = text\nunits = pixels\nposition = 4, 4\ntext = hi\n"
    "[click]\nexplosion = ring\ncount = 50\nemitter = cloud\n";

static isk_effect *load(void) { return scene_text_open(SCENE, 0); }

static char *describe(const isk_effect *fx)
{
    static char buf[8192];
    memset(buf, 0, sizeof buf);
    FILE *f = fmemopen(buf, sizeof buf, "w");
    isk_effect_describe(fx, f);
    fclose(f);
    return buf;
}

static void set_ok(isk_effect *fx, const char *sec, const char *key, const char *value)
{
    isk_error err = {0};
    cr_assert_eq(isk_effect_set(fx, sec, key, value, &err), ISK_OK, "[%s] %s = %s: %s", sec, key, value, err.message);
}

static void set_fails(isk_effect *fx, const char *sec, const char *key, const char *value, const char *msg)
{
    isk_error err = {0};
    cr_assert_neq(isk_effect_set(fx, sec, key, value, &err), ISK_OK, "[%s] %s = %s accepted", sec, key, value);
    cr_assert_str_eq(err.message, msg);
}

static const char *get(const isk_effect *fx, const char *sec, const char *key)
{
    static char buf[512];
    isk_error err = {0};
    cr_assert_eq(isk_effect_get(fx, sec, key, buf, sizeof buf, &err), ISK_OK, "%s", err.message);
    return buf;
}

static void frame(isk_effect *fx, isk_canvas *c, int n)
{
    for (int i = 0; i < n; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_render(fx, c), ISK_OK);
}

Test(live, a_force_enters_and_leaves_the_pipeline)
{
    isk_effect *fx = load();
    cr_assert_null(strstr(describe(fx), "drag"), "%s", describe(fx));
    set_ok(fx, "force air", "b", "0.3");
    cr_assert_not_null(strstr(describe(fx), "drag b=0.3"), "%s", describe(fx));
    cr_assert_str_eq(get(fx, "force air", "b"), "0.3");
    set_ok(fx, "force air", "b", "0");
    cr_assert_null(strstr(describe(fx), "drag"), "%s", describe(fx));
    /* a disabled potential switched on enters; off again, it leaves */
    cr_assert_null(strstr(describe(fx), "potential"));
    set_ok(fx, "force magnet", "enabled", "yes");
    cr_assert_not_null(strstr(describe(fx), "potential 1"), "%s", describe(fx));
    set_ok(fx, "force magnet", "enabled", "off");
    cr_assert_null(strstr(describe(fx), "potential"));
    /* walls and deflectors follow their lists too */
    set_ok(fx, "bounds", "sides", "none");
    cr_assert_null(strstr(describe(fx), "walls"));
    set_ok(fx, "bounds", "sides", "bottom");
    cr_assert_not_null(strstr(describe(fx), "walls     reflect: bottom"), "%s", describe(fx));
    set_ok(fx, "emitter sparks", "deflectors", "none");
    cr_assert_null(strstr(describe(fx), "  deflect "), "%s", describe(fx)); /* the stage, not [deflector NAME] */
    set_ok(fx, "scene", "integrator", "rk4");
    cr_assert_not_null(strstr(describe(fx), "integrate rk4"), "%s", describe(fx));
    set_ok(fx, "emitter cloud", "integrator", "verlet");
    cr_assert_not_null(strstr(describe(fx), "1 substep of verlet"), "%s", describe(fx));
    set_ok(fx, "scene", "substeps", "3");
    cr_assert_not_null(strstr(describe(fx), "3 substeps of rk4"), "%s", describe(fx));
    isk_effect_destroy(fx);
}

/* Refused values: a clear message and nothing changed (the run goes on
 * byte for byte as if nothing had been tried). */
Test(live, refused_values_change_nothing)
{
    isk_effect *a = load(), *b = load();
    isk_canvas ca, cb;
    cr_assert_eq(isk_canvas_init(&ca, 160, 120), ISK_OK);
    cr_assert_eq(isk_canvas_init(&cb, 160, 120), ISK_OK);
    frame(a, &ca, 30);
    frame(b, &cb, 30);
    char before[8192];
    snprintf(before, sizeof before, "%s", describe(b));
    set_fails(b, "emitter sparks", "rate", "1e8",
              "[emitter sparks] rate: expected a number between 0 and 1e7, got \"1e8\"");
    set_fails(b, "emitter sparks", "rat", "5", "[emitter sparks] unknown key 'rat'; did you mean 'rate'?");
    set_fails(b, "emitter spark", "rate", "5", "no emitter named 'spark'; did you mean 'sparks'?");
    set_fails(b, "emiter sparks", "rate", "5",
              "no section type 'emiter'; did you mean 'emitter'? (scene, view, force NAME, deflector NAME, bounds, "
              "emitter NAME, drawing NAME, click)");
    set_fails(b, "force gravity", "b", "1",
              "[force gravity] b: only for kind = drag (this force has kind = gravity)");
    set_fails(b, "emitter cloud", "rate", "5",
              "[emitter cloud] rate: only for source = stream (this emitter has source = explosion)");
    set_fails(b, "scene", "width", "640",
              "[scene] width: is fixed when the effect is created (change the definition and create the effect "
              "again)");
    set_fails(b, "emitter sparks", "source", "layer",
              "[emitter sparks] source: is fixed when the effect is created (change the definition and create the "
              "effect again)");
    set_fails(b, "force air", "b", "nan", "[force air] b: expected a number between 0 and 1e12, got \"nan\"");
    /* checked with the whole definition: a burst larger than the pool */
    set_fails(b, "emitter sparks", "count", "5000", "[emitter sparks] count: a burst of 5000 exceeds the capacity 2000");
    set_fails(b, "emitter sparks", "speed_min", "10", "[emitter sparks] speed_max: must be >= speed_min (10)");
    set_fails(b, "view", "xmax", "-9", "[view] xmin (-8) must be less than xmax (-9)");
    set_fails(b, "click", "count", "20000",
              "[click] count: 20000 is more than emitter 'cloud' accepts in one explosion (its limit is 10000: raise "
              "it)");
    set_fails(b, "emitter sparks", "forces", "gravity, wind", "[emitter sparks] forces: no force named 'wind'");
    set_fails(b, "drawing label", "text",
              "0123456789012345678901234567890123456789012345678901234567890123456789012345678901234567890123456789"
              "0123456789012345678901234567890",
              "[drawing label] text: text longer than 127 characters");
    isk_error err = {0};
    cr_assert_eq(isk_effect_set(NULL, "scene", "dt", "1", &err), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_set(b, NULL, "dt", "1", &err), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_set(b, "scene", "dt", NULL, &err), ISK_ERR_NULL);
    cr_assert_str_eq(describe(b), before);
    cr_assert_str_eq(get(b, "emitter sparks", "rate"), "200");
    cr_assert_str_eq(get(b, "emitter sparks", "forces"), "gravity, air, magnet");
    frame(a, &ca, 60);
    frame(b, &cb, 60);
    cr_assert(isk_canvas_equal(&ca, &cb), "a refused set changed the run");
    isk_canvas_free(&ca);
    isk_canvas_free(&cb);
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

/* A scripted session: the same sets at the same frames give the same
 * bytes; the same sets one frame later give other bytes. */
static void session(isk_canvas *c, int shift)
{
    isk_effect *fx = load();
    for (int f = 0; f < 120; f++) {
        if (f == 20 + shift)
            set_ok(fx, "force air", "b", "0.8");
        if (f == 40 + shift)
            set_ok(fx, "emitter sparks", "position", "-3, 1");
        if (f == 50 + shift)
            set_ok(fx, "force magnet", "enabled", "true");
        if (f == 60 + shift)
            set_ok(fx, "force magnet", "position", "-2, 4");
        if (f == 70 + shift)
            set_ok(fx, "scene", "dt", "1/120");
        if (f == 80 + shift)
            set_ok(fx, "emitter sparks", "rate", "500");
        if (f == 90 + shift)
            set_ok(fx, "emitter sparks", "color", "#40c0ff");
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    }
    cr_assert_eq(isk_effect_render(fx, c), ISK_OK);
    isk_effect_destroy(fx);
}

Test(live, same_sets_same_frames_same_bytes)
{
    isk_canvas a, b, c;
    cr_assert_eq(isk_canvas_init(&a, 160, 120), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 160, 120), ISK_OK);
    cr_assert_eq(isk_canvas_init(&c, 160, 120), ISK_OK);
    session(&a, 0);
    session(&b, 0);
    session(&c, 1);
    cr_assert(isk_canvas_equal(&a, &b));
    cr_assert_not(isk_canvas_equal(&a, &c));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_canvas_free(&c);
}

/* Every key reads back what it holds, and setting that text again is
 * accepted and changes nothing (the text round-trips bit for bit). */
Test(live, every_key_gets_and_sets_back)
{
    isk_effect *fx = load();
    const isk_effect_def *d = isk_effect_definition(fx);
    int checked = 0;
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        char sec[64];
        const char *name = NULL;
        switch (k->section) {
        case ISK_SECTION_FORCE: name = strcmp(k->name, "g") ? (strcmp(k->name, "b") ? "magnet" : "air") : "gravity"; break;
        case ISK_SECTION_DEFLECTOR: name = "ramp"; break;
        case ISK_SECTION_EMITTER: name = "sparks"; break;
        case ISK_SECTION_DRAWING: name = "label"; break;
        case ISK_SECTION_PROBE: continue; /* this scene has none; fixed at create (tests/test_probes.c) */
        default: break;
        }
        snprintf(sec, sizeof sec, "%s%s%s", isk_section_name(k->section), name ? " " : "", name ? name : "");
        char v[512], w[512];
        isk_error err = {0};
        if (isk_effect_get(fx, sec, k->name, v, sizeof v, &err) != ISK_OK) {
            cr_assert_not_null(strstr(err.message, "only for"), "[%s] %s: %s", sec, k->name, err.message);
            continue;
        }
        isk_effect_def before = *d;
        isk_status s = isk_effect_set(fx, sec, k->name, v, &err);
        if (k->create_only) {
            cr_assert_neq(s, ISK_OK, "%s", k->name);
            continue;
        }
        cr_assert_eq(s, ISK_OK, "[%s] %s = %s: %s", sec, k->name, v, err.message);
        cr_assert_eq(isk_effect_get(fx, sec, k->name, w, sizeof w, &err), ISK_OK);
        cr_assert_str_eq(v, w, "[%s] %s", sec, k->name);
        cr_assert_eq(memcmp(&before, d, sizeof before), 0, "[%s] %s = %s changed the definition", sec, k->name, v);
        checked++;
    }
    cr_assert_gt(checked, 60);
    char tiny[3];
    isk_error err = {0};
    cr_assert_eq(isk_effect_get(fx, "emitter sparks", "forces", tiny, sizeof tiny, &err), ISK_ERR_SIZE);
    cr_assert_eq(isk_effect_get(fx, "emitter sparks", "forces", tiny, 0, &err), ISK_ERR_SIZE);
    isk_effect_destroy(fx);
}

/* "at reset" keys are kept and shape the next reset's particles. */
Test(live, reset_keys_apply_at_reset)
{
    isk_effect *fx = load();
    cr_assert_eq(isk_effect_particles(fx, 1)->count, 300);
    set_ok(fx, "emitter cloud", "count", "120");
    cr_assert_str_eq(get(fx, "emitter cloud", "count"), "120");
    cr_assert_eq(isk_effect_particles(fx, 1)->count, 300, "an explosion is not re-fired by a set");
    cr_assert_eq(isk_effect_reset(fx), ISK_OK);
    cr_assert_eq(isk_effect_particles(fx, 1)->count, 120);
    isk_effect_destroy(fx);
}

/* A stream's rate changed mid-run: no catch-up burst, no gap; the births
 * of the second second follow the new rate. */
Test(live, stream_rate_changes_without_a_burst)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "s");
    e->born.source = ISK_SOURCE_STREAM;
    e->born.rate = 60;
    e->born.capacity = 100000;
    isk_effect *fx = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    for (int i = 0; i < 60; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 60);
    set_ok(fx, "emitter s", "rate", "600");
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 70, "one frame at 600/s");
    for (int i = 1; i < 60; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 660);
    set_ok(fx, "emitter s", "rate", "0");
    for (int i = 0; i < 30; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 660);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* A live position moves a stream's births and a potential (and a
 * potential's other keys leave its live position alone). */
Test(live, positions_of_streams_and_potentials)
{
    isk_effect *fx = load();
    set_ok(fx, "emitter sparks", "speed_min", "0");
    set_ok(fx, "emitter sparks", "speed_max", "0");
    set_ok(fx, "emitter sparks", "forces", "none");
    set_ok(fx, "emitter sparks", "position", "5, 7");
    /* The next frame's births spread along the way from (0, 0.5) to (5, 7),
     * so an emitter moved live leaves no gap; the later ones are there. */
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    const isk_particles *p = isk_effect_particles(fx, 0);
    const size_t first = p->count;
    cr_assert_gt(first, 1);
    for (size_t i = 0; i < first; i++) {
        double f = p->x[i] / 5;
        cr_assert(f > 0 && f <= 1 && fabs(p->y[i] - (0.5 + 6.5 * f)) < 1e-12, "%zu at (%g, %g)", i, p->x[i], p->y[i]);
    }
    for (int i = 1; i < 10; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_gt(p->count, first);
    for (size_t i = first; i < p->count; i++)
        cr_assert(p->x[i] == 5 && p->y[i] == 7, "%zu at (%g, %g)", i, p->x[i], p->y[i]);

    set_ok(fx, "force magnet", "velocity", "1, 0");
    set_ok(fx, "force magnet", "enabled", "true");
    size_t n;
    const isk_potential *pot = isk_effect_potentials(fx, &n);
    cr_assert_eq(n, 1);
    cr_assert(pot[0].r.x == 3 && pot[0].r.y == 6);
    for (int i = 0; i < 60; i++) /* moves by velocity*dt at the start of every step (the previous frame's move) */
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    pot = isk_effect_potentials(fx, &n);
    cr_assert_float_eq(pot[0].r.x, 4, 1e-12, "%.17g", pot[0].r.x);
    set_ok(fx, "force magnet", "k", "80");
    pot = isk_effect_potentials(fx, &n);
    cr_assert_float_eq(pot[0].r.x, 4, 1e-12, "k keeps the live position");
    cr_assert_eq(pot[0].k, 80);
    set_ok(fx, "force magnet", "position", "-1, 2");
    pot = isk_effect_potentials(fx, &n);
    cr_assert(pot[0].r.x == -1 && pot[0].r.y == 2);
    isk_effect_destroy(fx);
}

Test(live, potentials_added_and_removed_while_running)
{
    isk_effect *fx = load();
    isk_potential pot;
    isk_potential_init(&pot, 300, isk_vec2_make(0, 9), 1);
    pot.min_dist = 0.3;
    isk_error err = {0};
    cr_assert_eq(isk_effect_add_potential(fx, "added", &pot, &err), ISK_OK, "%s", err.message);
    size_t n;
    const isk_potential *p = isk_effect_potentials(fx, &n);
    cr_assert_eq(n, 2);
    cr_assert_eq(p[1].id, 2);
    cr_assert_not_null(strstr(describe(fx), "potential 2"), "%s", describe(fx));
    cr_assert_str_eq(get(fx, "force added", "k"), "300");
    cr_assert_str_eq(get(fx, "emitter cloud", "forces"), "gravity, added");
    /* it pulls: the cloud's centre of mass rises towards it */
    for (int i = 0; i < 30; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    const isk_particles *c = isk_effect_particles(fx, 1);
    double sy = 0;
    for (size_t i = 0; i < c->count; i++)
        sy += c->y[i];
    cr_assert_gt(sy / (double)c->count, 6.0);
    cr_assert_neq(isk_effect_add_potential(fx, "added", &pot, &err), ISK_OK);
    cr_assert_str_eq(err.message, "[force added]: a force of that name exists");
    cr_assert_neq(isk_effect_add_potential(fx, "a b", &pot, &err), ISK_OK);
    pot.k = NAN;
    cr_assert_neq(isk_effect_add_potential(fx, "nan", &pot, &err), ISK_OK);
    cr_assert_eq(isk_effect_remove_force(fx, "added", &err), ISK_OK, "%s", err.message);
    cr_assert_null(strstr(describe(fx), "potential 2"));
    cr_assert_str_eq(get(fx, "emitter cloud", "forces"), "gravity");
    cr_assert_eq(isk_effect_remove_force(fx, "gravity", &err), ISK_OK);
    cr_assert_str_eq(get(fx, "emitter sparks", "forces"), "air, magnet");
    cr_assert_neq(isk_effect_remove_force(fx, "gravty", &err), ISK_OK);
    cr_assert_str_eq(err.message, "no force named 'gravty'"); /* gravity is gone: nothing close */
    isk_effect_destroy(fx);
}
