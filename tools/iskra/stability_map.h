/* SPDX-License-Identifier: MIT */
/* tools/iskra/stability_map.h — the cells of `iskra bench stability` and
 * the map drawn from them (study_stability.c runs the cells,
 * stability_map.c draws them): one panel per integrator, frame step dt
 * across (log), substeps up, each cell coloured by its class, the drag
 * and spring edges of iskra/stability.h drawn as lines. */
#ifndef ISKRA_TOOL_STABILITY_MAP_H
#define ISKRA_TOOL_STABILITY_MAP_H

#include <stddef.h>

#include "iskra/effect.h"
#include "study.h"

/* dt = scene dt * 2^(j/2), j = STABILITY_DT_FIRST .. + STABILITY_NDT - 1 */
enum { STABILITY_NDT = 15, STABILITY_DT_FIRST = -2, STABILITY_NSUB = 4 };

typedef enum stability_class {
    STABILITY_STABLE = 0,
    STABILITY_OSCILLATING,
    STABILITY_GROWING,
    STABILITY_REMOVED,
    STABILITY_CLASS_COUNT
} stability_class;

/* "stable", "oscillating", "growing", "removed" (the CSV's words). */
extern const char *const stability_class_names[STABILITY_CLASS_COUNT];

typedef struct stability_cell {
    isk_integrator method;
    int substeps;
    double dt;
    long frames;
    stability_class cls;
    size_t removed, zigzag;
    double kinetic_ratio; /* largest kinetic energy over the reference's up to then */
    double drag_ratio;    /* b*h/m, the largest of the emitters' */
    double spring_ratio;  /* w*h of the stiffest linear spring, the largest of the emitters' */
} stability_cell;

typedef struct stability_map {
    char stem[128];
    isk_effect_def def;
    double scene_dt;
    int scene_substeps;
    isk_integrator scene_method;
    double dt[STABILITY_NDT];
    long frames[STABILITY_NDT];
    int substeps[STABILITY_NSUB];
    stability_cell cell[ISK_INTEGRATOR_COUNT][STABILITY_NSUB][STABILITY_NDT];
} stability_map;

/* Draws the map and writes it to o->out_dir/name as PNG: 0, or 1 after
 * printing why. */
int stability_map_write(const study_opts *o, const char *name, const stability_map *map);

/* `iskra bench stability` (study_stability.c); argv[0] is "stability". */
int bench_stability(int argc, char **argv);

#endif
