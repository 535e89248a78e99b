/* SPDX-License-Identifier: MIT */
/* Bounded memory and work within the documented limits: the memory an
 * effect could take with every pool full is checked at create against a
 * budget (isk_effect_def.max_memory, `--max-memory`), and the pool bounds
 * every source of particles (explosions and clicks too), drops counted. */
#include <criterion/criterion.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "tool_cli.h"

static void many_streams(isk_effect_def *d, int n, size_t capacity)
{
    isk_effect_def_init(d);
    for (int i = 0; i < n; i++) {
        char name[16];
        snprintf(name, sizeof name, "e%d", i);
        isk_emitter_def *e = isk_effect_def_add_emitter(d, name);
        e->born.source = ISK_SOURCE_STREAM;
        e->born.rate = 10;
        e->born.capacity = capacity;
    }
}

Test(limits, memory_budget_is_checked_at_create)
{
    isk_effect_def d;
    many_streams(&d, 64, 4000000); /* the audit's 64 x 4,000,000: 14 GB by frame 30 */
    size_t need = isk_effect_def_memory(&d);
    if ((double)SIZE_MAX > 64.0 * 4000000 * 56)
        cr_assert_gt((double)need, 64.0 * 4000000 * 56, "at least 56 bytes a particle: %zu", need);
    else /* more than a 32-bit size_t holds: the sum saturates */
        cr_assert_eq(need, SIZE_MAX, "%zu", need);
    isk_effect *fx = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_SIZE);
    cr_assert_null(fx);
    cr_assert_not_null(strstr(err.message, "scene: the effect could need "), "%s", err.message);
    cr_assert_not_null(strstr(err.message, "(emitter 'e0' (its pool full) 336 MiB, emitter 'e1' (its pool full) 336 MiB"),
                       "%s", err.message);
    char limit[64]; /* 4 GiB, or 2 GiB where size_t has 32 bits */
    snprintf(limit, sizeof limit, "more than the limit of %zu.0 GiB", ISK_EFFECT_DEFAULT_MAX_MEMORY >> 30);
    cr_assert_not_null(strstr(err.message, limit), "%s", err.message);
    d.max_memory = need; /* a program may allow it: then it is created (the pools are still empty) */
    d.max_work = 1e10;   /* 256 million particles a frame need more than the default work too */
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_destroy(fx);
    d.max_memory = need - 1;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_SIZE);
    isk_effect_def_free(&d);
    /* the estimate follows the store's growth: a pool of 100 takes a block of 128 */
    many_streams(&d, 1, 100);
    cr_assert_lt(isk_effect_def_memory(&d), (size_t)3 << 20); /* the 600 x 600 canvas's 1.4 MB with it */
    cr_assert_gt(isk_particles_bytes(100, 0), (size_t)(128 + 64) * 7 * 8);
    cr_assert_eq(isk_particles_bytes(ISK_PARTICLES_MAX + 1, 0), 0u);
    isk_effect_def_free(&d);
}

Test(limits, clicks_and_explosions_stop_at_the_pool)
{
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load_string(&d, "[emitter cloud]\nsource = explosion\nexplosion = gauss\ncount = 300\n"
                                           "capacity = 1000\n[click]\nexplosion = ring\ncount = 400\n",
                                       "pool", &err),
                 ISK_OK, "%s", err.message);
    isk_effect *fx = NULL;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_click(fx, 1, 1), ISK_OK);
    cr_assert_eq(isk_effect_click(fx, 1, 1), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 1000, "300 + 400 + 300 of the second click's 400");
    cr_assert_eq(isk_effect_dropped(fx, 0), 100);
    cr_assert_eq(isk_effect_click(fx, 2, 2), ISK_OK);
    cr_assert_eq(isk_effect_particle_count(fx), 1000);
    cr_assert_eq(isk_effect_dropped(fx, 0), 500);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
    /* a multi-Coulomb click into a pool that fills: the batches that do not fit are dropped */
    cr_assert_eq(isk_scene_load_string(&d, "[emitter s]\nsource = stream\nrate = 6000\ncapacity = 2000\n"
                                           "[click]\nexplosion = multi-coulomb\ncount = 5000\n",
                                       "mc", &err),
                 ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_click(fx, 0, 0), ISK_OK);
    for (int i = 0; i < 120; i++) {
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        cr_assert_leq(isk_effect_particle_count(fx), 2000);
    }
    cr_assert_eq(isk_effect_particle_count(fx), 2000);
    cr_assert_gt(isk_effect_dropped(fx, 0), 5000);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
    /* an explosion larger than its pool is refused where it is written */
    cr_assert_neq(isk_scene_load_string(&d, "[emitter c]\nsource = explosion\ncount = 5000\ncapacity = 100\n", "big",
                                        &err),
                  ISK_OK);
    cr_assert_str_eq(err.message, "big:3: [emitter c] count: 5000 exceeds the capacity 100 (raise capacity for more)");
}

Test(limits, max_memory_option)
{
    cli_fresh("out/test_limits/mm");
    FILE *f = fopen("out/test_limits/mm/huge.ini", "w");
    cr_assert_not_null(f);
    for (int i = 0; i < 20; i++)
        fprintf(f, "[emitter e%d]\nsource = stream\nrate = 10\ncapacity = 4000000\n", i);
    fclose(f);
    cr_assert_eq(cli_run("out/test_limits/mm", "describe out/test_limits/mm/huge.ini"), 2);
    char *e = cli_slurp("out/test_limits/mm/stderr.txt");
    if (SIZE_MAX >> 30 >= 8) {
        cr_assert_not_null(strstr(e, "huge.ini: scene: the effect could need 6.6 GiB"), "%s", e);
        free(e);
        cr_assert_eq(cli_run("out/test_limits/mm", "describe out/test_limits/mm/huge.ini --max-memory 8G"), 0);
    } else { /* a 32-bit program: 6.6 GiB and a budget of 8G are beyond its addresses */
        cr_assert_not_null(strstr(e, "huge.ini: scene: the effect could need more than can be addressed"), "%s", e);
        free(e);
        cr_assert_eq(cli_run("out/test_limits/mm", "describe out/test_limits/mm/huge.ini --max-memory 8G"), 2);
        e = cli_slurp("out/test_limits/mm/stderr.txt");
        cr_assert_not_null(strstr(e, "--max-memory: 8G is more than this program can address (at most 4294967295 bytes)"),
                           "%s", e);
        free(e);
    }
    const char *bad[] = {"12X", "0", "-1", "99999999999999999999G", "1e9", ""};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char a[200];
        snprintf(a, sizeof a, "describe fig09_stationary_particle --max-memory=%s", bad[i]);
        cr_assert_eq(cli_run("out/test_limits/mm", a), 2, "%s", a);
    }
    cr_assert_eq(cli_run("out/test_limits/mm", "describe fig09_stationary_particle --max-memory 512M"), 0);
}
