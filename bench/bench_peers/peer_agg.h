/* SPDX-License-Identifier: MIT */
/* bench/bench_peers/peer_agg.h — the AGG side of bench_peers behind a C
 * interface (AGG is C++; peer_agg.cpp is the only C++ in the project and
 * is built only for this benchmark).  Every call draws n items into an
 * RGBA8 buffer the caller owns; add != 0 uses AGG's "plus" compositing
 * operator, otherwise its normal (source-over) blender. */
#ifndef ISKRA_BENCH_PEER_AGG_H
#define ISKRA_BENCH_PEER_AGG_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct peer_agg peer_agg;

peer_agg *peer_agg_create(uint8_t *rgba, int width, int height, int stride);
void peer_agg_destroy(peer_agg *a);
/* anti-aliased 1x1 squares with top-left corner (x[i], y[i]) */
void peer_agg_dots(peer_agg *a, int n, const double *x, const double *y, const uint8_t col[4], int add);
void peer_agg_pixels(peer_agg *a, int n, const int *x, const int *y, const uint8_t col[4], int add);
void peer_agg_discs(peer_agg *a, int n, const double *cx, const double *cy, double r, const uint8_t col[4],
                    int add);
/* an S x S coverage mask at integer top-left (x[i], y[i]) in one colour:
 * AGG's span blender blend_solid_hspan, one call per row */
void peer_agg_masks(peer_agg *a, int n, const int *x, const int *y, const uint8_t *mask, int S,
                    const uint8_t col[4], int add);
/* an S x S premultiplied RGBA image at integer top-left (x[i], y[i]) */
void peer_agg_images(peer_agg *a, int n, const int *x, const int *y, const uint8_t *img, int S, int add);

#ifdef __cplusplus
}
#endif

#endif
