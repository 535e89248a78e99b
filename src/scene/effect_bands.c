/* A group's draw on the effect's threads: the canvas cut into bands of
 * rows, one per thread, each drawing every particle but blending only its
 * own rows (the draw functions of effect_render.c).  Each pixel then sees
 * the same particles in the same order as on one thread, so the bytes are
 * the same for every thread count and every choice of cuts; the cuts are
 * only chosen to share the work evenly. */
#include <stdlib.h>

#include "effect_internal.h"
#include "sim/pool.h"

/* Below this many particles a group is drawn on the caller alone (the
 * threads' start costs more than they save). */
#define FX_BAND_MIN_PARTICLES 16384
/* Particles sampled to place the cuts. */
#define FX_BAND_SAMPLES 1024

typedef struct band_job {
    isk_effect *e;
    isk_canvas *c;
    fx_group *g;
    fx_band band[ISK_POOL_MAX_THREADS];
    isk_status status[ISK_POOL_MAX_THREADS];
} band_job;

static void run_band(void *ctx, int worker, size_t item)
{
    (void)worker;
    band_job *j = ctx;
    j->status[item] = j->g->draw(j->e, j->c, j->g, &j->band[item]);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Cuts at the quantiles of a sample of the particles' screen rows, so each
 * band holds about the same number of particles (a fire or an explosion
 * fills a small part of the screen). */
static void place_cuts(const isk_effect *e, const fx_group *g, const isk_canvas *c, int nb, int *cut)
{
    double ys[FX_BAND_SAMPLES];
    const isk_particles *p = &g->store;
    const size_t step = p->count / FX_BAND_SAMPLES ? p->count / FX_BAND_SAMPLES : 1;
    int m = 0;
    for (size_t i = 0; i < p->count && m < FX_BAND_SAMPLES; i += step) {
        double X, Y;
        isk_view_to_screen(&e->view, p->x[i], p->y[i], &X, &Y);
        if (Y >= 0 && Y < c->height)
            ys[m++] = Y;
    }
    qsort(ys, (size_t)m, sizeof ys[0], cmp_double);
    cut[0] = 0;
    cut[nb] = c->height;
    for (int k = 1; k < nb; k++) {
        int r = m ? (int)ys[(size_t)m * (size_t)k / (size_t)nb] : c->height * k / nb;
        cut[k] = r < cut[k - 1] ? cut[k - 1] : r > c->height ? c->height : r;
    }
}

isk_status fx_draw_bands(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *whole)
{
    const int threads = e->pool ? isk_pool_threads(e->pool) : 1;
    if (threads < 2 || g->store.count < FX_BAND_MIN_PARTICLES || c->height < 2 * threads)
        return g->draw(e, c, g, whole);
    band_job *j = malloc(sizeof *j);
    if (!j) /* the draw itself needs no memory: do it on one thread */
        return g->draw(e, c, g, whole);
    j->e = e;
    j->c = c;
    j->g = g;
    int cut[ISK_POOL_MAX_THREADS + 1];
    place_cuts(e, g, c, threads, cut);
    for (int k = 0; k < threads; k++) {
        j->band[k] = *whole;
        j->band[k].r0 = cut[k];
        j->band[k].r1 = cut[k + 1];
    }
    isk_pool_for(e->pool, (size_t)threads, 2, run_band, j);
    isk_status s = ISK_OK;
    for (int k = 0; k < threads && s == ISK_OK; k++)
        s = j->status[k];
    free(j);
    return s;
}
