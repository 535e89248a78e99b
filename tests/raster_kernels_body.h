/* SPDX-License-Identifier: MIT */
/* tests/raster_kernels_body.h — the row kernels of src/raster/span.h and
 * their twins (span_sse2.h, span_vector.h, span_avx2.h) against the
 * per-pixel reference (tests/raster_ref.h), over random rows.  Included by
 * two test programs: test_raster_kernels.c (the build's own path: SSE2 on
 * x86-64, plus AVX2 when the CPU has it; the plain loops alone in the
 * reference build) and test_raster_kernels_generic.c (ISK__CPU_NO_SSE2:
 * the vector-extension path other targets use), so every path is checked
 * on this machine.
 * KERNEL_SUITE names the Criterion suite. */
#include <criterion/criterion.h>
#include <criterion/logging.h>

#include <stdlib.h>
#include <string.h>

#include "iskra/rng.h"
#include "raster/span.h"
#include "raster/span_avx2.h"
#include "raster_ref.h"

static const isk_blend K_MODES[3] = {ISK_BLEND_REPLACE, ISK_BLEND_OVER, ISK_BLEND_ADD};

static uint8_t k_byte(isk_rng *r)
{
    switch (isk_rng_below(r, 6)) {
    case 0: return 0;
    case 1: return 255;
    default: return (uint8_t)isk_rng_below(r, 256);
    }
}

/* A random row: destination pixels (opaque, mixed or random alpha) and
 * coverage bytes with runs of 0 and 255. */
static void k_row(isk_rng *r, uint8_t *d, uint8_t *cov, int n)
{
    int style = (int)isk_rng_below(r, 3);
    for (int i = 0; i < 4 * n; i++)
        d[i] = (uint8_t)isk_rng_below(r, 256);
    for (int i = 0; i < n; i++) {
        if (style == 0 || (style == 1 && isk_rng_below(r, 4)))
            d[4 * i + 3] = 255;
        cov[i] = k_byte(r);
        if (i > 0 && isk_rng_below(r, 3) == 0)
            cov[i] = cov[i - 1];
    }
}

static isk_color k_color(isk_rng *r)
{
    isk_color c = {k_byte(r), k_byte(r), k_byte(r), k_byte(r)};
    return c;
}

enum { K_MAXN = 70 };

Test(KERNEL_SUITE, span_cov_equals_blend_pixel_cov)
{
    isk_rng r;
    isk_rng_seed(&r, 11);
    uint8_t d0[4 * K_MAXN + 8], d1[4 * K_MAXN + 8], cov[K_MAXN];
    for (int t = 0; t < 60000; t++) {
        int n = (int)isk_rng_below(&r, K_MAXN + 1);
        k_row(&r, d0, cov, n);
        memset(d0 + 4 * n, 0x5A, 8); /* sentinels after the row */
        memcpy(d1, d0, sizeof d0);
        isk_color col = k_color(&r);
        isk_blend mode = K_MODES[isk_rng_below(&r, 3)];
        isk__span_cov(d0, cov, n, col, mode);
        for (int i = 0; i < n; i++)
            isk__rule_pixel_cov(d1 + 4 * i, col, cov[i], mode);
        cr_assert(memcmp(d0, d1, sizeof d0) == 0, "row %d (n %d, mode %d)", t, n, mode);
    }
}

Test(KERNEL_SUITE, span_add_bytes_saturates_like_the_rule)
{
    isk_rng r;
    isk_rng_seed(&r, 12);
    uint8_t d0[4 * K_MAXN + 8], d1[4 * K_MAXN + 8], q[4 * K_MAXN];
    for (int t = 0; t < 20000; t++) {
        int nb = 4 * (int)isk_rng_below(&r, K_MAXN + 1);
        for (int i = 0; i < nb; i++) {
            d0[i] = k_byte(&r);
            q[i] = k_byte(&r);
        }
        memset(d0 + nb, 0x5A, 8);
        memcpy(d1, d0, sizeof d0);
        isk__span_add_bytes(d0, q, nb);
        for (int i = 0; i < nb; i++)
            d1[i] = (uint8_t)(d1[i] + q[i] > 255 ? 255 : d1[i] + q[i]);
        cr_assert(memcmp(d0, d1, sizeof d0) == 0, "row %d", t);
    }
}

#if ISK__CPU_SSE2
Test(KERNEL_SUITE, sse2_div255_exact_for_every_product)
{
    for (uint32_t x = 0; x <= 255u * 255u; x += 8) {
        uint16_t in[8], out[8];
        for (int k = 0; k < 8; k++)
            in[k] = (uint16_t)(x + (uint32_t)k > 255u * 255u ? 255u * 255u : x + (uint32_t)k);
        __m128i v;
        memcpy(&v, in, 16);
        v = isk__s_div255(v);
        memcpy(out, &v, 16);
        for (int k = 0; k < 8; k++)
            cr_assert_eq(out[k], isk_div255(in[k]), "x = %u", in[k]);
    }
}
#endif

#if ISK__CPU_VECTOR
Test(KERNEL_SUITE, vector_div255_exact_for_every_product)
{
    for (uint32_t x = 0; x <= 255u * 255u; x += 8) {
        isk__u16x8 v;
        for (int k = 0; k < 8; k++)
            v[k] = (uint16_t)(x + (uint32_t)k > 255u * 255u ? 255u * 255u : x + (uint32_t)k);
        isk__u16x8 o = isk__v_div255(v);
        for (int k = 0; k < 8; k++)
            cr_assert_eq(o[k], isk_div255(v[k]), "x = %u", (unsigned)v[k]);
    }
}
#endif

#if ISK__CPU_AVX2
/* The AVX2 kernels are compiled into functions with the target attribute
 * and called only when the CPU has AVX2. */
static ISK__AVX2_FN void k_cov_avx2(uint8_t *d, const uint8_t *cov, int n, isk_color col, isk_blend mode)
{
    isk__span_cov_avx2(d, cov, n, col, mode);
}

static ISK__AVX2_FN void k_add_avx2(uint8_t *d, const uint8_t *q, int nb)
{
    isk__span_add_bytes_avx2(d, q, nb);
}

static ISK__AVX2_FN void k_over_inc_avx2(uint8_t *d, const uint8_t *inc, int n, isk_color col)
{
    isk__span_over_inc_avx2(d, inc, n, col);
}

Test(KERNEL_SUITE, avx2_kernels_equal_the_rule)
{
    if (!isk__have_avx2()) {
        /* info, not a warning: Criterion fails a run that logs one */
        cr_log_info("no AVX2 on this CPU: its kernels are not exercised here");
        return;
    }
    isk_rng r;
    isk_rng_seed(&r, 13);
    uint8_t d0[4 * K_MAXN + 8], d1[4 * K_MAXN + 8], cov[K_MAXN], inc[4 * K_MAXN];
    for (int t = 0; t < 60000; t++) {
        int n = (int)isk_rng_below(&r, K_MAXN + 1);
        k_row(&r, d0, cov, n);
        memset(d0 + 4 * n, 0x5A, 8);
        memcpy(d1, d0, sizeof d0);
        isk_color col = k_color(&r);
        int kind = (int)isk_rng_below(&r, 3);
        if (kind == 0) { /* the mask in a colour, any mode */
            isk_blend mode = K_MODES[isk_rng_below(&r, 3)];
            k_cov_avx2(d0, cov, n, col, mode);
            for (int i = 0; i < n; i++)
                isk__rule_pixel_cov(d1 + 4 * i, col, cov[i], mode);
        } else {
            /* a baked colour's increments (as isk_sprite_init makes them) */
            for (int i = 0; i < n; i++) {
                uint32_t a = isk_div255((uint32_t)col.a * cov[i]);
                inc[4 * i + 0] = (uint8_t)isk_div255((uint32_t)col.r * a);
                inc[4 * i + 1] = (uint8_t)isk_div255((uint32_t)col.g * a);
                inc[4 * i + 2] = (uint8_t)isk_div255((uint32_t)col.b * a);
                inc[4 * i + 3] = (uint8_t)a;
            }
            isk_blend mode = kind == 1 ? ISK_BLEND_ADD : ISK_BLEND_OVER;
            if (kind == 1)
                k_add_avx2(d0, inc, 4 * n);
            else
                k_over_inc_avx2(d0, inc, n, col);
            for (int i = 0; i < n; i++)
                isk__rule_pixel_cov(d1 + 4 * i, col, cov[i], mode);
        }
        cr_assert(memcmp(d0, d1, sizeof d0) == 0, "row %d (n %d, kind %d)", t, n, kind);
    }
}
#endif
