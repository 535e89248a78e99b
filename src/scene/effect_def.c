/* Building and copying effect definitions (plain data, see iskra/effect.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "effect_internal.h"

const char *const isk_force_kind_names[ISK_FORCE_KIND_COUNT] = {"gravity", "drag", "wind", "potential"};
const char *const isk_source_names[ISK_SOURCE_KIND_COUNT] = {"particle", "explosion", "layer", "stream"};
const char *const isk_rate_mode_names[ISK_RATE_MODE_COUNT] = {"accumulate", "thesis"};
const char *const isk_birth_mode_names[ISK_BIRTH_MODE_COUNT] = {"backdate", "thesis-jitter", "frame"};
const char *const isk_draw_mode_names[ISK_DRAW_COUNT] = {"dot", "pixel", "disc", "sprite", "none", "dot-browser"};
const char *const isk_drawing_kind_names[ISK_DRAWING_KIND_COUNT] = {"polyline", "disc", "text", "polygon", "sprite"};
const char *const isk_units_names[2] = {"world", "pixels"};
const char *const isk_view_kind_names[ISK_VIEWDEF_COUNT] = {"window", "camera"};

void isk_effect_def_init(isk_effect_def *d)
{
    memset(d, 0, sizeof *d);
    d->width = 600;
    d->height = 600;
    d->background = ISK_BLACK;
    d->clear = 1;
    d->view_kind = ISK_VIEWDEF_WINDOW;
    d->xmin = -10; d->xmax = 10; d->ymin = -10; d->ymax = 10;
    d->zoom = 10;
    d->dt = 1.0 / 60.0;
    d->substeps = 1;
    d->speed_divisor = 1.0;
    d->integrator = ISK_INTEGRATE_SEMI_EULER;
    d->seed = 1;
    d->centre = ISK_FIDELITY_SOUND;
    d->bounds.mode = ISK_BOUNCE_REFLECT;
    d->bounds.sides = 0;
    d->bounds.restitution = 1.0;
    d->click_explosion = ISK_EXPLOSION_COULOMB;
    d->click_count = 1000;
    d->click_emitter = -1;
}

void isk_effect_def_free(isk_effect_def *d)
{
    if (!d)
        return;
    for (int i = 0; i < d->ndrawings; i++)
        free(d->drawings[i].points);
    free(d->forces);
    free(d->deflectors);
    free(d->deflector_names);
    free(d->emitters);
    free(d->drawings);
    memset(d, 0, sizeof *d);
}

static void set_name(char *dst, const char *name)
{
    snprintf(dst, ISK_NAME_MAX, "%s", name ? name : "");
}

int isk_effect_def_add_force(isk_effect_def *d, const char *name, isk_force_kind kind)
{
    if (!d || d->nforces >= ISK_EFFECT_MAX_FORCES || (unsigned)kind >= ISK_FORCE_KIND_COUNT)
        return -1;
    isk_force_def *a = realloc(d->forces, sizeof *a * (size_t)(d->nforces + 1));
    if (!a)
        return -1;
    d->forces = a;
    isk_force_def *f = &a[d->nforces];
    memset(f, 0, sizeof *f);
    set_name(f->name, name);
    f->kind = kind;
    isk_potential_init(&f->pot, 0, isk_vec2_make(0, 0), 1);
    f->draw = 1;
    return d->nforces++;
}

int isk_effect_def_add_deflector(isk_effect_def *d, const char *name, isk_deflector seg)
{
    if (!d || d->ndeflectors >= ISK_EFFECT_MAX_DEFLECTORS)
        return -1;
    isk_deflector *a = realloc(d->deflectors, sizeof *a * (size_t)(d->ndeflectors + 1));
    if (!a)
        return -1;
    d->deflectors = a;
    char(*n)[ISK_NAME_MAX] = realloc(d->deflector_names, sizeof *n * (size_t)(d->ndeflectors + 1));
    if (!n)
        return -1;
    d->deflector_names = n;
    a[d->ndeflectors] = seg;
    set_name(n[d->ndeflectors], name);
    return d->ndeflectors++;
}

isk_emitter_def *isk_effect_def_add_emitter(isk_effect_def *d, const char *name)
{
    if (!d || d->nemitters >= ISK_EFFECT_MAX_EMITTERS)
        return NULL;
    isk_emitter_def *a = realloc(d->emitters, sizeof *a * (size_t)(d->nemitters + 1));
    if (!a)
        return NULL;
    d->emitters = a;
    isk_emitter_def *e = &a[d->nemitters];
    memset(e, 0, sizeof *e);
    set_name(e->name, name);
    e->source = ISK_SOURCE_PARTICLE;
    e->mass = 1.0;
    e->explosion = ISK_EXPLOSION_GAUSS;
    e->count = 0; /* explosions and layers must say how many; streams: no burst */
    e->kick = ISK_KICK_ALL;
    e->shape = ISK_SHAPE_POINT;
    e->launch = ISK_VELGEN_CONSTANT;
    e->rate_mode = ISK_RATE_ACCUMULATE;
    e->birth = ISK_BIRTH_BACKDATE;
    e->life = INFINITY;
    e->capacity = 100000;
    e->gravity_mult = 1.0;
    e->osc_use_table = 1;
    e->integrator = (isk_integrator)-1; /* inherit */
    e->substeps = 0;                    /* inherit */
    e->draw = ISK_DRAW_DOT;
    e->sprite = ISK_SPRITE_LINEAR;
    e->size = 0.1;
    e->color = ISK_YELLOW;
    e->blend = ISK_BLEND_OVER;
    e->order = d->nemitters;
    d->nemitters++;
    return e;
}

isk_drawing_def *isk_effect_def_add_drawing(isk_effect_def *d, const char *name, isk_drawing_kind kind)
{
    if (!d || d->ndrawings >= ISK_EFFECT_MAX_DRAWINGS)
        return NULL;
    isk_drawing_def *a = realloc(d->drawings, sizeof *a * (size_t)(d->ndrawings + 1));
    if (!a)
        return NULL;
    d->drawings = a;
    isk_drawing_def *s = &a[d->ndrawings++];
    memset(s, 0, sizeof *s);
    set_name(s->name, name);
    s->kind = kind;
    s->scale = 1;
    s->sprite = ISK_SPRITE_LINEAR;
    s->size = 1.0;
    s->color = ISK_WHITE;
    s->blend = ISK_BLEND_OVER;
    return s;
}

int isk_effect_def_find_force(const isk_effect_def *d, const char *name)
{
    for (int i = 0; d && name && i < d->nforces; i++)
        if (!strcmp(d->forces[i].name, name))
            return i;
    return -1;
}

int isk_effect_def_find_deflector(const isk_effect_def *d, const char *name)
{
    for (int i = 0; d && name && i < d->ndeflectors; i++)
        if (!strcmp(d->deflector_names[i], name))
            return i;
    return -1;
}

int isk_effect_def_find_emitter(const isk_effect_def *d, const char *name)
{
    for (int i = 0; d && name && i < d->nemitters; i++)
        if (!strcmp(d->emitters[i].name, name))
            return i;
    return -1;
}

isk_status isk_emitter_use_force(isk_emitter_def *e, int force)
{
    if (!e)
        return ISK_ERR_NULL;
    if (force < 0 || force >= ISK_EFFECT_MAX_FORCES)
        return ISK_ERR_RANGE;
    for (int i = 0; i < e->nforces; i++)
        if (e->forces[i] == force)
            return ISK_OK;
    if (e->nforces >= ISK_EFFECT_MAX_FORCES)
        return ISK_ERR_SIZE;
    e->forces[e->nforces++] = force;
    return ISK_OK;
}

isk_status isk_emitter_use_deflector(isk_emitter_def *e, int deflector)
{
    if (!e)
        return ISK_ERR_NULL;
    if (deflector < 0 || deflector >= ISK_EFFECT_MAX_DEFLECTORS)
        return ISK_ERR_RANGE;
    for (int i = 0; i < e->ndeflectors; i++)
        if (e->deflectors[i] == deflector)
            return ISK_OK;
    if (e->ndeflectors >= ISK_EFFECT_MAX_DEFLECTORS)
        return ISK_ERR_SIZE;
    e->deflectors[e->ndeflectors++] = deflector;
    return ISK_OK;
}

static void *dup_array(const void *src, size_t n, size_t size, int *ok)
{
    if (!src || n == 0)
        return NULL;
    void *p = malloc(n * size);
    if (!p) {
        *ok = 0;
        return NULL;
    }
    memcpy(p, src, n * size);
    return p;
}

isk_status fx_def_copy(isk_effect_def *dst, const isk_effect_def *src)
{
    int ok = 1;
    *dst = *src;
    dst->forces = dup_array(src->forces, (size_t)src->nforces, sizeof *src->forces, &ok);
    dst->deflectors = dup_array(src->deflectors, (size_t)src->ndeflectors, sizeof *src->deflectors, &ok);
    dst->deflector_names =
        dup_array(src->deflector_names, (size_t)src->ndeflectors, sizeof *src->deflector_names, &ok);
    dst->emitters = dup_array(src->emitters, (size_t)src->nemitters, sizeof *src->emitters, &ok);
    dst->drawings = dup_array(src->drawings, (size_t)src->ndrawings, sizeof *src->drawings, &ok);
    for (int i = 0; ok && i < dst->ndrawings; i++)
        dst->drawings[i].points = dup_array(src->drawings[i].points, (size_t)src->drawings[i].npoints * 2,
                                            sizeof(double), &ok);
    if (!ok) {
        /* Free what was copied; the copied drawings may hold NULL points. */
        for (int i = 0; dst->drawings && i < dst->ndrawings; i++)
            if (dst->drawings[i].points == src->drawings[i].points)
                dst->drawings[i].points = NULL;
        isk_effect_def_free(dst);
        return ISK_ERR_NOMEM;
    }
    return ISK_OK;
}
