/* SPDX-License-Identifier: MIT */
/* The pool of a target without threads (see pool.h): every item runs on
 * the caller, in order.  The bytes are those of every thread count, since
 * items never depend on which thread runs them or when. */
#include "sim/pool.h"

#if !ISK__POOL_THREADS /* else pool.c */
#include <stdlib.h>

struct isk_pool {
    int threads; /* what was asked for: callers size their scratch by it */
};

int isk__pool_online_cores(void) { return 1; }

isk_status isk__pool_create(isk_pool **out, int threads)
{
    if (!out)
        return ISK_ERR_NULL;
    *out = NULL;
    if (threads < 1 || threads > ISK_TASKS_MAX_WORKERS)
        return ISK_ERR_RANGE;
    isk_pool *p = malloc(sizeof *p);
    if (!p)
        return ISK_ERR_NOMEM;
    p->threads = threads;
    *out = p;
    return ISK_OK;
}

void isk__pool_destroy(isk_pool *p) { free(p); }

int isk__pool_threads(const isk_pool *p) { return p ? p->threads : 1; }

void isk__pool_for(isk_pool *p, size_t n, isk_task_fn *fn, void *ctx)
{
    (void)p;
    for (size_t i = 0; i < n; i++)
        fn(ctx, 0, i);
}
#else
typedef int isk__pool_serial_unused; /* ISO C wants a declaration in every file */
#endif
