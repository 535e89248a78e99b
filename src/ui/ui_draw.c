/* SPDX-License-Identifier: MIT */
/* Drawing for the widget layer: rounded boxes, text placed in rectangles,
 * icons, and the drawing-only widgets (clear, panel, box, label, text).
 * Everything goes through the rasterizer (iskra/draw.h, iskra/text.h) and
 * is clipped to the rectangle it belongs to. */
#include <math.h>
#include <string.h>

#include "iskra/draw.h"
#include "iskra/text.h"
#include "ui_internal.h"

#define PI 3.14159265358979323846

isk_color isk__ui_shade(isk_color c, int delta)
{
    int v[3] = {c.r + delta, c.g + delta, c.b + delta};
    for (int i = 0; i < 3; i++)
        v[i] = v[i] < 0 ? 0 : v[i] > 255 ? 255 : v[i];
    return isk_rgba((uint8_t)v[0], (uint8_t)v[1], (uint8_t)v[2], c.a);
}

isk_color isk__ui_dim(const isk_ui *ui, isk_color c)
{
    const isk_color b = ui->style.panel;
    return isk_rgba((uint8_t)((c.r + b.r) / 2), (uint8_t)((c.g + b.g) / 2), (uint8_t)((c.b + b.b) / 2), c.a);
}

/* A view of r clipped to the canvas; *ox, *oy receive where the view's
 * (0, 0) lies on the canvas.  0 when nothing of r is visible. */
static int view_of(isk_ui *ui, isk_ui_rect r, isk_canvas *v, int *ox, int *oy)
{
    if (!ui->canvas || r.w <= 0 || r.h <= 0)
        return 0;
    int x0 = r.x < 0 ? 0 : r.x, y0 = r.y < 0 ? 0 : r.y;
    long x1 = (long)r.x + r.w, y1 = (long)r.y + r.h;
    if (x1 > ui->canvas->width)
        x1 = ui->canvas->width;
    if (y1 > ui->canvas->height)
        y1 = ui->canvas->height;
    if (x1 <= x0 || y1 <= y0)
        return 0;
    if (isk_canvas_view(v, ui->canvas, x0, y0, (int)(x1 - x0), (int)(y1 - y0)) != ISK_OK)
        return 0;
    *ox = x0;
    *oy = y0;
    return 1;
}

void isk__ui_fill(isk_ui *ui, isk_ui_rect r, isk_color c)
{
    /* An opaque colour over anything is the colour itself: a plain fill of
     * the rectangle's view gives the same bytes as blending each pixel. */
    isk_canvas v, line;
    int ox, oy;
    if (c.a == 255 && view_of(ui, r, &v, &ox, &oy)) {
        /* the first row filled, the others copied from it */
        if (isk_canvas_view(&line, &v, 0, 0, v.width, 1) != ISK_OK)
            return;
        isk_canvas_fill(&line, c);
        for (int y = 1; y < v.height; y++)
            memcpy(isk_canvas_at(&v, 0, y), v.pixels, (size_t)v.width * 4);
    } else if (ui->canvas && r.w > 0 && r.h > 0)
        isk_fill_rect(ui->canvas, r.x, r.y, r.w, r.h, c, ISK_BLEND_OVER);
}

void isk__ui_disc(isk_ui *ui, double cx, double cy, double r, isk_color c)
{
    if (ui->canvas)
        isk_fill_circle_aa(ui->canvas, cx, cy, r, c, ISK_BLEND_OVER);
}

/* A quarter disc in the rad x rad square at (x, y) whose round side faces
 * away from (cx, cy) (a corner of a rounded box). */
static void corner(isk_ui *ui, int x, int y, int rad, double cx, double cy, isk_color c)
{
    isk_canvas v;
    int ox, oy;
    isk_ui_rect sq = {x, y, rad, rad};
    if (view_of(ui, sq, &v, &ox, &oy))
        isk_fill_circle_aa(&v, cx - ox, cy - oy, rad, c, ISK_BLEND_OVER);
}

void isk__ui_round(isk_ui *ui, isk_ui_rect r, int rad, isk_color c)
{
    if (!ui->canvas || r.w <= 0 || r.h <= 0)
        return;
    if (2 * rad > r.w)
        rad = r.w / 2;
    if (2 * rad > r.h)
        rad = r.h / 2;
    if (rad <= 0) {
        isk__ui_fill(ui, r, c);
        return;
    }
    isk_ui_rect mid = {r.x + rad, r.y, r.w - 2 * rad, r.h};
    isk_ui_rect left = {r.x, r.y + rad, rad, r.h - 2 * rad};
    isk_ui_rect right = {r.x + r.w - rad, r.y + rad, rad, r.h - 2 * rad};
    isk__ui_fill(ui, mid, c);
    isk__ui_fill(ui, left, c);
    isk__ui_fill(ui, right, c);
    const int xr = r.x + r.w - rad, yb = r.y + r.h - rad;
    corner(ui, r.x, r.y, rad, r.x + rad, r.y + rad, c);
    corner(ui, xr, r.y, rad, xr, r.y + rad, c);
    corner(ui, r.x, yb, rad, r.x + rad, yb, c);
    corner(ui, xr, yb, rad, xr, yb, c);
}

void isk__ui_round_outline(isk_ui *ui, isk_ui_rect r, int rad, int width, isk_color outline, isk_color fill)
{
    isk__ui_round(ui, r, rad, outline);
    isk__ui_round(ui, isk_ui_inset(r, width), rad > width ? rad - width : 0, fill);
}

/* ---- text ------------------------------------------------------------------------------ */

const isk_font_metrics *isk__ui_font(const isk_ui *ui)
{
    const isk_font_metrics *m = isk_font_metrics_of(ui->font);
    return m ? m : isk_font_metrics_of(ISK_FONT_5X8);
}

int isk__ui_text_y(const isk_ui *ui, isk_ui_rect r)
{
    /* Capitals and digits (7 font rows of the 5x8 font, 10 of the 6x13): centre those. */
    return r.y + (r.h - isk__ui_font(ui)->cap_h * ui->scale) / 2;
}

isk_ui_rect isk_ui_text_line(const isk_ui *ui, isk_ui_rect r)
{
    if (!ui)
        return r;
    const int y = isk__ui_text_y(ui, r);
    return (isk_ui_rect){r.x, y, r.w, r.y + r.h - y};
}

int isk__ui_text_x(const isk_ui *ui, isk_ui_rect r, const char *s, isk_ui_align align)
{
    int w = isk_ui_text_width(ui, s);
    if (align == ISK_UI_CENTER)
        return r.x + (r.w - w) / 2;
    if (align == ISK_UI_RIGHT)
        return r.x + r.w - w;
    return r.x;
}

void isk__ui_text_clip(isk_ui *ui, isk_ui_rect clip, int x, int y, const char *s, isk_color c)
{
    isk_canvas v;
    int ox, oy;
    if (s && *s && view_of(ui, clip, &v, &ox, &oy))
        isk_font_draw_text(&v, ui->font, x - ox, y - oy, s, ui->scale, c, ISK_BLEND_OVER);
}

void isk__ui_text_scaled(isk_ui *ui, isk_ui_rect r, const char *s, isk_color c, int scale)
{
    isk_canvas v;
    int ox, oy;
    int w = isk_font_text_width(ui->font, s, scale) - scale;
    if (s && *s && view_of(ui, r, &v, &ox, &oy))
        isk_font_draw_text(&v, ui->font, r.x + (r.w - w) / 2 - ox, r.y + (r.h - isk__ui_font(ui)->cap_h * scale) / 2 - oy,
                           s, scale, c, ISK_BLEND_OVER);
}

void isk__ui_text_line(isk_ui *ui, isk_ui_rect r, const char *s, isk_color c, isk_ui_align align)
{
    isk__ui_text_clip(ui, r, isk__ui_text_x(ui, r, s, align), isk__ui_text_y(ui, r), s, c);
}

/* Each line of s placed by `align`, starting at y. */
static void text_lines(isk_ui *ui, isk_ui_rect r, int y, const char *s, isk_color c, isk_ui_align align)
{
    char line[256];
    const int lh = isk_ui_line_height(ui);
    while (s && *s) {
        size_t n = strcspn(s, "\n");
        size_t k = n < sizeof line ? n : sizeof line - 1;
        memcpy(line, s, k);
        line[k] = 0;
        isk__ui_text_clip(ui, r, isk__ui_text_x(ui, r, line, align), y, line, c);
        y += lh;
        s += n;
        if (*s == '\n')
            s++;
    }
}

static int count_lines(const char *s)
{
    int n = 1;
    for (; s && *s; s++)
        n += *s == '\n';
    return n;
}

/* ---- icons ----------------------------------------------------------------------------- */

/* A thick arc of radius r around (cx, cy) from angle a0 to a1 (radians,
 * screen y down), as discs along it, with an arrow head at a1. */
static void arc_arrow(isk_ui *ui, double cx, double cy, double r, double a0, double a1, double width, isk_color c)
{
    const int n = (int)(fabs(a1 - a0) * r / (width * 0.25)) + 2;
    for (int i = 0; i <= n; i++) {
        double a = a0 + (a1 - a0) * i / n;
        isk__ui_disc(ui, cx + r * cos(a), cy + r * sin(a), width / 2, c);
    }
    /* The head: a triangle across the arc's end, pointing along it. */
    double ex = cx + r * cos(a1), ey = cy + r * sin(a1);
    double dir = a1 > a0 ? 1.0 : -1.0;
    double tx = -sin(a1) * dir, ty = cos(a1) * dir; /* tangent, along the motion */
    double nx = cos(a1), ny = sin(a1);               /* normal, outwards */
    double h = width * 1.6;
    isk_fill_triangle(ui->canvas, ex + nx * h, ey + ny * h, ex - nx * h, ey - ny * h, ex + tx * h * 1.3,
                      ey + ty * h * 1.3, c, ISK_BLEND_OVER);
}

void isk__ui_icon(isk_ui *ui, isk_ui_rect r, isk_ui_icon icon, isk_color c)
{
    if (!ui->canvas)
        return;
    const double d = (r.w < r.h ? r.w : r.h) * 0.42;
    const double cx = r.x + r.w / 2.0, cy = r.y + r.h / 2.0;
    isk_canvas *cv = ui->canvas;
    switch (icon) {
    case ISK_UI_ICON_PLAY:
        isk_fill_triangle(cv, cx - 0.38 * d, cy - 0.45 * d, cx - 0.38 * d, cy + 0.45 * d, cx + 0.45 * d, cy, c,
                          ISK_BLEND_OVER);
        break;
    case ISK_UI_ICON_PAUSE: {
        int w = (int)lround(0.26 * d), h = (int)lround(0.84 * d), gap = (int)lround(0.22 * d);
        int x = (int)lround(cx) - w - gap / 2, y = (int)lround(cy) - h / 2;
        isk_fill_rect(cv, x, y, w, h, c, ISK_BLEND_OVER);
        isk_fill_rect(cv, x + w + gap, y, w, h, c, ISK_BLEND_OVER);
        break;
    }
    case ISK_UI_ICON_STOP: {
        int s = (int)lround(0.7 * d);
        isk_fill_rect(cv, (int)lround(cx) - s / 2, (int)lround(cy) - s / 2, s, s, c, ISK_BLEND_OVER);
        break;
    }
    case ISK_UI_ICON_STEP: {
        isk_fill_triangle(cv, cx - 0.45 * d, cy - 0.42 * d, cx - 0.45 * d, cy + 0.42 * d, cx + 0.25 * d, cy, c,
                          ISK_BLEND_OVER);
        int w = (int)lround(0.16 * d), h = (int)lround(0.84 * d);
        isk_fill_rect(cv, (int)lround(cx + 0.3 * d), (int)lround(cy) - h / 2, w, h, c, ISK_BLEND_OVER);
        break;
    }
    case ISK_UI_ICON_RESET:
        arc_arrow(ui, cx, cy, 0.38 * d, -0.35 * PI, 1.25 * PI, 0.13 * d, c);
        break;
    case ISK_UI_ICON_RELOAD:
        arc_arrow(ui, cx, cy, 0.38 * d, 0.95 * PI, 1.85 * PI, 0.13 * d, c);
        arc_arrow(ui, cx, cy, 0.38 * d, -0.05 * PI, 0.85 * PI, 0.13 * d, c);
        break;
    default:
        break;
    }
}

/* ---- drawing-only widgets ----------------------------------------------------------------- */

void isk_ui_clear(isk_ui *ui)
{
    if (ui && ui->canvas)
        isk__ui_fill(ui, (isk_ui_rect){0, 0, ui->canvas->width, ui->canvas->height}, ui->style.background);
}

void isk_ui_panel(isk_ui *ui, isk_ui_rect r)
{
    if (!ui)
        return;
    isk__ui_round(ui, r, 3 * ui->scale, ui->style.panel);
    if (ui->npanels < ISK_UI_PANELS_MAX)
        ui->panels[ui->npanels++] = r; /* where a message about a field inside may go */
}

void isk_ui_box(isk_ui *ui, isk_ui_rect r)
{
    if (ui)
        isk__ui_round(ui, r, 3 * ui->scale, ui->style.box);
}

void isk_ui_label(isk_ui *ui, isk_ui_rect r, const char *text, isk_ui_align align)
{
    if (!ui || !text)
        return;
    int lines = count_lines(text);
    int y = isk__ui_text_y(ui, r) - (lines - 1) * isk_ui_line_height(ui) / 2;
    text_lines(ui, r, y, text, ui->disabled ? isk__ui_dim(ui, ui->style.label) : ui->style.label, align);
}

void isk_ui_text(isk_ui *ui, isk_ui_rect r, const char *text, isk_color color, isk_ui_align align)
{
    if (ui && text)
        text_lines(ui, r, r.y, text, ui->disabled ? isk__ui_dim(ui, color) : color, align);
}

/* Greedy wrapping by characters of the fixed-width font: words move to the
 * next line when they do not fit, a word longer than a line is cut. */
int isk_ui_wrap(const isk_ui *ui, const char *text, int width, char *out, size_t out_size)
{
    if (!out || out_size == 0)
        return 0;
    out[0] = 0;
    if (!ui || !text || !*text)
        return 0;
    const int per_line = width / (isk__ui_font(ui)->cell_w * ui->scale);
    if (per_line <= 4)
        return 0;
    size_t o = 0;
    int col = 0, lines = 1;
    for (const char *w = text; *w && o + 2 < out_size;) {
        if (*w == '\n') {
            out[o++] = '\n';
            col = 0;
            lines++;
            w++;
            continue;
        }
        size_t len = strcspn(w, " \n");
        if (col && col + 1 + (int)len > per_line) {
            out[o++] = '\n';
            col = 0;
            lines++;
        } else if (col) {
            out[o++] = ' ';
            col++;
        }
        for (size_t i = 0; i < len && o + 2 < out_size; i++, col++) {
            if (col == per_line) {
                out[o++] = '\n';
                col = 0;
                lines++;
            }
            out[o++] = w[i];
        }
        w += len;
        while (*w == ' ')
            w++;
    }
    out[o] = 0;
    return lines;
}

int isk_ui_text_wrapped(isk_ui *ui, isk_ui_rect r, const char *text, isk_color color)
{
    char lines[1024];
    if (!ui)
        return 0;
    int n = isk_ui_wrap(ui, text, r.w, lines, sizeof lines);
    if (n > 0)
        isk_ui_text(ui, r, lines, color, ISK_UI_LEFT);
    return n * isk_ui_line_height(ui);
}

void isk_ui_swatches(isk_ui *ui, isk_ui_rect r, const isk_color *colors, int n)
{
    if (!ui || !ui->canvas || !colors || n <= 0 || r.w <= 0 || r.h <= 0)
        return;
    const int s = ui->scale, sq = 4 * s;
    isk__ui_fill(ui, r, ui->style.border);
    isk_ui_rect in = isk_ui_inset(r, s);
    /* the checkerboard, in squares from the rectangle's corner */
    for (int y = 0; y < in.h; y += sq)
        for (int x = 0; x < in.w; x += sq) {
            isk_ui_rect c = {in.x + x, in.y + y, x + sq > in.w ? in.w - x : sq, y + sq > in.h ? in.h - y : sq};
            isk__ui_fill(ui, c, ((x / sq + y / sq) & 1) ? isk_rgba(0x99, 0x99, 0x99, 255) : isk_rgba(0x66, 0x66, 0x66, 255));
        }
    for (int i = 0; i < n; i++) {
        int x0 = (int)((long)in.w * i / n), x1 = (int)((long)in.w * (i + 1) / n);
        if (x1 > x0)
            isk_fill_rect(ui->canvas, in.x + x0, in.y, x1 - x0, in.h, colors[i], ISK_BLEND_OVER);
    }
}
