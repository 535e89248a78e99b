/* SPDX-License-Identifier: MIT */
/* Where the threaded draw cuts the canvas (effect_bands.c's
 * fx_place_cuts): at the quantiles of a sample of the particles' screen
 * rows, or of their columns when the particles crowd into a few rows.  The
 * cuts never change a byte (threads_check shows that); what they are for is
 * sharing the work evenly, and that is what is checked here: every band
 * holds its share of the whole store, within what a sample of 1024 allows.
 * A sort of the sample that got the order wrong would put the cuts
 * anywhere.  The shares (fx_shares: a band on a slower core gets fewer
 * particles) move the cuts, and follow the bands' times. */
#include <criterion/criterion.h>

#include <math.h>

#include "iskra/canvas.h"
#include "iskra/view.h"
#include "scene/effect_internal.h"
#include "scene_text.h"
#include "sim/pool.h"
#include "view/world_batch.h"

/* A layer filling a 640 x 480 view (rows and columns past 255, so both
 * digits of the sort count) in a box with a floor. */
static const char *LAYER = "[scene]\nwidth = 640\nheight = 480\n[force gravity]\ng = 400\n"
                           "[bounds]\nrestitution = 0.2\n"
                           "[emitter a]\nsource = layer\ncount = 60000\nlimit = 60000\nrect = -9, 9, -9, 9\n"
                           "forces = gravity\n";

/* Each band's share of the store's particles drawn on the canvas (by
 * their row, or column), against the shares asked for (NULL: 1/nb). */
static void check_shares(isk_effect *fx, const isk_canvas *c, int nb, int columns_expected, const fx_shares *want)
{
    const fx_group *g = &fx->groups[0];
    int cut[ISK_POOL_MAX_THREADS + 1];
    const int columns = fx_place_cuts(fx, g, c, nb, FX_BANDS_COLUMNS, want, cut);
    cr_assert_eq(columns, columns_expected, "%d bands: columns %d", nb, columns);
    const int n = columns ? c->width : c->height;
    cr_assert_eq(cut[0], 0);
    cr_assert_eq(cut[nb], n);
    for (int k = 0; k < nb; k++)
        cr_assert_leq(cut[k], cut[k + 1], "%d bands: cut %d", nb, k);
    size_t in[ISK_POOL_MAX_THREADS] = {0}, total = 0;
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
        const double asked = want ? want->share[k] : 1.0 / nb;
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
        check_shares(fx, &c, nb, columns, NULL);
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

/* Uneven shares (a band on a slower core gets fewer particles) move the
 * cuts, of rows and of columns alike. */
Test(band_cuts, the_cuts_follow_the_shares)
{
    isk_effect *fx = scene_text_open(LAYER, 1);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 640, 480), ISK_OK);
    fx_shares rows = {.nb = 3, .columns = 0, .share = {0.2, 0.5, 0.3}};
    fx_shares cols = {.nb = 2, .columns = 1, .share = {0.7, 0.3}};
    steps(fx, 5);
    check_shares(fx, &c, 3, 0, &rows);
    steps(fx, 235);
    check_shares(fx, &c, 2, 1, &cols);
    /* shares for the other kind of band, or another count, are not used */
    fx_shares other = {.nb = 2, .columns = 0, .share = {0.7, 0.3}};
    check_shares(fx, &c, 2, 1, NULL);
    int cut[3], even[3];
    fx_place_cuts(fx, &fx->groups[0], &c, 2, FX_BANDS_COLUMNS, &other, cut);
    fx_place_cuts(fx, &fx->groups[0], &c, 2, FX_BANDS_COLUMNS, NULL, even);
    cr_expect_eq(cut[1], even[1]);
    isk_canvas_free(&c);
    isk_effect_destroy(fx);
}

/* The shares move half-way toward each band's rate after every draw: with
 * bands that draw at fixed speeds, toward times that are equal. */
Test(band_cuts, the_shares_move_toward_equal_times)
{
    fx_shares s = {0};
    const double same[2] = {0.004, 0.004};
    fx_shares_update(&s, 2, 0, same);
    cr_assert_eq(s.nb, 2);
    cr_expect_float_eq(s.share[0], 0.5, 1e-12);
    /* band 1 three times slower: 0.5 (0.5 + 0.25) = 0.375 after one draw */
    const double slower[2] = {0.002, 0.006};
    fx_shares_update(&s, 2, 0, slower);
    cr_expect_float_eq(s.share[1], 0.375, 1e-12);
    cr_expect_float_eq(s.share[0] + s.share[1], 1.0, 1e-12);
    /* band k's time is its share over its speed (1 and 1/3): the shares
     * settle where the times are equal, 3/4 and 1/4 */
    for (int i = 0; i < 60; i++) {
        const double t[2] = {s.share[0] / 1.0, s.share[1] / (1.0 / 3.0)};
        fx_shares_update(&s, 2, 0, t);
    }
    cr_expect_float_eq(s.share[0], 0.75, 1e-6);
    /* a band that stalls keeps at least a quarter of its even share */
    const double stalled[2] = {0.001, 10.0};
    for (int i = 0; i < 20; i++)
        fx_shares_update(&s, 2, 0, stalled);
    cr_expect_geq(s.share[1], 0.125 - 1e-12);
    /* another count or kind of band starts from even; too many: none */
    const double four[4] = {0.001, 0.001, 0.001, 0.001};
    fx_shares_update(&s, 4, 1, four);
    cr_expect_eq(s.columns, 1);
    cr_expect_float_eq(s.share[3], 0.25, 1e-12);
    double many[FX_SHARES_MAX + 1];
    for (int k = 0; k <= FX_SHARES_MAX; k++)
        many[k] = 0.001;
    fx_shares_update(&s, FX_SHARES_MAX + 1, 0, many);
    cr_expect_eq(s.nb, 0);
}
