/* The block runner (see stage.h). */
#include "sim/stage.h"

#include "sim/pool.h"

#include <string.h>

void isk_pipeline_init(isk_pipeline *pl)
{
    memset(pl, 0, sizeof *pl);
}

isk_stage *isk_pipeline_add(isk_pipeline *pl, const isk_stage_kind *kind)
{
    if (pl->n >= ISK_PIPELINE_MAX)
        return NULL;
    isk_stage *s = &pl->stage[pl->n++];
    memset(s, 0, sizeof *s);
    s->kind = kind;
    return s;
}

/* Every stage, in order, on the block [o, o + n). */
static void run_block(const isk_pipeline *pl, isk_particles *p, size_t o, size_t n, double h, isk_scratch *s)
{
    isk_block b = {p, o, n, p->x + o, p->y + o, p->vx + o, p->vy + o, p->m + o, s};
    for (int k = 0; k < pl->n; k++)
        pl->stage[k].kind->run(&pl->stage[k], &b, h);
}

void isk_pipeline_run(const isk_pipeline *pl, isk_particles *p, size_t begin, size_t end, double h,
                      isk_scratch *s)
{
    for (size_t o = begin; o < end; o += ISK_SIM_BLOCK)
        run_block(pl, p, o, end - o < ISK_SIM_BLOCK ? end - o : ISK_SIM_BLOCK, h, s);
}

typedef struct pool_run {
    const isk_pipeline *pl;
    isk_particles *p;
    size_t begin, end;
    double h;
    isk_pool *pool;
} pool_run;

static void run_item(void *ctx, int worker, size_t item)
{
    const pool_run *r = ctx;
    size_t o = r->begin + item * ISK_SIM_BLOCK;
    run_block(r->pl, r->p, o, r->end - o < ISK_SIM_BLOCK ? r->end - o : ISK_SIM_BLOCK, r->h,
              isk_pool_scratch(r->pool, worker));
}

int isk_pipeline_run_pool(const isk_pipeline *pl, isk_particles *p, size_t begin, size_t end, double h,
                          isk_pool *pool)
{
    if (end <= begin)
        return 0;
    pool_run r = {pl, p, begin, end, h, pool};
    size_t blocks = (end - begin + ISK_SIM_BLOCK - 1) / ISK_SIM_BLOCK;
    isk_pool_for(pool, blocks, ISK_PIPELINE_MIN_PARALLEL_BLOCKS, run_item, &r);
    /* what the workers' motion stages found, combined after the join */
    int nonfinite = 0;
    for (int w = 0; w < isk_pool_threads(pool); w++) {
        isk_scratch *s = isk_pool_scratch(pool, w);
        nonfinite |= s->nonfinite;
        s->nonfinite = 0;
    }
    return nonfinite;
}

void isk_stage_describe_line(const isk_stage *st, FILE *out)
{
    fprintf(out, "  %-9s ", st->kind->name);
    st->kind->describe(st, out);
}

void isk_pipeline_describe(const isk_pipeline *pl, FILE *out)
{
    for (int k = 0; k < pl->n; k++) {
        isk_stage_describe_line(&pl->stage[k], out);
        fputc('\n', out);
    }
}
