/* SPDX-License-Identifier: MIT */
/* The thesis's console, control for control (its figures 21-25), beside
 * and below the canvas, plus what iskra adds:
 *
 *   beside the canvas   play, pause, stop, reset, reload, step; the speed
 *                       slider (f = 1 + 29*(1000 - s)/999); precision,
 *                       particles, explosion count, gravity, drag; the walls
 *                       as a square of four bars
 *   beside that         energy and particle-count charts, integrators with
 *                       their measured cost and energy drift
 *   below               click modes; the potentials (list, On/Off, charge, k,
 *                       P, max, min, x influence, x, y); the layer (count and
 *                       rectangle, at reset); save, screenshots, panel; keys;
 *                       the last message, whole
 *
 * On small screens (play_layout.c) the same parts stand in three columns
 * beside the canvas: the console and the click modes; the potentials and
 * the layer; the charts, integrators, files and messages.
 *
 * Every value shown is isk_effect_get of a key and every edit goes through
 * isk_effect_set (play_fields.c): ranges, names and messages are the key
 * table's.  The canvas is a widget too (play_canvas): clicks set off the
 * chosen explosion or add a potential, a potential's disc is picked and
 * dragged. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "iskra/keys.h"
#include "iskra/text.h"
#include "play.h"
#include "play_shadow.h"


/* ---- small helpers -------------------------------------------------------------------- */

#define U(n) isk_ui_px(&p->ui, (n))

static isk_ui_rect row(player *p, isk_ui_rect *area)
{
    isk_ui_rect r = isk_ui_cut_top(area, isk_ui_row_height(&p->ui));
    isk_ui_cut_top(area, U(GAP));
    return r;
}

/* "Label" on the left of a row, the rest for the widget. */
static isk_ui_rect labelled(player *p, isk_ui_rect *area, const char *label, int label_w)
{
    isk_ui_rect r = row(p, area);
    isk_ui_label(&p->ui, isk_ui_cut_left(&r, label_w), label, ISK_UI_LEFT);
    return r;
}

/* ---- beside the canvas ------------------------------------------------------------------ */

typedef struct button_look {
    play_action action;
    isk_ui_icon icon;
    isk_color color;
} button_look;

/* The thesis's colours: green play, blue pause, yellow stop, red reload. */
static const button_look buttons[] = {
    {PLAY_PLAY, ISK_UI_ICON_PLAY, {0x44, 0x8e, 0x44, 255}},   {PLAY_PAUSE, ISK_UI_ICON_PAUSE, {0x20, 0x67, 0xb9, 255}},
    {PLAY_STOP, ISK_UI_ICON_STOP, {0xbb, 0x96, 0x1c, 255}},   {PLAY_RESET, ISK_UI_ICON_RESET, {0xc8, 0x6a, 0x1e, 255}},
    {PLAY_RELOAD, ISK_UI_ICON_RELOAD, {0xd8, 0x2a, 0x1e, 255}}, {PLAY_STEP, ISK_UI_ICON_STEP, {0x5a, 0x5a, 0x66, 255}},
};

static void walls(player *p, isk_ui_rect box)
{
    isk_ui_box(&p->ui, box);
    isk_ui_rect in = isk_ui_inset(box, U(MARGIN));
    isk_ui_label(&p->ui, isk_ui_cut_top(&in, isk_ui_row_height(&p->ui)), "Walls", ISK_UI_CENTER);
    char sides[80];
    isk_error err;
    if (isk_effect_get(p->fx, "bounds", "sides", sides, sizeof sides, &err) != ISK_OK)
        return;
    /* The square: a bar on each side, corners left open. */
    int size = in.w < in.h ? in.w : in.h;
    const int t = U(6), g = U(2);
    isk_ui_rect sq = {in.x + (in.w - size) / 2, in.y + (in.h - size) / 2, size, size};
    const isk_ui_rect bar[4] = {
        {sq.x + t + g, sq.y, sq.w - 2 * (t + g), t},            /* top */
        {sq.x + sq.w - t, sq.y + t + g, t, sq.h - 2 * (t + g)}, /* right */
        {sq.x + t + g, sq.y + sq.h - t, sq.w - 2 * (t + g), t}, /* bottom */
        {sq.x, sq.y + t + g, t, sq.h - 2 * (t + g)},            /* left */
    };
    static const char *const names[4] = {"top", "right", "bottom", "left"};
    const isk_key *k = isk_key_find(ISK_SECTION_BOUNDS, "sides");
    const int all = !strcmp(sides, "all");
    int on[4], changed = 0;
    for (int i = 0; i < 4; i++) {
        on[i] = all || strstr(sides, names[i]) != NULL;
        char id[16];
        snprintf(id, sizeof id, "wall-%s", names[i]);
        changed |= isk_ui_toggle_bar(&p->ui, id, bar[i], &on[i]);
    }
    if (!changed || !k)
        return;
    /* Back into the key's own words (its names, in its order). */
    char v[80] = "";
    size_t used = 0;
    for (int n = 0; n < k->nnames; n++)
        for (int i = 0; i < 4; i++)
            if (on[i] && !strcmp(k->names[n], names[i]))
                used += (size_t)snprintf(v + used, sizeof v - used, "%s%s", used ? ", " : "", names[i]);
    play_set(p, "bounds", "sides", used ? v : "none");
}

static void explosion_count(player *p, isk_ui_rect r)
{
    char value[32], typed[64];
    isk_error err;
    if (isk_effect_get(p->fx, "click", "count", value, sizeof value, &err) != ISK_OK)
        return;
    if (isk_ui_field(&p->ui, "explosion-count", r, value, ISK_UI_FIELD_NUMBER, typed, sizeof typed) !=
        ISK_UI_FIELD_APPLY)
        return;
    if (isk_effect_set(p->fx, "click", "count", typed, &err) == ISK_OK) {
        play_shadow_set(p, "click", "count", typed);
        p->count_refused = 0;
        return;
    }
    isk_ui_field_error(&p->ui, "explosion-count", err.message);
    /* The thesis validates the count only at the click, and then does nothing. */
    if (isk_effect_definition(p->fx)->fidelity == ISK_FIDELITY_THESIS)
        p->count_refused = 1;
}

void play_transport(player *p, isk_ui_rect *a)
{
    isk_ui *ui = &p->ui;
    /* the buttons, with their keys under the pictures (three lines of text
     * tall at least); in two rows when one is too narrow for the keys */
    const int line_h = isk_ui_line_height(ui);
    const int button_h = U(30) > 3 * line_h + U(2) ? U(30) : 3 * line_h + U(2);
    const int nb = (int)(sizeof buttons / sizeof buttons[0]);
    int widest = 0; /* the widest key at text scale 1 (a button writes its key smaller when it must) */
    for (int i = 0; i < nb; i++) {
        int w = isk_font_text_width(ui->font, play_action_at(buttons[i].action)->keys, 1) - 1;
        widest = w > widest ? w : widest;
    }
    const int rows = (a->w - (nb - 1) * U(3)) / nb - U(2) < widest ? 2 : 1, per_row = (nb + rows - 1) / rows;
    isk_ui_rect line = isk_ui_cut_top(a, rows * button_h + (rows - 1) * U(3));
    isk_ui_cut_top(a, U(8));
    for (int i = 0; i < nb; i++) {
        const play_action_info *ai = play_action_at(buttons[i].action);
        if (isk_ui_icon_button(ui, ai->id, isk_ui_cell(line, per_row, rows, i % per_row, i / per_row, U(3)),
                               buttons[i].icon, buttons[i].color, ai->keys))
            play_do(p, buttons[i].action);
    }
    /* speed */
    isk_ui_rect r = labelled(p, a, "Speed", U(40));
    if (isk_ui_slider(ui, "speed", r, &p->slider, 1, 1000, 1)) {
        char v[40];
        snprintf(v, sizeof v, "%.17g", play_divisor_of_slider(p->slider));
        play_set(p, "scene", "speed_divisor", v);
    }
    char speed[96];
    const isk_effect_def *d = isk_effect_definition(p->fx);
    snprintf(speed, sizeof speed, "f = %.4g: each frame %.3g ms", d->speed_divisor, 1000 * d->dt / d->speed_divisor);
    isk_ui_rect st = isk_ui_cut_top(a, U(10) > line_h ? U(10) : line_h);
    isk_ui_text(ui, st, speed, ui->style.dim, ISK_UI_RIGHT);
    isk_ui_cut_top(a, U(GAP));
}

/* A field's refused value's message, in the flow of the column (it pushes
 * what follows down instead of covering it). */
static void message_under(player *p, const char *id, isk_ui_rect *a)
{
    isk_ui_field_message(&p->ui, id, a);
}

/* Buttons, speed, the fields and the walls, in the panel `box`. */
static void console(player *p, isk_ui_rect box, isk_ui_rect *rest)
{
    isk_ui *ui = &p->ui;
    isk_ui_panel(ui, box);
    isk_ui_rect a = isk_ui_inset(box, U(MARGIN));
    play_transport(p, &a);
    /* the fields, each refused value's message under its field */
    char sec[ISK_NAME_MAX + 16], count[32];
    play_precision_field(p, "precision", labelled(p, &a, "Precision", U(LABEL_W)));
    message_under(p, "precision", &a);
    snprintf(count, sizeof count, "%zu", isk_effect_particle_count(p->fx));
    isk_ui_field(ui, "particles", labelled(p, &a, "Particles", U(LABEL_W)), count, ISK_UI_FIELD_READONLY, NULL, 0);
    explosion_count(p, labelled(p, &a, "Explosions", U(LABEL_W)));
    message_under(p, "explosion-count", &a);
    play_key_field(p, "gravity", labelled(p, &a, "Gravity", U(LABEL_W)),
                   play_force_section(p->fx, ISK_FORCE_GRAVITY, sec, sizeof sec), "g");
    message_under(p, "gravity", &a);
    play_key_field(p, "drag", labelled(p, &a, "Drag", U(LABEL_W)),
                   play_force_section(p->fx, ISK_FORCE_DRAG, sec, sizeof sec), "b");
    message_under(p, "drag", &a);
    isk_ui_cut_top(&a, U(GAP));
    /* the walls */
    int wall = a.w < U(96) ? a.w : U(96);
    walls(p, isk_ui_cut_top(&a, wall));
    if (rest)
        *rest = a;
}

/* ---- below: click modes, potentials, layer ------------------------------------------------ */

static const char *mode_label(int mode)
{
    if (mode == PLAY_CLICK_ADD_POTENTIAL)
        return "add potential";
    if (mode == PLAY_CLICK_NONE)
        return "none";
    return isk_explosion_names[mode];
}

/* The click modes: in one row after "Click" (per_row 0), or under it in
 * rows of per_row. */
static void click_modes(player *p, isk_ui_rect r, int per_row)
{
    /* The explosions the [click] key accepts, then the console's own two. */
    const char *labels[PLAY_CLICK_MODES];
    const isk_key *k = isk_key_find(ISK_SECTION_CLICK, "explosion");
    int n = isk_key_choices(k, labels, ISK_EXPLOSION_COUNT);
    labels[n++] = mode_label(PLAY_CLICK_ADD_POTENTIAL);
    labels[n++] = mode_label(PLAY_CLICK_NONE);
    if (per_row)
        isk_ui_label(&p->ui, isk_ui_cut_top(&r, isk_ui_row_height(&p->ui)), "Click", ISK_UI_LEFT);
    else
        isk_ui_label(&p->ui, isk_ui_cut_left(&r, U(34)), "Click", ISK_UI_LEFT);
    int mode = p->click_mode;
    if (isk_ui_radio(&p->ui, "click", r, labels, n, per_row, &mode))
        play_set_click_mode(p, mode);
}

/* The potential forces of the definition, in the order of isk_effect_potentials. */
static int potential_force(const isk_effect_def *d, int k)
{
    for (int i = 0, seen = 0; i < d->nforces; i++)
        if (d->forces[i].kind == ISK_FORCE_POTENTIAL && seen++ == k)
            return i;
    return -1;
}

/* The potentials' list and editor in `box`: the list left of the editor
 * (wide), or above it (compact).  Refused values' messages of the editor
 * and of the layer go under the editor. */
static void potentials(player *p, isk_ui_rect box, int stacked)
{
    isk_ui *ui = &p->ui;
    isk_ui_box(ui, box);
    isk_ui_rect a = isk_ui_inset(box, U(MARGIN));
    const isk_effect_def *d = isk_effect_definition(p->fx);
    size_t n;
    const isk_potential *pots = isk_effect_potentials(p->fx, &n);
    char rows_text[ISK_EFFECT_MAX_FORCES][ISK_NAME_MAX + 24];
    const char *rows[ISK_EFFECT_MAX_FORCES];
    for (size_t k = 0; k < n && k < ISK_EFFECT_MAX_FORCES; k++) {
        int f = potential_force(d, (int)k);
        snprintf(rows_text[k], sizeof rows_text[k], "%d %s%s", pots[k].id, f >= 0 ? d->forces[f].name : "?",
                 pots[k].enabled ? "" : " (off)");
        rows[k] = rows_text[k];
    }
    if (p->selected >= (int)n)
        p->selected = (int)n - 1;
    isk_ui_rect left;
    if (stacked) {
        left = isk_ui_cut_top(&a, 5 * isk_ui_row_height(ui) + U(GAP) + U(2));
        isk_ui_cut_top(&a, U(8));
    } else {
        left = isk_ui_cut_left(&a, U(112));
        isk_ui_cut_left(&a, U(8));
    }
    isk_ui_rect under = isk_ui_cut_bottom(&left, isk_ui_row_height(ui));
    isk_ui_cut_bottom(&left, U(GAP));
    isk_ui_list(ui, "potentials", left, rows, (int)n, &p->selected, &p->pot_scroll);
    const int sel = p->selected >= 0 && p->selected < (int)n ? p->selected : -1;
    const int f = sel >= 0 ? potential_force(d, sel) : -1;
    char sec[ISK_NAME_MAX + 16];
    const char *section = f >= 0 ? (snprintf(sec, sizeof sec, "force %s", d->forces[f].name), sec) : NULL;
    isk_ui_set_disabled(ui, section == NULL);
    if (isk_ui_button(ui, "pot-on", isk_ui_cell(under, 3, 1, 0, 0, U(3)), "On") && section)
        play_set(p, section, "enabled", "true");
    if (isk_ui_button(ui, "pot-off", isk_ui_cell(under, 3, 1, 1, 0, U(3)), "Off") && section)
        play_set(p, section, "enabled", "false");
    if (isk_ui_button(ui, "pot-delete", isk_ui_cell(under, 3, 1, 2, 0, U(3)), "Del") && section) {
        isk_error err;
        char name[ISK_NAME_MAX];
        snprintf(name, sizeof name, "%s", d->forces[f].name);
        if (isk_effect_remove_force(p->fx, name, &err) != ISK_OK) {
            play_say(p, "%s", err.message);
        } else {
            play_say(p, "potential %s removed", name);
            play_shadow_remove_force(p, name);
        }
    }
    isk_ui_set_disabled(ui, 0);
    /* the editor: two columns of label + field */
    static const struct {
        const char *id, *label, *key;
    } cells[] = {
        {"pot-charge", "Charge", "charge"}, {"pot-k", "k", "k"},
        {"pot-p", "P", "exponent"},         {"pot-max", "Max", "max_distance"},
        {"pot-min", "Min", "min_distance"}, {"pot-xinf", "x infl.", "x_multiplier"},
    };
    /* Where it is now (it may move, or have been dragged), to 6 digits: a
     * field holds no more, and typing sets it exactly. */
    char live[80] = "";
    if (section)
        snprintf(live, sizeof live, "%.6g, %.6g", pots[sel].r.x, pots[sel].r.y);
    const int rowh = isk_ui_row_height(ui), gap = U(GAP);
    /* the labels' column: the thesis layout's, or as wide as "x infl." */
    const int label_w = stacked ? isk_ui_text_width(ui, "x infl.") + U(4) : U(44);
    const int cols = stacked ? 1 : 2, nrows = 8 / cols; /* compact: one column, so values have room */
    for (int i = 0; i < 8; i++) {
        isk_ui_rect c = isk_ui_cell(a, cols, nrows, i % cols, i / cols, U(8));
        c.h = rowh;
        c.y = a.y + (i / cols) * (rowh + gap);
        const char *label = i < 6 ? cells[i].label : i == 6 ? "x" : "y";
        isk_ui_label(ui, isk_ui_cut_left(&c, label_w), label, ISK_UI_LEFT);
        if (i < 6)
            play_key_field(p, cells[i].id, c, section, cells[i].key);
        else
            play_key_part_field(p, i == 6 ? "pot-x" : "pot-y", c, section, "position", i - 6, section ? live : NULL);
    }
}

/* Under the potentials' editor: a refused value's message of its fields or
 * the layer's (drawn after both, so either can be refused). */
static void editor_message(player *p, isk_ui_rect box, int stacked)
{
    isk_ui_rect a = isk_ui_inset(box, U(MARGIN));
    const int rowh = isk_ui_row_height(&p->ui), gap = U(GAP);
    if (stacked)
        isk_ui_cut_top(&a, 5 * rowh + U(GAP) + U(2) + U(8) + 8 * (rowh + gap));
    else
        isk_ui_cut_left(&a, U(112) + U(8));
    if (!stacked)
        isk_ui_cut_top(&a, 4 * (rowh + gap));
    isk_ui_field_message(&p->ui, NULL, &a);
}

static void layer(player *p, isk_ui_rect box)
{
    isk_ui *ui = &p->ui;
    char sec[ISK_NAME_MAX + 16], live[40] = "", title[64];
    const char *section = play_layer_section(p->fx, sec, sizeof sec);
    const isk_key *k = isk_key_find(ISK_SECTION_EMITTER, "rect");
    if (k)
        isk_key_live_text(k, live, sizeof live);
    snprintf(title, sizeof title, "Layer (%s)", live);
    isk_ui_rect a = box;
    isk_ui_label(ui, row(p, &a), title, ISK_UI_LEFT);
    play_key_field(p, "layer-count", labelled(p, &a, "Count", U(40)), section, "count");
    static const char *const names[4] = {"Xmin", "Xmax", "Ymin", "Ymax"};
    for (int i = 0; i < 4; i++) {
        char id[16];
        snprintf(id, sizeof id, "layer-%c%s", names[i][0] == 'X' ? 'x' : 'y', names[i] + 1);
        play_key_part_field(p, id, labelled(p, &a, names[i], U(40)), section, "rect", i, NULL);
    }
}

/* ---- beside the console and below it: what iskra adds ------------------------------------- */

void play_file_buttons(player *p, isk_ui_rect buttons)
{
    static const play_action more[] = {PLAY_SAVE, PLAY_SHOT, PLAY_SHOT_WINDOW, PLAY_PANEL};
    for (int i = 0; i < 4; i++) {
        const play_action_info *ai = play_action_at(more[i]);
        char label[32];
        snprintf(label, sizeof label, "%s %s", ai->label, ai->keys);
        if (isk_ui_button(&p->ui, ai->id, isk_ui_cell(buttons, 2, 2, i % 2, i / 2, U(GAP)), label))
            play_do(p, more[i]);
    }
}

/* Save, screenshots, panel; the last message, whole; the keys without a
 * button when there is room for all of them. */
void play_extras(player *p, isk_ui_rect a)
{
    isk_ui *ui = &p->ui;
    const int rh = isk_ui_row_height(ui);
    isk_ui_rect buttons = isk_ui_cut_top(&a, 2 * rh + U(GAP));
    isk_ui_cut_top(&a, U(GAP));
    play_file_buttons(p, buttons);
    /* the keys that have no button, then the last message */
    static const play_action listed[] = {PLAY_TOGGLE_PAUSE, PLAY_SLOWER, PLAY_FASTER, PLAY_MORE_PRECISION,
                                         PLAY_LESS_PRECISION, PLAY_BACK, PLAY_TIMELINE, PLAY_HUD, PLAY_QUIT};
    char text[400];
    size_t used = (size_t)snprintf(text, sizeof text, "keys: 1-%d click mode", PLAY_CLICK_MODES);
    for (size_t i = 0; i < sizeof listed / sizeof listed[0] && used < sizeof text; i++) {
        const play_action_info *ai = play_action_at(listed[i]);
        used += (size_t)snprintf(text + used, sizeof text - used, ", %s %s", ai->keys, ai->meaning);
    }
    if (used < sizeof text)
        snprintf(text + used, sizeof text - used, ". ns: stepping cost per particle-step%s; drift: of the "
                                                  "total energy since the integrator took over",
                 p->fixed_clock ? " (not timed with --fixed-clock)" : "");
    /* The message takes the lines it needs (two at least), from the bottom. */
    char lines[sizeof p->status + 64];
    const int n = isk_ui_wrap(ui, p->status, a.w, lines, sizeof lines);
    isk_ui_rect status = isk_ui_cut_bottom(&a, (n > 2 ? n : 2) * isk_ui_line_height(ui));
    char keys[sizeof text + 64];
    if (isk_ui_wrap(ui, text, a.w, keys, sizeof keys) * isk_ui_line_height(ui) <= a.h)
        isk_ui_text_wrapped(ui, a, text, ui->style.dim);
    if (p->status[0])
        isk_ui_text_wrapped(ui, status, p->status, ui->style.text);
}

/* The charts over the integrators' table, in `r`. */
static void charts_and_integrators(player *p, isk_ui_rect r)
{
    isk_ui_rect table = isk_ui_cut_bottom(&r, (ISK_INTEGRATOR_COUNT + 2) * isk_ui_row_height(&p->ui));
    isk_ui_cut_bottom(&r, U(GAP));
    play_charts_draw(p, r, 0);
    play_integrators(p, table);
}

/* The thesis page's layout: console and side beside the canvas, the rest below. */
static void wide(player *p)
{
    console(p, p->lay.console, NULL);
    isk_ui_panel(&p->ui, p->lay.side);
    charts_and_integrators(p, isk_ui_inset(p->lay.side, U(MARGIN)));
    isk_ui_panel(&p->ui, p->lay.bottom);
    isk_ui_rect a = isk_ui_inset(p->lay.bottom, U(MARGIN));
    /* under the canvas and the console: the thesis's bottom panel */
    isk_ui_rect thesis = isk_ui_cut_left(&a, p->lay.side.x - a.x - U(MARGIN));
    isk_ui_cut_left(&a, U(2 * MARGIN));
    click_modes(p, row(p, &thesis), 0);
    isk_ui_rect lay_box = isk_ui_cut_right(&thesis, U(112));
    isk_ui_cut_right(&thesis, U(8));
    potentials(p, thesis, 0);
    layer(p, lay_box);
    editor_message(p, thesis, 0);
    play_extras(p, a);
}

/* Small screens: three columns beside the canvas. */
static void compact(player *p)
{
    isk_ui *ui = &p->ui;
    isk_ui_rect rest;
    console(p, p->lay.column[0], &rest);
    isk_ui_cut_top(&rest, U(GAP));
    click_modes(p, isk_ui_cut_top(&rest, (1 + PLAY_CLICK_MODES) * isk_ui_row_height(ui)), 1);
    /* the potentials over the layer */
    isk_ui_panel(ui, p->lay.column[1]);
    isk_ui_rect b = isk_ui_inset(p->lay.column[1], U(MARGIN));
    const int rowh = isk_ui_row_height(ui), gap = U(GAP);
    isk_ui_rect pots = isk_ui_cut_top(&b, 2 * U(MARGIN) + 5 * rowh + U(GAP) + U(2) + U(8) + 8 * (rowh + gap) +
                                              4 * isk_ui_line_height(ui));
    isk_ui_cut_top(&b, U(8));
    potentials(p, pots, 1);
    layer(p, isk_ui_cut_top(&b, 6 * (rowh + gap)));
    editor_message(p, pots, 1);
    /* charts and integrators over the files and the messages */
    isk_ui_panel(ui, p->lay.column[2]);
    isk_ui_rect c = isk_ui_inset(p->lay.column[2], U(MARGIN));
    /* two charts of 120 px at least (what a chart needs), the integrators' table */
    isk_ui_rect top = isk_ui_cut_top(&c, 2 * U(126) + U(4) + U(GAP) + (ISK_INTEGRATOR_COUNT + 2) * rowh);
    isk_ui_cut_top(&c, U(GAP));
    charts_and_integrators(p, top);
    play_extras(p, c);
}

void play_panel(player *p)
{
    if (!p->panel)
        return;
    if (p->panel_kind == PLAY_PANEL_INSPECTOR)
        play_inspector(p);
    else if (p->arrangement == PLAY_COMPACT)
        compact(p);
    else
        wide(p);
}

/* ---- the canvas ---------------------------------------------------------------------------- */

/* The potential whose disc is under canvas pixel (x, y), or -1. */
static int potential_at(const player *p, double x, double y)
{
    size_t n;
    const isk_potential *pots = isk_effect_potentials(p->fx, &n);
    const isk_view *v = isk_effect_view(p->fx);
    double best = -1;
    int found = -1;
    for (size_t k = 0; k < n; k++) {
        double sx, sy;
        isk_view_to_screen(v, pots[k].r.x, pots[k].r.y, &sx, &sy);
        double rx, ry; /* the disc's radius in pixels (0.1 world units), at least a finger's width */
        isk_view_to_screen(v, pots[k].r.x + 0.1, pots[k].r.y, &rx, &ry);
        double r = fabs(rx - sx), reach = (r > 6 ? r : 6) + 3 * p->ui.scale;
        double d = hypot(x - sx, y - sy);
        if (d <= reach && (found < 0 || d < best)) {
            best = d;
            found = (int)k;
        }
    }
    return found;
}

static void next_potential_name(const isk_effect_def *d, char *out, size_t n)
{
    for (int k = 1; k < 1000; k++) {
        snprintf(out, n, "P%d", k);
        if (isk_effect_def_find_force(d, out) < 0)
            return;
    }
}

/* --follow: the emitter goes where the pointer is; a live position spreads
 * the next step's births along the way there, so it leaves no gaps. */
static void follow_mouse(player *p, double wx, double wy)
{
    const isk_effect_def *d = isk_effect_definition(p->fx);
    int k = isk_effect_def_find_emitter(d, p->follow);
    if (k < 0 || (d->emitters[k].born.position.x == wx && d->emitters[k].born.position.y == wy))
        return;
    char sec[ISK_NAME_MAX + 16];
    isk_error err;
    snprintf(sec, sizeof sec, "emitter %s", p->follow);
    if (isk_effect_move(p->fx, sec, wx, wy, &err) != ISK_OK)
        play_say(p, "%s", err.message);
    else
        play_shadow_move(p, sec, wx, wy);
}

void play_canvas(player *p)
{
    isk_ui_area_state a = isk_ui_area(&p->ui, "canvas", p->lay.canvas);
    if (play_rewind_input(p, &a))
        return; /* the timeline's bar took the pointer */
    const isk_effect_def *d = isk_effect_definition(p->fx);
    /* The thesis turns the click's whole pixel into world units; iskra
     * takes the pixel's centre. */
    const double off = d->fidelity == ISK_FIDELITY_THESIS ? 0.0 : 0.5;
    double wx, wy;
    isk_view_to_world(isk_effect_view(p->fx), a.x + off, a.y + off, &wx, &wy);
    if (p->follow && a.hover)
        follow_mouse(p, wx, wy);
    if (a.pressed) {
        int k = potential_at(p, a.x + 0.5, a.y + 0.5);
        if (k >= 0) {
            p->selected = k;
            p->dragging = 1;
            return;
        }
        if (p->click_mode < ISK_EXPLOSION_COUNT) {
            if (p->count_refused)
                return; /* the thesis: an invalid count, and the click does nothing */
            isk_status s = isk_effect_click(p->fx, wx, wy);
            if (s != ISK_OK)
                play_say(p, "click: %s", isk_status_str(s));
            else
                play_shadow_click(p, wx, wy);
            p->count_ref = (size_t)-1; /* new particles: the drift starts again */
        } else if (p->click_mode == PLAY_CLICK_ADD_POTENTIAL) {
            /* The thesis's new potential: k = 0 (no force until k is typed), charge 1, P 2. */
            isk_potential pot;
            isk_potential_init(&pot, 0.0, (isk_vec2){wx, wy}, 1.0);
            char name[16];
            isk_error err;
            next_potential_name(d, name, sizeof name);
            if (isk_effect_add_potential(p->fx, name, &pot, &err) != ISK_OK) {
                play_say(p, "%s", err.message);
            } else {
                play_shadow_add_potential(p, name, &pot);
                size_t n;
                isk_effect_potentials(p->fx, &n);
                p->selected = (int)n - 1;
                play_say(p, "potential %s added: type its k to give it a force", name);
            }
        }
        return;
    }
    if (p->dragging && (a.down || a.released)) {
        const isk_effect_def *def = isk_effect_definition(p->fx);
        int f = potential_force(def, p->selected);
        size_t n;
        const isk_potential *pots = isk_effect_potentials(p->fx, &n);
        if (f >= 0 && p->selected < (int)n && (pots[p->selected].r.x != wx || pots[p->selected].r.y != wy)) {
            char sec[ISK_NAME_MAX + 16], v[80];
            snprintf(sec, sizeof sec, "force %s", def->forces[f].name);
            snprintf(v, sizeof v, "%.17g, %.17g", wx, wy);
            play_set(p, sec, "position", v);
        }
        if (a.released)
            p->dragging = 0;
    }
}
