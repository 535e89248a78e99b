/* SPDX-License-Identifier: MIT */
/* src/chart/chart_frame.c — everything around the data: grid, frame, ticks,
 * tick labels, title and axis labels (the y label rotated).
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
    *f = isk__chart_axis_frac(a, a->t[k]);
    return *f >= -FEPS && *f <= 1.0 + FEPS;
}

void isk__chart_draw_grid(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
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
            double f = isk__chart_axis_frac(a, d + log10((double)m));
            if (f < -FEPS || f > 1.0 + FEPS)
                continue;
            if (horizontal)
                tick_x(ch, l, c, f, CHART_MINOR);
            else
                tick_y(ch, l, c, f, CHART_MINOR);
        }
    }
}

void isk__chart_draw_frame(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
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
 * glyph from the font's bitmaps: no temporary canvas, nothing to allocate.
 * (x, ybot) is the bottom-left of the turned first line; later lines go
 * right. */
static void draw_text_up(isk_canvas *c, isk_font font, int x, int ybot, const char *s, int scale, isk_color col)
{
    const isk_font_metrics *m = isk_font_metrics_of(font);
    const unsigned left = 1u << (m->glyph_w - 1); /* a row's leftmost pixel */
    int line = 0, ci = 0;
    for (; *s; s++) {
        if (*s == '\n') {
            line++;
            ci = 0;
            continue;
        }
        const uint8_t *g = isk_font_rows(font, (unsigned char)*s);
        for (int row = 0; row < m->glyph_h; row++)
            for (int colm = 0; colm < m->glyph_w; colm++) {
                if (!(g[row] & (left >> colm)))
                    continue;
                long long u = (long long)ci * m->cell_w + colm; /* along the text */
                long long v = (long long)line * m->cell_h + row;
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

static int text_width(const chart_layout *lay, const char *s)
{
    return isk_font_text_width(lay->font, s, lay->s);
}


void isk__chart_draw_text(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                     const chart_layout *lay, isk_canvas *c)
{
    int s = lay->s, pad = CHART_PAD * s, line_gap = chart_up(lay, CHART_LINE_GAP);
    double f;
    int ly = lay->B + s + CHART_TICK * s + CHART_GAP * s;
    for (int k = 0; k < x->n; k++) {
        if (!tick_frac(x, k, &f))
            continue;
        int w = text_width(lay, x->label[k]), iw = isk__chart_ink_width(lay, x->label[k]);
        int lx = clampi(col_of(lay, f) - (iw - s) / 2, 0, c->width - w);
        isk__chart_text_at(c, lay, lx, ly, x->label[k], ch->ink);
    }
    int right = lay->L - (s - 1) - CHART_TICK * s - CHART_GAP * s; /* one past the ink */
    for (int k = 0; k < y->n; k++) {
        if (!tick_frac(y, k, &f))
            continue;
        int iw = isk__chart_ink_width(lay, y->label[k]);
        isk__chart_text_at(c, lay, right - iw, row_of(lay, f) - lay->cap_mid, y->label[k], ch->ink);
    }
    int mid = (lay->L + lay->R + 1) / 2;
    if (lay->top2) {
        int ly2 = lay->T - s - (CHART_TICK + CHART_GAP) * s - lay->chh;
        for (int k = 0; k < lay->x2.n; k++) {
            f = chart_x2_frac(ch, lay, lay->x2.t[k]);
            if (!(f >= -FEPS && f <= 1.0 + FEPS))
                continue;
            int w = text_width(lay, lay->x2.label[k]), iw = isk__chart_ink_width(lay, lay->x2.label[k]);
            int lx = clampi(col_of(lay, f) - (iw - s) / 2, 0, c->width - w);
            isk__chart_text_at(c, lay, lx, ly2, lay->x2.label[k], ch->ink);
        }
        int w = text_width(lay, ch->x2_label), iw = isk__chart_ink_width(lay, ch->x2_label);
        int tx = clampi(mid - iw / 2, pad, c->width - pad - w);
        int ty = ly2 - line_gap - isk_font_text_height(lay->font, ch->x2_label, s);
        isk__chart_text_at(c, lay, tx, ty, ch->x2_label, ch->ink);
    }
    if (ch->title && *ch->title) {
        int w = text_width(lay, ch->title), iw = isk__chart_ink_width(lay, ch->title);
        int tx = clampi(mid - iw / 2, pad, c->width - pad - w);
        isk__chart_text_at(c, lay, tx, pad, ch->title, ch->ink);
        if (s > 1 && ch->ink.a == 255) /* bold: again one pixel right (at scale 1 it smudges) */
            isk__chart_text_at(c, lay, tx + 1, pad, ch->title, ch->ink);
    }
    if (ch->x_label && *ch->x_label) {
        int w = text_width(lay, ch->x_label), iw = isk__chart_ink_width(lay, ch->x_label);
        int tx = clampi(mid - iw / 2, pad, c->width - pad - w);
        int ty = ly + lay->chh + line_gap;
        isk__chart_text_at(c, lay, tx, ty, ch->x_label, ch->ink);
    }
    if (ch->y_label && *ch->y_label) {
        int iw = isk__chart_ink_width(lay, ch->y_label);
        int midy = (lay->T + lay->B + 1) / 2;
        int ybot = clampi(midy + iw / 2, iw + pad, c->height - pad);
        draw_text_up(c, lay->font, pad, ybot, ch->y_label, s, ch->ink);
    }
}

int isk__chart_ink_width(const chart_layout *lay, const char *s)
{
    int w = text_width(lay, s);
    return w > lay->space ? w - lay->space : w;
}

void isk__chart_text_at(isk_canvas *c, const chart_layout *lay, int x, int y, const char *s, isk_color col)
{
    isk_font_draw_text(c, lay->font, x, y, s, lay->s, col, ISK_BLEND_OVER);
}
