/* SPDX-License-Identifier: MIT */
/* Thesis figure 26: the "atomic mushroom", one fixed attracting potential.
 *
 * Scene nepokretni_privlacni_potencijal: view 0..10 (60 px per unit),
 * gravity 9.81, drag 0.47, walls right/bottom/left, a layer of 3500
 * particles at rest in [0,10]x[0,2], and potential 1: k = 800 at (5,5),
 * charge +1 (attracts, blue), P = 4 (|F| = 800/d^3), min distance 0.5,
 * max distance 0.1 (it switches off for good once a particle comes within
 * 0.1).  The click is simulated at (5, 1): under the potential, in the
 * middle of the layer's thickness (so the kick throws the layer above the
 * click upward).
 *
 * What it shows: the explosion throws the ground layer up and the potential
 * pulls the debris into a rising stem, while gravity and drag bring the
 * rest down in a cone.  The fastest debris reaches the potential within
 * ~15 frames and its max-distance switch turns it off for good (the disc
 * disappears, a thesis quirk), but the stem it started keeps rising.
 * Default frame 30 (0.5 s after the click).
 *
 * The simulator itself is examples/mushroom_scene.h.
 */
#include "mushroom_scene.h"

/* The thesis's potentials (catalogue §6), created before anything else so
 * they get ids 1, 2, ... as in the scene file. */
static int add_potentials(isk_system *s)
{
    isk_potential pot;
    int ok = 1;
    isk_potential_init(&pot, 800, isk_vec2_make(5, 5), +1);
    ok &= isk_potential_set_law(&pot, ISK_COULOMB_LAW_CODE, 4) == ISK_OK;
    pot.min_dist = 0.5;
    pot.max_dist = 0.1;
    ok &= isk_system_add_potential(s, &pot, NULL) == ISK_OK;
    return ok;
}

static const mushroom_scene scene = {
    .name = "fig26_mushroom_one_potential",
    .about = "thesis figure 26: atomic mushroom, one fixed potential",
    .size = 10,
    .gravity = 9.81,
    .drag = 0.47,
    .sides = ISK_SIDE_RIGHT | ISK_SIDE_BOTTOM | ISK_SIDE_LEFT,
    .layer_top = 2,
    .layer_count = 3500,
    .click_x = 5,
    .click_y = 1,
    .frames = 30,
    .add_potentials = add_potentials,
};

int main(int argc, char **argv)
{
    return mushroom_main(argc, argv, &scene);
}
