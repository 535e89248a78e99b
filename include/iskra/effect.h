/* SPDX-License-Identifier: MIT */
/* iskra/effect.h — a whole particle effect: named forces, deflectors, walls
 * and emitters, compiled into one list of stages per emitter, stepped and
 * drawn frame by frame, and changeable while it runs.
 *
 * This is what a scene file becomes (iskra/scene.h parses INI into an
 * isk_effect_def) and what C programs can fill directly.  The definition is
 * plain data whose every field is a row of the key table (iskra/keys.h:
 * type, range, default, meaning); isk_effect_def_init and the add functions
 * set the table's defaults, and isk_effect_create validates every field
 * against the same rows, with the parser's messages, then compiles:
 *
 * Example:
 *
 *     isk_effect_def d;
 *     isk_effect_def_init(&d);                  // defaults: 600x600, view -10..10, dt 1/60
 *     int g = isk_effect_def_add_force(&d, "gravity", ISK_FORCE_GRAVITY);
 *     isk_emitter_def *e = isk_effect_def_add_emitter(&d, "sparks");
 *     if (g < 0 || !e) { isk_effect_def_free(&d); return 1; }   // out of memory
 *     d.forces[g].g = 9.81;
 *     e->born.source = ISK_SOURCE_EXPLOSION;    // the parts: born, launch, life, motion, look, events
 *     e->born.explosion = ISK_EXPLOSION_GAUSS;
 *     e->born.count = 1000;
 *     isk_emitter_use_force(e, g);
 *     isk_effect *fx;  isk_error err;
 *     isk_status s = isk_effect_create(&fx, &d, &err);
 *     isk_effect_def_free(&d);                  // the effect keeps its own copy
 *     if (s != ISK_OK) { fprintf(stderr, "%s\n", err.message); return 1; }
 *     isk_canvas canvas;
 *     s = isk_canvas_init(&canvas, 600, 600);    // the definition's width x height
 *     for (int i = 0; i < 100 && s == ISK_OK; i++) s = isk_effect_step(fx);
 *     if (s == ISK_OK) s = isk_effect_render(fx, &canvas);
 *     isk_canvas_free(&canvas);
 *     isk_effect_destroy(fx);
 *     return s != ISK_OK;
 *
 * Only the effects a scene calls for are simulated.  Each emitter's stage list
 * holds exactly what that emitter needs, in this order:
 *     frame start: walls of draw_before_bounce, timed explosions;
 *     every substep: field (radial/tangential accelerations, turbulence) ->
 *     remember the start state (deflectors, or sound walls with potentials:
 *     kept by the integrator's own pass when it has one) -> forces it
 *     references + integrator (blocked) -> slowing -> oscillation -> walls -> deflectors ->
 *     spin (only where an angle is seen and spins) -> ageing; then the
 *     local-space carry -> hits (on_hit) -> culling (its deaths first as
 *     on_death events) -> births (streams: after the cull, so a full pool
 *     reads isk_effect_particle_count == capacity); after every emitter stepped: the
 *     sub-emitters' births, the probes' measures (only with probes,
 *     iskra/probes.h), then the trails' newest points
 * and its draw routine: trails (only with trail) -> colour/alpha/size over
 * life (only with gradients) -> draw (a texture or a streak: the look
 * part of isk_emitter_def).  A force no emitter references, a
 * zero-strength force, a disabled
 * potential, or a potential switched off by its maximum distance is not in
 * any list (the last leaves at the end of the frame in which it switched
 * off), so it costs nothing and changes nothing.  isk_effect_describe()
 * prints the lists.
 *
 * Determinism: every emitter owns an isk_rng seeded from (seed, emitter
 * index), so adding a force or an unrelated emitter after it never changes
 * its particles.  Same definition + same steps = byte-identical canvas.
 */
#ifndef ISKRA_EFFECT_H
#define ISKRA_EFFECT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "iskra/blend.h"
#include "iskra/bounds.h"
#include "iskra/canvas.h"
#include "iskra/deflector.h"
#include "iskra/explode.h"
#include "iskra/forces.h"
#include "iskra/gradient.h"
#include "iskra/integrate.h"
#include "iskra/shape.h"
#include "iskra/sinlut.h"
#include "iskra/sprite.h"
#include "iskra/status.h"
#include "iskra/tasks.h"
#include "iskra/vec2.h"
#include "iskra/view.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ISK_NAME_MAX 32
#define ISK_EFFECT_MAX_FORCES 64
#define ISK_EFFECT_MAX_DEFLECTORS 256
#define ISK_EFFECT_MAX_EMITTERS 64
#define ISK_EFFECT_MAX_DRAWINGS 64
#define ISK_EFFECT_MAX_TEXTURES 64
#define ISK_EFFECT_MAX_PROBES 16
/* Per emitter: the store's own bound (2^28); what memory allows is the
 * memory budget's to say (max_memory, isk_effect_def_memory). */
#define ISK_EFFECT_MAX_PARTICLES 268435456u
/* The memory an effect may need at its fullest unless isk_effect_def.max_memory says
 * otherwise: the smaller of 4 GiB and half the address space, so 4 GiB
 * where size_t has 64 bits and 2 GiB where it has 32 (a 32-bit program has
 * at most 4 GiB of addresses, shared by its code, stacks and canvases).
 * Computed in uintmax_t: (size_t)4 << 30 would be 0 with a 32-bit size_t. */
#define ISK_EFFECT_MAX_MEMORY_CEILING ((uintmax_t)4 << 30)
#define ISK_EFFECT_DEFAULT_MAX_MEMORY                                                            \
    ((size_t)((uintmax_t)SIZE_MAX / 2 + 1 < ISK_EFFECT_MAX_MEMORY_CEILING ? (uintmax_t)SIZE_MAX / 2 + 1 \
                                                                          : ISK_EFFECT_MAX_MEMORY_CEILING))

/* The work a frame or a prewarm may ask for unless isk_effect_def.max_work
 * says otherwise: about a few seconds of one core. */
#define ISK_EFFECT_DEFAULT_MAX_WORK 1e9

/* ---- forces ------------------------------------------------------------ */

typedef enum isk_force_kind {
    ISK_FORCE_GRAVITY = 0, /* F = (0, m*(-g*gravity_multiplier))   (thesis SilaTeza) */
    ISK_FORCE_DRAG,        /* F = -b*v                          (thesis Otpor) */
    ISK_FORCE_WIND,        /* a constant acceleration: F = m*accel (fire thesis's wind) */
    ISK_FORCE_POTENTIAL,   /* the thesis's Coulomb potential (iskra/forces.h) */
    ISK_FORCE_TURBULENCE,  /* a divergence-free noise field: an acceleration, whatever the mass */
    ISK_FORCE_KIND_COUNT
} isk_force_kind;

typedef struct isk_force_def {
    char name[ISK_NAME_MAX];
    isk_force_kind kind;
    double g;              /* GRAVITY: g >= 0 */
    double b;              /* DRAG: b >= 0 */
    isk_vec2 accel;        /* WIND */
    isk_potential pot;     /* POTENTIAL (id assigned at create: 1, 2, ... in list order);
                              pot.P is derived from exponent and law at create */
    double exponent;       /* POTENTIAL: the distance exponent as written (default 2) */
    isk_coulomb_law law;   /* POTENTIAL: how exponent reads: the code's P or the text's p */
    int draw;              /* POTENTIAL: draw as a disc of radius 0.1 with its id while on */
    int line;              /* where it was defined (scene files), 0 if unknown */

    /* turbulence: a = strength * curl psi, psi a smooth
     * gradient noise psi(x/scale, y/scale, speed*t) seeded from the scene's
     * seed and the force's index.  The curl is taken in the noise's own
     * coordinates (x/scale), so |a| is of the order of strength at any
     * scale, and the field has no divergence: it stirs, never gathers. */
    double strength;       /* TURBULENCE: units/s^2 (0: not in any list) */
    double scale;          /* TURBULENCE: the feature size in world units (> 0) */
    double speed;          /* TURBULENCE: how fast the pattern evolves (noise units per second) */
} isk_force_def;

/* ---- deflectors --------------------------------------------------------- */

typedef struct isk_deflector_def {
    char name[ISK_NAME_MAX];
    int line;
    isk_deflector seg;     /* the segment and how particles react (iskra/deflector.h) */
    int show;              /* 1: drawn after the drawings, before the particles, as a
                              1-px line from the segment as it is at each render */
    isk_color color;       /* of the line shown (default white) */
} isk_deflector_def;

/* ---- emitters ---------------------------------------------------------- */

typedef enum isk_source_kind {
    ISK_SOURCE_PARTICLE = 0, /* one particle: position, velocity, mass (figures 9-14) */
    ISK_SOURCE_EXPLOSION,    /* an isk_explosion of `count` at `position` at time `start` */
    ISK_SOURCE_LAYER,        /* the stationary layer: `count` at rest in `rect` */
    ISK_SOURCE_STREAM,       /* continuous emission: shape, velocity, rate, bursts */
    ISK_SOURCE_SUB,          /* a sub-emitter: `count` particles where another emitter's particle
                                dies (on_death) or bounces (on_hit) */
    ISK_SOURCE_KIND_COUNT
} isk_source_kind;

/* Where a stream emitter places new particles is an isk_shape_kind around
 * `position` (iskra/shape.h: point; disc of radius a; circle of radius a;
 * ring a <= r <= b; segment from position to position + (a, b); rect of
 * half-extents a, b; ellipse of semi-axes a, b), and how it launches them
 * an isk_velgen_kind (constant `velocity`; disc of radius speed_max around
 * `velocity`; direction `angle` with a speed in [speed_min, speed_max];
 * cone angle +- spread/2). */

typedef enum isk_rate_mode {
    ISK_RATE_ACCUMULATE = 0, /* fractional carry: exactly rate*t particles over time t */
    ISK_RATE_THESIS,         /* fire thesis: (unsigned)(dt*rate + 0.5) per frame, no carry */
    ISK_RATE_MODE_COUNT
} isk_rate_mode;

typedef enum isk_birth_mode {
    ISK_BIRTH_BACKDATE = 0,  /* born at the true time, advanced by its age (particle-engine thesis) */
    ISK_BIRTH_THESIS_JITTER, /* fire thesis: random whole-ms pre-advance, force and position only */
    ISK_BIRTH_FRAME,         /* all born at the end of the frame (shows banding) */
    ISK_BIRTH_MODE_COUNT
} isk_birth_mode;

typedef enum isk_draw_mode {
    ISK_DRAW_DOT = 0,    /* the coverage dot: 1x1 px, top-left at the point (the thesis browser) */
    ISK_DRAW_PIXEL,      /* the single pixel containing the point */
    ISK_DRAW_DISC,       /* anti-aliased disc of world radius size/2 */
    ISK_DRAW_SPRITE,     /* a baked sprite (iskra/sprite.h) of world size `size` */
    ISK_DRAW_NONE,       /* simulated, not drawn */
    ISK_DRAW_DOT_BROWSER, /* the dot by the thesis browser's rule (isk_draw_dot_browser): faithful */
    ISK_DRAW_COUNT
} isk_draw_mode;

/* How a particle's sprite is turned (isk_emitter_def.look.align). */
typedef enum isk_align_mode {
    ISK_ALIGN_NONE = 0,      /* by its angle only (rotation, spin) */
    ISK_ALIGN_VELOCITY,      /* along its velocity on screen, atan2(vy, vx), plus its angle */
    ISK_ALIGN_COUNT
} isk_align_mode;
/* Which of an emitter's particles are on top (isk_emitter_def.look.draw_order). */
typedef enum isk_draw_order {
    ISK_DRAW_ORDER_NEWEST = 0, /* the newest on top: drawn oldest first, in store order (LÖVE's "top") */
    ISK_DRAW_ORDER_OLDEST,     /* the oldest on top: drawn newest first (LÖVE's "bottom") */
    ISK_DRAW_ORDER_RANDOM,     /* a random order, shuffled again every frame (LÖVE's "random") */
    ISK_DRAW_ORDER_COUNT
} isk_draw_order;
/* align = velocity without a texture draws the sprite kind as a streak this
 * many times its size long (and its size wide). */
#define ISK_STREAK_STRETCH 4.0
/* look.spin_end's "none": the angular speed stays what it was at birth. */
#define ISK_SPIN_END_NONE INFINITY
/* The longest texture path, terminator included. */
#define ISK_TEXTURE_PATH_MAX 256

/* Over-life ramps: piecewise-linear in normalised age t = age/life, stops as
 * in iskra/gradient.h (baked once into tables at create). */
typedef struct isk_color_ramp {
    int n;                                         /* 0 = off (constant colour) */
    isk_color_stop stops[ISK_GRADIENT_MAX_STOPS];  /* t strictly increasing in [0, 1] */
} isk_color_ramp;

typedef struct isk_scalar_ramp {
    int n;                                         /* 0 = off */
    isk_scalar_stop stops[ISK_GRADIENT_MAX_STOPS];
} isk_scalar_ramp;

/* Where a stream's particles live (isk_emitter_def.born.space). */
typedef enum isk_space {
    ISK_SPACE_WORLD = 0, /* born on the emitter's path, then on their own */
    ISK_SPACE_LOCAL,     /* carried along by the emitter's motion every substep */
    ISK_SPACE_COUNT
} isk_space;

/* ---- the parts of an emitter ---------------------------------------------
 *
 * An emitter is six parts, one struct each, named for what they answer:
 * born (where, when and how many), launch (with what velocity and mass),
 * life (for how long), motion (what moves them), look (how they are drawn)
 * and events (what their deaths and bounces set off).  A field is the
 * [emitter NAME] key of the same name, less the part's name where the key
 * starts with it (`life_range` is life.range); each part's comment names
 * the fields that differ.  The key table (iskra/keys.h, `iskra keys`) gives
 * every key's type, range, default and meaning. */

/* Where and when its particles are born: the source, the place (a point,
 * a layer's rect, a stream's shape around position), how many and how
 * often, the emitter's own path and the pool they live in.  Every field is
 * the key of its name. */
typedef struct isk_emitter_born {
    isk_source_kind source;
    isk_vec2 position;         /* PARTICLE position; EXPLOSION centre; STREAM origin */
    isk_shape_kind shape;      /* STREAM, SUB */
    double shape_a, shape_b;   /* STREAM, SUB shape parameters (see isk_spawn_shape) */
    double shape_angle;        /* STREAM, SUB shape rotation, radians */
    int shape_faithful;        /* ELLIPSE: the particle-engine thesis's non-uniform sampler */
    isk_explosion explosion;   /* EXPLOSION kind */
    size_t count;              /* EXPLOSION, LAYER count (required); STREAM burst size (0: none);
                                  SUB particles per event */
    size_t limit;              /* largest accepted explosion (also clicks into this emitter;
                                  0: the thesis's 10,000) */
    isk_kick_target kick;      /* COULOMB kicks: all particles of this emitter, or only new */
    double start;              /* EXPLOSION / burst time, seconds */
    double rect[4];            /* LAYER xmin, xmax, ymin, ymax */
    double rate;               /* STREAM particles per second (0: bursts only) */
    isk_rate_mode rate_mode;
    isk_birth_mode birth;
    double burst_every;        /* STREAM: a burst of `count` every this many s (0: once at start) */
    double duration;           /* STREAM: emits for this many seconds from start, then stops (0: forever) */
    int loop;                  /* STREAM with a duration: starts again every duration, bursts included */
    double prewarm;            /* STREAM: seconds simulated before frame 0 (whole frames of dt;
                                  frame 0 shows the emitter, and the sub-emitters it feeds, as
                                  they are after them) */
    isk_vec2 emitter_velocity; /* STREAM: the emitter moves, position(t) = position + v*t, and births
                                  are placed on that path at their exact birth times */
    isk_space space;           /* STREAM: WORLD (default), or LOCAL: the particles move with the emitter */
    size_t capacity;           /* pool size, for every source: births, explosions and clicks
                                  beyond it are dropped and counted */
    int active;                /* 1 (default): births as scheduled; 0: none (a stream's births, a
                                  timed explosion, a sub-emitter's children), its particles live
                                  on; births due meanwhile are skipped, not caught up
                                  (isk_effect_set_active) */
} isk_emitter_born;

/* How a particle is launched: the velocity and mass it is born with.  kind
 * is the key `launch` (an isk_velgen_kind: constant velocity; a disc of
 * radius speed_max around velocity; direction angle with a speed in
 * [speed_min, speed_max]; cone angle +- spread/2); every other field is
 * the key of its name. */
typedef struct isk_emitter_launch {
    isk_velgen_kind kind;      /* STREAM, SUB */
    isk_vec2 velocity;         /* PARTICLE velocity; STREAM, SUB constant/disc-centre velocity */
    double angle, spread;      /* DIRECTION/CONE, radians */
    double speed_min, speed_max;
    double mass;               /* PARTICLE, LAYER, STREAM and SUB mass (min); default 1 */
    double mass_range;         /* STREAM, SUB: mass = mass + U*mass_range */
    double inherit;            /* SUB: the fraction 0..1 of the parent's velocity its children keep,
                                  added to the velocity drawn above */
    int outward;               /* STREAM, SUB (key launch_outward): the velocity drawn is turned by
                                  the direction from the shape's centre to the birth place, so
                                  angle 0 points straight outward (LÖVE's relative direction);
                                  a birth exactly on the centre is not turned */
} isk_emitter_launch;

/* How long a particle lives: lifetime = seconds + U*range.  seconds is the
 * key `life`, range the key `life_range`. */
typedef struct isk_emitter_life {
    double seconds;            /* INFINITY (default) = immortal */
    double range;
} isk_emitter_life;

/* What moves its particles once born: the forces and deflectors they feel,
 * the walls, accelerations about the emitter, buoyancy, slowing, the
 * oscillation and the integrator.  Each is a stage only for the emitters
 * that use it (isk_effect_describe shows it).  Fields are the keys of their
 * names, except: forces/nforces and deflectors/ndeflectors are the lists
 * the keys `forces` and `deflectors` name, and the two-number keys
 * osc_omega and osc_amplitude are each a _min and a _max field. */
typedef struct isk_emitter_motion {
    int forces[ISK_EFFECT_MAX_FORCES]; /* indices into isk_effect_def.forces */
    int nforces;
    int deflectors[ISK_EFFECT_MAX_DEFLECTORS]; /* indices into isk_effect_def.deflectors */
    int ndeflectors;
    int bounded;               /* 1: the effect's walls apply */
    int draw_before_bounce;    /* 1: the thesis examples' order (draw, then walls) */
    double gravity_multiplier; /* scales GRAVITY forces (default 1) */
    double weight;             /* buoyancy: an upward acceleration (fire thesis's weight) */
    double slowing;            /* damping per second: v *= max(0, 1 - slowing*dt) (never flips) */
    int slow_faithful;         /* 1: the fire thesis's order v += a*dt; v *= slow; p += v*dt (the
                                  slowed velocity moves the particle; drifts at a(1-k*dt)/k).
                                  0 (default): p moves with the unslowed velocity, slowing after,
                                  which drifts at exactly a/k at any dt.  Needs the semi-implicit
                                  Euler fast path (no drag or potential forces) */
    double radial_accel;       /* units/s^2 away from the emitter's current position (negative:
                                  towards it); none exactly at the position */
    double tangential_accel;   /* units/s^2 perpendicular to that, counter-clockwise for positive */
    /* Per-particle ranges: each particle adds its own U*range, drawn at its birth from a
     * random stream of its own, to the value above (0: none; no column, no draw). */
    double radial_accel_range;     /* radial = radial_accel + U*radial_accel_range */
    double tangential_accel_range; /* tangential = tangential_accel + U*tangential_accel_range */
    isk_vec2 wind_range;           /* its own constant acceleration (U1*x, U2*y), units/s^2 (LÖVE's
                                      linear acceleration between a wind force's and that plus this) */
    double slowing_range;          /* slowing = slowing + U*slowing_range (not with slow_faithful) */
    double osc_omega_min, osc_omega_max;         /* oscillation angular speed range, rad/s (0,0 = off) */
    double osc_amplitude_min, osc_amplitude_max; /* initial amplitude range, world units */
    double osc_decay;          /* amplitude *= max(0, 1 - decay*dt) */
    int osc_faithful;          /* 1: also add the offset change to vx (the thesis code) */
    isk_sinlut_mode osc_table; /* the sine: table floor (the fire thesis), round, lerp, or libm */
    int osc_random_phase;      /* 1: each particle starts at a random phase (offset preset to
                                  A*sin(phase), so no jump); 0: phase 0 (the thesis, presumably) */
    isk_integrator integrator; /* ISK_INTEGRATE_INHERIT (default): the scene's */
    int substeps;              /* 0 (default): the scene's */
    int paused;                /* 1: the emitter stands still: its particles neither move nor age,
                                  nothing is born into it (isk_effect_set_paused) */
} isk_emitter_motion;

/* How its particles are drawn: the draw mode, size and colour with their
 * variation at birth and their ramps over life, rotation and spin,
 * textures and flipbooks, the order among emitters, and trails
 * (docs/scene-format.md, "The looks of a particle").  Every field is the
 * key of its name.  At their defaults the variations cost and change
 * nothing: the angle column and the spin stage exist only with a rotation
 * or spin, each random draw only with its range (and after every other
 * draw of the birth), the size and colour columns only with size_range and
 * color_pick.  trail = N (0..ISK_TRAIL_MAX): each particle keeps its last
 * N positions (recorded once per frame, after the frame's steps) and is
 * drawn, before its own dot or sprite, as a ribbon through them
 * (isk_stroke_trail) trail_width pixels wide in the particle's colour,
 * fading by trail_fade towards its oldest point. */
typedef struct isk_emitter_look {
    isk_draw_mode draw;
    isk_sprite_kind sprite;
    double size;               /* DISC/SPRITE diameter in world units */
    double size_range;         /* size = size + U*size_range, world units (the size column) */
    isk_color color;           /* default yellow */
    isk_color_ramp color_pick; /* n > 0: base colour = these stops at a uniform t at birth, multiplied
                                  channel by channel by color_over_life (div255(a*b)) */
    isk_blend blend;           /* default over */
    isk_color_ramp color_over_life;
    isk_scalar_ramp alpha_over_life;  /* multiplies colour alpha */
    isk_scalar_ramp size_over_life;   /* multiplies size */
    int order;                 /* draw order key (ties: definition order) */
    isk_draw_order draw_order; /* which of its particles are on top (default the newest); oldest and
                                  random draw the emitter whole on the calling thread */
    double rotation, rotation_range; /* initial angle + U*range, radians (keys in degrees),
                                        counter-clockwise in the world */
    double spin, spin_range;   /* angular speed + U*range, rad/s (keys in deg/s); angles wrap into
                                  [-pi, pi) */
    double spin_end;           /* ISK_SPIN_END_NONE (default): the angular speed stays; else it
                                  changes linearly over the life by spin_end - spin, so a particle
                                  without spin_range ends its life turning at spin_end (LÖVE's
                                  setSpin(start, end)); immortal particles keep their start */
    isk_align_mode align;      /* VELOCITY: turned along the velocity (textures, and sprites as
                                  streaks ISK_STREAK_STRETCH times longer than wide) */
    char texture[ISK_TEXTURE_PATH_MAX]; /* "": none; else the name of the definition's texture drawn
                                  as the sprite (isk_effect_def.textures): a scene's PNG path, made
                                  relative to the scene file and read by the loader */
    isk_vec2 texture_grid;     /* cols, rows of a sprite sheet (whole numbers 1..256; default 1, 1) */
    double texture_fps;        /* 0: the frames play once over the life, floor(t*frames); > 0: at this
                                  rate of age, wrapping */
    int flipbook_random_start; /* 1: each particle's flipbook starts at a frame drawn at birth and
                                  plays on from it, wrapping (Godot's anim_offset) */
    isk_vec2 texture_origin;   /* the point of the frame (fractions of its width and height from its
                                  top-left corner) placed on the particle and turned about: 0.5, 0.5
                                  (default) its centre (LÖVE's setOffset, in fractions) */
    int trail;                 /* points of history, 0: no trail */
    double trail_width;        /* pixels, > 0 (default 1) */
    double trail_fade;         /* 0..1: alpha at the oldest point is colour alpha * (1 - trail_fade) */
} isk_emitter_look;

/* What its particles' deaths and bounces set off: on_death / on_hit name
 * (by index, -1: none) an emitter of source SUB that fires `count`
 * particles where one of these particles dies (its age reaches its life,
 * or a killing deflector takes it) / bounces on a wall or a deflector.
 * The event is the particle's position and velocity at the end of the
 * substep in which it died / bounced, at that substep's end time.  A SUB
 * emitter's children start at the event's position plus its shape's
 * offset (born.shape, shape_a, shape_b, shape_angle around (0, 0)), with a
 * velocity from its launch part plus launch.inherit times the parent's
 * velocity, and its life and look; they are born at the end of the frame
 * in which the event happened, advanced by their age through their own
 * stages (as a stream's back-dated births), so the result does not depend
 * on which of the two emitters steps first.  Both fields are the keys of
 * their names. */
typedef struct isk_emitter_events {
    int on_death;              /* emitter index of a SUB emitter, -1: none */
    int on_hit;                /* emitter index of a SUB emitter, -1: none */
} isk_emitter_events;

/* One [emitter NAME]: its name, where it was defined, the preset it
 * started from, and its six parts.  isk_effect_def_add_emitter sets every
 * field to its key's default; set the ones you need through the parts:
 *
 *     isk_emitter_def *e = isk_effect_def_add_emitter(&d, "fountain");
 *     if (!e) { isk_effect_def_free(&d); return 1; }  // out of memory
 *     e->born.source = ISK_SOURCE_STREAM;
 *     e->born.rate = 200;                          // key `rate`
 *     e->launch.kind = ISK_VELGEN_CONE;            // key `launch`
 *     e->launch.angle = 1.5708;                    // radians: straight up
 *     e->launch.spread = 0.5;
 *     e->launch.speed_min = 4;
 *     e->launch.speed_max = 6;
 *     e->life.seconds = 2;                         // key `life`
 *     e->life.range = 0.5;                         // key `life_range`
 *     e->look.color = isk_rgba(80, 160, 255, 255);
 *     isk_emitter_use_force(e, g);                 // g: a force's index (motion.forces)
 *
 * docs/versioning.md lists each old flat field (before 0.3.0) with its
 * place now. */
typedef struct isk_emitter_def {
    char name[ISK_NAME_MAX];
    int line;                  /* where it was defined (scene files), 0 if unknown */
    char preset[ISK_NAME_MAX]; /* the preset (iskra/presets.h) that filled it, "" for none; set by
                                  isk_preset_apply (scene files: `preset = NAME`); only a record:
                                  the parts hold what the preset set */
    isk_emitter_born born;
    isk_emitter_launch launch;
    isk_emitter_life life;
    isk_emitter_motion motion;
    isk_emitter_look look;
    isk_emitter_events events;
} isk_emitter_def;

/* An image the emitters draw as their particles' texture, held by the
 * definition under the name their `texture` key gives.  Creating an effect
 * makes each emitter's texture from these pixels, so it opens no file: the
 * scene loader reads the PNGs a scene names (iskra/scene.h,
 * isk_scene_load_textures for a definition filled in C), or a program
 * gives pixels with isk_effect_def_add_texture. */
typedef struct isk_texture_image {
    char name[ISK_TEXTURE_PATH_MAX]; /* what an emitter's `texture` names (a scene's: the resolved path) */
    isk_canvas pixels;               /* straight RGBA, owned by the definition (isk_effect_def_free) */
} isk_texture_image;

/* Static drawings (the triangles of figures 1-8, labels): drawn each frame
 * before the particles. */
typedef enum isk_drawing_kind {
    ISK_DRAWING_POLYLINE = 0, /* anti-aliased width-1 path through `points` */
    ISK_DRAWING_DISC,         /* anti-aliased disc at (x, y), radius r */
    ISK_DRAWING_TEXT,         /* bitmap-font text, baseline-left at (x, y) */
    ISK_DRAWING_POLYGON,      /* filled convex polygon (a fan of isk_fill_triangle) */
    ISK_DRAWING_SPRITE,       /* a sprite of kind `sprite`, diameter `size`, centred at (x, y) */
    ISK_DRAWING_KIND_COUNT
} isk_drawing_kind;

typedef struct isk_drawing_def {
    char name[ISK_NAME_MAX];
    int line;
    isk_drawing_kind kind;
    int pixels;                /* 1: coordinates are canvas pixels, not world units */
    double *points;            /* POLYLINE: x0,y0,x1,y1,... (owned) */
    int npoints;
    int closed;
    double x, y, r;            /* DISC centre and radius; TEXT position */
    char text[128];
    int scale;                 /* TEXT scale */
    isk_color color;
    isk_blend blend;
    isk_sprite_kind sprite;    /* SPRITE */
    double size;               /* SPRITE diameter (world units, or pixels with `pixels`) */
    int hairline;              /* POLYLINE: the browser's hairline (isk_stroke_polyline_hairline) */
} isk_drawing_def;

/* Probes: measuring tools for lessons and tests (iskra/probes.h reads
 * them; docs/scene-format.md, "Probes").  Each is measured after every
 * frame over the particles of its emitters; a definition without probes
 * runs, draws and describes exactly as if probes did not exist. */
typedef enum isk_probe_kind {
    ISK_PROBE_GATE = 0,    /* a segment: crossings in each direction, per second over `window` */
    ISK_PROBE_REGION,      /* a rectangle: count, mean speed, kinetic energy inside */
    ISK_PROBE_HISTOGRAM,   /* of speed, angle or age: `bins` counts over `range` */
    ISK_PROBE_TOTALS,      /* the scene's momentum, kinetic and potential energy */
    ISK_PROBE_KIND_COUNT
} isk_probe_kind;

typedef enum isk_probe_of {
    ISK_PROBE_OF_SPEED = 0, /* |v|, units/s */
    ISK_PROBE_OF_ANGLE,     /* atan2(vy, vx) in degrees, -180..180 */
    ISK_PROBE_OF_AGE,       /* seconds lived */
    ISK_PROBE_OF_COUNT
} isk_probe_of;

#define ISK_PROBE_MAX_BINS 64

typedef struct isk_probe_def {
    char name[ISK_NAME_MAX];
    int line;
    isk_probe_kind kind;
    double segment[4];         /* GATE: x0, y0, x1, y1 (world); forward crossings go from the left of
                                  (x0, y0) -> (x1, y1) to its right */
    double window;             /* GATE: the rates count the crossings of the last `window` seconds */
    double rect[4];            /* REGION: xmin, xmax, ymin, ymax (world) */
    isk_probe_of of;           /* HISTOGRAM */
    int bins;                  /* HISTOGRAM: 1..ISK_PROBE_MAX_BINS */
    double range[2];           /* HISTOGRAM: lo < hi; values outside are counted as under / over */
    int show;                  /* 1 (default): drawn over the particles */
    isk_color color;           /* of its drawing */
    int emitters[ISK_EFFECT_MAX_EMITTERS]; /* the emitters it measures (indices into
                                  isk_effect_def.emitters); nemitters 0: every emitter */
    int nemitters;
} isk_probe_def;

typedef enum isk_view_def_kind { ISK_VIEWDEF_WINDOW = 0, ISK_VIEWDEF_CAMERA, ISK_VIEWDEF_COUNT } isk_view_def_kind;

/* What a click does (isk_effect_click; `iskra play` calls it for a left
 * click): an explosion at the clicked point, into one emitter's store. */
typedef struct isk_click_def {
    int enabled;               /* 1: clicks explode (a scene's [click] section sets it) */
    isk_explosion explosion;   /* default coulomb */
    size_t count;              /* default 1000 */
    int emitter;               /* the emitter whose store receives it (-1: the first) */
    int at_start;              /* 1: click once by itself at (x, y) (the thesis's simulator */
    double x, y;               /*    scenes start with a click) ... */
    long after_frames;         /* ... after this many frames (0: at create and reset) */
} isk_click_def;

/* Hints for programs that show an effect (`iskra render`, `iskra play`);
 * the effect itself never reads them. */
typedef struct isk_show_def {
    long frames;               /* the frame `iskra render` shows by default (0) */
    int start_paused;          /* 1: `iskra play` pauses after the first frame (the thesis's prviFrame) */
} isk_show_def;

/* Names as scene files spell them, indexed by value (one table per enum;
 * the parser, describe, error messages and `iskra keys` all read these). */
extern const char *const isk_force_kind_names[ISK_FORCE_KIND_COUNT];     /* gravity drag wind potential turbulence */
extern const char *const isk_space_names[ISK_SPACE_COUNT];               /* world local */
extern const char *const isk_source_names[ISK_SOURCE_KIND_COUNT];        /* particle explosion layer stream sub */
extern const char *const isk_rate_mode_names[ISK_RATE_MODE_COUNT];       /* accumulate thesis */
extern const char *const isk_birth_mode_names[ISK_BIRTH_MODE_COUNT];     /* backdate thesis-jitter frame */
extern const char *const isk_draw_mode_names[ISK_DRAW_COUNT];            /* dot pixel disc sprite none dot-browser */
extern const char *const isk_drawing_kind_names[ISK_DRAWING_KIND_COUNT]; /* polyline disc text polygon sprite */
extern const char *const isk_units_names[2];                             /* world pixels (isk_drawing_def.pixels) */
extern const char *const isk_view_kind_names[ISK_VIEWDEF_COUNT];         /* window camera */
extern const char *const isk_align_names[ISK_ALIGN_COUNT];               /* none velocity */
extern const char *const isk_probe_kind_names[ISK_PROBE_KIND_COUNT];     /* gate region histogram totals */
extern const char *const isk_probe_of_names[ISK_PROBE_OF_COUNT];         /* speed angle age */
extern const char *const isk_draw_order_names[ISK_DRAW_ORDER_COUNT];     /* newest oldest random */

typedef struct isk_effect_def {
    int width, height;         /* canvas, default 600x600 */
    isk_color background;      /* default opaque black */
    int clear;                 /* 1: clear every frame (default); 0: trails accumulate */
    isk_view_def_kind view_kind;
    double xmin, xmax, ymin, ymax;    /* WINDOW */
    double zoom, tx, ty;              /* CAMERA */
    double dt;                 /* seconds per frame (default 1/60) */
    int substeps;              /* default 1 */
    double speed_divisor;      /* the thesis slider's f (default 1) */
    isk_integrator integrator; /* default semi-implicit Euler */
    uint64_t seed;
    isk_fidelity centre;       /* behaviour exactly on a potential without min distance */
    isk_fidelity fidelity;     /* THESIS: the thesis code's arithmetic everywhere (gravity as
                                  m*(-g) then dt/m, no constant-acceleration fast path) */

    isk_force_def *forces;         int nforces;
    isk_deflector_def *deflectors; int ndeflectors;
    isk_bounds bounds;         /* sides == 0: no walls */
    isk_emitter_def *emitters;     int nemitters;
    isk_drawing_def *drawings;     int ndrawings;
    isk_probe_def *probes;         int nprobes;     /* measured after every frame (iskra/probes.h) */
    isk_texture_image *textures;   int ntextures;  /* not scene keys: the images the emitters'
                                                      `texture` names, read by the loader */
    isk_click_def click;
    isk_show_def show;
    /* Not a scene key (a file must not raise its own limit): the most memory
     * the program lets this effect take at its fullest, every emitter's pool
     * full; isk_effect_create refuses a definition that could need more.  0:
     * ISK_EFFECT_DEFAULT_MAX_MEMORY. */
    size_t max_memory;
    /* Not a scene key either (it depends on the machine, never the result):
     * the threads the effect steps on, 1..256; 0 (default): ISKRA_THREADS
     * from the environment if it is set, else every online core.  The bytes
     * are the same for every number. */
    int threads;
    /* Not a scene key either: the most work the program lets a frame, or
     * the prewarm, ask for, in particle-steps (a particle through a stage
     * of cost 1) plus pixels a draw may touch, counted at their worst
     * (every store as full as its births allow, every particle at its
     * largest; docs/scene-format.md, "Budgets").  isk_effect_create
     * refuses a definition that could need more, naming what needs it.
     * 0: ISK_EFFECT_DEFAULT_MAX_WORK. */
    double max_work;
    /* Memory the program needs beside the effect (its encoders, another
     * canvas), counted against max_memory with the effect's; 0: none.
     * host_memory_for names it in a refusal ("the GIF encoder (800 x 600
     * frames)"); empty: "the program's own". */
    size_t host_memory;
    char host_memory_for[96];
} isk_effect_def;

/* Defaults as documented on each field; no forces, emitters or drawings. */
void isk_effect_def_init(isk_effect_def *d);
/* Frees the arrays (and drawing points, texture pixels); the struct can be
 * init'ed again. */
void isk_effect_def_free(isk_effect_def *d);
/* Appends an item with defaults; return its index, or -1 / NULL (too many, no
 * memory).  The arrays grow by realloc: a pointer returned by one add is
 * invalid after the next add of the same kind (keep indices, or finish the
 * item first). */
int isk_effect_def_add_force(isk_effect_def *d, const char *name, isk_force_kind kind);
int isk_effect_def_add_deflector(isk_effect_def *d, const char *name, isk_deflector seg);
isk_emitter_def *isk_effect_def_add_emitter(isk_effect_def *d, const char *name);
isk_drawing_def *isk_effect_def_add_drawing(isk_effect_def *d, const char *name, isk_drawing_kind kind);
isk_probe_def *isk_effect_def_add_probe(isk_effect_def *d, const char *name, isk_probe_kind kind);
/* The most memory the effect can take, in bytes: every emitter's pool full
 * (its capacity, the store's growth included, trails too), its scratch and
 * sprites, every image of the definition twice (its pixels and the
 * effect's copy), every texture made from them (one per image and grid,
 * isk_texture_bytes), the canvas it is drawn into, and host_memory. */
size_t isk_effect_def_memory(const isk_effect_def *d);

/* Index of the named force / deflector / emitter, or -1. */
int isk_effect_def_find_force(const isk_effect_def *d, const char *name);
int isk_effect_def_find_deflector(const isk_effect_def *d, const char *name);
int isk_effect_def_find_emitter(const isk_effect_def *d, const char *name);
/* Index of the texture of that name, or -1. */
int isk_effect_def_find_texture(const isk_effect_def *d, const char *name);

/* Gives the definition a copy of `image` (straight RGBA) as the texture
 * `name`: every emitter whose `texture` is `name` draws it (cut into its
 * texture_grid).  A texture of that name already there is replaced.  No
 * file is read: isk_scene_load_textures (iskra/scene.h) reads PNGs.
 * ISK_ERR_NULL; ISK_ERR_RANGE for a name empty or longer than
 * ISK_TEXTURE_PATH_MAX - 1; ISK_ERR_SIZE for a malformed canvas or a side
 * above ISK_TEXTURE_MAX_DIM (iskra/texture.h); ISK_ERR_FULL beyond
 * ISK_EFFECT_MAX_TEXTURES; ISK_ERR_NOMEM.  On error nothing changes and
 * err (may be NULL) names the texture. */
isk_status isk_effect_def_add_texture(isk_effect_def *d, const char *name, const isk_canvas *image, isk_error *err);
/* Adds a reference (no duplicates); ISK_ERR_RANGE for a bad index. */
isk_status isk_emitter_use_force(isk_emitter_def *e, int force);
isk_status isk_emitter_use_deflector(isk_emitter_def *e, int deflector);

/* ---- the runnable effect -------------------------------------------------- */

typedef struct isk_effect isk_effect;

/* Validates and compiles.  Errors name the item: "emitter 'smoke': life must
 * be > 0" (with "line N" when the def came from a file).  ISK_ERR_NULL,
 * ISK_ERR_RANGE, ISK_ERR_NAN, ISK_ERR_SIZE, ISK_ERR_NOMEM. */
isk_status isk_effect_create(isk_effect **out, const isk_effect_def *def, isk_error *err);
void isk_effect_destroy(isk_effect *e);

/* Back to the state right after create (same seed: same run again). */
isk_status isk_effect_reset(isk_effect *e);

/* One frame of dt (in substeps).  ISK_ERR_NOMEM if a spawn could not grow a store. */
isk_status isk_effect_step(isk_effect *e);

/* Draws the current state.  With def.clear (the default) the canvas is
 * filled with the background first; with clear == 0 (trails, as the
 * thesis's static trajectory figures) it draws over what is there, so the
 * caller renders after every step.  The canvas must be width x height
 * (ISK_ERR_SIZE otherwise). */
isk_status isk_effect_render(isk_effect *e, isk_canvas *c);

/* The image of frame `frames` from the current state, whatever def.clear
 * says: with clear, `frames` steps then one render; with trails, the canvas
 * is filled with the background and every one of the `frames` steps is
 * followed by a render (so frame 0 of a trail scene is the empty
 * background, as in the thesis, which draws after each move). */
isk_status isk_effect_run(isk_effect *e, isk_canvas *c, long frames);

/* One step followed by a render that keeps trails (used by `iskra play` and
 * by sequence rendering): equivalent to isk_effect_step + isk_effect_render. */
isk_status isk_effect_step_render(isk_effect *e, isk_canvas *c);

/* The click action at world point (x, y). */
isk_status isk_effect_click(isk_effect *e, double x, double y);

/* How many changes from outside the effect has taken since create: each
 * accepted isk_effect_set (and its typed setters), potential added or
 * removed, click, isk_effect_emit and isk_effect_move adds one; steps,
 * renders, reset and isk_effect_restore do not.  A caller that keeps a
 * timeline of snapshots (iskra play's rewind) learns from it that the
 * frames after now will differ from those it kept. */
unsigned long isk_effect_edits(const isk_effect *e);

/* ---- changing it while it runs ----------------------------------------------
 *
 * Any key of the key table (iskra/keys.h, `iskra keys`), by name, with its
 * value as text, as a scene file would write it:
 *
 *     isk_effect_set(fx, "force drag", "b", "0.3", &err);
 *     isk_effect_set(fx, "emitter sparks", "position", "1.5, 2", &err);
 *     isk_effect_set(fx, "scene", "substeps", "4", &err);
 *     char v[64];  isk_effect_get(fx, "bounds", "sides", v, sizeof v, &err);  // "left, right, bottom"
 *
 * `section` is spelled as in a scene file without the brackets: "scene",
 * "view", "bounds", "click", or a type and a name ("force drag", "emitter
 * sparks", "deflector floor", "drawing label").  A value is parsed and
 * checked through the key's row and then with the whole definition (a
 * stream's count against its capacity, ...), with the parser's messages
 * ("[emitter sparks] rate: expected a number between 0 and 10000000, got
 * "1e8""); a refused value changes nothing (ISK_ERR_RANGE; ISK_ERR_NULL,
 * ISK_ERR_NOMEM).  An accepted one is part of the definition from then on
 * (isk_effect_definition, isk_effect_reset and isk_effect_get see it) and
 * applies from the next step: the stage lists are recompiled, so a force set
 * to zero leaves the pipeline and describe, one set non-zero enters it.
 *
 * When a change takes effect is the key's `live` column: "yes" keys act at
 * the next step (forces, potentials including enabled, position and
 * velocity, walls, deflectors, the emitters' physics and drawing, a stream's
 * rate and position, dt, substeps, integrator, speed_divisor, the click);
 * "at reset" keys are stored now and shape the particles the next
 * isk_effect_reset creates (an explosion's count, a layer's rect, the seed);
 * keys marked "no" (width, height, and the kinds: a force's kind, an
 * emitter's source, a drawing's kind) are refused with a message saying so.
 * A potential's live position and on/off state are its own (it moves, it
 * may switch itself off): a change to another of its keys keeps them.
 * isk_effect_get gives the definition's value, in a form isk_effect_set and
 * scene files read back to the same bits; ISK_ERR_SIZE if buf is too small. */
isk_status isk_effect_set(isk_effect *e, const char *section, const char *key, const char *value, isk_error *err);
isk_status isk_effect_get(const isk_effect *e, const char *section, const char *key, char *buf, size_t size,
                          isk_error *err);

/* Adds a potential while running (the simulator's "add potential" click):
 * a [force NAME] of kind potential with pot's fields (its exponent is the
 * code's P), acting on every emitter from the next step, with the next free
 * id.  Removing a force takes it out of the definition and of every emitter
 * that referenced it.  Errors: ISK_ERR_NULL, ISK_ERR_RANGE (a name in use or
 * not a valid name, a bad field, no such force), ISK_ERR_FULL, ISK_ERR_NOMEM,
 * ISK_ERR_SIZE (a frame could then take more than def.max_work: nothing is
 * added, as a refused isk_effect_set changes nothing). */
isk_status isk_effect_add_potential(isk_effect *e, const char *name, const isk_potential *pot, isk_error *err);
isk_status isk_effect_remove_force(isk_effect *e, const char *name, isk_error *err);

/* ---- driving an emitter by hand ------------------------------------------------
 *
 * `section` is "emitter NAME", as for isk_effect_set.
 *
 *     isk_effect_emit(fx, "emitter sparks", 50, &err);        // 50 now (LÖVE's emit(50))
 *     isk_effect_set_active(fx, "emitter sparks", 0, &err);   // no more births; the sparks live on
 *     isk_effect_set_paused(fx, "emitter smoke", 1, &err);    // the smoke stands still
 *     isk_effect_move(fx, "emitter sparks", mx, my, &err);    // follow the mouse, without gaps
 *
 * isk_effect_emit: n particles now, at the current time: a stream's at its
 * place (on its path, in its shape) with its launch and age 0, whether or
 * not it is active; an explosion emitter's explosion of n at its position
 * (n up to its `limit`; a multi-coulomb one still releasing: ISK_ERR_FULL).
 * They are drawn by the next render and move from the next step.  Those
 * beyond the pool's capacity are dropped and counted (isk_effect_dropped),
 * as for every source.  Random numbers come from the emitter's stream, so
 * a run that emits at the same frames gives the same bytes.  Other sources:
 * ISK_ERR_RANGE.
 *
 * isk_effect_set_active: the key `active` (streams, explosions,
 * sub-emitters).  A stopped emitter is born nothing: a stream's births, a
 * timed explosion and a sub-emitter's children that fall due meanwhile
 * are skipped, not caught up; its particles live on.  Started again, a
 * stream's next birth comes one interval later (LÖVE's stop and start,
 * Godot's emitting).
 *
 * isk_effect_set_paused: the key `paused`.  A paused emitter stands
 * still: its particles neither move nor age, nothing is born into it (its
 * events are skipped), its trails are not recorded; it is drawn as it is.
 * Unpaused, a stream goes on as when started again.
 *
 * isk_effect_move: the key `position` as numbers: a stream's births of the
 * next frame spread along the way to (x, y) (no gap), an explosion
 * emitter's next explosion is there, a particle source's particle starts
 * there at the next reset.  The same bytes as isk_effect_set(fx, section,
 * "position", "%.17g, %.17g"), without parsing and recompiling.
 * ISK_ERR_NAN, ISK_ERR_RANGE (beyond ISK_COORD_MAX, a source without a
 * position).
 *
 * All four: ISK_ERR_NULL, ISK_ERR_RANGE (no such emitter, not an emitter),
 * ISK_ERR_NOMEM; a refused call changes nothing. */
isk_status isk_effect_emit(isk_effect *e, const char *section, size_t n, isk_error *err);
isk_status isk_effect_set_active(isk_effect *e, const char *section, int active, isk_error *err);
isk_status isk_effect_set_paused(isk_effect *e, const char *section, int paused, isk_error *err);
isk_status isk_effect_move(isk_effect *e, const char *section, double x, double y, isk_error *err);

/* Threads: how many the effect steps and draws on, and a new number
 * (1..256; 0: the default as isk_effect_def.threads says).  Changing it
 * never changes a byte of the result.  On two or more, a group of 16384
 * particles or more is drawn in bands of rows, one per thread; on four or
 * more, dots and pixels are first sorted into the bands, which keeps about
 * 6 bytes per particle of the largest such group between frames (when they
 * cannot be had, every band reads the whole group: slower, the same bytes).
 * ISK_ERR_RANGE, ISK_ERR_NOMEM, ISK_ERR_UNSUPPORTED. */
int isk_effect_threads(const isk_effect *e);
isk_status isk_effect_set_threads(isk_effect *e, int threads);
/* Your own job system instead of the effect's threads (iskra/tasks.h):
 * from now on the effect's independent items run through tasks->run on
 * tasks->workers workers (isk_effect_threads says how many); NULL: back to
 * threads of its own, as isk_effect_def.threads = 0 gives.  The bytes are
 * the same whatever runs them.  ISK_ERR_NULL (no effect, or no run),
 * ISK_ERR_RANGE (workers not in 1..ISK_TASKS_MAX_WORKERS), ISK_ERR_NOMEM;
 * on error the effect keeps what it had. */
isk_status isk_effect_set_tasks(isk_effect *e, const isk_tasks *tasks);

/* The live potentials (where they are now, whether they are still on), in
 * force order; *count receives how many.  Valid until the next change. */
const isk_potential *isk_effect_potentials(const isk_effect *e, size_t *count);

/* Substeps for every emitter that uses the scene's: the same as
 * isk_effect_set(e, "scene", "substeps", ...) with an int (1..1000). */
isk_status isk_effect_set_substeps(isk_effect *e, int substeps);

/* The compiled stage lists, one line per stage, per emitter; the drawings;
 * then the keys of [scene], [bounds], each [deflector NAME] and [click]
 * as "key = value; ..." lines. */
void isk_effect_describe(const isk_effect *e, FILE *out);

/* Read-only views for overlays and tests. */
size_t isk_effect_particle_count(const isk_effect *e);
/* The simulated time: the sum of every frame's dt / speed_divisor since
 * create or reset, each as it was at that frame (a live change of either
 * never rescales the time already elapsed, so the clock only moves
 * forward). */
double isk_effect_time(const isk_effect *e);
long isk_effect_frame(const isk_effect *e);
const isk_view *isk_effect_view(const isk_effect *e);
const isk_effect_def *isk_effect_definition(const isk_effect *e);
int isk_effect_emitter_count(const isk_effect *e);
const isk_particles *isk_effect_particles(const isk_effect *e, int emitter);
/* The forces an emitter's particles feel, as compiled for its steps (its
 * gravity forces times gravity_multiplier, its winds plus its weight, its
 * drag, the live potentials it picks): what the integrator evaluates, so
 * isk_forces_potential_energy of it is their potential energy.  NULL for
 * no such emitter.  Valid until the next change (isk_effect_set, reset). */
const isk_forces *isk_effect_forces(const isk_effect *e, int emitter);
/* Spawns lost to a full pool since create or reset: 64 bits on every system
 * (a rate of 10^7 at the longest step loses 10^10 in a frame), saturating. */
uint64_t isk_effect_dropped(const isk_effect *e, int emitter);
/* Particles removed since create or reset because their state went NaN or
 * infinite (no accepted scene does that, iskra/limits.h; the thesis
 * fidelity modes can): they are neither drawn nor kept in silence. */
size_t isk_effect_removed_nonfinite(const isk_effect *e, int emitter);

#ifdef __cplusplus
}
#endif

#endif
