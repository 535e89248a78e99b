/* The block runner (see stage.h). */
#include "sim/stage.h"

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

void isk_pipeline_run(const isk_pipeline *pl, isk_particles *p, size_t begin, size_t end, double h,
                      isk_scratch *s)
{
    isk_block b;
    b.p = p;
    b.s = s;
    for (size_t o = begin; o < end; o += ISK_SIM_BLOCK) {
        b.first = o;
        b.n = end - o < ISK_SIM_BLOCK ? end - o : ISK_SIM_BLOCK;
        b.x = p->x + o;
        b.y = p->y + o;
        b.vx = p->vx + o;
        b.vy = p->vy + o;
        b.m = p->m + o;
        for (int k = 0; k < pl->n; k++)
            pl->stage[k].kind->run(&pl->stage[k], &b, h);
    }
}

void isk_pipeline_describe(const isk_pipeline *pl, FILE *out)
{
    for (int k = 0; k < pl->n; k++) {
        fprintf(out, "  %-9s ", pl->stage[k].kind->name);
        pl->stage[k].kind->describe(&pl->stage[k], out);
        fputc('\n', out);
    }
}
