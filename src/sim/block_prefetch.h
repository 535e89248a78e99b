/* src/sim/block_prefetch.h — the columns of a block ahead, asked for while
 * the stages compute on this one (internal).
 *
 *     static void run_motion(const isk_stage *st, isk_block *b, double h)
 *     {
 *         isk_block_prefetch_ahead(b, 5);   // x, y, vx, vy and m of a block ahead
 *         ...
 *
 * Why: the hardware prefetcher follows a stream only within a 4 KiB page,
 * two blocks of one column, and a block's stages read its five columns one
 * after another in short bursts, so at every page it starts them afresh
 * and the block's arithmetic waits for memory instead of overlapping it.
 * Called by the first stage of a list that reads the store's columns (the
 * remember stage, else the motion or drift stage), and for its own columns
 * by a stage that reads more (the fire's sway).  A hint only: no byte changes.
 * Reads only, so a block ahead that another thread steps is shared, not
 * taken from it.
 *
 * The hint is for the block ISK_BLOCK_PREFETCH_AHEAD blocks on, not the
 * next one: a block's hints are a burst (16 lines a column, 128 for the
 * fire's eight), more than the core keeps in flight, so the last of them
 * were still arriving when the stages reached that block.  Two blocks ahead
 * leaves them a block's time to drain (bench_walls, same minutes: fire
 * 5.55 -> 3.85 ns a particle-step at 10^6, 6.93 -> 5.09 at 10^7; a start
 * remembered 2.82 -> 2.70; the other rows within noise; three blocks ahead
 * no better than two). */
#ifndef ISKRA_SIM_BLOCK_PREFETCH_H
#define ISKRA_SIM_BLOCK_PREFETCH_H

#include "sim/stage.h"

enum { ISK_BLOCK_PREFETCH_AHEAD = 2 };

/* The part of one column `col` of the store (col = p->x, p->osc_amp, ...:
 * any array of p->count doubles) ISK_BLOCK_PREFETCH_AHEAD blocks after b. */
static inline void isk_block_prefetch_ahead_of(const isk_block *b, const double *col)
{
#if defined(__GNUC__)
    const isk_particles *p = b->p;
    const size_t next = b->first + (size_t)ISK_BLOCK_PREFETCH_AHEAD * ISK_SIM_BLOCK;
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

/* `columns`: 4 for x, y, vx, vy; 5 with m too (ISK_BLOCK_PREFETCH_AHEAD
 * blocks after b). */
static inline void isk_block_prefetch_ahead(const isk_block *b, int columns)
{
    const isk_particles *p = b->p;
    const double *const col[5] = {p->x, p->y, p->vx, p->vy, p->m};
    for (int c = 0; c < columns && c < 5; c++)
        isk_block_prefetch_ahead_of(b, col[c]);
}

#endif
