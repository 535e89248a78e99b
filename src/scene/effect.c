/* The effect runtime: validation, compilation into per-emitter stage lists,
 * and the frame loop.  Drawing is in effect_render.c, stream emission in
 * effect_stream.c.
 *
 * The frame loop mirrors isk_system_step (src/sim/system.c) operation for
 * operation, so a thesis scene and the C example that uses isk_system give
 * identical bits: substeps outer, particles inner in blocks of
 * ISK_SIM_BLOCK, each block running the group's stages in order. */
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "effect_internal.h"
#include "sim/kernels.h"

/* ---- validation ----------------------------------------------------------- */

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

/* ---- compilation ------------------------------------------------------------ */

static void add_stage(fx_group *g, fx_stage_kind k, const char *fmt, ...)
{
    if (g->nstages >= FX_MAX_STAGES)
        return;
    fx_stage *s = &g->stages[g->nstages++];
    s->kind = k;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(s->label, sizeof s->label, fmt, ap);
    va_end(ap);
    g->has_stage[k] = 1;
}

static const char *explosion_name(isk_explosion k)
{
    static const char *names[] = {"ring", "uniform", "gauss", "coulomb", "multi-coulomb"};
    return (unsigned)k < ISK_EXPLOSION_COUNT ? names[k] : "?";
}

/* Rebuilds the group's force set and stage list from the definition and the
 * effect's current potentials (a potential switched off is dropped). */
static isk_status compile_group(isk_effect *e, fx_group *g)
{
    const isk_effect_def *d = &e->def;
    const isk_emitter_def *em = g->def;
    memset(g->has_stage, 0, sizeof g->has_stage);
    g->nstages = 0;
    double gsum = 0, bsum = 0, ax = 0, ay = 0;
    char forces_txt[100] = "";
    g->npots = 0;
    for (int i = 0; i < em->nforces; i++) {
        const isk_force_def *f = &d->forces[em->forces[i]];
        switch (f->kind) {
        case ISK_FORCE_GRAVITY: gsum += f->g * em->gravity_mult; break;
        case ISK_FORCE_DRAG: bsum += f->b; break;
        case ISK_FORCE_WIND: ax += f->accel.x; ay += f->accel.y; break;
        case ISK_FORCE_POTENTIAL:
            for (size_t k = 0; k < e->npots; k++) {
                isk_potential *p = &e->pots[k];
                if (e->pot_force[k] == em->forces[i] && p->enabled && p->k * p->charge != 0.0) {
                    g->pots[g->npots] = *p;
                    g->pot_src[g->npots] = (int)k;
                    g->npots++;
                }
            }
            break;
        default: break;
        }
    }
    ay += em->weight;
    g->forces.gravity = gsum;
    g->forces.drag = bsum;
    g->forces.ax = ax;
    g->forces.ay = ay;
    g->forces.pot = g->npots ? g->pots : NULL;
    g->forces.npot = g->npots;
    g->forces.centre = d->centre;

    /* Labels name only what acts. */
    size_t used = 0;
#define APPEND(...) used += (size_t)snprintf(forces_txt + used, used < sizeof forces_txt ? sizeof forces_txt - used : 0, __VA_ARGS__)
    if (gsum != 0) APPEND("%sgravity g=%g", used ? ", " : "", gsum);
    if (ax != 0 || ay != 0) APPEND("%saccel (%g, %g)", used ? ", " : "", ax, ay);
    if (bsum != 0) APPEND("%sdrag b=%g", used ? ", " : "", bsum);
    for (size_t k = 0; k < g->npots; k++) APPEND("%spotential %d", used ? ", " : "", g->pots[k].id);
#undef APPEND

    g->integrator = (int)em->integrator == -1 ? d->integrator : em->integrator;
    g->substeps = em->substeps ? em->substeps : d->substeps;

    if (em->source == ISK_SOURCE_EXPLOSION && (em->start > 0 || em->explosion == ISK_EXPLOSION_MULTI_COULOMB))
        add_stage(g, FX_STAGE_RELEASE, "release   %s explosion of %zu at t=%g s", explosion_name(em->explosion),
                  em->count, em->start);
    if (g->ndefl)
        add_stage(g, FX_STAGE_REMEMBER, "remember  positions (for deflectors)");
    int any_force = gsum != 0 || ax != 0 || ay != 0 || bsum != 0 || g->npots;
    int fast = g->integrator == ISK_INTEGRATE_SEMI_EULER && bsum == 0 && g->npots == 0 &&
               d->fidelity == ISK_FIDELITY_SOUND;
    if (fast) {
        /* Constant acceleration: gravity folds into it (a = -g), no mass needed. */
        g->ay = ay - gsum;
        g->ax = ax;
        if (em->slow_faithful && em->slowing > 0)
            add_stage(g, FX_STAGE_DRIFT_SLOW, "drift     thesis order: v += (%g, %g)*dt; v *= max(0, 1 - %g*dt); "
                      "p += v*dt", g->ax, g->ay, em->slowing);
        else if (g->ax != 0 || g->ay != 0)
            add_stage(g, FX_STAGE_DRIFT, "drift     semi-euler, constant acceleration (%g, %g)", g->ax, g->ay);
        else
            add_stage(g, FX_STAGE_DRIFT, "drift     semi-euler, no forces");
    } else {
        add_stage(g, FX_STAGE_MOTION, "integrate %s, forces: %s", isk_integrator_name(g->integrator),
                  any_force ? forces_txt : "none");
    }
    if (em->slowing > 0 && !g->has_stage[FX_STAGE_DRIFT_SLOW])
        add_stage(g, FX_STAGE_SLOW, "slow      v *= max(0, 1 - %g*dt)", em->slowing);
    if (g->has_osc)
        add_stage(g, FX_STAGE_OSCILLATE, "oscillate x, omega %g..%g rad/s, amplitude %g..%g, decay %g/s%s%s",
                  em->osc_omega_min, em->osc_omega_max, em->osc_amp_min, em->osc_amp_max, em->osc_decay,
                  em->osc_faithful ? ", thesis vx coupling" : "", em->osc_use_table ? ", sine table" : ", libm sin");
    if (em->bounded && d->bounds.sides != 0 && !em->draw_before_bounce)
        add_stage(g, FX_STAGE_WALLS, "walls     %s", d->bounds.mode == ISK_BOUNCE_THESIS ? "thesis zarobi" : "reflect");
    if (g->ndefl)
        add_stage(g, FX_STAGE_DEFLECT, "deflect   %d segment%s", g->ndefl, g->ndefl == 1 ? "" : "s");
    if (isfinite(em->life) || g->defl_can_kill)
        add_stage(g, FX_STAGE_AGE, "age       age += dt");
    if (em->source == ISK_SOURCE_STREAM)
        add_stage(g, FX_STAGE_SPAWN, "spawn     %g/s%s, %s births", em->rate,
                  em->rate_mode == ISK_RATE_THESIS ? " (thesis rounding)" : "",
                  em->birth == ISK_BIRTH_BACKDATE ? "back-dated"
                                                  : (em->birth == ISK_BIRTH_THESIS_JITTER ? "jittered" : "frame-aligned"));
    if (isfinite(em->life) || g->defl_can_kill)
        add_stage(g, FX_STAGE_CULL, "cull      age >= life");
    g->walls_after_draw = em->bounded && d->bounds.sides != 0 && em->draw_before_bounce;
    return ISK_OK;
}

/* ---- group state ---------------------------------------------------------- */

isk_status fx_group_sync(fx_group *g)
{
    if (!g->has_osc || g->osc_cap >= g->store.capacity)
        return ISK_OK;
    size_t cap = g->store.capacity;
    double **arrs[4] = {&g->osc_amp, &g->osc_phase, &g->osc_omega, &g->osc_off};
    for (int k = 0; k < 4; k++) {
        double *p = realloc(*arrs[k], cap * sizeof(double));
        if (!p)
            return ISK_ERR_NOMEM;
        *arrs[k] = p;
    }
    g->osc_cap = cap;
    return ISK_OK;
}

void fx_group_init_osc(isk_effect *e, fx_group *g, size_t i)
{
    const isk_emitter_def *em = g->def;
    g->osc_omega[i] = isk_rng_range(&g->rng, em->osc_omega_min, em->osc_omega_max);
    g->osc_amp[i] = isk_rng_range(&g->rng, em->osc_amp_min, em->osc_amp_max);
    g->osc_phase[i] = 0.0;
    g->osc_off[i] = 0.0;
    if (em->osc_random_phase) {
        /* The offset starts where the sine is, so the first step moves the
         * particle by the change only (the same sine as the stage). */
        double ph = isk_rng_range(&g->rng, 0.0, 6.283185307179586);
        g->osc_phase[i] = ph;
        g->osc_off[i] = g->osc_amp[i] * (em->osc_use_table ? isk_sinlut_floor(&e->sin_table, ph) : sin(ph));
    }
}

size_t fx_group_cull(fx_group *g)
{
    isk_particles *p = &g->store;
    size_t n = p->count, j = 0;
    for (size_t i = 0; i < n; i++) {
        if (p->age[i] >= p->life[i])
            continue;
        if (i != j) {
            p->x[j] = p->x[i]; p->y[j] = p->y[i];
            p->vx[j] = p->vx[i]; p->vy[j] = p->vy[i];
            p->m[j] = p->m[i]; p->age[j] = p->age[i]; p->life[j] = p->life[i];
            if (p->size) p->size[j] = p->size[i];
            if (p->color) p->color[j] = p->color[i];
            if (g->has_osc) {
                g->osc_amp[j] = g->osc_amp[i]; g->osc_phase[j] = g->osc_phase[i];
                g->osc_omega[j] = g->osc_omega[i]; g->osc_off[j] = g->osc_off[i];
            }
        }
        j++;
    }
    p->count = j;
    return n - j;
}

static uint64_t group_seed(uint64_t seed, int index)
{
    /* Emitter 0 uses the scene seed itself, so a one-emitter scene draws the
     * same numbers as a C program seeding one isk_system with that seed. */
    return seed + (uint64_t)index * 0x9E3779B97F4A7C15ull;
}

/* New particles [from, count) take the emitter's lifetime, life + U*range
 * (one uniform each, only with a finite life and a range), then their
 * oscillation state (omega, amplitude, ...); the parallel arrays grow first.
 * Every source's particles go through here. */
static isk_status adopt(isk_effect *e, fx_group *g, size_t from)
{
    const isk_emitter_def *em = g->def;
    isk_particles *p = &g->store;
    isk_status s = fx_group_sync(g);
    if (s != ISK_OK)
        return s;
    const int ranged = isfinite(em->life) && em->life_range > 0;
    for (size_t i = from; i < p->count; i++)
        p->life[i] = em->life + (ranged ? em->life_range * isk_rng_uniform(&g->rng) : 0.0);
    for (size_t i = from; g->has_osc && i < p->count; i++)
        fx_group_init_osc(e, g, i);
    return ISK_OK;
}

static isk_status fire_explosion(isk_effect *e, fx_group *g, isk_explosion kind, double cx, double cy, size_t count,
                                 isk_kick_target kick)
{
    const isk_emitter_def *em = g->def;
    size_t limit = em->limit ? em->limit : ISK_EXPLODE_THESIS_LIMIT;
    isk_particles *p = &g->store;
    size_t before = p->count;
    isk_status s;
    switch (kind) {
    case ISK_EXPLOSION_RING: s = isk_explode_ring(p, cx, cy, count, limit); break;
    case ISK_EXPLOSION_UNIFORM: s = isk_explode_uniform(p, &g->rng, cx, cy, count, limit); break;
    case ISK_EXPLOSION_GAUSS: s = isk_explode_gauss(p, &g->rng, cx, cy, count, limit); break;
    case ISK_EXPLOSION_COULOMB: s = isk_explode_coulomb(p, &g->rng, cx, cy, count, limit, kick); break;
    case ISK_EXPLOSION_MULTI_COULOMB:
        if (g->mc_active && !isk_multi_coulomb_done(&g->mc))
            return ISK_ERR_FULL;
        s = isk_multi_coulomb_start(&g->mc, cx, cy, count, limit);
        if (s == ISK_OK) {
            g->mc_active = 1;
            s = isk_multi_coulomb_release(&g->mc, p, &g->rng, NULL);
        }
        break;
    default: return ISK_ERR_RANGE;
    }
    return s != ISK_OK ? s : adopt(e, g, before);
}

/* Everything that exists at time 0. */
static isk_status populate(isk_effect *e, fx_group *g)
{
    const isk_emitter_def *em = g->def;
    isk_particles *p = &g->store;
    isk_status s = ISK_OK;
    switch (em->source) {
    case ISK_SOURCE_PARTICLE:
        s = isk_particles_add(p, em->pos.x, em->pos.y, em->vel.x, em->vel.y, em->mass, NULL);
        if (s == ISK_OK)
            s = adopt(e, g, 0);
        break;
    case ISK_SOURCE_LAYER: {
        size_t limit = em->limit ? em->limit : ISK_EXPLODE_THESIS_LIMIT;
        s = isk_explode_layer(p, &g->rng, em->rect[0], em->rect[1], em->rect[2], em->rect[3], em->count, limit);
        for (size_t i = 0; s == ISK_OK && i < p->count; i++)
            p->m[i] = em->mass;
        if (s == ISK_OK)
            s = adopt(e, g, 0);
        break;
    }
    case ISK_SOURCE_EXPLOSION:
        if (em->start <= 0) {
            s = fire_explosion(e, g, em->explosion, em->pos.x, em->pos.y, em->count, em->kick);
            g->fired = 1;
        }
        break;
    case ISK_SOURCE_STREAM:
        fx_stream_reset(g, 0.0);
        break;
    default: break;
    }
    return s;
}

static void free_group(fx_group *g)
{
    isk_particles_free(&g->store);
    free(g->pots);
    free(g->pot_src);
    free(g->defl);
    free(g->osc_amp); free(g->osc_phase); free(g->osc_omega); free(g->osc_off);
    fx_free_ramps(g);
}

/* Builds all groups from the definition: the state right after create. */
static isk_status build(isk_effect *e, isk_error *err)
{
    const isk_effect_def *d = &e->def;
    /* Potentials, ids 1, 2, ... in force order (the thesis's counter). */
    e->npots = 0;
    for (int i = 0; i < d->nforces; i++)
        if (d->forces[i].kind == ISK_FORCE_POTENTIAL) {
            e->pots[e->npots] = d->forces[i].pot;
            e->pots[e->npots].id = (int)e->npots + 1;
            e->pot_force[e->npots] = i;
            e->npots++;
        }
    e->time = 0;
    e->frame = 0;
    e->last_frame_time = 0;
    for (int gi = 0; gi < e->ngroups; gi++) {
        fx_group *g = &e->groups[gi];
        free_group(g);
        memset(g, 0, sizeof *g);
        g->index = gi;
        g->def = &d->emitters[gi];
        const isk_emitter_def *em = g->def;
        unsigned flags = 0;
        isk_status s = isk_particles_init(&g->store, 0, flags);
        if (s == ISK_OK && e->npots) {
            g->pots = calloc(e->npots, sizeof *g->pots);
            g->pot_src = calloc(e->npots, sizeof *g->pot_src);
            if (!g->pots || !g->pot_src)
                s = ISK_ERR_NOMEM;
        }
        if (s == ISK_OK && em->ndeflectors) {
            g->defl = calloc((size_t)em->ndeflectors, sizeof *g->defl);
            if (!g->defl)
                s = ISK_ERR_NOMEM;
            for (int k = 0; s == ISK_OK && k < em->ndeflectors; k++) {
                g->defl[k] = d->deflectors[em->deflectors[k]];
                g->defl_can_kill |= g->defl[k].reaction == ISK_DEFLECT_KILL;
            }
            g->ndefl = em->ndeflectors;
        }
        if (s != ISK_OK)
            return isk_error_set(err, s, "emitter '%s': %s", em->name, isk_status_str(s));
        g->has_osc = em->osc_amp_max > 0 && em->osc_omega_max != 0;
        g->slow_per_s = em->slowing;
        isk_rng_seed(&g->rng, group_seed(d->seed, gi));
        if ((s = fx_bake_ramps(g, err)) != ISK_OK)
            return s;
        compile_group(e, g);
        if ((s = populate(e, g)) != ISK_OK)
            return isk_error_set(err, s, "emitter '%s': cannot create its particles: %s", em->name,
                                 isk_status_str(s));
    }
    if (d->click_auto && d->click_after == 0) {
        isk_status s = isk_effect_click(e, d->click_x, d->click_y);
        if (s != ISK_OK)
            return isk_error_set(err, s, "click: %s", isk_status_str(s));
    }
    return ISK_OK;
}

isk_status isk_effect_create(isk_effect **out, const isk_effect_def *def, isk_error *err)
{
    if (!out || !def)
        return isk_error_set(err, ISK_ERR_NULL, "effect: NULL argument");
    *out = NULL;
    checker ck = {err, ISK_OK};
    if (!check_def(&ck, def))
        return ck.status;
    isk_effect *e = calloc(1, sizeof *e);
    if (!e)
        return isk_error_set(err, ISK_ERR_NOMEM, "effect: out of memory");
    isk_status s = fx_def_copy(&e->def, def);
    if (s != ISK_OK) {
        free(e);
        return isk_error_set(err, s, "effect: out of memory");
    }
    const isk_effect_def *d = &e->def;
    s = d->view_kind == ISK_VIEWDEF_CAMERA ? isk_view_camera(&e->view, d->width, d->height, d->zoom, d->tx, d->ty)
                                           : isk_view_window(&e->view, d->width, d->height, d->xmin, d->xmax,
                                                             d->ymin, d->ymax);
    if (s != ISK_OK) {
        isk_effect_destroy(e);
        return isk_error_set(err, s, "view: %s (window needs finite min < max; camera needs zoom > 0)",
                             isk_status_str(s));
    }
    e->ngroups = d->nemitters;
    e->groups = calloc((size_t)(d->nemitters ? d->nemitters : 1), sizeof *e->groups);
    e->draw_order = calloc((size_t)(d->nemitters ? d->nemitters : 1), sizeof *e->draw_order);
    e->pots = calloc((size_t)(d->nforces ? d->nforces : 1), sizeof *e->pots);
    e->pot_force = calloc((size_t)(d->nforces ? d->nforces : 1), sizeof *e->pot_force);
    if (!e->groups || !e->draw_order || !e->pots || !e->pot_force ||
        isk_sprite_cache_create(&e->sprites, 256) != ISK_OK || isk_sinlut_init(&e->sin_table, 4096) != ISK_OK) {
        isk_effect_destroy(e);
        return isk_error_set(err, ISK_ERR_NOMEM, "effect: out of memory");
    }
    /* Draw order: by `order`, ties by definition order (insertion sort: stable). */
    for (int i = 0; i < e->ngroups; i++) {
        int j = i;
        while (j > 0 && d->emitters[e->draw_order[j - 1]].order > d->emitters[i].order) {
            e->draw_order[j] = e->draw_order[j - 1];
            j--;
        }
        e->draw_order[j] = i;
    }
    if ((s = build(e, err)) != ISK_OK) {
        isk_effect_destroy(e);
        return s;
    }
    *out = e;
    return ISK_OK;
}

void isk_effect_destroy(isk_effect *e)
{
    if (!e)
        return;
    for (int i = 0; e->groups && i < e->ngroups; i++)
        free_group(&e->groups[i]);
    free(e->groups);
    free(e->draw_order);
    free(e->pots);
    free(e->pot_force);
    isk_sprite_cache_destroy(e->sprites);
    isk_effect_def_free(&e->def);
    free(e);
}

isk_status isk_effect_reset(isk_effect *e)
{
    if (!e)
        return ISK_ERR_NULL;
    return build(e, NULL);
}

/* ---- the frame loop --------------------------------------------------------- */

static void stage_drift(size_t n, double *restrict x, double *restrict y, double *restrict vx,
                        double *restrict vy, double ax, double ay, double h)
{
    /* v += a*h; r += h*v: semi-implicit Euler with a constant acceleration.
     * With a = (0, -g) this is the hand-written gravity loop, operation for
     * operation (vy + (-g*h) == vy - g*h in IEEE arithmetic). */
    const double dvx = ax * h, dvy = ay * h;
    if (ax == 0.0) {
        /* Gravity alone (the common case): vx does not change, so it is only
         * read; skipping its store saves an eighth of the memory traffic.
         * vx + 0 == vx for every vx but -0, and -0 + 0 = +0 would only
         * change the sign of a zero velocity, never a position. */
        for (size_t i = 0; i < n; i++) {
            double nvy = vy[i] + dvy;
            vy[i] = nvy;
            x[i] = x[i] + h * vx[i];
            y[i] = y[i] + h * nvy;
        }
        return;
    }
    for (size_t i = 0; i < n; i++) {
        double nvx = vx[i] + dvx, nvy = vy[i] + dvy;
        vx[i] = nvx;
        vy[i] = nvy;
        x[i] = x[i] + h * nvx;
        y[i] = y[i] + h * nvy;
    }
}

static void stage_slow(size_t n, double *restrict vx, double *restrict vy, double slowing, double h)
{
    /* The fire thesis's 1 - slowing*dt, clamped so a long frame can stop a
     * particle but never reverse it. */
    double f = 1.0 - slowing * h;
    if (!(f > 0.0))
        f = 0.0;
    for (size_t i = 0; i < n; i++) {
        vx[i] = isk_k_flush(vx[i] * f);
        vy[i] = isk_k_flush(vy[i] * f);
    }
}

static void stage_drift_slow(size_t n, double *restrict x, double *restrict y, double *restrict vx,
                             double *restrict vy, double ax, double ay, double slowing, double h)
{
    /* The fire thesis's Emitter::Advance: v -= F*dt; v *= slow; p += v*dt
     * (F in its sign is -a), slow clamped at 0. */
    const double dvx = ax * h, dvy = ay * h;
    double f = 1.0 - slowing * h;
    if (!(f > 0.0))
        f = 0.0;
    for (size_t i = 0; i < n; i++) {
        double nvx = isk_k_flush((vx[i] + dvx) * f), nvy = isk_k_flush((vy[i] + dvy) * f);
        vx[i] = nvx;
        vy[i] = nvy;
        x[i] = x[i] + h * nvx;
        y[i] = y[i] + h * nvy;
    }
}

static void stage_oscillate(isk_effect *e, fx_group *g, size_t o, size_t n, double *x, double *vx, double h)
{
    const isk_emitter_def *em = g->def;
    double decay = 1.0 - em->osc_decay * h;
    if (!(decay > 0.0))
        decay = 0.0;
    double *amp = g->osc_amp + o, *ph = g->osc_phase + o, *om = g->osc_omega + o, *off = g->osc_off + o;
    /* Four loops, one per choice, so no loop branches per particle. */
    if (em->osc_use_table && em->osc_faithful) {
        for (size_t i = 0; i < n; i++) {
            ph[i] += om[i] * h;
            double s = amp[i] * isk_sinlut_floor(&e->sin_table, ph[i]);
            double dx = s - off[i];
            x[i] += dx; vx[i] += dx; off[i] = s; amp[i] = isk_k_flush(amp[i] * decay);
        }
    } else if (em->osc_use_table) {
        for (size_t i = 0; i < n; i++) {
            ph[i] += om[i] * h;
            double s = amp[i] * isk_sinlut_floor(&e->sin_table, ph[i]);
            x[i] += s - off[i]; off[i] = s; amp[i] = isk_k_flush(amp[i] * decay);
        }
    } else if (em->osc_faithful) {
        for (size_t i = 0; i < n; i++) {
            ph[i] += om[i] * h;
            double s = amp[i] * sin(ph[i]);
            double dx = s - off[i];
            x[i] += dx; vx[i] += dx; off[i] = s; amp[i] = isk_k_flush(amp[i] * decay);
        }
    } else {
        for (size_t i = 0; i < n; i++) {
            ph[i] += om[i] * h;
            double s = amp[i] * sin(ph[i]);
            x[i] += s - off[i]; off[i] = s; amp[i] = isk_k_flush(amp[i] * decay);
        }
    }
}

void fx_run_stages(isk_effect *e, fx_group *g, size_t begin, size_t end, double h)
{
    isk_particles *p = &g->store;
    const isk_bounds *walls = &e->def.bounds;
    for (size_t o = begin; o < end; o += ISK_SIM_BLOCK) {
        size_t m = end - o < ISK_SIM_BLOCK ? end - o : ISK_SIM_BLOCK;
        double *x = p->x + o, *y = p->y + o, *vx = p->vx + o, *vy = p->vy + o;
        for (int si = 0; si < g->nstages; si++) {
            switch (g->stages[si].kind) {
            case FX_STAGE_REMEMBER:
                memcpy(e->x_old, x, m * sizeof *x);
                memcpy(e->y_old, y, m * sizeof *y);
                break;
            case FX_STAGE_DRIFT:
                stage_drift(m, x, y, vx, vy, g->ax, g->ay, h);
                break;
            case FX_STAGE_DRIFT_SLOW:
                stage_drift_slow(m, x, y, vx, vy, g->ax, g->ay, g->slow_per_s, h);
                break;
            case FX_STAGE_MOTION:
                isk_integrate_block(g->integrator, &g->forces, &e->scratch, m, x, y, vx, vy, p->m + o, h);
                break;
            case FX_STAGE_SLOW:
                stage_slow(m, vx, vy, g->slow_per_s, h);
                break;
            case FX_STAGE_OSCILLATE:
                stage_oscillate(e, g, o, m, x, vx, h);
                break;
            case FX_STAGE_WALLS:
                isk_bounds_apply_arrays(walls, m, x, y, vx, vy);
                break;
            case FX_STAGE_DEFLECT:
                memset(e->killed, 0, m);
                isk_deflect(g->defl, g->ndefl, x, y, vx, vy, e->x_old, e->y_old, m, &g->rng, e->killed, NULL);
                if (g->defl_can_kill)
                    for (size_t i = 0; i < m; i++)
                        if (e->killed[i])
                            p->life[o + i] = -INFINITY; /* culled at the end of the substep */
                break;
            case FX_STAGE_AGE:
                isk_particles_age(p, o, o + m, h);
                break;
            default: /* frame-level stages run in isk_effect_step */
                break;
            }
        }
    }
}

static void advance_one(isk_effect *e, fx_group *g, size_t i, double age)
{
    if (age > 0)
        fx_run_stages(e, g, i, i + 1, age);
}

/* The group's working copies of the potentials take the effect's current
 * position and state; a potential switched off anywhere is dropped. */
static void sync_potentials_in(isk_effect *e, fx_group *g)
{
    int dropped = 0;
    for (size_t k = 0; k < g->npots; k++) {
        const isk_potential *src = &e->pots[g->pot_src[k]];
        dropped |= !src->enabled;
        g->pots[k].r = src->r;
    }
    if (dropped)
        compile_group(e, g);
}

static int sync_potentials_out(isk_effect *e, fx_group *g)
{
    int off = 0;
    for (size_t k = 0; k < g->npots; k++)
        if (!g->pots[k].enabled && e->pots[g->pot_src[k]].enabled) {
            e->pots[g->pot_src[k]].enabled = 0; /* the sticky max-distance switch */
            off = 1;
        }
    return off;
}

static isk_status release_due(isk_effect *e, fx_group *g)
{
    const isk_emitter_def *em = g->def;
    if (em->source == ISK_SOURCE_EXPLOSION && !g->fired && e->time >= em->start) {
        g->fired = 1;
        isk_status s = fire_explosion(e, g, em->explosion, em->pos.x, em->pos.y, em->count, em->kick);
        if (s != ISK_OK)
            return s;
    }
    if (g->mc_active && !isk_multi_coulomb_done(&g->mc)) {
        size_t before = g->store.count;
        isk_status s = isk_multi_coulomb_release(&g->mc, &g->store, &g->rng, NULL);
        if (s != ISK_OK || (s = adopt(e, g, before)) != ISK_OK)
            return s;
    }
    return ISK_OK;
}

isk_status isk_effect_step(isk_effect *e)
{
    if (!e)
        return ISK_ERR_NULL;
    const isk_effect_def *d = &e->def;
    /* The thesis draws the potentials, then moves them: the move of the
     * previous frame happens now, after that frame was rendered. */
    if (e->last_frame_time != 0)
        for (size_t k = 0; k < e->npots; k++)
            isk_potential_move(&e->pots[k], e->last_frame_time);
    size_t total = 0;
    const double frame_time = d->dt / d->speed_divisor;
    for (int gi = 0; gi < e->ngroups; gi++) {
        fx_group *g = &e->groups[gi];
        isk_particles *p = &g->store;
        if (g->walls_after_draw && e->frame > 0)
            isk_bounds_apply(&d->bounds, p, 0, p->count);
        isk_status s = release_due(e, g);
        if (s != ISK_OK)
            return s;
        sync_potentials_in(e, g);
        const int N = g->substeps;
        const double h = d->dt / (double)N / d->speed_divisor;
        for (int j = 0; j < N; j++) {
            size_t n = p->count;
            fx_run_stages(e, g, 0, n, h);
            if (g->has_stage[FX_STAGE_SPAWN]) {
                s = fx_stream_spawn(e, g, e->time + h * j, h, advance_one);
                if (s != ISK_OK)
                    return s;
            }
            if (g->has_stage[FX_STAGE_CULL])
                fx_group_cull(g);
            if (sync_potentials_out(e, g))
                compile_group(e, g);
        }
        if (g->mc_active)
            isk_multi_coulomb_advance(&g->mc, h * (double)N);
        total += p->count;
    }
    e->frame++;
    /* Multiplied, not accumulated: 144 steps of 1/144 s end at 1 s as
     * exactly as 30 steps of 1/30 s do. */
    e->time = (double)e->frame * frame_time;
    /* The thesis's h stays unassigned when there are no particles: then its
     * potentials do not move. */
    e->last_frame_time = total ? frame_time : 0.0;
    if (d->click_auto && d->click_after > 0 && e->frame == d->click_after)
        return isk_effect_click(e, d->click_x, d->click_y);
    return ISK_OK;
}

isk_status isk_effect_step_render(isk_effect *e, isk_canvas *c)
{
    isk_status s = isk_effect_step(e);
    return s != ISK_OK ? s : isk_effect_render(e, c);
}

isk_status isk_effect_run(isk_effect *e, isk_canvas *c, long frames)
{
    if (!e || !c)
        return ISK_ERR_NULL;
    if (frames < 0)
        return ISK_ERR_RANGE;
    if (c->width != e->def.width || c->height != e->def.height)
        return ISK_ERR_SIZE;
    isk_status s = ISK_OK;
    if (e->def.clear) {
        for (long i = 0; i < frames && s == ISK_OK; i++)
            s = isk_effect_step(e);
        return s != ISK_OK ? s : isk_effect_render(e, c);
    }
    isk_canvas_fill(c, e->def.background);
    for (long i = 0; i < frames && s == ISK_OK; i++)
        s = isk_effect_step_render(e, c);
    return s;
}

isk_status isk_effect_render(isk_effect *e, isk_canvas *c)
{
    if (!e || !c)
        return ISK_ERR_NULL;
    if (c->width != e->def.width || c->height != e->def.height)
        return ISK_ERR_SIZE;
    return fx_render(e, c);
}

isk_status isk_effect_click(isk_effect *e, double x, double y)
{
    if (!e)
        return ISK_ERR_NULL;
    if (!isfinite(x) || !isfinite(y))
        return ISK_ERR_NAN;
    const isk_effect_def *d = &e->def;
    if (!(d->click_enabled || d->click_auto) || e->ngroups == 0)
        return ISK_OK;
    int gi = d->click_emitter >= 0 ? d->click_emitter : 0;
    fx_group *g = &e->groups[gi];
    return fire_explosion(e, g, d->click_explosion, x, y, d->click_count, g->def->kick);
}

isk_status isk_effect_set_substeps(isk_effect *e, int substeps)
{
    if (!e)
        return ISK_ERR_NULL;
    if (substeps < 1 || substeps > 10000)
        return ISK_ERR_RANGE;
    e->def.substeps = substeps;
    for (int i = 0; i < e->ngroups; i++)
        if (!e->groups[i].def->substeps)
            e->groups[i].substeps = substeps;
    return ISK_OK;
}

/* ---- inspection ------------------------------------------------------------ */

void isk_effect_describe(const isk_effect *e, FILE *out)
{
    if (!e || !out)
        return;
    for (int gi = 0; gi < e->ngroups; gi++) {
        const fx_group *g = &e->groups[gi];
        const isk_emitter_def *em = g->def;
        static const char *src[] = {"particle", "explosion", "layer", "stream"};
        static const char *draw[] = {"dot", "pixel", "disc", "sprite", "none", "browser dot"};
        fprintf(out, "emitter %s (%s, %zu particles, %d substep%s of %s):\n", em->name, src[em->source],
                g->store.count, g->substeps, g->substeps == 1 ? "" : "s", isk_integrator_name(g->integrator));
        for (int si = 0; si < g->nstages; si++)
            fprintf(out, "  %s\n", g->stages[si].label);
        if (g->walls_after_draw)
            fprintf(out, "  walls     %s (after drawing)\n",
                    e->def.bounds.mode == ISK_BOUNCE_THESIS ? "thesis zarobi" : "reflect");
        if (em->draw != ISK_DRAW_NONE)
            fprintf(out, "  draw      %s, %s%s%s%s\n", draw[em->draw], isk_blend_name(em->blend),
                    g->has_color_ramp ? ", colour over life" : "", g->has_alpha_ramp ? ", alpha over life" : "",
                    g->has_size_ramp ? ", size over life" : "");
    }
}

size_t isk_effect_particle_count(const isk_effect *e)
{
    size_t n = 0;
    for (int i = 0; e && i < e->ngroups; i++)
        n += e->groups[i].store.count;
    return n;
}

double isk_effect_time(const isk_effect *e) { return e ? e->time : 0.0; }
long isk_effect_frame(const isk_effect *e) { return e ? e->frame : 0; }
const isk_view *isk_effect_view(const isk_effect *e) { return e ? &e->view : NULL; }
const isk_effect_def *isk_effect_definition(const isk_effect *e) { return e ? &e->def : NULL; }
int isk_effect_emitter_count(const isk_effect *e) { return e ? e->ngroups : 0; }

const isk_particles *isk_effect_particles(const isk_effect *e, int emitter)
{
    return e && emitter >= 0 && emitter < e->ngroups ? &e->groups[emitter].store : NULL;
}

size_t isk_effect_dropped(const isk_effect *e, int emitter)
{
    return e && emitter >= 0 && emitter < e->ngroups ? e->groups[emitter].dropped : 0;
}
