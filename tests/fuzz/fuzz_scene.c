/* SPDX-License-Identifier: MIT */
/* libFuzzer target: scene text -> isk_scene_load_string -> isk_effect_create
 * -> a few steps and renders.  Built and run by `make fuzz` (clang with
 * -fsanitize=fuzzer,address,undefined); crashers land in
 * tests/fuzz/regressions/ and tests/test_scene_fuzz_regressions.c replays
 * them.  Every scene is created as written, within the budgets of
 * fuzz_budgets.h: what a definition may ask for is the library's budgets'
 * to bound, not the harness's. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/scene.h"
#include "fuzz_budgets.h"
#include "scene_mutator.h"

#define FRAMES 3

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = 0;
    isk_effect_def d;
    isk_error err;
    if (isk_scene_load_string(&d, text, "fuzz.ini", &err) == ISK_OK) {
        fuzz_set_budgets(&d);
        isk_effect *fx;
        if (isk_effect_create(&fx, &d, &err) == ISK_OK) {
            isk_canvas c;
            if (isk_canvas_init(&c, d.width, d.height) == ISK_OK) {
                for (int f = 0; f < FRAMES; f++)
                    if (isk_effect_step_render(fx, &c) != ISK_OK)
                        break;
                isk_effect_click(fx, 0.5, 0.5);
                isk_effect_step(fx);
                isk_effect_render(fx, &c);
                isk_canvas_free(&c);
            }
            isk_effect_destroy(fx);
        }
    }
    isk_effect_def_free(&d);
    free(text);
    return 0;
}

/* Mutations that know the scene format (scene_mutator.h). */
size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t max_size, unsigned int seed);
size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t max_size, unsigned int seed)
{
    return scene_mutate(data, size, max_size, seed);
}
