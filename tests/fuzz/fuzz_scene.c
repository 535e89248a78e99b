/* SPDX-License-Identifier: MIT */
/* libFuzzer target: scene text -> isk_scene_load_string -> isk_effect_create
 * -> a few steps and renders.  Built and run by `make fuzz` (clang with
 * -fsanitize=fuzzer,address,undefined); crashers land in
 * tests/fuzz/regressions/ and tests/test_scene_fuzz_regressions.c replays
 * them.  Definitions that would be merely slow (many particles, big canvases,
 * many substeps) are skipped after parsing, so the fuzzer spends its time
 * on the parser and on the runtime's handling of odd but small scenes. */
#include <math.h>
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
/* A trail costs, each frame, the pixels within its reach times its
 * segments that reach them: a click's 1000 ribbons 4096 px wide covered
 * the whole canvas each (13 s a frame under the sanitizers), and at
 * dt = 1000 s 5000 trails of 1 px crossed it each (4 s).  So trails are
 * kept narrow (but wide enough for trail.c's culling of wide ones) and
 * an emitter with trails small. */
#define MAX_TRAIL_WIDTH 32.0
#define MAX_TRAILED 200u
/* Likewise a disc or sprite may cover the whole canvas: 5000 discs
 * 1500 px across on a 2114 x 31 canvas took over 10 s. */
#define MAX_SIZED 500u

static size_t at_most(size_t v, size_t m) { return v < m ? v : m; }
static int at_most_i(int v, int m) { return v < m ? v : m; }

/* Makes a parsed definition quick to run, keeping everything else about it:
 * a big canvas is shrunk (aspect kept, the same world window on it, so the
 * view's scale changes but not what is in view), pools, counts and limits
 * are capped (taking the minimum keeps count <= limit <= capacity), and so
 * are substeps and the trails' widths, and the particles of an emitter
 * whose particles may each cover much of the canvas (trails, discs,
 * sprites).  The default 600x600 canvas is therefore fuzzed too (every
 * scene used to be skipped above 256x256, and the burst_every hang with
 * them).  0 when even that cannot make it small (huge sprites). */
static int make_small(isk_effect_def *d)
{
    long px = (long)d->width * d->height;
    if (px > MAX_PIXELS) {
        double k = sqrt((double)MAX_PIXELS / (double)px);
        d->width = d->width * k >= 1 ? (int)(d->width * k) : 1;
        d->height = d->height * k >= 1 ? (int)(d->height * k) : 1;
    }
    d->substeps = at_most_i(d->substeps, MAX_SUBSTEPS);
    for (int i = 0; i < d->nemitters; i++) {
        isk_emitter_def *e = &d->emitters[i];
        e->motion.substeps = at_most_i(e->motion.substeps, MAX_SUBSTEPS);
        const int sized = e->look.draw == ISK_DRAW_DISC || e->look.draw == ISK_DRAW_SPRITE;
        const size_t most = e->look.trail > 0 ? MAX_TRAILED : sized ? MAX_SIZED : MAX_PARTICLES / 4;
        e->born.capacity = at_most(e->born.capacity, most);
        e->born.limit = at_most(e->born.limit, most);
        e->born.count = at_most(e->born.count, most);
        d->click.count = at_most(d->click.count, most); /* it may land in this emitter */
        if (e->look.trail_width > MAX_TRAIL_WIDTH)
            e->look.trail_width = MAX_TRAIL_WIDTH;
        /* sprites and discs are drawn at size * pixels-per-unit */
        if (e->look.size * (double)d->width > 1e5)
            return 0;
    }
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
    if (isk_scene_load_string(&d, text, "fuzz.ini", &err) == ISK_OK && make_small(&d)) {
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
