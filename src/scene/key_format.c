/* SPDX-License-Identifier: MIT */
/* Field -> text that parses back to the same bits (see key_value.h), and
 * the table's defaults set through the parser. */
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

/* ---- format ------------------------------------------------------------------- */

static isk_status put(char *buf, size_t n, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;


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
    const char *name = isk__scv_color_name(c);
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

isk_status isk__fx_key_format(const isk_key *k, const void *item, const isk_effect_def *d, char *buf, size_t n)
{
    char t[40];
    if (n == 0)
        return ISK_ERR_RANGE;
    switch (k->type) {
    case ISK_KEY_NUMBER: {
        double v = *FX_AT_C(double, item, k->offset);
        const char *w = isk__fx_word_of(k, v);
        if (w)
            return put(buf, n, "%s", w);
        num(t, sizeof t, v);
        return put(buf, n, "%s", t);
    }
    case ISK_KEY_WHOLE:
    case ISK_KEY_LONG:
    case ISK_KEY_COUNT: {
        double v = isk__fx_whole_get(k, item); /* exact: every accepted value is below 2^53 */
        const char *w = isk__fx_word_of(k, v);
        return w ? put(buf, n, "%s", w) : put(buf, n, "%.0f", v);
    }
    case ISK_KEY_SEED: return put(buf, n, "%llu", (unsigned long long)*FX_AT_C(uint64_t, item, k->offset));
    case ISK_KEY_BOOL: return put(buf, n, "%s", *FX_AT_C(int, item, k->offset) ? "true" : "false");
    case ISK_KEY_COLOR: return colour_text(buf, n, *FX_AT_C(isk_color, item, k->offset));
    case ISK_KEY_ENUM: {
        /* A value's name first: a word for a named value is an old
         * spelling (osc_table's true = floor); words name the others
         * (an emitter's integrator "scene"). */
        int v = *FX_AT_C(int, item, k->offset);
        if (v >= 0 && v < k->nnames)
            return put(buf, n, "%s", k->names[v]);
        const char *w = isk__fx_word_of(k, v);
        return put(buf, n, "%s", w ? w : "?");
    }
    case ISK_KEY_VECTOR:
    case ISK_KEY_PAIR: return numbers_text(buf, n, FX_AT_C(double, item, k->offset), 2);
    case ISK_KEY_NUMBERS4: return numbers_text(buf, n, FX_AT_C(double, item, k->offset), 4);
    case ISK_KEY_POINT:
        if (!*FX_AT_C(int, item, k->aux))
            return put(buf, n, "none");
        return numbers_text(buf, n, FX_AT_C(double, item, k->offset), 2);
    case ISK_KEY_ANGLE: {
        /* Degrees when they read back to the same radians, else radians. */
        double r = *FX_AT_C(double, item, k->offset);
        const char *w = isk__fx_word_of(k, r);
        if (w)
            return put(buf, n, "%s", w);
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
        const isk_color_ramp *cr = FX_AT_C(isk_color_ramp, item, k->offset);
        const isk_scalar_ramp *sr = FX_AT_C(isk_scalar_ramp, item, k->offset);
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
    case ISK_KEY_TEXT: return put(buf, n, "%.*s", (int)k->aux, FX_AT_C(char, item, k->offset));
    case ISK_KEY_SIDES: {
        unsigned s = *FX_AT_C(unsigned, item, k->offset);
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
        const double *pts = *FX_AT_C(double *, item, k->offset);
        int count = *FX_AT_C(int, item, k->aux);
        if (!pts || count <= 0)
            return put(buf, n, "%s", "");
        return numbers_text(buf, n, pts, 2 * count);
    }
    case ISK_KEY_REFS: {
        const int *idx = FX_AT_C(int, item, k->offset);
        int count = *FX_AT_C(int, item, k->aux);
        if (count <= 0) /* a list of emitters: every emitter */
            return put(buf, n, "%s", k->refers == ISK_SECTION_EMITTER ? "all" : "none");
        size_t used = 0;
        for (int i = 0; i < count; i++) {
            if (put(buf + used, n - used, "%s%s", i ? ", " : "", d ? isk__fx_item_name(d, k->refers, idx[i]) : "?"))
                return ISK_ERR_RANGE;
            used += strlen(buf + used);
        }
        return ISK_OK;
    }
    case ISK_KEY_REF: {
        int v = *FX_AT_C(int, item, k->offset);
        return put(buf, n, "%s", v >= 0 && d ? isk__fx_item_name(d, k->refers, v) : "");
    }
    default: return ISK_ERR_RANGE;
    }
}


/* ---- defaults ------------------------------------------------------------------ */

isk_status isk__fx_key_set_default(const isk_key *k, void *item)
{
    /* An empty default means "none" except for a reference, where it is the
     * first item (-1). */
    if (!k->dflt || (!*k->dflt && k->type != ISK_KEY_REF) || k->type == ISK_KEY_REFS || k->type == ISK_KEY_POINTS)
        return ISK_OK;
    char why[160];
    return isk__fx_key_parse(k, item, k->dflt, NULL, why, sizeof why);
}

void isk__fx_section_defaults(isk_section_kind s, void *item)
{
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        if (k->section == s)
            isk__fx_key_set_default(k, item);
    }
}
