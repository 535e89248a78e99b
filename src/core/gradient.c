/* SPDX-License-Identifier: MIT */
/* Colour and scalar gradients baked into lookup tables (iskra/gradient.h). */
#include "iskra/gradient.h"

#include <math.h>
#include <stdlib.h>

/* Stop positions: 1..16 of them, finite, in [0, 1], strictly increasing. */
static isk_status check_t(const double *t, int n)
{
    double prev = -1.0;
    for (int k = 0; k < n; k++) {
        if (!isfinite(t[k]))
            return ISK_ERR_NAN;
        if (t[k] < 0.0 || t[k] > 1.0 || t[k] <= prev)
            return ISK_ERR_RANGE;
        prev = t[k];
    }
    return ISK_OK;
}

isk_status isk_color_stops_check(const isk_color_stop *stops, int n)
{
    if (!stops)
        return ISK_ERR_NULL;
    if (n < 1 || n > ISK_GRADIENT_MAX_STOPS)
        return ISK_ERR_SIZE;
    double t[ISK_GRADIENT_MAX_STOPS];
    for (int k = 0; k < n; k++)
        t[k] = stops[k].t;
    return check_t(t, n);
}

isk_status isk_scalar_stops_check(const isk_scalar_stop *stops, int n)
{
    if (!stops)
        return ISK_ERR_NULL;
    if (n < 1 || n > ISK_GRADIENT_MAX_STOPS)
        return ISK_ERR_SIZE;
    double t[ISK_GRADIENT_MAX_STOPS];
    for (int k = 0; k < n; k++) {
        if (!isfinite(stops[k].value))
            return ISK_ERR_NAN;
        t[k] = stops[k].t;
    }
    return check_t(t, n);
}

/* 1 when the plain floor(t*R) falls below k at some sample point t_k = k/R;
 * rounding is monotonic, so then every t >= t_k is fine too. */
static int needs_fixup(int res)
{
    for (int k = 1; k <= res; k++) {
        double tk = (double)k / res;
        if ((int)(tk * res) != k)
            return 1;
    }
    return 0;
}

/* The lookups' clamp: NaN and t <= 0 give 0, t >= 1 gives 1. */
static double clamp_t(double t)
{
    if (!(t > 0.0))
        return 0.0;
    return t >= 1.0 ? 1.0 : t;
}

static uint8_t lerp_channel(uint8_t a, uint8_t b, double f)
{
    double v = (double)a + ((double)b - (double)a) * f;
    double r = floor(v + 0.5); /* halves up */
    return (uint8_t)(r < 0.0 ? 0.0 : r > 255.0 ? 255.0 : r);
}

isk_color isk_color_gradient_eval(const isk_color_stop *s, int n, double t)
{
    if (!s || n < 1)
        return (isk_color){0, 0, 0, 0};
    t = clamp_t(t);
    if (t <= s[0].t)
        return s[0].color;
    if (t >= s[n - 1].t)
        return s[n - 1].color;
    int k = 0; /* the last stop at or before t */
    while (k + 1 < n - 1 && s[k + 1].t <= t)
        k++;
    double f = (t - s[k].t) / (s[k + 1].t - s[k].t);
    isk_color a = s[k].color, b = s[k + 1].color, c;
    c.r = lerp_channel(a.r, b.r, f);
    c.g = lerp_channel(a.g, b.g, f);
    c.b = lerp_channel(a.b, b.b, f);
    c.a = lerp_channel(a.a, b.a, f);
    return c;
}

double isk_scalar_gradient_eval(const isk_scalar_stop *s, int n, double t)
{
    if (!s || n < 1)
        return 0.0;
    t = clamp_t(t);
    if (t <= s[0].t)
        return s[0].value;
    if (t >= s[n - 1].t)
        return s[n - 1].value;
    int k = 0; /* the last stop at or before t */
    while (k + 1 < n - 1 && s[k + 1].t <= t)
        k++;
    double f = (t - s[k].t) / (s[k + 1].t - s[k].t);
    return s[k].value + (s[k + 1].value - s[k].value) * f;
}

isk_status isk_color_gradient_bake(isk_color_gradient *g, const isk_color_stop *stops, int n, int res)
{
    if (!g)
        return ISK_ERR_NULL;
    isk_status st = isk_color_stops_check(stops, n);
    if (st != ISK_OK)
        return st;
    if (res < 1 || res > ISK_GRADIENT_MAX_RES)
        return ISK_ERR_SIZE;
    isk_color *tab = malloc(((size_t)res + 1u) * sizeof *tab);
    if (!tab)
        return ISK_ERR_NOMEM;
    for (int i = 0; i <= res; i++)
        tab[i] = isk_color_gradient_eval(stops, n, (double)i / res);
    g->res = res;
    g->fixup = needs_fixup(res);
    g->table = tab;
    return ISK_OK;
}

isk_status isk_scalar_gradient_bake(isk_scalar_gradient *g, const isk_scalar_stop *stops, int n, int res)
{
    if (!g)
        return ISK_ERR_NULL;
    isk_status st = isk_scalar_stops_check(stops, n);
    if (st != ISK_OK)
        return st;
    if (res < 1 || res > ISK_GRADIENT_MAX_RES)
        return ISK_ERR_SIZE;
    double *tab = malloc(((size_t)res + 1u) * sizeof *tab);
    if (!tab)
        return ISK_ERR_NOMEM;
    for (int i = 0; i <= res; i++)
        tab[i] = isk_scalar_gradient_eval(stops, n, (double)i / res);
    g->res = res;
    g->fixup = needs_fixup(res);
    g->table = tab;
    return ISK_OK;
}

void isk_color_gradient_free(isk_color_gradient *g)
{
    if (g) {
        free(g->table);
        g->table = NULL;
        g->res = 0;
    }
}

void isk_scalar_gradient_free(isk_scalar_gradient *g)
{
    if (g) {
        free(g->table);
        g->table = NULL;
        g->res = 0;
    }
}
