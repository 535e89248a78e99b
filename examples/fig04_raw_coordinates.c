/* SPDX-License-Identifier: MIT */
/* Thesis figure 4: three triangles drawn straight in pixel coordinates.
 *
 * One local triangle A(0,0), B(150,0), C(75,150) is moved by (200,0),
 * (-75,200) and (-75,-150) and stroked in green with no transformation at
 * all.  The result shows why a world-to-screen view is needed: the canvas's
 * y axis points down, so the triangles come out upside down, and two of them
 * leave the canvas (the third keeps only its (0,0) corner).  Figure 8 draws
 * the same data through an isk_view.
 */
#include "example.h"

int main(int argc, char **argv)
{
    example_opts o = {0};
    example_parse(argc, argv, &o, 0, "fig04_raw_coordinates",
                  "thesis figure 4: triangles in raw screen coordinates");

    isk_canvas c;
    if (isk_canvas_init(&c, 500, 500) != ISK_OK)
        return 1;
    isk_canvas_fill(&c, ISK_WHITE);

    const double local[3][2] = {{0, 0}, {150, 0}, {75, 150}};
    const double shift[3][2] = {{200, 0}, {-75, 200}, {-75, -150}};
    for (int t = 0; t < 3; t++) {
        double path[8];
        for (int k = 0; k < 4; k++) { /* A, B, C, back to A */
            path[2 * k] = local[k % 3][0] + shift[t][0];
            path[2 * k + 1] = local[k % 3][1] + shift[t][1];
        }
        isk_stroke_polyline_hairline(&c, path, 4, 0, ISK_GREEN, ISK_BLEND_OVER);
    }

    int rc = example_show(&c, &o);
    isk_canvas_free(&c);
    return rc;
}
