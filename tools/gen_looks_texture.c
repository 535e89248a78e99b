/* SPDX-License-Identifier: MIT */
/* Writes the textures of scenes/textures/ (tools/looks_texture.h draws
 * them) with the library's own PNG writer, so the repository holds no image
 * made elsewhere:
 *
 *     cc -std=c11 -Iinclude tools/gen_looks_texture.c build/lib/libiskra.a -lpng -lz -lm -o gen_looks_texture
 *     ./gen_looks_texture arrows scenes/textures/arrows.png
 *     ./gen_looks_texture sparkle scenes/textures/sparkle.png
 *
 * tests/test_fx_looks.c checks that the committed files are these drawings. */
#include <stdio.h>
#include <string.h>

#include "iskra/png.h"
#include "looks_texture.h"

int main(int argc, char **argv)
{
    if (argc != 3 || (strcmp(argv[1], "arrows") && strcmp(argv[1], "sparkle"))) {
        fprintf(stderr, "usage: %s arrows|sparkle OUT.png\n", argv[0]);
        return 2;
    }
    isk_canvas img;
    if ((!strcmp(argv[1], "arrows") ? looks_texture_draw(&img) : looks_sparkle_draw(&img)) != ISK_OK) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    isk_error err;
    isk_status s = isk_png_write(&img, argv[2], &err);
    isk_canvas_free(&img);
    if (s != ISK_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    return 0;
}
