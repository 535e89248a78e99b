/* SPDX-License-Identifier: MIT */
/* bench_pipeline — what a scene's pipeline costs compared with the loop you
 * would write by hand.
 *
 * A gravity-only scene of 10^6 particles (an isk_effect_def: one explosion
 * emitter, drawing off, no walls, immortal particles) is stepped with
 * isk_effect_step and compared with a hand-written semi-implicit Euler loop
 * over plain SoA arrays doing only that:
 *     vy -= g*dt;  x += vx*dt;  y += vy*dt
 * The hand loop runs on the particle arrays of a second, identical effect
 * (same allocation, same layout): on this machine the whole working set sits
 * in L3, and where the kernel happens to place an array's pages moves a
 * memory-bound loop by up to ~1.8x (measured: the same hand loop over two
 * differently allocated copies of the same data), which would swamp the
 * pipeline's own cost.  The hand loop over separately malloc'd arrays is
 * printed too, for information.
 * Then the same scene plus an unreferenced Coulomb potential, and plus a
 * referenced but disabled one: neither may cost anything (they are not in
 * the pipeline).  Every round creates each variant afresh in a rotating
 * order and times STEPS steps; each figure is the median over ROUNDS, so
 * the allocator's page placement averages out.  Rendering is not timed.
 * Also checks that the effect and the hand loop end with identical bits.
 * Targets: A/hand <= 1.05; B/A and C/A within 2 %. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_util.h"
#include "iskra/effect.h"
#include "iskra/scene.h"

#define N 1000000
#define STEPS 20
#define ROUNDS 9

static const char *BASE = "[scene]\ndt = 1/60\nseed = 1\n"
                          "[force gravity]\ng = 9.81\n"
                          "[emitter cloud]\nsource = explosion\nexplosion = gauss\nposition = 0, 0\n"
                          "count = 1000000\nlimit = 1000000\ncapacity = 1000000\ndraw = none\nbounded = false\n";

static isk_effect *make(const char *extra, const char *forces)
{
    char text[2048];
    snprintf(text, sizeof text, "%sforces = %s\n%s", BASE, forces, extra);
    isk_effect_def d;
    isk_error err;
    isk_effect *fx = NULL;
    if (isk_scene_load_string(&d, text, "bench", &err) != ISK_OK) {
        fprintf(stderr, "bench_pipeline: %s\n", err.message);
        exit(1);
    }
    d.threads = 1; /* one core against the hand loop's one (bench_frame times the threads) */
    if (isk_effect_create(&fx, &d, &err) != ISK_OK) {
        fprintf(stderr, "bench_pipeline: %s\n", err.message);
        exit(1);
    }
    isk_effect_def_free(&d);
    return fx;
}

typedef struct soa {
    double *x, *y, *vx, *vy;
} soa;

static void hand_loop(soa *s, size_t n, double g, double dt)
{
    double *restrict x = s->x, *restrict y = s->y, *restrict vx = s->vx, *restrict vy = s->vy;
    for (size_t i = 0; i < n; i++) {
        vy[i] -= g * dt;
        x[i] += vx[i] * dt;
        y[i] += vy[i] * dt;
    }
}

static double time_effect(isk_effect *fx)
{
    double t0 = bench_now();
    for (int s = 0; s < STEPS; s++)
        if (isk_effect_step(fx) != ISK_OK) {
            fprintf(stderr, "bench_pipeline: step failed\n");
            exit(1);
        }
    return bench_now() - t0;
}

#define NV 4 /* scene, + unreferenced, + disabled, hand loop on an identical store */

static const char *const EXTRA[3][2] = {
    {"", "gravity"},
    {"[force coulomb]\nkind = potential\nk = 150\ncharge = -1\nposition = 0, -3\nmin_distance = 0.06\n",
     "gravity"},
    {"[force coulomb]\nkind = potential\nk = 150\ncharge = -1\nposition = 0, -3\nmin_distance = 0.06\n"
     "enabled = false\n",
     "gravity, coulomb"},
};

/* Times variant v on a freshly created effect (the hand loop steps the
 * arrays of an identical effect by hand). */
static double time_variant(int v, double dt)
{
    isk_effect *fx = make(EXTRA[v == 3 ? 0 : v][0], EXTRA[v == 3 ? 0 : v][1]);
    double t;
    if (v == 3) {
        isk_particles *p = (isk_particles *)isk_effect_particles(fx, 0);
        soa s = {p->x, p->y, p->vx, p->vy};
        double t0 = bench_now();
        for (int k = 0; k < STEPS; k++)
            hand_loop(&s, p->count, 9.81, dt);
        t = bench_now() - t0;
    } else {
        t = time_effect(fx);
    }
    isk_effect_destroy(fx);
    return t;
}

int main(void)
{
    isk_effect *a = make(EXTRA[0][0], EXTRA[0][1]);
    const isk_particles *pa = isk_effect_particles(a, 0);
    size_t n = pa->count;
    const double dt = isk_effect_definition(a)->dt;
    printf("pipeline of the gravity-only scene (iskra describe):\n");
    isk_effect_describe(a, stdout);

    /* Same bits: the scene and the hand loop over malloc'd copies. */
    soa h;
    h.x = malloc(n * sizeof(double));
    h.y = malloc(n * sizeof(double));
    h.vx = malloc(n * sizeof(double));
    h.vy = malloc(n * sizeof(double));
    if (!h.x || !h.y || !h.vx || !h.vy)
        return 1;
    memcpy(h.x, pa->x, n * sizeof(double));
    memcpy(h.y, pa->y, n * sizeof(double));
    memcpy(h.vx, pa->vx, n * sizeof(double));
    memcpy(h.vy, pa->vy, n * sizeof(double));
    for (int k = 0; k < STEPS; k++) {
        isk_effect_step(a);
        hand_loop(&h, n, 9.81, dt);
    }
    int same = !memcmp(h.x, pa->x, n * sizeof(double)) && !memcmp(h.y, pa->y, n * sizeof(double)) &&
               !memcmp(h.vy, pa->vy, n * sizeof(double));
    double tm[ROUNDS];
    for (int r = 0; r < ROUNDS; r++) {
        double t0 = bench_now();
        for (int k = 0; k < STEPS; k++)
            hand_loop(&h, n, 9.81, dt);
        tm[r] = bench_now() - t0;
    }
    isk_effect_destroy(a);
    free(h.x);
    free(h.y);
    free(h.vx);
    free(h.vy);

    /* Every round creates each variant afresh, in a rotating order, so where
     * the allocator puts the arrays (which moves this memory-bound loop by
     * several per cent) averages out instead of favouring one variant. */
    double t[NV][ROUNDS];
    for (int r = 0; r < ROUNDS; r++)
        for (int k = 0; k < NV; k++) {
            int v = (k + r) % NV;
            t[v][r] = time_variant(v, dt);
        }
    double ma = bench_median(t[0], ROUNDS), mb = bench_median(t[1], ROUNDS), mc = bench_median(t[2], ROUNDS),
           mh = bench_median(t[3], ROUNDS), mm = bench_median(tm, ROUNDS);
    const double per = 1e9 / ((double)n * STEPS);
    printf("\n%zu particles, %d steps per timing, median of %d rounds (each variant created afresh per round)\n",
           n, STEPS, ROUNDS);
    printf("  hand-written loop             %7.3f ns/particle/step  (on an identical store)\n", mh * per);
    printf("  hand-written loop, malloc'd   %7.3f ns/particle/step  (information: page placement)\n", mm * per);
    printf("  scene, gravity only           %7.3f ns/particle/step\n", ma * per);
    printf("  + unreferenced potential      %7.3f ns/particle/step\n", mb * per);
    printf("  + disabled potential          %7.3f ns/particle/step\n", mc * per);
    printf("  same bits as the hand loop after %d steps: %s\n", STEPS, same ? "yes" : "NO");
    printf("ratio scene / hand loop:               %.3f   (target <= 1.05)\n", ma / mh);
    printf("ratio with unreferenced potential:     %.3f   (target 0.98..1.02)\n", mb / ma);
    printf("ratio with disabled potential:         %.3f   (target 0.98..1.02)\n", mc / ma);
    return same ? 0 : 1;
}
