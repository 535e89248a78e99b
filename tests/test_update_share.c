/* SPDX-License-Identifier: MIT */
/* Which groups' updates are shared out over the threads (effect.c's
 * update_on_pool): a group whose update takes less than FX_POOL_MIN_SECONDS
 * on one thread steps on the caller alone, where waking the workers would
 * cost more than they save; a big one on the threads.  The choice is made
 * from the group's cost measured on the caller, at its first update, again
 * when its count halves or doubles, and now and then while it lies near
 * the line or its time on the threads falls under 4 times it.  The bytes
 * are the same either way (threads_check). */
#include <criterion/criterion.h>

#include "scene/effect_internal.h"
#include "scene_text.h"

static isk_effect *layer(const char *count)
{
    char text[512];
    snprintf(text, sizeof text,
             "[force gravity]\ng = 9.81\n[bounds]\nrestitution = 0.5\n"
             "[emitter a]\nsource = layer\ncount = %s\nlimit = %s\ncapacity = %s\nrect = -5, 5, -5, 5\n"
             "forces = gravity\n",
             count, count, count);
    return scene_text_open(text, 2);
}

Test(update_share, a_small_group_steps_on_the_caller_and_a_big_one_on_the_threads)
{
    /* 100 particles take well under 0.1 ms even under the sanitizers;
     * 300,000 take well over it on any machine */
    isk_effect *small = layer("100"), *big = layer("300000");
    cr_assert_eq(isk_effect_threads(small), 2);
    /* A fresh effect's first update also pays its one-time costs (under
     * clang's sanitizers 100 particles then took 0.3 ms, and went to the
     * threads until the next measure, FX_STEP_COST_AGAIN updates later):
     * one warming update, then the measures start afresh. */
    cr_assert_eq(isk_effect_step(small), ISK_OK);
    cr_assert_eq(isk_effect_step(big), ISK_OK);
    small->groups[0].step_cost = (fx_step_cost){0};
    big->groups[0].step_cost = (fx_step_cost){0};
    for (int f = 0; f < 5; f++) {
        cr_assert_eq(isk_effect_step(small), ISK_OK);
        cr_assert_eq(isk_effect_step(big), ISK_OK);
    }
    const fx_step_cost *s = &small->groups[0].step_cost, *b = &big->groups[0].step_cost;
    /* measured on the caller at every update: `since` starts again */
    cr_expect_gt(s->per_particle, 0.0);
    cr_expect_eq(s->count, 100);
    cr_expect_eq(s->since, 0);
    /* measured once, then 4 updates on the threads */
    cr_expect_gt(b->per_particle, 0.0);
    cr_expect_eq(b->count, 300000);
    cr_expect_eq(b->since, 4);
    isk_effect_destroy(small);
    isk_effect_destroy(big);
}

Test(update_share, a_group_that_became_cheap_is_measured_again)
{
    /* A group measured dear (as a falling layer is, before it comes to
     * rest at the same count) goes to the threads; once its time there
     * lies near the line, it is measured again on the caller, and its true
     * cost keeps it there.  (100 particles: under
     * ISK_PIPELINE_MIN_PARALLEL_BLOCKS, so "the threads" run it on the
     * caller, well under 0.4 ms even under the sanitizers.) */
    isk_effect *fx = layer("100");
    fx_step_cost *c = &fx->groups[0].step_cost;
    cr_assert_eq(isk_effect_step(fx), ISK_OK); /* the first measure */
    cr_assert_gt(c->per_particle, 0.0);
    *c = (fx_step_cost){1e-5, 100, 1000, 0.0}; /* 1 ms a step, long ago */
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_expect_eq(c->per_particle, 1e-5, "on the threads: no new measure");
    cr_expect_eq(c->since, 1001);
    cr_expect_gt(c->pool_seconds, 0.0);
    /* The update on the threads is wall time: one that the host
     * descheduled (CI under ASan, the VM busy) can take over 0.4 ms and
     * delay the new measure by an update, so a few are allowed. */
    for (int f = 0; f < 8 && !(c->per_particle < 1e-5); f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_expect_lt(c->per_particle, 1e-5, "measured again on the caller");
    cr_expect_eq(c->since, 0);
    cr_expect_eq(c->pool_seconds, 0.0);
    isk_effect_destroy(fx);
}

Test(update_share, one_thread_and_the_tests_switch_keep_the_old_paths)
{
    isk_effect *one = layer("1000"), *forced = layer("1000");
    cr_assert_eq(isk_effect_set_threads(one, 1), ISK_OK);
    forced->pool_always = 1;
    for (int f = 0; f < 3; f++) {
        cr_assert_eq(isk_effect_step(one), ISK_OK);
        cr_assert_eq(isk_effect_step(forced), ISK_OK);
    }
    cr_expect_eq(one->groups[0].step_cost.per_particle, 0.0); /* never measured */
    cr_expect_eq(forced->groups[0].step_cost.per_particle, 0.0);
    isk_effect_destroy(one);
    isk_effect_destroy(forced);
}
