/* Thesis figure 18: the Gaussian explosion.
 *
 * gaussEksplozija(0, -3, 10000, ...): 10,000 particles at (0, -3) with
 * velocity 3*(z1, z2), z1 and z2 standard normal from one Box-Muller pair
 * (u1, u2), and mass 2 + U (the draws per particle in the thesis's order:
 * u1, u2, then the mass).  Animated as the thesis's demo: dt = 0.001 s per
 * frame, no force (the mass does not matter yet), floor only, cleared every
 * frame, dots drawn before the bounce.
 *
 * What it teaches: normally distributed velocities give a round cloud,
 * dense in the middle and thinning out at the edge, much more like a real
 * explosion than figures 16 and 17.  Default frame 800 (0.8 s: the cloud's
 * standard deviation is 2.4 units, so it fits the canvas).
 * --seed N picks the random draws.
 */
#include "example.h"

#define DT 0.001 /* seconds per frame, as the thesis's file */

typedef struct scene {
    isk_system s;
    isk_view view;
} scene;

/* One requestAnimationFrame: clear, then every particle pomakni -> iscrtaj ->
 * zarobi (floor only).  Each particle is independent (no forces between
 * them), so stepping all, drawing all, then bouncing all gives the same
 * bits and the same picture.  Drawing is skipped when c is NULL. */
static void advance(scene *sc, isk_canvas *c)
{
    isk_system_step(&sc->s, DT); /* zero force: pomakni(dt, (0,0)) */
    if (c) {
        isk_canvas_fill(c, ISK_BLACK);
        const isk_particles *p = &sc->s.particles;
        for (size_t i = 0; i < p->count; i++)
            isk_world_dot_browser(c, &sc->view, p->x[i], p->y[i], ISK_YELLOW, ISK_BLEND_OVER);
    }
    isk_system_bounce(&sc->s); /* zarobi(gks, false, false, true, false) */
}

static void window_frame(void *state, isk_canvas *c) { advance(state, c); }

int main(int argc, char **argv)
{
    example_opts o = {.seed = 1, .frames = 800};
    example_parse(argc, argv, &o, EX_SEED | EX_FRAMES, "fig18_gauss",
                  "thesis figure 18: the Gaussian explosion");

    scene sc;
    isk_canvas c;
    if (isk_system_init(&sc.s, o.seed, 10000) != ISK_OK || isk_canvas_init(&c, 600, 600) != ISK_OK)
        return 1;
    isk_view_window(&sc.view, 600, 600, -10, 10, -10, 10);
    isk_bounds b;
    isk_bounds_thesis(&b, -10, 10, -10, 10, ISK_SIDE_BOTTOM);
    isk_system_set_bounds(&sc.s, &b, 0); /* bounce after drawing, not in the step */
    if (isk_system_explode(&sc.s, ISK_EXPLOSION_GAUSS, 0, -3, 10000) != ISK_OK)
        return 1;

    /* Frame 0 shows the particles where they start; frame N is the canvas
     * after N frames.  Only the last frame needs drawing. */
    isk_canvas_fill(&c, ISK_BLACK);
    if (o.frames == 0)
        for (size_t i = 0; i < sc.s.particles.count; i++)
            isk_world_dot_browser(&c, &sc.view, sc.s.particles.x[i], sc.s.particles.y[i], ISK_YELLOW,
                          ISK_BLEND_OVER);
    for (long f = 1; f <= o.frames; f++)
        advance(&sc, f == o.frames ? &c : NULL);
    int rc = example_write_png(&c, &o);
    if (!rc && o.window)
        rc = example_window(&c, &o, &sc, window_frame);
    isk_canvas_free(&c);
    isk_system_free(&sc.s);
    return rc;
}
