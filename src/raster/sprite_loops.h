/* SPDX-License-Identifier: MIT */
/* src/raster/sprite_loops.h — a placed sprite's rows blended onto the
 * canvas (internal): compiled by sprite.c for every CPU, with the row
 * kernels of raster/span.h, and by sprite_avx2.c for AVX2, with
 * span_avx2.h's (the same bytes: integer blending).
 *
 *     SPRITE_ROWS(rows_base, static, isk__span_cov, isk__span_add_bytes, isk__span_add_bytes16, NULL, NULL,
 *                 SRC_MASK)
 *
 * defines rows_base(c, s, pl, col, kind, mode), which draws the rows
 * [pl->jb, pl->je) of the sprite placed at pl in one of the SRC_ kinds. */
#ifndef ISKRA_RASTER_SPRITE_LOOPS_H
#define ISKRA_RASTER_SPRITE_LOOPS_H

#include <stddef.h>
#include <stdint.h>

#include "core/cpu.h"
#include "iskra/sprite.h"
#include "raster/blend_px.h"

/* Where the sprite lands: mask phase, origin and the clipped row/column
 * ranges.  0 when nothing is visible (or the input is NaN/Inf/huge). */
typedef struct placement {
    int p, x0, y0, jb, je, ib, ie;
} placement;

/* Rows of a sprite are a canvas stride apart, too far for the hardware
 * prefetcher: both ends of the first ROW_AHEAD rows are requested at once
 * (sprites wholly on the canvas; clipped ones are rare).  Requests inside
 * the row loop were tried and cost more than they saved. */
#define ROW_AHEAD 6

/* Source-over sprites up to this size blend whole rows (see draw_rows). */
#define OVER_WHOLE_MAX 16

/* The sprite's rows, each one span of the mask blended by the row kernels
 * of raster/span.h, the mode a constant (one loop per mode).  inc != 0:
 * the baked colour's premade additive increments (a saturating byte add of
 * two arrays).  A sprite wholly on the canvas uses the padded spans (whole
 * 4-pixel steps); a clipped one the exact spans cut to the canvas.  The
 * row kernels are parameters so the loop is compiled once per SIMD level. */
typedef void (*span_cov_fn)(uint8_t *, const uint8_t *, int, isk_color, isk_blend);
typedef void (*span_add_fn)(uint8_t *, const uint8_t *, int);
typedef void (*span_over_fn)(uint8_t *, const uint8_t *, int, isk_color);
typedef void (*rows_over_fn)(uint8_t *, size_t, const uint8_t *, size_t, const uint16_t *, int, isk_color);

/* What a row blends: the mask in a colour, or the baked colour's premade
 * increments, added or (AVX2) taken as a' for source-over. */
enum { SRC_MASK, SRC_INC_ADD, SRC_INC_OVER };

static ISK__INLINE void draw_rows(const isk_canvas *c, const isk_sprite *s, const placement *pl, isk_color col,
                                  int src_kind, isk_blend mode, span_cov_fn span_cov, span_add_fn span_add,
                                  span_add_fn span_add16, span_over_fn span_over, rows_over_fn rows_over)
{
    const int inc = src_kind != SRC_MASK;
    const int S = s->size;
    const size_t stride = c->stride, unit = inc ? 4u : 1u; /* source bytes per pixel */
    const uint8_t *src = inc ? s->inc[pl->p] : s->mask[pl->p];
    if (pl->jb == 0 && pl->je == S && pl->ib == 0 && pl->ie == S) {
        /* wholly on the canvas: padded spans, no clipping, rows by pointer steps */
        const uint16_t *span = s->vspan[pl->p];
        uint8_t *drow = c->pixels + (size_t)pl->y0 * stride + (size_t)pl->x0 * 4u;
#if defined(__GNUC__)
        for (int j = 0; j < S && j < ROW_AHEAD; j++) {
            __builtin_prefetch(drow + (size_t)j * stride + 4u * span[2 * j], 1);
            __builtin_prefetch(drow + (size_t)j * stride + 4u * span[2 * j + 1] - 1, 1);
        }
#endif
        if (src_kind == SRC_INC_OVER && rows_over) { /* one call: constants built once per sprite */
            /* small sprites whole rows, as the additive ones below */
            rows_over(drow, stride, src, 4u * (size_t)S, (S & 3) == 0 && S <= OVER_WHOLE_MAX ? NULL : span, S,
                      col);
            return;
        }
        /* Additive rows of a size that is a multiple of 4 are drawn whole
         * (adding zeros is harmless): every row then has the same length,
         * which the branch predictor keeps, where spans of four phases
         * mispredict more than the extra bytes cost.  Source-over, heavier
         * per pixel, keeps the spans. */
        const int uniform = (S & 3) == 0 && src_kind == SRC_INC_ADD;
        if (uniform) {
            /* the common sizes with a constant row length: each row's
             * 16- or 32-byte steps unrolled, no loop test inside a row */
            const size_t rb = 4u * (size_t)S;
            if (S == 32)
                for (int j = 0; j < 32; j++, drow += stride, src += 128)
                    span_add16(drow, src, 128);
            else if (S == 16)
                for (int j = 0; j < 16; j++, drow += stride, src += 64)
                    span_add16(drow, src, 64);
            else if (S == 8)
                for (int j = 0; j < 8; j++, drow += stride, src += 32)
                    span_add16(drow, src, 32);
            else
                for (int j = 0; j < S; j++, drow += stride, src += rb)
                    span_add16(drow, src, (int)rb);
            return;
        }
        for (int j = 0; j < S; j++, drow += stride, src += unit * (size_t)S) {
            const int b = span[2 * j], n = span[2 * j + 1] - b;
            if (src_kind == SRC_INC_ADD && !(n & 3))
                span_add16(drow + 4 * b, src + 4 * b, 4 * n); /* padded: whole 16-byte steps */
            else if (src_kind == SRC_INC_ADD) /* a row too short to pad (S not a multiple of 4) */
                span_add(drow + 4 * b, src + 4 * b, 4 * n);
            else if (src_kind == SRC_INC_OVER)
                span_over(drow + 4 * b, src + 4 * b, n, col);
            else
                span_cov(drow + 4 * b, src + b, n, col, mode);
        }
        return;
    }
    const uint16_t *span = s->span[pl->p];
    for (int j = pl->jb; j < pl->je; j++) {
        int b = span[2 * j] > pl->ib ? span[2 * j] : pl->ib;
        int e = span[2 * j + 1] < pl->ie ? span[2 * j + 1] : pl->ie;
        if (b >= e)
            continue;
        uint8_t *d = c->pixels + (size_t)(pl->y0 + j) * stride + (size_t)(pl->x0 + b) * 4u;
        const uint8_t *q = src + unit * ((size_t)j * (size_t)S + (size_t)b);
        if (src_kind == SRC_INC_ADD)
            span_add(d, q, 4 * (e - b));
        else if (src_kind == SRC_INC_OVER)
            span_over(d, q, e - b, col);
        else
            span_cov(d, q, e - b, col, mode);
    }
}

/* One function per SIMD level: kind SRC_INC_ADD = premade increments
 * (additive, baked colour), SRC_INC_OVER = the baked colour over (taken from
 * the increments where the level has a kernel for it, else from the mask),
 * SRC_MASK = the mask in col with the given mode. */
#define SPRITE_ROWS(NAME, ATTR, SPAN_COV, SPAN_ADD, SPAN_ADD16, SPAN_OVER, ROWS_OVER, OVER_KIND)                          \
    ATTR void NAME(const isk_canvas *c, const isk_sprite *s, const placement *pl, isk_color col, \
                          int kind, isk_blend mode)                                                  \
    {                                                                                                \
        if (kind == SRC_INC_ADD)                                                                     \
            draw_rows(c, s, pl, col, SRC_INC_ADD, ISK_BLEND_ADD, SPAN_COV, SPAN_ADD, SPAN_ADD16, SPAN_OVER, ROWS_OVER);     \
        else if (kind == SRC_INC_OVER)                                                               \
            draw_rows(c, s, pl, col, OVER_KIND, ISK_BLEND_OVER, SPAN_COV, SPAN_ADD, SPAN_ADD16, SPAN_OVER, ROWS_OVER);      \
        else if (mode == ISK_BLEND_ADD)                                                              \
            draw_rows(c, s, pl, col, SRC_MASK, ISK_BLEND_ADD, SPAN_COV, SPAN_ADD, SPAN_ADD16, SPAN_OVER, ROWS_OVER);        \
        else if (mode == ISK_BLEND_OVER)                                                             \
            draw_rows(c, s, pl, col, SRC_MASK, ISK_BLEND_OVER, SPAN_COV, SPAN_ADD, SPAN_ADD16, SPAN_OVER, ROWS_OVER);       \
        else                                                                                         \
            draw_rows(c, s, pl, col, SRC_MASK, ISK_BLEND_REPLACE, SPAN_COV, SPAN_ADD, SPAN_ADD16, SPAN_OVER, ROWS_OVER);    \
    }

#if ISK__CPU_AVX2
/* The rows for AVX2 (sprite_avx2.c), for a CPU that has it. */
void isk__sprite_rows_avx2(const isk_canvas *c, const isk_sprite *s, const placement *pl, isk_color col, int kind,
                           isk_blend mode);
#endif

#endif
