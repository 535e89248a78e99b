/* SPDX-License-Identifier: MIT */
/* iskra/probes.h — reading an effect's probes: the measuring tools a
 * scene's [probe NAME] sections (or isk_effect_def_add_probe) place.
 *
 * A probe is measured after every frame, from frame 1 on, over the
 * particles of its emitters (every emitter unless its `emitters` key names
 * some), on the caller's thread in a fixed order, so
 * its readings are the same on any number of threads:
 *   gate       the particles whose path over the frame (from where they were
 *              at its start, or were born, to where they are at its end)
 *              crosses the segment, counted in each direction since create
 *              or reset, and per second over the last `window` seconds
 *   region     how many particles are inside the rectangle (edges
 *              included), their mean speed and their kinetic energy
 *   histogram  every particle's speed, angle or age, counted in `bins`
 *              equal bins over `range` (the upper end in the last bin),
 *              with those below and above counted apart
 *   totals     the momentum, kinetic energy and potential energy (of every
 *              emitter: isk_effect_energy's numbers, which `iskra play`'s
 *              energy chart shows)
 * A particle that dies during a frame is not seen by that frame's
 * measure.  An effect without probes keeps no state for them and runs
 * exactly as before they existed.
 *
 * Example:
 *
 *     isk_effect_def d;
 *     isk_error err;
 *     const char *scene = "[emitter jet]\nsource = stream\nrate = 100\nvelocity = 5, 0\nlife = 3\n"
 *                         "[probe door]\nkind = gate\nsegment = 2, -1, 2, 1\n";
 *     if (isk_scene_load_string(&d, scene, "jet", &err) != ISK_OK) { fprintf(stderr, "%s\n", err.message); return 1; }
 *     isk_effect *fx;
 *     isk_status s = isk_effect_create(&fx, &d, &err);
 *     isk_effect_def_free(&d);
 *     if (s != ISK_OK) { fprintf(stderr, "%s\n", err.message); return 1; }
 *     for (int i = 0; i < 120 && s == ISK_OK; i++) s = isk_effect_step(fx);
 *     isk_probe_reading r;
 *     if (s == ISK_OK && isk_effect_probe_read(fx, 0, &r) == ISK_OK)
 *         printf("%s: %llu forward, %.1f per second\n", r.name, (unsigned long long)r.forward, r.rate_forward);
 *     isk_effect_destroy(fx);
 *     return s != ISK_OK;
 *
 * The readings as named numbers (for CSV files and charts): gate forward,
 * backward, rate_forward, rate_backward; region count, mean_speed,
 * kinetic; histogram under, bin0 .. bin(N-1), over; totals count, px, py,
 * kinetic, potential, energy.
 */
#ifndef ISKRA_PROBES_H
#define ISKRA_PROBES_H

#include <stddef.h>
#include <stdint.h>

#include "iskra/effect.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct isk_probe_reading {
    const char *name;          /* the probe's name (valid while the effect lives) */
    isk_probe_kind kind;
    long frame;                /* the frame it was measured after (0: not yet measured) */
    /* GATE */
    uint64_t forward, backward;        /* crossings since create or reset */
    double rate_forward, rate_backward; /* crossings per second over the last window (or the
                                           frames so far, while fewer) */
    /* REGION: the particles inside; HISTOGRAM: every particle; TOTALS: every particle */
    size_t count;
    double mean_speed;         /* REGION: mean |v| of those inside (0 when none) */
    double kinetic;            /* REGION, TOTALS: sum of m |v|^2 / 2 */
    /* HISTOGRAM */
    int bins;
    size_t bin[ISK_PROBE_MAX_BINS];
    size_t under, over;        /* values below range[0], above range[1] */
    /* TOTALS */
    double px, py;             /* momentum, sum of m v */
    double potential;          /* isk_forces_potential_energy of every emitter's forces (NAN: a law
                                  without an energy) */
} isk_probe_reading;

/* How many probes the effect has (0 for NULL). */
int isk_effect_probe_count(const isk_effect *e);
/* Probe i's latest reading.  ISK_ERR_NULL, ISK_ERR_RANGE (no probe i). */
isk_status isk_effect_probe_read(const isk_effect *e, int i, isk_probe_reading *out);

/* A reading as named numbers (the list above), up to max of them into
 * out; returns how many the reading has (when more than max, only max are
 * written; 0 for NULL). */
typedef struct isk_probe_value {
    char name[16];
    double value;
} isk_probe_value;
int isk_probe_values(const isk_probe_reading *r, isk_probe_value *out, int max);

/* The kinetic energy (sum of m |v|^2 / 2) of every particle, and the
 * potential energy of the forces each emitter's particles feel
 * (isk_forces_potential_energy of isk_effect_forces; NAN when a law has
 * none).  `iskra play`'s energy chart and the totals probe both read this.
 * ISK_ERR_NULL. */
isk_status isk_effect_energy(const isk_effect *e, double *kinetic, double *potential);

#ifdef __cplusplus
}
#endif

#endif
