/* SPDX-License-Identifier: MIT */
/* A sprite's rows (raster/sprite_loops.h) for AVX2: the mask and the
 * additive increments 8 pixels a step, and source-over of the baked colour
 * straight from its increments (raster/span_avx2.h; integer blending, the
 * same bytes).  sprite.c calls it where isk__have_avx2(). */
#include "core/cpu.h"

#if ISK__CPU_AVX2
#include "raster/span_avx2.h"
#include "raster/sprite_loops.h"

/* The baked colour's source-over rows out of line: inlined, their loops
 * moved the tinted sprites' row loops in the code and cost those 10%. */
static ISK__AVX2_FN __attribute__((noinline)) void rows_over_avx2(uint8_t *drow, size_t stride, const uint8_t *inc,
                                                                 size_t inc_stride, const uint16_t *span, int S,
                                                                 isk_color col)
{
    isk__rows_over_inc_avx2(drow, stride, inc, inc_stride, span, S, col);
}
SPRITE_ROWS(isk__sprite_rows_avx2, ISK__AVX2_FN, isk__span_cov_avx2, isk__span_add_bytes_avx2,
            isk__span_add_bytes16_avx2, isk__span_over_inc_avx2, rows_over_avx2, SRC_INC_OVER)
#else
typedef int isk__sprite_avx2_unused; /* ISO C wants a declaration in every file */
#endif
