/* SPDX-License-Identifier: MIT */
/* The simulator's warning when a live edit moves the scene across an edge
 * iskra knows (iskra/stability.h).
 *
 * After the panel and the shortcuts applied this frame's edits (dt,
 * substeps, the speed slider, an integrator, a drag's b, a potential, an
 * emitter's mass), the scene is placed against the edges, the worst
 * emitter deciding:
 *   drag     below iskra's cap (b*h/m <= 1), capped (the drag stops
 *            particles within a step), or past the integrator's own drag
 *            edge (where the textbook step would blow up);
 *   spring   below or past the integrator's spring edge (w*h) for the
 *            stiffest linear spring, a potential's core.
 * A change of place says so in the status line; the same place says
 * nothing, so the line is not taken over every frame, and the scene as
 * loaded says nothing either. */
#include <math.h>

#include "iskra/stability.h"
#include "play.h"

/* The worst emitter's place (0 below, higher worse) by `place`; its index
 * in *at (-1: no emitter), its ratio and edge. */
static int worst(const isk_effect_def *d, int (*place)(const isk_effect_def *, int, double *, double *), int *at,
                 double *ratio, double *edge)
{
    int w = 0;
    *at = -1;
    for (int i = 0; i < d->nemitters; i++) {
        double r, e;
        int k = place(d, i, &r, &e);
        if (*at < 0 || k > w || (k == w && r > *ratio)) {
            w = k;
            *at = i;
            *ratio = r;
            *edge = e;
        }
    }
    return w;
}

/* 0 below the cap, 1 capped, 2 past the method's drag edge. */
static int drag_place(const isk_effect_def *d, int i, double *ratio, double *edge)
{
    *ratio = isk_effect_def_drag_ratio(d, i);
    *edge = isk_integrator_drag_edge(isk_effect_def_emitter_integrator(d, i));
    return *ratio > *edge ? 2 : *ratio > ISK_DRAG_SATURATION ? 1 : 0;
}

/* 0 no spring or below its edge, 1 past it. */
static int spring_place(const isk_effect_def *d, int i, double *ratio, double *edge)
{
    *ratio = isk_effect_def_spring_ratio(d, i);
    *edge = isk_integrator_spring_edge(isk_effect_def_emitter_integrator(d, i));
    return *ratio > 0 && *ratio > *edge;
}

/* Records the new place in *level (1 + place; 0: not seen yet); 1 when it
 * changed from a place seen before. */
static int moved(int *level, int place)
{
    int before = *level;
    *level = 1 + place;
    return before != 0 && before != *level;
}

void play_stability_watch(player *p)
{
    const isk_effect_def *d = p->fx ? isk_effect_definition(p->fx) : NULL;
    if (!d || d->nemitters == 0)
        return;
    int at;
    double ratio = 0.0, edge = INFINITY;
    int w = worst(d, drag_place, &at, &ratio, &edge);
    if (moved(&p->drag_level, w)) {
        const char *name = d->emitters[at].name;
        const char *method = isk_integrator_name(isk_effect_def_emitter_integrator(d, at));
        if (w == 2)
            play_say(p, "warning: b*h/m = %.3g for '%s' is past %s's drag edge %.4g: its textbook step would blow "
                        "up; iskra caps the drag, so particles just stop - smaller dt or more substeps",
                     ratio, name, method, edge);
        else if (w == 1)
            play_say(p, "warning: b*h/m = %.3g for '%s' is past iskra's drag cap of 1: the drag stops particles "
                        "within a step (wrong, not unstable) - smaller dt or more substeps",
                     ratio, name);
        else
            play_say(p, "b*h/m = %.3g for '%s': below iskra's drag cap again", ratio, name);
    }
    w = worst(d, spring_place, &at, &ratio, &edge);
    if (moved(&p->spring_level, w)) {
        const char *name = d->emitters[at].name;
        const char *method = isk_integrator_name(isk_effect_def_emitter_integrator(d, at));
        if (w && edge > 0)
            play_say(p, "warning: w*h = %.3g for '%s' is past %s's spring edge %.4g: in a potential's core its "
                        "energy grows - smaller dt or more substeps",
                     ratio, name, method, edge);
        else if (w)
            play_say(p, "warning: %s grows the energy in a potential's core at any step (w*h = %.3g for '%s')",
                     method, ratio, name);
        else
            play_say(p, "w*h = %.3g for '%s': below %s's spring edge again", ratio, name, method);
    }
}
