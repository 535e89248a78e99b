/* SPDX-License-Identifier: MIT */
/* The rasterizer's primitives against the "touch floor".
 *
 * Touch floor: a loop that does the same world->screen transform as the
 * coverage dot and touches (reads and writes one byte of) the same 2x2
 * pixels, with no blending at all.  A dot cannot be cheaper than that: it
 * is the cost of the memory traffic and the transform.
 *
 * Every variant draws the same precomputed random items onto an 800x600
 * opaque canvas (refilled, untimed, before each pass); passes of all
 * variants are interleaved and each figure is the fastest of REPS passes
 * (the median beside it) in thread CPU time (bench_cpu_now), so the ratios
 * printed are measured in one run under the same load.  Single pixels are also compared with their own
 * floor: the same random pixels, one byte incremented.
 *
 *   build/bench/bench_raster [reps]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_util.h"
#include "iskra/draw.h"
#include "iskra/sprite.h"
#include "iskra/view.h"

enum { W = 800, H = 600, NDOTS = 1 << 18, NPIX = 1 << 18, NDISC = 1 << 12, NSPR = 1 << 12, MAXV = 64 };

typedef struct ctx {
    isk_canvas c;
    isk_view v;
    double *wx, *wy;     /* world positions of the dots */
    int *px, *py;        /* pixel positions */
    double *pwx, *pwy;   /* world points inside those pixels (for the batch) */
    double *cx, *cy;     /* screen centres of discs and sprites */
    isk_sprite spr[3][3];  /* [kind][size index] baked in the sprite colour */
} ctx;

static const isk_color DOT_COL = {255, 180, 60, 200};
static const int SPR_D[3] = {8, 12, 32};
static const double DISC_R[3] = {1.0, 3.0, 8.0};

/* ---- variants ----------------------------------------------------------- */

typedef struct variant {
    char name[48];
    void (*run)(ctx *, const struct variant *);
    long items;
    int blend;          /* isk_blend */
    int a, b, tinted;   /* variant parameters (kind, size index, ...) */
    double t[MAXV];     /* seconds per pass */
    double ns;          /* fastest pass, ns per item */
    double med;         /* median pass, ns per item */
} variant;

static void run_floor(ctx *k, const variant *vr)
{
    (void)vr;
    const isk_view *v = &k->v;
    uint8_t *px = k->c.pixels;
    const size_t stride = k->c.stride;
    for (long i = 0; i < NDOTS; i++) {
        double X = v->sx * k->wx[i] + v->px, Y = v->sy * k->wy[i] + v->py;
        if (!(X > -1.0 && X < W && Y > -1.0 && Y < H))
            continue;
        int ix = (int)floor(X), iy = (int)floor(Y);
        int l = ix >= 0, r = ix + 1 < W, t = iy >= 0, b = iy + 1 < H;
        uint8_t *p = px + (size_t)(iy + !t) * stride + (size_t)(ix + !l) * 4u;
        /* the same four pixels (clipped ones folded onto a visible one) */
        p[0]++;
        p[4u * (size_t)(r && l)]++;
        p[stride * (size_t)(b && t)]++;
        p[stride * (size_t)(b && t) + 4u * (size_t)(r && l)]++;
    }
}

/* The single pixel's floor: the same random pixels, one byte touched. */
static void run_pixel_floor(ctx *k, const variant *vr)
{
    (void)vr;
    uint8_t *px = k->c.pixels;
    const size_t stride = k->c.stride;
    for (long i = 0; i < NPIX; i++) {
        int x = k->px[i], y = k->py[i];
        if ((unsigned)x < (unsigned)W && (unsigned)y < (unsigned)H)
            px[(size_t)y * stride + (size_t)x * 4u]++;
    }
}

static void run_pixels(ctx *k, const variant *vr)
{
    isk_draw_pixels(&k->c, &k->v, NPIX, k->pwx, k->pwy, DOT_COL, (isk_blend)vr->blend);
}

static void run_dot(ctx *k, const variant *vr)
{
    for (long i = 0; i < NDOTS; i++) {
        double X, Y;
        isk_view_to_screen(&k->v, k->wx[i], k->wy[i], &X, &Y);
        isk_draw_dot(&k->c, X, Y, DOT_COL, (isk_blend)vr->blend);
    }
}

static void run_dot_browser(ctx *k, const variant *vr)
{
    for (long i = 0; i < NDOTS; i++) {
        double X, Y;
        isk_view_to_screen(&k->v, k->wx[i], k->wy[i], &X, &Y);
        isk_draw_dot_browser(&k->c, X, Y, DOT_COL, (isk_blend)vr->blend);
    }
}

static void run_dots(ctx *k, const variant *vr)
{
    isk_draw_dots(&k->c, &k->v, NDOTS, k->wx, k->wy, DOT_COL, (isk_blend)vr->blend);
}

static void run_dots_browser(ctx *k, const variant *vr)
{
    isk_draw_dots_browser(&k->c, &k->v, NDOTS, k->wx, k->wy, DOT_COL, (isk_blend)vr->blend);
}

/* isk_draw_pixel as a program calls it: the macro, inlined into the loop */
static void run_pixel(ctx *k, const variant *vr)
{
    for (long i = 0; i < NPIX; i++)
        isk_draw_pixel(&k->c, k->px[i], k->py[i], DOT_COL, (isk_blend)vr->blend);
}

/* the same through the function (a call a pixel, the mode chosen in it) */
static void run_pixel_call(ctx *k, const variant *vr)
{
    for (long i = 0; i < NPIX; i++)
        (isk_draw_pixel)(&k->c, k->px[i], k->py[i], DOT_COL, (isk_blend)vr->blend);
}

static void run_disc(ctx *k, const variant *vr)
{
    for (long i = 0; i < NDISC; i++)
        isk_fill_circle_aa(&k->c, k->cx[i], k->cy[i], DISC_R[vr->a], DOT_COL, (isk_blend)vr->blend);
}

static void run_sprite(ctx *k, const variant *vr)
{
    const isk_sprite *s = &k->spr[vr->a][vr->b];
    if (vr->tinted)
        for (long i = 0; i < NSPR; i++)
            isk_draw_sprite_tinted(&k->c, s, k->cx[i], k->cy[i], DOT_COL, (isk_blend)vr->blend);
    else
        for (long i = 0; i < NSPR; i++)
            isk_draw_sprite(&k->c, s, k->cx[i], k->cy[i], (isk_blend)vr->blend);
}

/* ---- set-up ------------------------------------------------------------- */


static const char *mode_name(int b)
{
    return b == ISK_BLEND_ADD ? "add" : "over";
}

int main(int argc, char **argv)
{
    const int reps = bench_reps_arg(argc, argv, 9, MAXV,
                                    "usage: bench_raster [REPS]\n"
                                    "  REPS: repetitions of each timing (the median is printed), default 9\n");
    static ctx k;
    if (isk_canvas_init(&k.c, W, H) != ISK_OK || isk_view_window(&k.v, W, H, -4, 4, -3, 3) != ISK_OK)
        return 1;
    k.wx = malloc(NDOTS * sizeof *k.wx);
    k.wy = malloc(NDOTS * sizeof *k.wy);
    k.px = malloc(NPIX * sizeof *k.px);
    k.py = malloc(NPIX * sizeof *k.py);
    k.pwx = malloc(NPIX * sizeof *k.pwx);
    k.pwy = malloc(NPIX * sizeof *k.pwy);
    k.cx = malloc(NSPR * sizeof *k.cx);
    k.cy = malloc(NSPR * sizeof *k.cy);
    if (!k.wx || !k.wy || !k.px || !k.py || !k.pwx || !k.pwy || !k.cx || !k.cy)
        return 1;
    unsigned long long seed = 12;
    for (long i = 0; i < NDOTS; i++) {
        k.wx[i] = -4.0 + 8.0 * bench_urand(&seed);
        k.wy[i] = -3.0 + 6.0 * bench_urand(&seed);
    }
    for (long i = 0; i < NPIX; i++) {
        k.px[i] = (int)(bench_urand(&seed) * W);
        k.py[i] = (int)(bench_urand(&seed) * H);
        isk_view_to_world(&k.v, k.px[i] + 0.5, k.py[i] + 0.5, &k.pwx[i], &k.pwy[i]);
    }
    for (long i = 0; i < NSPR; i++) {
        k.cx[i] = bench_urand(&seed) * W;
        k.cy[i] = bench_urand(&seed) * H;
    }
    for (int kind = 0; kind < 3; kind++)
        for (int d = 0; d < 3; d++)
            if (isk_sprite_init(&k.spr[kind][d], (isk_sprite_kind)kind, SPR_D[d], DOT_COL) != ISK_OK)
                return 1;

    static variant vs[80];
    int nv = 0;
#define ADD_VARIANT(fn, cnt, bl, A, B, T, ...)                                        \
    do {                                                                              \
        variant *vr_ = &vs[nv++];                                                     \
        snprintf(vr_->name, sizeof vr_->name, __VA_ARGS__);                           \
        vr_->run = fn; vr_->items = cnt; vr_->blend = bl;                             \
        vr_->a = A; vr_->b = B; vr_->tinted = T;                                      \
    } while (0)
    ADD_VARIANT(run_floor, NDOTS, 0, 0, 0, 0, "touch floor (transform + 2x2 touch)");
    for (int b = ISK_BLEND_OVER; b <= ISK_BLEND_ADD; b++)
        ADD_VARIANT(run_dot, NDOTS, b, 0, 0, 0, "dot, %s (isk_draw_dot per call)", mode_name(b));
    for (int b = ISK_BLEND_OVER; b <= ISK_BLEND_ADD; b++)
        ADD_VARIANT(run_dots, NDOTS, b, 0, 0, 0, "dots, %s (isk_draw_dots batch)", mode_name(b));
    for (int b = ISK_BLEND_OVER; b <= ISK_BLEND_ADD; b++)
        ADD_VARIANT(run_dot_browser, NDOTS, b, 0, 0, 0, "browser dot, %s (per call)", mode_name(b));
    for (int b = ISK_BLEND_OVER; b <= ISK_BLEND_ADD; b++)
        ADD_VARIANT(run_dots_browser, NDOTS, b, 0, 0, 0, "browser dots, %s (batch)", mode_name(b));
    int pixel_floor = nv;
    ADD_VARIANT(run_pixel_floor, NPIX, 0, 0, 0, 0, "pixel touch floor (1 byte, same pixels)");
    for (int b = ISK_BLEND_OVER; b <= ISK_BLEND_ADD; b++)
        ADD_VARIANT(run_pixel, NPIX, b, 0, 0, 0, "pixel, %s (isk_draw_pixel)", mode_name(b));
    for (int b = ISK_BLEND_OVER; b <= ISK_BLEND_ADD; b++)
        ADD_VARIANT(run_pixel_call, NPIX, b, 0, 0, 0, "pixel, %s ((isk_draw_pixel) called)", mode_name(b));
    for (int b = ISK_BLEND_OVER; b <= ISK_BLEND_ADD; b++)
        ADD_VARIANT(run_pixels, NPIX, b, 0, 0, 0, "pixels, %s (isk_draw_pixels batch)", mode_name(b));
    for (int r = 0; r < 3; r++)
        ADD_VARIANT(run_disc, NDISC, ISK_BLEND_OVER, r, 0, 0, "AA disc r=%g, over", DISC_R[r]);
    static const char *kinds[3] = {"disc", "linear", "smooth"};
    for (int kind = 0; kind < 3; kind++)
        for (int d = 0; d < 3; d++)
            for (int t = 0; t < 2; t++)
                for (int b = ISK_BLEND_OVER; b <= ISK_BLEND_ADD; b++)
                    ADD_VARIANT(run_sprite, NSPR, b, kind, d, t, "sprite %s d=%d%s, %s", kinds[kind], SPR_D[d],
                                t ? " tinted" : "", mode_name(b));

    for (int rep = 0; rep < reps; rep++)
        for (int i = 0; i < nv; i++) {
            isk_canvas_fill(&k.c, isk_rgba(20, 30, 40, 255));
            double t0 = bench_cpu_now();
            vs[i].run(&k, &vs[i]);
            vs[i].t[rep] = bench_cpu_now() - t0;
        }
    for (int i = 0; i < nv; i++) {
        vs[i].med = bench_median(vs[i].t, reps) * 1e9 / (double)vs[i].items; /* sorts t */
        vs[i].ns = vs[i].t[0] * 1e9 / (double)vs[i].items;
    }

    /* The machine is shared: interference only ever slows a pass down, so
     * the fastest of the interleaved passes is the figure (the median is
     * shown beside it); ratios are of fastest passes. */
    printf("bench_raster: 800x600 opaque canvas, fastest of %d interleaved passes (median in brackets)\n", reps);
    printf("%-44s %10s %10s %10s\n", "primitive", "ns/item", "(median)", "x floor");
    for (int i = 0; i < nv; i++) {
        /* dots against the dot floor, pixels against the pixel floor */
        double fl = i >= pixel_floor && i < pixel_floor + 7 ? vs[pixel_floor].ns : vs[0].ns;
        printf("%-44s %10.2f %10.2f %10.2f\n", vs[i].name, vs[i].ns, vs[i].med, vs[i].ns / fl);
    }
    for (int kind = 0; kind < 3; kind++)
        for (int d = 0; d < 3; d++)
            isk_sprite_free(&k.spr[kind][d]);
    free(k.wx); free(k.wy); free(k.px); free(k.py); free(k.pwx); free(k.pwy); free(k.cx); free(k.cy);
    isk_canvas_free(&k.c);
    return 0;
}
