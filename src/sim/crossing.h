/* SPDX-License-Identifier: MIT */
/* src/sim/crossing.h — counting paths that cross a segment (internal): the
 * deflectors' exact crossing test (src/sim/segment_exact.h) put to the
 * probes' gates, in crossing.c.
 *
 * Particle i moved from prev[stride*i], prev[stride*i + 1] to x[i], y[i];
 * each path that crosses the gate (x0, y0) -> (x1, y1) adds one to
 * *forward (from the gate's left to its right, walking from its first end
 * point to its second) or to *backward.  The touching rule is a
 * deflector's: a path that starts on the gate's line is leaving it and is
 * not counted, one that ends on it is, so a particle that stops on the
 * line is counted once.
 */
#ifndef ISKRA_SIM_CROSSING_H
#define ISKRA_SIM_CROSSING_H

#include <stddef.h>
#include <stdint.h>

#include "iskra/deflector.h"

void isk__segment_crossings(const isk_deflector *gate, size_t n, const double *x, const double *y,
                            const double *prev, size_t stride, uint64_t *forward, uint64_t *backward);

#endif
