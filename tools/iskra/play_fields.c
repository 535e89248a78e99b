/* SPDX-License-Identifier: MIT */
/* The console's fields: what each shows is isk_effect_get of its key, and
 * what is typed goes to isk_effect_set, so ranges and messages are the key
 * table's (a refused value keeps the field open with the table's message
 * under it).  In thesis fidelity the console's own rules come first, as
 * the thesis's page had them: gravity and drag outside 0..100000 (or not a
 * number) become 9.81 and 0.47, the precision may be fractional, and an
 * explosion count out of range makes clicks do nothing. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/keys.h"
#include "play.h"
#include "play_shadow.h"

/* "force NAME" / "emitter NAME" of the first force of a kind or the first
 * emitter of a source, or NULL. */
static const char *first_of(const isk_effect *fx, isk_section_kind s, int kind, char *buf, size_t n)
{
    const isk_effect_def *d = isk_effect_definition(fx);
    const int items = !d ? 0 : s == ISK_SECTION_FORCE ? d->nforces : d->nemitters;
    for (int i = 0; i < items; i++) {
        const int force = s == ISK_SECTION_FORCE;
        if ((force ? (int)d->forces[i].kind : (int)d->emitters[i].born.source) == kind) {
            snprintf(buf, n, "%s %s", isk_section_name(s), force ? d->forces[i].name : d->emitters[i].name);
            return buf;
        }
    }
    return NULL;
}

const char *play_force_section(const isk_effect *fx, isk_force_kind kind, char *buf, size_t n)
{
    return first_of(fx, ISK_SECTION_FORCE, (int)kind, buf, n);
}

const char *play_layer_section(const isk_effect *fx, char *buf, size_t n)
{
    return first_of(fx, ISK_SECTION_EMITTER, ISK_SOURCE_LAYER, buf, n);
}

int play_set(player *p, const char *section, const char *key, const char *value)
{
    isk_error err;
    if (isk_effect_set(p->fx, section, key, value, &err) != ISK_OK) {
        play_say(p, "%s", err.message);
        return -1;
    }
    play_shadow_set(p, section, key, value);
    return 0;
}

double play_divisor_of_slider(double s) { return 1.0 + 29.0 * (1000.0 - s) / 999.0; }

double play_slider_of_divisor(double f)
{
    double s = floor(1000.0 - (f - 1.0) * 999.0 / 29.0 + 0.5);
    return s < 1 ? 1 : s > 1000 ? 1000 : s;
}

/* The thesis page's replacement values, for the force fields it validated. */
typedef struct thesis_fallback {
    isk_force_kind kind;
    const char *key;
    const char *replacement;
} thesis_fallback;

static const thesis_fallback fallbacks[] = {
    {ISK_FORCE_GRAVITY, "g", "9.81"},
    {ISK_FORCE_DRAG, "b", "0.47"},
};

static const thesis_fallback *fallback_for(const isk_effect *fx, const char *section, const char *key)
{
    const isk_effect_def *d = isk_effect_definition(fx);
    if (d->fidelity != ISK_FIDELITY_THESIS || strncmp(section, "force ", 6))
        return NULL;
    int f = isk_effect_def_find_force(d, section + 6);
    for (size_t i = 0; f >= 0 && i < sizeof fallbacks / sizeof fallbacks[0]; i++)
        if (d->forces[f].kind == fallbacks[i].kind && !strcmp(key, fallbacks[i].key))
            return &fallbacks[i];
    return NULL;
}

/* JavaScript's parseFloat, near enough: the longest number at the start. */
static double parse_float(const char *s)
{
    char *end;
    double v = strtod(s, &end);
    return end == s ? NAN : v;
}

/* What a typed value does to the key; 1 when something was set. */
static int apply(player *p, const char *id, const char *section, const char *key, const char *typed)
{
    const thesis_fallback *fb = fallback_for(p->fx, section, key);
    isk_error err;
    if (fb) {
        double v = parse_float(typed);
        char num[40];
        const char *value = num;
        if (!(v >= 0 && v <= 100000)) {
            value = fb->replacement;
            play_say(p, "%s: \"%s\" is not 0..100000: the thesis puts %s", id, typed, fb->replacement);
        } else {
            snprintf(num, sizeof num, "%.17g", v);
        }
        if (isk_effect_set(p->fx, section, key, value, &err) != ISK_OK)
            return 0;
        play_shadow_set(p, section, key, value);
        return 1;
    }
    if (isk_effect_set(p->fx, section, key, typed, &err) != ISK_OK) {
        isk_ui_field_error(&p->ui, id, err.message);
        return 0;
    }
    play_shadow_set(p, section, key, typed);
    return 1;
}

static unsigned flags_of(const char *section, const char *key)
{
    char type[32];
    snprintf(type, sizeof type, "%s", section);
    type[strcspn(type, " ")] = 0;
    int s = isk_section_find(type);
    const isk_key *k = s >= 0 ? isk_key_find((isk_section_kind)s, key) : NULL;
    if (k && (k->type == ISK_KEY_NUMBER || k->type == ISK_KEY_WHOLE || k->type == ISK_KEY_COUNT ||
              k->type == ISK_KEY_LONG || k->type == ISK_KEY_VECTOR || k->type == ISK_KEY_NUMBERS4) &&
        !k->words)
        return ISK_UI_FIELD_NUMBER;
    return 0;
}

int play_key_field(player *p, const char *id, isk_ui_rect r, const char *section, const char *key)
{
    char value[128] = "-", typed[128];
    isk_error err;
    if (!section || isk_effect_get(p->fx, section, key, value, sizeof value, &err) != ISK_OK) {
        isk_ui_set_disabled(&p->ui, 1);
        isk_ui_field(&p->ui, id, r, "-", 0, NULL, 0);
        isk_ui_set_disabled(&p->ui, 0);
        return 0;
    }
    if (isk_ui_field(&p->ui, id, r, value, flags_of(section, key), typed, sizeof typed) != ISK_UI_FIELD_APPLY)
        return 0;
    return apply(p, id, section, key, typed);
}

/* Part `part` of a comma-separated list into out. */
static void list_part(const char *list, int part, char *out, size_t n)
{
    const char *s = list;
    for (int i = 0; i < part && s; i++) {
        s = strchr(s, ',');
        if (s)
            s++;
    }
    if (!s) {
        snprintf(out, n, "-");
        return;
    }
    while (*s == ' ')
        s++;
    size_t len = strcspn(s, ",");
    while (len && s[len - 1] == ' ')
        len--;
    snprintf(out, n, "%.*s", (int)len, s);
}

int play_key_part_field(player *p, const char *id, isk_ui_rect r, const char *section, const char *key, int part,
                        const char *current)
{
    char value[200], shown[64], typed[64];
    isk_error err;
    if (!section || (!current && isk_effect_get(p->fx, section, key, value, sizeof value, &err) != ISK_OK)) {
        isk_ui_set_disabled(&p->ui, 1);
        isk_ui_field(&p->ui, id, r, "-", 0, NULL, 0);
        isk_ui_set_disabled(&p->ui, 0);
        return 0;
    }
    if (current)
        snprintf(value, sizeof value, "%s", current);
    list_part(value, part, shown, sizeof shown);
    if (isk_ui_field(&p->ui, id, r, shown, ISK_UI_FIELD_NUMBER, typed, sizeof typed) != ISK_UI_FIELD_APPLY)
        return 0;
    /* The whole list again, with this part replaced. */
    char whole[256] = "", piece[64];
    size_t used = 0;
    for (int i = 0; i < 8; i++) {
        list_part(value, i, piece, sizeof piece);
        if (!strcmp(piece, "-"))
            break;
        used += (size_t)snprintf(whole + used, sizeof whole - used, "%s%s", i ? ", " : "", i == part ? typed : piece);
        if (used >= sizeof whole)
            return 0;
    }
    if (isk_effect_set(p->fx, section, key, whole, &err) != ISK_OK) {
        isk_ui_field_error(&p->ui, id, err.message);
        return 0;
    }
    play_shadow_set(p, section, key, whole);
    return 1;
}

/* The thesis's precision: `for (j = 0; j < precision; j++)` with steps of
 * dt/precision, so "2.5" runs 3 steps of dt/2.5 (time 1.2 times faster)
 * and a value that is not a number runs none. */
static int thesis_precision(player *p, const char *typed)
{
    double v = parse_float(typed);
    if (!(v > 0)) {
        p->physics_off = 1;
        snprintf(p->precision_text, sizeof p->precision_text, "%s", typed);
        play_say(p, "precision \"%s\": the thesis runs no step at all (physics stops until a number is typed)",
                 typed);
        return 1;
    }
    double n = ceil(v);
    if (n > 1000) {
        isk_ui_field_error(&p->ui, "precision", "at most 1000 substeps");
        return 0;
    }
    char sub[16], dt[40];
    snprintf(sub, sizeof sub, "%d", (int)n);
    snprintf(dt, sizeof dt, "%.17g", n == v ? p->base_dt : p->base_dt * n / v);
    if (play_set(p, "scene", "substeps", sub) || play_set(p, "scene", "dt", dt))
        return 0;
    p->physics_off = 0;
    if (n == v)
        p->precision_text[0] = 0;
    else {
        snprintf(p->precision_text, sizeof p->precision_text, "%s", typed);
        play_say(p, "precision %s: the thesis runs %d steps of dt/%s (time %.3g times faster)", typed, (int)n, typed,
                 n / v);
    }
    return 1;
}

int play_precision_field(player *p, const char *id, isk_ui_rect r)
{
    const isk_effect_def *d = isk_effect_definition(p->fx);
    char shown[64], typed[64];
    if (p->precision_text[0])
        snprintf(shown, sizeof shown, "%s", p->precision_text);
    else
        snprintf(shown, sizeof shown, "%d", d->substeps);
    const int thesis = d->fidelity == ISK_FIDELITY_THESIS;
    if (isk_ui_field(&p->ui, id, r, shown, ISK_UI_FIELD_NUMBER, typed, sizeof typed) != ISK_UI_FIELD_APPLY)
        return 0;
    if (thesis)
        return thesis_precision(p, typed);
    isk_error err;
    if (isk_effect_set(p->fx, "scene", "substeps", typed, &err) != ISK_OK) {
        isk_ui_field_error(&p->ui, id, err.message);
        return 0;
    }
    play_shadow_set(p, "scene", "substeps", typed);
    return 1;
}
