/* SPDX-License-Identifier: MIT */
/* src/chart/chart_series.c — series styles, lines and markers.
 *
 * Lines are clipped to the plot in axis-fraction space (Liang–Barsky on
 * fractions clamped to +-1e300, so nothing overflows) before they become
 * pixels.  A "pen" then walks the visible path: the dash pattern is
 * measured along it and continues across segments (and across the places
 * where a line leaves the plot and comes back); it restarts where a line
 * breaks at an unplaceable point.  Each dash is one isk_stroke_polyline, so
 * dashes that turn a corner get a proper join.  Thicker lines are the same
 * polyline stroked again shifted by +-spread in x and in y.
 */
#include <math.h>

#include "chart/chart_internal.h"
#include "iskra/draw.h"
#include "iskra/text.h"

#define PEN_MAX 128 /* points per stroked polyline (stroke cost grows with it) */

/* Okabe & Ito's palette (2008) without its yellow, which vanishes on white:
 * blue, vermillion, bluish green, reddish purple, orange, sky blue, black. */
static const isk_color palette[] = {
    {0, 114, 178, 255}, {213, 94, 0, 255},   {0, 158, 115, 255}, {204, 121, 167, 255},
    {230, 159, 0, 255}, {86, 180, 233, 255}, {0, 0, 0, 255},
};
#define NPALETTE ((int)(sizeof palette / sizeof palette[0]))

isk_chart_style isk_chart_style_default(int index)
{
    /* (marker, dash) = (i mod 6, (i + i/6) mod 4) differs for every i < 24:
     * i and i + 6t share the marker, and their dashes differ by 7t mod 4. */
    unsigned i = index < 0 ? 0u : (unsigned)index;
    isk_chart_style st;
    st.color = palette[i % NPALETTE];
    st.marker = (isk_chart_marker)(ISK_MARKER_CIRCLE + (int)(i % 6u));
    st.dash = (isk_chart_dash)((i + i / 6u) % 4u);
    return st;
}

typedef struct pen {
    isk_canvas *c;
    isk_color color;
    double spread;
    double pat[4];
    int npat;          /* 0: solid */
    int pi;            /* current pattern element (even: ink) */
    double left;       /* of that element */
    int has_pos;
    double px, py;     /* where the last segment ended */
    double xy[2 * PEN_MAX];
    int n;
} pen;

static void pen_init(pen *p, isk_canvas *c, const isk_chart_style *st, const chart_layout *lay)
{
    static const double dashed[] = {6, 4}, dotted[] = {2, 3}, dashdot[] = {7, 3, 2, 3};
    const double *pat = NULL;
    p->npat = 0;
    switch (st->dash) {
    case ISK_DASH_DASHED: pat = dashed; p->npat = 2; break;
    case ISK_DASH_DOTTED: pat = dotted; p->npat = 2; break;
    case ISK_DASH_DASHDOT: pat = dashdot; p->npat = 4; break;
    default: break;
    }
    for (int k = 0; k < p->npat; k++)
        p->pat[k] = pat[k] * lay->s;
    p->c = c;
    p->color = st->color;
    p->spread = lay->spread;
    p->pi = 0;
    p->left = p->npat ? p->pat[0] : 0.0;
    p->has_pos = 0;
    p->n = 0;
}

static void pen_flush(pen *p)
{
    if (p->n >= 2) {
        isk_stroke_polyline(p->c, p->xy, p->n, 0, p->color, ISK_BLEND_OVER);
        if (p->spread > 0.0) {
            static const double dir[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
            double sh[2 * PEN_MAX];
            for (int d = 0; d < 4; d++) {
                for (int k = 0; k < p->n; k++) {
                    sh[2 * k] = p->xy[2 * k] + dir[d][0] * p->spread;
                    sh[2 * k + 1] = p->xy[2 * k + 1] + dir[d][1] * p->spread;
                }
                isk_stroke_polyline(p->c, sh, p->n, 0, p->color, ISK_BLEND_OVER);
            }
        }
    }
    p->n = 0;
}

static void pen_point(pen *p, double x, double y)
{
    if (p->n == PEN_MAX) { /* keep going from the last point */
        double lx = p->xy[2 * p->n - 2], ly = p->xy[2 * p->n - 1];
        pen_flush(p);
        p->xy[0] = lx;
        p->xy[1] = ly;
        p->n = 1;
    }
    p->xy[2 * p->n] = x;
    p->xy[2 * p->n + 1] = y;
    p->n++;
}

/* The line stops here: the next one starts a fresh dash pattern. */
static void pen_break(pen *p)
{
    pen_flush(p);
    p->has_pos = 0;
    p->pi = 0;
    p->left = p->npat ? p->pat[0] : 0.0;
}

static void pen_segment(pen *p, double x0, double y0, double x1, double y1)
{
    if (!p->has_pos || x0 != p->px || y0 != p->py)
        pen_flush(p); /* the line left the plot and came back */
    p->has_pos = 1;
    p->px = x1;
    p->py = y1;
    double dx = x1 - x0, dy = y1 - y0, len = hypot(dx, dy);
    if (!(len > 0.0))
        return;
    if (p->npat == 0) {
        if (p->n == 0)
            pen_point(p, x0, y0);
        pen_point(p, x1, y1);
        return;
    }
    double pos = 0.0;
    while (pos < len) {
        double step = p->left < len - pos ? p->left : len - pos;
        int ink = (p->pi % 2) == 0;
        if (ink) {
            if (p->n == 0)
                pen_point(p, x0 + dx * (pos / len), y0 + dy * (pos / len));
            double e = pos + step;
            pen_point(p, e >= len ? x1 : x0 + dx * (e / len), e >= len ? y1 : y0 + dy * (e / len));
        }
        pos += step;
        p->left -= step;
        if (p->left <= 1e-9) {
            if (ink)
                pen_flush(p);
            p->pi = (p->pi + 1) % p->npat;
            p->left = p->pat[p->pi];
        }
    }
}

static double clamp01(double v)
{
    return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
}

/* Clips the segment between two fraction-space points to [0,1]^2.  End
 * points that are inside are kept bit for bit, so consecutive segments
 * still meet exactly.  A clipped end gets the boundary it was clipped by
 * exactly and only its other coordinate from the parameter: with ends near
 * +-1e300, ay + t*dy would cancel to nothing, while ax + t*dx along a short
 * dx stays exact.  Parameters can still round (a segment wholly above the
 * plot can get t0 = t1 = 1), so segments wholly on one side are rejected
 * first and the results are clamped: what comes out lies in the square.
 * (The rasterizer's isk__clip_segment is not enough here: it clips to a
 * guard box far outside the canvas, and a segment it passes between points
 * near +-1e300 made the dash walk below run practically forever; the chart
 * fuzz test catches that.) */
static int clip_unit(double *x0, double *y0, double *x1, double *y1)
{
    double ax = *x0, ay = *y0, bx = *x1, by = *y1;
    if ((ax < 0.0 && bx < 0.0) || (ax > 1.0 && bx > 1.0) || (ay < 0.0 && by < 0.0) || (ay > 1.0 && by > 1.0))
        return 0;
    double dx = bx - ax, dy = by - ay, t0 = 0.0, t1 = 1.0;
    int k0 = -1, k1 = -1;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {ax, 1.0 - ax, ay, 1.0 - ay};
    for (int k = 0; k < 4; k++) {
        if (p[k] == 0.0) {
            if (q[k] < 0.0)
                return 0;
            continue;
        }
        double r = q[k] / p[k];
        if (p[k] < 0.0) {
            if (r > t1)
                return 0;
            if (r > t0) {
                t0 = r;
                k0 = k;
            }
        } else {
            if (r < t0)
                return 0;
            if (r < t1) {
                t1 = r;
                k1 = k;
            }
        }
    }
    /* boundary k: x = 0, x = 1, y = 0, y = 1 */
    if (k0 >= 0) {
        *x0 = k0 < 2 ? (double)k0 : ax + t0 * dx;
        *y0 = k0 >= 2 ? (double)(k0 - 2) : ay + t0 * dy;
    }
    if (k1 >= 0) {
        *x1 = k1 < 2 ? (double)k1 : ax + t1 * dx;
        *y1 = k1 >= 2 ? (double)(k1 - 2) : ay + t1 * dy;
    }
    *x0 = clamp01(*x0);
    *y0 = clamp01(*y0);
    *x1 = clamp01(*x1);
    *y1 = clamp01(*y1);
    return 1;
}

static int point_frac(const isk_chart_series *s, size_t i, const chart_axis *x, const chart_axis *y,
                      double *fx, double *fy)
{
    double tx, ty;
    if (!isk__chart_axis_place(x->log, s->x[i], &tx) || !isk__chart_axis_place(y->log, s->y[i], &ty))
        return 0;
    *fx = isk__chart_axis_frac(x, tx);
    *fy = isk__chart_axis_frac(y, ty);
    return 1;
}

void isk__chart_draw_lines(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                      const chart_layout *lay, isk_canvas *parent)
{
    /* Stroked into a view of the frame's rectangle: anti-aliased edges and
     * thick strokes of a line on the range's edge cannot leak outside. */
    isk_canvas view;
    if (isk_canvas_view(&view, parent, lay->L, lay->T, lay->R - lay->L + 1, lay->B - lay->T + 1) != ISK_OK)
        return;
    isk_canvas *c = &view;
    chart_layout local = *lay;
    local.R -= local.L;
    local.B -= local.T;
    local.L = local.T = 0;
    lay = &local;
    for (size_t k = 0; k < ch->nseries; k++) {
        const isk_chart_series *s = &ch->series[k];
        if (s->n == 0 || s->style.dash == ISK_DASH_NONE)
            continue;
        pen p;
        pen_init(&p, c, &s->style, lay);
        int have_prev = 0;
        double pfx = 0.0, pfy = 0.0;
        for (size_t i = 0; i < s->n; i++) {
            double fx, fy;
            if (!point_frac(s, i, x, y, &fx, &fy)) {
                pen_break(&p);
                have_prev = 0;
                continue;
            }
            if (have_prev) {
                double ax = pfx, ay = pfy, bx = fx, by = fy;
                if (clip_unit(&ax, &ay, &bx, &by))
                    pen_segment(&p, chart_px(lay, ax), chart_py(lay, ay), chart_px(lay, bx),
                                chart_py(lay, by));
            }
            pfx = fx;
            pfy = fy;
            have_prev = 1;
        }
        pen_break(&p);
    }
}

/* Two or five width-1 strokes: a bolder line that stays anti-aliased. */
static void bold_line(isk_canvas *c, double x0, double y0, double x1, double y1, double spread,
                      isk_color col)
{
    isk_stroke_line(c, x0, y0, x1, y1, col, ISK_BLEND_OVER);
    if (spread > 0.0) {
        isk_stroke_line(c, x0 + spread, y0, x1 + spread, y1, col, ISK_BLEND_OVER);
        isk_stroke_line(c, x0 - spread, y0, x1 - spread, y1, col, ISK_BLEND_OVER);
        isk_stroke_line(c, x0, y0 + spread, x1, y1 + spread, col, ISK_BLEND_OVER);
        isk_stroke_line(c, x0, y0 - spread, x1, y1 - spread, col, ISK_BLEND_OVER);
    }
}

/* A marker centred on the pixel containing (x, y): fills are aliased, with
 * an anti-aliased outline on slanted edges so shapes read cleanly at 7 px. */
static void draw_marker(isk_canvas *c, isk_chart_marker m, double x, double y, const chart_layout *lay,
                        isk_color col)
{
    double fx = floor(x), fy = floor(y);
    if (!(fabs(fx) < 1e9) || !(fabs(fy) < 1e9))
        return;
    int ix = (int)fx, iy = (int)fy, r = lay->mark_r;
    double cx = fx + 0.5, cy = fy + 0.5, a = r + 1.0;
    double thick = 0.5 * lay->s;
    switch (m) {
    case ISK_MARKER_CIRCLE:
        isk_fill_circle_aa(c, cx, cy, r + 0.8, col, ISK_BLEND_OVER);
        break;
    case ISK_MARKER_SQUARE:
        isk_fill_rect(c, ix - r, iy - r, 2 * r + 1, 2 * r + 1, col, ISK_BLEND_OVER);
        break;
    case ISK_MARKER_TRIANGLE: {
        const double v[6] = {cx, cy - a, cx + a, cy + r, cx - a, cy + r};
        isk_fill_triangle(c, v[0], v[1], v[2], v[3], v[4], v[5], col, ISK_BLEND_OVER);
        isk_stroke_polyline(c, v, 3, 1, col, ISK_BLEND_OVER);
        break;
    }
    case ISK_MARKER_DIAMOND: {
        const double v[8] = {cx, cy - a, cx + a, cy, cx, cy + a, cx - a, cy};
        isk_fill_triangle(c, v[0], v[1], v[2], v[3], v[6], v[7], col, ISK_BLEND_OVER);
        isk_fill_triangle(c, v[2], v[3], v[4], v[5], v[6], v[7], col, ISK_BLEND_OVER);
        isk_stroke_polyline(c, v, 4, 1, col, ISK_BLEND_OVER);
        break;
    }
    case ISK_MARKER_CROSS:
        bold_line(c, cx - r, cy - r, cx + r, cy + r, thick, col);
        bold_line(c, cx - r, cy + r, cx + r, cy - r, thick, col);
        break;
    case ISK_MARKER_PLUS:
        bold_line(c, cx - a, cy, cx + a, cy, thick, col);
        bold_line(c, cx, cy - a, cx, cy + a, thick, col);
        break;
    default:
        break;
    }
}

void isk__chart_draw_markers(const isk_chart *ch, const chart_axis *x, const chart_axis *y,
                        const chart_layout *lay, isk_canvas *c)
{
    const double eps = 1e-9;
    for (size_t k = 0; k < ch->nseries; k++) {
        const isk_chart_series *s = &ch->series[k];
        if (s->style.marker == ISK_MARKER_NONE)
            continue;
        for (size_t i = 0; i < s->n; i++) {
            double fx, fy;
            if (!point_frac(s, i, x, y, &fx, &fy))
                continue;
            if (fx < -eps || fx > 1.0 + eps || fy < -eps || fy > 1.0 + eps)
                continue;
            draw_marker(c, s->style.marker, chart_px(lay, fx), chart_py(lay, fy), lay, s->style.color);
        }
    }
}

void isk__chart_draw_notes(const isk_chart *ch, const chart_axis *x, const chart_axis *y, const chart_layout *lay,
                      isk_canvas *c)
{
    const double eps = 1e-9;
    chart_layout big = *lay;
    big.mark_r = lay->mark_r + 2 * lay->s; /* a note's marker stands out from the series' */
    for (size_t k = 0; k < ch->nnotes; k++) {
        const isk_chart_note *n = &ch->notes[k];
        double tx, ty;
        if (!isk__chart_axis_place(x->log, n->x, &tx) || !isk__chart_axis_place(y->log, n->y, &ty))
            continue;
        double fx = isk__chart_axis_frac(x, tx), fy = isk__chart_axis_frac(y, ty);
        if (fx < -eps || fx > 1.0 + eps || fy < -eps || fy > 1.0 + eps)
            continue;
        double px = chart_px(lay, fx), py = chart_py(lay, fy);
        if (n->marker != ISK_MARKER_NONE)
            draw_marker(c, n->marker, px, py, &big, n->color);
        if (n->text && *n->text) /* up and to the right, at scale 1 (small beside the data) */
            isk_font_draw_text(c, lay->font, (int)floor(px) + big.mark_r + 1,
                               (int)floor(py) - big.mark_r - isk_font_metrics_of(lay->font)->cell_h, n->text, 1,
                               n->color, ISK_BLEND_OVER);
    }
}

void isk__chart_draw_sample(const isk_chart_style *st, double x0, double x1, double y, const chart_layout *lay,
                       isk_canvas *c)
{
    if (st->dash != ISK_DASH_NONE) {
        pen p;
        pen_init(&p, c, st, lay);
        pen_segment(&p, x0, y, x1, y);
        pen_break(&p);
    }
    if (st->marker != ISK_MARKER_NONE)
        draw_marker(c, st->marker, 0.5 * (x0 + x1), y, lay, st->color);
}
