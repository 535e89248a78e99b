/* SPDX-License-Identifier: MIT */
/* Baked gradients: exact at stops on the grid, within ceil(max slope / R)
 * levels elsewhere, clamping, validation, the index fix-up. */
#include <criterion/criterion.h>
#include <criterion/logging.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/gradient.h"
#include "iskra/rng.h"

static const int RESES[] = {1000, 100, 10000, 256, 999, 7, 1};

static int same_color(isk_color a, isk_color b)
{
    return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

static isk_color random_color(isk_rng *r)
{
    return isk_rgba((uint8_t)isk_rng_below(r, 256), (uint8_t)isk_rng_below(r, 256), (uint8_t)isk_rng_below(r, 256),
                    (uint8_t)isk_rng_below(r, 256));
}

/* Stops at distinct multiples of 1/res, increasing. */
static int grid_stops(isk_rng *r, int res, isk_color_stop *s)
{
    int n = 1 + (int)isk_rng_below(r, res + 1 < 16 ? (uint32_t)res + 1 : 16u);
    int k = (int)isk_rng_below(r, (uint32_t)(res - n + 2));
    for (int j = 0; j < n; j++) {
        s[j].t = (double)k / res;
        s[j].color = random_color(r);
        int room = res - k - (n - 1 - j); /* leave space for the rest */
        k += 1 + (room > 1 ? (int)isk_rng_below(r, (uint32_t)(room < 200 ? room : 200)) : 0);
    }
    return n;
}

Test(gradient, exact_at_stops_on_the_grid)
{
    isk_rng r;
    isk_rng_seed(&r, 25);
    for (size_t ri = 0; ri < sizeof RESES / sizeof RESES[0]; ri++) {
        int res = RESES[ri];
        for (int trial = 0; trial < 50; trial++) {
            isk_color_stop s[16];
            int n = grid_stops(&r, res, s);
            cr_assert_eq(isk_color_stops_check(s, n), ISK_OK);
            isk_color_gradient g;
            cr_assert_eq(isk_color_gradient_bake(&g, s, n, res), ISK_OK);
            for (int j = 0; j < n; j++) {
                isk_color c = isk_color_gradient_at(&g, s[j].t);
                cr_assert(same_color(c, s[j].color), "res %d stop %d at t=%.17g", res, j, s[j].t);
                cr_assert(same_color(c, isk_color_gradient_eval(s, n, s[j].t)));
            }
            /* every sample point reads its own entry = the exact value */
            for (int i = 0; i <= res; i++) {
                double t = (double)i / res;
                cr_assert(same_color(isk_color_gradient_at(&g, t), isk_color_gradient_eval(s, n, t)), "res %d i %d",
                          res, i);
            }
            isk_color_gradient_free(&g);
        }
    }
}

static double max_slope(const isk_color_stop *s, int n)
{
    double m = 0.0;
    for (int k = 0; k + 1 < n; k++) {
        const uint8_t *a = &s[k].color.r, *b = &s[k + 1].color.r;
        for (int ch = 0; ch < 4; ch++)
            m = fmax(m, fabs((double)b[ch] - (double)a[ch]) / (s[k + 1].t - s[k].t));
    }
    return m;
}

Test(gradient, error_bound_elsewhere)
{
    isk_rng r;
    isk_rng_seed(&r, 26);
    int worst_seen = 0;
    for (size_t ri = 0; ri < sizeof RESES / sizeof RESES[0]; ri++) {
        int res = RESES[ri];
        for (int trial = 0; trial < 40; trial++) {
            isk_color_stop s[16];
            int n = 1 + (int)isk_rng_below(&r, 16);
            double t = isk_rng_range(&r, 0.0, 0.3);
            for (int j = 0; j < n; j++) { /* arbitrary, increasing, in [0, 1] */
                s[j].t = t;
                s[j].color = random_color(&r);
                t += isk_rng_range(&r, 1e-3, 0.7 / n);
            }
            isk_color_gradient g;
            cr_assert_eq(isk_color_gradient_bake(&g, s, n, res), ISK_OK);
            int bound = (int)ceil(max_slope(s, n) / res);
            for (int i = 0; i < 20000; i++) {
                double u = (i % 5 == 0) ? s[i % n].t + isk_rng_range(&r, -1e-9, 1e-9) : isk_rng_uniform(&r);
                isk_color a = isk_color_gradient_at(&g, u), b = isk_color_gradient_eval(s, n, u);
                const uint8_t *pa = &a.r, *pb = &b.r;
                for (int ch = 0; ch < 4; ch++) {
                    int d = abs((int)pa[ch] - (int)pb[ch]);
                    cr_assert_leq(d, bound, "res %d t %.17g ch %d: %d vs %d (bound %d)", res, u, ch, pa[ch], pb[ch],
                                  bound);
                    if (res == 1000 && d > worst_seen)
                        worst_seen = d;
                }
            }
            isk_color_gradient_free(&g);
        }
    }
    cr_log_info("largest difference seen at R = 1000: %d levels", worst_seen);
}

/* The particle-engine digest's worked bounds at R = 1000. */
Test(gradient, thesis_worked_bounds)
{
    isk_color_stop bw[2] = {{0.0, {0, 0, 0, 255}}, {1.0, {255, 255, 255, 255}}};
    isk_color_stop steep[3] = {{0.0, {0, 0, 0, 255}}, {0.25, {255, 0, 0, 255}}, {1.0, {255, 0, 0, 255}}};
    isk_color_gradient g;
    cr_assert_eq(isk_color_gradient_bake(&g, bw, 2, ISK_GRADIENT_DEFAULT_RES), ISK_OK);
    cr_expect_eq(g.fixup, 0);
    int worst = 0;
    for (int i = 0; i <= 1000000; i++) {
        double t = i / 1e6;
        worst = fmax(worst, abs(isk_color_gradient_at(&g, t).r - isk_color_gradient_eval(bw, 2, t).r));
    }
    cr_expect_leq(worst, 1); /* ceil(0.255) */
    isk_color_gradient_free(&g);
    cr_assert_eq(isk_color_gradient_bake(&g, steep, 3, ISK_GRADIENT_DEFAULT_RES), ISK_OK);
    worst = 0;
    for (int i = 0; i <= 1000000; i++) {
        double t = i / 1e6;
        worst = fmax(worst, abs(isk_color_gradient_at(&g, t).r - isk_color_gradient_eval(steep, 3, t).r));
    }
    cr_expect_leq(worst, 2); /* ceil(1.02) */
    cr_expect_geq(worst, 1);
    isk_color_gradient_free(&g);
}

Test(gradient, clamping_and_ends)
{
    isk_color_stop s[2] = {{0.2, {10, 20, 30, 40}}, {0.8, {110, 120, 130, 140}}};
    isk_color_gradient g;
    cr_assert_eq(isk_color_gradient_bake(&g, s, 2, 1000), ISK_OK);
    double lows[] = {0.0, -0.0, -1.0, -INFINITY, NAN, -NAN, 0.1, 0.2};
    for (size_t i = 0; i < sizeof lows / sizeof lows[0]; i++)
        cr_expect(same_color(isk_color_gradient_at(&g, lows[i]), s[0].color), "t=%g", lows[i]);
    double highs[] = {1.0, 1.0000001, 1e300, INFINITY, 0.8, 0.9};
    for (size_t i = 0; i < sizeof highs / sizeof highs[0]; i++)
        cr_expect(same_color(isk_color_gradient_at(&g, highs[i]), s[1].color), "t=%g", highs[i]);
    cr_expect(same_color(g.table[1000], s[1].color)); /* t = 1 has its own entry */
    isk_color mid = isk_color_gradient_at(&g, 0.5);
    cr_expect(mid.r == 60 && mid.g == 70 && mid.b == 80 && mid.a == 90);
    isk_color_gradient_free(&g);
    /* one stop: constant */
    isk_color_stop one = {0.5, {1, 2, 3, 4}};
    cr_assert_eq(isk_color_gradient_bake(&g, &one, 1, 10), ISK_OK);
    for (int i = -2; i <= 12; i++)
        cr_expect(same_color(isk_color_gradient_at(&g, i / 10.0), one.color));
    isk_color_gradient_free(&g);
    isk_color_gradient_free(&g); /* safe twice */
    isk_color_gradient_free(NULL);
}

Test(gradient, validation_leaves_gradient_alone)
{
    isk_color_gradient g = {77, 0, NULL};
    isk_color_stop ok[2] = {{0.0, {0, 0, 0, 0}}, {1.0, {255, 255, 255, 255}}};
    isk_color_stop s[17];
    for (int i = 0; i < 17; i++) {
        s[i].t = i / 16.0;
        s[i].color = ISK_WHITE;
    }
    cr_expect_eq(isk_color_gradient_bake(&g, s, 0, 1000), ISK_ERR_SIZE);
    cr_expect_eq(isk_color_gradient_bake(&g, s, 17, 1000), ISK_ERR_SIZE);
    cr_expect_eq(isk_color_gradient_bake(&g, NULL, 2, 1000), ISK_ERR_NULL);
    cr_expect_eq(isk_color_gradient_bake(NULL, ok, 2, 1000), ISK_ERR_NULL);
    cr_expect_eq(isk_color_gradient_bake(&g, ok, 2, 0), ISK_ERR_SIZE);
    cr_expect_eq(isk_color_gradient_bake(&g, ok, 2, ISK_GRADIENT_MAX_RES + 1), ISK_ERR_SIZE);
    isk_color_stop bad[2] = {{0.0, {0, 0, 0, 0}}, {1.0, {0, 0, 0, 0}}};
    bad[1].t = NAN;
    cr_expect_eq(isk_color_gradient_bake(&g, bad, 2, 1000), ISK_ERR_NAN);
    bad[1].t = INFINITY;
    cr_expect_eq(isk_color_gradient_bake(&g, bad, 2, 1000), ISK_ERR_NAN);
    bad[1].t = 1.1;
    cr_expect_eq(isk_color_gradient_bake(&g, bad, 2, 1000), ISK_ERR_RANGE);
    bad[1].t = 0.0; /* not strictly increasing */
    cr_expect_eq(isk_color_gradient_bake(&g, bad, 2, 1000), ISK_ERR_RANGE);
    bad[0].t = -0.1;
    bad[1].t = 0.5;
    cr_expect_eq(isk_color_gradient_bake(&g, bad, 2, 1000), ISK_ERR_RANGE);
    cr_expect_eq(g.res, 77);
    cr_expect_null(g.table);
    isk_color_gradient g16;
    cr_expect_eq(isk_color_gradient_bake(&g16, s, 16, 1000), ISK_OK); /* 16 stops is the limit */
    isk_color_gradient_free(&g16);

    isk_scalar_gradient sg = {5, 0, NULL};
    isk_scalar_stop ss[2] = {{0.0, 1.0}, {1.0, NAN}};
    cr_expect_eq(isk_scalar_gradient_bake(&sg, ss, 2, 1000), ISK_ERR_NAN);
    ss[1].value = -INFINITY;
    cr_expect_eq(isk_scalar_gradient_bake(&sg, ss, 2, 1000), ISK_ERR_NAN);
    ss[1].value = 2.0;
    ss[1].t = 0.0;
    cr_expect_eq(isk_scalar_gradient_bake(&sg, ss, 2, 1000), ISK_ERR_RANGE);
    cr_expect_eq(sg.res, 5);
    cr_expect_null(sg.table);
}

Test(gradient, scalar_exact_and_bound)
{
    isk_rng r;
    isk_rng_seed(&r, 27);
    for (size_t ri = 0; ri < sizeof RESES / sizeof RESES[0]; ri++) {
        int res = RESES[ri];
        for (int trial = 0; trial < 30; trial++) {
            isk_color_stop cs[16];
            int n = grid_stops(&r, res, cs);
            isk_scalar_stop s[16];
            double slope = 0.0;
            for (int j = 0; j < n; j++) {
                s[j].t = cs[j].t;
                s[j].value = isk_rng_range(&r, -50.0, 50.0);
                if (j > 0)
                    slope = fmax(slope, fabs(s[j].value - s[j - 1].value) / (s[j].t - s[j - 1].t));
            }
            isk_scalar_gradient g;
            cr_assert_eq(isk_scalar_gradient_bake(&g, s, n, res), ISK_OK);
            for (int j = 0; j < n; j++)
                cr_assert_eq(isk_scalar_gradient_at(&g, s[j].t), s[j].value);
            for (int i = 0; i < 5000; i++) {
                double u = isk_rng_uniform(&r);
                double d = fabs(isk_scalar_gradient_at(&g, u) - isk_scalar_gradient_eval(s, n, u));
                /* plus rounding of two interpolations of values <= 50 */
                cr_assert_leq(d, slope / res + 1e-12, "res %d t %.17g", res, u);
            }
            isk_scalar_gradient_free(&g);
        }
    }
}

Test(gradient, index_fixup)
{
    isk_color_stop one = {0.0, {1, 2, 3, 4}};
    int expect_fix[] = {0, 1, 1, 0, 1, 0, 0}; /* for RESES: 100, 10000, 999 need it */
    for (size_t ri = 0; ri < sizeof RESES / sizeof RESES[0]; ri++) {
        int res = RESES[ri];
        isk_color_gradient g;
        cr_assert_eq(isk_color_gradient_bake(&g, &one, 1, res), ISK_OK);
        cr_expect_eq(g.fixup, expect_fix[ri], "res %d", res);
        for (int i = 0; i <= res; i++) {
            double t = (double)i / res;
            cr_assert_eq(isk_gradient_index(res, g.fixup, t), i, "res %d i %d", res, i);
            if (i > 0) { /* an ulp below: i - 1, or i (documented) */
                int j = isk_gradient_index(res, g.fixup, nextafter(t, 0.0));
                cr_assert(j == i - 1 || j == i, "res %d below %d", res, i);
            }
        }
        isk_color_gradient_free(&g);
    }
}
