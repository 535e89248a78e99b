/* SPDX-License-Identifier: MIT */
/* Layout by cutting rectangles, and the metrics every widget shares (see
 * iskra/ui.h). */
#include "iskra/text.h"
#include "ui_internal.h"

int isk_ui_px(const isk_ui *ui, int units) { return units * (ui ? ui->scale : 1); }

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
    return x >= r.x && y >= r.y && x - r.x < r.w && y - r.y < r.h;
}

isk_ui_rect isk_ui_inset(isk_ui_rect r, int d)
{
    isk_ui_rect o = {r.x + d, r.y + d, r.w - 2 * d, r.h - 2 * d};
    if (o.w < 0) {
        o.x = r.x + r.w / 2;
        o.w = 0;
    }
    if (o.h < 0) {
        o.y = r.y + r.h / 2;
        o.h = 0;
    }
    return o;
}

static int clamp_size(int size, int have)
{
    return size < 0 ? 0 : size > have ? have : size;
}

isk_ui_rect isk_ui_cut_top(isk_ui_rect *r, int size)
{
    size = clamp_size(size, r->h);
    isk_ui_rect o = {r->x, r->y, r->w, size};
    r->y += size;
    r->h -= size;
    return o;
}

isk_ui_rect isk_ui_cut_bottom(isk_ui_rect *r, int size)
{
    size = clamp_size(size, r->h);
    r->h -= size;
    isk_ui_rect o = {r->x, r->y + r->h, r->w, size};
    return o;
}

isk_ui_rect isk_ui_cut_left(isk_ui_rect *r, int size)
{
    size = clamp_size(size, r->w);
    isk_ui_rect o = {r->x, r->y, size, r->h};
    r->x += size;
    r->w -= size;
    return o;
}

isk_ui_rect isk_ui_cut_right(isk_ui_rect *r, int size)
{
    size = clamp_size(size, r->w);
    r->w -= size;
    isk_ui_rect o = {r->x + r->w, r->y, size, r->h};
    return o;
}

isk_ui_rect isk_ui_cell(isk_ui_rect r, int cols, int rows, int col, int row, int gap)
{
    isk_ui_rect o = {r.x, r.y, 0, 0};
    if (cols < 1 || rows < 1 || col < 0 || row < 0 || col >= cols || row >= rows)
        return o;
    /* Edges at whole pixels, so neighbouring cells share no pixel and the
     * last one ends exactly at r's edge. */
    long aw = (long)r.w - (long)gap * (cols - 1), ah = (long)r.h - (long)gap * (rows - 1);
    if (aw < 0)
        aw = 0;
    if (ah < 0)
        ah = 0;
    int x0 = (int)(aw * col / cols), x1 = (int)(aw * (col + 1) / cols);
    int y0 = (int)(ah * row / rows), y1 = (int)(ah * (row + 1) / rows);
    o.x = r.x + x0 + gap * col;
    o.y = r.y + y0 + gap * row;
    o.w = x1 - x0;
    o.h = y1 - y0;
    return o;
}

int isk_ui_fit_scale(int avail_w, int avail_h, int need_w, int need_h, int max_scale)
{
    int best = 1;
    for (int s = 2; s <= max_scale; s++)
        if ((long)need_w * s <= avail_w && (long)need_h * s <= avail_h)
            best = s;
    return best;
}
