/* SPDX-License-Identifier: MIT */
/* Layout by cutting rectangles, and the metrics every widget shares (see
 * iskra/ui.h). */
#include <limits.h>

#include "iskra/text.h"
#include "ui_internal.h"

/* Layout arithmetic saturates at the ends of int: a pointer event or a
 * rectangle at extreme coordinates gives a clipped answer, never signed
 * overflow (undefined behaviour in C). */
static int sat(long long v)
{
    return v > INT_MAX ? INT_MAX : v < INT_MIN ? INT_MIN : (int)v;
}

int isk_ui_px(const isk_ui *ui, int units) { return sat((long long)units * (ui ? ui->scale : 1)); }

/* Text of one cell's height plus 3 units above and below. */
int isk_ui_row_height(const isk_ui *ui) { return isk_ui_line_height(ui) + isk_ui_px(ui, 6); }

int isk_ui_line_height(const isk_ui *ui)
{
    const isk_font_metrics *m = ui ? isk_font_metrics_of(ui->font) : NULL;
    return isk_ui_px(ui, m ? m->cell_h : ISK_FONT_CELL_H);
}

int isk_ui_text_width(const isk_ui *ui, const char *s)
{
    /* Without the spacing column after the last character. */
    int w = ui ? isk_font_text_width(isk_font_metrics_of(ui->font) ? ui->font : ISK_FONT_5X8, s, ui->scale)
               : isk_text_width(s, 1);
    return w > 0 ? w - (ui ? ui->scale : 1) : 0;
}

int isk_ui_contains(isk_ui_rect r, int x, int y)
{
    return x >= r.x && y >= r.y && (long long)x - r.x < r.w && (long long)y - r.y < r.h;
}

isk_ui_rect isk_ui_inset(isk_ui_rect r, int d)
{
    isk_ui_rect o = {sat((long long)r.x + d), sat((long long)r.y + d), sat((long long)r.w - 2LL * d),
                     sat((long long)r.h - 2LL * d)};
    if (o.w < 0) {
        o.x = sat((long long)r.x + r.w / 2);
        o.w = 0;
    }
    if (o.h < 0) {
        o.y = sat((long long)r.y + r.h / 2);
        o.h = 0;
    }
    return o;
}

static int clamp_size(int size, int have)
{
    return size < 0 ? 0 : size > have ? have : size;
}

/* A NULL rectangle gives an empty cut and changes nothing. */
isk_ui_rect isk_ui_cut_top(isk_ui_rect *r, int size)
{
    if (!r)
        return (isk_ui_rect){0, 0, 0, 0};
    size = clamp_size(size, r->h);
    isk_ui_rect o = {r->x, r->y, r->w, size};
    r->y = sat((long long)r->y + size);
    r->h -= size;
    return o;
}

isk_ui_rect isk_ui_cut_bottom(isk_ui_rect *r, int size)
{
    if (!r)
        return (isk_ui_rect){0, 0, 0, 0};
    size = clamp_size(size, r->h);
    r->h -= size;
    isk_ui_rect o = {r->x, sat((long long)r->y + r->h), r->w, size};
    return o;
}

isk_ui_rect isk_ui_cut_left(isk_ui_rect *r, int size)
{
    if (!r)
        return (isk_ui_rect){0, 0, 0, 0};
    size = clamp_size(size, r->w);
    isk_ui_rect o = {r->x, r->y, size, r->h};
    r->x = sat((long long)r->x + size);
    r->w -= size;
    return o;
}

isk_ui_rect isk_ui_cut_right(isk_ui_rect *r, int size)
{
    if (!r)
        return (isk_ui_rect){0, 0, 0, 0};
    size = clamp_size(size, r->w);
    r->w -= size;
    isk_ui_rect o = {sat((long long)r->x + r->w), r->y, size, r->h};
    return o;
}

isk_ui_rect isk_ui_cell(isk_ui_rect r, int cols, int rows, int col, int row, int gap)
{
    isk_ui_rect o = {r.x, r.y, 0, 0};
    if (cols < 1 || rows < 1 || col < 0 || row < 0 || col >= cols || row >= rows)
        return o;
    /* Edges at whole pixels, so neighbouring cells share no pixel and the
     * last one ends exactly at r's edge. */
    long long aw = sat((long long)r.w - (long long)gap * (cols - 1)),
              ah = sat((long long)r.h - (long long)gap * (rows - 1));
    if (aw < 0)
        aw = 0;
    if (ah < 0)
        ah = 0;
    int x0 = (int)(aw * col / cols), x1 = (int)(aw * (col + 1) / cols);
    int y0 = (int)(ah * row / rows), y1 = (int)(ah * (row + 1) / rows);
    o.x = sat((long long)r.x + x0 + (long long)gap * col);
    o.y = sat((long long)r.y + y0 + (long long)gap * row);
    o.w = x1 - x0;
    o.h = y1 - y0;
    return o;
}

/* The largest s in 2..max_scale with need * s <= avail on both axes (each
 * condition holds for every s up to some limit), else 1: computed, not
 * searched, so any max_scale takes constant time. */
static long long scale_limit(int need, int avail, int max_scale)
{
    if (need > 0)
        return avail / need; /* negative avail: < 2 */
    return (long long)need * max_scale <= avail ? max_scale : -1;
}

int isk_ui_fit_scale(int avail_w, int avail_h, int need_w, int need_h, int max_scale)
{
    long long best = max_scale, w = scale_limit(need_w, avail_w, max_scale), h = scale_limit(need_h, avail_h, max_scale);
    if (w < best)
        best = w;
    if (h < best)
        best = h;
    return best >= 2 ? (int)best : 1;
}
