/* SPDX-License-Identifier: MIT */
/* Value tests for the rasterizer primitives (iskra/draw.h) and the blend
 * rules they rely on: exact bytes, exact pixel sets and counts. */
#include <criterion/criterion.h>

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/draw.h"
#include "iskra/rng.h"

#define ISK_TEST_PI 3.14159265358979323846

static isk_canvas make(int w, int h, isk_color bg)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, w, h), ISK_OK);
    isk_canvas_fill(&c, bg);
    return c;
}

static int px_eq(const isk_canvas *c, int x, int y, int r, int g, int b, int a)
{
    isk_color p = isk_canvas_get(c, x, y);
    return p.r == r && p.g == g && p.b == b && p.a == a;
}

/* Number of pixels whose bytes differ from `bg`. */
static long count_changed(const isk_canvas *c, isk_color bg)
{
    long n = 0;
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++) {
            isk_color p = isk_canvas_get(c, x, y);
            n += (p.r != bg.r || p.g != bg.g || p.b != bg.b || p.a != bg.a);
        }
    return n;
}

/* A unit "counter" colour: ADD with it raises R by exactly 1 per blend, so R
 * counts how many times each pixel was drawn. */
static const isk_color ONE = {1, 0, 0, 255};

/* ---- blending ------------------------------------------------------------ */

Test(blend, over_opaque_destination_exact_bytes)
{
    isk_canvas c = make(2, 1, ISK_BLUE);
    isk_draw_pixel(&c, 0, 0, isk_rgba(255, 0, 0, 128), ISK_BLEND_OVER);
    /* r = div255(255*128) = 128; b = div255(255*127) = (32385+127)/255 = 127 */
    cr_assert(px_eq(&c, 0, 0, 128, 0, 127, 255));
    cr_assert(px_eq(&c, 1, 0, 0, 0, 255, 255));
    isk_canvas_free(&c);
}

Test(blend, over_transparent_destination_keeps_source_colour)
{
    isk_canvas c = make(1, 1, ISK_TRANSPARENT);
    isk_draw_pixel(&c, 0, 0, isk_rgba(10, 200, 30, 77), ISK_BLEND_OVER);
    cr_assert(px_eq(&c, 0, 0, 10, 200, 30, 77));
    isk_canvas_free(&c);
}

Test(blend, add_saturates)
{
    isk_canvas c = make(1, 1, ISK_BLACK);
    isk_color red06 = isk_rgba(255, 0, 0, 153); /* alpha 0.6 */
    isk_draw_pixel(&c, 0, 0, red06, ISK_BLEND_ADD);
    cr_assert(px_eq(&c, 0, 0, 153, 0, 0, 255));
    isk_draw_pixel(&c, 0, 0, red06, ISK_BLEND_ADD);
    cr_assert(px_eq(&c, 0, 0, 255, 0, 0, 255));
    isk_canvas_free(&c);
}

Test(blend, replace_copies_all_channels)
{
    isk_canvas c = make(1, 1, ISK_WHITE);
    isk_draw_pixel(&c, 0, 0, isk_rgba(1, 2, 3, 4), ISK_BLEND_REPLACE);
    cr_assert(px_eq(&c, 0, 0, 1, 2, 3, 4));
    isk_canvas_free(&c);
}

/* One random primitive, fully described by its parameters. */
typedef struct draw_op {
    int kind;
    double a, b, r;
    isk_color col;
} draw_op;

static void apply(isk_canvas *c, const draw_op *o)
{
    switch (o->kind) {
    case 0: isk_draw_dot(c, o->a, o->b, o->col, ISK_BLEND_ADD); break;
    case 1: isk_fill_circle_aa(c, o->a, o->b, o->r, o->col, ISK_BLEND_ADD); break;
    case 2: isk_fill_rect(c, (int)o->a, (int)o->b, (int)o->r, (int)o->r, o->col, ISK_BLEND_ADD); break;
    case 3: isk_stroke_line(c, o->a, o->b, o->a + o->r, o->b + 2.0 * o->r, o->col, ISK_BLEND_ADD); break;
    default: isk_fill_circle(c, o->a, o->b, o->r, o->col, ISK_BLEND_ADD); break;
    }
}

Test(blend, add_is_order_independent)
{
    isk_rng rng;
    isk_rng_seed(&rng, 12345);
    draw_op ops[50];
    for (int i = 0; i < 50; i++) {
        ops[i].kind = (int)isk_rng_below(&rng, 5);
        ops[i].a = isk_rng_range(&rng, 0, 40);
        ops[i].b = isk_rng_range(&rng, 0, 40);
        ops[i].r = isk_rng_range(&rng, 1, 12);
        ops[i].col = isk_rgba((uint8_t)isk_rng_below(&rng, 256), (uint8_t)isk_rng_below(&rng, 256),
                              (uint8_t)isk_rng_below(&rng, 256), (uint8_t)isk_rng_below(&rng, 256));
    }
    isk_canvas a = make(48, 48, isk_rgba(5, 10, 20, 40));
    isk_canvas b = make(48, 48, isk_rgba(5, 10, 20, 40));
    for (int i = 0; i < 50; i++)
        apply(&a, &ops[i]);
    /* A fixed random permutation (Fisher–Yates). */
    int perm[50];
    for (int i = 0; i < 50; i++)
        perm[i] = i;
    for (int i = 49; i > 0; i--) {
        int j = (int)isk_rng_below(&rng, (uint32_t)i + 1);
        int t = perm[i]; perm[i] = perm[j]; perm[j] = t;
    }
    for (int i = 0; i < 50; i++)
        apply(&b, &ops[perm[i]]);
    cr_assert(isk_canvas_equal(&a, &b));
    cr_assert_gt(count_changed(&a, isk_rgba(5, 10, 20, 40)), 100);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

/* ---- pixel and rectangle --------------------------------------------------- */

Test(rect, pixel_out_of_range_is_ignored)
{
    isk_canvas c = make(4, 4, ISK_BLACK);
    int xs[] = {-1, 4, INT_MIN, INT_MAX};
    for (int i = 0; i < 4; i++) {
        isk_draw_pixel(&c, xs[i], 0, ISK_WHITE, ISK_BLEND_REPLACE);
        isk_draw_pixel(&c, 0, xs[i], ISK_WHITE, ISK_BLEND_REPLACE);
    }
    cr_assert_eq(count_changed(&c, ISK_BLACK), 0);
    isk_draw_pixel(&c, 3, 3, ISK_WHITE, ISK_BLEND_REPLACE);
    cr_assert_eq(count_changed(&c, ISK_BLACK), 1);
    cr_assert(px_eq(&c, 3, 3, 255, 255, 255, 255));
    isk_canvas_free(&c);
}

/* Expected pixel count of the canvas-style rectangle clipped to w x h. */
static long rect_expect(long long x, long long y, long long w, long long h, int cw, int ch)
{
    long long x0 = x, x1 = x + w, y0 = y, y1 = y + h, t;
    if (x1 < x0) { t = x0; x0 = x1; x1 = t; }
    if (y1 < y0) { t = y0; y0 = y1; y1 = t; }
    long n = 0;
    for (long long j = 0; j < ch; j++)
        for (long long i = 0; i < cw; i++)
            n += (i >= x0 && i < x1 && j >= y0 && j < y1);
    return n;
}

Test(rect, clipping_with_negative_and_huge_sizes)
{
    const int cases[][4] = {
        {2, 3, 5, 4},        {-3, -3, 6, 6},         {8, 8, -3, -2},      {5, 5, 0, 7},
        {5, 5, -100, -100},  {INT_MIN, INT_MIN, INT_MAX, INT_MAX},
        {INT_MAX, INT_MAX, INT_MIN, INT_MIN}, {0, 0, INT_MAX, INT_MAX}, {-5, 2, INT_MAX, 1},
        {INT_MAX, 0, 10, 10}, {INT_MIN, 0, -10, 10}, {15, 15, -INT_MAX, -INT_MAX},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        isk_canvas c = make(16, 12, ISK_BLACK);
        isk_fill_rect(&c, cases[k][0], cases[k][1], cases[k][2], cases[k][3], ONE, ISK_BLEND_ADD);
        long expect = rect_expect(cases[k][0], cases[k][1], cases[k][2], cases[k][3], 16, 12);
        cr_assert_eq(count_changed(&c, ISK_BLACK), expect, "case %zu", k);
        for (int y = 0; y < 12; y++)
            for (int x = 0; x < 16; x++)
                cr_assert_leq(isk_canvas_get(&c, x, y).r, 1);
        isk_canvas_free(&c);
    }
    /* A negative width extends left of x, like canvas fillRect(). */
    isk_canvas c = make(8, 8, ISK_BLACK);
    isk_fill_rect(&c, 5, 2, -2, 1, ISK_WHITE, ISK_BLEND_REPLACE);
    cr_assert(px_eq(&c, 3, 2, 255, 255, 255, 255));
    cr_assert(px_eq(&c, 4, 2, 255, 255, 255, 255));
    cr_assert_eq(count_changed(&c, ISK_BLACK), 2);
    isk_canvas_free(&c);
}

Test(rect, canvas_view_clips_and_offsets)
{
    isk_canvas parent = make(20, 20, ISK_BLACK), v;
    cr_assert_eq(isk_canvas_view(&v, &parent, 5, 6, 8, 4), ISK_OK);
    isk_fill_rect(&v, -10, -10, 100, 100, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_fill_circle(&v, 4, 2, 50, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_stroke_line(&v, -100, 1, 100, 1, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_draw_line(&v, -50, -50, 50, 50, ISK_WHITE, ISK_BLEND_REPLACE);
    cr_assert_eq(count_changed(&parent, ISK_BLACK), 32);
    for (int y = 0; y < 20; y++)
        for (int x = 0; x < 20; x++) {
            int inside = x >= 5 && x < 13 && y >= 6 && y < 10;
            cr_assert_eq(isk_canvas_get(&parent, x, y).r, inside ? 255 : 0);
        }
    /* A view wholly outside is 0x0: drawing into it changes nothing. */
    isk_canvas e;
    cr_assert_eq(isk_canvas_view(&e, &parent, 30, 30, 5, 5), ISK_OK);
    isk_canvas_fill(&parent, ISK_BLACK);
    isk_fill_rect(&e, 0, 0, 5, 5, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_draw_dot(&e, -0.5, -0.5, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_fill_circle_aa(&e, 0, 0, 3, ISK_WHITE, ISK_BLEND_REPLACE);
    cr_assert_eq(count_changed(&parent, ISK_BLACK), 0);
    isk_canvas_free(&parent);
}

/* ---- Bresenham lines ------------------------------------------------------- */

/* Checks the line from pixel (x0,y0) to (x1,y1): one pixel per major step,
 * both ends, each pixel once, every pixel within half a pixel of the ideal
 * line, and the same set in both directions. */
static void check_line(int x0, int y0, int x1, int y1)
{
    isk_canvas a = make(40, 40, ISK_BLACK), b = make(40, 40, ISK_BLACK);
    isk_draw_line(&a, x0 + 0.5, y0 + 0.5, x1 + 0.5, y1 + 0.5, ONE, ISK_BLEND_ADD);
    isk_draw_line(&b, x1 + 0.3, y1 + 0.9, x0 + 0.7, y0 + 0.1, ONE, ISK_BLEND_ADD);
    cr_assert(isk_canvas_equal(&a, &b), "line (%d,%d)-(%d,%d) not symmetric", x0, y0, x1, y1);
    int dx = abs(x1 - x0), dy = abs(y1 - y0);
    int n = (dx > dy ? dx : dy) + 1;
    cr_assert_eq(count_changed(&a, ISK_BLACK), n);
    cr_assert_eq(isk_canvas_get(&a, x0, y0).r, 1);
    cr_assert_eq(isk_canvas_get(&a, x1, y1).r, 1);
    for (int y = 0; y < 40; y++)
        for (int x = 0; x < 40; x++) {
            int v = isk_canvas_get(&a, x, y).r;
            cr_assert_leq(v, 1);
            if (!v || n == 1)
                continue;
            if (dx >= dy) {
                double ideal = y0 + (double)(y1 - y0) * (x - x0) / (x1 - x0);
                cr_assert_leq(fabs(y - ideal), 0.5);
            } else {
                double ideal = x0 + (double)(x1 - x0) * (y - y0) / (y1 - y0);
                cr_assert_leq(fabs(x - ideal), 0.5);
            }
        }
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(line, eight_octants)
{
    const int ends[][2] = {{30, 24}, {24, 30}, {16, 30}, {10, 24},
                           {10, 16}, {16, 10}, {24, 10}, {30, 16}};
    for (int k = 0; k < 8; k++)
        check_line(20, 20, ends[k][0], ends[k][1]);
    /* axis-aligned and diagonal */
    check_line(3, 5, 30, 5);
    check_line(5, 3, 5, 30);
    check_line(2, 2, 30, 30);
    check_line(30, 2, 2, 30);
    check_line(7, 7, 7, 7);
}

Test(line, known_pixel_set_and_tie_rule)
{
    /* (0,0)-(5,2): minor offset = round_half_up(i*2/5) = 0,0,1,1,2,2 */
    isk_canvas c = make(8, 4, ISK_BLACK);
    isk_draw_line(&c, 0.5, 0.5, 5.5, 2.5, ONE, ISK_BLEND_ADD);
    const int want[][2] = {{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 2}, {5, 2}};
    for (int k = 0; k < 6; k++)
        cr_assert_eq(isk_canvas_get(&c, want[k][0], want[k][1]).r, 1, "pixel %d", k);
    cr_assert_eq(count_changed(&c, ISK_BLACK), 6);
    /* (0,0)-(2,1): the tie at i = 1 rounds away from the left end. */
    isk_canvas_fill(&c, ISK_BLACK);
    isk_draw_line(&c, 2.5, 1.5, 0.5, 0.5, ONE, ISK_BLEND_ADD);
    cr_assert_eq(isk_canvas_get(&c, 0, 0).r, 1);
    cr_assert_eq(isk_canvas_get(&c, 1, 1).r, 1);
    cr_assert_eq(isk_canvas_get(&c, 2, 1).r, 1);
    cr_assert_eq(count_changed(&c, ISK_BLACK), 3);
    isk_canvas_free(&c);
}

Test(line, clipped_line_matches_unclipped_pixels)
{
    /* A line drawn on a small canvas must light exactly the pixels the same
     * line lights on a large canvas, restricted to the small one. */
    isk_rng rng;
    isk_rng_seed(&rng, 7);
    for (int t = 0; t < 500; t++) {
        double x0 = isk_rng_range(&rng, -60, 100), y0 = isk_rng_range(&rng, -60, 100);
        double x1 = isk_rng_range(&rng, -60, 100), y1 = isk_rng_range(&rng, -60, 100);
        isk_canvas big = make(300, 300, ISK_BLACK), small = make(40, 40, ISK_BLACK), v;
        cr_assert_eq(isk_canvas_view(&v, &big, 100, 100, 40, 40), ISK_OK);
        isk_draw_line(&big, x0 + 100, y0 + 100, x1 + 100, y1 + 100, ONE, ISK_BLEND_ADD);
        isk_draw_line(&small, x0, y0, x1, y1, ONE, ISK_BLEND_ADD);
        for (int y = 0; y < 40; y++)
            for (int x = 0; x < 40; x++)
                cr_assert_eq(isk_canvas_get(&small, x, y).r, isk_canvas_get(&v, x, y).r,
                             "t=%d (%d,%d)", t, x, y);
        isk_canvas_free(&big);
        isk_canvas_free(&small);
    }
}

Test(line, triangle_outline_blends_vertices_once)
{
    isk_canvas c = make(40, 40, ISK_BLACK);
    isk_draw_triangle(&c, 5.5, 5.5, 30.5, 8.5, 12.5, 33.5, ONE, ISK_BLEND_ADD);
    long n = 0;
    for (int y = 0; y < 40; y++)
        for (int x = 0; x < 40; x++) {
            int v = isk_canvas_get(&c, x, y).r;
            cr_assert_leq(v, 1, "(%d,%d) drawn %d times", x, y, v);
            n += v;
        }
    /* edge lengths in major steps: 25, 25, 28 → 78 pixels, each vertex once */
    cr_assert_eq(n, 78);
    cr_assert_eq(isk_canvas_get(&c, 5, 5).r, 1);
    cr_assert_eq(isk_canvas_get(&c, 30, 8).r, 1);
    cr_assert_eq(isk_canvas_get(&c, 12, 33).r, 1);
    /* all three vertices in one pixel: that pixel, once */
    isk_canvas_fill(&c, ISK_BLACK);
    isk_draw_triangle(&c, 3.1, 3.2, 3.9, 3.3, 3.5, 3.8, ONE, ISK_BLEND_ADD);
    cr_assert_eq(count_changed(&c, ISK_BLACK), 1);
    cr_assert_eq(isk_canvas_get(&c, 3, 3).r, 1);
    isk_canvas_free(&c);
}

/* ---- filled triangles ------------------------------------------------------ */

Test(triangle, top_left_rule_on_half_integer_vertices)
{
    isk_canvas c = make(8, 8, ISK_BLACK);
    /* Centres on the top and left edges are in, on the hypotenuse out. */
    isk_fill_triangle(&c, 0.5, 0.5, 4.5, 0.5, 0.5, 4.5, ONE, ISK_BLEND_ADD);
    cr_assert_eq(count_changed(&c, ISK_BLACK), 10);
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++)
            cr_assert_eq(isk_canvas_get(&c, i, j).r, i + j < 4 ? 1 : 0);
    /* The complementary triangle fills the rest of the 4x4 block, once. */
    isk_fill_triangle(&c, 4.5, 0.5, 4.5, 4.5, 0.5, 4.5, ONE, ISK_BLEND_ADD);
    cr_assert_eq(count_changed(&c, ISK_BLACK), 16);
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++)
            cr_assert_eq(isk_canvas_get(&c, i, j).r, 1);
    isk_canvas_free(&c);
}

Test(triangle, winding_does_not_matter_and_degenerate_draws_nothing)
{
    isk_canvas a = make(30, 30, ISK_BLACK), b = make(30, 30, ISK_BLACK);
    isk_fill_triangle(&a, 2.3, 4.1, 27.7, 9.2, 11.0, 26.6, ONE, ISK_BLEND_ADD);
    isk_fill_triangle(&b, 11.0, 26.6, 27.7, 9.2, 2.3, 4.1, ONE, ISK_BLEND_ADD);
    cr_assert(isk_canvas_equal(&a, &b));
    isk_canvas_fill(&a, ISK_BLACK);
    isk_fill_triangle(&a, 1.5, 1.5, 10.5, 10.5, 20.5, 20.5, ONE, ISK_BLEND_ADD);
    isk_fill_triangle(&a, 1.5, 1.5, 1.5, 1.5, 20.5, 3.5, ONE, ISK_BLEND_ADD);
    cr_assert_eq(count_changed(&a, ISK_BLACK), 0);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(triangle, shared_edges_are_drawn_once)
{
    /* A fan of triangles around a random centre, with random fractional
     * vertices: every pixel is drawn at most once, and every pixel whose
     * centre is well inside the fan's outline exactly once. */
    isk_rng rng;
    isk_rng_seed(&rng, 99);
    for (int t = 0; t < 20; t++) {
        isk_canvas c = make(64, 64, ISK_BLACK);
        double cx = isk_rng_range(&rng, 28, 36), cy = isk_rng_range(&rng, 28, 36);
        enum { K = 11 };
        double px[K], py[K];
        for (int k = 0; k < K; k++) {
            double ang = 2.0 * ISK_TEST_PI * (k + isk_rng_range(&rng, 0.0, 0.8)) / K;
            double rad = isk_rng_range(&rng, 15, 28);
            px[k] = cx + rad * cos(ang);
            py[k] = cy + rad * sin(ang);
        }
        /* Also the exactly shared diagonal of a pixel-aligned square. */
        for (int k = 0; k < K; k++)
            isk_fill_triangle(&c, cx, cy, px[k], py[k], px[(k + 1) % K], py[(k + 1) % K], ONE,
                              ISK_BLEND_ADD);
        for (int y = 0; y < 64; y++)
            for (int x = 0; x < 64; x++)
                cr_assert_leq(isk_canvas_get(&c, x, y).r, 1, "t=%d (%d,%d)", t, x, y);
        /* centre pixel region is covered */
        cr_assert_eq(isk_canvas_get(&c, (int)cx, (int)cy).r, 1);
        /* a pixel between two fan triangles (along a spoke) is covered once */
        for (int k = 0; k < K; k++) {
            double sx = cx + 0.5 * (px[k] - cx), sy = cy + 0.5 * (py[k] - cy);
            cr_assert_eq(isk_canvas_get(&c, (int)floor(sx), (int)floor(sy)).r, 1, "spoke %d", k);
        }
        isk_canvas_free(&c);
    }
    isk_canvas c = make(16, 16, ISK_BLACK);
    isk_fill_triangle(&c, 1, 1, 13, 1, 13, 13, ONE, ISK_BLEND_ADD);
    isk_fill_triangle(&c, 1, 1, 13, 13, 1, 13, ONE, ISK_BLEND_ADD);
    cr_assert_eq(count_changed(&c, ISK_BLACK), 144);
    for (int y = 1; y < 13; y++)
        for (int x = 1; x < 13; x++)
            cr_assert_eq(isk_canvas_get(&c, x, y).r, 1);
    isk_canvas_free(&c);
}

/* ---- circles --------------------------------------------------------------- */

static long brute_circle(double cx, double cy, double r)
{
    long n = 0;
    for (int j = 0; j < 64; j++)
        for (int i = 0; i < 64; i++) {
            double dx = i + 0.5 - cx, dy = j + 0.5 - cy;
            n += dx * dx + dy * dy < r * r;
        }
    return n;
}

Test(circle, pixel_counts_r1_to_r8)
{
    const long at_int[8] = {4, 12, 32, 52, 80, 112, 156, 208};
    const long at_centre[8] = {1, 9, 25, 45, 69, 109, 145, 193};
    for (int r = 1; r <= 8; r++) {
        isk_canvas c = make(64, 64, ISK_BLACK);
        isk_fill_circle(&c, 32, 32, r, ONE, ISK_BLEND_ADD);
        cr_assert_eq(count_changed(&c, ISK_BLACK), brute_circle(32, 32, r));
        cr_assert_eq(count_changed(&c, ISK_BLACK), at_int[r - 1], "r=%d integer centre", r);
        isk_canvas_fill(&c, ISK_BLACK);
        isk_fill_circle(&c, 32.5, 32.5, r, ONE, ISK_BLEND_ADD);
        cr_assert_eq(count_changed(&c, ISK_BLACK), brute_circle(32.5, 32.5, r));
        cr_assert_eq(count_changed(&c, ISK_BLACK), at_centre[r - 1], "r=%d pixel centre", r);
        isk_canvas_free(&c);
    }
    /* random centres and radii against brute force, including clipping */
    isk_rng rng;
    isk_rng_seed(&rng, 3);
    for (int t = 0; t < 200; t++) {
        double cx = isk_rng_range(&rng, -10, 74), cy = isk_rng_range(&rng, -10, 74);
        double r = isk_rng_range(&rng, 0, 20);
        isk_canvas c = make(64, 64, ISK_BLACK);
        isk_fill_circle(&c, cx, cy, r, ONE, ISK_BLEND_ADD);
        cr_assert_eq(count_changed(&c, ISK_BLACK), brute_circle(cx, cy, r), "t=%d", t);
        isk_canvas_free(&c);
    }
}

Test(circle, aa_exact_area_values)
{
    isk_canvas c = make(8, 8, ISK_TRANSPARENT);
    /* r = 0.5 at a pixel centre: the disc lies in one pixel, area pi/4 →
     * floor(255*0.7854 + 0.5) = 200; replace on transparent stores it in alpha */
    isk_fill_circle_aa(&c, 2.5, 2.5, 0.5, ISK_WHITE, ISK_BLEND_REPLACE);
    cr_assert(px_eq(&c, 2, 2, 255, 255, 255, 200));
    cr_assert_eq(count_changed(&c, ISK_TRANSPARENT), 1);
    /* r = 1 at an integer point: four quarter discs of area pi/4 */
    isk_canvas_fill(&c, ISK_TRANSPARENT);
    isk_fill_circle_aa(&c, 5, 5, 1, ISK_WHITE, ISK_BLEND_REPLACE);
    cr_assert_eq(count_changed(&c, ISK_TRANSPARENT), 4);
    cr_assert_eq(isk_canvas_get(&c, 4, 4).a, 200);
    cr_assert_eq(isk_canvas_get(&c, 5, 5).a, 200);
    isk_canvas_free(&c);
}

Test(circle, aa_total_coverage_matches_area)
{
    const double rs[] = {0.3, 1.7, 5.25, 13.0, 27.9};
    for (size_t k = 0; k < sizeof rs / sizeof rs[0]; k++) {
        double r = rs[k];
        isk_canvas c = make(64, 64, ISK_TRANSPARENT);
        isk_fill_circle_aa(&c, 31.37, 30.81, r, ISK_WHITE, ISK_BLEND_REPLACE);
        double sum = 0;
        long edge = 0;
        for (int y = 0; y < 64; y++)
            for (int x = 0; x < 64; x++) {
                int a = isk_canvas_get(&c, x, y).a;
                sum += a;
                edge += a > 0 && a < 255;
            }
        /* each pixel's byte is within 0.5 of 255*area */
        cr_assert_leq(fabs(sum / 255.0 - ISK_TEST_PI * r * r), 0.5 * edge / 255.0 + 1e-9, "r=%g", r);
        isk_canvas_free(&c);
    }
}

Test(circle, aa_big_radius_is_a_straight_edge)
{
    /* r = 1e6 centred far to the right: over the canvas the edge is the line
     * x = 10.25 (to 1e-5 px), so column 10 is 3/4 covered. */
    isk_canvas c = make(20, 4, ISK_TRANSPARENT);
    isk_fill_circle_aa(&c, 1e6 + 10.25, 2.0, 1e6, ISK_WHITE, ISK_BLEND_REPLACE);
    for (int y = 0; y < 4; y++) {
        cr_assert_eq(isk_canvas_get(&c, 9, y).a, 0);
        cr_assert_eq(isk_canvas_get(&c, 10, y).a, 191);
        cr_assert_eq(isk_canvas_get(&c, 11, y).a, 255);
    }
    isk_canvas_free(&c);
}

/* ---- coverage dot ---------------------------------------------------------- */

Test(dot, weights_sum_to_255)
{
    isk_rng rng;
    isk_rng_seed(&rng, 2024);
    for (int t = 0; t < 100000; t++) {
        double scale = t % 3 == 0 ? 1.0 : (t % 3 == 1 ? 1000.0 : 1e7);
        double x = isk_rng_range(&rng, -scale, scale), y = isk_rng_range(&rng, -scale, scale);
        uint8_t w[4];
        cr_assert_eq(isk_dot_weights(x, y, w), 1);
        int s = w[0] + w[1] + w[2] + w[3];
        cr_assert_eq(s, 255, "(%.17g, %.17g) sums to %d", x, y, s);
        /* each weight is within 1 of the exact area */
        double fx = x - floor(x), fy = y - floor(y);
        double ex[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
        for (int k = 0; k < 4; k++)
            cr_assert_lt(fabs(w[k] - 255.0 * ex[k]), 1.0);
    }
}

Test(dot, documented_values)
{
    uint8_t w[4];
    cr_assert_eq(isk_dot_weights(180, 420, w), 1);
    cr_assert(w[0] == 255 && w[1] == 0 && w[2] == 0 && w[3] == 0);
    cr_assert_eq(isk_dot_weights(-7, 3, w), 1);
    cr_assert(w[0] == 255 && w[1] == 0 && w[2] == 0 && w[3] == 0);
    isk_dot_weights(10.5, 3, w);
    cr_assert(w[0] == 128 && w[1] == 127 && w[2] == 0 && w[3] == 0);
    isk_dot_weights(10, 3.5, w);
    cr_assert(w[0] == 128 && w[1] == 0 && w[2] == 127 && w[3] == 0);
    isk_dot_weights(10.5, 3.5, w);
    cr_assert(w[0] == 64 && w[1] == 64 && w[2] == 64 && w[3] == 63);
    isk_dot_weights(2.0, 5.25, w); /* 191.25 and 63.75: the .75 gets the unit */
    cr_assert(w[0] == 191 && w[1] == 0 && w[2] == 64 && w[3] == 0);
    isk_dot_weights(-0.25, 0.0, w); /* block starts at -1: 0.25 and 0.75 */
    cr_assert(w[0] == 64 && w[1] == 191 && w[2] == 0 && w[3] == 0);
    cr_assert_eq(isk_dot_weights(NAN, 1, w), 0);
    cr_assert(w[0] == 0 && w[1] == 0 && w[2] == 0 && w[3] == 0);
    cr_assert_eq(isk_dot_weights(1, INFINITY, w), 0);
    cr_assert_eq(isk_dot_weights(-INFINITY, 1, w), 0);
}

Test(dot, draw_matches_weights_and_clips)
{
    isk_rng rng;
    isk_rng_seed(&rng, 5);
    for (int t = 0; t < 2000; t++) {
        double x = isk_rng_range(&rng, -2, 9), y = isk_rng_range(&rng, -2, 9);
        isk_canvas c = make(8, 8, ISK_TRANSPARENT);
        isk_draw_dot(&c, x, y, ISK_WHITE, ISK_BLEND_REPLACE);
        uint8_t w[4];
        isk_dot_weights(x, y, w);
        int ix = (int)floor(x), iy = (int)floor(y);
        for (int j = 0; j < 8; j++)
            for (int i = 0; i < 8; i++) {
                int expect = 0;
                if (j == iy && i == ix) expect = w[0];
                if (j == iy && i == ix + 1) expect = w[1];
                if (j == iy + 1 && i == ix) expect = w[2];
                if (j == iy + 1 && i == ix + 1) expect = w[3];
                cr_assert_eq(isk_canvas_get(&c, i, j).a, expect, "(%g,%g) pixel (%d,%d)", x, y, i, j);
            }
        isk_canvas_free(&c);
    }
}

Test(dot, figure9_integer_position_is_one_full_pixel)
{
    isk_canvas c = make(600, 600, ISK_BLACK);
    isk_draw_dot(&c, 180, 420, ISK_YELLOW, ISK_BLEND_OVER);
    cr_assert_eq(count_changed(&c, ISK_BLACK), 1);
    cr_assert(px_eq(&c, 180, 420, 255, 255, 0, 255));
    isk_canvas_free(&c);
}

/* ---- anti-aliased strokes -------------------------------------------------- */

Test(stroke, horizontal_integer_line_is_two_half_rows)
{
    isk_canvas c = make(500, 500, ISK_TRANSPARENT);
    isk_stroke_line(&c, 175, 300, 325, 300, ISK_BLACK, ISK_BLEND_REPLACE);
    for (int x = 170; x < 330; x++) {
        int in = x >= 175 && x < 325;
        cr_assert_eq(isk_canvas_get(&c, x, 299).a, in ? 128 : 0, "x=%d", x);
        cr_assert_eq(isk_canvas_get(&c, x, 300).a, in ? 128 : 0, "x=%d", x);
    }
    cr_assert_eq(count_changed(&c, ISK_TRANSPARENT), 300);
    /* at a pixel centre the same line is one full row */
    isk_canvas_fill(&c, ISK_TRANSPARENT);
    isk_stroke_line(&c, 10, 20.5, 30, 20.5, ISK_BLACK, ISK_BLEND_REPLACE);
    cr_assert_eq(count_changed(&c, ISK_TRANSPARENT), 20);
    cr_assert_eq(isk_canvas_get(&c, 10, 20).a, 255);
    cr_assert_eq(isk_canvas_get(&c, 29, 20).a, 255);
    /* vertical, butt ends at fractional positions: end pixels partly covered */
    isk_canvas_fill(&c, ISK_TRANSPARENT);
    isk_stroke_line(&c, 7.5, 3.25, 7.5, 6.5, ISK_BLACK, ISK_BLEND_REPLACE);
    cr_assert_eq(isk_canvas_get(&c, 7, 3).a, 191);
    cr_assert_eq(isk_canvas_get(&c, 7, 4).a, 255);
    cr_assert_eq(isk_canvas_get(&c, 7, 6).a, 128);
    cr_assert_eq(count_changed(&c, ISK_TRANSPARENT), 4);
    isk_canvas_free(&c);
}

Test(stroke, diagonal_row_sums_match_exact_area)
{
    /* A width-1 line at slope 3/4 has area 1/sin = 5/4 per row crossed. */
    isk_canvas c = make(60, 60, ISK_TRANSPARENT);
    isk_stroke_line(&c, 10, 10, 40, 50, ISK_WHITE, ISK_BLEND_REPLACE);
    for (int y = 15; y < 45; y++) {
        int s = 0;
        for (int x = 0; x < 60; x++)
            s += isk_canvas_get(&c, x, y).a;
        cr_assert_leq(abs(s - (int)lround(255 * 1.25)), 2, "row %d sum %d", y, s);
    }
    isk_canvas_free(&c);
}

Test(stroke, zero_length_and_invalid_draw_nothing)
{
    isk_canvas c = make(20, 20, ISK_BLACK);
    isk_stroke_line(&c, 5, 5, 5, 5, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_stroke_line(&c, 5, NAN, 10, 10, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_stroke_line(&c, 5, 5, INFINITY, 10, ISK_WHITE, ISK_BLEND_REPLACE);
    double one[2] = {3, 3};
    isk_stroke_polyline(&c, one, 1, 1, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_stroke_polyline(&c, NULL, 3, 0, ISK_WHITE, ISK_BLEND_REPLACE);
    double same[6] = {4, 4, 4, 4, 4, 4};
    isk_stroke_polyline(&c, same, 3, 1, ISK_WHITE, ISK_BLEND_REPLACE);
    cr_assert_eq(count_changed(&c, ISK_BLACK), 0);
    isk_canvas_free(&c);
}

Test(stroke, polyline_of_two_points_equals_line)
{
    isk_rng rng;
    isk_rng_seed(&rng, 11);
    for (int t = 0; t < 200; t++) {
        double xy[4];
        for (int k = 0; k < 4; k++)
            xy[k] = isk_rng_range(&rng, -10, 50);
        isk_canvas a = make(40, 40, ISK_BLACK), b = make(40, 40, ISK_BLACK);
        isk_stroke_line(&a, xy[0], xy[1], xy[2], xy[3], ISK_WHITE, ISK_BLEND_OVER);
        isk_stroke_polyline(&b, xy, 2, 0, ISK_WHITE, ISK_BLEND_OVER);
        cr_assert(isk_canvas_equal(&a, &b));
        isk_canvas_free(&a);
        isk_canvas_free(&b);
    }
}

Test(stroke, closed_square_joins_painted_once)
{
    /* Vertices at pixel centres: every stroke pixel, corners included (the
     * miter fills them), is fully covered and blended exactly once. */
    isk_canvas c = make(40, 30, ISK_WHITE);
    const double sq[8] = {10.5, 10.5, 30.5, 10.5, 30.5, 20.5, 10.5, 20.5};
    isk_color half_red = isk_rgba(255, 0, 0, 128);
    isk_stroke_polyline(&c, sq, 4, 1, half_red, ISK_BLEND_OVER);
    /* one blend of red at 128 over white: g = b = div255(255*127) = 127 */
    for (int y = 0; y < 30; y++)
        for (int x = 0; x < 40; x++) {
            int on = ((y == 10 || y == 20) && x >= 10 && x <= 30) ||
                     ((x == 10 || x == 30) && y >= 10 && y <= 20);
            cr_assert(px_eq(&c, x, y, 255, on ? 127 : 255, on ? 127 : 255, 255), "(%d,%d)", x, y);
        }
    isk_canvas_free(&c);
}

Test(stroke, open_path_has_butt_ends_and_union_at_overlap)
{
    /* The same square left open: at the start/end vertex the two butt ends
     * overlap in a quarter pixel; the union covers 3/4 of pixel (10,10). */
    isk_canvas c = make(40, 30, ISK_TRANSPARENT);
    const double sq[10] = {10.5, 10.5, 30.5, 10.5, 30.5, 20.5, 10.5, 20.5, 10.5, 10.5};
    isk_stroke_polyline(&c, sq, 5, 0, ISK_WHITE, ISK_BLEND_REPLACE);
    cr_assert_eq(isk_canvas_get(&c, 10, 10).a, 191);
    cr_assert_eq(isk_canvas_get(&c, 30, 10).a, 255);
    cr_assert_eq(isk_canvas_get(&c, 10, 20).a, 255);
    cr_assert_eq(isk_canvas_get(&c, 9, 10).a, 0);
    cr_assert_eq(isk_canvas_get(&c, 10, 9).a, 0);
    /* closing with a repeated point and closed=1 gives the full corner */
    isk_canvas_fill(&c, ISK_TRANSPARENT);
    isk_stroke_polyline(&c, sq, 5, 1, ISK_WHITE, ISK_BLEND_REPLACE);
    cr_assert_eq(isk_canvas_get(&c, 10, 10).a, 255);
    isk_canvas_free(&c);
}

static int miter_probe(double phi_deg)
{
    /* Two long segments meeting at V = (50.5, 50.5) with interior angle phi,
     * the bisector of the outer side pointing along +x. */
    double h = phi_deg * ISK_TEST_PI / 360.0;
    double xy[6] = {50.5 - 40 * cos(h), 50.5 - 40 * sin(h), 50.5, 50.5,
                    50.5 - 40 * cos(h), 50.5 + 40 * sin(h)};
    isk_canvas c = make(100, 100, ISK_TRANSPARENT);
    isk_stroke_polyline(&c, xy, 3, 0, ISK_WHITE, ISK_BLEND_REPLACE);
    int a = isk_canvas_get(&c, 53, 50).a;
    isk_canvas_free(&c);
    return a;
}

Test(stroke, miter_limit_10)
{
    /* ratio 1/sin(phi/2): 13 deg → 8.8 (miter tip 4.4 px out), 10 deg → 11.5
     * (over the limit: bevel, nothing 3 px beyond the vertex). */
    cr_assert_gt(miter_probe(13.0), 0);
    cr_assert_eq(miter_probe(10.0), 0);
}

Test(stroke, huge_coordinates_still_draw_the_visible_part)
{
    isk_canvas c = make(30, 30, ISK_TRANSPARENT);
    isk_stroke_line(&c, -1e300, 15.5, 1e300, 15.5, ISK_WHITE, ISK_BLEND_REPLACE);
    for (int x = 0; x < 30; x++)
        cr_assert_eq(isk_canvas_get(&c, x, 15).a, 255);
    cr_assert_eq(count_changed(&c, ISK_TRANSPARENT), 30);
    isk_canvas_fill(&c, ISK_TRANSPARENT);
    isk_draw_line(&c, 10.5, -1e300, 10.5, 1e300, ISK_WHITE, ISK_BLEND_REPLACE);
    cr_assert_eq(count_changed(&c, ISK_TRANSPARENT), 30);
    isk_canvas_fill(&c, ISK_TRANSPARENT);
    isk_fill_triangle(&c, -1e300, -1e300, 1e300, -1e300, 0, 1e300, ISK_WHITE, ISK_BLEND_REPLACE);
    cr_assert_eq(count_changed(&c, ISK_TRANSPARENT), 900);
    isk_canvas_fill(&c, ISK_TRANSPARENT);
    isk_fill_circle(&c, 15, 1e300, 1e300, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_fill_circle(&c, NAN, 5, 3, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_fill_circle(&c, 5, 5, INFINITY, ISK_WHITE, ISK_BLEND_REPLACE);
    isk_canvas_free(&c);
}

/* The browser's dot rule (faithful mode): Skia's fillRect coverage. */
Test(dot, browser_rule_values)
{
    int ix, iy;
    uint8_t w[4];
    cr_assert(isk_dot_weights_browser(180.0, 420.0, &ix, &iy, w));
    cr_assert(ix == 180 && iy == 420 && w[0] == 255 && w[1] == 0 && w[2] == 0 && w[3] == 0);
    /* Half a pixel right: two columns of 128/256 on a whole row (255). */
    cr_assert(isk_dot_weights_browser(10.5, 3.0, &ix, &iy, w));
    cr_assert(ix == 10 && w[0] == 127 && w[1] == 127 && w[2] == 0 && w[3] == 0);
    /* A sliver thinner than 1/512 px snaps away: no second column at all. */
    cr_assert(isk_dot_weights_browser(10.001, 3.0, &ix, &iy, w));
    cr_assert(ix == 10 && w[0] == 255 && w[1] == 0);
    /* Just below an integer snaps up to it (the cell moves). */
    cr_assert(isk_dot_weights_browser(10.999, 3.0, &ix, &iy, w));
    cr_assert(ix == 11 && w[0] == 255);
    /* Coverage is on Skia's 1/256 scale: two partial rows of a whole column
     * sum to 256; truncating row x column products loses a little. */
    isk_rng r;
    isk_rng_seed(&r, 5);
    for (int i = 0; i < 100000; i++) {
        double x = isk_rng_range(&r, -5, 600), y = isk_rng_range(&r, -5, 600);
        cr_assert(isk_dot_weights_browser(x, y, &ix, &iy, w));
        int sum = w[0] + w[1] + w[2] + w[3];
        cr_assert(sum <= 256 && sum >= 250, "sum %d at (%.17g, %.17g)", sum, x, y);
    }
    cr_assert(!isk_dot_weights_browser(NAN, 1, &ix, &iy, w));
    cr_assert(!isk_dot_weights_browser(1e300, 1, &ix, &iy, w));
    cr_assert(!isk_dot_weights_browser(1, -INFINITY, &ix, &iy, w));
}

Test(dot, browser_dot_draws_its_weights_and_clips)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 8, 8), ISK_OK);
    isk_canvas_fill(&c, ISK_BLACK);
    isk_draw_dot_browser(&c, 2.5, 3.25, ISK_YELLOW, ISK_BLEND_OVER);
    int ix, iy;
    uint8_t w[4];
    isk_dot_weights_browser(2.5, 3.25, &ix, &iy, w);
    cr_assert_eq(isk_canvas_get(&c, 2, 3).r, w[0]);
    cr_assert_eq(isk_canvas_get(&c, 3, 3).r, w[1]);
    cr_assert_eq(isk_canvas_get(&c, 2, 4).r, w[2]);
    cr_assert_eq(isk_canvas_get(&c, 3, 4).r, w[3]);
    isk_draw_dot_browser(&c, -1.5, 7.5, ISK_YELLOW, ISK_BLEND_OVER); /* partly outside */
    isk_draw_dot_browser(&c, NAN, 2, ISK_YELLOW, ISK_BLEND_OVER);
    isk_draw_dot_browser(&c, 1e300, -1e300, ISK_YELLOW, ISK_BLEND_OVER);
    cr_assert_eq(isk_canvas_get(&c, 0, 7).r, 0);
    isk_canvas_free(&c);
}
