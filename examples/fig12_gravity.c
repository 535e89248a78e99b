/* SPDX-License-Identifier: MIT */
/* Thesis figure 12: the trajectory of figure 10 under gravity.
 *
 * As figure 10 (mass 1, start (-4,-4), velocity (1,-2), dt = 0.25, 1000
 * steps, every step leaves a dot, floor only) plus SilaTeza(0.25), the
 * force (0, m*(-0.25)).  The thesis's loop:
 *
 *     const sila = silaTeza.F(cestica.materijalnaTocka);
 *     cestica.materijalnaTocka.pomakni(dt, sila);
 *     cestica.iscrtaj(gks);
 *     cestica.zarobi(gks, false, false, true, false);
 *
 * What it teaches: gravity bends the straight path into parabolas; the floor
 * is perfectly elastic (the bounce only flips the sign of the vertical
 * velocity), so the particle keeps hopping at the same height (12 floor
 * bounces in 1000 steps) while it drifts right at 1 unit/s and leaves the
 * canvas after x = 10.
 *
 * --csv PATH writes every step (see trajectory_csv.h), bit-exact with the
 * thesis's JavaScript.
 */
#include "example.h"
#include "trajectory_csv.h"

int main(int argc, char **argv)
{
    example_opts o = {0};
    example_parse(argc, argv, &o, EX_CSV, "fig12_gravity",
                  "thesis figure 12: a particle's trajectory under gravity");

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
        isk_vec2 sila = isk_gravity_force(&c.mp, 0.25); /* SilaTeza(0.25).F */
        isk_mp_move(&c.mp, dt, sila);
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
