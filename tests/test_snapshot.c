/* SPDX-License-Identifier: MIT */
/* Snapshots (iskra/snapshot.h): for every built-in scene, the snapshot of
 * every frame of a short run, restored (into another effect, in memory and
 * through the file's bytes) and stepped to the run's end, gives the
 * straight run's particles, counts and pixels, on 1 and 2 threads; live
 * changes and hand-made births are part of what is kept; a damaged or
 * hostile file is refused and leaves the effect as it was. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/canvas.h"
#include "iskra/effect.h"
#include "iskra/outfile.h"
#include "iskra/probes.h"
#include "iskra/scene.h"
#include "iskra/snapshot.h"
#include "scene_text.h"

enum { FRAMES = 6 };

/* What a run shows at its end: the pixels of a render on a cleared canvas,
 * every particle's state, the counts. */
typedef struct outcome {
    unsigned char *pixels;
    size_t npixels;
    double *state;
    size_t nstate;
    long frame;
    double time;
    uint64_t dropped;
} outcome;

static void look(isk_effect *fx, outcome *o)
{
    const isk_effect_def *d = isk_effect_definition(fx);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, d->width, d->height), ISK_OK);
    isk_canvas_fill(&c, d->background);
    cr_assert_eq(isk_effect_render(fx, &c), ISK_OK);
    o->npixels = c.stride * (size_t)c.height;
    o->pixels = malloc(o->npixels);
    memcpy(o->pixels, c.pixels, o->npixels);
    isk_canvas_free(&c);
    o->nstate = 0;
    o->dropped = 0;
    for (int g = 0; g < isk_effect_emitter_count(fx); g++) {
        o->nstate += 8 * isk_effect_particles(fx, g)->count;
        o->dropped += isk_effect_dropped(fx, g) + isk_effect_removed_nonfinite(fx, g);
    }
    o->state = malloc(sizeof *o->state * (o->nstate ? o->nstate : 1));
    size_t k = 0;
    for (int g = 0; g < isk_effect_emitter_count(fx); g++) {
        const isk_particles *p = isk_effect_particles(fx, g);
        for (size_t i = 0; i < p->count; i++) {
            const double v[8] = {p->x[i],   p->y[i],    p->vx[i], p->vy[i], p->m[i], p->age[i], p->life[i],
                                 p->angle ? p->angle[i] : 0.0};
            memcpy(o->state + k, v, sizeof v);
            k += 8;
        }
    }
    o->frame = isk_effect_frame(fx);
    o->time = isk_effect_time(fx);
}

static void expect_same(const outcome *a, const outcome *b, const char *what)
{
    cr_assert_eq(a->frame, b->frame, "%s: frame", what);
    cr_assert_eq(a->time, b->time, "%s: time", what);
    cr_assert_eq(a->dropped, b->dropped, "%s: dropped", what);
    cr_assert_eq(a->nstate, b->nstate, "%s: particles %zu vs %zu", what, a->nstate / 8, b->nstate / 8);
    cr_assert_eq(memcmp(a->state, b->state, sizeof *a->state * a->nstate), 0, "%s: particles differ", what);
    cr_assert_eq(a->npixels, b->npixels, "%s", what);
    cr_assert_eq(memcmp(a->pixels, b->pixels, a->npixels), 0, "%s: pixels differ", what);
}

static void outcome_free(outcome *o)
{
    free(o->pixels);
    free(o->state);
}

static isk_effect *open_builtin(const char *name, int threads)
{
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load(&d, name, &err), ISK_OK, "%s: %s", name, err.message);
    d.threads = threads;
    return scene_open_def(&d);
}

/* Every frame's snapshot of one scene, restored into `other` (in memory and
 * through its bytes) and run to the end, against the straight run. */
static void every_frame(const char *name, int threads, isk_effect *other)
{
    isk_effect *fx = open_builtin(name, threads);
    isk_snapshot *snap[FRAMES + 1];
    isk_error err = {0};
    for (int f = 0; f <= FRAMES; f++) {
        cr_assert_eq(isk_effect_snapshot(fx, &snap[f], &err), ISK_OK, "%s", err.message);
        cr_assert_eq(isk_snapshot_frame(snap[f]), f);
        if (f < FRAMES)
            cr_assert_eq(isk_effect_step(fx), ISK_OK);
    }
    outcome straight;
    look(fx, &straight);
    char what[160];
    for (int f = 0; f <= FRAMES; f++) {
        snprintf(what, sizeof what, "%s, %d thread(s), from frame %d", name, threads, f);
        cr_assert_eq(isk_effect_restore(other, snap[f], &err), ISK_OK, "%s: %s", what, err.message);
        for (int k = f; k < FRAMES; k++)
            cr_assert_eq(isk_effect_step(other), ISK_OK);
        outcome again;
        look(other, &again);
        expect_same(&straight, &again, what);
        outcome_free(&again);
    }
    /* through the file's bytes (a scene with a potential moved by C code cannot be written) */
    unsigned char *bytes;
    size_t n;
    if (isk_snapshot_encode(snap[2], &bytes, &n, &err) == ISK_OK) {
        isk_snapshot *back;
        cr_assert_eq(isk_snapshot_decode(&back, bytes, n, name, &err), ISK_OK, "%s: %s", name, err.message);
        cr_assert_eq(isk_effect_restore(other, back, &err), ISK_OK, "%s: %s", name, err.message);
        for (int k = 2; k < FRAMES; k++)
            cr_assert_eq(isk_effect_step(other), ISK_OK);
        outcome again;
        look(other, &again);
        snprintf(what, sizeof what, "%s, %d thread(s), from frame 2's file", name, threads);
        expect_same(&straight, &again, what);
        outcome_free(&again);
        unsigned char *bytes2;
        size_t n2;
        cr_assert_eq(isk_snapshot_encode(back, &bytes2, &n2, &err), ISK_OK, "%s", err.message);
        cr_assert(n2 == n && memcmp(bytes, bytes2, n) == 0, "%s: a decoded snapshot encodes to other bytes", name);
        free(bytes2);
        isk_snapshot_free(back);
        free(bytes);
    }
    for (int f = 0; f <= FRAMES; f++)
        isk_snapshot_free(snap[f]);
    outcome_free(&straight);
    isk_effect_destroy(fx);
}

static void every_scene(int threads)
{
    isk_effect *other = scene_text_open("[emitter x]\nsource = stream\nrate = 5\n", threads);
    for (int i = 0; i < isk_scene_builtin_count(); i++)
        every_frame(isk_scene_builtin_name(i), threads, other);
    isk_effect_destroy(other);
}

Test(snapshot, every_scene_every_frame_one_thread, .timeout = 300) { every_scene(1); }
Test(snapshot, every_scene_every_frame_two_threads, .timeout = 300) { every_scene(2); }

/* Live changes, a potential added, births by hand: all part of the state. */
Test(snapshot, live_changes_and_hand_births_are_kept)
{
    const char *text = "[scene]\nwidth = 100\nheight = 80\nseed = 3\n"
                       "[force gravity]\ng = 9.81\n"
                       "[bounds]\nsides = left, right, bottom\n"
                       "[emitter sparks]\nsource = stream\nrate = 120\nlaunch = cone\nangle = 90\nspread = 50\n"
                       "speed_min = 4\nspeed_max = 8\nlife = 1.5\ncapacity = 400\nforces = gravity\ntrail = 5\n"
                       "size_range = 0.05\ndraw = disc\nsize = 0.1\n"
                       "[emitter cycles]\nsource = stream\nrate = 30\nduration = 0.3\nloop = true\ncount = 4\n"
                       "burst_every = 0.1\nlife = 0.7\nlaunch = disc\nspeed_max = 2\nprewarm = 0.5\n";
    isk_effect *a = scene_text_open(text, 1), *b = scene_text_open(text, 2);
    isk_error err = {0};
    for (int f = 0; f < 10; f++)
        cr_assert_eq(isk_effect_step(a), ISK_OK);
    cr_assert_eq(isk_effect_set(a, "force gravity", "g", "3", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_set(a, "emitter sparks", "rate", "77", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_set(a, "emitter cycles", "emitter_velocity", "0.5, 0.25", &err), ISK_OK, "%s",
                 err.message);
    isk_potential pot;
    isk_potential_init(&pot, 20.0, (isk_vec2){1, 4}, 1.0);
    cr_assert_eq(isk_effect_add_potential(a, "magnet", &pot, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_move(a, "emitter sparks", 2, 1, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_emit(a, "emitter sparks", 30, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_step(a), ISK_OK); /* mid-move */
    isk_snapshot *snap;
    cr_assert_eq(isk_effect_snapshot(a, &snap, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_restore(b, snap, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_threads(b), 2, "a restore keeps the effect's threads");
    for (int f = 0; f < 40; f++) {
        cr_assert_eq(isk_effect_step(a), ISK_OK);
        cr_assert_eq(isk_effect_step(b), ISK_OK);
    }
    outcome oa, ob;
    look(a, &oa);
    look(b, &ob);
    expect_same(&oa, &ob, "after live changes");
    outcome_free(&oa);
    outcome_free(&ob);
    /* the definition came along: the live gravity, the added potential */
    char v[64];
    cr_assert_eq(isk_effect_get(b, "force gravity", "g", v, sizeof v, &err), ISK_OK);
    cr_assert_str_eq(v, "3");
    size_t npots;
    isk_effect_potentials(b, &npots);
    cr_assert_eq(npots, 1);
    /* and a reset of the restored effect starts its (live) definition again */
    cr_assert_eq(isk_effect_reset(b), ISK_OK);
    cr_assert_eq(isk_effect_frame(b), 0);
    isk_snapshot_free(snap);
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

static isk_snapshot *small_snapshot(unsigned char **bytes, size_t *n)
{
    isk_effect *fx = scene_text_open("[emitter e]\nsource = stream\nrate = 50\nlife = 2\ntrail = 3\n"
                                     "[emitter boom]\nsource = explosion\nexplosion = multi-coulomb\ncount = 900\n",
                                     1);
    for (int f = 0; f < 20; f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    isk_snapshot *snap;
    isk_error err = {0};
    cr_assert_eq(isk_effect_snapshot(fx, &snap, &err), ISK_OK);
    cr_assert_eq(isk_snapshot_encode(snap, bytes, n, &err), ISK_OK, "%s", err.message);
    isk_effect_destroy(fx);
    return snap;
}

/* A damaged file is refused whole: every byte flipped in turn, and the
 * file cut at every length; the effect it was to be restored into is
 * untouched.  (The checksum catches flips; the checks behind it are
 * tried by re-sealing the damaged bytes with a good checksum.) */
static uint64_t fnv(const unsigned char *b, size_t n)
{
    uint64_t h = 0xcbf29ce484222325ull;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * 0x100000001b3ull;
    return h;
}

static void reseal(unsigned char *b, size_t n)
{
    uint64_t h = fnv(b, n - 8);
    for (int i = 0; i < 8; i++)
        b[n - 8 + (size_t)i] = (unsigned char)(h >> (8 * i));
}

Test(snapshot, damaged_files_are_refused, .timeout = 300)
{
    unsigned char *bytes;
    size_t n;
    isk_snapshot *snap = small_snapshot(&bytes, &n);
    isk_error err = {0};
    isk_snapshot *back = NULL;
    unsigned char *copy = malloc(n);
    for (size_t cut = 0; cut < n; cut += 1 + cut / 64) {
        cr_assert_neq(isk_snapshot_decode(&back, bytes, cut, "cut", &err), ISK_OK, "cut at %zu accepted", cut);
        cr_assert_null(back);
    }
    memcpy(copy, bytes, n);
    copy[n / 2] ^= 1;
    cr_assert_eq(isk_snapshot_decode(&back, copy, n, "flip.snap", &err), ISK_ERR_FORMAT);
    cr_assert_str_eq(err.message, "flip.snap: the snapshot is damaged (its checksum does not match)");
    /* resealed damage: refused by the checks, or accepted and then runnable */
    isk_effect *fx = scene_text_open("[emitter x]\nsource = stream\nrate = 5\n", 1);
    size_t accepted = 0;
    uint64_t text = 0; /* the scene text's length, after the header line */
    for (int i = 0; i < 8; i++)
        text |= (uint64_t)bytes[17 + i] << (8 * i);
    const size_t whole = 25 + (size_t)text + 1200; /* the header, the scene, the rows: every byte; the particles sampled */
    for (size_t i = 0; i + 8 < n; i += i < whole ? 1 : 53)
        for (int bit = 0; bit < 8; bit += 3) {
            memcpy(copy, bytes, n);
            copy[i] ^= (unsigned char)(1u << bit);
            reseal(copy, n);
            isk_status s = isk_snapshot_decode(&back, copy, n, "hostile", &err);
            if (s != ISK_OK) {
                cr_assert_null(back);
                continue;
            }
            accepted++;
            if (isk_effect_restore(fx, back, &err) == ISK_OK)
                for (int f = 0; f < 3; f++)
                    cr_assert_eq(isk_effect_step(fx), ISK_OK);
            isk_snapshot_free(back);
            back = NULL;
        }
    cr_assert_gt(accepted, 0, "no flip was a valid snapshot: the check saw nothing (the last refusal: %s)",
                 err.message);
    free(copy);
    free(bytes);
    isk_snapshot_free(snap);
    isk_effect_destroy(fx);
}

static isk_vec2 circle(void *ctx, double t)
{
    (void)ctx;
    return (isk_vec2){cos(t), sin(t)};
}

Test(snapshot, refusals_name_the_problem)
{
    isk_error err = {0};
    isk_snapshot *back = NULL;
    const unsigned char junk[] = "PNG not a snapshot at all, really";
    cr_assert_eq(isk_snapshot_decode(&back, junk, sizeof junk, "x.snap", &err), ISK_ERR_FORMAT);
    cr_assert_str_eq(err.message, "x.snap: not an iskra snapshot (it does not start with \"ISKRA-SNAPSHOT 1\")");
    cr_assert_eq(isk_effect_snapshot(NULL, &back, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_restore(NULL, NULL, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_snapshot_load(&back, "/nonexistent/x.snap", &err), ISK_ERR_IO);
    isk_snapshot_free(NULL);
    /* a potential moved by a C function cannot go to a file */
    isk_effect *fx = scene_text_open("[emitter e]\nsource = stream\nrate = 5\n", 1);
    isk_potential pot;
    isk_potential_init(&pot, 1.0, (isk_vec2){0, 0}, 1.0);
    pot.motion = circle;
    cr_assert_eq(isk_effect_add_potential(fx, "p", &pot, &err), ISK_OK, "%s", err.message);
    isk_snapshot *snap;
    cr_assert_eq(isk_effect_snapshot(fx, &snap, &err), ISK_OK);
    unsigned char *bytes;
    size_t n;
    cr_assert_eq(isk_snapshot_encode(snap, &bytes, &n, &err), ISK_ERR_FORMAT);
    cr_assert_str_eq(err.message, "snapshot: potential 1 is moved by a C function, which a file cannot hold");
    isk_snapshot_free(snap);
    isk_effect_destroy(fx);
}

/* A file written and read back: save, load, run (two processes:
 * tests/test_snapshot_cli.c). */
Test(snapshot, a_file_resumes_the_run)
{
    unsigned char *bytes;
    size_t n;
    isk_snapshot *snap = small_snapshot(&bytes, &n);
    isk_error err = {0};
    cr_assert_eq(isk_make_dirs("build/test-out/snapshot", &err), ISK_OK, "%s", err.message);
    const char *path = "build/test-out/snapshot/at20.snap";
    cr_assert_eq(isk_snapshot_save(snap, path, &err), ISK_OK, "%s", err.message);
    isk_snapshot *back;
    cr_assert_eq(isk_snapshot_load(&back, path, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_snapshot_frame(back), 20);
    isk_effect *a = scene_text_open("[emitter q]\nsource = stream\nrate = 1\n", 1);
    isk_effect *b = scene_text_open("[emitter q]\nsource = stream\nrate = 1\n", 1);
    cr_assert_eq(isk_effect_restore(a, snap, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_restore(b, back, &err), ISK_OK, "%s", err.message);
    for (int f = 0; f < 30; f++) {
        cr_assert_eq(isk_effect_step(a), ISK_OK);
        cr_assert_eq(isk_effect_step(b), ISK_OK);
    }
    outcome oa, ob;
    look(a, &oa);
    look(b, &ob);
    expect_same(&oa, &ob, "from the file");
    cr_assert_gt(oa.nstate, 0);
    outcome_free(&oa);
    outcome_free(&ob);
    cr_assert_gt(isk_snapshot_bytes(back), 1000);
    isk_snapshot_free(snap);
    isk_snapshot_free(back);
    free(bytes);
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

/* a runs `before` frames and is kept; it runs `after` more.  b (another
 * effect) restored from the snapshot, in memory and then from its bytes,
 * runs `after` frames: it ends as a did, its probes reading alike. */
static void restored_goes_on_alike(isk_effect *a, isk_effect *b, int before, int after, const char *what)
{
    isk_error err = {0};
    for (int f = 0; f < before; f++)
        cr_assert_eq(isk_effect_step(a), ISK_OK);
    isk_snapshot *snap, *back;
    cr_assert_eq(isk_effect_snapshot(a, &snap, &err), ISK_OK);
    unsigned char *bytes;
    size_t n;
    cr_assert_eq(isk_snapshot_encode(snap, &bytes, &n, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_snapshot_decode(&back, bytes, n, what, &err), ISK_OK, "%s", err.message);
    for (int f = 0; f < after; f++)
        cr_assert_eq(isk_effect_step(a), ISK_OK);
    outcome oa;
    look(a, &oa);
    const isk_snapshot *from[2] = {snap, back};
    for (int k = 0; k < 2; k++) {
        char where[160];
        snprintf(where, sizeof where, "%s, %s", what, k ? "from bytes" : "in memory");
        cr_assert_eq(isk_effect_restore(b, from[k], &err), ISK_OK, "%s", err.message);
        for (int f = 0; f < after; f++)
            cr_assert_eq(isk_effect_step(b), ISK_OK);
        cr_assert_eq(isk_effect_probe_count(b), isk_effect_probe_count(a));
        for (int i = 0; i < isk_effect_probe_count(a); i++) {
            isk_probe_reading ra, rb;
            cr_assert_eq(isk_effect_probe_read(a, i, &ra), ISK_OK);
            cr_assert_eq(isk_effect_probe_read(b, i, &rb), ISK_OK);
            cr_assert_str_eq(ra.name, rb.name);
            cr_assert(ra.forward == rb.forward && ra.backward == rb.backward && ra.rate_forward == rb.rate_forward &&
                          ra.count == rb.count && ra.kinetic == rb.kinetic && ra.frame == rb.frame &&
                          !memcmp(ra.bin, rb.bin, sizeof ra.bin),
                      "probe %s differs after a restore (%s)", ra.name, where);
        }
        outcome ob;
        look(b, &ob);
        expect_same(&oa, &ob, where);
        outcome_free(&ob);
    }
    outcome_free(&oa);
    free(bytes);
    isk_snapshot_free(snap);
    isk_snapshot_free(back);
}

/* Probes are part of the state: a gate's crossings (drawn beside it) and
 * its window of rates come back with the frame. */
static isk_effect *probes_scene(void)
{
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load_file(&d, "tests/data/probes_stream.ini", &err), ISK_OK, "%s", err.message);
    d.threads = 1;
    return scene_open_def(&d);
}

Test(snapshot, probes_come_back_with_their_counts)
{
    isk_effect *a = probes_scene(), *b = probes_scene();
    cr_assert_gt(isk_effect_probe_count(a), 2);
    restored_goes_on_alike(a, b, 70, 40, "probes");
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}

/* The everyday settings' per-particle values (their columns), random
 * streams and draw orders come back too. */
static const char everyday[] =
    "[scene]\nwidth = 200\nheight = 120\nseed = 3\n[view]\nxmin = 0\nxmax = 25\nymin = 0\nymax = 10\n"
    "[force gravity]\ng = 9.81\n[force wind]\nacceleration = -3, 0\n"
    "[emitter swirl]\nsource = stream\nposition = 5, 5\nrate = 120\nlife = 2\nshape = gaussian\nshape_a = 1\n"
    "shape_b = 0.5\nlaunch = direction\nangle = 90\nspeed_min = 2\nspeed_max = 2\nlaunch_outward = true\n"
    "radial_accel = -2\nradial_accel_range = 1\ntangential_accel_range = 3\nspin = 90\nspin_end = -90\n"
    "draw = sprite\nsize = 0.6\ndraw_order = random\n"
    "[emitter fountain]\nsource = stream\nposition = 13, 1\nrate = 150\nlife = 1.5\nshape = rect_border\n"
    "shape_a = 1\nshape_b = 0.5\nlaunch = cone\nangle = 90\nspread = 10\nspeed_min = 9\nspeed_max = 10\n"
    "forces = gravity, wind\nwind_range = 6, 0\ndraw_order = oldest\ndraw = disc\nsize = 0.3\n"
    "[emitter jet]\nsource = stream\nposition = 17.5, 5\nrate = 150\nlife = 3\nshape = ellipse_border\n"
    "shape_a = 1\nshape_b = 0.5\nlaunch = cone\nangle = 0\nspread = 30\nspeed_min = 6\nspeed_max = 6\n"
    "slowing = 1\nslowing_range = 3\n";

Test(snapshot, everyday_settings_come_back)
{
    isk_effect *a = scene_text_open(everyday, 1), *b = scene_text_open(everyday, 2);
    restored_goes_on_alike(a, b, 40, 40, "everyday settings");
    isk_effect_destroy(a);
    isk_effect_destroy(b);
}
