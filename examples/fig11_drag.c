/* SPDX-License-Identifier: MIT */
/* Thesis figure 11: the trajectory of figure 10 with drag.
 *
 * As figure 10 (mass 1, start (-4,-4), velocity (1,-2), dt = 0.25, 1000
 * steps, every step leaves a dot, floor only) plus the medium's resistance
 * Otpor(0.1): F = -0.1 v.  The thesis's loop:
 *
 *     const silaOtpora = otporSredstva.F(cestica.materijalnaTocka);
 *     cestica.materijalnaTocka.pomakni(dt, silaOtpora);
 *     cestica.iscrtaj(gks);
 *     cestica.zarobi(gks, false, false, true, false);
 *
 * What it teaches: drag always opposes the motion, so with semi-implicit
 * Euler the velocity shrinks by the factor 1 - 0.1*0.25 = 0.975 every step;
 * the dots crowd together as the particle slows, it bounces once off the
 * floor and comes to rest near (5.75, 3.4384), where hundreds of dots pile
 * up on the same few pixels.
 *
 * --csv PATH writes every step (see trajectory_csv.h), bit-exact with the
 * thesis's JavaScript.
 */
#include "example.h"
#include "trajectory_csv.h"

int main(int argc, char **argv)
{
    example_opts o = {0};
    example_parse(argc, argv, &o, EX_CSV, "fig11_drag",
                  "thesis figure 11: a particle's trajectory with drag");

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
        isk_vec2 drag = isk_drag_force(&c.mp, 0.1); /* Otpor(0.1).F */
        isk_mp_move(&c.mp, dt, drag);
        isk_particle_draw(&c, &canvas, &view); /* draw BEFORE the bounce */
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
