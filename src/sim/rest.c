/* SPDX-License-Identifier: MIT */
/* Blocks at rest: the runner skips the motion of a block that stands still
 * (see rest.h). */
#include "sim/rest.h"

#include <stdlib.h>
#include <string.h>

/* A block's state: which axes rest (ISK_REST_X, ISK_REST_Y; both: the
 * block rests), and LOOKED_AT: at the last look, the samples of an axis
 * that does not rest were as at the look before, so the next step keeps
 * the moving axes' start and compares. */
enum { AWAKE = 0, AT_REST = ISK_REST_X | ISK_REST_Y, LOOKED_AT = 4 };

/* An awake block is looked at once in this many runs, blocks in turn:
 * after its step, while it is in L1, four of its particles are compared
 * with what they were at its last look (a hash of them per axis, kept for
 * the next: 24 bytes a block, a fifth of a byte a particle).  Only a
 * block whose samples stood still pays for the exact test, a copy and a
 * compare of the whole block, which cost about two steps of it: looking at
 * every sixteenth block that way slowed a moving layer by 12-20 %, and so
 * did reading samples before the step (16 cache lines touched ahead of the
 * stream, each a wait for memory).  A resting particle's velocity is not
 * zero (with semi-implicit Euler it keeps the offset that brings it back
 * to the wall), so no sign as cheap tells rest. */
#define REST_LOOK_EVERY 4

void isk__rest_init(isk_rest *r)
{
    memset(r, 0, sizeof *r);
}

void isk__rest_free(isk_rest *r)
{
    const uint64_t changes = r->changes + 1; /* what was at rest is no more */
    free(r->block);
    free(r->stand_in);
    isk__rest_init(r);
    r->changes = changes;
}

void isk__rest_forget(isk_rest *r, size_t from)
{
    if (from < r->valid) {
        r->valid = from;
        r->changes++;
    }
}

void isk__rest_wake_dying(isk_rest *r, const isk_particles *p)
{
    const size_t n = p->count < r->valid ? p->count : r->valid;
    for (size_t k = 0; k * ISK_SIM_BLOCK < n; k++) {
        if (!(r->block[k].state & AT_REST))
            continue; /* an awake block is stepped in full anyway */
        const size_t o = k * ISK_SIM_BLOCK, len = n - o < ISK_SIM_BLOCK ? n - o : ISK_SIM_BLOCK;
        const double *age = p->age + o, *life = p->life + o;
        int dying = 0;
        for (size_t i = 0; i < len; i++)
            dying |= age[i] >= life[i];
        if (dying) {
            r->block[k].state = AWAKE;
            r->changes++;
        }
    }
}

/* How many leading blocks of a store of `count` particles the states still
 * describe: all of them when those are the particles described, else the
 * whole blocks below the first change (a partial last block only when it
 * is the one they describe). */
static size_t described_blocks(const isk_rest *r, size_t count)
{
    return count == r->valid ? (count + ISK_SIM_BLOCK - 1) / ISK_SIM_BLOCK
                             : (count < r->valid ? count : r->valid) / ISK_SIM_BLOCK;
}

int isk__rest_all(const isk_rest *r, size_t count)
{
    const size_t blocks = (count + ISK_SIM_BLOCK - 1) / ISK_SIM_BLOCK;
    if (count == 0 || count != r->valid || blocks > r->cap)
        return 0;
    for (size_t k = 0; k < blocks; k++)
        if (r->block[k].state != AT_REST)
            return 0;
    return 1;
}

size_t isk__rest_blocks(const isk_rest *r, size_t count, unsigned axes)
{
    size_t n = 0, blocks = described_blocks(r, count);
    for (size_t k = 0; k < blocks && k < r->cap; k++)
        n += (r->block[k].state & axes) == axes;
    return n;
}

isk_rest_role isk__rest_skipped(const isk_stage *st)
{
    (void)st;
    return ISK_REST_SKIPPED;
}

isk_rest_role isk__rest_beside(const isk_stage *st)
{
    (void)st;
    return ISK_REST_BESIDE;
}

int isk__pipeline_rest_prefix(const isk_pipeline *pl)
{
    int k = 0;
    while (k < pl->n && pl->stage[k].kind->rest && pl->stage[k].kind->rest(&pl->stage[k]) == ISK_REST_SKIPPED)
        k++;
    for (int j = k; j < pl->n; j++)
        if (!pl->stage[j].kind->rest || pl->stage[j].kind->rest(&pl->stage[j]) != ISK_REST_BESIDE)
            return 0;
    return k;
}

/* Readies the states for a run over [0, end) with step h: blocks that
 * reach past the particles they describe (and every block after a change
 * of step) wake, and after the run the states describe [0, end).  Returns
 * how many leading stages a block at rest skips; 0 when there is nothing
 * to gain or no memory for the states: the run then steps every block in
 * full, and nothing is described. */
static int rest_ready(isk_rest *r, const isk_pipeline *pl, size_t end, double h, int workers)
{
    size_t blocks = (end + ISK_SIM_BLOCK - 1) / ISK_SIM_BLOCK;
    if (!(r->h == h)) /* == on purpose: a bit-identical step, NaN never */
        isk__rest_forget(r, 0);
    r->h = h;
    const int prefix = isk__pipeline_rest_prefix(pl);
    if (prefix == 0 || blocks == 0) {
        isk__rest_forget(r, 0);
        return 0;
    }
    if (workers > r->workers) {
        double *a = calloc((size_t)workers * 2 * ISK_SIM_BLOCK, sizeof *a);
        if (!a) {
            isk__rest_forget(r, 0);
            return 0;
        }
        free(r->stand_in);
        r->stand_in = a;
        r->workers = workers;
    }
    if (blocks > r->cap) {
        size_t cap = blocks + blocks / 2;
        isk_rest_block *a = realloc(r->block, cap * sizeof *a);
        if (!a) {
            isk__rest_forget(r, 0);
            return 0;
        }
        r->block = a;
        r->cap = cap;
    }
    const size_t kept = described_blocks(r, end); /* the others wake */
    memset(r->block + kept, 0, (blocks - kept) * sizeof *r->block); /* awake */
    r->changes += kept < blocks;
    r->valid = end;
    return prefix;
}

/* An axis's position and velocity columns in a block. */
static double **axis_col(isk_block *b, int axis, int c)
{
    return axis ? (c ? &b->vy : &b->y) : (c ? &b->vx : &b->x);
}

/* The skipped stages on a block looked at: the start of the axes that do
 * not rest kept, then compared bit for bit (a -0 that comes back as +0 is
 * a change).  Returns the axes that stood still. */
static __attribute__((noinline)) unsigned axes_in_place(const isk_pipeline *pl, int prefix, isk_block *b,
                                                        double h)
{
    double start[2][2][ISK_SIM_BLOCK];
    for (int a = 0; a < 2; a++)
        for (int c = 0; c < 2 && !(b->frozen >> a & 1u); c++)
            memcpy(start[a][c], *axis_col(b, a, c), b->n * sizeof(double));
    for (int k = 0; k < prefix; k++)
        pl->stage[k].kind->run(&pl->stage[k], b, h);
    unsigned still = 0;
    for (int a = 0; a < 2; a++)
        if (!(b->frozen >> a & 1u) && !memcmp(start[a][0], *axis_col(b, a, 0), b->n * sizeof(double)) &&
            !memcmp(start[a][1], *axis_col(b, a, 1), b->n * sizeof(double)))
            still |= 1u << a;
    return still;
}

/* After a step: a hash of four particles' position and velocity on each
 * axis that does not rest, against the block's samples, which then take
 * them.  Returns the axes that (most likely) stood still since the last
 * look; the exact look decides. */
static unsigned samples_still(isk_block *b, uint64_t sample[2])
{
    unsigned still = 0;
    for (int a = 0; a < 2; a++) {
        if (b->frozen >> a & 1u)
            continue;
        uint64_t h = 0;
        for (int j = 0; j < 4; j++)
            for (int c = 0; c < 2; c++) {
                uint64_t bits;
                memcpy(&bits, *axis_col(b, a, c) + (size_t)j * (b->n - 1) / 3, sizeof bits);
                h = (h ^ bits) * 0x9e3779b97f4a7c15u;
                h ^= h >> 29;
            }
        still |= (unsigned)(h == sample[a]) << a;
        sample[a] = h;
    }
    return still;
}

/* The skipped stages on a block, with the columns of its resting axis
 * (rb->state's) replaced by the worker's stand-ins: the stages are per
 * axis (ISK_REST_SKIPPED), so what they make of the stand-ins changes
 * nothing of the other axis, and the resting axis stays as it is.  Looks
 * at it when it is its turn, or when its samples stood still. */
static void run_skipped(const isk_pipeline *pl, int prefix, isk_block *b, double h, isk_rest_block *rb, int turn,
                        double *stand_in)
{
    const unsigned resting = rb->state & AT_REST;
    if (resting) {
        const int a = resting == ISK_REST_X ? 0 : 1;
        *axis_col(b, a, 0) = stand_in;
        *axis_col(b, a, 1) = stand_in + ISK_SIM_BLOCK;
        b->frozen = resting;
    }
    if (rb->state & LOOKED_AT) {
        rb->state = (unsigned char)(resting | axes_in_place(pl, prefix, b, h));
    } else {
        for (int k = 0; k < prefix; k++)
            pl->stage[k].kind->run(&pl->stage[k], b, h);
        if (turn && samples_still(b, rb->sample))
            rb->state |= LOOKED_AT;
    }
}

int isk__rest_begin(isk_rest *r, const isk_pipeline *pl, size_t end, double h, int workers, size_t *phase)
{
    const int prefix = rest_ready(r, pl, end, h, workers);
    if (prefix)
        *phase = r->runs++ % REST_LOOK_EVERY;
    return prefix;
}

void isk__rest_step(isk_rest *r, const isk_pipeline *pl, int prefix, const isk_block *b, size_t phase, int worker)
{
    isk_rest_block *rb = &r->block[b->first / ISK_SIM_BLOCK];
    if (rb->state == AT_REST)
        return;
    isk_block skipped = *b; /* its columns may become stand-ins; b keeps the store's */
    run_skipped(pl, prefix, &skipped, r->h, rb,
                (b->first / ISK_SIM_BLOCK + phase) % REST_LOOK_EVERY == 0,
                r->stand_in + (size_t)worker * 2 * ISK_SIM_BLOCK);
}
