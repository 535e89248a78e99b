/* SPDX-License-Identifier: MIT */
/* Gradient noise for turbulence (src/sim/field.h): Perlin's improved noise
 * in three dimensions, with the lattice gradients picked by a hash of the
 * lattice point and the key instead of a permutation table, so that a
 * noise is a 64-bit number and not 512 bytes, and two turbulences of one
 * scene differ by their keys alone.  Everything is exact IEEE arithmetic
 * on the arguments: the same bits on every machine and thread. */
#include <math.h>
#include <stdint.h>

#include "sim/field.h"

/* splitmix64's finaliser: every input bit reaches every output bit. */
static uint64_t mix(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

uint64_t isk__noise_key(uint64_t seed, int index)
{
    return mix(mix(seed ^ 0x7475726275u) + (uint64_t)(unsigned)index * 0x9E3779B97F4A7C15u);
}

/* Perlin's twelve edge directions (four repeated to make sixteen). */
static const signed char grad[16][3] = {{1, 1, 0},  {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1},  {-1, 0, 1},
                                        {1, 0, -1}, {-1, 0, -1}, {0, 1, 1}, {0, -1, 1},  {0, 1, -1}, {0, -1, -1},
                                        {1, 1, 0},  {-1, 1, 0}, {0, -1, 1}, {0, -1, -1}};

static const signed char *corner_grad(uint64_t key, int64_t i, int64_t j, int64_t k)
{
    uint64_t h = mix(key + (uint64_t)i * 0x9E3779B97F4A7C15u + (uint64_t)j * 0xC2B2AE3D27D4EB4Fu +
                     (uint64_t)k * 0x165667B19E3779F9u);
    return grad[h >> 60];
}

/* Beyond 2^52 a double has no fraction left: every point is a lattice
 * point, where the noise is 0 and its gradient that corner's, the same
 * everywhere past the clamp below (a uniform wind of sqrt 2 x strength). */
static const double lim = 4503599627370496.0; /* 2^52 */

/* The lattice cell of u and the fraction within it; u beyond 2^52 (and an
 * integer conversion would overflow) is clamped. */
static double cell(double u, int64_t *i)
{
    if (!(u > -lim))
        u = -lim; /* NaN too: never converted */
    if (u > lim)
        u = lim;
    double f = floor(u);
    *i = (int64_t)f;
    return u - f;
}

static double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
static double dfade(double t) { return 30.0 * t * t * (t * (t - 2.0) + 1.0); }

double isk__noise3(uint64_t key, double u, double v, double w, double *du, double *dv)
{
    /* Where the plane has no lattice fraction left (or is not a number)
     * there is no noise: a still field, not a wind.  Time (w) past it only
     * freezes the pattern. */
    if (!(fabs(u) < lim && fabs(v) < lim)) {
        if (du)
            *du = 0.0;
        if (dv)
            *dv = 0.0;
        return 0.0;
    }
    int64_t i, j, k;
    const double fu = cell(u, &i), fv = cell(v, &j), fw = cell(w, &k);
    const double su = fade(fu), sv = fade(fv), sw = fade(fw);
    const double dsu = dfade(fu), dsv = dfade(fv);
    double n = 0.0, nu = 0.0, nv = 0.0;
    for (int c = 0; c < 8; c++) {
        const int cu = c & 1, cv = (c >> 1) & 1, cw = (c >> 2) & 1;
        const signed char *g = corner_grad(key, i + cu, j + cv, k + cw);
        const double x = fu - cu, y = fv - cv, z = fw - cw;
        const double dot = g[0] * x + g[1] * y + g[2] * z;
        const double wu = cu ? su : 1.0 - su, wv = cv ? sv : 1.0 - sv, ww = cw ? sw : 1.0 - sw;
        const double dwu = cu ? dsu : -dsu, dwv = cv ? dsv : -dsv;
        n += wu * wv * ww * dot;
        nu += (dwu * dot + wu * g[0]) * wv * ww;
        nv += (dwv * dot + wv * g[1]) * wu * ww;
    }
    if (du)
        *du = nu;
    if (dv)
        *dv = nv;
    return n;
}
