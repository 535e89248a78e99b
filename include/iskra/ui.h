/* SPDX-License-Identifier: MIT */
/* iskra/ui.h — a small immediate-mode widget layer, drawn by iskra's own
 * rasterizer and bitmap font into any canvas (no other dependency).
 *
 * Immediate mode: there are no widget objects.  Every frame the program
 * calls one function per widget, with a name, a rectangle and the value it
 * shows; the function draws the widget and says what the user did to it.
 * The program keeps its own values; the layer keeps only which widget is
 * hovered, pressed or focused, and the text being edited.
 *
 * Example: a button and a number field, into which a script types a minus:
 *
 *     isk_canvas canvas;
 *     if (isk_canvas_init(&canvas, 320, 100) != ISK_OK) return 1;
 *     double gravity = 9.81;
 *     isk_ui ui;
 *     isk_ui_init(&ui, 2);                         // scale 2: text and metrics doubled
 *     for (int frame = 0; frame < 4; frame++) {
 *         isk_ui_rect f;                           // input (iskra/ui_sdl.h feeds a window's):
 *         if (frame == 1 && isk_ui_find(&ui, "gravity", &f)) {       // where the field was drawn
 *             isk_ui_input_button(&ui, f.x + 4, f.y + 4, 1);
 *             isk_ui_input_button(&ui, f.x + 4, f.y + 4, 0);           // a click on it,
 *             isk_ui_input_key(&ui, ISK_UI_KEY_HOME);
 *             isk_ui_input_text(&ui, "-");                             // "-9.81",
 *             isk_ui_input_key(&ui, ISK_UI_KEY_RETURN);                // applied
 *         }
 *         isk_ui_begin(&ui, &canvas);
 *         isk_ui_rect r = {0, 0, canvas.width, canvas.height}, row;
 *         isk_ui_panel(&ui, r);
 *         r = isk_ui_inset(r, isk_ui_px(&ui, 8));
 *         row = isk_ui_cut_top(&r, isk_ui_row_height(&ui));
 *         if (isk_ui_button(&ui, "reset", isk_ui_cut_left(&row, isk_ui_px(&ui, 60)), "Reset"))
 *             gravity = 9.81;
 *         char value_text[32], typed[64], rest;
 *         snprintf(value_text, sizeof value_text, "%g", gravity);
 *         double v;
 *         if (isk_ui_field(&ui, "gravity", row, value_text, ISK_UI_FIELD_NUMBER, typed, sizeof typed)
 *                 == ISK_UI_FIELD_APPLY) {
 *             if (sscanf(typed, "%lf %c", &v, &rest) == 1 && v >= 0) gravity = v;
 *             else isk_ui_field_error(&ui, "gravity", "expected a number >= 0");
 *         }
 *         isk_ui_end(&ui);                         // then show the canvas (iskra/sdl.h)
 *     }
 *     isk_error err;
 *     isk_status s = isk_png_write(&canvas, "ui.png", &err);   // the refusal, under the field
 *     if (s != ISK_OK) fprintf(stderr, "%s\n", err.message);
 *     isk_canvas_free(&canvas);
 *     return s != ISK_OK;
 *
 * Input.  The isk_ui_input_* functions queue events; each frame
 * (isk_ui_begin) takes them in order up to and including one mouse-button
 * change (a press and the release at the same spot count as one click), so
 * a burst of clicks and typing between two frames is played out over the
 * next frames exactly as it happened, and a scripted session gives the same
 * result whatever the frame timing.  Keys are ISK_UI_KEY_* or printable
 * ASCII (shortcuts); text is separate (what the keys typed).  While a text
 * field has the focus it takes the text and the editing keys (printable
 * keys, arrows, Home, End, Backspace, Delete, Return, Escape, Tab);
 * isk_ui_key() tells the program about the other keys, so a shortcut never
 * fires while the user types into a field.  include/iskra/ui_sdl.h feeds
 * iskra/sdl.h's events in.
 *
 * Widgets and what they return:
 *   button, icon button      1 when clicked (pressed and released over it)
 *   toggle (check box), bar  1 when flipped; *on holds the new state
 *   slider (linear, log)     1 while dragged (or wheeled) to a new value
 *   radio group              1 when another option is chosen
 *   choice (a drop-down)     1 when another option is chosen from its list
 *   list                     1 when another row is selected (wheel scrolls)
 *   selectable row           1 when clicked
 *   scroll bar               1 when clicked or dragged to another position
 *   field (text, number)     ISK_UI_FIELD_APPLY with the text typed (Return,
 *                            Tab, or a click elsewhere), ISK_UI_FIELD_CANCEL
 *                            (Escape: the text goes back to the value)
 *   label, text, wrapped text, panel, box, swatches   drawing only
 *   area                     where the pointer is and what the button does
 *                            over a rectangle (a canvas, for clicks and drags)
 * Editing a field: the focus (a click, Tab, isk_ui_focus) selects its whole
 * text, as a spin box does, so what is typed replaces the value; Ctrl+A
 * and a double click select all again; a click inside places the cursor;
 * Left/Right/Home/End move it and end the selection; Backspace and Delete
 * remove the selection or one character.
 * A refused value: call isk_ui_field_error after the APPLY; the field keeps
 * the typed text and the focus, until the next apply, Escape, or a click
 * elsewhere, and the message is shown whole, wrapped: where the program
 * puts it (isk_ui_field_message, in the flow of its layout, so it covers
 * nothing), or else in a box under the field within the panel that holds
 * the field (isk_ui_panel) or the canvas.
 *
 * Names: each widget's name is its identity (hover, focus) and its handle
 * for scripts and tests: isk_ui_find("reset") gives the rectangle the
 * widget had in the last frame.  Options of a radio group and of an open
 * choice are named "NAME/label" (lower case, spaces as '-':
 * "click/add-potential"), rows of a list "NAME/ROW" ("potentials/0").
 * Names are unique per frame; at most ISK_UI_ID_MAX - 1 characters are
 * kept.
 *
 * Layout is by cutting rectangles (isk_ui_cut_top/bottom/left/right take a
 * slice off a rectangle and shrink it); every size the layer draws is a
 * multiple of `scale` (isk_ui_px), and isk_ui_fit_scale picks the largest
 * scale at which a layout fits a window.  Text is in `font` (iskra/text.h):
 * the 5x8 font by default, whose capitals are 7 pixels tall at scale 1, or
 * ISK_FONT_6X13 (10 pixels at scale 1) for panels read from across a room;
 * row heights follow the font.
 *
 * Determinism: no clock and no global state (everything lives in the
 * isk_ui the program owns); the cursor does not blink.  The same inputs
 * and the same widget calls give the same pixels.
 */
#ifndef ISKRA_UI_H
#define ISKRA_UI_H

#include <stddef.h>
#include <stdint.h>

#include "iskra/canvas.h"
#include "iskra/color.h"
#include "iskra/text.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct isk_ui_rect {
    int x, y, w, h;
} isk_ui_rect;

/* Keys the layer knows by name; printable ASCII (32..126) are themselves.
 * (ISK_UI_TYPED marks a typed character in the frame's input.) */
enum {
    ISK_UI_KEY_NONE = 0,
    ISK_UI_TYPED = 0x10000,
    ISK_UI_KEY_BACKSPACE = 0x100,
    ISK_UI_KEY_DELETE,
    ISK_UI_KEY_RETURN,
    ISK_UI_KEY_ESCAPE,
    ISK_UI_KEY_TAB,
    ISK_UI_KEY_LEFT,
    ISK_UI_KEY_RIGHT,
    ISK_UI_KEY_UP,
    ISK_UI_KEY_DOWN,
    ISK_UI_KEY_HOME,
    ISK_UI_KEY_END,
    ISK_UI_KEY_F1, /* F1 + n - 1 for Fn, n = 1..12 */
    ISK_UI_KEY_F12 = ISK_UI_KEY_F1 + 11,
    ISK_UI_MOD_CTRL = 0x20000 /* or'ed into a key held with Ctrl: ISK_UI_MOD_CTRL | 'a' selects all */
};

typedef enum isk_ui_align { ISK_UI_LEFT = 0, ISK_UI_CENTER, ISK_UI_RIGHT } isk_ui_align;

/* Pictures for icon buttons, drawn with the rasterizer's primitives. */
typedef enum isk_ui_icon {
    ISK_UI_ICON_PLAY = 0, /* triangle */
    ISK_UI_ICON_PAUSE,    /* two bars */
    ISK_UI_ICON_STOP,     /* square */
    ISK_UI_ICON_STEP,     /* triangle and bar */
    ISK_UI_ICON_RESET,    /* one turning arrow */
    ISK_UI_ICON_RELOAD,   /* two turning arrows */
    ISK_UI_ICON_COUNT
} isk_ui_icon;

/* Colours of everything the layer draws. */
typedef struct isk_ui_style {
    isk_color background;     /* isk_ui_clear */
    isk_color panel;          /* isk_ui_panel */
    isk_color box;            /* isk_ui_box: a group inside a panel */
    isk_color label;          /* labels */
    isk_color text;           /* values, button text */
    isk_color dim;            /* read-only and disabled text */
    isk_color field;          /* field background */
    isk_color field_readonly; /* read-only field background */
    isk_color border;         /* field, list and button outlines */
    isk_color focus;          /* the focused field's outline, the cursor */
    isk_color button;         /* plain buttons */
    isk_color icon;           /* icons and text on coloured buttons */
    isk_color accent;         /* slider fill, radio dot, check mark, selected row */
    isk_color track;          /* the slider's track right of the knob */
    isk_color knob;           /* the slider's knob */
    isk_color bar_on;         /* toggle bars */
    isk_color error;          /* a refused value's message and outline */
    isk_color selection;      /* selected text's background */
} isk_ui_style;

/* The thesis simulator's dark look (the default of isk_ui_init). */
void isk_ui_style_dark(isk_ui_style *s);

#define ISK_UI_ID_MAX 72
#define ISK_UI_EDIT_MAX 256
#define ISK_UI_MAX_ITEMS 768
#define ISK_UI_QUEUE_MAX 256
#define ISK_UI_FRAME_KEYS 64
#define ISK_UI_CHOICE_MAX 32  /* options of a choice */
#define ISK_UI_LABEL_MAX 40   /* characters of an option's label kept for its list */
#define ISK_UI_PANELS_MAX 16  /* panels remembered per frame (where a message may go) */

/* A queued input event (see isk_ui_input_*). */
typedef struct isk_ui_event {
    int type;
    int x, y, value;
    char text[8];
    int clicks;
} isk_ui_event;

/* One widget of the last frame: its name and rectangle (isk_ui_find). */
typedef struct isk_ui_item {
    char id[ISK_UI_ID_MAX];
    isk_ui_rect r;
} isk_ui_item;

/* The layer's state.  Set `scale` and `style` (isk_ui_init does); the rest
 * is the layer's own, read through the functions below. */
typedef struct isk_ui {
    int scale;            /* 1, 2, 3, ...: text scale and every metric */
    isk_ui_style style;

    isk_canvas *canvas;
    /* this frame's input */
    int mouse_x, mouse_y, mouse_down, pressed, released, wheel;
    int keys[ISK_UI_FRAME_KEYS], nkeys; /* keys and typed characters (ISK_UI_TYPED | c), in order */
    uint64_t keys_taken;  /* bit i: keys[i] was used by a focused field */
    isk_ui_event queue[ISK_UI_QUEUE_MAX];
    int queue_len;
    int press_clicks;     /* 2 when this frame's press is a double click */
    /* between frames */
    uint32_t hot, active, focus, focus_next;
    int press_taken, focus_seen, tab_pending, disabled;
    char edit[ISK_UI_EDIT_MAX];
    int cursor, anchor;   /* the selection is between anchor and cursor (none when equal) */
    uint32_t edit_id;     /* the field whose text `edit` holds (kept after an apply) */
    char error[240];
    uint32_t error_id;
    char error_name[ISK_UI_ID_MAX]; /* the name of the field error_id is */
    isk_ui_rect error_rect;
    int error_placed;     /* the program showed the message this frame (isk_ui_field_message) */
    /* the open choice's list */
    uint32_t popup_id, popup_closed_id; /* the open one; the one a press closed this frame */
    int popup_seen, popup_n, popup_pick, popup_mark; /* option picked this frame; the chosen one */
    isk_ui_rect popup_rect;
    char popup_labels[ISK_UI_CHOICE_MAX][ISK_UI_LABEL_MAX];
    isk_ui_rect panels[ISK_UI_PANELS_MAX];
    int npanels;
    long frame;
    isk_ui_item items[ISK_UI_MAX_ITEMS];
    int nitems;
    isk_font font;        /* the text's font: ISK_FONT_5X8 (isk_ui_init) or ISK_FONT_6X13 */
} isk_ui;

/* scale < 1 counts as 1; the 5x8 font; the dark style. */
void isk_ui_init(isk_ui *ui, int scale);

/* ---- input (queued; taken by the next isk_ui_begin) --------------------------- */

void isk_ui_input_mouse(isk_ui *ui, int x, int y);            /* the pointer moved */
void isk_ui_input_button(isk_ui *ui, int x, int y, int down); /* left button pressed (1) / released (0) */
/* The same, with the window system's count of quick clicks at one spot
 * (2 for the press of a double click: a field selects all). */
void isk_ui_input_button_clicks(isk_ui *ui, int x, int y, int down, int clicks);
void isk_ui_input_wheel(isk_ui *ui, int dy);                  /* +1 away from the user, -1 towards */
void isk_ui_input_key(isk_ui *ui, int key);                   /* ISK_UI_KEY_* or printable ASCII,
                                                                 or'ed with ISK_UI_MOD_CTRL */
void isk_ui_input_text(isk_ui *ui, const char *utf8);         /* typed text: printable ASCII is kept */
/* Events still waiting (the program can run frames until it is 0). */
int isk_ui_pending(const isk_ui *ui);

/* ---- frames -------------------------------------------------------------------- */

/* Starts a frame that draws into `canvas` (kept until isk_ui_end). */
void isk_ui_begin(isk_ui *ui, isk_canvas *canvas);
/* Ends it: drops the focus of a field that was not drawn, draws a refused
 * value's message on top, forgets this frame's input. */
void isk_ui_end(isk_ui *ui);

/* 1 when `key` was pressed this frame and no focused field took it (see
 * the header comment); F1..F12 always reach the program. */
int isk_ui_key(const isk_ui *ui, int key);
/* This frame's keys that no field took, in order (typed text excluded):
 * at most max into out, returns how many.  For shortcuts that must see a
 * key pressed twice in one frame twice. */
int isk_ui_keys(const isk_ui *ui, int *out, int max);
/* 1 while a text field has the focus (keys go to it). */
int isk_ui_editing(const isk_ui *ui);
/* 1 when the pointer is over any widget drawn so far this frame. */
int isk_ui_hovering(const isk_ui *ui);
/* This frame's wheel notches (+1 away from the user) when the pointer is
 * over r, else 0: for scrolling a region the program lays out itself. */
int isk_ui_wheel(const isk_ui *ui, isk_ui_rect r);
/* 1 while the pointer is over r and no open choice's list covers it. */
int isk_ui_hovered(const isk_ui *ui, isk_ui_rect r);
/* Widgets drawn while disabled (1) are dimmed and ignore input. */
void isk_ui_set_disabled(isk_ui *ui, int disabled);
/* Gives a field the focus (as a click would), from the next frame. */
void isk_ui_focus(isk_ui *ui, const char *id);
/* 1 while field `id` has the focus (is being edited). */
int isk_ui_focused(const isk_ui *ui, const char *id);

/* The rectangle the widget `id` had in the last frame: 1, or 0 if none. */
int isk_ui_find(const isk_ui *ui, const char *id, isk_ui_rect *out);

/* ---- layout ------------------------------------------------------------------------ */

int isk_ui_px(const isk_ui *ui, int units);        /* units * scale */
int isk_ui_row_height(const isk_ui *ui);           /* a button's or field's height: a line + 6 units */
int isk_ui_line_height(const isk_ui *ui);          /* a line of text: the font's cell height * scale */
int isk_ui_text_width(const isk_ui *ui, const char *s);
/* `text` broken into lines at most `width` pixels wide (at spaces, and
 * inside words longer than a line; '\n' breaks too) into out; returns the
 * number of lines (0 for empty text or a width under five characters). */
int isk_ui_wrap(const isk_ui *ui, const char *text, int width, char *out, size_t out_size);
int isk_ui_contains(isk_ui_rect r, int x, int y);
isk_ui_rect isk_ui_inset(isk_ui_rect r, int d);    /* d off every side (never below 0 x 0) */
/* A slice of `size` pixels off one side of *r (clamped to what is left);
 * *r loses it. */
isk_ui_rect isk_ui_cut_top(isk_ui_rect *r, int size);
isk_ui_rect isk_ui_cut_bottom(isk_ui_rect *r, int size);
isk_ui_rect isk_ui_cut_left(isk_ui_rect *r, int size);
isk_ui_rect isk_ui_cut_right(isk_ui_rect *r, int size);
/* Cell (col, row) of r split into cols x rows with `gap` pixels between. */
isk_ui_rect isk_ui_cell(isk_ui_rect r, int cols, int rows, int col, int row, int gap);
/* The largest scale (1..max_scale) at which a layout of need_w x need_h
 * pixels at scale 1 fits avail_w x avail_h; 1 if none fits. */
int isk_ui_fit_scale(int avail_w, int avail_h, int need_w, int need_h, int max_scale);

/* ---- drawing --------------------------------------------------------------------------- */

void isk_ui_clear(isk_ui *ui);                        /* the whole canvas in style.background */
void isk_ui_panel(isk_ui *ui, isk_ui_rect r);         /* a rounded panel */
void isk_ui_box(isk_ui *ui, isk_ui_rect r);           /* a group inside a panel */
/* Text in the label colour, vertically centred in r (lines split at '\n'). */
void isk_ui_label(isk_ui *ui, isk_ui_rect r, const char *text, isk_ui_align align);
/* Text in any colour, top-aligned, clipped to r. */
void isk_ui_text(isk_ui *ui, isk_ui_rect r, const char *text, isk_color color, isk_ui_align align);
/* The line of r in which isk_ui_label centres one line of text: for
 * isk_ui_text in another colour, level with labels. */
isk_ui_rect isk_ui_text_line(const isk_ui *ui, isk_ui_rect r);
/* Text wrapped to r's width (isk_ui_wrap), top-aligned, clipped to r;
 * returns the height it needs (lines * line height), drawn or not. */
int isk_ui_text_wrapped(isk_ui *ui, isk_ui_rect r, const char *text, isk_color color);
/* Colours side by side over a checkerboard (so alpha shows): one swatch
 * (n = 1) or a ramp's samples, with an outline. */
void isk_ui_swatches(isk_ui *ui, isk_ui_rect r, const isk_color *colors, int n);

/* ---- widgets ------------------------------------------------------------------------- */

int isk_ui_button(isk_ui *ui, const char *id, isk_ui_rect r, const char *label);
/* A coloured button with a picture (the thesis's play/pause/stop/reload);
 * `label` (may be NULL) is written under the icon when r is tall enough. */
int isk_ui_icon_button(isk_ui *ui, const char *id, isk_ui_rect r, isk_ui_icon icon, isk_color color,
                       const char *label);
int isk_ui_toggle(isk_ui *ui, const char *id, isk_ui_rect r, const char *label, int *on);
/* A bar that is solid when on and a dashed outline when off (the thesis's
 * walls, drawn as the four sides of a square). */
int isk_ui_toggle_bar(isk_ui *ui, const char *id, isk_ui_rect r, int *on);
/* *value in [min, max], moved in multiples of step from min (step 0: any);
 * only a drag or the wheel changes *value (one outside [min, max] is shown
 * at the track's end and left as it is). */
int isk_ui_slider(isk_ui *ui, const char *id, isk_ui_rect r, double *value, double min, double max, double step);
/* The same over many decades: the track is logarithmic in |value| (a
 * symmetric log around 0, linear for |value| below `linear` > 0), so every
 * decade gets the same length; a dragged or wheeled value is rounded to 3
 * significant digits (and to whole numbers when `whole`). */
int isk_ui_slider_log(isk_ui *ui, const char *id, isk_ui_rect r, double *value, double min, double max, double linear,
                      int whole);
/* n options in rows of per_row (n: one row); *selected is the chosen index. */
int isk_ui_radio(isk_ui *ui, const char *id, isk_ui_rect r, const char *const *labels, int n, int per_row,
                 int *selected);
/* A drop-down: shows labels[*selected] (or "-" when it is out of range);
 * a click opens the list of all n options (at most ISK_UI_CHOICE_MAX)
 * under it, or above it when the canvas ends, drawn over everything at
 * isk_ui_end; a click on an option chooses it (returns 1), a click
 * anywhere else or Escape closes the list. */
int isk_ui_choice(isk_ui *ui, const char *id, isk_ui_rect r, const char *const *labels, int n, int *selected);
/* n rows; *selected (-1: none) and *scroll (the first row shown) are the
 * program's.  A scroll bar appears when the rows do not fit. */
int isk_ui_list(isk_ui *ui, const char *id, isk_ui_rect r, const char *const *rows, int n, int *selected,
                int *scroll);
/* One row of a list the program lays out itself: highlighted when
 * `selected`, shaded under the pointer; 1 when clicked. */
int isk_ui_selectable(isk_ui *ui, const char *id, isk_ui_rect r, const char *label, int selected);
/* A vertical scroll bar for `total` rows of which `visible` show from
 * *first: a click or drag on it moves *first there (1 when it changed).
 * Nothing is drawn when everything shows. */
int isk_ui_scrollbar(isk_ui *ui, const char *id, isk_ui_rect r, int *first, int total, int visible);

enum {
    ISK_UI_FIELD_NUMBER = 1u << 0,   /* only digits, sign, '.', 'e', '/' can be typed */
    ISK_UI_FIELD_READONLY = 1u << 1, /* shows `value`, cannot be edited */
};
typedef enum isk_ui_field_result {
    ISK_UI_FIELD_IDLE = 0,
    ISK_UI_FIELD_APPLY,  /* the typed text is in out */
    ISK_UI_FIELD_CANCEL
} isk_ui_field_result;
/* Shows `value`; a click edits it (cursor, Left/Right/Home/End, Backspace,
 * Delete).  On APPLY the typed text is copied to out (out_size bytes). */
isk_ui_field_result isk_ui_field(isk_ui *ui, const char *id, isk_ui_rect r, const char *value, unsigned flags,
                                 char *out, size_t out_size);
/* The value just applied in field `id` was refused: see the header comment. */
void isk_ui_field_error(isk_ui *ui, const char *id, const char *message);
/* Puts the refused value's message of field `id` (NULL: of whichever field
 * has one, unless it was put somewhere this frame) at the top of *area, wrapped to its width, and takes the height
 * it needs off *area; returns that height (0: no message).  Called where a
 * layout has room for it, so the message covers no other widget; a message
 * the program does not place is drawn at isk_ui_end in a box under its
 * field. */
int isk_ui_field_message(isk_ui *ui, const char *id, isk_ui_rect *area);
/* The text of the refused value's message (NULL: none), and which field's. */
const char *isk_ui_field_message_text(const isk_ui *ui, const char **id_out);

typedef struct isk_ui_area_state {
    int hover;     /* the pointer is over it */
    int pressed;   /* the button went down over it this frame */
    int down;      /* it holds the button (since a press over it): a drag */
    int released;  /* the button it held came up this frame */
    int x, y;      /* the pointer, relative to r's top-left */
} isk_ui_area_state;
isk_ui_area_state isk_ui_area(isk_ui *ui, const char *id, isk_ui_rect r);

#ifdef __cplusplus
}
#endif

#endif
