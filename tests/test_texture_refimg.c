/* SPDX-License-Identifier: MIT */
/* Reference images of textured sprites (iskra/texture.h), compared byte for
 * byte with refimg/<name>.png (tests/refimg.h): rotations, sizes (mip
 * levels), a flipbook, tints, the blend modes, and streaks made from a
 * sprite kind.  The textures are made here, so the images depend on
 * nothing but the library. */
#include <criterion/criterion.h>

#include <math.h>
#include <string.h>

#include "iskra/draw.h"
#include "iskra/text.h"
#include "iskra/texture.h"
#include "refimg_scene.h"

#define PI 3.14159265358979323846


static void set(isk_canvas *c, int x, int y, isk_color col)
{
    if (x >= 0 && y >= 0 && x < c->width && y < c->height)
        memcpy(isk_canvas_at(c, x, y), &col, 4);
}

/* 32x32: an arrow pointing right (+x: the direction `angle` turns), its
 * shaft shading from red to yellow along x, a blue square at the top-left
 * (so a mirror image cannot pass for a rotation), a half-transparent rim,
 * transparent elsewhere. */
static isk_texture arrow(void)
{
    isk_canvas img = refimg_canvas(32, 32, ISK_TRANSPARENT);
    for (int y = 0; y < 32; y++)
        for (int x = 0; x < 32; x++) {
            int shaft = x >= 3 && x < 21 && y >= 13 && y < 19;
            int head = x >= 21 && x < 30 && abs(y - 16) < 30 - x; /* tip at x = 29 */
            if (shaft || head)
                set(&img, x, y, isk_rgba(255, (uint8_t)(60 + 6 * x), 20, 255));
            if (x >= 3 && x < 10 && y >= 3 && y < 10)
                set(&img, x, y, isk_rgba(40, 120, 255, 255));
        }
    /* a rim of alpha 128 around everything drawn */
    isk_canvas rim = refimg_canvas(32, 32, ISK_TRANSPARENT);
    for (int y = 0; y < 32; y++)
        for (int x = 0; x < 32; x++) {
            if (isk_canvas_get(&img, x, y).a)
                continue;
            for (int k = 0; k < 4; k++) {
                int nx = x + (k == 0) - (k == 1), ny = y + (k == 2) - (k == 3);
                isk_color n = isk_canvas_get(&img, nx, ny);
                if (n.a == 255) {
                    n.a = 128;
                    set(&rim, x, y, n);
                    break;
                }
            }
        }
    for (int y = 0; y < 32; y++)
        for (int x = 0; x < 32; x++)
            if (isk_canvas_get(&rim, x, y).a)
                set(&img, x, y, isk_canvas_get(&rim, x, y));
    isk_texture t;
    cr_assert_eq(isk_texture_from_canvas(&t, &img, 1, 1), ISK_OK);
    isk_canvas_free(&img);
    isk_canvas_free(&rim);
    return t;
}

/* A 4 x 2 sheet of 16x16 frames: frame k a rounded tile of its own colour
 * with the digit k. */
static isk_texture digits(void)
{
    isk_canvas img = refimg_canvas(64, 32, ISK_TRANSPARENT);
    for (int k = 0; k < 8; k++) {
        int fx = (k % 4) * 16, fy = (k / 4) * 16;
        isk_color col = isk_rgba((uint8_t)(k & 1 ? 230 : 60), (uint8_t)(k & 2 ? 200 : 70), (uint8_t)(k & 4 ? 240 : 50), 255);
        for (int y = 1; y < 15; y++)
            for (int x = 1; x < 15; x++) {
                int corner = (x == 1 || x == 14) && (y == 1 || y == 14);
                if (!corner)
                    set(&img, fx + x, fy + y, col);
            }
        char s[2] = {(char)('0' + k), 0};
        isk_draw_text(&img, fx + 5, fy + 4, s, 1, ISK_WHITE, ISK_BLEND_REPLACE);
    }
    isk_texture t;
    cr_assert_eq(isk_texture_from_canvas(&t, &img, 4, 2), ISK_OK);
    isk_canvas_free(&img);
    return t;
}

static const double DEG = PI / 180.0;

/* 0, 30, 90 and 180 degrees (clockwise on screen) at 32 x 32 (one texel
 * per pixel), then 48 x 24 (stretched along the arrow, squeezed across). */
Test(refimg, texture_rotations)
{
    isk_texture t = arrow();
    isk_canvas c = refimg_canvas(200, 112, isk_rgba(24, 28, 40, 255));
    const double deg[4] = {0, 30, 90, 180};
    for (int k = 0; k < 4; k++) {
        isk_draw_texture(&c, &t, 0, 25 + 50 * k, 26, 32, 32, deg[k] * DEG, ISK_WHITE, ISK_BLEND_OVER);
        isk_draw_texture(&c, &t, 0, 25.5 + 50 * k, 82.25, 48, 24, deg[k] * DEG, ISK_WHITE, ISK_BLEND_OVER);
    }
    refimg_expect("texture_rotations", &c);
    isk_texture_free(&t);
}

/* One texture from 4 px to 96 px: 8 texels per pixel (level 3) up to a
 * 3x magnification (level 0, bilinear), unrotated and at 30 degrees. */
Test(refimg, texture_scales)
{
    isk_texture t = arrow();
    isk_canvas c = refimg_canvas(260, 200, isk_rgba(24, 28, 40, 255));
    const double size[6] = {4, 8, 16, 24, 48, 96};
    double x = 6;
    for (int k = 0; k < 6; k++) {
        double s = size[k], cx = x + s / 2;
        isk_draw_texture(&c, &t, 0, cx, k < 5 ? 30 : 52, s, s, 0.0, ISK_WHITE, ISK_BLEND_OVER);
        isk_draw_texture(&c, &t, 0, cx, k < 5 ? 90 : 150, s, s, 30 * DEG, ISK_WHITE, ISK_BLEND_OVER);
        x += s + 6;
    }
    refimg_expect("texture_scales", &c);
    isk_texture_free(&t);
}

/* Every frame of a 4 x 2 sheet at 1 and 2 texels per pixel... and 2.5x, one
 * rotated; frames -1 and 99 clamp to the first and the last. */
Test(refimg, texture_flipbook)
{
    isk_texture t = digits();
    isk_canvas c = refimg_canvas(208, 96, isk_rgba(16, 16, 16, 255));
    for (int k = 0; k < 8; k++) {
        isk_draw_texture(&c, &t, k, 12 + 20 * k, 12, 16, 16, 0.0, ISK_WHITE, ISK_BLEND_OVER);
        isk_draw_texture(&c, &t, k, 12 + 20 * k, 34, 8, 8, 0.0, ISK_WHITE, ISK_BLEND_OVER);
    }
    isk_draw_texture(&c, &t, -1, 180, 12, 16, 16, 0.0, ISK_WHITE, ISK_BLEND_OVER);
    isk_draw_texture(&c, &t, 99, 198, 12, 16, 16, 0.0, ISK_WHITE, ISK_BLEND_OVER);
    isk_draw_texture(&c, &t, 3, 40, 70, 40, 40, 0.0, ISK_WHITE, ISK_BLEND_OVER);
    isk_draw_texture(&c, &t, 5, 100, 70, 40, 40, 20 * DEG, ISK_WHITE, ISK_BLEND_OVER);
    isk_draw_texture(&c, &t, 6, 160, 70, 40, 20, -45 * DEG, ISK_WHITE, ISK_BLEND_OVER);
    refimg_expect("texture_flipbook", &c);
    isk_texture_free(&t);
}

/* Tints: white (unchanged), red, cyan, a grey, and white at alpha 160
 * and 64 over a striped background. */
Test(refimg, texture_tint)
{
    isk_texture t = arrow();
    isk_canvas c = refimg_canvas(230, 48, isk_rgba(24, 28, 40, 255));
    for (int x = 0; x < 230; x += 8)
        isk_fill_rect(&c, x, 0, 4, 48, isk_rgba(60, 60, 70, 255), ISK_BLEND_REPLACE);
    const isk_color tints[6] = {ISK_WHITE, {255, 64, 64, 255}, {64, 255, 255, 255}, {128, 128, 128, 255},
                                {255, 255, 255, 160}, {255, 255, 255, 64}};
    for (int k = 0; k < 6; k++)
        isk_draw_texture(&c, &t, 0, 22 + 37 * k, 24, 32, 32, -15 * DEG, tints[k], ISK_BLEND_OVER);
    refimg_expect("texture_tint", &c);
    isk_texture_free(&t);
}

/* The three modes, each over the striped opaque background (left half of
 * its cell) and over transparent black (right half), one unrotated and
 * one at 45 degrees: replace writes the sample (transparent texels too
 * where the frame covers, alpha 0 leaves the pixel), over composites,
 * add saturates. */
Test(refimg, texture_blend_modes)
{
    isk_texture t = arrow();
    isk_canvas c = refimg_canvas(240, 84, ISK_TRANSPARENT);
    for (int y = 0; y < 84; y++)
        for (int x = 0; x < 240; x++)
            if ((x / 40) % 2 == 0)
                set(&c, x, y, (y / 6) % 2 ? isk_rgba(200, 60, 60, 255) : isk_rgba(40, 40, 120, 255));
    const isk_blend modes[3] = {ISK_BLEND_REPLACE, ISK_BLEND_OVER, ISK_BLEND_ADD};
    for (int k = 0; k < 3; k++) {
        double x0 = 80 * k;
        isk_draw_texture(&c, &t, 0, x0 + 40, 21, 40, 36, 0.0, isk_rgba(255, 255, 255, 220), modes[k]);
        isk_draw_texture(&c, &t, 0, x0 + 40, 62, 32, 32, 45 * DEG, ISK_WHITE, modes[k]);
    }
    refimg_expect("texture_blend_modes", &c);
    isk_texture_free(&t);
}

/* Streaks (align = velocity): the linear and smooth sprite kinds as
 * textures, stretched along their velocity's angle, lengths 6..40 px,
 * widths 2..6 px, added over a dark background: sparks and rain. */
Test(refimg, texture_streaks)
{
    isk_texture lin, smo;
    cr_assert_eq(isk_texture_from_sprite(&lin, ISK_SPRITE_LINEAR, 32), ISK_OK);
    cr_assert_eq(isk_texture_from_sprite(&smo, ISK_SPRITE_SMOOTH, 32), ISK_OK);
    isk_canvas c = refimg_canvas(200, 120, isk_rgba(8, 8, 16, 255));
    for (int k = 0; k < 12; k++) {
        double a = 2 * PI * k / 12, len = 6 + 34 * (k % 4) / 3.0;
        double vx = cos(a), vy = sin(a);
        isk_draw_texture(&c, &lin, 0, 60 + 32 * vx, 60 + 32 * vy, len, 2 + (k % 3) * 2, atan2(vy, vx),
                         isk_rgba(255, 190, 80, 255), ISK_BLEND_ADD);
    }
    for (int k = 0; k < 10; k++) /* rain falling down and to the right */
        isk_draw_texture(&c, &smo, 0, 130 + 6.3 * k, 20 + 9.7 * k, 24, 3, atan2(5.0, 1.0),
                         isk_rgba(150, 190, 255, 200), ISK_BLEND_ADD);
    refimg_expect("texture_streaks", &c);
    isk_texture_free(&lin);
    isk_texture_free(&smo);
}
