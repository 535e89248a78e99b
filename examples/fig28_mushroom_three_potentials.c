/* Thesis figure 28: the "atomic mushroom" shaped by three potentials.
 *
 * Scene vise_potencijala_1: view 0..40 (15 px per unit), gravity 9.81,
 * drag 1.5, walls right/bottom/left, a layer of 15000 particles at rest in
 * [0,40]x[0,1.5], and three attracting (blue) potentials, all P = 9
 * (|F| ~ k/d^8) and max distance 0.3:
 *   1: k = 1.25e9 at (20,10), min 6.25, x multiplier 0.3 (the stem);
 *   2: k = 4e5 at (17,25), min 2.95;   3: k = 4e5 at (23,25), min 2.95
 *      (the two lobes of the cap).
 * The click is simulated at (20, 1.5): under potential 1, on top of the
 * layer.
 *
 * What it shows: the stem potential lifts a narrow column (its x multiplier
 * weakens the sideways pull) and the two upper potentials spread the top
 * into a cap: several simple attractors compose a recognisable shape.
 * Potential 1 switches off early (a particle passes within 0.3 of it);
 * 2 and 3 are still on at the default frame 60 (1 s after the click), the
 * column of debris climbing between them.
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
    isk_potential_init(&pot, 1.25e9, isk_vec2_make(20, 10), +1);
    ok &= isk_potential_set_law(&pot, ISK_COULOMB_LAW_CODE, 9) == ISK_OK;
    pot.min_dist = 6.25;
    pot.max_dist = 0.3;
    pot.x_mult = 0.3;
    ok &= isk_system_add_potential(s, &pot, NULL) == ISK_OK;
    for (int k = 0; k < 2; k++) {
        isk_potential_init(&pot, 4e5, isk_vec2_make(k ? 23 : 17, 25), +1);
        ok &= isk_potential_set_law(&pot, ISK_COULOMB_LAW_CODE, 9) == ISK_OK;
        pot.min_dist = 2.95;
        pot.max_dist = 0.3;
        ok &= isk_system_add_potential(s, &pot, NULL) == ISK_OK;
    }
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
    example_opts o = {.seed = 1, .frames = 60};
    example_parse(argc, argv, &o, EX_SEED | EX_FRAMES, "fig28_mushroom_three_potentials",
                  "thesis figure 28: atomic mushroom, three potentials");

    scene sc;
    isk_canvas c;
    if (isk_system_init(&sc.s, o.seed, 15000 + 1000) != ISK_OK ||
        isk_canvas_init(&c, 600, 600) != ISK_OK)
        return 1;
    isk_view_window(&sc.view, 600, 600, 0, 40, 0, 40);
    sc.s.forces.gravity = 9.81;
    sc.s.forces.drag = 1.5;
    sc.s.forces.centre = ISK_FIDELITY_THESIS; /* faithful: no guard exactly on a potential */
    sc.s.auto_move_potentials = 0;            /* moved by hand, after drawing */
    sc.s.coulomb_kick = ISK_KICK_ALL;         /* the click kicks every particle */
    isk_bounds b;
    isk_bounds_thesis(&b, 0, 40, 0, 40, ISK_SIDE_RIGHT | ISK_SIDE_BOTTOM | ISK_SIDE_LEFT);
    isk_system_set_bounds(&sc.s, &b, 1); /* the simulator bounces inside the step */
    if (!add_potentials(&sc.s))
        return 1;
    /* The stationary layer: 15000 particles of mass 1 at rest (the layer is not
     * limited to the explosion maximum of 10 000). */
    sc.s.explode_limit = 15000;
    if (isk_system_add_layer(&sc.s, 0, 40, 0, 1.5, 15000) != ISK_OK)
        return 1;
    sc.s.explode_limit = ISK_EXPLODE_THESIS_LIMIT;

    /* prviFrame: the scene runs one frame, then clears itself and pauses. */
    advance(&sc, NULL);
    /* The user's click, simulated: a Coulomb explosion of 1000 at (20, 1.5). */
    if (isk_system_explode(&sc.s, ISK_EXPLOSION_COULOMB, 20, 1.5, 1000) != ISK_OK)
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
