/* SPDX-License-Identifier: MIT */
/* Trails: each particle of an emitter with trail = N keeps its
 * last N positions in the store's trail column (a ring, newest at the
 * store's trail_head; it moves with its particle on cull and removal), and
 * is drawn, before the group's particles, as an anti-aliased ribbon through
 * them (isk_stroke_trail), oldest first.
 *
 * Recording: once per frame, at the end of isk_effect_step (after the
 * sub-emitters' births), so a trail is the particle's path sampled at the
 * frames shown, whatever the substeps; a new particle's points all start at
 * its position (its trail is a disc of the ribbon's width until it moves).
 * Width: trail_width in pixels, the same at every zoom, as a dot's size is:
 * a trail is a drawing aid, not a body in the world.  Colour: the
 * particle's own, as its draw gives it (colour and alpha over life
 * included), fading to alpha * (1 - trail_fade) at the oldest point.
 *
 * Threads: the group's trails are drawn in bands of rows with the band form
 * isk__stroke_trail_rows, each band reading every particle: the same bytes
 * on any number of threads. */
#include "effect_internal.h"
#include "effect_style.h"
#include "iskra/limits.h"
#include "raster/trail_rows.h"

void isk__fx_trail_record(isk_effect *e, long stepped)
{
    for (int i = 0; i < e->ngroups; i++)
        if (e->groups[i].store.trail && stepped + e->groups[i].frame_offset >= 0 &&
            !e->groups[i].def->motion.paused)
            isk_particles_record_trail(&e->groups[i].store);
}

/* A trail takes its particle's colour. */
static isk_color trail_color(const fx_group *g, size_t i)
{
    double mult;
    return fx_style(g, &g->store, i, fx_varies(g), &mult);
}

static isk_status draw_trails(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b)
{
    const isk_particles *p = &g->store;
    const int n = p->trail_len;
    if (!p->trail || n <= 0 || n > ISK_TRAIL_MAX)
        return ISK_OK;
    const isk_emitter_def *em = g->def;
    double xy[2 * ISK_TRAIL_MAX];
    for (size_t i = b->first; i < b->end; i++) {
        const double *t = p->trail + 2 * (size_t)n * i;
        for (int k = 0; k < n; k++) { /* oldest first: the slot after the newest */
            int slot = (p->trail_head + 1 + k) % n;
            isk_view_to_screen(&e->view, t[2 * slot], t[2 * slot + 1], &xy[2 * k], &xy[2 * k + 1]);
        }
        isk__stroke_trail_rows(c, xy, n, em->look.trail_width, trail_color(g, i), em->look.trail_fade,
                               em->look.blend, b->r0, b->r1);
    }
    return ISK_OK;
}

/* A trail's stroke blends only the band's rows (isk__stroke_trail_rows);
 * its reach is its width, so a band reads every particle; cost: a dot a
 * segment, times the points (isk__fx_trail_render's units); pixels: a
 * segment's square of the ribbon's width. */
const fx_draw_kind isk__fx_kind_trails = {"trails", draw_trails, NULL, 1.0, 0, FX_MAY_BANDS | FX_MAY_SPLIT,
                                          isk__fx_px_trail};

isk_status isk__fx_trail_render(isk_effect *e, isk_canvas *c, fx_group *g, const isk_color *fill)
{
    if (!g->store.trail) {
        if (fill)
            isk_canvas_fill(c, *fill);
        return ISK_OK;
    }
    const fx_band whole = isk__fx_band_whole(c, g);
    return isk__fx_draw_bands(e, c, g, &isk__fx_kind_trails, &whole, (double)g->store.trail_len, fill); /* a segment a point */
}
