/* SPDX-License-Identifier: MIT */
/* src/scene/effect_internal.h — the compiled form of an isk_effect (internal).
 *
 * An effect is a copy of its definition, the live potentials, and one
 * fx_group per emitter.  A group owns its particle store, its random stream
 * and what its emitter compiles to (effect_compile.c):
 *
 *   frame start   stages run once per frame before the substeps (the walls
 *                 of draw_before_bounce, timed and scheduled explosions)
 *   pipeline      the block runner's list (src/sim/stage.h), run over the
 *                 store every substep
 *   substep end   stages run after every substep (stream births, the cull)
 *   draw          the draw kind that draws the store, chosen once
 *
 * The frame loop (effect_frame.c) runs the lists; nothing in it asks which
 * stages exist.  Files, one job each:
 *   effect.c          lifecycle, workers, read-only views
 *   effect_frame.c    the frame loop, the clocks, prewarm
 *   effect_check.c    validation of a definition
 *   effect_compile.c  definition -> lists, and describe
 *   effect_group.c    explosions, their release, the cull
 *   effect_adopt.c    births: every source's particles enter through isk__fx_adopt
 *   effect_clock.c    the time of a frame, a group's time
 *   effect_live.c     changes while running: isk_effect_set / get, potentials
 *   effect_control.c  driving an emitter by hand: emit, set_active, set_paused, move
 *   effect_snapshot.c snapshots: the running state kept and put back (its rows:
 *                     snapshot_internal.h; as exact bytes: snapshot_bytes.c)
 *   effect_stream.c   when a stream's particles are born
 *   effect_events.c   sub-emitters: deaths and bounces as events, their children
 *   effect_render.c   a frame's drawing: drawings, deflectors, groups in order, potentials
 *   effect_draws.c    how a group looks: ramps, styles, the draw kinds (a row each)
 *   effect_bands.c    a draw shared out in bands (fast path: src/core/fast_paths.h)
 *   effect_retain.c   a group at rest drawn from recorded blends (fast path)
 *   effect_trail.c    trails: recorded after each frame, drawn first
 *   effect_def.c      building and copying definitions
 *   effect_probes.c   probes: measured after each frame, drawn last, read
 */
#ifndef ISKRA_SCENE_EFFECT_INTERNAL_H
#define ISKRA_SCENE_EFFECT_INTERNAL_H

#include <stdio.h>

#include "iskra/effect.h"
#include "iskra/probes.h"
#include "iskra/gradient.h"
#include "iskra/sinlut.h"
#include "sim/field.h"
#include "iskra/texture.h"
#include "sim/rest.h"
#include "sim/stage.h"
#include "sim/workers.h"
#include "view/world_batch.h"

typedef struct fx_group fx_group;

/* A simulated clock: the time at frame f is t0 + (f - f0) * step, a product
 * and not a running sum, so 144 frames of 1/144 s end at 1 s as exactly as
 * 30 of 1/30 s.  The step is the frame's simulated time (dt /
 * speed_divisor); when a live change alters it, the clock is rebased (t0:
 * the time now, f0: this frame), so the time already elapsed is never
 * rescaled and the clock only moves forward (effect.c; the clocks are read
 * in effect_clock.c). */
typedef struct fx_clock {
    double t0;
    long f0;
    double step;
} fx_clock;
double isk__fx_clock_at(const fx_clock *c, long frame);

/* ---- sub-emitters and trails ----
 * An event waiting in a sub-emitter's group: where and how fast the parent
 * was at the end of the substep in which it died or bounced, and that time. */
typedef struct fx_event {
    double x, y, vx, vy, t;
} fx_event;

typedef struct fx_events {
    fx_event *ev;
    size_t n, cap;
} fx_events;
/* ---- end of sub-emitters and trails ---- */

/* A group-level stage (frame start or substep end). */
typedef struct fx_step_kind {
    const char *name;
    /* t0: the simulated time at the start of the substep (of the frame for
     * frame-start stages, whose h is the frame's step); h: the substep. */
    isk_status (*run)(isk_effect *e, fx_group *g, double t0, double h);
    void (*describe)(const isk_effect *e, const fx_group *g, FILE *out);
} fx_step_kind;

#define FX_MAX_STEP_STAGES 4

/* What one band of a group's draw needs (effect_bands.c). */
typedef struct fx_band {
    int r0, r1;                                       /* the canvas rows [r0, r1) it blends */
    int c0, c1;                                       /* and columns [c0, c1) (only the batched dots
                                                       * get bands of columns: FX_MAY_COLUMNS) */
    size_t first, end;                                /* the particles [first, end) of the store, */
    const uint32_t *list;                             /* or, when not NULL, these, */
    size_t nlist;                                     /* in this order (effect_bands.c) */
    int index;                                        /* which band of its draw (retained records) */
    const isk_sprite *sprite[ISK_SPRITE_MAX_SIZE + 1]; /* by whole-pixel size (sprite groups) */
    double sprite_reach;                              /* rows a sprite can reach from its centre */
} fx_band;

/* The threaded draw's sorting of particles into bands (effect_bands.c):
 * kept between frames, grown as needed. */
typedef struct fx_bins {
    uint16_t *code;                /* per particle: its first and last band */
    uint32_t *idx;                 /* every band's particles, band after band */
    uint8_t *copies;               /* bands of columns after the first: their own copies of the
                                      canvas, in which they draw their columns (effect_bands.c) */
    size_t code_cap, idx_cap, copies_cap;
    long splits;                   /* draws whose particles were split among the threads (tests) */
} fx_bins;

/* Draws one band of a group's store (a draw kind's routine); ISK_ERR_NOMEM
 * when a sprite could not be baked. */
typedef isk_status (*fx_draw_fn)(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b);
typedef struct fx_draw_kind fx_draw_kind; /* effect_draws.c: a row per draw kind */

/* A group at rest drawn again from the blends its last draw recorded
 * (effect_retain.c, view/world_batch.h's retained dots). */
typedef struct fx_tile {
    int r0, r1, c0, c1;
    int y0, y1; /* the rows [y0, y1) its records blend (within [r0, r1); y0 == y1: none) */
} fx_tile;
typedef struct fx_retained {
    int nb;                       /* bands recorded, each with its records; 0: none */
    int columns;                  /* they are bands of columns (drawn in copies of the canvas) */
    int cap;                      /* bands the arrays below have room for */
    fx_tile *tile;                /* per band: its rows and columns */
    isk__dot_rec **rec;           /* per band: its records */
    size_t *n;                    /* per band: how many */
    int *failed;                  /* per band, while recording: a point the records cannot hold */
    /* what they are the blends of */
    uint64_t changes;             /* the group's isk_rest.changes */
    size_t count;
    isk_view view;
    int width, height, threads;
    unsigned rule;
    int refused;                  /* recording failed for this key: not tried again until it changes */
    long records, replays;        /* draws recorded and replayed (tests) */
} fx_retained;

/* The emitter's random streams.  The main one (fx_group.rng) draws what
 * the theses' scenes draw: positions, launch velocities, lives,
 * oscillation, the thesis's jitter, explosions.  Each optional attribute,
 * a draw that exists only when its key is set, has a stream of its own,
 * so turning the key on or off never moves the main stream's draws (and
 * so no other particle).  Seeds: effect_group.c's table. */
typedef enum fx_stream {
    FX_STREAM_MASS,     /* mass_range */
    FX_STREAM_ROTATION, /* rotation_range */
    FX_STREAM_SPIN,     /* spin_range */
    FX_STREAM_SIZE,     /* size_range */
    FX_STREAM_COLOR,    /* color_pick */
    FX_STREAM_CHANCE,   /* a deflector's probability */
    FX_STREAM_FRAME,    /* flipbook_random_start */
    FX_STREAM_RADIAL,   /* radial_accel_range */
    FX_STREAM_TANGENTIAL, /* tangential_accel_range */
    FX_STREAM_WIND,     /* wind_range */
    FX_STREAM_SLOWING,  /* slowing_range */
    FX_STREAM_COUNT
} fx_stream;

struct fx_group {
    int index;                     /* emitter index in the definition */
    const isk_emitter_def *def;    /* points into effect->def */
    isk_particles store;
    isk_rng rng;                   /* the main stream */
    isk_rng streams[FX_STREAM_COUNT]; /* one per optional attribute (fx_stream) */

    /* compiled (effect_compile.c) */
    const fx_step_kind *frame_start[FX_MAX_STEP_STAGES];
    int nframe_start;
    isk_pipeline pipeline;
    const fx_step_kind *substep_end[FX_MAX_STEP_STAGES];
    int nsubstep_end;
    isk_forces forces;             /* the motion stage's (potentials picked from effect->pots) */
    size_t *pick;                  /* room for every potential of the effect */
    size_t pick_cap;
    isk_deflector *defl;           /* the referenced deflectors' segments, in reference order */
    int ndefl, defl_cap;
    isk_integrator integrator;
    int substeps;
    double const_ax, const_ay;     /* the constant part of the acceleration (thesis jitter) */
    int parallel;                  /* its pipeline's blocks are independent: threads may share them */
    int rests;                     /* its blocks may rest (sim/stage.h's isk_rest): nothing but the
                                      pipeline moves its particles (effect_compile.c) */
    isk_rest rest;                 /* which blocks rest; forgotten on a recompile, a cull, a removal */
    int cull_unordered;            /* the order of its particles is seen by nothing (effect_compile.c) */
    int keep_on_canvas;            /* reflect walls hold it: one on the far edge is drawn on it */
    const fx_draw_kind *draw;      /* its particles' draw kind (effect_draws.c) */
    fx_retained retained;          /* its batched dots' blends while it rests (effect_retain.c) */
    uint32_t *draw_list;           /* draw_order oldest or random: the frame's order (effect_render.c) */
    size_t draw_list_cap;
    long shared_updates;           /* substeps whose update was shared out among the workers (tests) */

    /* explosions (effect_group.c) */
    isk_multi_coulomb mc;          /* ISK_EXPLOSION_MULTI_COULOMB */
    int mc_active;
    int fired;                     /* EXPLOSION with start > 0 has fired */

    /* stream state (effect_stream.c) */
    double origin;                 /* the k-th accumulator birth is due at origin + k/rate */
    uint64_t emitted;              /* accumulator births since origin */
    double next_burst;             /* time of the next burst */
    uint64_t dropped;              /* spawns lost to a full pool (saturates) */
    size_t removed_nonfinite;      /* particles removed because their state went non-finite */

    /* motion (effect_stream.c, src/sim/stage_field.c) */
    isk_field field;               /* the field stage's terms, and its clock (set every substep) */
    int has_field;                 /* the field stage is in the pipeline */
    long frame_offset;             /* prewarm: the frames this group ran before frame 0 */
    fx_clock clock;                /* its time at its frame (the effect's frame + frame_offset) */
    isk_vec2 path_base;            /* position(t) = path_base + emitter_velocity*(t - path_t) ... */
    double path_t;
    isk_vec2 path_from;            /* ... except during a live move: from path_from at path_t0 */
    double path_t0, path_t1;       /*     to the path's position at path_t1 */
    isk_vec2 carried;              /* local space: where the particles were last carried to */
    double cycle_start;            /* duration streams: the time cycle 0 begins */
    double cycle_births;           /* duration streams: accumulator births since cycle_start */
    double cycle_bursts;           /* duration streams: bursts since cycle_start */

    /* baked over-life tables (effect_render.c) */
    isk_color_gradient color_ramp;
    isk_scalar_gradient alpha_ramp, size_ramp;
    int has_color_ramp, has_alpha_ramp, has_size_ramp;

    /* looks (effect_looks.c, effect_texture.c) */
    const isk_texture *texture;    /* drawn through effect_texture.c: the emitter's texture (the
                                      effect's cache) or &streak; NULL: the usual draws */
    isk_texture streak;            /* a sprite kind as a texture (align = velocity, size_range) */
    /* ---- sub-emitters and trails: effect_events.c, effect_trail.c ---- */
    fx_events pending;             /* a SUB group's events, born at the end of the frame */
    /* ---- end of sub-emitters and trails ---- */
    int keep_prev;                 /* a gate measures it: the store keeps at least one trail point,
                                      each particle's position at the end of the last frame */
};

/* A probe's state (effect_probes.c): its latest reading and, for a gate,
 * the crossings of each of the last frames of its window. */
typedef struct fx_probe {
    isk_probe_reading r;
    uint64_t emitters;             /* bit i: it measures emitter i (ISK_EFFECT_MAX_EMITTERS is 64) */
    uint64_t *ring;                /* GATE: per frame, forward then backward crossings */
    double *ring_t;                /* GATE: per frame, its length in seconds */
    int ring_n, ring_head, ring_used;
} fx_probe;

struct isk_effect {
    isk_effect_def def;            /* deep copy, owned */
    isk_view view;
    isk_potential *pots;           /* the live potentials (force order), with ids */
    int *pot_force;                /* pots[k] is def.forces[pot_force[k]] */
    size_t npots, pots_cap;
    fx_group *groups;              /* one per emitter, definition order */
    int ngroups;
    int *draw_order;               /* group indices sorted by (order, index) */
    isk_scratch scratch;           /* for the caller's own block runs (births) */
    isk_workers workers;           /* who runs the groups' blocks and the draws' bands: its own
                                      threads or the caller's (isk_effect_set_tasks) */
    int no_rest;                   /* 1: no block rests, every stage runs (the tests' reference) */
    double update_min_work;        /* a group's update is shared out among the workers only from this
                                      much work (effect.c's FX_UPDATE_MIN_WORK; tests set 0) */
    double band_min_work;          /* a group's draw is shared out over the threads only from this much
                                      work, in batched coverage dots (FX_BAND_MIN_WORK; the tests that
                                      compare thread counts set 0, so every size is cut into bands) */
    int no_retain;                 /* tests: a group at rest is drawn in full every time (the reference
                                      for effect_retain.c's replays) */
    int split_always;              /* tests: every additive group's particles split among the threads
                                      (split_particles) wherever bands would be cut, to check both */
    isk_sinlut sin_table;
    fx_clock clock;                /* the effect's simulated time at its frame */
    double time;                   /* isk__fx_clock_at(&clock, frame), kept current */
    long frame;                    /* frames stepped since create or reset (negative while prewarming) */
    double last_frame_time;        /* potentials move by this at the next step */
    unsigned long edits;           /* changes from outside since create (isk_effect_edits): sets,
                                      potentials added or removed, clicks, births by hand, moves */
    isk_sprite_cache *sprites;
    fx_bins bins;
    isk_texture_cache *textures;   /* made at the first emitter with a texture (effect_looks.c) */
    fx_probe *probes;              /* one per def.probes (NULL without probes: nothing is measured) */
};

/* effect_live.c: the group of "emitter NAME" (messages start with fn);
 * ISK_ERR_NULL, ISK_ERR_RANGE (no such emitter, another section). */
isk_status isk__fx_emitter_of(isk_effect *e, const char *fn, const char *section, fx_group **g, isk_error *err);

/* effect.c: an effect of def, checked, its groups compiled, nothing born,
 * no threads started (a snapshot's restore builds one); and e taking
 * bare's state but keeping its own workers and test knobs, bare left with
 * e's old state to destroy (the lists are compiled again: ISK_ERR_NOMEM). */
isk_status isk__fx_create_bare(isk_effect **out, const isk_effect_def *def, isk_error *err);
isk_status isk__fx_take_state(isk_effect *e, isk_effect *bare);
/* effect_frame.c: the click action at (x, y) as part of the run (a click
 * at the start); isk_effect_click is the same from outside, an edit. */
isk_status isk__fx_click(isk_effect *e, double x, double y);

/* effect_check.c: validates a whole definition; messages name the item. */
isk_status isk__fx_check(const isk_effect_def *d, isk_error *err);

/* effect_def.c */
isk_status isk__fx_def_copy(isk_effect_def *dst, const isk_effect_def *src);
/* pot.P from the force's exponent and law. */
void isk__fx_force_sync(isk_force_def *f);
/* What one emitter's pool takes at its fullest (SIZE_MAX: more than can be);
 * keep_prev: the definition has a gate probe (one trail point at least). */
size_t isk__fx_emitter_memory(const isk_emitter_def *e, int keep_prev);
/* The emitter's particles sway (they need the store's oscillation columns). */
int isk__fx_emitter_oscillates(const isk_emitter_def *em);

/* effect_def_textures.c: the definition's textures (isk_effect_def.textures),
 * checked, copied (dst's arrays are set: free with isk_effect_def_free
 * even on ISK_ERR_NOMEM), freed. */
isk_status isk__fx_def_textures_check(const isk_effect_def *d, char *why, size_t n);
isk_status isk__fx_def_textures_copy(isk_effect_def *dst, const isk_effect_def *src);
void isk__fx_def_textures_free(isk_effect_def *d);

/* effect.c */
void isk__fx_sort_draw_order(isk_effect *e);

/* effect_frame.c: every clock at frame 0 of a frame of `step` seconds;
 * the frames before frame 0 that the prewarmed emitters ask for, run on
 * the built effect. */
void isk__fx_start_clocks(isk_effect *e, double step);
isk_status isk__fx_prewarm(isk_effect *e);

/* effect_compile.c: (re)builds the group's lists from the definition and the
 * effect's live potentials; ISK_ERR_FULL if a list overflowed (a bug),
 * ISK_ERR_NOMEM if the group's segments could not grow. */
isk_status isk__fx_compile(isk_effect *e, fx_group *g);
isk_status isk__fx_compile_all(isk_effect *e);
void isk__fx_describe_group(const isk_effect *e, const fx_group *g, FILE *out);

/* effect_group.c */
uint64_t isk__fx_group_seed(uint64_t seed, int index);
/* Seeds a group's main stream and its attribute streams from the scene's
 * seed and the group's index. */
void isk__fx_seed_streams(fx_group *g, uint64_t seed);
/* effect_adopt.c: new particles [from, count) take the emitter's lifetime,
 * then their oscillation state: every source's particles go through here. */
void isk__fx_adopt(isk_effect *e, fx_group *g, size_t from);
isk_status isk__fx_fire_explosion(isk_effect *e, fx_group *g, isk_explosion kind, double cx, double cy, size_t count,
                             isk_kick_target kick);
extern const fx_step_kind isk__fx_step_release;    /* frame start: timed and scheduled explosions */
extern const fx_step_kind isk__fx_step_late_walls; /* frame start: draw_before_bounce's walls */
extern const fx_step_kind isk__fx_step_cull;       /* substep end: age >= life */

/* effect_stream.c */
void isk__fx_stream_reset(fx_group *g, double time);
extern const fx_step_kind isk__fx_step_spawn;      /* substep end: births in (t0, t0 + h] */
extern const fx_step_kind isk__fx_step_carry;      /* substep end, before spawn: local space */
/* effect_clock.c: the group's clock at the current frame: the effect's
 * time, plus the frames a prewarm ran before frame 0. */
double isk__fx_group_time(const isk_effect *e, const fx_group *g);
/* The group's clock has started: its emitter is prewarmed at least as far
 * back as the effect's frame (always true from frame 0 on). */
int isk__fx_group_started(const isk_effect *e, const fx_group *g);
/* The group steps this frame: it has started and is not paused (a paused
 * group is neither moved, aged, born into, nor its trails recorded). */
int isk__fx_group_runs(const isk_effect *e, const fx_group *g);
/* Where the emitter is at time t (its path; em: its definition, which may
 * be an older copy than g->def during a live change). */
isk_vec2 isk__fx_emitter_pos(const fx_group *g, const isk_emitter_def *em, double t);
/* Sets the field stage's clock to time t (and the emitter's position then). */
void isk__fx_field_clock(fx_group *g, double t);
/* A live change of the emitter's position or velocity (old: the
 * definition before it): the path continues from where the emitter is
 * now; a new position is reached over the next frame, the births of that
 * frame spread along the way. */
void isk__fx_path_changed(isk_effect *e, fx_group *g, const isk_emitter_def *old, const char *key);
/* A live rate of a stream with a duration: the births of its cycles are
 * counted anew at the new rate, those due by now done (no catch-up burst). */
void isk__fx_stream_rate_changed(isk_effect *e, fx_group *g);
/* n births now (isk_effect_emit), at the emitter's place and with its
 * launch, age 0; those beyond the pool's room dropped and counted. */
isk_status isk__fx_stream_emit(isk_effect *e, fx_group *g, size_t n);
/* A stream starts again (active or unpaused): what fell due while it was
 * stopped is skipped, the next birth one interval from now (no catch-up). */
void isk__fx_stream_resume(isk_effect *e, fx_group *g);
/* The whole frames a prewarm runs (a double: it may be beyond any count). */
double isk__fx_prewarm_frames(const isk_effect_def *d, const isk_emitter_def *em);
/* Every emitter's prewarm in frames (frames[i] for emitter i): a stream's
 * own, and a sub-emitter's the largest of the emitters whose on_death or
 * on_hit reach it, directly or through a chain, so its children live on
 * the clock of the particles they came from. */
void isk__fx_prewarm_offsets(const isk_effect_def *d, double *frames);

/* effect_render.c */
isk_status isk__fx_render(isk_effect *e, isk_canvas *c);

/* effect_draws.c: the draw kinds, one row each (the meaning of every field
 * is written there, above the rows).  The band scheduler reads a group's
 * row and nothing else. */
enum { FX_MAY_BANDS = 1, FX_MAY_SORT = 2, FX_MAY_COLUMNS = 4, FX_MAY_SPLIT = 8, FX_MAY_RETAIN = 16 };
struct fx_draw_kind {
    const char *name;
    fx_draw_fn draw;                                                 /* one band of the group */
    isk_status (*prepare)(isk_effect *e, fx_group *g, fx_band *whole); /* before the bands, or NULL */
    double cost;                                                     /* a particle, in batched coverage dots */
    int reach;                                                       /* FX_MAY_SORT: rows beyond its own */
    unsigned may;                                                    /* FX_MAY_*: 0, drawn whole on the caller */
    double (*pixels)(const isk_effect *e, const fx_group *g);        /* the most a particle's draw touches, a unit (NULL: the canvas) */
};
extern const fx_draw_kind isk__fx_kind_dots, isk__fx_kind_browser_dots, isk__fx_kind_pixels, isk__fx_kind_styled_dots,
    isk__fx_kind_styled_pixels, isk__fx_kind_discs, isk__fx_kind_sprites, isk__fx_kind_textures, isk__fx_kind_nothing;
const fx_draw_kind *isk__fx_choose_draw(const fx_group *g);
extern const fx_draw_kind isk__fx_kind_trails; /* effect_trail.c: units are a trail's points */

/* effect_footprints.c: the pixels a particle's draw may touch, for the
 * draw kinds' rows (a coverage dot, a single pixel, a disc or sprite, a
 * texture, nothing, a trail's segment). */
double isk__fx_px_dot(const isk_effect *e, const fx_group *g);
double isk__fx_px_pixel(const isk_effect *e, const fx_group *g);
double isk__fx_px_round(const isk_effect *e, const fx_group *g);
double isk__fx_px_texture(const isk_effect *e, const fx_group *g);
double isk__fx_px_none(const isk_effect *e, const fx_group *g);
double isk__fx_px_trail(const isk_effect *e, const fx_group *g);
/* effect_budget.c: whether the definition could need more memory than
 * max_memory (1, with the message in msg); whether a frame and the prewarm
 * fit max_work (the groups compiled, nothing born). */
int isk__fx_memory_over(const isk_effect_def *d, char *msg, size_t n);
isk_status isk__fx_work_fits(const isk_effect *e, isk_error *err);

/* effect_bands.c: kind k's draw of g over the canvas, in bands on the
 * effect's workers when its row allows and the draw is worth it (whole:
 * the band of the canvas, with anything the kind prepared; units: the
 * kind's cost is per particle times this, a trail's points; fill: NULL, or
 * a colour the canvas is filled with first, each band filling its own
 * pixels on its own thread, so they start in its caches). */
isk_status isk__fx_draw_bands(isk_effect *e, isk_canvas *c, fx_group *g, const fx_draw_kind *k, const fx_band *whole,
                         double units, const isk_color *fill);
/* The band of g's whole draw: every row and column of c, every particle. */
fx_band isk__fx_band_whole(const isk_canvas *c, const fx_group *g);
/* The nb bands' cuts of the canvas for g's draw, at the quantiles of a
 * sample of its particles' screen rows (or columns, when `columns` allows
 * them and the rows cannot share the particles): cut[0] = 0 <= ... <=
 * cut[nb] = the canvas's height (or width); returns 1 for columns, 0 for
 * rows.  The cuts only share out the work: any cuts give the same bytes;
 * they depend on the particles alone, so they are the same on every run. */
int isk__fx_place_cuts(const isk_effect *e, const fx_group *g, const isk_canvas *c, int nb, int columns, int *cut);
/* Below this much work a group's draw runs on the caller alone, in batched
 * coverage dots (docs/performance.md, "When a draw is shared out"). */
#define FX_BAND_MIN_WORK 50000.0
/* Below this much work, in drifts of a particle (isk_stage_kind.cost), a
 * group's update runs on the caller alone: waking the workers would cost
 * more than they save (docs/performance.md, "When an update is shared
 * out"). */
#define FX_UPDATE_MIN_WORK 150000.0
void isk__fx_bins_free(fx_bins *b);
isk_status isk__fx_bake_ramps(fx_group *g, isk_error *err);
void isk__fx_free_ramps(fx_group *g);
/* A particle's colour and size: effect_style.h. */

/* effect_looks.c: rotation, spin, size and colour variation, textures. */
/* The optional store columns the emitter's looks need (ISK_PARTICLES_*). */
unsigned isk__fx_looks_columns(const isk_emitter_def *em);

/* effect_ranges.c: the per-particle ranges of the motion (radial_accel_range,
 * tangential_accel_range, wind_range, slowing_range).  The store columns
 * they need (ISK_PARTICLES_*); the draws of new particles [from, count)
 * (after the looks', each range from its own stream); the columns a live
 * change asks for. */
unsigned isk__fx_ranges_columns(const isk_emitter_def *em);
void isk__fx_ranges_adopt(fx_group *g, size_t from);
isk_status isk__fx_ranges_live(fx_group *g);
/* The emitter's particles turn by themselves (spin or spin_range): the spin stage. */
int isk__fx_looks_spins(const isk_emitter_def *em);
/* How much the angular speed changes over the life (spin_end - spin; 0
 * without spin_end). */
double isk__fx_looks_spin_change(const isk_emitter_def *em);
/* New particles [from, count): angle, spin, size, colour (after every other
 * draw of their birth; a draw only where a range or color_pick asks). */
void isk__fx_looks_adopt(fx_group *g, size_t from);
/* The emitter's texture made from the definition's pixels (through the
 * effect's cache) or its streak baked, so the draw can choose
 * effect_texture.c; messages name the texture.  No file is read. */
isk_status isk__fx_looks_prepare(isk_effect *e, fx_group *g, isk_error *err);
void isk__fx_looks_free(fx_group *g);
/* After a live change: the streak a sprite kind is drawn through, made or
 * unmade as the definition now says (from the definition alone, so it is
 * redone from the old one when the change is refused)... */
isk_status isk__fx_looks_streak(fx_group *g);
/* ... and, once the change is accepted, the columns its looks now need
 * (the particles there get the emitter's size and colour). */
isk_status isk__fx_looks_columns_live(fx_group *g);
/* What spans the looks' keys: NULL, or the key at fault with why. */
const char *isk__fx_looks_check(const isk_emitter_def *em, char *why, size_t n);
void isk__fx_looks_describe(const fx_group *g, FILE *out);
/* effect_texture.c: the draw of textured particles and streaks. */
isk_status isk__fx_draw_textures(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b);

/* ---- sub-emitters and trails ---------------------------------------
 * effect_stream.c: a stream's launcher and one birth, shared with the
 * sub-emitters' births (effect_events.c).  dv (NULL: none) is added to the
 * launch velocity before anything else reads it. */
typedef struct fx_launcher {
    isk_shape shape;
    isk_velgen launch;
    int moving;    /* the shape's centre follows the emitter's path */
    double place;  /* local space: every birth is placed at this time (the step's end); else NAN */
    double t1;     /* the step's end */
} fx_launcher;
/* The emitter's shape and launch, not moving (a sub-emitter's, or a stream's
 * before run_spawn sets its path). */
fx_launcher isk__fx_launcher_of(const isk_emitter_def *em);
/* tb: the birth's time (the field's clock and a moving emitter's place). */
isk_status isk__fx_birth(isk_effect *e, fx_group *g, const fx_launcher *l, double age, double tb, const double *dv);

/* effect_events.c */
/* The optional columns the emitter's keys call for (hit with on_hit, the
 * trail with trail > 0), added to or taken from the group's store. */
isk_status isk__fx_events_columns(fx_group *g);
void isk__fx_events_free(fx_group *g);
/* The cull's deaths as events of the group's on_death emitter, in index
 * order, at time t (the end of the substep). */
isk_status isk__fx_events_deaths(isk_effect *e, fx_group *g, double t);
/* Every SUB group's waiting events born, in group then event order (the
 * end of a frame, after every group stepped). */
isk_status isk__fx_events_release(isk_effect *e);
extern const fx_step_kind isk__fx_step_hits;       /* substep end: the bounces counted in hit as events */

/* effect_trail.c */
/* After frame `stepped`: each trailed group that stepped in it (a group
 * not yet started by a prewarm did not) takes its positions as its newest
 * points. */
void isk__fx_trail_record(isk_effect *e, long stepped);
/* The group's trails, drawn before its particles (in bands on the threads);
 * fill as isk__fx_draw_bands'. */
isk_status isk__fx_trail_render(isk_effect *e, isk_canvas *c, fx_group *g, const isk_color *fill);
/* ---- end of sub-emitters and trails ---- */

/* effect_probes.c: whether a gate measures the emitter (its store then
 * keeps its particles' last positions, fx_group.keep_prev); the probes'
 * state made or cleared to zero (create and reset); their measure after
 * frame `stepped`; their drawing; freed. */
int isk__fx_probes_need_prev(const isk_effect_def *d, int emitter);
isk_status isk__fx_probes_reset(isk_effect *e);
void isk__fx_probes_measure(isk_effect *e, long stepped);
void isk__fx_probes_render(isk_effect *e, isk_canvas *c);
void isk__fx_probes_describe(const isk_effect *e, FILE *out);
void isk__fx_probes_free(isk_effect *e);

/* effect_retain.c: a group at rest drawn from its recorded blends.
 *   rt = isk__fx_retain_begin(e, c, g, threads)  NULL: draw as usual; else
 *        rt->nb > 0: replay rt's bands (isk__fx_retain_replay each);
 *        rt->nb == 0: record this draw (isk__fx_retain_record each band, no
 *        split), then isk__fx_retain_end with its bands.
 * What is recorded is valid while every block of the group rests and its
 * isk_rest.changes, its count, the view, the canvas's size, the dot rule
 * and the thread count stay the same. */
fx_retained *isk__fx_retain_begin(isk_effect *e, const isk_canvas *c, fx_group *g, int threads);
isk_status isk__fx_retain_record(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b);
isk_status isk__fx_retain_replay(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b);
void isk__fx_retain_end(fx_retained *rt, const fx_band *band, int nb, int columns);
void isk__fx_retain_clear(fx_retained *rt); /* frees the records; keeps the counters */
/* effect_render.c: the batched dots' rule for g (ISK__BATCH_*, keep-on-canvas or-ed in). */
unsigned isk__fx_dots_rule(const fx_group *g);

/* A stream's interval between bursts as the schedule uses it: 0 (a single
 * burst), or burst_every read as at least ISK_BURST_EVERY_MIN, so that a
 * time over it is a finite count. */
static inline double isk__fx_burst_every(const isk_emitter_def *em)
{
    const double every = em->born.burst_every;
    return every > 0 && every < ISK_BURST_EVERY_MIN ? ISK_BURST_EVERY_MIN : every;
}

#endif
