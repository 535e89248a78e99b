/* src/sim/wall_screen.h — the walls' screen: which groups of a block have a
 * particle that ended its step outside the walls (internal).
 *
 * The bounces at the time of impact (iskra/impact.h) touch only particles
 * beyond a wall, a few per step; the screen finds their groups in one pass
 * over both axes, so the rest of the block costs a few vector operations
 * per particle:
 *
 *     isk_wall_box box = {left, right, bottom, top};    // a missing wall: -inf / +inf
 *     uint64_t flags = isk_wall_screen_pick()(n, x, y, &box);   // n <= ISK_WALL_SCREEN_SPAN
 *     // bit g set: some particle of [g * ISK_WALL_SCREEN, (g + 1) * ISK_WALL_SCREEN) is outside
 *
 * Outside means a sign bit set in x - left, right - x, y - bottom or
 * top - y (an exact hit, x == left, is +0: inside; a -0 on a +0 wall gives
 * -0, a false alarm).  A flag is a hint, not a verdict: the caller tests
 * each particle of a flagged group exactly.
 * A non-finite coordinate may be flagged or not (a NaN keeps its own sign;
 * a disabled wall's infinity against an infinite coordinate gives NaN):
 * the bounces leave non-finite particles to the runner either way.
 *
 * Three builds of the same arithmetic: the portable one (compiler-vectorized
 * loops, baseline x86-64 SSE2 or whatever the target has) and, on x86-64
 * CPUs that have them, AVX2 and AVX-512, chosen at run time.  They give the
 * same flags for every input (tests/test_wall_screen.c). */
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

typedef uint64_t (*isk_wall_screen_fn)(size_t n, const double *x, const double *y, const isk_wall_box *w);

uint64_t isk_wall_screen_portable(size_t n, const double *x, const double *y, const isk_wall_box *w);
/* The AVX2 and AVX-512 builds, each NULL when this build or this CPU has
 * none. */
isk_wall_screen_fn isk_wall_screen_avx2(void);
isk_wall_screen_fn isk_wall_screen_avx512(void);
/* The fastest build this CPU runs. */
isk_wall_screen_fn isk_wall_screen_pick(void);

#endif
