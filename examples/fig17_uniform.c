/* SPDX-License-Identifier: MIT */
/* Thesis figure 17: the uniform random explosion.
 *
 * 10,000 particles of mass 2 at (0, -3), each with velocity
 * (20U - 10, 20U - 10), U uniform in [0, 1) (the x draw first, as
 * Math.random() was called): velocities fill the square [-10, 10)^2.
 * Animated as the thesis's demo: dt = 0.001 s per frame, no force, floor
 * only, cleared every frame, dots drawn before the bounce.
 *
 * What it teaches: uniform random velocities give an expanding square filled
 * evenly with particles, not a round cloud: the shape of the velocity
 * distribution is the shape of the explosion.  Default frame 600 (0.6 s):
 * a square 12 units wide, its bottom edge nearly at the floor.
 * --seed N picks the random draws (the thesis used the unseedable
 * Math.random()).
 */

#include "explosion_demo.h"

static const explosion_demo demo = {
    .name = "fig17_uniform",
    .about = "thesis figure 17: the uniform random explosion",
    .kind = ISK_EXPLOSION_UNIFORM,
    .dt = 0.001,       /* seconds per frame, as the thesis's file */
    .frames = 600,   /* the frame rendered by default */
    .random = 1,   /* takes --seed */
};

int main(int argc, char **argv)
{
    return explosion_demo_main(argc, argv, &demo);
}
