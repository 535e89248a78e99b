/* src/view/world_place.h — the batched dot and pixel draws of a particle
 * store split in two steps, so that threads can share both (internal).
 *
 *   1. place: a thread takes a share of the points (a range of indices)
 *      and turns each point into an 8-byte record: the offset of its pixel
 *      (the top-left one of a dot's 2x2 block) and its four weights,
 *      appended to the bucket of the band of rows the record lies in.  A
 *      dot near the canvas's edges, or one whose block straddles two bands,
 *      becomes a "slow" record naming the point, in every band it may
 *      touch; the blend then draws it with the clipping single-dot kernel.
 *   2. blend: a thread takes a band and blends its bucket of every share,
 *      share after share.
 *
 * Shares are ranges in index order and a bucket keeps its share's order,
 * so every pixel sees the same points in the same order as in the one-pass
 * batch (world_batch.h): the bytes are isk__draw_batch_rows's for every
 * choice of shares and bands.  What the split buys: the place step reads
 * the store and never the canvas, so it shares out evenly by points; the
 * blend step reads only records and its own rows, which stay in its core's
 * cache; and no point's arithmetic is done twice, as it is when every band
 * scans the whole store.
 *
 *     isk__place pl = {c, v, x, y, rule, nb, band_of_row};
 *     if (isk__place_fits(c, n)) {
 *         isk__place_share(&pl, 0, n / 2, bucket[0]);    // on two threads,
 *         isk__place_share(&pl, n / 2, n, bucket[1]);    // each its share
 *         ...then for each band k, on any thread:
 *         const isk__place_bucket *mine[2] = {&bucket[0][k], &bucket[1][k]};
 *         isk__place_blend(c, &pl, col, mode, r0[k], r1[k], mine, 2);
 *     }
 *
 * A bucket grows as needed (kept between frames by its owner); when it
 * cannot, isk__place_share returns 0 and the caller draws that share's
 * points the one-pass way instead. */
#ifndef ISKRA_VIEW_WORLD_PLACE_H
#define ISKRA_VIEW_WORLD_PLACE_H

#include <stddef.h>
#include <stdint.h>

#include "iskra/view.h"

typedef struct isk__place_bucket {
    uint64_t *rec;
    size_t n, cap;
} isk__place_bucket;

typedef struct isk__place {
    const isk_canvas *c;         /* its geometry (place) and pixels (blend) */
    const isk_view *v;
    const double *x, *y;         /* the store's positions */
    unsigned rule;               /* an isk__batch_rule, maybe | ISK__BATCH_KEEP_ON_CANVAS */
    int nb;                      /* bands */
    const uint8_t *band_of_row;  /* the band of each canvas row, in row order (nb <= 256) */
} isk__place;

/* 1 when n points on this canvas fit the records (pixel offsets below
 * 2^31, indices below 2^32); else the one-pass batch must draw them. */
int isk__place_fits(const isk_canvas *c, size_t n);

/* Step 1 for the points [i0, i1): empties out[0 .. nb) and appends each
 * point's records.  0 when a bucket could not grow. */
int isk__place_share(const isk__place *pl, size_t i0, size_t i1, isk__place_bucket *out);

/* Step 2: blends buckets[0 .. nbuckets) in that order (one band's bucket
 * of every share, shares in index order) onto the rows [r0, r1) of the
 * band they were placed for, in colour col with the blend mode. */
void isk__place_blend(const isk__place *pl, isk_canvas *c, isk_color col, isk_blend mode, int r0, int r1,
                      const isk__place_bucket *const *buckets, int nbuckets);

void isk__place_bucket_free(isk__place_bucket *b);

#endif
