/* SPDX-License-Identifier: MIT */
/* iskra/gradient.h — colour and scalar ramps over a particle's life, baked
 * into a table so a lookup is one multiply and one read.
 *
 * The particle-engine thesis (§5.2.5) bakes its colour gradient into
 * "thousandths" once, before the simulation.  Same here, with the open ends
 * tied down:
 *
 *   - 1..16 stops, positions t in [0, 1], strictly increasing, values an RGBA
 *     colour or a double (size, alpha, ...); linear interpolation between
 *     stops, constant before the first and after the last stop;
 *   - the table has R + 1 entries (R = resolution, default 1000), entry i =
 *     the exact interpolation at t_i = i/R (the double nearest), so t = 1
 *     has its own entry;
 *   - lookup (floor indexing): t is clamped to [0, 1] (NaN reads entry 0) and
 *     entry i = floor(t * R) is used, so t_i <= t < t_{i+1} up to an ulp
 *     (a t an ulp below t_{i+1} may read entry i+1: harmless, it is within
 *     the bound below).  When R is such that floor(t_i * R) rounds below i
 *     for some sample point (never for R = 1000 or a power of two, but e.g.
 *     for R = 100 or 10000; checked at bake time) the lookup corrects it
 *     with one division, so a lookup exactly at a stop placed on a multiple
 *     of 1/R always returns that stop's value;
 *   - colour interpolation per channel is c0 + (c1 - c0)(t - t0)/(t1 - t0)
 *     rounded half up: isk_color_gradient_eval() computes it directly (the
 *     exact reference).  A table read differs from it by at most
 *     ceil(max slope / R) levels, max slope = max |dc|/dt over the stops in
 *     levels per unit t (tests/test_gradient.c checks both claims).
 *
 * Example:
 *
 *     isk_color_stop fire[3] = {{0.0, {255, 240, 160, 255}},
 *                               {0.3, {255, 140, 20, 220}},
 *                               {1.0, {80, 10, 0, 0}}};
 *     isk_color_gradient g;
 *     if (isk_color_gradient_bake(&g, fire, 3, ISK_GRADIENT_DEFAULT_RES) != ISK_OK) return 1;
 *     double age = 0.3, lifetime = 2.0;
 *     isk_color c = isk_color_gradient_at(&g, age / lifetime);   // half-way to the second stop
 *     printf("%d %d %d %d\n", c.r, c.g, c.b, c.a);
 *     isk_color_gradient_free(&g);
 *
 * Scalar gradients work the same way with doubles (no rounding: a table read
 * differs from the exact value by at most max slope / R, plus rounding).
 * Rebaking means baking a new gradient (the thesis rebakes on every stop
 * change).  Baking allocates; lookups never fail.
 */
#ifndef ISKRA_GRADIENT_H
#define ISKRA_GRADIENT_H

#include "iskra/color.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ISK_GRADIENT_MAX_STOPS 16
#define ISK_GRADIENT_DEFAULT_RES 1000
#define ISK_GRADIENT_MAX_RES 65536

typedef struct isk_color_stop {
    double t;
    isk_color color;
} isk_color_stop;

typedef struct isk_scalar_stop {
    double t;
    double value;
} isk_scalar_stop;

typedef struct isk_color_gradient {
    int res;           /* R: entries 0..R */
    int fixup;         /* 1 when floor(t*R) needs the correction (see above) */
    isk_color *table;
} isk_color_gradient;

typedef struct isk_scalar_gradient {
    int res;
    int fixup;
    double *table;
} isk_scalar_gradient;

/* Checks stops: ISK_ERR_NULL, ISK_ERR_SIZE (count outside 1..16), ISK_ERR_NAN
 * (non-finite t or value), ISK_ERR_RANGE (t outside [0, 1] or not strictly
 * increasing).  Bake functions also return ISK_ERR_SIZE for res outside
 * 1..65536 and ISK_ERR_NOMEM; on error *g is left unchanged. */
isk_status isk_color_stops_check(const isk_color_stop *stops, int n);
isk_status isk_scalar_stops_check(const isk_scalar_stop *stops, int n);

isk_status isk_color_gradient_bake(isk_color_gradient *g, const isk_color_stop *stops, int n, int res);
isk_status isk_scalar_gradient_bake(isk_scalar_gradient *g, const isk_scalar_stop *stops, int n, int res);
void isk_color_gradient_free(isk_color_gradient *g);
void isk_scalar_gradient_free(isk_scalar_gradient *g);

/* The exact interpolation (no table), for valid stops; t is clamped the same
 * way as in the lookups.  NULL stops or n < 1 give transparent black / 0. */
isk_color isk_color_gradient_eval(const isk_color_stop *stops, int n, double t);
double isk_scalar_gradient_eval(const isk_scalar_stop *stops, int n, double t);

/* Table index for t (see the lookup rule above). */
static inline int isk_gradient_index(int res, int fixup, double t)
{
    if (!(t > 0.0)) /* also NaN */
        return 0;
    if (t >= 1.0)
        return res;
    int i = (int)(t * res); /* 0 <= t*res <= res: in range */
    if (fixup && i < res && t >= (double)(i + 1) / res)
        i++;
    return i;
}

static inline isk_color isk_color_gradient_at(const isk_color_gradient *g, double t)
{
    return g->table[isk_gradient_index(g->res, g->fixup, t)];
}

static inline double isk_scalar_gradient_at(const isk_scalar_gradient *g, double t)
{
    return g->table[isk_gradient_index(g->res, g->fixup, t)];
}

#ifdef __cplusplus
}
#endif

#endif
