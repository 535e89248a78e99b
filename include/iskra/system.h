/* SPDX-License-Identifier: MIT */
/* iskra/system.h — one particle system: store + rng + forces + integrator +
 * substeps + bounds + time, stepped frame by frame.
 *
 * Plain data: every field is public and documented, so a scene compiler (or
 * a test) can fill it directly; the setters below validate for you.
 *
 * Example: a Coulomb explosion in a box open at the top, 120 frames drawn:
 *
 *     isk_system s;
 *     if (isk_system_init(&s, 42, 0) != ISK_OK) return 1;     // seed, initial capacity
 *     s.forces.gravity = 9.81;  s.forces.drag = 0.47;
 *     unsigned sides = ISK_SIDE_RIGHT | ISK_SIDE_BOTTOM | ISK_SIDE_LEFT;
 *     isk_status st = isk_bounds_thesis(&s.bounds, 0, 10, 0, 10, sides);
 *     s.bounce_in_step = 1;
 *     if (st == ISK_OK) st = isk_system_explode(&s, ISK_EXPLOSION_COULOMB, 5, 5, 1000);
 *     isk_view view;
 *     isk_canvas c = {0};
 *     if (st == ISK_OK) st = isk_view_window(&view, 300, 300, 0, 10, 0, 10);
 *     if (st == ISK_OK) st = isk_canvas_init(&c, 300, 300);
 *     for (int frame = 0; frame < 120 && st == ISK_OK; frame++) {
 *         st = isk_system_step(&s, 1.0 / 60);
 *         isk_canvas_fill(&c, ISK_BLACK);
 *         const isk_particles *p = &s.particles;
 *         isk_draw_dots(&c, &view, p->count, p->x, p->y, ISK_YELLOW, ISK_BLEND_OVER);
 *     }
 *     isk_canvas_free(&c);
 *     isk_system_free(&s);
 *     return st != ISK_OK;
 *
 * isk_system_step(sys, dt) — one frame, the thesis simulator's order:
 *   1. release due multi-Coulomb batches (scheduler, simulated time)
 *   2. h = dt / substeps / speed_divisor     (the thesis's dt/precision/f)
 *   3. substeps times, over the particles present at step 1 (index order,
 *      in blocks of ISK_SIM_BLOCK):
 *        forces (gravity -> drag -> potentials summed apart -> added last)
 *        -> integrator(h) -> bounds (if bounce_in_step) -> age += h (if ageing)
 *   4. time += h*substeps; if ageing: cull dead particles (order kept)
 *   5. if auto_move_potentials: every potential moves by motion(h*substeps)
 * The thesis's own frame also draws between 3 and 5 (particles after the
 * bounce, potentials before they move): leave auto_move_potentials = 0 and
 * call isk_system_move_potentials() after drawing to reproduce it exactly.
 * The thesis's examples draw BEFORE the bounce: bounce_in_step = 0, then
 * step, draw, isk_system_bounce().
 *
 * Defaults (isk_system_init): semi-implicit Euler (the thesis code), 1
 * substep, speed divisor 1, no gravity/drag/potentials, no bounds, ageing
 * off, potentials auto-move, Coulomb kick ISK_KICK_ALL (as the thesis
 * simulator), explosion limit 10 000, centre rule ISK_FIDELITY_SOUND.
 * Potential ids count 1, 2, 3, ... per system (the thesis's static counter
 * belongs to the system here, so two systems never interact).
 */
#ifndef ISKRA_SYSTEM_H
#define ISKRA_SYSTEM_H

#include <stddef.h>
#include <stdint.h>

#include "iskra/bounds.h"
#include "iskra/explode.h"
#include "iskra/forces.h"
#include "iskra/integrate.h"
#include "iskra/limits.h"
#include "iskra/particles.h"
#include "iskra/rng.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct isk_system {
    isk_particles particles;
    isk_rng rng;
    isk_forces forces;          /* forces.pot is owned by the system */
    size_t pot_capacity;
    int next_potential_id;      /* last id handed out (thesis: CoulombovPotencijal.br) */
    isk_integrator integrator;
    int substeps;               /* the thesis's "precision" N >= 1 */
    double speed_divisor;       /* the thesis's slider divisor f >= 1 (1 = real time) */
    isk_bounds bounds;          /* sides == 0: no walls */
    int bounce_in_step;         /* 1: bounce stage after the integrator */
    int ageing;                 /* 1: age += h, cull age >= life at the end of the step */
    int auto_move_potentials;   /* 1: potentials move at the end of the step */
    isk_kick_target coulomb_kick;
    size_t explode_limit;       /* largest accepted explosion count */
    double time;                /* simulated seconds */
    size_t removed_nonfinite;   /* particles removed because their state went NaN or infinite
                                   (the thesis centre rule can; iskra/limits.h) */
    isk_multi_coulomb *jobs;    /* multi-Coulomb explosions in progress */
    size_t njobs, job_capacity;
    isk_scratch scratch;
} isk_system;

/* Errors: ISK_ERR_NULL, ISK_ERR_SIZE, ISK_ERR_NOMEM (then *s is safe to free). */
isk_status isk_system_init(isk_system *s, uint64_t seed, size_t capacity);
void isk_system_free(isk_system *s);

/* Validating setters, with the ranges scene files have (iskra/limits.h).
 * ISK_ERR_NAN for non-finite, ISK_ERR_RANGE for |g| or b beyond
 * ISK_STRENGTH_MAX, a negative drag b, an unknown integrator, substeps
 * outside 1..ISK_SUBSTEPS_MAX.  Gravity may be negative (it then pulls
 * upwards). */
isk_status isk_system_set_gravity(isk_system *s, double g);
isk_status isk_system_set_drag(isk_system *s, double b);
isk_status isk_system_set_integrator(isk_system *s, isk_integrator method);
isk_status isk_system_set_substeps(isk_system *s, int substeps);
isk_status isk_system_set_bounds(isk_system *s, const isk_bounds *b, int bounce_in_step);

/* Appends a copy of *pot (validated) with the next id; *id may be NULL. */
isk_status isk_system_add_potential(isk_system *s, const isk_potential *pot, int *id);
/* The potential with this id, or NULL. */
isk_potential *isk_system_potential(isk_system *s, int id);
/* Moves every potential by its motion(param), in list order. */
void isk_system_move_potentials(isk_system *s, double param);

/* Runs an emitter on the system's store and rng with s->explode_limit.
 * MULTI_COULOMB releases batch 1 now and schedules the rest.  Errors as
 * iskra/explode.h; ISK_ERR_RANGE for an unknown kind. */
isk_status isk_system_explode(isk_system *s, isk_explosion kind, double cx, double cy, size_t count);
/* The stationary layer (mass 1, at rest) on the system's rng. */
isk_status isk_system_add_layer(isk_system *s, double xmin, double xmax, double ymin, double ymax,
                                size_t count);

/* One frame (see the top).  The fields are plain data, so the step checks
 * them against what scene files accept (iskra/limits.h): dt in [0,
 * ISK_DT_MAX] (0 is an empty step), speed divisor, substeps, the strengths
 * of gravity, acceleration and drag, every potential (isk_potential_validate).
 * Errors: ISK_ERR_NULL, ISK_ERR_NAN (dt or a field not finite),
 * ISK_ERR_RANGE (dt or a field out of range), ISK_ERR_NOMEM from a
 * multi-Coulomb release.  A particle whose state goes non-finite is removed
 * and counted in removed_nonfinite. */
isk_status isk_system_step(isk_system *s, double dt);

/* The bounce stage alone, on the whole store (for draw-before-bounce). */
void isk_system_bounce(isk_system *s);

#ifdef __cplusplus
}
#endif

#endif
