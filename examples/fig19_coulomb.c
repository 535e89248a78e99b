/* SPDX-License-Identifier: MIT */
/* Thesis figure 19: the Coulomb explosion.
 *
 * coulombEksplozija(0, -3, 10000, ...): 10,000 particles at rest in a tiny
 * Gaussian cloud around (0, -3) (sigma 0.02 per axis), mass 2 + U, then ONE
 * kick: a repelling potential at the centre (k = 150, charge -1, P = 2, min
 * distance 0.06) acts for a single step of dt 0.01, giving each particle
 * dv = 1.5 (r - c) / (m max(d, 0.06)^2).  Animated as the thesis's demo:
 * dt = 0.001 s per frame, no force, floor only, cleared every frame, dots
 * drawn before the bounce.
 *
 * What it teaches: pushing a random cloud apart with a central force makes
 * the explosion from physics rather than from a chosen velocity
 * distribution.  Inside the 0.06 radius the push grows linearly with the
 * distance, so the ~99% of particles there get a Gaussian velocity; the few
 * outside it are slower (1/d).  Default frame 700 (0.7 s): a round cloud,
 * its standard deviation 2-3 units (the mass 2..3 divides the push).  --seed N picks the cloud.
 */

#include "explosion_demo.h"

static const explosion_demo demo = {
    .name = "fig19_coulomb",
    .about = "thesis figure 19: the Coulomb explosion",
    .kind = ISK_EXPLOSION_COULOMB,
    .dt = 0.001,       /* seconds per frame, as the thesis's file */
    .frames = 700,   /* the frame rendered by default */
    .random = 1,   /* takes --seed */
};

int main(int argc, char **argv)
{
    return explosion_demo_main(argc, argv, &demo);
}
