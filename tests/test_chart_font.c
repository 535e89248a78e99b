/* SPDX-License-Identifier: MIT */
/* Chart text in the 6x13 font (isk_chart.font) and the legend over the
 * plot (ISK_LEGEND_ABOVE), drawn exactly as refimg/chart_font_6x13.png.
 * Every text of a chart in that font is at least 10 px tall, measured on
 * its pixels (the rule for `iskra play`'s window, whose charts use it);
 * the default font draws what it always drew. */
#include <criterion/criterion.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chart/chart_internal.h"
#include "iskra/chart.h"
#include "refimg.h"

static isk_canvas make(int w, int h)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, w, h), ISK_OK);
    isk_canvas_fill(&c, isk_rgba(1, 2, 3, 4));
    return c;
}

/* ---- two charts with every kind of text ----------------------------------- */

static const double lin_x[5] = {110, 130, 150, 170, 190}, lin_k[5] = {1120, 1180, 1260, 1330, 1410},
                    lin_p[5] = {1400, 1330, 1250, 1190, 1110}, lin_t[5] = {1520, 1510, 1510, 1520, 1520};
static const double log_x[4] = {2e1, 2e2, 2e3, 2e4}, log_a[4] = {1e-2, 1e-3, 1e-4, 1e-5},
                    log_b[4] = {3e-2, 9e-4, 3e-5, 2e-6};

/* Linear: title, axis labels, a note, the legend over the plot.  Every
 * text holds a capital or a digit, so each is as tall as the font's
 * capitals (a word of x-height letters alone would be shorter). */
static void linear_chart(isk_chart *ch, isk_chart_series s[3], isk_font font)
{
    s[0] = (isk_chart_series){"Kinetic", lin_x, lin_k, 5, isk_chart_style_default(0)};
    s[1] = (isk_chart_series){"Potential", lin_x, lin_p, 5, isk_chart_style_default(1)};
    s[2] = (isk_chart_series){"Total", lin_x, lin_t, 5, isk_chart_style_default(2)};
    static const isk_chart_note note = {150, 1260, "Mid 150", {0, 0, 0, 255}, ISK_MARKER_NONE};
    isk_chart_defaults(ch);
    ch->title = "Energy Chart";
    ch->x_label = "Time (s)";
    ch->y_label = "Energy (J)";
    ch->series = s;
    ch->nseries = 3;
    ch->legend = ISK_LEGEND_ABOVE;
    ch->notes = &note;
    ch->nnotes = 1;
    ch->grid = ch->background;
    ch->font = font;
}

/* Log-log with a top axis and the legend's box in a corner. */
static void log_chart(isk_chart *ch, isk_chart_series s[2], isk_font font)
{
    s[0] = (isk_chart_series){"Euler", log_x, log_a, 4, isk_chart_style_default(0)};
    s[1] = (isk_chart_series){"RK4", log_x, log_b, 4, isk_chart_style_default(1)};
    isk_chart_defaults(ch);
    ch->title = "Error 2D";
    ch->x_label = "NS (per step)";
    ch->y_label = "Error (m)";
    ch->x_log = ch->y_log = 1;
    ch->x2_label = "Steps (1/s)";
    ch->x2_scale = 1e9;
    ch->x2_inverse = 1;
    ch->series = s;
    ch->nseries = 2;
    ch->legend = ISK_LEGEND_TOP_RIGHT;
    ch->grid = ch->background;
    ch->font = font;
}

/* ---- the reference image ---------------------------------------------------------- */

/* Both charts in 6x13, and the linear one on a 210 x 160 canvas, where its
 * legend over the plot takes two rows. */
Test(refimg, chart_font_6x13)
{
    isk_canvas c = make(1180, 380);
    isk_canvas_fill(&c, isk_rgba(60, 60, 60, 255));
    isk_canvas v;
    isk_chart ch;
    isk_chart_series lin[3], lg[2];
    linear_chart(&ch, lin, ISK_FONT_6X13);
    ch.grid = isk_rgba(225, 225, 225, 255);
    cr_assert_eq(isk_canvas_view(&v, &c, 10, 10, 480, 360), ISK_OK);
    cr_assert_eq(isk_chart_draw(&ch, &v), ISK_OK);
    log_chart(&ch, lg, ISK_FONT_6X13);
    ch.grid = isk_rgba(225, 225, 225, 255);
    cr_assert_eq(isk_canvas_view(&v, &c, 500, 10, 450, 360), ISK_OK);
    cr_assert_eq(isk_chart_draw(&ch, &v), ISK_OK);
    linear_chart(&ch, lin, ISK_FONT_6X13);
    ch.title = NULL;
    ch.x_label = NULL;
    ch.y_label = "Energy";
    ch.notes = NULL;
    ch.nnotes = 0;
    cr_assert_eq(isk_canvas_view(&v, &c, 960, 10, 210, 160), ISK_OK);
    cr_assert_eq(isk_chart_draw(&ch, &v), ISK_OK);
    cr_assert(refimg_check("chart_font_6x13", &c), "refimg chart_font_6x13 differs");
    isk_canvas_free(&c);
}

/* ---- measuring text on the pixels ---------------------------------------------
 * The chart's ink (black here) is its frame, ticks and text; the series,
 * the grid and the legend's frame are other colours.  Pixels of the ink
 * are grouped into pieces (8-connected); the frame with its ticks is the
 * largest.  The others are glyphs, or parts of one ('i' and its dot), and
 * are joined into words: pieces side by side along a line (overlapping
 * across it) with at most a glyph's spacing between them, in either
 * direction, so the turned y label joins too.  A word's thickness (its
 * smaller extent) is the height of its text, as a text reads along its
 * longer side: every word here has two characters or more. */

typedef struct box {
    int x0, y0, x1, y1; /* inclusive */
} box;

typedef struct words {
    box w[256];
    int n;
} words;

static int is_ink(const isk_canvas *c, int x, int y)
{
    const uint8_t *p = isk_canvas_at(c, x, y);
    return p[0] == 0 && p[1] == 0 && p[2] == 0 && p[3] == 255;
}

/* The pieces of ink: their boxes, the frame's left out and what stands
 * within `near` pixels outside it. */
static int pieces(const isk_canvas *c, box *out, int max, int near)
{
    const int W = c->width, H = c->height;
    unsigned char *seen = calloc((size_t)W * (size_t)H, 1);
    int *stack = malloc(sizeof(int) * (size_t)W * (size_t)H);
    cr_assert(seen && stack);
    int n = 0, biggest = -1;
    long biggest_area = -1;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            if (seen[y * W + x] || !is_ink(c, x, y))
                continue;
            box b = {x, y, x, y};
            int top = 0;
            stack[top++] = y * W + x;
            seen[y * W + x] = 1;
            while (top > 0) {
                int i = stack[--top], px = i % W, py = i / W;
                b.x0 = px < b.x0 ? px : b.x0;
                b.x1 = px > b.x1 ? px : b.x1;
                b.y0 = py < b.y0 ? py : b.y0;
                b.y1 = py > b.y1 ? py : b.y1;
                for (int dy = -1; dy <= 1; dy++)
                    for (int dx = -1; dx <= 1; dx++) {
                        int qx = px + dx, qy = py + dy;
                        if (qx < 0 || qy < 0 || qx >= W || qy >= H || seen[qy * W + qx] || !is_ink(c, qx, qy))
                            continue;
                        seen[qy * W + qx] = 1;
                        stack[top++] = qy * W + qx;
                    }
            }
            cr_assert_lt(n, max);
            long area = (long)(b.x1 - b.x0 + 1) * (b.y1 - b.y0 + 1);
            if (area > biggest_area) {
                biggest_area = area;
                biggest = n;
            }
            out[n++] = b;
        }
    free(seen);
    free(stack);
    cr_assert_geq(biggest, 0, "no frame");
    const box f = out[biggest];
    out[biggest] = out[--n];
    /* the top axis's ticks stop a pixel short of the frame: not text */
    for (int i = 0; i < n; i++) {
        const box *b = &out[i];
        int inside = b->x0 > f.x0 && b->x1 < f.x1 && b->y0 > f.y0 && b->y1 < f.y1;
        int gx = b->x0 > f.x1 ? b->x0 - f.x1 : f.x0 > b->x1 ? f.x0 - b->x1 : 0;
        int gy = b->y0 > f.y1 ? b->y0 - f.y1 : f.y0 > b->y1 ? f.y0 - b->y1 : 0;
        if (!inside && gx <= near && gy <= near)
            out[i--] = out[--n];
    }
    return n;
}

/* Gap between two spans (negative: they overlap). */
static int gap(int a0, int a1, int b0, int b1)
{
    return a0 > b1 ? a0 - b1 - 1 : b0 > a1 ? b0 - a1 - 1 : -1;
}

static void measure(const isk_canvas *c, isk_font font, int scale, words *out)
{
    static box p[4096];
    int n = pieces(c, p, 4096, 2 * scale);
    const isk_font_metrics *m = isk_font_metrics_of(font);
    const int spacing = m->cell_w - 1; /* the widest blank between two glyphs of a word */
    /* join until nothing joins */
    for (int joined = 1; joined;) {
        joined = 0;
        for (int i = 0; i < n; i++)
            for (int j = i + 1; j < n; j++) {
                int gx = gap(p[i].x0, p[i].x1, p[j].x0, p[j].x1), gy = gap(p[i].y0, p[i].y1, p[j].y0, p[j].y1);
                if (!((gy < 0 && gx <= spacing) || (gx < 0 && gy <= spacing)))
                    continue;
                p[i].x0 = p[j].x0 < p[i].x0 ? p[j].x0 : p[i].x0;
                p[i].y0 = p[j].y0 < p[i].y0 ? p[j].y0 : p[i].y0;
                p[i].x1 = p[j].x1 > p[i].x1 ? p[j].x1 : p[i].x1;
                p[i].y1 = p[j].y1 > p[i].y1 ? p[j].y1 : p[i].y1;
                p[j--] = p[--n];
                joined = 1;
            }
    }
    cr_assert_leq(n, 256);
    out->n = n;
    memcpy(out->w, p, sizeof(box) * (size_t)n);
}

static int thickness(const box *b)
{
    int w = b->x1 - b->x0 + 1, h = b->y1 - b->y0 + 1;
    return w < h ? w : h;
}

/* The thinnest word of a chart drawn on a w x h canvas; *count: words. */
static int thinnest(const isk_chart *ch, int w, int h, int scale, int *count)
{
    isk_canvas c = make(w, h);
    cr_assert_eq(isk_chart_draw(ch, &c), ISK_OK);
    static words ws;
    measure(&c, ch->font, scale, &ws);
    int least = 1 << 30;
    for (int i = 0; i < ws.n; i++) {
        int t = thickness(&ws.w[i]);
        if (t < least) {
            least = t;
            cr_log_info("thinnest so far: %d px at (%d, %d)-(%d, %d)", t, ws.w[i].x0, ws.w[i].y0, ws.w[i].x1,
                        ws.w[i].y1);
        }
    }
    *count = ws.n;
    isk_canvas_free(&c);
    return least;
}

/* Every text of both charts, at scale 1 and at scale 2, is at least 10
 * px tall in the 6x13 font; the same measure finds the 5x8 font's shorter
 * (so it would see a text left in the small font). */
Test(chart_font, every_text_at_least_10_px_tall)
{
    static const int sizes[2][2] = {{480, 360}, {1200, 800}};
    for (int k = 0; k < 2; k++) {
        const int w = sizes[k][0], h = sizes[k][1], s = k + 1;
        isk_chart ch;
        isk_chart_series lin[3], lg[2];
        int n, least;
        linear_chart(&ch, lin, ISK_FONT_6X13);
        least = thinnest(&ch, w, h, s, &n);
        /* title, x and y labels (two words each), the legend's three names,
         * the note (two words), five x and some y tick labels */
        cr_expect_geq(n, 15, "%d words at %dx%d", n, w, h);
        cr_expect_geq(least, 10, "a text %d px tall in the linear chart at %dx%d", least, w, h);
        log_chart(&ch, lg, ISK_FONT_6X13);
        least = thinnest(&ch, w, h, s, &n);
        cr_expect_geq(n, 12, "%d words at %dx%d", n, w, h);
        cr_expect_geq(least, 10, "a text %d px tall in the log chart at %dx%d", least, w, h);

        linear_chart(&ch, lin, ISK_FONT_5X8);
        cr_expect_lt(thinnest(&ch, w, h, s, &n), 8 * s + 1, "the 5x8 font's texts are 7 or 8 px tall");
        log_chart(&ch, lg, ISK_FONT_5X8);
        cr_expect_lt(thinnest(&ch, w, h, s, &n), 8 * s + 1);
    }
}

/* The default is the 5x8 font, and naming it draws the same bytes. */
Test(chart_font, the_default_is_the_5x8_font_unchanged)
{
    isk_chart ch;
    memset(&ch, 0x5a, sizeof ch);
    isk_chart_defaults(&ch);
    cr_assert_eq(ch.font, ISK_FONT_5X8);
    isk_chart_series lin[3];
    linear_chart(&ch, lin, ISK_FONT_5X8);
    isk_canvas a = make(480, 360), b = make(480, 360);
    cr_assert_eq(isk_chart_draw(&ch, &a), ISK_OK);
    isk_chart d;
    isk_chart_defaults(&d);
    ch.font = d.font;
    cr_assert_eq(isk_chart_draw(&ch, &b), ISK_OK);
    cr_assert(isk_canvas_equal(&a, &b));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(chart_font, an_unknown_font_is_refused)
{
    isk_chart ch;
    isk_chart_series lin[3];
    linear_chart(&ch, lin, ISK_FONT_COUNT);
    isk_canvas c = make(480, 360), before = make(480, 360);
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_ERR_RANGE);
    ch.font = (isk_font)-1;
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_ERR_RANGE);
    cr_assert(isk_canvas_equal(&c, &before), "nothing drawn");
    isk_canvas_free(&c);
    isk_canvas_free(&before);
}

/* ---- the layout follows the font -------------------------------------------------- */

/* Widest y tick label's ink. */
static int widest(const chart_axis *y, isk_font font)
{
    int w = 0;
    for (int k = 0; k < y->n; k++) {
        int iw = isk_font_text_width(font, y->label[k], 1) - 1;
        w = iw > w ? iw : w;
    }
    return w;
}

/* The margins grow with the font's cells: title, half a line over the
 * frame, tick labels and x label with the gap under them, the turned y
 * label with its gap, the widest y tick label. */
Test(chart_font, the_margins_follow_the_font)
{
    isk_chart ch;
    isk_chart_series lin[3];
    isk_canvas c = make(480, 360);
    chart_axis x, y5, y13;
    chart_layout small, big;
    linear_chart(&ch, lin, ISK_FONT_5X8);
    ch.legend = ISK_LEGEND_NONE;
    cr_assert_eq(isk__chart_prepare(&ch, &c, &x, &y5, &small), ISK_OK);
    ch.font = ISK_FONT_6X13;
    cr_assert_eq(isk__chart_prepare(&ch, &c, &x, &y13, &big), ISK_OK);
    /* top: pad 6, the title's line (9 or 14) and pad 6, half a line (4 or
     * 7), 1: so 26 and 34 */
    cr_expect_eq(small.T, 6 + 9 + 6 + 4 + 1);
    cr_expect_eq(big.T, 6 + 14 + 6 + 7 + 1);
    /* bottom: pad 6, the x label's line with its gap (2 px in 5x8, 14/9 of
     * that in 6x13: 3), the tick labels' line, gap 3, tick 5, 1 */
    cr_expect_eq(small.B, 360 - 6 - (9 + 2) - 9 - 9);
    cr_expect_eq(big.B, 360 - 6 - (14 + 3) - 14 - 9);
    /* left: pad 6, the turned y label's line with its gap (4 px, 14/9 of
     * that: 6), the widest tick label's ink, gap 3 and tick 5 */
    cr_expect_eq(small.L, 6 + (9 + 4) + widest(&y5, ISK_FONT_5X8) + 8);
    cr_expect_eq(big.L, 6 + (14 + 6) + widest(&y13, ISK_FONT_6X13) + 8);
    cr_expect_gt(widest(&y13, ISK_FONT_6X13), widest(&y5, ISK_FONT_5X8));
    isk_canvas_free(&c);
}

/* Linear ticks stand at least 64 px apart across and 40 px up in 5x8
 * cells, 74 and 62 px in 6x13 ones (iskra/chart.h), then at the first
 * step of 1, 2 or 5 times a power of ten that covers the range in that
 * many: over 0..100, on 320 px across 5x8 allows 5 steps (of 20: six
 * ticks) and 6x13 4 (of 25, so 50: three ticks); on 400 px up, 10 steps
 * (of 10: eleven ticks) and 6 (of 16.7, so 20: six ticks). */
Test(chart_font, tick_spacing_follows_the_font)
{
    chart_axis a;
    memset(&a, 0, sizeof a);
    a.tlo = 0;
    a.thi = 100;
    isk__chart_axis_setup(&a, 0, 0, 0, 320, 1, ISK_FONT_5X8, 1);
    cr_expect_eq(a.n, 6);
    isk__chart_axis_setup(&a, 0, 0, 0, 320, 1, ISK_FONT_6X13, 1);
    cr_expect_eq(a.n, 3);
    isk__chart_axis_setup(&a, 0, 0, 0, 400, 0, ISK_FONT_5X8, 1);
    cr_expect_eq(a.n, 11);
    isk__chart_axis_setup(&a, 0, 0, 0, 400, 0, ISK_FONT_6X13, 1);
    cr_expect_eq(a.n, 6);
    /* at scale 2, twice the pixels: the same ticks on twice the length */
    isk__chart_axis_setup(&a, 0, 0, 0, 640, 1, ISK_FONT_6X13, 2);
    cr_expect_eq(a.n, 3);
}

/* A fitted linear axis whose labels fit at no step up to ten times the
 * data's span (across zero, three ticks on a plot too short for them)
 * keeps the data's range, bare, rather than growing its step until the
 * data are a sliver of the plot. */
Test(chart_font, a_short_axis_keeps_the_data_range)
{
    chart_axis a;
    memset(&a, 0, sizeof a);
    isk__chart_axis_setup(&a, 1, -8e6, 1e6, 54, 0, ISK_FONT_6X13, 1);
    cr_expect_eq(a.n, 0);
    cr_expect_eq(a.tlo, -8e6);
    cr_expect_eq(a.thi, 1e6);
    /* 56 px hold three labels two lines apart: -1e7, 0, 1e7 */
    isk__chart_axis_setup(&a, 1, -8e6, 1e6, 56, 0, ISK_FONT_6X13, 1);
    cr_expect_eq(a.n, 3);
    cr_expect_eq(a.tlo, -1e7);
    cr_expect_eq(a.thi, 1e7);
    /* within ten spans a step may still grow: 0.9..1.1 in 20 px across at
     * 5x8 ("0", "2": steps of 2, ten times the span) */
    isk__chart_axis_setup(&a, 1, 0.9, 1.1, 20, 1, ISK_FONT_5X8, 1);
    cr_expect_eq(a.n, 2, "%d", a.n);
    cr_expect_eq(a.tlo, 0.0);
    cr_expect_eq(a.thi, 2.0);
}
