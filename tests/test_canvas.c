/* SPDX-License-Identifier: MIT */
/* Canvas creation, wrapping, views and validation. */
#include <criterion/criterion.h>
#include <string.h>

#include "iskra/canvas.h"

Test(canvas, init_is_transparent_and_validates)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 3, 2), ISK_OK);
    cr_assert_eq(c.stride, 12u);
    for (int i = 0; i < 24; i++)
        cr_assert_eq(c.pixels[i], 0);
    isk_canvas_free(&c);
    cr_assert_null(c.pixels);
    isk_canvas_free(&c); /* twice is harmless */
    cr_assert_eq(isk_canvas_init(&c, 0, 5), ISK_ERR_SIZE);
    cr_assert_eq(isk_canvas_init(&c, 5, -1), ISK_ERR_SIZE);
    cr_assert_eq(isk_canvas_init(&c, ISK_CANVAS_MAX_DIM + 1, 1), ISK_ERR_SIZE);
    cr_assert_eq(isk_canvas_init(NULL, 5, 5), ISK_ERR_NULL);
}

Test(canvas, wrap_uses_caller_memory_and_stride)
{
    uint8_t mem[4 * 10 * 3 + 8];
    memset(mem, 0xAB, sizeof mem);
    isk_canvas c;
    cr_assert_eq(isk_canvas_wrap(&c, mem, 3, 3, 40), ISK_OK);
    isk_canvas_fill(&c, ISK_RED);
    cr_assert_eq(mem[40], 255);      /* row 1, pixel 0, R */
    cr_assert_eq(mem[12], 0xAB);     /* padding after row 0 untouched */
    isk_canvas_free(&c);              /* does not free caller memory */
    cr_assert_eq(isk_canvas_wrap(&c, mem, 3, 3, 11), ISK_ERR_SIZE);
    cr_assert_eq(isk_canvas_wrap(&c, NULL, 3, 3, 12), ISK_ERR_NULL);
}

Test(canvas, views_clip_and_share_pixels)
{
    isk_canvas c, v;
    cr_assert_eq(isk_canvas_init(&c, 10, 10), ISK_OK);
    cr_assert_eq(isk_canvas_view(&v, &c, 8, -2, 5, 5), ISK_OK);
    cr_assert_eq(v.width, 2);
    cr_assert_eq(v.height, 3);
    isk_canvas_fill(&v, ISK_WHITE);
    cr_assert_eq(isk_canvas_get(&c, 8, 0).r, 255);
    cr_assert_eq(isk_canvas_get(&c, 9, 2).r, 255);
    cr_assert_eq(isk_canvas_get(&c, 7, 0).r, 0);
    cr_assert_eq(isk_canvas_get(&c, 8, 3).r, 0);
    /* Entirely outside, or with overflowing extents: an empty view. */
    cr_assert_eq(isk_canvas_view(&v, &c, 20, 20, 5, 5), ISK_OK);
    cr_assert_eq(v.width, 0);
    cr_assert_eq(isk_canvas_view(&v, &c, 2147483647, 0, 2147483647, 5), ISK_OK);
    cr_assert_eq(v.width, 0);
    cr_assert_eq(isk_canvas_view(&v, &c, -2147483647 - 1, 0, 2147483647, 5), ISK_OK);
    cr_assert_eq(v.width, 0);
    cr_assert_eq(isk_canvas_view(&v, &c, 0, 0, -1, 5), ISK_ERR_SIZE);
    isk_canvas_fill(&v, ISK_WHITE); /* no-op on empty views */
    cr_assert_eq(isk_canvas_get(&c, -1, 0).a, 0);
    cr_assert_eq(isk_canvas_get(&c, 0, 10).a, 0);
    isk_canvas_free(&c);
}

Test(canvas, equal)
{
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, 4, 4), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 4, 4), ISK_OK);
    cr_assert(isk_canvas_equal(&a, &b));
    isk_canvas_at(&b, 3, 3)[3] = 1;
    cr_assert(!isk_canvas_equal(&a, &b));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

/* Two 4x3 grey canvases; b differs from a in two pixels: +10 in G at
 * (1, 2), -5 in A at (3, 0). */
static void two_canvases(isk_canvas *a, isk_canvas *b)
{
    cr_assert_eq(isk_canvas_init(a, 4, 3), ISK_OK);
    cr_assert_eq(isk_canvas_init(b, 4, 3), ISK_OK);
    isk_canvas_fill(a, isk_rgba(90, 90, 90, 255));
    isk_canvas_fill(b, isk_rgba(90, 90, 90, 255));
    isk_canvas_at(b, 1, 2)[1] = 100;
    isk_canvas_at(b, 3, 0)[3] = 250;
}

Test(canvas, compare_counts_and_marks_differences)
{
    isk_canvas a, b, img;
    two_canvases(&a, &b);
    isk_canvas_diff d;
    cr_assert_eq(isk_canvas_init(&img, 4, 3), ISK_OK);
    cr_assert(isk_canvas_compare(&a, &b, &d, &img));
    cr_assert_eq(d.pixels, 12);
    cr_assert_eq(d.differing, 2);
    cr_assert_eq(d.max_channel, 10);
    cr_assert_float_eq(d.mean_abs, 15.0 / 48.0, 1e-12);
    cr_assert_eq(isk_canvas_get(&img, 1, 2).g, 0);   /* magenta */
    cr_assert_eq(isk_canvas_get(&img, 1, 2).r, 255);
    cr_assert_eq(isk_canvas_get(&img, 0, 0).r, 30);  /* dimmed copy */
    isk_canvas_free(&img);
    /* Different sizes: 0, and the diff image covers both. */
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 5, 2), ISK_OK);
    cr_assert_eq(isk_canvas_init(&img, 5, 3), ISK_OK);
    cr_assert(!isk_canvas_compare(&a, &c, &d, &img));
    cr_assert_eq(d.differing, 0);
    cr_assert_eq(isk_canvas_get(&img, 4, 2).r, 255);
    cr_assert(isk_canvas_compare(&a, &a, NULL, NULL));
    isk_canvas_free(&img);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_canvas_free(&c);
}

/* The tolerance rule: a pixel counts when its largest channel difference is
 * beyond the limit (in either direction, any of the four channels). */
Test(canvas, count_beyond_counts_pixels_past_the_largest_channel_difference)
{
    isk_canvas a, b, c;
    two_canvases(&a, &b);             /* +10 in G, -5 in A */
    isk_canvas_at(&b, 0, 1)[0] = 88;  /* -2 in R */
    isk_canvas_at(&b, 0, 1)[2] = 94;  /* +4 in B: the pixel's largest is 4 */
    cr_assert_eq(isk_canvas_count_beyond(&a, &b, 0), 3, "0: every differing pixel");
    cr_assert_eq(isk_canvas_count_beyond(&a, &b, 3), 3);
    cr_assert_eq(isk_canvas_count_beyond(&a, &b, 4), 2, "4 is not beyond 4");
    cr_assert_eq(isk_canvas_count_beyond(&a, &b, 5), 1);
    cr_assert_eq(isk_canvas_count_beyond(&b, &a, 9), 1, "the order does not matter");
    cr_assert_eq(isk_canvas_count_beyond(&a, &b, 10), 0);
    cr_assert_eq(isk_canvas_count_beyond(&a, &b, 255), 0);
    /* Refusals: -1. */
    cr_assert_eq(isk_canvas_count_beyond(&a, &b, -1), -1);
    cr_assert_eq(isk_canvas_count_beyond(&a, &b, 256), -1);
    cr_assert_eq(isk_canvas_count_beyond(NULL, &b, 0), -1);
    cr_assert_eq(isk_canvas_count_beyond(&a, NULL, 0), -1);
    cr_assert_eq(isk_canvas_init(&c, 3, 4), ISK_OK);
    cr_assert_eq(isk_canvas_count_beyond(&a, &c, 0), -1, "sizes differ");
    isk_canvas bad = {NULL, 4, 3, 16, 0};
    cr_assert_eq(isk_canvas_count_beyond(&a, &bad, 0), -1, "no pixels");
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_canvas_free(&c);
}
