/* SPDX-License-Identifier: MIT */
/* The key table (iskra/keys.h): one row per key of a scene file.
 *
 * Every fact about a key is here and nowhere else: the parser, the
 * validation of C definitions, the defaults, live changes, `iskra keys` and
 * the key tables of docs/scene-format.md read these rows.  Rows are grouped
 * by section, in the order the documentation lists them. */
#include "iskra/keys.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/limits.h"
#include "iskra/texture.h"
#include "preset_list.h"

#define N(a) ((int)(sizeof(a) / sizeof((a)[0])))
#define BIT(k) (1u << (k))
#define ALL ISK_KEY_ALL_KINDS
#define NAMES(a) .names = (a), .nnames = N(a)

/* ranges */
#define GE(a) .lo_bound = ISK_BOUND_INCL, .min = (a)
#define GT(a) .lo_bound = ISK_BOUND_EXCL, .min = (a)
#define IN(a, b) .lo_bound = ISK_BOUND_INCL, .min = (a), .hi_bound = ISK_BOUND_INCL, .max = (b)
#define GT_LE(a, b) .lo_bound = ISK_BOUND_EXCL, .min = (a), .hi_bound = ISK_BOUND_INCL, .max = (b)

static const isk_key_word forever_words[] = {{"forever", INFINITY}, {"inf", INFINITY}, {"infinite", INFINITY},
                                             {"immortal", INFINITY}, {NULL, 0}};
static const isk_key_word off_words[] = {{"off", ISK_DIST_OFF}, {"none", ISK_DIST_OFF}, {NULL, 0}};
static const isk_key_word scene_words[] = {{"scene", 0}, {NULL, 0}};
static const isk_key_word inherit_words[] = {{"scene", ISK_INTEGRATE_INHERIT}, {NULL, 0}};
static const isk_key_word spin_end_words[] = {{"none", ISK_SPIN_END_NONE}, {NULL, 0}};
static const isk_key_word table_words[] = {{"true", ISK_SINLUT_FLOOR}, {"false", ISK_SINLUT_LIBM}, {NULL, 0}};

/* ---- what each name of an enum means (a row's `notes`) ---------------------
 * Indexed by value and sized by the enum's count, so a name without a note
 * is a NULL that tests/test_key_meanings.c finds.  A meaning never lists
 * the names itself: isk_key_meaning_text joins these to it. */
#define NOTES(a) .notes = (a)

static const char *const centre_notes[ISK_FIDELITY_COUNT] = {
    [ISK_FIDELITY_SOUND] = "zero force",
    [ISK_FIDELITY_THESIS] = "the thesis code's NaN",
};
static const char *const fidelity_notes[ISK_FIDELITY_COUNT] = {
    [ISK_FIDELITY_SOUND] = "the physically sound arithmetic (constant accelerations take a fast path)",
    [ISK_FIDELITY_THESIS] = ("the thesis code's arithmetic everywhere (gravity as m*(-g) then dt/m, no "
                             "constant-acceleration fast path), for bit-exact thesis scenes with random masses"),
};
static const char *const law_notes[ISK_COULOMB_LAW_COUNT] = {
    [ISK_COULOMB_LAW_CODE] = "exponent is the code's P, |F| = k|Q| d^(1-P)",
    [ISK_COULOMB_LAW_TEXT] = "the thesis text's p, P = p + 2",
};
static const char *const restitution_mode_notes[ISK_RESTITUTION_MODE_COUNT] = {
    [ISK_RESTITUTION_UNIFORM] = "c*(v - 2(v.n)n) (fire thesis)",
    [ISK_RESTITUTION_NORMAL] = "only the normal part scaled (particle-engine thesis)",
};
static const char *const bounce_mode_notes[ISK_BOUNCE_MODE_COUNT] = {
    [ISK_BOUNCE_THESIS] = "the thesis's zarobi (sign flip, only the floor clamps)",
    [ISK_BOUNCE_REFLECT] = ("the bounce at the time of impact with restitution (include/iskra/impact.h), never "
                            "tunnels or sticks"),
};
static const char *const source_notes[ISK_SOURCE_KIND_COUNT] = {
    [ISK_SOURCE_PARTICLE] = "one particle",
    [ISK_SOURCE_EXPLOSION] = "a thesis explosion",
    [ISK_SOURCE_LAYER] = "the stationary layer",
    [ISK_SOURCE_STREAM] = "continuous emission",
    [ISK_SOURCE_SUB] = ("a sub-emitter: count particles where another emitter's particle dies (on_death) or "
                        "bounces (on_hit)"),
};
static const char *const kick_notes[ISK_KICK_COUNT] = {
    [ISK_KICK_ALL] = "the whole emitter (the thesis)",
    [ISK_KICK_NEW] = "only the new particles",
};
static const char *const rate_mode_notes[ISK_RATE_MODE_COUNT] = {
    [ISK_RATE_ACCUMULATE] = "fractional carry (exact over time)",
    [ISK_RATE_THESIS] = "the fire thesis's rounding per frame",
};
static const char *const sine_notes[ISK_SINLUT_MODE_COUNT] = {
    [ISK_SINLUT_FLOOR] = "a 4096-entry table read by floor (the fire thesis; true is its old spelling)",
    [ISK_SINLUT_ROUND] = "the table's nearest entry",
    [ISK_SINLUT_LERP] = "linear interpolation in the table (1e-6)",
    [ISK_SINLUT_LIBM] = "libm's sin (false is its old spelling)",
};
static const char *const draw_notes[ISK_DRAW_COUNT] = {
    [ISK_DRAW_DOT] = "exact-area 1x1 square at the point",
    [ISK_DRAW_PIXEL] = "the single pixel containing the point",
    [ISK_DRAW_DISC] = "a disc of diameter size",
    [ISK_DRAW_SPRITE] = "a sprite of diameter size",
    [ISK_DRAW_NONE] = "simulated only",
    [ISK_DRAW_DOT_BROWSER] = "the thesis browser's rule",
};
static const char *const space_notes[ISK_SPACE_COUNT] = {
    [ISK_SPACE_WORLD] = "particles leave the emitter behind",
    [ISK_SPACE_LOCAL] = "they move with it",
};
static const char *const align_notes[ISK_ALIGN_COUNT] = {
    [ISK_ALIGN_NONE] = "by its angle only",
    [ISK_ALIGN_VELOCITY] = "turned along the velocity (a sprite kind becomes a streak 4 sizes long)",
};
static const char *const probe_kind_notes[ISK_PROBE_KIND_COUNT] = {
    [ISK_PROBE_GATE] = "crossings of a segment per second, in each direction",
    [ISK_PROBE_REGION] = "count, mean speed and kinetic energy inside a rectangle",
    [ISK_PROBE_HISTOGRAM] = "a histogram of every particle's speed, angle or age",
    [ISK_PROBE_TOTALS] = "the scene's momentum, kinetic and potential energy",
};
static const char *const probe_of_notes[ISK_PROBE_OF_COUNT] = {
    [ISK_PROBE_OF_SPEED] = "|v|, units/s",
    [ISK_PROBE_OF_ANGLE] = "the velocity's direction, degrees -180..180",
    [ISK_PROBE_OF_AGE] = "seconds lived",
};
static const char *const draw_order_notes[ISK_DRAW_ORDER_COUNT] = {
    [ISK_DRAW_ORDER_NEWEST] = "the newest on top: drawn oldest first",
    [ISK_DRAW_ORDER_OLDEST] = "the oldest on top: drawn newest first, on one thread",
    [ISK_DRAW_ORDER_RANDOM] = "shuffled again every frame, on one thread",
};
static const char *const units_notes[2] = {
    [0] = "world units",
    [1] = "canvas pixels (y down)",
};

/* ---- [scene] and [view]: fields of isk_effect_def ------------------------- */

#define SCENE(key) .section = ISK_SECTION_SCENE, .name = key
#define VIEW(key) .section = ISK_SECTION_VIEW, .name = key
#define DEF(f) .offset = offsetof(isk_effect_def, f)
#define WIN BIT(ISK_VIEWDEF_WINDOW)
#define CAM BIT(ISK_VIEWDEF_CAMERA)

/* ---- [force NAME]: isk_force_def ------------------------------------------ */

#define FORCE(key) .section = ISK_SECTION_FORCE, .name = key
#define FRC(f) .offset = offsetof(isk_force_def, f)
#define GRAV BIT(ISK_FORCE_GRAVITY)
#define DRAG BIT(ISK_FORCE_DRAG)
#define WIND BIT(ISK_FORCE_WIND)
#define POT BIT(ISK_FORCE_POTENTIAL)
#define TURB BIT(ISK_FORCE_TURBULENCE)

/* ---- [deflector NAME]: isk_deflector_def ---------------------------------- */

#define DEFL(key) .section = ISK_SECTION_DEFLECTOR, .name = key
#define SEG(f) .offset = offsetof(isk_deflector_def, seg.f)
#define DFL(f) .offset = offsetof(isk_deflector_def, f)

/* ---- [bounds]: isk_bounds -------------------------------------------------- */

#define BOUNDS(key) .section = ISK_SECTION_BOUNDS, .name = key
#define BND(f) .offset = offsetof(isk_bounds, f)

/* ---- [emitter NAME]: isk_emitter_def --------------------------------------- */
/* Each key is a field of one of the emitter's parts (born, launch, life,
 * motion, look, events: iskra/effect.h), named after the key. */

#define EMITTER(key) .section = ISK_SECTION_EMITTER, .name = key
#define EM(f) .offset = offsetof(isk_emitter_def, f)
#define S_P BIT(ISK_SOURCE_PARTICLE)
#define S_E BIT(ISK_SOURCE_EXPLOSION)
#define S_L BIT(ISK_SOURCE_LAYER)
#define S_S BIT(ISK_SOURCE_STREAM)
#define S_SUB BIT(ISK_SOURCE_SUB)

/* ---- [probe NAME]: isk_probe_def ------------------------------------------- */

#define PROBE(key) .section = ISK_SECTION_PROBE, .name = key
#define PRB(f) .offset = offsetof(isk_probe_def, f)
#define P_GATE BIT(ISK_PROBE_GATE)
#define P_REGION BIT(ISK_PROBE_REGION)
#define P_HIST BIT(ISK_PROBE_HISTOGRAM)

/* ---- [drawing NAME]: isk_drawing_def --------------------------------------- */

#define DRAWING(key) .section = ISK_SECTION_DRAWING, .name = key
#define DRW(f) .offset = offsetof(isk_drawing_def, f)
#define D_LINE BIT(ISK_DRAWING_POLYLINE)
#define D_DISC BIT(ISK_DRAWING_DISC)
#define D_TEXT BIT(ISK_DRAWING_TEXT)
#define D_POLY BIT(ISK_DRAWING_POLYGON)
#define D_SPR BIT(ISK_DRAWING_SPRITE)

/* ---- [click]: isk_click_def ------------------------------------------------ */

#define CLICK(key) .section = ISK_SECTION_CLICK, .name = key
#define CLK(f) .offset = offsetof(isk_click_def, f)

#define MAXP ((double)ISK_EFFECT_MAX_PARTICLES)

/* The limits of iskra/limits.h, as ranges (no accepted value may ever
 * give a NaN or an infinity: that header says why each is where it is). */
#define COORD IN(-ISK_COORD_MAX, ISK_COORD_MAX)
#define SPEED IN(-ISK_SPEED_LIMIT, ISK_SPEED_LIMIT)
#define STRENGTH IN(-ISK_STRENGTH_MAX, ISK_STRENGTH_MAX)

static const isk_key keys[] = {
    /* [scene] */
    {SCENE("width"), .type = ISK_KEY_WHOLE, DEF(width), IN(1, ISK_CANVAS_MAX_DIM), .dflt = "600", .create_only = 1,
     .meaning = "canvas width in pixels"},
    {SCENE("height"), .type = ISK_KEY_WHOLE, DEF(height), IN(1, ISK_CANVAS_MAX_DIM), .dflt = "600",
     .create_only = 1, .meaning = "canvas height in pixels"},
    {SCENE("background"), .type = ISK_KEY_COLOR, DEF(background), .dflt = "black", .live = ALL,
     .meaning = "fill colour"},
    {SCENE("clear"), .type = ISK_KEY_BOOL, DEF(clear), .dflt = "true", .live = ALL,
     .meaning = "clear every frame; false = trails (every step draws over the last, as the thesis's static "
                "trajectory figures)"},
    {SCENE("dt"), .type = ISK_KEY_NUMBER, DEF(dt), GT_LE(0, ISK_DT_MAX), .dflt = "1/60", .live = ALL,
     .meaning = "simulated seconds per frame"},
    {SCENE("substeps"), .type = ISK_KEY_WHOLE, DEF(substeps), IN(1, ISK_SUBSTEPS_MAX), .dflt = "1", .live = ALL,
     .meaning = "steps of dt/substeps per frame (the thesis's precision)"},
    {SCENE("integrator"), .type = ISK_KEY_ENUM, DEF(integrator), NAMES(isk_integrator_names), .dflt = "semi-euler",
     .live = ALL, .meaning = "time integrator (include/iskra/integrate.h)"},
    {SCENE("seed"), .type = ISK_KEY_SEED, DEF(seed), .dflt = "1",
     .meaning = "random seed; each emitter draws from its own stream seeded from (seed, emitter index)"},
    {SCENE("speed_divisor"), .type = ISK_KEY_NUMBER, DEF(speed_divisor),
     IN(ISK_SPEED_DIVISOR_MIN, ISK_SPEED_DIVISOR_MAX), .dflt = "1", .live = ALL,
     .meaning = "the thesis simulator's speed slider f: each frame simulates dt/f seconds, so the whole "
                "simulation (particles and moving potentials) runs f times slower"},
    {SCENE("centre"), .type = ISK_KEY_ENUM, DEF(centre), NAMES(isk_fidelity_names), NOTES(centre_notes),
     .dflt = "sound", .live = ALL, .meaning = "the force exactly on a potential without a min distance"},
    {SCENE("frames"), .type = ISK_KEY_LONG, DEF(show.frames), IN(0, 1e8), .dflt = "0", .live = ALL,
     .meaning = "the frame `iskra render` shows when --frames is not given (the effect ignores it)"},
    {SCENE("start_paused"), .type = ISK_KEY_BOOL, DEF(show.start_paused), .dflt = "false", .live = ALL,
     .meaning = "`iskra play` pauses after the first frame, as the thesis's simulator scenes do (prviFrame), so "
                "the class sees the start (the effect ignores it)"},
    {SCENE("fidelity"), .type = ISK_KEY_ENUM, DEF(fidelity), NAMES(isk_fidelity_names), NOTES(fidelity_notes),
     .dflt = "sound", .live = ALL, .meaning = "whose arithmetic the forces use"},

    /* [view] */
    {VIEW("xmin"), .type = ISK_KEY_NUMBER, DEF(xmin), .applies = WIN, .dflt = "-10", .live = ALL,
     .meaning = "left edge of the world window shown on the canvas"},
    {VIEW("xmax"), .type = ISK_KEY_NUMBER, DEF(xmax), .applies = WIN, .dflt = "10", .live = ALL,
     .meaning = "right edge (> xmin)"},
    {VIEW("ymin"), .type = ISK_KEY_NUMBER, DEF(ymin), .applies = WIN, .dflt = "-10", .live = ALL,
     .meaning = "bottom edge"},
    {VIEW("ymax"), .type = ISK_KEY_NUMBER, DEF(ymax), .applies = WIN, .dflt = "10", .live = ALL,
     .meaning = "top edge (> ymin)"},
    {VIEW("zoom"), .type = ISK_KEY_NUMBER, DEF(zoom), .applies = CAM, GT(0), .dflt = "10", .live = ALL,
     .meaning = "camera: smaller is closer; (w+h)/(2*zoom) pixels per unit"},
    {VIEW("pan"), .type = ISK_KEY_VECTOR, DEF(tx), .applies = CAM, .dflt = "0, 0", .live = ALL,
     .meaning = "camera translation (tx, ty)"},

    /* [force NAME] */
    {FORCE("kind"), .type = ISK_KEY_ENUM, FRC(kind), NAMES(isk_force_kind_names), .dflt = "gravity",
     .dflt_doc = "the section's NAME when it is a kind ([force drag])", .create_only = 1,
     .meaning = "what the force is"},
    {FORCE("g"), .type = ISK_KEY_NUMBER, FRC(g), .applies = GRAV, IN(0, ISK_STRENGTH_MAX), .dflt = "0", .live = ALL,
     .meaning = "F = (0, -m*g*gravity_multiplier)"},
    {FORCE("b"), .type = ISK_KEY_NUMBER, FRC(b), .applies = DRAG, IN(0, ISK_STRENGTH_MAX), .dflt = "0",
     .live = ALL, .meaning = "F = -b*v (never more than stops a particle within one step)"},
    {FORCE("acceleration"), .type = ISK_KEY_VECTOR, FRC(accel), .applies = WIND, STRENGTH, .dflt = "0, 0", .live = ALL,
     .meaning = "a constant acceleration, F = m*a"},
    {FORCE("k"), .type = ISK_KEY_NUMBER, FRC(pot.k), .applies = POT, .required = POT, .dflt = "0", .live = ALL,
     .meaning = "the potential's strength"},
    {FORCE("charge"), .type = ISK_KEY_NUMBER, FRC(pot.charge), .applies = POT, .dflt = "1", .live = ALL,
     .meaning = "Q; k*Q > 0 attracts"},
    {FORCE("position"), .type = ISK_KEY_VECTOR, FRC(pot.r), .applies = POT, .required = POT, COORD, .dflt = "0, 0",
     .live = ALL, .meaning = "x, y of the potential"},
    {FORCE("exponent"), .type = ISK_KEY_NUMBER, FRC(exponent), .applies = POT,
     IN(ISK_P_MIN - 2, ISK_P_MAX), .dflt = "2", .live = ALL,
     .meaning = "the distance exponent, read by law; the code's P must be 0..17 (|F| ~ d^(1-P): from a "
                "spring's d to d^-16)"},
    {FORCE("law"), .type = ISK_KEY_ENUM, FRC(law), .applies = POT, NAMES(isk_coulomb_law_names), NOTES(law_notes),
     .dflt = "code", .live = ALL, .meaning = "how exponent is read"},
    {FORCE("min_distance"), .type = ISK_KEY_NUMBER, FRC(pot.min_dist), .applies = POT, .words = off_words,
     .dflt = "off", .live = ALL,
     .meaning = "distances below it are clamped (softens the centre); <= 0 is off"},
    {FORCE("max_distance"), .type = ISK_KEY_NUMBER, FRC(pot.max_dist), .applies = POT, .words = off_words,
     .dflt = "off", .live = ALL,
     .meaning = "once any particle comes closer, the potential switches off for good (and leaves the "
                "pipeline); <= 0 is off"},
    {FORCE("x_multiplier"), .type = ISK_KEY_NUMBER, FRC(pot.x_mult), .applies = POT, .dflt = "1", .live = ALL,
     .meaning = "scales the force's x component only"},
    {FORCE("enabled"), .type = ISK_KEY_BOOL, FRC(pot.enabled), .applies = POT, .dflt = "true", .live = ALL,
     .meaning = "a disabled potential is not simulated at all (setting it true also revives one that "
                "switched itself off)"},
    {FORCE("velocity"), .type = ISK_KEY_VECTOR, FRC(pot.vel), .applies = POT, SPEED, .dflt = "0, 0", .live = ALL,
     .meaning = "the potential moves by velocity*dt/speed_divisor per frame"},
    {FORCE("draw"), .type = ISK_KEY_BOOL, FRC(draw), .applies = POT, .dflt = "true", .live = ALL,
     .meaning = "draw it as a disc of radius 0.1 with its number, while it is on"},

    /* [force NAME] turbulence (motion: src/sim/stage_field.c) */
    {FORCE("strength"), .type = ISK_KEY_NUMBER, FRC(strength), .applies = TURB, STRENGTH, .dflt = "0", .live = ALL,
     .meaning = "a = strength * curl psi (units/s^2): a divergence-free stirring, the same for every mass"},
    {FORCE("scale"), .type = ISK_KEY_NUMBER, FRC(scale), .applies = TURB,
     IN(ISK_TURBULENCE_SCALE_MIN, ISK_COORD_MAX), .dflt = "1", .live = ALL,
     .meaning = "the size of the swirls, world units"},
    {FORCE("speed"), .type = ISK_KEY_NUMBER, FRC(speed), .applies = TURB, IN(-1e6, 1e6), .dflt = "0", .live = ALL,
     .meaning = "how fast the swirls change: noise cells per second along psi's time axis (0: a still field)"},

    /* [deflector NAME] */
    {DEFL("segment"), .type = ISK_KEY_NUMBERS4, SEG(x0), .required = ALL, .what = "x0, y0, x1, y1",
     IN(-ISK_COORD_MAX, ISK_COORD_MAX), .dflt = "0, 0, 1, 0", .live = ALL,
     .meaning = "the end points x0, y0, x1, y1, which must differ (side tests keep their precision at any reach)"},
    {DEFL("restitution"), .type = ISK_KEY_NUMBER, SEG(restitution), IN(0, ISK_DEFLECT_RESTITUTION_MAX), .dflt = "1",
     .live = ALL,
     .meaning = "c: the velocity at impact is scaled by c at a bounce; above 1 a bumper, which never leaves a speed "
                "above 1e150"},
    {DEFL("probability"), .type = ISK_KEY_NUMBER, SEG(probability), IN(0, 1), .dflt = "1", .live = ALL,
     .meaning = "chance that a hit reacts (otherwise the particle passes)"},
    {DEFL("reaction"), .type = ISK_KEY_ENUM, SEG(reaction), NAMES(isk_deflect_reaction_names), .dflt = "bounce",
     .live = ALL, .meaning = "what a hit does"},
    {DEFL("restitution_mode"), .type = ISK_KEY_ENUM, SEG(mode), NAMES(isk_restitution_mode_names),
     NOTES(restitution_mode_notes), .dflt = "uniform", .live = ALL, .meaning = "what restitution scales"},
    {DEFL("show"), .type = ISK_KEY_BOOL, DFL(show), .dflt = "false", .live = ALL,
     .meaning = "draw the segment, after the drawings and before the particles, as a line 1 px wide (where the "
                "segment is at each frame)"},
    {DEFL("color"), .type = ISK_KEY_COLOR, DFL(color), .dflt = "white", .live = ALL,
     .meaning = "the colour of the line show draws"},

    /* [bounds] */
    {BOUNDS("mode"), .type = ISK_KEY_ENUM, BND(mode), NAMES(isk_bounce_mode_names), NOTES(bounce_mode_notes),
     .dflt = "reflect", .live = ALL, .meaning = "how a particle bounces off a wall"},
    {BOUNDS("sides"), .type = ISK_KEY_SIDES, BND(sides), NAMES(isk_side_names), .dflt = "none",
     .dflt_doc = "all when the scene has a [bounds] section", .live = ALL, .meaning = "which walls exist"},
    {BOUNDS("margin"), .type = ISK_KEY_NUMBER, BND(margin), GE(0), .dflt = "0",
     .dflt_doc = "0.1 with mode = thesis, 0 with reflect", .live = ALL,
     .meaning = "walls sit this far inside the window"},
    {BOUNDS("restitution"), .type = ISK_KEY_NUMBER, BND(restitution), .applies = BIT(ISK_BOUNCE_REFLECT), IN(0, 1),
     .dflt = "1", .live = ALL, .meaning = "c: the normal speed is scaled by c at a bounce"},
    {BOUNDS("window"), .type = ISK_KEY_NUMBERS4, BND(xmin), .what = "xmin, xmax, ymin, ymax",
     .dflt = "-10, 10, -10, 10",
     .dflt_doc = "the view's window (a camera view: its visible window at the scene's size)", .live = ALL,
     .meaning = "xmin, xmax, ymin, ymax the walls follow (min < max)"},

    /* [emitter NAME] */
    {EMITTER("preset"), .type = ISK_KEY_TEXT, EM(preset), .aux = sizeof(((isk_emitter_def *)0)->preset),
     .names = isk__fx_preset_names, .nnames = FX_PRESET_COUNT, .what = "a preset's name, or NAME, SCALE", .dflt = "",
     .create_only = 1, .directive = 1,
     .meaning = "the section's first key: starts the emitter from a preset (iskra/presets.h) at SCALE world units "
                "per 100 cocos2d points (default 1); keys after it override it"},
    {EMITTER("source"), .type = ISK_KEY_ENUM, EM(born.source), NAMES(isk_source_names), NOTES(source_notes),
     .dflt = "particle", .create_only = 1, .meaning = "where the particles come from"},
    {EMITTER("position"), .type = ISK_KEY_VECTOR, EM(born.position), .applies = S_P | S_E | S_S, COORD, .dflt = "0, 0",
     .live = S_E | S_S,
     .meaning = "the particle / explosion centre / stream origin"},
    {EMITTER("velocity"), .type = ISK_KEY_VECTOR, EM(launch.velocity), .applies = S_P | S_S | S_SUB, SPEED,
     .dflt = "0, 0", .live = S_S | S_SUB,
     .meaning = "the particle's velocity; a stream's constant (or disc-centre) velocity"},
    {EMITTER("mass"), .type = ISK_KEY_NUMBER, EM(launch.mass), .applies = S_P | S_L | S_S | S_SUB,
     IN(ISK_MASS_MIN, ISK_MASS_MAX), .dflt = "1", .live = S_S | S_SUB,
     .meaning = "(explosions set their own masses: 2 or 2 + U)"},
    {EMITTER("mass_range"), .type = ISK_KEY_NUMBER, EM(launch.mass_range), .applies = S_S | S_SUB, IN(0, ISK_MASS_MAX),
     .dflt = "0", .live = S_S | S_SUB,
     .meaning = "mass = mass + U*mass_range"},
    {EMITTER("explosion"), .type = ISK_KEY_ENUM, EM(born.explosion), .applies = S_E, NAMES(isk_explosion_names),
     .dflt = "gauss", .meaning = "the thesis's explosion types"},
    {EMITTER("count"), .type = ISK_KEY_COUNT, EM(born.count), .applies = S_E | S_L | S_S | S_SUB,
     .required = S_L | S_SUB, IN(0, MAXP), .dflt = "0", .live = S_S | S_SUB,
     .meaning = "particles: an explosion's or the layer's (1..limit); a stream's per burst (0: no bursts); a sub-emitter's "
                "per event (1..capacity)"},
    {EMITTER("limit"), .type = ISK_KEY_COUNT, EM(born.limit), .applies = S_E | S_L | S_S, IN(0, MAXP), .dflt = "0",
     .live = ALL,
     .meaning = "largest accepted explosion, clicks included (0: the thesis's 10,000)"},
    {EMITTER("kick"), .type = ISK_KEY_ENUM, EM(born.kick), .applies = S_E, NAMES(isk_kick_names), NOTES(kick_notes),
     .dflt = "all", .live = ALL, .meaning = "which particles a Coulomb kick pushes"},
    {EMITTER("start"), .type = ISK_KEY_NUMBER, EM(born.start), .applies = S_E | S_S, GE(0), .dflt = "0",
     .what = "a number of seconds", .meaning = "time of the explosion / first burst and of the stream's start"},
    {EMITTER("rect"), .type = ISK_KEY_NUMBERS4, EM(born.rect), .applies = S_L, .required = S_L, COORD,
     .what = "xmin, xmax, ymin, ymax", .dflt = "0, 0, 0, 0",
     .meaning = "xmin, xmax, ymin, ymax of the layer"},
    {EMITTER("shape"), .type = ISK_KEY_ENUM, EM(born.shape), .applies = S_S | S_SUB, NAMES(isk_shape_names),
     .dflt = "point", .live = S_S | S_SUB, .meaning = "where new particles appear around position"},
    {EMITTER("shape_a"), .type = ISK_KEY_NUMBER, EM(born.shape_a), .applies = S_S | S_SUB, COORD, .dflt = "0",
     .live = S_S | S_SUB,
     .meaning = "radius (disc, circle); inner radius (ring); x offset (segment); half-width (rect, rect_border); "
                "semi-axis (ellipse, ellipse_border); standard deviation along x (gaussian)"},
    {EMITTER("shape_b"), .type = ISK_KEY_NUMBER, EM(born.shape_b), .applies = S_S | S_SUB, COORD, .dflt = "0",
     .live = S_S | S_SUB,
     .meaning = "outer radius (ring); y offset (segment); half-height (rect, rect_border); semi-axis (ellipse, "
                "ellipse_border); standard deviation along y (gaussian)"},
    {EMITTER("shape_angle"), .type = ISK_KEY_ANGLE, EM(born.shape_angle), .applies = S_S | S_SUB, IN(-3600, 3600),
     .dflt = "0", .live = S_S | S_SUB, .meaning = "rotation of the shape"},
    {EMITTER("shape_faithful"), .type = ISK_KEY_BOOL, EM(born.shape_faithful), .applies = S_S | S_SUB, .dflt = "false",
     .live = S_S | S_SUB, .meaning = "ellipse: the particle-engine thesis's (non-uniform) sampler"},
    {EMITTER("launch"), .type = ISK_KEY_ENUM, EM(launch.kind), .applies = S_S | S_SUB, NAMES(isk_velgen_names),
     .dflt = "constant", .live = S_S | S_SUB, .meaning = "how initial velocities are drawn"},
    {EMITTER("launch_outward"), .type = ISK_KEY_BOOL, EM(launch.outward), .applies = S_S | S_SUB, .dflt = "false",
     .live = S_S | S_SUB,
     .meaning = "turn each launch velocity by the direction from the shape's centre to the birth place, so angle 0 "
                "points outward (not turned exactly on the centre)"},
    {EMITTER("angle"), .type = ISK_KEY_ANGLE, EM(launch.angle), .applies = S_S | S_SUB, IN(-3600, 3600), .dflt = "0",
     .live = S_S | S_SUB,
     .meaning = "direction of direction/cone launches"},
    {EMITTER("spread"), .type = ISK_KEY_ANGLE, EM(launch.spread), .applies = S_S | S_SUB, IN(0, 360), .dflt = "0",
     .live = S_S | S_SUB,
     .meaning = "opening of a cone launch"},
    {EMITTER("speed_min"), .type = ISK_KEY_NUMBER, EM(launch.speed_min), .applies = S_S | S_SUB,
     IN(0, ISK_SPEED_LIMIT), .dflt = "0", .live = S_S | S_SUB,
     .meaning = "slowest launch speed"},
    {EMITTER("speed_max"), .type = ISK_KEY_NUMBER, EM(launch.speed_max), .applies = S_S | S_SUB,
     IN(0, ISK_SPEED_LIMIT), .dflt = "0", .live = S_S | S_SUB,
     .meaning = "fastest launch speed (>= speed_min; disc: its radius)"},
    {EMITTER("rate"), .type = ISK_KEY_NUMBER, EM(born.rate), .applies = S_S, IN(0, 1e7), .dflt = "0", .live = S_S,
     .meaning = "particles per second (0: bursts only)"},
    {EMITTER("rate_mode"), .type = ISK_KEY_ENUM, EM(born.rate_mode), .applies = S_S, NAMES(isk_rate_mode_names),
     NOTES(rate_mode_notes), .dflt = "accumulate", .live = S_S, .meaning = "how rate*dt becomes whole particles"},
    {EMITTER("birth"), .type = ISK_KEY_ENUM, EM(born.birth), .applies = S_S, NAMES(isk_birth_mode_names),
     .dflt = "backdate", .live = S_S, .meaning = "when within a frame particles are born"},
    {EMITTER("burst_every"), .type = ISK_KEY_NUMBER, EM(born.burst_every), .applies = S_S, GE(0), .dflt = "0",
     .what = "a number of seconds", .live = S_S,
     .meaning = "a burst of count every this many seconds (0: once, at start)"},
    {EMITTER("life"), .type = ISK_KEY_NUMBER, EM(life.seconds), GT(0), .words = forever_words, .dflt = "forever",
     .what = "a number of seconds", .live = ALL, .meaning = "lifetime of new particles"},
    {EMITTER("life_range"), .type = ISK_KEY_NUMBER, EM(life.range), GE(0), .dflt = "0", .live = ALL,
     .meaning = "lifetime = life + U*life_range"},
    {EMITTER("capacity"), .type = ISK_KEY_COUNT, EM(born.capacity), IN(1, MAXP), .dflt = "100000", .live = ALL,
     .meaning = "pool size: spawns beyond it are dropped (and counted)"},
    {EMITTER("forces"), .type = ISK_KEY_REFS, EM(motion.forces), .aux = offsetof(isk_emitter_def, motion.nforces),
     .refers = ISK_SECTION_FORCE, .dflt = "none",
     .live = ALL, .meaning = "the forces acting on these particles"},
    {EMITTER("deflectors"), .type = ISK_KEY_REFS, EM(motion.deflectors),
     .aux = offsetof(isk_emitter_def, motion.ndeflectors), .refers = ISK_SECTION_DEFLECTOR,
     .dflt = "none", .live = ALL, .meaning = "the deflectors they hit"},
    {EMITTER("active"), .type = ISK_KEY_BOOL, EM(born.active), .applies = S_E | S_S | S_SUB, .dflt = "true",
     .live = S_E | S_S | S_SUB,
     .meaning = "false: nothing is born (its particles live on); births due meanwhile are skipped, not caught "
                "up"},
    {EMITTER("paused"), .type = ISK_KEY_BOOL, EM(motion.paused), .dflt = "false", .live = ALL,
     .meaning = "true: its particles stand still and do not age, nothing is born"},
    {EMITTER("bounded"), .type = ISK_KEY_BOOL, EM(motion.bounded), .dflt = "true", .live = ALL,
     .meaning = "the walls of [bounds] apply"},
    {EMITTER("draw_before_bounce"), .type = ISK_KEY_BOOL, EM(motion.draw_before_bounce), .dflt = "false", .live = ALL,
     .meaning = "the thesis examples' order: draw, then the walls"},
    {EMITTER("gravity_multiplier"), .type = ISK_KEY_NUMBER, EM(motion.gravity_multiplier), STRENGTH, .dflt = "1",
     .live = ALL,
     .meaning = "scales gravity forces for these particles"},
    {EMITTER("weight"), .type = ISK_KEY_NUMBER, EM(motion.weight), STRENGTH, .dflt = "0", .live = ALL,
     .meaning = "buoyancy: an upward acceleration (fire thesis)"},
    {EMITTER("slowing"), .type = ISK_KEY_NUMBER, EM(motion.slowing), GE(0), .dflt = "0", .live = ALL,
     .meaning = "damping per second: v *= max(0, 1 - slowing*dt)"},
    {EMITTER("slow_faithful"), .type = ISK_KEY_BOOL, EM(motion.slow_faithful), .dflt = "false", .live = ALL,
     .meaning = "the fire thesis's order: v += a*dt; v *= (1 - slowing*dt); p += v*dt (only with constant "
                "accelerations and semi-euler)"},
    {EMITTER("osc_omega"), .type = ISK_KEY_PAIR, EM(motion.osc_omega_min), STRENGTH, .what = "min, max", .dflt = "0, 0",
     .live = ALL,
     .meaning = "oscillation angular speed range, rad/s (0, 0: off; negative: the sway starts towards -x)"},
    {EMITTER("osc_amplitude"), .type = ISK_KEY_PAIR, EM(motion.osc_amplitude_min), IN(0, ISK_COORD_MAX),
     .what = "min, max", .dflt = "0, 0", .live = ALL,
     .meaning = "initial horizontal amplitude range, world units"},
    {EMITTER("osc_decay"), .type = ISK_KEY_NUMBER, EM(motion.osc_decay), GE(0), .dflt = "0", .live = ALL,
     .meaning = "amplitude *= max(0, 1 - decay*dt)"},
    {EMITTER("osc_faithful"), .type = ISK_KEY_BOOL, EM(motion.osc_faithful), .dflt = "false", .live = ALL,
     .meaning = "also add the offset change to vx (the fire thesis's code)"},
    {EMITTER("osc_table"), .type = ISK_KEY_ENUM, EM(motion.osc_table), NAMES(isk_sinlut_mode_names), NOTES(sine_notes),
     .words = table_words, .dflt = "floor", .live = ALL, .meaning = "the sine the oscillation reads"},
    {EMITTER("osc_random_phase"), .type = ISK_KEY_BOOL, EM(motion.osc_random_phase), .dflt = "false", .live = ALL,
     .meaning = "start each particle at a random phase (its offset preset, so it does not jump)"},
    {EMITTER("integrator"), .type = ISK_KEY_ENUM, EM(motion.integrator), NAMES(isk_integrator_names),
     .words = inherit_words, .dflt = "scene", .live = ALL, .meaning = "time integrator (scene: the scene's)"},
    {EMITTER("substeps"), .type = ISK_KEY_WHOLE, EM(motion.substeps), IN(1, 1000), .words = scene_words,
     .dflt = "scene", .live = ALL, .meaning = "substeps per frame (scene: the scene's)"},
    {EMITTER("draw"), .type = ISK_KEY_ENUM, EM(look.draw), NAMES(isk_draw_mode_names), NOTES(draw_notes), .dflt = "dot",
     .live = ALL, .meaning = "how a particle is drawn"},
    {EMITTER("sprite"), .type = ISK_KEY_ENUM, EM(look.sprite), NAMES(isk_sprite_kind_names), .dflt = "linear",
     .live = ALL, .meaning = "sprite shape (include/iskra/sprite.h)"},
    {EMITTER("size"), .type = ISK_KEY_NUMBER, EM(look.size), GT_LE(0, 1e6), .dflt = "0.1", .live = ALL,
     .meaning = "disc/sprite diameter, world units"},
    {EMITTER("color"), .type = ISK_KEY_COLOR, EM(look.color), .dflt = "yellow", .live = ALL,
     .meaning = "the particles' colour"},
    {EMITTER("blend"), .type = ISK_KEY_ENUM, EM(look.blend), NAMES(isk_blend_names), .dflt = "over", .live = ALL,
     .meaning = "how they combine with the canvas (include/iskra/blend.h)"},
    {EMITTER("color_over_life"), .type = ISK_KEY_COLOR_STOPS, EM(look.color_over_life), .dflt = "off", .live = ALL,
     .meaning = "replaces color by normalised age"},
    {EMITTER("alpha_over_life"), .type = ISK_KEY_SCALAR_STOPS, EM(look.alpha_over_life), IN(0, 1), .dflt = "off",
     .live = ALL, .meaning = "multiplies the colour's alpha"},
    {EMITTER("size_over_life"), .type = ISK_KEY_SCALAR_STOPS, EM(look.size_over_life), IN(0, 1e6), .dflt = "off",
     .live = ALL, .meaning = "multiplies size"},
    {EMITTER("order"), .type = ISK_KEY_WHOLE, EM(look.order), IN(-1000000, 1000000), .dflt = "0",
     .dflt_doc = "its definition index", .live = ALL,
     .meaning = "draw order (lower first; ties by definition order)"},
    {EMITTER("draw_order"), .type = ISK_KEY_ENUM, EM(look.draw_order), NAMES(isk_draw_order_names),
     NOTES(draw_order_notes), .dflt = "newest", .live = ALL,
     .meaning = "which of the emitter's own particles are on top (its trails keep the store's order)"},

    /* [emitter NAME] motion (src/sim/stage_field.c, src/scene/effect_stream.c) */
    {EMITTER("radial_accel"), .type = ISK_KEY_NUMBER, EM(motion.radial_accel), STRENGTH, .dflt = "0", .live = ALL,
     .meaning =
         "units/s^2 away from the emitter's current position (negative: towards it; exactly on it, along the velocity)"},
    {EMITTER("tangential_accel"), .type = ISK_KEY_NUMBER, EM(motion.tangential_accel), STRENGTH, .dflt = "0",
     .live = ALL,
     .meaning = "units/s^2 perpendicular to the radial direction, counter-clockwise for positive (orbits)"},
    {EMITTER("radial_accel_range"), .type = ISK_KEY_NUMBER, EM(motion.radial_accel_range), IN(0, ISK_STRENGTH_MAX),
     .dflt = "0", .live = ALL, .meaning = "radial = radial_accel + U*radial_accel_range, each particle its own"},
    {EMITTER("tangential_accel_range"), .type = ISK_KEY_NUMBER, EM(motion.tangential_accel_range),
     IN(0, ISK_STRENGTH_MAX), .dflt = "0", .live = ALL,
     .meaning = "tangential = tangential_accel + U*tangential_accel_range, each particle its own"},
    {EMITTER("wind_range"), .type = ISK_KEY_VECTOR, EM(motion.wind_range), STRENGTH, .dflt = "0, 0", .live = ALL,
     .meaning = "each particle's own constant acceleration (U1*x, U2*y), units/s^2, on top of its forces"},
    {EMITTER("slowing_range"), .type = ISK_KEY_NUMBER, EM(motion.slowing_range), GE(0), .dflt = "0", .live = ALL,
     .meaning = "slowing = slowing + U*slowing_range, each particle its own (not with slow_faithful)"},
    {EMITTER("emitter_velocity"), .type = ISK_KEY_VECTOR, EM(born.emitter_velocity), .applies = S_S, SPEED,
     .dflt = "0, 0", .live = S_S,
     .meaning = "the emitter moves: position(t) = position + v*t, births placed on the path at their exact times"},
    {EMITTER("space"), .type = ISK_KEY_ENUM, EM(born.space), .applies = S_S, NAMES(isk_space_names), NOTES(space_notes),
     .dflt = "world", .live = S_S, .meaning = "whether the particles follow the emitter's motion"},
    {EMITTER("duration"), .type = ISK_KEY_NUMBER, EM(born.duration), .applies = S_S, IN(0, ISK_DURATION_MAX),
     .dflt = "0", .what = "a number of seconds", .meaning = "emit for this many seconds from start, then stop "
                                                             "(0: forever); floor(rate*duration) per cycle"},
    {EMITTER("loop"), .type = ISK_KEY_BOOL, EM(born.loop), .applies = S_S, .dflt = "false",
     .meaning = "with a duration: start again every duration seconds, bursts included"},
    {EMITTER("prewarm"), .type = ISK_KEY_NUMBER, EM(born.prewarm), .applies = S_S, IN(0, ISK_PREWARM_MAX), .dflt = "0",
     .what = "a number of seconds",
     .meaning = "simulated before frame 0 (rounded to whole frames), so the effect is already going in frame 0"},
    /* ---- looks: rotation, spin, variation, textures and flipbooks ---- */
    {EMITTER("rotation"), .type = ISK_KEY_ANGLE, EM(look.rotation), IN(-3600, 3600), .dflt = "0", .live = ALL,
     .meaning = "initial angle, counter-clockwise (textures and streaks; a round sprite looks the same at every "
                "angle)"},
    {EMITTER("rotation_range"), .type = ISK_KEY_ANGLE, EM(look.rotation_range), IN(0, 3600), .dflt = "0", .live = ALL,
     .meaning = "angle = rotation + U*rotation_range"},
    {EMITTER("spin"), .type = ISK_KEY_ANGLE, EM(look.spin), IN(-ISK_SPIN_MAX, ISK_SPIN_MAX), .dflt = "0", .live = ALL,
     .what = "degrees per second", .meaning = "angular speed, degrees per second (counter-clockwise)"},
    {EMITTER("spin_range"), .type = ISK_KEY_ANGLE, EM(look.spin_range), IN(0, ISK_SPIN_MAX), .dflt = "0", .live = ALL,
     .what = "degrees per second", .meaning = "angular speed = spin + U*spin_range"},
    {EMITTER("spin_end"), .type = ISK_KEY_ANGLE, EM(look.spin_end), IN(-ISK_SPIN_MAX, ISK_SPIN_MAX),
     .words = spin_end_words, .dflt = "none", .live = ALL, .what = "degrees per second",
     .meaning = "the angular speed changes linearly over the life by spin_end - spin, ending at spin_end (plus "
                "its U*spin_range); none: it stays"},
    {EMITTER("align"), .type = ISK_KEY_ENUM, EM(look.align), NAMES(isk_align_names), NOTES(align_notes), .dflt = "none",
     .live = ALL, .meaning = "how a particle is turned"},
    {EMITTER("size_range"), .type = ISK_KEY_NUMBER, EM(look.size_range), IN(0, 1e6), .dflt = "0", .live = ALL,
     .meaning = "size = size + U*size_range, world units (fixed at birth)"},
    {EMITTER("color_pick"), .type = ISK_KEY_COLOR_STOPS, EM(look.color_pick), .dflt = "off", .live = ALL,
     .meaning = "base colour drawn from these stops at a uniform t at birth (color_over_life multiplies it)"},
    {EMITTER("texture"), .type = ISK_KEY_TEXT, EM(look.texture), .aux = sizeof(((isk_emitter_def *)0)->look.texture),
     .dflt = "", .dflt_doc = "none", .create_only = 1,
     .meaning = "a PNG drawn as each particle (relative to the scene file), turned, scaled to size, tinted by "
                "its colour"},
    {EMITTER("texture_grid"), .type = ISK_KEY_VECTOR, EM(look.texture_grid), IN(1, ISK_TEXTURE_MAX_GRID),
     .what = "cols, rows", .dflt = "1, 1", .create_only = 1,
     .meaning = "the texture is a sprite sheet of cols x rows frames, played over the life"},
    {EMITTER("texture_fps"), .type = ISK_KEY_NUMBER, EM(look.texture_fps), IN(0, 1e6), .dflt = "0", .live = ALL,
     .meaning = "frames per second of age, wrapping (0: once over the life)"},
    {EMITTER("flipbook_random_start"), .type = ISK_KEY_BOOL, EM(look.flipbook_random_start), .dflt = "false",
     .live = ALL,
     .meaning = "each particle's flipbook starts at a random frame and plays on from it, wrapping (the particles "
                "already there start at frame 0)"},
    {EMITTER("texture_origin"), .type = ISK_KEY_VECTOR, EM(look.texture_origin), IN(-16, 16), .what = "x, y",
     .dflt = "0.5, 0.5", .live = ALL,
     .meaning = "the point of the texture (fractions of a frame from its top-left corner) placed on the particle "
                "and turned about (0.5, 0.5: its centre)"},
    /* [emitter NAME]: sub-emitters and trails */
    {EMITTER("on_death"), .type = ISK_KEY_REF, EM(events.on_death), .refers = ISK_SECTION_EMITTER, .dflt = "",
     .dflt_doc = "none", .live = ALL,
     .meaning = "a sub-emitter (source = sub) that fires where one of these particles dies (its life ends, or a "
                "killing deflector takes it)"},
    {EMITTER("on_hit"), .type = ISK_KEY_REF, EM(events.on_hit), .refers = ISK_SECTION_EMITTER, .dflt = "",
     .dflt_doc = "none", .live = ALL,
     .meaning = "a sub-emitter (source = sub) that fires where one of these particles bounces on a wall or a "
                "deflector (once per bounce)"},
    {EMITTER("inherit"), .type = ISK_KEY_NUMBER, EM(launch.inherit), .applies = S_SUB, IN(0, 1), .dflt = "0",
     .live = ALL,
     .meaning = "the fraction of the parent's velocity the children keep, added to their launch velocity (1: "
                "all of it; more would make a chain faster at every generation)"},
    {EMITTER("trail"), .type = ISK_KEY_WHOLE, EM(look.trail), IN(0, ISK_TRAIL_MAX), .dflt = "0", .live = ALL,
     .meaning = "a ribbon through each particle's last N positions (one per frame), drawn under the particle "
                "(0: none)"},
    {EMITTER("trail_width"), .type = ISK_KEY_NUMBER, EM(look.trail_width), GT_LE(0, 4096), .dflt = "1", .live = ALL,
     .meaning = "the ribbon's width in pixels (the same at every zoom, as a dot)"},
    {EMITTER("trail_fade"), .type = ISK_KEY_NUMBER, EM(look.trail_fade), IN(0, 1), .dflt = "1", .live = ALL,
     .meaning = "how much the ribbon fades towards its oldest point: alpha there = the colour's alpha * (1 - "
                "trail_fade)"},

    /* [drawing NAME] */
    {DRAWING("kind"), .type = ISK_KEY_ENUM, DRW(kind), NAMES(isk_drawing_kind_names), .dflt = "polyline",
     .dflt_doc = "the NAME when it is a kind, else polyline with points, disc with radius, text with text",
     .create_only = 1, .meaning = "what the drawing is"},
    {DRAWING("units"), .type = ISK_KEY_ENUM, DRW(pixels), NAMES(isk_units_names), NOTES(units_notes),
     .dflt = "world", .live = ALL, .meaning = "what its coordinates are"},
    {DRAWING("points"), .type = ISK_KEY_POINTS, DRW(points), .aux = offsetof(isk_drawing_def, npoints),
     .applies = D_LINE | D_POLY, .required = D_LINE | D_POLY, IN(2, 64), .dflt = "", .live = ALL,
     .meaning = "x0, y0, x1, y1, ...: a polyline's path (2..64 points), a polygon's corners (3..64)"},
    {DRAWING("closed"), .type = ISK_KEY_BOOL, DRW(closed), .applies = D_LINE, .dflt = "false", .live = ALL,
     .meaning = "join the last point to the first"},
    {DRAWING("hairline"), .type = ISK_KEY_BOOL, DRW(hairline), .applies = D_LINE, .dflt = "false", .live = ALL,
     .meaning = "draw as the browser's canvas does at width 1 (a diagonal stays 2 px wide, no joins); false: the "
                "exact-area width-1 stroke with miter joins"},
    {DRAWING("position"), .type = ISK_KEY_VECTOR, DRW(x), .applies = D_DISC | D_TEXT | D_SPR,
     .required = D_DISC | D_TEXT | D_SPR, .dflt = "0, 0", .live = ALL,
     .meaning = "centre / text baseline start (pixels: top-left)"},
    {DRAWING("sprite"), .type = ISK_KEY_ENUM, DRW(sprite), .applies = D_SPR, NAMES(isk_sprite_kind_names),
     .dflt = "linear", .live = ALL, .meaning = "sprite shape"},
    {DRAWING("size"), .type = ISK_KEY_NUMBER, DRW(size), .applies = D_SPR, .required = D_SPR, GT_LE(0, 1e9),
     .dflt = "1", .live = ALL, .meaning = "the sprite's diameter"},
    {DRAWING("radius"), .type = ISK_KEY_NUMBER, DRW(r), .applies = D_DISC, .required = D_DISC, GT_LE(0, 1e9),
     .dflt = "1", .live = ALL, .meaning = "the disc's radius"},
    {DRAWING("text"), .type = ISK_KEY_TEXT, DRW(text), .aux = sizeof(((isk_drawing_def *)0)->text),
     .applies = D_TEXT, .required = D_TEXT, .dflt = "", .live = ALL, .meaning = "what to write"},
    {DRAWING("scale"), .type = ISK_KEY_WHOLE, DRW(scale), .applies = D_TEXT, IN(1, 64), .dflt = "1", .live = ALL,
     .meaning = "font scale"},
    {DRAWING("color"), .type = ISK_KEY_COLOR, DRW(color), .dflt = "white", .live = ALL, .meaning = "its colour"},
    {DRAWING("blend"), .type = ISK_KEY_ENUM, DRW(blend), NAMES(isk_blend_names), .dflt = "over", .live = ALL,
     .meaning = "how it combines with the canvas"},

    /* [click] */
    {CLICK("enabled"), .type = ISK_KEY_BOOL, CLK(enabled), .dflt = "false",
     .dflt_doc = "true when the scene has a [click] section", .live = ALL,
     .meaning = "a click explodes (isk_effect_click does nothing otherwise)"},
    {CLICK("explosion"), .type = ISK_KEY_ENUM, CLK(explosion), NAMES(isk_explosion_names), .dflt = "coulomb",
     .live = ALL, .meaning = "what a click sets off"},
    {CLICK("count"), .type = ISK_KEY_COUNT, CLK(count), IN(1, MAXP), .dflt = "1000", .live = ALL,
     .meaning = "particles per click (at most the receiving emitter's limit)"},
    {CLICK("emitter"), .type = ISK_KEY_REF, CLK(emitter), .refers = ISK_SECTION_EMITTER, .dflt = "", .dflt_doc = "the first emitter",
     .live = ALL, .meaning = "the emitter whose particles the click adds to (they get its forces, walls, drawing)"},
    {CLICK("at_start"), .type = ISK_KEY_POINT, CLK(x), .aux = offsetof(isk_click_def, at_start), COORD,
     .dflt = "none",
     .meaning = "also click once at this world point when the scene starts (the thesis's simulator scenes "
                "start with a click)"},
    {CLICK("after_frames"), .type = ISK_KEY_LONG, CLK(after_frames), IN(0, 1e8), .dflt = "0",
     .meaning = "with at_start: the click comes after this many frames (the thesis's scenes run one frame of "
                "the layer alone: 1)"},

    /* [probe NAME]: fixed when the effect is created (a probe's readings
     * start with the effect) */
    {PROBE("kind"), .type = ISK_KEY_ENUM, PRB(kind), NAMES(isk_probe_kind_names), NOTES(probe_kind_notes),
     .dflt = "gate", .dflt_doc = "the NAME when it is a kind", .create_only = 1, .meaning = "what the probe measures"},
    {PROBE("segment"), .type = ISK_KEY_NUMBERS4, PRB(segment), .applies = P_GATE, .required = P_GATE,
     .what = "x0, y0, x1, y1", IN(-ISK_COORD_MAX, ISK_COORD_MAX), .dflt = "0, 0, 1, 0", .create_only = 1,
     .meaning = "the gate's end points, which must differ; forward is from the left of x0, y0 -> x1, y1 to its "
                "right"},
    {PROBE("window"), .type = ISK_KEY_NUMBER, PRB(window), .applies = P_GATE, GT_LE(0, 3600), .dflt = "1",
     .create_only = 1, .meaning = "seconds: the rates count the crossings of the last window (whole frames)"},
    {PROBE("rect"), .type = ISK_KEY_NUMBERS4, PRB(rect), .applies = P_REGION, .required = P_REGION,
     .what = "xmin, xmax, ymin, ymax", IN(-ISK_COORD_MAX, ISK_COORD_MAX), .dflt = "-1, 1, -1, 1", .create_only = 1,
     .meaning = "the region, world units (xmin < xmax, ymin < ymax)"},
    {PROBE("of"), .type = ISK_KEY_ENUM, PRB(of), .applies = P_HIST, NAMES(isk_probe_of_names), NOTES(probe_of_notes),
     .dflt = "speed", .create_only = 1, .meaning = "what the histogram counts"},
    {PROBE("bins"), .type = ISK_KEY_WHOLE, PRB(bins), .applies = P_HIST, IN(1, ISK_PROBE_MAX_BINS), .dflt = "20",
     .create_only = 1, .meaning = "how many equal bins divide the range"},
    {PROBE("range"), .type = ISK_KEY_PAIR, PRB(range), .applies = P_HIST, .required = P_HIST,
     IN(-1e9, 1e9), .dflt = "0, 1", .create_only = 1,
     .meaning = "lo, hi (lo < hi): the values the bins cover; those outside count as under or over"},
    {PROBE("emitters"), .type = ISK_KEY_REFS, PRB(emitters), .aux = offsetof(isk_probe_def, nemitters),
     .refers = ISK_SECTION_EMITTER, .dflt = "all", .create_only = 1,
     .meaning = "the emitters whose particles it measures"},
    {PROBE("show"), .type = ISK_KEY_BOOL, PRB(show), .dflt = "true", .create_only = 1,
     .meaning = "draw it over the particles: a gate as its line and counts, a region as its outline, a "
                "histogram as bars at the bottom left"},
    {PROBE("color"), .type = ISK_KEY_COLOR, PRB(color), .dflt = "cyan", .create_only = 1,
     .meaning = "the colour it is drawn in"},
};

int isk_key_count(void) { return N(keys); }

const isk_key *isk_key_at(int i) { return i >= 0 && i < N(keys) ? &keys[i] : NULL; }

const isk_key *isk_key_find(isk_section_kind section, const char *name)
{
    for (int i = 0; name && i < N(keys); i++)
        if (keys[i].section == section && !strcmp(keys[i].name, name))
            return &keys[i];
    return NULL;
}

/* ---- sections ---------------------------------------------------------------- */

typedef struct section_info {
    const char *name;
    int named;
    const char *kind_key;
    const char *const *kind_names;
    int nkinds;
} section_info;

static const section_info sections[ISK_SECTION_COUNT] = {
    [ISK_SECTION_SCENE] = {"scene", 0, NULL, NULL, 0},
    [ISK_SECTION_VIEW] = {"view", 0, "", isk_view_kind_names, ISK_VIEWDEF_COUNT},
    [ISK_SECTION_FORCE] = {"force", 1, "kind", isk_force_kind_names, ISK_FORCE_KIND_COUNT},
    [ISK_SECTION_DEFLECTOR] = {"deflector", 1, NULL, NULL, 0},
    [ISK_SECTION_BOUNDS] = {"bounds", 0, "mode", isk_bounce_mode_names, ISK_BOUNCE_MODE_COUNT},
    [ISK_SECTION_EMITTER] = {"emitter", 1, "source", isk_source_names, ISK_SOURCE_KIND_COUNT},
    [ISK_SECTION_DRAWING] = {"drawing", 1, "kind", isk_drawing_kind_names, ISK_DRAWING_KIND_COUNT},
    [ISK_SECTION_CLICK] = {"click", 0, NULL, NULL, 0},
    [ISK_SECTION_PROBE] = {"probe", 1, "kind", isk_probe_kind_names, ISK_PROBE_KIND_COUNT},
};

const char *isk_section_name(isk_section_kind s)
{
    return (unsigned)s < ISK_SECTION_COUNT ? sections[s].name : NULL;
}

int isk_section_named(isk_section_kind s) { return (unsigned)s < ISK_SECTION_COUNT && sections[s].named; }

int isk_section_find(const char *type)
{
    for (int i = 0; type && i < ISK_SECTION_COUNT; i++)
        if (!strcmp(sections[i].name, type))
            return i;
    return -1;
}

const char *isk_section_kind_key(isk_section_kind s)
{
    return (unsigned)s < ISK_SECTION_COUNT ? sections[s].kind_key : NULL;
}

const char *const *isk_section_kind_names(isk_section_kind s, int *n)
{
    int k = (unsigned)s < ISK_SECTION_COUNT ? sections[s].nkinds : 0;
    if (n)
        *n = k;
    return k ? sections[s].kind_names : NULL;
}

const char *isk_key_type_name(isk_key_type t) /* "?" when out of range */
{
    static const char *const names[ISK_KEY_TYPE_COUNT] = {
        [ISK_KEY_NUMBER] = "number",       [ISK_KEY_WHOLE] = "whole",         [ISK_KEY_LONG] = "whole",
        [ISK_KEY_COUNT] = "whole",         [ISK_KEY_SEED] = "whole",          [ISK_KEY_BOOL] = "boolean",
        [ISK_KEY_COLOR] = "colour",        [ISK_KEY_ENUM] = "enum",           [ISK_KEY_VECTOR] = "vector",
        [ISK_KEY_POINT] = "vector",        [ISK_KEY_ANGLE] = "angle",         [ISK_KEY_PAIR] = "2 numbers",
        [ISK_KEY_NUMBERS4] = "4 numbers",  [ISK_KEY_COLOR_STOPS] = "colour stops",
        [ISK_KEY_SCALAR_STOPS] = "stops",  [ISK_KEY_TEXT] = "text",           [ISK_KEY_SIDES] = "sides",
        [ISK_KEY_POINTS] = "points",       [ISK_KEY_REFS] = "names",          [ISK_KEY_REF] = "name",
    };
    return (unsigned)t < ISK_KEY_TYPE_COUNT ? names[t] : "?";
}

/* ---- rows in words (tables, `iskra keys`, the documentation) ---------------- */

int isk_key_choices(const isk_key *k, const char **out, int max)
{
    int m = 0;
    if (!out)
        return 0;
    for (int i = 0; k && i < k->nnames && m < max; i++)
        out[m++] = k->names[i];
    for (int i = 0; k && k->words && k->words[i].word && m < max; i++)
        out[m++] = k->words[i].word;
    return m;
}

void isk_key_range_text(const isk_key *k, char *buf, size_t n)
{
    if (!buf || n == 0)
        return;
    buf[0] = 0;
    if (!k)
        return;
    if (k->type == ISK_KEY_SEED) {
        snprintf(buf, n, "0..2^64-1");
        return;
    }
    if (k->names) { /* enums, sides, and text that is a name from a list (`preset`) */
        const char *all[64];
        int m = isk_key_choices(k, all, 64);
        size_t used = 0;
        for (int i = 0; i < m; i++)
            used += (size_t)snprintf(buf + used, used < n ? n - used : 0, "%s%s", i ? ", " : "", all[i]);
        return;
    }
    if (k->lo_bound == ISK_BOUND_INCL && k->hi_bound == ISK_BOUND_INCL)
        snprintf(buf, n, "%.15g..%.15g", k->min, k->max);
    else if (k->lo_bound && k->hi_bound)
        snprintf(buf, n, "%s %.15g, %s %.15g", k->lo_bound == ISK_BOUND_INCL ? ">=" : ">", k->min,
                 k->hi_bound == ISK_BOUND_INCL ? "<=" : "<", k->max);
    else if (k->lo_bound)
        snprintf(buf, n, "%s %.15g", k->lo_bound == ISK_BOUND_INCL ? ">=" : ">", k->min);
    else if (k->hi_bound)
        snprintf(buf, n, "%s %.15g", k->hi_bound == ISK_BOUND_INCL ? "<=" : "<", k->max);
    size_t len = strlen(buf);
    if (k->type == ISK_KEY_POINTS)
        snprintf(buf + len, n - len, " points");
    if (k->words) { /* the first word; the others are synonyms */
        len = strlen(buf);
        snprintf(buf + len, n - len, "%s or %s", len ? "" : "any", k->words[0].word);
    }
}


void isk_key_kinds_text(const isk_key *k, unsigned mask, char *buf, size_t n)
{
    if (!buf || n == 0)
        return;
    buf[0] = 0;
    if (!k)
        return;
    int count;
    const char *const *names = isk_section_kind_names(k->section, &count);
    buf[0] = 0;
    if (!names || mask == 0 || mask == ALL)
        return;
    size_t used = 0;
    int any = 0;
    for (int i = 0; i < count; i++)
        if (mask >> i & 1u) {
            used += (size_t)snprintf(buf + used, used < n ? n - used : 0, "%s%s", any ? ", " : "", names[i]);
            any = 1;
        }
}

void isk_key_default_text(const isk_key *k, char *buf, size_t n)
{
    if (!buf || n == 0)
        return;
    if (!k)
        buf[0] = 0;
    else if (k->required && k->required == (k->applies ? k->applies : k->required))
        snprintf(buf, n, "required");
    else if (k->dflt_doc)
        snprintf(buf, n, "%s", k->dflt_doc);
    else
        snprintf(buf, n, "%s", k->dflt ? k->dflt : "");
}

void isk_key_live_text(const isk_key *k, char *buf, size_t n)
{
    if (!buf || n == 0)
        return;
    if (!k) {
        buf[0] = 0;
        return;
    }
    unsigned applies = k->applies ? k->applies : ALL;
    if (k->create_only)
        snprintf(buf, n, "no");
    else if (k->live == 0)
        snprintf(buf, n, "at reset");
    else if ((k->live & applies) == applies || k->live == ALL)
        snprintf(buf, n, "yes");
    else {
        char kinds[120];
        isk_key_kinds_text(k, k->live & applies, kinds, sizeof kinds);
        snprintf(buf, n, "%s (others at reset)", kinds);
    }
}

void isk_key_meaning_text(const isk_key *k, char *buf, size_t n)
{
    if (!buf || n == 0)
        return;
    buf[0] = 0;
    if (!k)
        return;
    size_t used = (size_t)snprintf(buf, n, "%s", k->meaning);
    for (int i = 0; k->notes && i < k->nnames; i++)
        used += (size_t)snprintf(buf + (used < n ? used : n), used < n ? n - used : 0, "%s%s = %s",
                                 i ? "; " : ": ", k->names[i], k->notes[i] ? k->notes[i] : "?");
}
