/* SPDX-License-Identifier: MIT */
/* How emitters and particles move: what every key owes
 * (tests/key_case.h): with it the bytes differ, at its default they are
 * today's, a bad value is refused with FILE:LINE and the CLI exits 2; and
 * each stage is in an emitter's lists only when that emitter uses it. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "key_case.h"
#include "scene_text.h"

static const char *base = "[scene]\nwidth = 64\nheight = 48\nseed = 3\n"
                          "[emitter e]\nsource = stream\nrate = 200\nlaunch = disc\nspeed_max = 4\n%s\n";
/* a moving emitter (local space needs a motion to show) */
static const char *moving = "[scene]\nwidth = 64\nheight = 48\nseed = 3\n"
                            "[emitter e]\nsource = stream\nrate = 200\nlaunch = disc\nspeed_max = 2\n"
                            "position = -6, 0\nemitter_velocity = 12, 0\n%s\n";
/* a short cycle (loop needs a duration to restart) */
static const char *cycle = "[scene]\nwidth = 64\nheight = 48\nseed = 3\n"
                           "[emitter e]\nsource = stream\nrate = 200\nlaunch = disc\nspeed_max = 4\n"
                           "life = 0.3\nduration = 0.2\ncount = 20\n%s\n";
/* a turbulence force the emitter uses */
static const char *stirred = "[scene]\nwidth = 64\nheight = 48\nseed = 3\n"
                             "[force t]\nkind = turbulence\nstrength = 20\n%s\n"
                             "[emitter e]\nsource = stream\nrate = 200\nlaunch = disc\nspeed_max = 1\n"
                             "forces = t\n";
static const char *unstirred = "[scene]\nwidth = 64\nheight = 48\nseed = 3\n"
                               "[force t]\nkind = turbulence\n%s\n"
                               "[emitter e]\nsource = stream\nrate = 200\nlaunch = disc\nspeed_max = 1\n"
                               "forces = t\n";

Test(fx_motion_keys, radial_and_tangential)
{
    key_case_differs(base, "radial_accel = -30", 30);
    key_case_same(base, "radial_accel = 0", 30);
    key_case_rejects(base, "radial_accel = nan", "radial_accel");
    key_case_rejects(base, "radial_accel = 1e13", "radial_accel");
    key_case_differs(base, "tangential_accel = 30", 30);
    key_case_same(base, "tangential_accel = 0", 30);
    key_case_rejects(base, "tangential_accel = inf", "tangential_accel");
}

Test(fx_motion_keys, turbulence)
{
    key_case_differs(unstirred, "strength = 20", 30);
    key_case_same(unstirred, "strength = 0", 30);
    key_case_differs(stirred, "scale = 0.5", 30);
    key_case_same(stirred, "scale = 1", 30);
    key_case_differs(stirred, "speed = 3", 30);
    key_case_same(stirred, "speed = 0", 30);
    key_case_rejects(unstirred, "strength = nan", "strength");
    key_case_rejects(stirred, "scale = 0", "scale");
    key_case_rejects(stirred, "scale = -2", "scale");
    key_case_rejects(stirred, "speed = 1e300", "speed");
}

Test(fx_motion_keys, emitter_velocity_and_space)
{
    key_case_differs(base, "emitter_velocity = 12, 0", 30);
    key_case_same(base, "emitter_velocity = 0, 0", 30);
    key_case_rejects(base, "emitter_velocity = 1e200, 0", "emitter_velocity");
    key_case_rejects(base, "emitter_velocity = nan, 0", "emitter_velocity");
    key_case_differs(moving, "space = local", 30);
    key_case_same(moving, "space = world", 30);
    key_case_rejects(moving, "space = galaxy", "space");
}

Test(fx_motion_keys, duration_and_loop)
{
    key_case_differs(base, "duration = 0.1", 30);
    key_case_same(base, "duration = 0", 30);
    key_case_rejects(base, "duration = -1", "duration");
    key_case_rejects(base, "duration = 1e300", "duration");
    key_case_rejects(base, "duration = nan", "duration");
    key_case_differs(cycle, "loop = true", 40);
    key_case_same(cycle, "loop = false", 40);
    key_case_rejects(cycle, "loop = maybe", "loop");
}

Test(fx_motion_keys, prewarm)
{
    key_case_differs(base, "prewarm = 0.5", 0);
    key_case_same(base, "prewarm = 0", 30);
    key_case_rejects(base, "prewarm = -1", "prewarm");
    key_case_rejects(base, "prewarm = 1e9", "prewarm");
    /* in range, but too many steps at this dt (iskra/limits.h) */
    key_case_rejects("[scene]\nwidth = 64\nheight = 48\ndt = 1e-4\n[emitter e]\nsource = stream\nrate = 20\n%s\n",
                     "prewarm = 3000", "prewarm");
}

static char *describe(const char *base_text, const char *line)
{
    char text[2048];
    snprintf(text, sizeof text, base_text, line);
    return scene_text_describe(text);
}

/* A stage is in the lists only for an emitter that uses it. */
Test(fx_motion_keys, stages_only_when_used)
{
    char *plain = describe(base, "");
    cr_assert_null(strstr(plain, "field"), "%s", plain);
    cr_assert_null(strstr(plain, "carry"), "%s", plain);
    cr_assert_null(strstr(plain, "path"), "%s", plain);
    free(plain);
    char *s = describe(base, "radial_accel = -3");
    cr_assert_not_null(strstr(s, "field     radial -3"), "%s", s);
    cr_assert_null(strstr(s, "tangential"), "%s", s);
    free(s);
    s = describe(base, "tangential_accel = 2");
    cr_assert_not_null(strstr(s, "tangential 2 (counter-clockwise)"), "%s", s);
    free(s);
    s = describe(unstirred, "strength = 0");
    cr_assert_null(strstr(s, "field"), "a zero-strength turbulence is in no list: %s", s);
    free(s);
    s = describe(stirred, "scale = 2");
    cr_assert_not_null(strstr(s, "turbulence strength 20 scale 2 speed 0"), "%s", s);
    free(s);
    s = describe(moving, "space = local");
    cr_assert_not_null(strstr(s, "carry"), "%s", s);
    cr_assert_not_null(strstr(s, "along the emitter's path at (12, 0)/s"), "%s", s);
    free(s);
    s = describe(moving, "");
    cr_assert_null(strstr(s, "carry"), "%s", s);
    free(s);
    s = describe(base, "prewarm = 0.25");
    cr_assert_not_null(strstr(s, "prewarmed 15 frames"), "%s", s);
    free(s);
    s = describe(cycle, "loop = true");
    cr_assert_not_null(strstr(s, "for 0.2 s in a loop"), "%s", s);
    free(s);
}

/* Reachable from C: the fields, with the key table's defaults and checks. */
Test(fx_motion_keys, from_c)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    int t = isk_effect_def_add_force(&d, "swirl", ISK_FORCE_TURBULENCE);
    cr_assert_geq(t, 0);
    cr_assert(d.forces[t].scale == 1 && d.forces[t].strength == 0 && d.forces[t].speed == 0);
    d.forces[t].strength = 3;
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "e");
    cr_assert_not_null(e);
    cr_assert(e->motion.radial_accel == 0 && e->motion.tangential_accel == 0 && e->born.space == ISK_SPACE_WORLD &&
              e->born.duration == 0 && !e->born.loop && e->born.prewarm == 0 && e->born.emitter_velocity.x == 0);
    e->born.source = ISK_SOURCE_STREAM;
    e->born.rate = 100;
    e->motion.radial_accel = -2;
    e->born.emitter_velocity = isk_vec2_make(1, 0);
    e->born.space = ISK_SPACE_LOCAL;
    e->born.duration = 1;
    e->born.loop = 1;
    e->born.prewarm = 0.5;
    cr_assert_eq(isk_emitter_use_force(e, t), ISK_OK);
    isk_effect *fx;
    isk_error err;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    cr_assert_gt(isk_effect_particle_count(fx), 40, "prewarmed");
    isk_effect_destroy(fx);
    /* the same checks as a file's */
    const struct {
        const char *what;
        double *field;
        double bad;
    } cases[] = {{"radial_accel", &d.emitters[0].motion.radial_accel, NAN},
                 {"tangential_accel", &d.emitters[0].motion.tangential_accel, 1e300},
                 {"duration", &d.emitters[0].born.duration, -1},
                 {"prewarm", &d.emitters[0].born.prewarm, 1e5},
                 {"scale", &d.forces[t].scale, 0}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double keep = *cases[i].field;
        *cases[i].field = cases[i].bad;
        cr_assert_neq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s accepted", cases[i].what);
        cr_assert_not_null(strstr(err.message, cases[i].what), "%s", err.message);
        *cases[i].field = keep;
    }
    d.dt = 1e-4; /* 0.5 s: 5000 steps, fine; 20 s: 200,000, too many */
    d.emitters[0].born.prewarm = 20;
    cr_assert_neq(isk_effect_create(&fx, &d, &err), ISK_OK);
    cr_assert_not_null(strstr(err.message, "prewarm"), "%s", err.message);
    isk_effect_def_free(&d);
}
