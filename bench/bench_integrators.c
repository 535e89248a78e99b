/* SPDX-License-Identifier: MIT */
/* bench_integrators — particle-steps per second of every integrator on 10^6
 * particles under gravity + linear drag + a floor bounce, against a plain
 * array-of-structs loop of the thesis's kind (per particle: force, pomakni,
 * zarobi), measured in the same run.
 *
 * Each measurement repeats whole steps until at least ~0.4 s have passed and
 * keeps the best of 3 such runs.  Only a clock lives here, never in the
 * library.  Total runtime is about 10-15 s.
 */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "bench_util.h"
#include "iskra/system.h"

enum { N_BIG = 1000000, N_SMALL = 16384 };
static size_t N = N_BIG;
static const double DT = 1.0 / 600, G = 9.81, DRAG = 0.47;

/* ---- the baseline: the thesis's objects as C structs ---- */
typedef struct vek { double x, y; } vek;
typedef struct cestica { double promjer; double masa; vek r, v; } cestica;

__attribute__((noinline)) static void aos_step(cestica *c, size_t n, double dt)
{
    for (size_t i = 0; i < n; i++) {
        cestica *p = &c[i];
        /* F = SilaTeza.F + Otpor.F */
        vek F = {0.0 + -DRAG * p->v.x, p->masa * -G + -DRAG * p->v.y};
        /* pomakni */
        double k = dt / p->masa;
        p->v.x += k * F.x;
        p->v.y += k * F.y;
        p->r.x += dt * p->v.x;
        p->r.y += dt * p->v.y;
        /* zarobi(bottom only) */
        if (p->r.y < 0.0 + p->promjer) {
            p->v.y = -p->v.y;
            p->r.y = 0.0 + p->promjer;
        }
    }
}

static void init_state(double *x, double *y, double *vx, double *vy, double *m, isk_rng *r, size_t i)
{
    *x = isk_rng_range(r, 0, 10);
    *y = isk_rng_range(r, 0, 10);
    *vx = isk_rng_range(r, -5, 5);
    *vy = isk_rng_range(r, -5, 5);
    *m = 1 + isk_rng_uniform(r);
    (void)i;
}

static double bench_aos(void)
{
    cestica *c = malloc(N * sizeof *c);
    if (!c)
        return 0;
    isk_rng r;
    isk_rng_seed(&r, 1);
    for (size_t i = 0; i < N; i++) {
        c[i].promjer = 0.1;
        init_state(&c[i].r.x, &c[i].r.y, &c[i].v.x, &c[i].v.y, &c[i].masa, &r, i);
    }
    double best = 0;
    for (int rep = 0; rep < 3; rep++) {
        double t0 = bench_now(), t;
        long steps = 0;
        do {
            aos_step(c, N, DT);
            steps++;
        } while ((t = bench_now() - t0) < 0.4);
        double rate = (double)steps * (double)N / t;
        if (rate > best)
            best = rate;
    }
    volatile double sink = c[N / 2].r.y;
    (void)sink;
    free(c);
    return best;
}

static double bench_system(isk_integrator method, isk_bounce_mode mode)
{
    isk_system s;
    if (isk_system_init(&s, 1, N) != ISK_OK)
        return 0;
    isk_system_set_gravity(&s, G);
    isk_system_set_drag(&s, DRAG);
    isk_system_set_integrator(&s, method);
    isk_bounds b;
    if (mode == ISK_BOUNCE_THESIS)
        isk_bounds_thesis(&b, 0, 10, 0, 10, ISK_SIDE_BOTTOM);
    else
        isk_bounds_reflect(&b, 0, 10, 0, 10, ISK_SIDE_BOTTOM, 0.1, 0.8);
    isk_system_set_bounds(&s, &b, 1);
    isk_rng r;
    isk_rng_seed(&r, 1);
    for (size_t i = 0; i < N; i++) {
        double x, y, vx, vy, m;
        init_state(&x, &y, &vx, &vy, &m, &r, i);
        isk_particles_add(&s.particles, x, y, vx, vy, m, NULL);
    }
    double best = 0;
    for (int rep = 0; rep < 3; rep++) {
        double t0 = bench_now(), t;
        long steps = 0;
        do {
            isk_system_step(&s, DT);
            steps++;
        } while ((t = bench_now() - t0) < 0.4);
        double rate = (double)steps * (double)N / t;
        if (rate > best)
            best = rate;
    }
    isk_system_free(&s);
    return best;
}

int main(void)
{
    printf("bench_integrators: %d particles, gravity %.2f + drag %.2f + floor bounce, dt 1/600\n", (int)N_BIG, G, DRAG);
    printf("(best of 3 runs of >= 0.4 s; M = 10^6 particle-steps per second)\n\n");
    double base = bench_aos();
    printf("%-34s %12s %10s\n", "variant (10^6 particles)", "M steps/s", "vs AoS");
    printf("%-34s %12.1f %10.2f\n", "AoS scalar loop (thesis kind)", base / 1e6, 1.0);
    for (int m = 0; m < ISK_INTEGRATOR_COUNT; m++) {
        char name[64];
        snprintf(name, sizeof name, "SoA %s, thesis floor", isk_integrator_name((isk_integrator)m));
        double r = bench_system((isk_integrator)m, ISK_BOUNCE_THESIS);
        printf("%-34s %12.1f %10.2f\n", name, r / 1e6, base > 0 ? r / base : 0);
    }
    double r = bench_system(ISK_INTEGRATE_SEMI_EULER, ISK_BOUNCE_REFLECT);
    printf("%-34s %12.1f %10.2f\n", "SoA semi-euler, sound reflect", r / 1e6, base > 0 ? r / base : 0);
    /* The same pair with the whole state in L2 (16 Ki particles): shows the
     * compute side once DRAM bandwidth is out of the picture. */
    N = N_SMALL;
    double base_s = bench_aos();
    double soa_s = bench_system(ISK_INTEGRATE_SEMI_EULER, ISK_BOUNCE_THESIS);
    printf("\n%-34s %12s %10s\n", "variant (16384 particles, in L2)", "M steps/s", "vs AoS");
    printf("%-34s %12.1f %10.2f\n", "AoS scalar loop (thesis kind)", base_s / 1e6, 1.0);
    printf("%-34s %12.1f %10.2f\n", "SoA semi-euler, thesis floor", soa_s / 1e6,
           base_s > 0 ? soa_s / base_s : 0);
    printf("\nsemi-euler, euler: 1 force evaluation per step; verlet 2; rk4 4;\n"
           "exact-drag: 1 (drag solved analytically; expm1 per particle, not vectorized).\n");
    return 0;
}
