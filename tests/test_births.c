/* SPDX-License-Identifier: MIT */
/* Every frame's work is bounded: births per frame are capped by the pool's
 * room, and the loops over time cannot spin (intervals down to 1e-300, the
 * largest rate at the longest step).  The timeouts only catch a hang: no
 * test here measures time. */
#include <criterion/criterion.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "iskra/effect.h"
#include "iskra/scene.h"

static isk_effect *stream(const char *keys, double dt)
{
    char text[1200];
    snprintf(text, sizeof text,
             "[scene]\ndt = %.17g\n[emitter s]\nsource = stream\nposition = 0, 0\nvelocity = 0, 1\n"
             "draw = none\nbounded = false\n%s",
             dt, keys);
    isk_effect_def d;
    isk_error err;
    isk_effect *fx = NULL;
    cr_assert_eq(isk_scene_load_string(&d, text, "births", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_def_free(&d);
    return fx;
}

/* burst_every from 1e-300 (below the clock's resolution: the schedule used
 * to stop advancing and the frame never ended) to 1e-3: each frame ends,
 * fills the pool, counts the rest as dropped, and the schedule moves on. */
Test(births, burst_intervals_down_to_1e_300_end_every_frame, .timeout = 60)
{
    for (int ex = -300; ex <= -3; ex += 9) {
        char keys[200];
        snprintf(keys, sizeof keys, "count = 2\nburst_every = 1e%d\ncapacity = 500\nlife = 0.25\n", ex);
        isk_effect *fx = stream(keys, 1.0 / 60);
        for (int f = 0; f < 40; f++) {
            cr_assert_eq(isk_effect_step(fx), ISK_OK);
            cr_assert_leq(isk_effect_particle_count(fx), 500);
        }
        const double due_per_frame = 2.0 / 60.0 * pow(10.0, -ex); /* count / every per frame */
        if (due_per_frame > 1000) {
            /* 40 frames is 0.67 s: the first pools died at 0.25 s and 0.5 s,
             * so a full pool now means the schedule kept moving. */
            const isk_particles *p = isk_effect_particles(fx, 0);
            cr_assert_eq(p->count, 500, "every 1e%d: the pool is full", ex);
            for (size_t i = 0; i < p->count; i++)
                cr_assert_lt(p->age[i], 0.25, "every 1e%d: an old particle", ex);
            cr_assert_gt(isk_effect_dropped(fx, 0), 0);
        }
        isk_effect_destroy(fx);
    }
}

/* burst_every below 1e-300, down to the smallest double (accepted): a
 * time over it was an infinite burst index, the next burst at infinity,
 * and emission stopped after the first life.  Now it is read as
 * ISK_BURST_EVERY_MIN, and the pool is still refilled after two lives;
 * the same with a looping duration (a whole cycle over it was NaN). */
Test(births, burst_intervals_down_to_the_smallest_double_keep_emitting, .timeout = 60)
{
    static const char *const every[] = {"5e-324", "1e-320", "2.2e-308", "1e-295"};
    for (int k = 0; k < 4; k++)
        for (int loop = 0; loop < 2; loop++) {
            char keys[200];
            snprintf(keys, sizeof keys, "count = 2\nburst_every = %s\ncapacity = 500\nlife = 0.25\n%s", every[k],
                     loop ? "duration = 0.1\nloop = true\n" : "");
            isk_effect *fx = stream(keys, 1.0 / 60);
            for (int f = 0; f < 40; f++)
                cr_assert_eq(isk_effect_step(fx), ISK_OK);
            const isk_particles *p = isk_effect_particles(fx, 0);
            cr_assert_eq(p->count, 500, "every %s%s: %zu alive after 0.67 s", every[k], loop ? ", looping" : "",
                         p->count);
            for (size_t i = 0; i < p->count; i++)
                cr_assert_lt(p->age[i], 0.25, "every %s: an old particle", every[k]);
            isk_effect_destroy(fx);
        }
}

/* The dropped count is the due births the pool had no room for, computed
 * rather than counted one by one: 10^4 bursts of 3 a frame into a pool of
 * 100 (their ages all below the life). */
Test(births, dropped_bursts_are_counted_not_looped)
{
    isk_effect *fx = stream("count = 3\nburst_every = 1e-6\ncapacity = 100\nlife = 10\n", 0.01);
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 100);
    /* 0.01 / 1e-6 + 1 = 10001 bursts due (the first at t = 0), 3 each. */
    size_t d = isk_effect_dropped(fx, 0);
    cr_assert(d >= 30003 - 100 - 3 && d <= 30003 - 100 + 3, "dropped %zu", d);
    isk_effect_destroy(fx);
}

/* The largest rate at the longest step: 10^7/s for 1000 s is 10^10 births
 * in one frame; the frame makes the pool's room of them and counts the rest
 * (it used to turn the loop 10^10 times).  The thesis's per-frame rounding
 * of the same, (unsigned)(10^10 + 0.5), is clamped before any cast. */
Test(births, the_largest_rate_at_the_longest_step_is_bounded, .timeout = 60)
{
    const char *modes[2] = {"accumulate", "thesis"};
    for (int m = 0; m < 2; m++) {
        char keys[200];
        snprintf(keys, sizeof keys, "rate = 1e7\nrate_mode = %s\ncapacity = 1000\n", modes[m]);
        isk_effect *fx = stream(keys, 1000);
        for (int f = 0; f < 3; f++)
            cr_assert_eq(isk_effect_step(fx), ISK_OK);
        cr_assert_eq(isk_effect_particle_count(fx), 1000);
        double d = (double)isk_effect_dropped(fx, 0);
        /* (+ the ~10 a frame due within its 1e-9 tolerance, counted early) */
        cr_assert(fabs(d - (3e10 - 1000)) <= 40, "%s: dropped %.0f", modes[m], d);
        isk_effect_destroy(fx);
    }
}

/* Long lives at a huge rate: only those young enough to be alive are made
 * (the dead ones are skipped in one step, not one turn each). */
Test(births, births_older_than_the_life_are_skipped_at_once, .timeout = 60)
{
    isk_effect *fx = stream("rate = 1e7\ncapacity = 4000000\nlife = 0.0001\n", 1000);
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    size_t n = isk_effect_particle_count(fx);
    /* births in the last 0.0001 s of the frame: 1000, and the ~10 due within
     * the step's tolerance after it (1e-9 of the time, effect_stream.c) */
    cr_assert(n >= 999 && n <= 1012, "%zu alive", n);
    cr_assert_eq(isk_effect_dropped(fx, 0), 0);
    isk_effect_destroy(fx);
}

/* A small pool at an ordinary rate drops and counts exactly what it cannot
 * hold, frame after frame, as before. */
Test(births, an_ordinary_full_pool_counts_each_lost_birth)
{
    isk_effect *fx = stream("rate = 600\ncapacity = 50\n", 1.0 / 60);
    for (int f = 0; f < 60; f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 50);
    size_t d = isk_effect_dropped(fx, 0);
    cr_assert(d >= 600 - 50 - 1 && d <= 600 - 50 + 1, "dropped %zu", d);
    isk_effect_destroy(fx);
}

/* The dead leave before the births (the cull runs before the spawn), so a
 * steady pool holds min(capacity, rate * life) at every frame's end, also
 * with lives shorter than a frame: 10^6/s for 0.01 s fills 1,000 places
 * at every frame (it used to alternate 1,000 and 0). */
Test(births, a_full_pool_of_short_lives_is_full_at_every_frame)
{
    isk_effect *fx = stream("rate = 1e6\ncapacity = 1000\nlife = 0.01\n", 1.0 / 60);
    for (int f = 0; f < 30; f++) {
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        cr_assert_eq(isk_effect_particle_count(fx), 1000, "frame %d: %zu alive", f, isk_effect_particle_count(fx));
    }
    isk_effect_destroy(fx);
}

/* A saturated pool of long lives: count == capacity after every step (it
 * read about a frame's deaths under the capacity, 383..400 of 400). */
Test(births, a_saturated_pool_reads_its_capacity)
{
    isk_effect *fx = stream("rate = 1e6\ncapacity = 400\nlife = 0.5\n", 1.0 / 60);
    for (int f = 0; f < 90; f++) {
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        cr_assert_eq(isk_effect_particle_count(fx), 400, "frame %d: %zu alive", f, isk_effect_particle_count(fx));
    }
    isk_effect_destroy(fx);
}

/* Below the capacity the pool holds rate * life once a life has passed:
 * 800/s for 0.5 s is 400 at every frame's end (births at k/800 s, those
 * of the last 0.5 s alive). */
Test(births, a_steady_pool_holds_rate_times_life)
{
    isk_effect *fx = stream("rate = 800\ncapacity = 1000\nlife = 0.5\n", 1.0 / 60);
    for (int f = 0; f < 120; f++) {
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        const size_t n = isk_effect_particle_count(fx);
        /* 401 when a birth falls on the frame's end a life ago: its age
         * reads a rounding under 0.5 */
        if (f >= 30)
            cr_assert(n == 400 || n == 401, "frame %d: %zu alive", f, n);
    }
    isk_effect_destroy(fx);
}

/* The scene the fuzzer kept (tests/fuzz/regressions/hang-burst_every-1e-300.ini)
 * as it stands, every key else at its default, and the same at 1e-8 (10^6
 * loop turns a frame before): frames end, rendered, with the births bounded
 * by the pool and the rest counted as dropped. */
Test(births, the_fuzzers_burst_every_scene_ends_its_frames, .timeout = 30)
{
    static const char *const every[] = {"1e-300", "1e-8"};
    for (int k = 0; k < 2; k++) {
        char text[200];
        snprintf(text, sizeof text, "[emitter s]\nsource = stream\ncount = 5\nburst_every = %s\n", every[k]);
        isk_effect_def d;
        isk_error err;
        isk_effect *fx = NULL;
        cr_assert_eq(isk_scene_load_string(&d, text, "regression", &err), ISK_OK, "%s", err.message);
        const size_t capacity = d.emitters[0].born.capacity;
        cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
        isk_canvas c;
        cr_assert_eq(isk_canvas_init(&c, d.width, d.height), ISK_OK);
        isk_effect_def_free(&d);
        for (int f = 0; f < 3; f++) {
            cr_assert_eq(isk_effect_step_render(fx, &c), ISK_OK);
            cr_assert_leq(isk_effect_particle_count(fx), capacity, "every %s", every[k]);
        }
        cr_assert_eq(isk_effect_particle_count(fx), capacity, "every %s: the pool is full", every[k]);
        cr_assert_gt(isk_effect_dropped(fx, 0), 0, "every %s: the rest is counted", every[k]);
        isk_canvas_free(&c);
        isk_effect_destroy(fx);
    }
}
