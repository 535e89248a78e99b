/* SPDX-License-Identifier: MIT */
/* The fire thesis's Table 5.1: update time of 10^3 .. 10^6 oscillating fire
 * particles with libm sin and with a sine lookup table.
 *
 * Measured through the effect runtime (isk_effect_step), with the update the
 * thesis's Emitter::Advance does per particle: lifetime check, external
 * force (wind + weight against gravity), slowing, position step, horizontal
 * oscillation with the thesis's vx coupling and amplitude decay.  The two
 * columns run the same stage list; only the oscillation's sine differs
 * (osc_table: isk_sinlut_floor on a 4096-entry table, or libm sin).
 * The two effects are stepped alternately, repetition by repetition, so
 * drift in the machine's speed affects both alike.  Times are medians of
 * REPS repetitions, each long enough (>= ~15 ms) to time reliably.
 *
 * The thesis's figures are from unknown hardware (C++, floats, 2014); only
 * the shape is comparable: linear scaling, and the table no slower than
 * sin.  `make bench` runs this with everything else.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "bench_util.h"
#include "iskra/effect.h"

#define REPS 7
#define PI 3.14159265358979323846

static isk_effect *fire(size_t n, int table)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    d.dt = 1.0 / 60;
    d.seed = 2014;
    int g = isk_effect_def_add_force(&d, "gravity", ISK_FORCE_GRAVITY);
    d.forces[g].g = 9.81;
    int w = isk_effect_def_add_force(&d, "wind", ISK_FORCE_WIND);
    d.forces[w].accel = isk_vec2_make(0.3, 0);
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "fire");
    e->born.source = ISK_SOURCE_STREAM;
    e->born.count = n; /* one burst of n at t = 0, then a steady population */
    e->born.capacity = n;
    e->born.shape = ISK_SHAPE_DISC;
    e->born.shape_a = 1;
    e->launch.kind = ISK_VELGEN_DISC;
    e->launch.speed_max = 1;
    e->life.seconds = 1e6; /* finite: the per-particle lifetime check runs, as in the thesis */
    e->motion.weight = 11;
    e->motion.slowing = 0.5;
    e->motion.osc_omega_min = 4;
    e->motion.osc_omega_max = 12;
    e->motion.osc_amplitude_min = 0.05;
    e->motion.osc_amplitude_max = 0.2;
    e->motion.osc_decay = 0.1;
    e->motion.osc_faithful = 1;
    e->motion.osc_table = table ? ISK_SINLUT_FLOOR : ISK_SINLUT_LIBM;
    e->look.draw = ISK_DRAW_NONE;
    isk_emitter_use_force(e, g);
    isk_emitter_use_force(e, w);
    isk_effect *fx = NULL;
    isk_error err;
    if (isk_effect_create(&fx, &d, &err) != ISK_OK) {
        fprintf(stderr, "bench_fire_table51: %s\n", err.message);
        exit(1);
    }
    isk_effect_def_free(&d);
    isk_effect_step(fx); /* the burst */
    if (isk_effect_particle_count(fx) != n) {
        fprintf(stderr, "bench_fire_table51: expected %zu particles, have %zu\n", n, isk_effect_particle_count(fx));
        exit(1);
    }
    return fx;
}

/* Seconds per step, timing `k` steps. */
static double time_steps(isk_effect *fx, int k)
{
    double t0 = bench_now();
    for (int i = 0; i < k; i++)
        isk_effect_step(fx);
    return (bench_now() - t0) / k;
}

int main(void)
{
    const size_t sizes[4] = {1000, 10000, 100000, 1000000};
    const double thesis_sin[4] = {0.3, 3.2, 35, 345}, thesis_lut[4] = {0.3, 2.9, 33, 313};
    double ours_sin[4], ours_lut[4];
    for (int s = 0; s < 4; s++) {
        size_t n = sizes[s];
        isk_effect *a = fire(n, 0), *b = fire(n, 1);
        int k = (int)(3000000 / n); /* steps per repetition: ~3e6 particle updates */
        if (k < 2)
            k = 2;
        time_steps(a, k); /* warm-up */
        time_steps(b, k);
        double ta[REPS], tb[REPS];
        for (int r = 0; r < REPS; r++) {
            ta[r] = time_steps(a, k);
            tb[r] = time_steps(b, k);
        }
        ours_sin[s] = bench_median(ta, REPS) * 1e3;
        ours_lut[s] = bench_median(tb, REPS) * 1e3;
        isk_effect_destroy(a);
        isk_effect_destroy(b);
    }
    printf("Fire thesis Table 5.1: update time per frame of oscillating fire particles\n");
    printf("(iskra: isk_effect_step, stages drift(wind+weight-gravity) + slow + oscillate(thesis vx coupling)\n"
           " + age + cull; median of %d repetitions; thesis: unknown 2014 hardware, C++ floats)\n\n", REPS);
    printf("%10s | %10s %10s | %12s %12s %12s\n", "particles", "thesis sin", "thesis LUT", "iskra libm",
           "iskra table", "table/libm");
    printf("-----------+-----------------------+---------------------------------------\n");
    for (int s = 0; s < 4; s++)
        printf("%10zu | %7.1f ms %7.1f ms | %9.3f ms %9.3f ms %12.3f\n", sizes[s], thesis_sin[s], thesis_lut[s],
               ours_sin[s], ours_lut[s], ours_lut[s] / ours_sin[s]);
    printf("\nscaling          thesis sin  thesis LUT  iskra libm  iskra table\n");
    for (int s = 2; s <= 3; s++)
        printf("t(%7zu)/t(%6zu) %8.2f %11.2f %11.2f %12.2f\n", sizes[s], sizes[s - 1],
               thesis_sin[s] / thesis_sin[s - 1], thesis_lut[s] / thesis_lut[s - 1], ours_sin[s] / ours_sin[s - 1],
               ours_lut[s] / ours_lut[s - 1]);
    /* ms per frame for 10^6 particles is numerically ns per particle. */
    printf("\nper-particle update at 10^6: iskra libm %.2f ns, table %.2f ns (thesis: %.0f ns, %.0f ns)\n",
           ours_sin[3], ours_lut[3], thesis_sin[3], thesis_lut[3]);
    printf("table/libm at 10^6: iskra %.3f, thesis %.3f\n", ours_lut[3] / ours_sin[3], thesis_lut[3] / thesis_sin[3]);
    return 0;
}
