/* SPDX-License-Identifier: MIT */
/* A group's draw on the effect's workers: the canvas cut into bands of
 * rows (or, for the batched dots when their particles crowd into a few
 * rows, of columns), one per worker, each blending only its own pixels
 * (the routine of the group's draw kind, effect_draws.c).  Each pixel then
 * sees the same particles in the same order as on one thread, so the bytes
 * are the same for every worker count and every choice of cuts; the cuts
 * are only chosen to share the work evenly.  What the scheduler may do
 * with a draw is what its kind's row declares (FX_MAY_*), and nothing else.
 *
 * Sorted bands (FX_MAY_SORT): a particle's draw touches no row further
 * than its kind's reach from its own, so on FX_BIN_MIN_BANDS bands or more
 * the particles are first sorted into the bands (world_batch.h's
 * isk__batch_bin, on the workers, each over its share of the store;
 * stable, so each band keeps index order), and a band then reads only its
 * own particles instead of every particle of the store.
 *
 * Bands of columns (FX_MAY_COLUMNS) share every row of the canvas, so the
 * cache lines at their edges would pass from core to core all through the
 * draw.  Every band of columns but the first therefore draws into a copy
 * of the canvas of its own (its columns copied in first and out after;
 * FX_COPIES_MAX_BYTES bounds the memory).  Its pixels see the same blends
 * from the same start, so the bytes are the same.
 *
 * Split draws (FX_MAY_SPLIT): a group that adds (ISK_BLEND_ADD) can
 * instead have its particles split among the workers (split_particles):
 * each draws its share of the store on the whole canvas, the first onto
 * the canvas itself, the others onto zeroed copies of their own, and the
 * copies are then added into the canvas, a strip of rows per worker.  What
 * a particle adds to a pixel does not depend on the pixel, and saturating
 * adds of amounts >= 0 give min(255, the sum) however they are grouped, so
 * the bytes are again those of one thread.  It is taken where the bands
 * would be columns.
 *
 * A group at rest (FX_MAY_RETAIN, effect_retain.c) records its blends band
 * by band at its first draw at rest, then replays them on the same bands
 * (replay_bands) until they would be stale: no cuts placed, no split.
 *
 * Every constant below is a measure of when the sharing pays: the
 * measures are in docs/performance.md, "When a draw is shared out". */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "effect_internal.h"
#include "iskra/draw.h"
#include "core/fast_paths.h"
#include "raster/span.h"
#include "sim/workers.h"
#include "view/world_batch.h"

/* Below FX_BAND_MIN_WORK (effect_internal.h) a group is drawn on the
 * caller alone: a second band costs a fixed part (waking a worker, placing
 * the cuts, fetching the canvas's lines from the caller's caches) and the
 * scan every band makes of the store.  The render's own clear, when the
 * bands do it, is work they share: a pixel of it counts as
 * 1/FX_FILL_PIXELS_A_DOT of a dot. */
#define FX_FILL_PIXELS_A_DOT 16.0
/* Particles sampled to place the cuts, in runs of neighbours (a cache
 * line of each column: lone samples would each miss). */
#define FX_BAND_SAMPLES 1024
#define FX_BAND_RUN 8
/* isk__batch_bin's codes hold band numbers up to 254. */
#define FX_BIN_MAX_BANDS 255
/* Sorting costs about two scans of the store (binning, then the lists);
 * each band scanning it whole costs one per band: sorting pays from this
 * many bands on. */
#define FX_BIN_MIN_BANDS 4
/* The most memory the copies of the bands of columns may take (beyond it
 * the bands draw in place: the same bytes). */
#define FX_COPIES_MAX_BYTES ((size_t)64 << 20)

typedef struct band_job {
    isk_effect *e;
    isk_canvas *c;
    fx_group *g;
    const isk_color *fill; /* NULL, or the colour every band first fills its own pixels with */
    int nb;
    /* one of each for every thread, in the job's own allocation (job_new):
     * sized for ISK_TASKS_MAX_WORKERS, the job was half a megabyte (a band
     * holds its sprites by size) that calloc zeroed every draw */
    fx_band *band;
    isk_status *status;
    uint8_t **copy;  /* a band of columns' own canvas pixels, or NULL: in place; for a
                      * split, every band's but the first, zeroed and added in after */
    int split;       /* the bands split the particles, not the canvas (split_particles) */
    fx_draw_fn draw; /* each band's (draw_band): the kind's, or effect_retain.c's record */
    int reach;       /* the kind's: rows beyond a particle's own its draw may touch */
    /* sorting into bands: share t of the store is [t n / nb, (t+1) n / nb)
     * (as many shares as bands, one per thread) */
    uint8_t *band_of_row;          /* the canvas's height */
    size_t *count;                 /* [t * nb + b]: share t's particles in band b */
    size_t *pos;                   /* [t * nb + b]: where share t writes them in band b */
} band_job;

/* A zeroed job for up to `threads` bands, or NULL. */
static band_job *job_new(int threads)
{
    const size_t t = (size_t)threads;
    band_job *j = calloc(1, sizeof *j + t * (sizeof *j->band + sizeof *j->copy + sizeof *j->status));
    if (!j)
        return NULL;
    /* widest alignment first: the job's size is a multiple of its own */
    j->band = (fx_band *)(void *)(j + 1);
    j->copy = (uint8_t **)(void *)(j->band + t);
    j->status = (isk_status *)(void *)(j->copy + t);
    return j;
}

/* Rows [r0, r1) of the columns [c0, c1) from one canvas's pixels to
 * another's (the same size and stride). */
static void copy_tile(uint8_t *to, const uint8_t *from, const isk_canvas *c, int r0, int r1, int c0, int c1)
{
    const size_t at = (size_t)c0 * 4u, len = (size_t)(c1 - c0) * 4u;
    for (int y = r0; y < r1; y++)
        memcpy(to + (size_t)y * c->stride + at, from + (size_t)y * c->stride + at, len);
}

static void copy_columns(uint8_t *to, const uint8_t *from, const isk_canvas *c, int c0, int c1)
{
    copy_tile(to, from, c, 0, c->height, c0, c1);
}

/* Bytes of a copy of c's pixels (its rows at its stride, the last one
 * ending with its last pixel). */
static size_t canvas_bytes(const isk_canvas *c)
{
    return (size_t)(c->height - 1) * c->stride + (size_t)c->width * 4u;
}

static void draw_band(band_job *j, size_t item)
{
    const fx_band *b = &j->band[item];
    if (j->split && item > 0) { /* its share of the particles' increments, added in after */
        isk_canvas own;
        isk_canvas_wrap(&own, j->copy[item], j->c->width, j->c->height, j->c->stride);
        memset(own.pixels, 0, canvas_bytes(j->c));
        j->status[item] = j->draw(j->e, &own, j->g, b);
        return;
    }
    if (!j->copy[item]) {
        if (j->fill)
            isk_fill_rect(j->c, b->c0, b->r0, b->c1 - b->c0, b->r1 - b->r0, *j->fill, ISK_BLEND_REPLACE);
        j->status[item] = j->draw(j->e, j->c, j->g, b);
        return;
    }
    isk_canvas own; /* the canvas's size and stride: its extent was checked when it was made */
    isk_canvas_wrap(&own, j->copy[item], j->c->width, j->c->height, j->c->stride);
    if (j->fill) /* what the copy would have brought in */
        isk_fill_rect(&own, b->c0, b->r0, b->c1 - b->c0, b->r1 - b->r0, *j->fill, ISK_BLEND_REPLACE);
    else
        copy_columns(own.pixels, j->c->pixels, j->c, b->c0, b->c1);
    j->status[item] = j->draw(j->e, &own, j->g, b);
    copy_columns(j->c->pixels, own.pixels, j->c, b->c0, b->c1);
}

static void run_band(void *ctx, int worker, size_t item)
{
    (void)worker;
    draw_band(ctx, item);
}

/* Points every band of columns after the first at a copy of the canvas of
 * its own (none when the memory cannot be had or would pass
 * FX_COPIES_MAX_BYTES: then they draw in place, with the same bytes). */
static void give_copies(band_job *j)
{
    fx_bins *bins = &j->e->bins;
    const size_t one = canvas_bytes(j->c);
    const size_t n = (size_t)(j->nb - 1);
    if (n == 0 || one > FX_COPIES_MAX_BYTES / n)
        return;
    if (bins->copies_cap < n * one) { /* nothing in them is kept: no realloc's copy */
        free(bins->copies);
        bins->copies_cap = 0;
        bins->copies = malloc(n * one);
        if (!bins->copies)
            return;
        bins->copies_cap = n * one;
    }
    for (int k = 1; k < j->nb; k++)
        j->copy[k] = bins->copies + (size_t)(k - 1) * one;
}

static size_t share_start(const band_job *j, size_t t)
{
    return (size_t)((unsigned long long)j->g->store.count * t / (size_t)j->nb);
}

static void bin_share(void *ctx, int worker, size_t t)
{
    (void)worker;
    band_job *j = ctx;
    isk__batch_bin(&j->e->view, j->c->height, j->g->store.y, share_start(j, t), share_start(j, t + 1), j->reach,
                   j->band_of_row, j->e->bins.code, j->count + t * (size_t)j->nb);
}

static void fill_share(void *ctx, int worker, size_t t)
{
    (void)worker;
    band_job *j = ctx;
    const uint16_t *code = j->e->bins.code;
    uint32_t *idx = j->e->bins.idx;
    size_t pos[FX_BIN_MAX_BANDS]; /* a copy: the shares' positions share cache lines */
    memcpy(pos, j->pos + t * (size_t)j->nb, (size_t)j->nb * sizeof *pos);
    for (size_t i = share_start(j, t), end = share_start(j, t + 1); i < end; i++) {
        const unsigned k = code[i];
        if (k == ISK__BIN_NONE)
            continue;
        for (unsigned b = k & 255u; b <= k >> 8; b++)
            idx[pos[b]++] = (uint32_t)i;
    }
}

/* Sorts v[0..m) (m <= FX_BAND_SAMPLES, each in [0, ISK_CANVAS_MAX_DIM]) by
 * two passes of 8-bit digits, least significant first: the draw waits for
 * the cuts, and a comparison function's calls would cost more than the
 * sort. */
static void sort_coordinates(int *v, int m)
{
    int tmp[FX_BAND_SAMPLES];
    int *from = v, *to = tmp;
    for (int shift = 0; shift < 16; shift += 8) {
        int start[257] = {0};
        for (int i = 0; i < m; i++)
            start[((from[i] >> shift) & 255) + 1]++;
        for (int d = 0; d < 256; d++)
            start[d + 1] += start[d];
        for (int i = 0; i < m; i++)
            to[start[(from[i] >> shift) & 255]++] = from[i];
        int *t = from;
        from = to;
        to = t;
    }
    /* after an even number of passes the sorted values are back in v */
}

/* The cuts 0 = cut[0] <= ... <= cut[nb] = n at even quantiles of the
 * sorted sample v[0..m) of screen coordinates in [0, n); returns how many
 * of the sample the fullest band holds. */
static int quantile_cuts(const int *v, int m, int nb, int n, int *cut)
{
    cut[0] = 0;
    cut[nb] = n;
    for (int k = 1; k < nb; k++) {
        int r = n * k / nb;
        if (m) {
            size_t q = (size_t)m * (size_t)k / (size_t)nb;
            r = v[q < (size_t)m ? q : (size_t)m - 1];
        }
        cut[k] = r < cut[k - 1] ? cut[k - 1] : r > n ? n : r;
    }
    int fullest = 0, i = 0;
    for (int k = 0; k < nb; k++) {
        int in = 0;
        for (; i < m && v[i] < cut[k + 1]; i++)
            in++;
        fullest = in > fullest ? in : fullest;
    }
    return fullest;
}

/* Cuts at the quantiles of a sample of the particles' screen rows, so each
 * band holds about the same number of particles (a fire or an explosion
 * fills a small part of the screen).  When the group's draw takes bands of
 * columns (FX_BANDS_COLUMNS) and the rows cannot share the particles (a
 * scene settled on its floor has most of them on its last row, and a row
 * is never cut), cuts at the quantiles of the columns instead: returns 1
 * for columns, 0 for rows. */
int isk__fx_place_cuts(const isk_effect *e, const fx_group *g, const isk_canvas *c, int nb, int columns_may, int *cut)
{
    int xs[FX_BAND_SAMPLES], ys[FX_BAND_SAMPLES]; /* whole columns and rows */
    const isk_particles *p = &g->store;
    /* runs of FX_BAND_RUN neighbours (a cache line of each column) spread
     * evenly over the store: the draw waits for the cuts */
    const size_t runs = FX_BAND_SAMPLES / FX_BAND_RUN;
    const size_t step = p->count / runs > FX_BAND_RUN ? p->count / runs : FX_BAND_RUN;
    int m = 0;
    for (size_t r = 0; r < runs; r++)
        for (size_t i = r * step; i < r * step + FX_BAND_RUN && i < p->count; i++) {
            double X, Y;
            isk_view_to_screen(&e->view, p->x[i], p->y[i], &X, &Y);
            if (g->keep_on_canvas) { /* where the draw puts them */
                X = isk__keep_on_canvas(X, c->width);
                Y = isk__keep_on_canvas(Y, c->height);
            }
            if (X >= 0 && X < c->width && Y >= 0 && Y < c->height) {
                xs[m] = (int)X;   /* >= 0: truncation is floor */
                ys[m++] = (int)Y; /* a band holds whole rows */
            }
        }
    sort_coordinates(ys, m);
    const int by_rows = quantile_cuts(ys, m, nb, c->height, cut);
    int columns = 0;
    if (columns_may && 4 * by_rows > 5 * ((m + nb - 1) / nb)) { /* rows not within 25 % of even */
        int col[ISK_TASKS_MAX_WORKERS + 1];
        sort_coordinates(xs, m);
        const int by_columns = quantile_cuts(xs, m, nb, c->width, col);
        if (4 * by_columns <= 3 * by_rows) { /* columns better by a quarter (else rows, which can be sorted) */
            columns = 1;
            memcpy(cut, col, (size_t)(nb + 1) * sizeof *cut);
        }
    }
    return columns;
}

static int grow(void **p, size_t *cap, size_t n, size_t size)
{
    if (*cap >= n)
        return 1;
    void *q = n <= SIZE_MAX / size ? realloc(*p, n * size) : NULL;
    if (!q)
        return 0;
    *p = q;
    *cap = n;
    return 1;
}

void isk__fx_bins_free(fx_bins *b)
{
    free(b->code);
    free(b->idx);
    free(b->copies);
    memset(b, 0, sizeof *b);
}

/* Sorts the group's particles into the job's bands and points each band at
 * its list.  0 when the memory cannot be had (then every band reads the
 * whole store, as without sorting: same bytes). */
static int sort_into_bands(band_job *j)
{
    fx_bins *bins = &j->e->bins;
    const size_t n = j->g->store.count, nb = (size_t)j->nb;
    if (j->nb > FX_BIN_MAX_BANDS || n > UINT32_MAX || !grow((void **)&bins->code, &bins->code_cap, n, 2))
        return 0;
    j->band_of_row = malloc((size_t)j->c->height);
    j->count = calloc(nb * nb, sizeof *j->count);
    j->pos = malloc(nb * nb * sizeof *j->pos);
    int ok = j->band_of_row && j->count && j->pos;
    if (ok) {
        for (int b = 0; b < j->nb; b++)
            memset(j->band_of_row + j->band[b].r0, b, (size_t)(j->band[b].r1 - j->band[b].r0));
        isk__workers_for(&j->e->workers, nb, 1, bin_share, j);
        /* band b's list: share 0's particles, then share 1's, ...: index order */
        size_t total = 0;
        for (size_t b = 0; b < nb; b++) {
            j->band[b].nlist = 0;
            for (size_t t = 0; t < nb; t++) {
                j->pos[t * nb + b] = total;
                total += j->count[t * nb + b];
                j->band[b].nlist += j->count[t * nb + b];
            }
        }
        ok = grow((void **)&bins->idx, &bins->idx_cap, total ? total : 1, 4);
        if (ok) {
            size_t start = 0;
            for (size_t b = 0; b < nb; b++) {
                j->band[b].list = bins->idx + start;
                start += j->band[b].nlist;
            }
            isk__workers_for(&j->e->workers, nb, 1, fill_share, j);
        }
    }
    free(j->band_of_row);
    free(j->count);
    free(j->pos);
    return ok;
}

/* Rows [r0, r1) of every split band's copy added into the canvas (the
 * strips of rows, one per thread, after the draw). */
static void add_copies(void *ctx, int worker, size_t strip)
{
    (void)worker;
    band_job *j = ctx;
    const isk_canvas *c = j->c;
    const int r0 = (int)((long long)c->height * (long long)strip / j->nb);
    const int r1 = (int)((long long)c->height * (long long)(strip + 1) / j->nb);
    for (int k = 1; k < j->nb; k++)
        for (int y = r0; y < r1; y++)
            isk__span_add_bytes(c->pixels + (size_t)y * c->stride, j->copy[k] + (size_t)y * c->stride,
                                c->width * 4);
}

/* The first of the bands' errors, if any; frees the job. */
static isk_status finish(band_job *j)
{
    isk_status s = ISK_OK;
    for (int k = 0; k < j->nb && s == ISK_OK; k++)
        s = j->status[k];
    free(j);
    return s;
}

/* Splits the group's particles into as many shares as threads (the first
 * drawn onto the canvas, each other onto a copy of its own): 0 when the
 * copies cannot be had. */
static int split_particles(band_job *j, const fx_band *whole, int threads)
{
    j->nb = threads;
    give_copies(j);
    if (!j->copy[1]) {
        j->nb = 0; /* for the bands instead */
        return 0;
    }
    const unsigned long long n = whole->end - whole->first;
    for (int k = 0; k < j->nb; k++) {
        fx_band *b = &j->band[k];
        *b = *whole;
        b->first = whole->first + (size_t)(n * (unsigned)k / (unsigned)threads);
        b->end = whole->first + (size_t)(n * (unsigned)(k + 1) / (unsigned)threads);
        b->list = NULL;
    }
    j->split = 1;
    j->e->bins.splits++;
    return 1;
}

fx_band isk__fx_band_whole(const isk_canvas *c, const fx_group *g)
{
    return (fx_band){.r0 = 0, .r1 = c->height, .c0 = 0, .c1 = c->width, .first = 0, .end = g->store.count};
}

/* A band's recorded blends (replay_bands).  They lie in its rows [y0, y1)
 * (a group at rest on its floor: a row or two), so a band with a copy of
 * the canvas fills only those there and copies only those out; its other
 * rows are filled in place.  The same bytes as draw_band: the blends are
 * cut to the same pixels (every record's block lies in [y0, y1)). */
static void replay_band(void *ctx, int worker, size_t item)
{
    (void)worker;
    band_job *j = ctx;
    const fx_tile *t = &j->g->retained.tile[item];
    fx_band b = j->band[item];
    const int w = b.c1 - b.c0;
    if (j->fill) { /* the rows no record blends */
        isk_fill_rect(j->c, b.c0, b.r0, w, t->y0 - b.r0, *j->fill, ISK_BLEND_REPLACE);
        isk_fill_rect(j->c, b.c0, t->y1, w, b.r1 - t->y1, *j->fill, ISK_BLEND_REPLACE);
    }
    b.r0 = t->y0;
    b.r1 = t->y1;
    if (b.r0 == b.r1) {
        j->status[item] = ISK_OK;
        return;
    }
    isk_canvas own = *j->c;
    if (j->copy[item]) {
        isk_canvas_wrap(&own, j->copy[item], j->c->width, j->c->height, j->c->stride);
        if (!j->fill)
            copy_tile(own.pixels, j->c->pixels, j->c, b.r0, b.r1, b.c0, b.c1);
    }
    if (j->fill)
        isk_fill_rect(&own, b.c0, b.r0, w, b.r1 - b.r0, *j->fill, ISK_BLEND_REPLACE);
    j->status[item] = isk__fx_retain_replay(j->e, &own, j->g, &b);
    if (j->copy[item])
        copy_tile(j->c->pixels, own.pixels, j->c, b.r0, b.r1, b.c0, b.c1);
}

/* Band k of the recorded ones: the whole band cut to its tile. */
static fx_band retained_band(const fx_band *whole, const fx_retained *rt, int k)
{
    fx_band b = *whole;
    const fx_tile *t = &rt->tile[k];
    b.r0 = t->r0, b.r1 = t->r1, b.c0 = t->c0, b.c1 = t->c1, b.index = k;
    return b;
}

/* The group's recorded blends drawn again, on the bands they were recorded
 * on (effect_retain.c): the same cuts. */
static isk_status replay_bands(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *whole,
                               const fx_retained *rt, const isk_color *fill)
{
    band_job *j = rt->nb > 1 ? job_new(rt->nb) : NULL;
    if (!j) { /* one band (the whole canvas), or no memory for the job: one after the other */
        if (fill && rt->nb == 1)
            isk_canvas_fill(c, *fill);
        isk_status s = ISK_OK;
        for (int k = 0; k < rt->nb && s == ISK_OK; k++) {
            const fx_band b = retained_band(whole, rt, k);
            if (fill && rt->nb > 1)
                isk_fill_rect(c, b.c0, b.r0, b.c1 - b.c0, b.r1 - b.r0, *fill, ISK_BLEND_REPLACE);
            s = isk__fx_retain_replay(e, c, g, &b);
        }
        return s;
    }
    j->e = e;
    j->c = c;
    j->g = g;
    j->fill = fill;
    j->nb = rt->nb;
    for (int k = 0; k < j->nb; k++)
        j->band[k] = retained_band(whole, rt, k);
    if (rt->columns)
        give_copies(j);
    isk__workers_for(&e->workers, (size_t)j->nb, 2, replay_band, j);
    return finish(j);
}

isk_status isk__fx_draw_bands(isk_effect *e, isk_canvas *c, fx_group *g, const fx_draw_kind *k, const fx_band *whole,
                         double units, const isk_color *fill)
{
    if (!ISK__FAST_BANDS) { /* the reference: the group drawn whole */
        if (fill)
            isk_canvas_fill(c, *fill);
        return k->draw(e, c, g, whole);
    }
    const int threads = isk__workers_count(&e->workers);
    fx_retained *rt = ISK__FAST_RETAIN && (k->may & FX_MAY_RETAIN) ? isk__fx_retain_begin(e, c, g, threads) : NULL;
    if (rt && rt->nb > 0) {
        rt->replays++;
        return replay_bands(e, c, g, whole, rt, fill);
    }
    band_job *j = NULL;
    const double work = (double)g->store.count * units * k->cost +
                        (fill ? (double)c->width * c->height / FX_FILL_PIXELS_A_DOT : 0.0);
    if ((k->may & FX_MAY_BANDS) && threads >= 2 && work >= e->band_min_work && g->store.count > 0 &&
        c->height >= 2 * threads)
        j = job_new(threads);
    if (!j) { /* on the caller alone (the draw itself needs no memory) */
        if (fill)
            isk_canvas_fill(c, *fill);
        if (!rt)
            return k->draw(e, c, g, whole);
        fx_band one = *whole;
        one.index = 0;
        const isk_status s = isk__fx_retain_record(e, c, g, &one);
        isk__fx_retain_end(rt, &one, 1, 0);
        return s;
    }
    j->e = e;
    j->c = c;
    j->g = g;
    j->fill = fill;
    j->draw = rt ? isk__fx_retain_record : k->draw;
    j->reach = k->reach;
    int cut[ISK_TASKS_MAX_WORKERS + 1];
    const int columns = isk__fx_place_cuts(e, g, c, threads, (k->may & FX_MAY_COLUMNS) != 0, cut);
    /* an additive group is split where its bands would be columns (which
     * draw in copies of the canvas anyway, and each scan the whole store;
     * docs/performance.md has the measures); not while its blends are
     * recorded (their replays take bands) */
    if (!rt && (k->may & FX_MAY_SPLIT) && g->def->look.blend == ISK_BLEND_ADD && (columns || e->split_always) &&
        split_particles(j, whole, threads)) {
        isk__workers_for(&e->workers, (size_t)j->nb, 2, run_band, j);
        isk__workers_for(&e->workers, (size_t)j->nb, 1, add_copies, j);
        return finish(j);
    }
    /* empty bands (cuts that coincide where the particles crowd into a
     * few rows) are dropped: a point then reaches at most 5 bands */
    for (int b = 0; b < threads; b++)
        if (cut[b] < cut[b + 1]) {
            fx_band *band = &j->band[j->nb];
            *band = *whole;
            band->index = j->nb++;
            if (columns) {
                band->c0 = cut[b];
                band->c1 = cut[b + 1];
            } else {
                band->r0 = cut[b];
                band->r1 = cut[b + 1];
            }
        }
    /* the sorting is by rows: bands of columns read the whole store */
    if (!(!columns && (k->may & FX_MAY_SORT) && j->nb >= FX_BIN_MIN_BANDS && sort_into_bands(j)))
        for (int b = 0; b < j->nb; b++)
            j->band[b].list = NULL;
    if (columns)
        give_copies(j);
    isk__workers_for(&e->workers, (size_t)j->nb, 2, run_band, j);
    if (rt)
        isk__fx_retain_end(rt, j->band, j->nb, columns);
    return finish(j);
}
