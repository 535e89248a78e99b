/* SPDX-License-Identifier: MIT */
/* Fuzz test for the rasterizer: 100,000 random primitives of every kind and
 * blend mode, with extreme and invalid coordinates (huge, ±1e300, ±Inf, NaN,
 * DBL_MAX, INT_MIN/INT_MAX), drawn into a view in the middle of a larger
 * buffer full of sentinel bytes.  Nothing may crash (run it under
 * SANITIZE=1 too) and no byte outside the view may change. */
#include <criterion/criterion.h>

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/draw.h"
#include "iskra/rng.h"

#define PW 96
#define PH 80
#define PAD 12 /* extra bytes at the end of each parent row */
#define VX 16
#define VY 12
#define VW 64
#define VH 56
#define SENTINEL 0xA5

static double rnd_coord(isk_rng *r, double size)
{
    switch (isk_rng_below(r, 16)) {
    case 0: return NAN;
    case 1: return isk_rng_below(r, 2) ? INFINITY : -INFINITY;
    case 2: return isk_rng_below(r, 2) ? 1e300 : -1e300;
    case 3: return isk_rng_below(r, 2) ? DBL_MAX : -DBL_MAX;
    case 4: return isk_rng_range(r, -1e12, 1e12);
    case 5: return isk_rng_below(r, 2) ? (double)INT_MAX + 0.5 : (double)INT_MIN - 0.5;
    case 6: return isk_rng_range(r, -1e6, 1e6);
    case 7: return (double)(int)isk_rng_below(r, 200) - 70.0; /* integers */
    case 8: return isk_rng_below(r, 2) ? 0x1p53 : -0x1p53;
    case 9: return isk_rng_below(r, 2) ? -0.0 : DBL_MIN;
    default: return isk_rng_range(r, -0.3 * size, 1.3 * size);
    }
}

static int rnd_int(isk_rng *r)
{
    switch (isk_rng_below(r, 8)) {
    case 0: return INT_MIN;
    case 1: return INT_MAX;
    case 2: return (int)isk_rng_u32(r);
    case 3: return INT_MAX - (int)isk_rng_below(r, 100);
    case 4: return INT_MIN + (int)isk_rng_below(r, 100);
    default: return (int)isk_rng_below(r, 120) - 30;
    }
}

static double rnd_radius(isk_rng *r)
{
    switch (isk_rng_below(r, 10)) {
    case 0: return NAN;
    case 1: return INFINITY;
    case 2: return 1e300;
    case 3: return -isk_rng_range(r, 0, 10);
    case 4: return 0.0;
    case 5: return isk_rng_range(r, 1e3, 1e9);
    default: return isk_rng_range(r, 0, 40);
    }
}

static void draw_random(isk_canvas *c, isk_rng *r)
{
    isk_color col = {(uint8_t)isk_rng_u32(r), (uint8_t)isk_rng_u32(r), (uint8_t)isk_rng_u32(r),
                     (uint8_t)isk_rng_u32(r)};
    isk_blend mode = (isk_blend)isk_rng_below(r, 3);
    double w = VW, h = VH;
    switch (isk_rng_below(r, 11)) {
    case 0:
        isk_draw_pixel(c, rnd_int(r), rnd_int(r), col, mode);
        break;
    case 1:
        isk_fill_rect(c, rnd_int(r), rnd_int(r), rnd_int(r), rnd_int(r), col, mode);
        break;
    case 2:
        isk_draw_line(c, rnd_coord(r, w), rnd_coord(r, h), rnd_coord(r, w), rnd_coord(r, h), col, mode);
        break;
    case 3:
        isk_draw_triangle(c, rnd_coord(r, w), rnd_coord(r, h), rnd_coord(r, w), rnd_coord(r, h),
                          rnd_coord(r, w), rnd_coord(r, h), col, mode);
        break;
    case 4:
        isk_fill_triangle(c, rnd_coord(r, w), rnd_coord(r, h), rnd_coord(r, w), rnd_coord(r, h),
                          rnd_coord(r, w), rnd_coord(r, h), col, mode);
        break;
    case 5:
        isk_fill_circle(c, rnd_coord(r, w), rnd_coord(r, h), rnd_radius(r), col, mode);
        break;
    case 6:
        isk_fill_circle_aa(c, rnd_coord(r, w), rnd_coord(r, h), rnd_radius(r), col, mode);
        break;
    case 7:
        isk_draw_dot(c, rnd_coord(r, w), rnd_coord(r, h), col, mode);
        break;
    case 8:
        isk_stroke_line(c, rnd_coord(r, w), rnd_coord(r, h), rnd_coord(r, w), rnd_coord(r, h), col, mode);
        break;
    case 9: {
        double xy[2 * 12];
        int n = (int)isk_rng_below(r, 13);
        /* mostly finite paths (a single NaN disables the whole path) */
        int wild = isk_rng_below(r, 4) == 0;
        for (int k = 0; k < n; k++) {
            xy[2 * k] = wild ? rnd_coord(r, w) : isk_rng_range(r, -20, w + 20);
            xy[2 * k + 1] = wild ? rnd_coord(r, h) : isk_rng_range(r, -20, h + 20);
            if (k > 0 && isk_rng_below(r, 6) == 0) { /* repeated points */
                xy[2 * k] = xy[2 * k - 2];
                xy[2 * k + 1] = xy[2 * k - 1];
            }
        }
        isk_stroke_polyline(c, xy, n, (int)isk_rng_below(r, 2), col, mode);
        break;
    }
    default: {
        uint8_t wt[4];
        double x = rnd_coord(r, w), y = rnd_coord(r, h);
        int ok = isk_dot_weights(x, y, wt);
        int s = wt[0] + wt[1] + wt[2] + wt[3];
        cr_assert_eq(s, ok ? 255 : 0);
        break;
    }
    }
}

static void check_border(const uint8_t *buf, size_t stride)
{
    for (int y = 0; y < PH; y++)
        for (size_t b = 0; b < stride; b++) {
            int inside = y >= VY && y < VY + VH && b >= (size_t)VX * 4 && b < (size_t)(VX + VW) * 4;
            if (!inside)
                cr_assert_eq(buf[(size_t)y * stride + b], SENTINEL, "byte %zu of row %d changed", b, y);
        }
}

Test(raster_fuzz, random_primitives_stay_inside_the_view)
{
    size_t stride = (size_t)PW * 4 + PAD;
    uint8_t *buf = malloc(stride * PH);
    cr_assert_not_null(buf);
    memset(buf, SENTINEL, stride * PH);
    isk_canvas parent, view;
    cr_assert_eq(isk_canvas_wrap(&parent, buf, PW, PH, stride), ISK_OK);
    cr_assert_eq(isk_canvas_view(&view, &parent, VX, VY, VW, VH), ISK_OK);
    cr_assert_eq(view.width, VW);
    cr_assert_eq(view.height, VH);

    isk_rng rng;
    isk_rng_seed(&rng, 0x15C2A);
    for (int i = 0; i < 100000; i++) {
        draw_random(&view, &rng);
        if (i % 5000 == 4999)
            check_border(buf, stride);
    }
    check_border(buf, stride);
    /* the view itself did get drawn into */
    long changed = 0;
    for (int y = 0; y < VH; y++)
        for (int x = 0; x < VW * 4; x++)
            changed += view.pixels[(size_t)y * stride + (size_t)x] != SENTINEL;
    cr_assert_gt(changed, VW * VH);
    free(buf);
}

Test(raster_fuzz, one_pixel_and_empty_views)
{
    /* Degenerate targets: a 1x1 view and a 0x0 view. */
    size_t stride = (size_t)PW * 4 + PAD;
    uint8_t *buf = malloc(stride * PH);
    cr_assert_not_null(buf);
    memset(buf, SENTINEL, stride * PH);
    isk_canvas parent, one, none;
    cr_assert_eq(isk_canvas_wrap(&parent, buf, PW, PH, stride), ISK_OK);
    cr_assert_eq(isk_canvas_view(&one, &parent, 40, 40, 1, 1), ISK_OK);
    cr_assert_eq(isk_canvas_view(&none, &parent, PW + 5, 0, 3, 3), ISK_OK);
    isk_rng rng;
    isk_rng_seed(&rng, 77);
    for (int i = 0; i < 20000; i++) {
        draw_random(&one, &rng);
        draw_random(&none, &rng);
    }
    for (int y = 0; y < PH; y++)
        for (size_t b = 0; b < stride; b++)
            if (!(y == 40 && b >= 160 && b < 164))
                cr_assert_eq(buf[(size_t)y * stride + b], SENTINEL);
    free(buf);
}
