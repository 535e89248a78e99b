/* SPDX-License-Identifier: MIT */
/* tools/iskra/scene_sweep.h — running one scene file under other settings,
 * for `iskra bench accuracy --scene` and `iskra bench stability`.
 *
 * A setting is an integrator, substeps and a frame step dt; it replaces
 * the scene's and every emitter's own (an emitter that names its own
 * integrator runs the swept one too: the sweep asks what the scene needs,
 * not what it has).  Everything else is the scene's: seed, births, forces,
 * walls, the click.  The effects are created from one loaded definition.
 *
 * The reference a scene is measured against is the method the rule of
 * sweep_reference picks, with more substeps: Yoshida's fourth-order
 * method where the forces are smooth, RK4 where they are not (walls and
 * deflectors bounce: a kink in time, which Yoshida's backward substep
 * steps across; turbulence and potentials that switch themselves off
 * change the forces in time or in one jump), because a high order only
 * pays while the force has the derivatives it assumes, and RK4 never
 * steps backwards. */
#ifndef ISKRA_TOOL_SCENE_SWEEP_H
#define ISKRA_TOOL_SCENE_SWEEP_H

#include <stddef.h>

#include "iskra/effect.h"

typedef struct sweep_setting {
    isk_integrator method;
    int substeps;
    double dt;
} sweep_setting;

/* Loads the scene (a file or a built-in name) for `iskra bench CMD`;
 * threads 0: every core.  Returns 0, or the exit status (2: a scene
 * error, 1: out of memory) after printing why. */
int sweep_load(const char *cmd, const char *scene, int threads, isk_effect_def *def);

/* Creates the effect of def under the setting (def is changed only for the
 * call).  Returns 0, or 1 after printing "iskra bench CMD: why". */
int sweep_create(const char *cmd, isk_effect_def *def, const sweep_setting *s, isk_effect **fx);

/* The largest of_emitter(def, i) over def's emitters under the setting:
 * isk_effect_def_drag_ratio (b*h/m) or isk_effect_def_spring_ratio (w*h)
 * of iskra/stability.h; 0 when no emitter has one. */
double sweep_ratio(isk_effect_def *def, const sweep_setting *s, double (*of_emitter)(const isk_effect_def *, int));

/* The reference method for def (see the top), and in *why the reason in a
 * few words ("smooth forces", "walls"). */
isk_integrator sweep_reference(const isk_effect_def *def, const char **why);

/* Totals over every emitter: live particles, kinetic energy sum m v^2 / 2,
 * particles removed as non-finite since create. */
size_t sweep_live(const isk_effect *fx);
double sweep_kinetic(const isk_effect *fx);
size_t sweep_removed(const isk_effect *fx);

/* The last path component of a scene argument without ".ini": the stem of
 * output names ("scenes/fig11_drag.ini" -> "fig11_drag"). */
void sweep_stem(const char *scene, char *out, size_t n);

#endif
