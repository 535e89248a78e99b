/* SPDX-License-Identifier: MIT */
/* The kernels of `make bench-web` (web_kernels.h): the full frame of
 * 10^6 coverage dots at 800x600 and its parts, on one thread, and two
 * controls, pure arithmetic and a pass over memory, that tell how much of
 * a ratio between the two sides is the machine's load (its cores and its
 * memory, shared with other work) rather than the code. */
#include "web_kernels.h"

#include <stdlib.h>
#include <string.h>

#include "../bench_layer.h"
#include "iskra/canvas.h"
#include "iskra/effect.h"

typedef enum kernel_id { K_ARITH, K_MEMORY, K_FRAME, K_DOT, K_SPRITE, K_UPDATE } kernel_id;

/* The order is kernel_id's. */
const web_kernel_info web_kernels[WEB_KERNELS] = {
    {"arith", "control: a chain of 10^7 dependent multiplications, no memory", 1, 9},
    {"memory", "control: a drag step over 5 columns of 2*10^6 doubles (80 MB, beyond the caches)", 1, 9},
    {"frame", "10^6 coverage dots at 800x600: update + clear + draw", 2, 15},
    {"dot", "10^6 coverage dots: clear + draw", 2, 15},
    {"sprite", "10^5 additive 8 px sprites: clear + draw", 2, 15},
    {"update", "10^6 particles stepped: gravity, drag, walls", 2, 15},
};

/* What each kernel is made of: the effect's size and look, and what a run does. */
typedef struct kernel_plan {
    size_t particles; /* 0: no effect (a control) */
    isk_draw_mode draw;
    int steps_before; /* steps at setup, so a draw alone has particles to draw */
    int step, render; /* what a run does */
} kernel_plan;

static const kernel_plan PLANS[WEB_KERNELS] = {
    [K_ARITH] = {0, ISK_DRAW_DOT, 0, 0, 0},
    [K_MEMORY] = {0, ISK_DRAW_DOT, 0, 0, 0},
    [K_FRAME] = {1000000, ISK_DRAW_DOT, 0, 1, 1},
    [K_DOT] = {1000000, ISK_DRAW_DOT, 1, 0, 1},
    [K_SPRITE] = {100000, ISK_DRAW_SPRITE, 1, 0, 1},
    [K_UPDATE] = {1000000, ISK_DRAW_DOT, 0, 1, 0},
};

enum { ARITH_CHAIN = 10000000, MEMORY_N = 2000000, MEMORY_COLS = 5 };

struct web_kernel {
    kernel_id id;
    const kernel_plan *plan;
    isk_effect *fx;   /* NULL for the controls */
    isk_canvas c;     /* allocated when the kernel draws */
    double product;   /* the arithmetic's running product */
    double *col[MEMORY_COLS]; /* the memory pass's x, y, vx, vy, 1/m */
};

/* A dependent chain: every multiplication waits for the one before, so no
 * compiler can vector it or hide its latency (-ffp-contract=off, no
 * fast-math: the order stays), and it touches no memory.  Its time is the
 * processor's alone, the same for native code and wasm. */
static double arithmetic_chain(double x)
{
    for (long i = 0; i < ARITH_CHAIN; i++)
        x = x * 1.0000001;
    return x;
}

/* The update's pattern over memory, as bench_controls.h's memory_given
 * times it on threads: five streams read and four written, a few
 * operations each, so the memory's bandwidth bounds it on both sides. */
static void memory_pass(double *const col[MEMORY_COLS])
{
    double *restrict x = col[0], *restrict y = col[1], *restrict vx = col[2], *restrict vy = col[3];
    const double *restrict inv_m = col[4];
    const double h = 1.0 / 60, g = -9.81, b = 0.3;
    for (size_t i = 0; i < MEMORY_N; i++) {
        const double k = b * inv_m[i];
        vx[i] -= h * k * vx[i];
        vy[i] += h * (g - k * vy[i]);
        x[i] += h * vx[i];
        y[i] += h * vy[i];
    }
}

isk_status web_kernel_setup(web_kernel **out, int id, isk_error *err)
{
    if (!out)
        return isk_error_set(err, ISK_ERR_NULL, "web_kernel_setup: no place for the kernel");
    *out = NULL;
    if (id < 0 || id >= WEB_KERNELS)
        return isk_error_set(err, ISK_ERR_RANGE, "no kernel %d (0 .. %d)", id, WEB_KERNELS - 1);
    web_kernel *k = calloc(1, sizeof *k);
    if (!k)
        return isk_error_set(err, ISK_ERR_NOMEM, "no memory for kernel %s", web_kernels[id].name);
    k->id = (kernel_id)id;
    k->plan = &PLANS[id];
    k->product = 1.0;
    isk_status s = ISK_OK;
    for (int c = 0; k->id == K_MEMORY && c < MEMORY_COLS && s == ISK_OK; c++) {
        k->col[c] = malloc(MEMORY_N * sizeof *k->col[c]);
        if (!k->col[c])
            s = ISK_ERR_NOMEM;
        for (size_t i = 0; k->col[c] && i < MEMORY_N; i++)
            k->col[c][i] = 1.0 + (double)(i % 7) / 8.0;
    }
    if (k->plan->particles) {
        s = bench_layer_effect(&k->fx, k->plan->particles, k->plan->draw, err);
        /* one thread: the browser's only one, and what the native side is held to */
        if (s == ISK_OK)
            s = isk_effect_set_threads(k->fx, 1);
        for (int i = 0; i < k->plan->steps_before && s == ISK_OK; i++)
            s = isk_effect_step(k->fx);
    }
    if (s == ISK_OK && k->plan->render)
        s = isk_canvas_init(&k->c, BENCH_LAYER_W, BENCH_LAYER_H);
    if (s != ISK_OK) {
        if (err && !err->message[0])
            isk_error_set(err, s, "kernel %s: %s", web_kernels[id].name, isk_status_str(s));
        web_kernel_free(k);
        return s;
    }
    *out = k;
    return ISK_OK;
}

isk_status web_kernel_run(web_kernel *k)
{
    if (!k)
        return ISK_ERR_NULL;
    if (k->id == K_ARITH) {
        k->product = arithmetic_chain(k->product);
        return ISK_OK;
    }
    if (k->id == K_MEMORY) {
        memory_pass(k->col);
        return ISK_OK;
    }
    isk_status s = k->plan->step ? isk_effect_step(k->fx) : ISK_OK;
    if (s == ISK_OK && k->plan->render)
        s = isk_effect_render(k->fx, &k->c);
    return s;
}

/* FNV-1a, 64 bits, over bytes. */
static const uint64_t FNV_BASIS = 14695981039346656037ull, FNV_PRIME = 1099511628211ull;

static uint64_t fnv1a(uint64_t h, const void *data, size_t size)
{
    const unsigned char *b = data;
    for (size_t i = 0; i < size; i++)
        h = (h ^ b[i]) * FNV_PRIME;
    return h;
}

uint64_t web_kernel_hash(const web_kernel *k)
{
    uint64_t h = FNV_BASIS;
    if (!k)
        return h;
    if (k->id == K_ARITH)
        return fnv1a(h, &k->product, sizeof k->product);
    for (int c = 0; k->id == K_MEMORY && c < MEMORY_COLS; c++)
        h = fnv1a(h, k->col[c], MEMORY_N * sizeof *k->col[c]);
    for (int e = 0; k->fx && e < isk_effect_emitter_count(k->fx); e++) {
        const isk_particles *p = isk_effect_particles(k->fx, e);
        const double *cols[4] = {p->x, p->y, p->vx, p->vy};
        for (int i = 0; i < 4; i++)
            h = fnv1a(h, cols[i], p->count * sizeof *cols[i]);
    }
    for (int y = 0; k->c.pixels && y < k->c.height; y++)
        h = fnv1a(h, k->c.pixels + (size_t)y * k->c.stride, 4 * (size_t)k->c.width);
    return h;
}

void web_kernel_free(web_kernel *k)
{
    if (!k)
        return;
    isk_effect_destroy(k->fx);
    for (int c = 0; c < MEMORY_COLS; c++)
        free(k->col[c]);
    if (k->c.pixels)
        isk_canvas_free(&k->c);
    free(k);
}
