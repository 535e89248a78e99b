/* SPDX-License-Identifier: MIT */
/* src/chart/chart_legend.c — the legend: one entry per named series (a
 * stretch of its line with its marker, then its name), either stacked in
 * a framed box inside a corner of the plot, or side by side in rows over
 * the plot (ISK_LEGEND_ABOVE), where it never hides data.
 *
 * Its room follows the chart's font (chart_across, chart_up), so a larger
 * font gets a larger box.  Sizes are capped at the canvas's so absurd
 * names or counts cannot overflow the sums (the legend is then simply
 * clipped).
 */
#include "chart/chart_internal.h"
#include "iskra/draw.h"

/* In pixels of the 5x8 font at scale 1: padding inside the box, the
 * sample's length, the sample to the name, between rows, and between
 * entries side by side. */
enum { LEGEND_PAD = 5, LEGEND_SAMPLE = 26, LEGEND_GAP = 6, LEGEND_ROW_GAP = 3, LEGEND_ENTRY_GAP = 12 };

typedef struct entry {
    const isk_chart_series *se;
    int w;  /* across: sample, gap, the name's ink */
    int h;  /* up: the taller of the name and the marker */
    int th; /* the name's height */
} entry;

static int named(const isk_chart_series *se)
{
    return se->name && *se->name;
}

static entry entry_of(const isk_chart_series *se, const chart_layout *lay, int W, int H)
{
    entry e;
    const int mark = 2 * lay->mark_r + 3;
    int w = isk__chart_ink_width(lay, se->name), th = isk_font_text_height(lay->font, se->name, lay->s);
    w = w > W ? W : w;
    e.se = se;
    e.th = th > H ? H : th;
    e.w = chart_across(lay, LEGEND_SAMPLE) + chart_across(lay, LEGEND_GAP) + w;
    e.h = e.th > mark ? e.th : mark;
    return e;
}

/* The entry with its top-left at (x, y) in a row eh pixels tall. */
static void draw_entry(const isk_chart *ch, const entry *e, int x, int y, const chart_layout *lay, isk_canvas *c)
{
    const int sample = chart_across(lay, LEGEND_SAMPLE);
    int cy = y + (e->h - 1) / 2; /* pixel row of the entry's middle */
    isk__chart_draw_sample(&e->se->style, x, x + sample, cy + 0.5, lay, c);
    /* one line: its capitals centred on the sample */
    int ty = e->th > lay->chh ? y : cy - lay->cap_mid;
    isk__chart_text_at(c, lay, x + sample + chart_across(lay, LEGEND_GAP), ty, e->se->name, ch->ink);
}

/* ---- a box in a corner of the plot ---------------------------------------- */

static void draw_box(const isk_chart *ch, const chart_layout *lay, isk_canvas *c)
{
    const int s = lay->s, padx = chart_across(lay, LEGEND_PAD), pady = chart_up(lay, LEGEND_PAD);
    const int rowgap = chart_up(lay, LEGEND_ROW_GAP);
    int w = 0, h = 0, rows = 0;
    for (size_t k = 0; k < ch->nseries && h <= c->height; k++) {
        if (!named(&ch->series[k]))
            continue;
        entry e = entry_of(&ch->series[k], lay, c->width, c->height);
        w = e.w > w ? e.w : w;
        h += e.h + (rows ? rowgap : 0);
        rows = 1;
    }
    if (rows == 0)
        return;
    /* the last row's spacing row is not ink: the box ends pady under its ink */
    int bw = padx + w + padx, bh = pady + h + pady - lay->vspace;
    int inset = 8 * s, bx, by;
    int left = lay->L + inset, right = lay->R - inset - bw;
    int top = lay->T + inset, bottom = lay->B - inset - bh;
    switch (ch->legend) {
    case ISK_LEGEND_TOP_LEFT: bx = left; by = top; break;
    case ISK_LEGEND_BOTTOM_LEFT: bx = left; by = bottom; break;
    case ISK_LEGEND_BOTTOM_RIGHT: bx = right; by = bottom; break;
    default: bx = right; by = top; break;
    }
    isk_color edge = ch->ink;
    edge.a = (uint8_t)(edge.a * 3 / 5);
    isk_fill_rect(c, bx, by, bw, bh, ch->background, ISK_BLEND_OVER);
    isk_fill_rect(c, bx, by, bw, 1, edge, ISK_BLEND_OVER);
    isk_fill_rect(c, bx, by + bh - 1, bw, 1, edge, ISK_BLEND_OVER);
    isk_fill_rect(c, bx, by + 1, 1, bh - 2, edge, ISK_BLEND_OVER);
    isk_fill_rect(c, bx + bw - 1, by + 1, 1, bh - 2, edge, ISK_BLEND_OVER);
    int ry = by + pady;
    for (size_t k = 0; k < ch->nseries && ry < c->height; k++) {
        if (!named(&ch->series[k]))
            continue;
        entry e = entry_of(&ch->series[k], lay, c->width, c->height);
        draw_entry(ch, &e, bx + padx, ry, lay, c);
        ry += e.h + rowgap;
    }
}

/* ---- rows over the plot ----------------------------------------------------- */

/* Lays the entries out in rows at most `width` wide (an entry wider than
 * that gets a row of its own), from row `top` down; with a canvas, draws
 * each row centred on column `mid`, kept on the canvas.  Returns the rows'
 * height. */
static int above_rows(const isk_chart *ch, const chart_layout *lay, int width, int W, int H, int top, int mid,
                      isk_canvas *c)
{
    const int egap = chart_across(lay, LEGEND_ENTRY_GAP), rowgap = chart_up(lay, LEGEND_ROW_GAP);
    const int pad = CHART_PAD * lay->s;
    int y = top;
    size_t k = 0;
    while (k < ch->nseries && y - top <= H) {
        /* one row: entries first..k-1 */
        size_t first = k;
        int row_w = 0, row_h = 0, n = 0;
        for (; k < ch->nseries; k++) {
            if (!named(&ch->series[k]))
                continue;
            entry e = entry_of(&ch->series[k], lay, W, H);
            if (n > 0 && row_w + egap + e.w > width)
                break;
            row_w += (n ? egap : 0) + e.w;
            row_h = e.h > row_h ? e.h : row_h;
            n++;
        }
        if (n == 0)
            break;
        if (y > top)
            y += rowgap;
        if (c) {
            int x = mid - row_w / 2;
            x = x > W - pad - row_w ? W - pad - row_w : x;
            x = x < pad ? pad : x;
            for (size_t j = first; j < k; j++) {
                if (!named(&ch->series[j]))
                    continue;
                entry e = entry_of(&ch->series[j], lay, W, H);
                entry in_row = e;
                in_row.h = row_h; /* every entry of a row centred on the row's middle */
                draw_entry(ch, &in_row, x, y, lay, c);
                x += e.w + egap;
            }
        }
        y += row_h;
    }
    return y - top;
}

int isk__chart_legend_above_height(const isk_chart *ch, const chart_layout *lay, int width, int W, int H)
{
    return above_rows(ch, lay, width, W, H, 0, 0, NULL);
}

void isk__chart_draw_legend(const isk_chart *ch, const chart_layout *lay, isk_canvas *c)
{
    if (ch->legend == ISK_LEGEND_NONE)
        return;
    if (ch->legend == ISK_LEGEND_ABOVE) {
        const int pad = CHART_PAD * lay->s;
        above_rows(ch, lay, c->width - 2 * pad, c->width, c->height, lay->legend_y, (lay->L + lay->R + 1) / 2, c);
        return;
    }
    draw_box(ch, lay, c);
}
