/* SPDX-License-Identifier: MIT */
/* iskra/tasks.h — run an effect's parallel work on your own threads.
 *
 * An effect shares out items that are independent of one another (blocks
 * of particles to step, bands of the canvas to draw) among workers.  By
 * default it starts threads of its own (isk_effect_set_threads).  A
 * program that has a job system already hands it that instead, as Box2D
 * v3's enqueueTask does: an isk_tasks says how many workers there are and
 * how to run a task's items on them.
 *
 * The bytes never depend on it: which worker runs which item, and in what
 * order, is never seen in the results (each worker has its own scratch,
 * and whatever is combined across items is combined afterwards in item
 * order), so any isk_tasks gives the same images as one thread.
 *
 * Example:
 *
 *     #include <stddef.h>
 *     #include "iskra/tasks.h"
 *
 *     // One worker, the calling thread: the items in order.  A real job
 *     // system would hand them to its threads, each call on a worker
 *     // number that no other call is using at the same moment.
 *     static void run_in_order(void *user, isk_task_fn *fn, void *task, size_t n)
 *     {
 *         (void)user;
 *         for (size_t i = 0; i < n; i++)
 *             fn(task, 0, i);
 *     }
 *
 *     // in main():
 *     isk_tasks tasks = {1, run_in_order, NULL};
 *     (void)tasks;  // isk_effect_set_tasks(fx, &tasks) (iskra/effect.h)
 */
#ifndef ISKRA_TASKS_H
#define ISKRA_TASKS_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The most workers an isk_tasks (or isk_effect_set_threads) may have. */
#define ISK_TASKS_MAX_WORKERS 256

/* One item of a task: `worker` is in [0, workers) and no two calls that
 * run at the same moment have the same one (it picks the worker's scratch). */
typedef void isk_task_fn(void *task, int worker, size_t item);

typedef struct isk_tasks {
    int workers; /* 1 .. ISK_TASKS_MAX_WORKERS */
    /* Calls fn(task, worker, i) exactly once for every i in [0, n), on
     * any threads in any order, and returns when all have returned. */
    void (*run)(void *user, isk_task_fn *fn, void *task, size_t n);
    void *user; /* passed to run */
} isk_tasks;

/* What the environment variable ISKRA_THREADS asks for, by the one rule
 * effects read it with (when a definition leaves `threads` at 0): decimal
 * digits giving 1..ISK_TASKS_MAX_WORKERS.  0 for anything else (NULL,
 * empty, "8 ", "1e2", "0", "999"): the variable is then ignored and every
 * core is used, so a program can tell its user (the iskra tool does). */
int isk_threads_from_text(const char *text);

#ifdef __cplusplus
}
#endif

#endif
