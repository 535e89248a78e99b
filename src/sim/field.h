/* SPDX-License-Identifier: MIT */
/* src/sim/field.h — accelerations that depend on where a particle is
 * (internal): the emitter-centred radial and tangential accelerations and
 * turbulence, the curl of a seeded gradient noise.
 *
 * With `own` set, each particle adds its own columns (radial_extra,
 * tangential_extra, and a constant acceleration wind_x, wind_y: the
 * per-particle ranges) where the store has them.
 *
 * The owner (an effect's group) fills an isk_field once per compile, keeps
 * its clock (the simulated time and the emitter's position at the start of
 * the step) up to date before every run, and puts isk__stage_field in the
 * pipeline when any term is non-zero:
 *
 *     isk_field f = {0};
 *     f.radial = -4;                              // towards the centre
 *     f.turb[f.nturb++] = isk__field_turbulence(2, 1.5, 0.3, isk__noise_key(seed, 0));
 *     f.t = t0; f.cx = 0; f.cy = 0;               // every step
 *     isk_stage *st = isk__pipeline_add(&pl, &isk__stage_field);
 *     st->u.field.f = &f;
 *
 * The noise is pure arithmetic on its arguments (no tables, no state), so
 * a block gives the same bits on any thread. */
#ifndef ISKRA_SIM_FIELD_H
#define ISKRA_SIM_FIELD_H

#include <stdint.h>

/* As many turbulences as an effect has forces. */
#define ISK_FIELD_MAX_TURB 64

typedef struct isk_field_turb {
    double strength;  /* units/s^2 */
    double inv_scale; /* 1 / the feature size */
    double speed;     /* noise units per second along the time axis */
    uint64_t key;     /* the noise's seed */
} isk_field_turb;

typedef struct isk_field {
    double radial, tangential; /* units/s^2 away from (cx, cy), and counter-clockwise around it */
    int own;                   /* the particles' own parts (radial_extra, tangential_extra, wind_x/y
                                  of iskra/particles.h) are added where their columns exist */
    int nturb;
    isk_field_turb turb[ISK_FIELD_MAX_TURB];
    /* the clock: the time and the emitter's position at the start of the step */
    double t, cx, cy;
} isk_field;

/* A noise seed from a scene seed and an item's index (a force's). */
uint64_t isk__noise_key(uint64_t seed, int index);

/* Gradient noise psi(u, v, w) (improved Perlin noise with hashed lattice
 * gradients, C2 in every coordinate) and its partial derivatives along u
 * and v; coordinates beyond +-2^52 are clamped there.  Returns psi. */
double isk__noise3(uint64_t key, double u, double v, double w, double *du, double *dv);

isk_field_turb isk__field_turbulence(double strength, double scale, double speed, uint64_t key);

/* The field's acceleration at (x, y) for a particle moving at (vx, vy)
 * (the stage's kernel, for one point).  Exactly on the centre the radial
 * and tangential terms take the velocity's direction (the way the particle
 * leaves the centre), and none when it is at rest there. */
void isk__field_accel(const isk_field *f, double x, double y, double vx, double vy, double *ax, double *ay);

#endif
