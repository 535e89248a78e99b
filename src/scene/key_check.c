/* SPDX-License-Identifier: MIT */
/* A field's value checked against its row (see key_value.h): what
 * isk_effect_create runs for C definitions, with the parser's messages. */
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

/* ---- check -------------------------------------------------------------------- */

static isk_status refused(const isk_key *k, const void *item, const isk_effect_def *d, char *why, size_t n)
{
    char got[MAX_TEXT];
    if (isk__fx_key_format(k, item, d, got, sizeof got) != 0)
        snprintf(got, sizeof got, "?");
    return isk__fx_expected(k, why, n, got);
}

static int numbers_ok(const isk_key *k, const double *v, int count)
{
    for (int i = 0; i < count; i++)
        if (!isfinite(v[i]) || !isk__fx_in_range(k, v[i]))
            return 0;
    return 1;
}

isk_status isk__fx_key_check(const isk_key *k, const void *item, const isk_effect_def *d, char *why, size_t n)
{
    switch (k->type) {
    case ISK_KEY_NUMBER: {
        double v = *FX_AT_C(double, item, k->offset);
        if (isk__fx_word_of(k, v) || (isfinite(v) && isk__fx_in_range(k, v)))
            return ISK_OK;
        return refused(k, item, d, why, n);
    }
    case ISK_KEY_WHOLE:
    case ISK_KEY_LONG:
    case ISK_KEY_COUNT: {
        double v = isk__fx_whole_get(k, item);
        return isk__fx_word_of(k, v) || isk__fx_in_range(k, v) ? ISK_OK : refused(k, item, d, why, n);
    }
    case ISK_KEY_BOOL: {
        int v = *FX_AT_C(int, item, k->offset);
        return v == 0 || v == 1 ? ISK_OK : refused(k, item, d, why, n);
    }
    case ISK_KEY_ENUM: {
        int v = *FX_AT_C(int, item, k->offset);
        return (v >= 0 && v < k->nnames) || isk__fx_word_of(k, v) ? ISK_OK : refused(k, item, d, why, n);
    }
    case ISK_KEY_VECTOR:
    case ISK_KEY_NUMBERS4: {
        const double *v = FX_AT_C(double, item, k->offset);
        return numbers_ok(k, v, k->type == ISK_KEY_VECTOR ? 2 : 4) ? ISK_OK : refused(k, item, d, why, n);
    }
    case ISK_KEY_POINT: {
        int given = *FX_AT_C(int, item, k->aux);
        const double *v = FX_AT_C(double, item, k->offset);
        return given == 0 || (given == 1 && numbers_ok(k, v, 2)) ? ISK_OK : refused(k, item, d, why, n);
    }
    case ISK_KEY_ANGLE: {
        double v = *FX_AT_C(double, item, k->offset);
        isk_key r = *k;
        r.min = k->min * (PI / 180.0);
        r.max = k->max * (PI / 180.0);
        return isk__fx_word_of(k, v) || (isfinite(v) && isk__fx_in_range(&r, v)) ? ISK_OK
                                                                                   : refused(k, item, d, why, n);
    }
    case ISK_KEY_PAIR: {
        const double *v = FX_AT_C(double, item, k->offset);
        if (!numbers_ok(k, v, 2))
            return refused(k, item, d, why, n);
        if (v[0] > v[1]) {
            snprintf(why, n, "min (%.15g) is greater than max (%.15g)", v[0], v[1]);
            return ISK_ERR_RANGE;
        }
        return ISK_OK;
    }
    case ISK_KEY_COLOR_STOPS: {
        const isk_color_ramp *r = FX_AT_C(isk_color_ramp, item, k->offset);
        if (r->n == 0 || (r->n > 0 && r->n <= ISK_GRADIENT_MAX_STOPS && isk_color_stops_check(r->stops, r->n) == ISK_OK))
            return ISK_OK;
        snprintf(why, n, "1..%d stops with t strictly increasing in [0, 1] expected", ISK_GRADIENT_MAX_STOPS);
        return ISK_ERR_RANGE;
    }
    case ISK_KEY_SCALAR_STOPS: {
        const isk_scalar_ramp *r = FX_AT_C(isk_scalar_ramp, item, k->offset);
        if (r->n == 0)
            return ISK_OK;
        if (r->n < 0 || r->n > ISK_GRADIENT_MAX_STOPS || isk_scalar_stops_check(r->stops, r->n) != ISK_OK) {
            snprintf(why, n, "1..%d finite stops with t strictly increasing in [0, 1] expected",
                     ISK_GRADIENT_MAX_STOPS);
            return ISK_ERR_RANGE;
        }
        for (int i = 0; i < r->n; i++)
            if (!isk__fx_in_range(k, r->stops[i].value)) {
                char want[120];
                isk__fx_range_words(k, "a number", want, sizeof want);
                snprintf(why, n, "stop %d: expected %s, got \"%.17g\"", i + 1, want, r->stops[i].value);
                return ISK_ERR_RANGE;
            }
        return ISK_OK;
    }
    case ISK_KEY_TEXT:
        if (memchr(FX_AT_C(char, item, k->offset), 0, k->aux))
            return ISK_OK;
        snprintf(why, n, "text longer than %zu characters (or not terminated)", k->aux - 1);
        return ISK_ERR_RANGE;
    case ISK_KEY_SIDES:
        return *FX_AT_C(unsigned, item, k->offset) & ~(unsigned)ISK_SIDE_ALL ? refused(k, item, d, why, n) : ISK_OK;
    case ISK_KEY_POINTS: {
        const double *pts = *FX_AT_C(double *, item, k->offset);
        int count = *FX_AT_C(int, item, k->aux);
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
        const int *idx = FX_AT_C(int, item, k->offset);
        int count = *FX_AT_C(int, item, k->aux);
        const int cap = isk__fx_refs_cap(k->refers);
        int total = d ? isk__fx_section_items(d, k->refers) : 0;
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
                    snprintf(why, n, "'%s' is listed twice", isk__fx_item_name(d, k->refers, idx[i]));
                    return ISK_ERR_RANGE;
                }
        }
        return ISK_OK;
    }
    case ISK_KEY_REF: {
        int v = *FX_AT_C(int, item, k->offset);
        int total = d ? isk__fx_section_items(d, k->refers) : 0;
        if (v >= -1 && v < total)
            return ISK_OK;
        snprintf(why, n, "%s %d does not exist", isk_section_name(k->refers), v);
        return ISK_ERR_RANGE;
    }
    default:
        return ISK_OK; /* SEED, COLOR: every value is valid */
    }
}
