/* SPDX-License-Identifier: MIT */
/* bench_stages — what each optional stage of a scene costs per particle,
 * measured in one run: a stream at a steady ~100,000 particles, stepped and
 * drawn with and without one key (or section) at a time.
 *
 * Every row is the base scene plus its lines in the emitter section (and
 * its own sections after it; gravity unless it lists its own forces).  Per row and round: the effect is created,
 * run for 75 frames to reach its steady population, then FRAMES steps are
 * timed (update: ns per particle-step) and FRAMES renders (draw: ns per
 * particle drawn), on one thread so the figures are the stage's, not the
 * pool's.  The rounds interleave the rows; each figure is the median of
 * ROUNDS, and "+" is the row's figure minus the base's: the stage's own
 * cost.  A key the scene does not use is in no list, so the base row is
 * also what every emitter without these keys costs (the determinism and
 * "costs nothing" tests check the bytes; this prints the time).  Run it
 * from the repository root (the texture rows read scenes/textures/).  A
 * sub-emitter row's children are counted in its particles and its time.  The
 * machine is shared: read the differences against their noise (the base
 * row's spread is printed). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_util.h"
#include "iskra/effect.h"
#include "iskra/scene.h"

enum { ROUNDS = 5, WARM = 75, FRAMES = 20 };

typedef struct row {
    const char *label;
    const char *emitter; /* lines added to [emitter e] */
    const char *extra;   /* sections after it */
} row;

static const char *base =
    "[scene]\nwidth = 400\nheight = 400\nseed = 7\n[view]\nxmin = -10\nxmax = 10\nymin = -10\nymax = 10\n"
    "[force gravity]\ng = 2\n"
    "[emitter e]\nsource = stream\nshape = disc\nshape_a = 2\nlaunch = disc\nspeed_max = 4\nrate = 100000\n"
    "life = 1\ncapacity = 200000\ndraw = sprite\nsize = 0.12\nblend = add\ncolor = #ff9040\n";

static const row rows[] = {
    {"base: stream, gravity, sprites", "", ""},
    {"slowing", "slowing = 0.5", ""},
    {"oscillation", "osc_omega = 1, 3\nosc_amplitude = 0.1, 0.3", ""},
    {"drag force", "forces = gravity, air", "[force air]\nkind = drag\nb = 0.3\n"},
    {"walls (reflect)", "", "[bounds]\nmode = reflect\nrestitution = 0.8\n"},
    {"deflector", "deflectors = floor", "[deflector floor]\nsegment = -10, -3, 10, -3\nrestitution = 0.5\n"},
    {"colour over life", "color_over_life = 0:white, 0.5:orange, 1:#40000000", ""},
    {"alpha + size over life", "alpha_over_life = 0:1, 1:0\nsize_over_life = 0:1, 1:0.3", ""},
    {"radial + tangential accel", "radial_accel = -1\ntangential_accel = 2", ""},
    {"turbulence force", "forces = gravity, swirl", "[force swirl]\nkind = turbulence\nstrength = 2\nscale = 1.5\nspeed = 0.3\n"},
    {"emitter_velocity", "emitter_velocity = 3, 0", ""},
    {"space = local", "emitter_velocity = 3, 0\nspace = local", ""},
    {"size_range", "size_range = 0.1", ""},
    {"color_pick", "color_pick = 0:red, 0.5:gold, 1:cyan", ""},
    {"align = velocity (streaks)", "align = velocity", ""},
    {"texture", "texture = scenes/textures/arrows.png\ntexture_grid = 4, 2", ""},
    {"texture + rotation + spin", "texture = scenes/textures/arrows.png\ntexture_grid = 4, 2\nrotation_range = 360\nspin = 90\nspin_range = 180", ""},
    {"trail = 8", "trail = 8", ""},
    {"on_death (10 sparks each)", "on_death = pop", "[emitter pop]\nsource = sub\ncount = 10\nlaunch = disc\nspeed_max = 2\nlife = 0.2\ncapacity = 200000\ndraw = none\n"},
    {"on_hit (deflector)", "deflectors = floor\non_hit = pop", "[deflector floor]\nsegment = -10, -3, 10, -3\nrestitution = 0.5\n[emitter pop]\nsource = sub\ncount = 1\nlife = 0.1\ncapacity = 200000\ndraw = none\n"},
};
#define NROWS ((int)(sizeof rows / sizeof rows[0]))

typedef struct result {
    double update[ROUNDS], draw[ROUNDS];
    size_t particles;
} result;

static int run_row(const row *r, result *out, int round)
{
    char text[4096];
    /* Every row has the base's gravity unless it lists its own forces. */
    snprintf(text, sizeof text, "%s%s\n%s%s", base, r->emitter, strstr(r->emitter, "forces =") ? "" : "forces = gravity\n",
             r->extra);
    isk_effect_def d;
    isk_error err = {0};
    isk_effect *fx = NULL;
    if (isk_scene_load_string(&d, text, r->label, &err) != ISK_OK ||
        isk_effect_create(&fx, &d, &err) != ISK_OK) {
        fprintf(stderr, "bench_stages: %s: %s\n", r->label, err.message);
        isk_effect_def_free(&d);
        return 0;
    }
    isk_canvas c;
    if (isk_canvas_init(&c, d.width, d.height) != ISK_OK) {
        isk_effect_def_free(&d);
        isk_effect_destroy(fx);
        return 0;
    }
    isk_effect_def_free(&d);
    isk_effect_set_threads(fx, 1);
    for (int i = 0; i < WARM; i++)
        isk_effect_step(fx);
    double t0 = bench_cpu_now();
    double steps = 0;
    for (int i = 0; i < FRAMES; i++) {
        steps += (double)isk_effect_particle_count(fx);
        isk_effect_step(fx);
    }
    double t1 = bench_cpu_now();
    for (int i = 0; i < FRAMES; i++)
        isk_effect_render(fx, &c);
    double t2 = bench_cpu_now();
    size_t n = isk_effect_particle_count(fx);
    out->update[round] = (t1 - t0) * 1e9 / steps;
    out->draw[round] = (t2 - t1) * 1e9 / ((double)n * FRAMES);
    out->particles = n;
    isk_canvas_free(&c);
    isk_effect_destroy(fx);
    return 1;
}

int main(void)
{
    static result res[NROWS];
    for (int round = 0; round < ROUNDS; round++)
        for (int i = 0; i < NROWS; i++)
            if (!run_row(&rows[i], &res[i], round))
                return 1;
    double spread_u[ROUNDS], spread_d[ROUNDS];
    memcpy(spread_u, res[0].update, sizeof spread_u);
    memcpy(spread_d, res[0].draw, sizeof spread_d);
    qsort(spread_u, ROUNDS, sizeof(double), bench_cmp);
    qsort(spread_d, ROUNDS, sizeof(double), bench_cmp);
    const double bu = bench_median(res[0].update, ROUNDS), bd = bench_median(res[0].draw, ROUNDS);
    printf("bench_stages: ns per particle, one thread, median of %d rounds (%d frames each, ~%zu particles)\n",
           ROUNDS, FRAMES, res[0].particles);
    printf("  base row's spread: update %.2f..%.2f, draw %.2f..%.2f\n", spread_u[0], spread_u[ROUNDS - 1],
           spread_d[0], spread_d[ROUNDS - 1]);
    printf("  %-34s %9s %8s %9s %8s %9s\n", "row", "particles", "update", "+stage", "draw", "+stage");
    for (int i = 0; i < NROWS; i++) {
        double u = bench_median(res[i].update, ROUNDS), dr = bench_median(res[i].draw, ROUNDS);
        printf("  %-34s %9zu %8.2f %+9.2f %8.2f %+9.2f\n", rows[i].label, res[i].particles, u, u - bu, dr, dr - bd);
    }
    return 0;
}
