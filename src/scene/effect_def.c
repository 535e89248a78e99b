/* SPDX-License-Identifier: MIT */
/* Building and copying effect definitions (plain data, see iskra/effect.h;
 * the enums' names are names.c's). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "effect_internal.h"
#include "iskra/limits.h"
#include "key_value.h"

/* Every default comes from the key table (iskra/keys.h); what is set here
 * besides is what no key describes: names, kinds passed in, definition
 * order. */
void isk_effect_def_init(isk_effect_def *d)
{
    if (!d)
        return;
    memset(d, 0, sizeof *d);
    isk__fx_section_defaults(ISK_SECTION_SCENE, d);
    isk__fx_section_defaults(ISK_SECTION_VIEW, d);
    isk__fx_section_defaults(ISK_SECTION_BOUNDS, &d->bounds);
    isk__fx_section_defaults(ISK_SECTION_CLICK, &d->click);
    d->view_kind = ISK_VIEWDEF_WINDOW;
}

void isk_effect_def_free(isk_effect_def *d)
{
    if (!d)
        return;
    for (int i = 0; d->drawings && i < d->ndrawings; i++)
        free(d->drawings[i].points);
    isk__fx_def_textures_free(d);
    free(d->forces);
    free(d->deflectors);
    free(d->emitters);
    free(d->drawings);
    free(d->probes);
    memset(d, 0, sizeof *d);
}

static void set_name(char *dst, const char *name)
{
    snprintf(dst, ISK_NAME_MAX, "%s", name ? name : "");
}

/* Grows one of the definition's arrays by an item; NULL when full or out of memory. */
static void *grow(void **array, int *count, int max, size_t size)
{
    if (*count < 0 || *count >= max)
        return NULL;
    char *a = realloc(*array, size * (size_t)(*count + 1));
    if (!a)
        return NULL;
    *array = a;
    void *item = a + size * (size_t)*count;
    memset(item, 0, size);
    (*count)++;
    return item;
}

int isk_effect_def_add_force(isk_effect_def *d, const char *name, isk_force_kind kind)
{
    if (!d || (unsigned)kind >= ISK_FORCE_KIND_COUNT)
        return -1;
    isk_force_def *f = grow((void **)&d->forces, &d->nforces, ISK_EFFECT_MAX_FORCES, sizeof *f);
    if (!f)
        return -1;
    isk__fx_section_defaults(ISK_SECTION_FORCE, f);
    set_name(f->name, name);
    f->kind = kind;
    isk__fx_force_sync(f);
    return d->nforces - 1;
}

int isk_effect_def_add_deflector(isk_effect_def *d, const char *name, isk_deflector seg)
{
    if (!d)
        return -1;
    isk_deflector_def *g = grow((void **)&d->deflectors, &d->ndeflectors, ISK_EFFECT_MAX_DEFLECTORS, sizeof *g);
    if (!g)
        return -1;
    isk__fx_section_defaults(ISK_SECTION_DEFLECTOR, g); /* show, color */
    set_name(g->name, name);
    g->seg = seg;
    return d->ndeflectors - 1;
}

isk_emitter_def *isk_effect_def_add_emitter(isk_effect_def *d, const char *name)
{
    if (!d)
        return NULL;
    isk_emitter_def *e = grow((void **)&d->emitters, &d->nemitters, ISK_EFFECT_MAX_EMITTERS, sizeof *e);
    if (!e)
        return NULL;
    isk__fx_section_defaults(ISK_SECTION_EMITTER, e);
    set_name(e->name, name);
    e->look.order = d->nemitters - 1;
    return e;
}

isk_probe_def *isk_effect_def_add_probe(isk_effect_def *d, const char *name, isk_probe_kind kind)
{
    if (!d || (unsigned)kind >= ISK_PROBE_KIND_COUNT)
        return NULL;
    isk_probe_def *q = grow((void **)&d->probes, &d->nprobes, ISK_EFFECT_MAX_PROBES, sizeof *q);
    if (!q)
        return NULL;
    isk__fx_section_defaults(ISK_SECTION_PROBE, q);
    set_name(q->name, name);
    q->kind = kind;
    return q;
}

isk_drawing_def *isk_effect_def_add_drawing(isk_effect_def *d, const char *name, isk_drawing_kind kind)
{
    if (!d || (unsigned)kind >= ISK_DRAWING_KIND_COUNT)
        return NULL;
    isk_drawing_def *s = grow((void **)&d->drawings, &d->ndrawings, ISK_EFFECT_MAX_DRAWINGS, sizeof *s);
    if (!s)
        return NULL;
    isk__fx_section_defaults(ISK_SECTION_DRAWING, s);
    set_name(s->name, name);
    s->kind = kind;
    return s;
}

int isk__fx_emitter_oscillates(const isk_emitter_def *em)
{
    return em->motion.osc_amplitude_max > 0 && em->motion.osc_omega_max != 0;
}

/* What one emitter's pool takes at its fullest (keep_prev: a gate probe
 * makes it keep one trail point). */
size_t isk__fx_emitter_memory(const isk_emitter_def *e, int keep_prev)
{
    const int points = e->look.trail > 0 && e->look.trail <= ISK_TRAIL_MAX ? e->look.trail : keep_prev ? 1 : 0;
    unsigned flags = (isk__fx_emitter_oscillates(e) ? ISK_PARTICLES_OSC : 0) | isk__fx_looks_columns(e) |
                     isk__fx_ranges_columns(e);
    /* sub-emitters and trails: the hit and trail columns, a sub-emitter's waiting events */
    flags |= (e->events.on_hit >= 0 ? ISK_PARTICLES_HIT : 0) | (points > 0 ? ISK_PARTICLES_TRAIL : 0);
    size_t b = isk_particles_bytes_trail(e->born.capacity, flags, points);
    if (b && e->born.source == ISK_SOURCE_SUB) {
        size_t q = e->born.capacity <= SIZE_MAX / sizeof(fx_event) ? e->born.capacity * sizeof(fx_event) : SIZE_MAX;
        b = q > SIZE_MAX - b ? 0 : b + q;
    }
    return b ? b : SIZE_MAX;
}

void isk__fx_force_sync(isk_force_def *f)
{
    if (isk_potential_set_law(&f->pot, f->law, f->exponent) != ISK_OK)
        f->pot.P = f->exponent; /* an unknown law is the check's to report */
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
        if (!strcmp(d->deflectors[i].name, name))
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
    for (int i = 0; i < e->motion.nforces; i++)
        if (e->motion.forces[i] == force)
            return ISK_OK;
    if (e->motion.nforces >= ISK_EFFECT_MAX_FORCES)
        return ISK_ERR_SIZE;
    e->motion.forces[e->motion.nforces++] = force;
    return ISK_OK;
}

isk_status isk_emitter_use_deflector(isk_emitter_def *e, int deflector)
{
    if (!e)
        return ISK_ERR_NULL;
    if (deflector < 0 || deflector >= ISK_EFFECT_MAX_DEFLECTORS)
        return ISK_ERR_RANGE;
    for (int i = 0; i < e->motion.ndeflectors; i++)
        if (e->motion.deflectors[i] == deflector)
            return ISK_OK;
    if (e->motion.ndeflectors >= ISK_EFFECT_MAX_DEFLECTORS)
        return ISK_ERR_SIZE;
    e->motion.deflectors[e->motion.ndeflectors++] = deflector;
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

isk_status isk__fx_def_copy(isk_effect_def *dst, const isk_effect_def *src)
{
    int ok = 1;
    *dst = *src;
    dst->forces = dup_array(src->forces, (size_t)src->nforces, sizeof *src->forces, &ok);
    dst->deflectors = dup_array(src->deflectors, (size_t)src->ndeflectors, sizeof *src->deflectors, &ok);
    dst->emitters = dup_array(src->emitters, (size_t)src->nemitters, sizeof *src->emitters, &ok);
    dst->drawings = dup_array(src->drawings, (size_t)src->ndrawings, sizeof *src->drawings, &ok);
    dst->probes = dup_array(src->probes, (size_t)src->nprobes, sizeof *src->probes, &ok);
    /* The drawings' points are copied one by one; until then (and if the
     * drawings themselves could not be copied) no copy shares the source's. */
    for (int i = 0; dst->drawings && i < dst->ndrawings; i++)
        dst->drawings[i].points = NULL;
    for (int i = 0; ok && dst->drawings && i < dst->ndrawings; i++)
        dst->drawings[i].points = dup_array(src->drawings[i].points, (size_t)src->drawings[i].npoints * 2,
                                            sizeof(double), &ok);
    if (isk__fx_def_textures_copy(dst, src) != ISK_OK) /* none shared either way */
        ok = 0;
    if (!ok) {
        if (!dst->drawings)
            dst->ndrawings = 0;
        if (!dst->probes)
            dst->nprobes = 0;
        isk_effect_def_free(dst);
        return ISK_ERR_NOMEM;
    }
    return ISK_OK;
}
