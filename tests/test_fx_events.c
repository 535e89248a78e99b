/* SPDX-License-Identifier: MIT */
/* Sub-emitters (on_death, on_hit, source = sub, count, inherit): exact
 * counts of children, drops counted, hits equal to bounces, children that do
 * not depend on which emitter steps first or on the threads, inherited
 * velocities, chains and cycles that end, the validation's messages, and
 * what an emitter that does not use them costs (no column, no stage). */
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "scene_text.h"
#include "tool_cli.h"

#define OUT "out/test_fx_events"

/* The scene on `threads` threads (0: the default). */
static isk_effect *make_on(const char *text, int threads) { return scene_text_open(text, threads); }
static isk_effect *make(const char *text) { return scene_text_open(text, 0); }

static void steps(isk_effect *fx, int n)
{
    for (int i = 0; i < n; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
}

static int find(const isk_effect *fx, const char *name)
{
    return isk_effect_def_find_emitter(isk_effect_definition(fx), name);
}

static size_t count_of(const isk_effect *fx, const char *name)
{
    return isk_effect_particles(fx, find(fx, name))->count;
}

/* 10 parents born at t = 0 live 0.5 s; each death fires `count` children.
 * %s: the child's capacity line, %s: extra parent keys. */
static char *deaths_scene(const char *child_extra, int substeps)
{
    static char buf[1024];
    snprintf(buf, sizeof buf,
             "[scene]\nwidth = 64\nheight = 64\nsubsteps = %d\n"
             "[emitter parent]\nsource = stream\ncount = 10\nlife = 0.5\nlaunch = disc\nspeed_max = 3\n"
             "on_death = kids\n"
             "[emitter kids]\nsource = sub\ncount = 7\nlaunch = disc\nspeed_max = 2\n%s\n",
             substeps, child_extra);
    return buf;
}

Test(fx_events, n_deaths_give_n_times_count_children)
{
    for (int sub = 1; sub <= 3; sub += 2) {
        isk_effect *fx = make(deaths_scene("", sub));
        steps(fx, 20);
        cr_assert_eq(count_of(fx, "parent"), 10);
        cr_assert_eq(count_of(fx, "kids"), 0);
        steps(fx, 20); /* the deaths happened at 0.5 s (frame 30) */
        cr_assert_eq(count_of(fx, "parent"), 0);
        cr_assert_eq(count_of(fx, "kids"), 70, "substeps %d", sub);
        cr_assert_eq(isk_effect_dropped(fx, find(fx, "kids")), 0);
        isk_effect_destroy(fx);
    }
}

Test(fx_events, a_full_pool_drops_and_counts_the_rest)
{
    isk_effect *fx = make(deaths_scene("capacity = 50", 1));
    steps(fx, 40);
    cr_assert_eq(count_of(fx, "kids"), 50);
    cr_assert_eq(isk_effect_dropped(fx, find(fx, "kids")), 20);
    isk_effect_destroy(fx);
}

/* The children of frame f are in frame f's state: born at its end, aged. */
Test(fx_events, children_appear_in_the_frame_of_the_death_advanced_by_their_age)
{
    isk_effect *fx = make("[scene]\nwidth = 64\nheight = 64\n"
                          "[emitter parent]\nsource = particle\nvelocity = 0, -6\nlife = 0.25\non_death = kids\n"
                          "[emitter kids]\nsource = sub\ncount = 1\nvelocity = 4, 0\n");
    int f = 0;
    while (count_of(fx, "parent") == 1 && f < 100) {
        steps(fx, 1);
        f++;
        cr_assert_eq(count_of(fx, "kids"), count_of(fx, "parent") == 0, "frame %d", f);
    }
    cr_assert(f == 15 || f == 16, "the parent's age reaches 0.25 s in frame %d", f);
    const isk_particles *k = isk_effect_particles(fx, find(fx, "kids"));
    /* the parent died where it was at the end of that substep */
    cr_assert_float_eq(k->y[0], -6.0 * f / 60, 1e-12);
    cr_assert_float_eq(k->x[0], 0.0, 1e-12);
    steps(fx, 30);
    cr_assert_float_eq(k->x[0], 4.0 * 30 / 60, 1e-12);
    isk_effect_destroy(fx);
}

Test(fx_events, inherit_adds_that_fraction_of_the_parents_velocity)
{
    isk_effect *fx = make("[scene]\nwidth = 64\nheight = 64\n"
                          "[emitter parent]\nsource = particle\nvelocity = 2, -6\nlife = 0.25\non_death = kids\n"
                          "[emitter kids]\nsource = sub\ncount = 3\nvelocity = 1, 0\ninherit = 0.5\n");
    steps(fx, 16);
    const isk_particles *k = isk_effect_particles(fx, find(fx, "kids"));
    cr_assert_eq(k->count, 3);
    for (size_t i = 0; i < 3; i++) {
        cr_assert_eq(k->vx[i], 1.0 + 0.5 * 2.0);
        cr_assert_eq(k->vy[i], 0.5 * -6.0);
    }
    isk_effect_destroy(fx);
}

/* The sub-emitter defined before its parent (it steps first) or after it:
 * the same children (launches without random draws, so the emitter's index,
 * which seeds its stream, does not matter), with substeps too. */
Test(fx_events, children_do_not_depend_on_which_emitter_steps_first)
{
    const char *parent = "[emitter parent]\nsource = stream\nrate = 37\nlife = 0.3\nlaunch = constant\n"
                         "velocity = 3, 5\nforces = gravity\non_death = kids\n";
    const char *kids = "[emitter kids]\nsource = sub\ncount = 2\nlaunch = constant\nvelocity = -1, 2\n"
                       "inherit = 0.25\nforces = gravity\nlife = 2\n";
    char a[1024], b[1024];
    const char *head = "[scene]\nwidth = 64\nheight = 64\nsubsteps = 3\n[force gravity]\ng = 9.81\n";
    snprintf(a, sizeof a, "%s%s%s", head, parent, kids);
    snprintf(b, sizeof b, "%s%s%s", head, kids, parent);
    isk_effect *fa = make(a), *fb = make(b);
    for (int f = 0; f < 120; f++) {
        steps(fa, 1);
        steps(fb, 1);
        const isk_particles *ka = isk_effect_particles(fa, find(fa, "kids"));
        const isk_particles *kb = isk_effect_particles(fb, find(fb, "kids"));
        cr_assert_eq(ka->count, kb->count, "frame %d", f);
        for (size_t i = 0; i < ka->count; i++)
            cr_assert(ka->x[i] == kb->x[i] && ka->y[i] == kb->y[i] && ka->vx[i] == kb->vx[i] &&
                          ka->vy[i] == kb->vy[i] && ka->age[i] == kb->age[i],
                      "frame %d child %zu", f, i);
    }
    cr_assert_gt(count_of(fa, "kids"), 50);
    isk_effect_destroy(fa);
    isk_effect_destroy(fb);
}

/* N particles fall onto a deflector floor once each (no gravity, elastic):
 * N bounces, N * count children; on walls, a particle between two walls
 * bounces at t = 1 and t = 3 s. */
Test(fx_events, on_hit_fires_once_per_bounce)
{
    for (int sub = 1; sub <= 4; sub += 3) {
        char text[1024];
        snprintf(text, sizeof text,
                 "[scene]\nwidth = 64\nheight = 64\nsubsteps = %d\n[deflector floor]\nsegment = -10, 0, 10, 0\n"
                 "[emitter rain]\nsource = stream\ncount = 25\nshape = segment\nposition = -5, 5\n"
                 "shape_a = 10\nvelocity = 0, -10\ndeflectors = floor\non_hit = splash\n"
                 "[emitter splash]\nsource = sub\ncount = 4\nlaunch = cone\nangle = 90\nspread = 90\n"
                 "speed_min = 1\nspeed_max = 2\n",
                 sub);
        isk_effect *fx = make(text);
        steps(fx, 29);
        cr_assert_eq(count_of(fx, "splash"), 0);
        steps(fx, 2); /* the floor is reached at t = 0.5 s */
        cr_assert_eq(count_of(fx, "splash"), 100, "substeps %d", sub);
        steps(fx, 60);
        cr_assert_eq(count_of(fx, "splash"), 100, "flying up: no more bounces");
        char *buf = NULL;
        size_t len = 0;
        FILE *f = open_memstream(&buf, &len);
        isk_effect_describe(fx, f);
        fclose(f);
        cr_assert_not_null(strstr(buf, "hits      bounces -> events of splash"), "%s", buf);
        free(buf);
        isk_effect_destroy(fx);
    }

    isk_effect *fx;

    fx = make("[scene]\nwidth = 64\nheight = 64\n[bounds]\nsides = left, right\n"
              "[emitter ball]\nsource = stream\ncount = 3\nvelocity = 10, 0\non_hit = spark\n"
              "[emitter spark]\nsource = sub\ncount = 2\nlife = 10\n");
    steps(fx, 59);
    cr_assert_eq(count_of(fx, "spark"), 0);
    steps(fx, 2);
    cr_assert_eq(count_of(fx, "spark"), 6);
    steps(fx, 120);
    cr_assert_eq(count_of(fx, "spark"), 12);
    isk_effect_destroy(fx);
}

/* A particle landing on the floor hits it once; lying there it presses
 * into it every substep, which is no bounce. */
Test(fx_events, resting_is_not_bouncing)
{
    isk_effect *fx = make("[scene]\nwidth = 64\nheight = 64\n[bounds]\nsides = bottom\nrestitution = 0\n"
                          "[force gravity]\ng = 9.81\n"
                          "[emitter ball]\nsource = particle\nposition = 0, -9\nforces = gravity\non_hit = spark\n"
                          "[emitter spark]\nsource = sub\ncount = 1\n");
    steps(fx, 30);
    cr_assert_eq(count_of(fx, "spark"), 1, "the landing");
    steps(fx, 300);
    cr_assert_eq(count_of(fx, "spark"), 1, "resting");
    isk_effect_destroy(fx);

    /* the same on a deflector floor */
    fx = make("[scene]\nwidth = 64\nheight = 64\n[force gravity]\ng = 9.81\n"
              "[deflector floor]\nsegment = -10, -10, 10, -10\nrestitution = 0.3\n"
              "[emitter ball]\nsource = particle\nposition = 0, -9\nforces = gravity\ndeflectors = floor\n"
              "on_hit = spark\n[emitter spark]\nsource = sub\ncount = 1\n");
    steps(fx, 600);
    size_t n = count_of(fx, "spark");
    cr_assert(n >= 1 && n <= 6, "%zu hits: a few hops, then it rests", n);
    steps(fx, 300);
    cr_assert_eq(count_of(fx, "spark"), n, "resting");
    isk_effect_destroy(fx);
}

/* Hits on deflectors and walls from threaded blocks: the same children on
 * 1, 2 and 3 threads (3000 parents: a dozen blocks). */
Test(fx_events, threads_give_the_same_children)
{
    size_t ref_count = 0;
    double *rx = NULL;
    for (int t = 1; t <= 3; t++) {
        char text[1024];
        snprintf(text, sizeof text,
                 "[scene]\nwidth = 64\nheight = 64\n[bounds]\nsides = left, right\n[force gravity]\ng = 9.81\n"
                 "[deflector floor]\nsegment = -10, -5, 10, -6\nrestitution = 0.7\n"
                 "[emitter rain]\nsource = stream\ncount = 3000\nshape = rect\nshape_a = 9\nshape_b = 4\n"
                 "launch = disc\nspeed_max = 8\nlife = 3\nforces = gravity\ndeflectors = floor\n"
                 "on_hit = splash\non_death = splash\n"
                 "[emitter splash]\nsource = sub\ncount = 2\nlaunch = disc\nspeed_max = 1\nlife = 0.5\n"
                 "capacity = 1000000\nforces = gravity\n");
        isk_effect *fx = make_on(text, t);
        steps(fx, 120);
        const isk_particles *k = isk_effect_particles(fx, find(fx, "splash"));
        if (t == 1) {
            ref_count = k->count;
            rx = malloc(sizeof *rx * 2 * (ref_count ? ref_count : 1));
            for (size_t i = 0; i < ref_count; i++) {
                rx[2 * i] = k->x[i];
                rx[2 * i + 1] = k->y[i];
            }
            cr_assert_gt(ref_count, 500);
        } else {
            cr_assert_eq(k->count, ref_count, "threads %d", t);
            for (size_t i = 0; i < ref_count; i++)
                cr_assert(k->x[i] == rx[2 * i] && k->y[i] == rx[2 * i + 1], "threads %d child %zu", t, i);
        }
        isk_effect_destroy(fx);
    }
    free(rx);
}

/* A cycle (a's deaths fire b, b's fire a) and a chain into itself: they run,
 * bounded by the pools, and count what does not fit. */
Test(fx_events, chains_and_cycles_end_bounded_by_the_pools)
{
    isk_effect *fx = make("[scene]\nwidth = 64\nheight = 64\n"
                          "[emitter seed]\nsource = stream\ncount = 3\nlife = 0.1\non_death = a\n"
                          "[emitter a]\nsource = sub\ncount = 5\nlife = 0.05\ncapacity = 400\non_death = b\n"
                          "[emitter b]\nsource = sub\ncount = 5\nlife = 0.05\ncapacity = 300\non_death = a\n");
    steps(fx, 200);
    cr_assert_leq(count_of(fx, "a"), 400);
    cr_assert_leq(count_of(fx, "b"), 300);
    cr_assert_gt(isk_effect_dropped(fx, find(fx, "a")) + isk_effect_dropped(fx, find(fx, "b")), 0);
    isk_effect_destroy(fx);

    fx = make("[scene]\nwidth = 64\nheight = 64\n"
              "[emitter seed]\nsource = particle\nlife = 0.1\non_death = self\n"
              "[emitter self]\nsource = sub\ncount = 1000\nlife = 1/60\ncapacity = 5000\non_death = self\n");
    steps(fx, 100);
    cr_assert_leq(count_of(fx, "self"), 5000);
    cr_assert_gt(isk_effect_dropped(fx, find(fx, "self")), 0);
    isk_effect_destroy(fx);
}

/* Set while running: the column and the stage come (and the trail goes)
 * with the key; reset starts again with no events waiting. */
Test(fx_events, live_changes_and_reset)
{
    isk_effect *fx = make("[scene]\nwidth = 64\nheight = 64\n"
                          "[emitter p]\nsource = stream\ncount = 4\nlife = 0.1\n"
                          "[emitter hold]\nsource = particle\non_hit = s\n"
                          "[emitter s]\nsource = sub\ncount = 3\n");
    isk_error err;
    cr_assert_eq(isk_effect_set(fx, "emitter p", "on_death", "s", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_set(fx, "emitter s", "trail", "5", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_set(fx, "emitter p", "on_death", "hold", &err), ISK_ERR_RANGE);
    cr_assert_not_null(strstr(err.message, "not a sub-emitter"), "%s", err.message);
    steps(fx, 10);
    cr_assert_eq(count_of(fx, "s"), 12);
    cr_assert_not_null(isk_effect_particles(fx, find(fx, "s"))->trail);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 64, 64), ISK_OK);
    cr_assert_eq(isk_effect_render(fx, &c), ISK_OK);
    cr_assert_eq(isk_effect_set(fx, "emitter s", "trail", "0", &err), ISK_OK, "%s", err.message);
    cr_assert_null(isk_effect_particles(fx, find(fx, "s"))->trail);
    cr_assert_eq(isk_effect_render(fx, &c), ISK_OK);
    cr_assert_eq(isk_effect_reset(fx), ISK_OK);
    cr_assert_eq(count_of(fx, "s"), 0);
    steps(fx, 10);
    cr_assert_eq(count_of(fx, "s"), 12, "the definition keeps the live on_death");
    isk_canvas_free(&c);
    isk_effect_destroy(fx);
}

/* What the keys cost when unused: no hit or trail column, no hits stage. */
Test(fx_events, unused_keys_add_no_column_and_no_stage)
{
    isk_effect *fx = make(deaths_scene("", 1));
    const isk_particles *p = isk_effect_particles(fx, find(fx, "parent"));
    cr_assert_null(p->hit);
    cr_assert_null(p->trail);
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    isk_effect_describe(fx, f);
    fclose(f);
    cr_assert_null(strstr(buf, "hits"), "%s", buf);
    cr_assert_not_null(strstr(buf, "deaths -> events of kids"), "%s", buf);
    free(buf);
    isk_effect_destroy(fx);
}

/* ---- validation ------------------------------------------------------------------ */

static void rejects(const char *text, const char *fragment)
{
    isk_effect_def d;
    isk_error err;
    isk_status s = isk_scene_load_string(&d, text, "t.ini", &err);
    if (s == ISK_OK) {
        isk_effect *fx = NULL;
        s = isk_effect_create(&fx, &d, &err);
        isk_effect_destroy(fx);
        isk_effect_def_free(&d);
    }
    cr_assert_neq(s, ISK_OK, "accepted: %s", text);
    cr_assert_not_null(strstr(err.message, fragment), "%s", err.message);
}

Test(fx_events, references_must_name_sub_emitters)
{
    rejects("[emitter a]\nsource = particle\non_death = b\n[emitter b]\nsource = stream\nrate = 1\n",
            "t.ini:3: [emitter a] on_death: 'b' is not a sub-emitter");
    rejects("[emitter a]\nsource = particle\n[emitter b]\nsource = sub\ncount = 2\n",
            "t.ini:4: [emitter b]");
    rejects("[emitter a]\nsource = particle\n[emitter b]\nsource = sub\ncount = 2\n", "never fires");
    rejects("[emitter a]\nsource = particle\non_hit = nobody\n", "t.ini:3");
    rejects("[emitter a]\nsource = particle\non_hit = b\n[emitter b]\nsource = sub\n", "count");
    rejects("[emitter a]\nsource = particle\non_hit = b\n[emitter b]\nsource = sub\ncount = 3\ncapacity = 2\n",
            "exceeds the capacity 2");
}

/* The counts through the CLI's --state: N parents dying, N * count rows. */
Test(fx_events, the_state_csv_counts_the_children)
{
    cli_fresh(OUT "/state");
    FILE *f = fopen(OUT "/state/s.ini", "w");
    cr_assert_not_null(f);
    fputs(deaths_scene("capacity = 50", 1), f);
    fclose(f);
    cr_assert_eq(cli_run(OUT "/state", "render " OUT "/state/s.ini --frames 40 --out " OUT "/state/s.png --state " OUT
                                       "/state/s.csv"),
                 0);
    char *csv = cli_slurp(OUT "/state/s.csv");
    int kids = 0, parents = 0;
    for (char *l = strchr(csv, '\n'); l; l = strchr(l + 1, '\n')) {
        kids += !strncmp(l + 1, "kids,", 5);
        parents += !strncmp(l + 1, "parent,", 7);
    }
    cr_assert_eq(kids, 50);
    cr_assert_eq(parents, 0);
    free(csv);
}

/* The same from C: the fields of isk_emitter_def. */
Test(fx_events, reachable_from_c)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    isk_emitter_def *p = isk_effect_def_add_emitter(&d, "parent");
    cr_assert_not_null(p);
    cr_assert_eq(p->events.on_death, -1);
    cr_assert_eq(p->events.on_hit, -1);
    cr_assert_eq(p->look.trail, 0);
    p->born.source = ISK_SOURCE_STREAM;
    p->born.count = 4;
    p->life.seconds = 0.1;
    p->look.trail = 3;
    isk_emitter_def *k = isk_effect_def_add_emitter(&d, "kids");
    cr_assert_not_null(k);
    k->born.source = ISK_SOURCE_SUB;
    k->born.count = 5;
    k->launch.inherit = 1.0;
    d.emitters[0].events.on_death = 1;
    isk_effect *fx;
    isk_error err;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    steps(fx, 10);
    cr_assert_eq(isk_effect_particles(fx, 1)->count, 20);
    isk_effect_destroy(fx);
    d.emitters[1].launch.inherit = 1.5;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    cr_assert_not_null(strstr(err.message, "inherit"), "%s", err.message);
    d.emitters[1].launch.inherit = 0;
    d.emitters[0].events.on_death = -1;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    cr_assert_not_null(strstr(err.message, "never fires"), "%s", err.message);
    isk_effect_def_free(&d);
}
