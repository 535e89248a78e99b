/* Writes scenes/textures/arrows.png, the sprite sheet of the looks' scenes
 * and tests (tools/looks_texture.h draws it), with the library's own PNG
 * writer, so the repository holds no image made elsewhere:
 *
 *     cc -std=c11 -Iinclude tools/gen_looks_texture.c build/lib/libiskra.a -lpng -lz -lm -o gen_looks_texture
 *     ./gen_looks_texture scenes/textures/arrows.png
 *
 * tests/test_fx_looks.c checks that the committed file is this drawing. */
#include <stdio.h>

#include "iskra/png.h"
#include "looks_texture.h"

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s OUT.png\n", argv[0]);
        return 2;
    }
    isk_canvas img;
    if (looks_texture_draw(&img) != ISK_OK) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    isk_error err;
    isk_status s = isk_png_write(&img, argv[1], &err);
    isk_canvas_free(&img);
    if (s != ISK_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    return 0;
}
