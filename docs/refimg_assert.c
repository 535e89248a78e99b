/* SPDX-License-Identifier: MIT */
/* A pixel-exact test of your own drawing with nothing but assert().
 *
 *     cc refimg_assert.c -o refimg_assert $(pkg-config --cflags --libs iskra)
 *     ISKRA_REFIMG_UPDATE=1 ./refimg_assert   # first run: writes ref/badge.png (look at it)
 *     ./refimg_assert                         # from then on: exact comparison
 *
 * On a mismatch it prints how many pixels differ and by how much and leaves
 * out/refimg/badge.actual.png and out/refimg/badge.diff.png (differences in
 * magenta); the assert then fails. */
#include <assert.h>
#include <iskra.h>
#include <stdio.h>

/* What is under test: your own rendering code. */
static void draw_badge(isk_canvas *c)
{
    isk_canvas_fill(c, isk_rgba(20, 24, 40, 255));
    isk_fill_circle_aa(c, 16, 16, 11, ISK_YELLOW, ISK_BLEND_OVER);
    isk_draw_text(c, 32, 12, "ok", 1, ISK_WHITE, ISK_BLEND_OVER);
}

int main(void)
{
    isk_canvas c;
    if (isk_canvas_init(&c, 64, 32) != ISK_OK)
        return 1;
    draw_badge(&c);
    isk_refimg_opts opts = {0}; /* exact; ISKRA_REFIMG_UPDATE=1 rewrites the reference */
    opts.out_dir = "out/refimg";
    isk_error err;
    isk_status s = isk_refimg_check(&c, "ref/badge.png", &opts, &err);
    if (s != ISK_OK)
        fprintf(stderr, "%s\n", err.message);
    assert(s == ISK_OK);
    isk_canvas_free(&c);
    return 0;
}
