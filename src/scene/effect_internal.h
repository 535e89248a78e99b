/* src/scene/effect_internal.h — the compiled form of an isk_effect (internal).
 *
 * An effect is a copy of its definition plus one fx_group per emitter.  A
 * group owns its particle store, its random generator and its compiled
 * stage list: plain arrays of stage kinds run block by block (ISK_SIM_BLOCK
 * particles at a time, so per-block scratch stays in L1) in the order the
 * list gives.  Nothing in a stage loop branches on scene-level choices: the
 * list decides which loops run at all.
 */
#ifndef ISKRA_SCENE_EFFECT_INTERNAL_H
#define ISKRA_SCENE_EFFECT_INTERNAL_H

#include "iskra/effect.h"
#include "iskra/gradient.h"
#include "iskra/sinlut.h"

/* Stages of a group's step, in the only order they ever run. */
typedef enum fx_stage_kind {
    FX_STAGE_RELEASE = 0,   /* scheduled multi-Coulomb batches / timed explosions */
    FX_STAGE_REMEMBER,      /* keep positions before moving (deflectors need the path) */
    FX_STAGE_DRIFT,         /* fast path: constant acceleration + semi-implicit Euler, no mass */
    FX_STAGE_DRIFT_SLOW,    /* the same with the fire thesis's slowing before the position step */
    FX_STAGE_MOTION,        /* forces + integrator (isk_integrate_block) */
    FX_STAGE_SLOW,          /* v *= max(0, 1 - slowing*h) */
    FX_STAGE_OSCILLATE,     /* horizontal flame oscillation */
    FX_STAGE_WALLS,         /* the effect's bounds */
    FX_STAGE_DEFLECT,       /* deflector segments */
    FX_STAGE_AGE,           /* age += h */
    FX_STAGE_SPAWN,         /* stream births in (t, t+h], back-dated */
    FX_STAGE_CULL,          /* remove age >= life */
    FX_STAGE_COUNT
} fx_stage_kind;

#define FX_MAX_STAGES 24

typedef struct fx_stage {
    fx_stage_kind kind;
    char label[120];        /* one line of `iskra describe` */
} fx_stage;

typedef struct fx_group {
    int index;                     /* emitter index in the definition */
    const isk_emitter_def *def;    /* points into effect->def */
    isk_particles store;
    isk_rng rng;
    isk_forces forces;             /* this group's forces for isk_integrate_block */
    isk_potential *pots;           /* working copies of the referenced, enabled potentials */
    int *pot_src;                  /* their indices in effect->pots */
    size_t npots;
    double ax, ay;                 /* constant acceleration (wind, weight, and gravity on the fast path) */
    isk_integrator integrator;
    int substeps;
    fx_stage stages[FX_MAX_STAGES];
    int nstages;
    int has_stage[FX_STAGE_COUNT];
    int walls_after_draw;          /* draw_before_bounce: walls run at the start of the next frame */
    isk_multi_coulomb mc;          /* ISK_EXPLOSION_MULTI_COULOMB */
    int mc_active;
    int fired;                     /* EXPLOSION with start > 0 has fired */
    isk_deflector *defl;           /* the referenced deflectors, copied */
    int ndefl;
    int defl_can_kill;             /* some deflector kills: the cull stage is needed */
    /* oscillation state, parallel to the store (only when has_osc) */
    int has_osc;
    double *osc_amp, *osc_phase, *osc_omega, *osc_off;
    size_t osc_cap;
    double slow_per_s;             /* the emitter's slowing */
    /* stream state (effect_stream.c) */
    uint64_t emitted;              /* stream births so far (accumulator mode: the next is due at start + (emitted+1)/rate) */
    double next_burst;             /* time of the next burst */
    size_t dropped;                /* spawns lost to a full pool */
    /* baked over-life tables (render) */
    isk_color_gradient color_ramp;
    isk_scalar_gradient alpha_ramp, size_ramp;
    int has_color_ramp, has_alpha_ramp, has_size_ramp;
} fx_group;

struct isk_effect {
    isk_effect_def def;            /* deep copy, owned */
    isk_view view;
    isk_potential *pots;           /* the effect's potentials (force order), with ids */
    int *pot_force;                /* pots[i] is def.forces[pot_force[i]] */
    size_t npots;
    fx_group *groups;              /* one per emitter, definition order */
    int ngroups;
    int *draw_order;               /* group indices sorted by (order, index) */
    isk_scratch scratch;
    isk_sinlut sin_table;
    double time;
    long frame;
    double last_frame_time;        /* potentials move by this at the next step */
    isk_sprite_cache *sprites;
    double x_old[ISK_SIM_BLOCK], y_old[ISK_SIM_BLOCK];
    uint8_t killed[ISK_SIM_BLOCK];
};

/* effect_def.c */
isk_status fx_def_copy(isk_effect_def *dst, const isk_effect_def *src);

/* effect_stream.c: stream emitters (continuous emission and bursts). */
isk_status fx_stream_validate(const isk_emitter_def *e, char *why, size_t n);
void fx_stream_reset(fx_group *g, double time);
/* Spawns the births due in (t0, t0 + h] into g->store and advances each by
 * its age through `advance` (the group's own stages on that one particle). */
typedef void (*fx_advance_fn)(isk_effect *e, fx_group *g, size_t i, double age);
isk_status fx_stream_spawn(isk_effect *e, fx_group *g, double t0, double h, fx_advance_fn advance);

/* effect_render.c */
isk_status fx_render(isk_effect *e, isk_canvas *c);
isk_status fx_bake_ramps(fx_group *g, isk_error *err);
void fx_free_ramps(fx_group *g);

/* effect.c: run the group's per-particle stages on [begin, end) with step h. */
void fx_run_stages(isk_effect *e, fx_group *g, size_t begin, size_t end, double h);
/* Grows the oscillation arrays to the store's capacity (call after adding). */
isk_status fx_group_sync(fx_group *g);
/* Initial oscillation state of particle i (draws omega, then amplitude,
 * then with osc_random_phase the phase). */
void fx_group_init_osc(isk_effect *e, fx_group *g, size_t i);
/* Removes particles with age >= life from the store and the parallel
 * arrays, keeping the order of the others. */
size_t fx_group_cull(fx_group *g);

#endif
