/* SPDX-License-Identifier: MIT */
/* src/sim/workers.h — who runs an effect's independent items, and each
 * worker's scratch (internal).
 *
 * The workers are either the effect's own threads (src/sim/pool.h) or a
 * caller's job system (iskra/tasks.h); the runner and the renderer see
 * only this:
 *
 *     isk_workers w;
 *     isk__workers_init(&w);
 *     if (isk__workers_start(&w, 4) != ISK_OK) ...          // its own threads: the caller + 3
 *     isk__workers_for(&w, nblocks, 8, run_block, &ctx);   // run_block(&ctx, worker, i) for every i
 *     isk_scratch *s = isk__workers_scratch(&w, worker);   // inside run_block
 *     isk__workers_free(&w);
 *
 * Below `min_items` items, or with one worker, everything runs on the
 * calling thread in item order, as worker 0. */
#ifndef ISKRA_SIM_WORKERS_H
#define ISKRA_SIM_WORKERS_H

#include <stddef.h>

#include "iskra/integrate.h"
#include "iskra/status.h"
#include "iskra/tasks.h"

struct isk_pool;
union isk_workers_slot;

typedef struct isk_workers {
    isk_tasks tasks;              /* how a task's items are run */
    struct isk_pool *pool;        /* the effect's own threads, or NULL (the caller's tasks) */
    union isk_workers_slot *slot; /* per worker: its scratch, on cache lines of its own */
    int n;                        /* tasks.workers: 1 when nothing is started */
} isk_workers;

void isk__workers_init(isk_workers *w);
void isk__workers_free(isk_workers *w);
/* Its own threads: `threads` in 1 .. ISK_TASKS_MAX_WORKERS (the caller is
 * one of them).  ISK_ERR_RANGE, ISK_ERR_NOMEM, ISK_ERR_UNSUPPORTED (a
 * thread could not start); on error w is as it was. */
isk_status isk__workers_start(isk_workers *w, int threads);
/* A caller's job system instead (validated: ISK_ERR_NULL without run,
 * ISK_ERR_RANGE for a worker count out of range); on error w is as it was. */
isk_status isk__workers_use(isk_workers *w, const isk_tasks *tasks);
int isk__workers_count(const isk_workers *w);
isk_scratch *isk__workers_scratch(isk_workers *w, int worker);
void isk__workers_for(isk_workers *w, size_t n, size_t min_items, isk_task_fn *fn, void *task);

#endif
