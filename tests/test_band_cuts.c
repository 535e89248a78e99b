/* SPDX-License-Identifier: MIT */
/* Where the threaded draw cuts the canvas (effect_bands.c's
 * isk__fx_place_cuts): at the quantiles of a sample of the particles' screen
 * rows, or of their columns when the particles crowd into a few rows.  The
 * cuts never change a byte (threads_check shows that); what they are for is
 * sharing the work evenly, and that is what is checked here: every band
 * holds its share of the whole store, within what a sample of 1024 allows.
 * A sort of the sample that got the order wrong would put the cuts
 * anywhere.  They depend on the particles alone (no clock), so two draws
 * of the same state are cut the same way. */
#include <criterion/criterion.h>

#include <math.h>

#include "iskra/canvas.h"
#include "iskra/view.h"
#include "scene/effect_internal.h"
#include "scene_text.h"
#include "view/world_batch.h"

/* A layer filling a 640 x 480 view (rows and columns past 255, so both
 * digits of the sort count) in a box with a floor. */
static const char *LAYER = "[scene]\nwidth = 640\nheight = 480\n[force gravity]\ng = 400\n"
                           "[bounds]\nrestitution = 0.2\n"
                           "[emitter a]\nsource = layer\ncount = 60000\nlimit = 60000\nrect = -9, 9, -9, 9\n"
                           "forces = gravity\n";

/* Each band's share of the store's particles drawn on the canvas (by
 * their row, or column), against 1/nb. */
static void check_shares(isk_effect *fx, const isk_canvas *c, int nb, int columns_expected)
{
    const fx_group *g = &fx->groups[0];
    int cut[ISK_TASKS_MAX_WORKERS + 1];
    const int columns = isk__fx_place_cuts(fx, g, c, nb, 1, cut);
    cr_assert_eq(columns, columns_expected, "%d bands: columns %d", nb, columns);
    const int n = columns ? c->width : c->height;
    cr_assert_eq(cut[0], 0);
    cr_assert_eq(cut[nb], n);
    for (int k = 0; k < nb; k++)
        cr_assert_leq(cut[k], cut[k + 1], "%d bands: cut %d", nb, k);
    size_t in[ISK_TASKS_MAX_WORKERS] = {0}, total = 0;
    for (size_t i = 0; i < g->store.count; i++) {
        double X, Y;
        isk_view_to_screen(&fx->view, g->store.x[i], g->store.y[i], &X, &Y);
        if (g->keep_on_canvas) { /* where the draw puts them: the floor's row, not the one below */
            X = isk__keep_on_canvas(X, c->width);
            Y = isk__keep_on_canvas(Y, c->height);
        }
        if (!(X >= 0 && X < c->width && Y >= 0 && Y < c->height))
            continue;
        const int v = (int)(columns ? X : Y);
        int b = 0;
        while (v >= cut[b + 1])
            b++;
        in[b]++;
        total++;
    }
    cr_assert_gt(total, 0);
    for (int k = 0; k < nb; k++) {
        const double share = (double)in[k] / (double)total;
        /* a quantile of 1024 samples is off by about 0.5/sqrt(1024) = 1.6 %
         * of the store; 5 % is three times that */
        const double asked = 1.0 / nb;
        cr_expect(fabs(share - asked) < 0.05, "%d bands by %s: band %d holds %.3f of the particles, not %.3f", nb,
                  columns ? "columns" : "rows", k, share, asked);
    }
}

static void steps(isk_effect *fx, int frames)
{
    for (int f = 0; f < frames; f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
}

/* The layer after `frames`, cut into 2..7 even bands (of columns or rows). */
static void even_bands_after(int frames, int columns)
{
    isk_effect *fx = scene_text_open(LAYER, 1);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 640, 480), ISK_OK);
    steps(fx, frames);
    for (int nb = 2; nb <= 7; nb++)
        check_shares(fx, &c, nb, columns);
    isk_canvas_free(&c);
    isk_effect_destroy(fx);
}

Test(band_cuts, a_falling_layer_is_cut_into_even_bands_of_rows)
{
    even_bands_after(5, 0);
}

Test(band_cuts, a_layer_settled_on_its_floor_is_cut_into_even_bands_of_columns)
{
    even_bands_after(240, 1);
}

/* The cuts are a function of the particles: the same state is cut the
 * same way every time, and a layer that may not take columns is cut into
 * rows. */
Test(band_cuts, the_cuts_depend_on_the_particles_alone)
{
    isk_effect *fx = scene_text_open(LAYER, 1);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 640, 480), ISK_OK);
    steps(fx, 240);
    int first[8], again[8], rows[8];
    for (int nb = 2; nb <= 7; nb++) {
        cr_assert_eq(isk__fx_place_cuts(fx, &fx->groups[0], &c, nb, 1, first), 1);
        for (int k = 0; k < 50; k++) {
            cr_assert_eq(isk__fx_place_cuts(fx, &fx->groups[0], &c, nb, 1, again), 1);
            cr_assert_arr_eq(first, again, (size_t)(nb + 1) * sizeof *first);
        }
        cr_assert_eq(isk__fx_place_cuts(fx, &fx->groups[0], &c, nb, 0, rows), 0);
        cr_assert_eq(rows[nb], 480);
    }
    isk_canvas_free(&c);
    isk_effect_destroy(fx);
}
