/* SPDX-License-Identifier: MIT */
/* The simulator's probe chart: a scene's probes (iskra/probes.h) over
 * simulated time, sampled with the energy chart (play_charts.c) and drawn
 * beside the particle count.  One line per number worth following: a
 * gate's forward and backward rates, a region's count.  A histogram is
 * drawn on the canvas itself and the totals' energy is the energy chart's
 * (isk_effect_energy), so neither has a line here.  A scene without such
 * probes has no series and no chart. */
#include <stdio.h>
#include <string.h>

#include "iskra/chart.h"
#include "iskra/probes.h"
#include "play.h"

/* At most this many points per line on the chart (as the energy chart's). */
#define PROBE_CHART_POINTS ((int)(sizeof ((play_probe_history *)0)->chart_t / sizeof(double)))

/* The numbers of reading r that are charted, into v (names into names);
 * how many. */
static int charted(const isk_probe_reading *r, double *v, char (*names)[48], int max)
{
    int n = 0;
#define ADD(label, value)                                                                                         \
    do {                                                                                                          \
        if (n < max) {                                                                                            \
            snprintf(names[n], sizeof names[n], "%s %s", r->name, label);                                         \
            v[n] = (value);                                                                                       \
        }                                                                                                         \
        n++;                                                                                                      \
    } while (0)
    switch (r->kind) {
    case ISK_PROBE_GATE:
        ADD("> /s", r->rate_forward);
        ADD("< /s", r->rate_backward);
        break;
    case ISK_PROBE_REGION: ADD("count", (double)r->count); break;
    default: break;
    }
#undef ADD
    return n;
}

void play_probes_reset(player *p)
{
    p->probe_hist.n = 0;
    p->probe_hist.nseries = 0;
}

void play_probes_sample(player *p)
{
    play_probe_history *h = &p->probe_hist;
    double v[PLAY_PROBE_SERIES];
    int ns = 0;
    for (int i = 0; i < isk_effect_probe_count(p->fx); i++) {
        isk_probe_reading r;
        if (isk_effect_probe_read(p->fx, i, &r) != ISK_OK || ns >= PLAY_PROBE_SERIES)
            continue;
        ns += charted(&r, v + ns, h->name + ns, PLAY_PROBE_SERIES - ns);
    }
    ns = ns < PLAY_PROBE_SERIES ? ns : PLAY_PROBE_SERIES;
    if (ns != h->nseries) /* another scene (a reload): start over */
        h->n = 0;
    h->nseries = ns;
    if (ns == 0)
        return;
    if (h->n == PLAY_HISTORY) { /* full: every other sample of the older half, as the energy chart */
        int w = 0;
        for (int i = 0; i < PLAY_HISTORY; i++)
            if (i >= PLAY_HISTORY / 2 || i % 2 == 0) {
                h->t[w] = h->t[i];
                for (int s = 0; s < ns; s++)
                    h->v[s][w] = h->v[s][i];
                w++;
            }
        h->n = w;
    }
    h->t[h->n] = isk_effect_time(p->fx);
    for (int s = 0; s < ns; s++)
        h->v[s][h->n] = v[s];
    h->n++;
}

void play_probes_chart(player *p, isk_canvas *c, isk_ui_rect r)
{
    play_probe_history *h = &p->probe_hist;
    static const isk_color colours[PLAY_PROBE_SERIES] = {
        {0x56, 0xb4, 0xe9, 255}, {0xe6, 0x9f, 0x00, 255}, {0x00, 0x9e, 0x73, 255}, {0xf0, 0xe4, 0x42, 255},
        {0xcc, 0x79, 0xa7, 255}, {0xd5, 0x5e, 0x00, 255}, {0x00, 0x72, 0xb2, 255}, {0xf0, 0xf0, 0xf0, 255}};
    /* every k-th sample and the last, at most PROBE_CHART_POINTS */
    double *t = h->chart_t;
    const int k = h->n > PROBE_CHART_POINTS ? (h->n + PROBE_CHART_POINTS - 2) / (PROBE_CHART_POINTS - 1) : 1;
    size_t m = 0;
    for (int i = 0; i < h->n && m < PROBE_CHART_POINTS; i++)
        if (i % k == 0 || i == h->n - 1) {
            t[m] = h->t[i];
            for (int s = 0; s < h->nseries; s++)
                h->chart_v[s][m] = h->v[s][i];
            m++;
        }
    isk_chart_series series[PLAY_PROBE_SERIES];
    for (int s = 0; s < h->nseries; s++)
        series[s] = (isk_chart_series){h->name[s], t, h->chart_v[s], m, {colours[s], ISK_DASH_SOLID, ISK_MARKER_NONE}};
    isk_chart ch;
    play_chart_look(&ch, p);
    ch.y_label = "probes";
    ch.x_label = "simulated seconds";
    ch.series = series;
    ch.nseries = h->nseries;
    ch.legend = ISK_LEGEND_ABOVE;
    play_chart_into(p, c, r, &ch, h->n ? "probes: no range yet" : "probes: when it runs");
}
