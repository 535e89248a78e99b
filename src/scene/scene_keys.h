/* src/scene/scene_keys.h — the sections and keys of scene files (internal).
 *
 * One table per section type.  Each key has an id (its bit in a section's
 * "seen" mask, for duplicate detection and for the checks at the end of the
 * file) and a mask of the section kinds it applies to (force kind, emitter
 * source, drawing kind, bounds mode; 0 = every kind).  The keys are parsed
 * in scene_parse.c; docs/scene-format.md documents them.
 */
#ifndef ISKRA_SCENE_KEYS_H
#define ISKRA_SCENE_KEYS_H

typedef enum sk_section {
    SK_SCENE = 0,
    SK_VIEW,
    SK_FORCE,
    SK_DEFLECTOR,
    SK_BOUNDS,
    SK_EMITTER,
    SK_DRAWING,
    SK_CLICK,
    SK_SECTION_COUNT
} sk_section;

typedef struct sk_key {
    const char *name;
    int id;
    unsigned kinds; /* bit k set: valid for kind k; 0: every kind */
} sk_key;

typedef struct sk_table {
    const char *name;  /* "emitter" */
    int named;         /* 1: [emitter NAME], 0: [scene] */
    const sk_key *keys;
    int nkeys;
} sk_table;

enum { K_SCENE_WIDTH, K_SCENE_HEIGHT, K_SCENE_BACKGROUND, K_SCENE_CLEAR, K_SCENE_DT, K_SCENE_SUBSTEPS,
       K_SCENE_INTEGRATOR, K_SCENE_SEED, K_SCENE_SPEED_DIVISOR, K_SCENE_CENTRE, K_SCENE_FRAMES,
       K_SCENE_FIDELITY };

enum { K_VIEW_XMIN, K_VIEW_XMAX, K_VIEW_YMIN, K_VIEW_YMAX, K_VIEW_ZOOM, K_VIEW_PAN };

enum { K_FORCE_KIND, K_FORCE_G, K_FORCE_B, K_FORCE_ACCEL, K_FORCE_K, K_FORCE_CHARGE, K_FORCE_POSITION,
       K_FORCE_EXPONENT, K_FORCE_LAW, K_FORCE_MIN, K_FORCE_MAX, K_FORCE_XMULT, K_FORCE_ENABLED,
       K_FORCE_VELOCITY, K_FORCE_DRAW };

enum { K_DEFL_SEGMENT, K_DEFL_RESTITUTION, K_DEFL_PROBABILITY, K_DEFL_REACTION, K_DEFL_MODE };

enum { K_BOUNDS_MODE, K_BOUNDS_SIDES, K_BOUNDS_MARGIN, K_BOUNDS_RESTITUTION, K_BOUNDS_WINDOW };

enum { K_EM_SOURCE, K_EM_POSITION, K_EM_VELOCITY, K_EM_MASS, K_EM_MASS_RANGE, K_EM_EXPLOSION, K_EM_COUNT,
       K_EM_LIMIT, K_EM_KICK, K_EM_START, K_EM_RECT, K_EM_SHAPE, K_EM_SHAPE_A, K_EM_SHAPE_B,
       K_EM_SHAPE_ANGLE, K_EM_SHAPE_FAITHFUL, K_EM_LAUNCH, K_EM_ANGLE, K_EM_SPREAD, K_EM_SPEED_MIN,
       K_EM_SPEED_MAX, K_EM_RATE, K_EM_RATE_MODE, K_EM_BIRTH, K_EM_BURST_EVERY, K_EM_LIFE, K_EM_LIFE_RANGE,
       K_EM_CAPACITY, K_EM_FORCES, K_EM_DEFLECTORS, K_EM_BOUNDED, K_EM_DRAW_BEFORE_BOUNCE, K_EM_GRAVITY_MULT,
       K_EM_WEIGHT, K_EM_SLOWING, K_EM_SLOW_FAITHFUL, K_EM_OSC_OMEGA, K_EM_OSC_AMPLITUDE, K_EM_OSC_DECAY, K_EM_OSC_FAITHFUL,
       K_EM_OSC_TABLE, K_EM_OSC_RANDOM_PHASE, K_EM_INTEGRATOR, K_EM_SUBSTEPS, K_EM_DRAW, K_EM_SPRITE, K_EM_SIZE, K_EM_COLOR,
       K_EM_BLEND, K_EM_COLOR_OVER_LIFE, K_EM_ALPHA_OVER_LIFE, K_EM_SIZE_OVER_LIFE, K_EM_ORDER };

enum { K_DRAW_KIND, K_DRAW_UNITS, K_DRAW_POINTS, K_DRAW_CLOSED, K_DRAW_POSITION, K_DRAW_RADIUS, K_DRAW_TEXT,
       K_DRAW_SCALE, K_DRAW_COLOR, K_DRAW_BLEND, K_DRAW_SPRITE, K_DRAW_SIZE, K_DRAW_HAIRLINE };

enum { K_CLICK_EXPLOSION, K_CLICK_COUNT, K_CLICK_EMITTER, K_CLICK_AT_START, K_CLICK_AFTER_FRAMES };

extern const sk_table sk_tables[SK_SECTION_COUNT];

/* Enum value names, in the order of the C enums. */
extern const char *const sk_integrator_names[];   /* isk_integrator */
extern const char *const sk_fidelity_names[];     /* isk_fidelity */
extern const char *const sk_force_kind_names[];   /* isk_force_kind */
extern const char *const sk_law_names[];          /* isk_coulomb_law */
extern const char *const sk_reaction_names[];     /* isk_deflect_reaction */
extern const char *const sk_restitution_names[];  /* isk_restitution_mode */
extern const char *const sk_bounce_names[];       /* isk_bounce_mode */
extern const char *const sk_side_names[];         /* top, right, bottom, left (bit order) */
extern const char *const sk_source_names[];       /* isk_source_kind */
extern const char *const sk_explosion_names[];    /* isk_explosion */
extern const char *const sk_kick_names[];         /* isk_kick_target */
extern const char *const sk_shape_names[];        /* isk_spawn_shape */
extern const char *const sk_launch_names[];       /* isk_launch_kind */
extern const char *const sk_rate_mode_names[];    /* isk_rate_mode */
extern const char *const sk_birth_names[];        /* isk_birth_mode */
extern const char *const sk_draw_names[];         /* isk_draw_mode */
extern const char *const sk_sprite_names[];       /* isk_sprite_kind */
extern const char *const sk_blend_names[];        /* isk_blend */
extern const char *const sk_drawing_names[];      /* isk_drawing_kind */
extern const char *const sk_units_names[];        /* world, pixels */

#endif
