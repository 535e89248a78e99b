/* SPDX-License-Identifier: MIT */
/* Who runs an effect's independent items (see workers.h). */
#include "sim/workers.h"

#include <stdlib.h>
#include <string.h>

#include "core/fast_paths.h"
#include "sim/pool.h"

/* A worker's scratch on cache lines of its own (and 64-byte aligned, for
 * the vector loops over it): a whole number of lines. */
union isk_workers_slot {
    isk_scratch s;
    unsigned char line[(sizeof(isk_scratch) + 63) / 64 * 64];
};

static void run_on_caller(void *user, isk_task_fn *fn, void *task, size_t n)
{
    (void)user;
    for (size_t i = 0; i < n; i++)
        fn(task, 0, i);
}

static void run_on_pool(void *user, isk_task_fn *fn, void *task, size_t n) { isk__pool_for(user, n, fn, task); }

void isk__workers_init(isk_workers *w)
{
    memset(w, 0, sizeof *w);
    w->tasks = (isk_tasks){1, run_on_caller, NULL};
    w->n = 1;
}

void isk__workers_free(isk_workers *w)
{
    isk__pool_destroy(w->pool);
    free(w->slot);
    isk__workers_init(w);
}

/* n zeroed scratch slots, or NULL. */
static union isk_workers_slot *slots(int n)
{
    union isk_workers_slot *s = aligned_alloc(64, sizeof *s * (size_t)n);
    if (s)
        memset(s, 0, sizeof *s * (size_t)n);
    return s;
}

isk_status isk__workers_start(isk_workers *w, int threads)
{
    if (threads < 1 || threads > ISK_TASKS_MAX_WORKERS)
        return ISK_ERR_RANGE;
    union isk_workers_slot *slot = slots(threads);
    if (!slot)
        return ISK_ERR_NOMEM;
    isk_pool *pool = NULL;
    isk_status s = ISK__FAST_WORKERS && threads > 1 ? isk__pool_create(&pool, threads) : ISK_OK;
    if (s != ISK_OK) {
        free(slot);
        return s;
    }
    isk__workers_free(w);
    w->pool = pool;
    w->slot = slot;
    w->n = threads;
    w->tasks = pool ? (isk_tasks){threads, run_on_pool, pool} : (isk_tasks){1, run_on_caller, NULL};
    return ISK_OK;
}

isk_status isk__workers_use(isk_workers *w, const isk_tasks *tasks)
{
    if (!tasks || !tasks->run)
        return ISK_ERR_NULL;
    if (tasks->workers < 1 || tasks->workers > ISK_TASKS_MAX_WORKERS)
        return ISK_ERR_RANGE;
    union isk_workers_slot *slot = slots(tasks->workers);
    if (!slot)
        return ISK_ERR_NOMEM;
    isk__workers_free(w);
    w->slot = slot;
    w->n = tasks->workers;
    w->tasks = *tasks;
    return ISK_OK;
}

int isk__workers_count(const isk_workers *w) { return w->n; }

isk_scratch *isk__workers_scratch(isk_workers *w, int worker) { return &w->slot[worker].s; }

void isk__workers_for(isk_workers *w, size_t n, size_t min_items, isk_task_fn *fn, void *task)
{
    if (n == 0)
        return;
    if (!ISK__FAST_WORKERS || w->n == 1 || n < min_items || n < 2) { /* the reference: in order */
        run_on_caller(NULL, fn, task, n);
        return;
    }
    w->tasks.run(w->tasks.user, fn, task, n);
}

int isk_threads_from_text(const char *text)
{
    if (!text || !*text)
        return 0;
    long n = 0;
    for (const char *c = text; *c; c++) {
        if (*c < '0' || *c > '9')
            return 0;
        n = n * 10 + (*c - '0');
        if (n > ISK_TASKS_MAX_WORKERS)
            return 0;
    }
    return n >= 1 ? (int)n : 0;
}
