/* A key's value as text and as a field (see key_value.h): parse, check and
 * format, by the row's type. */
#include "key_value.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/ini_read.h"
#include "scene/scene_values.h"

#define PI 3.14159265358979323846
#define MAX_TEXT (ISK_INI_MAX_LINE + 1)

/* ---- items ------------------------------------------------------------------- */

int fx_section_items(const isk_effect_def *d, isk_section_kind s)
{
    switch (s) {
    case ISK_SECTION_FORCE: return d->nforces;
    case ISK_SECTION_DEFLECTOR: return d->ndeflectors;
    case ISK_SECTION_EMITTER: return d->nemitters;
    case ISK_SECTION_DRAWING: return d->ndrawings;
    default: return 1;
    }
}

void *fx_section_item(isk_effect_def *d, isk_section_kind s, int i)
{
    if (i < 0 || i >= fx_section_items(d, s))
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
    default: return NULL;
    }
}

const void *fx_section_item_c(const isk_effect_def *d, isk_section_kind s, int i)
{
    return fx_section_item((isk_effect_def *)d, s, i);
}

const char *fx_item_name(const isk_effect_def *d, isk_section_kind s, int i)
{
    if (i < 0 || i >= fx_section_items(d, s))
        return "";
    switch (s) {
    case ISK_SECTION_FORCE: return d->forces[i].name;
    case ISK_SECTION_DEFLECTOR: return d->deflectors[i].name;
    case ISK_SECTION_EMITTER: return d->emitters[i].name;
    case ISK_SECTION_DRAWING: return d->drawings[i].name;
    default: return "";
    }
}

int fx_item_line(const isk_effect_def *d, isk_section_kind s, int i)
{
    if (i < 0 || i >= fx_section_items(d, s))
        return 0;
    switch (s) {
    case ISK_SECTION_FORCE: return d->forces[i].line;
    case ISK_SECTION_DEFLECTOR: return d->deflectors[i].line;
    case ISK_SECTION_EMITTER: return d->emitters[i].line;
    case ISK_SECTION_DRAWING: return d->drawings[i].line;
    default: return 0;
    }
}

int fx_item_kind(const isk_effect_def *d, isk_section_kind s, int i)
{
    if (i < 0 || i >= fx_section_items(d, s))
        return -1;
    switch (s) {
    case ISK_SECTION_VIEW: return (int)d->view_kind;
    case ISK_SECTION_FORCE: return (int)d->forces[i].kind;
    case ISK_SECTION_BOUNDS: return (int)d->bounds.mode;
    case ISK_SECTION_EMITTER: return (int)d->emitters[i].source;
    case ISK_SECTION_DRAWING: return (int)d->drawings[i].kind;
    default: return -1;
    }
}

int fx_key_applies(const isk_key *k, int kind)
{
    return kind < 0 || k->applies == 0 || (kind < 32 && (k->applies >> kind & 1u));
}

/* "gravity", "drag or wind" */
static void join_kinds(char *buf, size_t n, const char *const *names, int count, unsigned mask)
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

void fx_key_kind_message(const isk_key *k, int kind, char *buf, size_t n)
{
    int count;
    const char *const *names = isk_section_kind_names(k->section, &count);
    const char *word = isk_section_kind_key(k->section);
    static const char *const nouns[ISK_SECTION_COUNT] = {
        [ISK_SECTION_VIEW] = "[view]",       [ISK_SECTION_FORCE] = "force",     [ISK_SECTION_BOUNDS] = "[bounds]",
        [ISK_SECTION_EMITTER] = "emitter",   [ISK_SECTION_DRAWING] = "drawing",
    };
    if (!names || !word) {
        snprintf(buf, n, "does not apply here");
        return;
    }
    if (!*word)
        word = "kind";
    char list[160];
    join_kinds(list, sizeof list, names, count, k->applies);
    snprintf(buf, n, "only for %s = %s (this %s has %s = %s)", word, list, nouns[k->section], word,
             kind >= 0 && kind < count ? names[kind] : "?");
}

/* ---- field access (the fields' types differ; a row says which) ---------------- */

#define AT(T, item, off) ((T *)(void *)((char *)(item) + (off)))
#define AT_C(T, item, off) ((const T *)(const void *)((const char *)(item) + (off)))

/* Enum fields: every enum the table uses is int-sized (checked below). */
_Static_assert(sizeof(isk_integrator) == sizeof(int) && sizeof(isk_blend) == sizeof(int) &&
                   sizeof(isk_force_kind) == sizeof(int) && sizeof(isk_source_kind) == sizeof(int),
               "enum fields are read as int");

/* Whole-number fields come in three types; a row says which. */
static double whole_get(const isk_key *k, const void *item)
{
    switch (k->type) {
    case ISK_KEY_WHOLE: return (double)*AT_C(int, item, k->offset);
    case ISK_KEY_LONG: return (double)*AT_C(long, item, k->offset);
    default: return (double)*AT_C(size_t, item, k->offset);
    }
}

static void whole_set(const isk_key *k, void *item, double v)
{
    switch (k->type) {
    case ISK_KEY_WHOLE: *AT(int, item, k->offset) = (int)v; break;
    case ISK_KEY_LONG: *AT(long, item, k->offset) = (long)v; break;
    default: *AT(size_t, item, k->offset) = (size_t)v; break;
    }
}

/* ---- expectations and ranges (one wording for the parser and the check) ------- */

static void range_words(const isk_key *k, const char *what, char *buf, size_t n)
{
    const char *op_lo = k->lo_bound == ISK_BOUND_INCL ? ">=" : ">";
    const char *op_hi = k->hi_bound == ISK_BOUND_INCL ? "<=" : "<";
    if (k->lo_bound == ISK_BOUND_INCL && k->hi_bound == ISK_BOUND_INCL)
        snprintf(buf, n, "%s between %.15g and %.15g", what, k->min, k->max);
    else if (k->lo_bound && k->hi_bound)
        snprintf(buf, n, "%s %s %.15g and %s %.15g", what, op_lo, k->min, op_hi, k->max);
    else if (k->lo_bound)
        snprintf(buf, n, "%s %s %.15g", what, op_lo, k->min);
    else if (k->hi_bound)
        snprintf(buf, n, "%s %s %.15g", what, op_hi, k->max);
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

void fx_key_expect(const isk_key *k, char *buf, size_t n)
{
    switch (k->type) {
    case ISK_KEY_NUMBER:
        range_words(k, k->what ? k->what : "a number", buf, n);
        append_word(k, buf, n);
        return;
    case ISK_KEY_WHOLE:
    case ISK_KEY_LONG:
    case ISK_KEY_COUNT:
        range_words(k, k->what ? k->what : "a whole number", buf, n);
        append_word(k, buf, n);
        return;
    case ISK_KEY_SEED: snprintf(buf, n, "a whole number between 0 and 18446744073709551615"); return;
    case ISK_KEY_BOOL: snprintf(buf, n, "true or false (also yes/no, on/off, 1/0)"); return;
    case ISK_KEY_COLOR: snprintf(buf, n, "a colour (#rrggbb, #rrggbbaa or a name such as yellow)"); return;
    case ISK_KEY_ENUM: {
        const char *all[64];
        int m = isk_key_choices(k, all, 64);
        join_kinds(buf, n, all, m, m >= 32 ? ~0u : (1u << m) - 1u);
        return;
    }
    case ISK_KEY_VECTOR: snprintf(buf, n, "2 numbers \"%s\"", k->what ? k->what : "x, y"); return;
    case ISK_KEY_POINT: snprintf(buf, n, "2 numbers \"x, y\" or none"); return;
    case ISK_KEY_ANGLE: range_words(k, "an angle in degrees (or \"N rad\")", buf, n); return;
    case ISK_KEY_PAIR: snprintf(buf, n, "2 numbers \"%s\"", k->what ? k->what : "min, max"); return;
    case ISK_KEY_NUMBERS4: snprintf(buf, n, "4 numbers \"%s\"", k->what ? k->what : "a, b, c, d"); return;
    case ISK_KEY_COLOR_STOPS: snprintf(buf, n, "stops \"t:colour, t:colour, ...\" or off"); return;
    case ISK_KEY_SCALAR_STOPS: snprintf(buf, n, "stops \"t:value, t:value, ...\" or off"); return;
    case ISK_KEY_TEXT: snprintf(buf, n, "text of at most %zu characters", k->aux - 1); return;
    case ISK_KEY_SIDES: snprintf(buf, n, "sides \"top, right, bottom, left\" (any of them), all or none"); return;
    case ISK_KEY_POINTS:
        snprintf(buf, n, "%.15g to %.15g points \"x0, y0, x1, y1, ...\" (an even count of numbers)", k->min, k->max);
        return;
    case ISK_KEY_REFS: snprintf(buf, n, "%s names separated by commas (or all, none)", isk_section_name(k->refers)); return;
    case ISK_KEY_REF: snprintf(buf, n, "an %s name", isk_section_name(k->refers)); return;
    default: snprintf(buf, n, "a value"); return;
    }
}

static int in_range(const isk_key *k, double v)
{
    if (k->lo_bound == ISK_BOUND_INCL && !(v >= k->min)) return 0;
    if (k->lo_bound == ISK_BOUND_EXCL && !(v > k->min)) return 0;
    if (k->hi_bound == ISK_BOUND_INCL && !(v <= k->max)) return 0;
    if (k->hi_bound == ISK_BOUND_EXCL && !(v < k->max)) return 0;
    return 1;
}

static isk_status expected(const isk_key *k, char *why, size_t n, const char *got)
{
    char want[200];
    fx_key_expect(k, want, sizeof want);
    snprintf(why, n, "expected %s, got \"%s\"", want, got);
    return ISK_ERR_RANGE;
}

/* "expected ..., got "x"; did you mean "y"?" (a suggestion from names). */
static isk_status expected_or_guess(const isk_key *k, const char *text, const char *const *names, int count,
                                    char *why, size_t n)
{
    const char *s = count ? scv_suggest(text, names, count) : NULL;
    char want[200];
    fx_key_expect(k, want, sizeof want);
    snprintf(why, n, "expected %s, got \"%s\"%s%s%s", want, text, s ? "; did you mean \"" : "", s ? s : "",
             s ? "\"?" : "");
    return ISK_ERR_RANGE;
}

const char *fx_key_suggest(isk_section_kind section, const char *word)
{
    const char *names[128];
    int n = 0;
    for (int i = 0; i < isk_key_count() && n < 128; i++)
        if (isk_key_at(i)->section == section)
            names[n++] = isk_key_at(i)->name;
    return scv_suggest(word, names, n);
}

/* A word standing for a value: its index, or -1. */
static int word_index(const isk_key *k, const char *s)
{
    for (int i = 0; k->words && k->words[i].word; i++)
        if (scv_lookup(s, &k->words[i].word, 1) == 0)
            return i;
    return -1;
}

/* The word whose value v is, or NULL (exact comparison; INFINITY too). */
static const char *word_of(const isk_key *k, double v)
{
    for (int i = 0; k->words && k->words[i].word; i++)
        if (k->words[i].value == v)
            return k->words[i].word;
    return NULL;
}

/* ---- parse -------------------------------------------------------------------- */

/* Exactly `count` comma-separated numbers, each within the row's range. */
static isk_status parse_numbers(const isk_key *k, const char *text, int count, double *out, char *why, size_t n)
{
    char buf[MAX_TEXT], want[160];
    char *items[SCV_LIST_MAX];
    int got;
    fx_key_expect(k, want, sizeof want);
    if (strlen(text) >= sizeof buf || !scv_split(text, buf, sizeof buf, ',', items, SCV_LIST_MAX, &got) ||
        got != count) {
        snprintf(why, n, "expected %s, got \"%s\"", want, text);
        return ISK_ERR_RANGE;
    }
    for (int i = 0; i < count; i++)
        if (!scv_number(items[i], &out[i]) || !in_range(k, out[i])) {
            char w2[120];
            range_words(k, "a number", w2, sizeof w2);
            snprintf(why, n, "expected %s: item %d is not %s: \"%s\"", want, i + 1, w2, items[i]);
            return ISK_ERR_RANGE;
        }
    return ISK_OK;
}

static isk_status parse_whole(const isk_key *k, const char *text, double *out, char *why, size_t n)
{
    int w = word_index(k, text);
    if (w >= 0) {
        *out = k->words[w].value;
        return ISK_OK;
    }
    double x = 0;
    if (!scv_number(text, &x) || x != floor(x) || !in_range(k, x))
        return expected(k, why, n, text);
    *out = x;
    return ISK_OK;
}

static isk_status parse_stops(const isk_key *k, void *item, const char *text, char *why, size_t n)
{
    const int is_color = k->type == ISK_KEY_COLOR_STOPS;
    isk_color_ramp *cr = AT(isk_color_ramp, item, k->offset);
    isk_scalar_ramp *sr = AT(isk_scalar_ramp, item, k->offset);
    static const char *const off[] = {"off", "none"};
    if (scv_lookup(text, off, 2) >= 0) {
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
    if (strlen(text) >= sizeof buf || !scv_split(text, buf, sizeof buf, ',', items, SCV_LIST_MAX, &count) ||
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
        char *tv = scv_trim(items[i]), *val = scv_trim(colon + 1);
        double t;
        if (!scv_number(tv, &t) || t < 0 || t > 1) {
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
            if (!scv_color(val, &cs[i].color)) {
                snprintf(why, n, "stop %d: expected a colour (#rrggbb, #rrggbbaa or a name), got \"%s\"", i + 1, val);
                return ISK_ERR_RANGE;
            }
        } else {
            ss[i].t = t;
            if (!scv_number(val, &ss[i].value) || !in_range(k, ss[i].value)) {
                char want[120];
                range_words(k, "a number", want, sizeof want);
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
    unsigned *sides = AT(unsigned, item, k->offset);
    int w = scv_lookup(text, words, 2);
    if (w >= 0) {
        *sides = w == 0 ? ISK_SIDE_ALL : 0u;
        return ISK_OK;
    }
    char buf[MAX_TEXT];
    char *items[SCV_LIST_MAX];
    int count;
    if (strlen(text) >= sizeof buf || !scv_split(text, buf, sizeof buf, ',', items, SCV_LIST_MAX, &count) ||
        count == 0)
        return expected(k, why, n, text);
    unsigned mask = 0;
    for (int j = 0; j < count; j++) {
        int sd = scv_lookup(items[j], k->names, k->nnames);
        if (sd < 0) {
            const char *s = scv_suggest(items[j], k->names, k->nnames);
            snprintf(why, n, "expected top, right, bottom or left (or all, none), got \"%s\"%s%s%s", items[j],
                     s ? "; did you mean \"" : "", s ? s : "", s ? "\"?" : "");
            return ISK_ERR_RANGE;
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
    if (strlen(text) >= sizeof buf || !scv_split(text, buf, sizeof buf, ',', items, SCV_LIST_MAX, &count) ||
        count % 2 || count < 2 * (int)k->min || count > 2 * (int)k->max)
        return expected(k, why, n, text);
    double *pts = malloc(sizeof *pts * (size_t)count);
    if (!pts) {
        snprintf(why, n, "out of memory");
        return ISK_ERR_NOMEM;
    }
    for (int j = 0; j < count; j++)
        if (!scv_number(items[j], &pts[j])) {
            free(pts);
            snprintf(why, n, "item %d is not a number: \"%s\"", j + 1, items[j]);
            return ISK_ERR_RANGE;
        }
    double **field = AT(double *, item, k->offset);
    free(*field);
    *field = pts;
    *AT(int, item, k->aux) = count / 2;
    return ISK_OK;
}

static int name_ok(const char *s)
{
    if (!*s || strlen(s) >= ISK_NAME_MAX)
        return 0;
    for (; *s; s++)
        if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || (*s >= '0' && *s <= '9') || *s == '_' ||
              *s == '-' || *s == '.'))
            return 0;
    return 1;
}

/* "no force named 'gravty'; did you mean 'gravity'?" */
static isk_status unknown_name(const isk_key *k, const isk_effect_def *d, const char *name, char *why, size_t n)
{
    const char *sec = isk_section_name(k->refers);
    int count = d ? fx_section_items(d, k->refers) : 0;
    if (count == 0) {
        snprintf(why, n, "no %s named '%s' (the scene defines no [%s NAME] section)", sec, name, sec);
        return ISK_ERR_RANGE;
    }
    const char *names[ISK_EFFECT_MAX_DEFLECTORS];
    for (int i = 0; i < count && i < ISK_EFFECT_MAX_DEFLECTORS; i++)
        names[i] = fx_item_name(d, k->refers, i);
    const char *s = scv_suggest(name, names, count);
    snprintf(why, n, "no %s named '%s'%s%s%s", sec, name, s ? "; did you mean '" : "", s ? s : "", s ? "'?" : "");
    return ISK_ERR_RANGE;
}

static int find_name(const isk_effect_def *d, isk_section_kind s, const char *name)
{
    int count = d ? fx_section_items(d, s) : 0;
    for (int i = 0; i < count; i++)
        if (!strcmp(fx_item_name(d, s, i), name))
            return i;
    return -1;
}

static isk_status parse_refs(const isk_key *k, void *item, const char *text, const isk_effect_def *d, char *why, size_t n)
{
    int *idx = AT(int, item, k->offset);
    int *count = AT(int, item, k->aux);
    const int total = d ? fx_section_items(d, k->refers) : 0;
    const int cap = k->refers == ISK_SECTION_FORCE ? ISK_EFFECT_MAX_FORCES : ISK_EFFECT_MAX_DEFLECTORS;
    static const char *const words[] = {"all", "none"};
    int w = scv_lookup(text, words, 2);
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
    if (strlen(text) >= sizeof buf || !scv_split(text, buf, sizeof buf, ',', items, SCV_LIST_MAX, &m) ||
        m > cap)
        return expected(k, why, n, text);
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
    int *field = AT(int, item, k->offset);
    if (!*text) {
        *field = -1;
        return ISK_OK;
    }
    if (!name_ok(text))
        return expected(k, why, n, text);
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
    double *field = AT(double, item, k->offset);
    size_t len = strlen(text);
    double v;
    if (len > 3 && !strcmp(text + len - 3, "rad")) {
        char buf[64];
        size_t m = len - 3;
        while (m > 0 && (text[m - 1] == ' ' || text[m - 1] == '\t'))
            m--;
        if (m == 0 || m >= sizeof buf)
            return expected(k, why, n, text);
        memcpy(buf, text, m);
        buf[m] = 0;
        isk_key r = *k;
        r.min = k->min * (PI / 180.0);
        r.max = k->max * (PI / 180.0);
        if (!scv_number(buf, &v) || !in_range(&r, v))
            return expected(k, why, n, text);
        *field = v;
        return ISK_OK;
    }
    if (!scv_number(text, &v) || !in_range(k, v))
        return expected(k, why, n, text);
    *field = v * (PI / 180.0);
    return ISK_OK;
}

isk_status fx_key_parse(const isk_key *k, void *item, const char *text, const isk_effect_def *d, char *why, size_t n)
{
    double x = 0, q[4];
    int i;
    switch (k->type) {
    case ISK_KEY_NUMBER: {
        int w = word_index(k, text);
        if (w >= 0) {
            *AT(double, item, k->offset) = k->words[w].value;
            return ISK_OK;
        }
        if (!scv_number(text, &x) || !in_range(k, x))
            return expected(k, why, n, text);
        *AT(double, item, k->offset) = x;
        return ISK_OK;
    }
    case ISK_KEY_WHOLE:
    case ISK_KEY_LONG:
    case ISK_KEY_COUNT:
        if (parse_whole(k, text, &x, why, n))
            return ISK_ERR_RANGE;
        whole_set(k, item, x);
        return ISK_OK;
    case ISK_KEY_SEED:
        return scv_u64(text, AT(uint64_t, item, k->offset)) ? ISK_OK : expected(k, why, n, text);
    case ISK_KEY_BOOL:
        return scv_bool(text, AT(int, item, k->offset)) ? ISK_OK : expected(k, why, n, text);
    case ISK_KEY_COLOR:
        if (!scv_color(text, AT(isk_color, item, k->offset))) {
            const char *names[64];
            int m = scv_color_count < 64 ? scv_color_count : 64;
            for (int j = 0; j < m; j++)
                names[j] = scv_color_name_at(j);
            return expected_or_guess(k, text, names, text[0] != '#' ? m : 0, why, n);
        }
        return ISK_OK;
    case ISK_KEY_ENUM: {
        int w = word_index(k, text);
        if (w >= 0) {
            *AT(int, item, k->offset) = (int)k->words[w].value;
            return ISK_OK;
        }
        i = scv_lookup(text, k->names, k->nnames);
        if (i < 0)
            return expected_or_guess(k, text, k->names, k->nnames, why, n);
        *AT(int, item, k->offset) = i;
        return ISK_OK;
    }
    case ISK_KEY_VECTOR:
        if (parse_numbers(k, text, 2, q, why, n))
            return ISK_ERR_RANGE;
        memcpy(AT(double, item, k->offset), q, 2 * sizeof q[0]);
        return ISK_OK;
    case ISK_KEY_POINT: {
        static const char *const none[] = {"none", "off"};
        if (scv_lookup(text, none, 2) >= 0) {
            *AT(int, item, k->aux) = 0;
            return ISK_OK;
        }
        if (parse_numbers(k, text, 2, q, why, n))
            return ISK_ERR_RANGE;
        memcpy(AT(double, item, k->offset), q, 2 * sizeof q[0]);
        *AT(int, item, k->aux) = 1;
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
        memcpy(AT(double, item, k->offset), q, 2 * sizeof q[0]);
        return ISK_OK;
    case ISK_KEY_NUMBERS4:
        if (parse_numbers(k, text, 4, q, why, n))
            return ISK_ERR_RANGE;
        memcpy(AT(double, item, k->offset), q, 4 * sizeof q[0]);
        return ISK_OK;
    case ISK_KEY_COLOR_STOPS:
    case ISK_KEY_SCALAR_STOPS: return parse_stops(k, item, text, why, n);
    case ISK_KEY_TEXT: {
        size_t len = strlen(text);
        if (len >= k->aux) {
            snprintf(why, n, "text longer than %zu characters", k->aux - 1);
            return ISK_ERR_RANGE;
        }
        memcpy(AT(char, item, k->offset), text, len + 1);
        return ISK_OK;
    }
    case ISK_KEY_SIDES: return parse_sides(k, item, text, why, n);
    case ISK_KEY_POINTS: return parse_points(k, item, text, why, n);
    case ISK_KEY_REFS: return parse_refs(k, item, text, d, why, n);
    case ISK_KEY_REF: return parse_ref(k, item, text, d, why, n);
    default: snprintf(why, n, "unknown key type"); return ISK_ERR_RANGE;
    }
}

/* ---- check -------------------------------------------------------------------- */

static isk_status refused(const isk_key *k, const void *item, const isk_effect_def *d, char *why, size_t n)
{
    char got[MAX_TEXT];
    if (fx_key_format(k, item, d, got, sizeof got) != 0)
        snprintf(got, sizeof got, "?");
    return expected(k, why, n, got);
}

static int numbers_ok(const isk_key *k, const double *v, int count)
{
    for (int i = 0; i < count; i++)
        if (!isfinite(v[i]) || !in_range(k, v[i]))
            return 0;
    return 1;
}

isk_status fx_key_check(const isk_key *k, const void *item, const isk_effect_def *d, char *why, size_t n)
{
    switch (k->type) {
    case ISK_KEY_NUMBER: {
        double v = *AT_C(double, item, k->offset);
        if (word_of(k, v) || (isfinite(v) && in_range(k, v)))
            return ISK_OK;
        return refused(k, item, d, why, n);
    }
    case ISK_KEY_WHOLE:
    case ISK_KEY_LONG:
    case ISK_KEY_COUNT: {
        double v = whole_get(k, item);
        return word_of(k, v) || in_range(k, v) ? ISK_OK : refused(k, item, d, why, n);
    }
    case ISK_KEY_BOOL: {
        int v = *AT_C(int, item, k->offset);
        return v == 0 || v == 1 ? ISK_OK : refused(k, item, d, why, n);
    }
    case ISK_KEY_ENUM: {
        int v = *AT_C(int, item, k->offset);
        return (v >= 0 && v < k->nnames) || word_of(k, v) ? ISK_OK : refused(k, item, d, why, n);
    }
    case ISK_KEY_VECTOR:
    case ISK_KEY_NUMBERS4: {
        const double *v = AT_C(double, item, k->offset);
        return numbers_ok(k, v, k->type == ISK_KEY_VECTOR ? 2 : 4) ? ISK_OK : refused(k, item, d, why, n);
    }
    case ISK_KEY_POINT: {
        int given = *AT_C(int, item, k->aux);
        const double *v = AT_C(double, item, k->offset);
        return given == 0 || (given == 1 && numbers_ok(k, v, 2)) ? ISK_OK : refused(k, item, d, why, n);
    }
    case ISK_KEY_ANGLE: {
        double v = *AT_C(double, item, k->offset);
        isk_key r = *k;
        r.min = k->min * (PI / 180.0);
        r.max = k->max * (PI / 180.0);
        return isfinite(v) && in_range(&r, v) ? ISK_OK : refused(k, item, d, why, n);
    }
    case ISK_KEY_PAIR: {
        const double *v = AT_C(double, item, k->offset);
        if (!numbers_ok(k, v, 2))
            return refused(k, item, d, why, n);
        if (v[0] > v[1]) {
            snprintf(why, n, "min (%.15g) is greater than max (%.15g)", v[0], v[1]);
            return ISK_ERR_RANGE;
        }
        return ISK_OK;
    }
    case ISK_KEY_COLOR_STOPS: {
        const isk_color_ramp *r = AT_C(isk_color_ramp, item, k->offset);
        if (r->n == 0 || (r->n > 0 && r->n <= ISK_GRADIENT_MAX_STOPS && isk_color_stops_check(r->stops, r->n) == ISK_OK))
            return ISK_OK;
        snprintf(why, n, "1..%d stops with t strictly increasing in [0, 1] expected", ISK_GRADIENT_MAX_STOPS);
        return ISK_ERR_RANGE;
    }
    case ISK_KEY_SCALAR_STOPS: {
        const isk_scalar_ramp *r = AT_C(isk_scalar_ramp, item, k->offset);
        if (r->n == 0)
            return ISK_OK;
        if (r->n < 0 || r->n > ISK_GRADIENT_MAX_STOPS || isk_scalar_stops_check(r->stops, r->n) != ISK_OK) {
            snprintf(why, n, "1..%d finite stops with t strictly increasing in [0, 1] expected",
                     ISK_GRADIENT_MAX_STOPS);
            return ISK_ERR_RANGE;
        }
        for (int i = 0; i < r->n; i++)
            if (!in_range(k, r->stops[i].value)) {
                char want[120];
                range_words(k, "a number", want, sizeof want);
                snprintf(why, n, "stop %d: expected %s, got \"%.17g\"", i + 1, want, r->stops[i].value);
                return ISK_ERR_RANGE;
            }
        return ISK_OK;
    }
    case ISK_KEY_TEXT:
        if (memchr(AT_C(char, item, k->offset), 0, k->aux))
            return ISK_OK;
        snprintf(why, n, "text longer than %zu characters (or not terminated)", k->aux - 1);
        return ISK_ERR_RANGE;
    case ISK_KEY_SIDES:
        return *AT_C(unsigned, item, k->offset) & ~(unsigned)ISK_SIDE_ALL ? refused(k, item, d, why, n) : ISK_OK;
    case ISK_KEY_POINTS: {
        const double *pts = *AT_C(double *, item, k->offset);
        int count = *AT_C(int, item, k->aux);
        if (count == 0 && !pts)
            return ISK_OK; /* whether points are needed is the section's check */
        if (!pts || count < (int)k->min || count > 100000) {
            snprintf(why, n, "expected %.15g to 100000 points (and the array), got %d", k->min, count);
            return ISK_ERR_RANGE;
        }
        for (int i = 0; i < 2 * count; i++)
            if (!isfinite(pts[i])) {
                snprintf(why, n, "points must be finite (item %d is %.17g)", i + 1, pts[i]);
                return ISK_ERR_RANGE;
            }
        return ISK_OK;
    }
    case ISK_KEY_REFS: {
        const int *idx = AT_C(int, item, k->offset);
        int count = *AT_C(int, item, k->aux);
        const int cap = k->refers == ISK_SECTION_FORCE ? ISK_EFFECT_MAX_FORCES : ISK_EFFECT_MAX_DEFLECTORS;
        int total = d ? fx_section_items(d, k->refers) : 0;
        if (count < 0 || count > cap) {
            snprintf(why, n, "0..%d references expected, got %d", cap, count);
            return ISK_ERR_RANGE;
        }
        for (int i = 0; i < count; i++) {
            if (idx[i] < 0 || idx[i] >= total) {
                snprintf(why, n, "%s reference %d does not exist", isk_section_name(k->refers), idx[i]);
                return ISK_ERR_RANGE;
            }
            for (int j = 0; j < i; j++)
                if (idx[j] == idx[i]) {
                    snprintf(why, n, "'%s' is listed twice", fx_item_name(d, k->refers, idx[i]));
                    return ISK_ERR_RANGE;
                }
        }
        return ISK_OK;
    }
    case ISK_KEY_REF: {
        int v = *AT_C(int, item, k->offset);
        int total = d ? fx_section_items(d, k->refers) : 0;
        if (v >= -1 && v < total)
            return ISK_OK;
        snprintf(why, n, "%s %d does not exist", isk_section_name(k->refers), v);
        return ISK_ERR_RANGE;
    }
    default:
        return ISK_OK; /* SEED, COLOR: every value is valid */
    }
}

/* ---- format ------------------------------------------------------------------- */

static isk_status put(char *buf, size_t n, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#include <stdarg.h>

static isk_status put(char *buf, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int r = vsnprintf(buf, n, fmt, ap);
    va_end(ap);
    return r >= 0 && (size_t)r < n ? ISK_OK : ISK_ERR_SIZE;
}

/* Shortest decimal that reads back to the same double, without an
 * exponent where plain digits are as readable ("90", not "9e+01"). */
static void num(char *buf, size_t n, double v)
{
    const double a = fabs(v);
    const int plain = a >= 1e-5 && a < 1e16;
    for (int p = 1; p <= 17; p++) {
        snprintf(buf, n, "%.*g", p, v);
        if (plain && p < 17 && strchr(buf, 'e'))
            continue;
        if (strtod(buf, NULL) == v)
            return;
    }
}

static isk_status colour_text(char *buf, size_t n, isk_color c)
{
    const char *name = scv_color_name(c);
    if (name)
        return put(buf, n, "%s", name);
    if (c.a == 255)
        return put(buf, n, "#%02x%02x%02x", c.r, c.g, c.b);
    return put(buf, n, "#%02x%02x%02x%02x", c.r, c.g, c.b, c.a);
}

static isk_status numbers_text(char *buf, size_t n, const double *v, int count)
{
    size_t used = 0;
    buf[0] = 0;
    for (int i = 0; i < count; i++) {
        char t[40];
        num(t, sizeof t, v[i]);
        int r = snprintf(buf + used, n - used, "%s%s", i ? ", " : "", t);
        if (r < 0 || (size_t)r >= n - used)
            return ISK_ERR_RANGE;
        used += (size_t)r;
    }
    return ISK_OK;
}

isk_status fx_key_format(const isk_key *k, const void *item, const isk_effect_def *d, char *buf, size_t n)
{
    char t[40];
    if (n == 0)
        return ISK_ERR_RANGE;
    switch (k->type) {
    case ISK_KEY_NUMBER: {
        double v = *AT_C(double, item, k->offset);
        const char *w = word_of(k, v);
        if (w)
            return put(buf, n, "%s", w);
        num(t, sizeof t, v);
        return put(buf, n, "%s", t);
    }
    case ISK_KEY_WHOLE:
    case ISK_KEY_LONG:
    case ISK_KEY_COUNT: {
        double v = whole_get(k, item); /* exact: every accepted value is below 2^53 */
        const char *w = word_of(k, v);
        return w ? put(buf, n, "%s", w) : put(buf, n, "%.0f", v);
    }
    case ISK_KEY_SEED: return put(buf, n, "%llu", (unsigned long long)*AT_C(uint64_t, item, k->offset));
    case ISK_KEY_BOOL: return put(buf, n, "%s", *AT_C(int, item, k->offset) ? "true" : "false");
    case ISK_KEY_COLOR: return colour_text(buf, n, *AT_C(isk_color, item, k->offset));
    case ISK_KEY_ENUM: {
        int v = *AT_C(int, item, k->offset);
        const char *w = word_of(k, v);
        if (w)
            return put(buf, n, "%s", w);
        return put(buf, n, "%s", v >= 0 && v < k->nnames ? k->names[v] : "?");
    }
    case ISK_KEY_VECTOR:
    case ISK_KEY_PAIR: return numbers_text(buf, n, AT_C(double, item, k->offset), 2);
    case ISK_KEY_NUMBERS4: return numbers_text(buf, n, AT_C(double, item, k->offset), 4);
    case ISK_KEY_POINT:
        if (!*AT_C(int, item, k->aux))
            return put(buf, n, "none");
        return numbers_text(buf, n, AT_C(double, item, k->offset), 2);
    case ISK_KEY_ANGLE: {
        /* Degrees when they read back to the same radians, else radians. */
        double r = *AT_C(double, item, k->offset);
        double deg = r * (180.0 / PI);
        char dt[40];
        num(dt, sizeof dt, deg);
        if (strtod(dt, NULL) * (PI / 180.0) == r)
            return put(buf, n, "%s", dt);
        num(t, sizeof t, r);
        return put(buf, n, "%s rad", t);
    }
    case ISK_KEY_COLOR_STOPS:
    case ISK_KEY_SCALAR_STOPS: {
        const int is_color = k->type == ISK_KEY_COLOR_STOPS;
        const isk_color_ramp *cr = AT_C(isk_color_ramp, item, k->offset);
        const isk_scalar_ramp *sr = AT_C(isk_scalar_ramp, item, k->offset);
        int count = is_color ? cr->n : sr->n;
        if (count <= 0)
            return put(buf, n, "off");
        size_t used = 0;
        for (int i = 0; i < count && i < ISK_GRADIENT_MAX_STOPS; i++) {
            char tv[40], val[40];
            num(tv, sizeof tv, is_color ? cr->stops[i].t : sr->stops[i].t);
            if (is_color) {
                if (colour_text(val, sizeof val, cr->stops[i].color))
                    return ISK_ERR_SIZE;
            } else {
                num(val, sizeof val, sr->stops[i].value);
            }
            if (put(buf + used, n - used, "%s%s:%s", i ? ", " : "", tv, val))
                return ISK_ERR_RANGE;
            used += strlen(buf + used);
        }
        return ISK_OK;
    }
    case ISK_KEY_TEXT: return put(buf, n, "%.*s", (int)k->aux, AT_C(char, item, k->offset));
    case ISK_KEY_SIDES: {
        unsigned s = *AT_C(unsigned, item, k->offset);
        if (s == 0)
            return put(buf, n, "none");
        if (s == ISK_SIDE_ALL)
            return put(buf, n, "all");
        size_t used = 0;
        buf[0] = 0;
        for (int i = 0; i < k->nnames; i++)
            if (s >> i & 1u) {
                if (put(buf + used, n - used, "%s%s", used ? ", " : "", k->names[i]))
                    return ISK_ERR_RANGE;
                used += strlen(buf + used);
            }
        return ISK_OK;
    }
    case ISK_KEY_POINTS: {
        const double *pts = *AT_C(double *, item, k->offset);
        int count = *AT_C(int, item, k->aux);
        if (!pts || count <= 0)
            return put(buf, n, "%s", "");
        return numbers_text(buf, n, pts, 2 * count);
    }
    case ISK_KEY_REFS: {
        const int *idx = AT_C(int, item, k->offset);
        int count = *AT_C(int, item, k->aux);
        if (count <= 0)
            return put(buf, n, "none");
        size_t used = 0;
        for (int i = 0; i < count; i++) {
            if (put(buf + used, n - used, "%s%s", i ? ", " : "", d ? fx_item_name(d, k->refers, idx[i]) : "?"))
                return ISK_ERR_RANGE;
            used += strlen(buf + used);
        }
        return ISK_OK;
    }
    case ISK_KEY_REF: {
        int v = *AT_C(int, item, k->offset);
        return put(buf, n, "%s", v >= 0 && d ? fx_item_name(d, k->refers, v) : "");
    }
    default: return ISK_ERR_RANGE;
    }
}

/* ---- defaults ------------------------------------------------------------------ */

isk_status fx_key_set_default(const isk_key *k, void *item)
{
    /* An empty default means "none" except for a reference, where it is the
     * first item (-1). */
    if (!k->dflt || (!*k->dflt && k->type != ISK_KEY_REF) || k->type == ISK_KEY_REFS || k->type == ISK_KEY_POINTS)
        return ISK_OK;
    char why[160];
    return fx_key_parse(k, item, k->dflt, NULL, why, sizeof why);
}

void fx_section_defaults(isk_section_kind s, void *item)
{
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        if (k->section == s)
            fx_key_set_default(k, item);
    }
}
