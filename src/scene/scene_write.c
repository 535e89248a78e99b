/* SPDX-License-Identifier: MIT */
/* A definition written as a scene file (isk_scene_write, isk_scene_save in
 * iskra/scene.h): every key of every item, walked from the key table and
 * formatted by its row (isk__fx_key_format gives text that parses back to the
 * same bits), so the text reproduces the definition exactly, whatever was
 * changed while it ran.
 *
 * Sections come in the parser's order ([scene], [view], forces,
 * deflectors, [bounds], emitters, drawings, [click]); every section is
 * written, keys at their defaults too, so nothing depends on a default
 * that might change.  Keys that do not apply to an item's kind are left
 * out (the parser refuses them), and so is a reference to "the first
 * emitter" (its default) and empty text that is not required (an emitter
 * without a texture: "texture =" would say nothing).  What a line cannot
 * hold is refused with ISK_ERR_FORMAT rather than written wrong: a value
 * longer than a scene line, text that starts or ends with blanks or holds
 * a comment, a potential moved by a C function, an item without a name
 * or with one a section header cannot hold. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/outfile.h"
#include "iskra/scene.h"
#include "key_value.h"
#include "scene/ini_read.h"

typedef struct out {
    char *buf;
    size_t len, cap;
    int nomem;
} out;

static void put(out *o, const char *s)
{
    size_t n = strlen(s);
    if (o->nomem)
        return;
    if (o->len + n + 1 > o->cap) {
        size_t cap = o->cap ? o->cap : 4096;
        while (cap < o->len + n + 1)
            cap *= 2;
        char *b = realloc(o->buf, cap);
        if (!b) {
            o->nomem = 1;
            return;
        }
        o->buf = b;
        o->cap = cap;
    }
    memcpy(o->buf + o->len, s, n + 1);
    o->len += n;
}

/* Whether the parser reads `v` back as written: libinih trims blanks and
 * starts a comment at ';' after a blank. */
static int survives_ini(const char *v)
{
    size_t n = strlen(v);
    if (n && (v[0] == ' ' || v[0] == '\t' || v[n - 1] == ' ' || v[n - 1] == '\t'))
        return 0;
    for (size_t i = 1; i < n; i++)
        if (v[i] == ';' && (v[i - 1] == ' ' || v[i - 1] == '\t'))
            return 0;
    return !strchr(v, '\n') && !strchr(v, '\r') && v[0] != ';';
}

/* Whether a scene file must give the key for an item of that kind. */
static int required(const isk_key *k, int kind)
{
    return kind < 0 ? k->required != 0 : kind < 32 && (k->required >> kind & 1u);
}

static isk_status write_item(out *o, const isk_effect_def *d, isk_section_kind s, int index, isk_error *err)
{
    const char *name = isk__fx_item_name(d, s, index);
    /* A section header holds the name as it is: one that breaks the name
     * rule (names.c) would not load, or would inject lines ("x]\nrate = 1"). */
    if (isk_section_named(s) && (!isk__fx_name_ok(name, ISK_NAME_MAX) || isk__fx_name_reserved(name)))
        return isk_error_set(err, ISK_ERR_FORMAT, "%s %d: %s (a scene file needs a name of 1..%d letters, digits, "
                                                  "'_', '-' or '.', not \"all\" or \"none\")",
                             isk_section_name(s), index, *name ? "its name cannot be written" : "it has no name",
                             ISK_NAME_MAX - 1);
    char label[ISK_NAME_MAX + 24], value[ISK_INI_MAX_LINE + 2];
    snprintf(label, sizeof label, "[%s%s%s]", isk_section_name(s), *name ? " " : "", name);
    put(o, "\n");
    put(o, label);
    put(o, "\n");
    const void *item = isk__fx_section_item_c(d, s, index);
    const int kind = isk__fx_item_kind(d, s, index);
    if (s == ISK_SECTION_FORCE && d->forces[index].kind == ISK_FORCE_POTENTIAL && d->forces[index].pot.motion)
        return isk_error_set(err, ISK_ERR_FORMAT, "%s moves by a C function, which a scene file cannot hold", label);
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        if (k->section != s || !isk__fx_key_applies(k, kind) || k->directive)
            continue;
        if (k->type == ISK_KEY_REF && *(const int *)((const char *)item + k->offset) < 0)
            continue; /* "the first emitter" is the default, and has no name to write */
        if (k->type == ISK_KEY_TEXT && !*((const char *)item + k->offset) && !required(k, kind))
            continue; /* empty text ("texture =") is the key's absence: nothing to write */
        if (isk__fx_key_format(k, item, d, value, sizeof value) != ISK_OK || strlen(k->name) + 3 + strlen(value) >
                                                                             ISK_INI_MAX_LINE)
            return isk_error_set(err, ISK_ERR_FORMAT, "%s %s: the value is longer than a scene line holds (%d "
                                                      "characters)",
                                 label, k->name, ISK_INI_MAX_LINE);
        if (!survives_ini(value))
            return isk_error_set(err, ISK_ERR_FORMAT, "%s %s: \"%s\" cannot be written in a scene file (blanks "
                                                      "at either end, a line break, or ' ;' which starts a comment)",
                                 label, k->name, value);
        put(o, k->name);
        put(o, " = ");
        put(o, value);
        put(o, "\n");
    }
    return ISK_OK;
}

isk_status isk_scene_write(const isk_effect_def *d, char **text, isk_error *err)
{
    if (!text)
        return isk_error_set(err, ISK_ERR_NULL, "scene: NULL output");
    *text = NULL;
    if (!d)
        return isk_error_set(err, ISK_ERR_NULL, "scene: NULL definition");
    static const isk_section_kind order[] = {ISK_SECTION_SCENE,     ISK_SECTION_VIEW,   ISK_SECTION_FORCE,
                                             ISK_SECTION_DEFLECTOR, ISK_SECTION_BOUNDS, ISK_SECTION_EMITTER,
                                             ISK_SECTION_DRAWING,   ISK_SECTION_CLICK,  ISK_SECTION_PROBE};
    out o = {NULL, 0, 0, 0};
    put(&o, "; an iskra scene: every key of every section, as the definition held them\n");
    for (size_t j = 0; j < sizeof order / sizeof order[0]; j++) {
        const int n = isk__fx_section_items(d, order[j]);
        for (int i = 0; i < n; i++) {
            isk_status s = write_item(&o, d, order[j], i, err);
            if (s != ISK_OK) {
                free(o.buf);
                return s;
            }
        }
    }
    if (o.nomem) {
        free(o.buf);
        return isk_error_set(err, ISK_ERR_NOMEM, "scene: out of memory");
    }
    *text = o.buf;
    return ISK_OK;
}

isk_status isk_scene_save(const isk_effect_def *d, const char *path, isk_error *err)
{
    if (!path || !*path)
        return isk_error_set(err, ISK_ERR_NULL, "scene: no file name to save to");
    char *text;
    isk_status s = isk_scene_write(d, &text, err);
    if (s != ISK_OK)
        return s;
    /* iskra/outfile.h: a temporary beside it, then a rename, so an
     * existing file is replaced whole or not at all. */
    isk_outfile o;
    if ((s = isk_outfile_open(&o, path, err)) == ISK_OK) {
        size_t len = strlen(text);
        if (fwrite(text, 1, len, o.f) != len) {
            s = isk_error_set(err, ISK_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
            isk_outfile_abort(&o);
        } else {
            s = isk_outfile_commit(&o, err);
        }
    }
    free(text);
    return s;
}
