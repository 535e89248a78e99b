/* SPDX-License-Identifier: MIT */
/* Text -> field, by the row's type (see key_value.h). */
#include "key_value.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/ini_read.h"
#include "scene/scene_values.h"

#define PI 3.14159265358979323846
#define MAX_TEXT (ISK_INI_MAX_LINE + 1)

/* ---- parse -------------------------------------------------------------------- */

/* Exactly `count` comma-separated numbers, each within the row's range. */
static isk_status parse_numbers(const isk_key *k, const char *text, int count, double *out, char *why, size_t n)
{
    char buf[MAX_TEXT], want[160];
    char *items[SCV_LIST_MAX];
    int got;
    isk__fx_key_expect(k, want, sizeof want);
    if (strlen(text) >= sizeof buf || !isk__scv_split(text, buf, sizeof buf, ',', items, SCV_LIST_MAX, &got) ||
        got != count) {
        snprintf(why, n, "expected %s, got \"%s\"", want, text);
        return ISK_ERR_RANGE;
    }
    for (int i = 0; i < count; i++)
        if (!isk__scv_number(items[i], &out[i]) || !isk__fx_in_range(k, out[i])) {
            char w2[120];
            isk__fx_range_words(k, "a number", w2, sizeof w2);
            snprintf(why, n, "expected %s: item %d is not %s: \"%s\"", want, i + 1, w2, items[i]);
            return ISK_ERR_RANGE;
        }
    return ISK_OK;
}

static isk_status parse_whole(const isk_key *k, const char *text, double *out, char *why, size_t n)
{
    int w = isk__fx_word_index(k, text);
    if (w >= 0) {
        *out = k->words[w].value;
        return ISK_OK;
    }
    double x = 0;
    if (!isk__scv_number(text, &x) || x != floor(x) || !isk__fx_in_range(k, x))
        return isk__fx_expected(k, why, n, text);
    *out = x;
    return ISK_OK;
}

static isk_status parse_stops(const isk_key *k, void *item, const char *text, char *why, size_t n)
{
    const int is_color = k->type == ISK_KEY_COLOR_STOPS;
    isk_color_ramp *cr = FX_AT(isk_color_ramp, item, k->offset);
    isk_scalar_ramp *sr = FX_AT(isk_scalar_ramp, item, k->offset);
    static const char *const off[] = {"off", "none"};
    if (isk__scv_lookup(text, off, 2) >= 0) {
        if (is_color)
            cr->n = 0;
        else
            sr->n = 0;
        return ISK_OK;
    }
    char buf[MAX_TEXT];
    char *items[SCV_LIST_MAX];
    int count;
    const char *form = is_color ? "t:colour, t:colour, ..." : "t:value, t:value, ...";
    if (strlen(text) >= sizeof buf || !isk__scv_split(text, buf, sizeof buf, ',', items, SCV_LIST_MAX, &count) ||
        count < 1) {
        snprintf(why, n, "expected stops \"%s\", got \"%s\"", form, text);
        return ISK_ERR_RANGE;
    }
    if (count > ISK_GRADIENT_MAX_STOPS) {
        snprintf(why, n, "at most %d stops, got %d", ISK_GRADIENT_MAX_STOPS, count);
        return ISK_ERR_RANGE;
    }
    isk_color_stop cs[ISK_GRADIENT_MAX_STOPS];
    isk_scalar_stop ss[ISK_GRADIENT_MAX_STOPS];
    double prev = -1;
    for (int i = 0; i < count; i++) {
        char *colon = strchr(items[i], ':');
        if (!colon) {
            snprintf(why, n, "stop %d: expected \"t:%s\", got \"%s\"", i + 1, is_color ? "colour" : "value", items[i]);
            return ISK_ERR_RANGE;
        }
        *colon = 0;
        char *tv = isk__scv_trim(items[i]), *val = isk__scv_trim(colon + 1);
        double t;
        if (!isk__scv_number(tv, &t) || t < 0 || t > 1) {
            snprintf(why, n, "stop %d: expected a position t between 0 and 1, got \"%s\"", i + 1, tv);
            return ISK_ERR_RANGE;
        }
        if (t <= prev) {
            snprintf(why, n, "stop %d: positions must increase (%.15g after %.15g)", i + 1, t, prev);
            return ISK_ERR_RANGE;
        }
        prev = t;
        if (is_color) {
            cs[i].t = t;
            if (!isk__scv_color(val, &cs[i].color)) {
                snprintf(why, n, "stop %d: expected a colour (#rrggbb, #rrggbbaa or a name), got \"%s\"", i + 1, val);
                return ISK_ERR_RANGE;
            }
        } else {
            ss[i].t = t;
            if (!isk__scv_number(val, &ss[i].value) || !isk__fx_in_range(k, ss[i].value)) {
                char want[120];
                isk__fx_range_words(k, "a number", want, sizeof want);
                snprintf(why, n, "stop %d: expected %s, got \"%s\"", i + 1, want, val);
                return ISK_ERR_RANGE;
            }
        }
    }
    if (is_color) {
        memcpy(cr->stops, cs, sizeof cs[0] * (size_t)count);
        cr->n = count;
    } else {
        memcpy(sr->stops, ss, sizeof ss[0] * (size_t)count);
        sr->n = count;
    }
    return ISK_OK;
}

static isk_status parse_sides(const isk_key *k, void *item, const char *text, char *why, size_t n)
{
    static const char *const words[] = {"all", "none"};
    unsigned *sides = FX_AT(unsigned, item, k->offset);
    int w = isk__scv_lookup(text, words, 2);
    if (w >= 0) {
        *sides = w == 0 ? ISK_SIDE_ALL : 0u;
        return ISK_OK;
    }
    char buf[MAX_TEXT];
    char *items[SCV_LIST_MAX];
    int count;
    if (strlen(text) >= sizeof buf || !isk__scv_split(text, buf, sizeof buf, ',', items, SCV_LIST_MAX, &count) ||
        count == 0)
        return isk__fx_expected(k, why, n, text);
    unsigned mask = 0;
    for (int j = 0; j < count; j++) {
        int sd = isk__scv_lookup(items[j], k->names, k->nnames);
        if (sd < 0) {
            return isk__fx_expected_or_guess(k, items[j], k->names, k->nnames, why, n);
        }
        if (mask & (1u << sd)) {
            snprintf(why, n, "'%s' is listed twice", k->names[sd]);
            return ISK_ERR_RANGE;
        }
        mask |= 1u << sd;
    }
    *sides = mask;
    return ISK_OK;
}

static isk_status parse_points(const isk_key *k, void *item, const char *text, char *why, size_t n)
{
    char buf[MAX_TEXT];
    char *items[SCV_LIST_MAX];
    int count;
    if (strlen(text) >= sizeof buf || !isk__scv_split(text, buf, sizeof buf, ',', items, SCV_LIST_MAX, &count) ||
        count % 2 || count < 2 * (int)k->min || count > 2 * (int)k->max)
        return isk__fx_expected(k, why, n, text);
    double *pts = malloc(sizeof *pts * (size_t)count);
    if (!pts) {
        snprintf(why, n, "out of memory");
        return ISK_ERR_NOMEM;
    }
    for (int j = 0; j < count; j++)
        if (!isk__scv_number(items[j], &pts[j])) {
            free(pts);
            snprintf(why, n, "item %d is not a number: \"%s\"", j + 1, items[j]);
            return ISK_ERR_RANGE;
        }
    double **field = FX_AT(double *, item, k->offset);
    free(*field);
    *field = pts;
    *FX_AT(int, item, k->aux) = count / 2;
    return ISK_OK;
}

/* "no force named 'gravty'; did you mean 'gravity'?" */
static isk_status unknown_name(const isk_key *k, const isk_effect_def *d, const char *name, char *why, size_t n)
{
    const char *sec = isk_section_name(k->refers);
    int count = d ? isk__fx_section_items(d, k->refers) : 0;
    if (count == 0) {
        snprintf(why, n, "no %s named '%s' (the scene defines no [%s NAME] section)", sec, name, sec);
        return ISK_ERR_RANGE;
    }
    const char *names[ISK_EFFECT_MAX_DEFLECTORS];
    for (int i = 0; i < count && i < ISK_EFFECT_MAX_DEFLECTORS; i++)
        names[i] = isk__fx_item_name(d, k->refers, i);
    const char *s = isk__scv_suggest(name, names, count);
    snprintf(why, n, "no %s named '%s'%s%s%s", sec, name, s ? "; did you mean '" : "", s ? s : "", s ? "'?" : "");
    return ISK_ERR_RANGE;
}

static int find_name(const isk_effect_def *d, isk_section_kind s, const char *name)
{
    int count = d ? isk__fx_section_items(d, s) : 0;
    for (int i = 0; i < count; i++)
        if (!strcmp(isk__fx_item_name(d, s, i), name))
            return i;
    return -1;
}

static isk_status parse_refs(const isk_key *k, void *item, const char *text, const isk_effect_def *d, char *why, size_t n)
{
    int *idx = FX_AT(int, item, k->offset);
    int *count = FX_AT(int, item, k->aux);
    const int total = d ? isk__fx_section_items(d, k->refers) : 0;
    const int cap = isk__fx_refs_cap(k->refers);
    static const char *const words[] = {"all", "none"};
    int w = isk__scv_lookup(text, words, 2);
    if (w >= 0 && k->refers == ISK_SECTION_EMITTER) { /* all: the empty list, every emitter */
        if (w == 1) {
            snprintf(why, n, "name one or more emitters, or all");
            return ISK_ERR_RANGE;
        }
        *count = 0;
        return ISK_OK;
    }
    if (w >= 0) {
        int m = w == 0 ? (total < cap ? total : cap) : 0;
        for (int i = 0; i < m; i++)
            idx[i] = i;
        *count = m;
        return ISK_OK;
    }
    char buf[MAX_TEXT];
    char *items[SCV_LIST_MAX];
    int m;
    if (strlen(text) >= sizeof buf || !isk__scv_split(text, buf, sizeof buf, ',', items, SCV_LIST_MAX, &m) ||
        m > cap)
        return isk__fx_expected(k, why, n, text);
    int got[SCV_LIST_MAX];
    for (int j = 0; j < m; j++) {
        int i = find_name(d, k->refers, items[j]);
        if (i < 0)
            return unknown_name(k, d, items[j], why, n);
        for (int q = 0; q < j; q++)
            if (got[q] == i) {
                snprintf(why, n, "'%s' is listed twice", items[j]);
                return ISK_ERR_RANGE;
            }
        got[j] = i;
    }
    memcpy(idx, got, sizeof got[0] * (size_t)m);
    *count = m;
    return ISK_OK;
}

static isk_status parse_ref(const isk_key *k, void *item, const char *text, const isk_effect_def *d, char *why, size_t n)
{
    int *field = FX_AT(int, item, k->offset);
    if (!*text) {
        *field = -1;
        return ISK_OK;
    }
    if (!isk__fx_name_ok(text, ISK_NAME_MAX))
        return isk__fx_expected(k, why, n, text);
    int i = find_name(d, k->refers, text);
    if (i < 0)
        return unknown_name(k, d, text, why, n);
    *field = i;
    return ISK_OK;
}

/* Degrees ("90"), or radians with a suffix ("0.6 rad"): a radian value from
 * a C program then arrives bit for bit, where degrees would be rounded twice. */
static isk_status parse_angle(const isk_key *k, void *item, const char *text, char *why, size_t n)
{
    double *field = FX_AT(double, item, k->offset);
    size_t len = strlen(text);
    double v;
    int w = isk__fx_word_index(k, text); /* spin_end's none */
    if (w >= 0) {
        *field = k->words[w].value;
        return ISK_OK;
    }
    if (len > 3 && !strcmp(text + len - 3, "rad")) {
        char buf[64];
        size_t m = len - 3;
        while (m > 0 && (text[m - 1] == ' ' || text[m - 1] == '\t'))
            m--;
        if (m == 0 || m >= sizeof buf)
            return isk__fx_expected(k, why, n, text);
        memcpy(buf, text, m);
        buf[m] = 0;
        isk_key r = *k;
        r.min = k->min * (PI / 180.0);
        r.max = k->max * (PI / 180.0);
        if (!isk__scv_number(buf, &v) || !isk__fx_in_range(&r, v))
            return isk__fx_expected(k, why, n, text);
        *field = v;
        return ISK_OK;
    }
    if (!isk__scv_number(text, &v) || !isk__fx_in_range(k, v))
        return isk__fx_expected(k, why, n, text);
    *field = v * (PI / 180.0);
    return ISK_OK;
}

/* Whether the key's default is empty and documented as "none": that word,
 * the documented default written out, then reads as the default. */
static int none_is_default(const isk_key *k)
{
    return k->dflt && !*k->dflt && k->dflt_doc && !strcmp(k->dflt_doc, "none");
}

isk_status isk__fx_key_parse(const isk_key *k, void *item, const char *text, const isk_effect_def *d, char *why, size_t n)
{
    double x = 0, q[4];
    int i;
    if (none_is_default(k) && !strcmp(text, "none"))
        text = k->dflt;
    switch (k->type) {
    case ISK_KEY_NUMBER: {
        int w = isk__fx_word_index(k, text);
        if (w >= 0) {
            *FX_AT(double, item, k->offset) = k->words[w].value;
            return ISK_OK;
        }
        if (!isk__scv_number(text, &x) || !isk__fx_in_range(k, x))
            return isk__fx_expected(k, why, n, text);
        *FX_AT(double, item, k->offset) = x;
        return ISK_OK;
    }
    case ISK_KEY_WHOLE:
    case ISK_KEY_LONG:
    case ISK_KEY_COUNT:
        if (parse_whole(k, text, &x, why, n))
            return ISK_ERR_RANGE;
        isk__fx_whole_set(k, item, x);
        return ISK_OK;
    case ISK_KEY_SEED:
        return isk__scv_u64(text, FX_AT(uint64_t, item, k->offset)) ? ISK_OK : isk__fx_expected(k, why, n, text);
    case ISK_KEY_BOOL:
        return isk__scv_bool(text, FX_AT(int, item, k->offset)) ? ISK_OK : isk__fx_expected(k, why, n, text);
    case ISK_KEY_COLOR:
        if (!isk__scv_color(text, FX_AT(isk_color, item, k->offset))) {
            const char *names[64];
            int m = isk__scv_color_count < 64 ? isk__scv_color_count : 64;
            for (int j = 0; j < m; j++)
                names[j] = isk__scv_color_name_at(j);
            return isk__fx_expected_or_guess(k, text, names, text[0] != '#' ? m : 0, why, n);
        }
        return ISK_OK;
    case ISK_KEY_ENUM: {
        int w = isk__fx_word_index(k, text);
        if (w >= 0) {
            *FX_AT(int, item, k->offset) = (int)k->words[w].value;
            return ISK_OK;
        }
        i = isk__scv_lookup(text, k->names, k->nnames);
        if (i < 0)
            return isk__fx_expected_or_guess(k, text, k->names, k->nnames, why, n);
        *FX_AT(int, item, k->offset) = i;
        return ISK_OK;
    }
    case ISK_KEY_VECTOR:
        if (parse_numbers(k, text, 2, q, why, n))
            return ISK_ERR_RANGE;
        memcpy(FX_AT(double, item, k->offset), q, 2 * sizeof q[0]);
        return ISK_OK;
    case ISK_KEY_POINT: {
        static const char *const none[] = {"none", "off"};
        if (isk__scv_lookup(text, none, 2) >= 0) {
            *FX_AT(int, item, k->aux) = 0;
            return ISK_OK;
        }
        if (parse_numbers(k, text, 2, q, why, n))
            return ISK_ERR_RANGE;
        memcpy(FX_AT(double, item, k->offset), q, 2 * sizeof q[0]);
        *FX_AT(int, item, k->aux) = 1;
        return ISK_OK;
    }
    case ISK_KEY_ANGLE: return parse_angle(k, item, text, why, n);
    case ISK_KEY_PAIR:
        if (parse_numbers(k, text, 2, q, why, n))
            return ISK_ERR_RANGE;
        if (q[0] > q[1]) {
            snprintf(why, n, "min (%.15g) is greater than max (%.15g)", q[0], q[1]);
            return ISK_ERR_RANGE;
        }
        memcpy(FX_AT(double, item, k->offset), q, 2 * sizeof q[0]);
        return ISK_OK;
    case ISK_KEY_NUMBERS4:
        if (parse_numbers(k, text, 4, q, why, n))
            return ISK_ERR_RANGE;
        memcpy(FX_AT(double, item, k->offset), q, 4 * sizeof q[0]);
        return ISK_OK;
    case ISK_KEY_COLOR_STOPS:
    case ISK_KEY_SCALAR_STOPS: return parse_stops(k, item, text, why, n);
    case ISK_KEY_TEXT: {
        size_t len = strlen(text);
        if (len >= k->aux) {
            snprintf(why, n, "text longer than %zu characters", k->aux - 1);
            return ISK_ERR_RANGE;
        }
        memcpy(FX_AT(char, item, k->offset), text, len + 1);
        return ISK_OK;
    }
    case ISK_KEY_SIDES: return parse_sides(k, item, text, why, n);
    case ISK_KEY_POINTS: return parse_points(k, item, text, why, n);
    case ISK_KEY_REFS: return parse_refs(k, item, text, d, why, n);
    case ISK_KEY_REF: return parse_ref(k, item, text, d, why, n);
    default: snprintf(why, n, "unknown key type"); return ISK_ERR_RANGE;
    }
}
