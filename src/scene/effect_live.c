/* SPDX-License-Identifier: MIT */
/* Changing a running effect (isk_effect_set / isk_effect_get, adding and
 * removing forces): every value goes through its row of the key table, so
 * a live change is parsed, checked and refused exactly as a scene file's
 * line would be.  A change lands in the effect's definition, is checked
 * with the whole definition (a refused value changes nothing), then what
 * the running state keeps of it is brought up to date and every group's
 * lists are recompiled: it applies from the next step. */
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "effect_check.h"
#include "effect_internal.h"
#include "key_value.h"
#include "scene_values.h"

/* ---- addressing: "emitter sparks" -> (section, item) ---------------------------- */

typedef struct where {
    isk_section_kind section;
    int index;
    char label[ISK_NAME_MAX + 24]; /* "[emitter sparks]" */
} where;

static isk_status find_item(const isk_effect_def *d, const char *section, where *w, isk_error *err)
{
    char type[32];
    const char *name = strchr(section, ' ');
    size_t tl = name ? (size_t)(name - section) : strlen(section);
    if (tl >= sizeof type)
        tl = sizeof type - 1;
    memcpy(type, section, tl);
    type[tl] = 0;
    while (name && *name == ' ')
        name++;
    int s = isk_section_find(type);
    if (s < 0) {
        const char *types[ISK_SECTION_COUNT];
        for (int i = 0; i < ISK_SECTION_COUNT; i++)
            types[i] = isk_section_name((isk_section_kind)i);
        const char *sug = isk__scv_suggest(type, types, ISK_SECTION_COUNT);
        return isk_error_set(err, ISK_ERR_RANGE, "no section type '%s'%s%s%s (scene, view, force NAME, deflector NAME, "
                                                 "bounds, emitter NAME, drawing NAME, click)",
                             type, sug ? "; did you mean '" : "", sug ? sug : "", sug ? "'?" : "");
    }
    w->section = (isk_section_kind)s;
    const int named = isk_section_named(w->section);
    if (named && (!name || !*name))
        return isk_error_set(err, ISK_ERR_RANGE, "section '%s' needs a name: \"%s NAME\"", type, type);
    if (!named && name && *name)
        return isk_error_set(err, ISK_ERR_RANGE, "section '%s' takes no name (got \"%s\")", type, section);
    if (!named) {
        w->index = 0;
        snprintf(w->label, sizeof w->label, "[%s]", type);
        return ISK_OK;
    }
    int n = isk__fx_section_items(d, w->section);
    for (int i = 0; i < n; i++)
        if (!strcmp(isk__fx_item_name(d, w->section, i), name)) {
            w->index = i;
            snprintf(w->label, sizeof w->label, "[%s %s]", type, isk__fx_item_name(d, w->section, i));
            return ISK_OK;
        }
    const char *names[ISK_EFFECT_MAX_DEFLECTORS];
    for (int i = 0; i < n && i < ISK_EFFECT_MAX_DEFLECTORS; i++)
        names[i] = isk__fx_item_name(d, w->section, i);
    const char *sug = isk__scv_suggest(name, names, n);
    return isk_error_set(err, ISK_ERR_RANGE, "no %s named '%s'%s%s%s", type, name, sug ? "; did you mean '" : "",
                         sug ? sug : "", sug ? "'?" : "");
}

isk_status isk__fx_emitter_of(isk_effect *e, const char *fn, const char *section, fx_group **g, isk_error *err)
{
    if (!e || !section)
        return isk_error_set(err, ISK_ERR_NULL, "%s: NULL argument", fn);
    where w;
    isk_status s = find_item(&e->def, section, &w, err);
    if (s != ISK_OK)
        return s;
    if (w.section != ISK_SECTION_EMITTER)
        return isk_error_set(err, ISK_ERR_RANGE, "%s: %s is not an emitter (write \"emitter NAME\")", fn, w.label);
    *g = &e->groups[w.index];
    return ISK_OK;
}

static isk_status find_key(const isk_effect_def *d, const where *w, const char *key, const isk_key **out,
                           isk_error *err)
{
    const isk_key *k = isk_key_find(w->section, key);
    if (!k) {
        const char *sug = isk__fx_key_suggest(w->section, key);
        return isk_error_set(err, ISK_ERR_RANGE, "%s unknown key '%s'%s%s%s", w->label, key,
                             sug ? "; did you mean '" : "", sug ? sug : "", sug ? "'?" : "");
    }
    int kind = isk__fx_item_kind(d, w->section, w->index);
    if (!isk__fx_key_applies(k, kind)) {
        char msg[240];
        isk__fx_key_kind_message(k, kind, msg, sizeof msg);
        return isk_error_set(err, ISK_ERR_RANGE, "%s %s: %s", w->label, key, msg);
    }
    *out = k;
    return ISK_OK;
}

/* The item and the key's row, or the failure's status with its message. */
static isk_status locate(const isk_effect_def *d, const char *section, const char *key, where *w, const isk_key **k,
                         isk_error *err)
{
    isk_status s = find_item(d, section, w, err);
    return s != ISK_OK ? s : find_key(d, w, key, k, err);
}

/* ---- the report of a refused change ------------------------------------------------ */

typedef struct live_report {
    fx_report r;
    const isk_effect_def *d;
    isk_error *err;
    const char *label, *key; /* the change: "[emitter sparks]", "capacity" */
} live_report;

static void live_emit(fx_report *r, isk_status s, isk_section_kind section, int index, const char *key, int show_key,
                      const char *msg)
{
    const live_report *lr = (const live_report *)r;
    if (section == ISK_SECTION_SCENE && !key) {
        /* the whole definition's (its memory): named by the change that did it */
        isk_error_set(lr->err, s, "%s %s: %s", lr->label, lr->key, msg);
        return;
    }
    const char *name = isk__fx_item_name(lr->d, section, index);
    isk_error_set(lr->err, s, "[%s%s%s] %s%s%s", isk_section_name(section), *name ? " " : "", name,
                  key && show_key ? key : "", key && show_key ? ": " : "", msg);
}

/* ---- bringing the running state up to date ------------------------------------------ */

/* The live potentials of force `f` take the definition's new values; their
 * position and on/off state are their own (they move, they switch off)
 * unless the change was to that very key. */
static void update_potentials(isk_effect *e, int f, const char *key)
{
    isk_force_def *fd = &e->def.forces[f];
    isk__fx_force_sync(fd);
    for (size_t k = 0; k < e->npots; k++) {
        if (e->pot_force[k] != f)
            continue;
        isk_potential *p = &e->pots[k];
        isk_potential keep = *p;
        *p = fd->pot;
        p->id = keep.id;
        if (strcmp(key, "position"))
            p->r = keep.r;
        if (strcmp(key, "enabled"))
            p->enabled = keep.enabled;
    }
}

/* A stream's rate changed: the birth due next keeps its place within the
 * interval (a fraction of the way through the old one is the same fraction
 * of the new one), so no burst of catch-up births and no gap. */
static void rebase_stream(isk_effect *e, fx_group *g, double old_rate)
{
    const double t = isk__fx_group_time(e, g), rate = g->def->born.rate;
    double f = 0.0;
    if (old_rate > 0 && g->def->born.rate_mode == ISK_RATE_ACCUMULATE) {
        double last = g->origin + (double)g->emitted / old_rate;
        f = (t - last) * old_rate;
        if (!(f >= 0.0))
            f = 0.0;
        if (f >= 1.0)
            f = nextafter(1.0, 0.0);
    }
    g->origin = rate > 0 ? t - f / rate : t;
    g->emitted = 0;
}

/* What follows from the definition alone: the view, the draw order, a
 * sprite kind's streak, the potentials' parameters and every group's
 * lists.  Done before the work budget is counted (it reads them), and
 * done again from the old definition when the change is refused, which
 * leaves the effect as it was (only what rested is forgotten, and a
 * resting particle gives the same bytes either way). */
static isk_status derive(isk_effect *e, const where *w, const isk_key *k)
{
    isk_effect_def *d = &e->def;
    isk_status s = ISK_OK;
    switch (w->section) {
    case ISK_SECTION_VIEW:
        s = d->view_kind == ISK_VIEWDEF_CAMERA ? isk_view_camera(&e->view, d->width, d->height, d->zoom, d->tx, d->ty)
                                               : isk_view_window(&e->view, d->width, d->height, d->xmin, d->xmax,
                                                                 d->ymin, d->ymax);
        break;
    case ISK_SECTION_FORCE:
        if (d->forces[w->index].kind == ISK_FORCE_POTENTIAL)
            update_potentials(e, w->index, k->name);
        break;
    case ISK_SECTION_EMITTER:
        if (!strcmp(k->name, "order"))
            isk__fx_sort_draw_order(e);
        s = isk__fx_looks_streak(&e->groups[w->index]);
        break;
    default:
        break;
    }
    return s != ISK_OK ? s : isk__fx_compile_all(e);
}

/* What the running state keeps of an accepted change: an emitter's ramps,
 * the columns its looks, sway, events and trails now need, a stream's
 * next birth and a moved emitter's path. */
static isk_status carry(isk_effect *e, const where *w, const isk_key *k, const void *old_item)
{
    if (w->section != ISK_SECTION_EMITTER)
        return ISK_OK;
    fx_group *g = &e->groups[w->index];
    const isk_emitter_def *em = g->def, *old = old_item;
    isk_status s = ISK_OK;
    if (k->type == ISK_KEY_COLOR_STOPS || k->type == ISK_KEY_SCALAR_STOPS) {
        isk__fx_free_ramps(g);
        s = isk__fx_bake_ramps(g, NULL);
    }
    if (s == ISK_OK && isk__fx_emitter_oscillates(em) && !g->store.osc_amp)
        s = isk_particles_add_columns(&g->store, ISK_PARTICLES_OSC);
    if (s == ISK_OK)
        s = isk__fx_looks_columns_live(g);
    if (s == ISK_OK)
        s = isk__fx_ranges_live(g);
    if (s == ISK_OK)
        s = isk__fx_events_columns(g); /* on_hit, trail */
    if (!strcmp(k->name, "rate") && em->born.source == ISK_SOURCE_STREAM) {
        rebase_stream(e, g, old->born.rate);
        isk__fx_stream_rate_changed(e, g);
    }
    if ((!strcmp(k->name, "position") || !strcmp(k->name, "emitter_velocity")) && em->born.source == ISK_SOURCE_STREAM)
        isk__fx_path_changed(e, g, old, k->name); /* births spread along the way: no gap */
    /* started again: what fell due meanwhile is skipped, not caught up */
    const int ran = old->born.active && !old->motion.paused, runs = em->born.active && !em->motion.paused;
    if (!ran && runs && em->born.source == ISK_SOURCE_STREAM)
        isk__fx_stream_resume(e, g);
    return s != ISK_OK ? s : isk__fx_compile_all(e);
}

/* ---- set and get ------------------------------------------------------------------- */

isk_status isk_effect_set(isk_effect *e, const char *section, const char *key, const char *value, isk_error *err)
{
    if (!e || !section || !key || !value)
        return isk_error_set(err, ISK_ERR_NULL, "isk_effect_set: NULL argument");
    isk_effect_def *d = &e->def;
    where w;
    const isk_key *k;
    isk_status s = locate(d, section, key, &w, &k, err);
    if (s != ISK_OK)
        return s;
    if (k->create_only)
        return isk_error_set(err, ISK_ERR_RANGE, "%s %s: is fixed when the effect is created (change the "
                                                 "definition and create the effect again)",
                             w.label, key);
    /* Parse into a copy of the item, so a refused value changes nothing. */
    void *item = isk__fx_section_item(d, w.section, w.index);
    union {
        isk_effect_def def;
        isk_force_def force;
        isk_deflector_def deflector;
        isk_emitter_def emitter;
        isk_drawing_def drawing;
        isk_probe_def probe;
    } old, copy;
    size_t size = w.section == ISK_SECTION_SCENE || w.section == ISK_SECTION_VIEW ? sizeof(isk_effect_def)
                  : w.section == ISK_SECTION_FORCE                                ? sizeof(isk_force_def)
                  : w.section == ISK_SECTION_DEFLECTOR                            ? sizeof(isk_deflector_def)
                  : w.section == ISK_SECTION_BOUNDS                               ? sizeof(isk_bounds)
                  : w.section == ISK_SECTION_EMITTER                              ? sizeof(isk_emitter_def)
                  : w.section == ISK_SECTION_DRAWING                              ? sizeof(isk_drawing_def)
                  : w.section == ISK_SECTION_PROBE                                ? sizeof(isk_probe_def)
                                                                                  : sizeof(isk_click_def);
    memcpy(&old, item, size);
    memcpy(&copy, item, size);
    if (k->type == ISK_KEY_POINTS)
        copy.drawing.points = NULL; /* the parse allocates anew; the old points stay until it is accepted */
    char why[400];
    if ((s = isk__fx_key_parse(k, &copy, value, d, why, sizeof why)) != ISK_OK)
        return isk_error_set(err, s, "%s %s: %s", w.label, key, why);
    memcpy(item, &copy, size);
    live_report lr = {{live_emit, NULL, ISK_OK}, d, err, w.label, key};
    if ((s = isk__fx_check_def(d, &lr.r)) != ISK_OK) {
        if (k->type == ISK_KEY_POINTS)
            free(copy.drawing.points);
        memcpy(item, &old, size);
        return s;
    }
    /* The work it could then ask for, counted as at create: a change over
     * the budget is refused and every derived thing made again from the
     * old definition (the potentials' parameters too: kept aside). */
    isk_potential *pots = NULL;
    if (w.section == ISK_SECTION_FORCE && e->npots && !(pots = malloc(sizeof *pots * e->npots)))
        s = ISK_ERR_NOMEM;
    if (pots)
        memcpy(pots, e->pots, sizeof *pots * e->npots);
    if (s == ISK_OK && (s = derive(e, &w, k)) == ISK_OK)
        s = isk__fx_work_fits(e, err);
    else if (s != ISK_OK)
        isk_error_set(err, s, "%s", isk_status_str(s));
    if (s != ISK_OK) {
        char why_refused[sizeof err->message];
        snprintf(why_refused, sizeof why_refused, "%s", err ? err->message : "");
        memcpy(item, &old, size);
        if (pots)
            memcpy(e->pots, pots, sizeof *pots * e->npots);
        free(pots);
        if (k->type == ISK_KEY_POINTS)
            free(copy.drawing.points);
        if (w.section == ISK_SECTION_FORCE)
            isk__fx_compile_all(e); /* the potentials are back as they were, moved or not */
        else
            derive(e, &w, k);
        return isk_error_set(err, s, "%s %s: %s", w.label, key, why_refused);
    }
    free(pots);
    if (k->type == ISK_KEY_POINTS)
        free(old.drawing.points);
    e->edits++;
    s = carry(e, &w, k, &old);
    if (s != ISK_OK)
        return isk_error_set(err, s, "%s %s: %s", w.label, key, isk_status_str(s));
    return ISK_OK;
}

isk_status isk_effect_get(const isk_effect *e, const char *section, const char *key, char *buf, size_t size,
                          isk_error *err)
{
    if (!e || !section || !key || !buf)
        return isk_error_set(err, ISK_ERR_NULL, "isk_effect_get: NULL argument");
    if (size == 0)
        return isk_error_set(err, ISK_ERR_SIZE, "isk_effect_get: no room for the value");
    buf[0] = 0;
    const isk_effect_def *d = &e->def;
    where w;
    const isk_key *k;
    isk_status s = locate(d, section, key, &w, &k, err);
    if (s != ISK_OK)
        return s;
    if (isk__fx_key_format(k, isk__fx_section_item_c(d, w.section, w.index), d, buf, size) != ISK_OK) {
        buf[0] = 0;
        return isk_error_set(err, ISK_ERR_SIZE, "%s %s: the value needs more than %zu bytes", w.label, key, size);
    }
    return ISK_OK;
}

isk_status isk_effect_set_substeps(isk_effect *e, int substeps)
{
    if (!e)
        return ISK_ERR_NULL;
    char v[16];
    snprintf(v, sizeof v, "%d", substeps);
    return isk_effect_set(e, "scene", "substeps", v, NULL);
}

/* ---- forces while running ----------------------------------------------------------- */

/* Room for one more live potential (every group's pick list grows with it). */
static isk_status grow_pots(isk_effect *e)
{
    if (e->npots < e->pots_cap)
        return ISK_OK;
    size_t cap = e->pots_cap ? e->pots_cap * 2 : 4;
    isk_potential *p = realloc(e->pots, cap * sizeof *p);
    if (!p)
        return ISK_ERR_NOMEM;
    e->pots = p;
    int *f = realloc(e->pot_force, cap * sizeof *f);
    if (!f)
        return ISK_ERR_NOMEM;
    e->pot_force = f;
    for (int i = 0; i < e->ngroups; i++) {
        size_t *k = realloc(e->groups[i].pick, cap * sizeof *k);
        if (!k)
            return ISK_ERR_NOMEM;
        e->groups[i].pick = k;
        e->groups[i].pick_cap = cap;
    }
    e->pots_cap = cap;
    return ISK_OK;
}

isk_status isk_effect_add_potential(isk_effect *e, const char *name, const isk_potential *pot, isk_error *err)
{
    if (!e || !name || !pot)
        return isk_error_set(err, ISK_ERR_NULL, "isk_effect_add_potential: NULL argument");
    isk_effect_def *d = &e->def;
    if (isk_effect_def_find_force(d, name) >= 0)
        return isk_error_set(err, ISK_ERR_RANGE, "[force %s]: a force of that name exists", name);
    if (!*name || strlen(name) >= ISK_NAME_MAX || strspn(name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                               "0123456789_-.") != strlen(name))
        return isk_error_set(err, ISK_ERR_RANGE, "bad force name '%s': use letters, digits, '_', '-' or '.' (at most "
                                                 "%d characters)",
                             name, ISK_NAME_MAX - 1);
    if (isk_potential_validate(pot) != ISK_OK)
        return isk_error_set(err, ISK_ERR_RANGE, "[force %s]: the potential's fields must be finite (enabled 0 or 1)",
                             name);
    isk_status s = grow_pots(e);
    if (s != ISK_OK)
        return isk_error_set(err, s, "[force %s]: out of memory", name);
    int f = isk_effect_def_add_force(d, name, ISK_FORCE_POTENTIAL);
    if (f < 0)
        return isk_error_set(err, ISK_ERR_FULL, "[force %s]: at most %d forces (or out of memory)", name,
                             ISK_EFFECT_MAX_FORCES);
    isk_force_def *fd = &d->forces[f];
    fd->pot = *pot;
    fd->pot.id = 0;
    fd->exponent = pot->P;
    fd->law = ISK_COULOMB_LAW_CODE;
    for (int i = 0; i < d->nemitters; i++)
        isk_emitter_use_force(&d->emitters[i], f); /* the simulator's potentials act on every particle */
    int id = 0;
    for (size_t k = 0; k < e->npots; k++)
        if (e->pots[k].id > id)
            id = e->pots[k].id;
    e->pots[e->npots] = fd->pot;
    e->pots[e->npots].id = id + 1;
    e->pot_force[e->npots] = f;
    e->npots++;
    /* The work it could then ask for, counted as at create: over the
     * budget, the potential is taken out again and the effect is as it
     * was (its edits too). */
    const unsigned long edits = e->edits;
    isk_status s2 = isk__fx_compile_all(e);
    if (s2 == ISK_OK)
        s2 = isk__fx_work_fits(e, err);
    else
        isk_error_set(err, s2, "%s", isk_status_str(s2));
    if (s2 != ISK_OK) {
        char why[sizeof err->message];
        snprintf(why, sizeof why, "%s", err ? err->message : "");
        isk_effect_remove_force(e, name, NULL);
        e->edits = edits;
        return isk_error_set(err, s2, "[force %s]: %s", name, why);
    }
    e->edits = edits + 1;
    return ISK_OK;
}

isk_status isk_effect_remove_force(isk_effect *e, const char *name, isk_error *err)
{
    if (!e || !name)
        return isk_error_set(err, ISK_ERR_NULL, "isk_effect_remove_force: NULL argument");
    isk_effect_def *d = &e->def;
    int f = isk_effect_def_find_force(d, name);
    if (f < 0) {
        where w;
        char sec[ISK_NAME_MAX + 8];
        snprintf(sec, sizeof sec, "force %s", name);
        return find_item(d, sec, &w, err);
    }
    /* Every reference moves down past the removed force. */
    for (int i = 0; i < d->nemitters; i++) {
        isk_emitter_def *em = &d->emitters[i];
        int w = 0;
        for (int r = 0; r < em->motion.nforces; r++)
            if (em->motion.forces[r] != f)
                em->motion.forces[w++] = em->motion.forces[r] > f ? em->motion.forces[r] - 1 : em->motion.forces[r];
        em->motion.nforces = w;
    }
    memmove(&d->forces[f], &d->forces[f + 1], sizeof d->forces[0] * (size_t)(d->nforces - f - 1));
    d->nforces--;
    size_t w = 0;
    for (size_t k = 0; k < e->npots; k++) {
        if (e->pot_force[k] == f)
            continue;
        e->pots[w] = e->pots[k];
        e->pot_force[w] = e->pot_force[k] > f ? e->pot_force[k] - 1 : e->pot_force[k];
        w++;
    }
    e->npots = w;
    e->edits++;
    return isk__fx_compile_all(e);
}

const isk_potential *isk_effect_potentials(const isk_effect *e, size_t *count)
{
    if (count)
        *count = e ? e->npots : 0;
    return e && e->npots ? e->pots : NULL;
}
