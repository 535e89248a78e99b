/* SPDX-License-Identifier: MIT */
/* The budgets: the most memory an effect can take (isk_effect_def_memory,
 * against max_memory) and the most work a frame or a prewarm can ask for
 * (against max_work), each a sum of named parts, so a refusal says what
 * needs it and how much.
 *
 * Memory, the parts: the effect's own small tables; every emitter's pool
 * full (its capacity, trails included); every image the definition holds,
 * twice (the definition's pixels and the effect's copy); every texture
 * made from them, one per image and grid (isk_texture_bytes: each grid's
 * frames get their own borders and levels); the canvas it is drawn into;
 * and what the program declares it needs beside (host_memory: encoders).
 *
 * Work, in units of one particle's step through one stage of cost 1 (a
 * drift, isk_stage_kind.cost) or one pixel a draw may touch.  A frame:
 * for every emitter, the most particles it can hold (fx_most_alive) times
 * its substeps times its stages' cost, plus those particles times what
 * its draw kind may touch (fx_draw_kind.cost and .pixels, times its units:
 * a trail's segments), plus the canvas's fill.  A prewarm: its frames
 * times the steps of every emitter it runs (isk__fx_prewarm_offsets).  A
 * pixel count is never more than the canvas: a draw is clipped to it (a
 * drawing counts as the whole canvas). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "effect_internal.h"
#include "iskra/texture.h"
#include "sim/stage.h"

/* ---- memory -------------------------------------------------------------- */

typedef void (*fx_need_fn)(void *ctx, double amount, const char *what);

/* The image of the definition named `name`, or NULL. */
static const isk_canvas *image_of(const isk_effect_def *d, const char *name)
{
    const int k = isk_effect_def_find_texture(d, name);
    return k >= 0 ? &d->textures[k].pixels : NULL;
}

/* 1 when an emitter before `i` makes the same texture (image and grid). */
static int texture_made_before(const isk_effect_def *d, int i)
{
    const isk_emitter_look *a = &d->emitters[i].look;
    for (int j = 0; j < i; j++) {
        const isk_emitter_look *b = &d->emitters[j].look;
        if (b->texture[0] && !strncmp(a->texture, b->texture, sizeof a->texture) &&
            a->texture_grid.x == b->texture_grid.x && a->texture_grid.y == b->texture_grid.y)
            return 1;
    }
    return 0;
}

/* Every part of the memory, to `need`. */
static void memory_parts(const isk_effect_def *d, fx_need_fn need, void *ctx)
{
    char what[ISK_TEXTURE_PATH_MAX + 80];
    /* scratch, sine table, sprite cache, sorted order: small and bounded */
    need(ctx, (double)(sizeof(isk_effect_def) + ((size_t)1 << 20)), "the effect's tables");
    for (int i = 0; d->emitters && i < d->nemitters; i++) {
        snprintf(what, sizeof what, "emitter '%.*s' (its pool full)", ISK_NAME_MAX - 1, d->emitters[i].name);
        need(ctx, (double)isk__fx_emitter_memory(&d->emitters[i], isk__fx_probes_need_prev(d, i)), what);
    }
    for (int i = 0; d->textures && i < d->ntextures && i < ISK_EFFECT_MAX_TEXTURES; i++) {
        const isk_canvas *c = &d->textures[i].pixels;
        snprintf(what, sizeof what, "the image %.*s (%d x %d, the definition's and the effect's copy)",
                 ISK_TEXTURE_PATH_MAX - 1, d->textures[i].name, c->width, c->height);
        need(ctx, 2.0 * 4.0 * (double)(c->width > 0 ? c->width : 0) * (double)(c->height > 0 ? c->height : 0), what);
    }
    for (int i = 0; d->emitters && i < d->nemitters; i++) {
        const isk_emitter_look *l = &d->emitters[i].look;
        const isk_canvas *c = l->texture[0] && memchr(l->texture, 0, sizeof l->texture) ? image_of(d, l->texture) : NULL;
        if (!c || texture_made_before(d, i) || !(l->texture_grid.x >= 1 && l->texture_grid.x <= ISK_TEXTURE_MAX_GRID) ||
            !(l->texture_grid.y >= 1 && l->texture_grid.y <= ISK_TEXTURE_MAX_GRID))
            continue;
        const int cols = (int)l->texture_grid.x, rows = (int)l->texture_grid.y;
        snprintf(what, sizeof what, "the texture %.*s cut %d x %d", ISK_TEXTURE_PATH_MAX - 1, l->texture, cols, rows);
        need(ctx, (double)isk_texture_bytes(c->width, c->height, cols, rows), what);
    }
    snprintf(what, sizeof what, "the %d x %d canvas", d->width, d->height);
    need(ctx, 4.0 * (double)(d->width > 0 ? d->width : 0) * (double)(d->height > 0 ? d->height : 0), what);
    if (d->host_memory) {
        const int named = d->host_memory_for[0] && memchr(d->host_memory_for, 0, sizeof d->host_memory_for);
        snprintf(what, sizeof what, "%s", named ? d->host_memory_for : "the program's own");
        need(ctx, (double)d->host_memory, what);
    }
}

static void add_need(void *ctx, double amount, const char *what)
{
    (void)what;
    *(double *)ctx += amount;
}

static size_t to_size(double b)
{
    return b >= (double)SIZE_MAX ? SIZE_MAX : (size_t)b;
}

size_t isk_effect_def_memory(const isk_effect_def *d)
{
    if (!d)
        return 0;
    double total = 0;
    memory_parts(d, add_need, &total);
    return to_size(total);
}

/* The largest parts, for a message: at most FX_NEEDS_SHOWN, largest first. */
#define FX_NEEDS_SHOWN 3
typedef struct largest {
    double total;
    int n;
    double amount[FX_NEEDS_SHOWN];
    char what[FX_NEEDS_SHOWN][ISK_TEXTURE_PATH_MAX + 80];
} largest;

static void keep_largest(void *ctx, double amount, const char *what)
{
    largest *l = ctx;
    l->total += amount;
    int at = l->n;
    while (at > 0 && l->amount[at - 1] < amount)
        at--;
    if (at >= FX_NEEDS_SHOWN)
        return;
    const int last = l->n < FX_NEEDS_SHOWN ? l->n : FX_NEEDS_SHOWN - 1;
    for (int k = last; k > at; k--) {
        l->amount[k] = l->amount[k - 1];
        memcpy(l->what[k], l->what[k - 1], sizeof l->what[k]);
    }
    l->amount[at] = amount;
    snprintf(l->what[at], sizeof l->what[at], "%s", what);
    if (l->n < FX_NEEDS_SHOWN)
        l->n++;
}

/* "1.5 GiB", "233 MiB", "12 KiB" */
static void bytes_text(double b, char *buf, size_t n)
{
    if (b >= (double)SIZE_MAX)
        snprintf(buf, n, "more than can be addressed");
    else if (b >= (double)(1 << 30))
        snprintf(buf, n, "%.1f GiB", b / (double)(1 << 30));
    else if (b >= (double)(1 << 20))
        snprintf(buf, n, "%.0f MiB", b / (double)(1 << 20));
    else
        snprintf(buf, n, "%.0f KiB", b / 1024.0);
}

int isk__fx_memory_over(const isk_effect_def *d, char *msg, size_t n)
{
    const size_t limit = d->max_memory ? d->max_memory : ISK_EFFECT_DEFAULT_MAX_MEMORY;
    largest l;
    memset(&l, 0, sizeof l);
    memory_parts(d, keep_largest, &l);
    if (to_size(l.total) <= limit)
        return 0;
    char a[40], b[40];
    bytes_text(l.total, a, sizeof a);
    bytes_text((double)limit, b, sizeof b);
    size_t used = (size_t)snprintf(msg, n, "the effect could need %s at its fullest%s, more than the limit of %s (", a,
                                   d->host_memory ? " with what the program holds beside it" : "", b);
    for (int k = 0; k < l.n; k++) {
        char e[40];
        bytes_text(l.amount[k], e, sizeof e);
        used += (size_t)snprintf(msg + (used < n ? used : n), used < n ? n - used : 0, "%s%s %s", k ? ", " : "",
                                 l.what[k], e);
    }
    snprintf(msg + (used < n ? used : n), used < n ? n - used : 0,
             "%s): lower the capacities, sizes or grids%s, or raise the limit (--max-memory, "
             "isk_effect_def.max_memory)",
             l.n == FX_NEEDS_SHOWN ? ", ..." : "", d->host_memory ? " or what is written" : "");
    return 1;
}

/* ---- work ------------------------------------------------------------------ */

/* The most particles emitter i can hold at once: its capacity, or fewer
 * when its births are bounded (one particle, an explosion or a layer's
 * count, a stream of finite lives).  Clicks and sub-emitters fill a store
 * to its capacity. */
static double fx_most_alive(const isk_effect_def *d, int i)
{
    const isk_emitter_def *em = &d->emitters[i];
    const double cap = (double)em->born.capacity;
    const int clicked = (d->click.enabled || d->click.at_start) && (d->click.emitter == i || (d->click.emitter < 0 && i == 0));
    double most = cap;
    if (clicked)
        return cap;
    switch (em->born.source) {
    case ISK_SOURCE_PARTICLE: most = 1; break;
    case ISK_SOURCE_EXPLOSION:
    case ISK_SOURCE_LAYER: most = (double)em->born.count; break;
    case ISK_SOURCE_STREAM: {
        const double life = em->life.seconds + (em->life.range > 0 ? em->life.range : 0);
        if (!isfinite(life))
            break;
        double bursts = 0;
        if (em->born.count)
            bursts = (double)em->born.count *
                     (em->born.burst_every > 0 ? ceil(life / isk__fx_burst_every(em)) + 1
                      : em->born.loop && em->born.duration > 0 ? ceil(life / em->born.duration) + 1
                                                               : 1);
        most = ceil(em->born.rate * life) + 1 + bursts;
        break;
    }
    default: break;
    }
    return most < cap ? most : cap;
}

/* What one particle of g may touch by its kind's row; a row that does not
 * say, the whole canvas. */
static double kind_pixels(const isk_effect *e, const fx_group *g, const fx_draw_kind *k)
{
    return k->pixels ? k->pixels(e, g) : (double)e->def.width * (double)e->def.height;
}

/* The work of group g's draw: its particles times what its kind's row says
 * one may touch, times its units (a trail's segments). */
static double draw_work(const isk_effect *e, const fx_group *g, const fx_draw_kind *k, double units, double alive)
{
    return alive * units * (k->cost + kind_pixels(e, g, k));
}

typedef struct work_part {
    double amount;
    char what[200];
} work_part;

static void consider(work_part *top, double amount, const char *what)
{
    if (amount > top->amount) {
        top->amount = amount;
        snprintf(top->what, sizeof top->what, "%s", what);
    }
}

static void work_text(double w, char *buf, size_t n)
{
    snprintf(buf, n, "%.3g", w);
}

/* The refusal: the largest part, the total and the budget ("when": "a
 * frame" or "to prewarm"; "whole": what could take the total). */
static isk_status over_budget(isk_error *err, const work_part *top, double total, double budget, const char *when,
                              const char *units, const char *whole, const char *advice)
{
    char part[40], all[40], limit[40];
    work_text(top->amount, part, sizeof part);
    work_text(total, all, sizeof all);
    work_text(budget, limit, sizeof limit);
    return isk_error_set(err, ISK_ERR_SIZE,
                         "%s = %s units of work %s (%s); %s could take %s in all, more than the budget of %s "
                         "(--max-work, isk_effect_def.max_work): %s, or raise the budget",
                         top->what, part, when, units, whole, all, limit, advice);
}

isk_status isk__fx_work_fits(const isk_effect *e, isk_error *err)
{
    const isk_effect_def *d = &e->def;
    const double budget = d->max_work > 0 ? d->max_work : ISK_EFFECT_DEFAULT_MAX_WORK;
    /* the fill, and each drawing at most the canvas */
    double frame = (double)d->width * (double)d->height * (1.0 + (double)d->ndrawings), prewarm = 0;
    work_part top = {0, ""}, warm = {0, ""};
    double frames[ISK_EFFECT_MAX_EMITTERS];
    memset(frames, 0, sizeof frames);
    isk__fx_prewarm_offsets(d, frames);
    for (int i = 0; i < e->ngroups && i < ISK_EFFECT_MAX_EMITTERS; i++) {
        const fx_group *g = &e->groups[i];
        const char *name = g->def->name;
        const double alive = fx_most_alive(d, i);
        const double step = alive * (double)g->substeps * isk__pipeline_cost(&g->pipeline, 0);
        const fx_draw_kind *k = isk__fx_choose_draw(g);
        const double draw = draw_work(e, g, k, 1.0, alive);
        const int points = g->def->look.trail > 0 && g->def->look.trail <= ISK_TRAIL_MAX ? g->def->look.trail : 0;
        const double trail = points ? draw_work(e, g, &isk__fx_kind_trails, (double)points, alive) : 0.0;
        char what[200];
        snprintf(what, sizeof what, "emitter '%s': %.3g particles x %d substeps x %.3g (its stages)", name, alive,
                 g->substeps, isk__pipeline_cost(&g->pipeline, 0));
        consider(&top, step, what);
        snprintf(what, sizeof what, "emitter '%s': %.3g particles x %.3g pixels (its %s)", name, alive,
                 kind_pixels(e, g, k), k->name);
        consider(&top, draw, what);
        snprintf(what, sizeof what, "emitter '%s': trails of %.4g px x %d points x %.3g particles", name,
                 g->def->look.trail_width, points, alive);
        consider(&top, trail, what);
        frame += step + draw + trail;
        prewarm += frames[i] * step;
        snprintf(what, sizeof what, "emitter '%s': a prewarm of %.15g frames x %.3g particles x %d substeps x %.3g (its stages)",
                 name, frames[i], alive, g->substeps, isk__pipeline_cost(&g->pipeline, 0));
        consider(&warm, frames[i] * step, what);
    }
    if (!(frame <= budget))
        return over_budget(err, &top, frame, budget, "a frame", "particle-steps and pixels", "a frame", "lower them");
    if (!(prewarm <= budget))
        return over_budget(err, &warm, prewarm, budget, "to prewarm", "particle-steps", "the prewarm",
                           "lower the prewarm, rate or capacity");
    return ISK_OK;
}
