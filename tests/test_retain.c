/* SPDX-License-Identifier: MIT */
/* Retained dots: a group at rest drawn again from its recorded blends
 * (effect_retain.c, view/world_batch.h's isk__draw_batch_record and
 * isk__draw_batch_replay).
 *
 * The kernels: points recorded on a tile and replayed, in another colour
 * and blend mode, give the bytes of drawing them in full; a point that is
 * partly off the canvas ends the recording.
 *
 * The effect: two layers that settle on their floor (one over, one adding;
 * a third of the browser's dots, never recorded), the floor on the
 * canvas's last row or inside the view, drawn every frame against the same effect with
 * retention off, on 1, 2, 3 and 7 threads, the same bytes every frame,
 * through everything that must make the records stale (the view moves, by
 * a live edit or by its owner, a particle is written and forgotten, the
 * thread count changes, a wind lifts the layers off the floor) or must not
 * (a canvas whose rows lie further apart).  The records are replayed
 * only while every block rests, and only draws at rest record. */
#include <criterion/criterion.h>
#include "fast_paths_skip.h"

#include <stdlib.h>
#include <string.h>

#include "iskra/canvas.h"
#include "iskra/rng.h"
#include "iskra/view.h"
#include "scene/effect_internal.h"
#include "scene_text.h"
#include "view/world_batch.h"

enum { W = 97, H = 61, N = 3000 };

/* N points on the canvas (edge: some kept on its last row, their blocks
 * cut by the edge), or one partly off it. */
static void points(isk_rng *r, double *x, double *y, int edge, int off)
{
    for (int i = 0; i < N; i++) {
        x[i] = isk_rng_uniform(r) * (W - 1.0);
        y[i] = isk_rng_uniform(r) * (H - 1.0);
        if (i % 7 == 0 && edge)
            y[i] = H - 1.0 + 0.5 * isk_rng_uniform(r); /* kept on the last row */
        if (off && i == N / 2)
            x[i] = -0.5; /* its block's left column is off the canvas */
    }
}

static const isk_color COLORS[] = {{255, 200, 120, 160}, {30, 250, 90, 255}, {255, 255, 255, 40}};
static const isk_blend MODES[] = {ISK_BLEND_OVER, ISK_BLEND_ADD, ISK_BLEND_REPLACE};

Test(retain, replays_give_the_bytes_of_full_draws)
{
    SKIP_WITHOUT(ISK__FAST_RETAIN, "replays of a group at rest");
    isk_rng r;
    isk_rng_seed(&r, 5);
    isk_view v;
    cr_assert_eq(isk_view_window(&v, W, H, 0, W, 0, H), ISK_OK);
    double *x = malloc(N * sizeof *x), *y = malloc(N * sizeof *y);
    isk__dot_rec *rec = malloc(N * sizeof *rec);
    cr_assert(x && y && rec);
    isk_canvas full, again;
    cr_assert_eq(isk_canvas_init(&full, W, H), ISK_OK);
    cr_assert_eq(isk_canvas_init(&again, W, H), ISK_OK);
    /* the whole canvas, a band of rows, a band of columns */
    const int tiles[][4] = {{0, H, 0, W}, {17, 40, 0, W}, {0, H, 31, 64}};
    for (int round = 0; round < 20; round++) {
        const unsigned rule = ISK__BATCH_DOT | (round % 2 ? ISK__BATCH_KEEP_ON_CANVAS : 0u);
        points(&r, x, y, round % 2, 0);
        const int *t = tiles[round % 3];
        const size_t n = round == 19 ? 40 : N; /* below the coverage table's batch */
        isk__dot_recording rd = {rec, 0, 0};
        isk_canvas_fill(&full, (isk_color){10, 20, 30, 255});
        isk__draw_batch_record(&full, &v, n, NULL, x, y, COLORS[0], ISK_BLEND_OVER, rule, t[0], t[1], t[2], t[3], &rd);
        cr_assert_eq(rd.failed, 0, "round %d", round);
        cr_assert_gt(rd.n, 0);
        for (int k = 0; k < 3; k++) { /* another colour and mode, from the same records */
            isk_canvas_fill(&full, (isk_color){10, 20, 30, k == 2 ? 0 : 255});
            memcpy(again.pixels, full.pixels, (size_t)full.stride * H);
            isk__draw_batch_tile(&full, &v, n, x, y, COLORS[k], MODES[k], rule, t[0], t[1], t[2], t[3]);
            isk__draw_batch_replay(&again, rec, rd.n, COLORS[k], MODES[k], t[0], t[1], t[2], t[3]);
            cr_assert(!memcmp(full.pixels, again.pixels, (size_t)full.stride * H), "round %d, mode %d", round, k);
        }
    }
    /* partly off the canvas, or the browser's dots (whose blocks cut by an
     * edge are clipped): the clipping kernel's, not recorded */
    points(&r, x, y, 1, 0);
    isk__dot_recording edge = {rec, 0, 0};
    isk__draw_batch_record(&full, &v, N, NULL, x, y, COLORS[0], ISK_BLEND_OVER, ISK__BATCH_DOT_BROWSER, 0, H, 0, W,
                           &edge);
    cr_assert_eq(edge.failed, 1);
    points(&r, x, y, 1, 1);
    isk__dot_recording rd = {rec, 0, 0};
    isk__draw_batch_record(&full, &v, N, NULL, x, y, COLORS[0], ISK_BLEND_OVER, ISK__BATCH_DOT, 0, H, 0, W, &rd);
    cr_assert_eq(rd.failed, 1);
    /* single pixels are not recorded either */
    rd = (isk__dot_recording){rec, 0, 0};
    points(&r, x, y, 1, 0);
    isk__draw_batch_record(&full, &v, N, NULL, x, y, COLORS[0], ISK_BLEND_OVER, ISK__BATCH_PIXEL, 0, H, 0, W, &rd);
    cr_assert_eq(rd.failed, 1);
    isk_canvas_free(&full);
    isk_canvas_free(&again);
    free(x);
    free(y);
    free(rec);
}

/* The walls on the view's edges (the layers rest on the canvas's last row,
 * kept on it: their blocks cut by the edge), or a floor inside the view
 * (their blocks wholly on the canvas, over two rows). */
#define SCENE(bounds)                                                                                         \
    "[scene]\nwidth = 160\nheight = 120\n[view]\nxmin = -4\nxmax = 4\nymin = -3\nymax = 3\n"                 \
    "[force gravity]\ng = 9.81\n[force drag]\nkind = drag\nb = 0.4\n[force lift]\nkind = wind\n"             \
    "[bounds]\nmode = reflect\nsides = all\nrestitution = 0.3\n" bounds                                    \
    "[emitter layer]\nsource = layer\ncount = 3000\nrect = -3.9, 3.9, -2.3, -1\n"           \
    "forces = gravity, drag, lift\ndraw = dot\ncolor = #ffc878a0\n"                                          \
    "[emitter glow]\nsource = layer\ncount = 2000\nrect = -3.9, 3.9, -1, 2.9\n"                             \
    "forces = gravity, drag, lift\ndraw = dot\nblend = add\ncolor = #20100840\n"                             \
    "[emitter sparks]\nsource = layer\ncount = 500\nrect = -3.9, 3.9, -1, 2.9\n"                             \
    "forces = gravity, drag, lift\ndraw = dot-browser\ncolor = #ff304080\n"

static void set_both(isk_effect *a, isk_effect *b, const char *section, const char *key, const char *value)
{
    isk_error err;
    cr_assert_eq(isk_effect_set(a, section, key, value, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_set(b, section, key, value, &err), ISK_OK, "%s", err.message);
}

static long records(const isk_effect *e)
{
    return e->groups[0].retained.records + e->groups[1].retained.records;
}

static long replays(const isk_effect *e)
{
    return e->groups[0].retained.replays + e->groups[1].retained.replays;
}

static const char *const SCENES[] = {SCENE(""), SCENE("window = -4, 4, -2.43, 3\n")};

Test(retain, groups_at_rest_give_the_bytes_of_full_draws)
{
    SKIP_WITHOUT(ISK__FAST_RETAIN, "replays of a group at rest");
    static const int counts[] = {1, 2, 3, 7};
    for (int t = 0; t < 8; t++) {
        const int threads = counts[t % 4];
        const char *scene = SCENES[t / 4];
        isk_effect *a = scene_text_open(scene, threads), *b = scene_text_open(scene, threads);
        b->no_retain = 1;
        a->band_min_work = b->band_min_work = 0; /* every draw in bands, however small */
        isk_canvas ca, cb, wide_a, wide_b; /* wide: rows 20 bytes apart beyond their pixels */
        enum { STRIDE = 160 * 4 + 20 };
        uint8_t *buf_a = calloc(STRIDE, 120), *buf_b = calloc(STRIDE, 120);
        cr_assert(buf_a && buf_b);
        cr_assert_eq(isk_canvas_init(&ca, 160, 120), ISK_OK);
        cr_assert_eq(isk_canvas_init(&cb, 160, 120), ISK_OK);
        cr_assert_eq(isk_canvas_wrap(&wide_a, buf_a, 160, 120, STRIDE), ISK_OK);
        cr_assert_eq(isk_canvas_wrap(&wide_b, buf_b, 160, 120, STRIDE), ISK_OK);
        long replays_moving = -1, records_before_colour = -1;
        for (int frame = 1; frame <= 760; frame++) {
            cr_assert_eq(isk_effect_step(a), ISK_OK);
            cr_assert_eq(isk_effect_step(b), ISK_OK);
            if (frame < 300 && frame % 20) /* falling and settling: some frames drawn */
                continue;
            if (frame > 430 && frame < 440) /* the written particle's block wakes and rests again unseen */
                continue;
            if (frame == 425) /* the view moved by its owner, with no live edit */
                a->view.px += 0.25, b->view.px += 0.25;
            const int wide = frame >= 440 && frame < 450; /* the records hold pixels, not offsets */
            isk_canvas *pa = wide ? &wide_a : &ca, *pb = wide ? &wide_b : &cb;
            cr_assert_eq(isk_effect_render(a, pa), ISK_OK);
            cr_assert_eq(isk_effect_render(b, pb), ISK_OK);
            cr_assert(!memcmp(pa->pixels, pb->pixels, (size_t)pa->stride * (size_t)pa->height),
                      "scene %d, %d threads, frame %d: the canvases differ", t / 4, threads, frame);
            if (frame == 20)
                replays_moving = replays(a);
            if (frame == 430) { /* a particle written, and forgotten, as every writer must */
                for (isk_effect *e = a; e; e = e == a ? b : NULL) { /* to the floor's bare left end */
                    const size_t last = e->groups[0].store.count - 1;
                    e->groups[0].store.x[last] = -3.98;
                    isk__rest_forget(&e->groups[0].rest, last);
                }
            }
            if (frame == 440)
                cr_assert(isk__rest_all(&a->groups[0].rest, a->groups[0].store.count), "at rest again");
            if (frame == 400) {
                cr_assert(isk__rest_all(&a->groups[0].rest, a->groups[0].store.count), "the layer rests");
                cr_assert(isk__rest_all(&a->groups[1].rest, a->groups[1].store.count), "the glow rests");
                cr_assert_gt(replays(a), 40, "%d threads: %ld replays", threads, replays(a));
                cr_assert_eq(records(a), 2, "one record each since they rest: %ld", records(a));
                set_both(a, b, "view", "xmin", "-4.1"); /* the view moves: recorded again */
            }
            if (frame == 420)
                cr_assert_eq(records(a), 4, "%ld", records(a));
            if (frame == 460) { /* the view: once more each, the layer's written particle (once its
                                   block rests again): once more; another canvas: the same records */
                cr_assert_eq(records(a), 7, "%ld", records(a));
                records_before_colour = records(a);
                set_both(a, b, "emitter layer", "color", "#20ff40ff");
            }
            if (frame == 470) {
                /* a live edit recompiles: what rested is forgotten, recorded again */
                cr_assert_gt(records(a), records_before_colour, "%ld", records(a));
                records_before_colour = records(a);
                cr_assert_eq(isk_effect_set_threads(a, threads == 1 ? 2 : 1), ISK_OK);
                cr_assert_eq(isk_effect_set_threads(b, threads == 1 ? 2 : 1), ISK_OK);
            }
            if (frame == 480) {
                cr_assert_eq(records(a), records_before_colour + 2, "%ld", records(a));
                set_both(a, b, "force lift", "acceleration", "0, 25"); /* off the floor */
            }
            if (frame == 500)
                cr_assert(!isk__rest_all(&a->groups[0].rest, a->groups[0].store.count), "lifted, it moves");
        }
        cr_assert_eq(replays_moving, 0, "nothing rests while it falls");
        cr_assert_gt(records(a), records_before_colour + 2, "at rest on the ceiling: recorded again");
        cr_assert_eq(replays(b), 0);
        isk_canvas_free(&ca);
        isk_canvas_free(&cb);
        free(buf_a);
        free(buf_b);
        isk_effect_destroy(a);
        isk_effect_destroy(b);
    }
}
