/* SPDX-License-Identifier: MIT */
/* The threaded draw of an additive group (ISK_BLEND_ADD) by shares of its
 * particles instead of bands of the canvas (effect_bands.c's
 * split_particles): each thread draws its share onto a zeroed canvas of its
 * own, and the copies are added into the canvas after.  What a particle
 * adds to a pixel does not depend on the pixel, and saturating adds of
 * non-negative amounts give min(255, the sum) in any grouping, so the bytes
 * are one thread's (threads_check runs every scene both ways).  Checked
 * here: which groups are split, that saturated pixels and a canvas with
 * bytes between its rows (a wrapped buffer's stride) come out as on one
 * thread, and that those bytes are left alone. */
#include <criterion/criterion.h>
#include "fast_paths_skip.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/canvas.h"
#include "scene/effect_internal.h"
#include "scene_text.h"

/* The draws split on two threads at the last of `steps` steps and renders
 * of the scene `text`. */
static long splits_of(const char *text, int steps)
{
    isk_effect *fx = scene_text_open(text, 2);
    fx->no_retain = 1; /* at rest its blends would be replayed instead (test_retain.c) */
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, fx->def.width, fx->def.height), ISK_OK);
    long before = 0;
    for (int s = 0; s < steps; s++) {
        before = fx->bins.splits;
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        cr_assert_eq(isk_effect_render(fx, &c), ISK_OK);
    }
    const long n = fx->bins.splits - before;
    isk_canvas_free(&c);
    isk_effect_destroy(fx);
    return n;
}

#define SCENE "[scene]\nwidth = 200\nheight = 150\n[emitter e]\nsource = explosion\nexplosion = gauss\n"

/* Additive dots are split where their bands would be columns (a layer on
 * its floor), and stay in bands of rows while it falls; sprites and discs,
 * whose bands are always rows, are never split. */
#define LAYER(draw, blend)                                                                                  \
    "[scene]\nwidth = 640\nheight = 480\n[force gravity]\ng = 400\n[bounds]\nrestitution = 0.2\n"          \
    "[emitter a]\nsource = layer\ncount = 60000\nlimit = 60000\nrect = -9, 9, -9, 9\nforces = gravity\n"   \
    "draw = " draw "\nsize = 0.2\nblend = " blend "\n"

Test(band_split, additive_dots_are_split_where_their_bands_would_be_columns)
{
    SKIP_WITHOUT(ISK__FAST_BANDS, "draws split among the workers");
    cr_expect_eq(splits_of(LAYER("dot", "add"), 5), 0);
    cr_expect_eq(splits_of(LAYER("dot", "add"), 240), 1);
    cr_expect_eq(splits_of(LAYER("dot", "over"), 240), 0);
    cr_expect_eq(splits_of(LAYER("sprite", "add"), 240), 0);
    cr_expect_eq(splits_of(LAYER("disc", "add"), 240), 0);
}

/* A 200 x 150 canvas over a buffer whose rows lie `pad` bytes apart beyond
 * their pixels, the padding filled with 0xA5. */
static uint8_t *padded_canvas(isk_canvas *c, size_t pad)
{
    const size_t stride = 200 * 4 + pad;
    uint8_t *buf = malloc(stride * 150);
    cr_assert_not_null(buf);
    memset(buf, 0xA5, stride * 150);
    cr_assert_eq(isk_canvas_wrap(c, buf, 200, 150, stride), ISK_OK);
    return buf;
}

/* Bright sprites and dots piled on one place (most pixels saturate), drawn
 * on one thread and split on two and three, into a padded canvas. */
Test(band_split, saturated_pixels_and_a_padded_canvas_come_out_as_on_one_thread)
{
    SKIP_WITHOUT(ISK__FAST_BANDS, "draws split among the workers");
    const char *text = SCENE "count = 20000\nlimit = 20000\ndraw = sprite\nsize = 1.5\n"
                             "blend = add\ncolor = #ffc040ff\n"
                             "[emitter d]\nsource = explosion\nexplosion = uniform\ncount = 20000\nlimit = 20000\n"
                             "blend = add\ncolor = #40ff80ff\n";
    isk_canvas one;
    uint8_t *one_buf = padded_canvas(&one, 36);
    isk_effect *fx = scene_text_open(text, 1);
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_render(fx, &one), ISK_OK);
    isk_effect_destroy(fx);
    int saturated = 0;
    for (int y = 0; y < 150; y++)
        for (int x = 0; x < 200; x++)
            saturated += one.pixels[(size_t)y * one.stride + 4u * (size_t)x] == 255 ||
                         one.pixels[(size_t)y * one.stride + 4u * (size_t)x + 1] == 255;
    cr_assert_gt(saturated, 100, "the check needs saturated pixels: %d", saturated);
    for (int threads = 2; threads <= 3; threads++) {
        isk_canvas c;
        uint8_t *buf = padded_canvas(&c, 36);
        fx = scene_text_open(text, threads);
        fx->band_min_work = 0;
        fx->split_always = 1;
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        cr_assert_eq(isk_effect_render(fx, &c), ISK_OK);
        cr_expect_eq(fx->bins.splits, 2, "%d threads: both groups split", threads);
        isk_effect_destroy(fx);
        /* every byte, the padding's included */
        cr_expect_eq(memcmp(buf, one_buf, c.stride * 150), 0, "%d threads: other bytes", threads);
        free(buf);
    }
    free(one_buf);
}
