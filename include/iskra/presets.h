/* SPDX-License-Identifier: MIT */
/* iskra/presets.h — ready-made stream emitters: fire, smoke, sparks,
 * fountain, snow, explosion, galaxy, fireworks, rain and magic.
 *
 * Each function appends one emitter to an effect definition (and the items
 * of its own it needs, named after it and created or updated: a GRAVITY
 * force "<name>_gravity", a turbulence, a floor deflector, a sub-emitter
 * "<name>_burst"), fills every field the effect needs and returns the
 * emitter's index, or -1 (NULL definition, non-finite position, scale not a
 * finite number in (0, ISK_PRESET_SCALE_MAX], or no room for an item).
 * Adjust the returned emitter freely afterwards:
 *
 * Example:
 *
 *     isk_effect_def d;
 *     isk_effect_def_init(&d);
 *     int f = isk_preset_fire(&d, NULL, isk_vec2_make(0, -6), 3.0);
 *     int s = isk_preset_smoke(&d, NULL, isk_vec2_make(0, -4), 3.0);
 *     if (f < 0 || s < 0) { isk_effect_def_free(&d); return 1; }
 *     d.emitters[s].look.order = -1;      // smoke behind the flame
 *     isk_effect *fx; isk_error err;
 *     isk_status st = isk_effect_create(&fx, &d, &err);
 *     isk_effect_def_free(&d);
 *     if (st != ISK_OK) { fprintf(stderr, "%s\n", err.message); return 1; }
 *     for (int i = 0; i < 60 && st == ISK_OK; i++) st = isk_effect_step(fx);   // one second
 *     printf("%zu particles after 1 s\n", isk_effect_particle_count(fx));
 *     isk_effect_destroy(fx);
 *     return st != ISK_OK;
 *
 * Units.  The numbers start from cocos2d-x's built-in presets
 * (CCParticleExamples.cpp: ParticleFire, ParticleSmoke, ParticleFireworks,
 * ParticleSnow, ParticleExplosion), which are in points (screen pixels of a
 * 480x320 design) and seconds.  Here lengths, speeds and accelerations are
 * multiplied by scale/100: `scale` is the number of world units per 100
 * cocos2d points, so scale = 1 makes the cocos fire 0.8 units wide and about
 * 1.8 high, and the cocos screen 4.8 x 3.2 units.  Times (life, rates) are
 * kept.  `pos` is the emitter's centre (snow: the middle of the line it
 * falls from).  `name` NULL gives the preset's own name ("fire", ...).
 *
 * The six cocos2d presets (fire ... explosion) predate size_range,
 * color_pick, radial and tangential acceleration, textures and duration,
 * and keep what was done then, so their images stay: the mean of cocos's
 * size and colour variances, start -> end size constant (as in every cocos
 * preset used here), snow's +-1 radial/tangential jitter as a gentle
 * oscillation, radial-gradient sprites, the explosion's 0.1 s of emission
 * as one burst.  The newer presets (galaxy, fireworks, rain, magic) use
 * those keys.  cocos2d
 * colour ramps are two stops, start -> end; presets add what reads better
 * where noted (an alpha fade on smoke).  Rates and pool sizes are cocos's:
 * rate = total/life, capacity = total, so a full pool drops spawns (counted
 * by isk_effect_dropped) exactly where cocos2d stops emitting.
 *
 * Presets use the sound modes (fractional rate accumulator, back-dated
 * births, the runtime's slowing order); switch the emitter's rate_mode,
 * birth, osc_faithful, slow_faithful for the fire thesis's behaviour.
 * docs/fire.md has the table of every number.
 */
#ifndef ISKRA_PRESETS_H
#define ISKRA_PRESETS_H

#include "iskra/effect.h"
#include "iskra/limits.h"

#ifdef __cplusplus
extern "C" {
#endif

/* cocos2d ParticleFire: additive, orange (194, 64, 31) fading to black over
 * life 3 +- 0.25 s, 250 particles at 83.3/s from a 0.8 x 0.4 rectangle,
 * speed 0.6 +- 0.2 straight up +- 10 degrees, size 0.54, no gravity.  (Times
 * scale/100 for lengths, as above.) */
/* The presets by name (the names scene files give `preset`): how many,
 * the i-th's name (NULL out of range), the index of a name (-1: none). */
int isk_preset_count(void);
const char *isk_preset_name(int i);
int isk_preset_find(const char *name);

/* Appends the preset `preset` as an emitter named `name` (NULL: the
 * preset's name) at pos, as the functions below do; -1 on bad input. */
int isk_preset_add(isk_effect_def *d, const char *preset, const char *name, isk_vec2 pos, double scale);

/* Refills the existing emitter d->emitters[emitter] from the preset: every
 * field back to its default, then the preset's, keeping the emitter's name,
 * line, draw order and position (what `preset = NAME, SCALE` does in a
 * scene file); e->preset records the name.  Errors: ISK_ERR_NULL,
 * ISK_ERR_RANGE (unknown preset, emitter out of range, scale not in
 * (0, ISK_PRESET_SCALE_MAX]), ISK_ERR_FULL (no room for its forces),
 * ISK_ERR_NOMEM; on error the definition is as it was. */
isk_status isk_preset_apply(isk_effect_def *d, int emitter, const char *preset, double scale);

int isk_preset_fire(isk_effect_def *d, const char *name, isk_vec2 pos, double scale);

/* cocos2d ParticleSmoke: overpaint, grey (204) darkening to black over life
 * 4 +- 1 s, 200 particles at 50/s from a 0.4-wide line, speed 0.25 +- 0.1 up
 * +- 5 degrees, size 0.6; plus an alpha fade 0.5 -> 0 (cocos2d's smoke
 * texture is translucent; iskra's sprites are not), and ours: its own
 * TURBULENCE force "<name>_turbulence" (strength 15, scale 30, speed 0.25/s)
 * that stirs the plume into wisps. */
int isk_preset_smoke(isk_effect_def *d, const char *name, isk_vec2 pos, double scale);

/* Sparks (no cocos2d preset; modelled on ParticleFireworks with hot
 * colours): additive, white-yellow -> orange -> dark red fading out over
 * life 1 +- 0.4 s, 60/s from a disc of radius 0.15, speed 1.5..3 up +- 35
 * degrees, gravity 3, size 0.1, capacity 200. */
int isk_preset_sparks(isk_effect_def *d, const char *name, isk_vec2 pos, double scale);

/* cocos2d ParticleFireworks (a fountain): 1500 particles at 428.6/s from a
 * point, speed 1.8 +- 0.5 up +- 20 degrees, gravity 0.9, life 3.5 +- 1 s,
 * size 0.08, overpaint; cocos2d's random grey-to-white colours (0.5 +- 0.5)
 * become a water blue fading to 20 % alpha (cocos2d's end alpha 0.2). */
int isk_preset_fountain(isk_effect_def *d, const char *name, isk_vec2 pos, double scale);

/* cocos2d ParticleSnow: 700 particles at 10/s from a line 4.8 wide (the
 * cocos screen), speed 0.05 +- 0.01 down +- 5 degrees, gravity 0.01, life
 * 45 +- 15 s, size 0.1, white fading to transparent, overpaint; a slow
 * sideways sway (amplitude 0.05..0.15, 0.5..1.5 rad/s) stands in for
 * cocos2d's +-1 radial/tangential jitter. */
int isk_preset_snow(isk_effect_def *d, const char *name, isk_vec2 pos, double scale);

/* cocos2d ParticleExplosion: one burst of 700 at t = 0 in every direction,
 * speed 0.7 +- 0.4, life 5 +- 2 s, size 0.15, red (178, 25, 51) fading to
 * a transparent grey (128), overpaint, no gravity. */
int isk_preset_explosion(isk_effect_def *d, const char *name, isk_vec2 pos, double scale);

/* A galaxy (ours; cocos2d's ParticleGalaxy's radial and tangential
 * accelerations fill a round blob from its point): 3000 particles at 500/s
 * born at rest (+- 3) on a line 360 long through pos, pulled in by
 * radial_accel -40, turned counter-clockwise by tangential_accel 25 against
 * slowing 0.6, so the line's halves wind into two arms around a bright
 * core; life 6 +- 1 s, size 6, cocos's blue through violet to a warm white,
 * transparent at both ends, additive. */
int isk_preset_galaxy(isk_effect_def *d, const char *name, isk_vec2 pos, double scale);

/* Fireworks (ours; cocos2d's ParticleFireworks is the fountain): rockets at
 * 1.5/s from pos, up at 280..330 +- 15 degrees against a gravity of 150
 * ("<name>_gravity", shared with the sparks), life 1.1..1.5 s, each with a
 * 10-point trail 2 px wide; where a rocket dies (on_death) it bursts into
 * 120 sparks of its own sub-emitter "<name>_burst": a disc of speeds up to
 * 160 plus a quarter of the rocket's velocity (inherit 0.25), each spark's
 * colour picked (color_pick) from red, gold, green, cyan and violet and
 * fading from white over 1.2..1.8 s against slowing 0.8, with a 6-point
 * trail; additive.  Returns the rockets' index (the sparks follow it). */
int isk_preset_fireworks(isk_effect_def *d, const char *name, isk_vec2 pos, double scale);

/* cocos2d ParticleRain, with streaks and splashes (ours): drops from a line
 * 480 wide centred on pos, down at 380..460 (cocos's 130 +- 30 reads as
 * snow) +- 5 degrees, pushed by cocos's gravity (10, -10) as a wind force
 * "<name>_wind", drawn as streaks along their velocity (align = velocity),
 * size 5, blue-white (0.7, 0.8, 1) to half alpha, 60/s, life 0.85..1 s; they
 * land on their own deflector "<name>_floor", 320 below pos and 520 wide
 * (restitution 0.1), and every landing (on_hit) splashes 6 droplets of the
 * sub-emitter "<name>_splash": up +- 60 degrees at 60..130 under its own
 * gravity 300, 0.3..0.5 s, fading out, additive dots.  In a scene file the
 * floor stays where the preset put it (below the position it had then):
 * move it with a [deflector NAME_floor] section after the emitter. */
int isk_preset_rain(isk_effect_def *d, const char *name, isk_vec2 pos, double scale);

/* Magic (ours): a wand that moves at 120 to the right from pos
 * (emitter_velocity: its sparkles are placed on its path at their birth
 * times, so it leaves no gaps) and sheds 160 sparkles a second from a disc
 * of radius 10; they swirl around where the wand is now (tangential_accel
 * 300, radial_accel -150, slowing 1) with 10-point trails, spinning at
 * -180..180 degrees a second from a random angle (a round sprite shows no
 * spin: give the emitter a texture, as scenes/preset_magic.ini does), each
 * colour picked from violet, cyan and pink, white at first, fading out
 * over 0.8..1.4 s; additive. */
int isk_preset_magic(isk_effect_def *d, const char *name, isk_vec2 pos, double scale);

#ifdef __cplusplus
}
#endif

#endif
