/* Thesis figure 27: the "atomic mushroom" with a rising potential.
 *
 * Scene pokretni_privlacni_potencijal: view 0..10, gravity 9.81, drag 0.47,
 * walls right/bottom/left, a layer of 5500 particles at rest in
 * [0,10]x[0,1], and potential 1: k = 150 at (5, 5 - 3.2), charge +1
 * (attracts, blue), P = 3, x multiplier 0 (it pulls only vertically; the
 * distance is still Euclidean, so |F| = 150 |dy| / d^3), no min or max
 * distance, moving up by pomak(p) = (0, 20 p): 20 units per simulated
 * second, a third of a unit per frame.  It already moved once in the frame
 * the scene runs before pausing, and leaves the view after ~25 frames (its
 * disc is then off the canvas) while its pull keeps fading (~1/d^2).  The
 * click is simulated at (5, 1): under the potential, on top of the layer.
 *
 * What it shows: a potential that rises drags the debris up behind it into
 * a tall stem; with the potential gone the stem spreads and falls back.
 * Default frame 30 (0.5 s after the click).
 *
 * Common to the mushroom scenes (catalogue §4, §6): the thesis's simulator
 * on a 600x600 canvas, dt = 1/60 s per frame (precision 1, speed slider at
 * real time), per particle per frame: gravity m*(-g) + drag -o*v + the sum of
 * the potentials, semi-implicit Euler, then the thesis bounce (margin 0.1,
 * only the floor clamps); particles are drawn after the bounce as coverage
 * dots; each potential is drawn, then moved.  The scene starts with one
 * frame run and paused, waiting for a click; the click runs a Coulomb
 * explosion of 1000 particles whose kick hits EVERY particle, the layer
 * included (as the thesis's simulator does: mass-1 layer particles get
 * dv = 1.5/d away from the click).  This example makes that click itself at
 * frame 0, at the point named above, and --frames N renders frame N after
 * it.  The simulator's white FPS counter is left out: it depends on the
 * wall clock.  --seed N picks the layer and the explosion.
 */
#include <stdio.h>

#include "example.h"

#define DT (1.0 / 60) /* the simulator's frame-locked time step */

typedef struct scene {
    isk_system s;
    isk_view view;
} scene;

/* The thesis's potentials (catalogue §6), created before anything else so
 * they get ids 1, 2, ... as in the scene file. */
static int add_potentials(isk_system *s)
{
    isk_potential pot;
    int ok = 1;
    isk_potential_init(&pot, 150, isk_vec2_make(5, 5 - 3.2), +1);
    ok &= isk_potential_set_law(&pot, ISK_COULOMB_LAW_CODE, 3) == ISK_OK;
    pot.x_mult = 0;
    pot.vel = isk_vec2_make(0, 20); /* pomak(p) = (0, 20 p) */
    ok &= isk_system_add_potential(s, &pot, NULL) == ISK_OK;
    return ok;
}

/* Potentials as the simulator draws them, only while switched on: a disc of
 * world radius 0.1 (blue attracts, red repels) and the id in white. */
static void draw_potentials(scene *sc, isk_canvas *c)
{
    for (size_t k = 0; k < sc->s.forces.npot; k++) {
        const isk_potential *p = &sc->s.forces.pot[k];
        if (!p->enabled)
            continue;
        isk_world_disc(c, &sc->view, p->r.x, p->r.y, 0.1, p->charge >= 0 ? ISK_BLUE : ISK_RED,
                       ISK_BLEND_OVER);
        char id[16];
        snprintf(id, sizeof id, "%d", p->id);
        isk_world_text(c, &sc->view, p->r.x - 0.04, p->r.y - 0.06, id, 1, ISK_WHITE, ISK_BLEND_OVER);
    }
}

/* One simulator frame (catalogue §4.3): physics with the bounce inside the
 * step, clear, particles (after the bounce), potentials drawn THEN moved by
 * their motion(dt) (they move only when there are particles).  Drawing is
 * skipped when c is NULL; the physics is the same either way. */
static void advance(scene *sc, isk_canvas *c)
{
    isk_system_step(&sc->s, DT);
    if (c) {
        isk_canvas_fill(c, ISK_BLACK);
        const isk_particles *p = &sc->s.particles;
        for (size_t i = 0; i < p->count; i++)
            isk_world_dot_browser(c, &sc->view, p->x[i], p->y[i], ISK_YELLOW, ISK_BLEND_OVER);
        draw_potentials(sc, c);
    }
    if (sc->s.particles.count > 0)
        isk_system_move_potentials(&sc->s, DT);
}

static void window_frame(void *state, isk_canvas *c) { advance(state, c); }

int main(int argc, char **argv)
{
    example_opts o = {.seed = 1, .frames = 30};
    example_parse(argc, argv, &o, EX_SEED | EX_FRAMES, "fig27_mushroom_moving_potential",
                  "thesis figure 27: atomic mushroom, one moving potential");

    scene sc;
    isk_canvas c;
    if (isk_system_init(&sc.s, o.seed, 5500 + 1000) != ISK_OK ||
        isk_canvas_init(&c, 600, 600) != ISK_OK)
        return 1;
    isk_view_window(&sc.view, 600, 600, 0, 10, 0, 10);
    sc.s.forces.gravity = 9.81;
    sc.s.forces.drag = 0.47;
    sc.s.forces.centre = ISK_FIDELITY_THESIS; /* faithful: no guard exactly on a potential */
    sc.s.auto_move_potentials = 0;            /* moved by hand, after drawing */
    sc.s.coulomb_kick = ISK_KICK_ALL;         /* the click kicks every particle */
    isk_bounds b;
    isk_bounds_thesis(&b, 0, 10, 0, 10, ISK_SIDE_RIGHT | ISK_SIDE_BOTTOM | ISK_SIDE_LEFT);
    isk_system_set_bounds(&sc.s, &b, 1); /* the simulator bounces inside the step */
    if (!add_potentials(&sc.s))
        return 1;
    /* The stationary layer: 5500 particles of mass 1 at rest (the layer is not
     * limited to the explosion maximum of 10 000). */
    sc.s.explode_limit = 5500;
    if (isk_system_add_layer(&sc.s, 0, 10, 0, 1, 5500) != ISK_OK)
        return 1;
    sc.s.explode_limit = ISK_EXPLODE_THESIS_LIMIT;

    /* prviFrame: the scene runs one frame, then clears itself and pauses. */
    advance(&sc, NULL);
    /* The user's click, simulated: a Coulomb explosion of 1000 at (5, 1). */
    if (isk_system_explode(&sc.s, ISK_EXPLOSION_COULOMB, 5, 1, 1000) != ISK_OK)
        return 1;

    /* Frame 0: right after the click; frame N: after N more frames. */
    isk_canvas_fill(&c, ISK_BLACK);
    if (o.frames == 0) {
        for (size_t i = 0; i < sc.s.particles.count; i++)
            isk_world_dot_browser(&c, &sc.view, sc.s.particles.x[i], sc.s.particles.y[i], ISK_YELLOW,
                          ISK_BLEND_OVER);
        draw_potentials(&sc, &c);
    }
    for (long f = 1; f <= o.frames; f++)
        advance(&sc, f == o.frames ? &c : NULL);
    int rc = example_write_png(&c, &o);
    if (!rc && o.window)
        rc = example_window(&c, &o, &sc, window_frame);
    isk_canvas_free(&c);
    isk_system_free(&sc.s);
    return rc;
}
