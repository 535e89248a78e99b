/* SPDX-License-Identifier: MIT */
/* The widget layer's frame and input bookkeeping (see iskra/ui.h): the
 * input queue, which events one frame takes, names and rectangles of the
 * widgets, hover/press/focus. */
#include <stdio.h>
#include <string.h>

#include "ui_internal.h"

void isk_ui_style_dark(isk_ui_style *s)
{
    /* Sampled from the thesis's simulator page (figures 21-25). */
    s->background = isk_rgba(0x2b, 0x2b, 0x2b, 255);
    s->panel = isk_rgba(0x1c, 0x1c, 0x1c, 255);
    s->box = isk_rgba(0x2d, 0x2d, 0x2d, 255);
    s->label = isk_rgba(0xb3, 0x88, 0xeb, 255);
    s->text = isk_rgba(0xe6, 0xe0, 0xf0, 255);
    s->dim = isk_rgba(0x7a, 0x6a, 0x90, 255);
    s->field = isk_rgba(0x2b, 0x2b, 0x2b, 255);
    s->field_readonly = isk_rgba(0x1f, 0x1f, 0x1f, 255);
    s->border = isk_rgba(0x4a, 0x4a, 0x4a, 255);
    s->focus = isk_rgba(0x6e, 0xa8, 0xfe, 255);
    s->button = isk_rgba(0x3a, 0x3a, 0x3a, 255);
    s->icon = isk_rgba(0xff, 0xff, 0xff, 255);
    s->accent = isk_rgba(0x2b, 0x7b, 0xe4, 255);
    s->track = isk_rgba(0xd0, 0xd0, 0xd6, 255);
    s->knob = isk_rgba(0x67, 0x67, 0x74, 255);
    s->bar_on = isk_rgba(0x75, 0x75, 0x75, 255);
    s->error = isk_rgba(0xff, 0x6b, 0x5e, 255);
    s->selection = isk_rgba(0x2a, 0x4d, 0x80, 255);
}

void isk_ui_init(isk_ui *ui, int scale)
{
    if (!ui)
        return;
    memset(ui, 0, sizeof *ui);
    ui->scale = scale < 1 ? 1 : scale;
    ui->font = ISK_FONT_5X8;
    isk_ui_style_dark(&ui->style);
    ui->mouse_x = ui->mouse_y = -1;
}

/* ---- names ------------------------------------------------------------------------ */

uint32_t isk__ui_id(const char *name)
{
    uint32_t h = 2166136261u;
    for (const unsigned char *p = (const unsigned char *)(name ? name : ""); *p; p++)
        h = (h ^ *p) * 16777619u;
    return h ? h : 1u;
}

void isk__ui_sub_name(char *out, size_t n, const char *name, const char *label, int index)
{
    if (!label) {
        snprintf(out, n, "%s/%d", name, index);
        return;
    }
    size_t k = (size_t)snprintf(out, n, "%s/", name);
    for (const char *p = label; *p && k + 1 < n; p++, k++)
        out[k] = *p == ' ' ? '-' : (*p >= 'A' && *p <= 'Z') ? (char)(*p - 'A' + 'a') : *p;
    if (k < n)
        out[k] = 0;
}

void isk__ui_record(isk_ui *ui, const char *name, isk_ui_rect r)
{
    if (ui->nitems >= ISK_UI_MAX_ITEMS || !name)
        return;
    isk_ui_item *it = &ui->items[ui->nitems++];
    snprintf(it->id, sizeof it->id, "%s", name);
    it->r = r;
}

int isk_ui_find(const isk_ui *ui, const char *id, isk_ui_rect *out)
{
    for (int i = 0; ui && id && i < ui->nitems; i++)
        if (!strncmp(ui->items[i].id, id, ISK_UI_ID_MAX - 1)) {
            if (out)
                *out = ui->items[i].r;
            return 1;
        }
    return 0;
}

/* ---- input queue ---------------------------------------------------------------------- */

static void push(isk_ui *ui, isk_ui_event ev)
{
    if (!ui)
        return;
    if (ui->queue_len == ISK_UI_QUEUE_MAX) {
        /* Full: the oldest pointer motion gives way (later ones say where
         * the pointer is); with none to drop, the new event is lost. */
        int i = 0;
        while (i < ui->queue_len && ui->queue[i].type != UI_EV_MOVE)
            i++;
        if (i == ui->queue_len)
            return;
        memmove(&ui->queue[i], &ui->queue[i + 1], sizeof ui->queue[0] * (size_t)(ui->queue_len - i - 1));
        ui->queue_len--;
    }
    ui->queue[ui->queue_len++] = ev;
}

void isk_ui_input_mouse(isk_ui *ui, int x, int y)
{
    isk_ui_event e = {UI_EV_MOVE, x, y, 0, {0}, 0};
    push(ui, e);
}

void isk_ui_input_button_clicks(isk_ui *ui, int x, int y, int down, int clicks)
{
    isk_ui_event e = {UI_EV_BUTTON, x, y, down != 0, {0}, clicks > 1 ? clicks : 1};
    push(ui, e);
}

void isk_ui_input_button(isk_ui *ui, int x, int y, int down) { isk_ui_input_button_clicks(ui, x, y, down, 1); }

void isk_ui_input_wheel(isk_ui *ui, int dy)
{
    isk_ui_event e = {UI_EV_WHEEL, 0, 0, dy > 0 ? 1 : dy < 0 ? -1 : 0, {0}, 0};
    if (dy)
        push(ui, e);
}

void isk_ui_input_key(isk_ui *ui, int key)
{
    isk_ui_event e = {UI_EV_KEY, 0, 0, key, {0}, 0};
    if (key > 0)
        push(ui, e);
}

void isk_ui_input_text(isk_ui *ui, const char *utf8)
{
    /* Printable ASCII only (the font has nothing else), in pieces of 7. */
    isk_ui_event e = {UI_EV_TEXT, 0, 0, 0, {0}, 0};
    size_t k = 0;
    for (const unsigned char *p = (const unsigned char *)(utf8 ? utf8 : ""); *p; p++) {
        if (*p < 32 || *p > 126)
            continue;
        e.text[k++] = (char)*p;
        if (k == sizeof e.text - 1) {
            e.text[k] = 0;
            push(ui, e);
            k = 0;
        }
    }
    if (k) {
        e.text[k] = 0;
        push(ui, e);
    }
}

int isk_ui_pending(const isk_ui *ui) { return ui ? ui->queue_len : 0; }

static int ends_frame_input(int key)
{
    /* Keys that move the focus: what follows belongs to the next widget. */
    return key == ISK_UI_KEY_RETURN || key == ISK_UI_KEY_TAB || key == ISK_UI_KEY_ESCAPE;
}

/* Takes this frame's events: in order, up to and including one button
 * change (a press directly followed by its release at the same spot is one
 * click); keys and text after a button change wait for the next frame. */
static void take_input(isk_ui *ui)
{
    ui->pressed = ui->released = ui->wheel = 0;
    ui->press_clicks = 0;
    ui->nkeys = 0;
    ui->keys_taken = 0;
    int i = 0;
    for (; i < ui->queue_len; i++) {
        const isk_ui_event *e = &ui->queue[i];
        if (e->type == UI_EV_MOVE) {
            ui->mouse_x = e->x;
            ui->mouse_y = e->y;
        } else if (e->type == UI_EV_WHEEL) {
            ui->wheel += e->value;
        } else if (e->type == UI_EV_KEY) {
            if (ui->nkeys == ISK_UI_FRAME_KEYS)
                break;
            ui->keys[ui->nkeys++] = e->value;
            if (ends_frame_input(e->value)) {
                i++;
                break;
            }
        } else if (e->type == UI_EV_TEXT) {
            int n = (int)strlen(e->text);
            if (ui->nkeys + n > ISK_UI_FRAME_KEYS)
                break;
            for (int k = 0; k < n; k++)
                ui->keys[ui->nkeys++] = ISK_UI_TYPED | (unsigned char)e->text[k];
        } else if (e->type == UI_EV_BUTTON) {
            ui->mouse_x = e->x;
            ui->mouse_y = e->y;
            if (e->value) {
                ui->pressed = ui->mouse_down = 1;
                ui->press_clicks = e->clicks;
                const isk_ui_event *n = i + 1 < ui->queue_len ? &ui->queue[i + 1] : NULL;
                if (n && n->type == UI_EV_BUTTON && !n->value && n->x == e->x && n->y == e->y) {
                    ui->released = 1;
                    ui->mouse_down = 0;
                    i++;
                }
            } else {
                ui->released = 1;
                ui->mouse_down = 0;
            }
            i++;
            break;
        }
    }
    memmove(ui->queue, ui->queue + i, sizeof ui->queue[0] * (size_t)(ui->queue_len - i));
    ui->queue_len -= i;
}

/* ---- frames ---------------------------------------------------------------------------- */

void isk_ui_begin(isk_ui *ui, isk_canvas *canvas)
{
    if (!ui)
        return;
    ui->canvas = canvas && canvas->pixels ? canvas : NULL;
    take_input(ui);
    if (ui->focus_next) {
        /* A field clicked (or isk_ui_focus) last frame: the one that had the
         * focus applied its text then, so the buffer is free now. */
        ui->focus = ui->focus_next;
        ui->focus_next = 0;
        ui->edit_id = 0;
    }
    ui->hot = 0;
    ui->press_taken = 0;
    ui->focus_seen = 0;
    ui->disabled = 0;
    ui->nitems = 0;
    ui->npanels = 0;
    ui->error_placed = 0;
    ui->popup_seen = 0;
    ui->popup_pick = -1;
    ui->popup_closed_id = 0;
    isk__ui_popup_input(ui);
    /* A press anywhere else clears a refused value's message. */
    if (ui->pressed && ui->error_id && ui->focus != ui->error_id)
        ui->error_id = 0;
}

/* The container of a floating message: the smallest panel drawn this
 * frame that holds the field, else the canvas. */
static isk_ui_rect message_container(const isk_ui *ui, isk_ui_rect field)
{
    isk_ui_rect best = {0, 0, ui->canvas->width, ui->canvas->height};
    long best_area = -1;
    for (int i = 0; i < ui->npanels; i++) {
        isk_ui_rect p = ui->panels[i];
        long area = (long)p.w * p.h;
        if (field.x >= p.x && field.y >= p.y && field.x + field.w <= p.x + p.w && field.y + field.h <= p.y + p.h &&
            (best_area < 0 || area < best_area)) {
            best = p;
            best_area = area;
        }
    }
    return best;
}

/* A refused value's message the program did not place: in a box under its
 * field (above it when the container ends), as wide as its longest line,
 * wrapped to the container's width and kept inside it. */
static void floating_message(isk_ui *ui)
{
    const int s = ui->scale, pad = 3 * s;
    const isk_ui_rect in = message_container(ui, ui->error_rect);
    char lines[sizeof ui->error + 64];
    const int n = isk_ui_wrap(ui, ui->error, in.w - 2 * pad, lines, sizeof lines);
    if (n <= 0)
        return;
    int w = isk_ui_text_width(ui, lines) + 2 * pad;
    int h = (n - 1) * isk_ui_line_height(ui) + isk_font_metrics_of(ui->font)->glyph_h * s + 2 * pad;
    if (n == 1) /* one line: the height the box always had */
        h = isk_ui_line_height(ui) + 2 * pad;
    isk_ui_rect box = {ui->error_rect.x, ui->error_rect.y + ui->error_rect.h + s, w, h};
    if (box.x + box.w > in.x + in.w)
        box.x = in.x + in.w - box.w;
    if (box.x < in.x)
        box.x = in.x;
    if (box.y + box.h > in.y + in.h)
        box.y = ui->error_rect.y - h - s;
    isk__ui_round_outline(ui, box, 2 * s, s, ui->style.error, ui->style.panel);
    isk_ui_rect t = isk_ui_inset(box, pad);
    if (n == 1)
        isk__ui_text_line(ui, t, lines, ui->style.error, ISK_UI_LEFT);
    else
        isk_ui_text(ui, t, lines, ui->style.error, ISK_UI_LEFT);
}

void isk_ui_end(isk_ui *ui)
{
    if (!ui)
        return;
    if (ui->focus && !ui->focus_seen)
        ui->focus = 0;
    if (ui->released)
        ui->active = 0;
    if (ui->popup_id && !ui->popup_seen)
        ui->popup_id = 0; /* its choice was not drawn: the list goes with it */
    if (ui->error_id && ui->error[0] && ui->canvas && !ui->error_placed)
        floating_message(ui);
    isk__ui_popup_draw(ui);
    ui->frame++;
}

int isk_ui_key(const isk_ui *ui, int key)
{
    for (int i = 0; ui && i < ui->nkeys; i++)
        if (ui->keys[i] == key && !(ui->keys_taken >> i & 1u) && key < ISK_UI_TYPED)
            return 1;
    return 0;
}

int isk_ui_keys(const isk_ui *ui, int *out, int max)
{
    int m = 0;
    for (int i = 0; ui && out && i < ui->nkeys && m < max; i++)
        if (!(ui->keys_taken >> i & 1u) && ui->keys[i] < ISK_UI_TYPED)
            out[m++] = ui->keys[i];
    return m;
}

int isk_ui_editing(const isk_ui *ui) { return ui && ui->focus != 0; }

int isk_ui_hovering(const isk_ui *ui) { return ui && ui->hot != 0; }

int isk_ui_hovered(const isk_ui *ui, isk_ui_rect r)
{
    if (!ui || !isk_ui_contains(r, ui->mouse_x, ui->mouse_y))
        return 0;
    return !(ui->popup_id && isk_ui_contains(ui->popup_rect, ui->mouse_x, ui->mouse_y));
}

int isk_ui_wheel(const isk_ui *ui, isk_ui_rect r) { return isk_ui_hovered(ui, r) ? ui->wheel : 0; }

void isk_ui_set_disabled(isk_ui *ui, int disabled)
{
    if (ui)
        ui->disabled = disabled != 0;
}

void isk_ui_focus(isk_ui *ui, const char *id)
{
    if (!ui)
        return;
    if (id)
        ui->focus_next = isk__ui_id(id); /* the field loads its value when it is drawn */
    else
        ui->focus = ui->focus_next = 0;
}

int isk_ui_focused(const isk_ui *ui, const char *id) { return ui && id && ui->focus && ui->focus == isk__ui_id(id); }

ui_state isk__ui_interact(isk_ui *ui, uint32_t id, isk_ui_rect r)
{
    ui_state st = {0, 0, 0, 0, 0};
    if (ui->disabled)
        return st;
    const int inside = isk_ui_hovered(ui, r);
    if (inside) {
        st.hover = 1;
        ui->hot = id;
    }
    if (ui->pressed && inside && !ui->press_taken) {
        ui->active = id;
        ui->press_taken = 1;
        st.pressed = 1;
    }
    if (ui->active == id) {
        st.active = 1;
        if (ui->released) {
            st.released = 1;
            st.clicked = inside;
        }
    }
    return st;
}
