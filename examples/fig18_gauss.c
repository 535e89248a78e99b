/* SPDX-License-Identifier: MIT */
/* Thesis figure 18: the Gaussian explosion.
 *
 * gaussEksplozija(0, -3, 10000, ...): 10,000 particles at (0, -3) with
 * velocity 3*(z1, z2), z1 and z2 standard normal from one Box-Muller pair
 * (u1, u2), and mass 2 + U (the draws per particle in the thesis's order:
 * u1, u2, then the mass).  Animated as the thesis's demo: dt = 0.001 s per
 * frame, no force (the mass does not matter yet), floor only, cleared every
 * frame, dots drawn before the bounce.
 *
 * What it teaches: normally distributed velocities give a round cloud,
 * dense in the middle and thinning out at the edge, much more like a real
 * explosion than figures 16 and 17.  Default frame 800 (0.8 s: the cloud's
 * standard deviation is 2.4 units, so it fits the canvas).
 * --seed N picks the random draws.
 */

#include "explosion_demo.h"

static const explosion_demo demo = {
    .name = "fig18_gauss",
    .about = "thesis figure 18: the Gaussian explosion",
    .kind = ISK_EXPLOSION_GAUSS,
    .dt = 0.001,       /* seconds per frame, as the thesis's file */
    .frames = 800,   /* the frame rendered by default */
    .random = 1,   /* takes --seed */
};

int main(int argc, char **argv)
{
    return explosion_demo_main(argc, argv, &demo);
}
