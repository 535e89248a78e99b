/* SPDX-License-Identifier: MIT */
/* src/ui/ui_internal.h — what the widget files of src/ui share (internal).
 *
 * A widget is identified by the hash of its name (isk__ui_id), records its
 * rectangle for isk_ui_find (isk__ui_record), and asks isk__ui_interact whether the
 * pointer is over it and whether it holds the button.  Drawing helpers
 * (rounded boxes, icons, text placement) are in ui_draw.c. */
#ifndef ISKRA_UI_INTERNAL_H
#define ISKRA_UI_INTERNAL_H

#include "iskra/ui.h"

/* Event types of the input queue. */
enum { UI_EV_MOVE = 1, UI_EV_BUTTON, UI_EV_WHEEL, UI_EV_KEY, UI_EV_TEXT };

/* FNV-1a of the name; never 0 (0 means "no widget"). */
uint32_t isk__ui_id(const char *name);
/* "NAME/label" for options (lower case, spaces as '-'), "NAME/ROW" for rows. */
void isk__ui_sub_name(char *out, size_t n, const char *name, const char *label, int index);
void isk__ui_record(isk_ui *ui, const char *name, isk_ui_rect r);

typedef struct ui_state {
    int hover;    /* the pointer is over it (and nothing disables it) */
    int pressed;  /* it took the press this frame */
    int active;   /* it holds the button */
    int clicked;  /* the button came up over it after it took the press */
    int released; /* the button it held came up this frame */
} ui_state;
/* Hover and press bookkeeping for the widget `id` at r. */
ui_state isk__ui_interact(isk_ui *ui, uint32_t id, isk_ui_rect r);

/* Colours a little lighter / darker (hover, pressed). */
isk_color isk__ui_shade(isk_color c, int delta);
/* Half way to the background: disabled widgets. */
isk_color isk__ui_dim(const isk_ui *ui, isk_color c);

/* Drawing in the frame's canvas (ui->canvas; nothing when NULL). */
void isk__ui_fill(isk_ui *ui, isk_ui_rect r, isk_color c);
void isk__ui_round(isk_ui *ui, isk_ui_rect r, int radius, isk_color c);
/* A rounded box with a `width`-pixel outline. */
void isk__ui_round_outline(isk_ui *ui, isk_ui_rect r, int radius, int width, isk_color outline, isk_color fill);
void isk__ui_disc(isk_ui *ui, double cx, double cy, double r, isk_color c);
/* One line of text placed in r (vertically centred on the capitals),
 * clipped to r. */
void isk__ui_text_line(isk_ui *ui, isk_ui_rect r, const char *s, isk_color c, isk_ui_align align);
/* One line centred in r at another text scale. */
void isk__ui_text_scaled(isk_ui *ui, isk_ui_rect r, const char *s, isk_color c, int scale);
/* Text with its first cell's top-left at (x, y), clipped to `clip`. */
void isk__ui_text_clip(isk_ui *ui, isk_ui_rect clip, int x, int y, const char *s, isk_color c);
/* x of the text's first cell when placed in r with `align`. */
int isk__ui_text_x(const isk_ui *ui, isk_ui_rect r, const char *s, isk_ui_align align);
/* Top of a line of text vertically centred in r. */
int isk__ui_text_y(const isk_ui *ui, isk_ui_rect r);
void isk__ui_icon(isk_ui *ui, isk_ui_rect r, isk_ui_icon icon, isk_color c);
/* The font's metrics (never NULL: an unknown font counts as 5x8). */
const isk_font_metrics *isk__ui_font(const isk_ui *ui);

/* The open choice's list (ui_choice.c): at isk_ui_begin, a press on it
 * picks an option (and no widget under it gets the press), a press
 * elsewhere or Escape closes it; at isk_ui_end it is drawn over
 * everything. */
void isk__ui_popup_input(isk_ui *ui);
void isk__ui_popup_draw(isk_ui *ui);

#endif
