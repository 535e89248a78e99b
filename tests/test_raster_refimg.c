/* SPDX-License-Identifier: MIT */
/* Reference images for the rasterizer primitives: one small scene per
 * primitive, compared byte for byte with refimg/<name>.png (tests/refimg.h).
 * Regenerate on purpose with ISKRA_REFIMG_UPDATE=1 and look at the result. */
#include <criterion/criterion.h>

#include <math.h>

#include "iskra/draw.h"
#include "refimg_scene.h"

#define PI 3.14159265358979323846


Test(refimg, pixel_rect)
{
    isk_canvas c = refimg_canvas(64, 64, isk_rgba(20, 20, 40, 255));
    for (int i = 0; i < 16; i++)
        isk_draw_pixel(&c, 2 + 2 * i, 2, isk_rgba((uint8_t)(16 * i), 255, 128, 255), ISK_BLEND_REPLACE);
    isk_fill_rect(&c, 4, 8, 20, 12, ISK_RED, ISK_BLEND_REPLACE);
    isk_fill_rect(&c, 14, 14, 20, 12, isk_rgba(0, 0, 255, 128), ISK_BLEND_OVER);
    isk_fill_rect(&c, 40, 40, -12, -8, ISK_YELLOW, ISK_BLEND_REPLACE); /* negative size */
    isk_fill_rect(&c, 56, 30, 100, 10, ISK_GREEN, ISK_BLEND_REPLACE);  /* clipped right */
    isk_fill_rect(&c, -5, 50, 20, 100, ISK_WHITE, ISK_BLEND_REPLACE);  /* clipped left/bottom */
    isk_fill_rect(&c, 30, 48, 20, 10, isk_rgba(255, 0, 0, 160), ISK_BLEND_ADD);
    refimg_expect("pixel_rect", &c);
}

Test(refimg, line_bresenham)
{
    isk_canvas c = refimg_canvas(128, 128, ISK_BLACK);
    for (int k = 0; k < 32; k++) {
        double a = 2.0 * PI * k / 32.0;
        isk_color col = isk_rgba((uint8_t)(128 + 127 * cos(a)), (uint8_t)(128 + 127 * sin(a)), 255, 255);
        /* spokes alternate between fitting inside and running off the canvas */
        double len = k % 2 ? 58.0 : 90.0;
        isk_draw_line(&c, 64.5, 64.5, 64.5 + len * cos(a), 64.5 + len * sin(a), col, ISK_BLEND_REPLACE);
    }
    isk_draw_line(&c, 2.5, 125.5, 125.5, 125.5, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_draw_line(&c, 2.5, 2.5, 2.5, 125.5, ISK_WHITE, ISK_BLEND_REPLACE);
    refimg_expect("line_bresenham", &c);
}

Test(refimg, stroke_line)
{
    isk_canvas c = refimg_canvas(128, 128, ISK_WHITE);
    /* integer end points (straddling pixel edges) on the left half,
     * fractional ones on the right half */
    for (int k = 0; k <= 8; k++) {
        double a = PI / 2.0 * k / 8.0;
        isk_stroke_line(&c, 4, 4, 4 + 56 * cos(a), 4 + 56 * sin(a), ISK_BLACK, ISK_BLEND_OVER);
        isk_stroke_line(&c, 68.3, 4.7, 68.3 + 56 * cos(a), 4.7 + 56 * sin(a), ISK_BLACK, ISK_BLEND_OVER);
    }
    /* horizontal lines at y = n, n + 0.25, n + 0.5 and a vertical pair */
    isk_stroke_line(&c, 8, 80, 60, 80, ISK_BLACK, ISK_BLEND_OVER);
    isk_stroke_line(&c, 8, 86.25, 60, 86.25, ISK_BLACK, ISK_BLEND_OVER);
    isk_stroke_line(&c, 8, 92.5, 60, 92.5, ISK_BLACK, ISK_BLEND_OVER);
    isk_stroke_line(&c, 80, 72, 80, 124, ISK_RED, ISK_BLEND_OVER);
    isk_stroke_line(&c, 90.5, 72.3, 90.5, 123.6, ISK_RED, ISK_BLEND_OVER);
    isk_stroke_line(&c, 100.2, 75.1, 124.9, 120.4, ISK_BLUE, ISK_BLEND_OVER);
    refimg_expect("stroke_line", &c);
}

Test(refimg, stroke_polyline)
{
    isk_canvas c = refimg_canvas(200, 120, ISK_WHITE);
    /* the thesis's figure 1 triangle, scaled down: open, start/end with butt caps */
    const double tri[8] = {50, 10, 20, 50, 80, 50, 50, 10};
    isk_stroke_polyline(&c, tri, 4, 0, ISK_BLACK, ISK_BLEND_OVER);
    /* the same triangle closed: miter joins at every vertex */
    const double tri2[6] = {150, 10, 120, 50, 180, 50};
    isk_stroke_polyline(&c, tri2, 3, 1, ISK_BLACK, ISK_BLEND_OVER);
    /* zigzag with ever sharper turns: miters, then bevels past the limit */
    const double zig[14] = {10, 110, 30, 70, 45, 110, 55, 70, 62, 110, 66, 70, 68, 110};
    isk_stroke_polyline(&c, zig, 7, 0, isk_rgba(0, 0, 200, 255), ISK_BLEND_OVER);
    /* translucent closed star: joins and overlaps must not be darker */
    double star[10];
    for (int k = 0; k < 5; k++) {
        double a = -PI / 2 + k * 4.0 * PI / 5.0;
        star[2 * k] = 140 + 30 * cos(a);
        star[2 * k + 1] = 88 + 30 * sin(a);
    }
    isk_stroke_polyline(&c, star, 5, 1, isk_rgba(200, 0, 0, 160), ISK_BLEND_OVER);
    refimg_expect("stroke_polyline", &c);
}

Test(refimg, triangle_outline)
{
    isk_canvas c = refimg_canvas(96, 96, ISK_BLACK);
    isk_draw_triangle(&c, 10.5, 10.5, 85.5, 20.5, 30.5, 85.5, ISK_YELLOW, ISK_BLEND_REPLACE);
    isk_draw_triangle(&c, 50, 40, 90, 90, 40, 70, isk_rgba(0, 255, 255, 128), ISK_BLEND_ADD);
    isk_draw_triangle(&c, 5, 90, 20, 60, 35, 91, ISK_RED, ISK_BLEND_REPLACE);
    isk_draw_triangle(&c, 70, -20, 120, 10, 60, 30, ISK_GREEN, ISK_BLEND_REPLACE); /* clipped */
    refimg_expect("triangle_outline", &c);
}

Test(refimg, triangle_fill)
{
    isk_canvas c = refimg_canvas(96, 96, ISK_BLACK);
    /* a translucent additive fan: a shared edge drawn twice would show as a
     * brighter seam */
    const double cx = 48.3, cy = 47.6;
    for (int k = 0; k < 9; k++) {
        double a0 = 2 * PI * k / 9, a1 = 2 * PI * (k + 1) / 9;
        isk_color col = isk_rgba((uint8_t)(60 + 20 * k), 90, (uint8_t)(220 - 20 * k), 140);
        isk_fill_triangle(&c, cx, cy, cx + 40 * cos(a0), cy + 40 * sin(a0), cx + 40 * cos(a1),
                          cy + 40 * sin(a1), col, ISK_BLEND_ADD);
    }
    isk_fill_triangle(&c, -10, 80, 20, 120, 30, 70, ISK_WHITE, ISK_BLEND_REPLACE); /* clipped */
    isk_fill_triangle(&c, 80.5, 2.5, 94.5, 2.5, 94.5, 16.5, ISK_YELLOW, ISK_BLEND_REPLACE);
    refimg_expect("triangle_fill", &c);
}

Test(refimg, fill_circle)
{
    isk_canvas c = refimg_canvas(160, 48, ISK_BLACK);
    for (int r = 1; r <= 8; r++) {
        isk_fill_circle(&c, 10 + 19 * (r - 1), 12, r, ISK_WHITE, ISK_BLEND_REPLACE);      /* integer centre */
        isk_fill_circle(&c, 10.5 + 19 * (r - 1), 34.5, r, ISK_YELLOW, ISK_BLEND_REPLACE); /* pixel centre */
    }
    refimg_expect("fill_circle", &c);
}

Test(refimg, fill_circle_aa)
{
    isk_canvas c = refimg_canvas(128, 64, ISK_BLACK);
    const double rs[6] = {0.5, 1.3, 2.75, 5.0, 9.6, 14.2};
    for (int k = 0; k < 6; k++)
        isk_fill_circle_aa(&c, 8 + k * 20 + 0.1 * k, 16.3, rs[k], ISK_WHITE, ISK_BLEND_OVER);
    isk_fill_circle_aa(&c, 40, 48, 12, isk_rgba(255, 0, 0, 200), ISK_BLEND_OVER);
    isk_fill_circle_aa(&c, 52.5, 48.5, 12, isk_rgba(0, 255, 0, 200), ISK_BLEND_ADD);
    isk_fill_circle_aa(&c, 120, 60, 20, ISK_BLUE, ISK_BLEND_OVER); /* clipped */
    refimg_expect("fill_circle_aa", &c);
}

Test(refimg, coverage_dot)
{
    /* Dot (i, j) of an 8x8 grid sits at offset (i/8, j/8) from its cell. */
    isk_canvas c = refimg_canvas(64, 64, ISK_BLACK);
    for (int j = 0; j < 8; j++)
        for (int i = 0; i < 8; i++)
            isk_draw_dot(&c, 2 + 8 * i + i / 8.0, 2 + 8 * j + j / 8.0, ISK_YELLOW, ISK_BLEND_OVER);
    /* dots half off each edge */
    isk_draw_dot(&c, -0.5, 30.25, ISK_WHITE, ISK_BLEND_OVER);
    isk_draw_dot(&c, 63.5, 30.75, ISK_WHITE, ISK_BLEND_OVER);
    refimg_expect("coverage_dot", &c);
}

Test(refimg, blend_modes)
{
    /* Three panels (replace, over, add), each with overlapping translucent
     * red, green and blue discs and rectangles on a grey background. */
    isk_canvas c = refimg_canvas(192, 64, isk_rgba(64, 64, 64, 255));
    for (int m = 0; m < 3; m++) {
        isk_blend mode = (isk_blend)m;
        double ox = 64.0 * m;
        isk_fill_circle_aa(&c, ox + 24, 24, 16, isk_rgba(255, 0, 0, 160), mode);
        isk_fill_circle_aa(&c, ox + 40, 24, 16, isk_rgba(0, 255, 0, 160), mode);
        isk_fill_circle(&c, ox + 32, 38, 16, isk_rgba(0, 0, 255, 160), mode);
        isk_fill_rect(&c, (int)ox + 4, 50, 40, 10, isk_rgba(255, 255, 255, 100), mode);
        isk_stroke_line(&c, ox + 2, 62, ox + 62, 40, isk_rgba(255, 255, 0, 200), mode);
        for (int k = 0; k < 6; k++)
            isk_draw_dot(&c, ox + 50 + k * 1.5, 54.5, isk_rgba(255, 255, 255, 255), mode);
    }
    refimg_expect("blend_modes", &c);
}
