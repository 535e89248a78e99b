/* SPDX-License-Identifier: MIT */
/* Text and number fields (see iskra/ui.h): one edit buffer in the isk_ui,
 * owned by the focused field; Return, Tab or a click elsewhere apply the
 * text, Escape cancels.  A click gives a field the focus from the next
 * frame, after the field that had it has applied its text. */
#include <stdio.h>
#include <string.h>

#include "iskra/text.h"
#include "ui_internal.h"

static int number_char(char c)
{
    return (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E' || c == '/';
}

static int editing_key(int key)
{
    return (key >= 32 && key <= 126) || (key >= ISK_UI_KEY_BACKSPACE && key <= ISK_UI_KEY_END) ||
           (key & ISK_UI_TYPED);
}

static void insert(isk_ui *ui, char c, unsigned flags)
{
    size_t len = strlen(ui->edit);
    if (((flags & ISK_UI_FIELD_NUMBER) && !number_char(c)) || len + 1 >= sizeof ui->edit)
        return;
    memmove(ui->edit + ui->cursor + 1, ui->edit + ui->cursor, len - (size_t)ui->cursor + 1);
    ui->edit[ui->cursor++] = c;
}

/* Edits the buffer by key; returns APPLY / CANCEL for the keys that end
 * the edit. */
static isk_ui_field_result edit_key(isk_ui *ui, int key, unsigned flags)
{
    const int len = (int)strlen(ui->edit);
    if (key & ISK_UI_TYPED) {
        insert(ui, (char)(key & 0xff), flags);
        return ISK_UI_FIELD_IDLE;
    }
    switch (key) {
    case ISK_UI_KEY_LEFT: ui->cursor -= ui->cursor > 0; break;
    case ISK_UI_KEY_RIGHT: ui->cursor += ui->cursor < len; break;
    case ISK_UI_KEY_HOME: ui->cursor = 0; break;
    case ISK_UI_KEY_END: ui->cursor = len; break;
    case ISK_UI_KEY_BACKSPACE:
        if (ui->cursor > 0) {
            memmove(ui->edit + ui->cursor - 1, ui->edit + ui->cursor, (size_t)(len - ui->cursor) + 1);
            ui->cursor--;
        }
        break;
    case ISK_UI_KEY_DELETE:
        if (ui->cursor < len)
            memmove(ui->edit + ui->cursor, ui->edit + ui->cursor + 1, (size_t)(len - ui->cursor));
        break;
    case ISK_UI_KEY_RETURN: return ISK_UI_FIELD_APPLY;
    case ISK_UI_KEY_TAB: ui->tab_pending = 1; return ISK_UI_FIELD_APPLY;
    case ISK_UI_KEY_ESCAPE: return ISK_UI_FIELD_CANCEL;
    default: break;
    }
    return ISK_UI_FIELD_IDLE;
}

isk_ui_field_result isk_ui_field(isk_ui *ui, const char *id, isk_ui_rect r, const char *value, unsigned flags,
                                 char *out, size_t out_size)
{
    if (!ui || !id)
        return ISK_UI_FIELD_IDLE;
    if (!value)
        value = "";
    const uint32_t h = ui_id(id);
    const int s = ui->scale, pad = 4 * s, cell = ISK_FONT_CELL_W * s;
    const int readonly = (flags & ISK_UI_FIELD_READONLY) != 0;
    ui_record(ui, id, r);
    ui_state st = {0, 0, 0, 0, 0};
    if (!readonly)
        st = ui_interact(ui, h, r);
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
        ui->cursor = (int)strlen(ui->edit);
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
            /* A click inside moves the cursor to the nearest gap. */
            int tw = isk_ui_text_width(ui, ui->edit), x0 = tw <= inner.w ? inner.x + (inner.w - tw) / 2 : inner.x;
            int c = (ui->mouse_x - x0 + cell / 2) / cell, len = (int)strlen(ui->edit);
            ui->cursor = c < 0 ? 0 : c > len ? len : c;
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
        edge = ui_shade(edge, 24);
    isk_color bg = readonly ? ui->style.field_readonly : ui->style.field;
    if (ui->disabled) {
        edge = ui_dim(ui, edge);
        bg = ui_dim(ui, bg);
    }
    ui_round_outline(ui, r, 2 * s, s, edge, bg);
    const char *shown = still_editing ? ui->edit : value;
    isk_color ink = readonly || ui->disabled ? ui->style.dim : ui->style.text;
    int tw = isk_ui_text_width(ui, shown);
    int x0 = tw <= inner.w ? inner.x + (inner.w - tw) / 2 : inner.x;
    if (still_editing) {
        /* Keep the cursor in view when the text is wider than the field. */
        int cx = x0 + ui->cursor * cell;
        if (cx > inner.x + inner.w - s)
            x0 -= cx - (inner.x + inner.w - s);
    }
    ui_text_clip(ui, isk_ui_inset(r, s), x0, ui_text_y(ui, r), shown, ink);
    if (still_editing) {
        int cx = x0 + ui->cursor * cell - s;
        if (cx < inner.x - s)
            cx = inner.x - s;
        ui_fill(ui, (isk_ui_rect){cx, ui_text_y(ui, r) - s, s, 9 * s}, ui->style.focus);
    }
    if (erred)
        ui->error_rect = r;
    return result;
}

void isk_ui_field_error(isk_ui *ui, const char *id, const char *message)
{
    if (!ui || !id)
        return;
    const uint32_t h = ui_id(id);
    snprintf(ui->error, sizeof ui->error, "%s", message ? message : "refused");
    ui->error_id = h;
    isk_ui_find(ui, id, &ui->error_rect);
    /* Back to the typed text, unless the user went on to another field. */
    if (!ui->focus && !ui->focus_next && ui->edit_id == h) {
        ui->focus = h;
        ui->focus_seen = 1;
        ui->cursor = (int)strlen(ui->edit);
    }
}
