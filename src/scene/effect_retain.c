/* SPDX-License-Identifier: MIT */
/* A group at rest drawn again from what its last draw blended.
 *
 * When every block of a group rests (sim/stage.h's isk_rest: the runner no
 * longer moves them), its particles' x and y stay bit for bit as they
 * are, and so does every point's 2x2 block and weights.  So the first draw
 * at rest records its blends (view/world_batch.h's retained dots), band by
 * band, and the next draws do only those blends: the screen transform,
 * the select and the weights are skipped.  The bytes are the same as
 * drawing in full, because the recorded blends are the ones the full draw
 * would do, in its order, on the same bands.
 *
 * What makes the records stale is checked before every draw: the group's
 * isk_rest.changes (bumped by everything that can end a block's rest: a
 * forget, a wake, a change of step, a run without states), its count, the
 * view, the canvas's size, the dot rule and the thread count.  The colour
 * and the blend mode are not recorded: they can change freely.  The
 * records hold 8 bytes a particle, only while the group rests.
 *
 * What it saves: docs/performance.md, "Replays at rest". */
#include <stdlib.h>
#include <string.h>

#include "effect_internal.h"

/* Frees the bands and their records; the key stays. */
static void free_records(fx_retained *rt)
{
    for (int k = 0; k < rt->cap; k++)
        free(rt->rec[k]);
    free(rt->tile);
    free(rt->rec);
    free(rt->n);
    free(rt->failed);
    rt->tile = NULL;
    rt->rec = NULL;
    rt->n = NULL;
    rt->failed = NULL;
    rt->nb = rt->cap = rt->columns = 0;
}

void isk__fx_retain_clear(fx_retained *rt)
{
    free_records(rt);
    const long records = rt->records, replays = rt->replays;
    memset(rt, 0, sizeof *rt);
    rt->records = records;
    rt->replays = replays;
}

/* The same view, bit for bit (a -0 for a 0 is a change). */
static int same_view(const isk_view *a, const isk_view *b)
{
    const double da[] = {a->xmin, a->xmax, a->ymin, a->ymax, a->sx, a->sy, a->px, a->py, a->zoom, a->tx, a->ty, a->a};
    const double db[] = {b->xmin, b->xmax, b->ymin, b->ymax, b->sx, b->sy, b->px, b->py, b->zoom, b->tx, b->ty, b->a};
    return a->kind == b->kind && a->width == b->width && a->height == b->height && !memcmp(da, db, sizeof da);
}

/* Whether rt's records (or its refusal) are for this draw. */
static int same_key(const fx_retained *rt, const isk_effect *e, const isk_canvas *c, const fx_group *g, int threads)
{
    return rt->changes == g->rest.changes && rt->count == g->store.count && same_view(&rt->view, &e->view) &&
           rt->width == c->width && rt->height == c->height && rt->threads == threads && rt->rule == isk__fx_dots_rule(g);
}

/* Room for `bands` bands' records, each empty. */
static int make_room(fx_retained *rt, int bands)
{
    isk__fx_retain_clear(rt);
    rt->tile = calloc((size_t)bands, sizeof *rt->tile);
    rt->rec = calloc((size_t)bands, sizeof *rt->rec);
    rt->n = calloc((size_t)bands, sizeof *rt->n);
    rt->failed = calloc((size_t)bands, sizeof *rt->failed);
    if (!rt->tile || !rt->rec || !rt->n || !rt->failed) {
        isk__fx_retain_clear(rt);
        return 0;
    }
    rt->cap = bands;
    return 1;
}

fx_retained *isk__fx_retain_begin(isk_effect *e, const isk_canvas *c, fx_group *g, int threads)
{
    fx_retained *rt = &g->retained;
    const int resting = g->rests && !g->mc_active && !e->no_rest && !e->no_retain &&
                        isk__rest_all(&g->rest, g->store.count);
    if (!resting) {
        if (rt->cap || rt->refused)
            isk__fx_retain_clear(rt);
        return NULL;
    }
    const int same = same_key(rt, e, c, g, threads);
    if (same && rt->nb > 0)
        return rt; /* replay */
    if (same && rt->refused)
        return NULL;
    if (!make_room(rt, threads))
        return NULL; /* drawn in full: the same bytes */
    rt->changes = g->rest.changes;
    rt->count = g->store.count;
    rt->view = e->view;
    rt->width = c->width;
    rt->height = c->height;
    rt->threads = threads;
    rt->rule = isk__fx_dots_rule(g);
    return rt; /* record */
}

isk_status isk__fx_retain_record(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b)
{
    fx_retained *rt = &g->retained;
    const int k = b->index;
    const size_t m = b->list ? b->nlist : b->end - b->first;
    isk__dot_recording rec = {m ? malloc(m * sizeof *rec.rec) : NULL, 0, 0};
    if (m && !rec.rec) { /* drawn in full, not recorded */
        rt->failed[k] = 1;
        return g->draw->draw(e, c, g, b);
    }
    const double *x = g->store.x, *y = g->store.y;
    if (!b->list) {
        x += b->first;
        y += b->first;
    }
    isk__draw_batch_record(c, &e->view, m, b->list, x, y, g->def->look.color, g->def->look.blend, rt->rule, b->r0,
                           b->r1, b->c0, b->c1, &rec);
    /* what the band did not record is given back (the room was for every point it read) */
    isk__dot_rec *fit = rec.n ? realloc(rec.rec, rec.n * sizeof *rec.rec) : NULL;
    if (rec.n && fit)
        rec.rec = fit;
    else if (!rec.n) {
        free(rec.rec);
        rec.rec = NULL;
    }
    rt->rec[k] = rec.rec;
    rt->n[k] = rec.n;
    rt->failed[k] = rec.failed;
    int y0 = b->r1, y1 = b->r0; /* a block's rows are iy and iy + 1, cut to the band */
    for (size_t i = 0; i < rec.n; i++) {
        const int iy = rec.rec[i].iy & (ISK__REC_FULL - 1u);
        y0 = iy < y0 ? iy : y0;
        y1 = iy + 2 > y1 ? iy + 2 : y1;
    }
    rt->tile[k].y0 = y0 < b->r0 ? b->r0 : y0;
    rt->tile[k].y1 = y1 > b->r1 ? b->r1 : y1;
    if (rt->tile[k].y1 <= rt->tile[k].y0)
        rt->tile[k].y0 = rt->tile[k].y1 = b->r0;
    return ISK_OK;
}

isk_status isk__fx_retain_replay(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b)
{
    (void)e;
    const fx_retained *rt = &g->retained;
    isk__draw_batch_replay(c, rt->rec[b->index], rt->n[b->index], g->def->look.color, g->def->look.blend, b->r0, b->r1,
                           b->c0, b->c1);
    return ISK_OK;
}

void isk__fx_retain_end(fx_retained *rt, const fx_band *band, int nb, int columns)
{
    int failed = nb < 1 || nb > rt->cap;
    for (int k = 0; k < nb && !failed; k++)
        failed = rt->failed[k];
    if (failed) { /* the key stays, refused, so the next draws do not try again */
        free_records(rt);
        rt->refused = 1;
        return;
    }
    for (int k = 0; k < nb; k++) { /* (the rows its records blend: isk__fx_retain_record's) */
        rt->tile[k].r0 = band[k].r0;
        rt->tile[k].r1 = band[k].r1;
        rt->tile[k].c0 = band[k].c0;
        rt->tile[k].c1 = band[k].c1;
    }
    rt->nb = nb;
    rt->columns = columns;
    rt->records++;
}
