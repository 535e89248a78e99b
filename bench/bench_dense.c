/* SPDX-License-Identifier: MIT */
/* How far 16·10⁶ coverage dots are from 15 frames a second on this CPU,
 * and what would close the gap: the explosion thesis's GPU headline, which
 * the speed goals ask to report on when it is not reached.
 *
 * Three measurements, each in one run, medians of wall-clock time:
 *
 *   1. the frame as bench_frame times it (bench_layer.h's effect), on one
 *      thread and on all of them, against the 66.7 ms a frame of 15 FPS has,
 *      and the same work as independent effects, one per core, sharing
 *      nothing (bench_parts.h): the most the threads could make of it;
 *   2. the draw of the same points (isk_draw_dots' kernels, one band per
 *      thread) in the store's order and sorted by screen row: what a store
 *      kept in row order would give (the canvas's lines then come from the
 *      caches; the bytes change, as the draw order does);
 *   3. one gravity + drag + reflecting-walls step over double columns and
 *      over float columns, the same loop: what a float store would give
 *      (the update is bound by the bytes it moves).
 *
 * The projection at the end adds what 2. and 3. would save to 1.  It is a
 * projection, said as such: neither a sorted nor a float store exists, and
 * it leaves out what keeping a store in row order would cost (the time of
 * the counting sort of x and y alone is printed beside it).
 *
 *     build/bench/bench_dense            16·10⁶ particles
 *     build/bench/bench_dense --quick    4·10⁶ */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_layer.h"
#include "bench_parts.h"
#include "bench_util.h"
#include "iskra/view.h"
#include "view/world_batch.h"

enum { W = BENCH_LAYER_W, H = BENCH_LAYER_H, FRAMES = 6, REPS = 5, MAXT = BENCH_SHARES_MAX };

static const double TARGET_MS = 1000.0 / 15.0;

/* ---- 1. the effect's frame ------------------------------------------------ */

typedef struct frame_times {
    double update, draw; /* medians, ms (the draw with the render's clear) */
} frame_times;

/* Frames alternate between one thread and all, so a change in the
 * machine's load hits both alike; with parts (bench_parts.h: the same
 * work as independent effects, one per core, sharing nothing), a frame of
 * theirs follows each pair (*parts_ms: their median). */
static int time_effect(isk_effect *fx, isk_canvas *c, int all, frame_times out[2], bench_parts *parts,
                       double *parts_ms)
{
    double tu[2][FRAMES], td[2][FRAMES], tp[FRAMES];
    for (int f = -1; f < FRAMES; f++) { /* one frame to warm up */
        for (int k = 0; k < 2; k++) {
            if (isk_effect_set_threads(fx, k ? all : 1) != ISK_OK)
                return 1;
            double t0 = bench_now();
            isk_status s = isk_effect_step(fx);
            double t1 = bench_now();
            if (s == ISK_OK)
                s = isk_effect_render(fx, c);
            double t2 = bench_now();
            if (s != ISK_OK)
                return 1;
            if (f >= 0) {
                tu[k][f] = 1e3 * (t1 - t0);
                td[k][f] = 1e3 * (t2 - t1);
            }
        }
        if (parts) {
            const double sp = bench_parts_run(parts, 0, 1);
            if (sp < 0)
                return 1;
            if (f >= 0)
                tp[f] = 1e3 * sp;
        }
    }
    for (int k = 0; k < 2; k++) {
        out[k].update = bench_median(tu[k], FRAMES);
        out[k].draw = bench_median(td[k], FRAMES);
    }
    if (parts)
        *parts_ms = bench_median(tp, FRAMES);
    return 0;
}

/* ---- 2. the draw in store order and in row order ----------------------- */

typedef struct band_arg {
    isk_canvas *c;
    const isk_view *v;
    size_t n;
    const double *x, *y;
    int r0, r1;
} band_arg;

static void *draw_band(void *p)
{
    band_arg *a = p;
    isk__draw_batch_rows(a->c, a->v, a->n, a->x, a->y, isk_rgba(255, 200, 120, 160), ISK_BLEND_OVER,
                         ISK__BATCH_DOT | ISK__BATCH_KEEP_ON_CANVAS, a->r0, a->r1);
    return NULL;
}

/* The draw on `threads` bands of rows, one thread each.  start == NULL:
 * each band reads every point (the effect's threaded draw of two or three
 * bands); else the points are in row order (sort_by_row's buckets) and a
 * band reads only the range whose dots can reach its rows. */
static double draw_ms(isk_canvas *c, const isk_view *v, size_t n, const double *x, const double *y, int threads,
                      const size_t *start)
{
    band_arg a[MAXT];
    for (int k = 0; k < threads; k++) {
        const int r0 = H * k / threads, r1 = H * (k + 1) / threads;
        const size_t i0 = start ? start[r0] : 0, i1 = start ? start[r1 + 1] : n;
        a[k] = (band_arg){c, v, i1 - i0, x + i0, y + i0, r0, r1};
    }
    isk_canvas_fill(c, isk_rgba(0, 0, 0, 255));
    return 1e3 * bench_run_shares(draw_band, a, sizeof *a, threads, NULL);
}

/* x, y copied in the order of their screen rows, index order within a row
 * (a stable counting sort).  Bucket b holds the points of top row b - 1
 * (floor of the screen Y, as the dot kernels take it; bucket 0 is row -1,
 * whose dots reach row 0), bucket H + 1 the points off the canvas;
 * start[b] is where bucket b begins, start[H + 2] = n. */
static int sort_by_row(const isk_view *v, size_t n, const double *x, const double *y, double *sx, double *sy,
                       size_t start[H + 3])
{
    int *bucket = malloc(n * sizeof *bucket);
    if (!bucket)
        return 1;
    memset(start, 0, (H + 3) * sizeof *start);
    for (size_t i = 0; i < n; i++) {
        double X, Y;
        isk_view_to_screen(v, x[i], y[i], &X, &Y);
        Y = isk__keep_on_canvas(Y, H);
        bucket[i] = Y >= -1.0 && Y < H ? (int)floor(Y) + 1 : H + 1;
        start[bucket[i] + 1]++;
    }
    for (int b = 0; b < H + 2; b++)
        start[b + 1] += start[b];
    for (size_t i = 0; i < n; i++) {
        size_t k = start[bucket[i]]++;
        sx[k] = x[i];
        sy[k] = y[i];
    }
    for (int b = H + 1; b > 0; b--) /* back to where each bucket begins */
        start[b] = start[b - 1];
    start[0] = 0;
    free(bucket);
    return 0;
}

/* ---- 3. one step over double and over float columns -------------------- */

/* Semi-implicit Euler with gravity and linear drag, walls reflecting with
 * restitution 0.8: the same loop for both types, its selects written as
 * products so that gcc vectorizes both alike (a step of this kind, not
 * the effect's bytes). */
#define STEP_LOOP(NAME, T)                                                                                  \
    static void NAME(size_t i0, size_t i1, T *restrict x, T *restrict y, T *restrict vx, T *restrict vy)  \
    {                                                                                                      \
        const T dt = (T)(1.0 / 60.0), keep = (T)(1.0 - 0.3 / 60.0), g = (T)(-9.81 / 60.0), e = (T)-0.8;  \
        for (size_t i = i0; i < i1; i++) {                                                                 \
            T u = vx[i] * keep, w = vy[i] * keep + g;                                                      \
            T px = x[i] + u * dt, py = y[i] + w * dt;                                                      \
            const T l = isless(px, (T)-4) ? (T)1 : (T)0, r = isgreater(px, (T)4) ? (T)1 : (T)0;           \
            const T b = isless(py, (T)-3) ? (T)1 : (T)0, t = isgreater(py, (T)3) ? (T)1 : (T)0;           \
            u *= (T)1 + (l + r) * (e - (T)1);                                                              \
            w *= (T)1 + (b + t) * (e - (T)1);                                                              \
            px += l * ((T)-8 - (T)2 * px) + r * ((T)8 - (T)2 * px);                                        \
            py += b * ((T)-6 - (T)2 * py) + t * ((T)6 - (T)2 * py);                                        \
            x[i] = px, y[i] = py, vx[i] = u, vy[i] = w;                                                    \
        }                                                                                                  \
    }
STEP_LOOP(step_double, double)
STEP_LOOP(step_float, float)

typedef struct step_arg {
    int is_float;
    size_t i0, i1;
    void *col[4];
} step_arg;

static void *step_share(void *p)
{
    step_arg *a = p;
    if (a->is_float)
        step_float(a->i0, a->i1, a->col[0], a->col[1], a->col[2], a->col[3]);
    else
        step_double(a->i0, a->i1, a->col[0], a->col[1], a->col[2], a->col[3]);
    return NULL;
}

static double step_ms(void *col[4], int is_float, size_t n, int threads)
{
    step_arg a[MAXT];
    for (int k = 0; k < threads; k++)
        a[k] = (step_arg){is_float, n * (size_t)k / (size_t)threads, n * (size_t)(k + 1) / (size_t)threads,
                          {col[0], col[1], col[2], col[3]}};
    return 1e3 * bench_run_shares(step_share, a, sizeof *a, threads, NULL);
}

static int fill_columns(void *col[4], int is_float, size_t n, const double *x, const double *y)
{
    const size_t sz = is_float ? sizeof(float) : sizeof(double);
    for (int k = 0; k < 4; k++)
        if (!(col[k] = malloc(n * sz)))
            return 1;
    for (size_t i = 0; i < n; i++) {
        const double v[4] = {x[i], y[i], 0.0, 0.0};
        for (int k = 0; k < 4; k++) {
            if (is_float)
                ((float *)col[k])[i] = (float)v[k];
            else
                ((double *)col[k])[i] = v[k];
        }
    }
    return 0;
}

/* ---- the report ------------------------------------------------------------ */

int main(int argc, char **argv)
{
    const int quick = bench_quick_arg(argc, argv,
                                      "usage: bench_dense [--quick]\n"
                                      "  how far 16*10^6 dots are from 15 FPS, and what a row-ordered or a float\n"
                                      "  store would give; --quick: 4*10^6 particles\n");
    const size_t n = quick ? 4000000 : 16000000;
    isk_canvas c;
    isk_effect *fx = NULL;
    isk_error err = {0};
    if (isk_canvas_init(&c, W, H) != ISK_OK)
        return 1;
    if (bench_layer_effect(&fx, n, ISK_DRAW_DOT, &err) != ISK_OK) {
        printf("bench_dense: skipped, %zu particles do not fit: %s\n", n, err.message);
        isk_canvas_free(&c);
        return 0;
    }
    int all = isk_effect_threads(fx);
    if (all > MAXT)
        all = MAXT;
    printf("bench_dense: %zu coverage dots at %dx%d, 1 and %d threads; medians in ms; 15 FPS = %.1f ms a frame\n",
           n, W, H, all, TARGET_MS);

    frame_times ft[2];
    bench_parts parts;
    const int have_parts = all > 1 && bench_parts_start(&parts, all, n, ISK_DRAW_DOT, &err) == ISK_OK;
    double parts_ms = 0;
    int failed = time_effect(fx, &c, all, ft, have_parts ? &parts : NULL, &parts_ms);
    if (have_parts)
        bench_parts_stop(&parts);
    for (int k = 0; k < 2 && !failed; k++) {
        const double frame = ft[k].update + ft[k].draw;
        printf("1. the effect, %d thread%s:  update %6.1f  clear+draw %6.1f  frame %6.1f  (%.1f FPS, %.2fx "
               "the 15 FPS frame)\n",
               k ? all : 1, k && all > 1 ? "s" : " ", ft[k].update, ft[k].draw, frame, 1e3 / frame,
               frame / TARGET_MS);
    }
    if (have_parts && !failed) /* what the threads could get at best, sharing nothing */
        printf("   the same work as %d independent effects at once, one thread each (bench_parts.h): frame %6.1f  "
               "(%.1f FPS, %.2fx the 15 FPS frame)\n",
               all, parts_ms, 1e3 / parts_ms, parts_ms / TARGET_MS);
    else if (all > 1 && !failed)
        printf("   no independent parts: %s\n", err.message[0] ? err.message : "they could not be started");

    const isk_particles *p = isk_effect_particles(fx, 0);
    const size_t m = isk_effect_particle_count(fx);
    const isk_view *v = isk_effect_view(fx);
    double *sx = malloc(m * sizeof *sx), *sy = malloc(m * sizeof *sy);
    size_t start[H + 3];
    double row_gain[2] = {1, 1}, dsorted[2] = {0, 0};
    if (sx && sy) { /* their pages first, so the sort's time is the sort's */
        memset(sx, 0, m * sizeof *sx);
        memset(sy, 0, m * sizeof *sy);
    }
    const double ts0 = bench_now();
    if (!failed && (!sx || !sy || sort_by_row(v, m, p->x, p->y, sx, sy, start)))
        failed = 1;
    const double sort_ms = 1e3 * (bench_now() - ts0);
    for (int k = 0; k < 2 && !failed; k++) {
        const int threads = k ? all : 1;
        double ts[REPS], tr[REPS], tb[REPS];
        for (int r = 0; r < REPS; r++) {
            ts[r] = draw_ms(&c, v, m, p->x, p->y, threads, NULL);
            tr[r] = draw_ms(&c, v, m, sx, sy, threads, NULL);
            tb[r] = draw_ms(&c, v, m, sx, sy, threads, start);
        }
        const double store = bench_median(ts, REPS), rows = bench_median(tr, REPS), own = bench_median(tb, REPS);
        row_gain[k] = own / store;
        dsorted[k] = own;
        printf("2. the draw, %d thread%s:  store order %6.1f (%.2f ns a dot)  row order %6.1f (%.2f)", threads,
               k && all > 1 ? "s" : " ", store, 1e6 * store / (double)m, rows, 1e6 * rows / (double)m);
        if (threads > 1)
            printf(", each band only its rows' points %6.1f (%.2f)", own, 1e6 * own / (double)m);
        printf("  = %.2fx\n", row_gain[k]);
    }
    double float_gain[2] = {1, 1};
    void *dcol[4] = {0}, *fcol[4] = {0};
    if (!failed && (fill_columns(dcol, 0, m, p->x, p->y) || fill_columns(fcol, 1, m, p->x, p->y)))
        failed = 1;
    for (int k = 0; k < 2 && !failed; k++) {
        const int threads = k ? all : 1;
        double td[REPS], tf[REPS];
        step_ms(dcol, 0, m, threads); /* first touch of the pages */
        step_ms(fcol, 1, m, threads);
        for (int r = 0; r < REPS; r++) {
            td[r] = step_ms(dcol, 0, m, threads);
            tf[r] = step_ms(fcol, 1, m, threads);
        }
        const double dd = bench_median(td, REPS), ff = bench_median(tf, REPS);
        float_gain[k] = ff / dd;
        printf("3. a gravity + drag + walls step, %d thread%s:  double columns %6.1f  float columns %6.1f  = %.2fx\n",
               threads, k && all > 1 ? "s" : " ", dd, ff, float_gain[k]);
    }
    if (!failed) {
        const int k = all > 1;
        const double now = ft[k].update + ft[k].draw;
        const double fl = ft[k].update * float_gain[k] + ft[k].draw;
        const double both = ft[k].update * float_gain[k] + ft[k].draw * row_gain[k];
        printf("projection on %d thread%s (the effect's times, scaled by 2. and 3.; not counting the sort, which took"
               " %.1f ms on one thread for x and y alone):\n",
               all, all > 1 ? "s" : "", sort_ms);
        printf("   as it is %6.1f ms (%4.1f FPS);  float store %6.1f (%4.1f FPS);  float and row-ordered store "
               "%6.1f (%4.1f FPS)\n",
               now, 1e3 / now, fl, 1e3 / fl, both, 1e3 / both);
        printf("   15 FPS with a float store needs the draw within %.2f ns of core time a dot (%d thread%s);"
               " in row order it takes %.2f\n",
               1e6 * (TARGET_MS - ft[k].update * float_gain[k]) / (double)m * all, all,
               all > 1 ? "s" : "", 1e6 * dsorted[k] / (double)m * all);
    }
    for (int k = 0; k < 4; k++) {
        free(dcol[k]);
        free(fcol[k]);
    }
    free(sx);
    free(sy);
    isk_effect_destroy(fx);
    isk_canvas_free(&c);
    if (failed)
        printf("bench_dense: failed (out of memory or an effect error)\n");
    return failed;
}
