/* Thesis figure 20: the multiple Coulomb explosion.
 *
 * visestrukiCoulombEksplozija(0, -3, 10000, ...): the Coulomb explosion of
 * figure 19 released in 17 batches (16 x 600 + 400), batch i kicked on its
 * own by a potential of strength k_i = 80 (ln i + 0.5) (40 for the first,
 * 267 for the last: later batches fly FASTER, although the thesis's text
 * calls the factor a reduction).  The thesis's file animates with
 * dt = 0.00025 s per frame (the listing says 0.001) and releases batch i+1
 * after sleep(10/i ms) of wall-clock time; here the batches are released on
 * simulated time instead (batch i+1 at sum_{j<=i} 0.010/j s, i.e. within
 * the first 0.034 s = 135 frames), so the run is reproducible.  No force,
 * floor only, cleared every frame, dots drawn before the bounce; each frame
 * steps the particles present at its start.
 *
 * What it teaches: several overlapping explosions of growing strength give
 * a layered cloud, a dense core inside faster shells.  Default frame 2000
 * (0.5 s).  --seed N picks the clouds.
 */
#include "example.h"

#define DT 0.00025 /* seconds per frame, as the thesis's file */

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
    example_opts o = {.seed = 1, .frames = 2000};
    example_parse(argc, argv, &o, EX_SEED | EX_FRAMES, "fig20_multi_coulomb",
                  "thesis figure 20: the multiple Coulomb explosion");

    scene sc;
    isk_canvas c;
    if (isk_system_init(&sc.s, o.seed, 10000) != ISK_OK || isk_canvas_init(&c, 600, 600) != ISK_OK)
        return 1;
    isk_view_window(&sc.view, 600, 600, -10, 10, -10, 10);
    isk_bounds b;
    isk_bounds_thesis(&b, -10, 10, -10, 10, ISK_SIDE_BOTTOM);
    isk_system_set_bounds(&sc.s, &b, 0); /* bounce after drawing, not in the step */
    if (isk_system_explode(&sc.s, ISK_EXPLOSION_MULTI_COULOMB, 0, -3, 10000) != ISK_OK)
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
