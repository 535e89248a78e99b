/* SPDX-License-Identifier: MIT */
/* examples/mushroom_scene.h — the thesis's simulator running an "atomic
 * mushroom" scene, shared by figures 26-29 (each figure's file gives its
 * numbers and its potentials).
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
 * dv = 1.5/d away from the click).  The examples make that click themselves
 * at frame 0, at the point their file names, and --frames N renders frame N
 * after it.  The simulator's white FPS counter is left out: it depends on
 * the wall clock.  --seed N picks the layer and the explosion.
 */
#ifndef ISKRA_MUSHROOM_SCENE_H
#define ISKRA_MUSHROOM_SCENE_H

#include <stdio.h>

#include "example.h"

#define MUSHROOM_DT (1.0 / 60) /* the simulator's frame-locked time step */

typedef struct mushroom_scene {
    const char *name, *about;
    double size;              /* the view is 0..size on both axes */
    double gravity, drag;
    unsigned sides;           /* the thesis's walls (ISK_SIDE_*) */
    double layer_top;         /* the layer fills [0, size] x [0, layer_top] */
    size_t layer_count;
    double click_x, click_y;  /* where the simulated click explodes */
    long frames;              /* the frame rendered by default */
    /* Creates the thesis's potentials, before anything else, so they get
     * ids 1, 2, ... as in the scene file; returns 0 on failure. */
    int (*add_potentials)(isk_system *s);
} mushroom_scene;

typedef struct mushroom_state {
    isk_system s;
    isk_view view;
} mushroom_state;

/* Potentials as the simulator draws them, only while switched on: a disc of
 * radius 0.1 (blue attracts, red repels) and the id in white at
 * (x - 0.04, y - 0.06). */
static inline void mushroom_draw_potentials(mushroom_state *st, isk_canvas *c)
{
    for (size_t k = 0; k < st->s.forces.npot; k++) {
        const isk_potential *p = &st->s.forces.pot[k];
        if (!p->enabled)
            continue;
        isk_world_disc(c, &st->view, p->r.x, p->r.y, 0.1, p->charge >= 0 ? ISK_BLUE : ISK_RED, ISK_BLEND_OVER);
        char id[16];
        snprintf(id, sizeof id, "%d", p->id);
        isk_world_text(c, &st->view, p->r.x - 0.04, p->r.y - 0.06, id, 1, ISK_WHITE, ISK_BLEND_OVER);
    }
}

static inline void mushroom_draw(mushroom_state *st, isk_canvas *c)
{
    isk_canvas_fill(c, ISK_BLACK);
    const isk_particles *p = &st->s.particles;
    for (size_t i = 0; i < p->count; i++)
        isk_world_dot_browser(c, &st->view, p->x[i], p->y[i], ISK_YELLOW, ISK_BLEND_OVER);
    mushroom_draw_potentials(st, c);
}

/* One simulator frame (catalogue §4.3): physics with the bounce inside the
 * step, clear, particles (after the bounce), potentials drawn THEN moved by
 * their motion(dt) (they move only when there are particles).  Drawing is
 * skipped when c is NULL; the physics is the same either way. */
static inline void mushroom_advance(mushroom_state *st, isk_canvas *c)
{
    isk_system_step(&st->s, MUSHROOM_DT);
    if (c)
        mushroom_draw(st, c);
    if (st->s.particles.count > 0)
        isk_system_move_potentials(&st->s, MUSHROOM_DT);
}

static inline void mushroom_window_frame(void *state, isk_canvas *c) { mushroom_advance(state, c); }

static inline int mushroom_main(int argc, char **argv, const mushroom_scene *m)
{
    example_opts o = {.seed = 1, .frames = m->frames};
    example_parse(argc, argv, &o, EX_SEED | EX_FRAMES, m->name, m->about);

    mushroom_state st;
    isk_canvas c;
    if (isk_system_init(&st.s, o.seed, m->layer_count + 1000) != ISK_OK || isk_canvas_init(&c, 600, 600) != ISK_OK)
        return 1;
    isk_view_window(&st.view, 600, 600, 0, m->size, 0, m->size);
    st.s.forces.gravity = m->gravity;
    st.s.forces.drag = m->drag;
    st.s.forces.centre = ISK_FIDELITY_THESIS; /* faithful: no guard exactly on a potential */
    st.s.auto_move_potentials = 0;            /* moved by hand, after drawing */
    st.s.coulomb_kick = ISK_KICK_ALL;         /* the click kicks every particle */
    isk_bounds b;
    isk_bounds_thesis(&b, 0, m->size, 0, m->size, m->sides);
    isk_system_set_bounds(&st.s, &b, 1); /* the simulator bounces inside the step */
    if (!m->add_potentials(&st.s))
        return 1;
    /* The stationary layer: particles of mass 1 at rest (the layer is not
     * limited to the explosion maximum of 10 000). */
    st.s.explode_limit = m->layer_count;
    if (isk_system_add_layer(&st.s, 0, m->size, 0, m->layer_top, m->layer_count) != ISK_OK)
        return 1;
    st.s.explode_limit = ISK_EXPLODE_THESIS_LIMIT;

    /* prviFrame: the scene runs one frame, then clears itself and pauses. */
    mushroom_advance(&st, NULL);
    /* The user's click, simulated: a Coulomb explosion of 1000. */
    if (isk_system_explode(&st.s, ISK_EXPLOSION_COULOMB, m->click_x, m->click_y, 1000) != ISK_OK)
        return 1;

    /* Frame 0: right after the click; frame N: after N more frames. */
    isk_canvas_fill(&c, ISK_BLACK);
    if (o.frames == 0)
        mushroom_draw(&st, &c);
    for (long f = 1; f <= o.frames; f++)
        mushroom_advance(&st, f == o.frames ? &c : NULL);
    int rc = example_write_png(&c, &o);
    if (!rc && o.window)
        rc = example_window(&c, &o, &st, mushroom_window_frame);
    isk_canvas_free(&c);
    isk_system_free(&st.s);
    return rc;
}

#endif
