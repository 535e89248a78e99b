/* SPDX-License-Identifier: MIT */
/* src/sim/pool.h — a fixed set of worker threads: an effect's own, when
 * the caller gives it no job system of its own (internal; the runner and
 * the renderer reach it through src/sim/workers.h).
 *
 *     isk_pool *pool;
 *     if (isk__pool_create(&pool, 4) != ISK_OK) ...     // the caller + 3 threads
 *     isk__pool_for(pool, nblocks, run_block, &ctx);     // run_block(&ctx, worker, i) for every i
 *     isk__pool_destroy(pool);
 *
 * isk__pool_for hands out the items [0, n) in chunks to whichever thread
 * asks next (the caller works too) and returns when every item is done.
 * Which thread ran which item is never observable in the results: callers
 * only give it items that are independent of one another (blocks of
 * particles whose stages touch nothing outside their block, bands of a
 * canvas), each worker has its own scratch (workers.h), and anything
 * combined across items is combined afterwards in item order.  That is how
 * the bytes stay the same for every number of threads.
 *
 * One pool serves one caller at a time (an effect owns its pool).  A pool
 * of 1 thread runs everything on the caller, with no thread at all.
 *
 * Targets without threads (the browser's wasm32-wasi) get pool_serial.c
 * instead of pool.c: a pool of any size that runs every item on the
 * caller, in order, which gives the bytes of every thread count because
 * the items never depend on who runs them.  ISK__POOL_THREADS says which
 * of the two files this target compiles.
 */
#ifndef ISKRA_SIM_POOL_H
#define ISKRA_SIM_POOL_H

#include <stddef.h>

#include "iskra/status.h"
#include "iskra/tasks.h"

#if defined(__wasi__) && !defined(_REENTRANT)
#define ISK__POOL_THREADS 0
#else
#define ISK__POOL_THREADS 1
#endif

typedef struct isk_pool isk_pool;

/* threads in 1 .. ISK_TASKS_MAX_WORKERS (1: no extra thread; without
 * ISK__POOL_THREADS every size runs on the caller alone).
 * ISK_ERR_RANGE, ISK_ERR_NOMEM, or ISK_ERR_UNSUPPORTED when a thread
 * cannot be started. */
isk_status isk__pool_create(isk_pool **out, int threads);
void isk__pool_destroy(isk_pool *pool);
int isk__pool_threads(const isk_pool *pool);
/* fn(ctx, worker, i) for every i in [0, n), on every thread; returns when
 * all are done. */
void isk__pool_for(isk_pool *pool, size_t n, isk_task_fn *fn, void *ctx);
/* The machine's online cores (at least 1). */
int isk__pool_online_cores(void);

#endif
