/* SPDX-License-Identifier: MIT */
/* The block runner (see stage.h). */
#include "sim/stage.h"

#include "core/fast_paths.h"
#include "sim/rest.h"
#include "sim/workers.h"

#include <stdlib.h>
#include <string.h>

void isk__pipeline_init(isk_pipeline *pl)
{
    memset(pl, 0, sizeof *pl);
}

isk_stage *isk__pipeline_add(isk_pipeline *pl, const isk_stage_kind *kind)
{
    if (pl->n >= ISK_PIPELINE_MAX)
        return NULL;
    isk_stage *s = &pl->stage[pl->n++];
    memset(s, 0, sizeof *s);
    s->kind = kind;
    return s;
}

isk_stage *isk__pipeline_insert(isk_pipeline *pl, int at, const isk_stage_kind *kind)
{
    if (pl->n >= ISK_PIPELINE_MAX || at < 0 || at > pl->n)
        return NULL;
    memmove(&pl->stage[at + 1], &pl->stage[at], (size_t)(pl->n - at) * sizeof pl->stage[0]);
    pl->n++;
    isk_stage *s = &pl->stage[at];
    memset(s, 0, sizeof *s);
    s->kind = kind;
    return s;
}

unsigned isk__pipeline_needs(const isk_pipeline *pl)
{
    unsigned needs = 0;
    for (int k = 0; k < pl->n; k++)
        needs |= pl->stage[k].kind->needs ? pl->stage[k].kind->needs(&pl->stage[k]) : 0u;
    return needs;
}

double isk__pipeline_cost(const isk_pipeline *pl, int from)
{
    double c = 0.0;
    for (int k = from; k < pl->n; k++)
        c += pl->stage[k].kind->cost ? pl->stage[k].kind->cost(&pl->stage[k]) : 1.0;
    return c;
}

/* ---- the runner ------------------------------------------------------------ */

typedef struct run_job {
    const isk_pipeline *pl;
    isk_particles *p;
    size_t begin, end;
    double h;
    isk_workers *workers; /* NULL: on the caller */
    isk_rest *rest;       /* NULL: no block rests in this run */
    int prefix;           /* the stages a block at rest skips */
    size_t phase;         /* the rest's look schedule */
} run_job;

/* Every stage, in order, on block `item` of the run; a block under the
 * rest's watch runs its skippable stages through it (rest.c), then the
 * others. */
static void run_block(const run_job *r, size_t item, int worker, isk_scratch *s)
{
    const size_t o = r->begin + item * ISK_SIM_BLOCK;
    const size_t n = r->end - o < ISK_SIM_BLOCK ? r->end - o : ISK_SIM_BLOCK;
    isk_particles *p = r->p;
    isk_block b = {p, o, n, p->x + o, p->y + o, p->vx + o, p->vy + o, p->m + o, s, 0};
    int k = 0;
    if (r->rest) {
        if (!isk__rest_block_rests(r->rest, o))
            isk__rest_step(r->rest, r->pl, r->prefix, &b, r->phase, worker);
        k = r->prefix;
    }
    for (; k < r->pl->n; k++)
        r->pl->stage[k].kind->run(&r->pl->stage[k], &b, r->h);
}

static void run_item(void *task, int worker, size_t item)
{
    const run_job *r = task;
    run_block(r, item, worker, isk__workers_scratch(r->workers, worker));
}

int isk__pipeline_run(const isk_pipeline *pl, isk_particles *p, size_t begin, size_t end, double h, isk_scratch *s,
                     const isk_run_context *ctx)
{
    run_job r = {pl, p, begin, end, h, ctx ? ctx->workers : NULL, NULL, 0, 0};
    if (end <= begin)
        return s->nonfinite;
    const int workers = r.workers ? isk__workers_count(r.workers) : 1;
    if (ISK__FAST_REST && ctx && ctx->rest && begin == 0 &&
        (r.prefix = isk__rest_begin(ctx->rest, pl, end, h, workers, &r.phase)))
        r.rest = ctx->rest;
    const size_t blocks = (end - begin + ISK_SIM_BLOCK - 1) / ISK_SIM_BLOCK;
    if (!r.workers) {
        for (size_t i = 0; i < blocks; i++)
            run_block(&r, i, 0, s);
        return s->nonfinite;
    }
    isk__workers_for(r.workers, blocks, ISK_PIPELINE_MIN_PARALLEL_BLOCKS, run_item, &r);
    /* what the workers' motion stages found, combined after the join */
    for (int w = 0; w < workers; w++) {
        isk_scratch *ws = isk__workers_scratch(r.workers, w);
        s->nonfinite |= ws->nonfinite;
        ws->nonfinite = 0;
    }
    return s->nonfinite;
}

void isk__stage_describe_line(const isk_stage *st, FILE *out)
{
    fprintf(out, "  %-9s ", st->kind->name);
    st->kind->describe(st, out);
}

void isk__pipeline_describe(const isk_pipeline *pl, FILE *out)
{
    for (int k = 0; k < pl->n; k++) {
        isk__stage_describe_line(&pl->stage[k], out);
        fputc('\n', out);
    }
}
