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
 * both step through isk_pipeline_run, so "the same bits as the thesis's
 * loop" holds by construction, not by keeping two loops aligned.  Blocks
 * keep the per-block scratch (force accumulators, RK4 copies, the positions
 * before the move) in L1, and they are the unit that threads will share
 * out: the bytes never depend on who ran which block.
 *
 *     isk_pipeline pl;
 *     isk_pipeline_init(&pl);
 *     isk_stage *s = isk_pipeline_add(&pl, &isk_stage_motion);   // NULL when full
 *     s->u.motion.method = ISK_INTEGRATE_SEMI_EULER;
 *     s->u.motion.forces = &forces;
 *     isk_pipeline_run(&pl, &store, 0, store.count, h, &scratch);
 *
 * A stage kind is a row of plain data: its name (for `iskra describe`), its
 * kernel, and a function that writes its parameters in words.  Adding a
 * stage is one kind plus its kernel; no switch anywhere dispatches on it.
 * A stage the scene does not use is simply not in the list.  Stages that
 * run one after the other on the same columns may also be one kind doing
 * them in one pass (isk_stage_drift_sway: the drift, the slowing, the
 * sway), chosen by the list's compiler; it describes itself as the stages
 * it stands for, and gives their bits.
 */
#ifndef ISKRA_SIM_STAGE_H
#define ISKRA_SIM_STAGE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "iskra/bounds.h"
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

/* The sway's parameters (isk_stage_oscillate, and the sway of
 * isk_stage_drift_sway). */
typedef struct isk_stage_osc {
    double decay;                                    /* amplitude *= max(0, 1 - decay*h) */
    const isk_sinlut *table;
    isk_sinlut_mode mode;                            /* how the sine is read (ISK_SINLUT_LIBM: sin) */
    int faithful;                                    /* 1: also add the offset change to vx */
    double omega_min, omega_max, amp_min, amp_max;   /* for describe only */
} isk_stage_osc;

/* What a stage is to a block at rest (isk_rest, below). */
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

typedef struct isk_stage_kind {
    const char *name;                                        /* "drift" */
    void (*run)(const isk_stage *st, isk_block *b, double h);
    void (*describe)(const isk_stage *st, FILE *out);        /* the parameters, in words */
    isk_rest_role (*rest)(const isk_stage *st);              /* NULL: ISK_REST_BREAKS */
} isk_stage_kind;

/* The axes of a block at rest (isk_block.frozen, isk_rest_blocks). */
enum { ISK_REST_X = 1, ISK_REST_Y = 2 };

/* Per-kind parameters.  Pointers refer to data the owner keeps alive and
 * unchanged while the pipeline runs (recompile after changing them). */
struct isk_stage {
    const isk_stage_kind *kind;
    union {
        struct { double ax, ay; } drift;                     /* isk_stage_drift */
        struct { double ax, ay, slowing; } drift_slow;       /* isk_stage_drift_slow */
        struct {
            isk_integrator method;
            isk_forces *forces;
            int remember;                                    /* 1: also keep the start state in the scratch's
                                                                x_old.. (the remember stage, in the same pass) */
        } motion;
        struct { double slowing; } slow;
        isk_stage_osc osc;                                   /* isk_stage_oscillate */
        struct {
            double ax, ay;                                   /* the drift's constant acceleration */
            double slowing;                                  /* order THESIS or SOUND: the slowing */
            isk_drift_order order;                           /* which drift, with or without the slow stage */
            isk_stage_osc osc;
        } drift_sway;                                        /* isk_stage_drift_sway */
        struct {
            const isk_bounds *b;
            double drag;                                     /* the motion's linear drag b (impact.h) */
            int start;                                       /* 1: the start state was remembered (potentials
                                                                act): the remember stage or motion.remember */
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
        } deflect;
        struct { const struct isk_field *f; } field;         /* isk_stage_field (src/sim/field.h) */
        struct { double spin, spin_range; } spin;           /* isk_stage_spin: for describe only (rad/s) */
    } u;
};

/* Each kind appears at most once in a list, so this is a bound, not a cap
 * that could silently drop anything (isk_pipeline_add reports a full list). */
#define ISK_PIPELINE_MAX 16

typedef struct isk_pipeline {
    isk_stage stage[ISK_PIPELINE_MAX];
    int n;
} isk_pipeline;

/* Blocks at rest.  A block that the list's leading ISK_REST_SKIPPED stages
 * left with its x, y, vx, vy bit for bit as they were is at a fixed point
 * of those stages: they are one function of its state and their
 * parameters, so as long as nothing else writes its particles and the list
 * and the step stay the same, every later step leaves it so again.  The
 * runner then skips those stages for it and runs only the rest of the list
 * (ISK_REST_BESIDE: ageing, spin).  The bytes are the same as running every
 * stage, by that argument, not by a tolerance; a settled layer costs the
 * ageing and nothing more.
 *
 * The same holds for one axis: the skipped stages are per axis (x and vx
 * come out of x, vx and m alone), so a block whose y and vy came out as
 * they were (a floor under it) while x slides steps x alone from then on,
 * its y columns replaced by stand-ins the stages may compute on and whose
 * results are dropped (isk_block.frozen; the walls skip that axis).
 *
 * The runner finds the blocks itself: every few runs it looks at four
 * particles of each awake block in turn, axis by axis; when an axis's
 * stood still it keeps the block's start state in the next run and
 * compares it after the skipped stages; equal, that axis rests.  The
 * owner says what changed between runs:
 *   isk_rest_forget(&r, i)   the particles from i on were moved, removed,
 *                            or written (a cull that keeps the order: from
 *                            the first one it moved; one that fills holes:
 *                            isk_rest_wake_dying before it, its new count
 *                            after); particles appended need nothing
 *   isk_rest_forget(&r, 0)   the list or its parameters changed (recompile)
 * A different step h forgets by itself.  The runs with states cover
 * [0, end), so blocks count from particle 0.
 *
 *     isk_rest r;
 *     isk_rest_init(&r);
 *     isk_pipeline_run_rest(&pl, &store, store.count, h, &scratch, &r);
 *     ...
 *     isk_rest_free(&r); */
typedef struct isk_rest_block {
    uint64_t sample[2];  /* per axis, a hash of four particles' position and velocity at the
                            block's last look (a collision only costs an exact look that fails) */
    unsigned char state; /* the axes at rest, and whether to look at the others (stage.c) */
} isk_rest_block;

typedef struct isk_rest {
    isk_rest_block *block; /* one per block */
    size_t cap;            /* blocks there is room for */
    size_t valid;         /* particles [0, valid) are those the states describe */
    double h;             /* the step they were found at */
    size_t runs;          /* runs so far: whose turn it is to be looked at */
    double *stand_in;     /* per worker, 2 x ISK_SIM_BLOCK: a resting axis's columns while the
                             other axis steps (zeroed once; what the stages make of them is
                             never read) */
    int workers;          /* workers stand_in has room for */
    uint64_t changes;     /* counts what can end a block's rest (a forget below valid, a
                             change of step, a wake): while it and the count stay the
                             same and every block rests, no particle's x, y has changed */
} isk_rest;

void isk_rest_init(isk_rest *r);
void isk_rest_free(isk_rest *r);
void isk_rest_forget(isk_rest *r, size_t from);
/* Before a cull that fills the holes with the last particles (nothing
 * else moves): wakes the blocks at rest that hold a particle about to die
 * (age >= life).  The cull's new count is then forgotten from. */
void isk_rest_wake_dying(isk_rest *r, const isk_particles *p);
/* Blocks of [0, count) at rest on `axes` (ISK_REST_X | ISK_REST_Y: at rest;
 * for the tests and the benchmarks). */
size_t isk_rest_blocks(const isk_rest *r, size_t count, unsigned axes);
/* 1 when count > 0 and every block of [0, count) rests on both axes (the
 * states describe exactly those particles). */
int isk_rest_all(const isk_rest *r, size_t count);
/* How many leading stages of the list a block at rest skips (0: no block
 * of this list can rest). */
int isk_pipeline_rest_prefix(const isk_pipeline *pl);
/* The constant roles, for kinds whose role does not depend on parameters. */
isk_rest_role isk_rest_skipped(const isk_stage *st);
isk_rest_role isk_rest_beside(const isk_stage *st);

void isk_pipeline_init(isk_pipeline *pl);
/* Appends a stage of `kind` with zeroed parameters; NULL when the list is full. */
isk_stage *isk_pipeline_add(isk_pipeline *pl, const isk_stage_kind *kind);
/* Runs the list over particles [begin, end) of p with step h. */
void isk_pipeline_run(const isk_pipeline *pl, isk_particles *p, size_t begin, size_t end, double h,
                      isk_scratch *s);
/* The same over [0, end) with blocks at rest (rest may be NULL: none). */
void isk_pipeline_run_rest(const isk_pipeline *pl, isk_particles *p, size_t end, double h, isk_scratch *s,
                           isk_rest *rest);
/* The same with the blocks shared out over a pool's threads.  Only for
 * lists whose stages touch nothing outside their block (the compiler of the
 * list decides: a potential that can switch itself off, or a deflector
 * that draws from the owner's random stream, makes the order of particles
 * matter); then the bytes are the same for every number of threads.  Below
 * ISK_PIPELINE_MIN_PARALLEL_BLOCKS blocks it runs on the caller.  Returns
 * 1 when a motion stage found a non-finite state (the workers' scratch
 * flags, combined and cleared; isk_scratch.nonfinite), else 0. */
#define ISK_PIPELINE_MIN_PARALLEL_BLOCKS (2048 / ISK_SIM_BLOCK) /* 2048 particles, whatever the block */
struct isk_pool;
int isk_pipeline_run_pool(const isk_pipeline *pl, isk_particles *p, size_t begin, size_t end, double h,
                          struct isk_pool *pool);
/* The same over [0, end) with blocks at rest (rest may be NULL). */
int isk_pipeline_run_pool_rest(const isk_pipeline *pl, isk_particles *p, size_t end, double h,
                               struct isk_pool *pool, isk_rest *rest);
/* One line per stage: "  NAME      parameters". */
void isk_pipeline_describe(const isk_pipeline *pl, FILE *out);
/* One stage's line without its newline (for a stage that describes itself
 * as the stages it fuses). */
void isk_stage_describe_line(const isk_stage *st, FILE *out);

/* The stage kinds, in the only order they ever appear in a list. */
extern const isk_stage_kind isk_stage_field;      /* position-dependent accelerations (src/sim/field.h) */
extern const isk_stage_kind isk_stage_remember;   /* the state before the move (bounces at impact),
                                                     before a drift; a motion stage keeps it itself */
extern const isk_stage_kind isk_stage_drift;      /* constant acceleration + semi-implicit Euler, no mass */
extern const isk_stage_kind isk_stage_drift_slow; /* the same with the fire thesis's slowing in between */
extern const isk_stage_kind isk_stage_drift_sway; /* drift or drift_slow (+ slow), then oscillate, in one pass */
extern const isk_stage_kind isk_stage_motion;     /* forces + an integrator (isk_integrate_block) */
extern const isk_stage_kind isk_stage_slow;       /* v *= max(0, 1 - slowing*h) */
extern const isk_stage_kind isk_stage_oscillate;  /* the fire thesis's horizontal sway (ISK_PARTICLES_OSC) */
extern const isk_stage_kind isk_stage_walls;      /* isk_bounds_apply_step (after remember) */
extern const isk_stage_kind isk_stage_deflect;    /* deflector segments */
extern const isk_stage_kind isk_stage_spin;       /* angle += spin*h, wrapped (ISK_PARTICLES_ANGLE) */
extern const isk_stage_kind isk_stage_age;        /* age += h */

#endif
