/* SPDX-License-Identifier: MIT */
/* Textures (iskra/texture.h): making them (grids, premultiplication, mip
 * levels, bad input), drawing them against a plain per-pixel transcription
 * of the documented rule (every path: the blit, the rotated walker forced,
 * the portable arithmetic forced, bands of rows), the exact identities the
 * header promises (angle 0 through the rotated code, quarter turns equal
 * rotations in memory, the sprite texture equals the tinted sprite when
 * added), and loading / caching PNG files. */
#include <criterion/criterion.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "iskra/png.h"
#include "iskra/rng.h"
#include "canvas_pair.h"
#include "iskra/texture.h"
#include "iskra/texture_png.h"
#include "raster/texture_rows.h"

#define PI 3.14159265358979323846

/* Signed 128-bit integers for the exact sums of products below, in two
 * 64-bit words (two's complement): 32-bit targets have no __int128. */
typedef struct i128 {
    uint64_t hi, lo;
} i128;

static i128 i128_of(int64_t x)
{
    i128 r = {x < 0 ? UINT64_MAX : 0, (uint64_t)x};
    return r;
}

static i128 i128_add(i128 a, i128 b)
{
    i128 r = {a.hi + b.hi, a.lo + b.lo};
    r.hi += r.lo < a.lo; /* the carry */
    return r;
}

/* a * b, exactly: the four 32-bit partial products of |a| |b|, then the sign. */
static i128 i128_mul(int64_t a, int64_t b)
{
    uint64_t ua = a < 0 ? 0 - (uint64_t)a : (uint64_t)a, ub = b < 0 ? 0 - (uint64_t)b : (uint64_t)b;
    uint64_t a0 = ua & 0xFFFFFFFFu, a1 = ua >> 32, b0 = ub & 0xFFFFFFFFu, b1 = ub >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
    i128 r = {p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32), mid << 32 | (p00 & 0xFFFFFFFFu)};
    if ((a < 0) != (b < 0)) {
        i128 neg = {~r.hi, ~r.lo};
        r = i128_add(neg, i128_of(1));
    }
    return r;
}

static int i128_less(i128 a, i128 b)
{
    const uint64_t sign = (uint64_t)1 << 63;
    return (a.hi ^ sign) < (b.hi ^ sign) || (a.hi == b.hi && a.lo < b.lo);
}

static const isk_blend MODES[3] = {ISK_BLEND_REPLACE, ISK_BLEND_OVER, ISK_BLEND_ADD};

/* ---- the rule, transcribed pixel by pixel over the whole canvas --------------- */

static uint32_t d255(uint32_t x)
{
    return (x + 127u) / 255u;
}

static uint8_t sat(uint32_t x)
{
    return (uint8_t)(x > 255u ? 255u : x);
}

/* Q(x): nearest multiple of 2^-32, halves away from zero. */
static int64_t ref_q(double x)
{
    double v = x * 4294967296.0;
    double r = v >= 0 ? floor(v) : ceil(v);
    double f = v - r;
    if (f >= 0.5)
        r += 1.0;
    if (f <= -0.5)
        r -= 1.0;
    return (int64_t)r;
}

static const uint8_t *ref_texel(const isk_texture *t, int frame, int l, int x, int y)
{
    const isk_texture_level *lv = &t->level[l];
    return t->texels + (size_t)frame * t->frame_bytes + lv->offset + 4u * ((size_t)(y + 1) * (size_t)(lv->w + 2) + (size_t)(x + 1));
}

static void ref_blend(uint8_t *d, const uint32_t P[3], uint32_t A, isk_blend mode)
{
    if (A == 0)
        return;
    if (mode == ISK_BLEND_ADD) {
        for (int k = 0; k < 3; k++)
            d[k] = sat(d[k] + P[k]);
        d[3] = sat(d[3] + A);
    } else if (mode == ISK_BLEND_OVER) {
        uint32_t T = 255u * A + d[3] * (255u - A);
        for (int k = 0; k < 3; k++)
            d[k] = (uint8_t)((65025u * P[k] + (uint32_t)d[k] * d[3] * (255u - A) + T / 2u) / T);
        d[3] = (uint8_t)d255(T);
    } else {
        for (int k = 0; k < 3; k++)
            d[k] = (uint8_t)((255u * P[k] + A / 2u) / A);
        d[3] = (uint8_t)A;
    }
}

static void ref_draw_texture(isk_canvas *c, const isk_texture *t, int frame, double cx, double cy, double W, double H,
                             double angle, isk_color tint, isk_blend mode)
{
    if (!(fabs(cx) < 1048576.0 && fabs(cy) < 1048576.0) || !(W >= 1.0 / 1024 && W <= 32768 && H >= 1.0 / 1024 && H <= 32768) ||
        !isfinite(angle) || (int)mode < 0 || mode >= ISK_BLEND_COUNT)
        return;
    frame = frame < 0 ? 0 : frame >= t->frames ? t->frames - 1 : frame;
    double f = fmax(t->frame_w / W, t->frame_h / H);
    int L = 0;
    while (L + 1 < t->levels && ldexp(1.0, L + 1) <= f)
        L++;
    int wl = t->level[L].w, hl = t->level[L].h;
    double su = wl / W, sv = hl / H, cs = cos(angle), sn = sin(angle);
    double m00 = cs * su, m01 = sn * su, m10 = -sn * sv, m11 = cs * sv;
    int i0 = (int)floor(cx), j0 = (int)floor(cy);
    double ox = (i0 + 0.5) - cx, oy = (j0 + 0.5) - cy;
    int64_t U0 = ref_q(m00 * ox + m01 * oy + 0.5 * wl), V0 = ref_q(m10 * ox + m11 * oy + 0.5 * hl);
    int64_t DUX = ref_q(m00), DUY = ref_q(m01), DVX = ref_q(m10), DVY = ref_q(m11);
    const int64_t half = INT64_C(1) << 31, one = INT64_C(1) << 32;
    const i128 u_end = i128_add(i128_mul(wl, one), i128_of(half)), v_end = i128_add(i128_mul(hl, one), i128_of(half));
    for (int j = 0; j < c->height; j++)
        for (int i = 0; i < c->width; i++) {
            i128 U = i128_add(i128_add(i128_of(U0), i128_mul(i - i0, DUX)), i128_mul(j - j0, DUY));
            i128 V = i128_add(i128_add(i128_of(V0), i128_mul(i - i0, DVX)), i128_mul(j - j0, DVY));
            if (i128_less(U, i128_of(-half)) || !i128_less(U, u_end) || i128_less(V, i128_of(-half)) ||
                !i128_less(V, v_end))
                continue;
            /* the border is index 0; X, Y >= 0 and below (size + 1) * 2^32 */
            i128 X = i128_add(U, i128_of(half)), Y = i128_add(V, i128_of(half));
            int tx = (int)(X.hi << 32 | X.lo >> 32) - 1, ty = (int)(Y.hi << 32 | Y.lo >> 32) - 1;
            uint32_t fx = (uint32_t)((X.lo & 0xFFFFFFFFu) >> 25), fy = (uint32_t)((Y.lo & 0xFFFFFFFFu) >> 25);
            uint32_t S[4];
            for (int k = 0; k < 4; k++) {
                uint32_t acc = ref_texel(t, frame, L, tx, ty)[k] * (128u - fx) * (128u - fy) +
                               ref_texel(t, frame, L, tx + 1, ty)[k] * fx * (128u - fy) +
                               ref_texel(t, frame, L, tx, ty + 1)[k] * (128u - fx) * fy +
                               ref_texel(t, frame, L, tx + 1, ty + 1)[k] * fx * fy;
                S[k] = (acc + 8192u) >> 14;
            }
            uint32_t A = d255(S[3] * tint.a);
            uint32_t P[3] = {d255(tint.r * d255(S[0] * tint.a)), d255(tint.g * d255(S[1] * tint.a)),
                             d255(tint.b * d255(S[2] * tint.a))};
            ref_blend(isk_canvas_at(c, i, j), P, A, mode);
        }
}

/* ---- random inputs ---------------------------------------------------------------- */

static isk_color rnd_tint(isk_rng *r)
{
    return isk_rng_below(r, 3) == 0 ? ISK_WHITE : canvas_pair_rnd_color(r);
}

/* An image with opaque, transparent and translucent regions (blocks, so
 * the bilinear sample sees edges and flat runs). */
static isk_canvas rnd_image(isk_rng *r, int w, int h)
{
    isk_canvas img;
    cr_assert_eq(isk_canvas_init(&img, w, h), ISK_OK);
    int bs = 1 + (int)isk_rng_below(r, 4);
    for (int y = 0; y < h; y += bs)
        for (int x = 0; x < w; x += bs) {
            isk_color col = canvas_pair_rnd_color(r);
            for (int yy = y; yy < y + bs && yy < h; yy++)
                for (int xx = x; xx < x + bs && xx < w; xx++)
                    memcpy(isk_canvas_at(&img, xx, yy), &col, 4);
        }
    return img;
}

static isk_texture rnd_texture(isk_rng *r)
{
    int cols = 1 + (int)isk_rng_below(r, 3), rows = 1 + (int)isk_rng_below(r, 3);
    int fw = isk_rng_below(r, 6) == 0 ? 1 + (int)isk_rng_below(r, 3) : 1 + (int)isk_rng_below(r, 24);
    int fh = isk_rng_below(r, 4) == 0 ? fw : 1 + (int)isk_rng_below(r, 24);
    isk_canvas img = rnd_image(r, fw * cols, fh * rows);
    isk_texture t;
    cr_assert_eq(isk_texture_from_canvas(&t, &img, cols, rows), ISK_OK);
    isk_canvas_free(&img);
    return t;
}


static double rnd_coord(isk_rng *r, int n)
{
    switch (isk_rng_below(r, 20)) {
    case 0: return NAN;
    case 1: return isk_rng_below(r, 2) ? INFINITY : -INFINITY;
    case 2: return isk_rng_below(r, 2) ? 1e300 : -DBL_MAX;
    case 3: return isk_rng_below(r, 2) ? 1048576.0 : -1048575.5;
    case 4: return (double)(int)isk_rng_below(r, (uint32_t)n + 4) - 2.0;
    case 5: return ((double)(int)isk_rng_below(r, 2u * (uint32_t)n + 8) - 4.0) / 2.0;
    case 6: return ((double)(int)isk_rng_below(r, 128u * (uint32_t)n + 8) - 4.0) / 128.0;
    default: return isk_rng_range(r, -8.0, n + 8.0);
    }
}

static double rnd_extent(isk_rng *r)
{
    switch (isk_rng_below(r, 16)) {
    case 0: return isk_rng_range(r, 1.0 / 1024, 1.0);
    case 1: return isk_rng_below(r, 2) ? 1.0 / 1024 : 1.0 / 2048;
    case 2: return isk_rng_below(r, 2) ? NAN : -4.0;
    case 3: return isk_rng_range(r, 60, 400);
    case 4: return (double)(1 + isk_rng_below(r, 32));
    default: return isk_rng_range(r, 1.0, 48.0);
    }
}

static double rnd_angle(isk_rng *r)
{
    switch (isk_rng_below(r, 12)) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return PI / 2 * (double)isk_rng_below(r, 8);
    case 3: return isk_rng_below(r, 2) ? NAN : INFINITY;
    case 4: return isk_rng_range(r, -1e6, 1e6);
    default: return isk_rng_range(r, -7.0, 7.0);
    }
}

/* One random draw, by the library (with `paths`) on canvas 0 and by the
 * transcription on canvas 1. */
typedef struct draw_args {
    int frame;
    double cx, cy, w, h, angle;
    isk_color tint;
    isk_blend mode;
} draw_args;

static draw_args rnd_args(isk_rng *r, const isk_texture *t, int cw, int ch)
{
    draw_args a;
    a.frame = (int)isk_rng_below(r, (uint32_t)t->frames + 2) - 1;
    a.cx = rnd_coord(r, cw);
    a.cy = rnd_coord(r, ch);
    a.w = rnd_extent(r);
    a.h = isk_rng_below(r, 3) == 0 ? a.w : rnd_extent(r);
    a.angle = rnd_angle(r);
    a.tint = rnd_tint(r);
    a.mode = MODES[isk_rng_below(r, 3)];
    return a;
}

static void check_against_reference(unsigned seed, int cases, int paths)
{
    isk_rng r;
    isk_rng_seed(&r, seed);
    for (int n = 0; n < cases; n++) {
        isk_texture t = rnd_texture(&r);
        int w = 1 + (int)isk_rng_below(&r, 40), h = 1 + (int)isk_rng_below(&r, 40);
        canvas_pair p = canvas_pair_make(&r, w, h);
        for (int k = 0; k < 4; k++) {
            draw_args a = rnd_args(&r, &t, w, h);
            isk__draw_texture_rows(&p.c[0], &t, a.frame, a.cx, a.cy, a.w, a.h, a.angle, a.tint, a.mode, 0, h, paths);
            ref_draw_texture(&p.c[1], &t, a.frame, a.cx, a.cy, a.w, a.h, a.angle, a.tint, a.mode);
            size_t at;
            cr_assert(canvas_pair_equal(&p, &at),
                      "case %d.%d (paths %d): byte %zu differs: library %d, rule %d; texture %dx%d grid %dx%d, frame %d, "
                      "centre (%.17g, %.17g), size %.17g x %.17g, angle %.17g, tint %d %d %d %d, mode %d, canvas %dx%d",
                      n, k, paths, at, p.buf[0][at], p.buf[1][at], t.width, t.height, t.cols, t.rows, a.frame, a.cx, a.cy,
                      a.w, a.h, a.angle, a.tint.r, a.tint.g, a.tint.b, a.tint.a, a.mode, w, h);
        }
        canvas_pair_free(&p);
        isk_texture_free(&t);
    }
}

Test(texture_draw, equals_the_rule)
{
    check_against_reference(1, 1500, 0);
}

Test(texture_draw, rotated_walker_forced_equals_the_rule)
{
    check_against_reference(2, 1000, ISK__TEXTURE_GENERAL);
}

Test(texture_draw, sse2_kernels_equal_the_rule)
{
    check_against_reference(12, 600, ISK__TEXTURE_NO_AVX2);
    check_against_reference(13, 600, ISK__TEXTURE_NO_AVX2 | ISK__TEXTURE_GENERAL);
}

Test(texture_draw, portable_arithmetic_equals_the_rule)
{
    check_against_reference(3, 600, ISK__TEXTURE_SCALAR);
    check_against_reference(4, 600, ISK__TEXTURE_SCALAR | ISK__TEXTURE_GENERAL);
}

/* The proof: a rotation of 0 through the rotated code gives the
 * bytes of the unrotated blit, over random positions, sizes, tints, modes
 * (and destinations). */
Test(texture_draw, angle_zero_through_the_rotated_code_equals_the_blit)
{
    isk_rng r;
    isk_rng_seed(&r, 5);
    for (int n = 0; n < 3000; n++) {
        isk_texture t = rnd_texture(&r);
        int w = 1 + (int)isk_rng_below(&r, 64), h = 1 + (int)isk_rng_below(&r, 64);
        canvas_pair p = canvas_pair_make(&r, w, h);
        for (int k = 0; k < 4; k++) {
            draw_args a = rnd_args(&r, &t, w, h);
            a.angle = isk_rng_below(&r, 4) ? 0.0 : PI; /* pi: sin(pi) rounds away in fixed point */
            isk__draw_texture_rows(&p.c[0], &t, a.frame, a.cx, a.cy, a.w, a.h, a.angle, a.tint, a.mode, 0, h, 0);
            isk__draw_texture_rows(&p.c[1], &t, a.frame, a.cx, a.cy, a.w, a.h, a.angle, a.tint, a.mode, 0, h,
                                   ISK__TEXTURE_GENERAL);
        }
        size_t at;
        cr_assert(canvas_pair_equal(&p, &at),
                  "case %d: byte %zu differs (blit %d, rotated code %d)", n, at, p.buf[0][at],
                  p.buf[1][at]);
        canvas_pair_free(&p);
        isk_texture_free(&t);
    }
}

/* Bands of rows, drawn in any order, give the bytes of one call. */
Test(texture_draw, bands_of_rows_equal_the_whole_call)
{
    isk_rng r;
    isk_rng_seed(&r, 6);
    for (int n = 0; n < 1500; n++) {
        isk_texture t = rnd_texture(&r);
        int w = 1 + (int)isk_rng_below(&r, 48), h = 1 + (int)isk_rng_below(&r, 48);
        canvas_pair p = canvas_pair_make(&r, w, h);
        int cut = (int)isk_rng_below(&r, (uint32_t)h + 1);
        int cut2 = cut + (int)isk_rng_below(&r, (uint32_t)(h - cut) + 1);
        for (int k = 0; k < 4; k++) {
            draw_args a = rnd_args(&r, &t, w, h);
            int paths = (int)isk_rng_below(&r, 2) * ISK__TEXTURE_GENERAL;
            isk_draw_texture(&p.c[0], &t, a.frame, a.cx, a.cy, a.w, a.h, a.angle, a.tint, a.mode);
            isk__draw_texture_rows(&p.c[1], &t, a.frame, a.cx, a.cy, a.w, a.h, a.angle, a.tint, a.mode, cut2, h + 5, paths);
            isk__draw_texture_rows(&p.c[1], &t, a.frame, a.cx, a.cy, a.w, a.h, a.angle, a.tint, a.mode, -3, cut, paths);
            isk__draw_texture_rows(&p.c[1], &t, a.frame, a.cx, a.cy, a.w, a.h, a.angle, a.tint, a.mode, cut, cut2, paths);
        }
        size_t at;
        cr_assert(canvas_pair_equal(&p, &at), "case %d: byte %zu differs (whole %d, bands %d)", n, at, p.buf[0][at],
                  p.buf[1][at]);
        canvas_pair_free(&p);
        isk_texture_free(&t);
    }
}

/* A square frame rotated by quarter turns at 1 texel per pixel, its centre
 * on the pixel grid or off it by multiples of 1/128 px (the weights'
 * resolution), equals the frame rotated in memory and drawn unrotated. */
static isk_canvas rotate_image(const isk_canvas *src, int quarter)
{
    int S = src->width;
    isk_canvas out;
    cr_assert_eq(isk_canvas_init(&out, S, S), ISK_OK);
    for (int Y = 0; Y < S; Y++)
        for (int X = 0; X < S; X++) {
            int x = X, y = Y; /* the source texel shown at (X, Y) after `quarter` clockwise turns */
            for (int q = 0; q < quarter; q++) {
                int nx = y, ny = S - 1 - x;
                x = nx;
                y = ny;
            }
            memcpy(isk_canvas_at(&out, X, Y), isk_canvas_at(src, x, y), 4);
        }
    return out;
}

Test(texture_draw, quarter_turns_equal_rotations_in_memory)
{
    isk_rng r;
    isk_rng_seed(&r, 8);
    for (int n = 0; n < 400; n++) {
        int S = 1 + (int)isk_rng_below(&r, 20);
        isk_canvas img = rnd_image(&r, S, S);
        isk_texture t;
        cr_assert_eq(isk_texture_from_canvas(&t, &img, 1, 1), ISK_OK);
        int quarter = 1 + (int)isk_rng_below(&r, 3);
        isk_canvas rimg = rotate_image(&img, quarter);
        isk_texture rt;
        cr_assert_eq(isk_texture_from_canvas(&rt, &rimg, 1, 1), ISK_OK);
        int w = S + 8 + (int)isk_rng_below(&r, 8), h = S + 8 + (int)isk_rng_below(&r, 8);
        canvas_pair p = canvas_pair_make(&r, w, h);
        double off = isk_rng_below(&r, 2) ? 0.0 : 1.0;
        double ix = (double)(int)isk_rng_below(&r, 4), fx = (double)(int)isk_rng_below(&r, 128) / 128.0;
        double iy = (double)(int)isk_rng_below(&r, 4), fy = (double)(int)isk_rng_below(&r, 128) / 128.0;
        double cx = 4 + 0.5 * S + ix + off * fx, cy = 4 + 0.5 * S + iy + off * fy;
        isk_color tint = rnd_tint(&r);
        isk_blend mode = MODES[isk_rng_below(&r, 3)];
        isk_draw_texture(&p.c[0], &t, 0, cx, cy, S, S, quarter * PI / 2, tint, mode);
        isk_draw_texture(&p.c[1], &rt, 0, cx, cy, S, S, 0.0, tint, mode);
        size_t at;
        cr_assert(canvas_pair_equal(&p, &at),
                  "case %d: %dx%d, %d quarter turns, centre (%.10g, %.10g): byte %zu differs", n, S,
                  S, quarter, cx, cy, at);
        canvas_pair_free(&p);
        isk_texture_free(&t);
        isk_texture_free(&rt);
        isk_canvas_free(&img);
        isk_canvas_free(&rimg);
    }
}

/* At 1 texel per pixel with the centre on the grid the blit copies: REPLACE
 * writes exactly the frame's pixels (straight colour back from the
 * premultiplied texel, exact where alpha is 255), nothing around it. */
Test(texture_draw, unrotated_blit_at_scale_one_copies_the_frame)
{
    isk_canvas img;
    cr_assert_eq(isk_canvas_init(&img, 12, 6), ISK_OK);
    for (int y = 0; y < 6; y++)
        for (int x = 0; x < 12; x++) {
            uint8_t *q = isk_canvas_at(&img, x, y);
            q[0] = (uint8_t)(20 * x);
            q[1] = (uint8_t)(40 * y);
            q[2] = (uint8_t)(x * y);
            q[3] = 255;
        }
    isk_texture t;
    cr_assert_eq(isk_texture_from_canvas(&t, &img, 2, 1), ISK_OK); /* frames 6 x 6 */
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 20, 20), ISK_OK);
    isk_canvas_fill(&c, isk_rgba(1, 2, 3, 4));
    isk_draw_texture(&c, &t, 1, 10.0, 9.0, 6, 6, 0.0, ISK_WHITE, ISK_BLEND_REPLACE); /* pixels 7..12 x 6..11 */
    for (int y = 0; y < 20; y++)
        for (int x = 0; x < 20; x++) {
            isk_color got = isk_canvas_get(&c, x, y);
            int in = x >= 7 && x < 13 && y >= 6 && y < 12;
            isk_color want = in ? isk_canvas_get(&img, 6 + x - 7, y - 6) : isk_rgba(1, 2, 3, 4);
            cr_assert(memcmp(&got, &want, 4) == 0, "pixel (%d, %d): %d %d %d %d, want %d %d %d %d", x, y, got.r, got.g,
                      got.b, got.a, want.r, want.g, want.b, want.a);
        }
    isk_canvas_free(&c);
    isk_canvas_free(&img);
    isk_texture_free(&t);
}

/* The streak texture: added at the sprite's own size and phase it is the
 * tinted sprite byte for byte; source-over differs from the sprite's
 * straight-colour rule only by the premultiplied texel's rounding. */
Test(texture_draw, sprite_texture_equals_the_tinted_sprite)
{
    isk_rng r;
    isk_rng_seed(&r, 9);
    for (int n = 0; n < 300; n++) {
        isk_sprite_kind kind = (isk_sprite_kind)isk_rng_below(&r, 3);
        int S = 1 + (int)isk_rng_below(&r, 40);
        isk_sprite s;
        cr_assert_eq(isk_sprite_init(&s, kind, S, ISK_WHITE), ISK_OK);
        isk_texture t;
        cr_assert_eq(isk_texture_from_sprite(&t, kind, S), ISK_OK);
        int w = S + 10, h = S + 10;
        canvas_pair p = canvas_pair_make(&r, w, h);
        double cx = 0.5 * S + (double)(int)isk_rng_below(&r, 12) - 1.0;
        double cy = 0.5 * S + (double)(int)isk_rng_below(&r, 12) - 1.0;
        isk_color col = canvas_pair_rnd_color(&r);
        isk_draw_sprite_tinted(&p.c[0], &s, cx, cy, col, ISK_BLEND_ADD);
        isk_draw_texture(&p.c[1], &t, 0, cx, cy, S, S, 0.0, col, ISK_BLEND_ADD);
        size_t at;
        cr_assert(canvas_pair_equal(&p, &at), "case %d: kind %d size %d: byte %zu differs", n, kind, S, at);
        /* over, onto opaque pixels: within one level */
        isk_canvas_fill(&p.c[0], isk_rgba(30, 60, 90, 255));
        isk_canvas_fill(&p.c[1], isk_rgba(30, 60, 90, 255));
        isk_draw_sprite_tinted(&p.c[0], &s, cx, cy, col, ISK_BLEND_OVER);
        isk_draw_texture(&p.c[1], &t, 0, cx, cy, S, S, 0.0, col, ISK_BLEND_OVER);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                for (int k = 0; k < 4; k++) {
                    int a = isk_canvas_at(&p.c[0], x, y)[k], b = isk_canvas_at(&p.c[1], x, y)[k];
                    cr_assert(abs(a - b) <= 1, "over, case %d: pixel (%d, %d) channel %d: sprite %d, texture %d", n, x, y,
                              k, a, b);
                }
        canvas_pair_free(&p);
        isk_sprite_free(&s);
        isk_texture_free(&t);
    }
}

/* Tint: white changes nothing; tint alpha scales the sample's alpha. */
Test(texture_draw, white_tint_is_no_tint_and_alpha_scales)
{
    isk_canvas img;
    cr_assert_eq(isk_canvas_init(&img, 1, 1), ISK_OK);
    isk_canvas_fill(&img, isk_rgba(200, 100, 50, 255));
    isk_texture t;
    cr_assert_eq(isk_texture_from_canvas(&t, &img, 1, 1), ISK_OK);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 3, 3), ISK_OK);
    isk_draw_texture(&c, &t, 0, 1.5, 1.5, 1, 1, 0.0, ISK_WHITE, ISK_BLEND_ADD);
    isk_color got = isk_canvas_get(&c, 1, 1);
    cr_assert(got.r == 200 && got.g == 100 && got.b == 50 && got.a == 255);
    cr_assert_eq(isk_canvas_get(&c, 0, 1).a, 0); /* the half texel of border: A = 0, untouched */
    isk_canvas_fill(&c, ISK_TRANSPARENT);
    isk_draw_texture(&c, &t, 0, 1.5, 1.5, 1, 1, 0.0, isk_rgba(255, 0, 255, 128), ISK_BLEND_ADD);
    got = isk_canvas_get(&c, 1, 1);
    /* A = div255(255 * 128) = 128, P = div255(c * div255(s * 128)) */
    cr_assert(got.r == d255(255 * d255(200 * 128)) && got.g == 0 && got.b == d255(255 * d255(50 * 128)) && got.a == 128,
              "%d %d %d %d", got.r, got.g, got.b, got.a);
    isk_canvas_free(&c);
    isk_canvas_free(&img);
    isk_texture_free(&t);
}

/* Bad geometry draws nothing: NaN, infinities, huge centres and sizes,
 * sizes out of range, a bad mode, NULLs. */
Test(texture_draw, bad_input_draws_nothing)
{
    isk_rng r;
    isk_rng_seed(&r, 10);
    isk_texture t = rnd_texture(&r);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 16, 16), ISK_OK);
    isk_canvas_fill(&c, isk_rgba(9, 8, 7, 6));
    const double bad[] = {NAN, INFINITY, -INFINITY, 1e300, -1e300, DBL_MAX, 1048576.0, -1048576.0};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        isk_draw_texture(&c, &t, 0, bad[k], 8, 8, 8, 0, ISK_WHITE, ISK_BLEND_REPLACE);
        isk_draw_texture(&c, &t, 0, 8, bad[k], 8, 8, 0, ISK_WHITE, ISK_BLEND_REPLACE);
        isk_draw_texture(&c, &t, 0, 8, 8, bad[k], 8, 0, ISK_WHITE, ISK_BLEND_REPLACE);
        isk_draw_texture(&c, &t, 0, 8, 8, 8, -bad[k], 0, ISK_WHITE, ISK_BLEND_REPLACE);
        if (!isfinite(bad[k]))
            isk_draw_texture(&c, &t, 0, 8, 8, 8, 8, bad[k], ISK_WHITE, ISK_BLEND_REPLACE);
    }
    const double small[] = {0.0, -0.0, -1.0, 1.0 / 2048, 32769.0};
    for (size_t k = 0; k < sizeof small / sizeof small[0]; k++) {
        isk_draw_texture(&c, &t, 0, 8, 8, small[k], 8, 0, ISK_WHITE, ISK_BLEND_REPLACE);
        isk_draw_texture(&c, &t, 0, 8, 8, 8, small[k], 0, ISK_WHITE, ISK_BLEND_REPLACE);
    }
    isk_draw_texture(&c, &t, 0, 8, 8, 8, 8, 0, ISK_WHITE, (isk_blend)7);
    isk_draw_texture(&c, &t, 0, 8, 8, 8, 8, 0, ISK_WHITE, (isk_blend)-1);
    isk_draw_texture(&c, NULL, 0, 8, 8, 8, 8, 0, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_draw_texture(NULL, &t, 0, 8, 8, 8, 8, 0, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_texture empty;
    memset(&empty, 0, sizeof empty);
    isk_draw_texture(&c, &empty, 0, 8, 8, 8, 8, 0, ISK_WHITE, ISK_BLEND_REPLACE);
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            isk_color g = isk_canvas_get(&c, x, y);
            cr_assert(g.r == 9 && g.g == 8 && g.b == 7 && g.a == 6, "pixel (%d, %d) was drawn", x, y);
        }
    /* a huge angle is still an angle: something is drawn */
    isk_draw_texture(&c, &t, 0, 8, 8, 8, 8, 1e15, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_canvas_free(&c);
    isk_texture_free(&t);
}

/* Frames are clamped: below 0 is frame 0, beyond the last is the last. */
Test(texture_draw, frame_index_is_clamped)
{
    isk_rng r;
    isk_rng_seed(&r, 11);
    isk_canvas img = rnd_image(&r, 12, 8);
    isk_texture t;
    cr_assert_eq(isk_texture_from_canvas(&t, &img, 3, 2), ISK_OK);
    cr_assert_eq(t.frames, 6);
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, 10, 10), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 10, 10), ISK_OK);
    const int pairs[4][2] = {{-1, 0}, {-1000000, 0}, {6, 5}, {1 << 30, 5}};
    for (int k = 0; k < 4; k++) {
        isk_canvas_fill(&a, ISK_BLACK);
        isk_canvas_fill(&b, ISK_BLACK);
        isk_draw_texture(&a, &t, pairs[k][0], 5, 5, 7, 9, 0.3, ISK_WHITE, ISK_BLEND_OVER);
        isk_draw_texture(&b, &t, pairs[k][1], 5, 5, 7, 9, 0.3, ISK_WHITE, ISK_BLEND_OVER);
        cr_assert(isk_canvas_equal(&a, &b), "frame %d is not frame %d", pairs[k][0], pairs[k][1]);
    }
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_canvas_free(&img);
    isk_texture_free(&t);
}

/* ---- making textures ------------------------------------------------------------ */

Test(texture_make, grid_frames_premultiplied_with_border)
{
    isk_canvas img;
    cr_assert_eq(isk_canvas_init(&img, 6, 4), ISK_OK);
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 6; x++) {
            uint8_t *q = isk_canvas_at(&img, x, y);
            q[0] = (uint8_t)(40 * x + 3);
            q[1] = (uint8_t)(60 * y + 1);
            q[2] = 255;
            q[3] = (uint8_t)(30 * x + 50 * y + 5);
        }
    isk_texture t;
    cr_assert_eq(isk_texture_from_canvas(&t, &img, 3, 2), ISK_OK);
    cr_assert(t.width == 6 && t.height == 4 && t.cols == 3 && t.rows == 2 && t.frames == 6);
    cr_assert(t.frame_w == 2 && t.frame_h == 2 && t.levels == 2);
    cr_assert(t.level[1].w == 1 && t.level[1].h == 1);
    cr_assert_eq(t.frame_bytes, 4u * (16u + 9u));
    cr_assert_eq(t.bytes, 6u * t.frame_bytes);
    for (int f = 0; f < 6; f++) {
        const uint8_t *base = t.texels + (size_t)f * t.frame_bytes;
        for (int y = -1; y <= 2; y++)
            for (int x = -1; x <= 2; x++) {
                const uint8_t *q = base + 4u * ((size_t)(y + 1) * 4u + (size_t)(x + 1));
                if (x < 0 || y < 0 || x > 1 || y > 1) {
                    cr_assert(q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0, "frame %d border (%d, %d)", f, x, y);
                    continue;
                }
                const uint8_t *s = isk_canvas_at(&img, (f % 3) * 2 + x, (f / 3) * 2 + y);
                cr_assert(q[3] == s[3] && q[0] == d255(s[0] * s[3]) && q[1] == d255(s[1] * s[3]) &&
                              q[2] == d255(s[2] * s[3]),
                          "frame %d texel (%d, %d)", f, x, y);
            }
        /* level 1: the 2x2 average, rounded */
        const uint8_t *m = base + t.level[1].offset + 4u * (3u + 1u);
        for (int k = 0; k < 4; k++) {
            uint32_t sum = 0;
            for (int y = 0; y < 2; y++)
                for (int x = 0; x < 2; x++)
                    sum += base[4u * ((size_t)(y + 1) * 4u + (size_t)(x + 1)) + (size_t)k];
            cr_assert_eq(m[k], (sum + 2u) / 4u, "frame %d level 1 channel %d", f, k);
        }
    }
    isk_texture_free(&t);
    cr_assert(t.texels == NULL && t.frames == 0);
    isk_texture_free(&t); /* twice is fine */
    isk_texture_free(NULL);
    isk_canvas_free(&img);
}

Test(texture_make, mip_levels_down_to_one_texel)
{
    isk_canvas img;
    cr_assert_eq(isk_canvas_init(&img, 37, 5), ISK_OK);
    isk_canvas_fill(&img, isk_rgba(10, 20, 30, 200));
    isk_texture t;
    cr_assert_eq(isk_texture_from_canvas(&t, &img, 1, 1), ISK_OK);
    const int want[][2] = {{37, 5}, {19, 3}, {10, 2}, {5, 1}, {3, 1}, {2, 1}, {1, 1}};
    cr_assert_eq(t.levels, 7);
    size_t at = 0;
    for (int l = 0; l < t.levels; l++) {
        cr_assert(t.level[l].w == want[l][0] && t.level[l].h == want[l][1], "level %d is %dx%d", l, t.level[l].w,
                  t.level[l].h);
        cr_assert_eq(t.level[l].offset, at);
        at += 4u * (size_t)(want[l][0] + 2) * (size_t)(want[l][1] + 2);
        /* a flat image stays flat at every level */
        const uint8_t *q = t.texels + t.level[l].offset + 4u * ((size_t)(want[l][0] + 2) + 1u);
        cr_assert(q[0] == d255(10 * 200) && q[1] == d255(20 * 200) && q[2] == d255(30 * 200) && q[3] == 200);
    }
    cr_assert_eq(t.frame_bytes, at);
    isk_texture_free(&t);
    isk_canvas_free(&img);
}

Test(texture_make, bad_arguments)
{
    isk_canvas img;
    cr_assert_eq(isk_canvas_init(&img, 12, 8), ISK_OK);
    isk_texture t;
    cr_assert_eq(isk_texture_from_canvas(NULL, &img, 1, 1), ISK_ERR_NULL);
    cr_assert_eq(isk_texture_from_canvas(&t, NULL, 1, 1), ISK_ERR_NULL);
    const int grids[][2] = {{0, 1}, {1, 0}, {-1, 1}, {5, 1}, {1, 3}, {13, 1}, {257, 1}, {1, 1 << 30}};
    for (size_t k = 0; k < sizeof grids / sizeof grids[0]; k++) {
        memset(&t, 0x55, sizeof t);
        cr_assert_eq(isk_texture_from_canvas(&t, &img, grids[k][0], grids[k][1]), ISK_ERR_RANGE, "grid %d x %d",
                     grids[k][0], grids[k][1]);
        cr_assert(t.texels == NULL && t.frames == 0, "zeroed on error");
    }
    isk_canvas bad = img;
    bad.pixels = NULL;
    cr_assert_eq(isk_texture_from_canvas(&t, &bad, 1, 1), ISK_ERR_SIZE);
    bad = img;
    bad.stride = 4;
    cr_assert_eq(isk_texture_from_canvas(&t, &bad, 1, 1), ISK_ERR_SIZE);
    bad = img;
    bad.width = 0;
    cr_assert_eq(isk_texture_from_canvas(&t, &bad, 1, 1), ISK_ERR_SIZE);
    isk_canvas big;
    cr_assert_eq(isk_canvas_init(&big, ISK_TEXTURE_MAX_DIM + 1, 1), ISK_OK);
    cr_assert_eq(isk_texture_from_canvas(&t, &big, 1, 1), ISK_ERR_SIZE);
    isk_canvas_free(&big);
    cr_assert_eq(isk_texture_from_sprite(NULL, ISK_SPRITE_DISC, 4), ISK_ERR_NULL);
    cr_assert_eq(isk_texture_from_sprite(&t, (isk_sprite_kind)9, 4), ISK_ERR_RANGE);
    cr_assert_eq(isk_texture_from_sprite(&t, ISK_SPRITE_DISC, 0), ISK_ERR_SIZE);
    cr_assert_eq(isk_texture_from_sprite(&t, ISK_SPRITE_DISC, ISK_SPRITE_MAX_SIZE + 1), ISK_ERR_SIZE);
    isk_canvas_free(&img);
}

/* ---- files and the cache ---------------------------------------------------------- */

static void tmp_path(char *buf, size_t n, const char *name)
{
    snprintf(buf, n, "out/test_texture_%ld_%s", (long)getpid(), name);
}

static void write_png(const char *path, int w, int h)
{
    isk_canvas img;
    cr_assert_eq(isk_canvas_init(&img, w, h), ISK_OK);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint8_t *q = isk_canvas_at(&img, x, y);
            q[0] = (uint8_t)(x * 7);
            q[1] = (uint8_t)(y * 9);
            q[2] = 100;
            q[3] = (uint8_t)(128 + x);
        }
    isk_error err;
    cr_assert_eq(isk_png_write(&img, path, &err), ISK_OK, "%s", err.message);
    isk_canvas_free(&img);
}

Test(texture_file, load_checks_the_grid_and_names_the_file)
{
    cr_assert(system("mkdir -p out") == 0);
    char path[256];
    tmp_path(path, sizeof path, "sheet.png");
    write_png(path, 24, 8);
    isk_texture t;
    isk_error err;
    cr_assert_eq(isk_texture_load(&t, path, 3, 2, &err), ISK_OK, "%s", err.message);
    cr_assert(t.frames == 6 && t.frame_w == 8 && t.frame_h == 4);
    isk_texture_free(&t);

    cr_assert_eq(isk_texture_load(&t, path, 5, 1, &err), ISK_ERR_RANGE);
    cr_assert(strstr(err.message, path) && strstr(err.message, "24 x 8") && strstr(err.message, "5 x 1"), "%s",
              err.message);
    cr_assert(t.texels == NULL);
    cr_assert_eq(isk_texture_load(&t, path, 0, 1, &err), ISK_ERR_RANGE);
    cr_assert(strstr(err.message, path), "%s", err.message);
    cr_assert_eq(isk_texture_load(&t, "out/no_such_texture.png", 1, 1, &err), ISK_ERR_IO);
    cr_assert(strstr(err.message, "out/no_such_texture.png"), "%s", err.message);
    cr_assert_eq(isk_texture_load(&t, NULL, 1, 1, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_texture_load(NULL, path, 1, 1, NULL), ISK_ERR_NULL);

    char big[256];
    tmp_path(big, sizeof big, "wide.png");
    write_png(big, ISK_TEXTURE_MAX_DIM + 2, 1);
    cr_assert_eq(isk_texture_load(&t, big, 1, 1, &err), ISK_ERR_SIZE);
    cr_assert(strstr(err.message, big) && strstr(err.message, "4096"), "%s", err.message);

    char junk[256];
    tmp_path(junk, sizeof junk, "junk.png");
    FILE *f = fopen(junk, "wb");
    cr_assert(f);
    fputs("not a png at all", f);
    fclose(f);
    cr_assert_eq(isk_texture_load(&t, junk, 1, 1, &err), ISK_ERR_FORMAT);
    cr_assert(strstr(err.message, junk), "%s", err.message);
    remove(path);
    remove(big);
    remove(junk);
}

Test(texture_file, cache_loads_each_file_once)
{
    cr_assert(system("mkdir -p out") == 0);
    char a[256], b[256];
    tmp_path(a, sizeof a, "a.png");
    tmp_path(b, sizeof b, "b.png");
    write_png(a, 16, 16);
    write_png(b, 8, 8);
    isk_texture_cache *cache;
    cr_assert_eq(isk_texture_cache_create(&cache, 3), ISK_OK);
    isk_error err;
    const isk_texture *t1, *t2, *t3, *t4;
    cr_assert_eq(isk_texture_cache_get(cache, a, 1, 1, &t1, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_texture_cache_get(cache, a, 1, 1, &t2, &err), ISK_OK);
    cr_assert_eq(t1, t2);
    cr_assert_eq(isk_texture_cache_loads(cache), 1);
    cr_assert_eq(isk_texture_cache_get(cache, a, 2, 2, &t3, &err), ISK_OK); /* another grid: another texture */
    cr_assert(t3 != t1 && t3->frames == 4);
    const isk_texture *keep = t1;
    t4 = keep;
    cr_assert_eq(isk_texture_cache_get(cache, "out/missing.png", 1, 1, &t4, &err), ISK_ERR_IO);
    cr_assert_eq(t4, keep, "*out untouched on error");
    cr_assert_eq(isk_texture_cache_count(cache), 2, "a failed load is not kept");
    cr_assert_eq(isk_texture_cache_get(cache, b, 1, 1, &t4, &err), ISK_OK);
    cr_assert_eq(isk_texture_cache_get(cache, b, 2, 1, &t4, &err), ISK_ERR_FULL);
    cr_assert(strstr(err.message, b), "%s", err.message);
    cr_assert_eq(isk_texture_cache_get(cache, a, 1, 1, &t2, &err), ISK_OK, "a held texture is found when full");
    cr_assert_eq(isk_texture_cache_loads(cache), 3);
    isk_texture_cache_clear(cache);
    cr_assert_eq(isk_texture_cache_count(cache), 0);
    cr_assert_eq(isk_texture_cache_get(cache, a, 1, 1, &t1, &err), ISK_OK);
    cr_assert_eq(isk_texture_cache_loads(cache), 4);
    cr_assert_eq(isk_texture_cache_get(NULL, a, 1, 1, &t1, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_texture_cache_get(cache, NULL, 1, 1, &t1, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_texture_cache_get(cache, a, 1, 1, NULL, NULL), ISK_ERR_NULL);
    isk_texture_cache_destroy(cache);
    isk_texture_cache_destroy(NULL);
    isk_texture_cache *c2;
    cr_assert_eq(isk_texture_cache_create(&c2, 0), ISK_ERR_SIZE);
    cr_assert_eq(isk_texture_cache_create(&c2, ISK_TEXTURE_CACHE_MAX + 1), ISK_ERR_SIZE);
    cr_assert_eq(isk_texture_cache_create(NULL, 4), ISK_ERR_NULL);
    remove(a);
    remove(b);
}

/* The image rules and their messages live in the texture module; the PNG
 * readers (src/io) check a file's header by them before decoding. */
Test(texture_file, the_size_rules_name_the_texture)
{
    isk_error err;
    cr_assert_eq(isk_texture_check_size("t.png", 64, 32, 4, 2, &err), ISK_OK);
    cr_assert_eq(isk_texture_check_size("t.png", 64, 32, 3, 2, &err), ISK_ERR_RANGE);
    cr_assert(strstr(err.message, "t.png") && strstr(err.message, "64 x 32") && strstr(err.message, "3 x 2"), "%s",
              err.message);
    cr_assert_eq(isk_texture_check_size("t.png", 64, 32, 0, 1, &err), ISK_ERR_RANGE);
    cr_assert_eq(isk_texture_check_size("t.png", 64, 32, 1, ISK_TEXTURE_MAX_GRID + 1, &err), ISK_ERR_RANGE);
    cr_assert_eq(isk_texture_check_size("t.png", ISK_TEXTURE_MAX_DIM + 1, 1, 1, 1, &err), ISK_ERR_SIZE);
    cr_assert(strstr(err.message, "t.png") && strstr(err.message, "4096"), "%s", err.message);
    cr_assert_eq(isk_texture_check_size("t.png", 0, 5, 1, 1, &err), ISK_ERR_SIZE);
    cr_assert_eq(isk_texture_check_size(NULL, 8, 8, 1, 1, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_texture_check_size("t.png", 8, 8, 1, 1, NULL), ISK_OK);
}

/* A texture's pixels read from a PNG file or bytes: the header is checked
 * before decoding, and both give the file's canvas. */
Test(texture_file, image_read_gives_the_files_pixels)
{
    cr_assert(system("mkdir -p out") == 0);
    char path[256], big[256];
    tmp_path(path, sizeof path, "pixels.png");
    tmp_path(big, sizeof big, "pixels_wide.png");
    write_png(path, 24, 8);
    write_png(big, ISK_TEXTURE_MAX_DIM + 2, 1);
    isk_canvas want, img;
    isk_error err;
    cr_assert_eq(isk_png_read(&want, path, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_texture_image_read(&img, path, &err), ISK_OK, "%s", err.message);
    cr_assert(isk_canvas_equal(&img, &want));
    isk_canvas_free(&img);

    FILE *f = fopen(path, "rb");
    cr_assert_not_null(f);
    static unsigned char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    cr_assert_eq(isk_texture_image_read_memory(&img, buf, n, "bytes", &err), ISK_OK, "%s", err.message);
    cr_assert(isk_canvas_equal(&img, &want));
    isk_canvas_free(&img);
    cr_assert_neq(isk_texture_image_read_memory(&img, buf, n / 2, "half", &err), ISK_OK);
    cr_assert(strstr(err.message, "half") && img.pixels == NULL, "%s", err.message);

    cr_assert_eq(isk_texture_image_read(&img, big, &err), ISK_ERR_SIZE);
    cr_assert(strstr(err.message, big) && strstr(err.message, "4096") && img.pixels == NULL, "%s", err.message);
    cr_assert_eq(isk_texture_image_read(&img, "out/no_such_texture.png", &err), ISK_ERR_IO);
    cr_assert(strstr(err.message, "out/no_such_texture.png"), "%s", err.message);
    cr_assert_eq(isk_texture_image_read(&img, NULL, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_texture_image_read(NULL, path, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_texture_image_read_memory(&img, NULL, 4, "x", &err), ISK_ERR_NULL);
    cr_assert_eq(isk_texture_check_file(path, 5, 1, &err), ISK_ERR_RANGE);
    cr_assert_eq(isk_texture_check_file(path, 3, 2, &err), ISK_OK, "%s", err.message);
    isk_canvas_free(&want);
    remove(path);
    remove(big);
}

/* The cache made from pixels: a texture per (name, grid), made once, the
 * same as isk_texture_from_canvas; refusals are not kept. */
Test(texture_file, cache_from_a_canvas_makes_each_once)
{
    isk_canvas img;
    cr_assert_eq(isk_canvas_init(&img, 16, 8), ISK_OK);
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 16; x++)
            memcpy(isk_canvas_at(&img, x, y), (uint8_t[4]){(uint8_t)(x * 15), (uint8_t)(y * 30), 7, 200}, 4);
    isk_texture_cache *cache;
    cr_assert_eq(isk_texture_cache_create(&cache, 2), ISK_OK);
    const isk_texture *t1, *t2, *t3;
    isk_error err;
    cr_assert_eq(isk_texture_cache_get_canvas(cache, "img", &img, 2, 1, &t1, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_texture_cache_get_canvas(cache, "img", &img, 2, 1, &t2, &err), ISK_OK);
    cr_assert_eq(t1, t2);
    cr_assert_eq(isk_texture_cache_loads(cache), 1);
    isk_texture want;
    cr_assert_eq(isk_texture_from_canvas(&want, &img, 2, 1), ISK_OK);
    cr_assert(want.bytes == t1->bytes && !memcmp(want.texels, t1->texels, want.bytes));
    isk_texture_free(&want);
    t3 = t1;
    cr_assert_eq(isk_texture_cache_get_canvas(cache, "img", &img, 3, 1, &t3, &err), ISK_ERR_RANGE);
    cr_assert(strstr(err.message, "img") && strstr(err.message, "16 x 8"), "%s", err.message);
    cr_assert_eq(t3, t1, "*out untouched on error");
    cr_assert_eq(isk_texture_cache_count(cache), 1, "a refused texture is not kept");
    cr_assert_eq(isk_texture_cache_get_canvas(cache, "img", NULL, 1, 1, &t3, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_texture_cache_get_canvas(cache, NULL, &img, 1, 1, &t3, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_texture_cache_get_canvas(cache, "img", &img, 1, 1, &t3, &err), ISK_OK);
    cr_assert_eq(isk_texture_cache_get_canvas(cache, "other", &img, 1, 1, &t3, &err), ISK_ERR_FULL);
    isk_texture_cache_destroy(cache);
    isk_canvas_free(&img);
}
