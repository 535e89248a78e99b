/* SPDX-License-Identifier: MIT */
/* Thesis figure 13: the trajectory under gravity and drag together.
 *
 * As figure 10 (mass 1, start (-4,-4), velocity (1,-2), dt = 0.25, 1000
 * steps, every step leaves a dot, floor only) with both forces, summed as
 * the thesis sums them (gravity first, then drag):
 *
 *     const sila = silaTeza.F(cestica.materijalnaTocka);              // (0, -0.25 m)
 *     const silaOtpora = otporSredstva.F(cestica.materijalnaTocka);   // -0.1 v
 *     cestica.materijalnaTocka.pomakni(dt, sila.zbroji(silaOtpora));
 *     cestica.iscrtaj(gks);
 *     cestica.zarobi(gks, false, false, true, false);
 *
 * What it teaches: the most realistic of the four paths.  Each hop is lower
 * than the last because drag takes energy away, and the particle ends up
 * lying on the floor.  There a quirk of the thesis's bounce shows: every
 * step gravity pulls it just below the floor (y ~ -9.9079), it is drawn
 * there, then zarobi flips and clamps it; 788 of the 1000 steps trigger the
 * floor bounce.  The bright knot of overlapping dots where the path ends,
 * on the floor near x = 5.9, is that jitter.
 *
 * --csv PATH writes every step (see trajectory_csv.h), bit-exact with the
 * thesis's JavaScript.
 */
#include "example.h"
#include "trajectory_csv.h"

int main(int argc, char **argv)
{
    example_opts o = {0};
    example_parse(argc, argv, &o, EX_CSV, "fig13_drag_gravity",
                  "thesis figure 13: a particle's trajectory with gravity and drag");

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
        isk_vec2 sila = isk_gravity_force(&c.mp, 0.25);  /* SilaTeza(0.25).F */
        isk_vec2 otpor = isk_drag_force(&c.mp, 0.1);     /* Otpor(0.1).F */
        isk_mp_move(&c.mp, dt, isk_vec2_add(sila, otpor)); /* sila.zbroji(silaOtpora) */
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
