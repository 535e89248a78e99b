/* The placed draw (see world_place.h): records from a store, then blends
 * from records.  The arithmetic is view/dot_block.h's, as in the one-pass
 * batch (world_batch.c), so the bytes are the same. */
#include "view/world_place.h"

#include <stdlib.h>

#include "view/dot_block.h"
#include "view/world_batch.h"

/* A record's low word: the pixel's byte offset, or SLOW; its high word:
 * the four weights (w0 in the low byte), or a slow record's point. */
#define SLOW 0x80000000u
/* Records ahead whose pixels the blend prefetches. */
#define BLEND_AHEAD 16

int isk__place_fits(const isk_canvas *c, size_t n)
{
    if (!c || c->width < 1 || c->height < 1 || n > UINT32_MAX)
        return 0;
    /* the last row's last pixel, whole */
    const size_t rows = (size_t)c->height - 1, end = (size_t)c->width * 4u;
    return c->stride <= (SIZE_MAX - end) / (rows ? rows : 1) && rows * c->stride + end <= SLOW;
}

void isk__place_bucket_free(isk__place_bucket *b)
{
    free(b->rec);
    b->rec = NULL;
    b->n = b->cap = 0;
}

/* Out of line: a bucket grows a few times in its first frames, then never. */
static __attribute__((noinline)) int grow(isk__place_bucket *b)
{
    size_t cap = b->cap ? b->cap * 2 : 4096;
    if (cap < b->cap || cap > SIZE_MAX / sizeof *b->rec)
        return 0;
    uint64_t *r = realloc(b->rec, cap * sizeof *r);
    if (!r)
        return 0;
    b->rec = r;
    b->cap = cap;
    return 1;
}

static ISK__INLINE int push(isk__place_bucket *b, uint64_t r)
{
    if (b->n == b->cap && !grow(b))
        return 0;
    b->rec[b->n++] = r;
    return 1;
}

/* The screen point of particle i, as the batch computes it (select's Y,
 * the block's X; isk_view_to_screen's operations in its order). */
static void screen_xy(const isk__place *pl, size_t i, double *X, double *Y)
{
    const isk_view *v = pl->v;
    const double x = pl->x[i], y = pl->y[i];
    if (v->kind == ISK_VIEW_CAMERA) {
        *X = v->width / 2.0 + v->a * (x + v->tx);
        *Y = v->height / 2.0 - v->a * (y + v->ty);
    } else {
        *X = v->sx * x + v->px;
        *Y = v->sy * y + v->py;
    }
    if (pl->rule & ISK__BATCH_KEEP_ON_CANVAS) {
        *X = isk__keep_on_canvas(*X, pl->c->width);
        *Y = isk__keep_on_canvas(*Y, pl->c->height);
    }
}

/* ---- step 1 ---------------------------------------------------------------- */

/* A slow record in every band holding one of the rows floor(Y) - 1 ..
 * floor(Y) + 2: a superset of the rows either dot rule touches, so the
 * clipping kernel's own row test decides, as in the one-pass batch. */
static int push_slow(const isk__place *pl, isk__place_bucket *out, size_t i, double Y)
{
    const int H = pl->c->height, fy = isk__ifloor(Y); /* Y in (-2, H + 1): select kept it */
    const int lo = fy - 1 < 0 ? 0 : fy - 1, hi = fy + 2 >= H ? H - 1 : fy + 2;
    for (unsigned b = pl->band_of_row[lo]; b <= pl->band_of_row[hi]; b++)
        if (!push(&out[b], SLOW | (uint64_t)i << 32))
            return 0;
    return 1;
}

static ISK__INLINE int place_dots(const isk__place *pl, size_t i0, size_t i1, isk__place_bucket *out, int browser)
{
    const isk_canvas *c = pl->c;
    const isk_view *v = pl->v;
    const int camera = v->kind == ISK_VIEW_CAMERA, keep = (pl->rule & ISK__BATCH_KEEP_ON_CANVAS) != 0;
    const double hw = v->width / 2.0, a = v->a, tx = v->tx, sx = v->sx, px = v->px;
    const int H = c->height;
    /* the single-dot kernels' own first tests: a point outside them draws
     * nothing, so it is dropped here (also NaN) */
    const double lo = browser ? -2.0 : -1.0, xhi = browser ? c->width + 1.0 : (double)c->width;
    const double yhi = browser ? H + 1.0 : (double)H;
    const select_view sv = {camera, keep, v->height / 2.0, a, v->ty, v->sy, v->py, lo, yhi, H};
    const weights_fn weights = pick_weights(browser);
    const select_fn select = pick_select();
    const uint8_t *const band = pl->band_of_row;
    const size_t stride = c->stride;
    dot_block b;
    int32_t at[DOT_BLOCK];
    for (size_t s = i0; s < i1; s += DOT_BLOCK) {
        const int m = i1 - s < DOT_BLOCK ? (int)(i1 - s) : DOT_BLOCK;
        dot_block_prefetch_ahead(pl->x, pl->y, s, i1);
        const int sel = select(&sv, pl->y + s, m, b.y, b.ix);
        int kept = 0;
        for (int k = 0; k < sel; k++) { /* without a branch: the same shape for any scene */
            const double xi = pl->x[s + (size_t)b.ix[k]];
            const double X0 = camera ? hw + a * (xi + tx) : sx * xi + px;
            const double X = keep ? isk__keep_on_canvas(X0, c->width) : X0;
            b.x[kept] = X;
            b.y[kept] = b.y[k];
            at[kept] = b.ix[k];
            kept += (X > lo) & (X < xhi);
        }
        weights(&b, kept, c->width - 1.0, 0.0, H - 1.0);
        for (int k = 0; k < kept; k++) {
            if (b.fast[k]) {
                const unsigned bt = band[b.iy[k]];
                if (bt == band[b.iy[k] + 1]) {
                    uint32_t w;
                    memcpy(&w, b.w[k], 4);
                    const size_t off = (size_t)b.iy[k] * stride + (size_t)b.ix[k] * 4u;
                    if (!push(&out[bt], (uint64_t)off | (uint64_t)w << 32))
                        return 0;
                    continue;
                }
            }
            if (!push_slow(pl, out, s + (size_t)at[k], b.y[k]))
                return 0;
        }
    }
    return 1;
}

/* Pixels: the batch's in-canvas test, one row each (never slow). */
static int place_pixels(const isk__place *pl, size_t i0, size_t i1, isk__place_bucket *out)
{
    const isk_canvas *c = pl->c;
    const double W = c->width, H = c->height;
    for (size_t i = i0; i < i1; i++) {
        double X, Y;
        screen_xy(pl, i, &X, &Y);
        if (X >= 0 && Y >= 0 && X < W && Y < H) {
            const size_t off = (size_t)(int)Y * c->stride + (size_t)(int)X * 4u;
            if (!push(&out[pl->band_of_row[(int)Y]], off))
                return 0;
        }
    }
    return 1;
}

int isk__place_share(const isk__place *pl, size_t i0, size_t i1, isk__place_bucket *out)
{
    for (int k = 0; k < pl->nb; k++)
        out[k].n = 0;
    switch (pl->rule & ~ISK__BATCH_KEEP_ON_CANVAS) {
    case ISK__BATCH_DOT: return place_dots(pl, i0, i1, out, 0);
    case ISK__BATCH_DOT_BROWSER: return place_dots(pl, i0, i1, out, 1);
    case ISK__BATCH_PIXEL: return place_pixels(pl, i0, i1, out);
    default: return 1; /* an unknown rule draws nothing, as in the batch */
    }
}

/* ---- step 2 ---------------------------------------------------------------- */

/* A slow record: the point drawn by the clipping kernel, cut to the band. */
static __attribute__((noinline)) void blend_slow(const isk__place *pl, isk_canvas *c, const isk__cov_lut *lut,
                                                 isk_color col, int r0, int r1, size_t i, int browser,
                                                 isk_blend mode)
{
    double X, Y;
    screen_xy(pl, i, &X, &Y);
    if (browser)
        ISK__BLEND_DISPATCH(mode, isk__dot_browser_rows, c, r0, r1, X, Y, col, lut);
    else
        ISK__BLEND_DISPATCH(mode, isk__dot_rows, c, r0, r1, X, Y, col, lut);
}

static ISK__INLINE void blend_bucket(const isk__place *pl, isk_canvas *c, const isk__cov_lut *lut, isk_color col,
                                     int r0, int r1, const isk__place_bucket *q, int kind, isk_blend mode)
{
    uint8_t *const pixels = c->pixels;
    const size_t stride = c->stride, n = q->n;
    const uint64_t *const r = q->rec;
    for (size_t k = 0; k < n; k++) {
#if defined(__GNUC__)
        if (k + BLEND_AHEAD < n && !(r[k + BLEND_AHEAD] & SLOW)) {
            const uint8_t *p = pixels + (uint32_t)r[k + BLEND_AHEAD];
            __builtin_prefetch(p, 1);
            if (kind != ISK__BATCH_PIXEL)
                __builtin_prefetch(p + stride, 1);
        }
#endif
        const uint64_t e = r[k];
        if (e & SLOW) {
            blend_slow(pl, c, lut, col, r0, r1, (size_t)(e >> 32), kind == ISK__BATCH_DOT_BROWSER, mode);
            continue;
        }
        uint8_t *p = pixels + (uint32_t)e;
        if (kind == ISK__BATCH_PIXEL) {
            isk__px_lut(p, lut, 255, mode);
        } else {
            const uint32_t w = (uint32_t)(e >> 32);
            px2(p, col, lut, w & 255u, (w >> 8) & 255u, mode);
            px2(p + stride, col, lut, (w >> 16) & 255u, w >> 24, mode);
        }
    }
}

static ISK__INLINE void blend_all(const isk__place *pl, isk_canvas *c, const isk__cov_lut *lut, isk_color col,
                                  int r0, int r1, const isk__place_bucket *const *buckets, int nbuckets,
                                  isk_blend mode)
{
    const unsigned kind = pl->rule & ~ISK__BATCH_KEEP_ON_CANVAS;
    for (int k = 0; k < nbuckets; k++) {
        if (kind == ISK__BATCH_DOT)
            blend_bucket(pl, c, lut, col, r0, r1, buckets[k], ISK__BATCH_DOT, mode);
        else if (kind == ISK__BATCH_DOT_BROWSER)
            blend_bucket(pl, c, lut, col, r0, r1, buckets[k], ISK__BATCH_DOT_BROWSER, mode);
        else if (kind == ISK__BATCH_PIXEL)
            blend_bucket(pl, c, lut, col, r0, r1, buckets[k], ISK__BATCH_PIXEL, mode);
    }
}

void isk__place_blend(const isk__place *pl, isk_canvas *c, isk_color col, isk_blend mode, int r0, int r1,
                      const isk__place_bucket *const *buckets, int nbuckets)
{
    if (!c)
        return;
    r0 = r0 < 0 ? 0 : r0;
    r1 = r1 > c->height ? c->height : r1;
    if (!c->pixels || r0 >= r1) /* an empty band draws nothing (the kernels need a row) */
        return;
    isk__cov_lut lut;
    isk__cov_lut_init(&lut, col);
    ISK__BLEND_DISPATCH(mode, blend_all, pl, c, &lut, col, r0, r1, buckets, nbuckets);
}
