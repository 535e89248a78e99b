/* SPDX-License-Identifier: MIT */
/* Probes ([probe NAME], iskra/probes.h): a gate across a steady stream
 * reads the stream's rate; a ring explosion's speed histogram is one spike
 * at its launch speed; the totals' energy is the energy chart's function;
 * a region counts what is inside; the same readings on 1 and 2 threads;
 * a scene's bytes and stage lists do not change when a probe that is not
 * drawn is added; bad values are refused at their line; a scene with
 * probes saves and loads back; and the reference image of each kind. */
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/probes.h"
#include "iskra/scene.h"
#include "refimg.h"
#include "scene/effect_internal.h" /* a group's store and keep_prev, the effect's probe state */
#include "scene_text.h"

#include "../tools/iskra/play_energy.c" /* the simulator's energy chart's numbers */

/* A stream of `rate` particles per second from (-4, y) in [-1, 1],
 * launched to the right at 4..6 units/s, through a gate at x = 0. */
#define STREAM_RATE 200.0
static const char stream_scene[] = "[scene]\nwidth = 200\nheight = 200\nseed = 7\n"
                                   "[view]\nxmin = -5\nxmax = 5\nymin = -5\nymax = 5\n"
                                   "[emitter jet]\nsource = stream\nrate = 200\nposition = -4, 0\nshape = segment\n"
                                   "shape_a = 0\nshape_b = 2\nlaunch = direction\nangle = 0\nspeed_min = 4\n"
                                   "speed_max = 6\nlife = 4\n";

static isk_probe_reading read_probe(const isk_effect *fx, int i)
{
    isk_probe_reading r;
    cr_assert_eq(isk_effect_probe_read(fx, i, &r), ISK_OK);
    return r;
}

static isk_effect *open_with(const char *scene, const char *probes, int threads)
{
    char text[4096];
    snprintf(text, sizeof text, "%s%s", scene, probes);
    return scene_text_open(text, threads);
}

/* Crossings per second over a window of W seconds at a rate R: a count of
 * about R*W, whose Poisson spread is sqrt(R*W); the bound is three times
 * that, as a rate: 3*sqrt(R/W) (= 42.4 per second for R = 200, W = 1).
 * The reading must sit inside the bound at every frame once the window
 * holds only the steady stream, and so must the count of the last 3 s:
 * |N - 600| <= 3 sqrt(600) = 73.5. */
Test(probes, a_gate_across_a_steady_stream_reads_its_rate)
{
    isk_effect *fx = open_with(stream_scene, "[probe door]\nkind = gate\nsegment = 0, -3, 0, 3\nwindow = 1\n", 0);
    const double bound = 3.0 * sqrt(STREAM_RATE / 1.0);
    double worst = 0;
    uint64_t at2 = 0;
    for (int f = 1; f <= 300; f++) {
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        isk_probe_reading r = read_probe(fx, 0);
        cr_assert_eq(r.frame, f);
        cr_assert_eq(r.backward, 0, "nothing goes left");
        /* the first arrive after 4/6 s; the window is steady 1 s after 1 s more */
        if (f >= 60 * 2)
            worst = fmax(worst, fabs(r.rate_forward - STREAM_RATE));
        if (f == 60 * 2)
            at2 = r.forward;
    }
    cr_assert(worst <= bound, "rate off by %g (bound %g)", worst, bound);
    isk_probe_reading r = read_probe(fx, 0);
    const double last3 = (double)(r.forward - at2);
    cr_assert(fabs(last3 - 3 * STREAM_RATE) <= 3 * sqrt(3 * STREAM_RATE), "%g crossings in the last 3 s", last3);
    printf("gate: worst rate over frames 120..300 %g from %g (bound %g); %g crossings in the last 3 s\n",
           worst, STREAM_RATE, bound, last3);
    /* every particle born up to 5 s - 1 s of travel at most crossed once */
    cr_assert(r.forward >= (uint64_t)(STREAM_RATE * (5.0 - 1.0)) && r.forward <= (uint64_t)(STREAM_RATE * 5.0),
              "%llu crossings", (unsigned long long)r.forward);
    isk_effect_destroy(fx);
}

/* The gate's direction is the order of its end points: reversed, the same
 * crossings are backward ones. */
Test(probes, a_reversed_gate_counts_backward)
{
    isk_effect *a = open_with(stream_scene, "[probe door]\nkind = gate\nsegment = 0, -3, 0, 3\n", 1);
    isk_effect *b = open_with(stream_scene, "[probe door]\nkind = gate\nsegment = 0, 3, 0, -3\n", 1);
    for (int f = 0; f < 120; f++) {
        cr_assert_eq(isk_effect_step(a), ISK_OK);
        cr_assert_eq(isk_effect_step(b), ISK_OK);
    }
    isk_probe_reading ra = read_probe(a, 0), rb = read_probe(b, 0);
    cr_assert(ra.forward > 100);
    cr_assert_eq(ra.backward, 0);
    cr_assert_eq(rb.forward, 0);
    cr_assert_eq(rb.backward, ra.forward);
    cr_assert_eq(rb.rate_backward, ra.rate_forward);
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

/* A ring explosion launches every particle at |(4, 4)| = 4*sqrt(2) =
 * 5.65685...: with no force the histogram is one spike there, in the bin
 * [5.65, 5.66) of 5.6..5.7 in 10 bins, at every frame. */
Test(probes, a_ring_explosions_speed_histogram_is_one_spike)
{
    isk_effect *fx = scene_text_open("[emitter ring]\nsource = explosion\nexplosion = ring\ncount = 360\n"
                                     "[probe speeds]\nkind = histogram\nof = speed\nbins = 10\nrange = 5.6, 5.7\n",
                                     0);
    for (int f = 0; f < 30; f++) {
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        isk_probe_reading r = read_probe(fx, 0);
        cr_assert_eq(r.count, 360);
        cr_assert_eq(r.under + r.over, 0);
        for (int k = 0; k < 10; k++)
            cr_assert_eq(r.bin[k], k == 5 ? 360u : 0u, "frame %d bin %d holds %zu", f + 1, k, r.bin[k]);
    }
    isk_effect_destroy(fx);
}

/* The totals' energy is what `iskra play`'s energy chart computes for the
 * same frame (play_energy_of, compiled in from tools/iskra/play_energy.c),
 * bit for bit, and the sum it says: with gravity, potential energy m g y
 * per particle, and the kinetic energy recomputed here from the store. */
Test(probes, the_totals_energy_is_the_energy_charts)
{
    isk_effect *fx = scene_text_open("[force gravity]\ng = 9.81\n"
                                     "[emitter ring]\nsource = explosion\nexplosion = ring\ncount = 100\n"
                                     "forces = gravity\n[probe sums]\nkind = totals\n",
                                     2);
    for (int f = 0; f < 20; f++) {
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        isk_probe_reading r = read_probe(fx, 0);
        const play_energy chart = play_energy_of(fx);
        cr_assert(r.kinetic == chart.kinetic && r.potential == chart.potential, "the chart's numbers, bit for bit");
        cr_assert(r.kinetic > 0 && r.potential != 0);
        const isk_particles *p = isk_effect_particles(fx, 0);
        double k2 = 0, u2 = 0, px = 0;
        for (size_t i = 0; i < p->count; i++) {
            k2 += 0.5 * p->m[i] * (p->vx[i] * p->vx[i] + p->vy[i] * p->vy[i]);
            u2 += p->m[i] * 9.81 * p->y[i];
            px += p->m[i] * p->vx[i];
        }
        cr_assert(fabs(r.kinetic - k2) <= 1e-12 * k2, "kinetic %.17g vs %.17g", r.kinetic, k2);
        cr_assert(fabs(r.potential - u2) <= 1e-9 * (fabs(u2) + k2), "potential %.17g vs %.17g", r.potential, u2);
        cr_assert(fabs(r.px - px) <= 1e-9, "px %g vs %g", r.px, px);
        cr_assert_eq(r.count, 100);
    }
    isk_effect_destroy(fx);
}

/* A region counts the particles inside it: a ring of radius 4 sqrt(2) t
 * grows out of a 1 x 1 box at t = 0.5/(4) s (its x and y reach 0.5 when
 * 4 t = 0.5 at the diagonal particles; the others are out sooner). */
Test(probes, a_region_counts_whats_inside)
{
    isk_effect *fx = scene_text_open("[scene]\ndt = 0.01\n[emitter ring]\nsource = explosion\nexplosion = ring\n"
                                     "count = 100\n[probe box]\nkind = region\nrect = -0.5, 0.5, -0.5, 0.5\n",
                                     0);
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    isk_probe_reading r = read_probe(fx, 0);
    cr_assert_eq(r.count, 100, "at t = 0.01 every particle is within 0.0566 of the centre");
    cr_assert(fabs(r.mean_speed - 4 * sqrt(2.0)) < 1e-12);
    const isk_particles *p = isk_effect_particles(fx, 0);
    double mass = 0;
    for (size_t i = 0; i < p->count; i++)
        mass += p->m[i];
    cr_assert(fabs(r.kinetic - mass * 0.5 * 32) < 1e-9, "%.17g", r.kinetic);
    for (int f = 0; f < 20; f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    r = read_probe(fx, 0);
    cr_assert_eq(r.count, 0, "at t = 0.21 every particle is 1.19 from the centre");
    cr_assert_eq(r.mean_speed, 0);
    isk_effect_destroy(fx);
}

/* Every reading the same on 1 and 2 threads, frame by frame. */
Test(probes, the_same_readings_on_any_number_of_threads)
{
    const char *probes = "[probe door]\nkind = gate\nsegment = 0, -3, 0, 3\n"
                         "[probe box]\nkind = region\nrect = -2, 2, -2, 2\n"
                         "[probe ages]\nkind = histogram\nof = age\nbins = 8\nrange = 0, 4\n[probe totals]\n";
    isk_effect *a = open_with(stream_scene, probes, 1), *b = open_with(stream_scene, probes, 2);
    for (int f = 0; f < 150; f++) {
        cr_assert_eq(isk_effect_step(a), ISK_OK);
        cr_assert_eq(isk_effect_step(b), ISK_OK);
        for (int i = 0; i < isk_effect_probe_count(a); i++) {
            isk_probe_reading ra = read_probe(a, i), rb = read_probe(b, i);
            isk_probe_value va[80], vb[80];
            int n = isk_probe_values(&ra, va, 80);
            cr_assert_eq(n, isk_probe_values(&rb, vb, 80));
            for (int k = 0; k < n; k++)
                cr_assert(!memcmp(&va[k].value, &vb[k].value, sizeof(double)), "%s %s", ra.name, va[k].name);
        }
    }
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

static char *lists_of(isk_effect *fx)
{
    return scene_text_lists(fx);
}

/* A probe that is not drawn changes no byte of the image and no stage of
 * the lists (a gate makes every store keep its particles' last positions;
 * that draws nothing): describe only gains its probes block.  A scene
 * without probes says nothing of them. */
Test(probes, a_probe_not_drawn_changes_no_byte_and_no_stage)
{
    isk_effect *plain = open_with(stream_scene, "", 0);
    isk_effect *probed = open_with(stream_scene, "[probe door]\nkind = gate\nsegment = 0, -3, 0, 3\nshow = false\n"
                                                 "[probe t]\nkind = totals\n", 0);
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, 200, 200), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 200, 200), ISK_OK);
    cr_assert_eq(isk_effect_run(plain, &a, 90), ISK_OK);
    cr_assert_eq(isk_effect_run(probed, &b, 90), ISK_OK);
    cr_assert(!memcmp(a.pixels, b.pixels, (size_t)a.width * (size_t)a.height * 4), "the same bytes");
    cr_assert(read_probe(probed, 0).forward > 0, "and the gate counted");
    char *la = lists_of(plain), *lb = lists_of(probed);
    cr_assert_null(strstr(la, "probe"), "%s", la);
    char *block = strstr(lb, "probes (measured");
    cr_assert_not_null(block, "%s", lb);
    /* lb without its probes block (the lines from `block` to the [scene] line) is la */
    char *after = strstr(block, "[scene]");
    cr_assert_not_null(after);
    size_t head = (size_t)(block - lb);
    cr_assert(strlen(la) == head + strlen(after) && !strncmp(la, lb, head) && !strcmp(la + head, after),
              "without probes:\n%s\nwith:\n%s", la, lb);
    free(la);
    free(lb);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_effect_destroy(plain);
    isk_effect_destroy(probed);
}

/* `emitters` names what a probe measures: a gate on one of two streams
 * counts only that one, the totals of one only its particles; "all" is
 * every emitter. */
Test(probes, emitters_choose_what_is_measured)
{
    const char *two = "[emitter a]\nsource = stream\nrate = 60\nposition = -2, 0\nvelocity = 4, 0\nlife = 3\n"
                      "[emitter b]\nsource = stream\nrate = 60\nposition = -2, 1\nvelocity = 4, 0\nlife = 3\n"
                      "[probe both]\nkind = gate\nsegment = 0, -3, 0, 3\n"
                      "[probe only_b]\nkind = gate\nsegment = 0, -3, 0, 3\nemitters = b\n"
                      "[probe all_named]\nkind = gate\nsegment = 0, -3, 0, 3\nemitters = all\n"
                      "[probe tb]\nkind = totals\nemitters = b\n[probe ta]\nkind = totals\nemitters = a\n";
    isk_effect *fx = scene_text_open(two, 0);
    for (int f = 0; f < 90; f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    isk_probe_reading both = read_probe(fx, 0), b = read_probe(fx, 1), all = read_probe(fx, 2);
    isk_probe_reading tb = read_probe(fx, 3), ta = read_probe(fx, 4);
    cr_assert(b.forward > 30, "%llu", (unsigned long long)b.forward);
    cr_assert_eq(both.forward, 2 * b.forward, "the streams are the same, a row apart");
    cr_assert_eq(all.forward, both.forward);
    cr_assert_eq(tb.count, isk_effect_particles(fx, 1)->count);
    cr_assert_eq(ta.count, isk_effect_particles(fx, 0)->count);
    double k, u;
    cr_assert_eq(isk_effect_energy(fx, &k, &u), ISK_OK);
    cr_assert(fabs(ta.kinetic + tb.kinetic - k) <= 1e-12 * k);
    isk_effect_destroy(fx);
}

/* Without probes nothing of them exists: for every built-in scene no probe
 * state, no store keeps a position it would not keep for its own trail,
 * describe says nothing of probes, and the scene saves without a [probe]. */
Test(probes, a_scene_without_probes_has_nothing_of_them)
{
    for (int i = 0; i < isk_scene_builtin_count(); i++) {
        const char *name = isk_scene_builtin_name(i);
        isk_effect_def d;
        isk_error err;
        cr_assert_eq(isk_scene_load(&d, name, &err), ISK_OK, "%s", err.message);
        char *saved;
        cr_assert_eq(isk_scene_write(&d, &saved, &err), ISK_OK, "%s: %s", name, err.message);
        cr_assert_null(strstr(saved, "[probe"), "%s", name);
        free(saved);
        d.threads = 1;
        isk_effect *fx = scene_open_def(&d);
        cr_assert_eq(isk_effect_step(fx), ISK_OK, "%s", name);
        cr_assert_eq(isk_effect_probe_count(fx), 0, "%s", name);
        cr_assert_null(fx->probes, "%s", name);
        for (int g = 0; g < fx->ngroups; g++) {
            cr_assert_eq(fx->groups[g].keep_prev, 0, "%s", name);
            cr_assert_eq(fx->groups[g].store.trail != NULL, fx->groups[g].def->look.trail > 0, "%s emitter %d", name,
                         g);
        }
        char *lists = lists_of(fx);
        cr_assert_null(strstr(lists, "probe"), "%s:\n%s", name, lists);
        free(lists);
        isk_effect_destroy(fx);
    }
}

/* ---- scene files ---------------------------------------------------------------- */

static void refused(const char *probe, const char *expect)
{
    char text[1024];
    snprintf(text, sizeof text, "[emitter e]\nsource = stream\nrate = 10\n%s", probe);
    isk_effect_def d;
    isk_error err;
    cr_assert_neq(isk_scene_load_string(&d, text, "p.ini", &err), ISK_OK, "accepted: %s", probe);
    cr_assert_not_null(strstr(err.message, expect), "message: %s (expected %s)", err.message, expect);
}

Test(probes, bad_values_are_refused_at_their_line)
{
    refused("[probe g]\nkind = gate\nsegment = 1, 1, 1, 1\n", "p.ini:6: [probe g] segment: the two end points");
    refused("[probe g]\nkind = gate\n", "p.ini:4: [probe g] needs segment");
    refused("[probe r]\nkind = region\nrect = 1, -1, 0, 1\n", "p.ini:6: [probe r] rect: needs xmin < xmax");
    refused("[probe h]\nkind = histogram\nrange = 2, 2\n", "p.ini:6: [probe h] range: needs lo < hi");
    refused("[probe h]\nkind = histogram\nrange = 0, 1\nbins = 65\n", "p.ini:7: [probe h] bins:");
    refused("[probe h]\nkind = histogram\nrange = 0, 1\nof = colour\n", "p.ini:7: [probe h] of:");
    refused("[probe x]\nrect = 0, 1, 0, 1\n", "p.ini:4: [probe x] needs kind = gate, region, histogram or totals");
    refused("[probe g]\nkind = gate\nsegment = 0, 0, 1, 0\nbins = 4\n", "p.ini:7: [probe g] bins: only for kind");
    refused("[probe g]\nkind = gate\nsegment = 0, 0, 1, 0\nwindow = 0\n", "p.ini:7: [probe g] window:");
    refused("[probe]\nkind = totals\n", "needs a name");
    refused("[probe t]\nkind = totals\nemitters = none\n", "p.ini:6: [probe t] emitters: name one or more emitters, or all");
    refused("[probe t]\nkind = totals\nemitters = f\n", "p.ini:6: [probe t] emitters: no emitter named 'f'");
}

Test(probes, a_scene_with_probes_saves_and_loads_back)
{
    isk_effect_def d, back;
    isk_error err;
    const char *text = "[emitter e]\nsource = stream\nrate = 10\n"
                       "[probe door]\nkind = gate\nsegment = 0.1, -3, 0.25, 3\nwindow = 0.5\ncolor = #ff000080\n"
                       "[probe box]\nkind = region\nrect = -2, 2, -1.5, 1.5\nshow = false\n"
                       "[probe ages]\nkind = histogram\nof = age\nbins = 8\nrange = 0, 4\nemitters = e\n[probe totals]\n";
    cr_assert_eq(isk_scene_load_string(&d, text, "p.ini", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(d.nprobes, 4);
    cr_assert_eq(d.probes[0].kind, ISK_PROBE_GATE);
    cr_assert_eq(d.probes[3].kind, ISK_PROBE_TOTALS, "the name is the kind");
    char *saved;
    cr_assert_eq(isk_scene_write(&d, &saved, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_scene_load_string(&back, saved, "saved.ini", &err), ISK_OK, "%s\n%s", err.message, saved);
    cr_assert_eq(back.nprobes, 4);
    for (int i = 0; i < 4; i++) {
        back.probes[i].line = d.probes[i].line;
        cr_assert(!memcmp(&back.probes[i], &d.probes[i], sizeof d.probes[i]), "probe %d differs:\n%s", i, saved);
    }
    free(saved);
    isk_effect_def_free(&d);
    isk_effect_def_free(&back);
}

Test(probes, the_api_refuses_what_is_not_there)
{
    isk_effect *fx = scene_text_open("[emitter e]\nsource = stream\nrate = 10\n", 0);
    isk_probe_reading r;
    cr_assert_eq(isk_effect_probe_count(fx), 0);
    cr_assert_eq(isk_effect_probe_read(fx, 0, &r), ISK_ERR_RANGE);
    cr_assert_eq(isk_effect_probe_read(fx, -1, &r), ISK_ERR_RANGE);
    cr_assert_eq(isk_effect_probe_read(NULL, 0, &r), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_probe_read(fx, 0, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_probe_count(NULL), 0);
    cr_assert_eq(isk_probe_values(NULL, NULL, 0), 0);
    double k, u;
    cr_assert_eq(isk_effect_energy(NULL, &k, &u), ISK_ERR_NULL);
    isk_effect_destroy(fx);
}

/* A reset starts the counts again: the same readings as the first run. */
Test(probes, a_reset_starts_the_counts_again)
{
    isk_effect *fx = open_with(stream_scene, "[probe door]\nkind = gate\nsegment = 0, -3, 0, 3\n", 0);
    for (int f = 0; f < 100; f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    isk_probe_reading first = read_probe(fx, 0);
    cr_assert_eq(isk_effect_reset(fx), ISK_OK);
    cr_assert_eq(read_probe(fx, 0).forward, 0);
    cr_assert_eq(read_probe(fx, 0).frame, 0);
    for (int f = 0; f < 100; f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    isk_probe_reading again = read_probe(fx, 0);
    cr_assert_eq(again.forward, first.forward);
    cr_assert_eq(again.rate_forward, first.rate_forward);
    isk_error err;
    cr_assert_neq(isk_effect_set(fx, "probe door", "window", "2", &err), ISK_OK, "fixed at create");
    isk_effect_destroy(fx);
}

/* ---- reference images: each kind drawn ------------------------------------------- */

Test(probes, refimg_each_kind_drawn)
{
    isk_effect *fx = open_with(stream_scene, "[probe door]\nkind = gate\nsegment = 0, -3, 0, 3\n"
                                             "[probe box]\nkind = region\nrect = 1, 3, -2, 2\ncolor = orange\n"
                                             "[probe speeds]\nkind = histogram\nrange = 3, 7\nbins = 16\n"
                                             "[probe ages]\nkind = histogram\nof = age\nrange = 0, 4\n"
                                             "color = lime\n[probe totals]\n",
                               2);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 200, 200), ISK_OK);
    cr_assert_eq(isk_effect_run(fx, &c, 90), ISK_OK);
    cr_assert(refimg_check("probes_each_kind", &c), "refimg probes_each_kind differs");
    isk_canvas_free(&c);
    isk_effect_destroy(fx);
}
