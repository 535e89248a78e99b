/* SPDX-License-Identifier: MIT */
/* Sine lookup table: set-up, the slow huge-angle reduction and the bounds.
 * The lookups themselves are static inline in iskra/sinlut.h; the table is
 * generated into sinlut_table.c by tools/gen_sinlut.c. */
#include "iskra/sinlut.h"

#include <math.h>

/* 1/(2 pi) and 2 pi, each correctly rounded to double. */
static const double INV_TWO_PI = 0x1.45f306dc9c883p-3;
static const double TWO_PI = 0x1.921fb54442d18p+2;

/* log2 of n when n is a power of two in [MIN_N, MAX_N], else -1. */
static int table_log2(int n)
{
    if (n < ISK_SINLUT_MIN_N || n > ISK_SINLUT_MAX_N || (n & (n - 1)) != 0)
        return -1;
    int k = 0;
    while ((1 << k) < n)
        k++;
    return k;
}

isk_status isk_sinlut_init(isk_sinlut *lut, int n)
{
    if (!lut)
        return ISK_ERR_NULL;
    int k = table_log2(n);
    if (k < 0)
        return ISK_ERR_SIZE;
    lut->table = isk_sinlut_table;
    lut->stride = (size_t)(ISK_SINLUT_MAX_N / n);
    lut->mask = (uint64_t)n - 1u;
    /* Scaling by a power of two is exact, so every n shares the rounding of
     * 1/(2 pi) and t = theta*scale has the same relative error for all n. */
    lut->scale = ldexp(INV_TWO_PI, k);
    lut->n = n;
    return ISK_OK;
}

isk_status isk_sinlut_init_copy(isk_sinlut *lut, int n, double *buf, size_t buf_len)
{
    if (!lut || !buf)
        return ISK_ERR_NULL;
    isk_sinlut shared;
    isk_status st = isk_sinlut_init(&shared, n);
    if (st != ISK_OK)
        return st;
    if (buf_len < (size_t)n + 1u)
        return ISK_ERR_SIZE;
    for (size_t i = 0; i <= (size_t)n; i++)
        buf[i] = shared.table[i * shared.stride];
    *lut = shared;
    lut->table = buf;
    lut->stride = 1;
    return ISK_OK;
}

double isk_sinlut_reduce_slow(const isk_sinlut *lut, double theta)
{
    if (!lut || !isfinite(theta))
        return NAN;
    /* fmod is exact; |result| < 2 pi, so |t| <= n. */
    return fmod(theta, TWO_PI) * lut->scale;
}

const char *const isk_sinlut_mode_names[ISK_SINLUT_MODE_COUNT] = {"floor", "round", "lerp", "libm"};

double isk_sinlut_bound(int n, isk_sinlut_mode mode)
{
    if (table_log2(n) < 0)
        return 0.0;
    double h = TWO_PI / n;
    switch (mode) {
    case ISK_SINLUT_FLOOR: return h;
    case ISK_SINLUT_ROUND: return h / 2.0;
    case ISK_SINLUT_LERP: return h * h / 8.0;
    default: return 0.0;
    }
}

double isk_sinlut_eval(const isk_sinlut *lut, isk_sinlut_mode mode, double theta)
{
    if (!lut || !lut->table)
        return NAN;
    switch (mode) {
    case ISK_SINLUT_FLOOR: return isk_sinlut_floor(lut, theta);
    case ISK_SINLUT_ROUND: return isk_sinlut_round(lut, theta);
    case ISK_SINLUT_LERP: return isk_sinlut_lerp(lut, theta);
    case ISK_SINLUT_LIBM: return sin(theta);
    default: return NAN;
    }
}
