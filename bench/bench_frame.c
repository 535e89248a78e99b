/* A whole frame at 800x600, as a program showing an effect spends it:
 * update (isk_effect_step) and draw (isk_effect_render, which clears the
 * canvas to the background first), for 10^5 .. 1.6*10^7 coverage dots and
 * 10^5 additive sprites and 10^4 anti-aliased discs, on 1 .. all cores
 * (isk_effect_set_threads).  The clear is
 * timed inside the draw ("clr+draw"), not on its own: on the threads, each
 * band clears the pixels it then draws, which a clear timed apart (by the
 * caller, on one thread: 0.15-0.18 ms a frame here) would not show.  The
 * explosion thesis's headline is 1,000,192 particles at about 60 FPS and
 * 16M at about 15 FPS on a laptop GPU; the targets here are the same on
 * this CPU.
 *
 * The effect is bench_layer.h's (a layer filling the view, gravity, drag
 * and reflecting walls).  The bytes are the same on every thread
 * count (tests/checks/threads_check.c); this only times them.
 *
 * Every thread count runs its own copy of the effect, and the copies take
 * their frames in turn (frame f on 1 thread, frame f on 2 threads, ...,
 * then frame f + 1): all copies go through the same states, and a change
 * in the machine's load hits every thread count alike, so the speedups
 * compare like with like.  Medians of wall-clock time over the measured
 * frames.
 *
 * The machine is a shared VM: whether its second core is really there
 * changes from minute to minute.  So each row is followed by a control,
 * a job of pure arithmetic (no memory) on 1 thread and on each thread count
 * at once, after every row: "cores given" is how many cores' worth of work
 * the machine did, and a row's speedup can only be read against it;
 * "memory given" is the same for a pass over arrays beyond the caches,
 * the most a row whose update is bound by memory can gain there.
 *
 *     build/bench/bench_frame            every size, and 10^6 settled on the floor and at rest
 *     build/bench/bench_frame --quick    10^5 and 10^6 only */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_util.h"
#include "bench_layer.h"

enum { W = BENCH_LAYER_W, H = BENCH_LAYER_H };

typedef struct row {
    const char *what;
    size_t n;
    isk_draw_mode draw;
    int frames;
    int settle; /* frames stepped (not timed) before the first timed one */
} row;

/* The layer falls for its first 20 frames, bounces for the next few
 * hundred and then lies on the floor: the "settled" row times it after 6 s,
 * when most particles rest or hop on the floor and the walls' bounces at
 * the time of impact (a root solve a hop) are most of the update; the "at
 * rest" row after 10 s, when every particle rests and its block with it
 * (sim/stage.h's isk_rest: the runner skips the motion and the walls, and
 * the draw replays the blends its first draw at rest recorded,
 * scene/effect_retain.c). */
static const row ROWS[] = {
    {"dots", 100000, ISK_DRAW_DOT, 40, 0},    {"dots", 1000000, ISK_DRAW_DOT, 20, 0},
    {"settled", 1000000, ISK_DRAW_DOT, 10, 360}, {"at rest", 1000000, ISK_DRAW_DOT, 10, 600},
    {"dots", 4000000, ISK_DRAW_DOT, 8, 0},
    {"dots", 16000000, ISK_DRAW_DOT, 4, 0},   {"sprites", 100000, ISK_DRAW_SPRITE, 20, 0},
    {"discs", 10000, ISK_DRAW_DISC, 20, 0},
};
enum { NROWS = sizeof ROWS / sizeof ROWS[0] };

/* Resident memory in bytes (Linux /proc/self/statm), 0 when unknown. */
static double resident_bytes(void)
{
    FILE *f = fopen("/proc/self/statm", "r");
    long pages = 0, rss = 0;
    if (f) {
        if (fscanf(f, "%ld %ld", &pages, &rss) != 2)
            rss = 0;
        fclose(f);
    }
    return (double)rss * 4096.0;
}

/* ---- the control: cores the machine gives ---------------------------------- */

static void *arithmetic(void *arg)
{
    volatile double x = 1.0;
    for (long i = 0; i < 40000000; i++) /* a dependent chain: no memory, no vector */
        x = x * 1.0000001;
    return arg;
}

/* Work done on `threads` threads at once over the work of one, per unit of
 * time: `threads` when the machine gives that many cores. */
static double cores_given(int threads)
{
    pthread_t t[64];
    double t0 = bench_now();
    arithmetic(NULL);
    const double one = bench_now() - t0;
    int started = 0;
    t0 = bench_now();
    for (int k = 0; k < threads && k < 64; k++)
        started += pthread_create(&t[k], NULL, arithmetic, NULL) == 0;
    for (int k = 0; k < started; k++)
        pthread_join(t[k], NULL);
    const double all = bench_now() - t0;
    return all > 0 ? started * one / all : 0;
}

/* The same for memory: a semi-implicit Euler step with drag over five
 * columns of 2*10^6 (x, y, vx, vy, m: 80 MB, beyond the caches; five
 * streams read and four written, as the update's), on one thread and then
 * shared out over `threads`: how much more bandwidth that many threads get
 * than one for the update's pattern.  A row whose update is bound by memory
 * (a falling layer of 10^6 moves 72 MB a step) can speed up by that much
 * at most, however many cores it is given.  (A pass over two columns gets
 * more from a second thread: one thread alone cannot keep enough misses in
 * flight on two streams, while the update's nine let it take most of the
 * memory's bandwidth by itself.) */
enum { MEM_N = 2000000, MEM_COLS = 5 };
typedef struct mem_share {
    double *col[MEM_COLS];
    size_t lo, hi;
} mem_share;

static void *memory_pass(void *arg)
{
    mem_share *s = arg;
    double *restrict x = s->col[0], *restrict y = s->col[1], *restrict vx = s->col[2], *restrict vy = s->col[3];
    const double *restrict m = s->col[4];
    const double h = 1.0 / 60, g = -9.81, b = 0.3;
    for (size_t i = s->lo; i < s->hi; i++) {
        const double k = b * m[i]; /* m read as 1/m: no division to bound the pass */
        vx[i] -= h * k * vx[i];
        vy[i] += h * (g - k * vy[i]);
        x[i] += h * vx[i];
        y[i] += h * vy[i];
    }
    return NULL;
}

/* One pass over the columns shared out over `threads`: seconds, or a
 * negative number when a thread could not be started. */
static double memory_pass_time(double **col, int threads)
{
    pthread_t t[64];
    mem_share s[64];
    int started = 0;
    const int n = threads < 64 ? threads : 64;
    const double t0 = bench_now();
    for (int k = 0; k < n; k++) {
        memcpy(s[k].col, col, sizeof s[k].col);
        s[k].lo = (size_t)MEM_N * (size_t)k / (size_t)n;
        s[k].hi = (size_t)MEM_N * (size_t)(k + 1) / (size_t)n;
    }
    for (int k = 1; k < n; k++)
        started += pthread_create(&t[k], NULL, memory_pass, &s[k]) == 0;
    memory_pass(&s[0]);
    for (int k = 1; k <= started; k++)
        pthread_join(t[k], NULL);
    return started == n - 1 ? bench_now() - t0 : -1.0;
}

/* The best of seven passes each way, one thread and `threads` in turn (a
 * pass takes a millisecond or two: fewer let the machine's load decide). */
static double memory_given(int threads)
{
    double *col[MEM_COLS] = {NULL};
    int ok = 1;
    for (int c = 0; c < MEM_COLS; c++) {
        col[c] = malloc(MEM_N * sizeof *col[c]);
        ok = ok && col[c];
        for (size_t i = 0; col[c] && i < MEM_N; i++)
            col[c][i] = 1.0;
    }
    double one = 1e30, all = 1e30;
    for (int rep = 0; ok && rep < 7; rep++) {
        const double t1 = memory_pass_time(col, 1), tn = memory_pass_time(col, threads);
        one = t1 > 0 && t1 < one ? t1 : one;
        all = tn > 0 && tn < all ? tn : all;
    }
    for (int c = 0; c < MEM_COLS; c++)
        free(col[c]);
    return ok && one < 1e30 && all < 1e30 ? one / all : 0;
}

static void print_control(const int *tc, int nt)
{
    printf("%-8s %9s  control: cores given", "", "");
    for (int t = 1; t < nt; t++)
        printf("  %d threads: %.2f", tc[t], cores_given(tc[t]));
    printf(";  memory given");
    for (int t = 1; t < nt; t++)
        printf("  %d threads: %.2f", tc[t], memory_given(tc[t]));
    printf("\n");
}

/* The thread counts timed: every count up to 4 cores, then 4, 8, ... and
 * all of them (each count holds a copy of the store). */
static int thread_counts(int cores, int *t)
{
    int n = 0;
    for (int k = 1; k <= cores && n < 16; k = k < 4 ? k + 1 : k * 2)
        t[n++] = k;
    if (t[n - 1] != cores)
        t[n++] = cores;
    return n;
}

enum { MAXT = 17, MAXF = 64 };

int main(int argc, char **argv)
{
    const int quick = bench_quick_arg(argc, argv,
                                      "usage: bench_frame [--quick]\n"
                                      "  update, draw and frame times at 800x600 on 1 .. all cores;\n"
                                      "  --quick: 10^5 and 10^6 particles only\n");
    isk_canvas c;
    if (isk_canvas_init(&c, W, H) != ISK_OK)
        return 1;
    int tc[MAXT], nt = 0;
    printf("bench_frame: one frame at %dx%d = update + draw (with its clear); medians in ms; thread counts "
           "interleaved\n",
           W, H);
    printf("%-8s %9s %7s %8s %8s %8s %7s %8s\n", "draw", "particles", "threads", "update", "clr+draw", "frame", "FPS",
           "speedup");
    int failed = 0;
    for (int i = 0; i < NROWS && !failed; i++) {
        const row *r = &ROWS[i];
        if (quick && (r->n > 1000000 || r->settle))
            continue;
        isk_effect *fx[MAXT] = {NULL};
        isk_error err = {0};
        const double rss0 = resident_bytes();
        if (bench_layer_effect(&fx[0], r->n, r->draw, &err) != ISK_OK) {
            printf("%-8s %9zu  skipped: %s\n", r->what, r->n, err.message);
            continue;
        }
        if (!nt)
            nt = thread_counts(isk_effect_threads(fx[0]), tc);
        int copies = 1;
        for (int t = 1; t < nt && copies == t; t++)
            if (bench_layer_effect(&fx[t], r->n, r->draw, &err) == ISK_OK)
                copies++;
        if (copies < nt)
            printf("%-8s %9zu  only %d of %d copies fit: %s\n", r->what, r->n, copies, nt, err.message);
        double tu[MAXT][MAXF], td[MAXT][MAXF], tf[MAXT][MAXF];
        for (int t = 0; t < copies && !failed; t++)
            failed = isk_effect_set_threads(fx[t], tc[t]) != ISK_OK;
        for (int f = 0; f < r->settle && !failed; f++)
            for (int t = 0; t < copies && !failed; t++)
                failed = isk_effect_step(fx[t]) != ISK_OK;
        for (int f = -2; f < r->frames && !failed; f++) /* two frames to warm the caches */
            for (int t = 0; t < copies && !failed; t++) {
                double t0 = bench_now();
                isk_status s = isk_effect_step(fx[t]);
                double t1 = bench_now();
                if (s == ISK_OK)
                    s = isk_effect_render(fx[t], &c);
                double t2 = bench_now();
                failed = s != ISK_OK;
                if (f >= 0) {
                    tu[t][f] = 1e3 * (t1 - t0);
                    td[t][f] = 1e3 * (t2 - t1);
                    tf[t][f] = 1e3 * (t2 - t0);
                }
            }
        double frame1 = 0;
        for (int t = 0; t < copies && !failed; t++) {
            double u = bench_median(tu[t], r->frames);
            double dr = bench_median(td[t], r->frames), fr = bench_median(tf[t], r->frames);
            if (t == 0)
                frame1 = fr;
            printf("%-8s %9zu %7d %8.2f %8.2f %8.2f %7.1f %7.2fx\n", r->what, r->n, tc[t], u, dr, fr,
                   1e3 / fr, frame1 / fr);
        }
        /* Smaller rows' columns come from memory the earlier rows gave
         * back to malloc, already resident: their growth means nothing. */
        if (r->n >= 1000000)
            printf("%-8s %9zu  %.0f bytes a particle resident (the store, the pool's scratch; at rest, the "
                   "recorded blends)\n", "", r->n,
                   (resident_bytes() - rss0) / ((double)r->n * copies));
        print_control(tc, nt);
        for (int t = 0; t < copies; t++)
            isk_effect_destroy(fx[t]);
    }
    printf("targets: 10^6 dots >= 60 FPS and 1.6*10^7 >= 15 FPS on all cores; 2 threads >= 1.8x one\n");
    isk_canvas_free(&c);
    return failed;
}
