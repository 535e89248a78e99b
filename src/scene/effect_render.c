/* SPDX-License-Identifier: MIT */
/* Drawing an effect: static drawings and the deflectors shown, then each
 * emitter in draw order (its trails, then its particles, each through the
 * band scheduler), then the potentials (as the thesis simulator draws
 * them), then the probes (effect_probes.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "effect_internal.h"
#include "iskra/draw.h"
#include "iskra/text.h"
#include "raster/clip.h"

static isk_status draw_drawing(isk_effect *e, isk_canvas *c, const isk_view *v, const isk_drawing_def *s)
{
    switch (s->kind) {
    case ISK_DRAWING_POLYGON: {
        /* A fan from the first point; in world units each point goes
         * through the view first. */
        double x0 = s->points[0], y0 = s->points[1];
        if (!s->pixels)
            isk_view_to_screen(v, x0, y0, &x0, &y0);
        for (int k = 1; k + 1 < s->npoints; k++) {
            double x1 = s->points[2 * k], y1 = s->points[2 * k + 1];
            double x2 = s->points[2 * k + 2], y2 = s->points[2 * k + 3];
            if (!s->pixels) {
                isk_view_to_screen(v, x1, y1, &x1, &y1);
                isk_view_to_screen(v, x2, y2, &x2, &y2);
            }
            isk_fill_triangle(c, x0, y0, x1, y1, x2, y2, s->color, s->blend);
        }
        break;
    }
    case ISK_DRAWING_SPRITE: {
        double X = s->x, Y = s->y, d = s->size;
        if (!s->pixels) {
            isk_view_to_screen(v, s->x, s->y, &X, &Y);
            d = s->size * fabs(v->sx);
        }
        int px = d >= ISK_SPRITE_MAX_SIZE ? ISK_SPRITE_MAX_SIZE : (d >= 1.0 ? (int)(d + 0.5) : 1);
        const isk_sprite *spr;
        if (isk_sprite_cache_get(e->sprites, s->sprite, px, s->color, &spr) != ISK_OK) {
            isk_sprite_cache_clear(e->sprites);
            if (isk_sprite_cache_get(e->sprites, s->sprite, px, s->color, &spr) != ISK_OK)
                return ISK_ERR_NOMEM;
        }
        isk_draw_sprite(c, spr, X, Y, s->blend);
        break;
    }
    case ISK_DRAWING_POLYLINE:
        if (s->pixels && s->hairline)
            isk_stroke_polyline_hairline(c, s->points, s->npoints, s->closed, s->color, s->blend);
        else if (s->pixels)
            isk_stroke_polyline(c, s->points, s->npoints, s->closed, s->color, s->blend);
        else if (s->hairline)
            isk_world_polyline_hairline(c, v, s->points, s->npoints, s->closed, s->color, s->blend);
        else
            isk_world_polyline(c, v, s->points, s->npoints, s->closed, s->color, s->blend);
        break;
    case ISK_DRAWING_DISC:
        if (s->pixels)
            isk_fill_circle_aa(c, s->x, s->y, s->r, s->color, s->blend);
        else
            isk_world_disc(c, v, s->x, s->y, s->r, s->color, s->blend);
        break;
    case ISK_DRAWING_TEXT:
        if (s->pixels) {
            isk_draw_text(c, isk__floor_clamp(s->x, -1000000000, 1000000000),
                          isk__floor_clamp(s->y, -1000000000, 1000000000), s->text, s->scale, s->color, s->blend);
        } else {
            isk_world_text(c, v, s->x, s->y, s->text, s->scale, s->color, s->blend);
        }
        break;
    case ISK_DRAWING_KIND_COUNT:
        break;
    }
    return ISK_OK;
}

/* The deflectors with show = true: each segment drawn as a drawing's
 * polyline of two points is (the exact-area stroke 1 px wide, over), read
 * from the definition at every render, so a live change of the segment is
 * drawn where it now is. */
static void draw_deflectors(isk_canvas *c, const isk_view *v, const isk_effect_def *d)
{
    for (int i = 0; i < d->ndeflectors; i++) {
        const isk_deflector_def *f = &d->deflectors[i];
        if (!f->show)
            continue;
        const double xy[4] = {f->seg.x0, f->seg.y0, f->seg.x1, f->seg.y1};
        isk_world_polyline(c, v, xy, 2, 0, f->color, ISK_BLEND_OVER);
    }
}

static int any_deflector_shown(const isk_effect_def *d)
{
    for (int i = 0; i < d->ndeflectors; i++)
        if (d->deflectors[i].show)
            return 1;
    return 0;
}

/* draw_order oldest or random: the frame's order of g's particles, in
 * g->draw_list (oldest: the store's order reversed, newest first).  Random is a shuffle (Fisher-Yates) by a generator seeded
 * from the scene's seed, the emitter's index and the frame number alone:
 * the same order for the same frame on any number of threads, and no
 * draw from the emitter's own streams, so the simulation never sees it. */
static isk_status order_particles(const isk_effect *e, fx_group *g)
{
    const size_t n = g->store.count;
    if (n > g->draw_list_cap) {
        size_t cap = g->draw_list_cap ? g->draw_list_cap : 64;
        while (cap < n)
            cap *= 2;
        uint32_t *list = realloc(g->draw_list, cap * sizeof *list);
        if (!list)
            return ISK_ERR_NOMEM;
        g->draw_list = list;
        g->draw_list_cap = cap;
    }
    uint32_t *list = g->draw_list;
    for (size_t i = 0; i < n; i++) /* the store holds at most 2^28 (ISK_PARTICLES_MAX) */
        list[i] = (uint32_t)(g->def->look.draw_order == ISK_DRAW_ORDER_OLDEST ? n - 1 - i : i);
    if (g->def->look.draw_order == ISK_DRAW_ORDER_RANDOM && n > 1) {
        isk_rng r;
        isk_rng_seed(&r, isk__fx_group_seed(e->def.seed, g->index) ^ 0x64726177u /* "draw" */ ^
                             (uint64_t)e->frame * 0xD1B54A32D192ED03ull);
        for (size_t i = n - 1; i > 0; i--) {
            const size_t j = isk_rng_below(&r, (uint32_t)(i + 1));
            const uint32_t t = list[i];
            list[i] = list[j];
            list[j] = t;
        }
    }
    return ISK_OK;
}

/* A group's draw: its trails, then its particles, each on the workers in
 * bands where its kind allows (effect_bands.c).  fill: NULL, or the
 * background the canvas is cleared to first, by the bands of the group's
 * first pass. */
static isk_status render_group(isk_effect *e, isk_canvas *c, fx_group *g, const isk_color *fill)
{
    fx_band whole = isk__fx_band_whole(c, g);
    if (g->store.trail && g->def->look.trail > 0) { /* trails under the particles (effect_trail.c); a
                                                      gate's last positions alone draw nothing */
        isk_status s = isk__fx_trail_render(e, c, g, fill);
        if (s != ISK_OK)
            return s;
        fill = NULL;
    }
    const fx_draw_kind *k = g->draw;
    if (k->prepare) {
        isk_status s = k->prepare(e, g, &whole);
        if (s != ISK_OK)
            return s;
    }
    if (g->def->look.draw_order != ISK_DRAW_ORDER_NEWEST && g->def->look.draw != ISK_DRAW_NONE) {
        /* Another order than the store's: the whole list on this thread
         * (bands and replays at rest keep the store's order). */
        isk_status s = order_particles(e, g);
        if (s != ISK_OK)
            return s;
        if (fill)
            isk_canvas_fill(c, *fill);
        isk__fx_retain_clear(&g->retained);
        whole.list = g->draw_list;
        whole.nlist = g->store.count;
        return k->draw(e, c, g, &whole);
    }
    return isk__fx_draw_bands(e, c, g, k, &whole, 1.0, fill);
}

isk_status isk__fx_render(isk_effect *e, isk_canvas *c)
{
    const isk_effect_def *d = &e->def;
    /* The clear goes to the first group's bands when nothing is drawn
     * before it: each thread then clears the pixels it is about to blend,
     * and finds them in its own caches instead of the caller's. */
    const isk_color *fill = d->clear ? &d->background : NULL;
    if (fill && (d->ndrawings > 0 || any_deflector_shown(d) || e->ngroups == 0)) {
        isk_canvas_fill(c, *fill);
        fill = NULL;
    }
    for (int i = 0; i < d->ndrawings; i++) {
        isk_status s = draw_drawing(e, c, &e->view, &d->drawings[i]);
        if (s != ISK_OK)
            return s;
    }
    draw_deflectors(c, &e->view, d);
    for (int k = 0; k < e->ngroups; k++) {
        fx_group *g = &e->groups[e->draw_order[k]];
        isk_status s = render_group(e, c, g, fill);
        if (s != ISK_OK)
            return s;
        fill = NULL;
    }
    /* The thesis simulator's potentials: a disc of radius 0.1 (blue attracts,
     * red repels), then the id in white at (x - 0.04, y - 0.06). */
    for (size_t k = 0; k < e->npots; k++) {
        const isk_potential *pot = &e->pots[k];
        if (!pot->enabled || !d->forces[e->pot_force[k]].draw)
            continue;
        isk_color col = pot->charge >= 0 ? ISK_BLUE : ISK_RED;
        isk_world_disc(c, &e->view, pot->r.x, pot->r.y, 0.1, col, ISK_BLEND_OVER);
        char id[16];
        snprintf(id, sizeof id, "%d", pot->id);
        isk_world_text(c, &e->view, pot->r.x - 0.04, pot->r.y - 0.06, id, 1, ISK_WHITE, ISK_BLEND_OVER);
    }
    if (e->probes) /* over everything: they measure what is drawn */
        isk__fx_probes_render(e, c);
    return ISK_OK;
}
