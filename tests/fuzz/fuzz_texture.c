/* SPDX-License-Identifier: MIT */
/* libFuzzer target: PNG bytes -> a texture -> drawn, through the public API
 * both ways a program draws one:
 *   - isk_texture_from_canvas, cut into every grid the image divides into
 *     among 1 x 1, 2 x 1, 4 x 2 and 1 x 4, each frame drawn by
 *     isk_draw_texture at sizes from a fraction of a pixel to larger than
 *     the canvas, turned, stretched, half off the canvas, in every blend;
 *   - an effect whose emitters draw it as a texture (one frame, and the
 *     grid animated) and as the streak of a sprite kind, stepped and
 *     rendered.
 * Built and run by `make fuzz-texture` (clang with
 * -fsanitize=fuzzer,address,undefined) and by `make fuzz-smoke`; seeds in
 * tests/fuzz/png_corpus/, scenes/textures/ and tests/fuzz/texture_corpus/
 * (bytes that are no PNG make an image: image_of_bytes), crashers kept in
 * tests/fuzz/texture_regressions/.
 *
 * The library's own limits bound what is accepted (a side up to
 * ISK_TEXTURE_MAX_DIM); the harness sets the budgets a program would, so
 * each input stays quick under the sanitizers: the PNG reader's pixel cap
 * (a megapixel: a header may declare any size, only the cap is decoded)
 * and the effect's memory and work budgets (fuzz_budgets.h), which refuse
 * at create what would be slow. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/png.h"
#include "iskra/texture.h"
#include "fuzz_budgets.h"

#define MAX_PIXELS (1024 * 1024)

static void draw_directly(isk_canvas *c, const isk_canvas *img)
{
    static const int grids[][2] = {{1, 1}, {2, 1}, {4, 2}, {1, 4}};
    static const double sizes[] = {0.25, 1.0, 7.5, 40.0, 300.0};
    static const isk_blend blends[] = {ISK_BLEND_OVER, ISK_BLEND_ADD};
    for (size_t g = 0; g < sizeof grids / sizeof grids[0]; g++) {
        isk_texture t;
        if (isk_texture_from_canvas(&t, img, grids[g][0], grids[g][1]) != ISK_OK)
            continue; /* a grid this image does not divide into */
        for (int f = 0; f < t.frames; f++)
            for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
                for (size_t b = 0; b < sizeof blends / sizeof blends[0]; b++) {
                    const double w = sizes[s], h = sizes[s] * (1.0 + (double)f);
                    isk_draw_texture(c, &t, f, 10.5 + 7.0 * (double)s, 20.25, w, h, 0.7 * (double)(f + s),
                                     isk_rgba(255, 200, 100, 230), blends[b]);
                    isk_draw_texture(c, &t, f, -3.0, (double)c->height + 2.0, w, w, 0.0, isk_rgba(255, 255, 255, 255),
                                     blends[b]);
                }
        isk_texture_free(&t);
    }
}

/* An emitter of 40 particles drawing the texture `name` (cut cols x rows,
 * animated when there is more than one frame) or a streaked sprite. */
static void add_emitter(isk_effect_def *d, const char *name, int cols, int rows, double size)
{
    isk_emitter_def *e = isk_effect_def_add_emitter(d, name[0] ? name : "streak");
    if (!e)
        return;
    e->born.source = ISK_SOURCE_EXPLOSION;
    e->born.count = 40;
    e->born.capacity = 40;
    e->look.draw = ISK_DRAW_SPRITE;
    e->look.size = size;
    if (name[0]) {
        snprintf(e->look.texture, sizeof e->look.texture, "%s", name);
        e->look.texture_grid.x = cols;
        e->look.texture_grid.y = rows;
        e->look.texture_fps = cols * rows > 1 ? 10.0 : 0.0;
    } else {
        e->look.align = ISK_ALIGN_VELOCITY;
    }
}

static void draw_in_an_effect(const isk_canvas *img)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    d.width = 64;
    d.height = 48;
    fuzz_set_budgets(&d);
    if (isk_effect_def_add_texture(&d, "fuzz.png", img, NULL) == ISK_OK) {
        add_emitter(&d, "fuzz.png", 1, 1, 0.3);
        if (img->width % 2 == 0)
            add_emitter(&d, "fuzz.png", 2, 1, 0.05);
        add_emitter(&d, "", 1, 1, 0.1);
        for (int i = 0; i < d.nemitters; i++)
            snprintf(d.emitters[i].name, sizeof d.emitters[i].name, "e%d", i);
        isk_effect *fx;
        if (isk_effect_create(&fx, &d, NULL) == ISK_OK) {
            isk_canvas c;
            if (isk_canvas_init(&c, d.width, d.height) == ISK_OK) {
                for (int f = 0; f < 3; f++)
                    if (isk_effect_step_render(fx, &c) != ISK_OK)
                        break;
                isk_canvas_free(&c);
            }
            isk_effect_destroy(fx);
        }
    }
    isk_effect_def_free(&d);
}

/* Input that is not a PNG: an image made of the bytes, written as a PNG
 * (so it still goes PNG -> texture): bytes 0 and 1 the width and height
 * less one (1..256 each), the rest its pixels, repeated to fill it.  The
 * fuzzer reaches any size, grid and content without forging a CRC. */
static int image_of_bytes(const uint8_t *data, size_t size, isk_canvas *img)
{
    static const uint8_t png_signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (size >= 8 && !memcmp(data, png_signature, 8))
        return isk_png_read_memory(img, data, size, "fuzz.png", MAX_PIXELS, NULL) == ISK_OK;
    if (size < 3)
        return 0;
    isk_canvas made;
    if (isk_canvas_init(&made, data[0] + 1, data[1] + 1) != ISK_OK)
        return 0;
    const size_t row = (size_t)made.width * 4u;
    for (size_t y = 0; y < (size_t)made.height; y++)
        for (size_t x = 0; x < row; x++)
            made.pixels[y * made.stride + x] = data[2 + (y * row + x) % (size - 2)];
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    int ok = f && isk_png_write_stream(&made, f, "fuzz.png", NULL) == ISK_OK && fflush(f) == 0;
    if (f)
        fclose(f);
    ok = ok && isk_png_read_memory(img, buf, len, "fuzz.png", MAX_PIXELS, NULL) == ISK_OK;
    free(buf);
    isk_canvas_free(&made);
    return ok;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    isk_canvas img;
    if (!image_of_bytes(data, size, &img))
        return 0;
    isk_canvas c;
    if (isk_canvas_init(&c, 64, 48) == ISK_OK) {
        draw_directly(&c, &img);
        isk_canvas_free(&c);
    }
    draw_in_an_effect(&img);
    isk_canvas_free(&img);
    return 0;
}
