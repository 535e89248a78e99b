/* SPDX-License-Identifier: MIT */
/* Thesis figure 29: the "atomic mushroom" with four potentials, no gravity.
 *
 * Scene vise_potencijala_2: view 0..40 (15 px per unit), gravity 0, drag
 * 1.5, only the floor, a layer of 15000 particles at rest in [0,40]x[0,5],
 * and four potentials:
 *   1: k = 1.25e9 at (20,10), P = 9, min 6.25, max 0.3, x multiplier 0.3;
 *   2, 3: k = 4e5 at (17,25) and (23,25), P = 9, min 2.95, max 0.15;
 *   4: k = 2 at (20,45), charge -1 (repels, red; above the view, so its
 *      disc is off the canvas), P = 1: a constant push of 2 away from it,
 *      min 3 - with no gravity it acts as a weak, mostly downward gravity.
 * The click is simulated at (20, 5): under potential 1, on top of the
 * layer.
 *
 * What it shows: the same stem-and-cap construction as figure 28, with the
 * downward pull supplied by a far repelling potential instead of gravity.
 * Default frame 120 (2 s after the click).
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
        pot.max_dist = 0.15;
        ok &= isk_system_add_potential(s, &pot, NULL) == ISK_OK;
    }
    isk_potential_init(&pot, 2, isk_vec2_make(20, 45), -1);
    ok &= isk_potential_set_law(&pot, ISK_COULOMB_LAW_CODE, 1) == ISK_OK;
    pot.min_dist = 3;
    ok &= isk_system_add_potential(s, &pot, NULL) == ISK_OK;
    return ok;
}

static const mushroom_scene scene = {
    .name = "fig29_mushroom_four_potentials",
    .about = "thesis figure 29: atomic mushroom, four potentials",
    .size = 40,
    .gravity = 0,
    .drag = 1.5,
    .sides = ISK_SIDE_BOTTOM,
    .layer_top = 5,
    .layer_count = 15000,
    .click_x = 20,
    .click_y = 5,
    .frames = 120,
    .add_potentials = add_potentials,
};

int main(int argc, char **argv)
{
    return mushroom_main(argc, argv, &scene);
}
