/* SPDX-License-Identifier: MIT */
/* iskra/explode.h — the thesis's explosion generators (emitters) and its
 * stationary particle layer, adding particles to a store.
 *
 * Every emitter appends `count` particles in index order (so iteration and
 * drawing order are creation order).  All random draws come from the given
 * isk_rng, per particle in this order (the thesis's order):
 *     uniform  : Ux, Uy                       velocity (20U-10, 20U-10)
 *     Gauss    : u1, u2 (Box–Muller), U_mass  velocity 3*(z1, z2), mass 2+U
 *     Coulomb  : u1, u2, U_mass               position c + (z1/50, z2/50), mass 2+U
 *     layer    : Ux, Uy                       position (U*(xmax-xmin)+xmin, U*(ymax-ymin)+ymin)
 *     ring     : none
 * (isk_rng_normal2 takes u1 then u2 and guards ln 0; Math.random cannot be
 * replayed, so the random emitters match the thesis in distribution and
 * arithmetic, not in bits.  The ring and the kick arithmetic are bit-exact.)
 *
 * Example: the thesis's Gauss explosion of 10 000 particles at (0, -3):
 *
 *     isk_particles store;
 *     if (isk_particles_init(&store, 10000, 0) != ISK_OK) return 1;
 *     isk_rng rng;
 *     isk_rng_seed(&rng, 42);
 *     isk_status s = isk_explode_gauss(&store, &rng, 0, -3, 10000, ISK_EXPLODE_THESIS_LIMIT);
 *     printf("%zu particles, the first at speed (%g, %g)\n", store.count, store.vx[0], store.vy[0]);
 *     isk_particles_free(&store);
 *     return s != ISK_OK;
 *
 * Counts: 1 <= count <= limit, else ISK_ERR_RANGE (the thesis accepts 1..10000;
 * pass ISK_EXPLODE_THESIS_LIMIT for that, or a larger limit on purpose; limit 0
 * also means the thesis's 10000).  Non-finite centre/rectangle -> ISK_ERR_NAN;
 * NULL -> ISK_ERR_NULL; on any error nothing is added.
 *
 * Coulomb kick (djelujPotencijalomNaCestice): a temporary potential at the
 * centre, k = 150 (multi: k_i = 80*(ln i + 0.5)), Q = -1, P = 2, min 0.06,
 * acting for ONE semi-implicit Euler step of dt 0.01 with only that force:
 * |dv| = 1.5/(m d) away from the centre for d >= 0.06, linear inside.  In the
 * simulator the thesis kicks the WHOLE target store (ISK_KICK_ALL, faithful:
 * layer particles and earlier explosions get kicked too); ISK_KICK_NEW kicks
 * only the particles just created (sound).
 *
 * Multiple Coulomb (visestrukiCoulombEksplozija): batches of
 * s = max(1, floor(0.06*N)); B = floor(N/s) + 1, minus 1 when N mod s == 0; the
 * last batch holds N mod s when non-zero (N = 1000: 16x60 + 40, 17 batches).
 * Batch i (1-based) is created, then only it is kicked with k_i.  The thesis
 * releases batch i+1 after sleep(10/i ms) of wall-clock time; here batch i+1
 * is released when the explosion's simulated age reaches
 *     T_{i+1} = sum_{j=1..i} 0.010/j  seconds    (T_1 = 0),
 * by an isk_multi_coulomb scheduler that the system advances with its time.
 */
#ifndef ISKRA_EXPLODE_H
#define ISKRA_EXPLODE_H

#include <stddef.h>

#include "iskra/particles.h"
#include "iskra/rng.h"
#include "iskra/status.h"
#include "iskra/vec2.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ISK_EXPLODE_THESIS_LIMIT 10000u

typedef enum isk_kick_target {
    ISK_KICK_ALL = 0, /* thesis simulator: every particle of the store */
    ISK_KICK_NEW = 1, /* only the particles this emitter created */
    ISK_KICK_COUNT
} isk_kick_target;

/* The thesis's explosion kinds (isk_system_explode, the effect's emitters). */
typedef enum isk_explosion {
    ISK_EXPLOSION_RING = 0,      /* pravilnaEksplozija */
    ISK_EXPLOSION_UNIFORM,       /* the fig-17 uniform square */
    ISK_EXPLOSION_GAUSS,         /* gaussEksplozija */
    ISK_EXPLOSION_COULOMB,       /* coulombEksplozija (see the kick target) */
    ISK_EXPLOSION_MULTI_COULOMB, /* visestrukiCoulombEksplozija (scheduled batches) */
    ISK_EXPLOSION_COUNT
} isk_explosion;

/* Names as scene files spell them, indexed by value. */
extern const char *const isk_explosion_names[ISK_EXPLOSION_COUNT]; /* ring uniform gauss coulomb multi-coulomb */
extern const char *const isk_kick_names[ISK_KICK_COUNT];           /* all new */

/* Regular ring: position (cx, cy), velocity (4,4) rotated CCW by
 * (i*360)/count degrees with the thesis's rotation formula, mass 2. */
isk_status isk_explode_ring(isk_particles *p, double cx, double cy, size_t count, size_t limit);
/* Uniform square: velocity (20U-10, 20U-10), Ux first, mass 2. */
isk_status isk_explode_uniform(isk_particles *p, isk_rng *r, double cx, double cy, size_t count,
                               size_t limit);
/* Gaussian: velocity 3*N(0,1) per axis, mass 2+U. */
isk_status isk_explode_gauss(isk_particles *p, isk_rng *r, double cx, double cy, size_t count,
                             size_t limit);
/* Coulomb: sigma 0.02 cloud at rest, mass 2+U, then the k = 150 kick. */
isk_status isk_explode_coulomb(isk_particles *p, isk_rng *r, double cx, double cy, size_t count,
                               size_t limit, isk_kick_target target);
/* Stationary layer: uniform in [xmin,xmax) x [ymin,ymax), x drawn first,
 * mass 1, at rest.  Errors also ISK_ERR_RANGE for min > max. */
isk_status isk_explode_layer(isk_particles *p, isk_rng *r, double xmin, double xmax, double ymin,
                             double ymax, size_t count, size_t limit);

/* The ring's i-th velocity (bit-exact with pravilnaEksplozija). */
isk_vec2 isk_ring_velocity(size_t i, size_t count);

/* One Coulomb kick on particles [begin, end): one semi-implicit Euler step of
 * dt 0.01 with only the potential k, Q = -1, P = 2, min 0.06 at (cx, cy). */
void isk_coulomb_kick(isk_particles *p, size_t begin, size_t end, double cx, double cy, double k);

/* k_i = 80*(ln i + 0.5) for batch i >= 1. */
double isk_multi_coulomb_k(size_t batch);

/* Batch plan for N >= 1: size s, batch count, size of the last batch. */
void isk_multi_coulomb_plan(size_t n, size_t *batch_size, size_t *batches, size_t *last_size);

/* Release time of batch i >= 1 relative to the explosion: sum_{j<i} 0.010/j. */
double isk_multi_coulomb_release_time(size_t batch);

/* A multi-Coulomb explosion in progress: plain data. */
typedef struct isk_multi_coulomb {
    double cx, cy;
    size_t total, batch_size, batches, last_size;
    size_t next;         /* next batch to release, 1-based; > batches when done */
    double age;          /* simulated seconds since the explosion started */
    double next_release; /* release time of batch `next` */
} isk_multi_coulomb;

/* Validates and plans; releases nothing yet.  Errors as the emitters. */
isk_status isk_multi_coulomb_start(isk_multi_coulomb *mc, double cx, double cy, size_t count,
                                   size_t limit);
/* Releases every batch whose time has come (age >= release time) into p,
 * each kicked on its own; *released (may be NULL) receives how many
 * particles were added.  Errors: ISK_ERR_NULL, ISK_ERR_NOMEM/ISK_ERR_SIZE
 * (nothing of the failing batch is added). */
isk_status isk_multi_coulomb_release(isk_multi_coulomb *mc, isk_particles *p, isk_rng *r,
                                     size_t *released);
/* How many particles the next release would add (every batch due now). */
size_t isk_multi_coulomb_due(const isk_multi_coulomb *mc);
/* age += dt. */
void isk_multi_coulomb_advance(isk_multi_coulomb *mc, double dt);
int isk_multi_coulomb_done(const isk_multi_coulomb *mc);

#ifdef __cplusplus
}
#endif

#endif
