/* SPDX-License-Identifier: MIT */
/* Threads never change a byte: every shipped scene, and scenes large enough
 * that the blocks really are shared out, give the same canvas and the same
 * particles, bit for bit, on 1, 2, 3 and 7 threads; lists whose particles'
 * order matters (a potential that can switch itself off, a deflector that
 * draws at random) run in order and still match.
 *
 * A plain program, not a Criterion test, so that it also runs under
 * ThreadSanitizer (Criterion's process arena does not start under TSan):
 * tests/run_all.sh runs it in every build, and CI builds it with
 * `make threads-check SANITIZE=thread`.  Exit status 0 when everything
 * matches. */
#include <dirent.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "scene/effect_internal.h" /* band_min_work */
#include "core/fast_paths.h"
#include "sim/pool.h"

static const int THREADS[] = {1, 2, 3, 7};
#define NT (int)(sizeof THREADS / sizeof THREADS[0])
static int failures;
/* Whether a run's bands of columns drew in copies of the canvas of their
 * own (effect_bands.c), since it was last cleared. */
static int drew_in_copies;
/* Draws of additive groups split among the threads (effect_bands.c's
 * split_particles), over the whole check. */
static long splits;
/* Draws of a group at rest replayed from its recorded blends (effect_retain.c). */
static long replays;

#define CHECK(cond, ...)                                                                                        \
    do {                                                                                                       \
        if (!(cond)) {                                                                                         \
            fprintf(stderr, "threads_check: " __VA_ARGS__);                                                    \
            fputc('\n', stderr);                                                                               \
            failures++;                                                                                        \
        }                                                                                                      \
    } while (0)

/* `frames` frames on `threads` threads, additive groups split among them
 * (split) or cut into bands like the others, then drawn once more: the
 * canvas, and a hash of every particle's state (0 when the effect could
 * not be made). */
static unsigned long long run(const isk_effect_def *d, int threads, int split, long frames, isk_canvas *c)
{
    isk_effect_def copy = *d;
    copy.threads = threads;
    isk_effect *fx = NULL;
    isk_error err = {0};
    memset(c, 0, sizeof *c);
    const int made = isk_effect_create(&fx, &copy, &err) == ISK_OK;
    if (made) {
        fx->band_min_work = 0; /* every group's draw in bands, however small: those are what is checked */
        fx->update_min_work = 0; /* and every update that can be shared out */
        fx->split_always = split;
    }
    if (!made || isk_canvas_init(c, d->width, d->height) != ISK_OK || isk_effect_run(fx, c, frames) != ISK_OK) {
        CHECK(0, "%d threads: %s", threads, err.message);
        isk_effect_destroy(fx);
        return 0;
    }
    CHECK(isk_effect_threads(fx) == threads, "asked for %d threads, got %d", threads, isk_effect_threads(fx));
    /* drawn once more, the same state: the same bytes (a group at rest now
     * replays what the first draw recorded, effect_retain.c) */
    isk_canvas again;
    if (d->clear && isk_canvas_init(&again, d->width, d->height) == ISK_OK) {
        CHECK(isk_effect_render(fx, &again) == ISK_OK && isk_canvas_equal(c, &again),
              "%d threads: drawn again, other bytes", threads);
        isk_canvas_free(&again);
    }
    unsigned long long h = 1469598103934665603ull;
    for (int g = 0; g < isk_effect_emitter_count(fx); g++) {
        const isk_particles *p = isk_effect_particles(fx, g);
        const double *cols[] = {p->x, p->y, p->vx, p->vy, p->age};
        for (int k = 0; k < 5; k++)
            for (size_t i = 0; i < p->count; i++) {
                unsigned long long b;
                memcpy(&b, &cols[k][i], sizeof b);
                h = (h ^ b) * 1099511628211ull;
            }
    }
    drew_in_copies |= fx->bins.copies != NULL;
    splits += fx->bins.splits;
    for (int g = 0; g < fx->ngroups; g++)
        replays += fx->groups[g].retained.replays;
    isk_effect_destroy(fx);
    return h;
}

static void same_on_every_count(const isk_effect_def *d, long frames, const char *name)
{
    isk_canvas ref;
    unsigned long long href = run(d, 1, 0, frames, &ref);
    for (int t = 1; t < NT; t++)
        for (int split = 0; split < 2; split++) {
            isk_canvas c;
            unsigned long long h = run(d, THREADS[t], split, frames, &c);
            const char *how = split ? " (additive groups split)" : "";
            CHECK(isk_canvas_equal(&ref, &c), "%s: %d threads draw other bytes%s", name, THREADS[t], how);
            CHECK(h == href, "%s: %d threads move the particles differently%s", name, THREADS[t], how);
            isk_canvas_free(&c);
        }
    isk_canvas_free(&ref);
}

static void scene_text(const char *text, const char *name, long frames)
{
    isk_effect_def d;
    isk_error err = {0};
    if (isk_scene_load_string(&d, text, name, &err) != ISK_OK) {
        CHECK(0, "%s", err.message);
        return;
    }
    same_on_every_count(&d, frames, name);
    isk_effect_def_free(&d);
}

/* The thread ids of this process (Linux: /proc/self/task); at most cap. */
static int list_tasks(int *ids, int cap)
{
    int n = 0;
    DIR *dir = opendir("/proc/self/task");
    struct dirent *e;
    while (dir && (e = readdir(dir)))
        if (e->d_name[0] != '.' && n < cap)
            ids[n++] = atoi(e->d_name);
    if (dir)
        closedir(dir);
    return n;
}

static void *nothing(void *arg)
{
    return arg;
}

/* The library's workers block every signal, so a program's handler runs on
 * its own threads (Linux: each task's SigBlk mask in /proc).  Threads that
 * were there before the effect are not its workers: ThreadSanitizer starts
 * its own at the process's first pthread_create, so one is made first. */
static void workers_block_signals(void)
{
    isk_effect_def d;
    isk_error err = {0};
    if (isk_scene_load(&d, "fig16_regular", &err) != ISK_OK) {
        CHECK(0, "%s", err.message);
        return;
    }
    d.threads = 3;
    pthread_t t0;
    if (pthread_create(&t0, NULL, nothing, NULL) == 0)
        pthread_join(t0, NULL);
    int before[64], after[64];
    const int nbefore = list_tasks(before, 64);
    isk_effect *fx = NULL;
    if (isk_effect_create(&fx, &d, &err) != ISK_OK) {
        CHECK(0, "%s", err.message);
        isk_effect_def_free(&d);
        return;
    }
    const int nafter = list_tasks(after, 64);
    int workers = 0;
    for (int t = 0; t < nafter; t++) {
        int old = 0;
        for (int u = 0; u < nbefore; u++)
            old |= before[u] == after[t];
        if (old)
            continue;
        char path[64], line[256];
        snprintf(path, sizeof path, "/proc/self/task/%d/status", after[t]);
        FILE *f = fopen(path, "r");
        while (f && fgets(line, sizeof line, f))
            if (!strncmp(line, "SigBlk:", 7)) {
                unsigned long long mask = strtoull(line + 7, NULL, 16);
                CHECK((mask >> (SIGINT - 1) & 1) && (mask >> (SIGTERM - 1) & 1),
                      "worker %d does not block SIGINT and SIGTERM (SigBlk %llx)", after[t], mask);
                workers++;
            }
        if (f)
            fclose(f);
    }
    CHECK(workers == (ISK__FAST_WORKERS ? 2 : 0), "found %d new threads, expected %d workers", workers,
          ISK__FAST_WORKERS ? 2 : 0);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* A job of as many items as threads runs them all at once, one a thread
 * (a draw's bands): each item waits until every item has started.  Handed
 * out in chunks of several, the first thread took them all, so the draw's
 * bands ran one after the other. */
typedef struct together {
    atomic_int started;
    int ok[3];
} together;

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void wait_for_all(void *ctx, int worker, size_t item)
{
    (void)worker;
    together *t = ctx;
    atomic_fetch_add(&t->started, 1);
    const double t0 = seconds();
    while (atomic_load(&t->started) < 3 && seconds() - t0 < 10.0)
        ;
    t->ok[item] = atomic_load(&t->started) == 3;
}

static void items_run_together(void)
{
    isk_pool *pool = NULL;
    CHECK(isk__pool_create(&pool, 3) == ISK_OK, "pool of 3");
    if (!pool)
        return;
    together t = {.started = 0};
    isk__pool_for(pool, 3, wait_for_all, &t);
    CHECK(t.ok[0] && t.ok[1] && t.ok[2], "3 items on 3 threads did not run at the same time");
    isk__pool_destroy(pool);
}

/* Every item of a job is handed out once, to one of the pool's threads,
 * whatever the job's size against the claims' (pool.c's take_items: long
 * claims while much is left, one chunk at the end). */
typedef struct tally {
    atomic_int *count;
    int threads;
    atomic_int bad_worker;
} tally;

static void count_item(void *ctx, int worker, size_t item)
{
    tally *t = ctx;
    atomic_fetch_add(&t->count[item], 1);
    if (worker < 0 || worker >= t->threads)
        atomic_store(&t->bad_worker, 1);
}

static void every_item_once(void)
{
    static const size_t SIZES[] = {1, 2, 3, 5, 8, 63, 64, 65, 255, 257, 1000, 7813, 100003};
    static const int POOLS[] = {2, 3, 7};
    for (int k = 0; k < 3; k++) {
        isk_pool *pool = NULL;
        CHECK(isk__pool_create(&pool, POOLS[k]) == ISK_OK, "pool of %d", POOLS[k]);
        if (!pool)
            continue;
        for (size_t s = 0; s < sizeof SIZES / sizeof SIZES[0]; s++) {
            const size_t n = SIZES[s];
            tally t = {calloc(n, sizeof *t.count), POOLS[k], 0};
            if (!t.count)
                break;
            for (size_t i = 0; i < n; i++)
                atomic_init(&t.count[i], 0);
            isk__pool_for(pool, n, count_item, &t);
            size_t wrong = 0;
            for (size_t i = 0; i < n; i++)
                wrong += atomic_load(&t.count[i]) != 1;
            CHECK(wrong == 0, "%zu items on %d threads: %zu not run exactly once", n, POOLS[k], wrong);
            CHECK(!atomic_load(&t.bad_worker), "%zu items on %d threads: a worker number out of range", n,
                  POOLS[k]);
            free(t.count);
        }
        isk__pool_destroy(pool);
    }
}

int main(int argc, char **argv)
{
    workers_block_signals();
    items_run_together();
    every_item_once();
    /* --quick: the large scenes only (ThreadSanitizer is slow) */
    int quick = argc > 1 && !strcmp(argv[1], "--quick");
    for (int i = 0; !quick && i < isk_scene_builtin_count(); i++) {
        isk_effect_def d;
        isk_error err = {0};
        const char *name = isk_scene_builtin_name(i);
        if (isk_scene_load(&d, name, &err) != ISK_OK) {
            CHECK(0, "%s", err.message);
            continue;
        }
        same_on_every_count(&d, d.show.frames > 120 ? 120 : d.show.frames, name);
        isk_effect_def_free(&d);
    }
    /* Big enough that every substep shares its blocks out: gravity, drag, a
     * potential and walls on 60,000 particles, plus a stream with a deflector
     * and colour over life. */
    scene_text("[scene]\nwidth = 200\nheight = 150\nsubsteps = 2\nintegrator = rk4\n"
               "[force gravity]\ng = 9.81\n[force drag]\nb = 0.3\n"
               "[force well]\nkind = potential\nk = 30\nposition = 2, 3\nmin_distance = 0.5\n"
               "[deflector floor]\nsegment = -9, -6, 9, -7\nrestitution = 0.7\n"
               "[bounds]\nrestitution = 0.8\n"
               "[emitter cloud]\nsource = explosion\nexplosion = gauss\ncount = 60000\nlimit = 60000\n"
               "forces = gravity, drag, well\n"
               "[emitter fountain]\nsource = stream\nrate = 20000\nlife = 1.5\nlaunch = cone\nangle = 90\n"
               "spread = 40\nspeed_min = 5\nspeed_max = 9\nforces = gravity\ndeflectors = floor\n"
               "draw = sprite\nsize = 0.3\nblend = add\ncolor_over_life = 0:white, 1:#ff400000\n",
               "big", quick ? 10 : 40);
    /* Every draw cut into bands: browser dots, pixels, sprites (one
     * colour, and sized by a ramp) and discs, over and add, on more rows
     * than particles' worth of bands. */
    scene_text("[scene]\nwidth = 160\nheight = 120\nbackground = #102030\n"
               "[force gravity]\ng = 9.81\n"
               "[emitter a]\nsource = explosion\nexplosion = uniform\ncount = 20000\nlimit = 20000\n"
               "forces = gravity\ndraw = dot-browser\ncolor = #ff8040c0\n"
               "[emitter b]\nsource = explosion\nexplosion = gauss\ncount = 20000\nlimit = 20000\n"
               "draw = pixel\nblend = over\ncolor = #40ff80a0\n"
               "[emitter c]\nsource = explosion\nexplosion = ring\ncount = 20000\nlimit = 20000\n"
               "draw = sprite\nsize = 0.4\nblend = add\ncolor = #2040ff80\n"
               "[emitter d]\nsource = stream\nrate = 30000\nlife = 1\nlaunch = cone\nangle = 90\n"
               "spread = 60\nspeed_min = 2\nspeed_max = 6\nforces = gravity\ndraw = sprite\nsize = 0.5\n"
               "blend = over\nsize_over_life = 0:1, 1:0.2\n"
               "[emitter e]\nsource = explosion\nexplosion = gauss\ncount = 3000\nlimit = 3000\n"
               "forces = gravity\ndraw = disc\nsize = 0.3\nblend = over\ncolor = #ffc040a0\n",
               "draws", quick ? 10 : 40);
    /* Additive groups of every draw, split among the threads or cut into
     * bands: discs, dots coloured over their life, pixels, and sprites
     * sized over their life, all faint enough not to saturate (a particle
     * drawn twice, or by no one, shows). */
    const long splits_before = splits;
    scene_text("[scene]\nwidth = 160\nheight = 120\nbackground = #102030\n[force gravity]\ng = 9.81\n"
               "[emitter discs]\nsource = explosion\nexplosion = gauss\ncount = 3000\nlimit = 3000\n"
               "forces = gravity\ndraw = disc\nsize = 0.6\nblend = add\ncolor = #ff804010\n"
               "[emitter ramped]\nsource = explosion\nexplosion = uniform\ncount = 20000\nlimit = 20000\n"
               "life = 3\nforces = gravity\nblend = add\ncolor_over_life = 0:#ffffff20, 1:#ff400008\n"
               "[emitter pixels]\nsource = explosion\nexplosion = ring\ncount = 20000\nlimit = 20000\n"
               "draw = pixel\nblend = add\ncolor = #40ff8010\n"
               "[emitter sprites]\nsource = stream\nrate = 30000\nlife = 1\nlaunch = cone\nangle = 90\n"
               "spread = 60\nspeed_min = 2\nspeed_max = 6\nforces = gravity\ndraw = sprite\nsize = 0.5\n"
               "blend = add\ncolor = #2040ff18\nsize_over_life = 0:1, 1:0.2\n",
               "additive", quick ? 10 : 40);
    CHECK(!ISK__FAST_BANDS || splits > splits_before, "additive: no draw was split among the threads");
    /* A layer fallen onto its floor: most particles on the last row, so
     * the dots' bands are columns (effect_bands.c's place_cuts); exact-area
     * dots, the browser's and pixels, faint enough that the row does not
     * saturate (a dot drawn by the wrong band, or by none, shows). */
    drew_in_copies = 0;
    scene_text("[scene]\nwidth = 800\nheight = 60\nbackground = #20304080\n[force gravity]\ng = 400\n"
               "[bounds]\nrestitution = 0.2\n"
               "[emitter a]\nsource = layer\ncount = 20000\nlimit = 20000\nrect = -9, 9, -3, 6\n"
               "forces = gravity\ncolor = #ff804008\n"
               "[emitter b]\nsource = layer\ncount = 20000\nlimit = 20000\nrect = -9, 9, -3, 6\n"
               "forces = gravity\ndraw = dot-browser\nblend = add\ncolor = #10204010\n"
               "[emitter c]\nsource = layer\ncount = 20000\nlimit = 20000\nrect = -9, 9, -3, 6\n"
               "forces = gravity\ndraw = pixel\ncolor = #40ff8008\n",
               "settled", quick ? 30 : 60);
    CHECK(!ISK__FAST_BANDS || drew_in_copies, "settled: no band of columns drew in a copy of the canvas");
    /* Blocks at rest (sim/stage.h's isk_rest): a layer that settles in a
     * third of a second and stays (its draws then replayed from what the
     * first one at rest recorded), sparks that land and die at random
     * (their holes filled from the end: the dying blocks wake), drops that
     * die in order (everything after the first dead forgotten). */
    scene_text("[scene]\nwidth = 200\nheight = 60\n[force gravity]\ng = 400\n[bounds]\nrestitution = 0.2\n"
               "[emitter a]\nsource = layer\ncount = 20000\nlimit = 20000\nrect = -9, 9, -3, 6\n"
               "forces = gravity\ncolor = #ff804008\n"
               "[emitter sparks]\nsource = stream\nposition = -9, 5\nshape = segment\nshape_a = 18\n"
               "count = 6000\nrate = 200\nlife = 0.5\nlife_range = 1.5\nforces = gravity\nblend = add\n"
               "color = #2040ff20\n"
               "[emitter drops]\nsource = stream\nposition = -9, 5\nshape = segment\nshape_a = 18\n"
               "count = 6000\nrate = 3000\nlife = 0.6\nlife_range = 0.3\nforces = gravity\ncolor = #40ff8020\n",
               "at rest", quick ? 60 : 120);
    CHECK(!ISK__FAST_RETAIN || replays > 0, "at rest: no draw was replayed from recorded blends");
    /* An order-dependent list: a potential that switches itself off. */
    scene_text("[force trap]\nkind = potential\nk = 80\nposition = 0, 0\nmax_distance = 0.2\n"
               "[emitter layer]\nsource = layer\ncount = 20000\nlimit = 20000\nrect = -5, 5, -5, 5\n"
               "forces = trap\n",
               "trap", quick ? 10 : 60);
    if (failures)
        fprintf(stderr, "threads_check: %d failures\n", failures);
    else
        printf("threads_check: the same bytes on 1, 2, 3 and 7 threads\n");
    return failures != 0;
}
