/* The key tables of scene files (see scene_keys.h, docs/scene-format.md). */
#include "scene_keys.h"

#include "iskra/effect.h"

#define BIT(k) (1u << (k))
#define N(a) ((int)(sizeof(a) / sizeof((a)[0])))

static const sk_key scene_keys[] = {
    {"width", K_SCENE_WIDTH, 0},           {"height", K_SCENE_HEIGHT, 0},
    {"background", K_SCENE_BACKGROUND, 0}, {"clear", K_SCENE_CLEAR, 0},
    {"dt", K_SCENE_DT, 0},                 {"substeps", K_SCENE_SUBSTEPS, 0},
    {"integrator", K_SCENE_INTEGRATOR, 0}, {"seed", K_SCENE_SEED, 0},
    {"speed_divisor", K_SCENE_SPEED_DIVISOR, 0}, {"centre", K_SCENE_CENTRE, 0},
    {"frames", K_SCENE_FRAMES, 0},         {"fidelity", K_SCENE_FIDELITY, 0},
};

/* view "kinds": window (0), camera (1) */
static const sk_key view_keys[] = {
    {"xmin", K_VIEW_XMIN, BIT(ISK_VIEWDEF_WINDOW)}, {"xmax", K_VIEW_XMAX, BIT(ISK_VIEWDEF_WINDOW)},
    {"ymin", K_VIEW_YMIN, BIT(ISK_VIEWDEF_WINDOW)}, {"ymax", K_VIEW_YMAX, BIT(ISK_VIEWDEF_WINDOW)},
    {"zoom", K_VIEW_ZOOM, BIT(ISK_VIEWDEF_CAMERA)}, {"pan", K_VIEW_PAN, BIT(ISK_VIEWDEF_CAMERA)},
};

#define POT BIT(ISK_FORCE_POTENTIAL)
static const sk_key force_keys[] = {
    {"kind", K_FORCE_KIND, 0},
    {"g", K_FORCE_G, BIT(ISK_FORCE_GRAVITY)},
    {"b", K_FORCE_B, BIT(ISK_FORCE_DRAG)},
    {"acceleration", K_FORCE_ACCEL, BIT(ISK_FORCE_WIND)},
    {"k", K_FORCE_K, POT},
    {"charge", K_FORCE_CHARGE, POT},
    {"position", K_FORCE_POSITION, POT},
    {"exponent", K_FORCE_EXPONENT, POT},
    {"law", K_FORCE_LAW, POT},
    {"min_distance", K_FORCE_MIN, POT},
    {"max_distance", K_FORCE_MAX, POT},
    {"x_multiplier", K_FORCE_XMULT, POT},
    {"enabled", K_FORCE_ENABLED, POT},
    {"velocity", K_FORCE_VELOCITY, POT},
    {"draw", K_FORCE_DRAW, POT},
};

static const sk_key deflector_keys[] = {
    {"segment", K_DEFL_SEGMENT, 0},         {"restitution", K_DEFL_RESTITUTION, 0},
    {"probability", K_DEFL_PROBABILITY, 0}, {"reaction", K_DEFL_REACTION, 0},
    {"restitution_mode", K_DEFL_MODE, 0},
};

static const sk_key bounds_keys[] = {
    {"mode", K_BOUNDS_MODE, 0},
    {"sides", K_BOUNDS_SIDES, 0},
    {"margin", K_BOUNDS_MARGIN, 0},
    {"restitution", K_BOUNDS_RESTITUTION, BIT(ISK_BOUNCE_REFLECT)},
    {"window", K_BOUNDS_WINDOW, 0},
};

#define SRC_P BIT(ISK_SOURCE_PARTICLE)
#define SRC_E BIT(ISK_SOURCE_EXPLOSION)
#define SRC_L BIT(ISK_SOURCE_LAYER)
#define SRC_S BIT(ISK_SOURCE_STREAM)
static const sk_key emitter_keys[] = {
    {"source", K_EM_SOURCE, 0},
    {"position", K_EM_POSITION, SRC_P | SRC_E | SRC_S},
    {"velocity", K_EM_VELOCITY, SRC_P | SRC_S},
    {"mass", K_EM_MASS, SRC_P | SRC_L | SRC_S},
    {"mass_range", K_EM_MASS_RANGE, SRC_S},
    {"explosion", K_EM_EXPLOSION, SRC_E},
    {"count", K_EM_COUNT, SRC_E | SRC_L | SRC_S},
    {"limit", K_EM_LIMIT, SRC_E | SRC_L},
    {"kick", K_EM_KICK, SRC_E},
    {"start", K_EM_START, SRC_E | SRC_S},
    {"rect", K_EM_RECT, SRC_L},
    {"shape", K_EM_SHAPE, SRC_S},
    {"shape_a", K_EM_SHAPE_A, SRC_S},
    {"shape_b", K_EM_SHAPE_B, SRC_S},
    {"shape_angle", K_EM_SHAPE_ANGLE, SRC_S},
    {"shape_faithful", K_EM_SHAPE_FAITHFUL, SRC_S},
    {"launch", K_EM_LAUNCH, SRC_S},
    {"angle", K_EM_ANGLE, SRC_S},
    {"spread", K_EM_SPREAD, SRC_S},
    {"speed_min", K_EM_SPEED_MIN, SRC_S},
    {"speed_max", K_EM_SPEED_MAX, SRC_S},
    {"rate", K_EM_RATE, SRC_S},
    {"rate_mode", K_EM_RATE_MODE, SRC_S},
    {"birth", K_EM_BIRTH, SRC_S},
    {"burst_every", K_EM_BURST_EVERY, SRC_S},
    {"life", K_EM_LIFE, 0},
    {"life_range", K_EM_LIFE_RANGE, 0},
    {"capacity", K_EM_CAPACITY, 0},
    {"forces", K_EM_FORCES, 0},
    {"deflectors", K_EM_DEFLECTORS, 0},
    {"bounded", K_EM_BOUNDED, 0},
    {"draw_before_bounce", K_EM_DRAW_BEFORE_BOUNCE, 0},
    {"gravity_multiplier", K_EM_GRAVITY_MULT, 0},
    {"weight", K_EM_WEIGHT, 0},
    {"slowing", K_EM_SLOWING, 0},
    {"osc_omega", K_EM_OSC_OMEGA, 0},
    {"osc_amplitude", K_EM_OSC_AMPLITUDE, 0},
    {"osc_decay", K_EM_OSC_DECAY, 0},
    {"osc_faithful", K_EM_OSC_FAITHFUL, 0},
    {"osc_table", K_EM_OSC_TABLE, 0},
    {"osc_random_phase", K_EM_OSC_RANDOM_PHASE, 0},
    {"slow_faithful", K_EM_SLOW_FAITHFUL, 0},
    {"integrator", K_EM_INTEGRATOR, 0},
    {"substeps", K_EM_SUBSTEPS, 0},
    {"draw", K_EM_DRAW, 0},
    {"sprite", K_EM_SPRITE, 0},
    {"size", K_EM_SIZE, 0},
    {"color", K_EM_COLOR, 0},
    {"blend", K_EM_BLEND, 0},
    {"color_over_life", K_EM_COLOR_OVER_LIFE, 0},
    {"alpha_over_life", K_EM_ALPHA_OVER_LIFE, 0},
    {"size_over_life", K_EM_SIZE_OVER_LIFE, 0},
    {"order", K_EM_ORDER, 0},
};

static const sk_key drawing_keys[] = {
    {"kind", K_DRAW_KIND, 0},
    {"units", K_DRAW_UNITS, 0},
    {"points", K_DRAW_POINTS, BIT(ISK_DRAWING_POLYLINE) | BIT(ISK_DRAWING_POLYGON)},
    {"closed", K_DRAW_CLOSED, BIT(ISK_DRAWING_POLYLINE)},
    {"hairline", K_DRAW_HAIRLINE, BIT(ISK_DRAWING_POLYLINE)},
    {"position", K_DRAW_POSITION, BIT(ISK_DRAWING_DISC) | BIT(ISK_DRAWING_TEXT) | BIT(ISK_DRAWING_SPRITE)},
    {"sprite", K_DRAW_SPRITE, BIT(ISK_DRAWING_SPRITE)},
    {"size", K_DRAW_SIZE, BIT(ISK_DRAWING_SPRITE)},
    {"radius", K_DRAW_RADIUS, BIT(ISK_DRAWING_DISC)},
    {"text", K_DRAW_TEXT, BIT(ISK_DRAWING_TEXT)},
    {"scale", K_DRAW_SCALE, BIT(ISK_DRAWING_TEXT)},
    {"color", K_DRAW_COLOR, 0},
    {"blend", K_DRAW_BLEND, 0},
};

static const sk_key click_keys[] = {
    {"explosion", K_CLICK_EXPLOSION, 0},
    {"count", K_CLICK_COUNT, 0},
    {"emitter", K_CLICK_EMITTER, 0},
    {"at_start", K_CLICK_AT_START, 0},
    {"after_frames", K_CLICK_AFTER_FRAMES, 0},
};

const sk_table sk_tables[SK_SECTION_COUNT] = {
    [SK_SCENE] = {"scene", 0, scene_keys, N(scene_keys)},
    [SK_VIEW] = {"view", 0, view_keys, N(view_keys)},
    [SK_FORCE] = {"force", 1, force_keys, N(force_keys)},
    [SK_DEFLECTOR] = {"deflector", 1, deflector_keys, N(deflector_keys)},
    [SK_BOUNDS] = {"bounds", 0, bounds_keys, N(bounds_keys)},
    [SK_EMITTER] = {"emitter", 1, emitter_keys, N(emitter_keys)},
    [SK_DRAWING] = {"drawing", 1, drawing_keys, N(drawing_keys)},
    [SK_CLICK] = {"click", 0, click_keys, N(click_keys)},
};

const char *const sk_integrator_names[] = {"semi-euler", "euler", "verlet", "rk4", "exact-drag", NULL};
const char *const sk_fidelity_names[] = {"sound", "thesis", NULL};
const char *const sk_force_kind_names[] = {"gravity", "drag", "wind", "potential", NULL};
const char *const sk_law_names[] = {"code", "text", NULL};
const char *const sk_reaction_names[] = {"bounce", "kill", "stick", NULL};
const char *const sk_restitution_names[] = {"uniform", "normal", NULL};
const char *const sk_bounce_names[] = {"thesis", "reflect", NULL};
const char *const sk_side_names[] = {"top", "right", "bottom", "left", NULL};
const char *const sk_source_names[] = {"particle", "explosion", "layer", "stream", NULL};
const char *const sk_explosion_names[] = {"ring", "uniform", "gauss", "coulomb", "multi-coulomb", NULL};
const char *const sk_kick_names[] = {"all", "new", NULL};
const char *const sk_shape_names[] = {"point", "disc", "circle", "ring", "segment", "rect", "ellipse", NULL};
const char *const sk_launch_names[] = {"constant", "disc", "direction", "cone", NULL};
const char *const sk_rate_mode_names[] = {"accumulate", "thesis", NULL};
const char *const sk_birth_names[] = {"backdate", "thesis-jitter", "frame", NULL};
const char *const sk_draw_names[] = {"dot", "pixel", "disc", "sprite", "none", "dot-browser", NULL};
const char *const sk_sprite_names[] = {"disc", "linear", "smooth", NULL};
const char *const sk_blend_names[] = {"replace", "over", "add", NULL};
const char *const sk_drawing_names[] = {"polyline", "disc", "text", "polygon", "sprite", NULL};
const char *const sk_units_names[] = {"world", "pixels", NULL};
