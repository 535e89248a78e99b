/* SPDX-License-Identifier: MIT */
/* The simulator's warning when a live edit moves the scene across a drag
 * edge iskra knows (iskra/stability.h).
 *
 * After the panel and the shortcuts applied this frame's edits (dt,
 * substeps, the speed slider, an integrator, a drag's b, an emitter's
 * mass), the scene's drag is placed against the edges: below iskra's cap
 * (b*h/m <= 1), capped (the drag stops particles within a step), or past
 * the integrator's own edge (where the textbook step would blow up).  A
 * change of place says so in the status line; the same place says
 * nothing, so the line is not taken over every frame. */
#include <math.h>

#include "iskra/stability.h"
#include "play.h"

/* Where emitter i's drag sits: 0 below the cap, 1 capped, 2 past its
 * method's edge. */
static int place(const isk_effect_def *d, int i, double *ratio, double *edge)
{
    *ratio = isk_effect_def_drag_ratio(d, i);
    *edge = isk_integrator_drag_edge(isk_effect_def_emitter_integrator(d, i));
    return *ratio > *edge ? 2 : *ratio > ISK_DRAG_SATURATION ? 1 : 0;
}

void play_stability_watch(player *p)
{
    const isk_effect_def *d = p->fx ? isk_effect_definition(p->fx) : NULL;
    if (!d)
        return;
    int worst = 0, at = -1;
    double ratio = 0.0, edge = INFINITY;
    for (int i = 0; i < d->nemitters; i++) {
        double r, e;
        int k = place(d, i, &r, &e);
        if (at < 0 || k > worst || (k == worst && r > ratio)) {
            worst = k;
            at = i;
            ratio = r;
            edge = e;
        }
    }
    const int level = 1 + worst; /* 0: not seen yet */
    const int before = p->drag_level;
    p->drag_level = level;
    if (before == 0 || before == level || at < 0)
        return;
    const char *name = d->emitters[at].name;
    const char *method = isk_integrator_name(isk_effect_def_emitter_integrator(d, at));
    if (worst == 2)
        play_say(p, "warning: b*h/m = %.3g for '%s' is past %s's drag edge %.4g: its textbook step would blow up; "
                    "iskra caps the drag, so particles just stop - smaller dt or more substeps",
                 ratio, name, method, edge);
    else if (worst == 1)
        play_say(p, "warning: b*h/m = %.3g for '%s' is past iskra's drag cap of 1: the drag stops particles within "
                    "a step (wrong, not unstable) - smaller dt or more substeps",
                 ratio, name);
    else
        play_say(p, "b*h/m = %.3g for '%s': below iskra's drag cap again", ratio, name);
}
