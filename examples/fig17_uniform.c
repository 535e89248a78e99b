/* Thesis figure 17: the uniform random explosion.
 *
 * 10,000 particles of mass 2 at (0, -3), each with velocity
 * (20U - 10, 20U - 10), U uniform in [0, 1) (the x draw first, as
 * Math.random() was called): velocities fill the square [-10, 10)^2.
 * Animated as the thesis's demo: dt = 0.001 s per frame, no force, floor
 * only, cleared every frame, dots drawn before the bounce.
 *
 * What it teaches: uniform random velocities give an expanding square filled
 * evenly with particles, not a round cloud: the shape of the velocity
 * distribution is the shape of the explosion.  Default frame 600 (0.6 s):
 * a square 12 units wide, its bottom edge nearly at the floor.
 * --seed N picks the random draws (the thesis used the unseedable
 * Math.random()).
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
    example_opts o = {.seed = 1, .frames = 600};
    example_parse(argc, argv, &o, EX_SEED | EX_FRAMES, "fig17_uniform",
                  "thesis figure 17: the uniform random explosion");

    scene sc;
    isk_canvas c;
    if (isk_system_init(&sc.s, o.seed, 10000) != ISK_OK || isk_canvas_init(&c, 600, 600) != ISK_OK)
        return 1;
    isk_view_window(&sc.view, 600, 600, -10, 10, -10, 10);
    isk_bounds b;
    isk_bounds_thesis(&b, -10, 10, -10, 10, ISK_SIDE_BOTTOM);
    isk_system_set_bounds(&sc.s, &b, 0); /* bounce after drawing, not in the step */
    if (isk_system_explode(&sc.s, ISK_EXPLOSION_UNIFORM, 0, -3, 10000) != ISK_OK)
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
