/* SPDX-License-Identifier: MIT */
/* The widgets that are not text fields: buttons, toggles, slider, radio
 * group, list, area (see iskra/ui.h).  Each records its rectangle under its
 * name, asks isk__ui_interact what the pointer does to it, draws itself in the
 * state that results, and returns what happened. */
#include <math.h>
#include <stdio.h>

#include "iskra/draw.h"
#include "iskra/text.h"
#include "ui_internal.h"

static isk_color hover_shade(isk_color c, ui_state st)
{
    return st.active && st.hover ? isk__ui_shade(c, -18) : st.hover || st.active ? isk__ui_shade(c, 20) : c;
}

static isk_color text_colour(const isk_ui *ui, isk_color c)
{
    return ui->disabled ? isk__ui_dim(ui, c) : c;
}

int isk_ui_button(isk_ui *ui, const char *id, isk_ui_rect r, const char *label)
{
    if (!ui || !id)
        return 0;
    isk__ui_record(ui, id, r);
    ui_state st = isk__ui_interact(ui, isk__ui_id(id), r);
    const int s = ui->scale;
    isk_color bg = hover_shade(ui->style.button, st);
    isk__ui_round_outline(ui, r, 3 * s, s, ui->disabled ? isk__ui_dim(ui, ui->style.border) : ui->style.border,
                     ui->disabled ? isk__ui_dim(ui, bg) : bg);
    if (label)
        isk__ui_text_line(ui, r, label, text_colour(ui, ui->style.text), ISK_UI_CENTER);
    return st.clicked;
}

int isk_ui_icon_button(isk_ui *ui, const char *id, isk_ui_rect r, isk_ui_icon icon, isk_color color,
                       const char *label)
{
    if (!ui || !id)
        return 0;
    isk__ui_record(ui, id, r);
    ui_state st = isk__ui_interact(ui, isk__ui_id(id), r);
    const int s = ui->scale;
    isk_color bg = hover_shade(color, st);
    isk__ui_round(ui, r, 3 * s, ui->disabled ? isk__ui_dim(ui, bg) : bg);
    isk_ui_rect pic = r;
    const int cell_h = isk__ui_font(ui)->cell_h, line = cell_h * s;
    if (label && *label && r.h >= 3 * line) {
        /* The label under the picture, a size smaller when it would not fit. */
        int ts = s;
        while (ts > 1 && isk_font_text_width(ui->font, label, ts) - ts > r.w - 2 * s)
            ts--;
        isk_ui_rect under = isk_ui_cut_bottom(&pic, cell_h * ts + 2 * s);
        isk_ui_rect t = isk_ui_cut_top(&under, cell_h * ts);
        isk__ui_text_scaled(ui, t, label, text_colour(ui, ui->style.icon), ts);
    }
    isk__ui_icon(ui, pic, icon, text_colour(ui, ui->style.icon));
    return st.clicked;
}

/* A thick line as discs along it (check marks). */
static void thick_line(isk_ui *ui, double x0, double y0, double x1, double y1, double w, isk_color c)
{
    double len = hypot(x1 - x0, y1 - y0);
    int n = (int)(len / (w * 0.25)) + 1;
    for (int i = 0; i <= n; i++)
        isk__ui_disc(ui, x0 + (x1 - x0) * i / n, y0 + (y1 - y0) * i / n, w / 2, c);
}

int isk_ui_toggle(isk_ui *ui, const char *id, isk_ui_rect r, const char *label, int *on)
{
    if (!ui || !id || !on)
        return 0;
    isk__ui_record(ui, id, r);
    ui_state st = isk__ui_interact(ui, isk__ui_id(id), r);
    const int s = ui->scale, box = 11 * s;
    isk_ui_rect b = {r.x, r.y + (r.h - box) / 2, box, box};
    if (st.clicked)
        *on = !*on;
    isk_color edge = hover_shade(*on ? ui->style.accent : ui->style.border, st);
    isk__ui_round_outline(ui, b, 2 * s, s, ui->disabled ? isk__ui_dim(ui, edge) : edge,
                     *on ? (ui->disabled ? isk__ui_dim(ui, ui->style.accent) : ui->style.accent) : ui->style.field);
    if (*on) {
        const isk_color mark = text_colour(ui, ui->style.icon);
        thick_line(ui, b.x + 2.5 * s, b.y + 5.5 * s, b.x + 4.5 * s, b.y + 8 * s, 1.6 * s, mark);
        thick_line(ui, b.x + 4.5 * s, b.y + 8 * s, b.x + 8.5 * s, b.y + 3 * s, 1.6 * s, mark);
    }
    if (label) {
        isk_ui_rect t = r;
        isk_ui_cut_left(&t, box + 4 * s);
        isk__ui_text_line(ui, t, label, text_colour(ui, ui->style.label), ISK_UI_LEFT);
    }
    return st.clicked;
}

int isk_ui_toggle_bar(isk_ui *ui, const char *id, isk_ui_rect r, int *on)
{
    if (!ui || !id || !on)
        return 0;
    isk__ui_record(ui, id, r);
    ui_state st = isk__ui_interact(ui, isk__ui_id(id), r);
    if (st.clicked)
        *on = !*on;
    const int s = ui->scale;
    isk_color c = hover_shade(ui->style.bar_on, st);
    if (ui->disabled)
        c = isk__ui_dim(ui, c);
    if (*on) {
        isk__ui_round(ui, r, 2 * s, c);
        return st.clicked;
    }
    /* Off: a dashed outline of the bar. */
    const int dash = 3 * s, gap = 2 * s, t = s;
    for (int x = r.x; x < r.x + r.w; x += dash + gap) {
        int w = x + dash > r.x + r.w ? r.x + r.w - x : dash;
        isk__ui_fill(ui, (isk_ui_rect){x, r.y, w, t}, c);
        isk__ui_fill(ui, (isk_ui_rect){x, r.y + r.h - t, w, t}, c);
    }
    for (int y = r.y; y < r.y + r.h; y += dash + gap) {
        int h = y + dash > r.y + r.h ? r.y + r.h - y : dash;
        isk__ui_fill(ui, (isk_ui_rect){r.x, y, t, h}, c);
        isk__ui_fill(ui, (isk_ui_rect){r.x + r.w - t, y, t, h}, c);
    }
    return st.clicked;
}

static double snap(double v, double min, double max, double step)
{
    if (step > 0)
        v = min + floor((v - min) / step + 0.5) * step;
    return v < min ? min : v > max ? max : v;
}

/* Where a value lies along a slider's track (0..1) and back.  Linear, or a
 * symmetric log: g(v) = sign(v) * log10(1 + |v| / linear), so every decade
 * above `linear` gets the same length and the track passes through 0. */
typedef struct track {
    double min, max, linear; /* linear 0: a linear track */
} track;

static double symlog(double v, double linear) { return (v < 0 ? -1 : 1) * log10(1 + fabs(v) / linear); }

static double symexp(double g, double linear) { return (g < 0 ? -1 : 1) * linear * (pow(10, fabs(g)) - 1); }

static double track_f(const track *t, double v)
{
    if (t->linear <= 0)
        return (v - t->min) / (t->max - t->min);
    double a = symlog(t->min, t->linear), b = symlog(t->max, t->linear);
    return (symlog(v, t->linear) - a) / (b - a);
}

static double track_v(const track *t, double f)
{
    f = f < 0 ? 0 : f > 1 ? 1 : f;
    if (t->linear <= 0)
        return t->min + f * (t->max - t->min);
    double a = symlog(t->min, t->linear), b = symlog(t->max, t->linear);
    return symexp(a + f * (b - a), t->linear);
}

/* v to 3 significant digits (whole when asked), within [min, max]. */
static double round_3(double v, double min, double max, int whole)
{
    if (v != 0 && isfinite(v)) {
        double p = pow(10, floor(log10(fabs(v))) - 2);
        v = floor(v / p + 0.5) * p;
    }
    if (whole)
        v = floor(v + 0.5);
    return v < min ? min : v > max ? max : v;
}

static int slider(isk_ui *ui, const char *id, isk_ui_rect r, double *value, const track *t, double step, int whole)
{
    isk__ui_record(ui, id, r);
    ui_state st = isk__ui_interact(ui, isk__ui_id(id), r);
    const int s = ui->scale, knob = 7 * s;
    const double x0 = r.x + knob, x1 = r.x + r.w - knob;
    const double min = t->min, max = t->max;
    double v = isfinite(*value) ? *value : min;
    int moved = 0;
    if (st.active && (ui->mouse_down || st.released) && x1 > x0) {
        v = t->linear > 0 ? track_v(t, (ui->mouse_x - x0) / (x1 - x0))
                          : min + (ui->mouse_x - x0) / (x1 - x0) * (max - min);
        moved = 1;
    }
    if (st.hover && ui->wheel) {
        if (t->linear > 0)
            v = track_v(t, track_f(t, v) + ui->wheel / 50.0);
        else
            v += ui->wheel * (step > 0 ? step : (max - min) / 100.0);
        moved = 1;
    }
    /* Only the user moves the value: one outside the track is shown at its
     * end, and stays what it is until the knob is moved. */
    if (moved) {
        v = t->linear > 0 ? round_3(v, min, max, whole) : snap(v, min, max, step);
    } else {
        v = v < min ? min : v > max ? max : v;
    }
    const int changed = moved && v != *value;
    if (moved)
        *value = v;

    const double f = t->linear > 0 ? track_f(t, v) : (v - min) / (max - min);
    const double kx = x0 + f * (x1 - x0), cy = r.y + r.h / 2.0;
    isk_ui_rect bar = {(int)x0, (int)lround(cy) - 2 * s, (int)(x1 - x0), 4 * s};
    isk_ui_rect left = bar, right = bar;
    left.w = (int)lround(kx) - bar.x;
    right.x = bar.x + left.w;
    right.w = bar.w - left.w;
    isk__ui_round(ui, left, 2 * s, ui->disabled ? isk__ui_dim(ui, ui->style.accent) : ui->style.accent);
    isk__ui_round(ui, right, 2 * s, ui->disabled ? isk__ui_dim(ui, ui->style.track) : ui->style.track);
    isk_color k = hover_shade(ui->style.knob, st);
    isk__ui_disc(ui, kx, cy, knob, text_colour(ui, ui->style.track));
    isk__ui_disc(ui, kx, cy, knob - 1.5 * s, ui->disabled ? isk__ui_dim(ui, k) : k);
    return changed;
}

int isk_ui_slider(isk_ui *ui, const char *id, isk_ui_rect r, double *value, double min, double max, double step)
{
    if (!ui || !id || !value || !(max > min) || !isfinite(min) || !isfinite(max))
        return 0;
    track t = {min, max, 0};
    return slider(ui, id, r, value, &t, step, 0);
}

int isk_ui_slider_log(isk_ui *ui, const char *id, isk_ui_rect r, double *value, double min, double max, double linear,
                      int whole)
{
    if (!ui || !id || !value || !(max > min) || !isfinite(min) || !isfinite(max) || !(linear > 0) ||
        !isfinite(linear))
        return 0;
    track t = {min, max, linear};
    return slider(ui, id, r, value, &t, 0, whole);
}

int isk_ui_radio(isk_ui *ui, const char *id, isk_ui_rect r, const char *const *labels, int n, int per_row,
                 int *selected)
{
    if (!ui || !id || !labels || !selected || n <= 0)
        return 0;
    isk__ui_record(ui, id, r);
    const int cols = per_row > 0 && per_row < n ? per_row : n, rows = (n + cols - 1) / cols;
    const int s = ui->scale, ring = 5 * s;
    /* One row: each option as wide as its label, the room left shared out
     * evenly (or, when short of room, equal cells). */
    int natural = 0, extra = 0;
    if (rows == 1) {
        for (int i = 0; i < n; i++)
            natural += 2 * ring + 3 * s + isk_ui_text_width(ui, labels[i] ? labels[i] : "") + 4 * s;
        extra = natural <= r.w ? (r.w - natural) / n : -1;
    }
    int changed = 0, x = r.x;
    for (int i = 0; i < n; i++) {
        isk_ui_rect cell = isk_ui_cell(r, cols, rows, i % cols, i / cols, 0);
        if (rows == 1 && extra >= 0) {
            cell.x = x;
            cell.w = 2 * ring + 3 * s + isk_ui_text_width(ui, labels[i] ? labels[i] : "") + 4 * s + extra;
            x += cell.w;
        }
        char name[ISK_UI_ID_MAX];
        isk__ui_sub_name(name, sizeof name, id, labels[i], i);
        isk__ui_record(ui, name, cell);
        ui_state st = isk__ui_interact(ui, isk__ui_id(name), cell);
        if (st.clicked && *selected != i) {
            *selected = i;
            changed = 1;
        }
        const int on = *selected == i;
        const double cx = cell.x + ring, cy = cell.y + cell.h / 2.0;
        isk_color edge = hover_shade(on ? ui->style.accent : ui->style.border, st);
        isk__ui_disc(ui, cx, cy, ring, ui->disabled ? isk__ui_dim(ui, edge) : edge);
        isk__ui_disc(ui, cx, cy, ring - 1.25 * s, on ? ui->style.track : ui->style.field);
        if (on)
            isk__ui_disc(ui, cx, cy, ring - 2.5 * s, ui->disabled ? isk__ui_dim(ui, ui->style.accent) : ui->style.accent);
        isk_ui_rect t = cell;
        isk_ui_cut_left(&t, 2 * ring + 3 * s);
        isk__ui_text_line(ui, t, labels[i], text_colour(ui, ui->style.label), ISK_UI_LEFT);
    }
    return changed;
}

/* A scroll bar in `bar` for n rows of which `visible` show from *scroll
 * (clamped here); while `held` over the bar, *scroll follows the pointer. */
static void scroll_bar(isk_ui *ui, isk_ui_rect bar, int *scroll, int n, int visible, int held)
{
    const int s = ui->scale, max_scroll = n - visible;
    if (*scroll > max_scroll)
        *scroll = max_scroll;
    if (*scroll < 0)
        *scroll = 0;
    isk__ui_fill(ui, bar, ui->style.box);
    int th = bar.h * visible / n, ty = bar.y + (bar.h - th) * *scroll / max_scroll;
    isk__ui_round(ui, (isk_ui_rect){bar.x + s, ty, bar.w - 2 * s, th}, 2 * s, ui->style.bar_on);
    if (held && isk_ui_contains(bar, ui->mouse_x, ui->mouse_y))
        *scroll = (int)((long)(ui->mouse_y - bar.y) * (max_scroll + 1) / (bar.h > 0 ? bar.h : 1));
    if (*scroll > max_scroll)
        *scroll = max_scroll;
}

int isk_ui_list(isk_ui *ui, const char *id, isk_ui_rect r, const char *const *rows, int n, int *selected,
                int *scroll)
{
    if (!ui || !id || !selected || !scroll || n < 0 || (n > 0 && !rows))
        return 0;
    isk__ui_record(ui, id, r);
    const int s = ui->scale, rh = isk_ui_row_height(ui);
    isk__ui_round_outline(ui, r, 2 * s, s, ui->style.border, ui->style.field);
    isk_ui_rect in = isk_ui_inset(r, s);
    const int visible = in.h / rh > 0 ? in.h / rh : 1;
    ui_state whole = isk__ui_interact(ui, isk__ui_id(id), r);
    if (whole.hover && ui->wheel)
        *scroll -= ui->wheel;
    isk_ui_rect body = in;
    if (n > visible) {
        /* The scroll bar: a click on it moves the view there. */
        isk_ui_rect bar = isk_ui_cut_right(&body, 8 * s);
        scroll_bar(ui, bar, scroll, n, visible, whole.active && (ui->mouse_down || whole.released));
    } else {
        *scroll = 0;
    }
    int changed = 0;
    for (int i = *scroll; i < n && i < *scroll + visible; i++) {
        isk_ui_rect row = {body.x, body.y + (i - *scroll) * rh, body.w, rh};
        char name[ISK_UI_ID_MAX];
        isk__ui_sub_name(name, sizeof name, id, NULL, i);
        isk__ui_record(ui, name, row);
        int over = !ui->disabled && isk_ui_hovered(ui, row);
        if (whole.clicked && over && *selected != i) {
            *selected = i;
            changed = 1;
        }
        if (*selected == i)
            isk__ui_fill(ui, row, ui->disabled ? isk__ui_dim(ui, ui->style.accent) : ui->style.accent);
        else if (over)
            isk__ui_fill(ui, row, isk__ui_shade(ui->style.field, 16));
        isk_ui_rect t = isk_ui_inset(row, 0);
        isk_ui_cut_left(&t, 4 * s);
        isk__ui_text_line(ui, t, rows[i], text_colour(ui, ui->style.text), ISK_UI_LEFT);
    }
    return changed;
}

int isk_ui_scrollbar(isk_ui *ui, const char *id, isk_ui_rect r, int *first, int total, int visible)
{
    if (!ui || !id || !first)
        return 0;
    isk__ui_record(ui, id, r);
    ui_state st = isk__ui_interact(ui, isk__ui_id(id), r);
    const int before = *first;
    if (total <= visible || visible < 1) {
        *first = 0;
        return before != 0;
    }
    scroll_bar(ui, r, first, total, visible, st.active && (ui->mouse_down || st.released));
    return *first != before;
}

int isk_ui_selectable(isk_ui *ui, const char *id, isk_ui_rect r, const char *label, int selected)
{
    if (!ui || !id)
        return 0;
    isk__ui_record(ui, id, r);
    ui_state st = isk__ui_interact(ui, isk__ui_id(id), r);
    const int s = ui->scale;
    if (selected)
        isk__ui_fill(ui, r, ui->disabled ? isk__ui_dim(ui, ui->style.accent) : ui->style.accent);
    else if (st.hover)
        isk__ui_fill(ui, r, isk__ui_shade(ui->style.field, 16));
    isk_ui_rect t = r;
    isk_ui_cut_left(&t, 4 * s);
    if (label)
        isk__ui_text_line(ui, t, label, text_colour(ui, ui->style.text), ISK_UI_LEFT);
    return st.clicked;
}

isk_ui_area_state isk_ui_area(isk_ui *ui, const char *id, isk_ui_rect r)
{
    isk_ui_area_state a = {0, 0, 0, 0, 0, 0};
    if (!ui || !id)
        return a;
    isk__ui_record(ui, id, r);
    ui_state st = isk__ui_interact(ui, isk__ui_id(id), r);
    a.hover = st.hover;
    a.pressed = st.pressed;
    a.down = st.active && ui->mouse_down;
    a.released = st.released;
    a.x = ui->mouse_x - r.x;
    a.y = ui->mouse_y - r.y;
    return a;
}
