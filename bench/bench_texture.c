/* SPDX-License-Identifier: MIT */
/* Textured sprites and trails (iskra/texture.h, isk_stroke_trail), against
 * the radial sprite of the same size (iskra/sprite.h) drawn at the same
 * random centres.
 *
 *   textures   a 32x32 texture (the linear sprite kind as a texture, so
 *              the pixels are the sprite's) drawn at 8, 16 and 32 px, i.e.
 *              at one texel per pixel of mip levels 2, 1 and 0; unrotated
 *              (the blit) and rotated (random angles: the rotated walker),
 *              white and tinted, over and add; the radial linear sprite of
 *              that diameter, tinted, beside it
 *   trails     random short trails: N = 4, 8, 16, 32 points along a gentle
 *              curve a few px long (3 px per 4 points), widths 1 and 3,
 *              fade 1, over and add; and wide ones: 32 points 6 px apart
 *              along a bending path, 64 and 512 px wide, over (the search
 *              for each pixel's nearest segment is what they cost)
 *
 * Every variant draws the same precomputed items onto an 800x600 opaque
 * canvas (refilled, untimed, before each pass); passes of all variants are
 * interleaved and each figure is the fastest of REPS passes, the median
 * beside it, in thread CPU time (bench_cpu_now), so the ratios printed are
 * measured in one run under the same load.
 *
 *   build/bench/bench_texture [reps]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_util.h"
#include "iskra/draw.h"
#include "iskra/sprite.h"
#include "iskra/texture.h"

enum { W = 800, H = 600, NSPR = 1 << 12, NTRAIL = 1 << 11, NWIDE = 16, MAXN = 32, MAXV = 64 };

static const double PI = 3.14159265358979323846;
static const isk_color COL = {255, 180, 60, 200};
static const int SIZES[3] = {8, 16, 32};
static const int TRAIL_N[4] = {4, 8, 16, 32};
static const double TRAIL_W[2] = {1.0, 3.0};
static const double WIDE_W[2] = {64.0, 512.0};

typedef struct ctx {
    isk_canvas c;
    isk_texture tex;
    isk_sprite spr[3];
    double *cx, *cy, *ang;
    double *trail; /* NTRAIL trails of MAXN points, x y pairs */
    double *wide;  /* NWIDE trails of MAXN points */
} ctx;

typedef struct variant {
    char name[64];
    void (*run)(ctx *, const struct variant *);
    long items;
    int blend, size, rotated, tinted, n, width;
    double t[MAXV];
    double ns, med;
    int base; /* index of the variant this one is compared with, -1: none */
} variant;

static void run_texture(ctx *k, const variant *v)
{
    double s = SIZES[v->size];
    isk_color tint = v->tinted ? COL : ISK_WHITE;
    for (long i = 0; i < NSPR; i++)
        isk_draw_texture(&k->c, &k->tex, 0, k->cx[i], k->cy[i], s, s, v->rotated ? k->ang[i] : 0.0, tint,
                         (isk_blend)v->blend);
}

static void run_sprite(ctx *k, const variant *v)
{
    for (long i = 0; i < NSPR; i++)
        isk_draw_sprite_tinted(&k->c, &k->spr[v->size], k->cx[i], k->cy[i], COL, (isk_blend)v->blend);
}

static void run_trail(ctx *k, const variant *v)
{
    for (long i = 0; i < NTRAIL; i++)
        isk_stroke_trail(&k->c, k->trail + (size_t)i * 2 * MAXN + 2 * (MAXN - TRAIL_N[v->n]), TRAIL_N[v->n],
                         TRAIL_W[v->width], COL, 1.0, (isk_blend)v->blend);
}

static void run_wide_trail(ctx *k, const variant *v)
{
    for (long i = 0; i < NWIDE; i++)
        isk_stroke_trail(&k->c, k->wide + (size_t)i * 2 * MAXN, MAXN, WIDE_W[v->width], COL, 1.0,
                         (isk_blend)v->blend);
}

/* count paths of MAXN points, each starting at random at least
 * (mx, my) inside the canvas and turning by a random constant angle of at
 * most turn / 2 a step. */
static void make_paths(double *xy, long count, double mx, double my, double step, double turn,
                       unsigned long long *seed)
{
    for (long i = 0; i < count; i++) {
        double x = mx + bench_urand(seed) * (W - 2 * mx), y = my + bench_urand(seed) * (H - 2 * my);
        double a = bench_urand(seed) * 2 * PI, da = (bench_urand(seed) - 0.5) * turn;
        double *p = xy + (size_t)i * 2 * MAXN;
        for (int j = 0; j < MAXN; j++) {
            p[2 * j] = x;
            p[2 * j + 1] = y;
            x += step * cos(a);
            y += step * sin(a);
            a += da;
        }
    }
}

static const char *mode_name(int b)
{
    return b == ISK_BLEND_ADD ? "add" : "over";
}

int main(int argc, char **argv)
{
    const int reps = bench_reps_arg(argc, argv, 9, MAXV,
                                    "usage: bench_texture [REPS]\n"
                                    "  REPS: repetitions of each timing (the median is printed), default 9\n");
    static ctx k;
    if (isk_canvas_init(&k.c, W, H) != ISK_OK || isk_texture_from_sprite(&k.tex, ISK_SPRITE_LINEAR, 32) != ISK_OK)
        return 1;
    for (int s = 0; s < 3; s++)
        if (isk_sprite_init(&k.spr[s], ISK_SPRITE_LINEAR, SIZES[s], COL) != ISK_OK)
            return 1;
    k.cx = malloc(NSPR * sizeof *k.cx);
    k.cy = malloc(NSPR * sizeof *k.cy);
    k.ang = malloc(NSPR * sizeof *k.ang);
    k.trail = malloc((size_t)NTRAIL * 2 * MAXN * sizeof *k.trail);
    k.wide = malloc((size_t)NWIDE * 2 * MAXN * sizeof *k.wide);
    if (!k.cx || !k.cy || !k.ang || !k.trail || !k.wide)
        return 1;
    unsigned long long seed = 14;
    for (long i = 0; i < NSPR; i++) {
        k.cx[i] = bench_urand(&seed) * W;
        k.cy[i] = bench_urand(&seed) * H;
        k.ang[i] = bench_urand(&seed) * 2 * PI;
    }
    /* a trail: MAXN points 0.75 px apart along a slowly turning path; the
     * shorter variants use its newest points */
    make_paths(k.trail, NTRAIL, 20, 20, 0.75, 0.2, &seed);
    make_paths(k.wide, NWIDE, 200, 150, 6.0, 0.3, &seed);

    static variant vs[MAXV * 2];
    int nv = 0;
#define ADD(fn, cnt, B, S, R, T, N, WI, BASE, ...)                                        \
    do {                                                                                  \
        variant *v_ = &vs[nv++];                                                          \
        snprintf(v_->name, sizeof v_->name, __VA_ARGS__);                                 \
        v_->run = fn; v_->items = cnt; v_->blend = B; v_->size = S; v_->rotated = R;      \
        v_->tinted = T; v_->n = N; v_->width = WI; v_->base = BASE;                       \
    } while (0)
    for (int s = 0; s < 3; s++)
        for (int b = ISK_BLEND_OVER; b <= ISK_BLEND_ADD; b++) {
            int base = nv;
            ADD(run_sprite, NSPR, b, s, 0, 1, 0, 0, -1, "radial sprite %d px tinted, %s", SIZES[s], mode_name(b));
            for (int r = 0; r < 2; r++)
                for (int t = 0; t < 2; t++)
                    ADD(run_texture, NSPR, b, s, r, t, 0, 0, base, "texture %d px%s%s, %s", SIZES[s], r ? " rotated" : "",
                        t ? " tinted" : "", mode_name(b));
        }
    int first_trail = nv;
    for (int n = 0; n < 4; n++)
        for (int w = 0; w < 2; w++)
            for (int b = ISK_BLEND_OVER; b <= ISK_BLEND_ADD; b++)
                ADD(run_trail, NTRAIL, b, 0, 0, 0, n, w, -1, "trail N=%d width %g, %s", TRAIL_N[n], TRAIL_W[w],
                    mode_name(b));
    for (int w = 0; w < 2; w++)
        ADD(run_wide_trail, NWIDE, ISK_BLEND_OVER, 0, 0, 0, 0, w, -1, "trail N=%d width %g, 6 px apart, over", MAXN,
            WIDE_W[w]);

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
    printf("bench_texture: 800x600 opaque canvas, fastest of %d interleaved passes (median in brackets)\n", reps);
    printf("%-44s %10s %10s %12s\n", "primitive", "ns/item", "(median)", "x sprite");
    for (int i = 0; i < nv; i++) {
        if (i == first_trail)
            printf("%-44s %10s %10s\n", "", "ns/trail", "(median)");
        if (vs[i].base >= 0)
            printf("%-44s %10.1f %10.1f %12.2f\n", vs[i].name, vs[i].ns, vs[i].med, vs[i].ns / vs[vs[i].base].ns);
        else
            printf("%-44s %10.1f %10.1f\n", vs[i].name, vs[i].ns, vs[i].med);
    }
    for (int s = 0; s < 3; s++)
        isk_sprite_free(&k.spr[s]);
    isk_texture_free(&k.tex);
    free(k.cx);
    free(k.cy);
    free(k.ang);
    free(k.trail);
    free(k.wide);
    isk_canvas_free(&k.c);
    return 0;
}
