/* SPDX-License-Identifier: MIT */
/* The items of a definition the key table addresses (see key_value.h):
 * sections, their items, names, lines and kinds; and the shared helpers of
 * the key_*.c files: field access, ranges and expectations in words. */
#include "key_value.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/ini_read.h"
#include "scene/scene_values.h"


/* ---- items ------------------------------------------------------------------- */

int isk__fx_section_items(const isk_effect_def *d, isk_section_kind s)
{
    switch (s) {
    case ISK_SECTION_FORCE: return d->nforces;
    case ISK_SECTION_DEFLECTOR: return d->ndeflectors;
    case ISK_SECTION_EMITTER: return d->nemitters;
    case ISK_SECTION_DRAWING: return d->ndrawings;
    case ISK_SECTION_PROBE: return d->nprobes;
    default: return 1;
    }
}

void *isk__fx_section_item(isk_effect_def *d, isk_section_kind s, int i)
{
    if (i < 0 || i >= isk__fx_section_items(d, s))
        return NULL;
    switch (s) {
    case ISK_SECTION_SCENE:
    case ISK_SECTION_VIEW: return d;
    case ISK_SECTION_FORCE: return &d->forces[i];
    case ISK_SECTION_DEFLECTOR: return &d->deflectors[i];
    case ISK_SECTION_BOUNDS: return &d->bounds;
    case ISK_SECTION_EMITTER: return &d->emitters[i];
    case ISK_SECTION_DRAWING: return &d->drawings[i];
    case ISK_SECTION_CLICK: return &d->click;
    case ISK_SECTION_PROBE: return &d->probes[i];
    default: return NULL;
    }
}

const void *isk__fx_section_item_c(const isk_effect_def *d, isk_section_kind s, int i)
{
    return isk__fx_section_item((isk_effect_def *)d, s, i);
}

const char *isk__fx_item_name(const isk_effect_def *d, isk_section_kind s, int i)
{
    if (i < 0 || i >= isk__fx_section_items(d, s))
        return "";
    switch (s) {
    case ISK_SECTION_FORCE: return d->forces[i].name;
    case ISK_SECTION_DEFLECTOR: return d->deflectors[i].name;
    case ISK_SECTION_EMITTER: return d->emitters[i].name;
    case ISK_SECTION_DRAWING: return d->drawings[i].name;
    case ISK_SECTION_PROBE: return d->probes[i].name;
    default: return "";
    }
}

int isk__fx_item_line(const isk_effect_def *d, isk_section_kind s, int i)
{
    if (i < 0 || i >= isk__fx_section_items(d, s))
        return 0;
    switch (s) {
    case ISK_SECTION_FORCE: return d->forces[i].line;
    case ISK_SECTION_DEFLECTOR: return d->deflectors[i].line;
    case ISK_SECTION_EMITTER: return d->emitters[i].line;
    case ISK_SECTION_DRAWING: return d->drawings[i].line;
    case ISK_SECTION_PROBE: return d->probes[i].line;
    default: return 0;
    }
}

int isk__fx_item_kind(const isk_effect_def *d, isk_section_kind s, int i)
{
    if (i < 0 || i >= isk__fx_section_items(d, s))
        return -1;
    switch (s) {
    case ISK_SECTION_VIEW: return (int)d->view_kind;
    case ISK_SECTION_FORCE: return (int)d->forces[i].kind;
    case ISK_SECTION_BOUNDS: return (int)d->bounds.mode;
    case ISK_SECTION_EMITTER: return (int)d->emitters[i].born.source;
    case ISK_SECTION_DRAWING: return (int)d->drawings[i].kind;
    case ISK_SECTION_PROBE: return (int)d->probes[i].kind;
    default: return -1;
    }
}

int isk__fx_refs_cap(isk_section_kind refers)
{
    return refers == ISK_SECTION_FORCE     ? ISK_EFFECT_MAX_FORCES
           : refers == ISK_SECTION_EMITTER ? ISK_EFFECT_MAX_EMITTERS
                                           : ISK_EFFECT_MAX_DEFLECTORS;
}

int isk__fx_key_applies(const isk_key *k, int kind)
{
    return kind < 0 || k->applies == 0 || (kind < 32 && (k->applies >> kind & 1u));
}

/* "gravity", "drag or wind" */
void isk__fx_join_names(char *buf, size_t n, const char *const *names, int count, unsigned mask)
{
    int total = 0, j = 0;
    buf[0] = 0;
    for (int i = 0; i < count; i++)
        total += (mask >> i) & 1u;
    for (int i = 0; i < count; i++) {
        if (!(mask >> i & 1u))
            continue;
        size_t len = strlen(buf);
        snprintf(buf + len, n - len, "%s%s", j == 0 ? "" : (j == total - 1 ? " or " : ", "), names[i]);
        j++;
    }
}

void isk__fx_key_kind_message(const isk_key *k, int kind, char *buf, size_t n)
{
    int count;
    const char *const *names = isk_section_kind_names(k->section, &count);
    const char *word = isk_section_kind_key(k->section);
    static const char *const nouns[ISK_SECTION_COUNT] = {
        [ISK_SECTION_VIEW] = "[view]",       [ISK_SECTION_FORCE] = "force",     [ISK_SECTION_BOUNDS] = "[bounds]",
        [ISK_SECTION_EMITTER] = "emitter",   [ISK_SECTION_DRAWING] = "drawing",
        [ISK_SECTION_PROBE] = "probe",
    };
    if (!names || !word) {
        snprintf(buf, n, "does not apply here");
        return;
    }
    if (!*word)
        word = "kind";
    char list[160];
    isk__fx_join_names(list, sizeof list, names, count, k->applies);
    snprintf(buf, n, "only for %s = %s (this %s has %s = %s)", word, list, nouns[k->section], word,
             kind >= 0 && kind < count ? names[kind] : "?");
}


/* ---- field access (the fields' types differ; a row says which) ---------------- */


/* Enum fields: every enum the table uses is int-sized (checked below). */
_Static_assert(sizeof(isk_integrator) == sizeof(int) && sizeof(isk_blend) == sizeof(int) &&
                   sizeof(isk_force_kind) == sizeof(int) && sizeof(isk_source_kind) == sizeof(int),
               "enum fields are read as int");

/* Whole-number fields come in three types; a row says which. */
double isk__fx_whole_get(const isk_key *k, const void *item)
{
    switch (k->type) {
    case ISK_KEY_WHOLE: return (double)*FX_AT_C(int, item, k->offset);
    case ISK_KEY_LONG: return (double)*FX_AT_C(long, item, k->offset);
    default: return (double)*FX_AT_C(size_t, item, k->offset);
    }
}

void isk__fx_whole_set(const isk_key *k, void *item, double v)
{
    switch (k->type) {
    case ISK_KEY_WHOLE: *FX_AT(int, item, k->offset) = (int)v; break;
    case ISK_KEY_LONG: *FX_AT(long, item, k->offset) = (long)v; break;
    default: *FX_AT(size_t, item, k->offset) = (size_t)v; break;
    }
}


/* ---- expectations and ranges (one wording for the parser and the check) ------- */

/* An exponent as people write it: 1e+12 -> 1e12, 1.5e-07 -> 1.5e-7. */
static void tidy_exponent(char *s)
{
    char *x = strchr(s, 'e');
    if (!x)
        return;
    char *d = x + 1, *src = x + 1;
    if (*src == '+')
        src++;
    else if (*src == '-')
        *d++ = *src++;
    while (*src == '0' && src[1])
        src++;
    memmove(d, src, strlen(src) + 1);
}

/* A bound as a message shows it: %.15g, or where that takes more than six
 * characters the shortest exponent form that reads back the same if it is
 * shorter (1e12, not 1000000000000; 1000 and 2^28 = 268435456 stay), so a
 * message fits a field's error box. */
static void bound_words(double v, char *buf, size_t n)
{
    char plain[32], e[32];
    snprintf(plain, sizeof plain, "%.15g", v);
    int p = 0;
    do
        snprintf(e, sizeof e, "%.*e", p, v);
    while (strtod(e, NULL) != v && ++p < 17);
    tidy_exponent(plain);
    tidy_exponent(e);
    snprintf(buf, n, "%s", strlen(plain) > 6 && strlen(e) < strlen(plain) ? e : plain);
}

void isk__fx_range_words(const isk_key *k, const char *what, char *buf, size_t n)
{
    const char *op_lo = k->lo_bound == ISK_BOUND_INCL ? ">=" : ">";
    const char *op_hi = k->hi_bound == ISK_BOUND_INCL ? "<=" : "<";
    char lo[32], hi[32];
    bound_words(k->min, lo, sizeof lo);
    bound_words(k->max, hi, sizeof hi);
    if (k->lo_bound == ISK_BOUND_INCL && k->hi_bound == ISK_BOUND_INCL)
        snprintf(buf, n, "%s between %s and %s", what, lo, hi);
    else if (k->lo_bound && k->hi_bound)
        snprintf(buf, n, "%s %s %s and %s %s", what, op_lo, lo, op_hi, hi);
    else if (k->lo_bound)
        snprintf(buf, n, "%s %s %s", what, op_lo, lo);
    else if (k->hi_bound)
        snprintf(buf, n, "%s %s %s", what, op_hi, hi);
    else
        snprintf(buf, n, "%s", what);
}

/* " or forever" after a number's expectation (the first word only: the
 * others are synonyms). */
static void append_word(const isk_key *k, char *buf, size_t n)
{
    if (k->words) {
        size_t len = strlen(buf);
        snprintf(buf + len, n - len, " or %s", k->words[0].word);
    }
}

void isk__fx_key_expect(const isk_key *k, char *buf, size_t n)
{
    switch (k->type) {
    case ISK_KEY_NUMBER:
        isk__fx_range_words(k, k->what ? k->what : "a number", buf, n);
        append_word(k, buf, n);
        return;
    case ISK_KEY_WHOLE:
    case ISK_KEY_LONG:
    case ISK_KEY_COUNT:
        isk__fx_range_words(k, k->what ? k->what : "a whole number", buf, n);
        append_word(k, buf, n);
        return;
    case ISK_KEY_SEED: snprintf(buf, n, "a whole number between 0 and 18446744073709551615"); return;
    case ISK_KEY_BOOL: snprintf(buf, n, "true or false (also yes/no, on/off, 1/0)"); return;
    case ISK_KEY_COLOR: snprintf(buf, n, "a colour (#rrggbb, #rrggbbaa or a name such as yellow)"); return;
    case ISK_KEY_ENUM: {
        const char *all[64];
        int m = isk_key_choices(k, all, 64);
        isk__fx_join_names(buf, n, all, m, m >= 32 ? ~0u : (1u << m) - 1u);
        return;
    }
    case ISK_KEY_VECTOR: snprintf(buf, n, "2 numbers \"%s\"", k->what ? k->what : "x, y"); return;
    case ISK_KEY_POINT: snprintf(buf, n, "2 numbers \"x, y\" or none"); return;
    case ISK_KEY_ANGLE: isk__fx_range_words(k, "an angle in degrees (or \"N rad\")", buf, n); return;
    case ISK_KEY_PAIR: snprintf(buf, n, "2 numbers \"%s\"", k->what ? k->what : "min, max"); return;
    case ISK_KEY_NUMBERS4: snprintf(buf, n, "4 numbers \"%s\"", k->what ? k->what : "a, b, c, d"); return;
    case ISK_KEY_COLOR_STOPS: snprintf(buf, n, "stops \"t:colour, t:colour, ...\" or off"); return;
    case ISK_KEY_SCALAR_STOPS: snprintf(buf, n, "stops \"t:value, t:value, ...\" or off"); return;
    case ISK_KEY_TEXT: snprintf(buf, n, "text of at most %zu characters", k->aux - 1); return;
    case ISK_KEY_SIDES: {
        char sides[120];
        isk__fx_join_names(sides, sizeof sides, k->names, k->nnames, (1u << k->nnames) - 1u);
        snprintf(buf, n, "%s (or all, none)", sides);
        return;
    }
    case ISK_KEY_POINTS:
        snprintf(buf, n, "%.15g to %.15g points \"x0, y0, x1, y1, ...\" (an even count of numbers)", k->min, k->max);
        return;
    case ISK_KEY_REFS: snprintf(buf, n, "%s names separated by commas (or all, none)", isk_section_name(k->refers)); return;
    case ISK_KEY_REF: snprintf(buf, n, "an %s name", isk_section_name(k->refers)); return;
    default: snprintf(buf, n, "a value"); return;
    }
}

int isk__fx_in_range(const isk_key *k, double v)
{
    if (k->lo_bound == ISK_BOUND_INCL && !(v >= k->min)) return 0;
    if (k->lo_bound == ISK_BOUND_EXCL && !(v > k->min)) return 0;
    if (k->hi_bound == ISK_BOUND_INCL && !(v <= k->max)) return 0;
    if (k->hi_bound == ISK_BOUND_EXCL && !(v < k->max)) return 0;
    return 1;
}

isk_status isk__fx_expected(const isk_key *k, char *why, size_t n, const char *got)
{
    char want[200];
    isk__fx_key_expect(k, want, sizeof want);
    snprintf(why, n, "expected %s, got \"%s\"", want, got);
    return ISK_ERR_RANGE;
}

/* "expected ..., got "x"; did you mean "y"?" (a suggestion from names). */
isk_status isk__fx_expected_or_guess(const isk_key *k, const char *text, const char *const *names, int count,
                                    char *why, size_t n)
{
    const char *s = count ? isk__scv_suggest(text, names, count) : NULL;
    char want[200];
    isk__fx_key_expect(k, want, sizeof want);
    snprintf(why, n, "expected %s, got \"%s\"%s%s%s", want, text, s ? "; did you mean \"" : "", s ? s : "",
             s ? "\"?" : "");
    return ISK_ERR_RANGE;
}

const char *isk__fx_key_suggest(isk_section_kind section, const char *word)
{
    const char *names[128];
    int n = 0;
    for (int i = 0; i < isk_key_count() && n < 128; i++)
        if (isk_key_at(i)->section == section)
            names[n++] = isk_key_at(i)->name;
    return isk__scv_suggest(word, names, n);
}

/* A word standing for a value: its index, or -1. */
int isk__fx_word_index(const isk_key *k, const char *s)
{
    for (int i = 0; k->words && k->words[i].word; i++)
        if (isk__scv_lookup(s, &k->words[i].word, 1) == 0)
            return i;
    return -1;
}

/* The word whose value v is, or NULL (exact comparison; INFINITY too). */
const char *isk__fx_word_of(const isk_key *k, double v)
{
    for (int i = 0; k->words && k->words[i].word; i++)
        if (k->words[i].value == v)
            return k->words[i].word;
    return NULL;
}

/* ---- the public view of the items (iskra/keys.h) ------------------------------------------- */

int isk_key_items(const isk_effect_def *d, isk_section_kind s)
{
    return d && (unsigned)s < ISK_SECTION_COUNT ? isk__fx_section_items(d, s) : 0;
}

const char *isk_key_item_name(const isk_effect_def *d, isk_section_kind s, int i)
{
    return d && (unsigned)s < ISK_SECTION_COUNT ? isk__fx_item_name(d, s, i) : "";
}

int isk_key_item_kind(const isk_effect_def *d, isk_section_kind s, int i)
{
    return d && (unsigned)s < ISK_SECTION_COUNT ? isk__fx_item_kind(d, s, i) : -1;
}

const void *isk_key_item(const isk_effect_def *d, isk_section_kind s, int i)
{
    return d && (unsigned)s < ISK_SECTION_COUNT ? isk__fx_section_item_c(d, s, i) : NULL;
}

int isk_key_applies(const isk_key *k, int kind) { return k && isk__fx_key_applies(k, kind); }

isk_key_when isk_key_when_set(const isk_key *k, int kind)
{
    if (!k || k->create_only)
        return ISK_KEY_WHEN_CREATED;
    if (k->live == ISK_KEY_ALL_KINDS || (kind < 0 && k->live) || (kind >= 0 && kind < 32 && (k->live >> kind & 1u)))
        return ISK_KEY_WHEN_LIVE;
    return ISK_KEY_WHEN_RESET;
}
