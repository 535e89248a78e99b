/* SPDX-License-Identifier: MIT */
/* Worker threads for independent items (see pool.h): POSIX threads, one
 * mutex and two condition variables; every thread takes its own range of
 * the items first, in chunks (long ones while much is left) claimed by an
 * atomic counter, then helps with the others' ranges. */
#include "sim/pool.h"

#if ISK__POOL_THREADS /* else pool_serial.c */
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <unistd.h>

/* The fewest items a thread takes at a time (fewer only at the end of a
 * job, or for a job of few items): long enough that each thread streams
 * through long runs of the store.  A claim takes more while much is left
 * (take_range), so the runs are longer still at the start of a job and the
 * shares even out at its end; each thread starts on a range of its own
 * (the same blocks every frame, still in its caches).  The count rule in
 * isk__pool_for still gives every thread at least four chunks, and a job of
 * few items (a draw's bands: one per thread) is handed out one at a time,
 * or the first thread to come would take them all.  The measures behind
 * the numbers: docs/performance.md, "The pool's chunks". */
enum { CHUNK = 64 };

/* How long the caller waits awake for workers that are all running (then
 * asleep), in spin-loop hints: the last claims of a job are one chunk
 * each.  A count, not a time: the library reads no clock, and the wait
 * only decides how soon the caller notices, never what is computed
 * (docs/performance.md, "Threads", has what it is worth). */
#define CALLER_SPIN_ROUNDS 32768

/* A thread's own part of a job's items, on cache lines of its own. */
typedef struct pool_range {
    _Alignas(64) atomic_size_t next; /* the first of its items nobody has taken */
    size_t end;
} pool_range;

struct isk_pool {
    int threads;
    pthread_t *tid;            /* threads - 1 of them */
    pthread_mutex_t lock;
    pthread_cond_t start, done;
    /* the current job (set under the lock before generation moves on) */
    isk_task_fn *fn;
    void *ctx;
    size_t chunk;
    pool_range *range;         /* thread t's own items, [t n / threads, (t+1) n / threads) */
    int generation;            /* a new job bumps it */
    atomic_int running;        /* workers still inside the current job (changed under the lock) */
    atomic_int awake;          /* workers that have started the current job */
    int quit;
};

typedef struct worker_arg {
    isk_pool *pool;
    int worker;
} worker_arg;

/* Claims from one range (guided, as OpenMP calls it): a quarter of what
 * is left in it, never less than the job's chunk, so the first claims are
 * long runs and the last are one chunk. */
static void take_range(isk_pool *p, pool_range *r, int worker)
{
    const size_t end = r->end, least = p->chunk;
    size_t i = atomic_load_explicit(&r->next, memory_order_relaxed);
    for (;;) {
        if (i >= end)
            return;
        size_t take = (end - i) / 4;
        take = take < least ? least : take;
        take = take < end - i ? take : end - i;
        if (!atomic_compare_exchange_weak_explicit(&r->next, &i, i + take, memory_order_relaxed,
                                                   memory_order_relaxed))
            continue; /* i now holds what another thread left: try again from there */
        for (size_t stop = i + take; i < stop; i++)
            p->fn(p->ctx, worker, i);
        i = atomic_load_explicit(&r->next, memory_order_relaxed);
    }
}

/* Every thread starts on a range of its own, the same items at every job
 * of the same size (so the blocks a thread stepped last frame are still
 * in its caches this frame), then helps with the others' in turn; both
 * threads end within a chunk of each other. */
static void take_items(isk_pool *p, int worker)
{
    for (int k = 0; k < p->threads; k++)
        take_range(p, &p->range[(worker + k) % p->threads], worker);
}

/* The processor's hint that this is a spin loop. */
static void spin_pause(void)
{
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#elif defined(__aarch64__)
    __asm__ __volatile__("yield");
#endif
}

/* Spins until *v is 0 or `rounds` hints have passed. */
static void spin_until_zero(atomic_int *v, long rounds)
{
    for (long k = 0; k < rounds; k++) {
        if (atomic_load(v) == 0)
            return;
        spin_pause();
    }
}

static void *worker_main(void *arg)
{
    isk_pool *p = ((worker_arg *)arg)->pool;
    const int worker = ((worker_arg *)arg)->worker;
    free(arg);
    int seen = 0;
    pthread_mutex_lock(&p->lock);
    for (;;) {
        while (p->generation == seen && !p->quit)
            pthread_cond_wait(&p->start, &p->lock);
        if (p->quit)
            break;
        seen = p->generation;
        atomic_fetch_add(&p->awake, 1);
        pthread_mutex_unlock(&p->lock);
        take_items(p, worker);
        pthread_mutex_lock(&p->lock);
        if (atomic_fetch_sub(&p->running, 1) == 1)
            pthread_cond_signal(&p->done);
    }
    pthread_mutex_unlock(&p->lock);
    return NULL;
}

int isk__pool_online_cores(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : n > ISK_TASKS_MAX_WORKERS ? ISK_TASKS_MAX_WORKERS : (int)n;
}

isk_status isk__pool_create(isk_pool **out, int threads)
{
    if (!out)
        return ISK_ERR_NULL;
    *out = NULL;
    if (threads < 1 || threads > ISK_TASKS_MAX_WORKERS)
        return ISK_ERR_RANGE;
    isk_pool *p = calloc(1, sizeof *p);
    if (!p)
        return ISK_ERR_NOMEM;
    p->threads = threads;
    p->range = aligned_alloc(64, sizeof *p->range * (size_t)threads);
    p->tid = calloc((size_t)threads, sizeof *p->tid);
    if (!p->range || !p->tid) {
        free(p->range);
        free(p->tid);
        free(p);
        return ISK_ERR_NOMEM;
    }
    for (int t = 0; t < threads; t++) {
        atomic_init(&p->range[t].next, 0);
        p->range[t].end = 0;
    }
    pthread_mutex_init(&p->lock, NULL);
    pthread_cond_init(&p->start, NULL);
    pthread_cond_init(&p->done, NULL);
    atomic_init(&p->running, 0);
    atomic_init(&p->awake, 0);
    /* Workers start with every signal blocked (they inherit this mask), so
     * a process signal goes to one of the caller's threads: a program's
     * handler and its own blocking (the CLI's removal of temporaries) keep
     * working when a library thread exists. */
    sigset_t all, caller;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &caller);
    isk_status s = ISK_OK;
    for (int w = 1; w < threads && s == ISK_OK; w++) {
        worker_arg *a = malloc(sizeof *a);
        s = a ? ISK_OK : ISK_ERR_NOMEM;
        if (a) {
            a->pool = p;
            a->worker = w;
            if (pthread_create(&p->tid[w - 1], NULL, worker_main, a) != 0) {
                free(a);
                s = ISK_ERR_UNSUPPORTED;
            }
        }
        if (s != ISK_OK)
            p->threads = w; /* the ones started are joined */
    }
    pthread_sigmask(SIG_SETMASK, &caller, NULL);
    if (s != ISK_OK) {
        isk__pool_destroy(p);
        return s;
    }
    *out = p;
    return ISK_OK;
}

void isk__pool_destroy(isk_pool *p)
{
    if (!p)
        return;
    pthread_mutex_lock(&p->lock);
    p->quit = 1;
    pthread_cond_broadcast(&p->start);
    pthread_mutex_unlock(&p->lock);
    for (int w = 1; w < p->threads; w++)
        pthread_join(p->tid[w - 1], NULL);
    pthread_mutex_destroy(&p->lock);
    pthread_cond_destroy(&p->start);
    pthread_cond_destroy(&p->done);
    free(p->range);
    free(p->tid);
    free(p);
}

int isk__pool_threads(const isk_pool *p) { return p ? p->threads : 1; }

void isk__pool_for(isk_pool *p, size_t n, isk_task_fn *fn, void *ctx)
{
    if (n == 0)
        return;
    if (p->threads == 1 || n < 2) {
        for (size_t i = 0; i < n; i++)
            fn(ctx, 0, i);
        return;
    }
    pthread_mutex_lock(&p->lock);
    p->fn = fn;
    p->ctx = ctx;
    /* every thread can get at least four chunks */
    p->chunk = n / ((size_t)p->threads * 4) < CHUNK ? n / ((size_t)p->threads * 4) : CHUNK;
    if (p->chunk < 1)
        p->chunk = 1;
    for (int t = 0; t < p->threads; t++) {
        atomic_store_explicit(&p->range[t].next, (size_t)((unsigned long long)n * t / p->threads),
                              memory_order_relaxed);
        p->range[t].end = (size_t)((unsigned long long)n * (t + 1) / p->threads);
    }
    atomic_store(&p->running, p->threads - 1);
    atomic_store(&p->awake, 0);
    p->generation++;
    pthread_cond_broadcast(&p->start);
    pthread_mutex_unlock(&p->lock);
    take_items(p, 0);
    /* When every worker has started the job, they end soon after the
     * caller (their last claims are a chunk each): waiting for them asleep
     * would add the time the system takes to run a woken thread again.  A
     * worker still asleep is waited for asleep: spinning then can keep it
     * from waking where two virtual cores share a physical one. */
    if (atomic_load(&p->awake) == p->threads - 1)
        spin_until_zero(&p->running, CALLER_SPIN_ROUNDS);
    pthread_mutex_lock(&p->lock);
    while (atomic_load(&p->running) > 0)
        pthread_cond_wait(&p->done, &p->lock);
    pthread_mutex_unlock(&p->lock);
}
#endif
