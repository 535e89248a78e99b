/* SPDX-License-Identifier: MIT */
/* A stream's time.  `duration` emits floor(rate*duration)
 * particles per cycle and `loop` restarts the cycle, bursts included (the
 * counts are exact, at any step); `prewarm` runs whole frames before frame
 * 0, so a prewarmed fire's frame 0 is the un-prewarmed fire's frame N,
 * byte for byte and state for state, while the clock still reads 0. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "scene_text.h"

static isk_effect *open_text(const char *text) { return scene_text_open(text, 0); }

/* rate 50/s and bursts of 7 unless `extra` says otherwise */
static size_t count_after(const char *dt, long frames, const char *extra)
{
    char text[1024];
    snprintf(text, sizeof text,
             "[scene]\ndt = %s\n[emitter e]\nsource = stream\nduration = 0.4\ncapacity = 100000\n%s\n%s%s",
             dt, extra, strstr(extra, "rate") ? "" : "rate = 50\n", strstr(extra, "count") ? "" : "count = 7\n");
    isk_effect *fx = open_text(text);
    for (long i = 0; i < frames; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    size_t n = isk_effect_particle_count(fx);
    cr_assert_eq(isk_effect_dropped(fx, 0), 0);
    isk_effect_destroy(fx);
    return n;
}

Test(fx_motion_time, duration_counts_are_exact)
{
    /* one cycle: 50 * 0.4 = 20 births and the burst at start, then nothing */
    cr_assert_eq(count_after("1/60", 60, ""), 27);
    cr_assert_eq(count_after("1/60", 600, ""), 27);
    cr_assert_eq(count_after("1/30", 300, ""), 27);
    cr_assert_eq(count_after("1/60", 12, ""), 7 + 10); /* at 0.2 s: half the cycle */
}

Test(fx_motion_time, loop_restarts_births_and_bursts)
{
    /* at 1.9 s: 4 whole cycles (80) + 15 of the fifth; bursts at 0, .4, .8, 1.2, 1.6 */
    cr_assert_eq(count_after("1/60", 114, "loop = true"), 95 + 35);
    /* at 2 s the sixth cycle's burst is due; the same at 30 and 144 steps/s */
    cr_assert_eq(count_after("1/60", 120, "loop = true"), 100 + 42);
    cr_assert_eq(count_after("1/30", 60, "loop = true"), 100 + 42);
    cr_assert_eq(count_after("1/144", 288, "loop = true"), 100 + 42);
    /* bursts every 0.15 s within a cycle of 0.4: at 0, .15, .3 (three per cycle) */
    cr_assert_eq(count_after("1/60", 120, "loop = true\nburst_every = 0.15"), 100 + 5 * 21 + 7);
    /* a start shifts every cycle */
    cr_assert_eq(count_after("1/60", 60, "loop = true\nstart = 0.5"), 20 + 5 + 14);
    /* rate * duration not whole: floor(45 * 0.4) = 18 per cycle */
    cr_assert_eq(count_after("1/60", 120, "loop = true\nrate = 45\ncount = 0"), 5 * 18);
}

/* A full pool: the drops are counted, the cycles go on. */
Test(fx_motion_time, a_full_pool_drops_and_counts)
{
    isk_effect *fx = open_text("[scene]\ndt = 1/60\n[emitter e]\nsource = stream\nrate = 50\nduration = 0.4\n"
                               "count = 7\nloop = true\ncapacity = 30\n");
    for (int i = 0; i < 120; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 30);
    cr_assert_eq(isk_effect_dropped(fx, 0), 142 - 30);
    isk_effect_destroy(fx);
}

static const char *fire = "[scene]\nseed = 5\nwidth = 160\nheight = 120\ndt = 1/60\nsubsteps = 2\n"
                          "[force swirl]\nkind = turbulence\nstrength = 3\nscale = 1\nspeed = 0.7\n"
                          "[emitter flame]\nsource = stream\nrate = 400\nshape = disc\nshape_a = 1\n"
                          "launch = cone\nangle = 90\nspread = 40\nspeed_min = 1\nspeed_max = 3\nlife = 1\n"
                          "life_range = 0.5\nweight = 2\nforces = swirl\ndraw = disc\nsize = 0.4\nblend = add\n"
                          "color_over_life = 0:#ffdd55, 1:#aa220000\nosc_omega = 3, 6\nosc_amplitude = 0.1, 0.3\n"
                          "emitter_velocity = 0.5, 0\n%s\n"
                          "[emitter embers]\nsource = stream\nrate = 60\nlaunch = disc\nspeed_max = 2\nlife = 0.8\n"
                          "color = orange\n%s\n";

static isk_effect *open_fire(const char *flame, const char *embers)
{
    char text[2048];
    snprintf(text, sizeof text, fire, flame, embers);
    return open_text(text);
}

static void assert_same_state(const isk_particles *p, const isk_particles *q)
{
    cr_assert_eq(p->count, q->count);
    cr_assert_gt(p->count, 0);
    const size_t b = p->count * sizeof(double);
    cr_assert(!memcmp(p->x, q->x, b) && !memcmp(p->y, q->y, b) && !memcmp(p->vx, q->vx, b) &&
              !memcmp(p->vy, q->vy, b) && !memcmp(p->age, q->age, b) && !memcmp(p->life, q->life, b));
}

Test(fx_motion_time, prewarmed_frame_0_is_frame_n, .timeout = 60)
{
    const int N = 45;
    isk_effect *warm = open_fire("prewarm = 0.75", "prewarm = 0.75"); /* 0.75 s = 45 frames */
    isk_effect *cold = open_fire("", "");
    cr_assert_eq(isk_effect_frame(warm), 0);
    cr_assert_eq(isk_effect_time(warm), 0.0, "frame 0's time stays 0");
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, 160, 120), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 160, 120), ISK_OK);
    cr_assert_eq(isk_effect_run(warm, &a, 0), ISK_OK);
    cr_assert_eq(isk_effect_run(cold, &b, N), ISK_OK);
    cr_assert(!memcmp(a.pixels, b.pixels, (size_t)a.stride * (size_t)a.height), "the renders differ");
    for (int g = 0; g < 2; g++)
        assert_same_state(isk_effect_particles(warm, g), isk_effect_particles(cold, g));
    /* and so on from there */
    for (int i = 0; i < 20; i++) {
        cr_assert_eq(isk_effect_step(warm), ISK_OK);
        cr_assert_eq(isk_effect_step(cold), ISK_OK);
    }
    for (int g = 0; g < 2; g++)
        assert_same_state(isk_effect_particles(warm, g), isk_effect_particles(cold, g));
    /* reset prewarms again */
    cr_assert_eq(isk_effect_reset(warm), ISK_OK);
    cr_assert_eq(isk_effect_run(warm, &a, 0), ISK_OK);
    isk_effect_destroy(cold);
    cold = open_fire("", "");
    cr_assert_eq(isk_effect_run(cold, &b, N), ISK_OK);
    cr_assert(!memcmp(a.pixels, b.pixels, (size_t)a.stride * (size_t)a.height));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_effect_destroy(warm);
    isk_effect_destroy(cold);
}

/* Only the emitter that prewarms runs ahead; the other starts at 0. */
Test(fx_motion_time, prewarm_is_per_emitter)
{
    isk_effect *warm = open_fire("prewarm = 0.5", "");
    isk_effect *cold = open_fire("", "");
    cr_assert_eq(isk_effect_particles(cold, 0)->count, 0);
    cr_assert_gt(isk_effect_particles(warm, 0)->count, 100);
    cr_assert_eq(isk_effect_particles(warm, 1)->count, 0);
    for (int i = 0; i < 10; i++) {
        cr_assert_eq(isk_effect_step(warm), ISK_OK);
        cr_assert_eq(isk_effect_step(cold), ISK_OK);
    }
    assert_same_state(isk_effect_particles(warm, 1), isk_effect_particles(cold, 1));
    isk_effect_destroy(warm);
    isk_effect_destroy(cold);
}

/* A live rate change within a looped cycle: no catch-up burst, the new
 * rate from then on, and the next cycles at the new rate exactly. */
Test(fx_motion_time, live_rate_of_a_cycle)
{
    isk_effect *fx = open_text("[scene]\ndt = 1/60\n[emitter e]\nsource = stream\nrate = 50\nduration = 0.4\n"
                               "loop = true\ncapacity = 100000\n");
    for (int i = 0; i < 12; i++) /* 0.2 s: 10 births */
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 10);
    isk_error err;
    cr_assert_eq(isk_effect_set(fx, "emitter e", "rate", "100", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_leq(isk_effect_particle_count(fx), 12, "no catch-up: %zu", isk_effect_particle_count(fx));
    for (int i = 0; i < 11; i++) /* to 0.4 s: the rest of the cycle at 100/s, 20 more */
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    const size_t at_end = isk_effect_particle_count(fx);
    cr_assert_eq(at_end, 30, "%zu", at_end);
    for (int i = 0; i < 24; i++) /* a whole cycle at 100/s */
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), at_end + 40);
    isk_effect_destroy(fx);
}
