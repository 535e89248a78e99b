/* SPDX-License-Identifier: MIT */
/* Thesis figure 8: the triangles of figure 4 drawn through a view.
 *
 * The world window -400..400 on both axes is mapped onto the 500x500 canvas
 * (sx = 0.625, sy = -0.625, px = py = 250): y now points up and every
 * triangle lands inside the canvas, the right way up.
 */
#include "example.h"

int main(int argc, char **argv)
{
    example_opts o = {0};
    example_parse(argc, argv, &o, 0, "fig08_view_transform",
                  "thesis figure 8: triangles through the world-to-screen view");

    isk_canvas c;
    isk_view v;
    if (isk_canvas_init(&c, 500, 500) != ISK_OK)
        return 1;
    if (isk_view_window(&v, c.width, c.height, -400, 400, -400, 400) != ISK_OK)
        return 1;
    isk_canvas_fill(&c, ISK_WHITE);

    const double local[3][2] = {{0, 0}, {150, 0}, {75, 150}};
    const double shift[3][2] = {{200, 0}, {-75, 200}, {-75, -150}};
    for (int t = 0; t < 3; t++) {
        double path[8];
        for (int k = 0; k < 4; k++) {
            path[2 * k] = local[k % 3][0] + shift[t][0];
            path[2 * k + 1] = local[k % 3][1] + shift[t][1];
        }
        isk_world_polyline_hairline(&c, &v, path, 4, 0, ISK_GREEN, ISK_BLEND_OVER);
    }

    int rc = example_show(&c, &o);
    isk_canvas_free(&c);
    return rc;
}
