/* SPDX-License-Identifier: MIT */
/* Hybrid Tausworthe generator (three Tausworthe steps xor an LCG). */
#include "iskra/rng.h"

#include <math.h>

static uint32_t taus_step(uint32_t *z, int s1, int s2, int s3, uint32_t m)
{
    uint32_t b = ((*z << s1) ^ *z) >> s2;
    *z = ((*z & m) << s3) ^ b;
    return *z;
}

static uint32_t lcg_step(uint32_t *z)
{
    *z = 1664525u * *z + 1013904223u;
    return *z;
}

static uint64_t splitmix64(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

void isk_rng_seed(isk_rng *r, uint64_t seed)
{
    if (!r)
        return;
    uint64_t s = seed;
    uint64_t a = splitmix64(&s), b = splitmix64(&s);
    r->z1 = (uint32_t)a;
    r->z2 = (uint32_t)(a >> 32);
    r->z3 = (uint32_t)b;
    r->z4 = (uint32_t)(b >> 32);
    /* A Tausworthe word below its minimum degenerates to a short cycle. */
    if (r->z1 < 2u) r->z1 += 2u;
    if (r->z2 < 8u) r->z2 += 8u;
    if (r->z3 < 16u) r->z3 += 16u;
}

uint32_t isk_rng_u32(isk_rng *r)
{
    if (!r) /* no generator: every draw is 0 (so uniform 0, range lo, normal 0) */
        return 0u;
    return taus_step(&r->z1, 13, 19, 12, 4294967294u) ^ taus_step(&r->z2, 2, 25, 4, 4294967288u) ^
           taus_step(&r->z3, 3, 11, 17, 4294967280u) ^ lcg_step(&r->z4);
}

double isk_rng_uniform(isk_rng *r)
{
    uint32_t a = isk_rng_u32(r) >> 5; /* 27 bits */
    uint32_t b = isk_rng_u32(r) >> 6; /* 26 bits */
    return ((double)a * 67108864.0 + (double)b) * (1.0 / 9007199254740992.0);
}

double isk_rng_range(isk_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * isk_rng_uniform(r);
}

uint32_t isk_rng_below(isk_rng *r, uint32_t n)
{
    if (n == 0u || !r) /* (a NULL generator's zeros would never pass the rejection) */
        return 0u;
    /* Lemire's multiply-and-reject: unbiased, usually one draw. */
    uint64_t m = (uint64_t)isk_rng_u32(r) * n;
    uint32_t low = (uint32_t)m;
    if (low < n) {
        uint32_t threshold = (uint32_t)(-n) % n;
        while (low < threshold) {
            m = (uint64_t)isk_rng_u32(r) * n;
            low = (uint32_t)m;
        }
    }
    return (uint32_t)(m >> 32);
}

void isk_rng_normal2(isk_rng *r, double *z0, double *z1)
{
    const double two_pi = 6.283185307179586;
    double u1 = 1.0 - isk_rng_uniform(r); /* (0, 1]: ln never sees 0 */
    double u2 = isk_rng_uniform(r);
    double rad = sqrt(-2.0 * log(u1));
    double th = two_pi * u2;
    if (z0) *z0 = rad * cos(th);
    if (z1) *z1 = rad * sin(th);
}
