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
    e->source = ISK_SOURCE_STREAM;
    e->draw = ISK_DRAW_SPRITE;
    e->sprite = ISK_SPRITE_LINEAR;
    e->launch = ISK_VELGEN_CONE;
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
        fx_section_defaults(ISK_SECTION_EMITTER, &d->emitters[k]);
        memcpy(d->emitters[k].name, keep.name, sizeof keep.name);
        d->emitters[k].line = keep.line;
        d->emitters[k].order = keep.order;
    }
    d->emitters[k].source = ISK_SOURCE_SUB;
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
    e->shape = ISK_SHAPE_RECT;      /* posVar (40, 20) */
    e->shape_a = 40 * u;
    e->shape_b = 20 * u;
    e->angle = 90 * DEG;            /* 90 +- 10 degrees */
    e->spread = 20 * DEG;
    e->speed_min = 40 * u;          /* 60 +- 20 */
    e->speed_max = 80 * u;
    e->life = 2.75;                 /* 3 +- 0.25 s */
    e->life_range = 0.5;
    e->capacity = 250;              /* totalParticles */
    e->rate = 250.0 / 3.0;          /* total / life */
    e->size = 54 * u;               /* 54 (+-10) */
    e->color = isk_rgba(194, 64, 31, 255);  /* (0.76, 0.25, 0.12, 1) */
    ramp2(&e->color_over_life, e->color, isk_rgba(0, 0, 0, 255));
    e->blend = ISK_BLEND_ADD;
    return 1;
}

static int fill_smoke(isk_effect_def *d, int i, double u)
{
    isk_emitter_def *e = &d->emitters[i];
    base(e);
    e->shape = ISK_SHAPE_RECT;      /* posVar (20, 0) */
    e->shape_a = 20 * u;
    e->shape_b = 0;
    e->angle = 90 * DEG;            /* 90 +- 5 */
    e->spread = 10 * DEG;
    e->speed_min = 15 * u;          /* 25 +- 10 */
    e->speed_max = 35 * u;
    e->life = 3.0;                  /* 4 +- 1 */
    e->life_range = 2.0;
    e->capacity = 200;
    e->rate = 200.0 / 4.0;
    e->size = 60 * u;
    e->sprite = ISK_SPRITE_SMOOTH;
    e->color = isk_rgba(204, 204, 204, 255); /* 0.8 grey -> black */
    ramp2(&e->color_over_life, e->color, isk_rgba(0, 0, 0, 255));
    e->alpha_over_life.n = 2;       /* ours: cocos2d's texture is translucent */
    e->alpha_over_life.stops[0] = (isk_scalar_stop){0.0, 0.5};
    e->alpha_over_life.stops[1] = (isk_scalar_stop){1.0, 0.0};
    e->blend = ISK_BLEND_OVER;
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
    e->shape = ISK_SHAPE_DISC;
    e->shape_a = 15 * u;
    e->angle = 90 * DEG;
    e->spread = 70 * DEG;
    e->speed_min = 150 * u;
    e->speed_max = 300 * u;
    e->life = 0.6;
    e->life_range = 0.8;
    e->capacity = 200;
    e->rate = 60;
    e->size = 10 * u;
    e->color = isk_rgba(255, 240, 190, 255);
    e->color_over_life.n = 3;
    e->color_over_life.stops[0] = (isk_color_stop){0.0, isk_rgba(255, 240, 190, 255)};
    e->color_over_life.stops[1] = (isk_color_stop){0.4, isk_rgba(255, 150, 40, 255)};
    e->color_over_life.stops[2] = (isk_color_stop){1.0, isk_rgba(180, 30, 0, 0)};
    e->blend = ISK_BLEND_ADD;
    return own_gravity(d, i, 300 * u);
}

static int fill_fountain(isk_effect_def *d, int i, double u)
{
    isk_emitter_def *e = &d->emitters[i];
    base(e);
    e->shape = ISK_SHAPE_POINT;
    e->angle = 90 * DEG;            /* 90 +- 20 */
    e->spread = 40 * DEG;
    e->speed_min = 130 * u;         /* 180 +- 50 */
    e->speed_max = 230 * u;
    e->life = 2.5;                  /* 3.5 +- 1 */
    e->life_range = 2.0;
    e->capacity = 1500;
    e->rate = 1500.0 / 3.5;
    e->size = 8 * u;                /* 8 +- 2 */
    e->color = isk_rgba(140, 200, 255, 255);
    ramp2(&e->color_over_life, e->color, isk_rgba(40, 90, 200, 51)); /* end alpha 0.2 */
    e->blend = ISK_BLEND_OVER;
    return own_gravity(d, i, 90 * u);
}

static int fill_snow(isk_effect_def *d, int i, double u)
{
    isk_emitter_def *e = &d->emitters[i];
    base(e);
    e->shape = ISK_SHAPE_RECT;      /* posVar (w/2, 0) of a 480-point screen */
    e->shape_a = 240 * u;
    e->shape_b = 0;
    e->angle = -90 * DEG;           /* -90 +- 5 */
    e->spread = 10 * DEG;
    e->speed_min = 4 * u;           /* 5 +- 1 */
    e->speed_max = 6 * u;
    e->life = 30;                   /* 45 +- 15 */
    e->life_range = 30;
    e->capacity = 700;
    e->rate = 10;
    e->size = 10 * u;               /* 10 +- 5 */
    e->sprite = ISK_SPRITE_SMOOTH;
    e->color = ISK_WHITE;
    ramp2(&e->color_over_life, ISK_WHITE, isk_rgba(255, 255, 255, 0));
    e->osc_omega_min = 0.5;         /* ours: a sway instead of the radial/tangential jitter */
    e->osc_omega_max = 1.5;
    e->osc_amp_min = 5 * u;
    e->osc_amp_max = 15 * u;
    e->blend = ISK_BLEND_OVER;
    return own_gravity(d, i, 1 * u);
}

static int fill_explosion(isk_effect_def *d, int i, double u)
{
    isk_emitter_def *e = &d->emitters[i];
    base(e);
    e->shape = ISK_SHAPE_POINT;
    e->angle = 90 * DEG;            /* 90 +- 360: every direction */
    e->spread = 360 * DEG;
    e->speed_min = 30 * u;          /* 70 +- 40 */
    e->speed_max = 110 * u;
    e->life = 3;                    /* 5 +- 2 */
    e->life_range = 4;
    e->capacity = 700;
    e->count = 700;                 /* duration 0.1 s at total/duration: one burst */
    e->start = 0;
    e->rate = 0;
    e->size = 15 * u;               /* 15 +- 10 */
    e->color = isk_rgba(178, 25, 51, 255);
    ramp2(&e->color_over_life, e->color, isk_rgba(128, 128, 128, 0));
    e->blend = ISK_BLEND_OVER;
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
    e->shape = ISK_SHAPE_RECT;
    e->shape_a = 180 * u;
    e->shape_b = 3 * u;
    e->launch = ISK_VELGEN_DISC;
    e->speed_max = 3 * u;
    e->radial_accel = -40 * u;
    e->tangential_accel = 25 * u;
    e->slowing = 0.6;
    e->life = 5;                    /* 6 +- 1 */
    e->life_range = 2;
    e->capacity = 3000;
    e->rate = 500;
    e->size = 6 * u;
    e->color = isk_rgba(31, 64, 194, 255);
    e->color_over_life.n = 3;
    e->color_over_life.stops[0] = (isk_color_stop){0.0, isk_rgba(31, 64, 194, 0)};
    e->color_over_life.stops[1] = (isk_color_stop){0.5, isk_rgba(150, 110, 255, 200)};
    e->color_over_life.stops[2] = (isk_color_stop){1.0, isk_rgba(255, 236, 200, 0)};
    e->blend = ISK_BLEND_ADD;
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
    r->shape = ISK_SHAPE_POINT;
    r->angle = 90 * DEG;
    r->spread = 30 * DEG;
    r->speed_min = 280 * u;
    r->speed_max = 330 * u;
    r->rate = 1.5;
    r->life = 1.1;
    r->life_range = 0.4;
    r->capacity = 8;
    r->sprite = ISK_SPRITE_SMOOTH;
    r->size = 8 * u;
    r->color = isk_rgba(255, 224, 160, 255);
    r->blend = ISK_BLEND_ADD;
    r->trail = 10;
    r->trail_width = 2;
    r->trail_fade = 1;
    r->on_death = b;
    s->count = 120;
    s->launch = ISK_VELGEN_DISC;
    s->speed_max = 160 * u;
    s->inherit = 0.25;
    s->life = 1.2;
    s->life_range = 0.6;
    s->slowing = 0.8;
    s->capacity = 8 * 120;
    s->draw = ISK_DRAW_SPRITE;
    s->sprite = ISK_SPRITE_SMOOTH;
    s->size = 5 * u;
    s->blend = ISK_BLEND_ADD;
    s->color_pick.n = 5;
    s->color_pick.stops[0] = (isk_color_stop){0.0, isk_rgba(255, 70, 60, 255)};
    s->color_pick.stops[1] = (isk_color_stop){0.25, isk_rgba(255, 200, 60, 255)};
    s->color_pick.stops[2] = (isk_color_stop){0.5, isk_rgba(90, 255, 110, 255)};
    s->color_pick.stops[3] = (isk_color_stop){0.75, isk_rgba(80, 200, 255, 255)};
    s->color_pick.stops[4] = (isk_color_stop){1.0, isk_rgba(200, 110, 255, 255)};
    stops3(&s->color_over_life, isk_rgba(255, 255, 255, 255), 0.6, isk_rgba(255, 255, 255, 220),
           isk_rgba(120, 80, 80, 0));
    s->trail = 6;
    s->trail_width = 1.5;
    s->trail_fade = 1;
    if (!own_gravity(d, i, 150 * u))
        return 0;
    return isk_emitter_use_force(&d->emitters[b], d->emitters[i].forces[d->emitters[i].nforces - 1]) == ISK_OK;
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
    r->shape = ISK_SHAPE_RECT;
    r->shape_a = 240 * u;
    r->shape_b = 0;
    r->angle = -90 * DEG;
    r->spread = 10 * DEG;
    r->speed_min = 380 * u;
    r->speed_max = 460 * u;
    r->rate = 60;
    r->life = 0.85;
    r->life_range = 0.15;
    r->capacity = 80;
    r->sprite = ISK_SPRITE_SMOOTH;
    r->size = 5 * u;
    r->align = ISK_ALIGN_VELOCITY;
    r->color = isk_rgba(179, 204, 255, 255);
    ramp2(&r->color_over_life, r->color, isk_rgba(179, 204, 255, 128));
    r->blend = ISK_BLEND_OVER;
    r->on_hit = sp;
    s->count = 6;
    s->launch = ISK_VELGEN_CONE;
    s->angle = 90 * DEG;
    s->spread = 120 * DEG;
    s->speed_min = 60 * u;
    s->speed_max = 130 * u;
    s->life = 0.3;
    s->life_range = 0.2;
    s->capacity = 400;
    s->draw = ISK_DRAW_DOT;
    s->color = isk_rgba(210, 230, 255, 255);
    s->alpha_over_life.n = 2;
    s->alpha_over_life.stops[0] = (isk_scalar_stop){0.0, 1.0};
    s->alpha_over_life.stops[1] = (isk_scalar_stop){1.0, 0.0};
    s->blend = ISK_BLEND_ADD;
    const isk_vec2 p = r->pos;
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
    e->shape = ISK_SHAPE_DISC;
    e->shape_a = 10 * u;
    e->launch = ISK_VELGEN_DISC;
    e->speed_max = 60 * u;
    e->emitter_velocity = isk_vec2_make(120 * u, 0);
    e->tangential_accel = 300 * u;
    e->radial_accel = -150 * u;
    e->slowing = 1.0;
    e->rate = 160;
    e->life = 0.8;
    e->life_range = 0.6;
    e->capacity = 200;
    e->rotation_range = 360 * DEG;
    e->spin = -180 * DEG;
    e->spin_range = 360 * DEG;
    e->sprite = ISK_SPRITE_SMOOTH;
    e->size = 14 * u;
    e->blend = ISK_BLEND_ADD;
    e->color_pick.n = 3;
    e->color_pick.stops[0] = (isk_color_stop){0.0, isk_rgba(170, 90, 255, 255)};
    e->color_pick.stops[1] = (isk_color_stop){0.5, isk_rgba(80, 220, 255, 255)};
    e->color_pick.stops[2] = (isk_color_stop){1.0, isk_rgba(255, 110, 200, 255)};
    stops3(&e->color_over_life, isk_rgba(255, 255, 255, 255), 0.3, isk_rgba(255, 255, 255, 230),
           isk_rgba(255, 255, 255, 0));
    e->trail = 10;
    e->trail_width = 1.5;
    e->trail_fade = 1;
    return 1;
}

/* ---- the table: one entry per preset (preset_list.h) --------------------- */

/* Fills emitter i (already at the key table's defaults) with lengths in
 * units of u = scale/100; 0 when a force it needs found no room. */
typedef int preset_fill(isk_effect_def *d, int i, double u);
#define PRESET_FILL(name) fill_##name,
static preset_fill *const fills[FX_PRESET_COUNT] = {FX_PRESETS(PRESET_FILL)};

int isk_preset_count(void) { return FX_PRESET_COUNT; }

const char *isk_preset_name(int i) { return i >= 0 && i < FX_PRESET_COUNT ? fx_preset_names[i] : NULL; }

int isk_preset_find(const char *name)
{
    for (int i = 0; name && i < FX_PRESET_COUNT; i++)
        if (!strcmp(fx_preset_names[i], name))
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
    fx_section_defaults(ISK_SECTION_EMITTER, e);
    memcpy(e->name, keep.name, sizeof e->name);
    e->line = keep.line;
    e->order = keep.order;
    e->pos = keep.pos;
    snprintf(e->preset, sizeof e->preset, "%s", fx_preset_names[p]);
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
    e->pos = pos;
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
