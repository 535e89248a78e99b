/* SPDX-License-Identifier: MIT */
/* src/sim/pool.h — a fixed set of worker threads for the block runner and
 * the renderer (internal).
 *
 *     isk_pool *pool;
 *     if (isk_pool_create(&pool, 4) != ISK_OK) ...     // the caller + 3 threads
 *     isk_pool_for(pool, nblocks, run_block, &ctx);     // run_block(&ctx, worker, i) for every i
 *     isk_pool_destroy(pool);
 *
 * isk_pool_for hands out the items [0, n) in small chunks to whichever
 * thread asks next (the caller works too) and returns when every item is
 * done.  Which thread ran which item is never observable in the results:
 * callers only give it items that are independent of one another (blocks of
 * particles whose stages touch nothing outside their block, tiles of a
 * canvas), each worker has its own scratch, and anything combined across
 * items is combined afterwards in item order.  That is how the bytes stay
 * the same for every number of threads.
 *
 * One pool serves one caller at a time (an effect owns its pool).  A pool
 * of 1 thread runs everything on the caller, with no thread at all.
 */
#ifndef ISKRA_SIM_POOL_H
#define ISKRA_SIM_POOL_H

#include <stddef.h>

#include "iskra/integrate.h"
#include "iskra/status.h"

/* More threads than this are refused (the machine's cores are far fewer). */
#define ISK_POOL_MAX_THREADS 256

typedef struct isk_pool isk_pool;

typedef void (*isk_pool_fn)(void *ctx, int worker, size_t item);

/* threads >= 1 (1: no extra thread).  ISK_ERR_RANGE, ISK_ERR_NOMEM, or
 * ISK_ERR_UNSUPPORTED when a thread cannot be started. */
isk_status isk_pool_create(isk_pool **out, int threads);
void isk_pool_destroy(isk_pool *pool);
int isk_pool_threads(const isk_pool *pool);
/* The worker's own per-block scratch (worker 0 is the caller). */
isk_scratch *isk_pool_scratch(isk_pool *pool, int worker);
/* fn(ctx, worker, i) for every i in [0, n), on every thread; returns when
 * all are done.  With one thread, or n below `min_items`, everything runs
 * on the caller in item order. */
void isk_pool_for(isk_pool *pool, size_t n, size_t min_items, isk_pool_fn fn, void *ctx);

/* A monotonic clock, in seconds: what the pool and the threaded draw time
 * themselves with. */
double isk_pool_seconds(void);
/* The machine's online cores (at least 1). */
int isk_pool_online_cores(void);

#endif
