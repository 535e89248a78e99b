/* SPDX-License-Identifier: MIT */
/* Spawn shapes and velocity generators: inequalities, distributions, draw
 * counts, rotation, validation. */
#include <criterion/criterion.h>
#include <criterion/logging.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/rng.h"
#include "iskra/shape.h"

#define PI 3.14159265358979323846
enum { N = 100000 };

static double xs[N], ys[N];

static void sample(const isk_shape *s, uint64_t seed)
{
    isk_rng r;
    isk_rng_seed(&r, seed);
    cr_assert_eq(isk_shape_sample_n(s, &r, N, xs, ys), ISK_OK);
}

/* The local offset of sample i (rotation undone). */
static void local(const isk_shape *s, int i, double *u, double *v)
{
    double dx = xs[i] - s->cx, dy = ys[i] - s->cy, c = cos(s->angle), sn = sin(s->angle);
    *u = c * dx + sn * dy;
    *v = -sn * dx + c * dy;
}

Test(shape, every_sample_satisfies_its_shape)
{
    const double eps = 1e-12;
    for (int rot = 0; rot < 2; rot++) {
        isk_shape shapes[] = {
            isk_shape_point(3, -2),
            isk_shape_disc(1, 2, 3),
            isk_shape_circle(-1, 0, 2.5),
            isk_shape_ring(0, 5, 1.5, 2.0),
            isk_shape_segment(1, 1, 4, -2),
            isk_shape_rect(-3, 2, 2, 0.5),
            isk_shape_ellipse(2, 2, 2, 1, ISK_ELLIPSE_UNIFORM),
            isk_shape_ellipse(2, 2, 2, 1, ISK_ELLIPSE_THESIS),
            isk_shape_gaussian(1, -1, 0.5, 2),
            isk_shape_rect_border(-3, 2, 2, 0.5),
            isk_shape_ellipse_border(2, 2, 2, 1),
        };
        for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; k++) {
            isk_shape *s = &shapes[k];
            s->angle = rot ? 0.7 : 0.0;
            cr_assert_eq(isk_shape_check(s), ISK_OK);
            sample(s, 100 + k);
            for (int i = 0; i < N; i++) {
                double u, v;
                local(s, i, &u, &v);
                double r = hypot(u, v);
                switch (s->kind) {
                case ISK_SHAPE_POINT:
                    cr_assert(xs[i] == s->cx && ys[i] == s->cy);
                    break;
                case ISK_SHAPE_DISC:
                    cr_assert_leq(r, s->a * (1 + eps));
                    break;
                case ISK_SHAPE_CIRCLE:
                    cr_assert_leq(fabs(r - s->a), s->a * eps);
                    break;
                case ISK_SHAPE_RING:
                    cr_assert(r >= s->a * (1 - eps) && r <= s->b * (1 + eps), "r = %.17g", r);
                    break;
                case ISK_SHAPE_SEGMENT: {
                    /* on the line through the start along (a, b), parameter in [0, 1] */
                    double dx = xs[i] - s->cx, dy = ys[i] - s->cy;
                    double ca = cos(s->angle), sa = sin(s->angle);
                    double ax = ca * s->a - sa * s->b, ay = sa * s->a + ca * s->b;
                    double len2 = ax * ax + ay * ay;
                    cr_assert_lt(fabs(ax * dy - ay * dx) / sqrt(len2), 1e-9);
                    double t = (ax * dx + ay * dy) / len2;
                    cr_assert(t >= -eps && t <= 1 + eps, "t = %g", t);
                    break;
                }
                case ISK_SHAPE_RECT:
                    cr_assert(fabs(u) <= s->a * (1 + eps) + eps && fabs(v) <= s->b * (1 + eps) + eps);
                    break;
                case ISK_SHAPE_ELLIPSE:
                    cr_assert_leq((u / s->a) * (u / s->a) + (v / s->b) * (v / s->b), 1 + 1e-9);
                    break;
                case ISK_SHAPE_GAUSSIAN: /* unbounded: finite, and within 9 sigma (p < 1e-17) */
                    cr_assert(fabs(u) <= 9 * s->a && fabs(v) <= 9 * s->b, "(%g, %g)", u, v);
                    break;
                case ISK_SHAPE_RECT_BORDER: { /* inside the rect, on one of its sides */
                    const double tol = 1e-12 * (1 + s->a + s->b);
                    cr_assert(fabs(u) <= s->a + tol && fabs(v) <= s->b + tol);
                    cr_assert(fabs(fabs(u) - s->a) <= tol || fabs(fabs(v) - s->b) <= tol, "(%g, %g)", u, v);
                    break;
                }
                case ISK_SHAPE_ELLIPSE_BORDER:
                    cr_assert_leq(fabs((u / s->a) * (u / s->a) + (v / s->b) * (v / s->b) - 1), 1e-9);
                    break;
                default:
                    cr_assert_fail("a shape kind without a test");
                }
            }
        }
    }
}

static double tip_fraction(isk_ellipse_mode mode)
{
    isk_shape s = isk_shape_ellipse(0, 0, 2, 1, mode);
    sample(&s, 7 + mode);
    long tip = 0;
    for (int i = 0; i < N; i++)
        tip += fabs(xs[i]) > 0.9 * 2;
    return (double)tip / N;
}

/* Particle-engine checks 8 and 9 (at 10^5 samples, so a wider tolerance
 * than the digest's 10^6: the standard error is 0.0006 and 0.0009). */
Test(shape, ellipse_modes)
{
    double uni = tip_fraction(ISK_ELLIPSE_UNIFORM), thesis = tip_fraction(ISK_ELLIPSE_THESIS);
    cr_log_info("ellipse A=2 B=1, |x| > 0.9A: area-uniform %.4f, thesis %.4f", uni, thesis);
    cr_expect_leq(fabs(uni - 0.0374), 0.003);
    cr_expect_leq(fabs(thesis - 0.1004), 0.005);
}

Test(shape, disc_centroid_and_uniformity)
{
    isk_shape s = isk_shape_disc(10, -4, 3);
    sample(&s, 9);
    double mx = 0, my = 0;
    long inner = 0;
    for (int i = 0; i < N; i++) {
        mx += xs[i];
        my += ys[i];
        inner += hypot(xs[i] - 10, ys[i] + 4) < 3 / sqrt(2.0); /* half the area */
    }
    mx /= N;
    my /= N;
    cr_expect_leq(hypot(mx - 10, my + 4), 0.02 * 3);
    cr_expect_leq(fabs((double)inner / N - 0.5), 0.01, "area-uniform: half inside r/sqrt(2)");
    /* ring: area-uniform between the radii */
    isk_shape g = isk_shape_ring(0, 0, 1, 2);
    sample(&g, 10);
    long in = 0;
    double mid = sqrt(2.5); /* splits the ring's area in half */
    for (int i = 0; i < N; i++)
        in += hypot(xs[i], ys[i]) < mid;
    cr_expect_leq(fabs((double)in / N - 0.5), 0.01);
}

/* Particle-engine check 11: rotating by 90 degrees turns local (1, 0) into
 * world (0, 1). */
Test(shape, rotation)
{
    isk_shape s = isk_shape_segment(0, 0, 1, 0);
    s.angle = PI / 2;
    isk_rng r;
    isk_rng_seed(&r, 1);
    for (int i = 0; i < 1000; i++) {
        double x, y;
        isk_shape_sample(&s, &r, &x, &y);
        cr_assert_leq(fabs(x), 1e-6);
        cr_assert(y >= 0 && y <= 1 + 1e-12);
    }
    /* unrotated samples are exact: a rect with half sizes 0 is its centre */
    isk_shape p = isk_shape_rect(0.1, 0.2, 0, 0);
    isk_rng_seed(&r, 1);
    double x, y;
    isk_shape_sample(&p, &r, &x, &y);
    cr_expect(x == 0.1 && y == 0.2);
}

/* The documented number of uniforms per sample, for every kind. */
Test(shape, draw_counts)
{
    struct { isk_shape s; int draws; } shapes[] = {
        {isk_shape_point(0, 0), 0},        {isk_shape_disc(0, 0, 1), 2},
        {isk_shape_circle(0, 0, 1), 1},    {isk_shape_ring(0, 0, 1, 2), 2},
        {isk_shape_segment(0, 0, 1, 1), 1}, {isk_shape_rect(0, 0, 1, 1), 2},
        {isk_shape_ellipse(0, 0, 2, 1, ISK_ELLIPSE_UNIFORM), 2},
        {isk_shape_ellipse(0, 0, 2, 1, ISK_ELLIPSE_THESIS), 2},
        {isk_shape_gaussian(0, 0, 2, 1), 2}, {isk_shape_rect_border(0, 0, 2, 1), 1},
        {isk_shape_ellipse_border(0, 0, 2, 1), 1},
    };
    for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; k++) {
        isk_rng r, twin;
        isk_rng_seed(&r, 55);
        isk_rng_seed(&twin, 55);
        double x[10], y[10];
        cr_assert_eq(isk_shape_sample_n(&shapes[k].s, &r, 10, x, y), ISK_OK);
        for (int i = 0; i < 10 * shapes[k].draws; i++)
            isk_rng_uniform(&twin);
        cr_expect_eq(memcmp(&r, &twin, sizeof r), 0, "shape %zu", k);
        /* sample_n equals repeated sample */
        isk_rng_seed(&r, 55);
        for (int i = 0; i < 10; i++) {
            double a, b;
            isk_shape_sample(&shapes[k].s, &r, &a, &b);
            cr_expect(a == x[i] && b == y[i]);
        }
    }
    struct { isk_velgen v; int draws; } vels[] = {
        {isk_velgen_constant(1, 2), 0},
        {isk_velgen_disc(3), 2},
        {isk_velgen_direction(1, 2, 3), 1},
        {isk_velgen_cone(1, 0.5, 2, 3), 2},
    };
    for (size_t k = 0; k < sizeof vels / sizeof vels[0]; k++) {
        isk_rng r, twin;
        isk_rng_seed(&r, 56);
        isk_rng_seed(&twin, 56);
        double x[10], y[10];
        cr_assert_eq(isk_velgen_sample_n(&vels[k].v, &r, 10, x, y), ISK_OK);
        for (int i = 0; i < 10 * vels[k].draws; i++)
            isk_rng_uniform(&twin);
        cr_expect_eq(memcmp(&r, &twin, sizeof r), 0, "velgen %zu", k);
    }
}

/* Particle-engine check 10 (at 10^5): angles within +-spread/2 and a 30-bin
 * histogram close to uniform. */
Test(shape, cone_angles)
{
    const double dir = 1.0, spread = PI / 3; /* 60 degrees */
    isk_velgen v = isk_velgen_cone(dir, spread, 2.0, 5.0);
    isk_rng r;
    isk_rng_seed(&r, 62);
    cr_assert_eq(isk_velgen_sample_n(&v, &r, N, xs, ys), ISK_OK);
    long bins[30] = {0};
    for (int i = 0; i < N; i++) {
        double a = atan2(ys[i], xs[i]) - dir, s = hypot(xs[i], ys[i]);
        cr_assert_leq(fabs(a), spread / 2 + 1e-6);
        cr_assert(s >= 2.0 - 1e-12 && s <= 5.0 + 1e-12);
        int b = (int)((a + spread / 2) / spread * 30);
        bins[b < 0 ? 0 : b > 29 ? 29 : b]++;
    }
    double chi2 = 0, e = N / 30.0;
    for (int b = 0; b < 30; b++)
        chi2 += (bins[b] - e) * (bins[b] - e) / e;
    cr_log_info("cone: chi^2 = %.1f over 29 degrees of freedom", chi2);
    cr_expect_lt(chi2, 70.0); /* p ~ 3e-5 for 29 dof: loose on purpose */
}

/* Fire thesis §5 check 10. */
Test(shape, velocity_generators)
{
    isk_rng r;
    isk_rng_seed(&r, 61);
    isk_velgen c = isk_velgen_constant(1.25, -3.5);
    double vx, vy;
    isk_velgen_sample(&c, &r, &vx, &vy);
    cr_expect(vx == 1.25 && vy == -3.5);

    isk_velgen d = isk_velgen_disc(4.0);
    cr_assert_eq(isk_velgen_sample_n(&d, &r, N, xs, ys), ISK_OK);
    double mx = 0, my = 0;
    for (int i = 0; i < N; i++) {
        cr_assert_leq(hypot(xs[i], ys[i]), 4.0 * (1 + 1e-12));
        mx += xs[i];
        my += ys[i];
    }
    cr_expect_leq(hypot(mx / N, my / N), 0.02 * 4.0);

    isk_velgen f = isk_velgen_direction(2.0, 1.0, 3.0);
    cr_assert_eq(isk_velgen_sample_n(&f, &r, N, xs, ys), ISK_OK);
    for (int i = 0; i < N; i++) {
        cr_assert_leq(fabs(atan2(ys[i], xs[i]) - 2.0), 1e-5);
        double s = hypot(xs[i], ys[i]);
        cr_assert(s >= 1.0 - 1e-12 && s <= 3.0 + 1e-12);
    }
}

Test(shape, validation)
{
    isk_shape bad[] = {
        isk_shape_disc(0, 0, -1),
        isk_shape_circle(0, 0, -0.5),
        isk_shape_ring(0, 0, 2, 1),
        isk_shape_ring(0, 0, -1, 1),
        isk_shape_rect(0, 0, -1, 1),
        isk_shape_ellipse(0, 0, 1, -1, ISK_ELLIPSE_UNIFORM),
        isk_shape_ellipse(0, 0, 1, 1, (isk_ellipse_mode)4),
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        cr_expect_eq(isk_shape_check(&bad[i]), ISK_ERR_RANGE, "case %zu", i);
    isk_shape nans[] = {
        isk_shape_disc(NAN, 0, 1), isk_shape_disc(0, 0, NAN), isk_shape_ring(0, 0, 1, INFINITY),
        isk_shape_segment(0, 0, NAN, 1), isk_shape_point(0, -INFINITY),
    };
    for (size_t i = 0; i < sizeof nans / sizeof nans[0]; i++)
        cr_expect_eq(isk_shape_check(&nans[i]), ISK_ERR_NAN, "case %zu", i);
    isk_shape rot = isk_shape_disc(0, 0, 1);
    rot.angle = NAN;
    cr_expect_eq(isk_shape_check(&rot), ISK_ERR_NAN);
    isk_shape kind = isk_shape_disc(0, 0, 1);
    kind.kind = (isk_shape_kind)99;
    cr_expect_eq(isk_shape_check(&kind), ISK_ERR_RANGE);
    cr_expect_eq(isk_shape_check(NULL), ISK_ERR_NULL);
    /* fine: zero radii, a point with unused NaN fields */
    isk_shape zero = isk_shape_ring(0, 0, 0, 0);
    cr_expect_eq(isk_shape_check(&zero), ISK_OK);
    isk_shape pt = isk_shape_point(1, 1);
    pt.a = NAN;
    cr_expect_eq(isk_shape_check(&pt), ISK_OK);

    isk_velgen vb[] = {
        isk_velgen_disc(-1), isk_velgen_direction(0, 2, 1), isk_velgen_direction(0, -1, 1),
        isk_velgen_cone(0, -0.1, 1, 2), isk_velgen_cone(0, 7.0, 1, 2),
    };
    for (size_t i = 0; i < sizeof vb / sizeof vb[0]; i++)
        cr_expect_eq(isk_velgen_check(&vb[i]), ISK_ERR_RANGE, "velgen case %zu", i);
    isk_velgen vn[] = {
        isk_velgen_constant(NAN, 0), isk_velgen_disc(INFINITY), isk_velgen_direction(NAN, 1, 2),
        isk_velgen_cone(0, NAN, 1, 2),
    };
    for (size_t i = 0; i < sizeof vn / sizeof vn[0]; i++)
        cr_expect_eq(isk_velgen_check(&vn[i]), ISK_ERR_NAN, "velgen nan case %zu", i);
    isk_velgen vk = isk_velgen_disc(1);
    vk.kind = (isk_velgen_kind)9;
    cr_expect_eq(isk_velgen_check(&vk), ISK_ERR_RANGE);

    /* sample_n validates and writes nothing on error */
    isk_rng r;
    isk_rng_seed(&r, 1);
    double x[2] = {7, 7}, y[2] = {7, 7};
    cr_expect_eq(isk_shape_sample_n(&bad[0], &r, 2, x, y), ISK_ERR_RANGE);
    cr_expect(x[0] == 7 && y[1] == 7);
    isk_shape ok = isk_shape_disc(0, 0, 1);
    cr_expect_eq(isk_shape_sample_n(&ok, NULL, 2, x, y), ISK_ERR_NULL);
    cr_expect_eq(isk_shape_sample_n(&ok, &r, 2, NULL, y), ISK_ERR_NULL);
    cr_expect_eq(isk_shape_sample_n(&ok, &r, 0, NULL, NULL), ISK_OK);
    cr_expect_eq(isk_velgen_sample_n(&vb[0], &r, 2, x, y), ISK_ERR_RANGE);
    cr_expect_eq(isk_velgen_sample_n(NULL, &r, 2, x, y), ISK_ERR_NULL);
}

/* The gaussian area (LÖVE's `normal`): over 10^5 births the sample
 * standard deviations are a and b within 1.5% (the standard error of a
 * standard deviation is sigma/sqrt(2N) = 0.22%), the means 0 within
 * 0.02 sigma (standard error 0.0032 sigma), x and y uncorrelated (|r| <
 * 0.02), and 68.3% +- 1% of the x offsets within one sigma. */
Test(shape, gaussian_spread)
{
    isk_shape s = isk_shape_gaussian(3, -1, 0.5, 2.0);
    sample(&s, 11);
    double mx = 0, my = 0;
    for (int i = 0; i < N; i++) {
        mx += xs[i] - 3;
        my += ys[i] + 1;
    }
    mx /= N;
    my /= N;
    double vx = 0, vy = 0, cxy = 0;
    long within = 0;
    for (int i = 0; i < N; i++) {
        const double dx = xs[i] - 3 - mx, dy = ys[i] + 1 - my;
        vx += dx * dx;
        vy += dy * dy;
        cxy += dx * dy;
        within += fabs(xs[i] - 3) < 0.5;
    }
    const double sx = sqrt(vx / (N - 1)), sy = sqrt(vy / (N - 1)), r = cxy / sqrt(vx * vy);
    cr_log_info("gaussian 0.5, 2: sd %.4f, %.4f; means %.4f, %.4f; r %.4f; within 1 sd %.4f", sx, sy, mx, my, r,
                (double)within / N);
    cr_assert_lt(fabs(sx / 0.5 - 1), 0.015, "sd x %g", sx);
    cr_assert_lt(fabs(sy / 2.0 - 1), 0.015, "sd y %g", sy);
    cr_assert_lt(fabs(mx), 0.02 * 0.5);
    cr_assert_lt(fabs(my), 0.02 * 2.0);
    cr_assert_lt(fabs(r), 0.02);
    cr_assert_lt(fabs((double)within / N - 0.6827), 0.01);
}

/* The rectangle's border is covered uniformly along its length: with
 * half sizes 3 and 1 the long sides (12 of the 16 units) get 75% of the
 * births, each side its share within 1% (standard error 0.14%). */
Test(shape, rect_border_uniform_along_the_outline)
{
    isk_shape s = isk_shape_rect_border(0, 0, 3, 1);
    sample(&s, 12);
    long side[4] = {0};
    for (int i = 0; i < N; i++) {
        if (xs[i] == 3 && fabs(ys[i]) < 1)
            side[0]++;
        else if (ys[i] == 1)
            side[1]++;
        else if (xs[i] == -3)
            side[2]++;
        else if (ys[i] == -1)
            side[3]++;
    }
    cr_assert_eq(side[0] + side[1] + side[2] + side[3], N, "every birth on a side");
    const double want[4] = {2.0 / 16, 6.0 / 16, 2.0 / 16, 6.0 / 16};
    for (int k = 0; k < 4; k++)
        cr_assert_lt(fabs((double)side[k] / N - want[k]), 0.01, "side %d: %g", k, (double)side[k] / N);
}

/* The ellipse's border at a uniform parameter (LÖVE's borderellipse):
 * the parameter angle atan2(y/b, x/a) falls in each quarter turn 25% +- 1%
 * of the time. */
Test(shape, ellipse_border_uniform_parameter)
{
    isk_shape s = isk_shape_ellipse_border(0, 0, 4, 1);
    sample(&s, 13);
    long q[4] = {0};
    for (int i = 0; i < N; i++) {
        double phi = atan2(ys[i] / 1.0, xs[i] / 4.0);
        q[(int)floor((phi + PI) / (PI / 2)) & 3]++;
    }
    for (int k = 0; k < 4; k++)
        cr_assert_lt(fabs((double)q[k] / N - 0.25), 0.01, "quarter %d: %g", k, (double)q[k] / N);
}
