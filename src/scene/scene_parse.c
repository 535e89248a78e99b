/* Scene files -> isk_effect_def (see iskra/scene.h, docs/scene-format.md).
 *
 * How a file is read:
 *   1. Leading blanks of every line are removed (so indented keys are just
 *      keys: libinih would otherwise take an indented line as a continuation
 *      of the previous value) and every line is pre-scanned: section headers
 *      are recorded with their line numbers (libinih does not report headers,
 *      nor sections without keys, and truncates long section names), and the
 *      first syntax error (over-long line, header without ']', text after
 *      ']', a line that is neither a header, a comment nor key = value) ends
 *      the text handed to libinih, so errors are always reported in file
 *      order.
 *   2. libinih calls on_key() for every key; before handling a key on line L
 *      every header above L is "opened": validated (known type, name rules,
 *      no duplicate) and its item is appended to the definition.  The value
 *      is parsed and stored at once; the line of every key is remembered.
 *   3. At the end: the remaining headers are opened, then per section the
 *      checks that need the whole section (a key that does not apply to the
 *      section's kind, required keys, min < max pairs, potential laws, bounds
 *      window defaulting to the view), then references (forces, deflectors,
 *      the click's emitter) are resolved, so forward references work.
 * The first error stops everything; the definition is then emptied.
 */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/scene.h"
#include "scene/ini_read.h"
#include "scene_keys.h"
#include "scene_values.h"

#define PI 3.14159265358979323846
#define MAX_SECTIONS (ISK_EFFECT_MAX_FORCES + ISK_EFFECT_MAX_DEFLECTORS + ISK_EFFECT_MAX_EMITTERS + \
                      ISK_EFFECT_MAX_DRAWINGS + 4)
#define MAX_SUBSTEPS 1000
#define MAX_FRAMES 100000000
#define MAX_POLYLINE_POINTS 64

typedef struct header {
    int line;
    const char *text; /* between '[' and ']' (not terminated) */
    size_t len;
} header;

typedef struct section {
    sk_section type;
    char name[ISK_NAME_MAX];
    int line;
    int index;               /* item index in the definition (-1: none) */
    uint64_t seen;           /* key ids set in this section */
    int key_line[64];
    char forces_ref[ISK_INI_MAX_LINE + 1];   /* emitter: the raw lists */
    char defl_ref[ISK_INI_MAX_LINE + 1];
    char emitter_ref[ISK_NAME_MAX];          /* click */
    double exponent;         /* force: exponent as written */
    int law;
} section;

typedef struct parser {
    isk_effect_def *d;
    const char *name;
    isk_error *err;
    header *hdr;
    int nhdr, next_hdr;
    section *sec;
    int nsec, cur;
    int syntax_line;         /* first syntax error found by the pre-scan, 0 if none */
    char syntax_msg[160];
} parser;

/* ---- messages ------------------------------------------------------------ */

static void sec_label(const section *s, char *buf, size_t n)
{
    if (s->name[0])
        snprintf(buf, n, "[%s %s]", sk_tables[s->type].name, s->name);
    else
        snprintf(buf, n, "[%s]", sk_tables[s->type].name);
}

/* "FILE:LINE: [section] key: message" */
static int key_fail(parser *P, int line, const char *key, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
static int key_fail(parser *P, int line, const char *key, const char *fmt, ...)
{
    char msg[320], label[80];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    sec_label(&P->sec[P->cur], label, sizeof label);
    if (key)
        return isk_ini_error(P->err, P->name, line, "%s %s: %s", label, key, msg);
    return isk_ini_error(P->err, P->name, line, "%s %s", label, msg);
}

/* isk_ini_suggest, plus one swap of adjacent letters ("widht" -> "width"),
 * the commonest typo, which plain edit distance counts as two. */
static const char *suggest(const char *word, const char *const *names, int count)
{
    const char *s = isk_ini_suggest(word, names, (size_t)count);
    if (s)
        return s;
    size_t n = strlen(word);
    for (int i = 0; i < count; i++) {
        if (strlen(names[i]) != n)
            continue;
        size_t a = 0;
        while (a < n && word[a] == names[i][a])
            a++;
        if (a + 1 < n && word[a] == names[i][a + 1] && word[a + 1] == names[i][a] &&
            !strcmp(word + a + 2, names[i] + a + 2))
            return names[i];
    }
    return NULL;
}

/* Appends "; did you mean 'x'?" when a candidate is close. */
static void suggest_names(char *buf, size_t n, const char *word, const char *const *names, int count,
                          const char *quote_l, const char *quote_r)
{
    const char *s = suggest(word, names, count);
    if (s)
        snprintf(buf, n, "; did you mean %s%s%s?", quote_l, s, quote_r);
    else
        buf[0] = 0;
}

static int count_names(const char *const *names)
{
    int n = 0;
    while (names[n])
        n++;
    return n;
}

/* "ring, uniform, gauss or coulomb" */
static void join_names(char *buf, size_t n, const char *const *names, unsigned mask)
{
    buf[0] = 0;
    int total = 0, k = 0;
    for (int i = 0; names[i]; i++)
        if (!mask || (mask >> i & 1u))
            total++;
    for (int i = 0; names[i]; i++) {
        if (mask && !(mask >> i & 1u))
            continue;
        size_t len = strlen(buf);
        snprintf(buf + len, n - len, "%s%s", k == 0 ? "" : (k == total - 1 ? " or " : ", "), names[i]);
        k++;
    }
}

/* ---- value getters (0 ok, 1 failed with the message set) ------------------- */

enum { B_NONE = 0, B_INC, B_EXC };
typedef struct range {
    int lo_kind, hi_kind;
    double lo, hi;
} range;
#define R_ANY ((range){B_NONE, B_NONE, 0, 0})
#define R_GE(a) ((range){B_INC, B_NONE, (a), 0})
#define R_GT(a) ((range){B_EXC, B_NONE, (a), 0})
#define R_IN(a, b) ((range){B_INC, B_INC, (a), (b)})
#define R_GT_LE(a, b) ((range){B_EXC, B_INC, (a), (b)})

static void range_text(char *buf, size_t n, const char *what, range r)
{
    if (r.lo_kind == B_INC && r.hi_kind == B_INC)
        snprintf(buf, n, "%s between %.15g and %.15g", what, r.lo, r.hi);
    else if (r.lo_kind && r.hi_kind)
        snprintf(buf, n, "%s %s %.15g and %s %.15g", what, r.lo_kind == B_INC ? ">=" : ">", r.lo,
                 r.hi_kind == B_INC ? "<=" : "<", r.hi);
    else if (r.lo_kind)
        snprintf(buf, n, "%s %s %.15g", what, r.lo_kind == B_INC ? ">=" : ">", r.lo);
    else if (r.hi_kind)
        snprintf(buf, n, "%s %s %.15g", what, r.hi_kind == B_INC ? "<=" : "<", r.hi);
    else
        snprintf(buf, n, "%s", what);
}

static int in_range(double v, range r)
{
    if (r.lo_kind == B_INC && !(v >= r.lo)) return 0;
    if (r.lo_kind == B_EXC && !(v > r.lo)) return 0;
    if (r.hi_kind == B_INC && !(v <= r.hi)) return 0;
    if (r.hi_kind == B_EXC && !(v < r.hi)) return 0;
    return 1;
}

static int get_real(parser *P, int line, const char *key, const char *v, range r, double *out)
{
    double x = 0;
    if (!scv_number(v, &x) || !in_range(x, r)) {
        char want[120];
        range_text(want, sizeof want, "a number", r);
        return key_fail(P, line, key, "expected %s, got \"%s\"", want, v);
    }
    *out = x;
    return 0;
}

static int get_int(parser *P, int line, const char *key, const char *v, double lo, double hi, double *out)
{
    double x = 0;
    if (!scv_number(v, &x) || x != floor(x) || x < lo || x > hi) {
        char want[120];
        range_text(want, sizeof want, "a whole number", R_IN(lo, hi));
        return key_fail(P, line, key, "expected %s, got \"%s\"", want, v);
    }
    *out = x;
    return 0;
}

static int get_bool(parser *P, int line, const char *key, const char *v, int *out)
{
    if (!scv_bool(v, out))
        return key_fail(P, line, key, "expected true or false (also yes/no, on/off, 1/0), got \"%s\"", v);
    return 0;
}

static int get_color(parser *P, int line, const char *key, const char *v, isk_color *out)
{
    if (!scv_color(v, out)) {
        char hint[80] = "";
        if (v[0] != '#')
            suggest_names(hint, sizeof hint, v, scv_color_names, scv_color_count, "\"", "\"");
        return key_fail(P, line, key,
                        "expected a colour (#rrggbb, #rrggbbaa or a name such as yellow), got \"%s\"%s", v,
                        hint);
    }
    return 0;
}

static int get_enum(parser *P, int line, const char *key, const char *v, const char *const *names, int *out)
{
    int n = count_names(names);
    int i = scv_lookup(v, names, n);
    if (i < 0) {
        char list[200], hint[80];
        join_names(list, sizeof list, names, 0);
        suggest_names(hint, sizeof hint, v, names, n, "\"", "\"");
        return key_fail(P, line, key, "expected %s, got \"%s\"%s", list, v, hint);
    }
    *out = i;
    return 0;
}

/* Exactly n comma-separated numbers, each in range r. */
static int get_numbers(parser *P, int line, const char *key, const char *v, int n, const char *form, range r,
                       double *out)
{
    char buf[ISK_INI_MAX_LINE + 1];
    char *items[SCV_LIST_MAX];
    int got;
    if (!scv_split(v, buf, sizeof buf, ',', items, SCV_LIST_MAX, &got) || got != n)
        return key_fail(P, line, key, "expected %d numbers \"%s\", got \"%s\"", n, form, v);
    for (int i = 0; i < n; i++)
        if (!scv_number(items[i], &out[i]) || !in_range(out[i], r)) {
            char w2[120];
            range_text(w2, sizeof w2, "a number", r);
            return key_fail(P, line, key, "expected %d numbers \"%s\": item %d is not %s: \"%s\"", n, form, i + 1,
                            w2, items[i]);
        }
    return 0;
}

static int get_vec(parser *P, int line, const char *key, const char *v, isk_vec2 *out)
{
    double xy[2] = {0, 0};
    if (get_numbers(P, line, key, v, 2, "x, y", R_ANY, xy))
        return 1;
    *out = isk_vec2_make(xy[0], xy[1]);
    return 0;
}

/* A number of degrees, returned in radians. */
/* Degrees ("90"), or radians with a suffix ("0.6 rad"): a radian value from
 * a C program then arrives bit for bit, where degrees would be rounded twice. */
static int get_angle(parser *P, int line, const char *key, const char *v, range r, double *out)
{
    size_t n = strlen(v);
    if (n > 3 && !strcmp(v + n - 3, "rad")) {
        char buf[64];
        size_t m = n - 3;
        while (m > 0 && (v[m - 1] == ' ' || v[m - 1] == '\t'))
            m--;
        if (m == 0 || m >= sizeof buf)
            return key_fail(P, line, key, "expected an angle in degrees or \"N rad\", got \"%s\"", v);
        memcpy(buf, v, m);
        buf[m] = 0;
        double rad;
        range rr = r;
        rr.lo = r.lo * (PI / 180.0);
        rr.hi = r.hi * (PI / 180.0);
        if (get_real(P, line, key, buf, rr, &rad))
            return 1;
        *out = rad;
        return 0;
    }
    double deg = 0;
    if (get_real(P, line, key, v, r, &deg))
        return 1;
    *out = deg * (PI / 180.0);
    return 0;
}

/* "min, max" with 0 <= min <= max (any sign when `signed_ok`) */
static int get_min_max_r(parser *P, int line, const char *key, const char *v, int signed_ok, double *lo,
                         double *hi)
{
    double mm[2] = {0, 0};
    if (get_numbers(P, line, key, v, 2, "min, max", signed_ok ? R_ANY : R_GE(0), mm))
        return 1;
    if (mm[0] > mm[1])
        return key_fail(P, line, key, "min (%.15g) is greater than max (%.15g)", mm[0], mm[1]);
    *lo = mm[0];
    *hi = mm[1];
    return 0;
}

static int get_min_max(parser *P, int line, const char *key, const char *v, double *lo, double *hi)
{
    return get_min_max_r(P, line, key, v, 0, lo, hi);
}

/* "t:value, t:value, ..." — colour (is_color) or scalar stops in range r. */
static int get_stops(parser *P, int line, const char *key, const char *v, int is_color, range r,
                     isk_color_stop *cs, isk_scalar_stop *ss, int *count)
{
    char buf[ISK_INI_MAX_LINE + 1];
    char *items[SCV_LIST_MAX];
    int n;
    const char *form = is_color ? "t:colour, t:colour, ..." : "t:value, t:value, ...";
    if (!scv_split(v, buf, sizeof buf, ',', items, SCV_LIST_MAX, &n) || n < 1)
        return key_fail(P, line, key, "expected stops \"%s\", got \"%s\"", form, v);
    if (n > ISK_GRADIENT_MAX_STOPS)
        return key_fail(P, line, key, "at most %d stops, got %d", ISK_GRADIENT_MAX_STOPS, n);
    double prev = -1;
    for (int i = 0; i < n; i++) {
        char *colon = strchr(items[i], ':');
        if (!colon)
            return key_fail(P, line, key, "stop %d: expected \"t:%s\", got \"%s\"", i + 1,
                            is_color ? "colour" : "value", items[i]);
        *colon = 0;
        char *tv = items[i], *val = colon + 1;
        while (*val == ' ' || *val == '\t')
            val++;
        size_t tl = strlen(tv);
        while (tl && (tv[tl - 1] == ' ' || tv[tl - 1] == '\t'))
            tv[--tl] = 0;
        double t;
        if (!scv_number(tv, &t) || t < 0 || t > 1)
            return key_fail(P, line, key, "stop %d: expected a position t between 0 and 1, got \"%s\"", i + 1, tv);
        if (t <= prev)
            return key_fail(P, line, key, "stop %d: positions must increase (%.15g after %.15g)", i + 1, t, prev);
        prev = t;
        if (is_color) {
            cs[i].t = t;
            if (!scv_color(val, &cs[i].color))
                return key_fail(P, line, key, "stop %d: expected a colour (#rrggbb, #rrggbbaa or a name), got \"%s\"",
                                i + 1, val);
        } else {
            ss[i].t = t;
            double x;
            if (!scv_number(val, &x) || !in_range(x, r)) {
                char want[120];
                range_text(want, sizeof want, "a number", r);
                return key_fail(P, line, key, "stop %d: expected %s, got \"%s\"", i + 1, want, val);
            }
            ss[i].value = x;
        }
    }
    *count = n;
    return 0;
}

/* min/max distance: a number, or "off" (the thesis's -1). */
static int get_distance(parser *P, int line, const char *key, const char *v, double *out)
{
    static const char *const off[] = {"off", "none"};
    if (scv_lookup(v, off, 2) >= 0) {
        *out = ISK_DIST_OFF;
        return 0;
    }
    double x = 0;
    if (!scv_number(v, &x))
        return key_fail(P, line, key, "expected a distance (a number; <= 0 or \"off\" switches it off), got \"%s\"", v);
    *out = x;
    return 0;
}

/* ---- sections ------------------------------------------------------------- */

static int valid_name(const char *s)
{
    if (!*s)
        return 0;
    for (; *s; s++)
        if (!isalnum((unsigned char)*s) && *s != '_' && *s != '-' && *s != '.')
            return 0;
    return 1;
}

static int open_header(parser *P, const header *h)
{
    char text[ISK_INI_MAX_LINE + 1];
    size_t len = h->len < sizeof text - 1 ? h->len : sizeof text - 1;
    memcpy(text, h->text, len);
    text[len] = 0;
    /* type, then an optional name */
    char *p = text;
    while (*p == ' ' || *p == '\t')
        p++;
    char *type = p;
    while (*p && *p != ' ' && *p != '\t')
        p++;
    char *name = p;
    if (*p) {
        *p = 0;
        name = p + 1;
    }
    while (*name == ' ' || *name == '\t')
        name++;
    size_t nl = strlen(name);
    while (nl && (name[nl - 1] == ' ' || name[nl - 1] == '\t'))
        name[--nl] = 0;

    int t = -1;
    const char *types[SK_SECTION_COUNT];
    for (int i = 0; i < SK_SECTION_COUNT; i++) {
        types[i] = sk_tables[i].name;
        if (!strcmp(type, types[i]))
            t = i;
    }
    if (t < 0) {
        const char *s = suggest(type, types, SK_SECTION_COUNT);
        if (!*type)
            return isk_ini_error(P->err, P->name, h->line, "empty section header []");
        if (s)
            return isk_ini_error(P->err, P->name, h->line, "unknown section [%s%s%s]; did you mean [%s%s%s]?", type,
                                 *name ? " " : "", name, s, *name ? " " : "", name);
        return isk_ini_error(P->err, P->name, h->line,
                             "unknown section [%s]; sections are [scene], [view], [force NAME], "
                             "[deflector NAME], [bounds], [emitter NAME], [drawing NAME] and [click]",
                             type);
    }
    const sk_table *tab = &sk_tables[t];
    if (tab->named && !*name)
        return isk_ini_error(P->err, P->name, h->line, "section [%s] needs a name: [%s NAME]", type, type);
    if (!tab->named && *name)
        return isk_ini_error(P->err, P->name, h->line, "section [%s] takes no name (got [%s %s])", type, type, name);
    if (tab->named && (!valid_name(name) || strlen(name) >= ISK_NAME_MAX))
        return isk_ini_error(P->err, P->name, h->line,
                             "bad name '%s' in [%s %s]: use letters, digits, '_', '-' or '.' "
                             "(at most %d characters)",
                             name, type, name, ISK_NAME_MAX - 1);
    if (tab->named && (!strcmp(name, "all") || !strcmp(name, "none")))
        return isk_ini_error(P->err, P->name, h->line, "'%s' is reserved and cannot name a [%s]", name, type);
    for (int i = 0; i < P->nsec; i++)
        if (P->sec[i].type == (sk_section)t && !strcmp(P->sec[i].name, name)) {
            if (*name)
                return isk_ini_error(P->err, P->name, h->line, "duplicate section [%s %s] (first defined at line %d)",
                                     type, name, P->sec[i].line);
            return isk_ini_error(P->err, P->name, h->line, "duplicate section [%s] (first defined at line %d)", type,
                                 P->sec[i].line);
        }
    if (P->nsec >= MAX_SECTIONS)
        return isk_ini_error(P->err, P->name, h->line, "too many sections (at most %d)", MAX_SECTIONS);

    section s;
    memset(&s, 0, sizeof s);
    s.type = (sk_section)t;
    size_t nlen = strnlen(name, sizeof s.name - 1); /* names were checked shorter already */
    memcpy(s.name, name, nlen);
    s.name[nlen] = 0;
    s.line = h->line;
    s.index = -1;
    isk_effect_def *d = P->d;
    switch (t) {
    case SK_FORCE:
        s.index = isk_effect_def_add_force(d, name, ISK_FORCE_GRAVITY);
        if (s.index < 0)
            return isk_ini_error(P->err, P->name, h->line, "too many forces (at most %d)", ISK_EFFECT_MAX_FORCES);
        d->forces[s.index].line = h->line;
        s.exponent = 2;
        break;
    case SK_DEFLECTOR:
        s.index = isk_effect_def_add_deflector(d, name, isk_deflector_segment(0, 0, 1, 0));
        if (s.index < 0)
            return isk_ini_error(P->err, P->name, h->line, "too many deflectors (at most %d)",
                                 ISK_EFFECT_MAX_DEFLECTORS);
        break;
    case SK_EMITTER: {
        isk_emitter_def *e = isk_effect_def_add_emitter(d, name);
        if (!e)
            return isk_ini_error(P->err, P->name, h->line, "too many emitters (at most %d)", ISK_EFFECT_MAX_EMITTERS);
        e->line = h->line;
        e->bounded = 1; /* the walls of [bounds], if any, apply unless bounded = false */
        s.index = d->nemitters - 1;
        break;
    }
    case SK_DRAWING: {
        isk_drawing_def *g = isk_effect_def_add_drawing(d, name, ISK_DRAWING_POLYLINE);
        if (!g)
            return isk_ini_error(P->err, P->name, h->line, "too many drawings (at most %d)", ISK_EFFECT_MAX_DRAWINGS);
        g->line = h->line;
        s.index = d->ndrawings - 1;
        break;
    }
    case SK_BOUNDS:
        d->bounds.sides = ISK_SIDE_ALL;
        break;
    case SK_CLICK:
        d->click_enabled = 1;
        break;
    default:
        break;
    }
    if (P->nsec % 16 == 0) {
        section *a = realloc(P->sec, sizeof *a * (size_t)(P->nsec + 16));
        if (!a) {
            isk_error_set(P->err, ISK_ERR_NOMEM, "%s: out of memory", P->name);
            return 1;
        }
        P->sec = a;
    }
    P->sec[P->nsec] = s;
    P->cur = P->nsec++;
    return 0;
}

/* Opens every header above `line`. */
static int open_headers_before(parser *P, int line)
{
    while (P->next_hdr < P->nhdr && P->hdr[P->next_hdr].line < line)
        if (open_header(P, &P->hdr[P->next_hdr++]))
            return 1;
    return 0;
}

/* ---- keys ----------------------------------------------------------------- */

static int set_scene(parser *P, int id, const char *k, const char *v, int ln)
{
    isk_effect_def *d = P->d;
    double x = 0;
    int i;
    switch (id) {
    case K_SCENE_WIDTH:
        if (get_int(P, ln, k, v, 1, ISK_CANVAS_MAX_DIM, &x)) return 1;
        d->width = (int)x;
        return 0;
    case K_SCENE_HEIGHT:
        if (get_int(P, ln, k, v, 1, ISK_CANVAS_MAX_DIM, &x)) return 1;
        d->height = (int)x;
        return 0;
    case K_SCENE_BACKGROUND: return get_color(P, ln, k, v, &d->background);
    case K_SCENE_CLEAR: return get_bool(P, ln, k, v, &d->clear);
    case K_SCENE_DT: return get_real(P, ln, k, v, R_GT_LE(0, 1000), &d->dt);
    case K_SCENE_SUBSTEPS:
        if (get_int(P, ln, k, v, 1, MAX_SUBSTEPS, &x)) return 1;
        d->substeps = (int)x;
        return 0;
    case K_SCENE_INTEGRATOR:
        if (get_enum(P, ln, k, v, sk_integrator_names, &i)) return 1;
        d->integrator = (isk_integrator)i;
        return 0;
    case K_SCENE_SEED:
        if (!scv_u64(v, &d->seed))
            return key_fail(P, ln, k, "expected a whole number between 0 and 18446744073709551615, got \"%s\"", v);
        return 0;
    case K_SCENE_SPEED_DIVISOR: return get_real(P, ln, k, v, R_GT_LE(0, 1e6), &d->speed_divisor);
    case K_SCENE_CENTRE:
        if (get_enum(P, ln, k, v, sk_fidelity_names, &i)) return 1;
        d->centre = (isk_fidelity)i;
        return 0;
    case K_SCENE_FIDELITY:
        if (get_enum(P, ln, k, v, sk_fidelity_names, &i)) return 1;
        d->fidelity = (isk_fidelity)i;
        return 0;
    case K_SCENE_FRAMES:
        if (get_int(P, ln, k, v, 0, MAX_FRAMES, &x)) return 1;
        d->frames = (long)x;
        return 0;
    }
    return 0;
}

static int set_view(parser *P, int id, const char *k, const char *v, int ln)
{
    isk_effect_def *d = P->d;
    switch (id) {
    case K_VIEW_XMIN: return get_real(P, ln, k, v, R_ANY, &d->xmin);
    case K_VIEW_XMAX: return get_real(P, ln, k, v, R_ANY, &d->xmax);
    case K_VIEW_YMIN: return get_real(P, ln, k, v, R_ANY, &d->ymin);
    case K_VIEW_YMAX: return get_real(P, ln, k, v, R_ANY, &d->ymax);
    case K_VIEW_ZOOM: return get_real(P, ln, k, v, R_GT(0), &d->zoom);
    case K_VIEW_PAN: {
        isk_vec2 t;
        if (get_vec(P, ln, k, v, &t)) return 1;
        d->tx = t.x;
        d->ty = t.y;
        return 0;
    }
    }
    return 0;
}

static int set_force(parser *P, section *s, int id, const char *k, const char *v, int ln)
{
    isk_force_def *f = &P->d->forces[s->index];
    int i;
    switch (id) {
    case K_FORCE_KIND:
        if (get_enum(P, ln, k, v, sk_force_kind_names, &i)) return 1;
        f->kind = (isk_force_kind)i;
        return 0;
    case K_FORCE_G: return get_real(P, ln, k, v, R_GE(0), &f->g);
    case K_FORCE_B: return get_real(P, ln, k, v, R_GE(0), &f->b);
    case K_FORCE_ACCEL: return get_vec(P, ln, k, v, &f->accel);
    case K_FORCE_K: return get_real(P, ln, k, v, R_ANY, &f->pot.k);
    case K_FORCE_CHARGE: return get_real(P, ln, k, v, R_ANY, &f->pot.charge);
    case K_FORCE_POSITION: return get_vec(P, ln, k, v, &f->pot.r);
    case K_FORCE_EXPONENT: return get_real(P, ln, k, v, R_IN(-1000, 1000), &s->exponent);
    case K_FORCE_LAW: return get_enum(P, ln, k, v, sk_law_names, &s->law);
    case K_FORCE_MIN: return get_distance(P, ln, k, v, &f->pot.min_dist);
    case K_FORCE_MAX: return get_distance(P, ln, k, v, &f->pot.max_dist);
    case K_FORCE_XMULT: return get_real(P, ln, k, v, R_ANY, &f->pot.x_mult);
    case K_FORCE_ENABLED: return get_bool(P, ln, k, v, &f->pot.enabled);
    case K_FORCE_VELOCITY: return get_vec(P, ln, k, v, &f->pot.vel);
    case K_FORCE_DRAW: return get_bool(P, ln, k, v, &f->draw);
    }
    return 0;
}

static int set_deflector(parser *P, section *s, int id, const char *k, const char *v, int ln)
{
    isk_deflector *g = &P->d->deflectors[s->index];
    int i;
    switch (id) {
    case K_DEFL_SEGMENT: {
        double q[4] = {0};
        if (get_numbers(P, ln, k, v, 4, "x0, y0, x1, y1", R_ANY, q)) return 1;
        if (q[0] == q[2] && q[1] == q[3])
            return key_fail(P, ln, k, "the two end points are the same (a segment needs a length)");
        g->x0 = q[0]; g->y0 = q[1]; g->x1 = q[2]; g->y1 = q[3];
        return 0;
    }
    case K_DEFL_RESTITUTION: return get_real(P, ln, k, v, R_IN(0, 1000), &g->restitution);
    case K_DEFL_PROBABILITY: return get_real(P, ln, k, v, R_IN(0, 1), &g->probability);
    case K_DEFL_REACTION:
        if (get_enum(P, ln, k, v, sk_reaction_names, &i)) return 1;
        g->reaction = (isk_deflect_reaction)i;
        return 0;
    case K_DEFL_MODE:
        if (get_enum(P, ln, k, v, sk_restitution_names, &i)) return 1;
        g->mode = (isk_restitution_mode)i;
        return 0;
    }
    return 0;
}

static int get_window(parser *P, int ln, const char *k, const char *v, double *w)
{
    if (get_numbers(P, ln, k, v, 4, "xmin, xmax, ymin, ymax", R_ANY, w)) return 1;
    if (!(w[0] < w[1]) || !(w[2] < w[3]))
        return key_fail(P, ln, k, "needs xmin < xmax and ymin < ymax, got \"%s\"", v);
    return 0;
}

static int set_bounds(parser *P, int id, const char *k, const char *v, int ln)
{
    isk_bounds *b = &P->d->bounds;
    int i;
    switch (id) {
    case K_BOUNDS_MODE:
        if (get_enum(P, ln, k, v, sk_bounce_names, &i)) return 1;
        b->mode = (isk_bounce_mode)i;
        return 0;
    case K_BOUNDS_SIDES: {
        static const char *const words[] = {"all", "none"};
        if (scv_lookup(v, words, 2) == 0) { b->sides = ISK_SIDE_ALL; return 0; }
        if (scv_lookup(v, words, 2) == 1) { b->sides = 0; return 0; }
        char buf[ISK_INI_MAX_LINE + 1];
        char *items[SCV_LIST_MAX];
        int n;
        if (!scv_split(v, buf, sizeof buf, ',', items, SCV_LIST_MAX, &n) || n == 0)
            return key_fail(P, ln, k, "expected sides \"top, right, bottom, left\" (any of them), all or none, "
                                      "got \"%s\"", v);
        unsigned sides = 0;
        for (int j = 0; j < n; j++) {
            int sd = scv_lookup(items[j], sk_side_names, 4);
            if (sd < 0) {
                char hint[80];
                suggest_names(hint, sizeof hint, items[j], sk_side_names, 4, "\"", "\"");
                return key_fail(P, ln, k, "expected top, right, bottom or left (or all, none), got \"%s\"%s",
                                items[j], hint);
            }
            if (sides & (1u << sd))
                return key_fail(P, ln, k, "'%s' is listed twice", sk_side_names[sd]);
            sides |= 1u << sd;
        }
        b->sides = sides;
        return 0;
    }
    case K_BOUNDS_MARGIN: return get_real(P, ln, k, v, R_GE(0), &b->margin);
    case K_BOUNDS_RESTITUTION: return get_real(P, ln, k, v, R_IN(0, 1), &b->restitution);
    case K_BOUNDS_WINDOW: {
        double w[4] = {0};
        if (get_window(P, ln, k, v, w)) return 1;
        b->xmin = w[0]; b->xmax = w[1]; b->ymin = w[2]; b->ymax = w[3];
        return 0;
    }
    }
    return 0;
}

static int get_count(parser *P, int ln, const char *k, const char *v, double lo, size_t *out)
{
    double x = 0;
    if (get_int(P, ln, k, v, lo, ISK_EFFECT_MAX_PARTICLES, &x)) return 1;
    *out = (size_t)x;
    return 0;
}

static int set_emitter(parser *P, section *s, int id, const char *k, const char *v, int ln)
{
    isk_emitter_def *e = &P->d->emitters[s->index];
    int i;
    double x = 0, q[4] = {0};
    switch (id) {
    case K_EM_SOURCE:
        if (get_enum(P, ln, k, v, sk_source_names, &i)) return 1;
        e->source = (isk_source_kind)i;
        return 0;
    case K_EM_POSITION: return get_vec(P, ln, k, v, &e->pos);
    case K_EM_VELOCITY: return get_vec(P, ln, k, v, &e->vel);
    case K_EM_MASS: return get_real(P, ln, k, v, R_GT(0), &e->mass);
    case K_EM_MASS_RANGE: return get_real(P, ln, k, v, R_GE(0), &e->mass_range);
    case K_EM_EXPLOSION:
        if (get_enum(P, ln, k, v, sk_explosion_names, &i)) return 1;
        e->explosion = (isk_explosion)i;
        return 0;
    case K_EM_COUNT: return get_count(P, ln, k, v, 1, &e->count);
    case K_EM_LIMIT: return get_count(P, ln, k, v, 0, &e->limit);
    case K_EM_KICK:
        if (get_enum(P, ln, k, v, sk_kick_names, &i)) return 1;
        e->kick = (isk_kick_target)i;
        return 0;
    case K_EM_START: return get_real(P, ln, k, v, R_GE(0), &e->start);
    case K_EM_RECT:
        if (get_numbers(P, ln, k, v, 4, "xmin, xmax, ymin, ymax", R_ANY, q)) return 1;
        if (q[0] > q[1] || q[2] > q[3])
            return key_fail(P, ln, k, "needs xmin <= xmax and ymin <= ymax, got \"%s\"", v);
        memcpy(e->rect, q, sizeof e->rect);
        return 0;
    case K_EM_SHAPE:
        if (get_enum(P, ln, k, v, sk_shape_names, &i)) return 1;
        e->shape = (isk_shape_kind)i;
        return 0;
    case K_EM_SHAPE_A: return get_real(P, ln, k, v, R_ANY, &e->shape_a);
    case K_EM_SHAPE_B: return get_real(P, ln, k, v, R_ANY, &e->shape_b);
    case K_EM_SHAPE_ANGLE: return get_angle(P, ln, k, v, R_IN(-3600, 3600), &e->shape_angle);
    case K_EM_SHAPE_FAITHFUL: return get_bool(P, ln, k, v, &e->shape_faithful);
    case K_EM_LAUNCH:
        if (get_enum(P, ln, k, v, sk_launch_names, &i)) return 1;
        e->launch = (isk_velgen_kind)i;
        return 0;
    case K_EM_ANGLE: return get_angle(P, ln, k, v, R_IN(-3600, 3600), &e->angle);
    case K_EM_SPREAD: return get_angle(P, ln, k, v, R_IN(0, 360), &e->spread);
    case K_EM_SPEED_MIN: return get_real(P, ln, k, v, R_GE(0), &e->speed_min);
    case K_EM_SPEED_MAX: return get_real(P, ln, k, v, R_GE(0), &e->speed_max);
    case K_EM_RATE: return get_real(P, ln, k, v, R_IN(0, 1e8), &e->rate);
    case K_EM_RATE_MODE:
        if (get_enum(P, ln, k, v, sk_rate_mode_names, &i)) return 1;
        e->rate_mode = (isk_rate_mode)i;
        return 0;
    case K_EM_BIRTH:
        if (get_enum(P, ln, k, v, sk_birth_names, &i)) return 1;
        e->birth = (isk_birth_mode)i;
        return 0;
    case K_EM_BURST_EVERY: return get_real(P, ln, k, v, R_GE(0), &e->burst_every);
    case K_EM_LIFE: {
        static const char *const forever[] = {"forever", "inf", "infinite", "immortal"};
        if (scv_lookup(v, forever, 4) >= 0) {
            e->life = INFINITY;
            return 0;
        }
        if (!scv_number(v, &x) || !(x > 0))
            return key_fail(P, ln, k, "expected a number of seconds > 0 or forever, got \"%s\"", v);
        e->life = x;
        return 0;
    }
    case K_EM_LIFE_RANGE: return get_real(P, ln, k, v, R_GE(0), &e->life_range);
    case K_EM_CAPACITY: return get_count(P, ln, k, v, 1, &e->capacity);
    case K_EM_FORCES: snprintf(s->forces_ref, sizeof s->forces_ref, "%s", v); return 0;
    case K_EM_DEFLECTORS: snprintf(s->defl_ref, sizeof s->defl_ref, "%s", v); return 0;
    case K_EM_BOUNDED: return get_bool(P, ln, k, v, &e->bounded);
    case K_EM_DRAW_BEFORE_BOUNCE: return get_bool(P, ln, k, v, &e->draw_before_bounce);
    case K_EM_GRAVITY_MULT: return get_real(P, ln, k, v, R_ANY, &e->gravity_mult);
    case K_EM_WEIGHT: return get_real(P, ln, k, v, R_ANY, &e->weight);
    case K_EM_SLOWING: return get_real(P, ln, k, v, R_GE(0), &e->slowing);
    case K_EM_OSC_OMEGA: /* negative: the flame sways the other way first */
        return get_min_max_r(P, ln, k, v, 1, &e->osc_omega_min, &e->osc_omega_max);
    case K_EM_OSC_AMPLITUDE: return get_min_max(P, ln, k, v, &e->osc_amp_min, &e->osc_amp_max);
    case K_EM_OSC_DECAY: return get_real(P, ln, k, v, R_GE(0), &e->osc_decay);
    case K_EM_OSC_FAITHFUL: return get_bool(P, ln, k, v, &e->osc_faithful);
    case K_EM_OSC_TABLE: return get_bool(P, ln, k, v, &e->osc_use_table);
    case K_EM_OSC_RANDOM_PHASE: return get_bool(P, ln, k, v, &e->osc_random_phase);
    case K_EM_SLOW_FAITHFUL: return get_bool(P, ln, k, v, &e->slow_faithful);
    case K_EM_INTEGRATOR:
        if (get_enum(P, ln, k, v, sk_integrator_names, &i)) return 1;
        e->integrator = (isk_integrator)i;
        return 0;
    case K_EM_SUBSTEPS:
        if (get_int(P, ln, k, v, 1, MAX_SUBSTEPS, &x)) return 1;
        e->substeps = (int)x;
        return 0;
    case K_EM_DRAW:
        if (get_enum(P, ln, k, v, sk_draw_names, &i)) return 1;
        e->draw = (isk_draw_mode)i;
        return 0;
    case K_EM_SPRITE:
        if (get_enum(P, ln, k, v, sk_sprite_names, &i)) return 1;
        e->sprite = (isk_sprite_kind)i;
        return 0;
    case K_EM_SIZE: return get_real(P, ln, k, v, R_GT_LE(0, 1e6), &e->size);
    case K_EM_COLOR: return get_color(P, ln, k, v, &e->color);
    case K_EM_BLEND:
        if (get_enum(P, ln, k, v, sk_blend_names, &i)) return 1;
        e->blend = (isk_blend)i;
        return 0;
    case K_EM_COLOR_OVER_LIFE:
        return get_stops(P, ln, k, v, 1, R_ANY, e->color_over_life.stops, NULL, &e->color_over_life.n);
    case K_EM_ALPHA_OVER_LIFE:
        return get_stops(P, ln, k, v, 0, R_IN(0, 1), NULL, e->alpha_over_life.stops, &e->alpha_over_life.n);
    case K_EM_SIZE_OVER_LIFE:
        return get_stops(P, ln, k, v, 0, R_IN(0, 1e6), NULL, e->size_over_life.stops, &e->size_over_life.n);
    case K_EM_ORDER:
        if (get_int(P, ln, k, v, -1000000, 1000000, &x)) return 1;
        e->order = (int)x;
        return 0;
    }
    return 0;
}

static int set_drawing(parser *P, section *s, int id, const char *k, const char *v, int ln)
{
    isk_drawing_def *g = &P->d->drawings[s->index];
    int i;
    double x = 0;
    switch (id) {
    case K_DRAW_KIND:
        if (get_enum(P, ln, k, v, sk_drawing_names, &i)) return 1;
        g->kind = (isk_drawing_kind)i;
        return 0;
    case K_DRAW_UNITS: return get_enum(P, ln, k, v, sk_units_names, &g->pixels);
    case K_DRAW_POINTS: {
        char buf[ISK_INI_MAX_LINE + 1];
        char *items[SCV_LIST_MAX];
        int n;
        if (!scv_split(v, buf, sizeof buf, ',', items, SCV_LIST_MAX, &n) || n < 4 || n % 2 ||
            n > 2 * MAX_POLYLINE_POINTS)
            return key_fail(P, ln, k, "expected 2 to %d points \"x0, y0, x1, y1, ...\" (an even count of numbers), "
                                      "got \"%s\"", MAX_POLYLINE_POINTS, v);
        double *pts = malloc(sizeof *pts * (size_t)n);
        if (!pts) {
            isk_error_set(P->err, ISK_ERR_NOMEM, "%s: out of memory", P->name);
            return 1;
        }
        for (int j = 0; j < n; j++)
            if (!scv_number(items[j], &pts[j])) {
                free(pts);
                return key_fail(P, ln, k, "item %d is not a number: \"%s\"", j + 1, items[j]);
            }
        free(g->points);
        g->points = pts;
        g->npoints = n / 2;
        return 0;
    }
    case K_DRAW_CLOSED: return get_bool(P, ln, k, v, &g->closed);
    case K_DRAW_HAIRLINE: return get_bool(P, ln, k, v, &g->hairline);
    case K_DRAW_POSITION: {
        isk_vec2 p;
        if (get_vec(P, ln, k, v, &p)) return 1;
        g->x = p.x;
        g->y = p.y;
        return 0;
    }
    case K_DRAW_RADIUS: return get_real(P, ln, k, v, R_GT_LE(0, 1e9), &g->r);
    case K_DRAW_TEXT: {
        size_t n = strlen(v);
        if (n >= sizeof g->text)
            return key_fail(P, ln, k, "text longer than %d characters", (int)sizeof g->text - 1);
        memcpy(g->text, v, n + 1);
        return 0;
    }
    case K_DRAW_SCALE:
        if (get_int(P, ln, k, v, 1, 64, &x)) return 1;
        g->scale = (int)x;
        return 0;
    case K_DRAW_COLOR: return get_color(P, ln, k, v, &g->color);
    case K_DRAW_BLEND:
        if (get_enum(P, ln, k, v, sk_blend_names, &i)) return 1;
        g->blend = (isk_blend)i;
        return 0;
    case K_DRAW_SPRITE:
        if (get_enum(P, ln, k, v, sk_sprite_names, &i)) return 1;
        g->sprite = (isk_sprite_kind)i;
        return 0;
    case K_DRAW_SIZE: return get_real(P, ln, k, v, R_GT_LE(0, 1e9), &g->size);
    }
    return 0;
}

static int set_click(parser *P, section *s, int id, const char *k, const char *v, int ln)
{
    isk_effect_def *d = P->d;
    int i;
    switch (id) {
    case K_CLICK_EXPLOSION:
        if (get_enum(P, ln, k, v, sk_explosion_names, &i)) return 1;
        d->click_explosion = (isk_explosion)i;
        return 0;
    case K_CLICK_COUNT: return get_count(P, ln, k, v, 1, &d->click_count);
    case K_CLICK_EMITTER:
        if (!valid_name(v) || strlen(v) >= ISK_NAME_MAX)
            return key_fail(P, ln, k, "expected an emitter name, got \"%s\"", v);
        snprintf(s->emitter_ref, sizeof s->emitter_ref, "%s", v);
        return 0;
    case K_CLICK_AT_START: {
        isk_vec2 p;
        if (get_vec(P, ln, k, v, &p)) return 1;
        d->click_auto = 1;
        d->click_x = p.x;
        d->click_y = p.y;
        return 0;
    }
    case K_CLICK_AFTER_FRAMES: {
        double f;
        if (get_int(P, ln, k, v, 0, 1e8, &f)) return 1;
        d->click_after = (long)f;
        return 0;
    }
    }
    return 0;
}

static int on_key(void *user, const char *section_name, const char *key, const char *value, int line,
                  isk_error *err)
{
    (void)section_name; /* we use our own header scan (see the top) */
    (void)err;
    parser *P = user;
    if (open_headers_before(P, line))
        return 1;
    if (P->cur < 0)
        return isk_ini_error(P->err, P->name, line,
                             "'%s = %s' is outside any section (start the file with a section such as [scene])",
                             key, value);
    section *s = &P->sec[P->cur];
    const sk_table *tab = &sk_tables[s->type];
    const sk_key *kd = NULL;
    for (int i = 0; i < tab->nkeys; i++)
        if (!strcmp(tab->keys[i].name, key))
            kd = &tab->keys[i];
    if (!kd) {
        const char *names[64];
        for (int i = 0; i < tab->nkeys; i++)
            names[i] = tab->keys[i].name;
        const char *sug = suggest(key, names, tab->nkeys);
        if (sug)
            return key_fail(P, line, NULL, "unknown key '%s'; did you mean '%s'?", key, sug);
        for (int t = 0; t < SK_SECTION_COUNT; t++)
            for (int i = 0; i < sk_tables[t].nkeys; i++)
                if (!strcmp(sk_tables[t].keys[i].name, key))
                    return key_fail(P, line, NULL, "unknown key '%s' (it belongs in a [%s%s] section)", key,
                                    sk_tables[t].name, sk_tables[t].named ? " NAME" : "");
        return key_fail(P, line, NULL, "unknown key '%s' (see docs/scene-format.md for the keys of [%s])", key,
                        tab->name);
    }
    if (s->seen >> kd->id & 1u)
        return key_fail(P, line, key, "given twice (first at line %d)", s->key_line[kd->id]);
    s->seen |= (uint64_t)1 << kd->id;
    s->key_line[kd->id] = line;
    switch (s->type) {
    case SK_SCENE: return set_scene(P, kd->id, key, value, line);
    case SK_VIEW: return set_view(P, kd->id, key, value, line);
    case SK_FORCE: return set_force(P, s, kd->id, key, value, line);
    case SK_DEFLECTOR: return set_deflector(P, s, kd->id, key, value, line);
    case SK_BOUNDS: return set_bounds(P, kd->id, key, value, line);
    case SK_EMITTER: return set_emitter(P, s, kd->id, key, value, line);
    case SK_DRAWING: return set_drawing(P, s, kd->id, key, value, line);
    case SK_CLICK: return set_click(P, s, kd->id, key, value, line);
    default: return 0;
    }
}

/* ---- end of file checks ----------------------------------------------------- */

#define SEEN(s, id) ((s)->seen >> (id) & 1u)

/* Every key set in s must apply to kind `kind`. */
static int check_kinds(parser *P, section *s, unsigned kind, const char *kind_key, const char *const *kind_names,
                       const char *noun)
{
    const sk_table *tab = &sk_tables[s->type];
    for (int i = 0; i < tab->nkeys; i++) {
        const sk_key *kd = &tab->keys[i];
        if (!SEEN(s, kd->id) || !kd->kinds || (kd->kinds >> kind & 1u))
            continue;
        char list[200];
        join_names(list, sizeof list, kind_names, kd->kinds);
        return key_fail(P, s->key_line[kd->id], kd->name, "only for %s = %s (this %s has %s = %s)", kind_key, list,
                        noun, kind_key, kind_names[kind]);
    }
    return 0;
}

static int require(parser *P, section *s, int id, const char *key, const char *why)
{
    if (SEEN(s, id))
        return 0;
    return key_fail(P, s->line, NULL, "needs %s (%s)", key, why);
}

/* Resolves a list of names ("a, b", "all", "none" or empty) to indices. */
static int resolve_list(parser *P, section *s, int key_id, const char *key, const char *list, const char *noun,
                        int (*find)(const isk_effect_def *, const char *), int count,
                        const char *(*name_of)(const isk_effect_def *, int),
                        isk_status (*use)(isk_emitter_def *, int))
{
    isk_emitter_def *e = &P->d->emitters[s->index];
    int line = s->key_line[key_id];
    static const char *const words[] = {"all", "none"};
    int w = scv_lookup(list, words, 2);
    if (w == 0) {
        for (int i = 0; i < count; i++)
            use(e, i);
        return 0;
    }
    if (w == 1)
        return 0;
    char buf[ISK_INI_MAX_LINE + 1];
    char *items[SCV_LIST_MAX];
    int n;
    if (!scv_split(list, buf, sizeof buf, ',', items, SCV_LIST_MAX, &n))
        return key_fail(P, line, key, "expected %s names separated by commas (or all, none), got \"%s\"", noun, list);
    for (int j = 0; j < n; j++) {
        int idx = find(P->d, items[j]);
        if (idx < 0) {
            const char *names[ISK_EFFECT_MAX_DEFLECTORS];
            for (int i = 0; i < count; i++)
                names[i] = name_of(P->d, i);
            char hint[80];
            suggest_names(hint, sizeof hint, items[j], names, count, "'", "'");
            if (!count)
                snprintf(hint, sizeof hint, " (the scene defines no [%s NAME] section)", noun);
            return key_fail(P, line, key, "no %s named '%s'%s", noun, items[j], hint);
        }
        for (int i = 0; i < j; i++)
            if (!strcmp(items[i], items[j]))
                return key_fail(P, line, key, "'%s' is listed twice", items[j]);
        use(e, idx);
    }
    return 0;
}

static const char *force_name(const isk_effect_def *d, int i) { return d->forces[i].name; }
static const char *defl_name(const isk_effect_def *d, int i) { return d->deflector_names[i]; }

static int finish_section(parser *P, int si)
{
    section *s = &P->sec[si];
    isk_effect_def *d = P->d;
    P->cur = si;
    switch (s->type) {
    case SK_VIEW: {
        int win = 0, cam = 0, wline = 0, cline = 0;
        for (int id = K_VIEW_XMIN; id <= K_VIEW_YMAX; id++)
            if (SEEN(s, id)) { win = 1; if (s->key_line[id] > wline) wline = s->key_line[id]; }
        for (int id = K_VIEW_ZOOM; id <= K_VIEW_PAN; id++)
            if (SEEN(s, id)) { cam = 1; if (s->key_line[id] > cline) cline = s->key_line[id]; }
        if (win && cam)
            return key_fail(P, wline > cline ? wline : cline, NULL,
                            "mixes a world window (xmin, xmax, ymin, ymax) with a camera (zoom, pan): use one");
        d->view_kind = cam ? ISK_VIEWDEF_CAMERA : ISK_VIEWDEF_WINDOW;
        if (!(d->xmin < d->xmax))
            return key_fail(P, SEEN(s, K_VIEW_XMAX) ? s->key_line[K_VIEW_XMAX] : s->key_line[K_VIEW_XMIN], NULL,
                            "xmin (%.15g) must be less than xmax (%.15g)", d->xmin, d->xmax);
        if (!(d->ymin < d->ymax))
            return key_fail(P, SEEN(s, K_VIEW_YMAX) ? s->key_line[K_VIEW_YMAX] : s->key_line[K_VIEW_YMIN], NULL,
                            "ymin (%.15g) must be less than ymax (%.15g)", d->ymin, d->ymax);
        return 0;
    }
    case SK_FORCE: {
        isk_force_def *f = &d->forces[s->index];
        if (!SEEN(s, K_FORCE_KIND)) {
            int k = scv_lookup(s->name, sk_force_kind_names, ISK_FORCE_KIND_COUNT);
            if (k < 0)
                return key_fail(P, s->line, NULL, "needs kind = gravity, drag, wind or potential");
            f->kind = (isk_force_kind)k;
        }
        if (check_kinds(P, s, f->kind, "kind", sk_force_kind_names, "force"))
            return 1;
        if (f->kind == ISK_FORCE_POTENTIAL) {
            if (require(P, s, K_FORCE_K, "k", "the potential's strength") ||
                require(P, s, K_FORCE_POSITION, "position", "x, y of the potential"))
                return 1;
            if (SEEN(s, K_FORCE_LAW) && !SEEN(s, K_FORCE_EXPONENT))
                return key_fail(P, s->key_line[K_FORCE_LAW], "law", "needs an exponent to apply to");
            if (isk_potential_set_law(&f->pot, (isk_coulomb_law)s->law, s->exponent) != ISK_OK)
                return key_fail(P, s->key_line[K_FORCE_EXPONENT], "exponent", "is not usable");
        }
        return 0;
    }
    case SK_DEFLECTOR:
        return require(P, s, K_DEFL_SEGMENT, "segment", "x0, y0, x1, y1");
    case SK_BOUNDS: {
        isk_bounds *b = &d->bounds;
        if (check_kinds(P, s, b->mode, "mode", sk_bounce_names, "[bounds]"))
            return 1;
        if (!SEEN(s, K_BOUNDS_MARGIN))
            b->margin = b->mode == ISK_BOUNCE_THESIS ? 0.1 : 0.0;
        if (!SEEN(s, K_BOUNDS_WINDOW)) {
            if (d->view_kind == ISK_VIEWDEF_CAMERA) {
                isk_view v;
                if (isk_view_camera(&v, d->width, d->height, d->zoom, d->tx, d->ty) != ISK_OK)
                    return key_fail(P, s->line, NULL, "cannot derive its window from the [view] camera");
                b->xmin = v.xmin; b->xmax = v.xmax; b->ymin = v.ymin; b->ymax = v.ymax;
            } else {
                b->xmin = d->xmin; b->xmax = d->xmax; b->ymin = d->ymin; b->ymax = d->ymax;
            }
        }
        if (b->sides && (!(b->xmin + b->margin < b->xmax - b->margin) ||
                         !(b->ymin + b->margin < b->ymax - b->margin)))
            return key_fail(P, SEEN(s, K_BOUNDS_MARGIN) ? s->key_line[K_BOUNDS_MARGIN] : s->line, NULL,
                            "margin %.15g leaves no room between the walls", b->margin);
        return 0;
    }
    case SK_EMITTER: {
        isk_emitter_def *e = &d->emitters[s->index];
        if (check_kinds(P, s, e->source, "source", sk_source_names, "emitter"))
            return 1;
        if (e->source == ISK_SOURCE_LAYER && require(P, s, K_EM_RECT, "rect", "xmin, xmax, ymin, ymax of the layer"))
            return 1;
        if (e->source == ISK_SOURCE_LAYER && !SEEN(s, K_EM_COUNT))
            return require(P, s, K_EM_COUNT, "count", "how many particles the layer holds");
        if (SEEN(s, K_EM_SPEED_MIN) && SEEN(s, K_EM_SPEED_MAX) && e->speed_min > e->speed_max)
            return key_fail(P, s->key_line[K_EM_SPEED_MAX], "speed_max", "must be >= speed_min (%.15g)",
                            e->speed_min);
        if (SEEN(s, K_EM_FORCES) &&
            resolve_list(P, s, K_EM_FORCES, "forces", s->forces_ref, "force", isk_effect_def_find_force,
                         d->nforces, force_name, isk_emitter_use_force))
            return 1;
        if (SEEN(s, K_EM_DEFLECTORS) &&
            resolve_list(P, s, K_EM_DEFLECTORS, "deflectors", s->defl_ref, "deflector",
                         isk_effect_def_find_deflector, d->ndeflectors, defl_name, isk_emitter_use_deflector))
            return 1;
        return 0;
    }
    case SK_DRAWING: {
        isk_drawing_def *g = &d->drawings[s->index];
        if (!SEEN(s, K_DRAW_KIND)) {
            int k = scv_lookup(s->name, sk_drawing_names, ISK_DRAWING_KIND_COUNT);
            if (k < 0 && SEEN(s, K_DRAW_POINTS))
                k = ISK_DRAWING_POLYLINE;
            else if (k < 0 && SEEN(s, K_DRAW_RADIUS))
                k = ISK_DRAWING_DISC;
            else if (k < 0 && SEEN(s, K_DRAW_TEXT))
                k = ISK_DRAWING_TEXT;
            if (k < 0)
                return key_fail(P, s->line, NULL, "needs kind = polyline, polygon, disc, sprite or text");
            g->kind = (isk_drawing_kind)k;
        }
        if (check_kinds(P, s, g->kind, "kind", sk_drawing_names, "drawing"))
            return 1;
        if (g->kind == ISK_DRAWING_POLYLINE || g->kind == ISK_DRAWING_POLYGON)
            return require(P, s, K_DRAW_POINTS, "points", "x0, y0, x1, y1, ...");
        if (require(P, s, K_DRAW_POSITION, "position", "x, y"))
            return 1;
        if (g->kind == ISK_DRAWING_DISC)
            return require(P, s, K_DRAW_RADIUS, "radius", "the disc's radius");
        if (g->kind == ISK_DRAWING_SPRITE)
            return require(P, s, K_DRAW_SIZE, "size", "the sprite's diameter");
        return require(P, s, K_DRAW_TEXT, "text", "what to write");
    }
    case SK_CLICK:
        if (SEEN(s, K_CLICK_EMITTER)) {
            int idx = isk_effect_def_find_emitter(d, s->emitter_ref);
            if (idx < 0) {
                const char *names[ISK_EFFECT_MAX_EMITTERS];
                for (int i = 0; i < d->nemitters; i++)
                    names[i] = d->emitters[i].name;
                char hint[80];
                suggest_names(hint, sizeof hint, s->emitter_ref, names, d->nemitters, "'", "'");
                return key_fail(P, s->key_line[K_CLICK_EMITTER], "emitter", "no emitter named '%s'%s",
                                s->emitter_ref, hint);
            }
            d->click_emitter = idx;
        }
        return 0;
    default:
        return 0;
    }
}

/* ---- pre-scan ------------------------------------------------------------- */

static void syntax(parser *P, int line, const char *msg)
{
    if (!P->syntax_line) {
        P->syntax_line = line;
        snprintf(P->syntax_msg, sizeof P->syntax_msg, "%s", msg);
    }
}

/* libinih's inline-comment rule: ';' at the start or after a blank. */
static const char *find_chars_or_comment(const char *s, const char *end, const char *chars)
{
    int was_space = 0;
    for (; s < end; s++) {
        if (strchr(chars, *s) || (was_space && *s == ';'))
            return s;
        was_space = isspace((unsigned char)*s);
    }
    return end;
}

/* Copies text into buf without leading blanks on each line, records headers
 * and cuts the text at the first syntax error. */
static int prescan(parser *P, const char *text, char *buf)
{
    const char *p = text;
    char *o = buf;
    char *cut = NULL;
    int line = 0;
    while (*p) {
        line++;
        const char *nl = strchr(p, '\n');
        const char *end = nl ? nl : p + strlen(p);
        char *line_start = o;
        if ((size_t)(end - p) > ISK_INI_MAX_LINE && !P->syntax_line) {
            char m[80];
            snprintf(m, sizeof m, "line too long (at most %d characters)", ISK_INI_MAX_LINE);
            syntax(P, line, m);
            cut = line_start;
        }
        const char *s = p;
        if (line == 1 && (unsigned char)s[0] == 0xEF && (unsigned char)s[1] == 0xBB && (unsigned char)s[2] == 0xBF)
            s += 3;
        while (s < end && isspace((unsigned char)*s))
            s++;
        const char *e = end;
        while (e > s && isspace((unsigned char)e[-1]))
            e--;
        memcpy(o, s, (size_t)(end - s));
        const char *ls = o; /* stripped line in buf */
        o += end - s;
        if (nl)
            *o++ = '\n';
        p = nl ? nl + 1 : end;
        if (P->syntax_line)
            continue;
        size_t len = (size_t)(e - s);
        if (len == 0 || *s == ';' || *s == '#')
            continue;
        if (*s == '[') {
            const char *close = find_chars_or_comment(s + 1, e, "]");
            if (close == e || *close != ']') {
                syntax(P, line, "section header without ']'");
                cut = line_start;
                continue;
            }
            const char *after = close + 1;
            while (after < e && (*after == ' ' || *after == '\t'))
                after++;
            if (after < e && *after != ';' && *after != '#') {
                syntax(P, line, "unexpected text after ']' (a comment starts with ';')");
                cut = line_start;
                continue;
            }
            if (P->nhdr >= MAX_SECTIONS + 1) {
                char m[80];
                snprintf(m, sizeof m, "too many sections (at most %d)", MAX_SECTIONS);
                syntax(P, line, m);
                cut = line_start;
                continue;
            }
            if (P->nhdr % 32 == 0) {
                header *a = realloc(P->hdr, sizeof *a * (size_t)(P->nhdr + 32));
                if (!a)
                    return 1;
                P->hdr = a;
            }
            P->hdr[P->nhdr].line = line;
            P->hdr[P->nhdr].text = ls + 1;
            P->hdr[P->nhdr].len = (size_t)(close - s - 1);
            P->nhdr++;
            continue;
        }
        const char *eq = find_chars_or_comment(s, e, "=:");
        if (eq == e || (*eq != '=' && *eq != ':')) {
            syntax(P, line, "cannot parse this line: expected [section], key = value, or a ; comment");
            cut = line_start;
            continue;
        }
        const char *ke = eq;
        while (ke > s && isspace((unsigned char)ke[-1]))
            ke--;
        if (ke == s) {
            syntax(P, line, "missing key name before '='");
            cut = line_start;
        }
    }
    *o = 0;
    if (cut)
        *cut = 0; /* libinih sees only the lines before the syntax error */
    return 0;
}

/* ---- entry points ----------------------------------------------------------- */

isk_status isk_scene_load_string(isk_effect_def *out, const char *text, const char *name, isk_error *err)
{
    if (!out)
        return isk_error_set(err, ISK_ERR_NULL, "scene: NULL definition");
    isk_effect_def_init(out);
    if (!text)
        return isk_error_set(err, ISK_ERR_NULL, "scene: NULL text");
    if (!name)
        name = "<string>";
    size_t len = strlen(text);
    if (len > ISK_INI_MAX_BYTES)
        return isk_error_set(err, ISK_ERR_SIZE, "%s: scene larger than %u bytes", name, ISK_INI_MAX_BYTES);
    isk_error local;
    if (!err)
        err = &local;
    parser P;
    memset(&P, 0, sizeof P);
    P.d = out;
    P.name = name;
    P.err = err;
    P.cur = -1;
    char *buf = malloc(len + 1);
    isk_status st = ISK_OK;
    if (!buf || prescan(&P, text, buf)) {
        st = isk_error_set(err, ISK_ERR_NOMEM, "%s: out of memory", name);
        goto done;
    }
    st = isk_ini_parse_string(buf, name, on_key, &P, err);
    if (st != ISK_OK)
        goto done;
    if (P.syntax_line) {
        /* headers above the bad line may still be wrong themselves */
        if (open_headers_before(&P, P.syntax_line)) {
            st = err->status;
            goto done;
        }
        isk_ini_error(err, name, P.syntax_line, "%s", P.syntax_msg);
        st = ISK_ERR_FORMAT;
        goto done;
    }
    if (open_headers_before(&P, 1 << 30)) {
        st = err->status;
        goto done;
    }
    for (int i = 0; i < P.nsec; i++)
        if (finish_section(&P, i)) {
            st = err->status;
            goto done;
        }
done:
    free(buf);
    free(P.hdr);
    free(P.sec);
    if (st != ISK_OK) {
        if (st == ISK_OK)
            st = ISK_ERR_FORMAT;
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
    isk_status rs = isk_ini_read_file(path, &buf, err);
    if (rs != ISK_OK)
        return rs;
    isk_status s = isk_scene_load_string(out, buf, path, err);
    free(buf);
    return s;
}
