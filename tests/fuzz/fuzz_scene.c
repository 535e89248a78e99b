/* libFuzzer target: scene text -> isk_scene_load_string -> isk_effect_create
 * -> a few steps and renders.  Built and run by `make fuzz` (clang with
 * -fsanitize=fuzzer,address,undefined); crashers land in
 * tests/fuzz/regressions/ and tests/test_scene_fuzz_regressions.c replays
 * them.  Definitions that would be merely slow (many particles, big canvases,
 * many substeps) are skipped after parsing, so the fuzzer spends its time
 * on the parser and on the runtime's handling of odd but small scenes. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/scene.h"
#include "scene_mutator.h"

#define MAX_PARTICLES 20000u
#define MAX_PIXELS (256 * 256)
#define MAX_SUBSTEPS 8
#define FRAMES 3

/* 1 if the definition is small enough to run quickly. */
static int small_enough(const isk_effect_def *d)
{
    if ((long)d->width * d->height > MAX_PIXELS || d->substeps > MAX_SUBSTEPS)
        return 0;
    size_t total = d->click.enabled || d->click.at_start ? d->click.count : 0;
    for (int i = 0; i < d->nemitters; i++) {
        const isk_emitter_def *e = &d->emitters[i];
        if (e->substeps > MAX_SUBSTEPS || e->capacity > MAX_PARTICLES || e->limit > MAX_PARTICLES)
            return 0;
        total += e->count;
        if (e->source == ISK_SOURCE_STREAM)
            total += e->capacity;
    }
    if (total > MAX_PARTICLES)
        return 0;
    /* sprites and discs are drawn at size * pixels-per-unit: keep them small */
    for (int i = 0; i < d->nemitters; i++)
        if (d->emitters[i].size * (double)d->width > 1e5)
            return 0;
    return 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = 0;
    isk_effect_def d;
    isk_error err;
    if (isk_scene_load_string(&d, text, "fuzz.ini", &err) == ISK_OK && small_enough(&d)) {
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
