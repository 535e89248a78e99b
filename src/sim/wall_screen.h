/* SPDX-License-Identifier: MIT */
/* src/sim/wall_screen.h — the walls' screen: which particles of a block
 * ended their step outside the walls, by groups (internal).
 *
 * The bounces at the time of impact (iskra/impact.h) touch only particles
 * beyond a wall, a few per step; the screen finds them in one pass over
 * both axes, so the rest of the block costs a few vector operations per
 * particle, and the walls look only at the groups it flags:
 *
 *     isk_wall_box box = {left, right, bottom, top};    // a missing wall: -inf / +inf
 *     isk_wall_outside out;
 *     uint64_t flags = isk__wall_screen_pick()(n, x, y, &box, &out);   // n <= ISK_WALL_SCREEN_SPAN
 *     // bit g of flags: some particle of group g, [g * ISK_WALL_SCREEN, (g + 1) * ISK_WALL_SCREEN),
 *     // is outside; bit j of out.x[g] (out.y[g]): particle g * ISK_WALL_SCREEN + j is outside on x (y)
 *
 * Outside on x means !(left <= x && x <= right): beyond a wall, or NaN (an
 * exact hit, x == left, is inside, and so is -0 on a +0 wall; an infinity
 * is inside a missing wall's infinity): the walls' own test, and the
 * caller takes the masks as its verdict for each particle.  Every group
 * first gets a cheaper test, a sign bit set in x - left, right - x,
 * y - bottom or top - y, and only a group it fires for gets its masks
 * computed (the others get zero masks).  That test catches every finite
 * particle outside; a NaN whose sign bit is clear escapes it, so a NaN may
 * be in the masks or not (the bounces leave non-finite particles to the
 * runner either way).  Flag g is set exactly when out.x[g] | out.y[g] is
 * not 0.  The call writes both masks of every group it covers,
 * g < ceil(n / ISK_WALL_SCREEN), with zeros past n.
 *
 * Three builds of the same compares: the portable one (baseline x86-64
 * SSE2 or whatever the target has) and, on x86-64 CPUs that have them,
 * AVX2 and AVX-512, chosen at run time.  They give the same flags and
 * masks for every input (tests/test_wall_screen.c). */
#ifndef ISKRA_SIM_WALL_SCREEN_H
#define ISKRA_SIM_WALL_SCREEN_H

#include <stddef.h>
#include <stdint.h>

typedef struct isk_wall_box {
    double left, right, bottom, top;
} isk_wall_box;

/* A group: a step in which a few particles hit tests ISK_WALL_SCREEN of
 * them one by one per hit, not the whole block.  One call answers for up
 * to 64 groups (a bit each). */
enum { ISK_WALL_SCREEN = 16, ISK_WALL_SCREEN_GROUPS = 64, ISK_WALL_SCREEN_SPAN = 16 * 64 };

/* Who is outside, a mask per group and axis. */
typedef struct isk_wall_outside {
    uint16_t x[ISK_WALL_SCREEN_GROUPS], y[ISK_WALL_SCREEN_GROUPS];
} isk_wall_outside;

typedef uint64_t (*isk_wall_screen_fn)(size_t n, const double *x, const double *y, const isk_wall_box *w,
                                       isk_wall_outside *out);

uint64_t isk__wall_screen_portable(size_t n, const double *x, const double *y, const isk_wall_box *w,
                                  isk_wall_outside *out);
/* The AVX2 and AVX-512 builds, each NULL when this build or this CPU has
 * none. */
isk_wall_screen_fn isk__wall_screen_avx2(void);
isk_wall_screen_fn isk__wall_screen_avx512(void);
/* The fastest build this CPU runs. */
isk_wall_screen_fn isk__wall_screen_pick(void);

#endif
