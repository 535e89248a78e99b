/* SPDX-License-Identifier: MIT */
/* The shadow run of `iskra play` (--shadow, G): a reference copy of the
 * running scene stepped beside it, so the canvas can show how far each
 * particle is from where a much finer integration puts it.
 *
 * The reference starts as a snapshot of the running scene (the same seed,
 * the same particles, the same births to come) with only its integrator
 * and substeps changed: Yoshida-4 where every force is smooth, RK4 where
 * one is not (walls, deflectors, turbulence, a potential with a minimum or
 * maximum distance: a high-order composition gains nothing across a kink
 * and RK4 is the robust fourth order), at PLAY_SHADOW_FACTOR times the
 * substeps (--shadow-factor; clamped to the substeps' limit).  Every live
 * edit reaches both (the hooks below, called where the running scene is
 * changed); an edit of the integrator or the substeps gives the reference
 * its own again, for the new substeps.  A reset, reload or seek of the
 * timeline starts it again from the running scene.  Particles are paired
 * by slot, per emitter, while the emitter's counts agree; from the frame
 * they first differ (a deflector's kill, a particle removed as non-finite,
 * a wall's kill in one run only) that emitter is not compared until the
 * shadow starts again, and the canvas says so.
 *
 * With the shadow off (p->shadow NULL) nothing here runs: the pipeline,
 * describe and the window's pixels are those of a plain `iskra play`.
 *
 *     p->shadow_wanted = 1;          // --shadow: play_restarted starts it
 *     play_shadow_toggle(p);         // G
 *     play_shadow_set(p, "force drag", "b", "0.3");   // after the running scene took it
 *     play_shadow_draw(p);           // over the canvas, before the HUD
 */
#ifndef ISKRA_TOOL_PLAY_SHADOW_H
#define ISKRA_TOOL_PLAY_SHADOW_H

#include <stddef.h>
#include <stdio.h>

#include "play.h"

#define PLAY_SHADOW_FACTOR 16 /* the reference's substeps per substep of the scene */

/* The error of one frame: each paired particle's distance from its
 * reference, in pixels (the running scene's view). */
typedef struct play_shadow_error {
    double median, p99, max;   /* nearest rank: the ceil(q n)-th smallest */
    size_t compared;           /* particles paired */
} play_shadow_error;

/* The median, 99th percentile and largest of px[0..n-1], sorting px in
 * place (all zeros for n == 0). */
play_shadow_error play_shadow_error_of(double *px, size_t n);

/* On (start it from the running scene) or off (free it); says which. */
void play_shadow_toggle(player *p);
/* Starts it again from the running scene, when wanted (reset, reload, a
 * seek of the timeline); a failure turns it off and says why. */
void play_shadow_restart(player *p);
/* After each step of the running scene, which took main_seconds: one step
 * of the reference, timed; the seconds it took (the scene's own cost
 * leaves them out). */
double play_shadow_stepped(player *p, double main_seconds);
/* After a shown frame's steps: the error, into the chart's history. */
void play_shadow_measure(player *p);
/* The ghosts, the error's text and chart over the canvas in p->shown. */
void play_shadow_draw(player *p);
void play_shadow_free(player *p);
/* One line for the end of a session (stderr): the reference, the last
 * frame's error, how many were compared since which frame. */
void play_shadow_report(const player *p, FILE *f);
/* The last frame's error (zeros while off). */
play_shadow_error play_shadow_last(const player *p);

/* The running scene took an edit: the reference takes the same. */
void play_shadow_set(player *p, const char *section, const char *key, const char *value);
void play_shadow_click(player *p, double x, double y);
void play_shadow_move(player *p, const char *section, double x, double y);
void play_shadow_add_potential(player *p, const char *name, const isk_potential *pot);
void play_shadow_remove_force(player *p, const char *name);

#endif
