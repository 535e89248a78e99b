/* src/chart/chart_internal.h — what the chart's files share (internal).
 *
 * A chart is drawn in three steps: validate everything and compute the
 * layout (chart.c, using the axis code in chart_axis.c), then draw — grid,
 * series lines, frame and ticks, markers, text, legend — with nothing left
 * that can fail, so an error never leaves a half-drawn canvas.
 *
 * Axis coordinates: an axis works in "t" space, the value itself on a
 * linear axis and log10 of it on a log axis, so log ranges down to
 * subnormals (t = -323.3) and up to DBL_MAX (t = 308.3) never overflow.
 * A fraction f in [0, 1] runs across the plot; the frame's pixel
 * columns/rows sit exactly at f = 0 and f = 1.
 */
#ifndef ISKRA_CHART_INTERNAL_H
#define ISKRA_CHART_INTERNAL_H

#include "iskra/chart.h"

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
    int s;            /* text scale (1, or 2 on wide canvases) */
    int cw, chh;      /* font cell width and height at scale s */
    int L, R, T, B;   /* frame columns L, R and rows T (top), B (bottom) */
    double spread;    /* extra stroke offset for series lines (thickness) */
    int mark_r;       /* marker half size in pixels */
} chart_layout;

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

/* ---- chart.c ------------------------------------------------------------- */

/* Validates the chart and computes both axes and the layout (everything
 * isk_chart_draw does before it draws); the canvas is only measured. */
isk_status chart_prepare(const isk_chart *ch, const isk_canvas *c, chart_axis *x, chart_axis *y,
                         chart_layout *lay);

/* ---- chart_axis.c -------------------------------------------------------- */

/* The t coordinate of value v, and whether v can be placed at all. */
int chart_axis_place(int log, double v, double *t);

/* Fraction of the way from tlo to thi (never NaN for finite t; clamped
 * to +-1e300 so later differences cannot overflow). */
double chart_axis_frac(const chart_axis *a, double t);

/* Chooses the range (when fitted) and the labelled ticks of an axis `len`
 * pixels long.  fitted: [dmin, dmax] is the data's extent in t space (may
 * be equal) and a->log is set; otherwise a->log, a->tlo, a->thi are set.
 * horizontal: labels stand side by side (x axis), else stacked (y axis).
 * Never fails: at worst an axis gets no labels. */
void chart_axis_setup(chart_axis *a, int fitted, double dmin, double dmax, int len, int horizontal,
                      int scale);

/* Label text of a linear tick value v on an axis whose step is m * 10^e and
 * whose largest tick magnitude is vmax (the rule is in chart.h). */
void chart_format_linear(char *buf, size_t n, double v, int e, double vmax);

/* ---- chart_series.c ------------------------------------------------------ */

/* Lines (clipped to the frame) of every series. */
void chart_draw_lines(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                      const chart_layout *lay, isk_canvas *c);
/* Markers of every series at points inside the range. */
void chart_draw_markers(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                        const chart_layout *lay, isk_canvas *c);
/* A legend sample: a horizontal stretch of the series' line from x0 to x1
 * at row y with its marker in the middle. */
void chart_draw_sample(const isk_chart_style *st, double x0, double x1, double y, const chart_layout *lay,
                       isk_canvas *c);

/* ---- chart_frame.c ------------------------------------------------------- */

void chart_draw_grid(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                     const chart_layout *lay, isk_canvas *c);
void chart_draw_frame(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                      const chart_layout *lay, isk_canvas *c);
void chart_draw_text(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                     const chart_layout *lay, isk_canvas *c);
void chart_draw_legend(const isk_chart *ch, const chart_layout *lay, isk_canvas *c);

/* Layout constants, in pixels at scale 1 (times lay->s). */
#define CHART_PAD 6        /* canvas edge to anything */
#define CHART_TICK 5       /* labelled tick length (outside the frame) */
#define CHART_MINOR 3      /* unlabelled tick length */
#define CHART_GAP 3        /* tick end to its label */

#endif
