/* SPDX-License-Identifier: MIT */
/* The effect's clock and prewarm.
 *
 * prewarm: the whole effect is built before any frame runs, so a stream
 * that prewarms may name sub-emitters defined before or after it, and frame
 * 0 of an effect prewarmed by T holds what frame T/dt holds without it,
 * children and trails included, byte for byte: for every preset, and for
 * chains of sub-emitters in either order.
 *
 * The clock: a frame advances it by the step actually taken (dt /
 * speed_divisor at that frame), so live changes of either never rewrite the
 * time already elapsed: the clock only moves forward, and a stream's births
 * follow rate x simulated time through any sequence of changes. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/presets.h"
#include "iskra/rng.h"
#include "iskra/scene.h"
#include "scene_text.h"

/* The renders and every group's particles are the same, byte for byte. */
static void assert_same(isk_effect *a, isk_effect *b, const char *what)
{
    const isk_effect_def *d = isk_effect_definition(a);
    isk_canvas ca, cb;
    cr_assert_eq(isk_canvas_init(&ca, d->width, d->height), ISK_OK);
    cr_assert_eq(isk_canvas_init(&cb, d->width, d->height), ISK_OK);
    cr_assert_eq(isk_effect_render(a, &ca), ISK_OK);
    cr_assert_eq(isk_effect_render(b, &cb), ISK_OK);
    cr_assert(!memcmp(ca.pixels, cb.pixels, (size_t)ca.stride * (size_t)ca.height), "%s: the renders differ", what);
    isk_canvas_free(&ca);
    isk_canvas_free(&cb);
    for (int g = 0; g < isk_effect_emitter_count(a); g++) {
        const isk_particles *p = isk_effect_particles(a, g), *q = isk_effect_particles(b, g);
        cr_assert_eq(p->count, q->count, "%s, emitter %d: %zu particles against %zu", what, g, p->count, q->count);
        const size_t n = p->count * sizeof(double);
        cr_assert(!memcmp(p->x, q->x, n) && !memcmp(p->y, q->y, n) && !memcmp(p->vx, q->vx, n) &&
                      !memcmp(p->vy, q->vy, n) && !memcmp(p->age, q->age, n) && !memcmp(p->life, q->life, n),
                  "%s, emitter %d: the particles differ", what, g);
        cr_assert_eq(isk_effect_dropped(a, g), isk_effect_dropped(b, g), "%s, emitter %d: drops differ", what, g);
    }
}

/* `warm` (prewarmed by `frames`) at frame 0 against `cold` at that frame,
 * and both again 15 frames on. */
static void assert_prewarm_is_frames(isk_effect *warm, isk_effect *cold, long frames, const char *what)
{
    cr_assert_eq(isk_effect_frame(warm), 0, "%s", what);
    cr_assert_eq(isk_effect_time(warm), 0.0, "%s: frame 0's time stays 0", what);
    for (long i = 0; i < frames; i++)
        cr_assert_eq(isk_effect_step(cold), ISK_OK);
    assert_same(warm, cold, what);
    for (int i = 0; i < 15; i++) {
        cr_assert_eq(isk_effect_step(warm), ISK_OK);
        cr_assert_eq(isk_effect_step(cold), ISK_OK);
    }
    assert_same(warm, cold, what);
}

static isk_effect *open_preset(const char *preset, const char *prewarm)
{
    char text[512];
    snprintf(text, sizeof text,
             "[scene]\nwidth = 160\nheight = 120\nseed = 9\n[view]\nxmin = -4\nxmax = 4\nymin = -2\nymax = 4\n"
             "[emitter it]\npreset = %s\n%s\n",
             preset, prewarm);
    return scene_text_open(text, 0);
}

/* Every preset; fireworks and rain feed sub-emitters (on_death, on_hit)
 * that are defined after them: this crashed at load. */
Test(prewarm, every_preset_frame_0_is_frame_n, .timeout = 120)
{
    cr_assert_geq(isk_preset_count(), 10);
    for (int i = 0; i < isk_preset_count(); i++) {
        const char *name = isk_preset_name(i);
        isk_effect *warm = open_preset(name, "prewarm = 1.5"); /* 90 frames at the default 1/60 */
        isk_effect *cold = open_preset(name, "");
        assert_prewarm_is_frames(warm, cold, 90, name);
        isk_effect_destroy(warm);
        isk_effect_destroy(cold);
    }
}

/* The sub-emitters of fireworks and rain have children at frame 0. */
Test(prewarm, children_are_there_at_frame_0)
{
    static const char *const presets[] = {"fireworks", "rain"};
    for (int i = 0; i < 2; i++) {
        isk_effect *fx = open_preset(presets[i], "prewarm = 3");
        cr_assert_eq(isk_effect_emitter_count(fx), 2, "%s", presets[i]);
        cr_assert_gt(isk_effect_particles(fx, 1)->count, 0, "%s: no children at frame 0", presets[i]);
        isk_effect_destroy(fx);
    }
}

/* A chain: a stream whose deaths feed sub-emitter `a`, whose deaths feed
 * sub-emitter `b`; `b` also takes the stream's bounces on a floor.  Built
 * in either order, with trails and a turbulence (the field's clock); the
 * fourth item, a stream that does not prewarm, only where asked. */
static const char *chain_items[] = {
    "[emitter root]\nsource = stream\nrate = 40\nlaunch = cone\nangle = 90\nspread = 50\nspeed_min = 2\n"
    "speed_max = 4\nlife = 0.6\nlife_range = 0.4\nforces = g, swirl\ndeflectors = floor\non_death = a\non_hit = b\n"
    "trail = 5\ntrail_width = 2\ndraw = disc\nsize = 0.1\n%s\n",
    "[emitter a]\nsource = sub\ncount = 4\nlaunch = disc\nspeed_max = 1.5\nlife = 0.4\nforces = g\non_death = b\n"
    "inherit = 0.3\ncolor = orange\ntrail = 3\n",
    "[emitter b]\nsource = sub\ncount = 2\nlaunch = disc\nspeed_max = 0.5\nlife = 0.3\nforces = swirl\n"
    "color = cyan\n",
    "[emitter other]\nsource = stream\nrate = 10\nlaunch = disc\nspeed_max = 1\nlife = 2\ncolor = white\n",
};

static isk_effect *open_chain(const int *order, int n, const char *prewarm)
{
    char text[4096], item[1024];
    int len = snprintf(text, sizeof text,
                       "[scene]\nwidth = 120\nheight = 90\nseed = 3\ndt = 1/50\n[view]\nxmin = -3\nxmax = 3\n"
                       "ymin = -1\nymax = 3.5\n[force g]\nkind = gravity\ng = 5\n[force swirl]\nkind = turbulence\n"
                       "strength = 2\nscale = 1\nspeed = 0.5\n[deflector floor]\nsegment = -3, 0, 3, 0\n"
                       "restitution = 0.6\n");
    for (int k = 0; k < n; k++) {
        snprintf(item, sizeof item, chain_items[order[k]], prewarm);
        len += snprintf(text + len, sizeof text - (size_t)len, "%s", item);
    }
    cr_assert_lt(len, (int)sizeof text);
    return scene_text_open(text, 0);
}

static int emitter_named(const isk_effect *fx, const char *name)
{
    const isk_effect_def *d = isk_effect_definition(fx);
    for (int g = 0; g < d->nemitters; g++)
        if (!strcmp(d->emitters[g].name, name))
            return g;
    cr_assert_fail("no emitter %s", name);
    return -1;
}

Test(prewarm, a_chain_of_sub_emitters_in_either_order, .timeout = 60)
{
    static const int orders[][3] = {{0, 1, 2}, {2, 1, 0}, {1, 0, 2}};
    for (int o = 0; o < 3; o++) {
        char what[64];
        snprintf(what, sizeof what, "order %d%d%d", orders[o][0], orders[o][1], orders[o][2]);
        isk_effect *warm = open_chain(orders[o], 3, "prewarm = 2"); /* 100 frames */
        isk_effect *cold = open_chain(orders[o], 3, "");
        cr_assert_gt(isk_effect_particles(warm, emitter_named(warm, "b"))->count, 0,
                     "%s: the chain's end is empty at frame 0", what);
        assert_prewarm_is_frames(warm, cold, 100, what);
        isk_effect_destroy(warm);
        isk_effect_destroy(cold);
    }
}

/* An emitter that does not prewarm starts at frame 0, with its own
 * particles, whatever the others do. */
Test(prewarm, only_the_prewarmed_chain_runs_ahead)
{
    static const int order[4] = {3, 2, 0, 1};
    isk_effect *warm = open_chain(order, 4, "prewarm = 2");
    isk_effect *cold = open_chain(order, 4, "");
    const int other = emitter_named(warm, "other");
    cr_assert_eq(isk_effect_particles(warm, other)->count, 0);
    for (int i = 0; i < 30; i++) {
        cr_assert_eq(isk_effect_step(warm), ISK_OK);
        cr_assert_eq(isk_effect_step(cold), ISK_OK);
    }
    const isk_particles *p = isk_effect_particles(warm, other), *q = isk_effect_particles(cold, other);
    cr_assert_eq(p->count, q->count);
    cr_assert_gt(p->count, 0);
    cr_assert(!memcmp(p->x, q->x, p->count * sizeof(double)) && !memcmp(p->y, q->y, p->count * sizeof(double)));
    isk_effect_destroy(warm);
    isk_effect_destroy(cold);
}

/* A sub-emitter runs as long as the prewarm that feeds it: its substeps
 * are bounded with the prewarm's, and the message says so. */
Test(prewarm, a_sub_emitter_fed_by_a_long_prewarm_is_bounded)
{
    isk_effect_def d;
    isk_error err;
    cr_assert_neq(isk_scene_load_string(&d,
                                       "[emitter root]\nsource = stream\nrate = 1\nlife = 1\nprewarm = 100\n"
                                       "on_death = spark\n[emitter spark]\nsource = sub\ncount = 1\nsubsteps = 1000\n",
                                       "t.ini", &err),
                 ISK_OK);
    cr_assert(strstr(err.message, "t.ini:10:") && strstr(err.message, "[emitter spark]") &&
                  strstr(err.message, "prewarm 6000 frames, 6000000 of its substeps"),
              "%s", err.message);
}

/* ---- the clock ------------------------------------------------------------ */

static isk_effect *open_stream(void)
{
    return scene_text_open("[scene]\ndt = 1/60\n[emitter s]\nsource = stream\nrate = 100\nlife = 1e9\n"
                           "capacity = 1000000\nlaunch = disc\nspeed_max = 1\n",
                           0);
}

static void set(isk_effect *fx, const char *key, double v)
{
    char text[64];
    isk_error err;
    snprintf(text, sizeof text, "%.17g", v);
    cr_assert_eq(isk_effect_set(fx, "scene", key, text, &err), ISK_OK, "%s = %s: %s", key, text, err.message);
}

/* Slowing down and back: the clock goes on from where it was. */
Test(clock, the_speed_divisor_never_rewrites_elapsed_time)
{
    isk_effect *fx = open_stream();
    for (int i = 0; i < 120; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_float_eq(isk_effect_time(fx), 2.0, 1e-12);
    cr_assert_eq(isk_effect_particle_count(fx), 200);
    set(fx, "speed_divisor", 30);
    cr_assert_float_eq(isk_effect_time(fx), 2.0, 1e-12, "setting the divisor moved the clock");
    for (int i = 0; i < 90; i++) /* 90 frames of 1/1800 s: 0.05 s */
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_float_eq(isk_effect_time(fx), 2.05, 1e-12);
    cr_assert_eq(isk_effect_particle_count(fx), 205, "the stream stopped or raced in slow motion");
    set(fx, "speed_divisor", 1);
    for (int i = 0; i < 60; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_float_eq(isk_effect_time(fx), 3.05, 1e-12);
    cr_assert_eq(isk_effect_particle_count(fx), 305, "a second at full speed is 100 births");
    isk_effect_destroy(fx);
}

/* Any sequence of live dt and speed_divisor changes: a clock that only
 * moves forward by the step taken, and births = rate x time, within one
 * per change. */
Test(clock, births_follow_simulated_time_through_any_changes)
{
    for (uint64_t seed = 1; seed <= 8; seed++) {
        isk_effect *fx = open_stream();
        isk_rng rng;
        isk_rng_seed(&rng, seed);
        double want = 0.0, last = isk_effect_time(fx);
        int changes = 0;
        for (int f = 0; f < 600; f++) {
            const double u = isk_rng_uniform(&rng);
            if (u < 0.05) {
                set(fx, "speed_divisor", 1.0 + 59.0 * isk_rng_uniform(&rng));
                changes++;
            } else if (u < 0.10) {
                set(fx, "dt", 1.0 / (10.0 + 230.0 * isk_rng_uniform(&rng)));
                changes++;
            }
            const isk_effect_def *d = isk_effect_definition(fx);
            want += d->dt / d->speed_divisor;
            cr_assert_eq(isk_effect_step(fx), ISK_OK);
            const double now = isk_effect_time(fx);
            cr_assert_gt(now, last, "seed %llu frame %d: the clock went from %.17g to %.17g",
                         (unsigned long long)seed, f, last, now);
            cr_assert_float_eq(now, want, 1e-9 * (1.0 + want), "seed %llu frame %d: %.17g, stepped %.17g",
                               (unsigned long long)seed, f, now, want);
            last = now;
        }
        const double births = (double)isk_effect_particle_count(fx);
        cr_assert_gt(changes, 20);
        cr_assert(fabs(births - 100.0 * want) <= 1.0 + changes, "seed %llu: %g births in %.6g s with %d changes",
                  (unsigned long long)seed, births, want, changes);
        isk_effect_destroy(fx);
    }
}

/* A change of speed while prewarmed: the prewarmed group's clock keeps its
 * lead, and both go on at the new step. */
Test(clock, a_prewarmed_group_keeps_its_lead)
{
    isk_effect *fx = scene_text_open("[scene]\ndt = 1/60\n[emitter s]\nsource = stream\nrate = 100\nlife = 1e9\n"
                                     "capacity = 100000\nprewarm = 1\n",
                                     0);
    cr_assert_eq(isk_effect_particle_count(fx), 100);
    for (int i = 0; i < 30; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    set(fx, "speed_divisor", 10);
    for (int i = 0; i < 60; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_float_eq(isk_effect_time(fx), 0.6, 1e-12);
    cr_assert_eq(isk_effect_particle_count(fx), 160);
    isk_effect_destroy(fx);
}
