/* SPDX-License-Identifier: MIT */
/* libFuzzer target: live changes, then save and reload.  The input is a
 * scene, a line "%%", then one command a line:
 *
 *     emitter sparks | rate | 500     isk_effect_set(fx, "emitter sparks", "rate", "500")
 *     step 3                          three steps and renders
 *     click 0.5 0.25                  isk_effect_click
 *
 * After the commands, the running effect's definition
 * (isk_effect_definition: every accepted change in it) is saved
 * (isk_scene_write) and loaded again: a saved scene must load, save to the
 * same text, and an effect created from it must draw the same bytes, frame
 * after frame, as one created from the definition it was saved from.  Any
 * difference aborts.  Built and run by `make fuzz-live` (clang with
 * -fsanitize=fuzzer,address,undefined) and by `make fuzz-smoke`; seeds in
 * tests/fuzz/live_corpus/, crashers kept in tests/fuzz/live_regressions/.
 *
 * What a scene or a change may ask for is the library's budgets' to bound
 * (a change over them is refused, as at create); the harness sets them as
 * a program would (fuzz_budgets.h), and one thread (the bytes are the
 * same for every number), since the sanitizers make each run several
 * times slower.  A step command runs at most MAX_STEPS steps: how long
 * the harness runs an input, not a limit of the library's. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "fuzz_budgets.h"
#include "scene_mutator.h"

#define MAX_STEPS 30
#define COMPARED_FRAMES 3

static void set_budgets(isk_effect_def *d)
{
    fuzz_set_budgets(d);
    d->threads = 1;
}

static char *trim(char *s)
{
    while (*s == ' ' || *s == '\t')
        s++;
    size_t n = strlen(s);
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r'))
        s[--n] = 0;
    return s;
}

/* One command line (see the top). */
static void command(isk_effect *fx, isk_canvas *c, char *line)
{
    char *bar = strchr(line, '|'), *bar2 = bar ? strchr(bar + 1, '|') : NULL;
    if (bar2) {
        *bar = *bar2 = 0;
        isk_effect_set(fx, trim(line), trim(bar + 1), trim(bar2 + 1), NULL);
        return;
    }
    long n;
    double x, y;
    if (sscanf(line, " step %ld", &n) == 1) {
        for (long i = 0; i < n && i < MAX_STEPS; i++)
            if (isk_effect_step_render(fx, c) != ISK_OK)
                break;
    } else if (sscanf(line, " click %lf %lf", &x, &y) == 2) {
        isk_effect_click(fx, x, y);
    }
}

/* Frames 1..COMPARED_FRAMES of a new effect of d into out (width * height
 * * 4 bytes each); 0 when it cannot be created or run. */
static int frames_of(const isk_effect_def *d, uint8_t *out)
{
    isk_effect *fx;
    if (isk_effect_create(&fx, d, NULL) != ISK_OK)
        return 0;
    isk_canvas c = {0};
    int ok = isk_canvas_init(&c, d->width, d->height) == ISK_OK;
    const size_t frame = ok ? (size_t)c.width * 4u * (size_t)c.height : 0;
    for (int f = 0; ok && f < COMPARED_FRAMES; f++) {
        ok = isk_effect_step_render(fx, &c) == ISK_OK;
        for (int y = 0; ok && y < c.height; y++)
            memcpy(out + (size_t)f * frame + (size_t)y * (size_t)c.width * 4u, c.pixels + (size_t)y * c.stride,
                   (size_t)c.width * 4u);
    }
    if (c.pixels)
        isk_canvas_free(&c);
    isk_effect_destroy(fx);
    return ok;
}

/* Saves d, loads it again: the same text again, the same frames. */
static void save_and_reload(const isk_effect_def *d)
{
    char *text, *again_text;
    if (isk_scene_write(d, &text, NULL) != ISK_OK)
        return; /* a value no scene line can hold: refused by name, nothing to reload */
    isk_effect_def again;
    isk_error err;
    if (isk_scene_load_string(&again, text, "fuzz.ini", &err) != ISK_OK) {
        fprintf(stderr, "a saved scene does not load: %s\n%s\n", err.message, text);
        abort();
    }
    set_budgets(&again);
    if (isk_scene_write(&again, &again_text, &err) != ISK_OK || strcmp(text, again_text)) {
        fprintf(stderr, "a saved scene saves to another text:\n%s\n----\n%s\n", text, again_text);
        abort();
    }
    const size_t bytes = (size_t)d->width * (size_t)d->height * 4u * COMPARED_FRAMES;
    uint8_t *want = malloc(bytes), *got = malloc(bytes);
    if (want && got && frames_of(d, want)) {
        if (!frames_of(&again, got)) {
            fprintf(stderr, "a saved scene loads but does not run:\n%s\n", text);
            abort();
        }
        if (memcmp(want, got, bytes)) {
            fprintf(stderr, "a saved scene draws other bytes than its definition:\n%s\n", text);
            abort();
        }
    }
    free(want);
    free(got);
    free(again_text);
    isk_effect_def_free(&again);
    free(text);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = 0;
    char *commands = strstr(text, "\n%%\n");
    if (commands) {
        *commands = 0;
        commands += 4;
    }
    isk_effect_def d;
    isk_effect *fx;
    if (isk_scene_load_string(&d, text, "fuzz.ini", NULL) == ISK_OK) {
        set_budgets(&d);
        if (isk_effect_create(&fx, &d, NULL) == ISK_OK) {
            isk_canvas c;
            if (isk_canvas_init(&c, d.width, d.height) == ISK_OK) {
                for (char *line = commands, *next; line && *line; line = next) {
                    next = strchr(line, '\n');
                    if (next)
                        *next++ = 0;
                    command(fx, &c, line);
                }
                isk_canvas_free(&c);
            }
            save_and_reload(isk_effect_definition(fx));
            isk_effect_destroy(fx);
        }
    }
    isk_effect_def_free(&d);
    free(text);
    return 0;
}

/* The scene part mutates as a scene does (scene_mutator.h); the commands by
 * libFuzzer's bytes. */
size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t max_size, unsigned int seed);
size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t max_size, unsigned int seed)
{
    return scene_mutate(data, size, max_size, seed);
}
