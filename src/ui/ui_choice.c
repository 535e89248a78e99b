/* SPDX-License-Identifier: MIT */
/* The choice (a drop-down, see iskra/ui.h): a button showing the chosen
 * option; a click opens the list of all options over everything else.
 *
 * Immediate mode with a list drawn over later widgets: the list's
 * rectangle and labels are kept in the isk_ui between frames (copied, so
 * the program's strings need not outlive the frame).  At isk_ui_begin a
 * press on the open list is the list's alone (isk__ui_popup_input marks the
 * press taken, so no widget under it reacts) and picks an option, which
 * the choice returns when it is drawn; a press anywhere else, or Escape,
 * closes the list.  The list opens at the press on its choice (so the
 * release, one frame later or in the same frame, does nothing more).  At isk_ui_end the list is drawn on top. */
#include <stdio.h>
#include <string.h>

#include "iskra/draw.h"
#include "ui_internal.h"

/* Row i of the open list. */
static isk_ui_rect option_rect(const isk_ui *ui, int i)
{
    const int rh = isk_ui_row_height(ui), s = ui->scale;
    return (isk_ui_rect){ui->popup_rect.x + s, ui->popup_rect.y + s + i * rh, ui->popup_rect.w - 2 * s, rh};
}

void isk__ui_popup_input(isk_ui *ui)
{
    if (!ui->popup_id)
        return;
    for (int i = 0; i < ui->nkeys; i++)
        if (ui->keys[i] == ISK_UI_KEY_ESCAPE) {
            ui->keys_taken |= (uint64_t)1 << i; /* Escape closes the list; it is no shortcut then */
            ui->popup_id = 0;
            return;
        }
    if (!ui->pressed)
        return;
    if (isk_ui_contains(ui->popup_rect, ui->mouse_x, ui->mouse_y)) {
        for (int i = 0; i < ui->popup_n; i++)
            if (isk_ui_contains(option_rect(ui, i), ui->mouse_x, ui->mouse_y))
                ui->popup_pick = i;
        ui->press_taken = 1; /* the list's press: nothing under it sees it */
        return;
    }
    /* Elsewhere: the list closes (a press on its own choice would open it
     * again: it stays closed). */
    ui->popup_closed_id = ui->popup_id;
    ui->popup_id = 0;
}

int isk_ui_choice(isk_ui *ui, const char *id, isk_ui_rect r, const char *const *labels, int n, int *selected)
{
    if (!ui || !id || !labels || !selected || n <= 0)
        return 0;
    if (n > ISK_UI_CHOICE_MAX)
        n = ISK_UI_CHOICE_MAX;
    const uint32_t h = isk__ui_id(id);
    const int s = ui->scale;
    isk__ui_record(ui, id, r);
    ui_state st = isk__ui_interact(ui, h, r);
    int changed = 0;
    if (ui->popup_id == h) {
        ui->popup_seen = 1;
        if (ui->popup_pick >= 0) {
            if (ui->popup_pick < n && ui->popup_pick != *selected) {
                *selected = ui->popup_pick;
                changed = 1;
            }
            ui->popup_id = 0;
        }
    } else if (st.pressed && ui->popup_closed_id != h) {
        ui->popup_id = h; /* opens at the press; drawn from isk_ui_end of this frame on */
        ui->popup_seen = 1;
    }
    if (ui->popup_id == h) {
        /* The list: under the button, or above it when the canvas ends there. */
        const int rh = isk_ui_row_height(ui), lh = n * rh + 2 * s;
        int y = r.y + r.h + s;
        if (ui->canvas && y + lh > ui->canvas->height && r.y - lh - s >= 0)
            y = r.y - lh - s;
        ui->popup_rect = (isk_ui_rect){r.x, y, r.w, lh};
        ui->popup_n = n;
        for (int i = 0; i < n; i++) {
            snprintf(ui->popup_labels[i], sizeof ui->popup_labels[i], "%s", labels[i] ? labels[i] : "");
            char name[ISK_UI_ID_MAX];
            isk__ui_sub_name(name, sizeof name, id, ui->popup_labels[i], i);
            isk__ui_record(ui, name, option_rect(ui, i));
        }
        ui->popup_mark = *selected;
    }
    /* the button: the chosen label, and a small triangle at the right */
    isk_color bg = st.hover || ui->popup_id == h ? isk__ui_shade(ui->style.field, 16) : ui->style.field;
    isk_color edge = ui->popup_id == h ? ui->style.focus : st.hover ? isk__ui_shade(ui->style.border, 24) : ui->style.border;
    if (ui->disabled) {
        bg = isk__ui_dim(ui, bg);
        edge = isk__ui_dim(ui, edge);
    }
    isk__ui_round_outline(ui, r, 2 * s, s, edge, bg);
    isk_ui_rect t = isk_ui_inset(r, 4 * s);
    isk_ui_rect arrow = isk_ui_cut_right(&t, 7 * s);
    const double cx = arrow.x + arrow.w / 2.0, cy = r.y + r.h / 2.0;
    if (ui->canvas)
        isk_fill_triangle(ui->canvas, cx - 3.5 * s, cy - 1.75 * s, cx + 3.5 * s, cy - 1.75 * s, cx, cy + 2.25 * s,
                          ui->disabled ? isk__ui_dim(ui, ui->style.label) : ui->style.label, ISK_BLEND_OVER);
    const char *label = *selected >= 0 && *selected < n && labels[*selected] ? labels[*selected] : "-";
    isk__ui_text_line(ui, t, label, ui->disabled ? isk__ui_dim(ui, ui->style.text) : ui->style.text, ISK_UI_LEFT);
    return changed;
}

void isk__ui_popup_draw(isk_ui *ui)
{
    if (!ui->popup_id || !ui->canvas)
        return;
    const int s = ui->scale;
    isk__ui_round_outline(ui, ui->popup_rect, 2 * s, s, ui->style.focus, ui->style.panel);
    for (int i = 0; i < ui->popup_n; i++) {
        isk_ui_rect row = option_rect(ui, i);
        if (i == ui->popup_mark)
            isk__ui_fill(ui, row, ui->style.accent);
        else if (isk_ui_contains(row, ui->mouse_x, ui->mouse_y))
            isk__ui_fill(ui, row, isk__ui_shade(ui->style.panel, 24));
        isk_ui_rect t = row;
        isk_ui_cut_left(&t, 4 * s);
        isk__ui_text_line(ui, t, ui->popup_labels[i], ui->style.text, ISK_UI_LEFT);
    }
}
