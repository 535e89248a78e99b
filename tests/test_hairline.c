/* SPDX-License-Identifier: MIT */
/* Anti-aliased hairlines (the browser's width-1 strokes): coverage rule,
 * symmetry, clipping, reference image. */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "iskra/draw.h"
#include "iskra/rng.h"
#include "refimg.h"

/* Coverage written into a transparent canvas with REPLACE: alpha = coverage. */
static int alpha_at(const isk_canvas *c, int x, int y) { return isk_canvas_get(c, x, y).a; }

Test(hairline, horizontal_on_a_pixel_boundary_is_two_rows_127_128)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 40, 20), ISK_OK);
    isk_stroke_hairline(&c, 5, 10, 25, 10, ISK_WHITE, ISK_BLEND_REPLACE);
    for (int x = 0; x < 40; x++) {
        int inside = x >= 5 && x < 25;
        cr_assert_eq(alpha_at(&c, x, 9), inside ? 127 : 0, "x %d", x);
        cr_assert_eq(alpha_at(&c, x, 10), inside ? 128 : 0, "x %d", x);
        cr_assert_eq(alpha_at(&c, x, 8), 0);
        cr_assert_eq(alpha_at(&c, x, 11), 0);
    }
    isk_canvas_free(&c);
}

Test(hairline, centred_in_a_pixel_is_one_crisp_row)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 40, 20), ISK_OK);
    isk_stroke_hairline(&c, 5, 10.5, 25, 10.5, ISK_WHITE, ISK_BLEND_REPLACE);
    for (int x = 5; x < 25; x++) {
        cr_assert_eq(alpha_at(&c, x, 10), 255);
        cr_assert_eq(alpha_at(&c, x, 9), 0);
        cr_assert_eq(alpha_at(&c, x, 11), 0);
    }
    isk_canvas_free(&c);
}

Test(hairline, one_pixel_of_coverage_per_major_step)
{
    /* Any slope: every row (steep) or column (shallow) crossed over its
     * whole length carries 254..255 of coverage on at most 2 pixels. */
    isk_rng r;
    isk_rng_seed(&r, 11);
    for (int k = 0; k < 200; k++) {
        isk_canvas c;
        cr_assert_eq(isk_canvas_init(&c, 64, 64), ISK_OK);
        double x0 = isk_rng_range(&r, 4, 60), y0 = isk_rng_range(&r, 4, 60);
        double x1 = isk_rng_range(&r, 4, 60), y1 = isk_rng_range(&r, 4, 60);
        isk_stroke_hairline(&c, x0, y0, x1, y1, ISK_WHITE, ISK_BLEND_REPLACE);
        int steep = fabs(y1 - y0) >= fabs(x1 - x0);
        double lo = steep ? fmin(y0, y1) : fmin(x0, x1), hi = steep ? fmax(y0, y1) : fmax(x0, x1);
        for (int j = (int)ceil(lo); j + 1 <= (int)floor(hi); j++) {
            int sum = 0, lit = 0;
            for (int i = 0; i < 64; i++) {
                int a = steep ? alpha_at(&c, i, j) : alpha_at(&c, j, i);
                sum += a;
                lit += a > 0;
            }
            cr_assert(sum >= 254 && sum <= 255, "line %d: step %d has coverage %d", k, j, sum);
            cr_assert_leq(lit, 2);
        }
        isk_canvas_free(&c);
    }
}

Test(hairline, direction_does_not_matter)
{
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, 80, 80), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 80, 80), ISK_OK);
    isk_stroke_hairline(&a, 3.3, 70.125, 77.5, 9.75, ISK_WHITE, ISK_BLEND_ADD);
    isk_stroke_hairline(&b, 77.5, 9.75, 3.3, 70.125, ISK_WHITE, ISK_BLEND_ADD);
    cr_assert(isk_canvas_equal(&a, &b));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(hairline, extreme_coordinates_stay_inside)
{
    uint8_t mem[48 * 4 * 40];
    memset(mem, 0xAB, sizeof mem);
    isk_canvas big, c;
    cr_assert_eq(isk_canvas_wrap(&big, mem, 48, 40, 48 * 4), ISK_OK);
    cr_assert_eq(isk_canvas_view(&c, &big, 8, 8, 32, 24), ISK_OK);
    const double v[] = {-1e300, -1e9, -3.5, 0, 0.5, 16.25, 31.9, 32, 1e9, 1e300, INFINITY, -INFINITY, NAN};
    const int nv = (int)(sizeof v / sizeof v[0]);
    for (int a = 0; a < nv; a++)
        for (int b = 0; b < nv; b++) {
            isk_stroke_hairline(&c, v[a], v[b], v[(a + 3) % nv], v[(b + 5) % nv], ISK_RED, ISK_BLEND_OVER);
            isk_stroke_hairline(&c, v[a], 5, v[b], 20, ISK_RED, ISK_BLEND_OVER);
        }
    const double path[] = {-1e300, 3, 10, 1e300, NAN, 4, 20, 20};
    isk_stroke_polyline_hairline(&c, path, 4, 1, ISK_RED, ISK_BLEND_OVER);
    for (int y = 0; y < 40; y++)
        for (int x = 0; x < 48; x++)
            if (!(x >= 8 && x < 40 && y >= 8 && y < 32))
                cr_assert_eq(mem[(y * 48 + x) * 4], 0xAB, "(%d,%d) touched", x, y);
}

Test(refimg, stroke_hairline)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 160, 120), ISK_OK);
    isk_canvas_fill(&c, ISK_WHITE);
    for (int k = 0; k < 24; k++) {
        double t = k * 6.283185307179586 / 24;
        isk_stroke_hairline(&c, 60, 60, 60 + 50 * cos(t), 60 + 50 * sin(t), ISK_BLACK, ISK_BLEND_OVER);
    }
    const double tri[] = {130, 20, 115.5, 50.25, 149.75, 50.25};
    isk_stroke_polyline_hairline(&c, tri, 3, 1, ISK_GREEN, ISK_BLEND_OVER);
    isk_stroke_hairline(&c, 112, 80, 152, 80, ISK_BLUE, ISK_BLEND_OVER);
    isk_stroke_hairline(&c, 112, 90.5, 152, 90.5, ISK_BLUE, ISK_BLEND_OVER);
    cr_assert(refimg_check("stroke_hairline", &c));
    isk_canvas_free(&c);
}
