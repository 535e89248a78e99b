/* SPDX-License-Identifier: MIT */
/* src/chart/chart_internal.h — the steps of drawing a chart (internal).
 *
 * A chart is drawn in three steps: validate everything and compute the
 * layout (chart.c, using the axis code of chart_axis.h), then draw — grid,
 * series lines, frame and ticks, markers, text, legend (chart_series.c,
 * chart_frame.c, chart_legend.c) — with nothing left that can fail, so an
 * error never leaves a half-drawn canvas.
 */
#ifndef ISKRA_CHART_INTERNAL_H
#define ISKRA_CHART_INTERNAL_H

#include "chart/chart_axis.h"

/* ---- chart.c ------------------------------------------------------------- */

/* Validates the chart and computes both axes and the layout (everything
 * isk_chart_draw does before it draws); the canvas is only measured. */
isk_status isk__chart_prepare(const isk_chart *ch, const isk_canvas *c, chart_axis *x, chart_axis *y,
                         chart_layout *lay);

/* ---- chart_series.c ------------------------------------------------------ */

/* Lines (clipped to the frame) of every series. */
void isk__chart_draw_lines(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                      const chart_layout *lay, isk_canvas *c);
/* Markers of every series at points inside the range. */
void isk__chart_draw_markers(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                        const chart_layout *lay, isk_canvas *c);
/* The notes: markers and texts at their points (inside the range). */
void isk__chart_draw_notes(const isk_chart *ch, const chart_axis *x, const chart_axis *y, const chart_layout *lay,
                      isk_canvas *c);
/* A legend sample: a horizontal stretch of the series' line from x0 to x1
 * at row y with its marker in the middle. */
void isk__chart_draw_sample(const isk_chart_style *st, double x0, double x1, double y, const chart_layout *lay,
                       isk_canvas *c);

/* ---- chart_frame.c ------------------------------------------------------- */

void isk__chart_draw_grid(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                     const chart_layout *lay, isk_canvas *c);
void isk__chart_draw_frame(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                      const chart_layout *lay, isk_canvas *c);
void isk__chart_draw_text(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                     const chart_layout *lay, isk_canvas *c);
/* Width of the inked part of a one-line string in the chart's font (its
 * width without the trailing spacing column). */
int isk__chart_ink_width(const chart_layout *lay, const char *s);
/* A string in the chart's font and scale, its first cell's top-left at (x, y). */
void isk__chart_text_at(isk_canvas *c, const chart_layout *lay, int x, int y, const char *s, isk_color col);

/* ---- chart_legend.c ------------------------------------------------------ */

/* Height of the rows of an ISK_LEGEND_ABOVE legend whose rows may be
 * `width` pixels wide, on a canvas W x H (0: no named series). */
int isk__chart_legend_above_height(const isk_chart *ch, const chart_layout *lay, int width, int W, int H);
void isk__chart_draw_legend(const isk_chart *ch, const chart_layout *lay, isk_canvas *c);

#endif
