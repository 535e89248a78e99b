/* SPDX-License-Identifier: MIT */
/* The band scheduler reads a draw kind's row and nothing else
 * (effect_draws.c): what it may do with the draw, and how many rows beyond
 * its own a particle's draw reaches.
 *
 * A test-only kind draws a particle as two pixels, on its own row and
 * three rows below: one row more than the dots reach.  Declared so, it is
 * drawn byte for byte the same on 1, 2, 3 and 7 workers (on 4 and more the
 * particles are sorted into the bands by that reach).  Declared with the
 * dots' reach, the sorted bands lose pixels: the row is what keeps the
 * bytes, so the check can fail.  A kind that declares nothing is drawn
 * whole, on the caller. */
#include <criterion/criterion.h>
#include "fast_paths_skip.h"

#include <math.h>
#include <string.h>

#include "iskra/draw.h"
#include "scene/effect_internal.h"
#include "scene_text.h"
#include "view/world_batch.h"

static long whole_draws, band_draws;

/* Two pixels a particle, at rows floor(Y) and floor(Y) + 3, cut to the band. */
static isk_status draw_pair(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b)
{
    const isk_particles *p = &g->store;
    if (b->r0 == 0 && b->r1 == c->height)
        whole_draws++;
    else
        band_draws++;
    const size_t n = b->list ? b->nlist : b->end;
    for (size_t k = b->list ? 0 : b->first; k < n; k++) {
        const size_t i = b->list ? b->list[k] : k;
        double X, Y;
        isk_view_to_screen(&e->view, p->x[i], p->y[i], &X, &Y);
        if (!(X >= 0 && X < c->width && Y >= 0 && Y < c->height))
            continue;
        const int x = (int)X, y = (int)Y;
        for (int d = 0; d <= 3; d += 3)
            if (y + d >= b->r0 && y + d < b->r1)
                isk_draw_pixel(c, x, y + d, isk_rgba(255, 200, 40, 160), ISK_BLEND_OVER);
    }
    return ISK_OK;
}

static const fx_draw_kind pair_declared = {.name = "pairs", .draw = draw_pair, .cost = 1.0,
                                           .reach = ISK__DOT_REACH + 1, .may = FX_MAY_BANDS | FX_MAY_SORT};
static const fx_draw_kind pair_too_short = {.name = "pairs", .draw = draw_pair, .cost = 1.0,
                                            .reach = ISK__DOT_REACH, .may = FX_MAY_BANDS | FX_MAY_SORT};
static const fx_draw_kind pair_undeclared = {.name = "pairs", .draw = draw_pair};

/* A falling layer that covers the canvas, drawn with `kind` on `threads`
 * workers after each of 20 frames, every draw in bands however small. */
static void draw_with(const fx_draw_kind *kind, int threads, isk_canvas *c)
{
    isk_effect *fx = scene_text_open("[scene]\nwidth = 200\nheight = 150\nseed = 4\n[view]\nxmin = -5\nxmax = 5\n"
                                     "ymin = -4\nymax = 4\n[force g]\nkind = gravity\ng = 2\n"
                                     "[emitter a]\nsource = layer\ncount = 20000\nlimit = 20000\n"
                                     "rect = -5, 5, -4, 4\nforces = g\n",
                                     threads);
    fx->band_min_work = 0;
    fx->groups[0].draw = kind;
    cr_assert_eq(isk_canvas_init(c, 200, 150), ISK_OK);
    for (int f = 0; f < 20; f++)
        cr_assert_eq(isk_effect_step_render(fx, c), ISK_OK);
    isk_effect_destroy(fx);
}

static size_t differing(const isk_canvas *a, const isk_canvas *b)
{
    size_t n = 0;
    for (int y = 0; y < a->height; y++)
        n += memcmp(a->pixels + (size_t)y * a->stride, b->pixels + (size_t)y * b->stride, (size_t)a->width * 4) != 0;
    return n;
}

Test(draw_kinds, a_kind_that_reaches_further_is_the_same_on_every_thread_count)
{
    isk_canvas one;
    draw_with(&pair_declared, 1, &one);
    static const int threads[] = {2, 3, 7};
    for (int k = 0; k < 3; k++) {
        isk_canvas many;
        band_draws = 0;
        draw_with(&pair_declared, threads[k], &many);
        if (ISK__FAST_BANDS)
            cr_expect_gt(band_draws, 0, "%d workers: never drawn in bands", threads[k]);
        cr_expect_eq(differing(&one, &many), 0, "%d workers: %zu rows differ", threads[k], differing(&one, &many));
        isk_canvas_free(&many);
    }
    isk_canvas_free(&one);
}

/* The same routine with the dots' reach: sorted into 7 bands, the pixels
 * three rows below a band's last rows are lost. */
Test(draw_kinds, a_reach_declared_too_short_loses_pixels)
{
    SKIP_WITHOUT(ISK__FAST_BANDS, "draws in bands");
    isk_canvas one, seven;
    draw_with(&pair_declared, 1, &one);
    draw_with(&pair_too_short, 7, &seven);
    cr_expect_gt(differing(&one, &seven), 0, "the declared reach made no difference: the check cannot fail");
    isk_canvas_free(&one);
    isk_canvas_free(&seven);
}

Test(draw_kinds, a_kind_that_declares_nothing_is_drawn_whole)
{
    isk_canvas one, seven;
    draw_with(&pair_declared, 1, &one);
    whole_draws = band_draws = 0;
    draw_with(&pair_undeclared, 7, &seven);
    cr_expect_eq(band_draws, 0);
    cr_expect_eq(whole_draws, 20);
    cr_expect_eq(differing(&one, &seven), 0);
    isk_canvas_free(&one);
    isk_canvas_free(&seven);
}

/* Every kind the library chooses declares itself: a name, a routine, and
 * bands (each honours its band's rows); sorting only with a finite reach. */
Test(draw_kinds, the_librarys_kinds_declare_themselves)
{
    const fx_draw_kind *kinds[] = {&isk__fx_kind_dots,    &isk__fx_kind_browser_dots, &isk__fx_kind_pixels,
                                   &isk__fx_kind_styled_dots, &isk__fx_kind_styled_pixels, &isk__fx_kind_discs,
                                   &isk__fx_kind_sprites, &isk__fx_kind_textures};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        cr_expect(kinds[k]->name && kinds[k]->draw, "kind %zu", k);
        cr_expect(kinds[k]->may & FX_MAY_BANDS, "%s", kinds[k]->name);
        cr_expect(!(kinds[k]->may & FX_MAY_SORT) || kinds[k]->reach >= ISK__DOT_REACH, "%s", kinds[k]->name);
        cr_expect_gt(kinds[k]->cost, 0.0, "%s", kinds[k]->name);
    }
    cr_expect_eq(isk__fx_kind_nothing.may, 0);
}
