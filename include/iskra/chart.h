/* SPDX-License-Identifier: MIT */
/* iskra/chart.h — line charts drawn by iskra's own rasterizer.
 *
 * Made for work-precision diagrams (error against time, log–log) and other
 * measured curves: axes with ticks and labels (linear or log), a title, axis
 * labels, one line-and-marker style per series and a legend.  Plain data:
 * fill an isk_chart (start from isk_chart_defaults), point it at your
 * series, draw it into any canvas, write the canvas with iskra/png.h.
 *
 * Example:
 *
 *     double t[] = {1e-9, 2e-9, 4e-9}, e[] = {1e-2, 1e-4, 1e-6};
 *     isk_chart_series s = {"rk4", t, e, 3, isk_chart_style_default(3)};
 *     isk_chart ch;
 *     isk_chart_defaults(&ch);
 *     ch.title = "projectile with drag";
 *     ch.x_label = "seconds per particle-step";
 *     ch.y_label = "max position error";
 *     ch.x_log = ch.y_log = 1;
 *     ch.series = &s;  ch.nseries = 1;
 *     isk_canvas c;
 *     if (isk_canvas_init(&c, 800, 600) != ISK_OK) return 1;
 *     isk_error err;
 *     isk_status st = isk_chart_draw(&ch, &c);
 *     if (st != ISK_OK)
 *         fprintf(stderr, "chart: %s\n", isk_status_str(st));
 *     else if ((st = isk_png_write(&c, "chart.png", &err)) != ISK_OK)
 *         fprintf(stderr, "%s\n", err.message);
 *     isk_canvas_free(&c);
 *     return st != ISK_OK;
 *
 * Ranges: an axis whose min and max are both NaN (the default) fits the
 * data — every point that can be placed on both axes, wherever the other
 * axis's explicit range is; a log axis then widens to whole decades, a
 * linear one to whole "nice" steps (1, 2 or 5 times a power of ten) of
 * the step its ticks use (when no step up to ten times the data's span
 * lets the labels fit, it gets no labels and the data's own range rather
 * than a range that squeezes the data into a sliver).  Data all on one
 * value still gets a range: a log axis spans the value's decade plus one
 * either side (all at 1e-3 gives 1e-4..1e-2), a linear one the value
 * +-10% (+-1 around 0 or a subnormal).
 * Explicit ranges are used as given.  Lines are clipped to the frame;
 * markers are drawn for points inside the range (a marker on the range's
 * edge may overlap the frame).  Points that cannot be placed (NaN, +-Inf,
 * or <= 0 on a log axis) are skipped and break the line there, so a gap is
 * visible rather than hidden; a point alone between two gaps shows as its
 * marker.  Any finite data is safe, 1e300 and subnormals included.
 *
 * Ticks: log axes put a labelled tick at every decade (every 2nd, 3rd, 4th,
 * 5th, 10th, ... — multiples of k, so 1e0 stays labelled — when neighbours
 * would come closer than one character cell across or a blank line up) and
 * unlabelled ticks at the skipped decades when they are >= 4 px apart, and
 * at 2..9 when a decade is >= 40 px; labels read "1e-6", "1e0", "1e3".
 * When at most three decades are labelled and there is room, 2..9 (or else
 * 2 and 5) times each power are labelled too: "1e-2 2e-2 5e-2 1e-1"; a
 * range too narrow even for that (2.1..2.9) gets 1-2-5 steps of its
 * values, labelled like a linear axis ("2.2", "2.4").  Linear ticks are at
 * least 64 px apart across and 40 px up with the 5x8 font at scale 1, and
 * as much more as the font's cells are wider and taller (74 and 62 px
 * with the 6x13 font; twice those at scale 2), more where labels would
 * collide.  Linear labels drop trailing zeros, so each shows
 * the digits its tick needs ("0", "0.5", "1", "1.5"; "-2", "0", "2");
 * while the largest tick is within [1e-3, 1e5) they are plain decimals
 * ("0.0005", "50000"), otherwise short scientific ("2e4", "1.5e-4").
 * Light grid lines sit under the data at the labelled ticks.
 *
 * Look: text uses a built-in bitmap font (iskra/text.h): `font`, the 5x8
 * one by default (capitals 7 px tall), or ISK_FONT_6X13 (capitals 10 px
 * tall, for a chart read from across a room, on a projector).  Its scale
 * is 1, or 2 when the canvas is at least 1200 x 400 pixels, which also
 * makes lines about 2.5 px wide instead of 1.5, markers 13 px instead of
 * 7, the frame and ticks 2 px, and the title bold.  The room the layout
 * gives text follows the font's cells: the margins for tick labels, title
 * and axis labels, the tick spacing and the legend's box grow with it.  The title is centred over the plot,
 * the x label under it, the y label turned 90 degrees (read bottom to
 * top).  The legend sits inside the chosen corner of the plot on a
 * background-filled box with a thin frame, one row per named series (a
 * stretch of its line, its marker, its name); for work-precision diagrams
 * ISK_LEGEND_BOTTOM_LEFT is usually empty.  ISK_LEGEND_ABOVE puts the
 * entries side by side over the plot instead, under the title, each row
 * centred on the plot and no wider than the canvas allows (more rows as
 * needed, at most a third of the height): the plot is shorter, but no
 * data hides behind the legend.  Output is deterministic: the
 * same chart gives the same bytes (tested against refimg/chart_*.png).
 *
 * Extras, off by default (isk_chart_defaults):
 *   notes     short texts at data points, each with an optional marker of
 *             its own drawn larger than the series' (a point singled out,
 *             "dt = 1/60"), the text up and to the right of the point, in
 *             the note's colour; a note outside the range is not drawn;
 *   x2_label  a second x axis along the top, for a quantity that is
 *             x2_scale / x (x2_inverse) or x2_scale * x, ticked like a log
 *             axis (only when the x axis is log, and x2_scale > 0): a cost
 *             per particle on the bottom, particles per frame on the top.
 */
#ifndef ISKRA_CHART_H
#define ISKRA_CHART_H

#include <stddef.h>

#include "iskra/canvas.h"
#include "iskra/status.h"
#include "iskra/text.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum isk_chart_marker {
    ISK_MARKER_NONE = 0,
    ISK_MARKER_CIRCLE,
    ISK_MARKER_SQUARE,
    ISK_MARKER_TRIANGLE,
    ISK_MARKER_DIAMOND,
    ISK_MARKER_CROSS, /* x */
    ISK_MARKER_PLUS,  /* + */
    ISK_MARKER_COUNT
} isk_chart_marker;

typedef enum isk_chart_dash {
    ISK_DASH_SOLID = 0,
    ISK_DASH_DASHED,
    ISK_DASH_DOTTED,
    ISK_DASH_DASHDOT,
    ISK_DASH_NONE, /* markers only */
    ISK_DASH_COUNT
} isk_chart_dash;

typedef struct isk_chart_style {
    isk_color color;
    isk_chart_dash dash;
    isk_chart_marker marker;
} isk_chart_style;

typedef struct isk_chart_series {
    const char *name;     /* legend text (NULL or "": not in the legend) */
    const double *x, *y;  /* n points, drawn in the given order */
    size_t n;
    isk_chart_style style;
} isk_chart_series;

/* A text at a data point (see Extras). */
typedef struct isk_chart_note {
    double x, y;
    const char *text;        /* NULL or "": the marker alone */
    isk_color color;
    isk_chart_marker marker; /* ISK_MARKER_NONE: the text alone */
} isk_chart_note;

typedef enum isk_chart_legend {
    ISK_LEGEND_TOP_RIGHT = 0,
    ISK_LEGEND_TOP_LEFT,
    ISK_LEGEND_BOTTOM_LEFT,
    ISK_LEGEND_BOTTOM_RIGHT,
    ISK_LEGEND_NONE,
    ISK_LEGEND_ABOVE, /* over the plot, under the title: entries side by side, in rows */
    ISK_LEGEND_COUNT
} isk_chart_legend;

typedef struct isk_chart {
    const char *title, *x_label, *y_label; /* NULL: none */
    int x_log, y_log;                      /* nonzero: logarithmic axis */
    double x_min, x_max, y_min, y_max;     /* NaN (both of an axis): fit the data */
    const isk_chart_series *series;        /* caller-owned, nseries entries */
    size_t nseries;
    isk_chart_legend legend;
    isk_color background, ink, grid;       /* white, black, light grey by default */
    const isk_chart_note *notes;           /* caller-owned, nnotes entries (see Extras) */
    size_t nnotes;
    const char *x2_label;                  /* NULL: no top axis (see Extras) */
    double x2_scale;
    int x2_inverse;
    isk_font font;                         /* every text's font (see Look) */
} isk_chart;

/* No title or labels, linear axes fitted to the data, legend top right,
 * black on white, no notes, no top axis, the 5x8 font. */
void isk_chart_defaults(isk_chart *ch);

/* A style for series number i (0, 1, 2, ...; negative counts as 0):
 * colours from Okabe and Ito's palette for colour-blind readers (without
 * its yellow, too faint on white: blue, vermillion, bluish green, reddish
 * purple, orange, sky blue, black, then again), markers circle, square,
 * triangle, diamond, cross, plus in turn, and dashes chosen so that every
 * index up to 23 gets a distinct (dash, marker) pair — series differ even
 * in grey. */
isk_chart_style isk_chart_style_default(int index);

/* Draws the whole chart over the canvas (it fills it with the background).
 * Errors, checked in this order (nothing is drawn):
 *   ISK_ERR_NULL   chart or canvas NULL, a canvas without pixels, series
 *                  NULL with nseries > 0, a series with n > 0 and NULL x/y,
 *                  notes NULL with nnotes > 0;
 *   ISK_ERR_SIZE   canvas smaller than 160 x 120;
 *   then for the x axis, then the y axis:
 *   ISK_ERR_RANGE  only one of the axis's min/max set (the other NaN);
 *   ISK_ERR_NAN    an explicit range bound is +-Inf;
 *   ISK_ERR_RANGE  min >= max, or a log axis with min <= 0;
 *   and last:
 *   ISK_ERR_RANGE  an unknown legend, font, dash or marker value (of a
 *                  series or a note); a top axis with x2_scale not finite
 *                  and > 0;
 *                  a data-fitted axis with no placeable point (see Ranges
 *                  above). */
isk_status isk_chart_draw(const isk_chart *ch, isk_canvas *c);

#ifdef __cplusplus
}
#endif

#endif
