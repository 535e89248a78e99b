/* SPDX-License-Identifier: MIT */
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
        pot.max_dist = 0.3;
        ok &= isk_system_add_potential(s, &pot, NULL) == ISK_OK;
    }
    return ok;
}

static const mushroom_scene scene = {
    .name = "fig28_mushroom_three_potentials",
    .about = "thesis figure 28: atomic mushroom, three potentials",
    .size = 40,
    .gravity = 9.81,
    .drag = 1.5,
    .sides = ISK_SIDE_RIGHT | ISK_SIDE_BOTTOM | ISK_SIDE_LEFT,
    .layer_top = 1.5,
    .layer_count = 15000,
    .click_x = 20,
    .click_y = 1.5,
    .frames = 60,
    .add_potentials = add_potentials,
};

int main(int argc, char **argv)
{
    return mushroom_main(argc, argv, &scene);
}
