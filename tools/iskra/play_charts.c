/* SPDX-License-Identifier: MIT */
/* The simulator's live charts (iskra/chart.h): kinetic, potential and total
 * energy over time, and the number of particles; and the integrator table,
 * which puts each integrator's measured cost (ns per particle-step, the
 * stepping alone) beside the energy drift it showed, so what accuracy costs
 * in time can be seen while it runs.  The drift is the relative change of
 * the total energy since the integrator took over (or since the particles
 * last changed: a click, a reset); drag and walls change the energy too. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "iskra/chart.h"
#include "iskra/keys.h"
#include "play.h"

void play_charts_reset(player *p)
{
    p->hist.n = 0;
    p->energy_ref_valid = 0;
    p->chart_drawn_n = -1;
    play_probes_reset(p);
}

static void push(play_history *h, double t, double ke, double pe, double count)
{
    if (h->n == PLAY_HISTORY) {
        /* Full: keep every other sample of the older half, so the chart
         * still starts at the beginning but holds a bounded number of points. */
        int w = 0;
        for (int i = 0; i < PLAY_HISTORY; i++)
            if (i >= PLAY_HISTORY / 2 || i % 2 == 0) {
                h->t[w] = h->t[i];
                h->kinetic[w] = h->kinetic[i];
                h->potential[w] = h->potential[i];
                h->total[w] = h->total[i];
                h->count[w] = h->count[i];
                w++;
            }
        h->n = w;
    }
    h->t[h->n] = t;
    h->kinetic[h->n] = ke;
    h->potential[h->n] = pe;
    h->total[h->n] = ke + pe;
    h->count[h->n] = count;
    h->n++;
}

void play_charts_sample(player *p, double seconds_per_particle_step, long particle_steps)
{
    const isk_effect_def *d = isk_effect_definition(p->fx);
    play_energy e = play_energy_of(p->fx);
    const double pe = e.potential, total = e.kinetic + pe;
    const size_t count = isk_effect_particle_count(p->fx);
    push(&p->hist, isk_effect_time(p->fx), e.kinetic, pe, (double)count);
    play_probes_sample(p);
    play_integrator_stats *st = &p->stats[d->integrator];
    if (!p->fixed_clock && particle_steps > 0) {
        double ns = seconds_per_particle_step * 1e9;
        st->ns = st->have_ns ? 0.9 * st->ns + 0.1 * ns : ns;
        st->have_ns = 1;
    }
    if (!p->energy_ref_valid || count != p->count_ref || p->ref_integrator != (int)d->integrator) {
        p->energy_ref = total;
        /* The size of the energies in play: a total near 0 (kinetic and
         * potential cancelling) must not make every change look huge. */
        p->energy_scale = fabs(total) > e.kinetic + fabs(pe) ? fabs(total) : e.kinetic + fabs(pe);
        p->count_ref = count;
        p->ref_integrator = (int)d->integrator;
        p->energy_ref_valid = 1;
        return;
    }
    if (count > 0 && isfinite(total)) {
        double scale = p->energy_scale > 0 ? p->energy_scale : 1.0;
        st->drift = (total - p->energy_ref) / scale;
        st->have_drift = 1;
    }
}

void play_chart_look(isk_chart *ch, const player *p)
{
    isk_chart_defaults(ch);
    ch->font = ISK_FONT_6X13; /* capitals 10 px tall, as the panel's: read from across a classroom */
    ch->background = p->ui.style.panel;
    ch->ink = p->ui.style.label;
    ch->grid = p->ui.style.box;
}

/* At most this many points per line (play_chart_points): the exact-area
 * strokes cost in proportion to pixels times points, and a chart column is
 * a few hundred pixels wide. */
#define CHART_POINTS ((int)(sizeof ((play_chart_points *)0)->t / sizeof(double)))

static void keep(const play_history *h, int j, play_chart_points *o)
{
    if ((int)o->n >= CHART_POINTS || (o->n && o->t[o->n - 1] == h->t[j] && o->v[3][o->n - 1] == h->count[j]))
        return;
    o->t[o->n] = h->t[j];
    o->v[0][o->n] = h->kinetic[j];
    o->v[1][o->n] = h->potential[j];
    o->v[2][o->n] = h->total[j];
    o->v[3][o->n] = h->count[j];
    o->n++;
}

/* Every k-th sample, k chosen so that about CHART_POINTS / 2 remain, and
 * both sides of every change of the particle count (a click shows as a
 * step, not a ramp), and the last. */
static void thin(const play_history *h, play_chart_points *o)
{
    const int k = h->n > CHART_POINTS / 2 ? (2 * h->n + CHART_POINTS - 1) / CHART_POINTS : 1;
    o->n = 0;
    for (int i = 0; i < h->n; i++) {
        if (i + 1 < h->n && h->count[i + 1] != h->count[i]) {
            keep(h, i, o);
            keep(h, i + 1, o);
        } else if (i % k == 0 || i == h->n - 1) {
            keep(h, i, o);
        }
    }
}

void play_chart_into(player *p, isk_canvas *c, isk_ui_rect r, const isk_chart *ch, const char *empty)
{
    isk_canvas v;
    if (isk_canvas_view(&v, c, r.x, r.y, r.w, r.h) == ISK_OK && v.width >= 160 && v.height >= 120 &&
        isk_chart_draw(ch, &v) == ISK_OK)
        return;
    /* No data yet (or no room): a box saying so, in the widgets' colours. */
    isk_ui tmp;
    isk_ui_init(&tmp, p->ui.scale);
    tmp.style = p->ui.style;
    tmp.font = p->ui.font;
    isk_ui_begin(&tmp, c);
    isk_ui_box(&tmp, r);
    isk_ui_label(&tmp, r, empty, ISK_UI_CENTER);
    isk_ui_end(&tmp);
}

/* The two charts' arrangement.  Side by side when each gets at least
 * SIDE_MIN_W pixels across (or the caller asks for it): each then has its
 * own x axis.  Stacked otherwise, the particle count's chart at the bottom
 * with PARTICLES_MIN_H pixels or nearly half: both plot the same times, so
 * the x label under the lower chart serves both, and the energy chart
 * above uses the height the label would take.  Either way the quantity is
 * the y label (turned, beside the plot, where height is scarcer than
 * width) and the energy legend stands in rows over the plot, where it
 * hides no data. */
enum { SIDE_MIN_W = 200, PARTICLES_MIN_H = 120 };

static void render_charts(player *p, isk_canvas *c, int side_by_side)
{
    play_chart_points *t = &p->chart_points;
    thin(&p->hist, t);
    isk_canvas_fill(c, p->ui.style.panel);
    isk_ui_rect r = {0, 0, c->width, c->height};
    const int gap = isk_ui_px(&p->ui, 4);
    side_by_side = side_by_side || (r.w - gap) / 2 >= SIDE_MIN_W;
    int lower_h = r.h * 9 / 20 > PARTICLES_MIN_H ? r.h * 9 / 20 : PARTICLES_MIN_H;
    isk_ui_rect top = side_by_side ? isk_ui_cut_left(&r, (r.w - gap) / 2) : isk_ui_cut_top(&r, r.h - gap - lower_h);
    if (side_by_side)
        isk_ui_cut_left(&r, gap);
    else
        isk_ui_cut_top(&r, gap);
    isk_chart ch;
    play_chart_look(&ch, p);
    static const isk_color colours[3] = {{0x56, 0xb4, 0xe9, 255}, {0xe6, 0x9f, 0x00, 255}, {0xf0, 0xf0, 0xf0, 255}};
    isk_chart_series s[3] = {
        {"kinetic", t->t, t->v[0], t->n, {colours[0], ISK_DASH_SOLID, ISK_MARKER_NONE}},
        {"potential", t->t, t->v[1], t->n, {colours[1], ISK_DASH_DASHED, ISK_MARKER_NONE}},
        {"total", t->t, t->v[2], t->n, {colours[2], ISK_DASH_SOLID, ISK_MARKER_NONE}},
    };
    static const char *const seconds = "simulated seconds";
    ch.y_label = "energy";
    ch.x_label = side_by_side ? seconds : NULL;
    ch.series = s;
    ch.nseries = 3;
    ch.legend = ISK_LEGEND_ABOVE;
    play_chart_into(p, c, top, &ch, t->n ? "energy: no range yet" : "energy: when it runs");
    if (p->probe_hist.nseries > 0) { /* the probes' chart beside (or under) the particle count's */
        isk_ui_rect pr = side_by_side ? isk_ui_cut_bottom(&r, (r.h - gap) / 2) : isk_ui_cut_right(&r, (r.w - gap) / 2);
        play_probes_chart(p, c, pr);
        if (side_by_side)
            isk_ui_cut_bottom(&r, gap);
        else
            isk_ui_cut_right(&r, gap);
    }
    play_chart_look(&ch, p);
    isk_chart_series n = {NULL, t->t, t->v[3], t->n, {colours[0], ISK_DASH_SOLID, ISK_MARKER_NONE}};
    ch.y_label = "particles";
    ch.x_label = seconds;
    ch.series = &n;
    ch.nseries = 1;
    ch.legend = ISK_LEGEND_NONE;
    play_chart_into(p, c, r, &ch, "particles: when it runs");
}

void play_charts_draw(player *p, isk_ui_rect r, int side_by_side)
{
    isk_canvas *cache = &p->chart_cache;
    if (r.w <= 0 || r.h <= 0 || !p->shown || r.x + r.w > p->shown->width || r.y + r.h > p->shown->height)
        return;
    /* Drawn again twice a second at 60 frames per second (by frame count,
     * so a script's frames are the same), every frame for the first 30
     * samples, and whenever the samples start over. */
    if (cache->width != r.w || cache->height != r.h) {
        isk_canvas_free(cache);
        if (isk_canvas_init(cache, r.w, r.h) != ISK_OK)
            return;
        p->chart_drawn_n = -1;
    }
    const int n = p->hist.n;
    if (p->chart_drawn_n < 0 || n < p->chart_drawn_n ||
        (n != p->chart_drawn_n && (p->frames_shown % 30 == 0 || n < 30))) {
        render_charts(p, cache, side_by_side);
        p->chart_drawn_n = n;
    }
    for (int y = 0; y < r.h; y++)
        memcpy(isk_canvas_at(p->shown, r.x, r.y + y), isk_canvas_at(cache, 0, y), (size_t)r.w * 4);
}

void play_integrators(player *p, isk_ui_rect r)
{
    isk_ui *ui = &p->ui;
    const isk_key *k = isk_key_find(ISK_SECTION_SCENE, "integrator");
    const char *names[ISK_INTEGRATOR_COUNT];
    int n = k ? k->nnames : 0;
    for (int i = 0; i < n && i < ISK_INTEGRATOR_COUNT; i++)
        names[i] = k->names[i];
    const int rh = isk_ui_row_height(ui);
    isk_ui_rect head = isk_ui_cut_top(&r, rh);
    isk_ui_rect table = isk_ui_cut_top(&r, rh * n);
    const int name_w = r.w * 9 / 20, cost_w = r.w * 5 / 20;
    isk_ui_rect hn = isk_ui_cut_left(&head, name_w), hc = isk_ui_cut_left(&head, cost_w);
    isk_ui_label(ui, hn, "Integrator", ISK_UI_LEFT);
    isk_ui_label(ui, hc, "ns", ISK_UI_RIGHT);
    isk_ui_label(ui, head, "drift", ISK_UI_RIGHT);
    int cur = (int)isk_effect_definition(p->fx)->integrator;
    if (isk_ui_radio(ui, "integrator", isk_ui_cut_left(&table, name_w), names, n, 1, &cur))
        play_set(p, "scene", "integrator", names[cur]);
    isk_ui_rect cost = isk_ui_cut_left(&table, cost_w);
    for (int i = 0; i < n; i++) {
        const play_integrator_stats *st = &p->stats[i];
        char a[32] = "-", b[32] = "-";
        if (st->have_ns)
            snprintf(a, sizeof a, "%.3g", st->ns);
        if (st->have_drift)
            snprintf(b, sizeof b, "%+.1e", st->drift);
        isk_ui_rect c = isk_ui_cell(cost, 1, n, 0, i, 0), d = isk_ui_cell(table, 1, n, 0, i, 0);
        isk_ui_label(ui, c, a, ISK_UI_RIGHT);
        isk_ui_label(ui, d, b, ISK_UI_RIGHT);
    }
}
