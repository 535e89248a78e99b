/* SPDX-License-Identifier: MIT */
/* Validation of effect definitions (see effect_check.h): the key table's
 * rows for every field, one function per section for what spans fields. */
#include "effect_check.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "effect_internal.h"
#include "iskra/limits.h"
#include "iskra/shape.h"
#include "key_value.h"

typedef struct ctx {
    const isk_effect_def *d;
    isk_section_kind section;
    int index;
    fx_report *r;
} ctx;

static isk_status report(ctx *c, isk_status s, const char *key, int show_key, const char *fmt, va_list ap)
{
    char msg[400];
    vsnprintf(msg, sizeof msg, fmt, ap);
    if (c->r->status == ISK_OK)
        c->r->status = s;
    c->r->emit(c->r, s, c->section, c->index, key, show_key, msg);
    return s;
}

/* A failure about `key`: "key: message" with show_key, else "message"
 * pointing at the key's line (when it has one). */
static isk_status fail(ctx *c, const char *key, int show_key, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
static isk_status fail(ctx *c, const char *key, int show_key, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    isk_status s = report(c, ISK_ERR_RANGE, key, show_key, fmt, ap);
    va_end(ap);
    return s;
}
#define bad_key(c, key, ...) fail(c, key, 1, __VA_ARGS__)
#define bad_item(c, key, ...) fail(c, key, 0, __VA_ARGS__)

/* ---- per section: what spans fields -------------------------------------------- */

static isk_status check_view(ctx *c)
{
    const isk_effect_def *d = c->d;
    if (d->view_kind == ISK_VIEWDEF_CAMERA) {
        isk_view v;
        if (isk_view_camera(&v, d->width, d->height, d->zoom, d->tx, d->ty) != ISK_OK)
            return bad_item(c, "zoom", "zoom %.15g and pan (%.15g, %.15g) give no usable camera", d->zoom, d->tx, d->ty);
        return ISK_OK;
    }
    if (!(d->xmin < d->xmax))
        return bad_item(c, "xmax", "xmin (%.15g) must be less than xmax (%.15g)", d->xmin, d->xmax);
    if (!(d->ymin < d->ymax))
        return bad_item(c, "ymax", "ymin (%.15g) must be less than ymax (%.15g)", d->ymin, d->ymax);
    if (!isfinite(d->xmax - d->xmin) || !isfinite(d->ymax - d->ymin))
        return bad_item(c, "xmax", "the window is too large: its width or height (xmax - xmin, ymax - ymin) "
                                   "overflows a double");
    return ISK_OK;
}

static isk_status check_force(ctx *c)
{
    const isk_force_def *f = &c->d->forces[c->index];
    if (f->kind != ISK_FORCE_POTENTIAL)
        return ISK_OK;
    isk_potential p = f->pot;
    if (isk_potential_set_law(&p, f->law, f->exponent) != ISK_OK || isk_potential_validate(&p) != ISK_OK) {
        if (isfinite(p.P) && !(p.P >= ISK_P_MIN && p.P <= ISK_P_MAX))
            return bad_key(c, "exponent", "%.15g read as the %s law is P = %.15g; the force goes as d^(1-P) and "
                                          "P must be %g..%g (from a spring's d to d^-16)",
                           f->exponent, isk_coulomb_law_names[f->law], p.P, ISK_P_MIN, ISK_P_MAX);
        return bad_key(c, "exponent", "gives no usable potential");
    }
    return ISK_OK;
}

static isk_status check_deflector(ctx *c)
{
    const isk_deflector *g = &c->d->deflectors[c->index].seg;
    if (g->x0 == g->x1 && g->y0 == g->y1)
        return bad_key(c, "segment", "the two end points are the same (a segment needs a length)");
    return ISK_OK;
}

static isk_status check_bounds(ctx *c)
{
    const isk_bounds *b = &c->d->bounds;
    if (!b->sides)
        return ISK_OK;
    if (!(b->xmin < b->xmax) || !(b->ymin < b->ymax))
        return bad_key(c, "window", "needs xmin < xmax and ymin < ymax, got %.15g, %.15g, %.15g, %.15g", b->xmin,
                       b->xmax, b->ymin, b->ymax);
    if (!isfinite(b->xmax - b->xmin) || !isfinite(b->ymax - b->ymin))
        return bad_key(c, "window", "is too large: its width or height overflows a double");
    if (!(b->xmin + b->margin < b->xmax - b->margin) || !(b->ymin + b->margin < b->ymax - b->margin))
        return bad_item(c, "margin", "margin %.15g leaves no room between the walls", b->margin);
    return ISK_OK;
}

static size_t limit_of(const isk_emitter_def *e)
{
    return e->born.limit ? e->born.limit : ISK_EXPLODE_THESIS_LIMIT;
}

static isk_status check_stream(ctx *c, const isk_emitter_def *e)
{
    isk_shape s = {0};
    s.kind = e->born.shape;
    s.a = e->born.shape_a;
    s.b = e->born.shape_b;
    s.angle = e->born.shape_angle;
    s.ellipse_mode = e->born.shape_faithful ? ISK_ELLIPSE_THESIS : ISK_ELLIPSE_UNIFORM;
    if (isk_shape_check(&s) != ISK_OK)
        return bad_key(c, "shape", "%s needs shape_a, shape_b >= 0%s", isk_shape_names[e->born.shape],
                       e->born.shape == ISK_SHAPE_RING ? " and shape_a <= shape_b" : "");
    if (e->launch.speed_min > e->launch.speed_max)
        return bad_key(c, "speed_max", "must be >= speed_min (%.15g)", e->launch.speed_min);
    if (e->born.count > e->born.capacity)
        return bad_key(c, "count", "a burst of %zu exceeds the capacity %zu", e->born.count, e->born.capacity);
    return ISK_OK; /* rate 0 and no bursts is an idle stream: stopped live, and saved and loaded so */
}

/* ---- sub-emitters and trails ----
 * on_death / on_hit must name a sub-emitter; a sub-emitter must be named by
 * some emitter's on_death or on_hit (an error, not a warning: it could never
 * emit, so it is a mistake, most likely a misspelt or forgotten reference).
 * Chains and cycles are allowed: every event's children are bounded by the
 * pool (effect_events.c). */
static isk_status check_sub_emitters(ctx *c, const isk_emitter_def *e)
{
    const isk_effect_def *d = c->d;
    static const char *const keys[2] = {"on_death", "on_hit"};
    const int refs[2] = {e->events.on_death, e->events.on_hit};
    for (int k = 0; k < 2; k++) {
        if (refs[k] < 0)
            continue;
        const isk_emitter_def *t = &d->emitters[refs[k]];
        if (t->born.source != ISK_SOURCE_SUB)
            return bad_key(c, keys[k], "'%s' is not a sub-emitter (it needs source = sub)", t->name);
    }
    if (e->born.source != ISK_SOURCE_SUB)
        return ISK_OK;
    if (e->born.count < 1 || e->born.count > e->born.capacity)
        return bad_key(c, "count", "a sub-emitter fires 1..capacity (%zu) particles per event", e->born.capacity);
    for (int i = 0; i < d->nemitters; i++)
        if (d->emitters[i].events.on_death == c->index || d->emitters[i].events.on_hit == c->index)
            return ISK_OK;
    return bad_item(c, "source", "a sub-emitter that no emitter's on_death or on_hit names never fires");
}
/* ---- end of sub-emitters and trails ---- */

static isk_status check_emitter(ctx *c)
{
    const isk_effect_def *d = c->d;
    const isk_emitter_def *e = &d->emitters[c->index];
    switch (e->born.source) {
    case ISK_SOURCE_EXPLOSION:
    case ISK_SOURCE_LAYER: {
        /* An empty layer is the thesis simulator's own start ("Sloj" 0): the
         * particles come from clicks. */
        const size_t least = e->born.source == ISK_SOURCE_LAYER ? 0 : 1;
        if (e->born.count < least || e->born.count > limit_of(e))
            return bad_key(c, "count", "must be %zu..%zu (raise limit for more)", least, limit_of(e));
        if (e->born.count > e->born.capacity)
            return bad_key(c, "count", "%zu exceeds the capacity %zu (raise capacity for more)", e->born.count,
                           e->born.capacity);
        if (e->born.source == ISK_SOURCE_LAYER &&
            (e->born.rect[0] > e->born.rect[1] || e->born.rect[2] > e->born.rect[3]))
            return bad_key(c, "rect", "needs xmin <= xmax and ymin <= ymax");
        break;
    }
    case ISK_SOURCE_STREAM:
    case ISK_SOURCE_SUB: { /* a sub-emitter: a stream's shape and launch */
        isk_status s = check_stream(c, e);
        if (s != ISK_OK)
            return s;
        break;
    }
    default:
        break;
    }
    /* A prewarm runs at create and reset, so it is bounded (iskra/limits.h):
     * a stream's own, and a sub-emitter's, which runs as long as the
     * longest prewarm of the emitters that feed it. */
    double frames[ISK_EFFECT_MAX_EMITTERS];
    isk__fx_prewarm_offsets(d, frames);
    const double steps = frames[c->index] * (double)(e->motion.substeps ? e->motion.substeps : d->substeps);
    if (frames[c->index] > 0 && !(steps <= ISK_PREWARM_MAX_STEPS)) {
        if (e->born.source == ISK_SOURCE_SUB)
            return bad_item(c, "substeps", "the emitters feeding this sub-emitter prewarm %.15g frames, %.15g of its "
                                           "substeps; at most %d (iskra/limits.h): lower their prewarm or its substeps",
                            frames[c->index], steps, ISK_PREWARM_MAX_STEPS);
        return bad_key(c, "prewarm", "%.15g s is %.15g substeps of this emitter at dt %.15g; at most %d "
                                     "(iskra/limits.h)",
                       e->born.prewarm, steps, d->dt, ISK_PREWARM_MAX_STEPS);
    }
    char why[200];
    const char *looks = isk__fx_looks_check(e, why, sizeof why);
    if (looks)
        return bad_key(c, looks, "%s", why);
    isk_status se = check_sub_emitters(c, e);
    if (se != ISK_OK)
        return se;
    if (e->motion.slow_faithful && e->motion.slowing_range > 0)
        return bad_key(c, "slowing_range", "not with slow_faithful (the fire thesis's order slows every particle "
                                           "alike, in one fused step)");
    if (e->motion.slow_faithful && e->motion.slowing > 0) {
        /* The thesis order is a fused constant-acceleration kernel. */
        isk_integrator m = e->motion.integrator == ISK_INTEGRATE_INHERIT ? d->integrator : e->motion.integrator;
        int ok = m == ISK_INTEGRATE_SEMI_EULER && d->fidelity == ISK_FIDELITY_SOUND;
        for (int i = 0; ok && i < e->motion.nforces; i++) {
            const isk_force_def *f = &d->forces[e->motion.forces[i]];
            ok = !(f->kind == ISK_FORCE_DRAG && f->b != 0) && f->kind != ISK_FORCE_POTENTIAL;
        }
        if (!ok)
            return bad_key(c, "slow_faithful", "the thesis slowing order needs the semi-implicit Euler integrator, "
                                               "sound fidelity and only gravity/wind forces");
    }
    return ISK_OK;
}

static isk_status check_drawing(ctx *c)
{
    const isk_drawing_def *g = &c->d->drawings[c->index];
    if (g->kind == ISK_DRAWING_POLYLINE && (!g->points || g->npoints < 2))
        return bad_key(c, "points", "a polyline needs 2 or more points");
    if (g->kind == ISK_DRAWING_POLYGON && (!g->points || g->npoints < 3))
        return bad_key(c, "points", "a polygon needs 3 or more points");
    return ISK_OK;
}

/* What spans a probe's keys: a gate's end points differ, a region and a
 * histogram's range are not empty. */
static isk_status check_probe(ctx *c)
{
    const isk_probe_def *q = &c->d->probes[c->index];
    if (q->kind == ISK_PROBE_GATE && q->segment[0] == q->segment[2] && q->segment[1] == q->segment[3])
        return bad_key(c, "segment", "the two end points are the same point");
    if (q->kind == ISK_PROBE_REGION && !(q->rect[0] < q->rect[1] && q->rect[2] < q->rect[3]))
        return bad_key(c, "rect", "needs xmin < xmax and ymin < ymax (got %.15g, %.15g, %.15g, %.15g)", q->rect[0],
                       q->rect[1], q->rect[2], q->rect[3]);
    if (q->kind == ISK_PROBE_HISTOGRAM && !(q->range[0] < q->range[1]))
        return bad_key(c, "range", "needs lo < hi (got %.15g, %.15g)", q->range[0], q->range[1]);
    return ISK_OK;
}

static isk_status check_click(ctx *c)
{
    const isk_effect_def *d = c->d;
    const isk_click_def *k = &d->click;
    if (!k->enabled && !k->at_start)
        return ISK_OK;
    if (d->nemitters == 0)
        return bad_item(c, "emitter", "the click needs an emitter to receive it");
    const isk_emitter_def *e = &d->emitters[k->emitter >= 0 ? k->emitter : 0];
    if (k->count > limit_of(e))
        return bad_key(c, "count", "%zu is more than emitter '%s' accepts in one explosion (its limit is %zu: raise "
                                   "it)",
                       k->count, e->name, limit_of(e));
    return ISK_OK;
}

typedef isk_status (*section_check)(ctx *c);

static const section_check section_checks[ISK_SECTION_COUNT] = {
    [ISK_SECTION_VIEW] = check_view,       [ISK_SECTION_FORCE] = check_force,
    [ISK_SECTION_DEFLECTOR] = check_deflector, [ISK_SECTION_BOUNDS] = check_bounds,
    [ISK_SECTION_EMITTER] = check_emitter, [ISK_SECTION_DRAWING] = check_drawing,
    [ISK_SECTION_CLICK] = check_click,     [ISK_SECTION_PROBE] = check_probe,
};

/* ---- the whole item, the whole definition ---------------------------------------- */

isk_status isk__fx_check_item(const isk_effect_def *d, isk_section_kind s, int index, int rows, fx_report *r)
{
    ctx c = {d, s, index, r};
    const void *item = isk__fx_section_item_c(d, s, index);
    if (!item)
        return bad_item(&c, NULL, "no such item");
    const int kind = isk__fx_item_kind(d, s, index);
    int nkinds = 0;
    isk_section_kind_names(s, &nkinds);
    if (nkinds && (kind < 0 || kind >= nkinds))
        return bad_key(&c, isk_section_kind_key(s), "unknown %s %d", isk_section_kind_key(s), kind);
    for (int i = 0; rows && i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        char why[300];
        if (k->section == s && isk__fx_key_applies(k, kind) && isk__fx_key_check(k, item, d, why, sizeof why) != 0)
            return bad_key(&c, k->name, "%s", why);
    }
    return section_checks[s] ? section_checks[s](&c) : ISK_OK;
}

static isk_status structure_fails(const isk_effect_def *d, fx_report *r, isk_status s, const char *msg);

/* Every name follows the scene files' rule (names.c), so a definition
 * made in C saves to a file that loads: no name carries a ']' or a line
 * break into a section header.  Checked before any name is compared or
 * printed (a name need not even be terminated). */
static isk_status valid_names(const isk_effect_def *d, isk_section_kind s, fx_report *r)
{
    for (int i = 0; i < isk__fx_section_items(d, s); i++) {
        const char *a = isk__fx_item_name(d, s, i);
        if (isk_section_named(s) && *a && (!isk__fx_name_ok(a, ISK_NAME_MAX) || isk__fx_name_reserved(a))) {
            char why[200];
            snprintf(why, sizeof why, "%s %d: a name is 1..%d letters, digits, '_', '-' or '.' (not \"all\" or "
                     "\"none\")", isk_section_name(s), i, ISK_NAME_MAX - 1);
            return structure_fails(d, r, ISK_ERR_RANGE, why);
        }
    }
    return ISK_OK;
}

static isk_status unique_names(const isk_effect_def *d, isk_section_kind s, fx_report *r)
{
    int n = isk__fx_section_items(d, s);
    for (int i = 0; i < n; i++) {
        const char *a = isk__fx_item_name(d, s, i);
        for (int j = 0; *a && j < i; j++)
            if (!strcmp(a, isk__fx_item_name(d, s, j))) {
                ctx c = {d, s, i, r};
                return bad_item(&c, NULL, "a second %s named '%s'", isk_section_name(s), a);
            }
    }
    return ISK_OK;
}

static isk_status structure_fails(const isk_effect_def *d, fx_report *r, isk_status s, const char *msg)
{
    (void)d;
    if (r->status == ISK_OK)
        r->status = s;
    r->emit(r, s, ISK_SECTION_SCENE, 0, NULL, 0, msg);
    return s;
}

/* Every pool full, every texture and the canvas must fit the program's
 * memory limit (effect_budget.c says what takes what). */
static isk_status memory_fits(const isk_effect_def *d, fx_report *r)
{
    char msg[1200];
    return isk__fx_memory_over(d, msg, sizeof msg) ? structure_fails(d, r, ISK_ERR_SIZE, msg) : ISK_OK;
}

isk_status isk__fx_check_def(const isk_effect_def *d, fx_report *r)
{
    if (d->nforces < 0 || d->nforces > ISK_EFFECT_MAX_FORCES || d->nemitters < 0 ||
        d->nemitters > ISK_EFFECT_MAX_EMITTERS || d->ndeflectors < 0 || d->ndeflectors > ISK_EFFECT_MAX_DEFLECTORS ||
        d->ndrawings < 0 || d->ndrawings > ISK_EFFECT_MAX_DRAWINGS || d->nprobes < 0 ||
        d->nprobes > ISK_EFFECT_MAX_PROBES) {
        char msg[160];
        snprintf(msg, sizeof msg, "at most %d forces, %d deflectors, %d emitters, %d drawings and %d probes",
                 ISK_EFFECT_MAX_FORCES, ISK_EFFECT_MAX_DEFLECTORS, ISK_EFFECT_MAX_EMITTERS, ISK_EFFECT_MAX_DRAWINGS,
                 ISK_EFFECT_MAX_PROBES);
        return structure_fails(d, r, ISK_ERR_SIZE, msg);
    }
    if ((d->nforces && !d->forces) || (d->ndeflectors && !d->deflectors) || (d->nemitters && !d->emitters) ||
        (d->ndrawings && !d->drawings) || (d->nprobes && !d->probes))
        return structure_fails(d, r, ISK_ERR_NULL, "a count is set but its array is NULL");
    char why[sizeof(((isk_error *)0)->message)];
    isk_status ts = isk__fx_def_textures_check(d, why, sizeof why);
    if (ts != ISK_OK)
        return structure_fails(d, r, ts, why);
    if (d->threads < 0 || d->threads > 256)
        return structure_fails(d, r, ISK_ERR_RANGE, "threads must be 0 (the default) .. 256");
    for (int s = 0; s < ISK_SECTION_COUNT; s++) {
        isk_status st = valid_names(d, (isk_section_kind)s, r);
        if (st == ISK_OK)
            st = unique_names(d, (isk_section_kind)s, r);
        for (int i = 0; st == ISK_OK && i < isk__fx_section_items(d, (isk_section_kind)s); i++)
            st = isk__fx_check_item(d, (isk_section_kind)s, i, 1, r);
        if (st != ISK_OK)
            return st;
    }
    /* last: a value out of its key's range is reported by its key first */
    return memory_fits(d, r);
}

/* ---- isk_effect_create's reporter ---------------------------------------------- */

typedef struct create_report {
    fx_report r; /* first: the emit callback gets this struct back */
    const isk_effect_def *d;
    isk_error *err;
} create_report;

/* "emitter 'smoke' (line 12): rate: expected ..." */
static void create_emit(fx_report *r, isk_status s, isk_section_kind section, int index, const char *key,
                        int show_key, const char *msg)
{
    const create_report *cr = (const create_report *)r;
    const isk_effect_def *d = cr->d;
    char where[32] = "";
    int line = isk__fx_item_line(d, section, index);
    if (line > 0)
        snprintf(where, sizeof where, " (line %d)", line);
    const char *sec = isk_section_name(section);
    if (isk_section_named(section))
        isk_error_set(cr->err, s, "%s '%s'%s: %s%s%s", sec, isk__fx_item_name(d, section, index), where,
                      key && show_key ? key : "", key && show_key ? ": " : "", msg);
    else
        isk_error_set(cr->err, s, "%s%s: %s%s%s", sec, where, key && show_key ? key : "",
                      key && show_key ? ": " : "", msg);
}

isk_status isk__fx_check(const isk_effect_def *d, isk_error *err)
{
    create_report cr = {{create_emit, NULL, ISK_OK}, d, err};
    return isk__fx_check_def(d, &cr.r);
}
