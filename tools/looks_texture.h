/* SPDX-License-Identifier: MIT */
/* tools/looks_texture.h — the textures of the scenes in scenes/textures/,
 * drawn with the library (header-only, shared by tools/gen_looks_texture.c,
 * which writes the files, and tests/test_fx_looks.c, which checks that the
 * committed files are exactly these drawings): arrows.png (below) and
 * sparkle.png (looks_sparkle_draw, the magic preset's scene).
 *
 * A 4 x 2 sheet of 16x16 frames.  Every frame is a white arrow pointing
 * right (+x: the direction a texture's angle turns) on transparent black,
 * with a half-transparent rim, so a tint colours it and a rotation shows;
 * frame k has k + 1 pixels of a grey tick row under the shaft, so each
 * frame of a flipbook can be told from the others.
 *
 *     isk_canvas img;
 *     if (looks_texture_draw(&img) != ISK_OK) return 1;   // 64x32
 */
#ifndef ISKRA_TOOLS_LOOKS_TEXTURE_H
#define ISKRA_TOOLS_LOOKS_TEXTURE_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/canvas.h"
#include "iskra/color.h"

#define LOOKS_TEXTURE_COLS 4
#define LOOKS_TEXTURE_ROWS 2
#define LOOKS_TEXTURE_FRAME 16

static inline void looks_texture_set(isk_canvas *c, int x, int y, isk_color col)
{
    if (x >= 0 && y >= 0 && x < c->width && y < c->height)
        memcpy(isk_canvas_at(c, x, y), &col, 4);
}

static inline isk_status looks_texture_draw(isk_canvas *img)
{
    const int F = LOOKS_TEXTURE_FRAME;
    isk_status s = isk_canvas_init(img, F * LOOKS_TEXTURE_COLS, F * LOOKS_TEXTURE_ROWS);
    if (s != ISK_OK)
        return s;
    isk_canvas_fill(img, ISK_TRANSPARENT);
    for (int k = 0; k < LOOKS_TEXTURE_COLS * LOOKS_TEXTURE_ROWS; k++) {
        const int ox = (k % LOOKS_TEXTURE_COLS) * F, oy = (k / LOOKS_TEXTURE_COLS) * F;
        for (int y = 0; y < F; y++)
            for (int x = 0; x < F; x++) {
                int shaft = x >= 2 && x < 10 && y >= 6 && y < 10;
                int head = x >= 10 && x < 15 && abs(2 * y - 15) < 2 * (15 - x); /* tip at x = 14 */
                int tick = y == 12 && x >= 2 && x < 3 + k;
                if (shaft || head)
                    looks_texture_set(img, ox + x, oy + y, ISK_WHITE);
                else if (tick)
                    looks_texture_set(img, ox + x, oy + y, isk_rgba(160, 160, 160, 255));
                else if ((x >= 1 && x < 11 && y >= 5 && y < 11) || (x >= 9 && x < 16 && abs(2 * y - 15) < 2 * (16 - x)))
                    looks_texture_set(img, ox + x, oy + y, isk_rgba(255, 255, 255, 128)); /* the rim */
            }
    }
    return ISK_OK;
}

/* sparkle.png: a 32x32 white four-pointed star on transparent black, its
 * alpha the brightest of a soft core (1 - r/0.4) and two thin rays along
 * the axes that taper to their tips, so a spin shows and a tint colours it.
 * Pixel centres at (x + 0.5, y + 0.5) over [-1, 1]^2; only + - * / and
 * sqrt, so the bytes are the same everywhere. */
#define LOOKS_SPARKLE_SIZE 32

static inline double looks_sparkle_ray(double along, double across)
{
    const double a = along < 0 ? -along : along, c = across < 0 ? -across : across;
    if (a >= 1.0)
        return 0.0;
    const double w = 0.16 * (1.0 - a) + 0.01; /* half-width, tapering to the tip */
    return c >= w ? 0.0 : (1.0 - a) * (1.0 - c / w);
}

static inline isk_status looks_sparkle_draw(isk_canvas *img)
{
    const int S = LOOKS_SPARKLE_SIZE;
    isk_status s = isk_canvas_init(img, S, S);
    if (s != ISK_OK)
        return s;
    isk_canvas_fill(img, ISK_TRANSPARENT);
    for (int y = 0; y < S; y++)
        for (int x = 0; x < S; x++) {
            const double u = (2.0 * x + 1.0) / S - 1.0, v = (2.0 * y + 1.0) / S - 1.0;
            const double r = sqrt(u * u + v * v);
            double a = r < 0.4 ? 1.0 - r / 0.4 : 0.0, rx = looks_sparkle_ray(u, v), ry = looks_sparkle_ray(v, u);
            a = a > rx ? a : rx;
            a = a > ry ? a : ry;
            const int alpha = (int)(255.0 * a + 0.5);
            if (alpha > 0)
                looks_texture_set(img, x, y, isk_rgba(255, 255, 255, (uint8_t)alpha));
        }
    return ISK_OK;
}

#endif
