/* SPDX-License-Identifier: MIT */
/* src/sim/stage.h — the block runner: a list of stages, each a kernel on
 * plain arrays with its own parameters, run over a particle store in fixed
 * blocks of ISK_SIM_BLOCK particles (internal).
 *
 * The one loop of the simulation, written once:
 *
 *     for (each block [o, o + n) of [begin, end), in index order)
 *         for (each stage of the pipeline, in list order)
 *             stage->kind->run(stage, &block, h);
 *
 * isk_system_step (src/sim/system.c) and the effect runtime (src/scene)
 * both step through isk__pipeline_run, so "the same bits as the thesis's
 * loop" holds by construction, not by keeping two loops aligned.  Blocks
 * keep the per-block scratch (force accumulators, RK4 copies, the positions
 * before the move) in L1, and they are the unit that threads will share
 * out: the bytes never depend on who ran which block.
 *
 *     isk_pipeline pl;
 *     isk__pipeline_init(&pl);
 *     isk_stage *s = isk__pipeline_add(&pl, &isk__stage_motion);   // NULL when full
 *     s->u.motion.method = ISK_INTEGRATE_SEMI_EULER;
 *     s->u.motion.forces = &forces;
 *     isk__pipeline_run(&pl, &store, 0, store.count, h, &scratch, NULL);
 *
 * A stage kind is a row of plain data: its name (for `iskra describe`), its
 * kernel, and a function that writes its parameters in words.  Adding a
 * stage is one kind plus its kernel; no switch anywhere dispatches on it.
 * A stage the scene does not use is simply not in the list.  Stages that
 * run one after the other on the same columns may also be one kind doing
 * them in one pass (isk__stage_drift_sway: the drift, the slowing, the
 * sway), chosen by the list's compiler; it describes itself as the stages
 * it stands for, and gives their bits.
 */
#ifndef ISKRA_SIM_STAGE_H
#define ISKRA_SIM_STAGE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "iskra/bounds.h"
#include "iskra/contacts.h"
#include "iskra/deflector.h"
#include "iskra/forces.h"
#include "iskra/integrate.h"
#include "iskra/particles.h"
#include "iskra/rng.h"
#include "iskra/sinlut.h"
#include "sim/sway.h" /* isk_drift_order */

/* What every stage of one block may use: the store (for its optional
 * columns), offset pointers to the block's first particle, and the
 * per-block scratch (iskra/integrate.h's isk_scratch: one per thread). */
typedef struct isk_block {
    isk_particles *p;
    size_t first, n;                 /* particles [first, first + n) */
    double *x, *y, *vx, *vy, *m;     /* p->x + first, ... */
    isk_scratch *s;
    unsigned frozen;                 /* ISK_REST_X, ISK_REST_Y: that axis rests, and its two
                                        pointers are stand-ins whose results are dropped
                                        (a stage may skip its work on them: the walls do) */
} isk_block;

typedef struct isk_stage isk_stage;

/* The sway's parameters (isk__stage_oscillate, and the sway of
 * isk__stage_drift_sway). */
typedef struct isk_stage_osc {
    double decay;                                    /* amplitude *= max(0, 1 - decay*h) */
    const isk_sinlut *table;
    isk_sinlut_mode mode;                            /* how the sine is read (ISK_SINLUT_LIBM: sin) */
    int faithful;                                    /* 1: also add the offset change to vx */
    double omega_min, omega_max, amp_min, amp_max;   /* for describe only */
} isk_stage_osc;

/* What a stage is to a block at rest (src/sim/rest.h). */
typedef enum isk_rest_role {
    ISK_REST_BREAKS = 0, /* may move a block at rest, or reads a clock, a random stream, other
                            particles or columns beyond x, y, vx, vy, m: no block rests */
    ISK_REST_SKIPPED,    /* a function of each particle's x, y, vx, vy, m and the stage's parameters
                            alone, writing nothing but x, y, vx, vy (and the scratch), and per
                            axis: x and vx come out of x, vx and m alone, y and vy of y, vy and
                            m: skipped for a block at rest, run on the moving axis of a block
                            whose other axis rests */
    ISK_REST_BESIDE      /* neither reads nor writes x, y, vx, vy: runs on every block */
} isk_rest_role;

/* What a stage needs of the runner and of the list (isk_stage_kind.needs);
 * the list's compiler folds them (isk__pipeline_needs) instead of asking
 * about the scene:
 *   ISK_NEEDS_ORDER  its blocks must run one after the other, in particle
 *                    order (it changes what the next particle sees: a
 *                    potential that switches itself off, draws from the
 *                    owner's random stream): the list runs on one thread
 *   ISK_NEEDS_START  the state each particle starts the step from (a
 *                    bounce at the time of impact): the list keeps it, by
 *                    the remember stage or in the motion stage's own pass */
enum { ISK_NEEDS_ORDER = 1u, ISK_NEEDS_START = 2u };

typedef struct isk_stage_kind {
    const char *name;                                        /* "drift" */
    void (*run)(const isk_stage *st, isk_block *b, double h);
    void (*describe)(const isk_stage *st, FILE *out);        /* the parameters, in words */
    isk_rest_role (*rest)(const isk_stage *st);              /* NULL: ISK_REST_BREAKS */
    double (*cost)(const isk_stage *st);                     /* a particle's step, in drifts (the drift
                                                                of a particle is 1); NULL: 1.  What
                                                                decides whether a run is shared out
                                                                among workers, never a byte */
    unsigned (*needs)(const isk_stage *st);                  /* ISK_NEEDS_*; NULL: none */
} isk_stage_kind;

/* The axes of a block at rest (isk_block.frozen, isk__rest_blocks). */
enum { ISK_REST_X = 1, ISK_REST_Y = 2 };

/* Per-kind parameters.  Pointers refer to data the owner keeps alive and
 * unchanged while the pipeline runs (recompile after changing them). */
struct isk_stage {
    const isk_stage_kind *kind;
    union {
        struct { double ax, ay; } drift;                     /* isk__stage_drift */
        struct { double ax, ay, slowing; } drift_slow;       /* isk__stage_drift_slow */
        struct {
            isk_integrator method;
            isk_forces *forces;
            unsigned laws;                                   /* isk_forces_laws(forces) when the list was
                                                                made (isk__stage_motion_init), if known:
                                                                the laws only shrink until the next
                                                                compile (a potential switching off) */
            int laws_known;                                  /* 0: work them out at every block */
            int remember;                                    /* 1: also keep the start state in the scratch's
                                                                x_old.. (the remember stage, in the same pass) */
        } motion;
        struct { double slowing; } slow;
        isk_stage_osc osc;                                   /* isk__stage_oscillate */
        struct {
            double ax, ay;                                   /* the drift's constant acceleration */
            double slowing;                                  /* order THESIS or SOUND: the slowing */
            isk_drift_order order;                           /* which drift, with or without the slow stage */
            isk_stage_osc osc;
        } drift_sway;                                        /* isk__stage_drift_sway */
        struct {
            const isk_bounds *b;
            double drag;                                     /* the motion's linear drag b (impact.h) */
            int curved;                                      /* 1: the flight is not a constant acceleration's
                                                                (potentials act): it needs the start state */
            int start;                                       /* 1: the list keeps the start state (the
                                                                remember stage or motion.remember) */
            double ax, ay, offset;                           /* else: the constant acceleration and the
                                                                integrator's velocity offset */
            int hit;                                         /* count bounces into p->hit (on_hit) */
        } walls;
        struct {
            const isk_deflector *segs;
            int n;
            isk_rng *rng;                                    /* the owner's stream (probabilities) */
            int can_kill;                                    /* some segment kills: life = -inf */
            double drag;                                     /* the motion's linear drag b */
            int hit;                                         /* count bounces into p->hit (on_hit) */
            const isk_bounds *walls;                         /* NULL, or sound walls met in the same
                                                                pass (iskra/contacts.h): no walls stage */
            isk_contact_integrator redo;                     /* the integrator and forces that fly the rest
                                                                of a step after a contact, when redo_on */
            int redo_on;                                     /* 0: the fitted flight does (iskra/contacts.h) */
        } deflect;
        struct { const struct isk_field *f; } field;         /* isk__stage_field (src/sim/field.h) */
        struct { double spin, spin_range, change; } spin;   /* isk__stage_spin: for describe only (rad/s);
                                                               isk__stage_spin_life: change over the life */
    } u;
};

/* Each kind appears at most once in a list, so this is a bound, not a cap
 * that could silently drop anything (isk__pipeline_add reports a full list). */
#define ISK_PIPELINE_MAX 16

typedef struct isk_pipeline {
    isk_stage stage[ISK_PIPELINE_MAX];
    int n;
} isk_pipeline;

/* What the stages of the list need, or-ed (ISK_NEEDS_*). */
unsigned isk__pipeline_needs(const isk_pipeline *pl);
/* Inserts a stage of `kind` with zeroed parameters before stage `at` (0 ..
 * pl->n); NULL when the list is full. */
isk_stage *isk__pipeline_insert(isk_pipeline *pl, int at, const isk_stage_kind *kind);
/* What stages [from, n) of the list declare a particle's step costs, in
 * drifts (isk_stage_kind.cost). */
double isk__pipeline_cost(const isk_pipeline *pl, int from);
/* How many leading stages of the list a block at rest skips (0: no block
 * of this list can rest; rest.c). */
int isk__pipeline_rest_prefix(const isk_pipeline *pl);
/* The constant roles, for kinds whose role does not depend on parameters. */
isk_rest_role isk__rest_skipped(const isk_stage *st);
isk_rest_role isk__rest_beside(const isk_stage *st);

void isk__pipeline_init(isk_pipeline *pl);
/* Appends a stage of `kind` with zeroed parameters; NULL when the list is full. */
isk_stage *isk__pipeline_add(isk_pipeline *pl, const isk_stage_kind *kind);
/* What a run may use beyond the calling thread: both optional. */
struct isk_workers;
struct isk_rest;
typedef struct isk_run_context {
    struct isk_workers *workers; /* NULL: every block on the caller; else the blocks shared out
                                    among the workers (src/sim/workers.h), each with its own
                                    scratch.  Only for lists whose stages touch nothing outside
                                    their block (the list's compiler decides: a potential that can
                                    switch itself off, or a deflector that draws from the owner's
                                    random stream, makes the order of particles matter); then the
                                    bytes are the same for every number of workers.  Below
                                    ISK_PIPELINE_MIN_PARALLEL_BLOCKS blocks it runs on the caller. */
    struct isk_rest *rest;       /* NULL: every block steps in full; else blocks at rest skip the
                                    stages that would leave them as they are (src/sim/rest.h;
                                    only with begin = 0) */
} isk_run_context;
#define ISK_PIPELINE_MIN_PARALLEL_BLOCKS (2048 / ISK_SIM_BLOCK) /* 2048 particles, whatever the block */

/* Runs the list over particles [begin, end) of p with step h: the one loop
 * at the top of this file.  s: the caller's scratch; ctx: NULL, or what
 * the run may use.  Returns s->nonfinite, 1 when a motion stage found a
 * non-finite state (the workers' flags are combined into it and cleared:
 * iskra/integrate.h's isk_scratch.nonfinite). */
int isk__pipeline_run(const isk_pipeline *pl, isk_particles *p, size_t begin, size_t end, double h, isk_scratch *s,
                     const isk_run_context *ctx);
/* One line per stage: "  NAME      parameters". */
void isk__pipeline_describe(const isk_pipeline *pl, FILE *out);
/* One stage's line without its newline (for a stage that describes itself
 * as the stages it fuses). */
void isk__stage_describe_line(const isk_stage *st, FILE *out);

/* The stage kinds, in the only order they ever appear in a list. */
extern const isk_stage_kind isk__stage_field;      /* position-dependent accelerations (src/sim/field.h) */
extern const isk_stage_kind isk__stage_remember;   /* the state before the move (bounces at impact),
                                                     before a drift; a motion stage keeps it itself */
extern const isk_stage_kind isk__stage_drift;      /* constant acceleration + semi-implicit Euler, no mass */
extern const isk_stage_kind isk__stage_drift_slow; /* the same with the fire thesis's slowing in between */
extern const isk_stage_kind isk__stage_drift_sway; /* drift or drift_slow (+ slow), then oscillate, in one pass */
extern const isk_stage_kind isk__stage_motion;
/* A motion stage's parameters: its integrator and forces, and the laws
 * that act in them now (so its blocks need not work them out). */
void isk__stage_motion_init(isk_stage *st, isk_integrator method, isk_forces *f);     /* forces + an integrator (isk_integrate_block) */
extern const isk_stage_kind isk__stage_slow;       /* v *= max(0, 1 - slowing*h) */
extern const isk_stage_kind isk__stage_slow_each;  /* the same with slowing + the particle's slowing_extra */
extern const isk_stage_kind isk__stage_oscillate;  /* the fire thesis's horizontal sway (ISK_PARTICLES_OSC) */
extern const isk_stage_kind isk__stage_walls;      /* isk_bounds_apply_step (after remember) */
extern const isk_stage_kind isk__stage_deflect;    /* deflector segments, and the walls with them or
                                                     with potentials (iskra/contacts.h) */
/* Whether the contact pass flies the rest of a step after a contact with
 * the integrator (iskra/contacts.h): when potentials act (the force varies
 * along the path), none of them may switch itself off (extra evaluations
 * would trip it), and the integrator's positions lie on the flight
 * (velocity offset 0; the Euler forms keep the flight and their offset:
 * first order either way). */
int isk__contacts_redo(const isk_forces *f, isk_integrator method);
extern const isk_stage_kind isk__stage_spin;       /* angle += spin*h, wrapped (ISK_PARTICLES_ANGLE) */
extern const isk_stage_kind isk__stage_spin_life;  /* the same with spin + change*t at normalised age t */
extern const isk_stage_kind isk__stage_age;        /* age += h */

#endif
