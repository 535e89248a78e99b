/* SPDX-License-Identifier: MIT */
/* src/chart/chart.c — isk_chart_draw: checks, layout, and the drawing order.
 *
 * Everything that can fail is decided before the first pixel is written,
 * so an error leaves the canvas untouched.  The layout works from the
 * outside in: text heights fix the top and bottom margins, the y axis's
 * labels (which depend only on the plot's height) fix the left margin, and
 * only then is the x axis ticked for the width that is left.
 */
#include <math.h>

#include "chart/chart_internal.h"
#include "iskra/draw.h"
#include "iskra/text.h"

#define MIN_W 160
#define MIN_H 120
#define WIDE 1200 /* canvases at least this wide and this tall get scale-2 text */
#define TALL 400

void isk_chart_defaults(isk_chart *ch)
{
    if (!ch)
        return;
    ch->title = ch->x_label = ch->y_label = NULL;
    ch->x_log = ch->y_log = 0;
    ch->x_min = ch->x_max = ch->y_min = ch->y_max = NAN;
    ch->series = NULL;
    ch->nseries = 0;
    ch->legend = ISK_LEGEND_TOP_RIGHT;
    ch->background = ISK_WHITE;
    ch->ink = ISK_BLACK;
    ch->grid = isk_rgba(225, 225, 225, 255);
    ch->notes = NULL;
    ch->nnotes = 0;
    ch->x2_label = NULL;
    ch->x2_scale = 1.0;
    ch->x2_inverse = 0;
    ch->font = ISK_FONT_5X8;
}

static isk_status check_range(double mn, double mx, int log)
{
    int a = isnan(mn), b = isnan(mx);
    if (a && b)
        return ISK_OK;
    if (a || b)
        return ISK_ERR_RANGE;
    if (isinf(mn) || isinf(mx))
        return ISK_ERR_NAN;
    if (!(mn < mx) || (log && mn <= 0.0))
        return ISK_ERR_RANGE;
    return ISK_OK;
}

static isk_status validate(const isk_chart *ch, const isk_canvas *c)
{
    if (!ch || !c || !c->pixels || (ch->nseries > 0 && !ch->series) || (ch->nnotes > 0 && !ch->notes))
        return ISK_ERR_NULL;
    for (size_t k = 0; k < ch->nseries; k++)
        if (ch->series[k].n > 0 && (!ch->series[k].x || !ch->series[k].y))
            return ISK_ERR_NULL;
    if (c->width < MIN_W || c->height < MIN_H)
        return ISK_ERR_SIZE;
    isk_status st = check_range(ch->x_min, ch->x_max, ch->x_log != 0);
    if (st == ISK_OK)
        st = check_range(ch->y_min, ch->y_max, ch->y_log != 0);
    if (st != ISK_OK)
        return st;
    if ((unsigned)ch->legend >= (unsigned)ISK_LEGEND_COUNT || !isk_font_metrics_of(ch->font))
        return ISK_ERR_RANGE;
    for (size_t k = 0; k < ch->nseries; k++) {
        const isk_chart_style *s = &ch->series[k].style;
        if ((unsigned)s->dash >= (unsigned)ISK_DASH_COUNT || (unsigned)s->marker >= (unsigned)ISK_MARKER_COUNT)
            return ISK_ERR_RANGE;
    }
    for (size_t k = 0; k < ch->nnotes; k++)
        if ((unsigned)ch->notes[k].marker >= (unsigned)ISK_MARKER_COUNT)
            return ISK_ERR_RANGE;
    if (ch->x2_label && !(isfinite(ch->x2_scale) && ch->x2_scale > 0.0))
        return ISK_ERR_RANGE;
    return ISK_OK;
}

/* The extent, in t space, of the points that can be placed on both axes. */
static size_t data_extent(const isk_chart *ch, double *x0, double *x1, double *y0, double *y1)
{
    size_t count = 0;
    for (size_t k = 0; k < ch->nseries; k++) {
        const isk_chart_series *s = &ch->series[k];
        for (size_t i = 0; i < s->n; i++) {
            double tx, ty;
            if (!isk__chart_axis_place(ch->x_log != 0, s->x[i], &tx) || !isk__chart_axis_place(ch->y_log != 0, s->y[i], &ty))
                continue;
            if (count == 0) {
                *x0 = *x1 = tx;
                *y0 = *y1 = ty;
            } else {
                *x0 = tx < *x0 ? tx : *x0;
                *x1 = tx > *x1 ? tx : *x1;
                *y0 = ty < *y0 ? ty : *y0;
                *y1 = ty > *y1 ? ty : *y1;
            }
            count++;
        }
    }
    return count;
}

/* An explicit range in t space (the checks above passed). */
static void explicit_range(chart_axis *a, double mn, double mx)
{
    a->tlo = a->log ? log10(mn) : mn;
    a->thi = a->log ? log10(mx) : mx;
    if (!(a->tlo < a->thi)) /* neighbouring doubles whose logs round together */
        a->thi = nextafter(a->tlo, INFINITY);
}

static int lines_of(isk_font font, const char *s)
{
    return isk_font_text_height(font, s, 1) / isk_font_metrics_of(font)->cell_h;
}

/* The text's part of the layout: the font's sizes at scale s. */
static void text_layout(chart_layout *lay, isk_font font, int s)
{
    const isk_font_metrics *m = isk_font_metrics_of(font);
    lay->s = s;
    lay->font = font;
    lay->cw = m->cell_w * s;
    lay->chh = m->cell_h * s;
    lay->space = (m->cell_w - m->glyph_w) * s;
    lay->vspace = (m->cell_h - m->glyph_h) * s;
    lay->cap_mid = (m->cap_h - 1) / 2 * s;
}

isk_status isk__chart_prepare(const isk_chart *ch, const isk_canvas *c, chart_axis *xa, chart_axis *ya,
                         chart_layout *out)
{
    isk_status st = validate(ch, c);
    if (st != ISK_OK)
        return st;
    int fit_x = isnan(ch->x_min), fit_y = isnan(ch->y_min);
    double dx0 = 0.0, dx1 = 0.0, dy0 = 0.0, dy1 = 0.0;
    if ((fit_x || fit_y) && data_extent(ch, &dx0, &dx1, &dy0, &dy1) == 0)
        return ISK_ERR_RANGE;

    chart_layout lay;
    int W = c->width, H = c->height;
    int s = (W >= WIDE && H >= TALL) ? 2 : 1;
    const isk_font font = ch->font;
    text_layout(&lay, font, s);
    lay.spread = s == 1 ? 0.25 : 0.75;
    lay.mark_r = s == 1 ? 3 : 6;
    int pad = CHART_PAD * s;
    /* Many-line texts get at most a sixth of the height each (the rest
     * overlaps), so a plot always remains. */
    const int line_gap = chart_up(&lay, CHART_LINE_GAP);
    int title_h = (ch->title && *ch->title) ? isk_font_text_height(font, ch->title, s) + pad : 0;
    int xlab_h = (ch->x_label && *ch->x_label) ? isk_font_text_height(font, ch->x_label, s) + line_gap : 0;
    title_h = title_h > H / 6 ? H / 6 : title_h;
    xlab_h = xlab_h > H / 6 ? H / 6 : xlab_h;
    /* A top axis: its label line and its tick labels above the frame. */
    lay.top2 = ch->x2_label && *ch->x2_label && ch->x_log;
    int top2_h = 0;
    if (lay.top2)
        top2_h = isk_font_text_height(font, ch->x2_label, s) + line_gap + lay.chh + (CHART_GAP + CHART_TICK) * s;
    top2_h = top2_h > H / 6 ? H / 6 : top2_h;
    /* A legend over the plot: its rows under the title (at most a third of
     * the height). */
    int legend_h = ch->legend == ISK_LEGEND_ABOVE ? isk__chart_legend_above_height(ch, &lay, W - 2 * pad, W, H) : 0;
    legend_h = legend_h > H / 3 ? H / 3 : legend_h;
    lay.legend_y = pad + title_h;
    lay.T = pad + title_h + legend_h + top2_h + lay.chh / 2 + s;
    lay.B = H - pad - xlab_h - lay.chh - (CHART_GAP + CHART_TICK + 1) * s;

    chart_axis ax, ay;
    ax.log = ch->x_log != 0;
    ay.log = ch->y_log != 0;
    if (!fit_y)
        explicit_range(&ay, ch->y_min, ch->y_max);
    isk__chart_axis_setup(&ay, fit_y, dy0, dy1, lay.B - lay.T, 0, font, s);

    int maxw = 0;
    for (int k = 0; k < ay.n; k++) {
        int w = isk_font_text_width(font, ay.label[k], s) - lay.space;
        maxw = w > maxw ? w : maxw;
    }
    const int ylab_gap = chart_up(&lay, CHART_YLABEL_GAP);
    int ylab_w = (ch->y_label && *ch->y_label) ? lines_of(font, ch->y_label) * lay.chh + ylab_gap : 0;
    ylab_w = ylab_w > W / 6 ? W / 6 : ylab_w;
    lay.L = pad + ylab_w + maxw + (CHART_GAP + CHART_TICK) * s + (s - 1);
    if (lay.L > W / 2) /* absurd labels: keep a plot, let them clip */
        lay.L = W / 2;
    lay.R = W - 1 - (s - 1) - pad - lay.cw;

    /* The last x label is centred on its tick and may stick out past the
     * frame: if it would come closer than pad to the canvas edge, narrow
     * the plot by that much and tick again (once; a narrower axis only
     * ever gets sparser labels). */
    for (int pass = 0; pass < 2; pass++) {
        if (!fit_x)
            explicit_range(&ax, ch->x_min, ch->x_max);
        isk__chart_axis_setup(&ax, fit_x, dx0, dx1, lay.R - lay.L, 1, font, s);
        int over = 0;
        for (int k = 0; k < ax.n; k++) {
            double f = isk__chart_axis_frac(&ax, ax.t[k]);
            if (!(f >= 0.0 && f <= 1.0 + 1e-6))
                continue;
            int iw = isk_font_text_width(font, ax.label[k], s) - lay.space;
            int end = (int)floor(chart_px(&lay, f > 1.0 ? 1.0 : f)) + iw - iw / 2 + pad;
            over = end - (W - 1) > over ? end - (W - 1) : over;
        }
        if (over == 0 || lay.R - over <= lay.L + W / 4)
            break;
        lay.R -= over;
    }

    if (lay.top2) {
        /* The top axis's range in its own t space: t2 = log10(scale) -+ t. */
        const double ls = log10(ch->x2_scale);
        chart_axis *a2 = &lay.x2;
        a2->log = 1;
        a2->tlo = ch->x2_inverse ? ls - ax.thi : ls + ax.tlo;
        a2->thi = ch->x2_inverse ? ls - ax.tlo : ls + ax.thi;
        isk__chart_axis_setup(a2, 0, 0.0, 0.0, lay.R - lay.L, 1, font, s);
    }
    *xa = ax;
    *ya = ay;
    *out = lay;
    return ISK_OK;
}

isk_status isk_chart_draw(const isk_chart *ch, isk_canvas *c)
{
    chart_axis ax, ay;
    chart_layout lay;
    isk_status st = isk__chart_prepare(ch, c, &ax, &ay, &lay);
    if (st != ISK_OK)
        return st;
    isk_canvas_fill(c, ch->background);
    isk__chart_draw_grid(ch, &ax, &ay, &lay, c);
    isk__chart_draw_lines(ch, &ax, &ay, &lay, c);
    isk__chart_draw_frame(ch, &ax, &ay, &lay, c);
    isk__chart_draw_markers(ch, &ax, &ay, &lay, c);
    isk__chart_draw_notes(ch, &ax, &ay, &lay, c);
    isk__chart_draw_text(ch, &ax, &ay, &lay, c);
    isk__chart_draw_legend(ch, &lay, c);
    return ISK_OK;
}
