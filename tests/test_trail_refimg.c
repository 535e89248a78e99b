/* SPDX-License-Identifier: MIT */
/* Reference images of trails (isk_stroke_trail), compared byte for byte with
 * refimg/<name>.png (tests/refimg.h): straight, curved and self-crossing
 * ribbons at widths 1 and 3, fade 0 and 1; the blend modes; a burst of short
 * spark trails, the case the primitive is made for. */
#include <criterion/criterion.h>

#include <math.h>
#include <string.h>

#include "iskra/draw.h"
#include "iskra/rng.h"
#include "refimg_scene.h"

#define PI 3.14159265358979323846


/* n points of a curve through a cell: kind 0 straight, 1 an arc turning
 * 270 degrees, 2 a figure eight (crossing itself), 3 a spiral. */
static int curve(int kind, double x0, double y0, double *xy)
{
    int n = 0;
    for (int k = 0; k < 48; k++) {
        double t = k / 47.0, x, y;
        switch (kind) {
        case 0: x = 8 + 64 * t; y = 10 + 34 * t; break;
        case 1: x = 40 + 24 * cos(1.5 * PI * t); y = 28 + 20 * sin(1.5 * PI * t); break;
        case 2: x = 40 + 28 * sin(2 * PI * t); y = 28 + 18 * sin(4 * PI * t); break;
        default: x = 40 + (4 + 22 * t) * cos(4 * PI * t); y = 28 + (3 + 17 * t) * sin(4 * PI * t); break;
        }
        xy[2 * n] = x0 + x;
        xy[2 * n + 1] = y0 + y;
        n++;
    }
    return n;
}

/* Rows: width 1 fade 0, width 1 fade 1, width 3 fade 0, width 3 fade 1;
 * columns: straight, arc, figure eight, spiral.  Source-over of a
 * translucent colour, so a pixel painted twice would show. */
Test(refimg, trail_shapes)
{
    isk_canvas c = refimg_canvas(320, 224, isk_rgba(18, 20, 30, 255));
    const double widths[4] = {1, 1, 3, 3}, fades[4] = {0, 1, 0, 1};
    double xy[96];
    for (int row = 0; row < 4; row++)
        for (int col = 0; col < 4; col++) {
            int n = curve(col, 80 * col, 56 * row, xy);
            isk_stroke_trail(&c, xy, n, widths[row], isk_rgba(255, 200, 90, 190), fades[row], ISK_BLEND_OVER);
        }
    refimg_expect("trail_shapes", &c);
}

/* Widths 0.25 (drawn at 0.5 px, half alpha), 0.5, 1.5, 6 and one point (a
 * disc) of widths 1 and 6, added in white. */
Test(refimg, trail_widths)
{
    isk_canvas c = refimg_canvas(200, 80, ISK_BLACK);
    const double widths[4] = {0.25, 0.5, 1.5, 6};
    for (int k = 0; k < 4; k++) {
        const double xy[6] = {10, 10.3 + 16 * k, 60, 14 + 16 * k, 110, 9.7 + 16 * k};
        isk_stroke_trail(&c, xy, 3, widths[k], ISK_WHITE, 0.0, ISK_BLEND_ADD);
    }
    const double dot1[2] = {140.5, 20.25}, dot6[2] = {170.3, 40.6};
    isk_stroke_trail(&c, dot1, 1, 1.0, ISK_WHITE, 0.0, ISK_BLEND_ADD);
    isk_stroke_trail(&c, dot6, 1, 6.0, ISK_WHITE, 0.0, ISK_BLEND_ADD);
    refimg_expect("trail_widths", &c);
}

/* Replace, over and add, each over an opaque striped ground (left) and
 * transparent black (right), a figure eight of width 4, fading. */
Test(refimg, trail_blend_modes)
{
    isk_canvas c = refimg_canvas(240, 64, ISK_TRANSPARENT);
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 240; x++)
            if ((x / 40) % 2 == 0) {
                isk_color col = (y / 6) % 2 ? isk_rgba(200, 60, 60, 255) : isk_rgba(40, 40, 120, 255);
                memcpy(isk_canvas_at(&c, x, y), &col, 4);
            }
    const isk_blend modes[3] = {ISK_BLEND_REPLACE, ISK_BLEND_OVER, ISK_BLEND_ADD};
    double xy[96];
    for (int k = 0; k < 3; k++) {
        int n = curve(2, 80 * k, 4, xy);
        isk_stroke_trail(&c, xy, n, 4.0, isk_rgba(120, 255, 160, 220), 0.8, modes[k]);
    }
    refimg_expect("trail_blend_modes", &c);
}

/* A burst: 240 sparks flying out under gravity, each with a trail of its
 * last 4 to 24 positions (a few px long), width 1 to 2, fading to nothing,
 * added. */
Test(refimg, trail_sparks)
{
    isk_canvas c = refimg_canvas(240, 160, isk_rgba(6, 6, 12, 255));
    isk_rng r;
    isk_rng_seed(&r, 31);
    double xy[48];
    for (int k = 0; k < 240; k++) {
        double a = isk_rng_range(&r, 0, 2 * PI), v = isk_rng_range(&r, 40, 110);
        double vx = v * cos(a), vy = v * sin(a) - 30, age = isk_rng_range(&r, 0.3, 0.9);
        int n = 4 + (int)isk_rng_below(&r, 21);
        for (int j = 0; j < n; j++) { /* oldest first: positions at age - (n - 1 - j) dt */
            double t = age - (n - 1 - j) * 0.012;
            if (t < 0)
                t = 0;
            xy[2 * j] = 120 + vx * t;
            xy[2 * j + 1] = 70 + vy * t + 0.5 * 120 * t * t;
        }
        /* one draw a statement: the order of a call's arguments is unspecified
         * (gcc and clang differ), and the image must not depend on it */
        uint8_t blue = (uint8_t)isk_rng_range(&r, 30, 90), green = (uint8_t)isk_rng_range(&r, 120, 230);
        isk_color col = isk_rgba(255, green, blue, 230);
        isk_stroke_trail(&c, xy, n, isk_rng_range(&r, 1.0, 2.0), col, 1.0, ISK_BLEND_ADD);
    }
    refimg_expect("trail_sparks", &c);
}
