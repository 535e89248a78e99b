/* SPDX-License-Identifier: MIT */
/* Drawing an effect: static drawings and the deflectors shown, then each
 * emitter in draw order, then the potentials (as the thesis simulator draws
 * them).  Over-life ramps are
 * baked once per emitter at create and read per particle. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "effect_internal.h"
#include "iskra/draw.h"
#include "iskra/text.h"
#include "raster/circle_rows.h"
#include "raster/clip.h"
#include "raster/dot_kernel.h"
#include "raster/sprite_rows.h"
#include "view/world_batch.h"

isk_status fx_bake_ramps(fx_group *g, isk_error *err)
{
    const isk_emitter_def *em = g->def;
    isk_status s = ISK_OK;
    if (em->color_over_life.n) {
        s = isk_color_gradient_bake(&g->color_ramp, em->color_over_life.stops, em->color_over_life.n,
                                    ISK_GRADIENT_DEFAULT_RES);
        g->has_color_ramp = s == ISK_OK;
    }
    if (s == ISK_OK && em->alpha_over_life.n) {
        s = isk_scalar_gradient_bake(&g->alpha_ramp, em->alpha_over_life.stops, em->alpha_over_life.n,
                                     ISK_GRADIENT_DEFAULT_RES);
        g->has_alpha_ramp = s == ISK_OK;
    }
    if (s == ISK_OK && em->size_over_life.n) {
        s = isk_scalar_gradient_bake(&g->size_ramp, em->size_over_life.stops, em->size_over_life.n,
                                     ISK_GRADIENT_DEFAULT_RES);
        g->has_size_ramp = s == ISK_OK;
    }
    if (s != ISK_OK)
        return isk_error_set(err, s, "emitter '%s': cannot bake its over-life ramps: %s", em->name,
                             isk_status_str(s));
    return ISK_OK;
}

void fx_free_ramps(fx_group *g)
{
    if (g->has_color_ramp)
        isk_color_gradient_free(&g->color_ramp);
    if (g->has_alpha_ramp)
        isk_scalar_gradient_free(&g->alpha_ramp);
    if (g->has_size_ramp)
        isk_scalar_gradient_free(&g->size_ramp);
    g->has_color_ramp = g->has_alpha_ramp = g->has_size_ramp = 0;
}

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

/* The colour, alpha and size multiplier of particle i at normalised age t. */
static inline isk_color particle_color(const fx_group *g, const isk_particles *p, size_t i, double t,
                                       double *size_mult)
{
    isk_color col = p->color ? p->color[i] : g->def->color;
    if (g->has_color_ramp) {
        isk_color ramp = isk_color_gradient_at(&g->color_ramp, t);
        /* a picked base colour (color_pick) is multiplied, channel by
         * channel, div255(base * ramp); otherwise the ramp is the colour */
        if (g->def->color_pick.n && p->color)
            ramp = isk_rgba((uint8_t)((col.r * ramp.r + 127) / 255), (uint8_t)((col.g * ramp.g + 127) / 255),
                            (uint8_t)((col.b * ramp.b + 127) / 255), (uint8_t)((col.a * ramp.a + 127) / 255));
        col = ramp;
    }
    if (g->has_alpha_ramp) {
        double a = col.a * isk_scalar_gradient_at(&g->alpha_ramp, t);
        col.a = (uint8_t)(a >= 255.0 ? 255 : (a > 0 ? (int)(a + 0.5) : 0));
    }
    *size_mult = g->has_size_ramp ? isk_scalar_gradient_at(&g->size_ramp, t) : 1.0;
    return col;
}

int fx_varies(const fx_group *g)
{
    return g->has_color_ramp || g->has_alpha_ramp || g->has_size_ramp || g->store.color;
}

/* Particle i's colour and size multiplier, constant unless something varies
 * (a group-level fact: the branch always goes the same way). */
static inline isk_color style(const fx_group *g, const isk_particles *p, size_t i, int vary, double *mult)
{
    *mult = 1.0;
    if (!vary)
        return g->def->color;
    double t = isfinite(p->life[i]) && p->life[i] > 0 ? p->age[i] / p->life[i] : 0.0;
    return particle_color(g, p, i, t, mult);
}

/* style() for effect_texture.c (the draws here keep the inline one). */
isk_color fx_style(const fx_group *g, const isk_particles *p, size_t i, int vary, double *mult)
{
    return style(g, p, i, vary, mult);
}

isk_color fx_particle_color(const fx_group *g, size_t i) /* the trails' colour (effect_trail.c) */
{
    double mult;
    return style(g, &g->store, i, fx_varies(g), &mult);
}

/* ---- the groups' draws --------------------------------------------------
 * Each draws the rows [b->r0, b->r1) of the canvas: the whole canvas on one
 * thread, or one band per thread (fx_render_group).  Every primitive used
 * here places its shape on the whole canvas and cuts only the blend to the
 * band (view/world_batch.h, raster/sprite_rows.h, raster/dot_kernel.h), so
 * the bands give the bytes of the whole draw for any number of threads. */

/* Particle i's screen point, kept on the canvas where the group's walls
 * hold it (as the batched kernels' ISK__BATCH_KEEP_ON_CANVAS does). */
static void screen_point(const isk_effect *e, const isk_canvas *c, const fx_group *g, size_t i, double *X,
                         double *Y)
{
    isk_view_to_screen(&e->view, g->store.x[i], g->store.y[i], X, Y);
    if (g->keep_on_canvas) {
        *X = isk__keep_on_canvas(*X, c->width);
        *Y = isk__keep_on_canvas(*Y, c->height);
    }
}

/* One colour per particle (a ramp or per-particle colours): the view
 * transform and one dot each. */
static isk_status draw_styled_dots(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b)
{
    const isk_particles *p = &g->store;
    const isk_blend blend = g->def->blend;
    const int browser = g->def->draw == ISK_DRAW_DOT_BROWSER;
    const size_t n = b->list ? b->nlist : b->end;
    for (size_t k = b->list ? 0 : b->first; k < n; k++) {
        const size_t i = b->list ? b->list[k] : k;
        double X, Y, mult;
        screen_point(e, c, g, i, &X, &Y);
        isk_color col = style(g, p, i, 1, &mult);
        if (browser)
            ISK__BLEND_DISPATCH(blend, isk__dot_browser_rows, c, b->r0, b->r1, X, Y, col, NULL);
        else
            ISK__BLEND_DISPATCH(blend, isk__dot_rows, c, b->r0, b->r1, X, Y, col, NULL);
    }
    return ISK_OK;
}

unsigned fx_dots_rule(const fx_group *g)
{
    const unsigned rule = g->def->draw == ISK_DRAW_DOT_BROWSER ? ISK__BATCH_DOT_BROWSER
                          : g->def->draw == ISK_DRAW_PIXEL     ? ISK__BATCH_PIXEL
                                                               : ISK__BATCH_DOT;
    return g->keep_on_canvas ? rule | ISK__BATCH_KEEP_ON_CANVAS : rule;
}

/* One colour for the whole group: the batched kernels (iskra/view.h). */
static isk_status draw_dots(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b)
{
    const unsigned rule = fx_dots_rule(g);
    if (b->list)
        isk__draw_batch_list_rows(c, &e->view, b->list, b->nlist, g->store.x, g->store.y, g->def->color,
                                  g->def->blend, rule, b->r0, b->r1);
    else
        isk__draw_batch_tile(c, &e->view, b->end - b->first, g->store.x + b->first, g->store.y + b->first,
                             g->def->color, g->def->blend, rule, b->r0, b->r1, b->c0, b->c1);
    return ISK_OK;
}

static isk_status draw_styled_pixels(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b)
{
    const isk_particles *p = &g->store;
    const size_t n = b->list ? b->nlist : b->end;
    for (size_t k = b->list ? 0 : b->first; k < n; k++) {
        const size_t i = b->list ? b->list[k] : k;
        double X, Y, mult;
        screen_point(e, c, g, i, &X, &Y);
        isk_color col = style(g, p, i, 1, &mult);
        if (X >= 0 && Y >= b->r0 && X < c->width && Y < b->r1)
            isk_draw_pixel(c, (int)X, (int)Y, col, g->def->blend);
    }
    return ISK_OK;
}

static isk_status draw_discs(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b)
{
    const isk_particles *p = &g->store;
    const int vary = fx_varies(g);
    const double scale = fabs(e->view.sx);
    for (size_t i = b->first; i < b->end; i++) {
        double X, Y, mult;
        isk_view_to_screen(&e->view, p->x[i], p->y[i], &X, &Y);
        isk_color col = style(g, p, i, vary, &mult);
        const double size = p->size ? p->size[i] : g->def->size; /* size_range: its own */
        isk__fill_circle_aa_rows(c, X, Y, 0.5 * size * mult * scale, col, g->def->blend, b->r0, b->r1);
    }
    return ISK_OK;
}

/* A sprite's whole-pixel size for a size multiplier. */
static int sprite_px(const fx_group *g, double scale, double mult)
{
    double d = g->def->size * mult * scale;
    if (!(d > 0))
        return 0;
    return d >= ISK_SPRITE_MAX_SIZE ? ISK_SPRITE_MAX_SIZE : (d >= 1.0 ? (int)(d + 0.5) : 1);
}

/* Every sprite the group can need, by whole-pixel size, baked before the
 * draw: one size, or one per entry of the size ramp's table (the
 * multipliers a particle can have).  The bands then only read the table;
 * the cache is never touched from two threads.  ISK_ERR_FULL when the
 * sizes do not fit the cache (the draw then runs whole, on one thread). */
static isk_status prepare_sprites(isk_effect *e, fx_group *g, fx_band *b)
{
    const int tinted = g->has_color_ramp || g->has_alpha_ramp || g->store.color;
    const isk_color bake_col = tinted ? ISK_WHITE : g->def->color;
    const double scale = fabs(e->view.sx);
    const int n = g->has_size_ramp ? g->size_ramp.res + 1 : 1;
    for (int attempt = 0; attempt < 2; attempt++) {
        isk_status s = ISK_OK;
        memset(b->sprite, 0, sizeof b->sprite);
        b->sprite_reach = 0;
        for (int k = 0; k < n && s == ISK_OK; k++) {
            int px = sprite_px(g, scale, g->has_size_ramp ? g->size_ramp.table[k] : 1.0);
            if (px && !b->sprite[px])
                s = isk_sprite_cache_get(e->sprites, g->def->sprite, px, bake_col, &b->sprite[px]);
            /* a mask of S rows sits at its centre, snapped to half pixels,
             * minus S/2: it reaches S/2 + 1 rows either way at most */
            if (s == ISK_OK && px && b->sprite[px]->size / 2.0 + 2.0 > b->sprite_reach)
                b->sprite_reach = b->sprite[px]->size / 2.0 + 2.0;
        }
        if (s == ISK_OK)
            return ISK_OK;
        if (s != ISK_ERR_FULL)
            return s;
        isk_sprite_cache_clear(e->sprites); /* full of other sizes: start over once */
    }
    return ISK_ERR_FULL;
}

/* Sprites: with a constant colour, one sprite baked in that colour (its
 * blend table makes drawing cheapest); when the colour or alpha varies per
 * particle (ramps), one mask per size baked in white and drawn tinted, so a
 * ramp of a thousand colours bakes nothing more.  Both give
 * isk_blend_pixel_cov's bytes exactly.  A size ramp gives each particle its
 * own whole-pixel size (the sprites prepare_sprites baked). */
static isk_status draw_sprites(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b)
{
    const isk_particles *p = &g->store;
    const int vary = fx_varies(g);
    const int tinted = g->has_color_ramp || g->has_alpha_ramp || p->color;
    const double scale = fabs(e->view.sx);
    /* a band's thread reads every particle: those whose sprite cannot reach
     * its rows (NaN included: the sprite would not be placed) are passed
     * over before their style is worked out, chunk by chunk, by the dots'
     * branch-free select; the test as a branch was a coin toss on two
     * bands of a shuffled store, a quarter of the threaded sprite draw.
     * The reach is a row wider than a sprite can touch, so the select's
     * strict bounds drop nothing the band would draw. */
    enum { CHUNK = 256 };
    double ys[CHUNK];
    int32_t in_reach[CHUNK];
    const double lo = b->r0 - b->sprite_reach, hi = b->r1 + b->sprite_reach;
    for (size_t o = b->first; o < b->end; o += CHUNK) {
        const int m = b->end - o < CHUNK ? (int)(b->end - o) : CHUNK;
        const int k = isk__batch_select_rows(&e->view, p->y + o, m, lo, hi, ys, in_reach);
        for (int q = 0; q < k; q++) {
            const size_t i = o + (size_t)in_reach[q];
            double X, Y, mult;
            isk_view_to_screen(&e->view, p->x[i], p->y[i], &X, &Y);
            isk_color col = style(g, p, i, vary, &mult);
            const isk_sprite *spr = b->sprite[sprite_px(g, scale, mult)];
            if (spr)
                isk__draw_sprite_rows(c, spr, X, Y, tinted ? &col : NULL, g->def->blend, b->r0, b->r1);
        }
    }
    return ISK_OK;
}

static isk_status draw_nothing(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b)
{
    (void)e;
    (void)c;
    (void)g;
    (void)b;
    return ISK_OK;
}

fx_draw_fn fx_choose_draw(const fx_group *g)
{
    const int vary = fx_varies(g);
    if (g->texture && g->def->draw != ISK_DRAW_NONE)
        return fx_draw_textures; /* a texture or a streak (effect_texture.c) */
    switch (g->def->draw) {
    case ISK_DRAW_DOT:
    case ISK_DRAW_DOT_BROWSER: return vary ? draw_styled_dots : draw_dots;
    case ISK_DRAW_PIXEL: return vary ? draw_styled_pixels : draw_dots;
    case ISK_DRAW_DISC: return draw_discs;
    case ISK_DRAW_SPRITE: return draw_sprites;
    default: return draw_nothing;
    }
}

/* What a particle of g costs to draw on one thread, in batched coverage
 * dots (8-9 ns each here): fx_draw_bands shares a draw out over the
 * threads only when the whole is worth it.  Measured on one thread
 * (bench_layer.h's layer, 2026-12-04): a batched single pixel 3.6-5 ns,
 * but its bands gain least (every band scans the store for a pixel's
 * worth of work), so it counts for a third; an 8 px sprite 42-45 ns, and
 * textures and per-particle colours (a screen transform, a style and a
 * kernel call each) at least as much.  Those count for ten: their bands
 * gain from 10^4 sprites on, where the dots' gain from 5*10^4 (both after
 * a clear by the caller; effect_bands.c has the figures). */
static double draw_cost(const fx_group *g)
{
    if (g->draw == draw_dots)
        return g->def->draw == ISK_DRAW_PIXEL ? 1.0 / 3.0 : 1.0;
    return 10.0;
}

/* A group's draw: on the effect's threads in bands.  fill: NULL, or the
 * background the canvas is cleared to first, by the bands of the group's
 * first pass. */
static isk_status render_group(isk_effect *e, isk_canvas *c, fx_group *g, const isk_color *fill)
{
    fx_band whole = fx_band_whole(c, g);
    if (g->store.trail) { /* trails under the particles (effect_trail.c) */
        isk_status s = fx_trail_render(e, c, g, fill);
        if (s != ISK_OK)
            return s;
        fill = NULL;
    }
    if (g->draw == draw_sprites) {
        isk_status s = prepare_sprites(e, g, &whole);
        if (s != ISK_OK)
            return s;
    }
    /* dots and pixels reach at most a row beyond their own (the margin
     * world_batch.h's binning keeps), so their bands can take only their
     * own particles; sprites reach far and read them all */
    const unsigned can = (g->draw != draw_sprites && g->draw != fx_draw_textures && g->draw != draw_discs
                              ? FX_BANDS_SORT
                              : 0u) |
                         (g->draw == draw_dots ? FX_BANDS_COLUMNS : 0u) |
                         /* the exact-area dots' blends can be recorded (world_batch.h) */
                         (g->draw == draw_dots && g->def->draw == ISK_DRAW_DOT ? FX_BANDS_RETAIN : 0u);
    return fx_draw_bands(e, c, g, &whole, can, draw_cost(g), fill, &g->shares);
}

isk_status fx_render(isk_effect *e, isk_canvas *c)
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
    return ISK_OK;
}
