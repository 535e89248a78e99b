/* SPDX-License-Identifier: MIT */
/* iskra/particles.h — the particle store: structure of arrays, doubles.
 *
 * One array per attribute so the simulation stages are tight loops the
 * compiler vectorizes (see docs/vectorization.md).  Always present:
 * position x, y; velocity vx, vy; mass m; age and lifetime life.  Optional,
 * allocated only when the scene asks (flags at init), otherwise NULL:
 * per-particle colour (ISK_PARTICLES_COLOR), size (ISK_PARTICLES_SIZE) and
 * the fire thesis's horizontal oscillation (ISK_PARTICLES_OSC: amplitude,
 * phase, angular speed and the offset already applied), the sprite's angle
 * and angular speed (ISK_PARTICLES_ANGLE), the first frame of a flipbook
 * (ISK_PARTICLES_FRAME), and each particle's own part of the emitter's
 * accelerations and slowing (ISK_PARTICLES_RADIAL, _TANGENTIAL, _WIND,
 * _SLOWING).  Every column moves
 * with its particle: growth, removal and culling treat them all alike.
 *
 * Example:
 *
 *     isk_particles p;
 *     if (isk_particles_init(&p, 1024, 0) != ISK_OK) return 1;
 *     size_t i;
 *     isk_status s = isk_particles_add(&p, 0, -3, 4, 4, 2.0, &i);   // x, y, vx, vy, m
 *     for (size_t k = 0; k < p.count; k++) p.x[k] += 1;
 *     if (s == ISK_OK) printf("particle %zu at (%g, %g)\n", i, p.x[i], p.y[i]);
 *     isk_particles_free(&p);
 *     return s != ISK_OK;
 *
 * Iteration order (a contract: drawing composites in this order, and the
 * thesis's potentials switch off depending on it): index 0..count-1, which
 * is insertion order until something is removed.  isk_particles_remove(i) is
 * O(1): the LAST particle moves into slot i (order changes only for that
 * one).  isk_particles_cull() removes dead particles (age >= life) keeping
 * the relative order of the survivors (one O(n) pass).
 *
 * Arrays are 64-byte aligned and grow geometrically; pointers into them are
 * invalidated by any call that adds particles.  New particles get age 0 and
 * life = INFINITY (immortal, as every thesis particle).
 */
#ifndef ISKRA_PARTICLES_H
#define ISKRA_PARTICLES_H

#include <stddef.h>
#include <stdint.h>

#include "iskra/color.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
    ISK_PARTICLES_COLOR = 1u << 0, /* allocate the colour array */
    ISK_PARTICLES_SIZE = 1u << 1,  /* allocate the size array */
    ISK_PARTICLES_OSC = 1u << 2,   /* allocate the four oscillation arrays */
    /* looks */
    ISK_PARTICLES_ANGLE = 1u << 3, /* allocate the angle and spin arrays */
    /* ---- sub-emitters and trails ---- */
    ISK_PARTICLES_HIT = 1u << 4,   /* allocate hit: bounces in the current substep */
    /* ---- end of sub-emitters and trails ---- */
    ISK_PARTICLES_TRAIL = 1u << 5, /* in flags while the trail column is there (isk_particles_set_trail
                                      adds it with its length; init and add_columns refuse it) */
    ISK_PARTICLES_FRAME = 1u << 6, /* allocate frame0: a flipbook's first frame per particle */
    /* ---- per-particle ranges of the motion ---- */
    ISK_PARTICLES_RADIAL = 1u << 7,     /* allocate radial_extra */
    ISK_PARTICLES_TANGENTIAL = 1u << 8, /* allocate tangential_extra */
    ISK_PARTICLES_WIND = 1u << 9,       /* allocate wind_x, wind_y */
    ISK_PARTICLES_SLOWING = 1u << 10,   /* allocate slowing_extra */
    ISK_PARTICLES_FLAGS = 31u | ISK_PARTICLES_FRAME | ISK_PARTICLES_RADIAL | ISK_PARTICLES_TANGENTIAL |
                          ISK_PARTICLES_WIND | ISK_PARTICLES_SLOWING /* every flag init and add_columns take */
};

/* ---- sub-emitters and trails: the bits of isk_particles.hit ---- */
enum { ISK_HIT_COUNT = 0x3Fu, ISK_HIT_DEFLECTOR = 0x40u, ISK_HIT_WALL = 0x80u };

/* Largest capacity a store accepts (about 2.7e8 particles; more is an error,
 * not an overflow). */
#define ISK_PARTICLES_MAX ((size_t)1 << 28)

typedef struct isk_particles {
    size_t count, capacity;
    double *x, *y;       /* position */
    double *vx, *vy;     /* velocity */
    double *m;           /* mass (> 0) */
    double *age, *life;  /* seconds lived, lifetime (INFINITY = immortal) */
    double *size;        /* NULL unless ISK_PARTICLES_SIZE */
    isk_color *color;    /* NULL unless ISK_PARTICLES_COLOR */
    double *osc_amp;     /* the four NULL unless ISK_PARTICLES_OSC (new particles: 0) */
    double *osc_phase;
    double *osc_omega;
    double *osc_offset;  /* the offset already added to x */
    /* looks: NULL unless ISK_PARTICLES_ANGLE (new particles: 0) */
    double *angle;       /* radians, counter-clockwise in the world, kept in [-pi, pi) */
    double *spin;        /* rad/s */
    /* ---- sub-emitters and trails ---- */
    unsigned char *hit;  /* NULL unless ISK_PARTICLES_HIT: the bounces (walls, deflectors) the
                            contact stages counted in this substep (ISK_HIT_COUNT bits, saturating),
                            and whether it touched a wall / a deflector in the substep before
                            (ISK_HIT_WALL, ISK_HIT_DEFLECTOR: a touch that follows a touch is
                            resting or sliding, not a bounce); new particles: 0 */
    double *trail;       /* NULL unless ISK_PARTICLES_TRAIL: trail_len points (x, y) per particle,
                            particle i's at trail + 2*trail_len*i, a ring whose newest point is at
                            slot trail_head (new particles: every slot at their position) */
    int trail_len;       /* points per particle (1..ISK_TRAIL_MAX; 0 without the column) */
    int trail_head;      /* the ring's newest slot, the same for every particle */
    /* ---- end of sub-emitters and trails ---- */
    uint16_t *frame0;    /* NULL unless ISK_PARTICLES_FRAME: the frame a flipbook starts at
                            (new particles: 0) */
    /* each particle's own part, added to its emitter's value (new particles: 0) */
    double *radial_extra;     /* NULL unless ISK_PARTICLES_RADIAL: units/s^2 */
    double *tangential_extra; /* NULL unless ISK_PARTICLES_TANGENTIAL: units/s^2 */
    double *wind_x, *wind_y;  /* NULL unless ISK_PARTICLES_WIND: an acceleration, units/s^2 */
    double *slowing_extra;    /* NULL unless ISK_PARTICLES_SLOWING: per second */
    unsigned flags;
    isk_color default_color; /* given to new particles when color != NULL (yellow) */
    double default_size;     /* given to new particles when size != NULL (0.1) */
    void *block;             /* the one allocation holding every array (internal) */
} isk_particles;

/* Empty store with room for `capacity` particles (0 is fine).  Errors:
 * ISK_ERR_NULL, ISK_ERR_SIZE (capacity > ISK_PARTICLES_MAX or unknown flag
 * bits), ISK_ERR_NOMEM.  On error *p is left empty and safe to free. */
isk_status isk_particles_init(isk_particles *p, size_t capacity, unsigned flags);
void isk_particles_free(isk_particles *p);

/* The most memory a store with these flags takes while it grows to hold
 * `count` particles: its arrays at the capacity growth reaches, plus the
 * arrays it grew from (both exist while it moves).  0 if count is too large. */
size_t isk_particles_bytes(size_t count, unsigned flags);

/* Makes room for at least `capacity` particles; all-or-nothing. */
isk_status isk_particles_reserve(isk_particles *p, size_t capacity);

/* Adds the optional columns of `flags` to a store that lacks them; the
 * particles already there get what new ones get (default colour and size,
 * oscillation 0).  All-or-nothing.  Errors: ISK_ERR_NULL, ISK_ERR_SIZE
 * (unknown flag bits), ISK_ERR_NOMEM. */
isk_status isk_particles_add_columns(isk_particles *p, unsigned flags);

/* Appends one particle; *index (may be NULL) receives its slot.  Errors:
 * ISK_ERR_NULL, ISK_ERR_NAN (non-finite value), ISK_ERR_RANGE (m <= 0),
 * ISK_ERR_SIZE/ISK_ERR_NOMEM when the store cannot grow. */
isk_status isk_particles_add(isk_particles *p, double x, double y, double vx, double vy, double m,
                             size_t *index);

/* O(1) removal: the last particle takes slot i.  Out of range: no-op. */
void isk_particles_remove(isk_particles *p, size_t i);

/* Removes every particle with age >= life, keeping the order of the others;
 * returns how many were removed. */
size_t isk_particles_cull(isk_particles *p);

/* The same removal without keeping the order: each hole takes the last
 * live particle, so at most as many particles move as died (a fire whose
 * oldest die first would otherwise move every particle every frame).  For
 * stores whose order nothing observes, e.g. drawn additively. */
size_t isk_particles_cull_unordered(isk_particles *p);

/* Removes every particle whose position, velocity, mass or age is not
 * finite (or whose life is NaN), keeping the order of the others; returns
 * how many were removed.  The block runner's owners call it when a motion
 * stage reports a non-finite state (iskra/limits.h): they count what it
 * removes. */
size_t isk_particles_remove_nonfinite(isk_particles *p);

/* Adds dt to the ages of [begin, end), end clamped to the count (a stage;
 * the system runs it only when ageing is on). */
void isk_particles_age(isk_particles *p, size_t begin, size_t end, double dt);

void isk_particles_clear(isk_particles *p);

/* ---- sub-emitters and trails ----
 * Adds the trail column with `points` points per particle (1..ISK_TRAIL_MAX,
 * iskra/limits.h) to a store, or changes its length; every particle's trail
 * starts again at its position.  0 removes the column.  All-or-nothing.
 * Errors: ISK_ERR_NULL, ISK_ERR_RANGE (points out of range), ISK_ERR_NOMEM. */
isk_status isk_particles_set_trail(isk_particles *p, int points);

/* dst becomes a copy of src: the same particles, columns, trail and
 * defaults, in memory of its own (dst: a store, which is freed, or all zero).
 * All-or-nothing: ISK_ERR_NULL, ISK_ERR_NOMEM. */
isk_status isk_particles_copy(isk_particles *dst, const isk_particles *src);
/* Records the current positions as every particle's newest trail point (the
 * ring moves on by one slot).  No-op without the column. */
void isk_particles_record_trail(isk_particles *p);
/* The most memory a store with a trail of `points` takes while it grows to
 * hold `count` particles (as isk_particles_bytes). */
size_t isk_particles_bytes_trail(size_t count, unsigned flags, int points);
/* ---- end of sub-emitters and trails ---- */

#ifdef __cplusplus
}
#endif

#endif
