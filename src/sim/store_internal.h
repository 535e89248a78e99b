/* src/sim/store_internal.h — unchecked store helpers for the emitters. */
#ifndef ISKRA_SIM_STORE_INTERNAL_H
#define ISKRA_SIM_STORE_INTERNAL_H

#include "iskra/particles.h"

/* Ensures room for `extra` more particles (all-or-nothing). */
isk_status isk_store_grow_for(isk_particles *p, size_t extra);
/* Appends without checks; the caller reserved room.  Returns the slot. */
size_t isk_store_push(isk_particles *p, double x, double y, double vx, double vy, double m);

#endif
