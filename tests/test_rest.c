/* SPDX-License-Identifier: MIT */
/* Blocks at rest (sim/rest.h): the runner skips the motion
 * stages of a block that they leave bit for bit as it was, and the bytes
 * stay those of running every stage.
 *
 * The stage lists: a store half of which settles on the floor (blocks
 * 0..7: no sideways speed) and half of which slides along it (blocks
 * 8..15, whose drag never quite stops them), run with and without the
 * states, compared bit for bit along the way, on the caller and on 2 and
 * 3 workers; blocks do come to rest, and only the settled ones.
 * What the owner must say: a particle written and forgotten gives the same
 * bytes, written and not forgotten it stays where it rested (so the stages
 * really were skipped, and forgetting is what keeps the bytes); a new step
 * forgets by itself.  Which lists may rest (isk__pipeline_rest_prefix).
 *
 * The effect: a settling layer beside a stream of mortal particles that
 * die on the floor (ordered culls) and a live wind that lifts
 * the layer off, on 1, 2 and 3 threads, against the same effect with no
 * block at rest: the same stores and the same canvases. */
#include <criterion/criterion.h>
#include "fast_paths_skip.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "iskra/canvas.h"
#include "iskra/integrate.h"
#include "iskra/particles.h"
#include "scene/effect_internal.h"
#include "scene_text.h"
#include "sim/rest.h"
#include "sim/workers.h"
#include "sim/stage.h"

enum { N = 16 * ISK_SIM_BLOCK, SETTLING = 8 * ISK_SIM_BLOCK, BOTH = ISK_REST_X | ISK_REST_Y };
static const double H = 1.0 / 600;

typedef struct lists {
    isk_forces f;
    isk_bounds box;
    isk_pipeline pl;
} lists;

/* gravity + drag, semi-implicit Euler, reflect walls c = 0.5, ageing */
static void lists_init(lists *l)
{
    memset(l, 0, sizeof *l);
    l->f.gravity = 9.81;
    l->f.drag = 0.3;
    cr_assert_eq(isk_bounds_reflect(&l->box, -5, 5, 0, 10, ISK_SIDE_ALL, 0.0, 0.5), ISK_OK);
    isk__pipeline_init(&l->pl);
    isk_stage *s = isk__pipeline_add(&l->pl, &isk__stage_motion);
    s->u.motion.method = ISK_INTEGRATE_SEMI_EULER;
    s->u.motion.forces = &l->f;
    s = isk__pipeline_add(&l->pl, &isk__stage_walls);
    s->u.walls.b = &l->box;
    s->u.walls.drag = l->f.drag;
    s->u.walls.ay = -l->f.gravity;
    s->u.walls.offset = isk_integrator_velocity_offset(ISK_INTEGRATE_SEMI_EULER);
    isk__pipeline_add(&l->pl, &isk__stage_age);
}

static void store_fill(isk_particles *p)
{
    cr_assert_eq(isk_particles_init(p, N, 0), ISK_OK);
    uint64_t r = 7;
    for (size_t i = 0; i < N; i++) {
        r = r * 6364136223846793005ull + 1442695040888963407ull;
        double u = (double)(r >> 11) / 9007199254740992.0;
        double vx = i < SETTLING ? 0.0 : 2.0 + u;
        cr_assert_eq(isk_particles_add(p, -4.5 + 9.0 * u, 0.2 + 3.0 * u, vx, 0.0, 1.0 + u, NULL), ISK_OK);
    }
}

static int same_store(const isk_particles *a, const isk_particles *b)
{
    const size_t bytes = a->count * sizeof(double);
    return a->count == b->count && !memcmp(a->x, b->x, bytes) && !memcmp(a->y, b->y, bytes) &&
           !memcmp(a->vx, b->vx, bytes) && !memcmp(a->vy, b->vy, bytes) && !memcmp(a->age, b->age, bytes);
}

static isk_scratch *scratch(void)
{
    isk_scratch *s = calloc(1, sizeof *s);
    cr_assert_not_null(s);
    return s;
}

/* steps of the lists over p with rest (NULL: every stage), on the caller or
 * workers (NULL: the caller) */
static void steps(lists *l, isk_particles *p, isk_rest *rest, isk_scratch *s, isk_workers *w, int n, double h)
{
    const isk_run_context ctx = {w, rest};
    for (int k = 0; k < n; k++)
        isk__pipeline_run(&l->pl, p, 0, p->count, h, s, &ctx);
}

Test(rest, settled_blocks_rest_with_the_same_bits)
{
    SKIP_WITHOUT(ISK__FAST_REST, "blocks at rest");
    lists l;
    lists_init(&l);
    isk_particles a, b;
    store_fill(&a);
    store_fill(&b);
    isk_rest r;
    isk__rest_init(&r);
    isk_scratch *s = scratch();
    cr_assert_eq(isk__pipeline_rest_prefix(&l.pl), 2);
    for (int round = 0; round < 40; round++) { /* 4 s of 1/600 */
        steps(&l, &a, &r, s, NULL, 60, H);
        steps(&l, &b, NULL, s, NULL, 60, H);
        cr_assert(same_store(&a, &b), "round %d", round);
    }
    size_t rested = isk__rest_blocks(&r, a.count, BOTH);
    cr_assert_eq(rested, SETTLING / ISK_SIM_BLOCK, "%zu blocks at rest: the settled ones, not the sliding ones",
                 rested);
    size_t y_rests = isk__rest_blocks(&r, a.count, ISK_REST_Y);
    cr_assert_eq(y_rests, N / ISK_SIM_BLOCK, "%zu blocks' y at rest: the sliding ones' too", y_rests);
    cr_assert_eq(isk__rest_blocks(&r, a.count, ISK_REST_X), SETTLING / ISK_SIM_BLOCK, "x rests where it stands");
    isk__rest_free(&r);
    isk_particles_free(&a);
    isk_particles_free(&b);
    free(s);
}

/* Every integrator is per axis: a block whose y rests while its x slides
 * steps its x alone with the same bits.  Which integrators bring a particle
 * to a bit-exact rest is theirs; those that do are counted. */
Test(rest, every_integrator_per_axis)
{
    SKIP_WITHOUT(ISK__FAST_REST, "blocks at rest");
    isk_scratch *s = scratch();
    int rested_somewhere = 0;
    for (int m = 0; m < ISK_INTEGRATOR_COUNT; m++) {
        lists l;
        lists_init(&l);
        l.pl.stage[0].u.motion.method = (isk_integrator)m;
        l.pl.stage[1].u.walls.offset = isk_integrator_velocity_offset((isk_integrator)m);
        isk_particles a, b;
        store_fill(&a);
        store_fill(&b);
        isk_rest r;
        isk__rest_init(&r);
        for (int round = 0; round < 20; round++) {
            steps(&l, &a, &r, s, NULL, 120, H);
            steps(&l, &b, NULL, s, NULL, 120, H);
            cr_assert(same_store(&a, &b), "%s, round %d", isk_integrator_name((isk_integrator)m), round);
        }
        rested_somewhere += isk__rest_blocks(&r, a.count, ISK_REST_Y) > 0;
        isk__rest_free(&r);
        isk_particles_free(&a);
        isk_particles_free(&b);
    }
    cr_assert_geq(rested_somewhere, 4, "blocks rested under %d integrators", rested_somewhere);
    free(s);
}

Test(rest, written_particles_must_be_forgotten)
{
    SKIP_WITHOUT(ISK__FAST_REST, "blocks at rest");
    lists l;
    lists_init(&l);
    isk_particles a, b, c;
    store_fill(&a);
    store_fill(&b);
    store_fill(&c);
    isk_rest ra, rc;
    isk__rest_init(&ra);
    isk__rest_init(&rc);
    isk_scratch *s = scratch();
    steps(&l, &a, &ra, s, NULL, 2400, H);
    steps(&l, &b, NULL, s, NULL, 2400, H);
    steps(&l, &c, &rc, s, NULL, 2400, H);
    cr_assert_gt(isk__rest_blocks(&ra, a.count, BOTH), 0);
    const size_t k = 3 * ISK_SIM_BLOCK + 5; /* in a block at rest: lifted 2 up */
    a.y[k] += 2;
    b.y[k] += 2;
    c.y[k] += 2;
    const double lifted = c.y[k];
    isk__rest_forget(&ra, k);
    steps(&l, &a, &ra, s, NULL, 30, H);
    steps(&l, &b, NULL, s, NULL, 30, H);
    steps(&l, &c, &rc, s, NULL, 30, H);
    cr_assert(same_store(&a, &b), "forgotten: the same bytes");
    cr_assert(!same_store(&c, &b), "not forgotten: the block stayed at rest");
    cr_assert_eq(c.y[k], lifted, "the lifted particle hangs in the air: %g", c.y[k]);
    cr_assert_lt(b.y[k], lifted, "it falls when stepped");
    /* a new step forgets by itself */
    steps(&l, &a, &ra, s, NULL, 900, H / 2);
    steps(&l, &b, NULL, s, NULL, 900, H / 2);
    cr_assert(same_store(&a, &b), "half the step: the same bytes");
    isk__rest_free(&ra);
    isk__rest_free(&rc);
    isk_particles_free(&a);
    isk_particles_free(&b);
    isk_particles_free(&c);
    free(s);
}

Test(rest, threads_give_the_same_bits)
{
    SKIP_WITHOUT(ISK__FAST_REST, "blocks at rest");
    lists l;
    lists_init(&l);
    isk_scratch *s = scratch();
    for (int threads = 2; threads <= 3; threads++) {
        isk_particles a, ref;
        store_fill(&a);
        store_fill(&ref);
        isk_workers pool;
        isk__workers_init(&pool);
        cr_assert_eq(isk__workers_start(&pool, threads), ISK_OK);
        isk_rest r;
        isk__rest_init(&r);
        for (int round = 0; round < 30; round++) {
            steps(&l, &a, &r, s, &pool, 80, H);
            steps(&l, &ref, NULL, s, NULL, 80, H);
            cr_assert(same_store(&a, &ref), "%d threads, round %d", threads, round);
        }
        cr_assert_eq(isk__rest_blocks(&r, a.count, BOTH), SETTLING / ISK_SIM_BLOCK);
        isk__rest_free(&r);
        isk__workers_free(&pool);
        isk_particles_free(&a);
        isk_particles_free(&ref);
    }
    free(s);
}

Test(rest, which_lists_may_rest)
{
    lists l;
    lists_init(&l);
    cr_assert_eq(isk__pipeline_rest_prefix(&l.pl), 2, "integrate, walls skipped; age beside");
    l.pl.stage[1].u.walls.hit = 1;
    cr_assert_eq(isk__pipeline_rest_prefix(&l.pl), 0, "counting bounces");
    l.pl.stage[1].u.walls.hit = 0;
    isk_potential pot;
    isk_potential_init(&pot, 1.0, isk_vec2_make(0, 5), -2.0);
    l.f.pot = &pot;
    l.f.npot = 1;
    cr_assert_eq(isk__pipeline_rest_prefix(&l.pl), 0, "a potential");
    l.f.npot = 0;
    isk__pipeline_add(&l.pl, &isk__stage_deflect);
    cr_assert_eq(isk__pipeline_rest_prefix(&l.pl), 0, "a deflector after the age");

    isk_pipeline pl;
    isk__pipeline_init(&pl);
    isk__pipeline_add(&pl, &isk__stage_remember);
    isk__pipeline_add(&pl, &isk__stage_drift);
    isk__pipeline_add(&pl, &isk__stage_slow);
    isk__pipeline_add(&pl, &isk__stage_spin);
    isk__pipeline_add(&pl, &isk__stage_age);
    cr_assert_eq(isk__pipeline_rest_prefix(&pl), 3);
    isk__pipeline_init(&pl);
    isk__pipeline_add(&pl, &isk__stage_field);
    isk__pipeline_add(&pl, &isk__stage_drift);
    cr_assert_eq(isk__pipeline_rest_prefix(&pl), 0, "a field has a clock");
    isk__pipeline_init(&pl);
    isk__pipeline_add(&pl, &isk__stage_drift_sway);
    cr_assert_eq(isk__pipeline_rest_prefix(&pl), 0, "the sway's phase moves on");
    isk__pipeline_init(&pl);
    isk__pipeline_add(&pl, &isk__stage_age);
    cr_assert_eq(isk__pipeline_rest_prefix(&pl), 0, "nothing to skip");
}

/* ---- the effect --------------------------------------------------------------- */

static const char *SCENE = "[scene]\nwidth = 160\nheight = 120\ndt = 1/60\nseed = 4\n"
                           "[view]\nxmin = -4\nxmax = 4\nymin = -3\nymax = 3\n"
                           "[force gravity]\ng = 9.81\n[force drag]\nb = 0.3\n"
                           "[force lift]\nkind = wind\nacceleration = 0, 0\n"
                           "[bounds]\nmode = reflect\nsides = all\nrestitution = 0.3\n"
                           "[emitter layer]\nsource = layer\ncount = 3000\nrect = -3.9, 3.9, -2.9, 2.9\n"
                           "forces = gravity, drag, lift\ndraw = dot\ncolor = #ffc878a0\n"
                           "[emitter sparks]\nsource = stream\nposition = -3.5, 0\nshape = segment\nshape_a = 7\n"
                           "count = 1024\nrate = 30\nlife = 3\nlife_range = 6\nforces = gravity, drag\n"
                           "draw = dot\nblend = add\ncolor = #80c0ff\n"
                           "[emitter drops]\nsource = stream\nposition = -3.5, 0\nshape = segment\nshape_a = 7\n"
                           "count = 1024\nrate = 30\nlife = 4\nlife_range = 2\nforces = gravity, drag\ndraw = dot\ncolor = #40ff80\n";

static int same_effect(isk_effect *a, isk_effect *b)
{
    for (int gi = 0; gi < a->ngroups; gi++)
        if (!same_store(&a->groups[gi].store, &b->groups[gi].store))
            return 0;
    return 1;
}

static void render_both(isk_effect *a, isk_effect *b, isk_canvas *ca, isk_canvas *cb, int frame, int threads)
{
    cr_assert_eq(isk_effect_render(a, ca), ISK_OK);
    cr_assert_eq(isk_effect_render(b, cb), ISK_OK);
    cr_assert(!memcmp(ca->pixels, cb->pixels, (size_t)ca->stride * (size_t)ca->height),
              "%d threads, frame %d: the canvases differ", threads, frame);
}

Test(rest, effect_same_bytes_on_every_thread_count)
{
    SKIP_WITHOUT(ISK__FAST_REST, "blocks at rest");
    for (int threads = 1; threads <= 3; threads++) {
        isk_effect *a = scene_text_open(SCENE, threads), *b = scene_text_open(SCENE, threads);
        b->no_rest = 1;
        a->update_min_work = b->update_min_work = 0; /* the groups are small: share their updates all the same */
        cr_assert(a->groups[0].rests && a->groups[1].rests && a->groups[2].rests, "every group may rest");
        isk_canvas ca, cb;
        cr_assert_eq(isk_canvas_init(&ca, 160, 120), ISK_OK);
        cr_assert_eq(isk_canvas_init(&cb, 160, 120), ISK_OK);
        cr_assert(a->groups[1].cull_unordered && !a->groups[2].cull_unordered, "sparks fill holes, drops keep order");
        size_t rested = 0, most[3] = {0, 0, 0};
        for (int frame = 1; frame <= 700; frame++) {
            cr_assert_eq(isk_effect_step(a), ISK_OK);
            cr_assert_eq(isk_effect_step(b), ISK_OK);
            for (int gi = 1; gi < 3; gi++) {
                size_t r = isk__rest_blocks(&a->groups[gi].rest, a->groups[gi].store.count, BOTH);
                most[gi] = r > most[gi] ? r : most[gi];
            }
            if (frame % 50 == 0) {
                cr_assert(same_effect(a, b), "%d threads, frame %d: the stores differ", threads, frame);
                render_both(a, b, &ca, &cb, frame, threads);
            }
            if (frame == 510)
                cr_assert_eq(isk__rest_blocks(&a->groups[0].rest, a->groups[0].store.count, BOTH), 0, "lifted: none rests");
            if (frame == 500) { /* settled: a wind lifts the layer off the floor (to rest on the ceiling) */
                rested = isk__rest_blocks(&a->groups[0].rest, a->groups[0].store.count, BOTH);
                isk_error err;
                cr_assert_eq(isk_effect_set(a, "force lift", "acceleration", "0, 20", &err), ISK_OK, "%s",
                             err.message);
                cr_assert_eq(isk_effect_set(b, "force lift", "acceleration", "0, 20", &err), ISK_OK, "%s",
                             err.message);
            }
        }
        cr_assert_gt(rested, 3000 / ISK_SIM_BLOCK / 2, "%zu of the layer's blocks rested by frame 500", rested);
        cr_assert_gt(most[1], 0, "the sparks' blocks rest between their culls");
        cr_assert_gt(most[2], 0, "the drops' blocks rest before their first deaths");
        cr_assert(same_effect(a, b));
        isk_canvas_free(&ca);
        isk_canvas_free(&cb);
        isk_effect_destroy(a);
        isk_effect_destroy(b);
    }
}

/* The thesis's simulator: a click's Coulomb explosion kicks every particle
 * of the emitter, those at rest too. */
Test(rest, a_click_kicks_the_particles_at_rest)
{
    SKIP_WITHOUT(ISK__FAST_REST, "blocks at rest");
    static const char *const text =
        "[scene]\nwidth = 100\nheight = 100\n[view]\nxmin = 0\nxmax = 10\nymin = 0\nymax = 10\n"
        "[force gravity]\ng = 9.81\n[bounds]\nmode = reflect\nsides = all\nrestitution = 0.3\n"
        "[emitter particles]\nsource = layer\ncount = 2000\nrect = 0, 10, 0, 3\nforces = gravity\n"
        "[click]\nexplosion = coulomb\ncount = 500\nemitter = particles\n";
    isk_effect *a = scene_text_open(text, 2), *b = scene_text_open(text, 2);
    b->no_rest = 1;
    for (int frame = 1; frame <= 400; frame++) {
        cr_assert_eq(isk_effect_step(a), ISK_OK);
        cr_assert_eq(isk_effect_step(b), ISK_OK);
        if (frame == 300) {
            cr_assert_gt(isk__rest_blocks(&a->groups[0].rest, a->groups[0].store.count, BOTH), 10);
            cr_assert_eq(isk_effect_click(a, 5, 1), ISK_OK);
            cr_assert_eq(isk_effect_click(b, 5, 1), ISK_OK);
        }
    }
    cr_assert(same_effect(a, b));
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

Test(rest, groups_that_may_not_rest)
{
    static const char *const scenes[] = {
        /* a potential */
        "[force well]\nkind = potential\nposition = 0, 0\nk = 1\n"
        "[emitter e]\nsource = layer\ncount = 10\nrect = -1, 1, -1, 1\nforces = well\n",
        /* bounces counted for a sub-emitter */
        "[bounds]\nmode = reflect\nsides = all\n[force gravity]\ng = 9.81\n"
        "[emitter e]\nsource = layer\ncount = 10\nrect = -1, 1, -1, 1\nforces = gravity\non_hit = s\n"
        "[emitter s]\nsource = sub\ncount = 1\nlife = 1\n",
        /* local space: the emitter carries its particles */
        "[emitter e]\nsource = stream\nrate = 10\nspace = local\nemitter_velocity = 1, 0\n",
    };
    for (size_t k = 0; k < sizeof scenes / sizeof scenes[0]; k++) {
        isk_effect *fx = scene_text_open(scenes[k], 1);
        cr_assert_eq(fx->groups[0].rests, 0, "scene %zu", k);
        isk_effect_destroy(fx);
    }
}
