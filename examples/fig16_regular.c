/* SPDX-License-Identifier: MIT */
/* Thesis figure 16: the regular (ring) explosion.
 *
 * pravilnaEksplozija(0, -3, 10000, ...): 10,000 particles of mass 2, all at
 * (0, -3), the i-th with velocity (4, 4) rotated by i*360/10000 degrees
 * (speed 4*sqrt(2) ~ 5.657, the first at 45 degrees; the thesis's buggy
 * rotation formula is exact for (4, 4)).  Animated as the thesis's demo:
 * dt = 0.001 s per frame, no force, the floor at y = -9.9 the only wall,
 * each frame cleared and every particle drawn as a coverage dot before its
 * bounce.
 *
 * What it teaches: equal speeds in evenly spaced directions make a thin
 * circle that just grows (about 0.17 px per frame) and bounces off the
 * floor: the rim of a shock wave, not an explosion.  Default frame 1500
 * (1.5 s, radius 8.5 units): the ring has hit the floor and its bottom arc
 * is folding back up.  No randomness, so no --seed.
 */

#include "explosion_demo.h"

static const explosion_demo demo = {
    .name = "fig16_regular",
    .about = "thesis figure 16: the regular (ring) explosion",
    .kind = ISK_EXPLOSION_RING,
    .dt = 0.001,       /* seconds per frame, as the thesis's file */
    .frames = 1500,   /* the frame rendered by default */
    .random = 0,   /* no random draws: no --seed */
};

int main(int argc, char **argv)
{
    return explosion_demo_main(argc, argv, &demo);
}
