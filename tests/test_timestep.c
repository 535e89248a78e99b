/* SPDX-License-Identifier: MIT */
/* The fixed-step accumulator: exact step counts, no spiral of death. */
#include <criterion/criterion.h>
#include <math.h>

#include "iskra/timestep.h"

Test(timestep, steady_frames_give_one_step_each)
{
    isk_timestep ts;
    cr_assert_eq(isk_timestep_init(&ts, 0.25, 4), ISK_OK);
    /* 0.25 is exact in binary: no drift over many frames. */
    for (int i = 0; i < 1000; i++)
        cr_assert_eq(isk_timestep_advance(&ts, 0.25), 1);
    cr_assert_eq(ts.steps, 1000);
    cr_assert_eq(ts.dropped, 0.0);
}

Test(timestep, fast_and_slow_frames_average_out)
{
    isk_timestep ts;
    cr_assert_eq(isk_timestep_init(&ts, 1.0 / 60.0, 8), ISK_OK);
    long total = 0;
    /* 144 Hz for 10 s, then 30 Hz for 10 s: 1200 steps either way (+-1 for
     * the fraction still accumulated). */
    for (int i = 0; i < 1440; i++)
        total += isk_timestep_advance(&ts, 1.0 / 144.0);
    cr_assert(labs(total - 600) <= 1, "got %ld", total);
    for (int i = 0; i < 300; i++)
        total += isk_timestep_advance(&ts, 1.0 / 30.0);
    cr_assert(labs(total - 1200) <= 1, "got %ld", total);
    cr_assert_eq(ts.dropped, 0.0);
}

Test(timestep, a_stall_is_dropped_not_replayed)
{
    isk_timestep ts;
    cr_assert_eq(isk_timestep_init(&ts, 0.01, 5), ISK_OK);
    cr_assert_eq(isk_timestep_advance(&ts, 600.0), 5);
    cr_assert_lt(ts.accumulated, 0.01);
    cr_assert_gt(ts.dropped, 599.0);
    /* The next normal frame is normal. */
    int n = isk_timestep_advance(&ts, 0.01);
    cr_assert(n == 1 || n == 2);
}

Test(timestep, bad_input)
{
    isk_timestep ts;
    cr_assert_eq(isk_timestep_init(&ts, 0, 5), ISK_ERR_RANGE);
    cr_assert_eq(isk_timestep_init(&ts, -1, 5), ISK_ERR_RANGE);
    cr_assert_eq(isk_timestep_init(&ts, NAN, 5), ISK_ERR_NAN);
    cr_assert_eq(isk_timestep_init(&ts, 0.1, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_timestep_init(NULL, 0.1, 1), ISK_ERR_NULL);
    cr_assert_eq(isk_timestep_init(&ts, 0.1, 3), ISK_OK);
    cr_assert_eq(isk_timestep_advance(&ts, NAN), 0);
    cr_assert_eq(isk_timestep_advance(&ts, -5), 0);
    cr_assert_eq(isk_timestep_advance(&ts, INFINITY), 0); /* a broken clock, not a stall */
    cr_assert_eq(isk_timestep_advance(&ts, 1.0), 3);
    double a = isk_timestep_alpha(&ts);
    cr_assert(a >= 0 && a < 1);
}
