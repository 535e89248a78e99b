/* SPDX-License-Identifier: MIT */
/* One key of the running scene as the widget its row of the key table
 * calls for (the inspector's rows, play_inspector.c):
 *
 *   a number with both bounds   a slider over the row's range (logarithmic
 *                               when it spans more than three decades) and
 *                               a field for the exact value
 *   a boolean                   a check box
 *   an enum                     a choice of its names (and the words that
 *                               stand for other values: an emitter's
 *                               integrator "scene")
 *   a colour                    its swatch and a field
 *   colour stops                the ramp drawn, and a field under it
 *   anything else               a field
 *
 * Every value shown is isk_effect_get's and every change goes through
 * isk_effect_set, so ranges, names and messages are the key table's; a
 * refused value stays in its field with the table's message. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/gradient.h"
#include "play.h"
#include "play_shadow.h"

#define U(n) isk_ui_px(&p->ui, (n))

typedef enum widget_kind { W_FIELD = 0, W_SLIDER, W_TOGGLE, W_CHOICE, W_COLOR, W_RAMP } widget_kind;

static int is_number(isk_key_type t)
{
    return t == ISK_KEY_NUMBER || t == ISK_KEY_WHOLE || t == ISK_KEY_LONG || t == ISK_KEY_COUNT || t == ISK_KEY_ANGLE;
}

static widget_kind widget_of(const isk_key *k)
{
    switch (k->type) {
    case ISK_KEY_BOOL: return W_TOGGLE;
    case ISK_KEY_ENUM: return W_CHOICE;
    case ISK_KEY_COLOR: return W_COLOR;
    case ISK_KEY_COLOR_STOPS: return W_RAMP;
    default:
        /* A word ("forever", "off") is no place on a track: those get a field. */
        return is_number(k->type) && k->lo_bound && k->hi_bound && !k->words ? W_SLIDER : W_FIELD;
    }
}

int play_key_widget_rows(const isk_key *k) { return widget_of(k) == W_RAMP ? 2 : 1; }

/* isk_effect_set; a refusal's message goes to the field `id`. */
static void set(player *p, const char *id, const play_item *it, const isk_key *k, const char *value)
{
    isk_error err;
    if (isk_effect_set(p->fx, it->name, k->name, value, &err) != ISK_OK)
        isk_ui_field_error(&p->ui, id, err.message);
    else
        play_shadow_set(p, it->name, k->name, value);
}

/* The field showing `value`; what is typed goes to isk_effect_set. */
static void field(player *p, const char *id, isk_ui_rect r, const play_item *it, const isk_key *k, const char *value)
{
    /* Plain numbers take only what a number is made of; lists, words and text anything. */
    const unsigned flags = is_number(k->type) && !k->words && k->type != ISK_KEY_ANGLE ? ISK_UI_FIELD_NUMBER : 0;
    char typed[ISK_UI_EDIT_MAX];
    if (isk_ui_field(&p->ui, id, r, value, flags, typed, sizeof typed) == ISK_UI_FIELD_APPLY)
        set(p, id, it, k, typed);
}

/* ---- the slider ---------------------------------------------------------------------------- */

static int is_whole(const isk_key *k)
{
    return k->type == ISK_KEY_WHOLE || k->type == ISK_KEY_LONG || k->type == ISK_KEY_COUNT;
}

/* The number a value's text stands for (an angle's in degrees, as its
 * range is): "90", "1.5707963267948966 rad". */
static double number_of(const isk_key *k, const char *text)
{
    char *end;
    double v = strtod(text, &end);
    if (k->type == ISK_KEY_ANGLE && strstr(end, "rad"))
        v *= 180.0 / 3.14159265358979323846;
    return v;
}

/* The track's ends: the row's range; an exclusive bound moved in by a
 * little, so the track's end is a value the key takes. */
static void track_of(const isk_key *k, double *lo, double *hi)
{
    const double span = k->max - k->min, nudge = is_whole(k) ? 1 : 1e-6 * (span < 1 ? span : 1);
    *lo = k->lo_bound == ISK_BOUND_EXCL ? k->min + nudge : k->min;
    *hi = k->hi_bound == ISK_BOUND_EXCL ? k->max - nudge : k->max;
}

static void slider(player *p, const char *id, isk_ui_rect r, const play_item *it, const isk_key *k, const char *value)
{
    isk_ui *ui = &p->ui;
    isk_ui_rect f = isk_ui_cut_right(&r, r.w * 2 / 5);
    isk_ui_cut_right(&r, U(4));
    double lo, hi, v = number_of(k, value);
    track_of(k, &lo, &hi);
    char sid[ISK_UI_ID_MAX];
    snprintf(sid, sizeof sid, "%s/slider", id);
    /* More than three decades: every decade the same length (linear below one step). */
    const int whole = is_whole(k);
    const double step = whole ? 1 : 0.01;
    const int changed = hi - lo > 1000 * step ? isk_ui_slider_log(ui, sid, r, &v, lo, hi, step, whole)
                                              : isk_ui_slider(ui, sid, r, &v, lo, hi, whole ? 1 : 0);
    if (changed) {
        char text[48];
        snprintf(text, sizeof text, whole ? "%.0f" : "%.6g", v);
        set(p, id, it, k, text);
    }
    field(p, id, f, it, k, value);
}

/* ---- choice, toggle, colours ---------------------------------------------------------------- */

/* An enum's options: its names, then the words for values no name has
 * (a word for a named value is an old spelling: osc_table's true). */
static int options(const isk_key *k, const char **out, int max)
{
    int n = 0;
    for (int i = 0; i < k->nnames && n < max; i++)
        out[n++] = k->names[i];
    for (int i = 0; k->words && k->words[i].word && n < max; i++) {
        const double v = k->words[i].value;
        if (!(v >= 0 && v < k->nnames && v == floor(v)))
            out[n++] = k->words[i].word;
    }
    return n;
}

static void choice(player *p, const char *id, isk_ui_rect r, const play_item *it, const isk_key *k, const char *value)
{
    const char *labels[ISK_UI_CHOICE_MAX];
    const int n = options(k, labels, ISK_UI_CHOICE_MAX);
    int sel = -1;
    for (int i = 0; i < n; i++)
        if (!strcmp(labels[i], value))
            sel = i;
    if (isk_ui_choice(&p->ui, id, r, labels, n, &sel))
        set(p, id, it, k, labels[sel]);
}

static void toggle(player *p, const char *id, isk_ui_rect r, const play_item *it, const isk_key *k, const char *value)
{
    int on = !strcmp(value, "true");
    if (isk_ui_toggle(&p->ui, id, r, on ? "on" : "off", &on))
        set(p, id, it, k, on ? "true" : "false");
}

/* The field's value in the definition (its row's offset into the item). */
static const void *field_of(const player *p, const play_item *it, const isk_key *k)
{
    const char *item = isk_key_item(isk_effect_definition(p->fx), it->section, it->index);
    return item ? item + k->offset : NULL;
}

static void colour(player *p, const char *id, isk_ui_rect r, const play_item *it, const isk_key *k, const char *value)
{
    const isk_color *c = field_of(p, it, k);
    isk_ui_rect sw = isk_ui_cut_left(&r, r.h * 2);
    isk_ui_cut_left(&r, U(4));
    if (c)
        isk_ui_swatches(&p->ui, sw, c, 1);
    field(p, id, r, it, k, value);
}

/* The ramp over a particle's life, left (birth) to right (death); "off":
 * the emitter's colour. */
static void ramp(player *p, const char *id, isk_ui_rect r, isk_ui_rect below, const play_item *it, const isk_key *k,
                 const char *value)
{
    const isk_color_ramp *cr = field_of(p, it, k);
    isk_color samples[64];
    int n = 0;
    if (cr && cr->n > 0) {
        for (n = 0; n < 64; n++)
            samples[n] = isk_color_gradient_eval(cr->stops, cr->n, n / 63.0);
    } else {
        const isk_key *base = isk_key_find(it->section, "color");
        const isk_color *c = base ? field_of(p, it, base) : NULL;
        if (c)
            samples[n++] = *c;
    }
    if (n)
        isk_ui_swatches(&p->ui, isk_ui_inset(r, U(2)), samples, n);
    field(p, id, below, it, k, value);
}

void play_key_widget(player *p, const char *id, isk_ui_rect r, isk_ui_rect second, const play_item *it,
                     const isk_key *k)
{
    char value[ISK_UI_EDIT_MAX];
    isk_error err;
    if (isk_effect_get(p->fx, it->name, k->name, value, sizeof value, &err) != ISK_OK)
        snprintf(value, sizeof value, "?");
    switch (widget_of(k)) {
    case W_SLIDER: slider(p, id, r, it, k, value); break;
    case W_TOGGLE: toggle(p, id, r, it, k, value); break;
    case W_CHOICE: choice(p, id, r, it, k, value); break;
    case W_COLOR: colour(p, id, r, it, k, value); break;
    case W_RAMP: ramp(p, id, r, second, it, k, value); break;
    default: field(p, id, r, it, k, value); break;
    }
}
