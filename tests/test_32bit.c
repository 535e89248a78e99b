/* SPDX-License-Identifier: MIT */
/* Sizes and counts that must hold where size_t, long and pointers have 32
 * bits (`make test M32=1` runs the whole suite so; these run in every
 * build and check what a 64-bit build alone would never show): the
 * default memory budget, every preset and built-in scene created with it,
 * memory estimates that are 0 or saturate instead of wrapping, and file
 * offsets and inode numbers of 64 bits.  (Dropped spawns counted past
 * 2^32: test_births.) */
#include <criterion/criterion.h>
#include <stdint.h>
#include <stdio.h>
#include <sys/types.h>

#include "iskra/effect.h"
#include "iskra/particles.h"
#include "iskra/presets.h"
#include "iskra/scene.h"

/* The smaller of 4 GiB and half the address space (iskra/effect.h): never
 * 0, as (size_t)4 << 30 was with a 32-bit size_t. */
Test(word_size, the_default_budget_is_4_GiB_or_half_the_address_space)
{
    const uintmax_t half = (uintmax_t)SIZE_MAX / 2 + 1, four = (uintmax_t)4 << 30;
    cr_assert_eq((uintmax_t)ISK_EFFECT_DEFAULT_MAX_MEMORY, half < four ? half : four);
    cr_assert_geq((uintmax_t)ISK_EFFECT_DEFAULT_MAX_MEMORY, (uintmax_t)2 << 30);
    if (sizeof(size_t) == 4)
        cr_assert_eq((uintmax_t)ISK_EFFECT_DEFAULT_MAX_MEMORY, (uintmax_t)2 << 30);
    else
        cr_assert_eq((uintmax_t)ISK_EFFECT_DEFAULT_MAX_MEMORY, four);
}

/* Every preset, alone, with the default budget: created, and stepped until
 * its first particles are out. */
Test(word_size, every_preset_creates_within_the_default_budget)
{
    cr_assert_geq(isk_preset_count(), 10);
    for (int i = 0; i < isk_preset_count(); i++) {
        isk_effect_def d;
        isk_effect_def_init(&d);
        cr_assert_geq(isk_preset_add(&d, isk_preset_name(i), NULL, isk_vec2_make(0, 0), 1.0), 0, "%s",
                      isk_preset_name(i));
        cr_assert_leq(isk_effect_def_memory(&d), ISK_EFFECT_DEFAULT_MAX_MEMORY, "%s", isk_preset_name(i));
        isk_effect *fx = NULL;
        isk_error err = {0};
        cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s: %s", isk_preset_name(i), err.message);
        for (int f = 0; f < 600 && isk_effect_particle_count(fx) == 0; f++) /* fireworks: a rocket a second */
            cr_assert_eq(isk_effect_step(fx), ISK_OK, "%s", isk_preset_name(i));
        cr_assert_gt(isk_effect_particle_count(fx), 0, "%s", isk_preset_name(i));
        isk_effect_destroy(fx);
        isk_effect_def_free(&d);
    }
}

/* Every built-in scene (`iskra list`) with the default budget. */
Test(word_size, every_builtin_scene_creates_within_the_default_budget)
{
    cr_assert_gt(isk_scene_builtin_count(), 0);
    for (int i = 0; i < isk_scene_builtin_count(); i++) {
        const char *name = isk_scene_builtin_name(i);
        isk_effect_def d;
        isk_error err = {0};
        cr_assert_eq(isk_scene_load(&d, name, &err), ISK_OK, "%s: %s", name, err.message);
        isk_effect *fx = NULL;
        cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s: %s", name, err.message);
        cr_assert_eq(isk_effect_step(fx), ISK_OK, "%s", name);
        isk_effect_destroy(fx);
        isk_effect_def_free(&d);
    }
}

/* A store's bytes are the true number or 0 (cannot be addressed), never a
 * product wrapped to a small number: the largest pool with the longest
 * trail needs 2^28 x (7 x 8 + 64 x 16) bytes, about 2^38. */
Test(word_size, store_bytes_never_wrap)
{
    const double per_particle = 7 * 8 + ISK_TRAIL_MAX * 16;
    const size_t counts[] = {(size_t)1 << 20, (size_t)1 << 22, (size_t)1 << 24, ISK_PARTICLES_MAX};
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++) {
        size_t b = isk_particles_bytes_trail(counts[i], ISK_PARTICLES_TRAIL, ISK_TRAIL_MAX);
        double need = (double)counts[i] * per_particle;
        if (need > (double)(SIZE_MAX / 2))
            cr_assert_eq(b, 0, "%zu particles: %zu bytes, of %.0f", counts[i], b, need);
        else
            cr_assert_geq((double)b, need, "%zu particles", counts[i]);
    }
    /* and the budget sees such an emitter as more than can be addressed */
    isk_effect_def d;
    isk_effect_def_init(&d);
    for (int i = 0; i < ISK_EFFECT_MAX_EMITTERS; i++) {
        char name[16];
        snprintf(name, sizeof name, "e%d", i);
        isk_emitter_def *e = isk_effect_def_add_emitter(&d, name);
        cr_assert_not_null(e);
        e->born.capacity = ISK_PARTICLES_MAX;
        e->look.trail = ISK_TRAIL_MAX;
    }
    double total = 64.0 * (double)ISK_PARTICLES_MAX * per_particle;
    size_t need = isk_effect_def_memory(&d);
    cr_assert(need == SIZE_MAX || (double)need >= total, "%zu bytes, of %.0f", need, total);
    isk_effect_def_free(&d);
}

/* Where the trail's block cannot be addressed, adding it fails and leaves
 * the store as it was (a wrapped size would have allocated a block too
 * small for the trail).  On a 64-bit system the same block is 4.5 GB,
 * which the test does not ask for. */
Test(word_size, a_trail_beyond_the_address_space_is_refused)
{
    if (sizeof(size_t) > 4)
        cr_skip_test("64-bit size_t: the block can be addressed");
    isk_particles p;
    cr_assert_eq(isk_particles_init(&p, (size_t)1 << 22, 0), ISK_OK); /* 4M particles: 235 MB */
    cr_assert_eq(isk_particles_set_trail(&p, ISK_TRAIL_MAX), ISK_ERR_NOMEM); /* + 4 GiB of trail */
    cr_assert_eq(p.trail_len, 0);
    cr_assert_null(p.trail);
    cr_assert_geq(p.capacity, (size_t)1 << 22);
    isk_particles_free(&p);
}

/* The library's stat() and fopen() see 64-bit file offsets and inode
 * numbers in every build (-D_FILE_OFFSET_BITS=64): on a 32-bit system
 * without it, stat fails with EOVERFLOW for a file over 2 GiB or on a file
 * system with 64-bit inode numbers, and a scene file would then be taken
 * for a built-in name, an output for a file that is not there. */
Test(word_size, file_offsets_and_inode_numbers_have_64_bits)
{
    cr_assert_eq(sizeof(off_t), 8);
    cr_assert_eq(sizeof(ino_t), 8);
}
