/* SPDX-License-Identifier: MIT */
/* Thesis figure 9: one particle that does not move.
 *
 * The first particle of the thesis: new Cestica(0.1, new MaterijalnaTocka(1,
 * (-4,-4), (0,0))) drawn once on a 600x600 canvas whose world window is
 * -10..10 on both axes (X = 30x + 300, Y = 300 - 30y).  A particle is drawn
 * as the browser drew the thesis's fillRect(X, Y, 1, 1): a 1x1 square whose
 * top-left corner is the transformed point.  (-4,-4) lands on the integer
 * point (180, 420), so exactly one pixel, (180, 420), is lit, fully yellow.
 * (The red circle in the thesis's screenshot was drawn by hand around it.)
 */
#include "example.h"

int main(int argc, char **argv)
{
    example_opts o = {0};
    example_parse(argc, argv, &o, 0, "fig09_stationary_particle",
                  "thesis figure 9: one stationary particle");

    isk_canvas canvas;
    isk_view view;
    if (isk_canvas_init(&canvas, 600, 600) != ISK_OK)
        return 1;
    isk_view_window(&view, 600, 600, -10, 10, -10, 10);
    isk_canvas_fill(&canvas, ISK_BLACK); /* the canvas's CSS background */

    isk_particle c;
    isk_particle_init(&c, 1, isk_vec2_make(-4, -4), isk_vec2_make(0, 0));
    isk_particle_draw(&c, &canvas, &view); /* cestica.iscrtaj(gks) */

    int rc = example_show(&canvas, &o);
    isk_canvas_free(&canvas);
    return rc;
}
