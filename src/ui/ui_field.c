/* SPDX-License-Identifier: MIT */
/* Text and number fields (see iskra/ui.h): one edit buffer in the isk_ui,
 * owned by the focused field; Return, Tab or a click elsewhere apply the
 * text, Escape cancels.  A click gives a field the focus from the next
 * frame, after the field that had it has applied its text.
 *
 * Selection: the text between ui->anchor and ui->cursor.  Taking the focus
 * selects everything (a spin box's rule: typing "10" into a field showing
 * 9.81 gives 10, not 9.8110), as do Ctrl+A and a double click; typing or
 * deleting replaces the selection; moving the cursor ends it. */
#include <stdio.h>
#include <string.h>

#include "iskra/text.h"
#include "ui_internal.h"

static int number_char(char c)
{
    return (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E' || c == '/';
}

/* Keys a focused field takes (so they are never shortcuts while typing). */
static int editing_key(int key)
{
    const int plain = key & ~ISK_UI_MOD_CTRL;
    return (plain >= 32 && plain <= 126) || (key >= ISK_UI_KEY_BACKSPACE && key <= ISK_UI_KEY_END) ||
           (key & ISK_UI_TYPED);
}

static int sel_start(const isk_ui *ui) { return ui->anchor < ui->cursor ? ui->anchor : ui->cursor; }
static int sel_end(const isk_ui *ui) { return ui->anchor < ui->cursor ? ui->cursor : ui->anchor; }

static void select_all(isk_ui *ui)
{
    ui->anchor = 0;
    ui->cursor = (int)strlen(ui->edit);
}

static void place_cursor(isk_ui *ui, int at) { ui->cursor = ui->anchor = at; }

/* Removes the selected text; 1 if there was any. */
static int delete_selection(isk_ui *ui)
{
    const int a = sel_start(ui), b = sel_end(ui), len = (int)strlen(ui->edit);
    if (a == b)
        return 0;
    memmove(ui->edit + a, ui->edit + b, (size_t)(len - b) + 1);
    place_cursor(ui, a);
    return 1;
}

static void insert(isk_ui *ui, char c, unsigned flags)
{
    if ((flags & ISK_UI_FIELD_NUMBER) && !number_char(c))
        return;
    delete_selection(ui);
    size_t len = strlen(ui->edit);
    if (len + 1 >= sizeof ui->edit)
        return;
    memmove(ui->edit + ui->cursor + 1, ui->edit + ui->cursor, len - (size_t)ui->cursor + 1);
    ui->edit[ui->cursor++] = c;
    ui->anchor = ui->cursor;
}

/* Edits the buffer by key; returns APPLY / CANCEL for the keys that end
 * the edit. */
static isk_ui_field_result edit_key(isk_ui *ui, int key, unsigned flags)
{
    const int len = (int)strlen(ui->edit), selected = sel_start(ui) != sel_end(ui);
    if (key & ISK_UI_TYPED) {
        insert(ui, (char)(key & 0xff), flags);
        return ISK_UI_FIELD_IDLE;
    }
    switch (key) {
    case ISK_UI_MOD_CTRL | 'a': select_all(ui); break;
    case ISK_UI_KEY_LEFT: place_cursor(ui, selected ? sel_start(ui) : ui->cursor - (ui->cursor > 0)); break;
    case ISK_UI_KEY_RIGHT: place_cursor(ui, selected ? sel_end(ui) : ui->cursor + (ui->cursor < len)); break;
    case ISK_UI_KEY_HOME: place_cursor(ui, 0); break;
    case ISK_UI_KEY_END: place_cursor(ui, len); break;
    case ISK_UI_KEY_BACKSPACE:
        if (!delete_selection(ui) && ui->cursor > 0) {
            memmove(ui->edit + ui->cursor - 1, ui->edit + ui->cursor, (size_t)(len - ui->cursor) + 1);
            place_cursor(ui, ui->cursor - 1);
        }
        break;
    case ISK_UI_KEY_DELETE:
        if (!delete_selection(ui) && ui->cursor < len)
            memmove(ui->edit + ui->cursor, ui->edit + ui->cursor + 1, (size_t)(len - ui->cursor));
        break;
    case ISK_UI_KEY_RETURN: return ISK_UI_FIELD_APPLY;
    case ISK_UI_KEY_TAB: ui->tab_pending = 1; return ISK_UI_FIELD_APPLY;
    case ISK_UI_KEY_ESCAPE: return ISK_UI_FIELD_CANCEL;
    default: break; /* other keys and Ctrl combinations: taken, nothing done */
    }
    return ISK_UI_FIELD_IDLE;
}

/* x of the first character of the shown text in `inner` (centred when it
 * fits; while editing, scrolled so the cursor stays in view). */
static int text_x(const isk_ui *ui, isk_ui_rect inner, const char *shown, int editing)
{
    const int s = ui->scale, cell = isk__ui_font(ui)->cell_w * s;
    int tw = isk_ui_text_width(ui, shown);
    int x0 = tw <= inner.w ? inner.x + (inner.w - tw) / 2 : inner.x;
    if (editing) {
        int cx = x0 + ui->cursor * cell;
        if (cx > inner.x + inner.w - s)
            x0 -= cx - (inner.x + inner.w - s);
    }
    return x0;
}

isk_ui_field_result isk_ui_field(isk_ui *ui, const char *id, isk_ui_rect r, const char *value, unsigned flags,
                                 char *out, size_t out_size)
{
    if (!ui || !id)
        return ISK_UI_FIELD_IDLE;
    if (!value)
        value = "";
    const uint32_t h = isk__ui_id(id);
    const int s = ui->scale, pad = 4 * s, cell = isk__ui_font(ui)->cell_w * s;
    const int readonly = (flags & ISK_UI_FIELD_READONLY) != 0;
    isk__ui_record(ui, id, r);
    ui_state st = {0, 0, 0, 0, 0};
    if (!readonly)
        st = isk__ui_interact(ui, h, r);
    isk_ui_field_result result = ISK_UI_FIELD_IDLE;

    if (!readonly && !ui->disabled && ui->tab_pending && ui->focus != h) {
        ui->tab_pending = 0;
        ui->focus = h;
        ui->edit_id = 0;
    }
    int focused = ui->focus == h && !readonly && !ui->disabled;
    if (st.pressed && !focused)
        ui->focus_next = h;
    if (focused && ui->edit_id != h) {
        snprintf(ui->edit, sizeof ui->edit, "%s", value);
        select_all(ui);
        ui->edit_id = h;
    }
    isk_ui_rect inner = isk_ui_inset(r, pad);
    if (focused) {
        ui->focus_seen = 1;
        for (int i = 0; i < ui->nkeys && result == ISK_UI_FIELD_IDLE; i++)
            if (editing_key(ui->keys[i]) && !(ui->keys_taken >> i & 1u)) { /* not a field's before us */
                ui->keys_taken |= (uint64_t)1 << i;
                result = edit_key(ui, ui->keys[i], flags);
            }
        if (result == ISK_UI_FIELD_IDLE && ui->pressed && !st.pressed && !isk_ui_contains(r, ui->mouse_x, ui->mouse_y))
            result = ISK_UI_FIELD_APPLY; /* a click elsewhere: the browser's change on blur */
        if (st.pressed) {
            if (ui->press_clicks >= 2) {
                select_all(ui); /* a double click */
            } else {
                /* A click inside puts the cursor in the nearest gap. */
                int x0 = text_x(ui, inner, ui->edit, 0);
                int c = (ui->mouse_x - x0 + cell / 2) / cell, len = (int)strlen(ui->edit);
                place_cursor(ui, c < 0 ? 0 : c > len ? len : c);
            }
        }
        if (result == ISK_UI_FIELD_APPLY) {
            if (out && out_size)
                snprintf(out, out_size, "%s", ui->edit);
            ui->focus = 0; /* edit_id stays: isk_ui_field_error can hand the text back */
            if (ui->error_id == h)
                ui->error_id = 0;
        } else if (result == ISK_UI_FIELD_CANCEL) {
            ui->focus = 0;
            ui->edit_id = 0;
            if (ui->error_id == h)
                ui->error_id = 0;
        }
    }

    /* drawing */
    const int erred = ui->error_id == h, still_editing = ui->focus == h;
    isk_color edge = erred ? ui->style.error : still_editing ? ui->style.focus : ui->style.border;
    if (st.hover && !still_editing && !erred)
        edge = isk__ui_shade(edge, 24);
    isk_color bg = readonly ? ui->style.field_readonly : ui->style.field;
    if (ui->disabled) {
        edge = isk__ui_dim(ui, edge);
        bg = isk__ui_dim(ui, bg);
    }
    isk__ui_round_outline(ui, r, 2 * s, s, edge, bg);
    const char *shown = still_editing ? ui->edit : value;
    isk_color ink = readonly || ui->disabled ? ui->style.dim : ui->style.text;
    const int x0 = text_x(ui, inner, shown, still_editing), ty = isk__ui_text_y(ui, r);
    const int line = isk_ui_line_height(ui);
    isk_ui_rect clip = isk_ui_inset(r, s);
    if (still_editing && sel_start(ui) != sel_end(ui)) {
        /* the selection's cells, under the text, within the field */
        int a = x0 + sel_start(ui) * cell - s, b = x0 + sel_end(ui) * cell;
        a = a < clip.x ? clip.x : a;
        b = b > clip.x + clip.w ? clip.x + clip.w : b;
        if (b > a)
            isk__ui_fill(ui, (isk_ui_rect){a, ty - s, b - a, line}, ui->style.selection);
    }
    isk__ui_text_clip(ui, clip, x0, ty, shown, ink);
    if (still_editing && sel_start(ui) == sel_end(ui)) {
        int cx = x0 + ui->cursor * cell - s;
        if (cx < inner.x - s)
            cx = inner.x - s;
        isk__ui_fill(ui, (isk_ui_rect){cx, ty - s, s, line}, ui->style.focus);
    }
    if (erred)
        ui->error_rect = r;
    return result;
}

void isk_ui_field_error(isk_ui *ui, const char *id, const char *message)
{
    if (!ui || !id)
        return;
    const uint32_t h = isk__ui_id(id);
    snprintf(ui->error, sizeof ui->error, "%s", message ? message : "refused");
    snprintf(ui->error_name, sizeof ui->error_name, "%s", id);
    ui->error_id = h;
    isk_ui_find(ui, id, &ui->error_rect);
    /* Back to the typed text, the cursor after it, unless the user went on
     * to another field. */
    if (!ui->focus && !ui->focus_next && ui->edit_id == h) {
        ui->focus = h;
        ui->focus_seen = 1;
        place_cursor(ui, (int)strlen(ui->edit));
    }
}

const char *isk_ui_field_message_text(const isk_ui *ui, const char **id_out)
{
    const int has = ui && ui->error_id && ui->error[0];
    if (id_out)
        *id_out = has ? ui->error_name : NULL;
    return has ? ui->error : NULL;
}

int isk_ui_field_message(isk_ui *ui, const char *id, isk_ui_rect *area)
{
    if (!ui || !area || !ui->error_id || !ui->error[0] || (id && isk__ui_id(id) != ui->error_id) ||
        (!id && ui->error_placed))
        return 0;
    /* In a box with the error's outline: the text wrapped inside it. */
    const int s = ui->scale, pad = 3 * s;
    char lines[sizeof ui->error + 64];
    const int n = isk_ui_wrap(ui, ui->error, area->w - 2 * pad, lines, sizeof lines);
    if (n <= 0)
        return 0;
    const int h = n * isk_ui_line_height(ui) + 2 * pad - s;
    isk_ui_rect box = isk_ui_cut_top(area, h);
    isk_ui_cut_top(area, isk_ui_px(ui, 4));
    isk__ui_round_outline(ui, box, 2 * s, s, ui->style.error, ui->style.panel);
    isk_ui_text(ui, isk_ui_inset(box, pad), lines, ui->style.error, ISK_UI_LEFT);
    ui->error_placed = 1;
    return h + isk_ui_px(ui, 4);
}
