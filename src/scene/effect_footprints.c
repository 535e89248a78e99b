/* SPDX-License-Identifier: MIT */
/* Footprints: the most pixels one particle's draw may touch, for the draw
 * kinds' rows (fx_draw_kind.pixels, effect_draws.c and effect_trail.c),
 * which the work budget reads (effect_budget.c).  Each is at most the
 * canvas: a draw is clipped to it. */
#include <math.h>

#include "effect_internal.h"
#include "iskra/texture.h"

/* The pixels of a square of side s (plus a pixel of anti-aliasing each
 * way), at most the canvas's. */
static double square_px(const isk_effect *e, double s)
{
    const double canvas = (double)e->def.width * (double)e->def.height;
    const double a = (s + 2.0) * (s + 2.0);
    return a < canvas ? a : canvas;
}

/* A particle's largest size in pixels: size plus its range, times the
 * largest size_over_life, times the view's larger scale. */
static double size_px(const isk_effect *e, const fx_group *g)
{
    const isk_emitter_look *l = &g->def->look;
    double mult = l->size_over_life.n > 0 ? 0.0 : 1.0;
    for (int k = 0; k < l->size_over_life.n; k++)
        mult = l->size_over_life.stops[k].value > mult ? l->size_over_life.stops[k].value : mult;
    const double scale = fabs(e->view.sx) > fabs(e->view.sy) ? fabs(e->view.sx) : fabs(e->view.sy);
    return (l->size + (l->size_range > 0 ? l->size_range : 0)) * mult * scale;
}

double isk__fx_px_dot(const isk_effect *e, const fx_group *g)
{
    (void)g;
    return square_px(e, 0.0); /* a coverage dot touches 2 x 2 pixels */
}

double isk__fx_px_pixel(const isk_effect *e, const fx_group *g)
{
    (void)e;
    (void)g;
    return 1.0;
}

double isk__fx_px_round(const isk_effect *e, const fx_group *g)
{
    return square_px(e, size_px(e, g)); /* a disc or a sprite of that diameter */
}

double isk__fx_px_texture(const isk_effect *e, const fx_group *g)
{
    const isk_texture *t = g->texture;
    const double aspect = t && t->frame_w > 0 ? (double)t->frame_h / (double)t->frame_w : 1.0;
    const double stretch = t == &g->streak ? ISK_STREAK_STRETCH : 1.0;
    double w = size_px(e, g);
    w = w < ISK_TEXTURE_DRAW_MAX ? w : ISK_TEXTURE_DRAW_MAX;
    return square_px(e, w * hypot(stretch, aspect)); /* turned any way: within its diagonal */
}

double isk__fx_px_none(const isk_effect *e, const fx_group *g)
{
    (void)e;
    (void)g;
    return 0.0;
}

double isk__fx_px_trail(const isk_effect *e, const fx_group *g)
{
    return square_px(e, g->def->look.trail_width); /* a segment: a ribbon's width each way */
}
