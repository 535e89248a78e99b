/* SPDX-License-Identifier: MIT */
/* Probes (iskra/probes.h): gates, regions, histograms and totals,
 * measured after every frame over their emitters' particles (every
 * emitter's unless `emitters` names some) and drawn over everything else.
 *
 * Nothing here runs for an effect without probes: e->probes is NULL, no
 * store keeps a position for them, the frame loop and the render skip
 * them with one test.  A gate needs where each particle was at the start
 * of the frame: the store's trail column holds it (its newest point is
 * the particle's position at the end of the last frame, or where it was
 * born, and it follows its particle through culls), so the store of every
 * emitter a gate measures keeps at least one trail point
 * (fx_group.keep_prev); only an
 * emitter's own `trail` draws one.  The crossing test is the deflectors'
 * (sim/crossing.h).  Everything is measured on the caller's thread in
 * group then particle order: the readings are the same on any number of
 * threads. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect_internal.h"
#include "iskra/draw.h"
#include "iskra/text.h"
#include "sim/crossing.h"

/* A gate's window in frames is fixed at create (at that frame length):
 * its rates are the crossings of those frames over their own lengths. */
#define FX_PROBE_MAX_WINDOW_FRAMES 100000

_Static_assert(ISK_EFFECT_MAX_EMITTERS <= 64, "a probe's emitters are the bits of a uint64_t");

/* The emitters probe q measures, as bits. */
static uint64_t emitter_bits(const isk_probe_def *q)
{
    if (q->nemitters <= 0)
        return ~(uint64_t)0;
    uint64_t bits = 0;
    for (int i = 0; i < q->nemitters && i < ISK_EFFECT_MAX_EMITTERS; i++)
        bits |= (uint64_t)1 << q->emitters[i];
    return bits;
}

int isk__fx_probes_need_prev(const isk_effect_def *d, int emitter)
{
    for (int i = 0; i < d->nprobes; i++)
        if (d->probes[i].kind == ISK_PROBE_GATE && (emitter_bits(&d->probes[i]) >> emitter & 1u))
            return 1;
    return 0;
}

static int window_frames(const isk_effect_def *d, const isk_probe_def *q)
{
    const double frames = ceil(q->window / (d->dt / d->speed_divisor) - 1e-9);
    return frames < 1 ? 1 : frames > FX_PROBE_MAX_WINDOW_FRAMES ? FX_PROBE_MAX_WINDOW_FRAMES : (int)frames;
}

isk_status isk__fx_probes_reset(isk_effect *e)
{
    const isk_effect_def *d = &e->def;
    if (d->nprobes == 0)
        return ISK_OK;
    if (!e->probes && !(e->probes = calloc((size_t)d->nprobes, sizeof *e->probes)))
        return ISK_ERR_NOMEM;
    for (int i = 0; i < d->nprobes; i++) {
        fx_probe *p = &e->probes[i];
        const isk_probe_def *q = &d->probes[i];
        memset(&p->r, 0, sizeof p->r);
        p->r.name = q->name;
        p->r.kind = q->kind;
        p->r.bins = q->kind == ISK_PROBE_HISTOGRAM ? q->bins : 0;
        p->emitters = emitter_bits(q);
        p->ring_head = p->ring_used = 0;
        if (q->kind != ISK_PROBE_GATE || p->ring)
            continue;
        p->ring_n = window_frames(d, q);
        p->ring = calloc((size_t)p->ring_n * 2, sizeof *p->ring);
        p->ring_t = calloc((size_t)p->ring_n, sizeof *p->ring_t);
        if (!p->ring || !p->ring_t)
            return ISK_ERR_NOMEM;
    }
    return ISK_OK;
}

void isk__fx_probes_free(isk_effect *e)
{
    for (int i = 0; e->probes && i < e->def.nprobes; i++) {
        free(e->probes[i].ring);
        free(e->probes[i].ring_t);
    }
    free(e->probes);
    e->probes = NULL;
}

/* ---- the measures ------------------------------------------------------------ */

static void measure_gate(isk_effect *e, fx_probe *p, const isk_probe_def *q, long stepped)
{
    const isk_deflector gate = isk_deflector_segment(q->segment[0], q->segment[1], q->segment[2], q->segment[3]);
    uint64_t f = 0, b = 0;
    for (int gi = 0; gi < e->ngroups; gi++) {
        const fx_group *g = &e->groups[gi];
        const isk_particles *s = &g->store;
        if (!(p->emitters >> gi & 1u) || !s->trail || s->trail_len < 1 || stepped + g->frame_offset < 0)
            continue; /* a group a prewarm has not started did not move */
        isk__segment_crossings(&gate, s->count, s->x, s->y, s->trail + 2 * (size_t)s->trail_head,
                               2 * (size_t)s->trail_len, &f, &b);
    }
    p->r.forward += f;
    p->r.backward += b;
    /* this frame into the window's ring, the oldest out */
    const int h = p->ring_head;
    p->ring[2 * h] = f;
    p->ring[2 * h + 1] = b;
    p->ring_t[h] = e->def.dt / e->def.speed_divisor;
    p->ring_head = (h + 1) % p->ring_n;
    if (p->ring_used < p->ring_n)
        p->ring_used++;
    uint64_t wf = 0, wb = 0;
    double t = 0;
    for (int k = 0; k < p->ring_used; k++) {
        wf += p->ring[2 * k];
        wb += p->ring[2 * k + 1];
        t += p->ring_t[k];
    }
    p->r.rate_forward = t > 0 ? (double)wf / t : 0.0;
    p->r.rate_backward = t > 0 ? (double)wb / t : 0.0;
}

static double speed_of(const isk_particles *s, size_t i)
{
    return hypot(s->vx[i], s->vy[i]);
}

static void measure_region(isk_effect *e, fx_probe *p, const isk_probe_def *q)
{
    size_t n = 0;
    double speed = 0, kinetic = 0;
    for (int gi = 0; gi < e->ngroups; gi++) {
        if (!(p->emitters >> gi & 1u))
            continue;
        const isk_particles *s = &e->groups[gi].store;
        for (size_t i = 0; i < s->count; i++)
            if (s->x[i] >= q->rect[0] && s->x[i] <= q->rect[1] && s->y[i] >= q->rect[2] && s->y[i] <= q->rect[3]) {
                n++;
                speed += speed_of(s, i);
                kinetic += 0.5 * s->m[i] * (s->vx[i] * s->vx[i] + s->vy[i] * s->vy[i]);
            }
    }
    p->r.count = n;
    p->r.mean_speed = n ? speed / (double)n : 0.0;
    p->r.kinetic = kinetic;
}

static double value_of(const isk_particles *s, size_t i, isk_probe_of of)
{
    switch (of) {
    case ISK_PROBE_OF_ANGLE: return atan2(s->vy[i], s->vx[i]) * (180.0 / 3.14159265358979323846);
    case ISK_PROBE_OF_AGE: return s->age[i];
    default: return speed_of(s, i);
    }
}

static void measure_histogram(isk_effect *e, fx_probe *p, const isk_probe_def *q)
{
    isk_probe_reading *r = &p->r;
    memset(r->bin, 0, sizeof r->bin);
    r->under = r->over = r->count = 0;
    const double lo = q->range[0], hi = q->range[1], width = hi - lo;
    for (int gi = 0; gi < e->ngroups; gi++) {
        if (!(p->emitters >> gi & 1u))
            continue;
        const isk_particles *s = &e->groups[gi].store;
        for (size_t i = 0; i < s->count; i++) {
            const double v = value_of(s, i, q->of);
            r->count++;
            if (!(v >= lo)) /* NaN too: no bin holds it */
                r->under++;
            else if (v > hi)
                r->over++;
            else {
                double k = floor((v - lo) / width * (double)q->bins);
                r->bin[k >= q->bins ? q->bins - 1 : (int)k]++;
            }
        }
    }
}

/* The kinetic and potential energy of the emitters of `bits`, in group
 * order: isk_effect_energy's (every bit) and the totals' numbers. */
static void energy_of(const isk_effect *e, uint64_t bits, double *kinetic, double *potential)
{
    double k = 0, u = 0;
    for (int g = 0; g < e->ngroups; g++) {
        if (!(bits >> g & 1u))
            continue;
        const isk_particles *p = &e->groups[g].store;
        for (size_t i = 0; i < p->count; i++)
            k += 0.5 * p->m[i] * (p->vx[i] * p->vx[i] + p->vy[i] * p->vy[i]);
        double ug;
        if (isk_forces_potential_energy(&e->groups[g].forces, p->count, p->x, p->y, p->m, &ug) != ISK_OK)
            ug = NAN; /* a law without an energy: no number rather than a wrong one */
        u += ug;
    }
    *kinetic = k;
    *potential = u;
}

static void measure_totals(isk_effect *e, fx_probe *p)
{
    double px = 0, py = 0;
    size_t n = 0;
    for (int gi = 0; gi < e->ngroups; gi++) {
        if (!(p->emitters >> gi & 1u))
            continue;
        const isk_particles *s = &e->groups[gi].store;
        for (size_t i = 0; i < s->count; i++) {
            px += s->m[i] * s->vx[i];
            py += s->m[i] * s->vy[i];
        }
        n += s->count;
    }
    p->r.count = n;
    p->r.px = px;
    p->r.py = py;
    energy_of(e, p->emitters, &p->r.kinetic, &p->r.potential);
}

void isk__fx_probes_measure(isk_effect *e, long stepped)
{
    const isk_effect_def *d = &e->def;
    if (!e->probes || stepped < 0) /* a prewarm's frames are before frame 0: nothing to read yet */
        return;
    for (int i = 0; i < d->nprobes; i++) {
        fx_probe *p = &e->probes[i];
        const isk_probe_def *q = &d->probes[i];
        switch (q->kind) {
        case ISK_PROBE_GATE: measure_gate(e, p, q, stepped); break;
        case ISK_PROBE_REGION: measure_region(e, p, q); break;
        case ISK_PROBE_HISTOGRAM: measure_histogram(e, p, q); break;
        default: measure_totals(e, p); break;
        }
        p->r.frame = e->frame;
    }
}

/* ---- reading ------------------------------------------------------------------ */

int isk_effect_probe_count(const isk_effect *e)
{
    return e ? e->def.nprobes : 0;
}

isk_status isk_effect_probe_read(const isk_effect *e, int i, isk_probe_reading *out)
{
    if (!e || !out)
        return ISK_ERR_NULL;
    if (i < 0 || i >= e->def.nprobes || !e->probes)
        return ISK_ERR_RANGE;
    *out = e->probes[i].r;
    return ISK_OK;
}

isk_status isk_effect_energy(const isk_effect *e, double *kinetic, double *potential)
{
    if (!e || !kinetic || !potential)
        return ISK_ERR_NULL;
    energy_of(e, ~(uint64_t)0, kinetic, potential);
    return ISK_OK;
}

static int put(isk_probe_value *out, int n, int max, const char *name, double v)
{
    if (n < max) {
        snprintf(out[n].name, sizeof out[n].name, "%s", name);
        out[n].value = v;
    }
    return n + 1;
}

int isk_probe_values(const isk_probe_reading *r, isk_probe_value *out, int max)
{
    int n = 0;
    if (!r || (!out && max > 0))
        return 0;
    switch (r->kind) {
    case ISK_PROBE_GATE:
        n = put(out, n, max, "forward", (double)r->forward);
        n = put(out, n, max, "backward", (double)r->backward);
        n = put(out, n, max, "rate_forward", r->rate_forward);
        n = put(out, n, max, "rate_backward", r->rate_backward);
        break;
    case ISK_PROBE_REGION:
        n = put(out, n, max, "count", (double)r->count);
        n = put(out, n, max, "mean_speed", r->mean_speed);
        n = put(out, n, max, "kinetic", r->kinetic);
        break;
    case ISK_PROBE_HISTOGRAM:
        n = put(out, n, max, "under", (double)r->under);
        for (int k = 0; k < r->bins && k < ISK_PROBE_MAX_BINS; k++) {
            char name[16];
            snprintf(name, sizeof name, "bin%d", k);
            n = put(out, n, max, name, (double)r->bin[k]);
        }
        n = put(out, n, max, "over", (double)r->over);
        break;
    default:
        n = put(out, n, max, "count", (double)r->count);
        n = put(out, n, max, "px", r->px);
        n = put(out, n, max, "py", r->py);
        n = put(out, n, max, "kinetic", r->kinetic);
        n = put(out, n, max, "potential", r->potential);
        n = put(out, n, max, "energy", r->kinetic + r->potential);
        break;
    }
    return n;
}

/* ---- drawing ------------------------------------------------------------------- */

/* A histogram's box: BAR_W px a bin, BOX_H px tall, stacked up from the
 * bottom left corner, one above the other in probe order. */
enum { PROBE_MARGIN = 4, BAR_W = 3, BOX_H = 40, LABEL_H = 10 };

static void draw_rect_outline(isk_canvas *c, double x0, double y0, double x1, double y1, isk_color col)
{
    const double xy[8] = {x0, y0, x1, y0, x1, y1, x0, y1};
    isk_stroke_polyline(c, xy, 4, 1, col, ISK_BLEND_OVER);
}

static void draw_histogram(isk_canvas *c, const fx_probe *p, const isk_probe_def *q, int slot)
{
    const int w = q->bins * BAR_W, x0 = PROBE_MARGIN;
    const int base = c->height - PROBE_MARGIN - slot * (BOX_H + LABEL_H + PROBE_MARGIN);
    size_t most = 0;
    for (int k = 0; k < q->bins; k++)
        most = p->r.bin[k] > most ? p->r.bin[k] : most;
    isk_color dim = q->color;
    dim.a = (uint8_t)(dim.a / 4);
    isk_fill_rect(c, x0, base - BOX_H, w, BOX_H, dim, ISK_BLEND_OVER);
    for (int k = 0; most && k < q->bins; k++) {
        /* bar heights in whole pixels, rounded up so a single count shows */
        const int h = (int)((p->r.bin[k] * (size_t)BOX_H + most - 1) / most);
        isk_fill_rect(c, x0 + k * BAR_W, base - h, BAR_W - 1, h, q->color, ISK_BLEND_OVER);
    }
    isk_draw_text(c, x0, base - BOX_H - LABEL_H + 1, q->name, 1, q->color, ISK_BLEND_OVER);
}

void isk__fx_probes_render(isk_effect *e, isk_canvas *c)
{
    const isk_effect_def *d = &e->def;
    int slot = 0;
    for (int i = 0; e->probes && i < d->nprobes; i++) {
        const isk_probe_def *q = &d->probes[i];
        const fx_probe *p = &e->probes[i];
        if (!q->show)
            continue;
        char text[64];
        double ax, ay, bx, by;
        switch (q->kind) {
        case ISK_PROBE_GATE:
            isk_view_to_screen(&e->view, q->segment[0], q->segment[1], &ax, &ay);
            isk_view_to_screen(&e->view, q->segment[2], q->segment[3], &bx, &by);
            isk_stroke_line(c, ax, ay, bx, by, q->color, ISK_BLEND_OVER);
            snprintf(text, sizeof text, "%s >%llu <%llu", q->name, (unsigned long long)p->r.forward,
                     (unsigned long long)p->r.backward);
            isk_draw_text(c, (int)fmin(fmax(bx + 3, -1e6), 1e6), (int)fmin(fmax(by, -1e6), 1e6), text, 1, q->color,
                          ISK_BLEND_OVER);
            break;
        case ISK_PROBE_REGION:
            isk_view_to_screen(&e->view, q->rect[0], q->rect[3], &ax, &ay);
            isk_view_to_screen(&e->view, q->rect[1], q->rect[2], &bx, &by);
            draw_rect_outline(c, ax, ay, bx, by, q->color);
            snprintf(text, sizeof text, "%s %zu", q->name, p->r.count);
            isk_draw_text(c, (int)fmin(fmax(ax, -1e6), 1e6), (int)fmin(fmax(ay - 2, -1e6), 1e6), text, 1, q->color,
                          ISK_BLEND_OVER);
            break;
        case ISK_PROBE_HISTOGRAM:
            draw_histogram(c, p, q, slot++);
            break;
        default:
            break; /* totals: numbers only (iskra render --probes, iskra play's chart) */
        }
    }
}

void isk__fx_probes_describe(const isk_effect *e, FILE *out)
{
    const isk_effect_def *d = &e->def;
    if (d->nprobes)
        fprintf(out, "probes (measured after every frame, drawn last):\n");
    for (int i = 0; i < d->nprobes; i++) {
        const isk_probe_def *q = &d->probes[i];
        fprintf(out, "  %-9s %s", isk_probe_kind_names[q->kind], q->name);
        if (q->kind == ISK_PROBE_GATE)
            fprintf(out, ", %g, %g -> %g, %g, rates over %g s (%d frames)", q->segment[0], q->segment[1],
                    q->segment[2], q->segment[3], q->window, e->probes ? e->probes[i].ring_n : 0);
        else if (q->kind == ISK_PROBE_REGION)
            fprintf(out, ", x %g..%g, y %g..%g", q->rect[0], q->rect[1], q->rect[2], q->rect[3]);
        else if (q->kind == ISK_PROBE_HISTOGRAM)
            fprintf(out, " of %s, %d bins over %g..%g", isk_probe_of_names[q->of], q->bins, q->range[0], q->range[1]);
        for (int k = 0; k < q->nemitters; k++)
            fprintf(out, "%s%s", k ? ", " : "; emitters ", d->emitters[q->emitters[k]].name);
        fprintf(out, "%s\n", q->show ? "" : ", not drawn");
    }
}
