/* SPDX-License-Identifier: MIT */
/* bench/bench_controls.h — what the machine gives a second thread, measured
 * beside a benchmark's own rows: on a shared VM that changes from minute to
 * minute, and a speedup can only be read against it.
 *
 *     printf("cores %.2f  memory %.2f  shared lines %.2fx\n",
 *            cores_given(2), memory_given(2), shared_lines_cost(2));
 *
 * cores_given: a job of pure arithmetic on 1 thread and on `threads` at
 * once, how many cores' worth of work the machine did.  memory_given: the
 * same for the update's pattern over columns beyond the caches.
 * shared_lines_cost: how much longer the threads take to write lines that
 * every thread has just read than lines only the writer read.
 * bench_run_shares: a function on shares of a job at once, one thread
 * each, the caller taking the first (what the controls and bench_dense's
 * threaded loops time).
 *
 * Header-only (static functions) so each benchmark stays one program. */
#ifndef ISKRA_BENCH_CONTROLS_H
#define ISKRA_BENCH_CONTROLS_H

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "bench_util.h"

/* Threads started one by one wait here until all are (go = 1), or learn
 * that one could not be started (go = -1) and return: a barrier sized for
 * all of them would otherwise never open. */
typedef struct bench_gate {
    pthread_mutex_t lock;
    pthread_cond_t open;
    int go;
} bench_gate;
#define BENCH_GATE_INIT {PTHREAD_MUTEX_INITIALIZER, PTHREAD_COND_INITIALIZER, 0}

/* 1: every thread started, go on; 0: return. */
static inline int bench_gate_wait(bench_gate *g)
{
    pthread_mutex_lock(&g->lock);
    while (!g->go)
        pthread_cond_wait(&g->open, &g->lock);
    const int go = g->go;
    pthread_mutex_unlock(&g->lock);
    return go > 0;
}

static inline void bench_gate_open(bench_gate *g, int all_started)
{
    pthread_mutex_lock(&g->lock);
    g->go = all_started ? 1 : -1;
    pthread_cond_broadcast(&g->open);
    pthread_mutex_unlock(&g->lock);
}

/* fn on `threads` shares at once (at most BENCH_SHARES_MAX), share k's
 * argument at args + k * size: share 0 on the caller, the others on
 * threads of their own.  Seconds of wall time.  A share whose thread
 * cannot be started runs on the caller instead (the time then says so),
 * and *all_started, when not NULL, is 0. */
enum { BENCH_SHARES_MAX = 64 };
static inline double bench_run_shares(void *(*fn)(void *), void *args, size_t size, int threads, int *all_started)
{
    pthread_t t[BENCH_SHARES_MAX];
    int started[BENCH_SHARES_MAX] = {0}, all = 1;
    threads = threads < BENCH_SHARES_MAX ? threads : BENCH_SHARES_MAX;
    char *a = args;
    const double t0 = bench_now();
    for (int k = 1; k < threads; k++) {
        started[k] = pthread_create(&t[k], NULL, fn, a + (size_t)k * size) == 0;
        if (!started[k])
            fn(a + (size_t)k * size);
        all &= started[k];
    }
    fn(a);
    for (int k = 1; k < threads; k++)
        if (started[k])
            pthread_join(t[k], NULL);
    if (all_started)
        *all_started = all;
    return bench_now() - t0;
}

static inline void *arithmetic(void *arg)
{
    volatile double x = 1.0;
    for (long i = 0; i < 40000000; i++) /* a dependent chain: no memory, no vector */
        x = x * 1.0000001;
    return arg;
}

/* Work done on `threads` threads at once over the work of one, per unit of
 * time: `threads` when the machine gives that many cores (0 when a thread
 * could not be started). */
static inline double cores_given(int threads)
{
    char none; /* arithmetic takes no argument */
    threads = threads < BENCH_SHARES_MAX ? threads : BENCH_SHARES_MAX;
    const double one = bench_run_shares(arithmetic, &none, 0, 1, NULL);
    int all = 0;
    const double at_once = bench_run_shares(arithmetic, &none, 0, threads, &all);
    return all && at_once > 0 ? threads * one / at_once : 0;
}

/* The same for memory: a semi-implicit Euler step with drag over five
 * columns of 2*10^6 (x, y, vx, vy, m: 80 MB, beyond the caches; five
 * streams read and four written, as the update's), on one thread and then
 * shared out over `threads`: how much more bandwidth that many threads get
 * than one for the update's pattern.  A row whose update is bound by memory
 * (a falling layer of 10^6 moves 72 MB a step) can speed up by that much
 * at most, however many cores it is given.  (A pass over two columns gets
 * more from a second thread: one thread alone cannot keep enough misses in
 * flight on two streams, while the update's nine let it take most of the
 * memory's bandwidth by itself.) */
enum { MEM_N = 2000000, MEM_COLS = 5 };
typedef struct mem_share {
    double *col[MEM_COLS];
    size_t lo, hi;
} mem_share;

static inline void *memory_pass(void *arg)
{
    mem_share *s = arg;
    double *restrict x = s->col[0], *restrict y = s->col[1], *restrict vx = s->col[2], *restrict vy = s->col[3];
    const double *restrict m = s->col[4];
    const double h = 1.0 / 60, g = -9.81, b = 0.3;
    for (size_t i = s->lo; i < s->hi; i++) {
        const double k = b * m[i]; /* m read as 1/m: no division to bound the pass */
        vx[i] -= h * k * vx[i];
        vy[i] += h * (g - k * vy[i]);
        x[i] += h * vx[i];
        y[i] += h * vy[i];
    }
    return NULL;
}

/* One pass over the columns shared out over `threads`: seconds, or a
 * negative number when a thread could not be started. */
static inline double memory_pass_time(double **col, int threads)
{
    mem_share s[BENCH_SHARES_MAX];
    const int n = threads < BENCH_SHARES_MAX ? threads : BENCH_SHARES_MAX;
    for (int k = 0; k < n; k++) {
        memcpy(s[k].col, col, sizeof s[k].col);
        s[k].lo = (size_t)MEM_N * (size_t)k / (size_t)n;
        s[k].hi = (size_t)MEM_N * (size_t)(k + 1) / (size_t)n;
    }
    int all = 0;
    const double seconds = bench_run_shares(memory_pass, s, sizeof *s, n, &all);
    return all ? seconds : -1.0;
}

/* The best of seven passes each way, one thread and `threads` in turn (a
 * pass takes a millisecond or two: fewer let the machine's load decide). */
static inline double memory_given(int threads)
{
    double *col[MEM_COLS] = {NULL};
    int ok = 1;
    for (int c = 0; c < MEM_COLS; c++) {
        col[c] = malloc(MEM_N * sizeof *col[c]);
        ok = ok && col[c];
        for (size_t i = 0; col[c] && i < MEM_N; i++)
            col[c][i] = 1.0;
    }
    double one = 1e30, all = 1e30;
    for (int rep = 0; ok && rep < 7; rep++) {
        const double t1 = memory_pass_time(col, 1), tn = memory_pass_time(col, threads);
        one = t1 > 0 && t1 < one ? t1 : one;
        all = tn > 0 && tn < all ? tn : all;
    }
    for (int c = 0; c < MEM_COLS; c++)
        free(col[c]);
    return ok && one < 1e30 && all < 1e30 ? one / all : 0;
}

/* The cost of passing lines between the cores.  A threaded frame does it
 * every frame: each band of the draw reads every particle's x and y, and
 * the next update, each thread on its own share, writes them.  When the
 * two virtual cores share a cache that costs nothing; when the VM places
 * them apart (for minutes at a time here), a write must first take the
 * line from the other core's caches.  Measured as that pattern: every
 * thread reads the whole of SHARED_BYTES, then each writes its own share
 * of it, against each reading and then writing its own share only; the
 * ratio of the writes' times, best of seven each (1.0 near; 3-4 far, as
 * seen on 2026-12-05). */
enum { SHARED_BYTES = 16 << 20, SHARED_REPS = 7 };

typedef struct shared_pass {
    double *a;
    size_t n;
    int threads, k, read_all;
    bench_gate *gate;
    pthread_barrier_t *read, *write, *done;
    double seconds[SHARED_REPS];
} shared_pass;

static inline void *shared_lines_thread(void *arg)
{
    shared_pass *s = arg;
    if (!bench_gate_wait(s->gate))
        return NULL;
    const size_t lo = s->n * (size_t)s->k / (size_t)s->threads, hi = s->n * (size_t)(s->k + 1) / (size_t)s->threads;
    for (int rep = 0; rep < SHARED_REPS; rep++) {
        pthread_barrier_wait(s->read);
        volatile double sum = 0.0;
        double acc = 0.0;
        for (size_t i = s->read_all ? 0 : lo; i < (s->read_all ? s->n : hi); i += 8) /* a line each */
            acc += s->a[i];
        sum = acc;
        (void)sum;
        pthread_barrier_wait(s->write);
        const double t0 = bench_now();
        for (size_t i = lo; i < hi; i++)
            s->a[i] = s->a[i] * 0.5 + 1.0;
        s->seconds[rep] = bench_now() - t0;
        pthread_barrier_wait(s->done);
    }
    return NULL;
}

/* The slowest thread's best write time, the lines read as read_all says;
 * negative when a thread could not be started. */
static inline double shared_lines_pass(double *a, size_t n, int threads, int read_all)
{
    pthread_t t[64];
    shared_pass s[64];
    pthread_barrier_t read, write, done;
    pthread_barrier_init(&read, NULL, (unsigned)threads);
    pthread_barrier_init(&write, NULL, (unsigned)threads);
    pthread_barrier_init(&done, NULL, (unsigned)threads);
    bench_gate gate = BENCH_GATE_INIT;
    int started = 1;
    for (int k = 0; k < threads; k++)
        s[k] = (shared_pass){a, n, threads, k, read_all, &gate, &read, &write, &done, {0}};
    for (int k = 1; k < threads && started == k; k++)
        started += pthread_create(&t[k], NULL, shared_lines_thread, &s[k]) == 0;
    bench_gate_open(&gate, started == threads);
    double worst = -1.0;
    if (started == threads) {
        shared_lines_thread(&s[0]);
        worst = 0.0;
        for (int k = 0; k < threads; k++) {
            double best = 1e30;
            for (int rep = 0; rep < SHARED_REPS; rep++)
                best = s[k].seconds[rep] < best ? s[k].seconds[rep] : best;
            worst = best > worst ? best : worst;
        }
    }
    for (int k = 1; k < started; k++)
        pthread_join(t[k], NULL);
    pthread_barrier_destroy(&read);
    pthread_barrier_destroy(&write);
    pthread_barrier_destroy(&done);
    return worst;
}

/* The writes' time after every thread read the lines over their time after
 * only the writer did: 1 when passing lines between the cores is free; 0
 * when it could not be measured. */
static inline double shared_lines_cost(int threads)
{
    if (threads < 2 || threads > 64)
        return 0.0;
    const size_t n = SHARED_BYTES / sizeof(double);
    double *a = malloc(SHARED_BYTES);
    if (!a)
        return 0.0;
    for (size_t i = 0; i < n; i++)
        a[i] = 1.0;
    const double own = shared_lines_pass(a, n, threads, 0), all = shared_lines_pass(a, n, threads, 1);
    free(a);
    return own > 0 && all > 0 ? all / own : 0.0;
}

#endif
