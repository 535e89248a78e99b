/* tools/looks_texture.h — the sprite sheet of scenes/textures/arrows.png,
 * drawn with the library (header-only, shared by tools/gen_looks_texture.c,
 * which writes the file, and tests/test_fx_looks.c, which checks that the
 * committed file is exactly this drawing).
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

#endif
