/* SPDX-License-Identifier: MIT */
/* tests/fuzz/fuzz_budgets.h — the budgets every fuzz target creates its
 * effects with (header-only).
 *
 *     isk_effect_def d;  ...loaded...
 *     fuzz_set_budgets(&d);                 // before isk_effect_create
 *
 * What a definition may ask for is the library's budgets' to bound, not
 * the harness's: every scene is created as written, with budgets of a
 * tenth of the default work and 256 MiB of memory, since the fuzzers run
 * under the sanitizers (several times slower) and want their inputs
 * quick.  A scene over them is refused at create, as the tool refuses it;
 * one accepted and still slow is a gap in the estimate
 * (src/scene/effect_budget.c) for the fuzzer to find. */
#ifndef ISKRA_TESTS_FUZZ_BUDGETS_H
#define ISKRA_TESTS_FUZZ_BUDGETS_H

#include "iskra/effect.h"

#define FUZZ_MAX_WORK (ISK_EFFECT_DEFAULT_MAX_WORK / 10)
#define FUZZ_MAX_MEMORY ((size_t)256 << 20)

static inline void fuzz_set_budgets(isk_effect_def *d)
{
    d->max_work = FUZZ_MAX_WORK;
    d->max_memory = FUZZ_MAX_MEMORY;
}

#endif
