/* SPDX-License-Identifier: MIT */
/* The shadow run (play_shadow.h): a reference copy of the running scene,
 * integrated finer, stepped beside it; each particle's distance from its
 * reference in pixels, as ghosts on the canvas and as a chart of the
 * median and the 99th percentile over time, with what the reference costs
 * against the scene's own stepping. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/chart.h"
#include "iskra/draw.h"
#include "iskra/limits.h"
#include "iskra/snapshot.h"
#include "iskra/text.h"
#include "play_shadow.h"
#include "progress.h"

#define SHADOW_HISTORY PLAY_HISTORY
#define SHADOW_LINES 9

typedef struct play_shadow {
    isk_effect *fx;            /* the reference run */
    isk_integrator integrator; /* what it integrates with (the rule: rule_for) */
    char why[96];              /* the rule's reason, for the canvas */
    int clamped;               /* 1: factor x substeps passed the limit */
    unsigned long edits_seen;  /* the running scene's isk_effect_edits the reference has followed */
    long since;                /* the running scene's frame when the reference started */
    long *diverged;            /* per emitter: the frame its counts first differed, or -1 */
    int nemitters;
    double *px;                /* this frame's errors, one per paired particle */
    size_t px_cap;
    play_shadow_error last;
    double main_s, shadow_s;   /* seconds per step, smoothed */
    int timed;
    /* the chart: error over time, thinned as the energy chart's history */
    int n;
    double t[SHADOW_HISTORY], median[SHADOW_HISTORY], p99[SHADOW_HISTORY];
    isk_canvas chart;
    int chart_drawn_n;
} play_shadow;

static int by_value(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double rank(const double *sorted, size_t n, double q)
{
    size_t k = (size_t)ceil(q * (double)n);
    return sorted[k > 0 ? (k <= n ? k - 1 : n - 1) : 0];
}

play_shadow_error play_shadow_error_of(double *px, size_t n)
{
    play_shadow_error e = {0, 0, 0, n};
    if (n == 0)
        return e;
    qsort(px, n, sizeof *px, by_value);
    e.median = rank(px, n, 0.5);
    e.p99 = rank(px, n, 0.99);
    e.max = px[n - 1];
    return e;
}

play_shadow_error play_shadow_last(const player *p)
{
    play_shadow_error none = {0, 0, 0, 0};
    return p->shadow ? p->shadow->last : none;
}

/* The rule: RK4 where a force or a boundary is not smooth (a wall or a
 * deflector reflects, turbulence is gradient noise, a potential's minimum
 * distance clamps and its maximum switches it off): Yoshida-4's higher
 * order needs smooth forces across each step, RK4 is the robust fourth
 * order.  Yoshida-4 otherwise (symplectic: no energy drift of its own). */
static isk_integrator rule_for(const isk_effect_def *d, char *why, size_t n)
{
    int walls = d->bounds.sides != 0, deflectors = d->ndeflectors > 0, turbulence = 0, limited = 0;
    for (int i = 0; i < d->nforces; i++) {
        const isk_force_def *f = &d->forces[i];
        turbulence |= f->kind == ISK_FORCE_TURBULENCE && f->strength != 0;
        limited |= f->kind == ISK_FORCE_POTENTIAL && (f->pot.min_dist > 0 || f->pot.max_dist > 0);
    }
    if (!(walls || deflectors || turbulence || limited)) {
        snprintf(why, n, "smooth forces");
        return ISK_INTEGRATE_YOSHIDA4;
    }
    const char *const what[4] = {walls ? "walls" : NULL, deflectors ? "deflectors" : NULL,
                                 turbulence ? "turbulence" : NULL, limited ? "limited potentials" : NULL};
    size_t used = (size_t)snprintf(why, n, "not smooth:");
    for (int i = 0, k = 0; i < 4; i++)
        if (what[i] && used < n)
            used += (size_t)snprintf(why + used, n - used, "%s %s", k++ ? "," : "", what[i]);
    return ISK_INTEGRATE_RK4;
}

static void say_off(player *p, const char *what, const char *message)
{
    play_say(p, "shadow off: %s: %s", what, message);
    play_shadow_free(p);
    p->shadow_wanted = 0;
}

static int factor_of(const player *p) { return p->shadow_factor > 0 ? p->shadow_factor : PLAY_SHADOW_FACTOR; }

/* factor x n substeps, at most ISK_SUBSTEPS_MAX (noted). */
static int finer(play_shadow *s, int factor, int n)
{
    if ((long)factor * n <= ISK_SUBSTEPS_MAX)
        return factor * n;
    s->clamped = 1;
    return ISK_SUBSTEPS_MAX;
}

/* The reference's integrator and substeps, from the running scene's:
 * every emitter that has its own gets its own again. */
static int apply_settings(player *p)
{
    play_shadow *s = p->shadow;
    const isk_effect_def *d = isk_effect_definition(p->fx);
    const int factor = factor_of(p);
    isk_error err;
    char v[32], sec[ISK_NAME_MAX + 16];
    s->integrator = rule_for(d, s->why, sizeof s->why);
    s->clamped = 0;
    const char *method = isk_integrator_names[s->integrator];
    snprintf(v, sizeof v, "%d", finer(s, factor, d->substeps));
    if (isk_effect_set(s->fx, "scene", "integrator", method, &err) != ISK_OK ||
        isk_effect_set(s->fx, "scene", "substeps", v, &err) != ISK_OK) {
        say_off(p, "the reference's integration", err.message);
        return -1;
    }
    for (int i = 0; i < d->nemitters; i++) {
        const isk_emitter_motion *m = &d->emitters[i].motion;
        snprintf(sec, sizeof sec, "emitter %s", d->emitters[i].name);
        if (m->substeps > 0)
            snprintf(v, sizeof v, "%d", finer(s, factor, m->substeps));
        else
            snprintf(v, sizeof v, "scene");
        if (isk_effect_set(s->fx, sec, "integrator", m->integrator == ISK_INTEGRATE_INHERIT ? "scene" : method,
                           &err) != ISK_OK ||
            isk_effect_set(s->fx, sec, "substeps", v, &err) != ISK_OK) {
            say_off(p, "the reference's integration", err.message);
            return -1;
        }
    }
    return 0;
}

void play_shadow_free(player *p)
{
    play_shadow *s = p->shadow;
    if (!s)
        return;
    isk_effect_destroy(s->fx);
    isk_canvas_free(&s->chart);
    free(s->diverged);
    free(s->px);
    free(s);
    p->shadow = NULL;
}

void play_shadow_report(const player *p, FILE *f)
{
    const play_shadow *s = p->shadow;
    if (!s)
        return;
    char cap[40] = "";
    if (s->clamped)
        snprintf(cap, sizeof cap, ", capped at %d", ISK_SUBSTEPS_MAX);
    fprintf(f, "iskra play: shadow at frame %ld (%s at %dx the substeps%s): median %.9g px, p99 %.9g px, "
               "max %.9g px; %zu of %zu particles compared from frame %ld\n",
            isk_effect_frame(p->fx), isk_integrator_names[s->integrator], factor_of(p), cap, s->last.median, s->last.p99, s->last.max, s->last.compared,
            isk_effect_particle_count(p->fx), s->since);
}

void play_shadow_restart(player *p)
{
    if (!p->shadow_wanted) {
        play_shadow_free(p);
        return;
    }
    isk_error err;
    if (!p->shadow) {
        play_shadow *s = calloc(1, sizeof *s);
        if (!s) {
            say_off(p, "the reference", "out of memory");
            return;
        }
        if (isk_effect_create(&s->fx, isk_effect_definition(p->fx), &err) != ISK_OK) {
            free(s);
            say_off(p, "the reference", err.message);
            return;
        }
        p->shadow = s;
    }
    play_shadow *s = p->shadow;
    isk_snapshot *snap = NULL;
    if (isk_effect_snapshot(p->fx, &snap, &err) != ISK_OK || isk_effect_restore(s->fx, snap, &err) != ISK_OK) {
        isk_snapshot_free(snap);
        say_off(p, "the reference", err.message);
        return;
    }
    isk_snapshot_free(snap);
    if (apply_settings(p) != 0)
        return;
    const int ne = isk_effect_emitter_count(p->fx);
    long *dv = realloc(s->diverged, (size_t)(ne > 0 ? ne : 1) * sizeof *dv);
    if (!dv) {
        say_off(p, "the reference", "out of memory");
        return;
    }
    s->diverged = dv;
    s->nemitters = ne;
    for (int i = 0; i < ne; i++)
        dv[i] = -1;
    s->edits_seen = isk_effect_edits(p->fx);
    s->since = isk_effect_frame(p->fx);
    s->n = 0;
    s->chart_drawn_n = -1;
    s->last = (play_shadow_error){0, 0, 0, 0};
    play_shadow_measure(p);
}

void play_shadow_toggle(player *p)
{
    p->shadow_wanted = !p->shadow_wanted;
    play_shadow_restart(p);
    if (p->shadow)
        play_say(p, "shadow on: %s at %dx the substeps beside the scene (G: off)",
                 isk_integrator_names[p->shadow->integrator], factor_of(p));
    else if (!p->shadow_wanted)
        play_say(p, "shadow off");
}

/* An edit of the running scene that no hook followed (a new control that
 * calls the library directly): the reference starts again from the
 * running scene rather than drift from it unseen. */
static int followed(player *p)
{
    if (isk_effect_edits(p->fx) == p->shadow->edits_seen)
        return 1;
    play_say(p, "shadow: started again from the running scene (an edit it could not follow)");
    play_shadow_restart(p);
    return 0;
}

double play_shadow_stepped(player *p, double main_seconds)
{
    if (!p->shadow || !followed(p))
        return 0.0;
    play_shadow *s = p->shadow;
    const double t0 = progress_now();
    isk_status st = isk_effect_step(s->fx);
    const double seconds = progress_now() - t0;
    if (st != ISK_OK) {
        say_off(p, "the reference's step", isk_status_str(st));
        return seconds;
    }
    /* main_seconds is the scene's step (with its render when it keeps trails) */
    s->main_s = s->timed ? 0.9 * s->main_s + 0.1 * main_seconds : main_seconds;
    s->shadow_s = s->timed ? 0.9 * s->shadow_s + 0.1 * seconds : seconds;
    s->timed = 1;
    return seconds;
}

static void push(play_shadow *s, double t, double median, double p99)
{
    if (s->n == SHADOW_HISTORY) { /* full: every other sample of the older half */
        int w = 0;
        for (int i = 0; i < SHADOW_HISTORY; i++)
            if (i >= SHADOW_HISTORY / 2 || i % 2 == 0) {
                s->t[w] = s->t[i];
                s->median[w] = s->median[i];
                s->p99[w] = s->p99[i];
                w++;
            }
        s->n = w;
    }
    s->t[s->n] = t;
    s->median[s->n] = median;
    s->p99[s->n] = p99;
    s->n++;
}

void play_shadow_measure(player *p)
{
    if (!p->shadow || !followed(p))
        return;
    play_shadow *s = p->shadow;
    const isk_view *view = isk_effect_view(p->fx);
    size_t need = isk_effect_particle_count(p->fx);
    if (need > s->px_cap) {
        double *px = realloc(s->px, need * sizeof *px);
        if (!px) {
            say_off(p, "the comparison", "out of memory");
            return;
        }
        s->px = px;
        s->px_cap = need;
    }
    size_t n = 0;
    for (int e = 0; e < s->nemitters; e++) {
        const isk_particles *a = isk_effect_particles(p->fx, e), *b = isk_effect_particles(s->fx, e);
        if (s->diverged[e] >= 0 || !a || !b)
            continue;
        if (a->count != b->count) { /* slots no longer pair the same particles */
            s->diverged[e] = isk_effect_frame(p->fx);
            continue;
        }
        for (size_t k = 0; k < a->count && n < s->px_cap; k++) {
            double ax, ay, bx, by;
            isk_view_to_screen(view, a->x[k], a->y[k], &ax, &ay);
            isk_view_to_screen(view, b->x[k], b->y[k], &bx, &by);
            const double d = hypot(ax - bx, ay - by);
            if (isfinite(d))
                s->px[n++] = d;
        }
    }
    s->last = play_shadow_error_of(s->px, n);
    if (n > 0) /* nothing compared is no error: a gap in the chart */
        push(s, isk_effect_time(p->fx), s->last.median, s->last.p99);
}

/* ---- the edits, followed -------------------------------------------------------------------- */

static int is_integration(const char *section, const char *key)
{
    return (!strcmp(section, "scene") || !strncmp(section, "emitter ", 8)) &&
           (!strcmp(key, "integrator") || !strcmp(key, "substeps"));
}

/* After the reference took an edit: the running scene's edits are followed
 * so far; an edit that changes the rule's choice (walls on, say) gives the
 * reference its integration again. */
static void took(player *p, isk_status st, const char *message, int integration)
{
    if (st != ISK_OK) {
        say_off(p, "the reference refused an edit the scene took", message);
        return;
    }
    char why[96];
    if (integration || rule_for(isk_effect_definition(p->fx), why, sizeof why) != p->shadow->integrator)
        if (apply_settings(p) != 0)
            return;
    p->shadow->edits_seen = isk_effect_edits(p->fx);
}

void play_shadow_set(player *p, const char *section, const char *key, const char *value)
{
    if (!p->shadow)
        return;
    isk_error err = {0};
    const int integration = is_integration(section, key);
    /* the reference keeps its own integrator and substeps: apply_settings gives them */
    isk_status st = integration ? ISK_OK : isk_effect_set(p->shadow->fx, section, key, value, &err);
    took(p, st, err.message, integration);
}

void play_shadow_click(player *p, double x, double y)
{
    if (p->shadow)
        took(p, isk_effect_click(p->shadow->fx, x, y), "the click", 0);
}

void play_shadow_move(player *p, const char *section, double x, double y)
{
    isk_error err = {0};
    if (p->shadow)
        took(p, isk_effect_move(p->shadow->fx, section, x, y, &err), err.message, 0);
}

void play_shadow_add_potential(player *p, const char *name, const isk_potential *pot)
{
    isk_error err = {0};
    if (p->shadow)
        took(p, isk_effect_add_potential(p->shadow->fx, name, pot, &err), err.message, 0);
}

void play_shadow_remove_force(player *p, const char *name)
{
    isk_error err = {0};
    if (p->shadow)
        took(p, isk_effect_remove_force(p->shadow->fx, name, &err), err.message, 0);
}

/* ---- over the canvas ------------------------------------------------------------------------ */

/* The ghosts' colours by error in pixels: below 0.5 px the eye sees no
 * difference, 2 px is a dot's width, 8 px is plainly somewhere else. */
static const struct {
    double below;
    isk_color colour;
    const char *label;
} bands[] = {
    {0.5, {0x00, 0x9e, 0x73, 110}, "<0.5"},
    {2, {0xf0, 0xe4, 0x42, 120}, "<2"},
    {8, {0xe6, 0x9f, 0x00, 140}, "<8"},
    {INFINITY, {0xd5, 0x5e, 0x00, 170}, ">=8 px"},
};
enum { NBANDS = (int)(sizeof bands / sizeof bands[0]) };

static isk_color colour_of(double px)
{
    int i = 0;
    while (i < NBANDS - 1 && !(px < bands[i].below))
        i++;
    return bands[i].colour;
}

/* Each compared reference particle as a faint 3x3 square at its place,
 * coloured by how far the running scene's particle is from it. */
static void ghosts(player *p, isk_canvas *v)
{
    play_shadow *s = p->shadow;
    const isk_view *view = isk_effect_view(p->fx);
    for (int e = 0; e < s->nemitters; e++) {
        const isk_particles *a = isk_effect_particles(p->fx, e), *b = isk_effect_particles(s->fx, e);
        if (s->diverged[e] >= 0 || !a || !b || a->count != b->count)
            continue;
        for (size_t k = 0; k < b->count; k++) {
            double ax, ay, bx, by;
            isk_view_to_screen(view, a->x[k], a->y[k], &ax, &ay);
            isk_view_to_screen(view, b->x[k], b->y[k], &bx, &by);
            if (!(bx > -2 && by > -2 && bx < v->width + 2 && by < v->height + 2))
                continue; /* also NaN: nothing to place */
            isk_fill_rect(v, (int)floor(bx) - 1, (int)floor(by) - 1, 3, 3, colour_of(hypot(ax - bx, ay - by)),
                          ISK_BLEND_OVER);
        }
    }
}

static void chart_of(player *p, isk_canvas *c)
{
    play_shadow *s = p->shadow;
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.background = p->ui.style.panel;
    ch.ink = p->ui.style.label;
    ch.grid = p->ui.style.box;
    ch.x_label = "simulated seconds";
    ch.y_label = "error, px";
    ch.y_log = 1; /* errors grow by decades; the median and the tail differ by as much */
    ch.legend = ISK_LEGEND_ABOVE;
    isk_chart_series lines[2] = {
        {"median", s->t, s->median, (size_t)s->n, {bands[0].colour, ISK_DASH_SOLID, ISK_MARKER_NONE}},
        {"99th percentile", s->t, s->p99, (size_t)s->n, {bands[3].colour, ISK_DASH_SOLID, ISK_MARKER_NONE}},
    };
    lines[0].style.color.a = lines[1].style.color.a = 255;
    ch.series = lines;
    ch.nseries = 2;
    int above_zero = 0;
    for (int i = 0; i < s->n; i++)
        above_zero |= s->p99[i] > 0;
    if (s->n < 2 || !above_zero || isk_chart_draw(&ch, c) != ISK_OK) {
        isk_canvas_fill(c, p->ui.style.panel);
        isk_font_draw_text(c, ISK_FONT_6X13, 8, 8,
                           s->n < 2 ? "error over time: when it runs" : "error: exactly 0 px so far", 1,
                           p->ui.style.label, ISK_BLEND_OVER);
    }
}

/* What the reference is, its error now, its cost, what is not compared. */
static int text_lines(player *p, char lines[SHADOW_LINES][160])
{
    play_shadow *s = p->shadow;
    const isk_effect_def *d = isk_effect_definition(p->fx);
    int n = 0;
    snprintf(lines[n++], 160, "shadow: %s at %dx the substeps%s", isk_integrator_names[s->integrator],
             factor_of(p), s->clamped ? ", capped" : "");
    snprintf(lines[n++], 160, "  (%s)", s->why);
    if (s->last.compared)
        snprintf(lines[n++], 160, "median %.3g px, p99 %.3g px, max %.3g px", s->last.median, s->last.p99,
                 s->last.max);
    else
        snprintf(lines[n++], 160, "error: no particle to compare");
    snprintf(lines[n++], 160, "%zu of %zu compared, from frame %ld", s->last.compared,
             isk_effect_particle_count(p->fx), s->since);
    if (p->fixed_clock)
        snprintf(lines[n++], 160, "cost: not timed (--fixed-clock)");
    else if (s->timed && s->main_s > 0)
        snprintf(lines[n++], 160, "cost: %.3gx the scene's own step", s->shadow_s / s->main_s);
    else
        snprintf(lines[n++], 160, "cost: when it runs");
    for (int e = 0; e < s->nemitters && n < SHADOW_LINES - 1; e++)
        if (s->diverged[e] >= 0)
            snprintf(lines[n++], 160, "%.20s: counts differ at %ld: not compared", d->emitters[e].name,
                     s->diverged[e]);
    lines[n++][0] = 0; /* the legend's row */
    return n;
}

void play_shadow_draw(player *p)
{
    if (!p->shadow)
        return;
    play_shadow *s = p->shadow;
    isk_canvas v;
    const play_layout *l = &p->lay;
    if (isk_canvas_view(&v, p->shown, l->canvas.x, l->canvas.y, l->canvas.w, l->canvas.h) != ISK_OK)
        return;
    ghosts(p, &v);
    /* At the canvas's top right: the text, the ghosts' legend, the chart. */
    const isk_font f = ISK_FONT_6X13;
    const int lh = isk_font_text_height(f, "X", 1) + 2, pad = 4;
    char lines[SHADOW_LINES][160];
    const int n = text_lines(p, lines);
    /* Half the canvas's width at its top right; a narrow canvas gives all
     * its width, at its foot (the HUD has the top left). */
    int w = v.width / 2 < 240 ? v.width : v.width / 2 > 420 ? 420 : v.width / 2;
    int ch_h = w * 11 / 20 >= 120 ? w * 11 / 20 : 120;
    const int x = v.width - w, text_h = n * lh + 2 * pad;
    if (text_h + ch_h > v.height)
        ch_h = 0; /* no room for the chart */
    const int y0 = w == v.width ? v.height - text_h - ch_h : 0;
    isk_fill_rect(&v, x, y0, w, text_h, isk_rgba(0, 0, 0, 200), ISK_BLEND_OVER);
    for (int i = 0; i < n - 1; i++)
        isk_font_draw_text(&v, f, x + pad, y0 + pad + i * lh, lines[i], 1, ISK_WHITE, ISK_BLEND_OVER);
    int lx = x + pad, ly = y0 + pad + (n - 1) * lh;
    isk_font_draw_text(&v, f, lx, ly, "ghosts:", 1, ISK_WHITE, ISK_BLEND_OVER);
    lx += isk_font_text_width(f, "ghosts: ", 1);
    for (int i = 0; i < NBANDS; i++) {
        isk_color c = bands[i].colour;
        c.a = 255;
        isk_fill_rect(&v, lx, ly + 2, 7, 7, c, ISK_BLEND_OVER);
        isk_font_draw_text(&v, f, lx + 10, ly, bands[i].label, 1, ISK_WHITE, ISK_BLEND_OVER);
        lx += 10 + isk_font_text_width(f, bands[i].label, 1) + 8;
    }
    if (ch_h < 120 || w < 160)
        return; /* the chart needs 160 x 120 */
    if (s->chart.width != w || s->chart.height != ch_h) {
        isk_canvas_free(&s->chart);
        if (isk_canvas_init(&s->chart, w, ch_h) != ISK_OK)
            return;
        s->chart_drawn_n = -1;
    }
    /* Drawn again as the energy chart is: every frame for the first 30
     * samples, then every 30 shown frames (by count: scripts see the same). */
    if (s->chart_drawn_n < 0 || s->n < s->chart_drawn_n ||
        (s->n != s->chart_drawn_n && (p->frames_shown % 30 == 0 || s->n < 30))) {
        chart_of(p, &s->chart);
        s->chart_drawn_n = s->n;
    }
    for (int y = 0; y < ch_h; y++)
        memcpy(isk_canvas_at(&v, x, y0 + text_h + y), isk_canvas_at(&s->chart, 0, y), (size_t)w * 4);
}
