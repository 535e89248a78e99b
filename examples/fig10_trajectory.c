/* SPDX-License-Identifier: MIT */
/* Thesis figure 10: the trajectory of a particle with no force acting.
 *
 * Mass 1, start (-4,-4), velocity (1,-2), time step dt = 0.25 s, 1000 steps
 * (250 s).  The thesis's loop, line for line:
 *
 *     for (i = 0; i < 1000; i++) {
 *         cestica.materijalnaTocka.pomakni(dt, new Vektor2D(0, 0));
 *         cestica.iscrtaj(gks);                          // draw BEFORE the bounce
 *         cestica.zarobi(gks, false, false, true, false); // floor only
 *     }
 *
 * The canvas is never cleared, so every step leaves a dot: a static picture
 * of the whole path.  What it teaches: with no force the particle moves in
 * a straight line at constant speed; the floor (y = -10 + 0.1, the particle's
 * "diameter") flips the vertical velocity once, at step 12, and the particle
 * then flies up and to the right off the canvas for good (there is no top or
 * right wall), so only the first ~50 dots are visible.  Each dot sits at a
 * fractional pixel position and is spread over up to 2x2 pixels by exact
 * area, as the browser's anti-aliased fillRect did (the half-bright pairs).
 *
 * --csv PATH writes every step's drawn position and end state (see
 * trajectory_csv.h); the numbers equal the thesis's JavaScript bit for bit.
 */
#include "example.h"
#include "trajectory_csv.h"

int main(int argc, char **argv)
{
    example_opts o = {0};
    example_parse(argc, argv, &o, EX_CSV, "fig10_trajectory",
                  "thesis figure 10: a particle's trajectory, no force");

    isk_canvas canvas;
    isk_view view;
    FILE *csv;
    if (isk_canvas_init(&canvas, 600, 600) != ISK_OK)
        return 1;
    isk_view_window(&view, 600, 600, -10, 10, -10, 10);
    isk_canvas_fill(&canvas, ISK_BLACK);
    if (csv_open(&csv, o.csv, o.name))
        return 1;

    isk_particle c;
    isk_particle_init(&c, 1, isk_vec2_make(-4, -4), isk_vec2_make(1, -2));
    const double dt = 0.25;
    for (int i = 0; i < 1000; i++) {
        isk_mp_move(&c.mp, dt, isk_vec2_make(0, 0));
        isk_particle_draw(&c, &canvas, &view);
        isk_vec2 drawn = c.mp.r;
        isk_particle_zarobi(&c, &view, 0, 0, 1, 0); /* top, right, bottom, left */
        csv_row(csv, i + 1, drawn, &c);
    }

    int rc = csv_close(csv, o.csv, o.name);
    if (!rc && (o.png || o.window))
        rc = example_show(&canvas, &o);
    isk_canvas_free(&canvas);
    return rc;
}
