/* What accuracy costs in time: error against time, measured in one run.
 *
 * 1. Integrators x step sizes on a problem with a closed form: a projectile
 *    under gravity g and linear drag b (mass m), dv/dt = (0, -g) - (b/m) v:
 *        v(t) = v_inf + (v0 - v_inf) e^{-kt},  k = b/m,  v_inf = (0, -g/k)
 *        r(t) = r0 + v_inf t + (v0 - v_inf)(1 - e^{-kt})/k
 *    N particles with different launch velocities run to T = 2 s; we report
 *    the largest position error at T and the time per particle-step, and
 *    which setting reaches a given error most cheaply.
 * 2. A position-only force with a closed form: the thesis's potential with
 *    exponent P = 0 is a linear spring, F = kQ (r_pot - r), so
 *    r(t) = r0 cos(wt) + (v0/w) sin(wt), w^2 = kQ/m.  Here velocity Verlet
 *    shows its second order (with drag, a velocity-dependent force, it is
 *    only first order: problem 1).
 * 3. The sine table: each mode and size against libm sin, max error and
 *    nanoseconds per lookup.
 *
 * Timings are medians of repeated runs on whatever else the machine is
 * doing; ratios inside one run are what to read. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_util.h"
#include "iskra/integrate.h"
#include "iskra/particles.h"
#include "iskra/sinlut.h"

enum { NP = 10000 };
static const double G = 9.81, B = 0.8, M = 1.0, T = 2.0;

static void launch(size_t i, double *vx, double *vy)
{
    double ang = 0.2 + 1.2 * (double)i / NP;
    double sp = 5.0 + 10.0 * (double)((i * 7919) % NP) / NP;
    *vx = sp * cos(ang);
    *vy = sp * sin(ang);
}

static int spring = 0; /* 0: projectile problem, 1: spring problem */
static const double W = 3.0; /* spring angular frequency, kQ = W^2 (m = 1) */

static void exact(double vx0, double vy0, double t, double *x, double *y)
{
    if (spring) { /* starts at (1, 0) */
        *x = cos(W * t) + vx0 / W * sin(W * t);
        *y = vy0 / W * sin(W * t);
        return;
    }
    double k = B / M, vinf = -G / k, f = -expm1(-k * t) / k;
    *x = vx0 * f;
    *y = vinf * t + (vy0 - vinf) * f;
}

/* Runs NP particles to T with `steps` steps of `method`; returns the max
 * position error and the seconds per particle-step (median of reps). */
static void run(isk_integrator method, long steps, int reps, double *err, double *sec_per)
{
    isk_particles p;
    isk_scratch *s = malloc(sizeof *s);
    isk_forces f = {0};
    isk_potential pot;
    isk_potential_init(&pot, W * W, isk_vec2_make(0, 0), 1);
    pot.P = 0;
    if (spring) {
        f.pot = &pot;
        f.npot = 1;
    } else {
        f.gravity = G;
        f.drag = B;
    }
    double times[16];
    for (int r = 0; r < reps; r++) {
        isk_particles_init(&p, NP, 0);
        for (size_t i = 0; i < NP; i++) {
            double vx, vy;
            launch(i, &vx, &vy);
            isk_particles_add(&p, spring ? 1 : 0, 0, vx, vy, M, NULL);
        }
        double dt = T / (double)steps;
        double t0 = bench_now();
        for (long k = 0; k < steps; k++)
            isk_integrate_range(method, &f, s, &p, 0, p.count, dt);
        times[r] = bench_now() - t0;
        if (r == reps - 1) {
            double worst = 0;
            for (size_t i = 0; i < NP; i++) {
                double vx, vy, x, y;
                launch(i, &vx, &vy);
                exact(vx, vy, T, &x, &y);
                double e = hypot(p.x[i] - x, p.y[i] - y);
                if (e > worst) worst = e;
            }
            *err = worst;
        }
        isk_particles_free(&p);
    }
    *sec_per = bench_median(times, reps) / ((double)NP * (double)steps);
    free(s);
}

static void table(const char *title, const isk_integrator *methods, int nm)
{
    const long steps[] = {30, 60, 120, 240, 480, 960};
    enum { NS = 6 };
    double err[8][NS], cost[8][NS];
    printf("%s\n\n%-11s", title, "steps/s ->");
    for (int j = 0; j < NS; j++)
        printf(" %21ld", (long)(steps[j] / T));
    printf("\n");
    for (int i = 0; i < nm; i++) {
        printf("%-11s", isk_integrator_name(methods[i]));
        for (int j = 0; j < NS; j++) {
            run(methods[i], steps[j], 5, &err[i][j], &cost[i][j]);
            printf("  %9.2e @ %5.2f ns", err[i][j], cost[i][j] * 1e9);
        }
        printf("\n");
    }
    printf("observed order (log2 of the error ratio when dt halves, 480 -> 960 steps):");
    for (int i = 0; i < nm; i++)
        printf("  %s %.2f", isk_integrator_name(methods[i]), log2(err[i][NS - 2] / err[i][NS - 1]));
    printf("\ncheapest setting reaching an error (ns per particle for the whole 2 s run):\n");
    const double targets[] = {1e-1, 1e-3, 1e-6, 1e-9, 1e-12};
    for (int t = 0; t < 5; t++) {
        int bi = -1, bj = -1;
        double best = INFINITY;
        for (int i = 0; i < nm; i++)
            for (int j = 0; j < NS; j++) {
                double per_particle = cost[i][j] * (double)steps[j];
                if (err[i][j] <= targets[t] && per_particle < best) {
                    best = per_particle;
                    bi = i;
                    bj = j;
                }
            }
        if (bi < 0)
            printf("  error <= %.0e: not reached by any setting here\n", targets[t]);
        else
            printf("  error <= %.0e: %-10s at %4ld steps/s: %8.1f ns (error %.1e)\n", targets[t],
                   isk_integrator_name(methods[bi]), (long)(steps[bj] / T), best * 1e9, err[bi][bj]);
    }
    printf("\n");
}

int main(void)
{
    const isk_integrator all[] = {ISK_INTEGRATE_EULER, ISK_INTEGRATE_SEMI_EULER, ISK_INTEGRATE_VERLET,
                                  ISK_INTEGRATE_RK4, ISK_INTEGRATE_EXACT_DRAG};
    char title[200];
    snprintf(title, sizeof title,
             "1. projectile, gravity %.2f + linear drag %.2f, %d particles, T = %.0f s, error = max |r - r_exact|", G,
             B, NP, T);
    table(title, all, 5);
    spring = 1;
    snprintf(title, sizeof title,
             "2. spring (potential with P = 0, w = %.0f rad/s), %d particles, T = %.0f s (exact-drag: no drag, "
             "the spring is frozen over each step)", W, NP, T);
    table(title, all, 5);
    /* Sine table vs libm. */
    printf("\nsine: max |error| over [-1e4, 1e4] and ns per call (table lookups are inline)\n");
    enum { NS = 1 << 20 };
    double *th = malloc(NS * sizeof *th), *out = malloc(NS * sizeof *out);
    for (int i = 0; i < NS; i++)
        th[i] = -1e4 + 2e4 * (double)((uint64_t)i * 2654435761u % NS) / NS;
    double t0 = bench_now(), sink = 0;
    for (int i = 0; i < NS; i++)
        out[i] = sin(th[i]);
    double t_libm = bench_now() - t0;
    for (int i = 0; i < NS; i++)
        sink += out[i];
    printf("  %-16s %10s %8.2f ns\n", "libm sin", "(reference)", t_libm / NS * 1e9);
    const int sizes[] = {256, 1024, 4096, 65536};
    const char *mode_names[] = {"floor", "round", "lerp"};
    for (int si = 0; si < 4; si++) {
        isk_sinlut lut;
        isk_sinlut_init(&lut, sizes[si]);
        for (int mode = 0; mode < 3; mode++) {
            double worst = 0;
            t0 = bench_now();
            if (mode == 0)
                for (int i = 0; i < NS; i++) out[i] = isk_sinlut_floor(&lut, th[i]);
            else if (mode == 1)
                for (int i = 0; i < NS; i++) out[i] = isk_sinlut_round(&lut, th[i]);
            else
                for (int i = 0; i < NS; i++) out[i] = isk_sinlut_lerp(&lut, th[i]);
            double t = bench_now() - t0;
            for (int i = 0; i < NS; i++) {
                double e = fabs(out[i] - sin(th[i]));
                if (e > worst) worst = e;
                sink += out[i];
            }
            char name[32];
            snprintf(name, sizeof name, "table %d %s", sizes[si], mode_names[mode]);
            printf("  %-16s %10.2e %8.2f ns  (%.2fx libm time)\n", name, worst, t / NS * 1e9, t / t_libm);
        }
    }
    free(th);
    free(out);
    return sink == 12345.678 ? 1 : 0; /* keeps the loops from being optimised away */
}
