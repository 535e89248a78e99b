/* SPDX-License-Identifier: MIT */
/* What a group's particles look like on the canvas: the over-life ramps
 * (baked once per emitter at create, read per particle), each particle's
 * colour and size, and the draw kinds, one row each (fx_draw_kind): the
 * routine that draws a band of the group, and what the band scheduler
 * (effect_bands.c) may do with it. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/fast_paths.h"
#include "effect_internal.h"
#include "effect_style.h"
#include "raster/circle_rows.h"
#include "raster/clip.h"
#include "raster/dot_kernel.h"
#include "raster/sprite_rows.h"
#include "view/world_batch.h"

isk_status isk__fx_bake_ramps(fx_group *g, isk_error *err)
{
    const isk_emitter_def *em = g->def;
    isk_status s = ISK_OK;
    if (em->look.color_over_life.n) {
        s = isk_color_gradient_bake(&g->color_ramp, em->look.color_over_life.stops, em->look.color_over_life.n,
                                    ISK_GRADIENT_DEFAULT_RES);
        g->has_color_ramp = s == ISK_OK;
    }
    if (s == ISK_OK && em->look.alpha_over_life.n) {
        s = isk_scalar_gradient_bake(&g->alpha_ramp, em->look.alpha_over_life.stops, em->look.alpha_over_life.n,
                                     ISK_GRADIENT_DEFAULT_RES);
        g->has_alpha_ramp = s == ISK_OK;
    }
    if (s == ISK_OK && em->look.size_over_life.n) {
        s = isk_scalar_gradient_bake(&g->size_ramp, em->look.size_over_life.stops, em->look.size_over_life.n,
                                     ISK_GRADIENT_DEFAULT_RES);
        g->has_size_ramp = s == ISK_OK;
    }
    if (s != ISK_OK)
        return isk_error_set(err, s, "emitter '%s': cannot bake its over-life ramps: %s", em->name,
                             isk_status_str(s));
    return ISK_OK;
}

void isk__fx_free_ramps(fx_group *g)
{
    if (g->has_color_ramp)
        isk_color_gradient_free(&g->color_ramp);
    if (g->has_alpha_ramp)
        isk_scalar_gradient_free(&g->alpha_ramp);
    if (g->has_size_ramp)
        isk_scalar_gradient_free(&g->size_ramp);
    g->has_color_ramp = g->has_alpha_ramp = g->has_size_ramp = 0;
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
    const isk_blend blend = g->def->look.blend;
    const int browser = g->def->look.draw == ISK_DRAW_DOT_BROWSER;
    const int vary = fx_varies(g);
    const size_t n = b->list ? b->nlist : b->end;
    for (size_t k = b->list ? 0 : b->first; k < n; k++) {
        const size_t i = b->list ? b->list[k] : k;
        double X, Y, mult;
        screen_point(e, c, g, i, &X, &Y);
        isk_color col = fx_style(g, p, i, vary, &mult);
        if (browser)
            ISK__BLEND_DISPATCH(blend, isk__dot_browser_rows, c, b->r0, b->r1, X, Y, col, NULL);
        else
            ISK__BLEND_DISPATCH(blend, isk__dot_rows, c, b->r0, b->r1, X, Y, col, NULL);
    }
    return ISK_OK;
}

unsigned isk__fx_dots_rule(const fx_group *g)
{
    const unsigned rule = g->def->look.draw == ISK_DRAW_DOT_BROWSER ? ISK__BATCH_DOT_BROWSER
                          : g->def->look.draw == ISK_DRAW_PIXEL     ? ISK__BATCH_PIXEL
                                                               : ISK__BATCH_DOT;
    return g->keep_on_canvas ? rule | ISK__BATCH_KEEP_ON_CANVAS : rule;
}

static isk_status draw_styled_pixels(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b);

/* One colour for the whole group: the batched kernels (iskra/view.h).  The
 * reference build draws it one dot or pixel at a time, as the styled draws
 * do (the same bytes: tests/test_raster_fast.c). */
static isk_status draw_dots(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b)
{
    if (!ISK__FAST_BATCH)
        return g->def->look.draw == ISK_DRAW_PIXEL ? draw_styled_pixels(e, c, g, b) : draw_styled_dots(e, c, g, b);
    const unsigned rule = isk__fx_dots_rule(g);
    if (b->list)
        isk__draw_batch_list_rows(c, &e->view, b->list, b->nlist, g->store.x, g->store.y, g->def->look.color,
                                  g->def->look.blend, rule, b->r0, b->r1);
    else
        isk__draw_batch_tile(c, &e->view, b->end - b->first, g->store.x + b->first, g->store.y + b->first,
                             g->def->look.color, g->def->look.blend, rule, b->r0, b->r1, b->c0, b->c1);
    return ISK_OK;
}

static isk_status draw_styled_pixels(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b)
{
    const isk_particles *p = &g->store;
    const int vary = fx_varies(g);
    const size_t n = b->list ? b->nlist : b->end;
    for (size_t k = b->list ? 0 : b->first; k < n; k++) {
        const size_t i = b->list ? b->list[k] : k;
        double X, Y, mult;
        screen_point(e, c, g, i, &X, &Y);
        isk_color col = fx_style(g, p, i, vary, &mult);
        if (X >= 0 && Y >= b->r0 && X < c->width && Y < b->r1)
            isk_draw_pixel(c, (int)X, (int)Y, col, g->def->look.blend);
    }
    return ISK_OK;
}

static isk_status draw_discs(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b)
{
    const isk_particles *p = &g->store;
    const int vary = fx_varies(g);
    const double scale = fabs(e->view.sx);
    const size_t n = b->list ? b->nlist : b->end;
    for (size_t k = b->list ? 0 : b->first; k < n; k++) {
        const size_t i = b->list ? b->list[k] : k;
        double X, Y, mult;
        isk_view_to_screen(&e->view, p->x[i], p->y[i], &X, &Y);
        isk_color col = fx_style(g, p, i, vary, &mult);
        const double size = p->size ? p->size[i] : g->def->look.size; /* size_range: its own */
        isk__fill_circle_aa_rows(c, X, Y, 0.5 * size * mult * scale, col, g->def->look.blend, b->r0, b->r1);
    }
    return ISK_OK;
}

/* A sprite's whole-pixel size for a size multiplier. */
static int sprite_px(const fx_group *g, double scale, double mult)
{
    double d = g->def->look.size * mult * scale;
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
    const isk_color bake_col = tinted ? ISK_WHITE : g->def->look.color;
    const double scale = fabs(e->view.sx);
    const int n = g->has_size_ramp ? g->size_ramp.res + 1 : 1;
    for (int attempt = 0; attempt < 2; attempt++) {
        isk_status s = ISK_OK;
        memset(b->sprite, 0, sizeof b->sprite);
        b->sprite_reach = 0;
        for (int k = 0; k < n && s == ISK_OK; k++) {
            int px = sprite_px(g, scale, g->has_size_ramp ? g->size_ramp.table[k] : 1.0);
            if (px && !b->sprite[px])
                s = isk_sprite_cache_get(e->sprites, g->def->look.sprite, px, bake_col, &b->sprite[px]);
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

/* Particle i's sprite, of its size and in its colour, over the band's rows. */
static inline void draw_one_sprite(const isk_effect *e, isk_canvas *c, const fx_group *g, const fx_band *b,
                                   size_t i, int vary, int tinted, double scale)
{
    const isk_particles *p = &g->store;
    double X, Y, mult;
    isk_view_to_screen(&e->view, p->x[i], p->y[i], &X, &Y);
    isk_color col = fx_style(g, p, i, vary, &mult);
    const isk_sprite *spr = b->sprite[sprite_px(g, scale, mult)];
    if (spr)
        isk__draw_sprite_rows(c, spr, X, Y, tinted ? &col : NULL, g->def->look.blend, b->r0, b->r1);
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
    if (b->list) { /* another order than the store's (draw_order): drawn whole, one by one */
        for (size_t k = 0; k < b->nlist; k++)
            draw_one_sprite(e, c, g, b, b->list[k], vary, tinted, scale);
        return ISK_OK;
    }
    enum { CHUNK = 256 };
    double ys[CHUNK];
    int32_t in_reach[CHUNK];
    const double lo = b->r0 - b->sprite_reach, hi = b->r1 + b->sprite_reach;
    for (size_t o = b->first; o < b->end; o += CHUNK) {
        const int m = b->end - o < CHUNK ? (int)(b->end - o) : CHUNK;
        const int k = isk__batch_select_rows(&e->view, p->y + o, m, lo, hi, ys, in_reach);
        for (int q = 0; q < k; q++)
            draw_one_sprite(e, c, g, b, o + (size_t)in_reach[q], vary, tinted, scale);
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

/* ---- the draw kinds -------------------------------------------------------
 * Each kind is a row: its routine and what the band scheduler may do with
 * it (effect_bands.c reads the row and nothing else: never the routine's
 * address).  A row that leaves `may` at 0 is drawn whole, on the caller.
 *
 *   FX_MAY_BANDS    the routine blends only the rows [b->r0, b->r1) of a
 *                   shape it places on the whole canvas: bands of rows give
 *                   the whole draw's bytes
 *   FX_MAY_SORT     a particle's draw touches no row further than `reach`
 *                   from its own (floor of its screen Y): a band may get
 *                   only the particles within reach of its rows
 *   FX_MAY_COLUMNS  the same for columns: bands of columns [b->c0, b->c1)
 *   FX_MAY_SPLIT    with an additive blend, what a particle adds to a
 *                   pixel does not depend on the pixel: its particles may
 *                   be split among the workers onto canvases of their own
 *   FX_MAY_RETAIN   its blends can be recorded while the group rests and
 *                   replayed (effect_retain.c)
 * cost: a particle's draw on one thread, in batched coverage dots (what
 * the scheduler weighs against FX_BAND_MIN_WORK).
 * pixels: the most pixels a particle's draw may touch (effect_budget.c:
 * the work budget counts cost + pixels a particle). */
#define FX_ROWS (FX_MAY_BANDS | FX_MAY_SPLIT)

const fx_draw_kind isk__fx_kind_dots = {"dots", draw_dots, NULL, 1.0, ISK__DOT_REACH,
                                   FX_ROWS | FX_MAY_SORT | FX_MAY_COLUMNS | FX_MAY_RETAIN, isk__fx_px_dot};
const fx_draw_kind isk__fx_kind_browser_dots = {"browser dots", draw_dots, NULL, 1.0, ISK__DOT_REACH,
                                           FX_ROWS | FX_MAY_SORT | FX_MAY_COLUMNS, isk__fx_px_dot};
/* a third of a dot: a single pixel's bands gain least (every band scans
 * the store for a pixel's worth of work) */
const fx_draw_kind isk__fx_kind_pixels = {"pixels", draw_dots, NULL, 1.0 / 3.0, ISK__DOT_REACH,
                                     FX_ROWS | FX_MAY_SORT | FX_MAY_COLUMNS, isk__fx_px_pixel};
/* a screen transform, a style and a kernel call each: ten dots */
const fx_draw_kind isk__fx_kind_styled_dots = {"dots, a colour each", draw_styled_dots, NULL, 10.0, ISK__DOT_REACH,
                                          FX_ROWS | FX_MAY_SORT, isk__fx_px_dot};
const fx_draw_kind isk__fx_kind_styled_pixels = {"pixels, a colour each", draw_styled_pixels, NULL, 10.0, ISK__DOT_REACH,
                                            FX_ROWS | FX_MAY_SORT, isk__fx_px_pixel};
const fx_draw_kind isk__fx_kind_discs = {"discs", draw_discs, NULL, 10.0, 0, FX_ROWS, isk__fx_px_round};
const fx_draw_kind isk__fx_kind_sprites = {"sprites", draw_sprites, prepare_sprites, 10.0, 0, FX_ROWS, isk__fx_px_round};
const fx_draw_kind isk__fx_kind_textures = {"textures", isk__fx_draw_textures, NULL, 10.0, 0, FX_ROWS, isk__fx_px_texture};
const fx_draw_kind isk__fx_kind_nothing = {"nothing", draw_nothing, NULL, 0.0, 0, 0, isk__fx_px_none};

const fx_draw_kind *isk__fx_choose_draw(const fx_group *g)
{
    const int vary = fx_varies(g);
    if (g->texture && g->def->look.draw != ISK_DRAW_NONE)
        return &isk__fx_kind_textures; /* a texture or a streak (effect_texture.c) */
    switch (g->def->look.draw) {
    case ISK_DRAW_DOT: return vary ? &isk__fx_kind_styled_dots : &isk__fx_kind_dots;
    case ISK_DRAW_DOT_BROWSER: return vary ? &isk__fx_kind_styled_dots : &isk__fx_kind_browser_dots;
    case ISK_DRAW_PIXEL: return vary ? &isk__fx_kind_styled_pixels : &isk__fx_kind_pixels;
    case ISK_DRAW_DISC: return &isk__fx_kind_discs;
    case ISK_DRAW_SPRITE: return &isk__fx_kind_sprites;
    default: return &isk__fx_kind_nothing;
    }
}
