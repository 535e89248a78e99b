/* SPDX-License-Identifier: MIT */
/* Which groups' updates are shared out among the workers (effect.c's
 * update_work against FX_UPDATE_MIN_WORK): decided from counts alone, the
 * particles times what the group's stages declare they cost, a block at
 * rest counting only the stages it does not skip.  No clock: the same
 * decisions on every run.  A caller's own job system (isk_effect_set_tasks)
 * runs them instead of the effect's threads, with the same bytes whatever
 * order and worker it runs the items in. */
#include <criterion/criterion.h>
#include "fast_paths_skip.h"

#include <string.h>

#include "scene/effect_internal.h"
#include "scene_text.h"

static isk_effect *layer(const char *count, int threads)
{
    char text[512];
    snprintf(text, sizeof text,
             "[force gravity]\ng = 9.81\n[bounds]\nrestitution = 0.5\n"
             "[emitter a]\nsource = layer\ncount = %s\nlimit = %s\ncapacity = %s\nrect = -5, 5, -5, 5\n"
             "forces = gravity\n",
             count, count, count);
    return scene_text_open(text, threads);
}

Test(update_share, a_small_group_steps_on_the_caller_and_a_big_one_on_the_workers)
{
    isk_effect *small = layer("100", 2), *big = layer("300000", 2);
    cr_assert_eq(isk_effect_threads(small), 2);
    for (int f = 0; f < 5; f++) {
        cr_assert_eq(isk_effect_step(small), ISK_OK);
        cr_assert_eq(isk_effect_step(big), ISK_OK);
    }
    cr_expect_eq(small->groups[0].shared_updates, 0);
    cr_expect_eq(big->groups[0].shared_updates, 5);
    isk_effect_destroy(small);
    isk_effect_destroy(big);
}

/* A layer of 10^5 falls on the workers; once it lies at rest on its floor
 * its blocks skip their motion and what is left is too little to share. */
Test(update_share, a_group_at_rest_is_cheap)
{
    SKIP_WITHOUT(ISK__FAST_REST, "blocks at rest");
    isk_effect *fx = layer("100000", 2);
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_expect_eq(fx->groups[0].shared_updates, 1, "falling, it is shared");
    for (int f = 0; f < 1200; f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    const fx_group *g = &fx->groups[0];
    cr_assert(isk__rest_all(&g->rest, g->store.count), "the layer has not come to rest");
    const long before = g->shared_updates;
    for (int f = 0; f < 10; f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_expect_eq(g->shared_updates, before, "at rest, it steps on the caller");
    isk_effect_destroy(fx);
}

/* Two runs of the same effect decide the same, update by update. */
Test(update_share, the_same_decisions_on_every_run)
{
    isk_effect *a = layer("60000", 2), *b = layer("60000", 2);
    for (int f = 0; f < 400; f++) {
        cr_assert_eq(isk_effect_step(a), ISK_OK);
        cr_assert_eq(isk_effect_step(b), ISK_OK);
        cr_assert_eq(a->groups[0].shared_updates, b->groups[0].shared_updates, "frame %d", f);
    }
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

Test(update_share, one_worker_never_shares)
{
    isk_effect *one = layer("300000", 1);
    for (int f = 0; f < 3; f++)
        cr_assert_eq(isk_effect_step(one), ISK_OK);
    cr_expect_eq(one->groups[0].shared_updates, 0);
    isk_effect_destroy(one);
}

/* ---- a caller's job system ------------------------------------------------- */

/* Runs the items last to first, on worker numbers that go round: any order
 * and any worker must give the same bytes.  Counts what it ran. */
typedef struct backwards {
    int workers;
    long tasks, items;
} backwards;

static void run_backwards(void *user, isk_task_fn *fn, void *task, size_t n)
{
    backwards *b = user;
    b->tasks++;
    for (size_t i = n; i-- > 0;) {
        fn(task, (int)(i % (size_t)b->workers), i);
        b->items++;
    }
}

Test(update_share, a_callers_tasks_give_the_same_bytes)
{
    isk_effect *mine = layer("200000", 1), *theirs = layer("200000", 1);
    backwards b = {3, 0, 0};
    const isk_tasks tasks = {3, run_backwards, &b};
    cr_assert_eq(isk_effect_set_tasks(theirs, &tasks), ISK_OK);
    cr_assert_eq(isk_effect_threads(theirs), 3);
    theirs->band_min_work = 0; /* and every draw in bands */
    isk_canvas ca, cb;
    const isk_effect_def *d = isk_effect_definition(mine);
    cr_assert_eq(isk_canvas_init(&ca, d->width, d->height), ISK_OK);
    cr_assert_eq(isk_canvas_init(&cb, d->width, d->height), ISK_OK);
    for (int f = 0; f < 40; f++) {
        cr_assert_eq(isk_effect_step_render(mine, &ca), ISK_OK);
        cr_assert_eq(isk_effect_step_render(theirs, &cb), ISK_OK);
    }
    const isk_particles *p = isk_effect_particles(mine, 0), *q = isk_effect_particles(theirs, 0);
    cr_assert(!memcmp(p->x, q->x, p->count * sizeof(double)) && !memcmp(p->vy, q->vy, p->count * sizeof(double)));
    cr_assert(!memcmp(ca.pixels, cb.pixels, (size_t)ca.stride * (size_t)ca.height), "the canvases differ");
    if (ISK__FAST_WORKERS)
        cr_expect_geq(b.tasks, 80, "the updates and the draws went through the caller's tasks: %ld", b.tasks);
    if (ISK__FAST_WORKERS)
        cr_expect_gt(b.items, 40 * (200000 / ISK_SIM_BLOCK));
    /* back to threads of its own */
    cr_assert_eq(isk_effect_set_tasks(theirs, NULL), ISK_OK);
    const long tasks_then = b.tasks;
    cr_assert_eq(isk_effect_step(theirs), ISK_OK);
    cr_expect_eq(b.tasks, tasks_then);
    isk_canvas_free(&ca);
    isk_canvas_free(&cb);
    isk_effect_destroy(mine);
    isk_effect_destroy(theirs);
}

Test(update_share, bad_tasks_are_refused_and_change_nothing)
{
    isk_effect *fx = layer("100", 2);
    backwards b = {2, 0, 0};
    isk_tasks t = {2, NULL, &b};
    cr_expect_eq(isk_effect_set_tasks(fx, &t), ISK_ERR_NULL);
    t.run = run_backwards;
    t.workers = 0;
    cr_expect_eq(isk_effect_set_tasks(fx, &t), ISK_ERR_RANGE);
    t.workers = ISK_TASKS_MAX_WORKERS + 1;
    cr_expect_eq(isk_effect_set_tasks(fx, &t), ISK_ERR_RANGE);
    cr_expect_eq(isk_effect_set_tasks(NULL, &t), ISK_ERR_NULL);
    cr_expect_eq(isk_effect_threads(fx), 2, "a refused job system keeps the threads");
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    isk_effect_destroy(fx);
}
