/* SPDX-License-Identifier: MIT */
/* src/chart/chart_axis.c — axis ranges, tick positions and tick labels.
 *
 * Linear axes step by m * 10^e with m in {1, 2, 5}: the first step (from a
 * preferred tick spacing in pixels) whose labels do not collide wins; a
 * fitted axis is widened to whole steps of the step it ends up with, so
 * its ends carry labels.  Log axes label every k-th decade for the smallest
 * k whose labels fit; a few wide decades also get 2..9 or 2, 5 times each
 * power, and a range inside one decade falls back to 1-2-5 ticks of the
 * values themselves.  "Fit" always means the same test: neighbouring labels
 * keep a character cell (x) or a blank line (y) apart.  Step values are built as
 * integer * m / 10^-e rather than by accumulating a double step, so "0.3"
 * is 3/10 and not 0.1+0.1+0.1.  Every double -> int conversion below is of
 * a number already known to be small.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "chart/chart_axis.h"
#include "iskra/text.h"

#define TOL 1e-9           /* in units of a step or a decade */
#define MAX_STEP_TRIES 48  /* each try at least doubles the step */
#define PREF_X 64          /* preferred linear tick spacing, px of the 5x8 font at scale 1 */
#define PREF_Y 40          /* (follows the labels' font: x by its cell width, y by its line height) */

int isk__chart_axis_place(int log, double v, double *t)
{
    if (!isfinite(v) || (log && v <= 0.0))
        return 0;
    *t = log ? log10(v) : v;
    return 1;
}

double isk__chart_axis_frac(const chart_axis *a, double t)
{
    double span = a->thi - a->tlo, d = t - a->tlo, f;
    if (isfinite(span) && isfinite(d))
        f = d / span;
    else /* only linear ranges near DBL_MAX get here; halves cannot overflow */
        f = (t * 0.5 - a->tlo * 0.5) / (a->thi * 0.5 - a->tlo * 0.5);
    if (isnan(f))
        return 0.0;
    if (f > 1e300)
        return 1e300;
    if (f < -1e300)
        return -1e300;
    return f;
}

/* i * m * 10^e, dividing by an exact-ish power of ten where we can. */
static double step_mul(double i, int m, int e)
{
    double im = i * (double)m;
    if (e >= 0)
        return im * pow(10.0, e);
    if (e >= -308)
        return im / pow(10.0, -e);
    return im * pow(10.0, e);
}

/* Smallest m * 10^e >= raw with m in {1, 2, 5}; raw > 0 and finite. */
static void nice_ceil(double raw, int *m, int *e)
{
    double lg = floor(log10(raw));
    int ex = (int)lg; /* |lg| <= 324 */
    double base = pow(10.0, ex);
    if (raw <= base)
        *m = 1;
    else if (raw <= 2.0 * base)
        *m = 2;
    else if (raw <= 5.0 * base)
        *m = 5;
    else {
        *m = 1;
        ex++;
    }
    *e = ex;
}

static void next_step(int *m, int *e)
{
    if (*m == 1)
        *m = 2;
    else if (*m == 2)
        *m = 5;
    else {
        *m = 1;
        (*e)++;
    }
}

/* Trailing zeros of a decimal fraction, then a bare point, go. */
static void strip_zeros(char *s)
{
    if (!strchr(s, '.'))
        return;
    size_t n = strlen(s);
    while (n > 0 && s[n - 1] == '0')
        s[--n] = '\0';
    if (n > 0 && s[n - 1] == '.')
        s[--n] = '\0';
}

void isk__chart_format_linear(char *buf, size_t n, double v, int e, double vmax)
{
    if (n == 0)
        return;
    if (v == 0.0 || !isfinite(v)) {
        snprintf(buf, n, "0");
        return;
    }
    if (vmax < 1e5 && vmax >= 1e-3) {
        int dec = e < 0 ? -e : 0;
        if (dec > 20)
            dec = 20;
        snprintf(buf, n, "%.*f", dec, v);
        strip_zeros(buf);
        if (strcmp(buf, "-0") == 0)
            snprintf(buf, n, "0");
        return;
    }
    /* Scientific: as many mantissa digits as the step needs, then tidy
     * "1.50e+04" into "1.5e4". */
    double ex = floor(log10(fabs(v)));
    double d = ex - (double)e;
    int digits = d < 0.0 ? 0 : d > 16.0 ? 16 : (int)d;
    char tmp[64];
    snprintf(tmp, sizeof tmp, "%.*e", digits, v);
    char *ep = strchr(tmp, 'e');
    if (!ep) {
        snprintf(buf, n, "%s", tmp);
        return;
    }
    *ep = '\0';
    strip_zeros(tmp);
    const char *x = ep + 1;
    int neg = (*x == '-');
    if (*x == '-' || *x == '+')
        x++;
    while (x[0] == '0' && x[1] != '\0')
        x++;
    snprintf(buf, n, "%se%s%s", tmp, neg ? "-" : "", x);
}

/* The text an axis's labels are written in. */
typedef struct label_text {
    isk_font font;
    int scale;
    int cw, chh; /* the font's cell width and line height at that scale */
} label_text;

/* Do the labels of a, laid out along an axis len pixels long, keep at
 * least a cell (x) or a line (y) apart? */
static int labels_fit(const chart_axis *a, int len, int horizontal, const label_text *lt)
{
    double prev = 0.0;
    for (int k = 0; k < a->n; k++) {
        double p = isk__chart_axis_frac(a, a->t[k]) * (double)len;
        double half = horizontal ? 0.5 * isk_font_text_width(lt->font, a->label[k], lt->scale) : 0.5 * lt->chh;
        double gap = horizontal ? lt->cw : lt->chh;
        if (k > 0 && (p - half) - prev < gap)
            return 0;
        prev = p + half;
    }
    return 1;
}

/* Ticks m*10^e*i for i in [ceil(lo/step), floor(hi/step)] into a (values
 * are positioned at log10(v) when logpos).  Returns 0 when there would be
 * too many, or when the doubles cannot tell neighbouring ticks apart. */
static int linear_ticks(chart_axis *a, double lo, double hi, int m, int e, int logpos)
{
    a->n = 0;
    double step = step_mul(1.0, m, e);
    if (!(step > 0.0) || !isfinite(step))
        return 0;
    double i0 = ceil(lo / step - TOL), i1 = floor(hi / step + TOL);
    if (!isfinite(i0) || !isfinite(i1))
        return 0;
    if (i1 < i0)
        return 1; /* no tick falls in the range: fine, just bare */
    if (i1 - i0 >= CHART_MAX_TICKS)
        return 0;
    int cnt = (int)(i1 - i0) + 1;
    double vals[CHART_MAX_TICKS], vmax = 0.0;
    for (int k = 0; k < cnt; k++) {
        vals[k] = step_mul(i0 + k, m, e);
        if (!isfinite(vals[k]) || (k > 0 && !(vals[k] > vals[k - 1])))
            return 0;
        if (fabs(vals[k]) > vmax)
            vmax = fabs(vals[k]);
    }
    for (int k = 0; k < cnt; k++) {
        double t = vals[k];
        if (logpos) {
            if (!(t > 0.0))
                continue;
            t = log10(t);
        }
        a->t[a->n] = t;
        isk__chart_format_linear(a->label[a->n], CHART_LABEL_MAX, vals[k], e, vmax);
        a->n++;
    }
    return 1;
}

/* Linear ticks over [lo, hi] (values), widening the axis to whole steps
 * when fitted.  For a log axis's fallback, logpos places ticks at log10(v)
 * and a->tlo/thi stay as they are. */
static void choose_linear(chart_axis *a, int fitted, double lo, double hi, int len, int horizontal,
                          const label_text *lt, int logpos)
{
    int pref = horizontal ? PREF_X * lt->cw / ISK_FONT_CELL_W : PREF_Y * lt->chh / ISK_FONT_CELL_H;
    double nmax = len / pref < 2 ? 2.0 : (double)(len / pref);
    double raw = (hi * 0.5 - lo * 0.5) / nmax * 2.0;
    a->n = 0;
    if (!(raw > 0.0) || !isfinite(raw))
        raw = !(raw > 0.0) ? DBL_MIN : DBL_MAX / 4.0;
    int m, e;
    nice_ceil(raw, &m, &e);
    for (int tries = 0; tries < MAX_STEP_TRIES; tries++, next_step(&m, &e)) {
        if (fitted) {
            double step = step_mul(1.0, m, e);
            double flo = step_mul(floor(lo / step + TOL), m, e);
            double fhi = step_mul(ceil(hi / step - TOL), m, e);
            a->tlo = isfinite(flo) ? flo : lo;
            a->thi = isfinite(fhi) ? fhi : hi;
            if (!(a->tlo < a->thi)) {
                a->tlo = lo;
                a->thi = hi;
            }
        }
        if (!linear_ticks(a, fitted ? a->tlo : lo, fitted ? a->thi : hi, m, e, logpos))
            continue;
        if (labels_fit(a, len, horizontal, lt))
            return;
        /* Past ten times the data's span, wider steps only squeeze the
         * data into a sliver of the plot (and across zero they never get
         * fewer than three ticks): better no labels than a useless range. */
        if (fitted && step_mul(0.05, m, e) >= hi * 0.5 - lo * 0.5)
            break;
    }
    a->n = 0;
    if (fitted) {
        a->tlo = lo;
        a->thi = hi;
    }
}

static const int decade_steps[] = {1,   2,   3,   4,   5,   6,   10,  12,  15,  20,  25,  30,
                                   40,  50,  60,  100, 150, 200, 250, 300, 400, 500, 600, 1000};

/* Labels at every k-th decade; returns the count (0 also when none fit). */
static int choose_decades(chart_axis *a, int len, int horizontal, const label_text *lt)
{
    /* |t| <= ~330 for any positive double, so these are small integers. */
    double d0 = ceil(a->tlo - TOL), d1 = floor(a->thi + TOL);
    a->n = 0;
    a->decade_step = 0;
    if (d1 < d0)
        return 0;
    for (size_t s = 0; s < sizeof decade_steps / sizeof decade_steps[0]; s++) {
        int k = decade_steps[s];
        a->n = 0;
        int too_many = 0;
        for (int d = (int)d0; d <= (int)d1; d++) {
            if (d % k != 0)
                continue;
            if (a->n == CHART_MAX_TICKS) {
                too_many = 1;
                break;
            }
            a->t[a->n] = (double)d;
            snprintf(a->label[a->n], CHART_LABEL_MAX, "1e%d", d);
            a->n++;
        }
        if (!too_many && labels_fit(a, len, horizontal, lt)) {
            a->decade_step = k;
            return a->n;
        }
    }
    a->n = 0;
    return 0;
}

/* Labels at m * 10^d for every m in ms; returns the count, 0 when they do
 * not fit.  Only called for axes spanning a few decades. */
static int choose_mantissas(chart_axis *a, const int *ms, int nm, int len, int horizontal,
                            const label_text *lt)
{
    a->n = 0;
    for (double d = floor(a->tlo); d <= ceil(a->thi); d += 1.0)
        for (int i = 0; i < nm; i++) {
            double t = d + log10((double)ms[i]);
            if (t < a->tlo - TOL || t > a->thi + TOL)
                continue;
            if (a->n == CHART_MAX_TICKS)
                return a->n = 0;
            a->t[a->n] = t;
            snprintf(a->label[a->n], CHART_LABEL_MAX, "%de%d", ms[i], (int)d);
            a->n++;
        }
    if (!labels_fit(a, len, horizontal, lt))
        a->n = 0;
    return a->n;
}

static void setup_log(chart_axis *a, int fitted, double dmin, double dmax, int len, int horizontal,
                      const label_text *lt)
{
    if (fitted) {
        a->tlo = floor(dmin + TOL);
        a->thi = ceil(dmax - TOL);
        if (!(a->tlo < a->thi)) { /* all on one decade: show it in the middle */
            a->tlo = floor(dmin + TOL) - 1.0;
            a->thi = a->tlo + 2.0;
        }
    }
    int ndec = choose_decades(a, len, horizontal, lt);
    if (ndec > 3 || a->decade_step > 1)
        return;
    /* A few wide decades: label 2..9, or 2 and 5, times each power too. */
    static const int all[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9}, few[3] = {1, 2, 5};
    chart_axis alt = *a;
    if (a->thi - a->tlo < 40.0 && (choose_mantissas(&alt, all, 9, len, horizontal, lt) > ndec ||
                                   choose_mantissas(&alt, few, 3, len, horizontal, lt) > ndec)) {
        alt.decade_step = 1;
        *a = alt;
        ndec = a->n;
    }
    if (ndec >= 2)
        return;
    /* Within one decade: 1-2-5 steps of the values ("2.2", "2.4"). */
    alt = *a;
    double lo = pow(10.0, a->tlo), hi = pow(10.0, a->thi);
    if (lo > 0.0 && isfinite(hi) && lo < hi) {
        choose_linear(&alt, 0, lo, hi, len, horizontal, lt, 1);
        if (alt.n > a->n) {
            alt.decade_step = 0;
            *a = alt;
        }
    }
}

void isk__chart_axis_setup(chart_axis *a, int fitted, double dmin, double dmax, int len, int horizontal,
                      isk_font font, int scale)
{
    const isk_font_metrics *m = isk_font_metrics_of(font);
    if (!m) /* the chart checked its font: only a caller of this file's own can get here */
        m = isk_font_metrics_of(font = ISK_FONT_5X8);
    const label_text lt = {font, scale, m->cell_w * scale, m->cell_h * scale};
    if (len < 1)
        len = 1;
    a->n = 0;
    a->decade_step = 0;
    if (a->log) {
        setup_log(a, fitted, dmin, dmax, len, horizontal, &lt);
        return;
    }
    if (fitted && !(dmin < dmax)) {
        /* One value: widen by 10% of it (or to -1..1 around 0 or a
         * subnormal), clamped so the ends stay finite. */
        double v = dmin, d = fabs(v) * 0.1;
        if (d < DBL_MIN) {
            dmin = v - 1.0;
            dmax = v + 1.0;
        } else {
            dmin = v - d < -DBL_MAX ? -DBL_MAX : v - d;
            dmax = v + d > DBL_MAX ? DBL_MAX : v + d;
        }
    }
    if (!fitted) {
        dmin = a->tlo;
        dmax = a->thi;
    }
    choose_linear(a, fitted, dmin, dmax, len, horizontal, &lt, 0);
}
