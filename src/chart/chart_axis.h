/* SPDX-License-Identifier: MIT */
/* src/chart/chart_axis.h — the chart's coordinates: axes in "t" space,
 * the pixel layout and the ticks (internal; chart_axis.c).
 *
 * Axis coordinates: an axis works in "t" space, the value itself on a
 * linear axis and log10 of it on a log axis, so log ranges down to
 * subnormals (t = -323.3) and up to DBL_MAX (t = 308.3) never overflow.
 * A fraction f in [0, 1] runs across the plot; the frame's pixel
 * columns/rows sit exactly at f = 0 and f = 1.
 *
 *     chart_axis a = {.log = 1};
 *     isk__chart_axis_setup(&a, 1, -3.0, 2.0, 400, 1, ISK_FONT_5X8, 1);   // fitted to 1e-3 .. 1e2
 *     double t, x;
 *     if (isk__chart_axis_place(a.log, 0.5, &t)) x = chart_px(&lay, isk__chart_axis_frac(&a, t));
 */
#ifndef ISKRA_CHART_AXIS_H
#define ISKRA_CHART_AXIS_H

#include <stddef.h>

#include "iskra/chart.h"
#include "iskra/text.h"

/* More labelled ticks than this on one axis are never readable. */
#define CHART_MAX_TICKS 64
#define CHART_LABEL_MAX 32

typedef struct chart_axis {
    int log;                 /* 1: t = log10(value) */
    double tlo, thi;         /* the range in t space, tlo < thi */
    int decade_step;         /* log axis labelled at decades: every k-th; 0 otherwise */
    int n;                   /* labelled ticks */
    double t[CHART_MAX_TICKS];
    char label[CHART_MAX_TICKS][CHART_LABEL_MAX];
} chart_axis;

/* Pixel geometry shared by the drawing files. */
typedef struct chart_layout {
    int s;            /* scale of text and strokes (1, or 2 on wide canvases) */
    isk_font font;    /* the text's font (isk_chart.font) */
    int cw, chh;      /* its cell width and line height at scale s */
    int space;        /* its spacing column at scale s: a text's ink ends this far before its width */
    int vspace;       /* its spacing row at scale s: a line's ink ends this far above its height */
    int cap_mid;      /* rows from a line's top to the middle of its capitals, at scale s */
    int L, R, T, B;   /* frame columns L, R and rows T (top), B (bottom) */
    double spread;    /* extra stroke offset for series lines (thickness) */
    int mark_r;       /* marker half size in pixels */
    int legend_y;     /* the top row of an ISK_LEGEND_ABOVE legend */
    int top2;         /* a second x axis along the top (isk_chart.x2_label) */
    chart_axis x2;    /* its ticks, in its own t space (see chart_x2_frac) */
} chart_layout;

/* Fraction across the plot of top-axis coordinate t2 (x2_inverse: the top
 * axis runs the other way). */
static inline double chart_x2_frac(const isk_chart *ch, const chart_layout *l, double t2)
{
    double f = (t2 - l->x2.tlo) / (l->x2.thi - l->x2.tlo);
    return ch->x2_inverse ? 1.0 - f : f;
}

/* Pixel coordinates of axis fractions: f = 0 and f = 1 fall on the centres
 * of the frame's columns L, R (rows B, T). */
static inline double chart_px(const chart_layout *l, double f)
{
    return (double)l->L + 0.5 + f * (double)(l->R - l->L);
}
static inline double chart_py(const chart_layout *l, double f)
{
    return (double)l->B + 0.5 - f * (double)(l->B - l->T);
}

/* The t coordinate of value v, and whether v can be placed at all. */
int isk__chart_axis_place(int log, double v, double *t);

/* Fraction of the way from tlo to thi (never NaN for finite t; clamped
 * to +-1e300 so later differences cannot overflow). */
double isk__chart_axis_frac(const chart_axis *a, double t);

/* Chooses the range (when fitted) and the labelled ticks of an axis `len`
 * pixels long.  fitted: [dmin, dmax] is the data's extent in t space (may
 * be equal) and a->log is set; otherwise a->log, a->tlo, a->thi are set.
 * horizontal: labels stand side by side (x axis), else stacked (y axis);
 * they are written in `font` at `scale` (a known font).  Never fails: at
 * worst an axis gets no labels. */
void isk__chart_axis_setup(chart_axis *a, int fitted, double dmin, double dmax, int len, int horizontal,
                      isk_font font, int scale);

/* Label text of a linear tick value v on an axis whose step is m * 10^e and
 * whose largest tick magnitude is vmax (the rule is in chart.h). */
void isk__chart_format_linear(char *buf, size_t n, double v, int e, double vmax);

/* Layout constants, in pixels at scale 1 (times lay->s). */
#define CHART_PAD 6        /* canvas edge to anything */
#define CHART_TICK 5       /* labelled tick length (outside the frame) */
#define CHART_MINOR 3      /* unlabelled tick length */
#define CHART_GAP 3        /* tick end to its label */

/* Room around text is given in pixels of the 5x8 font at scale 1 and
 * follows the chart's font: lengths across by its cell width, lengths up by
 * its line height (for the 5x8 font exactly n * s, so its charts keep
 * their pixels). */
static inline int chart_across(const chart_layout *l, int n)
{
    return n * l->cw / ISK_FONT_CELL_W;
}
static inline int chart_up(const chart_layout *l, int n)
{
    return n * l->chh / ISK_FONT_CELL_H;
}
#define CHART_LINE_GAP 2   /* up: between a line of text and the next text under it */
#define CHART_YLABEL_GAP 4 /* up (the y label is turned): y label to the widest y tick label */

#endif
