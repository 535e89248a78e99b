/* SPDX-License-Identifier: MIT */
/* The README's first program: a circle and some text, written to a PNG. */
#include <iskra.h>
#include <stdio.h>

int main(void)
{
    isk_canvas c;
    if (isk_canvas_init(&c, 200, 120) != ISK_OK) return 1;
    isk_canvas_fill(&c, ISK_BLACK);
    isk_fill_circle_aa(&c, 60, 60, 40, ISK_YELLOW, ISK_BLEND_OVER);
    isk_draw_text(&c, 110, 52, "iskra", 2, ISK_WHITE, ISK_BLEND_OVER);
    isk_error err;
    if (isk_png_write(&c, "hello.png", &err) != ISK_OK) { fprintf(stderr, "%s\n", err.message); return 1; }
    isk_canvas_free(&c);
    return 0;
}
