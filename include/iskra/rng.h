/* SPDX-License-Identifier: MIT */
/* iskra/rng.h — the seeded random number generator every random draw uses.
 *
 * The explosion thesis's hybrid Tausworthe generator (its WebGPU chapter,
 * after GPU Gems 3 ch. 37): three Tausworthe steps xor a linear congruential
 * step, each on 32-bit state.  Here the four words are state that advances
 * on every draw (the thesis's shader version recomputes from fixed keys).
 *
 * Example:
 *
 *     isk_rng r;
 *     isk_rng_seed(&r, 42);
 *     double u = isk_rng_uniform(&r);        // [0, 1)
 *     double z0, z1;
 *     isk_rng_normal2(&r, &z0, &z1);         // two N(0,1) draws
 *     printf("%.17g %.17g %.17g\n", u, z0, z1);   // the same on every machine
 *
 * One generator per system, passed explicitly: no global state, so two
 * systems in one process never disturb each other, and the same seed gives
 * the same sequence on every machine (integer arithmetic; the only libm calls
 * are in isk_rng_normal2, see below).
 *
 * Draw order is part of the contract: isk_rng_uniform consumes exactly two
 * 32-bit outputs (high 27 bits of the first, high 26 of the second, 53 bits
 * in all); isk_rng_normal2 consumes exactly two uniforms (u1 then u2, the
 * order of the thesis's Box–Muller) and uses log, sqrt, cos and sin.
 */
#ifndef ISKRA_RNG_H
#define ISKRA_RNG_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct isk_rng {
    uint32_t z1, z2, z3, z4;
} isk_rng;

/* Derives the four state words from a 64-bit seed (splitmix64), forcing the
 * Tausworthe words above their minimum values (z1 >= 2, z2 >= 8, z3 >= 16). */
void isk_rng_seed(isk_rng *r, uint64_t seed);

/* Next raw 32-bit output: taus(z1) ^ taus(z2) ^ taus(z3) ^ lcg(z4).
 * A NULL generator is a programming error that never crashes: every draw
 * from it is 0 (uniform 0.0, range lo, below 0, normals 0), and seeding it
 * does nothing. */
uint32_t isk_rng_u32(isk_rng *r);

/* Uniform double in [0, 1) with 53 random bits. */
double isk_rng_uniform(isk_rng *r);

/* Uniform double in [lo, hi): lo + (hi - lo) * u. */
double isk_rng_range(isk_rng *r, double lo, double hi);

/* Uniform integer in [0, n) without modulo bias (n > 0); 0 when n == 0. */
uint32_t isk_rng_below(isk_rng *r, uint32_t n);

/* Two independent N(0,1) draws by Box–Muller:
 *   z0 = sqrt(-2 ln u1) cos(2 pi u2),  z1 = sqrt(-2 ln u1) sin(2 pi u2)
 * with u1 taken as 1 - uniform, in (0, 1], so ln 0 can never happen. */
void isk_rng_normal2(isk_rng *r, double *z0, double *z1);

#ifdef __cplusplus
}
#endif

#endif
