/* SPDX-License-Identifier: MIT */
/* Rewind (iskra/timeline.h): scrubbing back and forth, then forward to the
 * end, ends on the bytes of a run that never scrubbed (with and without
 * trails); the campfire's first minute fits 64 MB and every frame of it
 * comes back exactly; an edit in the past forks the timeline; a budget
 * too small for one frame turns rewind off. */
#include <criterion/criterion.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/canvas.h"
#include "iskra/effect.h"
#include "iskra/scene.h"
#include "iskra/timeline.h"
#include "scene_text.h"

static uint64_t hash_canvas(const isk_canvas *c)
{
    uint64_t h = 0xcbf29ce484222325ull;
    for (int y = 0; y < c->height; y++)
        for (size_t i = 0; i < (size_t)c->width * 4; i++)
            h = (h ^ c->pixels[(size_t)y * c->stride + i]) * 0x100000001b3ull;
    return h;
}

static uint64_t hash_state(const isk_effect *fx)
{
    uint64_t h = 0xcbf29ce484222325ull;
    for (int g = 0; g < isk_effect_emitter_count(fx); g++) {
        const isk_particles *p = isk_effect_particles(fx, g);
        const double *cols[] = {p->x, p->y, p->vx, p->vy, p->age};
        for (int k = 0; k < 5; k++) {
            const unsigned char *b = (const unsigned char *)cols[k];
            for (size_t i = 0; i < p->count * sizeof(double); i++)
                h = (h ^ b[i]) * 0x100000001b3ull;
        }
    }
    return h;
}

static isk_effect *open_scene(const char *name)
{
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load(&d, name, &err), ISK_OK, "%s: %s", name, err.message);
    d.threads = 1;
    return scene_open_def(&d);
}

/* One shown frame as a player does it: the edits, a step, the drawing. */
static void frame(isk_timeline *t, isk_effect *fx, isk_canvas *c)
{
    cr_assert_eq(isk_timeline_watch(t, fx, c), ISK_OK);
    if (isk_effect_definition(fx)->clear)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    else
        cr_assert_eq(isk_effect_step_render(fx, c), ISK_OK);
    cr_assert_eq(isk_timeline_stepped(t, fx, c), ISK_OK);
}

static void start(isk_effect *fx, isk_canvas *c)
{
    const isk_effect_def *d = isk_effect_definition(fx);
    cr_assert_eq(isk_canvas_init(c, d->width, d->height), ISK_OK);
    cr_assert_eq(isk_effect_run(fx, c, 0), ISK_OK);
}

static void scrub_then_finish(const char *name, int frames)
{
    /* never scrubbed */
    isk_effect *a = open_scene(name);
    isk_canvas ca;
    start(a, &ca);
    for (int f = 0; f < frames; f++)
        cr_assert_eq(isk_effect_definition(a)->clear ? isk_effect_step(a) : isk_effect_step_render(a, &ca), ISK_OK);
    if (isk_effect_definition(a)->clear)
        cr_assert_eq(isk_effect_render(a, &ca), ISK_OK);
    /* scrubbed back and forth on the way */
    isk_effect *b = open_scene(name);
    isk_canvas cb;
    start(b, &cb);
    isk_timeline *t = isk_timeline_create((size_t)64 << 20);
    cr_assert_not_null(t);
    cr_assert_eq(isk_timeline_restart(t, b, &cb), ISK_OK);
    for (int f = 0; f < frames * 2 / 3; f++)
        frame(t, b, &cb);
    const long to[] = {3, frames / 2, 1, frames / 3, 0, frames * 2 / 3 - 1, 7, frames * 2 / 3};
    for (size_t i = 0; i < sizeof to / sizeof to[0]; i++) {
        cr_assert_eq(isk_timeline_seek(t, b, &cb, to[i]), ISK_OK);
        cr_assert_eq(isk_effect_frame(b), to[i], "%s: at %ld after seeking to %ld", name, isk_effect_frame(b), to[i]);
    }
    cr_assert_eq(isk_timeline_seek(t, b, &cb, 5), ISK_OK);
    while (isk_effect_frame(b) < frames) /* and on from the past, along the same timeline */
        frame(t, b, &cb);
    if (isk_effect_definition(b)->clear)
        cr_assert_eq(isk_effect_render(b, &cb), ISK_OK);
    cr_assert_eq(hash_state(a), hash_state(b), "%s: particles differ", name);
    cr_assert_eq(hash_canvas(&ca), hash_canvas(&cb), "%s: pixels differ", name);
    cr_assert_eq(isk_timeline_last(t), frames);
    isk_timeline_destroy(t);
    isk_canvas_free(&ca);
    isk_canvas_free(&cb);
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

Test(timeline, scrubbing_then_finishing_gives_the_straight_run) { scrub_then_finish("fire_campfire", 90); }

/* A scene that draws trails over its canvas (clear = false): the canvas
 * comes back with the frame. */
Test(timeline, trails_come_back_with_their_frame) { scrub_then_finish("fig10_trajectory", 60); }

/* The campfire's first minute (3600 frames at 60/s) fits 64 MB, and
 * every frame sampled comes back with its bytes. */
Test(timeline, the_campfires_first_minute_fits_64_mb, .timeout = 600)
{
    enum { FRAMES = 3600, EVERY = 97 };
    isk_effect *fx = open_scene("fire_campfire");
    isk_canvas c;
    start(fx, &c);
    isk_timeline *t = isk_timeline_create((size_t)64 << 20);
    cr_assert_eq(isk_timeline_restart(t, fx, &c), ISK_OK);
    uint64_t want[FRAMES / EVERY + 1];
    size_t most = 0;
    for (int f = 1; f <= FRAMES; f++) {
        frame(t, fx, &c);
        if (isk_timeline_bytes(t) > most)
            most = isk_timeline_bytes(t);
        if (f % EVERY == 0)
            want[f / EVERY] = hash_state(fx);
    }
    cr_assert_leq(most, (size_t)64 << 20, "%zu bytes kept", most);
    cr_assert_eq(isk_timeline_first(t), 0, "the first minute is kept whole");
    cr_log_info("campfire, 3600 frames: at most %zu kB kept, %d checkpoints, one every %d frames", most >> 10,
                isk_timeline_checkpoints(t), isk_timeline_every(t));
    for (int f = FRAMES / EVERY * EVERY; f >= EVERY; f -= EVERY) {
        cr_assert_eq(isk_timeline_seek(t, fx, &c, f), ISK_OK);
        cr_assert_eq(hash_state(fx), want[f / EVERY], "frame %d differs after a seek", f);
    }
    isk_timeline_destroy(t);
    isk_canvas_free(&c);
    isk_effect_destroy(fx);
}

/* Thinning: a budget of a few checkpoints keeps every frame reachable. */
Test(timeline, a_small_budget_thins_and_stays_exact)
{
    isk_effect *fx = open_scene("fire_campfire");
    isk_canvas c;
    start(fx, &c);
    isk_timeline *probe = isk_timeline_create(SIZE_MAX / 2);
    cr_assert_eq(isk_timeline_restart(probe, fx, &c), ISK_OK);
    const size_t one = isk_timeline_bytes(probe);
    isk_timeline_destroy(probe);
    isk_timeline *t = isk_timeline_create(one * 20); /* the campfire grows: about 10 checkpoints */
    cr_assert_eq(isk_timeline_restart(t, fx, &c), ISK_OK);
    uint64_t want[301];
    want[0] = hash_state(fx);
    for (int f = 1; f <= 300; f++) {
        frame(t, fx, &c);
        want[f] = hash_state(fx);
        cr_assert_leq(isk_timeline_bytes(t), one * 20);
    }
    cr_assert_gt(isk_timeline_every(t), ISK_TIMELINE_EVERY, "the budget never made it thin");
    for (int f = 300; f >= 0; f -= 13) {
        cr_assert_eq(isk_timeline_seek(t, fx, &c, f), ISK_OK);
        cr_assert_eq(isk_effect_frame(fx), f);
        cr_assert_eq(hash_state(fx), want[f], "frame %d", f);
    }
    isk_timeline_destroy(t);
    isk_canvas_free(&c);
    isk_effect_destroy(fx);
}

/* Editing in the past forks the timeline there: the frames after it are
 * forgotten, and going on gives what a run with the edit at that frame
 * gives. */
Test(timeline, an_edit_in_the_past_forks_the_timeline)
{
    isk_effect *fx = open_scene("fire_campfire");
    isk_canvas c;
    start(fx, &c);
    isk_timeline *t = isk_timeline_create((size_t)64 << 20);
    cr_assert_eq(isk_timeline_restart(t, fx, &c), ISK_OK);
    for (int f = 0; f < 80; f++)
        frame(t, fx, &c);
    cr_assert_eq(isk_timeline_seek(t, fx, &c, 30), ISK_OK);
    isk_error err = {0};
    const int substeps = isk_effect_definition(fx)->substeps;
    cr_assert_neq(substeps, 3);
    const unsigned long edits = isk_effect_edits(fx);
    cr_assert_eq(isk_effect_set(fx, "scene", "substeps", "3", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_edits(fx), edits + 1);
    for (int f = 30; f < 50; f++)
        frame(t, fx, &c);
    cr_assert_eq(isk_timeline_last(t), 50, "the old frames 51..80 are another future");
    const uint64_t forked = hash_state(fx);
    /* the same edit at frame 30 of a straight run */
    isk_effect *b = open_scene("fire_campfire");
    for (int f = 0; f < 30; f++)
        cr_assert_eq(isk_effect_step(b), ISK_OK);
    cr_assert_eq(isk_effect_set(b, "scene", "substeps", "3", &err), ISK_OK);
    for (int f = 30; f < 50; f++)
        cr_assert_eq(isk_effect_step(b), ISK_OK);
    cr_assert_eq(hash_state(b), forked);
    /* and back before the edit: the definition then, the old frames */
    cr_assert_eq(isk_timeline_seek(t, fx, &c, 20), ISK_OK);
    cr_assert_eq(isk_effect_definition(fx)->substeps, substeps);
    isk_timeline_destroy(t);
    isk_canvas_free(&c);
    isk_effect_destroy(fx);
    isk_effect_destroy(b);
}

Test(timeline, a_budget_too_small_turns_it_off)
{
    isk_effect *fx = open_scene("fire_campfire");
    isk_timeline *t = isk_timeline_create(1000);
    cr_assert_eq(isk_timeline_restart(t, fx, NULL), ISK_OK);
    cr_assert(isk_timeline_is_off(t));
    cr_assert_eq(isk_timeline_bytes(t), 0);
    for (int f = 0; f < 10; f++)
        frame(t, fx, NULL);
    cr_assert_eq(isk_timeline_seek(t, fx, NULL, 2), ISK_OK);
    cr_assert_eq(isk_effect_frame(fx), 10, "an off timeline moved the run");
    cr_assert_eq(isk_timeline_seek(NULL, fx, NULL, 2), ISK_ERR_NULL);
    isk_timeline_destroy(t);
    isk_effect_destroy(fx);
}
