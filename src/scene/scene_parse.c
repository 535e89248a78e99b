/* SPDX-License-Identifier: MIT */
/* Scene files -> isk_effect_def (see iskra/scene.h, docs/scene-format.md).
 *
 * The key table (iskra/keys.h) knows every key: its field, type, range,
 * default and the kinds it applies to.  This file knows what only a file
 * has: sections and their names, lines, keys given twice, keys given that
 * do not apply, required keys, and the defaults that follow from other keys
 * (a force's kind from its name, the walls' margin from their mode).
 *
 * How a file is read (ini_read.h does the lines):
 *   1. Every section header opens its item at once, in file order (with the
 *      table's defaults); every key is parsed through its row into the item
 *      and its line remembered.  References to other sections (`forces`,
 *      `deflectors`, the click's `emitter`) are kept as text.
 *   2. At the end, per section: its kind, the keys that do not apply to it,
 *      the required ones, the derived defaults.  Then the references are
 *      resolved (so forward references work), and last the checks that span
 *      fields, which are isk_effect_create's own (effect_check.c), reported
 *      at the line of the key they are about.
 * The first error stops everything; the definition is then emptied.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect_check.h"
#include "effect_internal.h"
#include "iskra/limits.h"
#include "iskra/presets.h"
#include "iskra/scene.h"
#include "key_value.h"
#include "scene/ini_read.h"
#include "scene/scene_load.h"
#include "scene_values.h"

#define MAX_SECTIONS (ISK_EFFECT_MAX_FORCES + ISK_EFFECT_MAX_DEFLECTORS + ISK_EFFECT_MAX_EMITTERS + \
                      ISK_EFFECT_MAX_DRAWINGS + ISK_EFFECT_MAX_PROBES + 4)

typedef struct section {
    isk_section_kind type;
    char name[ISK_NAME_MAX];
    int line;
    int index;          /* item index in the definition */
    int reused;         /* it names an item a preset made: its keys change that item */
    int *key_line;      /* per row of the key table: the line it was given on, 0 if not */
    char **deferred;    /* per row: the text of a reference, resolved at the end */
} section;

typedef struct parser {
    isk_effect_def *d;
    const char *name;
    isk_error *err;
    section *sec;
    int nsec, cur;
    int nkeys;          /* rows in the key table */
} parser;

/* ---- messages ---------------------------------------------------------------- */

static void sec_label(const section *s, char *buf, size_t n)
{
    if (s->name[0])
        snprintf(buf, n, "[%s %s]", isk_section_name(s->type), s->name);
    else
        snprintf(buf, n, "[%s]", isk_section_name(s->type));
}

/* "FILE:LINE: [section] key: message" (without key: "[section] message") */
static isk_status fail_at(parser *P, const section *s, int line, const char *key, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;
static isk_status fail_at(parser *P, const section *s, int line, const char *key, const char *fmt, ...)
{
    char msg[400], label[80];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    sec_label(s, label, sizeof label);
    if (key)
        return isk__ini_error(P->err, P->name, line, "%s %s: %s", label, key, msg);
    return isk__ini_error(P->err, P->name, line, "%s %s", label, msg);
}

/* The rows are one array (iskra/keys.h): a row's index is its offset. */
static int row_index(const isk_key *k)
{
    return k ? (int)(k - isk_key_at(0)) : -1;
}

static int given(const section *s, const isk_key *k)
{
    int i = row_index(k);
    return i >= 0 && s->key_line[i] > 0;
}

static int line_of(const section *s, const char *key)
{
    const isk_key *k = key ? isk_key_find(s->type, key) : NULL;
    int i = k ? row_index(k) : -1;
    return i >= 0 && s->key_line[i] > 0 ? s->key_line[i] : s->line;
}

/* ---- sections ------------------------------------------------------------------ */

/* A new item of the section's type, with the table's defaults. */
static isk_status add_item(parser *P, section *s, const char *name, int line)
{
    isk_effect_def *d = P->d;
    const char *what = NULL;
    int max = 0;
    switch (s->type) {
    case ISK_SECTION_FORCE:
        s->index = isk_effect_def_add_force(d, name, ISK_FORCE_GRAVITY);
        if (s->index >= 0)
            d->forces[s->index].line = line;
        what = "forces", max = ISK_EFFECT_MAX_FORCES;
        break;
    case ISK_SECTION_DEFLECTOR: {
        isk_deflector seg = {0};
        s->index = isk_effect_def_add_deflector(d, name, seg);
        if (s->index >= 0) {
            d->deflectors[s->index].line = line;
            isk__fx_section_defaults(ISK_SECTION_DEFLECTOR, &d->deflectors[s->index]);
        }
        what = "deflectors", max = ISK_EFFECT_MAX_DEFLECTORS;
        break;
    }
    case ISK_SECTION_EMITTER: {
        isk_emitter_def *e = isk_effect_def_add_emitter(d, name);
        s->index = e ? d->nemitters - 1 : -1;
        if (e)
            e->line = line;
        what = "emitters", max = ISK_EFFECT_MAX_EMITTERS;
        break;
    }
    case ISK_SECTION_DRAWING: {
        isk_drawing_def *g = isk_effect_def_add_drawing(d, name, ISK_DRAWING_POLYLINE);
        s->index = g ? d->ndrawings - 1 : -1;
        if (g)
            g->line = line;
        what = "drawings", max = ISK_EFFECT_MAX_DRAWINGS;
        break;
    }
    case ISK_SECTION_PROBE: {
        isk_probe_def *q = isk_effect_def_add_probe(d, name, ISK_PROBE_GATE);
        s->index = q ? d->nprobes - 1 : -1;
        if (q)
            q->line = line;
        what = "probes", max = ISK_EFFECT_MAX_PROBES;
        break;
    }
    case ISK_SECTION_BOUNDS:
        s->index = 0;
        d->bounds.sides = ISK_SIDE_ALL; /* a [bounds] section means walls, unless `sides` says otherwise */
        break;
    case ISK_SECTION_CLICK:
        s->index = 0;
        d->click.enabled = 1;
        break;
    default:
        s->index = 0;
        break;
    }
    if (s->index < 0 && isk__fx_section_items(d, s->type) >= max)
        return isk__ini_error(P->err, P->name, line, "too many %s (at most %d)", what, max);
    if (s->index < 0) /* room, so the add could not allocate */
        return isk_error_set(P->err, ISK_ERR_NOMEM, "%s: out of memory", P->name);
    return ISK_OK;
}

/* The index of the force, deflector or emitter called `name` that a
 * preset made (no section has opened it: a section's own name is refused
 * as a duplicate before this), else -1.  A section of that name then
 * changes the preset's item, key by key, as the keys after `preset` change
 * its emitter. */
static int preset_made(const isk_effect_def *d, isk_section_kind type, const char *name)
{
    switch (type) {
    case ISK_SECTION_FORCE: return isk_effect_def_find_force(d, name);
    case ISK_SECTION_DEFLECTOR: return isk_effect_def_find_deflector(d, name);
    case ISK_SECTION_EMITTER: return isk_effect_def_find_emitter(d, name);
    default: return -1;
    }
}

static isk_status on_section(void *user, const char *header, int line, isk_error *err)
{
    (void)err;
    parser *P = user;
    char text[ISK_INI_MAX_LINE + 1];
    snprintf(text, sizeof text, "%s", header);
    char *type = isk__scv_trim(text), *name = type;
    while (*name && *name != ' ' && *name != '\t')
        name++;
    if (*name)
        *name++ = 0;
    name = isk__scv_trim(name);

    int t = isk_section_find(type);
    if (t < 0) {
        const char *types[ISK_SECTION_COUNT];
        for (int i = 0; i < ISK_SECTION_COUNT; i++)
            types[i] = isk_section_name((isk_section_kind)i);
        if (!*type)
            return isk__ini_error(P->err, P->name, line, "empty section header []");
        const char *s = isk__scv_suggest(type, types, ISK_SECTION_COUNT);
        if (s)
            return isk__ini_error(P->err, P->name, line, "unknown section [%s%s%s]; did you mean [%s%s%s]?", type,
                                 *name ? " " : "", name, s, *name ? " " : "", name);
        return isk__ini_error(P->err, P->name, line,
                             "unknown section [%s]; sections are [scene], [view], [force NAME], "
                             "[deflector NAME], [bounds], [emitter NAME], [drawing NAME], [click] and [probe NAME]",
                             type);
    }
    const int named = isk_section_named((isk_section_kind)t);
    if (named && !*name)
        return isk__ini_error(P->err, P->name, line, "section [%s] needs a name: [%s NAME]", type, type);
    if (!named && *name)
        return isk__ini_error(P->err, P->name, line, "section [%s] takes no name (got [%s %s])", type, type, name);
    if (named && !isk__fx_name_ok(name, strlen(name) + 1))
        return isk__ini_error(P->err, P->name, line,
                             "bad name '%s' in [%s %s]: use letters, digits, '_', '-' or '.' "
                             "(at most %d characters)",
                             name, type, name, ISK_NAME_MAX - 1);
    if (named && isk__fx_name_reserved(name))
        return isk__ini_error(P->err, P->name, line, "'%s' is reserved and cannot name a [%s]", name, type);
    for (int i = 0; i < P->nsec; i++)
        if (P->sec[i].type == (isk_section_kind)t && !strcmp(P->sec[i].name, name)) {
            if (*name)
                return isk__ini_error(P->err, P->name, line, "duplicate section [%s %s] (first defined at line %d)",
                                     type, name, P->sec[i].line);
            return isk__ini_error(P->err, P->name, line, "duplicate section [%s] (first defined at line %d)", type,
                                 P->sec[i].line);
        }
    if (P->nsec >= MAX_SECTIONS)
        return isk__ini_error(P->err, P->name, line, "too many sections (at most %d)", MAX_SECTIONS);
    if (P->nsec % 16 == 0) {
        section *a = realloc(P->sec, sizeof *a * (size_t)(P->nsec + 16));
        if (!a) {
            return isk_error_set(P->err, ISK_ERR_NOMEM, "%s: out of memory", P->name);
        }
        P->sec = a;
    }
    section *s = &P->sec[P->nsec];
    memset(s, 0, sizeof *s);
    s->type = (isk_section_kind)t;
    snprintf(s->name, sizeof s->name, "%s", name);
    s->line = line;
    s->key_line = calloc((size_t)P->nkeys, sizeof *s->key_line);
    s->deferred = calloc((size_t)P->nkeys, sizeof *s->deferred);
    P->nsec++; /* counted before it can fail, so it is freed */
    if (!s->key_line || !s->deferred) {
        return isk_error_set(P->err, ISK_ERR_NOMEM, "%s: out of memory", P->name);
    }
    P->cur = P->nsec - 1;
    const int made = preset_made(P->d, s->type, name);
    if (made >= 0) {
        s->index = made;
        s->reused = 1;
        return ISK_OK;
    }
    return add_item(P, s, name, line);
}

/* ---- keys ---------------------------------------------------------------------- */

static isk_status unknown_key(parser *P, const section *s, const char *key, int line)
{
    const char *sug = isk__fx_key_suggest(s->type, key);
    if (sug)
        return fail_at(P, s, line, NULL, "unknown key '%s'; did you mean '%s'?", key, sug);
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        if (!strcmp(k->name, key))
            return fail_at(P, s, line, NULL, "unknown key '%s' (it belongs in a [%s%s] section)", key,
                           isk_section_name(k->section), isk_section_named(k->section) ? " NAME" : "");
    }
    return fail_at(P, s, line, NULL, "unknown key '%s' (see docs/scene-format.md for the keys of [%s])", key,
                   isk_section_name(s->type));
}

/* `preset = NAME[, SCALE]`, the one directive: it fills the emitter where
 * it stands, so it must come before every other key of its section (which
 * then override it). */
static isk_status apply_preset(parser *P, section *s, const isk_key *k, int line)
{
    for (int i = 0; i < P->nkeys; i++)
        if (s->key_line[i] && s->key_line[i] != line)
            return fail_at(P, s, line, k->name, "must be the section's first key (line %d sets %s before it, "
                           "which the preset would overwrite)", s->key_line[i], isk_key_at(i)->name);
    isk_emitter_def *e = &P->d->emitters[s->index];
    char name[ISK_NAME_MAX];
    snprintf(name, sizeof name, "%s", e->preset);
    double scale = 1.0;
    char *comma = strchr(name, ',');
    if (comma) {
        *comma = 0;
        char *end;
        scale = strtod(comma + 1, &end);
        while (*end == ' ' || *end == '\t')
            end++;
        if (end == comma + 1 || *end || !(scale > 0) || scale > ISK_PRESET_SCALE_MAX)
            return fail_at(P, s, line, k->name, "the scale after the name must be a number in (0, %g], not '%s'",
                           ISK_PRESET_SCALE_MAX, comma + 1);
    }
    for (char *t = name + strlen(name); t > name && (t[-1] == ' ' || t[-1] == '\t');)
        *--t = 0;
    if (isk_preset_find(name) < 0) {
        /* the row's names are the presets (preset_list.h) */
        char list[300];
        isk__fx_join_names(list, sizeof list, k->names, k->nnames, (1u << k->nnames) - 1u);
        const char *guess = isk__scv_suggest(name, k->names, k->nnames);
        return fail_at(P, s, line, k->name, "no preset '%s'%s%s%s (the presets: %s)", name,
                       guess ? "; did you mean '" : "", guess ? guess : "", guess ? "'?" : "", list);
    }
    isk_status st = isk_preset_apply(P->d, s->index, name, scale);
    if (st == ISK_ERR_NOMEM)
        return isk_error_set(P->err, st, "%s: out of memory", P->name);
    if (st == ISK_ERR_FULL)
        return fail_at(P, s, line, k->name, "the preset's own force finds no room (at most %d forces)",
                       ISK_EFFECT_MAX_FORCES);
    if (st != ISK_OK)
        return fail_at(P, s, line, k->name, "%s", isk_status_str(st));
    P->d->emitters[s->index].line = s->line; /* the preset may have moved the emitters (its own added) */
    return ISK_OK;
}

static isk_status on_key(void *user, const char *section_name, const char *key, const char *value, int line,
                  isk_error *err)
{
    (void)section_name; /* the section callback already told us (whole, with its line) */
    (void)err;
    parser *P = user;
    if (P->cur < 0)
        return isk__ini_error(P->err, P->name, line,
                             "'%s = %s' is outside any section (start the file with a section such as [scene])",
                             key, value);
    section *s = &P->sec[P->cur];
    const isk_key *k = isk_key_find(s->type, key);
    if (!k)
        return unknown_key(P, s, key, line);
    int r = row_index(k);
    if (s->key_line[r])
        return fail_at(P, s, line, key, "given twice (first at line %d)", s->key_line[r]);
    s->key_line[r] = line;
    if (k->type == ISK_KEY_REFS || k->type == ISK_KEY_REF) {
        /* Resolved at the end: the sections it names may come later. */
        s->deferred[r] = malloc(strlen(value) + 1);
        if (!s->deferred[r]) {
            return isk_error_set(P->err, ISK_ERR_NOMEM, "%s: out of memory", P->name);
        }
        memcpy(s->deferred[r], value, strlen(value) + 1);
        return ISK_OK;
    }
    char why[400];
    isk_status st = isk__fx_key_parse(k, isk__fx_section_item(P->d, s->type, s->index), value, P->d, why, sizeof why);
    if (st == ISK_ERR_NOMEM)
        return isk_error_set(P->err, st, "%s: out of memory", P->name);
    if (st != ISK_OK)
        return fail_at(P, s, line, key, "%s", why);
    if (k->directive)
        return apply_preset(P, s, k, line);
    return ISK_OK;
}

/* ---- the end of the file -------------------------------------------------------- */

/* "needs kind = gravity, drag, ... or turbulence" from the kind key's
 * names, and a did-you-mean when the section's name is close to one
 * ([force gravty]). */
static isk_status needs_kind(parser *P, section *s, const isk_key *kk)
{
    char list[300];
    isk__fx_join_names(list, sizeof list, kk->names, kk->nnames, (1u << kk->nnames) - 1u);
    const char *guess = isk__scv_suggest(s->name, kk->names, kk->nnames);
    if (guess)
        return fail_at(P, s, s->line, NULL, "needs kind = %s; did you mean [%s %s]?", list, isk_section_name(s->type),
                       guess);
    return fail_at(P, s, s->line, NULL, "needs kind = %s", list);
}

/* The kind a section has when `kind` is not given: its name, if it is a
 * kind; for drawings, what its keys say; for probes, nothing else. */
static isk_status derive_kind(parser *P, section *s)
{
    isk_effect_def *d = P->d;
    const isk_key *kk = isk_key_find(s->type, "kind");
    if (!kk || given(s, kk))
        return ISK_OK;
    if (s->type == ISK_SECTION_FORCE) {
        int k = isk__scv_lookup(s->name, kk->names, kk->nnames);
        if (k < 0)
            return needs_kind(P, s, kk);
        d->forces[s->index].kind = (isk_force_kind)k;
        return ISK_OK;
    }
    int k = isk__scv_lookup(s->name, kk->names, kk->nnames);
    if (s->type == ISK_SECTION_PROBE) { /* a probe's kind: `kind`, or its name */
        if (k < 0)
            return needs_kind(P, s, kk);
        d->probes[s->index].kind = (isk_probe_kind)k;
        return ISK_OK;
    }
    if (k < 0 && given(s, isk_key_find(s->type, "points")))
        k = ISK_DRAWING_POLYLINE;
    else if (k < 0 && given(s, isk_key_find(s->type, "radius")))
        k = ISK_DRAWING_DISC;
    else if (k < 0 && given(s, isk_key_find(s->type, "text")))
        k = ISK_DRAWING_TEXT;
    if (k < 0)
        return needs_kind(P, s, kk);
    d->drawings[s->index].kind = (isk_drawing_kind)k;
    return ISK_OK;
}

/* A window (xmin, xmax, ymin, ymax) or a camera (zoom, pan), from the keys given. */
static isk_status view_kind(parser *P, section *s)
{
    int win = 0, cam = 0, wline = 0, cline = 0;
    for (int i = 0; i < P->nkeys; i++) {
        const isk_key *k = isk_key_at(i);
        if (k->section != ISK_SECTION_VIEW || !s->key_line[i])
            continue;
        int *flag = k->applies == (1u << ISK_VIEWDEF_CAMERA) ? &cam : &win;
        int *ln = flag == &cam ? &cline : &wline;
        *flag = 1;
        if (s->key_line[i] > *ln)
            *ln = s->key_line[i];
    }
    if (win && cam)
        return fail_at(P, s, wline > cline ? wline : cline, NULL,
                       "mixes a world window (xmin, xmax, ymin, ymax) with a camera (zoom, pan): use one");
    P->d->view_kind = cam ? ISK_VIEWDEF_CAMERA : ISK_VIEWDEF_WINDOW;
    return ISK_OK;
}

/* Keys given that do not apply to the kind (the first in the file), then
 * the required ones not given (in table order). */
static isk_status kinds_and_required(parser *P, section *s)
{
    const int kind = isk__fx_item_kind(P->d, s->type, s->index);
    if (s->type == ISK_SECTION_VIEW)
        return ISK_OK; /* the keys given decided its kind */
    const isk_key *first = NULL;
    int first_line = 0;
    for (int i = 0; i < P->nkeys; i++) {
        const isk_key *k = isk_key_at(i);
        if (k->section == s->type && s->key_line[i] && !isk__fx_key_applies(k, kind) &&
            (!first || s->key_line[i] < first_line)) {
            first = k;
            first_line = s->key_line[i];
        }
    }
    if (first) {
        char msg[240];
        isk__fx_key_kind_message(first, kind, msg, sizeof msg);
        return fail_at(P, s, first_line, first->name, "%s", msg);
    }
    for (int i = 0; i < P->nkeys && !s->reused; i++) { /* a preset's item has them all */
        const isk_key *k = isk_key_at(i);
        if (k->section == s->type && !s->key_line[i] && (kind < 0 ? k->required != 0 : (k->required >> kind & 1u)))
            return fail_at(P, s, s->line, NULL, "needs %s (%s)", k->name, k->meaning);
    }
    return ISK_OK;
}

/* Defaults that follow from other keys. */
static isk_status derived_defaults(parser *P, section *s)
{
    isk_effect_def *d = P->d;
    if (s->type == ISK_SECTION_FORCE) {
        isk_force_def *f = &d->forces[s->index];
        if (given(s, isk_key_find(s->type, "law")) && !given(s, isk_key_find(s->type, "exponent")))
            return fail_at(P, s, line_of(s, "law"), "law", "needs an exponent to apply to");
        isk__fx_force_sync(f);
        return ISK_OK;
    }
    if (s->type == ISK_SECTION_EMITTER) {
        isk_emitter_def *e = &d->emitters[s->index];
        char why[400];
        const char *key;
        isk_status st = isk__fx_scene_texture(d, e, P->name, &key, why, sizeof why); /* the texture beside the file */
        if (st == ISK_ERR_NOMEM)
            return isk_error_set(P->err, st, "%s: out of memory", P->name);
        if (st != ISK_OK)
            return fail_at(P, s, line_of(s, key), key, "%s", why);
        return ISK_OK;
    }
    if (s->type != ISK_SECTION_BOUNDS)
        return ISK_OK;
    isk_bounds *b = &d->bounds;
    if (!given(s, isk_key_find(s->type, "margin")))
        b->margin = b->mode == ISK_BOUNCE_THESIS ? 0.1 : 0.0;
    if (!given(s, isk_key_find(s->type, "window"))) {
        if (d->view_kind == ISK_VIEWDEF_CAMERA) {
            isk_view v;
            if (isk_view_camera(&v, d->width, d->height, d->zoom, d->tx, d->ty) != ISK_OK)
                return fail_at(P, s, s->line, NULL, "cannot derive its window from the [view] camera");
            b->xmin = v.xmin; b->xmax = v.xmax; b->ymin = v.ymin; b->ymax = v.ymax;
        } else {
            b->xmin = d->xmin; b->xmax = d->xmax; b->ymin = d->ymin; b->ymax = d->ymax;
        }
    }
    return ISK_OK;
}

static isk_status resolve(parser *P, section *s)
{
    for (int i = 0; i < P->nkeys; i++) {
        if (!s->deferred[i])
            continue;
        const isk_key *k = isk_key_at(i);
        char why[400];
        if (isk__fx_key_parse(k, isk__fx_section_item(P->d, s->type, s->index), s->deferred[i], P->d, why, sizeof why))
            return fail_at(P, s, s->key_line[i], k->name, "%s", why);
    }
    return ISK_OK;
}

/* The checks effect_check.c shares with isk_effect_create, at the line of
 * the key they are about. */
typedef struct parse_report {
    fx_report r;
    parser *P;
} parse_report;

static void parse_emit(fx_report *r, isk_status st, isk_section_kind type, int index, const char *key, int show_key,
                       const char *msg)
{
    (void)st;
    parser *P = ((parse_report *)r)->P;
    for (int i = 0; i < P->nsec; i++) {
        section *s = &P->sec[i];
        if (s->type == type && s->index == index) {
            fail_at(P, s, line_of(s, key), show_key ? key : NULL, "%s", msg);
            return;
        }
    }
    isk__ini_error(P->err, P->name, 1, "[%s] %s%s%s", isk_section_name(type), key && show_key ? key : "",
                  key && show_key ? ": " : "", msg);
}

static isk_status finish(parser *P)
{
    for (int i = 0; i < P->nsec; i++) {
        section *s = &P->sec[i];
        isk_status st = resolve(P, s);
        if (st == ISK_OK && !s->reused) /* a preset's item has its kind */
            st = s->type == ISK_SECTION_VIEW ? view_kind(P, s) : derive_kind(P, s);
        if (st == ISK_OK)
            st = kinds_and_required(P, s);
        if (st == ISK_OK)
            st = derived_defaults(P, s);
        if (st != ISK_OK)
            return st;
    }
    parse_report pr = {{parse_emit, NULL, ISK_OK}, P};
    for (int i = 0; i < P->nsec; i++)
        if (isk__fx_check_item(P->d, P->sec[i].type, P->sec[i].index, 0, &pr.r) != ISK_OK)
            return ISK_ERR_FORMAT; /* reported as FILE:LINE by parse_emit */
    return ISK_OK;
}

/* ---- entry points ----------------------------------------------------------------- */

isk_status isk_scene_load_string(isk_effect_def *out, const char *text, const char *name, isk_error *err)
{
    if (!out)
        return isk_error_set(err, ISK_ERR_NULL, "scene: NULL definition");
    isk_effect_def_init(out);
    if (!text)
        return isk_error_set(err, ISK_ERR_NULL, "scene: NULL text");
    if (!name)
        name = "<string>";
    if (strlen(text) > ISK_INI_MAX_BYTES)
        return isk_error_set(err, ISK_ERR_SIZE, "%s: scene larger than %u bytes", name, ISK_INI_MAX_BYTES);
    isk_error local;
    if (!err)
        err = &local;
    parser P = {out, name, err, NULL, 0, -1, isk_key_count()};
    isk_status st = isk__ini_parse(text, name, on_section, on_key, &P, err);
    if (st == ISK_OK)
        st = finish(&P);
    for (int i = 0; i < P.nsec; i++) {
        for (int k = 0; P.sec[i].deferred && k < P.nkeys; k++)
            free(P.sec[i].deferred[k]);
        free(P.sec[i].deferred);
        free(P.sec[i].key_line);
    }
    free(P.sec);
    if (st != ISK_OK) {
        isk_effect_def_free(out);
        isk_effect_def_init(out);
    }
    return st;
}

isk_status isk_scene_load_file(isk_effect_def *out, const char *path, isk_error *err)
{
    if (!out)
        return isk_error_set(err, ISK_ERR_NULL, "scene: NULL definition");
    isk_effect_def_init(out);
    char *buf;
    isk_status rs = isk__ini_read_file(path, &buf, err);
    if (rs != ISK_OK)
        return rs;
    isk_status s = isk_scene_load_string(out, buf, path, err);
    free(buf);
    return s;
}
