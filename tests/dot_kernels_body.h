/* SPDX-License-Identifier: MIT */
/* tests/dot_kernels_body.h — the coverage dot's 2x2 blends and their twins
 * (raster/dot_kernel.h's isk__blend_2x2 with dot_kernel_sse2.h or
 * dot_kernel_vector.h; view/dot_block.h's px2 and px4 with
 * dot_block_sse2.h or dot_block_vector.h) against the per-pixel reference
 * (tests/raster_ref.h), over random blocks, colours, weights and
 * destinations.  Included by two test programs: test_dot_kernels.c (the
 * build's own path: SSE2 on x86-64, the plain code in the reference build)
 * and test_dot_kernels_generic.c (ISK__CPU_NO_SSE2: the vector-extension
 * path other targets, wasm among them, use), so every path is checked on
 * this machine.  DOT_SUITE names the Criterion suite. */
#include <criterion/criterion.h>

#include <string.h>

#include "iskra/rng.h"
#include "raster/blend_px.h"
#include "raster/dot_kernel.h"
#include "raster_ref.h"
#include "view/dot_block.h"

static const isk_blend D_MODES[3] = {ISK_BLEND_REPLACE, ISK_BLEND_OVER, ISK_BLEND_ADD};

static uint8_t d_byte(isk_rng *r)
{
    switch (isk_rng_below(r, 6)) {
    case 0: return 0;
    case 1: return 255;
    default: return (uint8_t)isk_rng_below(r, 256);
    }
}

/* A canvas's pixels: all opaque (the twins' fast case), random alphas, or
 * opaque but for a few (a row of the block with one pixel that is not). */
static void d_pixels(isk_rng *r, uint8_t *px, size_t n)
{
    const int style = (int)isk_rng_below(r, 3);
    for (size_t i = 0; i < n; i++)
        px[i] = (uint8_t)isk_rng_below(r, 256);
    for (size_t i = 3; i < n; i += 4)
        px[i] = style == 1 ? d_byte(r) : style == 2 && isk_rng_below(r, 8) == 0 ? d_byte(r) : 255;
}

/* Four weights: the exact-area rule's (summing to 255), or any bytes (the
 * blend takes any coverage). */
static void d_weights(isk_rng *r, uint32_t w[4])
{
    if (isk_rng_below(r, 2)) {
        isk__dot_weights_frac(isk_rng_range(r, 0.0, 1.0), isk_rng_range(r, 0.0, 1.0), w);
    } else {
        for (int q = 0; q < 4; q++)
            w[q] = d_byte(r);
    }
}

static isk_color d_color(isk_rng *r)
{
    return (isk_color){d_byte(r), d_byte(r), d_byte(r), d_byte(r)};
}

enum { D_W = 6, D_H = 4, D_STRIDE = 4 * D_W + 8 }; /* rows padded: the stride is not the width */

Test(DOT_SUITE, blend_2x2_is_the_per_pixel_rule)
{
    isk_rng r;
    isk_rng_seed(&r, 11);
    static isk__cov_lut lut;
    for (int t = 0; t < 60000; t++) {
        uint8_t got[D_STRIDE * D_H], want[D_STRIDE * D_H];
        d_pixels(&r, got, sizeof got);
        memcpy(want, got, sizeof got);
        isk_canvas c = {got, D_W, D_H, D_STRIDE, 0}, ref = {want, D_W, D_H, D_STRIDE, 0};
        /* mostly wholly on the canvas (the twins' case), some cut by an edge */
        const int ix = (int)isk_rng_below(&r, D_W + 2) - 1, iy = (int)isk_rng_below(&r, D_H + 2) - 1;
        uint32_t w[4];
        uint8_t w8[4];
        d_weights(&r, w);
        for (int q = 0; q < 4; q++)
            w8[q] = (uint8_t)w[q];
        const isk_color col = d_color(&r);
        const isk_blend mode = D_MODES[t % 3];
        const int with_lut = (t / 3) % 2; /* the single dot's (no table) and the batch's */
        if (with_lut)
            isk__cov_lut_init(&lut, col);
        isk__blend_2x2(&c, ix, iy, w, col, with_lut ? &lut : NULL, mode);
        ref_blend_2x2(&ref, ix, iy, w8, col, mode);
        cr_assert(memcmp(got, want, sizeof got) == 0, "case %d: mode %d, table %d, block (%d, %d)", t, (int)mode,
                  with_lut, ix, iy);
    }
}

Test(DOT_SUITE, px2_and_px4_are_the_per_pixel_rule)
{
    isk_rng r;
    isk_rng_seed(&r, 12);
    static isk__cov_lut lut;
    for (int t = 0; t < 60000; t++) {
        uint8_t got[D_STRIDE * 2], want[D_STRIDE * 2];
        d_pixels(&r, got, sizeof got);
        memcpy(want, got, sizeof got);
        const size_t at = 4u * isk_rng_below(&r, D_W - 1);
        uint32_t w[4];
        uint8_t w8[4];
        d_weights(&r, w);
        for (int q = 0; q < 4; q++)
            w8[q] = (uint8_t)w[q];
        const isk_color col = d_color(&r);
        const isk_blend mode = D_MODES[t % 3];
        isk__cov_lut_init(&lut, col);
        if ((t / 3) % 2) {
            px4(got + at, D_STRIDE, col, &lut, w8, mode);
        } else {
            px2(got + at, col, &lut, w[0], w[1], mode);
            px2(got + at + D_STRIDE, col, &lut, w[2], w[3], mode);
        }
        for (int q = 0; q < 4; q++)
            isk__rule_pixel_cov(want + at + (q >= 2 ? D_STRIDE : 0) + 4u * (unsigned)(q & 1), col, w8[q], mode);
        cr_assert(memcmp(got, want, sizeof got) == 0, "case %d: mode %d, %s", t, (int)mode,
                  (t / 3) % 2 ? "px4" : "px2");
    }
}
