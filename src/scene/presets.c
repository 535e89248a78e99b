/* SPDX-License-Identifier: MIT */
/* Ready-made emitters (iskra/presets.h): cocos2d-x's preset numbers in
 * world units.  Every number is documented in the header and docs/fire.md. */
#include "iskra/presets.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "iskra/limits.h"
#include "key_value.h"
#include "preset_list.h"

#define DEG (3.14159265358979323846 / 180.0)

/* The common part of every preset: a stream emitter with sprites. */
static void base(isk_emitter_def *e)
{
    e->born.source = ISK_SOURCE_STREAM;
    e->look.draw = ISK_DRAW_SPRITE;
    e->look.sprite = ISK_SPRITE_LINEAR;
    e->launch.kind = ISK_VELGEN_CONE;
}

/* The emitter's own force "<name>_<what>" of `kind`, added (or found, to be
 * updated) and referenced; NULL when there is no room.  The pointer lasts
 * until the next force is added (the array may move). */
static isk_force_def *own_force(isk_effect_def *d, int index, const char *what, isk_force_kind kind)
{
    char fname[ISK_NAME_MAX];
    snprintf(fname, sizeof fname, "%.*s_%s", (int)(ISK_NAME_MAX - 2 - strlen(what)), d->emitters[index].name, what);
    int f = isk_effect_def_find_force(d, fname);
    if (f < 0)
        f = isk_effect_def_add_force(d, fname, kind);
    if (f < 0 || isk_emitter_use_force(&d->emitters[index], f) != ISK_OK)
        return NULL;
    d->forces[f].kind = kind;
    return &d->forces[f];
}

static int own_gravity(isk_effect_def *d, int index, double g)
{
    isk_force_def *f = own_force(d, index, "gravity", ISK_FORCE_GRAVITY);
    if (f)
        f->g = g;
    return f != NULL;
}

/* The emitter's own sub-emitter "<name>_<what>" (source = sub), added or
 * found, back at the key table's defaults (keeping its name, line and
 * order); its index, -1 when there is no room.  Adding may move the
 * emitters: callers take their pointers after it. */
static int own_sub_emitter(isk_effect_def *d, int index, const char *what)
{
    char name[ISK_NAME_MAX];
    snprintf(name, sizeof name, "%.*s_%s", (int)(ISK_NAME_MAX - 2 - strlen(what)), d->emitters[index].name, what);
    int k = isk_effect_def_find_emitter(d, name);
    if (k < 0) {
        if (!isk_effect_def_add_emitter(d, name))
            return -1;
        k = d->nemitters - 1;
    } else {
        isk_emitter_def keep = d->emitters[k];
        isk__fx_section_defaults(ISK_SECTION_EMITTER, &d->emitters[k]);
        memcpy(d->emitters[k].name, keep.name, sizeof keep.name);
        d->emitters[k].line = keep.line;
        d->emitters[k].look.order = keep.look.order;
    }
    d->emitters[k].born.source = ISK_SOURCE_SUB;
    return k;
}

/* The emitter's own deflector "<name>_<what>": seg, added or found and
 * updated, and referenced; 0 when there is no room. */
static int own_deflector(isk_effect_def *d, int index, const char *what, isk_deflector seg)
{
    char name[ISK_NAME_MAX];
    snprintf(name, sizeof name, "%.*s_%s", (int)(ISK_NAME_MAX - 2 - strlen(what)), d->emitters[index].name, what);
    int k = isk_effect_def_find_deflector(d, name);
    if (k < 0)
        k = isk_effect_def_add_deflector(d, name, seg);
    if (k < 0)
        return 0;
    d->deflectors[k].seg = seg;
    return isk_emitter_use_deflector(&d->emitters[index], k) == ISK_OK;
}

static void stops3(isk_color_ramp *r, isk_color a, double tb, isk_color b, isk_color c)
{
    r->n = 3;
    r->stops[0] = (isk_color_stop){0.0, a};
    r->stops[1] = (isk_color_stop){tb, b};
    r->stops[2] = (isk_color_stop){1.0, c};
}

static void ramp2(isk_color_ramp *r, isk_color a, isk_color b)
{
    r->n = 2;
    r->stops[0].t = 0.0;
    r->stops[0].color = a;
    r->stops[1].t = 1.0;
    r->stops[1].color = b;
}

static int fill_fire(isk_effect_def *d, int i, double u)
{
    isk_emitter_def *e = &d->emitters[i];
    base(e);
    e->born.shape = ISK_SHAPE_RECT; /* posVar (40, 20) */
    e->born.shape_a = 40 * u;
    e->born.shape_b = 20 * u;
    e->launch.angle = 90 * DEG;     /* 90 +- 10 degrees */
    e->launch.spread = 20 * DEG;
    e->launch.speed_min = 40 * u;   /* 60 +- 20 */
    e->launch.speed_max = 80 * u;
    e->life.seconds = 2.75;         /* 3 +- 0.25 s */
    e->life.range = 0.5;
    e->born.capacity = 250;         /* totalParticles */
    e->born.rate = 250.0 / 3.0;     /* total / life */
    e->look.size = 54 * u;          /* 54 (+-10) */
    e->look.color = isk_rgba(194, 64, 31, 255);  /* (0.76, 0.25, 0.12, 1) */
    ramp2(&e->look.color_over_life, e->look.color, isk_rgba(0, 0, 0, 255));
    e->look.blend = ISK_BLEND_ADD;
    return 1;
}

static int fill_smoke(isk_effect_def *d, int i, double u)
{
    isk_emitter_def *e = &d->emitters[i];
    base(e);
    e->born.shape = ISK_SHAPE_RECT; /* posVar (20, 0) */
    e->born.shape_a = 20 * u;
    e->born.shape_b = 0;
    e->launch.angle = 90 * DEG;     /* 90 +- 5 */
    e->launch.spread = 10 * DEG;
    e->launch.speed_min = 15 * u;   /* 25 +- 10 */
    e->launch.speed_max = 35 * u;
    e->life.seconds = 3.0;          /* 4 +- 1 */
    e->life.range = 2.0;
    e->born.capacity = 200;
    e->born.rate = 200.0 / 4.0;
    e->look.size = 60 * u;
    e->look.sprite = ISK_SPRITE_SMOOTH;
    e->look.color = isk_rgba(204, 204, 204, 255); /* 0.8 grey -> black */
    ramp2(&e->look.color_over_life, e->look.color, isk_rgba(0, 0, 0, 255));
    e->look.alpha_over_life.n = 2;  /* ours: cocos2d's texture is translucent */
    e->look.alpha_over_life.stops[0] = (isk_scalar_stop){0.0, 0.5};
    e->look.alpha_over_life.stops[1] = (isk_scalar_stop){1.0, 0.0};
    e->look.blend = ISK_BLEND_OVER;
    /* Ours: cocos2d's smoke rises straight; a turbulence about the plume's
     * width stirs it (the field has no divergence: it swirls, never
     * gathers the smoke into clumps). */
    isk_force_def *t = own_force(d, i, "turbulence", ISK_FORCE_TURBULENCE);
    if (!t)
        return 0;
    t->strength = 15 * u;
    t->scale = 30 * u;
    t->speed = 0.25;
    return 1;
}

static int fill_sparks(isk_effect_def *d, int i, double u)
{
    isk_emitter_def *e = &d->emitters[i];
    base(e);
    e->born.shape = ISK_SHAPE_DISC;
    e->born.shape_a = 15 * u;
    e->launch.angle = 90 * DEG;
    e->launch.spread = 70 * DEG;
    e->launch.speed_min = 150 * u;
    e->launch.speed_max = 300 * u;
    e->life.seconds = 0.6;
    e->life.range = 0.8;
    e->born.capacity = 200;
    e->born.rate = 60;
    e->look.size = 10 * u;
    e->look.color = isk_rgba(255, 240, 190, 255);
    e->look.color_over_life.n = 3;
    e->look.color_over_life.stops[0] = (isk_color_stop){0.0, isk_rgba(255, 240, 190, 255)};
    e->look.color_over_life.stops[1] = (isk_color_stop){0.4, isk_rgba(255, 150, 40, 255)};
    e->look.color_over_life.stops[2] = (isk_color_stop){1.0, isk_rgba(180, 30, 0, 0)};
    e->look.blend = ISK_BLEND_ADD;
    return own_gravity(d, i, 300 * u);
}

static int fill_fountain(isk_effect_def *d, int i, double u)
{
    isk_emitter_def *e = &d->emitters[i];
    base(e);
    e->born.shape = ISK_SHAPE_POINT;
    e->launch.angle = 90 * DEG;     /* 90 +- 20 */
    e->launch.spread = 40 * DEG;
    e->launch.speed_min = 130 * u;  /* 180 +- 50 */
    e->launch.speed_max = 230 * u;
    e->life.seconds = 2.5;          /* 3.5 +- 1 */
    e->life.range = 2.0;
    e->born.capacity = 1500;
    e->born.rate = 1500.0 / 3.5;
    e->look.size = 8 * u;           /* 8 +- 2 */
    e->look.color = isk_rgba(140, 200, 255, 255);
    ramp2(&e->look.color_over_life, e->look.color, isk_rgba(40, 90, 200, 51)); /* end alpha 0.2 */
    e->look.blend = ISK_BLEND_OVER;
    return own_gravity(d, i, 90 * u);
}

static int fill_snow(isk_effect_def *d, int i, double u)
{
    isk_emitter_def *e = &d->emitters[i];
    base(e);
    e->born.shape = ISK_SHAPE_RECT; /* posVar (w/2, 0) of a 480-point screen */
    e->born.shape_a = 240 * u;
    e->born.shape_b = 0;
    e->launch.angle = -90 * DEG;    /* -90 +- 5 */
    e->launch.spread = 10 * DEG;
    e->launch.speed_min = 4 * u;    /* 5 +- 1 */
    e->launch.speed_max = 6 * u;
    e->life.seconds = 30;           /* 45 +- 15 */
    e->life.range = 30;
    e->born.capacity = 700;
    e->born.rate = 10;
    e->look.size = 10 * u;          /* 10 +- 5 */
    e->look.sprite = ISK_SPRITE_SMOOTH;
    e->look.color = ISK_WHITE;
    ramp2(&e->look.color_over_life, ISK_WHITE, isk_rgba(255, 255, 255, 0));
    e->motion.osc_omega_min = 0.5;  /* ours: a sway instead of the radial/tangential jitter */
    e->motion.osc_omega_max = 1.5;
    e->motion.osc_amplitude_min = 5 * u;
    e->motion.osc_amplitude_max = 15 * u;
    e->look.blend = ISK_BLEND_OVER;
    return own_gravity(d, i, 1 * u);
}

static int fill_explosion(isk_effect_def *d, int i, double u)
{
    isk_emitter_def *e = &d->emitters[i];
    base(e);
    e->born.shape = ISK_SHAPE_POINT;
    e->launch.angle = 90 * DEG;     /* 90 +- 360: every direction */
    e->launch.spread = 360 * DEG;
    e->launch.speed_min = 30 * u;   /* 70 +- 40 */
    e->launch.speed_max = 110 * u;
    e->life.seconds = 3;            /* 5 +- 2 */
    e->life.range = 4;
    e->born.capacity = 700;
    e->born.count = 700;            /* duration 0.1 s at total/duration: one burst */
    e->born.start = 0;
    e->born.rate = 0;
    e->look.size = 15 * u;          /* 15 +- 10 */
    e->look.color = isk_rgba(178, 25, 51, 255);
    ramp2(&e->look.color_over_life, e->look.color, isk_rgba(128, 128, 128, 0));
    e->look.blend = ISK_BLEND_OVER;
    return 1;
}

/* Ours (cocos2d's ParticleGalaxy pulls with a radial acceleration of -80
 * and turns with a tangential one of 80 from a point, which fills a round
 * blob): particles born at rest along a line through the centre, 3.6 long,
 * pulled in (radial -40) and turned counter-clockwise (tangential 25)
 * against a friction (slowing 0.6): the two halves of the line wind into
 * two spiral arms around a bright core.  3000 particles at 500/s, life
 * 6 +- 1 s, size 6, blue (0.12, 0.25, 0.76, cocos's) through violet to a
 * warm white, additive. */
static int fill_galaxy(isk_effect_def *d, int i, double u)
{
    isk_emitter_def *e = &d->emitters[i];
    base(e);
    e->born.shape = ISK_SHAPE_RECT;
    e->born.shape_a = 180 * u;
    e->born.shape_b = 3 * u;
    e->launch.kind = ISK_VELGEN_DISC;
    e->launch.speed_max = 3 * u;
    e->motion.radial_accel = -40 * u;
    e->motion.tangential_accel = 25 * u;
    e->motion.slowing = 0.6;
    e->life.seconds = 5;                    /* 6 +- 1 */
    e->life.range = 2;
    e->born.capacity = 3000;
    e->born.rate = 500;
    e->look.size = 6 * u;
    e->look.color = isk_rgba(31, 64, 194, 255);
    e->look.color_over_life.n = 3;
    e->look.color_over_life.stops[0] = (isk_color_stop){0.0, isk_rgba(31, 64, 194, 0)};
    e->look.color_over_life.stops[1] = (isk_color_stop){0.5, isk_rgba(150, 110, 255, 200)};
    e->look.color_over_life.stops[2] = (isk_color_stop){1.0, isk_rgba(255, 236, 200, 0)};
    e->look.blend = ISK_BLEND_ADD;
    return 1;
}

/* Fireworks (ours: cocos2d's ParticleFireworks is the fountain above):
 * rockets at 1.5/s from pos, up at 280..330 +- 15 degrees against gravity
 * 150, life 1.1..1.5 s, with a 10-point trail 2 px wide; each bursts where
 * it dies (on_death) into 120 sparks of "<name>_burst" (source = sub), in a
 * disc of speed up to 160 with a quarter of the rocket's velocity, each
 * spark's colour picked from red, gold, green, cyan and violet, fading
 * from white over its 1.2..1.8 s against a friction (slowing 0.8), with a
 * 6-point trail.  Additive, the gravity shared. */
static int fill_fireworks(isk_effect_def *d, int i, double u)
{
    const int b = own_sub_emitter(d, i, "burst");
    if (b < 0)
        return 0;
    isk_emitter_def *r = &d->emitters[i], *s = &d->emitters[b];
    base(r);
    r->born.shape = ISK_SHAPE_POINT;
    r->launch.angle = 90 * DEG;
    r->launch.spread = 30 * DEG;
    r->launch.speed_min = 280 * u;
    r->launch.speed_max = 330 * u;
    r->born.rate = 1.5;
    r->life.seconds = 1.1;
    r->life.range = 0.4;
    r->born.capacity = 8;
    r->look.sprite = ISK_SPRITE_SMOOTH;
    r->look.size = 8 * u;
    r->look.color = isk_rgba(255, 224, 160, 255);
    r->look.blend = ISK_BLEND_ADD;
    r->look.trail = 10;
    r->look.trail_width = 2;
    r->look.trail_fade = 1;
    r->events.on_death = b;
    s->born.count = 120;
    s->launch.kind = ISK_VELGEN_DISC;
    s->launch.speed_max = 160 * u;
    s->launch.inherit = 0.25;
    s->life.seconds = 1.2;
    s->life.range = 0.6;
    s->motion.slowing = 0.8;
    s->born.capacity = 8 * 120;
    s->look.draw = ISK_DRAW_SPRITE;
    s->look.sprite = ISK_SPRITE_SMOOTH;
    s->look.size = 5 * u;
    s->look.blend = ISK_BLEND_ADD;
    s->look.color_pick.n = 5;
    s->look.color_pick.stops[0] = (isk_color_stop){0.0, isk_rgba(255, 70, 60, 255)};
    s->look.color_pick.stops[1] = (isk_color_stop){0.25, isk_rgba(255, 200, 60, 255)};
    s->look.color_pick.stops[2] = (isk_color_stop){0.5, isk_rgba(90, 255, 110, 255)};
    s->look.color_pick.stops[3] = (isk_color_stop){0.75, isk_rgba(80, 200, 255, 255)};
    s->look.color_pick.stops[4] = (isk_color_stop){1.0, isk_rgba(200, 110, 255, 255)};
    stops3(&s->look.color_over_life, isk_rgba(255, 255, 255, 255), 0.6, isk_rgba(255, 255, 255, 220),
           isk_rgba(120, 80, 80, 0));
    s->look.trail = 6;
    s->look.trail_width = 1.5;
    s->look.trail_fade = 1;
    if (!own_gravity(d, i, 150 * u))
        return 0;
    return isk_emitter_use_force(&d->emitters[b], d->emitters[i].motion.forces[d->emitters[i].motion.nforces - 1]) ==
        ISK_OK;
}

/* cocos2d ParticleRain, ours where noted: drops from a line 4.8 wide centred
 * on pos (the cocos screen), down at 380..460 (cocos: 130 +- 30, too slow
 * to read as rain) +- 5 degrees, pushed by cocos's gravity (10, -10) as a
 * wind, drawn as streaks along their velocity (align = velocity) of size 5,
 * blue-white (0.7, 0.8, 1) fading to half alpha (cocos's), 60/s; they fall
 * 3.2 onto their own floor "<name>_floor" (restitution 0.1) and every hit
 * splashes (on_hit) 6 droplets of "<name>_splash" up +- 60 degrees at
 * 60..130 under their own gravity 300, 0.3..0.5 s, fading out, additive. */
static int fill_rain(isk_effect_def *d, int i, double u)
{
    const int sp = own_sub_emitter(d, i, "splash");
    if (sp < 0)
        return 0;
    isk_emitter_def *r = &d->emitters[i], *s = &d->emitters[sp];
    base(r);
    r->born.shape = ISK_SHAPE_RECT;
    r->born.shape_a = 240 * u;
    r->born.shape_b = 0;
    r->launch.angle = -90 * DEG;
    r->launch.spread = 10 * DEG;
    r->launch.speed_min = 380 * u;
    r->launch.speed_max = 460 * u;
    r->born.rate = 60;
    r->life.seconds = 0.85;
    r->life.range = 0.15;
    r->born.capacity = 80;
    r->look.sprite = ISK_SPRITE_SMOOTH;
    r->look.size = 5 * u;
    r->look.align = ISK_ALIGN_VELOCITY;
    r->look.color = isk_rgba(179, 204, 255, 255);
    ramp2(&r->look.color_over_life, r->look.color, isk_rgba(179, 204, 255, 128));
    r->look.blend = ISK_BLEND_OVER;
    r->events.on_hit = sp;
    s->born.count = 6;
    s->launch.kind = ISK_VELGEN_CONE;
    s->launch.angle = 90 * DEG;
    s->launch.spread = 120 * DEG;
    s->launch.speed_min = 60 * u;
    s->launch.speed_max = 130 * u;
    s->life.seconds = 0.3;
    s->life.range = 0.2;
    s->born.capacity = 400;
    s->look.draw = ISK_DRAW_DOT;
    s->look.color = isk_rgba(210, 230, 255, 255);
    s->look.alpha_over_life.n = 2;
    s->look.alpha_over_life.stops[0] = (isk_scalar_stop){0.0, 1.0};
    s->look.alpha_over_life.stops[1] = (isk_scalar_stop){1.0, 0.0};
    s->look.blend = ISK_BLEND_ADD;
    const isk_vec2 p = r->born.position;
    isk_deflector floor = isk_deflector_segment(p.x - 260 * u, p.y - 320 * u, p.x + 260 * u, p.y - 320 * u);
    floor.restitution = 0.1;
    isk_force_def *w = own_force(d, i, "wind", ISK_FORCE_WIND);
    if (!w)
        return 0;
    w->accel = isk_vec2_make(10 * u, -10 * u); /* before another force moves the array */
    return own_deflector(d, i, "floor", floor) && own_gravity(d, sp, 300 * u);
}

/* Magic (ours): a wand moving at 120 to the right (emitter_velocity) that
 * sheds 160 sparkles a second from a disc of radius 10, which swirl around
 * where the wand is now (tangential_accel 300, radial_accel -150, slowing
 * 1) with 10-point trails, each spinning at -180..180 degrees a second from
 * a random angle (shown by a texture: the scene magic gives one), its
 * colour picked from violet, cyan and pink, white at first, fading out over
 * 0.8..1.4 s; additive. */
static int fill_magic(isk_effect_def *d, int i, double u)
{
    isk_emitter_def *e = &d->emitters[i];
    base(e);
    e->born.shape = ISK_SHAPE_DISC;
    e->born.shape_a = 10 * u;
    e->launch.kind = ISK_VELGEN_DISC;
    e->launch.speed_max = 60 * u;
    e->born.emitter_velocity = isk_vec2_make(120 * u, 0);
    e->motion.tangential_accel = 300 * u;
    e->motion.radial_accel = -150 * u;
    e->motion.slowing = 1.0;
    e->born.rate = 160;
    e->life.seconds = 0.8;
    e->life.range = 0.6;
    e->born.capacity = 200;
    e->look.rotation_range = 360 * DEG;
    e->look.spin = -180 * DEG;
    e->look.spin_range = 360 * DEG;
    e->look.sprite = ISK_SPRITE_SMOOTH;
    e->look.size = 14 * u;
    e->look.blend = ISK_BLEND_ADD;
    e->look.color_pick.n = 3;
    e->look.color_pick.stops[0] = (isk_color_stop){0.0, isk_rgba(170, 90, 255, 255)};
    e->look.color_pick.stops[1] = (isk_color_stop){0.5, isk_rgba(80, 220, 255, 255)};
    e->look.color_pick.stops[2] = (isk_color_stop){1.0, isk_rgba(255, 110, 200, 255)};
    stops3(&e->look.color_over_life, isk_rgba(255, 255, 255, 255), 0.3, isk_rgba(255, 255, 255, 230),
           isk_rgba(255, 255, 255, 0));
    e->look.trail = 10;
    e->look.trail_width = 1.5;
    e->look.trail_fade = 1;
    return 1;
}

/* ---- the table: one entry per preset (preset_list.h) --------------------- */

/* Fills emitter i (already at the key table's defaults) with lengths in
 * units of u = scale/100; 0 when a force it needs found no room. */
typedef int preset_fill(isk_effect_def *d, int i, double u);
#define PRESET_FILL(name) fill_##name,
static preset_fill *const fills[FX_PRESET_COUNT] = {FX_PRESETS(PRESET_FILL)};

int isk_preset_count(void) { return FX_PRESET_COUNT; }

const char *isk_preset_name(int i) { return i >= 0 && i < FX_PRESET_COUNT ? isk__fx_preset_names[i] : NULL; }

int isk_preset_find(const char *name)
{
    for (int i = 0; name && i < FX_PRESET_COUNT; i++)
        if (!strcmp(isk__fx_preset_names[i], name))
            return i;
    return -1;
}

static int valid_scale(double scale) { return isfinite(scale) && scale > 0 && scale <= ISK_PRESET_SCALE_MAX; }

isk_status isk_preset_apply(isk_effect_def *d, int emitter, const char *preset, double scale)
{
    if (!d || !preset)
        return ISK_ERR_NULL;
    const int p = isk_preset_find(preset);
    if (p < 0 || emitter < 0 || emitter >= d->nemitters || !valid_scale(scale))
        return ISK_ERR_RANGE;
    isk_emitter_def *e = &d->emitters[emitter];
    isk_emitter_def keep = *e;
    isk__fx_section_defaults(ISK_SECTION_EMITTER, e);
    memcpy(e->name, keep.name, sizeof e->name);
    e->line = keep.line;
    e->look.order = keep.look.order;
    e->born.position = keep.born.position;
    snprintf(e->preset, sizeof e->preset, "%s", isk__fx_preset_names[p]);
    const int nforces = d->nforces, ndeflectors = d->ndeflectors, nemitters = d->nemitters;
    if (!fills[p](d, emitter, scale / 100.0)) {
        /* an item of its own found no room, or could not be allocated */
        const isk_status why = d->nforces >= ISK_EFFECT_MAX_FORCES || d->ndeflectors >= ISK_EFFECT_MAX_DEFLECTORS ||
                                       d->nemitters >= ISK_EFFECT_MAX_EMITTERS
                                   ? ISK_ERR_FULL
                                   : ISK_ERR_NOMEM;
        d->nforces = nforces;
        d->ndeflectors = ndeflectors;
        d->nemitters = nemitters;
        d->emitters[emitter] = keep;
        return why;
    }
    return ISK_OK;
}

int isk_preset_add(isk_effect_def *d, const char *preset, const char *name, isk_vec2 pos, double scale)
{
    if (!d || isk_preset_find(preset) < 0 || !isfinite(pos.x) || !isfinite(pos.y) || !valid_scale(scale))
        return -1;
    isk_emitter_def *e = isk_effect_def_add_emitter(d, name ? name : preset);
    if (!e)
        return -1;
    e->born.position = pos;
    const int i = d->nemitters - 1; /* a preset may add emitters of its own after it */
    if (isk_preset_apply(d, i, preset, scale) != ISK_OK) {
        d->nemitters = i; /* an item it needed found no room */
        return -1;
    }
    return i;
}

/* The named functions of iskra/presets.h, one per row. */
#define NAMED_PRESET(n)                                                                       \
    int isk_preset_##n(isk_effect_def *d, const char *name, isk_vec2 pos, double scale)      \
    {                                                                                         \
        return isk_preset_add(d, #n, name, pos, scale);                                       \
    }
NAMED_PRESET(fire)
NAMED_PRESET(smoke)
NAMED_PRESET(sparks)
NAMED_PRESET(fountain)
NAMED_PRESET(snow)
NAMED_PRESET(explosion)
NAMED_PRESET(galaxy)
NAMED_PRESET(fireworks)
NAMED_PRESET(rain)
NAMED_PRESET(magic)
