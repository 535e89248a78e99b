/* SPDX-License-Identifier: MIT */
/* src/sim/rest.h — blocks at rest: the block runner skips the motion of a
 * block of particles that stands still (internal).
 *
 * A block that the list's leading ISK_REST_SKIPPED stages
 * left with its x, y, vx, vy bit for bit as they were is at a fixed point
 * of those stages: they are one function of its state and their
 * parameters, so as long as nothing else writes its particles and the list
 * and the step stay the same, every later step leaves it so again.  The
 * runner then skips those stages for it and runs only the rest of the list
 * (ISK_REST_BESIDE: ageing, spin).  The bytes are the same as running every
 * stage, by that argument, not by a tolerance; a settled layer costs the
 * ageing and nothing more.
 *
 * The same holds for one axis: the skipped stages are per axis (x and vx
 * come out of x, vx and m alone), so a block whose y and vy came out as
 * they were (a floor under it) while x slides steps x alone from then on,
 * its y columns replaced by stand-ins the stages may compute on and whose
 * results are dropped (isk_block.frozen; the walls skip that axis).
 *
 * The runner finds the blocks itself: every few runs it looks at four
 * particles of each awake block in turn, axis by axis; when an axis's
 * stood still it keeps the block's start state in the next run and
 * compares it after the skipped stages; equal, that axis rests.  The
 * owner says what changed between runs:
 *   isk__rest_forget(&r, i)   the particles from i on were moved, removed,
 *                            or written (a cull that keeps the order: from
 *                            the first one it moved; one that fills holes:
 *                            isk__rest_wake_dying before it, its new count
 *                            after); particles appended need nothing
 *   isk__rest_forget(&r, 0)   the list or its parameters changed (recompile)
 * A different step h forgets by itself.  The runs with states cover
 * [0, end), so blocks count from particle 0.
 *
 *     isk_rest r;
 *     isk__rest_init(&r);
 *     isk_run_context ctx = {NULL, &r};
 *     isk__pipeline_run(&pl, &store, 0, store.count, h, &scratch, &ctx);
 *     ...
 *     isk__rest_free(&r);
 */
#ifndef ISKRA_SIM_REST_H
#define ISKRA_SIM_REST_H

#include <stddef.h>
#include <stdint.h>

#include "sim/stage.h"

typedef struct isk_rest_block {
    uint64_t sample[2];  /* per axis, a hash of four particles' position and velocity at the
                            block's last look (a collision only costs an exact look that fails) */
    unsigned char state; /* the axes at rest, and whether to look at the others (rest.c) */
} isk_rest_block;

typedef struct isk_rest {
    isk_rest_block *block; /* one per block */
    size_t cap;            /* blocks there is room for */
    size_t valid;         /* particles [0, valid) are those the states describe */
    double h;             /* the step they were found at */
    size_t runs;          /* runs so far: whose turn it is to be looked at */
    double *stand_in;     /* per worker, 2 x ISK_SIM_BLOCK: a resting axis's columns while the
                             other axis steps (zeroed once; what the stages make of them is
                             never read) */
    int workers;          /* workers stand_in has room for */
    uint64_t changes;     /* counts what can end a block's rest (a forget below valid, a
                             change of step, a wake): while it and the count stay the
                             same and every block rests, no particle's x, y has changed */
} isk_rest;

void isk__rest_init(isk_rest *r);
void isk__rest_free(isk_rest *r);
void isk__rest_forget(isk_rest *r, size_t from);
/* Before a cull that fills the holes with the last particles (nothing
 * else moves): wakes the blocks at rest that hold a particle about to die
 * (age >= life).  The cull's new count is then forgotten from. */
void isk__rest_wake_dying(isk_rest *r, const isk_particles *p);
/* Blocks of [0, count) at rest on `axes` (ISK_REST_X | ISK_REST_Y: at rest;
 * for the tests and the benchmarks). */
size_t isk__rest_blocks(const isk_rest *r, size_t count, unsigned axes);
/* 1 when count > 0 and every block of [0, count) rests on both axes (the
 * states describe exactly those particles). */
int isk__rest_all(const isk_rest *r, size_t count);

/* For the runner (stage.c).  isk__rest_begin readies the states for a run
 * over [0, end) with step h and `workers` workers: blocks that reach past
 * the particles they describe (and every block after a change of step)
 * wake, and after the run the states describe [0, end).  It returns how
 * many leading stages a block at rest skips (0: nothing to gain, or no
 * memory for the states: the run then steps every block in full) and the
 * run's phase.  isk__rest_step then runs those stages on block b (the
 * worker's stand-ins for a resting axis) as its state says. */
int isk__rest_begin(isk_rest *r, const isk_pipeline *pl, size_t end, double h, int workers, size_t *phase);
void isk__rest_step(isk_rest *r, const isk_pipeline *pl, int prefix, const isk_block *b, size_t phase, int worker);
/* Whether the block starting at particle `first` rests on both axes: then
 * isk__rest_step has nothing to do (the runner asks first, inline: a
 * layer at rest is thousands of blocks a step). */
static inline int isk__rest_block_rests(const isk_rest *r, size_t first)
{
    return r->block[first / ISK_SIM_BLOCK].state == (ISK_REST_X | ISK_REST_Y);
}

#endif
