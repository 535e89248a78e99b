/* SPDX-License-Identifier: MIT */
/* A 10^7-step run with drag: do decaying velocities make steps slower?
 *
 * Linear drag alone multiplies every velocity by about (1 - b dt/m) per
 * step, so after a few thousand simulated seconds the velocities reach the
 * subnormal range (below 2.2e-308).  Arithmetic on subnormals takes a slow
 * microcode path on x86 (about 100x here), and round-to-nearest then keeps
 * them there for good: v (1 - b dt/m) rounds back to v.  iskra flushes
 * decaying speeds below ISK_FLUSH_TINY to zero (iskra/integrate.h).
 *
 * This benchmark times the library's semi-implicit Euler step (256
 * particles, drag 0.8, dt 1/60) over the first and the last 18,000 of 10^7
 * steps (18,000 steps are 300 simulated seconds: at the start the speeds
 * are still normal numbers, down to about 1e-104) and checks, as a benchmark check (not a timed unit test), that
 * end / start stays under 1.5; it exits 1 otherwise.  For the lesson it
 * also runs the same update as a plain loop without the flush, and prints
 * how much slower its steps become once the velocities are subnormal. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_util.h"
#include "iskra/integrate.h"

enum { N = 256, WINDOW = 18000, ROUNDS = 9 };
static const long STEPS = 10000000;
static const double B = 0.8, DT = 1.0 / 60;

/* Median over ROUNDS sub-windows of the seconds per step of `steps` steps. */
static double time_library(isk_forces *f, isk_scratch *s, isk_particles *p, long steps)
{
    double t[ROUNDS];
    long per = steps / ROUNDS;
    for (int r = 0; r < ROUNDS; r++) {
        double t0 = bench_now();
        for (long k = 0; k < per; k++)
            isk_integrate_range(ISK_INTEGRATE_SEMI_EULER, f, s, p, 0, p->count, DT);
        t[r] = (bench_now() - t0) / (double)per;
    }
    return bench_median(t, ROUNDS);
}

/* The same update without the flush (what the thesis's loop does). */
static void plain_steps(double *x, double *v, long steps)
{
    for (long k = 0; k < steps; k++)
        for (int i = 0; i < N; i++) {
            double f = (-B) * v[i];
            v[i] = v[i] + DT * f;
            x[i] = x[i] + DT * v[i];
        }
}

static double time_plain(double *x, double *v, long steps)
{
    double t[ROUNDS];
    long per = steps / ROUNDS;
    for (int r = 0; r < ROUNDS; r++) {
        double t0 = bench_now();
        plain_steps(x, v, per);
        t[r] = (bench_now() - t0) / (double)per;
    }
    return bench_median(t, ROUNDS);
}

int main(void)
{
    isk_particles p;
    isk_scratch *s = malloc(sizeof *s);
    if (!s || isk_particles_init(&p, N, 0) != ISK_OK)
        return 1;
    for (int i = 0; i < N; i++)
        isk_particles_add(&p, 0, 0, 1.0 + i, -0.5 * i, 1, NULL);
    isk_forces f = {.drag = B};
    /* Warm up the CPU (clock, caches) on a copy, so the first window does
     * not pay for it. */
    isk_particles warm;
    if (isk_particles_init(&warm, N, 0) != ISK_OK)
        return 1;
    for (int i = 0; i < N; i++)
        isk_particles_add(&warm, 0, 0, 1.0 + i, -0.5 * i, 1, NULL);
    time_library(&f, s, &warm, WINDOW);
    isk_particles_free(&warm);

    double start = time_library(&f, s, &p, WINDOW);
    for (long k = 2 * (WINDOW / ROUNDS * ROUNDS); k < STEPS; k++)
        isk_integrate_range(ISK_INTEGRATE_SEMI_EULER, &f, s, &p, 0, p.count, DT);
    double end = time_library(&f, s, &p, WINDOW);
    int finite = 1, at_rest = 1;
    for (size_t i = 0; i < p.count; i++) {
        finite &= isfinite(p.x[i]) && isfinite(p.y[i]) && isfinite(p.vx[i]) && isfinite(p.vy[i]);
        at_rest &= p.vx[i] == 0 && p.vy[i] == 0;
    }
    double ratio = end / start;
    printf("10^7 steps with drag, %d particles, semi-implicit Euler (library):\n", N);
    printf("  first 18,000 steps: %.1f ns/step, last 18,000: %.1f ns/step, end/start = %.2f (must stay < 1.5)\n",
           start * 1e9, end * 1e9, ratio);
    printf("  velocities at the end: %s; every value finite: %s\n", at_rest ? "exactly 0" : "NOT all zero",
           finite ? "yes" : "NO");

    /* The lesson: the same loop without the flush. */
    double *x = calloc(N, sizeof *x), *v = malloc(N * sizeof *v);
    if (!x || !v)
        return 1;
    for (int i = 0; i < N; i++)
        v[i] = 1.0 + i;
    plain_steps(x, v, WINDOW / 10); /* warm-up: still far from subnormal */
    for (int i = 0; i < N; i++) {
        x[i] = 0;
        v[i] = 1.0 + i;
    }
    double plain_start = time_plain(x, v, WINDOW / 10);
    plain_steps(x, v, 60000); /* ~1000 simulated seconds: the velocities are subnormal now */
    int subnormal = 0;
    for (int i = 0; i < N; i++)
        subnormal += fpclassify(v[i]) == FP_SUBNORMAL;
    double plain_end = time_plain(x, v, WINDOW / 10);
    printf("without the flush (a plain loop): %.1f ns/step at the start, %.1f ns/step after 60,000 steps\n"
           "  (%d of %d velocities subnormal): end/start = %.1f\n",
           plain_start * 1e9, plain_end * 1e9, subnormal, N, plain_end / plain_start);
    free(x);
    free(v);
    free(s);
    isk_particles_free(&p);
    if (!(ratio < 1.5) || !finite || !at_rest) {
        printf("FAIL: the long run %s\n", !(ratio < 1.5) ? "got slower" : "did not end finite and at rest");
        return 1;
    }
    return 0;
}
