/* Validation of an effect definition: every field of every item, with
 * messages that name the item ("emitter 'smoke' (line 12): ..."). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>

#include "effect_internal.h"
typedef struct checker {
    isk_error *err;
    isk_status status;
} checker;

/* "emitter 'smoke' (line 12): life must be > 0" */
static int fail(checker *ck, isk_status s, const char *what, const char *name, int line, const char *fmt, ...)
{
    char msg[300], where[96];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (line > 0)
        snprintf(where, sizeof where, " (line %d)", line);
    else
        where[0] = 0;
    if (name)
        isk_error_set(ck->err, s, "%s '%s'%s: %s", what, name, where, msg);
    else
        isk_error_set(ck->err, s, "%s: %s", what, msg);
    ck->status = s;
    return 0;
}

#define FIN(x) isfinite(x)

static int check_ramp_c(checker *ck, const isk_emitter_def *e, const isk_color_ramp *r, const char *what)
{
    if (r->n == 0)
        return 1;
    isk_status s = isk_color_stops_check(r->stops, r->n);
    if (s != ISK_OK)
        return fail(ck, s, "emitter", e->name, e->line,
                    "%s: 1..%d stops with t strictly increasing in [0, 1] expected", what, ISK_GRADIENT_MAX_STOPS);
    return 1;
}

static int check_ramp_s(checker *ck, const isk_emitter_def *e, const isk_scalar_ramp *r, const char *what)
{
    if (r->n == 0)
        return 1;
    isk_status s = isk_scalar_stops_check(r->stops, r->n);
    if (s != ISK_OK)
        return fail(ck, s, "emitter", e->name, e->line,
                    "%s: 1..%d finite stops with t strictly increasing in [0, 1] expected", what,
                    ISK_GRADIENT_MAX_STOPS);
    for (int i = 0; i < r->n; i++)
        if (r->stops[i].value < 0)
            return fail(ck, ISK_ERR_RANGE, "emitter", e->name, e->line, "%s: values must be >= 0", what);
    return 1;
}

static int check_emitter(checker *ck, const isk_effect_def *d, const isk_emitter_def *e)
{
    const char *n = e->name;
    int L = e->line;
    if ((unsigned)e->source >= ISK_SOURCE_KIND_COUNT)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "unknown source kind %d", (int)e->source);
    if (!FIN(e->pos.x) || !FIN(e->pos.y) || !FIN(e->vel.x) || !FIN(e->vel.y))
        return fail(ck, ISK_ERR_NAN, "emitter", n, L, "position and velocity must be finite");
    if (!FIN(e->mass) || !(e->mass > 0))
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "mass must be a finite number > 0");
    if (!FIN(e->mass_range) || e->mass_range < 0)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "mass range must be >= 0");
    if (!FIN(e->start) || e->start < 0)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "start time must be >= 0");
    size_t limit = e->limit ? e->limit : ISK_EXPLODE_THESIS_LIMIT;
    if (limit > ISK_EFFECT_MAX_PARTICLES)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "limit must be <= %u", ISK_EFFECT_MAX_PARTICLES);
    if ((unsigned)e->kick > ISK_KICK_NEW)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "unknown kick target");
    switch (e->source) {
    case ISK_SOURCE_EXPLOSION:
        if ((unsigned)e->explosion >= ISK_EXPLOSION_COUNT)
            return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "unknown explosion kind");
        /* fallthrough */
    case ISK_SOURCE_LAYER:
        if (e->count < 1 || e->count > limit)
            return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "count must be 1..%zu (raise limit for more)", limit);
        if (e->source == ISK_SOURCE_LAYER &&
            (!FIN(e->rect[0]) || !FIN(e->rect[1]) || !FIN(e->rect[2]) || !FIN(e->rect[3]) ||
             e->rect[0] > e->rect[1] || e->rect[2] > e->rect[3]))
            return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "layer rectangle must be finite with min <= max");
        break;
    case ISK_SOURCE_STREAM: {
        char why[200];
        if (fx_stream_validate(e, why, sizeof why) != ISK_OK)
            return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "%s", why);
        break;
    }
    default:
        break;
    }
    if (!(e->life > 0) || isnan(e->life) || !FIN(e->life_range) || e->life_range < 0)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "life must be > 0 (or infinite) and life range >= 0");
    if (e->capacity < 1 || e->capacity > ISK_EFFECT_MAX_PARTICLES)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "capacity must be 1..%u", ISK_EFFECT_MAX_PARTICLES);
    if (e->nforces < 0 || e->nforces > ISK_EFFECT_MAX_FORCES || e->ndeflectors < 0 ||
        e->ndeflectors > ISK_EFFECT_MAX_DEFLECTORS)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "too many references");
    for (int i = 0; i < e->nforces; i++)
        if (e->forces[i] < 0 || e->forces[i] >= d->nforces)
            return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "force reference %d does not exist", e->forces[i]);
    for (int i = 0; i < e->ndeflectors; i++)
        if (e->deflectors[i] < 0 || e->deflectors[i] >= d->ndeflectors)
            return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "deflector reference %d does not exist",
                        e->deflectors[i]);
    if (!FIN(e->gravity_mult) || !FIN(e->weight) || !FIN(e->slowing) || e->slowing < 0)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L,
                    "gravity multiplier and weight must be finite, slowing finite and >= 0");
    if (!FIN(e->osc_omega_min) || !FIN(e->osc_omega_max) || !FIN(e->osc_amp_min) || !FIN(e->osc_amp_max) ||
        e->osc_omega_min > e->osc_omega_max || e->osc_amp_min > e->osc_amp_max || e->osc_amp_min < 0 ||
        !FIN(e->osc_decay) || e->osc_decay < 0)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L,
                    "oscillation ranges must be finite with min <= max, amplitude and decay >= 0");
    if ((int)e->integrator != -1 && (unsigned)e->integrator >= ISK_INTEGRATOR_COUNT)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "unknown integrator");
    if (e->slow_faithful && e->slowing > 0) {
        /* The thesis order is a fused constant-acceleration kernel. */
        int ok = ((int)e->integrator == -1 ? d->integrator : e->integrator) == ISK_INTEGRATE_SEMI_EULER &&
                 d->fidelity == ISK_FIDELITY_SOUND;
        for (int i = 0; ok && i < e->nforces; i++) {
            const isk_force_def *f = &d->forces[e->forces[i]];
            ok = !(f->kind == ISK_FORCE_DRAG && f->b != 0) && f->kind != ISK_FORCE_POTENTIAL;
        }
        if (!ok)
            return fail(ck, ISK_ERR_RANGE, "emitter", n, L,
                        "the thesis slowing order needs the semi-implicit Euler integrator, sound fidelity "
                        "and only gravity/wind forces");
    }
    if (e->substeps < 0 || e->substeps > 10000)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "substeps must be 1..10000 (0 inherits)");
    if ((unsigned)e->draw >= ISK_DRAW_COUNT)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "unknown draw mode");
    if ((unsigned)e->sprite > ISK_SPRITE_SMOOTH)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "unknown sprite kind");
    if ((unsigned)e->blend > ISK_BLEND_ADD)
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "unknown blend mode");
    if ((e->draw == ISK_DRAW_DISC || e->draw == ISK_DRAW_SPRITE) && (!FIN(e->size) || !(e->size > 0)))
        return fail(ck, ISK_ERR_RANGE, "emitter", n, L, "size must be a finite number > 0");
    if (!check_ramp_c(ck, e, &e->color_over_life, "colour over life") ||
        !check_ramp_s(ck, e, &e->alpha_over_life, "alpha over life") ||
        !check_ramp_s(ck, e, &e->size_over_life, "size over life"))
        return 0;
    return 1;
}

static int check_def(checker *ck, const isk_effect_def *d)
{
    if (d->width < 1 || d->height < 1 || d->width > ISK_CANVAS_MAX_DIM || d->height > ISK_CANVAS_MAX_DIM)
        return fail(ck, ISK_ERR_SIZE, "scene", NULL, 0, "canvas size must be 1..%d in each direction",
                    ISK_CANVAS_MAX_DIM);
    if (!FIN(d->dt) || !(d->dt > 0) || d->dt > 3600)
        return fail(ck, ISK_ERR_RANGE, "scene", NULL, 0, "dt must be a number in (0, 3600] seconds");
    if (d->substeps < 1 || d->substeps > 10000)
        return fail(ck, ISK_ERR_RANGE, "scene", NULL, 0, "substeps must be 1..10000");
    if (!FIN(d->speed_divisor) || !(d->speed_divisor > 0))
        return fail(ck, ISK_ERR_RANGE, "scene", NULL, 0, "speed divisor must be > 0");
    if ((unsigned)d->integrator >= ISK_INTEGRATOR_COUNT)
        return fail(ck, ISK_ERR_RANGE, "scene", NULL, 0, "unknown integrator");
    if ((unsigned)d->centre > ISK_FIDELITY_THESIS || (unsigned)d->fidelity > ISK_FIDELITY_THESIS)
        return fail(ck, ISK_ERR_RANGE, "scene", NULL, 0, "unknown fidelity");
    if (d->nforces < 0 || d->nforces > ISK_EFFECT_MAX_FORCES || d->nemitters < 0 ||
        d->nemitters > ISK_EFFECT_MAX_EMITTERS || d->ndeflectors < 0 || d->ndeflectors > ISK_EFFECT_MAX_DEFLECTORS ||
        d->ndrawings < 0 || d->ndrawings > ISK_EFFECT_MAX_DRAWINGS)
        return fail(ck, ISK_ERR_SIZE, "scene", NULL, 0, "too many forces, emitters, deflectors or drawings");
    for (int i = 0; i < d->nforces; i++) {
        const isk_force_def *f = &d->forces[i];
        if ((unsigned)f->kind >= ISK_FORCE_KIND_COUNT)
            return fail(ck, ISK_ERR_RANGE, "force", f->name, f->line, "unknown kind");
        if (!FIN(f->g) || f->g < 0 || !FIN(f->b) || f->b < 0)
            return fail(ck, ISK_ERR_RANGE, "force", f->name, f->line, "g and b must be finite and >= 0");
        if (!FIN(f->accel.x) || !FIN(f->accel.y))
            return fail(ck, ISK_ERR_NAN, "force", f->name, f->line, "acceleration must be finite");
        if (f->kind == ISK_FORCE_POTENTIAL && isk_potential_validate(&f->pot) != ISK_OK)
            return fail(ck, ISK_ERR_RANGE, "force", f->name, f->line,
                        "potential fields must be finite (enabled 0 or 1)");
    }
    for (int i = 0; i < d->ndeflectors; i++)
        if (isk_deflector_check(&d->deflectors[i]) != ISK_OK)
            return fail(ck, ISK_ERR_RANGE, "deflector", d->deflector_names ? d->deflector_names[i] : "?", 0,
                        "needs finite end points that differ, restitution >= 0, probability in [0, 1]");
    if (d->bounds.sides != 0 && isk_bounds_validate(&d->bounds) != ISK_OK)
        return fail(ck, ISK_ERR_RANGE, "bounds", NULL, 0,
                    "walls need a finite window with min < max, margin >= 0, restitution in [0, 1]");
    for (int i = 0; i < d->nemitters; i++)
        if (!check_emitter(ck, d, &d->emitters[i]))
            return 0;
    for (int i = 0; i < d->ndrawings; i++) {
        const isk_drawing_def *s = &d->drawings[i];
        if ((unsigned)s->kind >= ISK_DRAWING_KIND_COUNT || (unsigned)s->blend > ISK_BLEND_ADD)
            return fail(ck, ISK_ERR_RANGE, "drawing", s->name, s->line, "unknown kind or blend");
        if (s->kind == ISK_DRAWING_POLYLINE && (!s->points || s->npoints < 2 || s->npoints > 100000))
            return fail(ck, ISK_ERR_RANGE, "drawing", s->name, s->line, "a polyline needs 2..100000 points");
        if (s->kind == ISK_DRAWING_POLYGON && (!s->points || s->npoints < 3 || s->npoints > 100000))
            return fail(ck, ISK_ERR_RANGE, "drawing", s->name, s->line, "a polygon needs 3..100000 points");
        if ((s->kind == ISK_DRAWING_POLYLINE || s->kind == ISK_DRAWING_POLYGON))
            for (int k = 0; k < 2 * s->npoints; k++)
                if (!FIN(s->points[k]))
                    return fail(ck, ISK_ERR_NAN, "drawing", s->name, s->line, "points must be finite");
        if (!FIN(s->x) || !FIN(s->y) || !FIN(s->r))
            return fail(ck, ISK_ERR_NAN, "drawing", s->name, s->line, "position and radius must be finite");
        if (s->kind == ISK_DRAWING_SPRITE &&
            ((unsigned)s->sprite > ISK_SPRITE_SMOOTH || !FIN(s->size) || !(s->size > 0)))
            return fail(ck, ISK_ERR_RANGE, "drawing", s->name, s->line, "a sprite needs a kind and a size > 0");
        if (s->kind == ISK_DRAWING_TEXT && (s->scale < 1 || s->scale > 64))
            return fail(ck, ISK_ERR_RANGE, "drawing", s->name, s->line, "text scale must be 1..64");
    }
    if (d->click_enabled || d->click_auto) {
        if ((unsigned)d->click_explosion >= ISK_EXPLOSION_COUNT)
            return fail(ck, ISK_ERR_RANGE, "click", NULL, 0, "unknown explosion kind");
        if (d->click_emitter >= d->nemitters || d->nemitters == 0)
            return fail(ck, ISK_ERR_RANGE, "click", NULL, 0, "the click needs an emitter to receive it");
        if (!FIN(d->click_x) || !FIN(d->click_y))
            return fail(ck, ISK_ERR_NAN, "click", NULL, 0, "click point must be finite");
        if (d->click_after < 0)
            return fail(ck, ISK_ERR_RANGE, "click", NULL, 0, "after_frames must be >= 0");
    }
    return 1;
}


isk_status fx_check(const isk_effect_def *d, isk_error *err)
{
    checker ck = {err, ISK_OK};
    return check_def(&ck, d) ? ISK_OK : ck.status;
}
