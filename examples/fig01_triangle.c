/* SPDX-License-Identifier: MIT */
/* Thesis figure 1: one stroked triangle on a 500x500 canvas.
 *
 * The thesis's first canvas example: a path moveTo(250,200), lineTo(175,300),
 * lineTo(325,300), lineTo(250,200) and stroke() with the defaults (black,
 * width 1).  The path returns to its start with lineTo, not closePath, so the
 * apex has two butt ends while the base corners get miter joins.  Integer
 * coordinates lie on pixel boundaries, so each edge covers two half-lit
 * pixels: this is what an anti-aliased width-1 line looks like.
 */
#include "example.h"

int main(int argc, char **argv)
{
    example_opts o = {0};
    example_parse(argc, argv, &o, 0, "fig01_triangle", "thesis figure 1: a stroked triangle");

    isk_canvas c;
    if (isk_canvas_init(&c, 500, 500) != ISK_OK)
        return 1;
    isk_canvas_fill(&c, ISK_WHITE);

    const double path[] = {250, 200, 175, 300, 325, 300, 250, 200};
    isk_stroke_polyline_hairline(&c, path, 4, 0, ISK_BLACK, ISK_BLEND_OVER);

    int rc = example_show(&c, &o);
    isk_canvas_free(&c);
    return rc;
}
