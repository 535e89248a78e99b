/* SPDX-License-Identifier: MIT */
/* The GIF writer's per-frame palette (src/io/quantize.h): exact colours up
 * to 256, median cut above, deterministic, alpha composited over black. */
#include <criterion/criterion.h>
#include <stdlib.h>
#include <string.h>

#include "io/quantize.h"

static void decode(const uint8_t *pal, int n, const uint8_t *idx, int npix, uint8_t *rgb)
{
    for (int i = 0; i < npix; i++) {
        cr_assert_lt(idx[i], n);
        memcpy(rgb + 3 * i, pal + 3 * idx[i], 3);
    }
}

Test(quantize, up_to_256_colours_are_kept_exactly_and_sorted)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 16, 16), ISK_OK);
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            uint8_t *p = isk_canvas_at(&c, x, y);
            p[0] = (uint8_t)(255 - x * 16 - y); /* 256 distinct colours */
            p[1] = (uint8_t)(y * 16);
            p[2] = (uint8_t)x;
            p[3] = 255;
        }
    isk__quant q;
    cr_assert_eq(isk__quant_init(&q, 256), ISK_OK);
    uint8_t pal[768], idx[256], rgb[768];
    int n;
    cr_assert_eq(isk__quant_frame(&q, &c, pal, &n, idx), ISK_OK);
    cr_assert_eq(n, 256);
    decode(pal, n, idx, 256, rgb);
    for (int i = 0; i < 256; i++)
        cr_assert_eq(memcmp(rgb + 3 * i, isk_canvas_at(&c, i % 16, i / 16), 3), 0, "pixel %d", i);
    for (int i = 1; i < n; i++) {
        uint32_t a = (uint32_t)pal[3 * i - 3] << 16 | pal[3 * i - 2] << 8 | pal[3 * i - 1];
        uint32_t b = (uint32_t)pal[3 * i] << 16 | pal[3 * i + 1] << 8 | pal[3 * i + 2];
        cr_assert_lt(a, b, "the palette is sorted by colour");
    }
    /* translucent pixels are composited over black: (200, 100, 50) at alpha 128 */
    isk_canvas one;
    cr_assert_eq(isk_canvas_init(&one, 1, 1), ISK_OK);
    memcpy(one.pixels, (uint8_t[4]){200, 100, 50, 128}, 4);
    cr_assert_eq(isk__quant_frame(&q, &one, pal, &n, idx), ISK_OK);
    cr_assert(n == 1 && pal[0] == 100 && pal[1] == 50 && pal[2] == 25, "%d %d %d", pal[0], pal[1], pal[2]);
    isk_canvas_free(&one);
    isk__quant_free(&q);
    isk_canvas_free(&c);
}

Test(quantize, many_colours_get_a_close_deterministic_palette)
{
    enum { W = 256, H = 128 };
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, W, H), ISK_OK);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            uint8_t *p = isk_canvas_at(&c, x, y);
            p[0] = (uint8_t)x;
            p[1] = (uint8_t)(2 * y);
            p[2] = (uint8_t)((x * y) >> 7);
            p[3] = 255;
        }
    isk__quant q;
    cr_assert_eq(isk__quant_init(&q, W * H), ISK_OK);
    static uint8_t idx[W * H], idx2[W * H], rgb[3 * W * H];
    uint8_t pal[768], pal2[768];
    int n, n2;
    cr_assert_eq(isk__quant_frame(&q, &c, pal, &n, idx), ISK_OK);
    cr_assert_eq(n, 256);
    decode(pal, n, idx, W * H, rgb);
    long sum = 0;
    int worst = 0;
    for (int i = 0; i < W * H; i++)
        for (int k = 0; k < 3; k++) {
            int d = abs(rgb[3 * i + k] - isk_canvas_at(&c, i % W, i / W)[k]);
            sum += d;
            worst = d > worst ? d : worst;
        }
    double mean = (double)sum / (3.0 * W * H);
    cr_assert_lt(mean, 6.0, "mean error %.2f for 32768 colours in 256", mean);
    cr_assert_lt(worst, 48, "worst channel error %d", worst);
    cr_assert_eq(isk__quant_frame(&q, &c, pal2, &n2, idx2), ISK_OK);
    cr_assert(n2 == n && !memcmp(pal, pal2, 768) && !memcmp(idx, idx2, sizeof idx), "not deterministic");
    /* a canvas larger than the quantizer was made for is refused */
    isk_canvas big;
    cr_assert_eq(isk_canvas_init(&big, W + 1, H), ISK_OK);
    cr_assert_eq(isk__quant_frame(&q, &big, pal, &n, idx), ISK_ERR_SIZE);
    isk_canvas_free(&big);
    isk__quant_free(&q);
    isk__quant_free(&q);
    cr_assert_eq(isk__quant_init(&q, 0), ISK_ERR_SIZE);
    isk_canvas_free(&c);
}
