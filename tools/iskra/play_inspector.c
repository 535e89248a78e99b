/* SPDX-License-Identifier: MIT */
/* The inspector: the panel of every scene that is not one of the explosion
 * thesis's simulator scenes (play_panel_for).  It is built from the key
 * table alone, as Godot's inspector is from a node's properties:
 *
 *   the transport    play, pause, stop, reset, reload, step; speed
 *   the sections     every section of the running scene (emitters first,
 *                    then forces, deflectors, [bounds], [click], [scene],
 *                    [view], drawings), one selected
 *   a filter         only the keys whose name holds it
 *   the keys         the selected section's keys that isk_effect_set takes
 *                    for its kind, each the widget its row calls for
 *                    (play_key_widget.c); a refused value's message under
 *                    its key; keys that wait for a reset are marked *
 *   help             the hovered or edited key's meaning, range and when
 *                    it applies, from its row
 *   files            save, screenshots, panel
 * and below the canvas the last message (whole) and the charts (the
 * message goes over the help when the canvas leaves no room below it).
 *
 * Widget names: "section/emitter-flame" selects a section; a key's widget
 * is "emitter-flame/rate" ("scene/dt" for the unnamed sections), a
 * slider's track "emitter-flame/rate/slider", a choice's options
 * "emitter-flame/blend/add".  A script can press a key scrolled out of
 * view: play_inspector_reveal brings it in first. */
#include <stdio.h>
#include <string.h>

#include "play.h"

#define U(n) isk_ui_px(&p->ui, (n))

/* The order of the sections in the list: what an effect is made of first. */
static const isk_section_kind order[] = {ISK_SECTION_EMITTER, ISK_SECTION_FORCE,   ISK_SECTION_DEFLECTOR,
                                         ISK_SECTION_BOUNDS,  ISK_SECTION_CLICK,   ISK_SECTION_SCENE,
                                         ISK_SECTION_VIEW,    ISK_SECTION_DRAWING};
#define NORDER ((int)(sizeof order / sizeof order[0]))

static void item_of(const isk_effect_def *d, isk_section_kind s, int i, play_item *it)
{
    const char *name = isk_key_item_name(d, s, i);
    it->section = s;
    it->index = i;
    it->kind = isk_key_item_kind(d, s, i);
    snprintf(it->name, sizeof it->name, "%s%s%s", isk_section_name(s), *name ? " " : "", name);
    snprintf(it->token, sizeof it->token, "%s%s%s", isk_section_name(s), *name ? "-" : "", name);
}

/* The n-th section in the list's order; 0 past the end. */
static int nth_item(const isk_effect_def *d, int n, play_item *it)
{
    for (int o = 0; o < NORDER; o++) {
        const int count = isk_key_items(d, order[o]);
        if (n < count) {
            item_of(d, order[o], n, it);
            return 1;
        }
        n -= count;
    }
    return 0;
}

/* The widget names of a section and of one of its keys (see the top). */
static void section_widget_id(const play_item *it, char id[ISK_UI_ID_MAX])
{
    snprintf(id, ISK_UI_ID_MAX, "section/%s", it->token);
}

static void key_widget_id(const play_item *it, const isk_key *k, char id[ISK_UI_ID_MAX])
{
    snprintf(id, ISK_UI_ID_MAX, "%s/%s", it->token, k->name);
}

/* The name of the item's kind ("gravity", "stream"), or NULL for a
 * section without kinds. */
static const char *kind_name(const play_item *it)
{
    int nk;
    const char *const *kinds = isk_section_kind_names(it->section, &nk);
    return kinds && it->kind >= 0 && it->kind < nk ? kinds[it->kind] : NULL;
}

static int item_count(const isk_effect_def *d)
{
    int n = 0;
    for (int o = 0; o < NORDER; o++)
        n += isk_key_items(d, order[o]);
    return n;
}

/* Whether the inspector shows key k for an item of `kind`: one that
 * applies to it and that isk_effect_set takes (not the kinds, width,
 * height; not `preset`, which only acts where it stands in a file). */
static int shown_key(const isk_key *k, isk_section_kind s, int kind)
{
    return k->section == s && isk_key_applies(k, kind) && !k->directive &&
           isk_key_when_set(k, kind) != ISK_KEY_WHEN_CREATED;
}

/* The keys of the selected item that pass the filter, into keys (at most max). */
static int keys_of(const player *p, const play_item *it, const isk_key **keys, int max)
{
    int n = 0;
    for (int i = 0; i < isk_key_count() && n < max; i++) {
        const isk_key *k = isk_key_at(i);
        if (shown_key(k, it->section, it->kind) && (!p->insp.filter[0] || strstr(k->name, p->insp.filter)))
            keys[n++] = k;
    }
    return n;
}

void play_inspector_begin(player *p)
{
    const isk_effect_def *d = isk_effect_definition(p->fx);
    play_inspector_state *in = &p->insp;
    if (in->section >= 0 && in->section < ISK_SECTION_COUNT && in->item < isk_key_items(d, in->section))
        return; /* a reload keeps the section shown, while it is there */
    in->section = isk_key_items(d, ISK_SECTION_EMITTER) ? ISK_SECTION_EMITTER : ISK_SECTION_SCENE;
    in->item = 0;
    in->sections_scroll = in->keys_scroll = 0;
}

static int reveal(player *p, const char *wanted, int apply);

/* ---- the parts ----------------------------------------------------------------------------- */

static void sections(player *p, isk_ui_rect r)
{
    isk_ui *ui = &p->ui;
    const isk_effect_def *d = isk_effect_definition(p->fx);
    const int rh = isk_ui_row_height(ui), n = item_count(d), visible = r.h / rh;
    isk_ui_rect bar = isk_ui_cut_right(&r, U(8));
    isk_ui_cut_right(&r, U(2));
    p->insp.sections_scroll -= isk_ui_wheel(ui, r);
    isk_ui_scrollbar(ui, "sections-scroll", bar, &p->insp.sections_scroll, n, visible);
    if (p->insp.sections_scroll > n - visible)
        p->insp.sections_scroll = n - visible;
    if (p->insp.sections_scroll < 0)
        p->insp.sections_scroll = 0;
    for (int row = 0; row < visible; row++) {
        play_item it;
        if (!nth_item(d, p->insp.sections_scroll + row, &it))
            break;
        isk_ui_rect line = {r.x, r.y + row * rh, r.w, rh};
        char id[ISK_UI_ID_MAX];
        section_widget_id(&it, id);
        const int selected = (int)it.section == p->insp.section && it.index == p->insp.item;
        if (isk_ui_selectable(ui, id, line, it.name, selected) && !selected) {
            p->insp.section = it.section;
            p->insp.item = it.index;
            p->insp.keys_scroll = 0;
        }
        const char *kind = kind_name(&it);
        isk_ui_text(ui, isk_ui_text_line(ui, isk_ui_inset(line, U(4))), kind ? kind : "",
                    selected ? ui->style.text : ui->style.dim, ISK_UI_RIGHT);
    }
}

/* The key the help box explains: the one being edited, else the one under the pointer. */
typedef struct help {
    const isk_key *k;
    int kind, focused;
} help;

static void keys(player *p, const play_item *it, isk_ui_rect r, help *h)
{
    isk_ui *ui = &p->ui;
    const isk_key *list[200];
    const int n = keys_of(p, it, list, 200);
    const int rh = isk_ui_row_height(ui), gap = U(GAP), pitch = rh + gap;
    isk_ui_rect bar = isk_ui_cut_right(&r, U(8));
    isk_ui_cut_right(&r, U(4));
    /* the labels' column: as wide as the longest name (and its mark), at most 45 % */
    int label_w = 0;
    for (int i = 0; i < n; i++) {
        char t[64];
        snprintf(t, sizeof t, "%s*", list[i]->name);
        int w = isk_ui_text_width(ui, t) + U(8);
        label_w = w > label_w ? w : label_w;
    }
    if (label_w > r.w * 45 / 100)
        label_w = r.w * 45 / 100;
    p->insp.keys_scroll -= isk_ui_wheel(ui, r);
    const int visible = r.h / pitch > 0 ? r.h / pitch : 1;
    isk_ui_scrollbar(ui, "keys-scroll", bar, &p->insp.keys_scroll, n, visible);
    if (p->insp.keys_scroll > n - 1)
        p->insp.keys_scroll = n - 1;
    if (p->insp.keys_scroll < 0)
        p->insp.keys_scroll = 0;
    if (n == 0) {
        isk_ui_text_wrapped(ui, r, p->insp.filter[0] ? "no key of this section has that in its name" :
                                                       "nothing here can change while it runs", ui->style.dim);
        return;
    }
    isk_ui_rect a = r;
    for (int i = p->insp.keys_scroll; i < n; i++) {
        const isk_key *k = list[i];
        const int rows = play_key_widget_rows(k);
        if (a.h < rows * pitch - gap)
            break; /* only whole keys are drawn */
        isk_ui_rect line = isk_ui_cut_top(&a, rh), second = {0, 0, 0, 0};
        isk_ui_cut_top(&a, gap);
        if (rows == 2) {
            second = isk_ui_cut_top(&a, rh);
            isk_ui_cut_top(&a, gap);
        }
        char id[ISK_UI_ID_MAX], label[64];
        key_widget_id(it, k, id);
        const int later = isk_key_when_set(k, it->kind) == ISK_KEY_WHEN_RESET;
        snprintf(label, sizeof label, "%s%s", k->name, later ? "*" : "");
        isk_ui_rect widget = line;
        isk_ui_rect lr = isk_ui_cut_left(&widget, label_w);
        isk_ui_text(ui, isk_ui_text_line(ui, lr), label, later ? ui->style.dim : ui->style.label, ISK_UI_LEFT);
        if (rows == 2)
            isk_ui_cut_left(&second, label_w);
        play_key_widget(p, id, widget, second, it, k);
        /* the message of a refused value, under its key, pushing the rest down */
        isk_ui_field_message(ui, id, &a);
        isk_ui_rect whole = {line.x, line.y, line.w, (rows == 2 ? second.y + second.h : line.y + line.h) - line.y};
        if (isk_ui_focused(ui, id)) {
            h->k = k;
            h->kind = it->kind;
            h->focused = 1;
        } else if (!h->focused && isk_ui_hovered(ui, whole)) {
            h->k = k;
            h->kind = it->kind;
        }
    }
}

/* The help box: the key's meaning, range and when it applies. */
static void help_box(player *p, const help *h, isk_ui_rect r)
{
    isk_ui *ui = &p->ui;
    isk_ui_box(ui, r);
    isk_ui_rect in = isk_ui_inset(r, U(4));
    char text[700];
    if (!h->k) {
        snprintf(text, sizeof text, "Point at a key to see what it does; * marks a key that applies at the next "
                                    "reset (R).");
        isk_ui_text_wrapped(ui, in, text, ui->style.dim);
        return;
    }
    char range[200], when[80];
    isk_key_range_text(h->k, range, sizeof range);
    const isk_key_when w = isk_key_when_set(h->k, h->kind);
    snprintf(when, sizeof when, "%s", w == ISK_KEY_WHEN_LIVE ? "Applies at once" : "Applies at the next reset (R)");
    snprintf(text, sizeof text, "%s: %s.%s%s%s %s.", h->k->name, h->k->meaning, range[0] ? " Range: " : "", range,
             range[0] ? "." : "", when);
    isk_ui_text_wrapped(ui, in, text, ui->style.text);
}

void play_inspector(player *p)
{
    isk_ui *ui = &p->ui;
    const isk_effect_def *d = isk_effect_definition(p->fx);
    isk_ui_panel(ui, p->lay.inspector);
    isk_ui_rect a = isk_ui_inset(p->lay.inspector, U(MARGIN));
    play_transport(p, &a);
    const int rh = isk_ui_row_height(ui), line_h = isk_ui_line_height(ui);
    /* the files at the bottom; over them the help; the message when there is no room under the canvas */
    isk_ui_rect files = isk_ui_cut_bottom(&a, 2 * rh + U(GAP));
    isk_ui_cut_bottom(&a, U(GAP));
    isk_ui_rect help_r = isk_ui_cut_bottom(&a, 4 * line_h + U(8));
    isk_ui_cut_bottom(&a, U(GAP));
    /* the last message: below the canvas, or here when the canvas leaves no room there */
    const int room_under = p->lay.under.h >= 4 * line_h + 2 * U(MARGIN);
    if (!room_under && p->status[0]) {
        char lines[sizeof p->status + 64];
        const int m = isk_ui_wrap(ui, p->status, a.w, lines, sizeof lines);
        isk_ui_text_wrapped(ui, isk_ui_cut_bottom(&a, m * line_h), p->status, ui->style.text);
        isk_ui_cut_bottom(&a, U(GAP));
    }
    /* the sections: six rows, fewer when the scene has fewer */
    const int n = item_count(d), rows = n < 6 ? n : 6;
    isk_ui_rect list = isk_ui_cut_top(&a, rows * rh);
    isk_ui_cut_top(&a, U(GAP));
    sections(p, list);
    /* the filter */
    isk_ui_rect f = isk_ui_cut_top(&a, rh);
    isk_ui_cut_top(&a, U(GAP));
    isk_ui_label(ui, isk_ui_cut_left(&f, isk_ui_text_width(ui, "Filter") + U(8)), "Filter", ISK_UI_LEFT);
    char typed[sizeof p->insp.filter];
    if (isk_ui_field(ui, "filter", f, p->insp.filter, 0, typed, sizeof typed) == ISK_UI_FIELD_APPLY) {
        snprintf(p->insp.filter, sizeof p->insp.filter, "%s", typed);
        p->insp.keys_scroll = 0;
    }
    /* the selected section's keys */
    play_item it;
    if (p->insp.section < 0 || p->insp.section >= ISK_SECTION_COUNT || p->insp.item >= isk_key_items(d, p->insp.section))
        play_inspector_begin(p);
    item_of(d, (isk_section_kind)p->insp.section, p->insp.item, &it);
    isk_ui_rect head = isk_ui_cut_top(&a, rh);
    char title[ISK_NAME_MAX + 40];
    snprintf(title, sizeof title, "[%s]", it.name);
    isk_ui_box(ui, head);
    isk_ui_rect ht = isk_ui_text_line(ui, isk_ui_inset(head, U(4)));
    isk_ui_text(ui, ht, title, ui->style.text, ISK_UI_LEFT);
    const char *kind_of_item = kind_name(&it);
    if (kind_of_item) {
        char kind[60];
        snprintf(kind, sizeof kind, "%s = %s", isk_section_kind_key(it.section)[0] ? isk_section_kind_key(it.section)
                                                                                   : "kind",
                 kind_of_item);
        isk_ui_text(ui, ht, kind, ui->style.dim, ISK_UI_RIGHT);
    }
    isk_ui_cut_top(&a, U(GAP));
    help h = {NULL, -1, 0};
    keys(p, &it, a, &h);
    help_box(p, &h, help_r);
    /* files, and the message where the canvas leaves no room for it */
    play_file_buttons(p, files);
    isk_ui_rect under = p->lay.under;
    if (room_under) {
        isk_ui_panel(ui, under);
        isk_ui_rect u = isk_ui_inset(under, U(MARGIN));
        char lines[sizeof p->status + 64];
        const int m = isk_ui_wrap(ui, p->status, u.w, lines, sizeof lines);
        isk_ui_rect msg = isk_ui_cut_top(&u, (m > 2 ? m : 2) * line_h);
        isk_ui_cut_top(&u, U(GAP));
        if (p->status[0])
            isk_ui_text_wrapped(ui, msg, p->status, ui->style.text);
        play_charts_draw(p, u, 1);
    }
    if (p->insp.reveal[0]) {
        reveal(p, p->insp.reveal, 1);
        p->insp.reveal[0] = 0;
    }
}

/* ---- names ---------------------------------------------------------------------------------- */

void play_inspector_names(const player *p, void (*name)(void *user, const char *name), void *user)
{
    const isk_effect_def *d = isk_effect_definition(p->fx);
    play_item it;
    char id[ISK_UI_ID_MAX];
    for (int i = 0; nth_item(d, i, &it); i++) {
        section_widget_id(&it, id);
        name(user, id);
    }
    for (int i = 0; nth_item(d, i, &it); i++)
        for (int r = 0; r < isk_key_count(); r++) {
            const isk_key *k = isk_key_at(r);
            if (shown_key(k, it.section, it.kind)) {
                key_widget_id(&it, k, id);
                name(user, id);
            }
        }
}

/* Selects the section of widget `wanted` and scrolls to it; 1 when the
 * inspector has it (apply: 0 only asks). */
static int reveal(player *p, const char *wanted, int apply)
{
    const isk_effect_def *d = isk_effect_definition(p->fx);
    play_item it;
    for (int i = 0; nth_item(d, i, &it); i++) {
        char id[ISK_UI_ID_MAX];
        section_widget_id(&it, id);
        const size_t tl = strlen(it.token);
        const int is_section = !strcmp(wanted, id);
        const int in_section = !strncmp(wanted, it.token, tl) && wanted[tl] == '/';
        if (!is_section && !in_section)
            continue;
        if (apply && (p->insp.sections_scroll > i || p->insp.sections_scroll + 5 < i))
            p->insp.sections_scroll = i; /* the section into the list's view */
        if (is_section)
            return 1;
        /* the key, at the top of the keys' view (without a filter) */
        char filter[sizeof p->insp.filter];
        snprintf(filter, sizeof filter, "%s", p->insp.filter);
        p->insp.filter[0] = 0;
        const isk_key *list[200];
        const int nk = keys_of(p, &it, list, 200);
        snprintf(p->insp.filter, sizeof p->insp.filter, "%s", filter);
        const char *key = wanted + tl + 1;
        for (int k = 0; k < nk; k++) {
            size_t kl = strlen(list[k]->name);
            if (!strncmp(key, list[k]->name, kl) && (key[kl] == 0 || key[kl] == '/')) {
                if (apply) {
                    p->insp.section = it.section;
                    p->insp.item = it.index;
                    p->insp.filter[0] = 0;
                    p->insp.keys_scroll = k;
                }
                return 1;
            }
        }
        return 0;
    }
    return 0;
}

int play_inspector_reveal(player *p, const char *wanted)
{
    if (p->panel_kind != PLAY_PANEL_INSPECTOR || !p->panel || !reveal(p, wanted, 0))
        return 0;
    /* At the end of the next frame, after its input reached the fields
     * shown now (text typed into one goes where it was typed). */
    snprintf(p->insp.reveal, sizeof p->insp.reveal, "%s", wanted);
    return 1;
}
