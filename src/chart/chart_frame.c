/* SPDX-License-Identifier: MIT */
/* src/chart/chart_frame.c — everything around the data: grid, frame, ticks,
 * tick labels, title, axis labels (the y label rotated) and the legend.
 *
 * All of it is aliased rectangles and bitmap text on whole pixels, so the
 * frame and ticks are crisp; tick positions round to the pixel column/row
 * of the tick's fraction, the same pixel centres the series are drawn on.
 */
#include <math.h>
#include <string.h>

#include "chart/chart_internal.h"
#include "iskra/draw.h"
#include "iskra/text.h"

#define FEPS 1e-6 /* a tick this far outside [0, 1] is still at the end */

/* Pixel column (x) or row (y) of fraction f; f is within [-FEPS, 1+FEPS]. */
static int col_of(const chart_layout *l, double f)
{
    return (int)floor(chart_px(l, f < 0.0 ? 0.0 : f > 1.0 ? 1.0 : f));
}
static int row_of(const chart_layout *l, double f)
{
    return (int)floor(chart_py(l, f < 0.0 ? 0.0 : f > 1.0 ? 1.0 : f));
}

static int tick_frac(const chart_axis *a, int k, double *f)
{
    *f = chart_axis_frac(a, a->t[k]);
    return *f >= -FEPS && *f <= 1.0 + FEPS;
}

void chart_draw_grid(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                     const chart_layout *lay, isk_canvas *c)
{
    double f;
    for (int k = 0; k < x->n; k++) {
        if (!tick_frac(x, k, &f))
            continue;
        int px = col_of(lay, f);
        if (px > lay->L && px < lay->R)
            isk_fill_rect(c, px, lay->T + 1, 1, lay->B - lay->T - 1, ch->grid, ISK_BLEND_OVER);
    }
    for (int k = 0; k < y->n; k++) {
        if (!tick_frac(y, k, &f))
            continue;
        int py = row_of(lay, f);
        if (py > lay->T && py < lay->B)
            isk_fill_rect(c, lay->L + 1, py, lay->R - lay->L - 1, 1, ch->grid, ISK_BLEND_OVER);
    }
}

static void tick_x(const isk_chart *ch, const chart_layout *l, isk_canvas *c, double f, int len)
{
    isk_fill_rect(c, col_of(l, f), l->B + l->s, l->s, len * l->s, ch->ink, ISK_BLEND_OVER);
}

static void tick_y(const isk_chart *ch, const chart_layout *l, isk_canvas *c, double f, int len)
{
    isk_fill_rect(c, l->L - (l->s - 1) - len * l->s, row_of(l, f), len * l->s, l->s, ch->ink,
                  ISK_BLEND_OVER);
}

/* Unlabelled ticks of a log axis: every decade when only every k-th is
 * labelled, and 2..9 inside decades wide enough to tell them apart. */
static void minor_ticks(const isk_chart *ch, const chart_axis *a, const chart_layout *l, isk_canvas *c,
                        int horizontal)
{
    if (!a->log)
        return;
    int len = horizontal ? l->R - l->L : l->B - l->T;
    double dp = len / (a->thi - a->tlo); /* pixels per decade */
    int decades = dp >= 4.0 * l->s && a->decade_step != 1;
    int subs = dp >= 40.0 * l->s;
    if (!decades && !subs)
        return;
    /* Here dp >= 4 px, so at most len/4 + 2 decades are visited. */
    for (double d = floor(a->tlo); d <= ceil(a->thi); d += 1.0) {
        for (int m = 1; m <= 9; m++) {
            if ((m == 1 && !decades) || (m > 1 && !subs))
                continue;
            double f = chart_axis_frac(a, d + log10((double)m));
            if (f < -FEPS || f > 1.0 + FEPS)
                continue;
            if (horizontal)
                tick_x(ch, l, c, f, CHART_MINOR);
            else
                tick_y(ch, l, c, f, CHART_MINOR);
        }
    }
}

void chart_draw_frame(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                      const chart_layout *lay, isk_canvas *c)
{
    int s = lay->s, o = s - 1; /* a thicker frame grows outwards */
    int w = lay->R - lay->L + 1 + 2 * o, h = lay->B - lay->T + 1;
    isk_fill_rect(c, lay->L - o, lay->T - o, w, s, ch->ink, ISK_BLEND_OVER);
    isk_fill_rect(c, lay->L - o, lay->B, w, s, ch->ink, ISK_BLEND_OVER);
    isk_fill_rect(c, lay->L - o, lay->T + 1, s, h - 2, ch->ink, ISK_BLEND_OVER);
    isk_fill_rect(c, lay->R, lay->T + 1, s, h - 2, ch->ink, ISK_BLEND_OVER);
    minor_ticks(ch, x, lay, c, 1);
    minor_ticks(ch, y, lay, c, 0);
    double f;
    for (int k = 0; k < x->n; k++)
        if (tick_frac(x, k, &f))
            tick_x(ch, lay, c, f, CHART_TICK);
    for (int k = 0; k < y->n; k++)
        if (tick_frac(y, k, &f))
            tick_y(ch, lay, c, f, CHART_TICK);
    for (int k = 0; lay->top2 && k < lay->x2.n; k++) { /* the top axis, ticks outside the frame */
        f = chart_x2_frac(ch, lay, lay->x2.t[k]);
        if (f >= -FEPS && f <= 1.0 + FEPS)
            isk_fill_rect(c, col_of(lay, f), lay->T - s - CHART_TICK * s, s, CHART_TICK * s, ch->ink, ISK_BLEND_OVER);
    }
}

/* Text drawn turned 90 degrees anticlockwise (read bottom to top), glyph by
 * glyph from the font bitmaps: no temporary canvas, nothing to allocate.
 * (x, ybot) is the bottom-left of the turned first line; later lines go
 * right. */
static void draw_text_up(isk_canvas *c, int x, int ybot, const char *s, int scale, isk_color col)
{
    int line = 0, ci = 0;
    for (; *s; s++) {
        if (*s == '\n') {
            line++;
            ci = 0;
            continue;
        }
        const uint8_t *g = isk_font_glyph((unsigned char)*s);
        for (int row = 0; row < ISK_FONT_GLYPH_H; row++)
            for (int colm = 0; colm < ISK_FONT_GLYPH_W; colm++) {
                if (!(g[row] & (0x10u >> colm)))
                    continue;
                long long u = (long long)ci * ISK_FONT_CELL_W + colm; /* along the text */
                long long v = (long long)line * ISK_FONT_CELL_H + row;
                long long px = x + v * scale, py = ybot - (u + 1) * scale + 1;
                if (px < -scale || py < -scale || px > c->width || py > c->height)
                    continue;
                isk_fill_rect(c, (int)px, (int)py, scale, scale, col, ISK_BLEND_OVER);
            }
        ci++;
    }
}

static int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* Width of the inked part of a one-line string (no trailing spacing). */
static int ink_width(const char *s, int scale)
{
    int w = isk_text_width(s, scale);
    return w > scale ? w - scale : w;
}

void chart_draw_text(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                     const chart_layout *lay, isk_canvas *c)
{
    int s = lay->s, pad = CHART_PAD * s;
    double f;
    int ly = lay->B + s + CHART_TICK * s + CHART_GAP * s;
    for (int k = 0; k < x->n; k++) {
        if (!tick_frac(x, k, &f))
            continue;
        int w = isk_text_width(x->label[k], s), iw = ink_width(x->label[k], s);
        int lx = clampi(col_of(lay, f) - (iw - s) / 2, 0, c->width - w);
        isk_draw_text(c, lx, ly, x->label[k], s, ch->ink, ISK_BLEND_OVER);
    }
    int right = lay->L - (s - 1) - CHART_TICK * s - CHART_GAP * s; /* one past the ink */
    for (int k = 0; k < y->n; k++) {
        if (!tick_frac(y, k, &f))
            continue;
        int iw = ink_width(y->label[k], s);
        isk_draw_text(c, right - iw, row_of(lay, f) - 3 * s, y->label[k], s, ch->ink, ISK_BLEND_OVER);
    }
    int mid = (lay->L + lay->R + 1) / 2;
    if (lay->top2) {
        int ly2 = lay->T - s - (CHART_TICK + CHART_GAP) * s - lay->chh;
        for (int k = 0; k < lay->x2.n; k++) {
            f = chart_x2_frac(ch, lay, lay->x2.t[k]);
            if (!(f >= -FEPS && f <= 1.0 + FEPS))
                continue;
            int w = isk_text_width(lay->x2.label[k], s), iw = ink_width(lay->x2.label[k], s);
            int lx = clampi(col_of(lay, f) - (iw - s) / 2, 0, c->width - w);
            isk_draw_text(c, lx, ly2, lay->x2.label[k], s, ch->ink, ISK_BLEND_OVER);
        }
        int w = isk_text_width(ch->x2_label, s), iw = ink_width(ch->x2_label, s);
        int tx = clampi(mid - iw / 2, pad, c->width - pad - w);
        isk_draw_text(c, tx, ly2 - 2 * s - isk_text_height(ch->x2_label, s), ch->x2_label, s, ch->ink,
                      ISK_BLEND_OVER);
    }
    if (ch->title && *ch->title) {
        int w = isk_text_width(ch->title, s), iw = ink_width(ch->title, s);
        int tx = clampi(mid - iw / 2, pad, c->width - pad - w);
        isk_draw_text(c, tx, pad, ch->title, s, ch->ink, ISK_BLEND_OVER);
        if (s > 1 && ch->ink.a == 255) /* bold: again one pixel right (at scale 1 it smudges) */
            isk_draw_text(c, tx + 1, pad, ch->title, s, ch->ink, ISK_BLEND_OVER);
    }
    if (ch->x_label && *ch->x_label) {
        int w = isk_text_width(ch->x_label, s), iw = ink_width(ch->x_label, s);
        int tx = clampi(mid - iw / 2, pad, c->width - pad - w);
        int ty = ly + lay->chh + 2 * s;
        isk_draw_text(c, tx, ty, ch->x_label, s, ch->ink, ISK_BLEND_OVER);
    }
    if (ch->y_label && *ch->y_label) {
        int iw = ink_width(ch->y_label, s);
        int midy = (lay->T + lay->B + 1) / 2;
        int ybot = clampi(midy + iw / 2, iw + pad, c->height - pad);
        draw_text_up(c, pad, ybot, ch->y_label, s, ch->ink);
    }
}

void chart_draw_legend(const isk_chart *ch, const chart_layout *lay, isk_canvas *c)
{
    if (ch->legend == ISK_LEGEND_NONE)
        return;
    int s = lay->s, bp = 5 * s, sample = 26 * s, gap = 6 * s, rowgap = 3 * s;
    int mark = 2 * lay->mark_r + 3;
    /* Sizes are capped at the canvas's so absurd names or counts cannot
     * overflow the sums (the box is then simply clipped). */
    int textw = 0, h = 0, rows = 0;
    for (size_t k = 0; k < ch->nseries && h <= c->height; k++) {
        const char *name = ch->series[k].name;
        if (!name || !*name)
            continue;
        int w = ink_width(name, s), th = isk_text_height(name, s);
        w = w > c->width ? c->width : w;
        th = th > c->height ? c->height : th;
        textw = w > textw ? w : textw;
        h += (th > mark ? th : mark) + (rows ? rowgap : 0);
        rows = 1;
    }
    if (rows == 0)
        return;
    int bw = bp + sample + gap + textw + bp, bh = bp + h + bp - s;
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
    int ry = by + bp;
    for (size_t k = 0; k < ch->nseries && ry < c->height; k++) {
        const isk_chart_series *se = &ch->series[k];
        if (!se->name || !*se->name)
            continue;
        int th = isk_text_height(se->name, s);
        th = th > c->height ? c->height : th;
        int eh = th > mark ? th : mark;
        int cy = ry + (eh - 1) / 2; /* pixel row of the entry's middle */
        chart_draw_sample(&se->style, bx + bp, bx + bp + sample, cy + 0.5, lay, c);
        /* one line: centred on the sample (capitals span rows 0..6) */
        int ty = th > lay->chh ? ry : cy - 3 * s;
        isk_draw_text(c, bx + bp + sample + gap, ty, se->name, s, ch->ink, ISK_BLEND_OVER);
        ry += eh + rowgap;
    }
}
