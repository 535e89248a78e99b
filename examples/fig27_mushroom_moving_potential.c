/* SPDX-License-Identifier: MIT */
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
 * The simulator itself is examples/mushroom_scene.h.
 */
#include "mushroom_scene.h"

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

static const mushroom_scene scene = {
    .name = "fig27_mushroom_moving_potential",
    .about = "thesis figure 27: atomic mushroom, one moving potential",
    .size = 10,
    .gravity = 9.81,
    .drag = 0.47,
    .sides = ISK_SIDE_RIGHT | ISK_SIDE_BOTTOM | ISK_SIDE_LEFT,
    .layer_top = 1,
    .layer_count = 5500,
    .click_x = 5,
    .click_y = 1,
    .frames = 30,
    .add_potentials = add_potentials,
};

int main(int argc, char **argv)
{
    return mushroom_main(argc, argv, &scene);
}
