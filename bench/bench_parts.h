/* SPDX-License-Identifier: MIT */
/* bench/bench_parts.h — a bench_frame row's work done as independent
 * parts: `parts` copies of bench_layer.h's effect with n / parts particles
 * each, every one on one thread of its own, their frames all at once.
 * They share nothing (no store, no canvas, no pool), so their speedup over
 * the whole on one thread is what the machine gives that many cores for
 * this work: the measure the speed goals started from ("two processes of
 * half the size take about half the time").  A threaded effect can be
 * read against it: whatever it loses beyond it is the cost of sharing one
 * store and one canvas between the cores.
 *
 *     bench_parts p;
 *     isk_error err = {0};
 *     if (bench_parts_start(&p, 2, 1000000, ISK_DRAW_DOT, &err) == ISK_OK) {
 *         bench_parts_run(&p, 1, 600);             // every part steps 600 times (not timed)
 *         double s = bench_parts_run(&p, 0, 1);    // one frame each (step + render), at once
 *         bench_parts_stop(&p);
 *     }
 *
 * Header-only (static functions) so each benchmark stays one program. */
#ifndef ISKRA_BENCH_PARTS_H
#define ISKRA_BENCH_PARTS_H

#include <pthread.h>

#include "bench_controls.h"
#include "bench_layer.h"
#include "bench_util.h"

enum { BENCH_PARTS_MAX = 64 };

typedef struct bench_parts bench_parts;

typedef struct bench_part {
    bench_parts *all;
    int k;
    isk_effect *fx;
    isk_canvas c;
    isk_status status;
} bench_part;

struct bench_parts {
    int n;
    bench_part part[BENCH_PARTS_MAX];
    pthread_t tid[BENCH_PARTS_MAX]; /* part k > 0's */
    int started;                    /* threads started */
    bench_gate gate;
    pthread_barrier_t start, done;
    int quit, steps_only, times;    /* the job of the next start */
};

static inline void bench_part_job(bench_part *p)
{
    const bench_parts *a = p->all;
    for (int i = 0; i < a->times && p->status == ISK_OK; i++) {
        p->status = isk_effect_step(p->fx);
        if (p->status == ISK_OK && !a->steps_only)
            p->status = isk_effect_render(p->fx, &p->c);
    }
}

static inline void *bench_part_thread(void *arg)
{
    bench_part *p = arg;
    if (!bench_gate_wait(&p->all->gate))
        return NULL;
    for (;;) {
        pthread_barrier_wait(&p->all->start);
        if (p->all->quit)
            return NULL;
        bench_part_job(p);
        pthread_barrier_wait(&p->all->done);
    }
}

static inline void bench_parts_free(bench_parts *a)
{
    for (int k = 0; k < a->n; k++) {
        isk_effect_destroy(a->part[k].fx);
        isk_canvas_free(&a->part[k].c);
    }
}

/* The parts' effects and threads; on failure nothing is left. */
static inline isk_status bench_parts_start(bench_parts *a, int parts, size_t n, isk_draw_mode draw,
                                            isk_error *err)
{
    memset(a, 0, sizeof *a);
    if (parts < 1 || parts > BENCH_PARTS_MAX)
        return ISK_ERR_RANGE;
    a->n = parts;
    isk_status s = ISK_OK;
    for (int k = 0; k < parts && s == ISK_OK; k++) {
        bench_part *p = &a->part[k];
        *p = (bench_part){a, k, NULL, {0}, ISK_OK};
        const size_t share = (size_t)((unsigned long long)n * (unsigned)(k + 1) / (unsigned)parts -
                                      (unsigned long long)n * (unsigned)k / (unsigned)parts);
        s = bench_layer_effect(&p->fx, share, draw, err);
        if (s == ISK_OK)
            s = isk_effect_set_threads(p->fx, 1);
        if (s == ISK_OK)
            s = isk_canvas_init(&p->c, BENCH_LAYER_W, BENCH_LAYER_H);
    }
    if (s != ISK_OK) {
        bench_parts_free(a);
        return s;
    }
    a->gate = (bench_gate)BENCH_GATE_INIT;
    pthread_barrier_init(&a->start, NULL, (unsigned)parts);
    pthread_barrier_init(&a->done, NULL, (unsigned)parts);
    a->started = 1;
    for (int k = 1; k < parts && a->started == k; k++)
        a->started += pthread_create(&a->tid[k], NULL, bench_part_thread, &a->part[k]) == 0;
    bench_gate_open(&a->gate, a->started == parts);
    if (a->started < parts) {
        for (int k = 1; k < a->started; k++)
            pthread_join(a->tid[k], NULL);
        pthread_barrier_destroy(&a->start);
        pthread_barrier_destroy(&a->done);
        bench_parts_free(a);
        return ISK_ERR_UNSUPPORTED;
    }
    return ISK_OK;
}

/* Every part, at once, `times` frames (steps_only: steps, no render):
 * seconds from the start of the first to the end of the last, or a
 * negative number when a part failed. */
static inline double bench_parts_run(bench_parts *a, int steps_only, int times)
{
    a->steps_only = steps_only;
    a->times = times;
    const double t0 = bench_now();
    pthread_barrier_wait(&a->start);
    bench_part_job(&a->part[0]);
    pthread_barrier_wait(&a->done);
    const double t = bench_now() - t0;
    for (int k = 0; k < a->n; k++)
        if (a->part[k].status != ISK_OK)
            return -1.0;
    return t;
}

static inline void bench_parts_stop(bench_parts *a)
{
    a->quit = 1;
    pthread_barrier_wait(&a->start);
    for (int k = 1; k < a->n; k++)
        pthread_join(a->tid[k], NULL);
    pthread_barrier_destroy(&a->start);
    pthread_barrier_destroy(&a->done);
    bench_parts_free(a);
}

#endif
