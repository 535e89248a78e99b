/* SPDX-License-Identifier: MIT */
/* src/sim/store_internal.h — unchecked store helpers for the emitters. */
#ifndef ISKRA_SIM_STORE_INTERNAL_H
#define ISKRA_SIM_STORE_INTERNAL_H

#include "iskra/particles.h"

/* Ensures room for `extra` more particles (all-or-nothing). */
isk_status isk__store_grow_for(isk_particles *p, size_t extra);
/* Appends without checks; the caller reserved room.  Returns the slot. */
size_t isk__store_push(isk_particles *p, double x, double y, double vx, double vy, double m);
/* isk_particles_cull (unordered: _cull_unordered) and
 * isk_particles_remove_nonfinite, also telling the first slot whose
 * particle moved or left (count when none did): what a runner's blocks at
 * rest must forget (sim/stage.h). */
size_t isk__store_cull(isk_particles *p, int unordered, size_t *first_moved);
size_t isk__store_remove_nonfinite(isk_particles *p, size_t *first_moved);

/* The arrays a store has, in a fixed order: its bytes, the bytes of one
 * particle's element, whether it holds doubles, whether it is the
 * lifetime (the one double column that may be +infinity).  out has room
 * for ISK__STORE_COLUMNS; returns how many (snapshots, effect_snapshot.c). */
enum { ISK__STORE_COLUMNS = 32 };
typedef struct isk__store_column {
    unsigned char *bytes;
    size_t elem;
    int doubles, life;
} isk__store_column;
size_t isk__store_columns(const isk_particles *p, isk__store_column *out);

#endif
