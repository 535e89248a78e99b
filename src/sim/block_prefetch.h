/* src/sim/block_prefetch.h — the next block's columns, asked for while the
 * stages compute on this one (internal).
 *
 *     static void run_motion(const isk_stage *st, isk_block *b, double h)
 *     {
 *         isk_block_prefetch_next(b, 5);   // x, y, vx, vy and m of the block after b
 *         ...
 *
 * Why: the hardware prefetcher follows a stream only within a 4 KiB page,
 * two blocks of one column, and a block's stages read its five columns one
 * after another in short bursts, so at every page it starts them afresh
 * and the block's arithmetic waits for memory instead of overlapping it.
 * Called by the first stage of a list that reads the store's columns (the
 * remember stage, else the motion or drift stage), and for its own columns
 * by a stage that reads more (the fire's sway).  A hint only: no byte changes.
 * Reads only, so a next block that another thread steps is shared, not
 * taken from it. */
#ifndef ISKRA_SIM_BLOCK_PREFETCH_H
#define ISKRA_SIM_BLOCK_PREFETCH_H

#include "sim/stage.h"

/* The next block's part of one column `col` of the store (col = p->x,
 * p->osc_amp, ...: any array of p->count doubles). */
static inline void isk_block_prefetch_next_of(const isk_block *b, const double *col)
{
#if defined(__GNUC__)
    const isk_particles *p = b->p;
    const size_t next = b->first + b->n;
    if (next >= p->count || !col)
        return;
    const size_t n = p->count - next < ISK_SIM_BLOCK ? p->count - next : ISK_SIM_BLOCK;
    for (size_t i = 0; i < n; i += 64 / sizeof(double))
        __builtin_prefetch(col + next + i, 0, 3);
#else
    (void)b;
    (void)col;
#endif
}

/* `columns`: 4 for x, y, vx, vy; 5 with m too. */
static inline void isk_block_prefetch_next(const isk_block *b, int columns)
{
    const isk_particles *p = b->p;
    const double *const col[5] = {p->x, p->y, p->vx, p->vy, p->m};
    for (int c = 0; c < columns && c < 5; c++)
        isk_block_prefetch_next_of(b, col[c]);
}

#endif
