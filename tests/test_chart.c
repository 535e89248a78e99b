/* SPDX-License-Identifier: MIT */
/* Charts (iskra/chart.h): reference images of whole charts (suite refimg)
 * and unit tests of validation, ranges, ticks and labels (suite chart).
 * The image data is synthetic but shaped like real work-precision results:
 * error = C h^p until round-off takes over, time proportional to 1/h. */
#include <criterion/criterion.h>

#include <float.h>
#include <math.h>
#include <string.h>

#include "chart/chart_internal.h"
#include "iskra/chart.h"
#include "iskra/draw.h"
#include "refimg.h"

#define NPT 12

static isk_canvas make(int w, int h)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, w, h), ISK_OK);
    isk_canvas_fill(&c, isk_rgba(1, 2, 3, 4));
    return c;
}

static void check(const char *name, isk_canvas *c)
{
    cr_assert(refimg_check(name, c), "refimg %s differs", name);
    isk_canvas_free(c);
}

static isk_chart_series series(const char *name, const double *x, const double *y, size_t n, int style)
{
    isk_chart_series s = {name, x, y, n, isk_chart_style_default(style)};
    return s;
}

/* ---- work-precision data ------------------------------------------------ */

/* Five integrators: cost per step, order, error constant. */
static const char *const wp_names[5] = {"euler", "semi-implicit euler", "midpoint", "rk4", "verlet"};
static const double wp_cost[5] = {1.0, 1.1, 2.1, 4.0, 1.3};
static const double wp_order[5] = {1, 1, 2, 4, 2};
static const double wp_const[5] = {4.0, 1.5, 0.8, 0.05, 0.3};

static void wp_data(double x[5][NPT], double y[5][NPT])
{
    for (int s = 0; s < 5; s++)
        for (int k = 0; k < NPT; k++) {
            double h = ldexp(1.0, -k);
            x[s][k] = 1e-9 * wp_cost[s] / h * (1.0 + 0.05 * (k % 3));
            /* truncation error, then round-off growing with the step count */
            y[s][k] = wp_const[s] * pow(h, wp_order[s] + (s == 3 ? 1.0 : 0.0)) + 5e-18 / sqrt(h);
        }
}

static void wp_chart(isk_chart *ch, isk_chart_series ser[5], double x[5][NPT], double y[5][NPT])
{
    wp_data(x, y);
    for (int s = 0; s < 5; s++)
        ser[s] = series(wp_names[s], x[s], y[s], NPT, s);
    isk_chart_defaults(ch);
    ch->title = "work-precision: projectile with drag";
    ch->x_label = "seconds per particle";
    ch->y_label = "max position error";
    ch->x_log = ch->y_log = 1;
    ch->series = ser;
    ch->nseries = 5;
    ch->legend = ISK_LEGEND_BOTTOM_LEFT;
}

/* ---- reference images ---------------------------------------------------- */

Test(refimg, chart_loglog)
{
    double x[5][NPT], y[5][NPT];
    isk_chart_series ser[5];
    isk_chart ch;
    wp_chart(&ch, ser, x, y);
    isk_canvas c = make(800, 600);
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    check("chart_loglog", &c);
}

/* At 1200 px wide text and lines double. */
Test(refimg, chart_loglog_wide)
{
    double x[5][NPT], y[5][NPT];
    isk_chart_series ser[5];
    isk_chart ch;
    wp_chart(&ch, ser, x, y);
    isk_canvas c = make(1200, 800);
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    check("chart_loglog_wide", &c);
}

Test(refimg, chart_linear)
{
    enum { N = 41 };
    double x[N], a[N], b[N], d[N];
    for (int i = 0; i < N; i++) {
        x[i] = 0.25 * i;
        a[i] = 2.6 * exp(-x[i] / 4.0) * cos(2.0 * x[i]);
        b[i] = 1.5 - 0.35 * x[i];
        d[i] = -2.2 + 0.04 * x[i] * x[i];
    }
    isk_chart_series ser[3] = {series("damped", x, a, N, 0), series("drift", x, b, N, 1),
                               series("parabola", x, d, N, 2)};
    ser[0].style.marker = ISK_MARKER_NONE;
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = "linear axes, negative values";
    ch.x_label = "time (s)";
    ch.y_label = "height (m)";
    ch.series = ser;
    ch.nseries = 3;
    isk_canvas c = make(640, 420);
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    check("chart_linear", &c);
}

/* Every marker (columns of points) with every dash (rows of lines). */
Test(refimg, chart_styles)
{
    enum { NS = ISK_MARKER_COUNT * ISK_DASH_COUNT, NP = 6 };
    static double x[NP], y[NS][NP];
    isk_chart_series ser[NS];
    for (int i = 0; i < NP; i++)
        x[i] = i;
    for (int d = 0; d < ISK_DASH_COUNT; d++)
        for (int m = 0; m < ISK_MARKER_COUNT; m++) {
            int k = d * ISK_MARKER_COUNT + m;
            for (int i = 0; i < NP; i++)
                y[k][i] = k + ((i % 2) ? 0.35 : 0.0);
            ser[k] = series(NULL, x, y[k], NP, k);
            ser[k].style.dash = (isk_chart_dash)d;
            ser[k].style.marker = (isk_chart_marker)m;
        }
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = "markers x dashes";
    ch.x_min = -0.5;
    ch.x_max = 5.5;
    ch.y_min = -1;
    ch.y_max = NS;
    ch.series = ser;
    ch.nseries = NS;
    isk_canvas c = make(420, 640);
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    check("chart_styles", &c);
}

/* Unplaceable points on log axes break the line: NaN, 0, negatives, Inf.
 * A point alone between two gaps shows as its marker only. */
Test(refimg, chart_gaps)
{
    const double x[10] = {1, 2, 4, 8, 16, 32, 64, 128, 256, 512};
    const double a[10] = {1e-1, 3e-2, NAN, 4e-3, 1e-3, 0.0, 9e-5, -1.0, 2e-6, 5e-7};
    const double b[10] = {INFINITY, 5e-1, 2e-1, 8e-2, NAN, 1e-2, NAN, 1e-3, 4e-4, 1e-4};
    const double xs[10] = {1, 2, -4, 8, 16, 32, 0.0, 128, 256, NAN};
    const double c3[10] = {2e-5, 2e-5, 2e-5, 2e-5, 2e-5, 2e-5, 2e-5, 2e-5, 2e-5, 2e-5};
    isk_chart_series ser[3] = {series("NaN, 0 and -1 in y", x, a, 10, 0),
                               series("Inf and NaN in y", x, b, 10, 1),
                               series("-4, 0, NaN in x", xs, c3, 10, 2)};
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = "gaps";
    ch.x_log = ch.y_log = 1;
    ch.series = ser;
    ch.nseries = 3;
    isk_canvas c = make(480, 360);
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    check("chart_gaps", &c);
}

/* Explicit ranges: the data runs far outside and is clipped at the frame;
 * markers appear only for points inside the range. */
Test(refimg, chart_clip)
{
    enum { N = 50 };
    double x[N], a[N];
    for (int i = 0; i < N; i++) {
        x[i] = 0.25 * i - 1.0;
        a[i] = 1.6 * sin(x[i]);
    }
    /* segments between x = -1e300 and 1e300 cross the plot nearly level,
     * at y = 0.8 and y = 0.6 */
    const double zx[3] = {-1e300, 1e300, -1e300}, zy[3] = {0.9, 0.7, 0.5};
    const double bx[4] = {-1e300, 3.0, 5.0, 1e300}, by[4] = {-5.0, 0.5, -0.5, 5.0};
    isk_chart_series ser[3] = {series("sine", x, a, N, 0), series("zigzag 1e300", zx, zy, 3, 1),
                               series("far ends", bx, by, 4, 3)};
    ser[1].style.marker = ISK_MARKER_NONE;
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = "explicit ranges clip";
    ch.x_min = 2.0;
    ch.x_max = 8.0;
    ch.y_min = -1.0;
    ch.y_max = 1.0;
    ch.series = ser;
    ch.nseries = 3;
    ch.legend = ISK_LEGEND_BOTTOM_RIGHT;
    isk_canvas c = make(480, 360);
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    check("chart_clip", &c);
}

/* Each legend position on a small chart, and the smallest canvas. */
Test(refimg, chart_legend)
{
    const double x[5] = {1, 2, 3, 4, 5}, a[5] = {1, 4, 9, 16, 25}, b[5] = {25, 16, 9, 4, 1};
    isk_chart_series ser[2] = {series("up", x, a, 5, 0), series("down", x, b, 5, 1)};
    isk_canvas c = make(720, 400);
    isk_canvas_fill(&c, isk_rgba(60, 60, 60, 255));
    for (int k = 0; k < 6; k++) {
        isk_canvas v;
        int w = k == 5 ? 160 : 238, h = k == 5 ? 120 : 198;
        cr_assert_eq(isk_canvas_view(&v, &c, 1 + (k % 3) * 240, 1 + (k / 3) * 200, w, h), ISK_OK);
        isk_chart ch;
        isk_chart_defaults(&ch);
        ch.series = ser;
        ch.nseries = 2;
        ch.legend = k == 5 ? ISK_LEGEND_TOP_LEFT : (isk_chart_legend)k;
        static const char *const titles[6] = {"top right", "top left", "bottom left", "bottom right",
                                              "no legend", "160x120"};
        ch.title = titles[k];
        ch.x_label = "x";
        ch.y_label = "y";
        cr_assert_eq(isk_chart_draw(&ch, &v), ISK_OK);
    }
    check("chart_legend", &c);
}

/* A log axis spanning less than a decade is labelled at 2..9 times the
 * power; one spanning hundreds of decades labels every k-th. */
Test(refimg, chart_logrange)
{
    const double x[4] = {2.2, 3.0, 5.0, 7.5}, y[4] = {1e-300, 1e-100, 1e100, 1e300};
    isk_chart_series ser[1] = {series("wide", x, y, 4, 4)};
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = "2..8 and 1e-300..1e300";
    ch.x_log = ch.y_log = 1;
    ch.x_min = 2.0;
    ch.x_max = 8.0;
    ch.series = ser;
    ch.nseries = 1;
    ch.legend = ISK_LEGEND_NONE;
    isk_canvas c = make(400, 300);
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    check("chart_logrange", &c);
}

/* ---- validation ---------------------------------------------------------- */

/* Every error leaves the canvas as it was. */
static void expect_error(const isk_chart *ch, isk_status want)
{
    isk_canvas c = make(200, 150), before = make(200, 150);
    cr_assert_eq(isk_chart_draw(ch, &c), want);
    cr_assert(isk_canvas_equal(&c, &before), "canvas changed on error");
    isk_canvas_free(&c);
    isk_canvas_free(&before);
}

static const double vx[3] = {1, 2, 3}, vy[3] = {1, 10, 100};

static void valid_chart(isk_chart *ch, isk_chart_series *s)
{
    *s = series("s", vx, vy, 3, 0);
    isk_chart_defaults(ch);
    ch->series = s;
    ch->nseries = 1;
}

Test(chart, valid_baseline)
{
    isk_chart ch;
    isk_chart_series s;
    valid_chart(&ch, &s);
    isk_canvas c = make(200, 150);
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    isk_canvas_free(&c);
}

Test(chart, error_null)
{
    isk_chart ch;
    isk_chart_series s;
    valid_chart(&ch, &s);
    isk_canvas c = make(200, 150);
    cr_assert_eq(isk_chart_draw(NULL, &c), ISK_ERR_NULL);
    cr_assert_eq(isk_chart_draw(&ch, NULL), ISK_ERR_NULL);
    isk_canvas_free(&c);
    isk_canvas empty = {0};
    cr_assert_eq(isk_chart_draw(&ch, &empty), ISK_ERR_NULL);
    ch.series = NULL;
    expect_error(&ch, ISK_ERR_NULL);
    valid_chart(&ch, &s);
    s.x = NULL;
    expect_error(&ch, ISK_ERR_NULL);
    valid_chart(&ch, &s);
    s.y = NULL;
    expect_error(&ch, ISK_ERR_NULL);
    /* n == 0 needs no arrays */
    valid_chart(&ch, &s);
    isk_chart_series two[2] = {s, series("none", NULL, NULL, 0, 1)};
    ch.series = two;
    ch.nseries = 2;
    isk_canvas ok = make(200, 150);
    cr_assert_eq(isk_chart_draw(&ch, &ok), ISK_OK);
    isk_canvas_free(&ok);
}

Test(chart, error_size)
{
    isk_chart ch;
    isk_chart_series s;
    valid_chart(&ch, &s);
    isk_canvas c = make(159, 120), d = make(160, 119), e = make(160, 120);
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_ERR_SIZE);
    cr_assert_eq(isk_chart_draw(&ch, &d), ISK_ERR_SIZE);
    cr_assert_eq(isk_chart_draw(&ch, &e), ISK_OK);
    isk_canvas_free(&c);
    isk_canvas_free(&d);
    isk_canvas_free(&e);
}

Test(chart, error_range_bounds)
{
    isk_chart ch;
    isk_chart_series s;
    valid_chart(&ch, &s);
    ch.x_min = 0.0; /* only one bound */
    expect_error(&ch, ISK_ERR_RANGE);
    valid_chart(&ch, &s);
    ch.y_max = 1.0;
    expect_error(&ch, ISK_ERR_RANGE);
    valid_chart(&ch, &s);
    ch.x_min = 2.0; /* min >= max */
    ch.x_max = 2.0;
    expect_error(&ch, ISK_ERR_RANGE);
    ch.x_max = 1.0;
    expect_error(&ch, ISK_ERR_RANGE);
    valid_chart(&ch, &s);
    ch.y_log = 1; /* log with min <= 0 */
    ch.y_min = 0.0;
    ch.y_max = 10.0;
    expect_error(&ch, ISK_ERR_RANGE);
    ch.y_min = -1.0;
    expect_error(&ch, ISK_ERR_RANGE);
    ch.y_min = 1e-300;
    isk_canvas c = make(200, 150);
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    isk_canvas_free(&c);
}

Test(chart, error_range_no_data)
{
    isk_chart ch;
    isk_chart_series s;
    valid_chart(&ch, &s);
    ch.nseries = 0; /* fitted axes, no series */
    expect_error(&ch, ISK_ERR_RANGE);
    const double bad[3] = {NAN, INFINITY, -INFINITY};
    valid_chart(&ch, &s);
    s.y = bad;
    expect_error(&ch, ISK_ERR_RANGE);
    const double neg[3] = {-1, 0, -5};
    valid_chart(&ch, &s);
    s.x = neg;
    ch.x_log = 1; /* nothing positive on a fitted log axis */
    expect_error(&ch, ISK_ERR_RANGE);
    /* With both ranges explicit no data is needed at all. */
    ch.x_min = 1;
    ch.x_max = 10;
    ch.y_min = 0;
    ch.y_max = 1;
    isk_canvas c = make(200, 150);
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    ch.nseries = 0;
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    isk_canvas_free(&c);
    /* One explicit axis: the other fits the points placeable on both. */
    valid_chart(&ch, &s);
    ch.x_min = 100; /* all points outside: still fitted, still drawn */
    ch.x_max = 200;
    isk_canvas d = make(200, 150);
    cr_assert_eq(isk_chart_draw(&ch, &d), ISK_OK);
    isk_canvas_free(&d);
}

Test(chart, error_range_enums)
{
    isk_chart ch;
    isk_chart_series s;
    valid_chart(&ch, &s);
    s.style.dash = ISK_DASH_COUNT;
    expect_error(&ch, ISK_ERR_RANGE);
    s.style.dash = (isk_chart_dash)-1;
    expect_error(&ch, ISK_ERR_RANGE);
    valid_chart(&ch, &s);
    s.style.marker = ISK_MARKER_COUNT;
    expect_error(&ch, ISK_ERR_RANGE);
    s.style.marker = (isk_chart_marker)-3;
    expect_error(&ch, ISK_ERR_RANGE);
    valid_chart(&ch, &s);
    ch.legend = ISK_LEGEND_COUNT;
    expect_error(&ch, ISK_ERR_RANGE);
    ch.legend = (isk_chart_legend)99;
    expect_error(&ch, ISK_ERR_RANGE);
}

Test(chart, error_nan_bounds)
{
    isk_chart ch;
    isk_chart_series s;
    valid_chart(&ch, &s);
    ch.x_min = -INFINITY;
    ch.x_max = 1.0;
    expect_error(&ch, ISK_ERR_NAN);
    ch.x_min = 0.0;
    ch.x_max = INFINITY;
    expect_error(&ch, ISK_ERR_NAN);
    valid_chart(&ch, &s);
    ch.y_min = -INFINITY;
    ch.y_max = INFINITY;
    expect_error(&ch, ISK_ERR_NAN);
}

/* When several things are wrong, the first in the header's order wins. */
Test(chart, error_order)
{
    isk_chart ch;
    isk_chart_series s;
    isk_canvas small = make(100, 100), ok = make(200, 150);
    valid_chart(&ch, &s);
    ch.series = NULL; /* NULL before SIZE */
    cr_assert_eq(isk_chart_draw(&ch, &small), ISK_ERR_NULL);
    valid_chart(&ch, &s);
    ch.x_min = 1.0; /* SIZE before the axes */
    cr_assert_eq(isk_chart_draw(&ch, &small), ISK_ERR_SIZE);
    ch.y_min = -INFINITY; /* x (one bound: RANGE) before y (Inf: NAN) */
    ch.y_max = 0.0;
    cr_assert_eq(isk_chart_draw(&ch, &ok), ISK_ERR_RANGE);
    ch.x_min = NAN; /* now y's NAN comes before a bad legend */
    ch.legend = ISK_LEGEND_COUNT;
    cr_assert_eq(isk_chart_draw(&ch, &ok), ISK_ERR_NAN);
    ch.x_min = ch.x_max = 1.0; /* x min >= max: RANGE before y's NAN */
    cr_assert_eq(isk_chart_draw(&ch, &ok), ISK_ERR_RANGE);
    isk_canvas_free(&small);
    isk_canvas_free(&ok);
}

/* ---- defaults and styles ------------------------------------------------- */

Test(chart, defaults)
{
    isk_chart ch;
    memset(&ch, 0x5a, sizeof ch);
    isk_chart_defaults(&ch);
    cr_assert_null(ch.title);
    cr_assert_null(ch.x_label);
    cr_assert_null(ch.y_label);
    cr_assert_eq(ch.x_log, 0);
    cr_assert_eq(ch.y_log, 0);
    cr_assert(isnan(ch.x_min) && isnan(ch.x_max) && isnan(ch.y_min) && isnan(ch.y_max));
    cr_assert_null(ch.series);
    cr_assert_eq(ch.nseries, 0);
    cr_assert_eq(ch.legend, ISK_LEGEND_TOP_RIGHT);
    cr_assert_eq(ch.background.r, 255);
    cr_assert_eq(ch.ink.r, 0);
    cr_assert_eq(ch.ink.a, 255);
    isk_chart_defaults(NULL); /* harmless */
}

Test(chart, style_default_distinct)
{
    for (int i = 0; i < 24; i++) {
        isk_chart_style a = isk_chart_style_default(i);
        cr_assert(a.marker > ISK_MARKER_NONE && a.marker < ISK_MARKER_COUNT);
        cr_assert(a.dash >= ISK_DASH_SOLID && a.dash < ISK_DASH_NONE);
        cr_assert_eq(a.color.a, 255);
        for (int j = 0; j < i; j++) {
            isk_chart_style b = isk_chart_style_default(j);
            /* apart even in grey: the (marker, dash) pair alone differs */
            cr_assert(a.marker != b.marker || a.dash != b.dash, "styles %d and %d look alike", i, j);
        }
    }
    /* neighbours differ in colour, and the first five are all solid-ish apart */
    for (int i = 1; i < 7; i++) {
        isk_color a = isk_chart_style_default(i).color, b = isk_chart_style_default(i - 1).color;
        cr_assert(a.r != b.r || a.g != b.g || a.b != b.b);
    }
    isk_chart_style n = isk_chart_style_default(-5), z = isk_chart_style_default(0);
    cr_assert_eq(n.marker, z.marker);
    (void)isk_chart_style_default(2147483647);
}

/* ---- ticks and labels ---------------------------------------------------- */

static void axis_labels(chart_axis *a, char *out, size_t n)
{
    out[0] = '\0';
    for (int k = 0; k < a->n; k++) {
        if (k)
            strncat(out, " ", n - strlen(out) - 1);
        strncat(out, a->label[k], n - strlen(out) - 1);
    }
}

static chart_axis log_axis(double lo, double hi, int len, int horizontal)
{
    chart_axis a;
    memset(&a, 0, sizeof a);
    a.log = 1;
    a.tlo = log10(lo);
    a.thi = log10(hi);
    isk__chart_axis_setup(&a, 0, 0, 0, len, horizontal, ISK_FONT_5X8, 1);
    return a;
}

static chart_axis lin_fit(double lo, double hi, int len, int horizontal)
{
    chart_axis a;
    memset(&a, 0, sizeof a);
    isk__chart_axis_setup(&a, 1, lo, hi, len, horizontal, ISK_FONT_5X8, 1);
    return a;
}

static chart_axis lin_explicit(double lo, double hi, int len, int horizontal)
{
    chart_axis a;
    memset(&a, 0, sizeof a);
    a.tlo = lo;
    a.thi = hi;
    isk__chart_axis_setup(&a, 0, 0, 0, len, horizontal, ISK_FONT_5X8, 1);
    return a;
}

#define LABELS_EQ(axis, want)                                                                      \
    do {                                                                                           \
        char got_[2048];                                                                           \
        chart_axis ax_ = (axis);                                                                   \
        axis_labels(&ax_, got_, sizeof got_);                                                      \
        cr_assert_str_eq(got_, want);                                                              \
    } while (0)

Test(chart, ticks_log_decades)
{
    LABELS_EQ(log_axis(1e-9, 1e-5, 600, 1), "1e-9 1e-8 1e-7 1e-6 1e-5");
    chart_axis a = log_axis(1e-9, 1e-5, 600, 1);
    cr_assert_eq(a.decade_step, 1);
    cr_assert_float_eq(a.t[0], -9.0, 1e-12);
    /* 17 decades on a 480 px y axis: every one */
    LABELS_EQ(log_axis(1e-16, 10, 480, 0),
              "1e-16 1e-15 1e-14 1e-13 1e-12 1e-11 1e-10 1e-9 1e-8 1e-7 1e-6 1e-5 1e-4 1e-3 1e-2 1e-1 "
              "1e0 1e1");
    /* ... on a 200 px one: every 2nd (others would touch) */
    a = log_axis(1e-16, 10, 200, 0);
    cr_assert_eq(a.decade_step, 2);
    LABELS_EQ(a, "1e-16 1e-14 1e-12 1e-10 1e-8 1e-6 1e-4 1e-2 1e0");
    /* 17 decades across 300 px: labels 5 cells wide need every 4th */
    a = log_axis(1e-16, 10, 300, 1);
    cr_assert_gt(a.decade_step, 1);
    for (int k = 0; k < a.n; k++)
        cr_assert_eq((int)a.t[k] % a.decade_step, 0);
    /* the extremes of double */
    a = log_axis(5e-324, DBL_MAX, 400, 0);
    cr_assert_gt(a.n, 2);
    cr_assert_leq(a.n, CHART_MAX_TICKS);
}

Test(chart, ticks_log_fitted)
{
    chart_axis a;
    memset(&a, 0, sizeof a);
    a.log = 1;
    isk__chart_axis_setup(&a, 1, log10(3e-9), log10(7e-6), 600, 1, ISK_FONT_5X8, 1);
    cr_assert_float_eq(a.tlo, -9.0, 0);
    cr_assert_float_eq(a.thi, -5.0, 0);
    /* all on one decade: one more each side */
    isk__chart_axis_setup(&a, 1, -3.0, -3.0, 600, 1, ISK_FONT_5X8, 1);
    cr_assert_float_eq(a.tlo, -4.0, 0);
    cr_assert_float_eq(a.thi, -2.0, 0);
    /* subnormal to DBL_MAX: still finite t */
    isk__chart_axis_setup(&a, 1, log10(5e-324), log10(DBL_MAX), 600, 0, ISK_FONT_5X8, 1);
    cr_assert_float_eq(a.tlo, -324.0, 0);
    cr_assert_float_eq(a.thi, 309.0, 0);
}

Test(chart, ticks_log_mantissas)
{
    /* up to three wide decades: 2..9 or 2 and 5 times each power as well */
    LABELS_EQ(log_axis(2, 8, 500, 1), "2e0 3e0 4e0 5e0 6e0 7e0 8e0");
    LABELS_EQ(log_axis(2, 8, 200, 1), "2e0 5e0");
    LABELS_EQ(log_axis(0.02, 0.05, 300, 0), "2e-2 3e-2 4e-2 5e-2");
    LABELS_EQ(log_axis(1e-2, 1, 580, 0), "1e-2 2e-2 5e-2 1e-1 2e-1 5e-1 1e0");
    /* narrow decades keep decade labels only */
    LABELS_EQ(log_axis(1e-2, 1, 100, 0), "1e-2 1e-1 1e0");
    LABELS_EQ(log_axis(1e1, 1e5, 890, 1), "1e1 1e2 1e3 1e4 1e5");
    /* inside one decade and between mantissas: the values' own 1-2-5 steps */
    LABELS_EQ(log_axis(2.1, 2.9, 300, 1), "2.2 2.4 2.6 2.8");
}

Test(chart, ticks_linear_nice)
{
    chart_axis a = lin_fit(0.0, 7.3, 600, 1);
    cr_assert_float_eq(a.tlo, 0.0, 0);
    cr_assert_float_eq(a.thi, 8.0, 0);
    LABELS_EQ(a, "0 1 2 3 4 5 6 7 8");
    a = lin_fit(0.0, 7.3, 200, 1); /* ticks stay >= 64 px apart */
    LABELS_EQ(a, "0 5 10");
    LABELS_EQ(lin_fit(0.0, 1.5, 400, 1), "0 0.5 1 1.5");
    LABELS_EQ(lin_fit(-2.2, 2.6, 160, 0), "-4 -2 0 2 4");
    LABELS_EQ(lin_fit(-2.2, 2.6, 300, 0), "-3 -2 -1 0 1 2 3");
    LABELS_EQ(lin_explicit(0.3, 0.7, 400, 1), "0.3 0.4 0.5 0.6 0.7");
    LABELS_EQ(lin_explicit(-1, 1, 300, 0), "-1 -0.5 0 0.5 1");
}

Test(chart, ticks_linear_labels)
{
    /* fixed notation while the largest tick is in [1e-3, 1e5) */
    LABELS_EQ(lin_explicit(0, 50000, 400, 1), "0 10000 20000 30000 40000 50000");
    LABELS_EQ(lin_explicit(0, 0.002, 300, 1), "0 0.0005 0.001 0.0015 0.002");
    LABELS_EQ(lin_explicit(1, 1.00005, 500, 1), "1 1.00001 1.00002 1.00003 1.00004 1.00005");
    /* scientific outside it, mantissa digits as the step needs */
    LABELS_EQ(lin_explicit(0, 1e5, 400, 1), "0 2e4 4e4 6e4 8e4 1e5");
    LABELS_EQ(lin_explicit(0, 3e-4, 400, 1), "0 5e-5 1e-4 1.5e-4 2e-4 2.5e-4 3e-4");
    LABELS_EQ(lin_explicit(1e5, 2e5, 250, 0), "1e5 1.2e5 1.4e5 1.6e5 1.8e5 2e5");
    char buf[CHART_LABEL_MAX];
    isk__chart_format_linear(buf, sizeof buf, -1.5e-7, -8, 2e-7);
    cr_assert_str_eq(buf, "-1.5e-7");
    isk__chart_format_linear(buf, sizeof buf, -0.0, 0, 1);
    cr_assert_str_eq(buf, "0");
    isk__chart_format_linear(buf, sizeof buf, DBL_MAX, 307, DBL_MAX);
    cr_assert_str_eq(buf, "1.8e308");
}

Test(chart, ticks_linear_degenerate)
{
    /* all points equal: 10% either side, or -1..1 around 0 and subnormals */
    chart_axis a = lin_fit(5.0, 5.0, 400, 1);
    cr_assert(a.tlo < 5.0 && a.thi > 5.0 && a.tlo >= 4.0 && a.thi <= 6.0);
    cr_assert_gt(a.n, 1);
    a = lin_fit(0.0, 0.0, 400, 0);
    cr_assert_float_eq(a.tlo, -1.0, 0);
    cr_assert_float_eq(a.thi, 1.0, 0);
    a = lin_fit(5e-324, 5e-324, 400, 0);
    cr_assert(a.tlo < 0.0 && a.thi > 0.0);
    a = lin_fit(-DBL_MAX, DBL_MAX, 400, 1);
    cr_assert(isfinite(a.tlo) && isfinite(a.thi) && a.tlo < a.thi);
    a = lin_fit(DBL_MAX, DBL_MAX, 400, 0);
    cr_assert(isfinite(a.tlo) && isfinite(a.thi) && a.tlo < a.thi);
    /* a range far below its magnitude's precision: no crash, few labels */
    a = lin_explicit(1e17, 1e17 + 64, 400, 1);
    cr_assert_leq(a.n, CHART_MAX_TICKS);
    a = lin_explicit(0, 5e-324, 400, 1);
    cr_assert_leq(a.n, CHART_MAX_TICKS);
    for (int k = 1; k < a.n; k++)
        cr_assert_gt(a.t[k], a.t[k - 1]);
}

Test(chart, labels_never_overlap)
{
    /* For many ranges and lengths, labels keep their gap. */
    const double spans[][2] = {{0, 7.3},    {-2.2, 2.6}, {1e-3, 9e4}, {-123456, 789},
                               {0.1, 0.11}, {1e10, 3e10}, {-1e-6, 1e-6}};
    for (size_t i = 0; i < sizeof spans / sizeof spans[0]; i++)
        for (int len = 100; len <= 1500; len += 70)
            for (int hz = 0; hz < 2; hz++) {
                chart_axis a = lin_fit(spans[i][0], spans[i][1], len, hz);
                cr_assert_geq(a.n, 1, "no labels for %g..%g at %d", spans[i][0], spans[i][1], len);
                double prev = -1e9;
                for (int k = 0; k < a.n; k++) {
                    double p = isk__chart_axis_frac(&a, a.t[k]) * len;
                    double half = hz ? 0.5 * (6.0 * strlen(a.label[k])) : 4.5;
                    cr_assert_geq(p - half - prev, hz ? 6.0 : 9.0, "%s too close", a.label[k]);
                    prev = p + half;
                }
            }
}

/* ---- whole charts on odd data --------------------------------------------- */

Test(chart, deterministic)
{
    double x[5][NPT], y[5][NPT];
    isk_chart_series ser[5];
    isk_chart ch;
    wp_chart(&ch, ser, x, y);
    isk_canvas a = make(640, 480), b = make(640, 480);
    cr_assert_eq(isk_chart_draw(&ch, &a), ISK_OK);
    cr_assert_eq(isk_chart_draw(&ch, &b), ISK_OK);
    cr_assert(isk_canvas_equal(&a, &b));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

/* Data far outside explicit ranges changes only pixels inside the frame. */
Test(chart, clip_stays_inside)
{
    /* a horizontal, a vertical and a diagonal line through the plot, each
     * from far outside to far outside */
    const double x[6] = {-1e300, 1e300, 0.5, 0.5, 30, -30};
    const double y[6] = {0.5, 0.5, -1e300, 1e300, 7, -7};
    isk_chart_series ser = series(NULL, x, y, 6, 0);
    ser.style.marker = ISK_MARKER_NONE;
    for (int thick = 0; thick < 2; thick++) {
        isk_chart ch;
        isk_chart_defaults(&ch);
        ch.x_min = 0;
        ch.x_max = 1;
        ch.y_min = 0;
        ch.y_max = 1;
        ch.legend = ISK_LEGEND_NONE;
        int w = thick ? 1300 : 400;
        isk_canvas empty = make(w, 300), full = make(w, 300);
        cr_assert_eq(isk_chart_draw(&ch, &empty), ISK_OK);
        ch.series = &ser;
        ch.nseries = 1;
        cr_assert_eq(isk_chart_draw(&ch, &full), ISK_OK);
        chart_axis ax, ay;
        chart_layout lay;
        cr_assert_eq(isk__chart_prepare(&ch, &full, &ax, &ay, &lay), ISK_OK);
        long changed = 0;
        for (int j = 0; j < full.height; j++)
            for (int i = 0; i < full.width; i++) {
                isk_color p = isk_canvas_get(&full, i, j), q = isk_canvas_get(&empty, i, j);
                if (p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a)
                    continue;
                changed++;
                cr_assert(i > lay.L && i < lay.R && j > lay.T && j < lay.B, "pixel (%d, %d) outside the plot",
                          i, j);
            }
        cr_assert_gt(changed, 100); /* the lines did cross the plot */
        isk_canvas_free(&empty);
        isk_canvas_free(&full);
    }
}

/* Small deterministic generator for the fuzz test. */
static unsigned long long lcg(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return *s >> 33;
}

/* Extreme values in every combination: no crash (the sanitizers watch), a
 * status from the documented list, and nothing outside a view changes. */
Test(chart, fuzz_extremes)
{
    static const double vals[] = {NAN,    INFINITY, -INFINITY, 0.0,     -0.0,    1.0,     -1.0,
                                  1e300,  -1e300,   DBL_MAX,   -DBL_MAX, DBL_MIN, 5e-324,  -5e-324,
                                  1e-300, 3.7,      1e15,      1e15 + 1, 123456789, -2e-8, 0.1};
    const int nv = (int)(sizeof vals / sizeof vals[0]);
    isk_canvas big = make(420, 320), ref = make(420, 320);
    const int vx0 = 70, vy0 = 60, vw = 260, vh = 190;
    unsigned long long seed = 12345;
    for (int it = 0; it < 400; it++) {
        enum { N = 9 };
        double x[2][N], y[2][N];
        for (int s = 0; s < 2; s++)
            for (int i = 0; i < N; i++) {
                x[s][i] = vals[lcg(&seed) % (unsigned)nv];
                y[s][i] = vals[lcg(&seed) % (unsigned)nv];
                if (lcg(&seed) % 3 == 0) /* some ordinary points too */
                    y[s][i] = (double)(lcg(&seed) % 1000) * 1e-3;
            }
        isk_chart_series ser[2] = {series("a", x[0], y[0], N, it), series("b", x[1], y[1], N, it + 1)};
        isk_chart ch;
        isk_chart_defaults(&ch);
        ch.series = ser;
        ch.nseries = 2;
        ch.x_log = (int)(lcg(&seed) % 2);
        ch.y_log = (int)(lcg(&seed) % 2);
        ch.legend = (isk_chart_legend)(lcg(&seed) % ISK_LEGEND_COUNT);
        if (lcg(&seed) % 3 == 0) {
            double a = vals[lcg(&seed) % (unsigned)nv], b = vals[lcg(&seed) % (unsigned)nv];
            ch.x_min = a < b ? a : b;
            ch.x_max = a < b ? b : a;
        }
        if (lcg(&seed) % 3 == 0) {
            double a = vals[lcg(&seed) % (unsigned)nv], b = vals[lcg(&seed) % (unsigned)nv];
            ch.y_min = a < b ? a : b;
            ch.y_max = a < b ? b : a;
        }
        isk_canvas view;
        cr_assert_eq(isk_canvas_view(&view, &big, vx0, vy0, vw, vh), ISK_OK);
        isk_status st = isk_chart_draw(&ch, &view);
        cr_assert(st == ISK_OK || st == ISK_ERR_RANGE || st == ISK_ERR_NAN, "iteration %d: status %d", it, st);
        for (int j = 0; j < big.height; j++)
            for (int i = 0; i < big.width; i++) {
                if (i >= vx0 && i < vx0 + vw && j >= vy0 && j < vy0 + vh)
                    continue;
                isk_color p = isk_canvas_get(&big, i, j), q = isk_canvas_get(&ref, i, j);
                cr_assert(p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a,
                          "iteration %d wrote (%d, %d) outside its view", it, i, j);
            }
    }
    isk_canvas_free(&big);
    isk_canvas_free(&ref);
}

/* Long, many-line and non-ASCII text and a hundred named series: drawn,
 * and nothing outside the view changes. */
Test(chart, odd_text_and_many_series)
{
    static char longname[3000];
    memset(longname, 'w', sizeof longname - 1);
    longname[sizeof longname - 1] = '\0';
    static const char *const texts[] = {"", "a", "two\nlines", "\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n", "caf\xc3\xa9 \x01\xff",
                                        longname};
    enum { NS = 100 };
    static double x[3] = {1, 2, 3}, y[3] = {3, 1, 2};
    isk_chart_series ser[NS];
    for (int k = 0; k < NS; k++)
        ser[k] = series(texts[k % 6], x, y, 3, k);
    isk_canvas big = make(700, 500), ref = make(700, 500);
    for (int t = 0; t < 6; t++)
        for (int size = 0; size < 2; size++) {
            isk_chart ch;
            isk_chart_defaults(&ch);
            ch.title = texts[t];
            ch.x_label = texts[(t + 1) % 6];
            ch.y_label = texts[(t + 2) % 6];
            ch.series = ser;
            ch.nseries = NS;
            ch.legend = (isk_chart_legend)(t % 4);
            isk_canvas_fill(&big, isk_rgba(1, 2, 3, 4)); /* as ref again */
            isk_canvas view;
            int vw = size ? 400 : 160, vh = size ? 300 : 120;
            cr_assert_eq(isk_canvas_view(&view, &big, 50, 40, vw, vh), ISK_OK);
            cr_assert_eq(isk_chart_draw(&ch, &view), ISK_OK);
            for (int j = 0; j < big.height; j++)
                for (int i = 0; i < big.width; i++) {
                    if (i >= 50 && i < 50 + vw && j >= 40 && j < 40 + vh)
                        continue;
                    isk_color p = isk_canvas_get(&big, i, j), q = isk_canvas_get(&ref, i, j);
                    cr_assert(p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a, "t %d size %d wrote (%d, %d)", t, size, i, j);
                }
        }
    isk_canvas_free(&big);
    isk_canvas_free(&ref);
}
