/* SPDX-License-Identifier: MIT */
/* src/view/world_batch.h — the batched store drawing of iskra/view.h,
 * restricted to a band of canvas rows (internal).
 *
 *     isk__draw_batch_rows(c, v, n, x, y, col, mode, ISK__BATCH_DOT, r0, r1);
 *
 * draws exactly the pixels of rows [r0, r1) that the whole batch would
 * draw, with the same bytes: every point is placed on the whole canvas and
 * only the blend is cut to the band.  Bands that cover the canvas, drawn
 * in any order or at the same time, therefore give the bytes of one call
 * (each pixel sees the same points in the same order): the renderer's
 * threads each take a band.  r0 and r1 are clamped to the canvas. */
#ifndef ISKRA_VIEW_WORLD_BATCH_H
#define ISKRA_VIEW_WORLD_BATCH_H

#include <stdint.h>

#include "iskra/view.h"

typedef enum isk__batch_rule {
    ISK__BATCH_DOT,         /* isk_draw_dots */
    ISK__BATCH_DOT_BROWSER, /* isk_draw_dots_browser */
    ISK__BATCH_PIXEL        /* isk_draw_pixels */
} isk__batch_rule;

/* Or-ed into the rule: a screen coordinate in (n - 1, n] (n the canvas's
 * width or height) is moved to n - 1 first, so a particle exactly on the
 * right or bottom edge is drawn in the last column or row instead of just
 * outside (isk__keep_on_canvas; the effects' particles use it). */
#define ISK__BATCH_KEEP_ON_CANVAS 0x100u

/* What ISK__BATCH_KEEP_ON_CANVAS does to one coordinate. */
static inline double isk__keep_on_canvas(double v, int n)
{
    return v > n - 1.0 && v <= (double)n ? n - 1.0 : v;
}

void isk__draw_batch_rows(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                          isk_color col, isk_blend mode, unsigned rule, int r0, int r1);

/* The same cut to the columns [c0, c1) too: a tile of a threaded draw
 * whose particles crowd into a few rows (a scene settled on its floor). */
void isk__draw_batch_tile(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y,
                          isk_color col, isk_blend mode, unsigned rule, int r0, int r1, int c0, int c1);

/* The same for the points list[0..m) only, in that order (a band's points,
 * which isk__batch_bin found). */
void isk__draw_batch_list_rows(isk_canvas *c, const isk_view *v, const uint32_t *list, size_t m, const double *x,
                               const double *y, isk_color col, isk_blend mode, unsigned rule, int r0, int r1);

/* ---- retained dots: a batch drawn again without its arithmetic ----------
 * While a batch draws it can record what it blended: each point's 2x2
 * block (its top-left pixel, whether it lies wholly on the tile) and its
 * four weights, in the order blended.  isk__draw_batch_replay then does
 * exactly those blends again, in that order, with any colour and blend
 * mode: the bytes of the batch drawn again, as long as the points, the
 * view, the canvas's size, the rule and the tile are what they were (an
 * effect's group at rest, effect_retain.c), at a quarter to a half of the
 * time.  Only the exact-area dot records; a point the single-dot kernel
 * must clip (partly off the canvas), or a batch of the browser's dots
 * (whose blocks cut by an edge, a band's too, are all clipped) or of single
 * pixels ends the recording as failed (it still draws). */
#define ISK__REC_FULL 0x8000u /* or-ed into iy: the block lies wholly on the tile */
typedef struct isk__dot_rec {
    uint16_t ix, iy; /* the block's top-left pixel (iy | ISK__REC_FULL) */
    uint8_t w[4];    /* its weights, row by row */
} isk__dot_rec;

typedef struct isk__dot_recording {
    isk__dot_rec *rec; /* room for every point the batch reads (n, or m of a list) */
    size_t n;          /* recorded so far */
    int failed;        /* a point the records cannot hold was drawn */
} isk__dot_recording;

/* isk__draw_batch_tile, of list[0..n) when list is not NULL (as
 * isk__draw_batch_list_rows), recording into *rec as it draws. */
void isk__draw_batch_record(isk_canvas *c, const isk_view *v, size_t n, const uint32_t *list, const double *x,
                            const double *y, isk_color col, isk_blend mode, unsigned rule, int r0, int r1, int c0,
                            int c1, isk__dot_recording *rec);
/* The recorded blends rec[0..n) on the tile [r0, r1) x [c0, c1) they were
 * recorded on. */
void isk__draw_batch_replay(isk_canvas *c, const isk__dot_rec *rec, size_t n, isk_color col, isk_blend mode, int r0,
                            int r1, int c0, int c1);

/* The points y[0..m) whose screen Y (isk_view_to_screen's, bit for bit)
 * lies strictly between lo and hi, NaN never: their places in oix and
 * their Y in oy, in order; returns how many.  Without branches (on a band
 * of a threaded draw most points may be another band's, in an order no
 * predictor learns): the dots' own select, the widest build the CPU has.
 * oy and oix hold m entries each, rounded up to a multiple of 8 (the
 * vector builds store whole groups past the last point kept). */
int isk__batch_select_rows(const isk_view *v, const double *y, int m, double lo, double hi, double *oy,
                           int32_t *oix);

/* ---- binning a batch by bands of rows (a threaded draw) ------------------
 * So that a band's thread reads only its own points, the points are first
 * sorted into bands (stably: each band keeps index order).  A point goes to
 * every band holding one of the rows floor(Y) - reach .. floor(Y) + reach
 * (Y its screen row, the kernels' arithmetic; reach: the rows beyond its
 * own that the point's draw may touch, as its draw kind declares it), so
 * the draw's own row test, run again on the band, decides exactly as on
 * the whole batch, and the bytes are the same.  band_of_row[r] is the band
 * of canvas row r (bands in row order, at most 255 of them).  code[i] gets
 * first | last << 8, the bands the point goes to, or ISK__BIN_NONE;
 * count[b] grows by the points band b gets. */
#define ISK__BIN_NONE 0xFFFFu
/* The rows beyond its own (floor of its screen Y) that a dot of any rule
 * or a pixel may touch: floor(Y) + 1, and a row spare (their draw kinds'
 * reach). */
#define ISK__DOT_REACH 2
void isk__batch_bin(const isk_view *v, int height, const double *y, size_t i0, size_t i1, int reach,
                    const uint8_t *band_of_row, uint16_t *code, size_t *count);

#endif
