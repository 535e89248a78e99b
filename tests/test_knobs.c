/* SPDX-License-Identifier: MIT */
/* The deterministic claims of `iskra bench accuracy --only knobs`
 * (tools/iskra/study_knobs_*.c), checked against the library.  Timings are
 * never asserted; these are the error figures the study prints, which do
 * not depend on the machine.  Claims already covered elsewhere are not
 * repeated: the sine bounds themselves (test_sinlut), the ellipse's tip
 * fractions (test_shape), rounding at 20/45/100 per s and 60 steps/s and
 * the 30-vs-144 agreement (test_fire, test_effect). */
#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/integrate.h"
#include "iskra/particles.h"
#include "iskra/rng.h"
#include "iskra/shape.h"
#include "iskra/sinlut.h"

#define PI 3.14159265358979323846

/* ---- sine: the bounds are tight -------------------------------------------- */

/* The study's quick angle set (2^16 uniform draws in [-1e4, 1e4], seed 1):
 * every size and lookup comes within 1 % of its bound, so the chart's
 * errors are the bounds, not luck. */
Test(knobs, sine_errors_reach_their_bounds)
{
    enum { N = 1 << 16 };
    double *th = malloc(N * sizeof *th), *ref = malloc(N * sizeof *ref);
    cr_assert(th && ref);
    isk_rng r;
    isk_rng_seed(&r, 1);
    for (int i = 0; i < N; i++) {
        th[i] = isk_rng_range(&r, -1e4, 1e4);
        ref[i] = sin(th[i]);
    }
    const isk_sinlut_mode modes[3] = {ISK_SINLUT_FLOOR, ISK_SINLUT_ROUND, ISK_SINLUT_LERP};
    for (int n = 64; n <= 65536; n *= 2) {
        isk_sinlut lut;
        cr_assert_eq(isk_sinlut_init(&lut, n), ISK_OK);
        for (int m = 0; m < 3; m++) {
            double worst = 0;
            for (int i = 0; i < N; i++)
                worst = fmax(worst, fabs(isk_sinlut_eval(&lut, modes[m], th[i]) - ref[i]));
            double bound = isk_sinlut_bound(n, modes[m]);
            cr_expect(worst >= 0.99 * bound, "N %d mode %d: %g < 0.99 * %g", n, m, worst, bound);
            cr_expect(worst <= bound + 1e4 * 0x1p-52 + 0x1p-52, "N %d mode %d: %g > %g", n, m, worst, bound);
        }
    }
    free(th);
    free(ref);
}

/* ---- emission: counts per second --------------------------------------------- */

static isk_effect *stream(int fps, double rate, isk_rate_mode rm, isk_birth_mode bm, double vx, double vy, double g)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    d.dt = 1.0 / fps;
    d.seed = 7;
    int gi = -1;
    if (g > 0) {
        gi = isk_effect_def_add_force(&d, "gravity", ISK_FORCE_GRAVITY);
        cr_assert_geq(gi, 0);
        d.forces[gi].g = g;
    }
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "stream");
    cr_assert_not_null(e);
    e->born.source = ISK_SOURCE_STREAM;
    e->born.rate = rate;
    e->born.rate_mode = rm;
    e->born.birth = bm;
    e->launch.velocity = isk_vec2_make(vx, vy);
    e->born.capacity = 8192;
    e->look.draw = ISK_DRAW_NONE;
    if (gi >= 0)
        isk_emitter_use_force(e, gi);
    isk_effect *fx = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_def_free(&d);
    return fx;
}

static const int FPS[8] = {24, 30, 48, 60, 90, 120, 144, 240};

/* The table the study prints: steps * round(rate/steps) after 1 s with the
 * thesis's rounding (20/s vanishes above 40 steps/s; 90/s swings from 0 to
 * 144), exactly `rate` with the accumulator, which is never a whole
 * particle behind or ahead at any step. */
Test(knobs, emission_counts_after_one_second)
{
    const double rates[3] = {20, 90, 1000};
    const size_t thesis[3][8] = {{24, 30, 0, 0, 0, 0, 0, 0},
                                 {96, 90, 96, 120, 90, 120, 144, 0},
                                 {1008, 990, 1008, 1020, 990, 960, 1008, 960}};
    for (int r = 0; r < 3; r++)
        for (int f = 0; f < 8; f++) {
            isk_effect *fx = stream(FPS[f], rates[r], ISK_RATE_THESIS, ISK_BIRTH_BACKDATE, 0, 1, 0);
            for (int n = 0; n < FPS[f]; n++)
                cr_assert_eq(isk_effect_step(fx), ISK_OK);
            cr_expect_eq(isk_effect_particle_count(fx), thesis[r][f], "thesis %g/s at %d steps/s: %zu", rates[r],
                         FPS[f], isk_effect_particle_count(fx));
            isk_effect_destroy(fx);

            fx = stream(FPS[f], rates[r], ISK_RATE_ACCUMULATE, ISK_BIRTH_BACKDATE, 0, 1, 0);
            double worst = 0;
            for (int n = 1; n <= FPS[f]; n++) {
                cr_assert_eq(isk_effect_step(fx), ISK_OK);
                worst = fmax(worst, fabs((double)isk_effect_particle_count(fx) - rates[r] * n / FPS[f]));
            }
            cr_expect_eq(isk_effect_particle_count(fx), (size_t)rates[r], "accumulator %g/s at %d steps/s", rates[r],
                         FPS[f]);
            cr_expect_lt(worst, 1.0, "accumulator %g/s at %d steps/s: %g behind/ahead", rates[r], FPS[f], worst);
            isk_effect_destroy(fx);
        }
}

/* The thesis's rounding emits up to twice the rate: at 60 steps/s a rate
 * of 30/s gives dt*rate + 0.5 = 1 every step, 60 particles a second (200 %),
 * and a rate just below it, 29.99/s, gives 0 every step (0 %). */
Test(knobs, thesis_rounding_emits_from_nothing_to_twice_the_rate)
{
    const double rates[2] = {30, 29.99};
    const size_t expected[2] = {60, 0};
    for (int r = 0; r < 2; r++) {
        isk_effect *fx = stream(60, rates[r], ISK_RATE_THESIS, ISK_BIRTH_BACKDATE, 0, 1, 0);
        for (int n = 0; n < 60; n++)
            cr_assert_eq(isk_effect_step(fx), ISK_OK);
        cr_expect_eq(isk_effect_particle_count(fx), expected[r], "thesis %g/s at 60 steps/s: %zu", rates[r],
                     isk_effect_particle_count(fx));
        isk_effect_destroy(fx);
    }
}

/* ---- emission: where sub-step births are ---------------------------------------- */

typedef struct birth_err {
    double mean, max, max_ratio; /* max_ratio: max of error / (g tau h / 2) */
} birth_err;

/* 1000 particles/s from a point with a fixed launch velocity for 1 s; the
 * k-th particle against r = v0 tau + a tau^2/2, tau = 1 - k/1000. */
static birth_err births(int fps, isk_birth_mode bm, double vx, double vy, double g)
{
    isk_effect *fx = stream(fps, 1000, ISK_RATE_ACCUMULATE, bm, vx, vy, g);
    for (int n = 0; n < fps; n++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    const isk_particles *p = isk_effect_particles(fx, 0);
    cr_assert_eq(p->count, 1000u);
    birth_err e = {0, 0, 0};
    const double h = 1.0 / fps;
    for (size_t i = 0; i < p->count; i++) {
        double tau = 1.0 - (double)(i + 1) / 1000;
        double d = hypot(p->x[i] - vx * tau, p->y[i] - (vy * tau - g * tau * tau / 2));
        e.mean += d / (double)p->count;
        e.max = fmax(e.max, d);
        if (g > 0 && tau > 0)
            e.max_ratio = fmax(e.max_ratio, d / (g * tau * h / 2));
    }
    isk_effect_destroy(fx);
    return e;
}

/* Without forces the error is the speed times the birth-time error:
 * back-dated births are exact up to rounding; end-of-frame births are off
 * by their true age (< h, mean about h/2); the thesis's jitter by
 * |jitter - age| (< h, mean about h/3). */
Test(knobs, birth_modes_without_forces)
{
    const double vx = 3, vy = 4, speed = 5;
    for (int f = 0; f < 8; f++) {
        const double h = 1.0 / FPS[f];
        birth_err b = births(FPS[f], ISK_BIRTH_BACKDATE, vx, vy, 0);
        birth_err j = births(FPS[f], ISK_BIRTH_THESIS_JITTER, vx, vy, 0);
        birth_err e = births(FPS[f], ISK_BIRTH_FRAME, vx, vy, 0);
        cr_expect_leq(b.max, 1e-13, "backdate at %d steps/s: %g", FPS[f], b.max);
        cr_expect_leq(e.max, speed * h * (1 + 1e-12), "frame at %d steps/s: %g", FPS[f], e.max);
        /* a particle due just after a step's start waits almost h */
        cr_expect_geq(e.max, speed * (h - 1e-3) * (1 - 1e-9), "frame at %d steps/s: %g", FPS[f], e.max);
        cr_expect_leq(j.max, speed * h * (1 + 1e-12), "jitter at %d steps/s: %g", FPS[f], j.max);
        cr_expect(e.mean > 0.45 * speed * h && e.mean < 0.52 * speed * h, "frame mean %g, h %g", e.mean, h);
        cr_expect(j.mean > 0.30 * speed * h && j.mean < 0.37 * speed * h, "jitter mean %g, h %g", j.mean, h);
    }
}

/* Under gravity a back-dated particle carries semi-implicit Euler's error,
 * g sum(h_j^2)/2 <= g tau h / 2 (docs/fire.md); particles born exactly on
 * a step reach the bound. */
Test(knobs, backdated_birth_under_gravity_reaches_the_documented_bound)
{
    for (int f = 0; f < 8; f++) {
        birth_err b = births(FPS[f], ISK_BIRTH_BACKDATE, 3, 8, 9.81);
        cr_expect(b.max_ratio <= 1 + 1e-9 && b.max_ratio >= 0.999, "%d steps/s: error / bound = %.6f", FPS[f],
                  b.max_ratio);
    }
}

/* ---- ellipse: distance from area-uniform --------------------------------------------- */

/* The thesis sampler's CDF of s = (x/a)^2 + (y/b)^2 (the study's formula):
 * F(r) = r * integral_0^{pi/2} cos^2 t / sqrt(1 - r sin^2 t) dt. */
static double thesis_cdf(double r)
{
    if (r >= 1)
        return 1;
    enum { K = 256 };
    double h = (PI / 2) / K, sum = 0;
    for (int i = 0; i <= K; i++) {
        double t = i * h, c = cos(t), s = sin(t);
        sum += c * c / sqrt(1 - r * s * s) * (i == 0 || i == K ? 1 : (i % 2 ? 4 : 2));
    }
    return r * sum * h / 3;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Sorted s of n samples. */
static double *radii2(isk_ellipse_mode mode, size_t n, uint64_t seed)
{
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
    cr_assert(x && y);
    isk_shape sh = isk_shape_ellipse(0, 0, 2, 1, mode);
    isk_rng r;
    isk_rng_seed(&r, seed);
    cr_assert_eq(isk_shape_sample_n(&sh, &r, n, x, y), ISK_OK);
    for (size_t i = 0; i < n; i++)
        x[i] = (x[i] / 2) * (x[i] / 2) + y[i] * y[i];
    free(y);
    qsort(x, n, sizeof *x, cmp_double);
    return x;
}

/* sup |F_n - F| for the sorted sample s against the CDF F. */
static double ks(const double *s, size_t n, double (*F)(double))
{
    double d = 0;
    for (size_t i = 0; i < n; i++) {
        double f = F(s[i]);
        d = fmax(d, fmax((double)(i + 1) / (double)n - f, f - (double)i / (double)n));
    }
    return d;
}

static double uniform_cdf(double r) { return r < 0 ? 0 : (r > 1 ? 1 : r); }

/* The derived CDF matches the thesis sampler (so the study's limit
 * max |F(r) - r| = 0.082 is the thesis sampler's), and the area-uniform
 * sampler's s is uniform: its KS distance is within Kolmogorov's 99.9 %
 * point 1.95/sqrt(n), the thesis's is 25 times that. */
Test(knobs, ellipse_radius_distribution)
{
    const size_t n = 100000;
    double *t = radii2(ISK_ELLIPSE_THESIS, n, 1002), *u = radii2(ISK_ELLIPSE_UNIFORM, n, 1002);
    double limit = 0;
    for (int i = 1; i < 4000; i++)
        limit = fmax(limit, fabs(thesis_cdf(i / 4000.0) - i / 4000.0));
    cr_expect(fabs(limit - 0.0820) < 5e-4, "limit %g", limit);
    double ks_t = ks(t, n, thesis_cdf), ks_tu = ks(t, n, uniform_cdf), ks_u = ks(u, n, uniform_cdf);
    cr_expect_lt(ks_t * sqrt((double)n), 1.95, "thesis sample against the derived CDF: %g", ks_t);
    cr_expect_lt(ks_u * sqrt((double)n), 1.95, "uniform sample against U(0,1): %g", ks_u);
    cr_expect_lt(fabs(ks_tu - limit), 1.95 / sqrt((double)n), "thesis KS %g, limit %g", ks_tu, limit);
    free(t);
    free(u);
}

/* ---- float vs double ---------------------------------------------------------- */

/* The float study's own step (a header, so this test checks the very code
 * the study times): in double it must reproduce the library's bits. */
#include "../tools/iskra/study_float_step.h"

enum { NP = 2000 };
static const double G = 9.81, B = 0.8;

static void launch(size_t i, double *vx, double *vy)
{
    double ang = 0.2 + 1.2 * (double)i / NP;
    double sp = 5.0 + 10.0 * (double)((i * 7919) % NP) / NP;
    *vx = sp * cos(ang);
    *vy = sp * sin(ang);
}

/* Max |r - r_exact| at T after T*steps_per_s steps from (x0, 0): the
 * library's double path, or the float loop. */
static double projectile(int use_float, double x0, double T, int steps_per_s)
{
    const long steps = (long)(steps_per_s * T + 0.5);
    const double dt = 1.0 / steps_per_s;
    static double px[NP], py[NP];
    if (use_float) {
        static float f[5][NP];
        for (size_t i = 0; i < NP; i++) {
            double vx, vy;
            launch(i, &vx, &vy);
            f[0][i] = (float)x0, f[1][i] = 0, f[2][i] = (float)vx, f[3][i] = (float)vy, f[4][i] = 1;
        }
        for (long k = 0; k < steps; k++)
            study_step_float(NP, f[0], f[1], f[2], f[3], f[4], (float)G, (float)B, (float)dt);
        for (size_t i = 0; i < NP; i++)
            px[i] = f[0][i], py[i] = f[1][i];
    } else {
        isk_particles p;
        cr_assert_eq(isk_particles_init(&p, NP, 0), ISK_OK);
        isk_scratch *s = malloc(sizeof *s);
        cr_assert_not_null(s);
        for (size_t i = 0; i < NP; i++) {
            double vx, vy;
            launch(i, &vx, &vy);
            isk_particles_add(&p, x0, 0, vx, vy, 1, NULL);
        }
        isk_forces fo = {0};
        fo.gravity = G;
        fo.drag = B;
        for (long k = 0; k < steps; k++)
            isk_integrate_range(ISK_INTEGRATE_SEMI_EULER, &fo, s, &p, 0, p.count, dt);
        memcpy(px, p.x, NP * sizeof *px);
        memcpy(py, p.y, NP * sizeof *py);
        free(s);
        isk_particles_free(&p);
    }
    double worst = 0;
    for (size_t i = 0; i < NP; i++) {
        double vx, vy, k = B, vinf = -G / k, f = -expm1(-k * T) / k; /* m = 1 */
        launch(i, &vx, &vy);
        worst = fmax(worst, hypot(px[i] - (x0 + vx * f), py[i] - (vinf * T + (vy - vinf) * f)));
    }
    return worst;
}

Test(knobs, float_loop_in_double_is_the_library_bit_for_bit)
{
    enum { n = 300 };
    static double d[5][n];
    isk_particles p;
    cr_assert_eq(isk_particles_init(&p, n, 0), ISK_OK);
    isk_scratch *s = malloc(sizeof *s);
    cr_assert_not_null(s);
    for (size_t i = 0; i < n; i++) {
        double vx = 10 * cos(0.01 * (double)i), vy = 10 * sin(0.01 * (double)i), m = 0.5 + 0.01 * (double)i;
        isk_particles_add(&p, 1e4 * (double)(i % 3), -3, vx, vy, m, NULL);
        d[0][i] = p.x[i], d[1][i] = p.y[i], d[2][i] = vx, d[3][i] = vy, d[4][i] = m;
    }
    isk_forces fo = {0};
    fo.gravity = G;
    fo.drag = B;
    for (int k = 0; k < 1000; k++) {
        isk_integrate_range(ISK_INTEGRATE_SEMI_EULER, &fo, s, &p, 0, p.count, 1.0 / 60);
        study_step_double(n, d[0], d[1], d[2], d[3], d[4], G, B, 1.0 / 60);
    }
    cr_expect_eq(memcmp(p.x, d[0], sizeof d[0]), 0);
    cr_expect_eq(memcmp(p.y, d[1], sizeof d[1]), 0);
    cr_expect_eq(memcmp(p.vx, d[2], sizeof d[2]), 0);
    cr_expect_eq(memcmp(p.vy, d[3], sizeof d[3]), 0);
    free(s);
    isk_particles_free(&p);
}

/* Near the origin float is as good as double over 2 s (the step's own
 * error dominates); launched from x0 = 1e4, where a float's spacing is
 * 2^-10, its error grows once the steps get small: past double's at 480
 * steps/s and over a thousand times double's at 7680. */
Test(knobs, float_error_near_the_origin_and_far_from_it)
{
    for (int sps = 30; sps <= 960; sps *= 2) {
        double ed = projectile(0, 0, 2, sps), ef = projectile(1, 0, 2, sps);
        cr_expect(fabs(ef / ed - 1) < 0.01, "origin, %d steps/s: float %g, double %g", sps, ef, ed);
    }
    double d480 = projectile(0, 1e4, 2, 480), f480 = projectile(1, 1e4, 2, 480);
    double d7680 = projectile(0, 1e4, 2, 7680), f7680 = projectile(1, 1e4, 2, 7680);
    cr_expect_gt(f480, 2 * d480, "1e4, 480 steps/s: float %g, double %g", f480, d480);
    cr_expect_gt(f7680, 1000 * d7680, "1e4, 7680 steps/s: float %g, double %g", f7680, d7680);
    cr_expect_gt(f7680, f480, "float's error grows as the step shrinks: %g, %g", f7680, f480);
    cr_expect_lt(d7680, d480, "double's error falls as the step shrinks: %g, %g", d7680, d480);
}
