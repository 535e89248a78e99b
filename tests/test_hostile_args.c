/* SPDX-License-Identifier: MIT */
/* Every public function of core, raster, view, chart and io keeps its
 * contract on hostile arguments: NULL pointers, zero, negative and
 * overflowing sizes, NaN and infinities.  Functions that can fail return
 * the documented status; the others do nothing (or return their documented
 * neutral value) — none crashes, hangs or writes out of bounds.  One test
 * per function, so a crash names it; the suite also runs under ASan+UBSan
 * (make test SANITIZE=1, SANITIZE=clang).
 *
 * Also the sim's force and explosion helpers and the widget layer's
 * layout arithmetic, which a pointer event at extreme coordinates reaches
 * (the rest of src/sim and src/scene have their own tests). */
#include <criterion/criterion.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "iskra/blend.h"
#include "iskra/canvas.h"
#include "iskra/chart.h"
#include "iskra/draw.h"
#include "iskra/explode.h"
#include "iskra/forces.h"
#include "iskra/outfile.h"
#include "iskra/gradient.h"
#include "iskra/png.h"
#include "iskra/rng.h"
#include "iskra/sinlut.h"
#include "iskra/sprite.h"
#include "iskra/tasks.h"
#include "iskra/status.h"
#include "iskra/text.h"
#include "iskra/timestep.h"
#include "iskra/ui.h"
#include "iskra/view.h"

/* Opaque to the optimiser, so passing them is not a compile-time warning. */
static void *volatile null_ptr = NULL;
#define NUL ((void *)null_ptr)

static const double BAD[] = {NAN, INFINITY, -INFINITY, 1e300, -1e300, 0x1p62, -0x1p62};
enum { NBAD = sizeof BAD / sizeof BAD[0] };

/* A small canvas with a sentinel border around it in one allocation: any
 * write outside the canvas changes the border. */
typedef struct fenced {
    uint8_t mem[(8 + 2) * 4 * (6 + 2)];
    isk_canvas c;
} fenced;

static void fence_init(fenced *f)
{
    memset(f->mem, 0xA5, sizeof f->mem);
    cr_assert_eq(isk_canvas_wrap(&f->c, f->mem + (8 + 2) * 4 + 4, 8, 6, (8 + 2) * 4), ISK_OK);
    for (int y = 0; y < 6; y++)
        memset(isk_canvas_at(&f->c, 0, y), 0, 8 * 4);
}

static void fence_check(const fenced *f)
{
    for (size_t i = 0; i < sizeof f->mem; i++) {
        size_t row = i / ((8 + 2) * 4), col = i % ((8 + 2) * 4);
        int inside = row >= 1 && row <= 6 && col >= 4 && col < 4 + 8 * 4;
        if (!inside)
            cr_assert_eq(f->mem[i], 0xA5, "write outside the canvas at row %zu byte %zu", row, col);
    }
}

/* Hostile canvases: NULL, zeroed, NULL pixels with a size, negative sizes. */
static isk_canvas zeroed, nopixels, negative;
static void hostile_init(void)
{
    memset(&zeroed, 0, sizeof zeroed);
    nopixels = (isk_canvas){NULL, 10, 10, 40, 0};
    static uint8_t px[64];
    negative = (isk_canvas){px, -4, -4, 16, 0};
}
#define EACH_HOSTILE_CANVAS(c)                                                                                     \
    for (isk_canvas *c##_list[] = {NUL, &zeroed, &nopixels, &negative}, **c##_p = c##_list;                        \
         c##_p < c##_list + 4; c##_p++)                                                                            \
        for (isk_canvas *c = *c##_p; c; c = NULL)

TestSuite(hostile, .init = hostile_init);

/* ---- core: status ---------------------------------------------------------- */

Test(hostile, isk_status_str)
{
    const int codes[] = {-1, ISK_STATUS_COUNT, ISK_STATUS_COUNT + 1, INT_MAX, INT_MIN};
    for (size_t i = 0; i < sizeof codes / sizeof codes[0]; i++)
        cr_assert_not_null(isk_status_str((isk_status)codes[i]));
    for (int s = 0; s < ISK_STATUS_COUNT; s++)
        cr_assert_str_neq(isk_status_str((isk_status)s), "unknown status");
}

Test(hostile, isk_error_set)
{
    cr_assert_eq(isk_error_set(NUL, ISK_ERR_IO, "x %d", 1), ISK_ERR_IO);
    isk_error e;
    /* through a pointer: a NULL format is the point, not a warning */
    isk_status (*set)(isk_error *, isk_status, const char *, ...) = isk_error_set;
    cr_assert_eq(set(&e, ISK_ERR_RANGE, NUL), ISK_ERR_RANGE);
    cr_assert_str_eq(e.message, "");
    char big[2000];
    memset(big, 'x', sizeof big - 1);
    big[sizeof big - 1] = 0;
    cr_assert_eq(isk_error_set(&e, ISK_ERR_SIZE, "%s", big), ISK_ERR_SIZE);
    cr_assert_eq(strlen(e.message), sizeof e.message - 1);
}

/* ---- core: rng --------------------------------------------------------------- */

Test(hostile, isk_rng_seed) { isk_rng_seed(NUL, 1); }
Test(hostile, isk_rng_u32) { cr_assert_eq(isk_rng_u32(NUL), 0u); }
Test(hostile, isk_rng_uniform) { cr_assert_eq(isk_rng_uniform(NUL), 0.0); }
Test(hostile, isk_rng_range)
{
    cr_assert_eq(isk_rng_range(NUL, 2.0, 3.0), 2.0);
    isk_rng r;
    isk_rng_seed(&r, 7);
    double v = isk_rng_range(&r, -1e308, 1e308); /* hi - lo overflows: still a call, no trap */
    (void)v;
}
Test(hostile, isk_rng_below, .timeout = 5)
{
    cr_assert_eq(isk_rng_below(NUL, 10), 0u); /* must not spin on a NULL generator */
    isk_rng r;
    isk_rng_seed(&r, 7);
    cr_assert_eq(isk_rng_below(&r, 0), 0u);
    cr_assert_eq(isk_rng_below(&r, 1), 0u);
    cr_assert_lt(isk_rng_below(&r, UINT32_MAX), UINT32_MAX);
}
Test(hostile, isk_rng_normal2)
{
    double a = 1, b = 1;
    isk_rng_normal2(NUL, &a, &b);
    cr_assert(a == 0.0 && b == 0.0);
    isk_rng r;
    isk_rng_seed(&r, 7);
    isk_rng_normal2(&r, NUL, NUL);
}

/* ---- core: sine table ---------------------------------------------------- */

Test(hostile, isk_sinlut_init)
{
    isk_sinlut l;
    cr_assert_eq(isk_sinlut_init(NUL, 1024), ISK_ERR_NULL);
    const int bad[] = {0, -1, -1024, 15, 17, 1000, 131072, INT_MAX, INT_MIN};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        cr_assert_eq(isk_sinlut_init(&l, bad[i]), ISK_ERR_SIZE, "n = %d", bad[i]);
}
Test(hostile, isk_sinlut_init_copy)
{
    isk_sinlut l;
    double buf[17];
    cr_assert_eq(isk_sinlut_init_copy(NUL, 16, buf, 17), ISK_ERR_NULL);
    cr_assert_eq(isk_sinlut_init_copy(&l, 16, NUL, 17), ISK_ERR_NULL);
    cr_assert_eq(isk_sinlut_init_copy(&l, 16, buf, 16), ISK_ERR_SIZE);
    cr_assert_eq(isk_sinlut_init_copy(&l, 16, buf, 0), ISK_ERR_SIZE);
    cr_assert_eq(isk_sinlut_init_copy(&l, INT_MAX, buf, SIZE_MAX), ISK_ERR_SIZE);
    cr_assert_eq(isk_sinlut_init_copy(&l, -16, buf, 17), ISK_ERR_SIZE);
}
Test(hostile, isk_sinlut_bound)
{
    cr_assert_eq(isk_sinlut_bound(0, ISK_SINLUT_FLOOR), 0.0);
    cr_assert_eq(isk_sinlut_bound(-16, ISK_SINLUT_LERP), 0.0);
    cr_assert_eq(isk_sinlut_bound(INT_MAX, ISK_SINLUT_ROUND), 0.0);
    cr_assert_eq(isk_sinlut_bound(16, (isk_sinlut_mode)99), 0.0);
}
Test(hostile, isk_sinlut_eval)
{
    cr_assert(isnan(isk_sinlut_eval(NUL, ISK_SINLUT_FLOOR, 1.0)));
    isk_sinlut l;
    cr_assert_eq(isk_sinlut_init(&l, 64), ISK_OK);
    cr_assert(isnan(isk_sinlut_eval(&l, (isk_sinlut_mode)-1, 1.0)));
    for (int i = 0; i < NBAD; i++)
        for (int m = 0; m < 3; m++) {
            double v = isk_sinlut_eval(&l, (isk_sinlut_mode)m, BAD[i]);
            cr_assert(isnan(v) || (v >= -1.0 && v <= 1.0), "mode %d theta %g gave %g", m, BAD[i], v);
        }
}
Test(hostile, isk_sinlut_reduce_slow)
{
    cr_assert(isnan(isk_sinlut_reduce_slow(NUL, 1e300)));
    isk_sinlut l;
    cr_assert_eq(isk_sinlut_init(&l, 64), ISK_OK);
    cr_assert(isnan(isk_sinlut_reduce_slow(&l, NAN)));
    cr_assert(isnan(isk_sinlut_reduce_slow(&l, INFINITY)));
    cr_assert(fabs(isk_sinlut_reduce_slow(&l, 1e300)) <= 64.0);
}

/* ---- core: gradients ----------------------------------------------------- */

static const isk_color_stop CSTOPS[2] = {{0.0, {0, 0, 0, 255}}, {1.0, {255, 255, 255, 255}}};
static const isk_scalar_stop SSTOPS[2] = {{0.0, 1.0}, {1.0, 2.0}};

Test(hostile, isk_color_stops_check)
{
    cr_assert_eq(isk_color_stops_check(NUL, 2), ISK_ERR_NULL);
    cr_assert_eq(isk_color_stops_check(CSTOPS, 0), ISK_ERR_SIZE);
    cr_assert_eq(isk_color_stops_check(CSTOPS, -1), ISK_ERR_SIZE);
    cr_assert_eq(isk_color_stops_check(CSTOPS, INT_MAX), ISK_ERR_SIZE);
    isk_color_stop s[2] = {{NAN, {0}}, {1.0, {0}}};
    cr_assert_eq(isk_color_stops_check(s, 2), ISK_ERR_NAN);
}
Test(hostile, isk_scalar_stops_check)
{
    cr_assert_eq(isk_scalar_stops_check(NUL, 2), ISK_ERR_NULL);
    cr_assert_eq(isk_scalar_stops_check(SSTOPS, 0), ISK_ERR_SIZE);
    cr_assert_eq(isk_scalar_stops_check(SSTOPS, INT_MIN), ISK_ERR_SIZE);
    isk_scalar_stop s[2] = {{0.0, INFINITY}, {1.0, 0}};
    cr_assert_eq(isk_scalar_stops_check(s, 2), ISK_ERR_NAN);
}
Test(hostile, isk_color_gradient_bake)
{
    isk_color_gradient g;
    cr_assert_eq(isk_color_gradient_bake(NUL, CSTOPS, 2, 10), ISK_ERR_NULL);
    cr_assert_eq(isk_color_gradient_bake(&g, NUL, 2, 10), ISK_ERR_NULL);
    cr_assert_eq(isk_color_gradient_bake(&g, CSTOPS, 2, 0), ISK_ERR_SIZE);
    cr_assert_eq(isk_color_gradient_bake(&g, CSTOPS, 2, -5), ISK_ERR_SIZE);
    cr_assert_eq(isk_color_gradient_bake(&g, CSTOPS, 2, INT_MAX), ISK_ERR_SIZE);
    cr_assert_eq(isk_color_gradient_bake(&g, CSTOPS, -2, 10), ISK_ERR_SIZE);
}
Test(hostile, isk_scalar_gradient_bake)
{
    isk_scalar_gradient g;
    cr_assert_eq(isk_scalar_gradient_bake(NUL, SSTOPS, 2, 10), ISK_ERR_NULL);
    cr_assert_eq(isk_scalar_gradient_bake(&g, NUL, 2, 10), ISK_ERR_NULL);
    cr_assert_eq(isk_scalar_gradient_bake(&g, SSTOPS, 2, INT_MAX), ISK_ERR_SIZE);
    cr_assert_eq(isk_scalar_gradient_bake(&g, SSTOPS, INT_MAX, 10), ISK_ERR_SIZE);
}
Test(hostile, isk_color_gradient_free)
{
    isk_color_gradient_free(NUL);
    isk_color_gradient g = {0};
    isk_color_gradient_free(&g);
    isk_color_gradient_free(&g);
}
Test(hostile, isk_scalar_gradient_free)
{
    isk_scalar_gradient_free(NUL);
    isk_scalar_gradient g = {0};
    isk_scalar_gradient_free(&g);
}
Test(hostile, isk_color_gradient_eval)
{
    isk_color c = isk_color_gradient_eval(NUL, 2, 0.5);
    cr_assert(c.r == 0 && c.g == 0 && c.b == 0 && c.a == 0);
    c = isk_color_gradient_eval(CSTOPS, 0, 0.5);
    cr_assert(c.a == 0);
    c = isk_color_gradient_eval(CSTOPS, -3, 0.5);
    cr_assert(c.a == 0);
    for (int i = 0; i < NBAD; i++)
        isk_color_gradient_eval(CSTOPS, 2, BAD[i]);
}
Test(hostile, isk_scalar_gradient_eval)
{
    cr_assert_eq(isk_scalar_gradient_eval(NUL, 2, 0.5), 0.0);
    cr_assert_eq(isk_scalar_gradient_eval(SSTOPS, 0, 0.5), 0.0);
    cr_assert_eq(isk_scalar_gradient_eval(SSTOPS, INT_MIN, 0.5), 0.0);
    for (int i = 0; i < NBAD; i++)
        cr_assert(isfinite(isk_scalar_gradient_eval(SSTOPS, 2, BAD[i])));
}

/* ---- core: timestep ------------------------------------------------------ */

Test(hostile, isk_timestep_init)
{
    isk_timestep ts;
    cr_assert_eq(isk_timestep_init(NUL, 0.1, 1), ISK_ERR_NULL);
    cr_assert_eq(isk_timestep_init(&ts, 0.1, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_timestep_init(&ts, 0.1, -1), ISK_ERR_RANGE);
    cr_assert_eq(isk_timestep_init(&ts, 0.1, INT_MIN), ISK_ERR_RANGE);
    cr_assert_eq(isk_timestep_init(&ts, -INFINITY, 1), ISK_ERR_NAN);
    cr_assert_eq(isk_timestep_init(&ts, 1e-320, 1), ISK_OK); /* subnormal but > 0 */
}
Test(hostile, isk_timestep_advance, .timeout = 10)
{
    cr_assert_eq(isk_timestep_advance(NUL, 1.0), 0);
    isk_timestep zero;
    memset(&zero, 0, sizeof zero);
    cr_assert_eq(isk_timestep_advance(&zero, 1.0), 0, "an uninitialised accumulator hands out nothing");
    /* max_steps = INT_MAX: no int overflow, no two-billion-step loop */
    isk_timestep ts;
    cr_assert_eq(isk_timestep_init(&ts, 1e-9, INT_MAX), ISK_OK);
    int n = isk_timestep_advance(&ts, 1.0);
    cr_assert(n > 999990000 && n <= 1000000000, "n = %d", n);
    cr_assert(ts.accumulated >= 0.0 && ts.accumulated < ts.dt);
    n = isk_timestep_advance(&ts, 1e300);
    cr_assert_eq(n, INT_MAX);
    cr_assert(ts.accumulated >= 0.0 && ts.accumulated < ts.dt, "%g", ts.accumulated);
    cr_assert(isfinite(ts.dropped));
    cr_assert_eq(isk_timestep_init(&ts, 1e300, INT_MAX), ISK_OK); /* the cap overflows to inf */
    cr_assert_eq(isk_timestep_advance(&ts, 1e299), 0);
    cr_assert_eq(isk_timestep_advance(&ts, 1.7e308), 170000000);
    cr_assert(ts.accumulated >= 0.0 && ts.accumulated < ts.dt, "%g", ts.accumulated);
    cr_assert_eq(isk_timestep_init(&ts, 1e-320, 3), ISK_OK);
    cr_assert_eq(isk_timestep_advance(&ts, 1.0), 3);
    cr_assert(ts.accumulated >= 0.0 && ts.accumulated < ts.dt);
}
Test(hostile, isk_timestep_alpha)
{
    cr_assert_eq(isk_timestep_alpha(NUL), 0.0);
    isk_timestep zero;
    memset(&zero, 0, sizeof zero);
    cr_assert_eq(isk_timestep_alpha(&zero), 0.0);
}
Test(hostile, isk_timestep_reset) { isk_timestep_reset(NUL); }

/* ---- raster: canvas ------------------------------------------------------ */

Test(hostile, isk_canvas_init)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(NUL, 4, 4), ISK_ERR_NULL);
    const int bad[][2] = {{0, 4}, {4, 0}, {-1, 4}, {4, -1}, {INT_MAX, 1}, {1, INT_MAX}, {INT_MIN, INT_MIN},
                          {ISK_CANVAS_MAX_DIM + 1, 1}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        cr_assert_eq(isk_canvas_init(&c, bad[i][0], bad[i][1]), ISK_ERR_SIZE);
        cr_assert_null(c.pixels);
        isk_canvas_free(&c);
    }
}
Test(hostile, isk_canvas_wrap)
{
    uint8_t px[64];
    isk_canvas c;
    cr_assert_eq(isk_canvas_wrap(NUL, px, 4, 4, 16), ISK_ERR_NULL);
    cr_assert_eq(isk_canvas_wrap(&c, NUL, 4, 4, 16), ISK_ERR_NULL);
    cr_assert_eq(isk_canvas_wrap(&c, px, 4, 4, 15), ISK_ERR_SIZE);
    cr_assert_eq(isk_canvas_wrap(&c, px, 0, 4, 16), ISK_ERR_SIZE);
    cr_assert_eq(isk_canvas_wrap(&c, px, -4, 4, 16), ISK_ERR_SIZE);
    /* a stride whose y * stride wraps around the address space */
    cr_assert_eq(isk_canvas_wrap(&c, px, 4, 4, SIZE_MAX), ISK_ERR_SIZE);
    cr_assert_eq(isk_canvas_wrap(&c, px, 4, 4, SIZE_MAX / 2), ISK_ERR_SIZE);
    cr_assert_eq(isk_canvas_wrap(&c, px, 4, 3, SIZE_MAX / 2 + 1), ISK_ERR_SIZE);
    cr_assert_eq(isk_canvas_wrap(&c, px, 4, 2, (size_t)PTRDIFF_MAX), ISK_ERR_SIZE);
    /* one row: the stride is never multiplied, any stride >= 16 will do */
    cr_assert_eq(isk_canvas_wrap(&c, px, 4, 1, 16), ISK_OK);
    cr_assert_eq(isk_canvas_wrap(&c, px, 4, 4, 16), ISK_OK);
}
Test(hostile, isk_canvas_view)
{
    fenced f;
    fence_init(&f);
    isk_canvas v;
    cr_assert_eq(isk_canvas_view(NUL, &f.c, 0, 0, 1, 1), ISK_ERR_NULL);
    cr_assert_eq(isk_canvas_view(&v, NUL, 0, 0, 1, 1), ISK_ERR_NULL);
    cr_assert_eq(isk_canvas_view(&v, &f.c, 0, 0, -1, 1), ISK_ERR_SIZE);
    cr_assert_eq(isk_canvas_view(&v, &f.c, 0, 0, 1, INT_MIN), ISK_ERR_SIZE);
    cr_assert_eq(isk_canvas_view(&v, &f.c, INT_MAX, INT_MAX, INT_MAX, INT_MAX), ISK_OK);
    cr_assert_eq(v.width, 0);
    cr_assert_eq(isk_canvas_view(&v, &f.c, INT_MIN, INT_MIN, INT_MAX, INT_MAX), ISK_OK);
    isk_canvas_fill(&v, ISK_WHITE);
    fence_check(&f);
    EACH_HOSTILE_CANVAS(h)
    {
        isk_status s = isk_canvas_view(&v, h, 0, 0, 5, 5);
        cr_assert(s == ISK_ERR_NULL || (s == ISK_OK && v.width == 0 && v.height == 0));
    }
}
Test(hostile, isk_canvas_free)
{
    isk_canvas_free(NUL);
    isk_canvas c = {0};
    isk_canvas_free(&c);
    isk_canvas_free(&c);
}
Test(hostile, isk_canvas_fill)
{
    EACH_HOSTILE_CANVAS(h) isk_canvas_fill(h, ISK_WHITE);
}
Test(hostile, isk_canvas_get)
{
    EACH_HOSTILE_CANVAS(h) cr_assert_eq(isk_canvas_get(h, 0, 0).a, 0);
    fenced f;
    fence_init(&f);
    cr_assert_eq(isk_canvas_get(&f.c, INT_MIN, INT_MAX).a, 0);
    cr_assert_eq(isk_canvas_get(&f.c, 8, 0).a, 0);
}
Test(hostile, isk_canvas_equal)
{
    fenced f;
    fence_init(&f);
    cr_assert(isk_canvas_equal(&f.c, &f.c));
    EACH_HOSTILE_CANVAS(h)
    {
        cr_assert_not(isk_canvas_equal(h, &f.c));
        cr_assert_not(isk_canvas_equal(&f.c, h));
    }
    cr_assert_not(isk_canvas_equal(&nopixels, &nopixels));
    cr_assert_not(isk_canvas_equal(&negative, &negative));
    /* two empty canvases are equal */
    cr_assert(isk_canvas_equal(&zeroed, &zeroed));
}
Test(hostile, isk_canvas_compare)
{
    fenced f;
    fence_init(&f);
    isk_canvas_diff d;
    EACH_HOSTILE_CANVAS(h)
    {
        memset(&d, 0x55, sizeof d);
        if (h != &zeroed) {
            cr_assert_eq(isk_canvas_compare(h, &f.c, &d, NULL), 0);
            cr_assert_eq(d.differing, 0);
            cr_assert_eq(d.pixels, 0);
        }
        cr_assert_eq(isk_canvas_compare(&f.c, h, NULL, NULL), 0);
        /* a hostile canvas as the diff image is ignored, never written */
        cr_assert_eq(isk_canvas_compare(&f.c, &f.c, &d, h), 1);
    }
    cr_assert_eq(isk_canvas_compare(&nopixels, &nopixels, &d, NULL), 0);
    fence_check(&f);
}
Test(hostile, isk_canvas_count_beyond)
{
    fenced f;
    fence_init(&f);
    EACH_HOSTILE_CANVAS(h)
    {
        cr_assert_eq(isk_canvas_count_beyond(h, &f.c, 0), -1);
        cr_assert_eq(isk_canvas_count_beyond(&f.c, h, 255), -1);
    }
    cr_assert_eq(isk_canvas_count_beyond(&nopixels, &nopixels, 0), -1);
    cr_assert_eq(isk_canvas_count_beyond(&zeroed, &zeroed, 0), 0, "two empty canvases: nothing beyond");
    const int tolerances[] = {-1, 256, INT_MIN, INT_MAX};
    for (size_t i = 0; i < sizeof tolerances / sizeof tolerances[0]; i++)
        cr_assert_eq(isk_canvas_count_beyond(&f.c, &f.c, tolerances[i]), -1);
    cr_assert_eq(isk_canvas_count_beyond(&f.c, &f.c, 0), 0);
    fence_check(&f);
}

/* ---- raster: blending ------------------------------------------------------ */

Test(hostile, isk_blend_pixel)
{
    uint8_t px[4] = {1, 2, 3, 4};
    isk_blend_pixel(px, ISK_WHITE, (isk_blend)99); /* unknown mode: untouched */
    cr_assert(px[0] == 1 && px[3] == 4);
    isk_blend_pixel(NUL, ISK_WHITE, ISK_BLEND_OVER);
}
Test(hostile, isk_blend_pixel_cov)
{
    uint8_t px[4] = {1, 2, 3, 4};
    isk_blend_pixel_cov(px, ISK_WHITE, 255, (isk_blend)-1);
    cr_assert(px[0] == 1 && px[3] == 4);
    isk_blend_pixel_cov(NUL, ISK_WHITE, 255, ISK_BLEND_ADD);
}
Test(hostile, isk_blend_name)
{
    cr_assert_null(isk_blend_name((isk_blend)-1));
    cr_assert_null(isk_blend_name((isk_blend)3));
}

/* ---- raster: primitives (a hostile canvas, then hostile coordinates on a
 * fenced one: nothing may land outside) ------------------------------------ */

#define DRAW_TEST(fn, hostile_call, coord_call)                                                                    \
    Test(hostile, fn)                                                                                              \
    {                                                                                                              \
        EACH_HOSTILE_CANVAS(c) { hostile_call; }                                                                   \
        fenced f;                                                                                                  \
        fence_init(&f);                                                                                            \
        isk_canvas *c = &f.c;                                                                                      \
        for (int i = 0; i < NBAD; i++)                                                                             \
            for (int j = 0; j < NBAD; j++) {                                                                       \
                double a = BAD[i], b = BAD[j];                                                                     \
                (void)a;                                                                                           \
                (void)b;                                                                                           \
                coord_call;                                                                                        \
            }                                                                                                      \
        fence_check(&f);                                                                                           \
    }

static const isk_color INK = {255, 255, 255, 255};
static const double PTS[8] = {1, 1, 6, 1, 6, 5, 1e300, -1e300};

DRAW_TEST(isk_draw_pixel, isk_draw_pixel(c, 0, 0, INK, ISK_BLEND_OVER),
          isk_draw_pixel(c, i - 3 + (i == 0 ? INT_MIN + 3 : 0), j * 2 - 1, INK, ISK_BLEND_ADD))
DRAW_TEST(isk_fill_rect, isk_fill_rect(c, 0, 0, 4, 4, INK, ISK_BLEND_OVER),
          isk_fill_rect(c, i == 0 ? INT_MIN : -2, j == 0 ? INT_MAX : 1, INT_MAX, i == 1 ? INT_MIN : INT_MAX, INK,
                        ISK_BLEND_OVER))
DRAW_TEST(isk_draw_line, isk_draw_line(c, 0, 0, 3, 3, INK, ISK_BLEND_OVER),
          isk_draw_line(c, a, b, 3, 3, INK, ISK_BLEND_OVER))
DRAW_TEST(isk_draw_triangle, isk_draw_triangle(c, 0, 0, 3, 3, 0, 3, INK, ISK_BLEND_OVER),
          isk_draw_triangle(c, a, b, 3, 3, b, 1, INK, ISK_BLEND_OVER))
DRAW_TEST(isk_fill_triangle, isk_fill_triangle(c, 0, 0, 3, 3, 0, 3, INK, ISK_BLEND_OVER),
          isk_fill_triangle(c, a, 1, 6, b, 1, 5, INK, ISK_BLEND_ADD))
DRAW_TEST(isk_fill_circle, isk_fill_circle(c, 2, 2, 2, INK, ISK_BLEND_OVER),
          isk_fill_circle(c, a, 2, fabs(b), INK, ISK_BLEND_OVER))
DRAW_TEST(isk_draw_dot, isk_draw_dot(c, 1, 1, INK, ISK_BLEND_OVER), isk_draw_dot(c, a, b, INK, ISK_BLEND_OVER))
DRAW_TEST(isk_stroke_line, isk_stroke_line(c, 0, 0, 3, 3, INK, ISK_BLEND_OVER),
          isk_stroke_line(c, a, 2, 3, b, INK, ISK_BLEND_OVER))
DRAW_TEST(isk_stroke_polyline,
          (isk_stroke_polyline(c, PTS, 3, 1, INK, ISK_BLEND_OVER), isk_stroke_polyline(c, NUL, 3, 1, INK, 0)),
          (isk_stroke_polyline(c, PTS, 4, 1, INK, ISK_BLEND_OVER), isk_stroke_polyline(c, PTS, -1, 0, INK, 0),
           isk_stroke_polyline(c, PTS, 0, 0, INK, 0), isk_stroke_polyline(c, NUL, 4, 0, INK, 0)))
DRAW_TEST(isk_fill_circle_aa, isk_fill_circle_aa(c, 2, 2, 2, INK, ISK_BLEND_OVER),
          isk_fill_circle_aa(c, a, b, 3, INK, ISK_BLEND_OVER))
DRAW_TEST(isk_stroke_hairline, isk_stroke_hairline(c, 0, 0, 3, 3, INK, ISK_BLEND_OVER),
          isk_stroke_hairline(c, a, 1, b, 4, INK, ISK_BLEND_OVER))
DRAW_TEST(isk_stroke_polyline_hairline, isk_stroke_polyline_hairline(c, PTS, 3, 1, INK, ISK_BLEND_OVER),
          (isk_stroke_polyline_hairline(c, PTS, 4, 1, INK, ISK_BLEND_OVER),
           isk_stroke_polyline_hairline(c, PTS, INT_MIN, 1, INK, ISK_BLEND_OVER),
           isk_stroke_polyline_hairline(c, NUL, 3, 1, INK, ISK_BLEND_OVER)))
DRAW_TEST(isk_draw_dot_browser, isk_draw_dot_browser(c, 1, 1, INK, ISK_BLEND_OVER),
          isk_draw_dot_browser(c, a, b, INK, ISK_BLEND_OVER))

Test(hostile, isk_dot_weights)
{
    uint8_t w[4] = {9, 9, 9, 9};
    for (int i = 0; i < NBAD; i++) {
        int ok = isk_dot_weights(BAD[i], 0.5, w);
        cr_assert(ok == 0 || ok == 1);
    }
    cr_assert_eq(isk_dot_weights(NAN, 0, w), 0);
    cr_assert(w[0] == 0 && w[1] == 0 && w[2] == 0 && w[3] == 0);
    cr_assert_eq(isk_dot_weights(0.5, 0.5, NUL), 0);
}
Test(hostile, isk_dot_weights_browser)
{
    uint8_t w[4];
    int ix, iy;
    for (int i = 0; i < NBAD; i++)
        for (int j = 0; j < NBAD; j++)
            isk_dot_weights_browser(BAD[i], BAD[j], &ix, &iy, w);
    cr_assert_eq(isk_dot_weights_browser(NAN, 0, &ix, &iy, w), 0);
    cr_assert_eq(isk_dot_weights_browser(0.5, 0.5, NUL, &iy, w), 0);
    cr_assert_eq(isk_dot_weights_browser(0.5, 0.5, &ix, NUL, w), 0);
    cr_assert_eq(isk_dot_weights_browser(0.5, 0.5, &ix, &iy, NUL), 0);
}

/* ---- raster: text ---------------------------------------------------------- */

Test(hostile, isk_text_width)
{
    cr_assert_eq(isk_text_width(NUL, 1), 0);
    cr_assert_eq(isk_text_width("abc", 0), 0);
    cr_assert_eq(isk_text_width("abc", -1), 0);
    cr_assert_eq(isk_text_width("abc", INT_MAX), INT_MAX); /* saturates */
}
Test(hostile, isk_text_height)
{
    cr_assert_eq(isk_text_height(NUL, 1), 0);
    cr_assert_eq(isk_text_height("a\nb", INT_MIN), 0);
    cr_assert_eq(isk_text_height("a\nb", INT_MAX), INT_MAX);
}
Test(hostile, isk_draw_text)
{
    EACH_HOSTILE_CANVAS(c) isk_draw_text(c, 0, 0, "hi", 1, INK, ISK_BLEND_OVER);
    fenced f;
    fence_init(&f);
    const int xy[] = {INT_MIN, -7, 0, 3, INT_MAX};
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 5; j++) {
            isk_draw_text(&f.c, xy[i], xy[j], "W\nW\xff", 1, INK, ISK_BLEND_OVER);
            isk_draw_text(&f.c, xy[i], xy[j], "W", INT_MAX, INK, ISK_BLEND_OVER);
        }
    isk_draw_text(&f.c, 0, 0, NUL, 1, INK, ISK_BLEND_OVER);
    isk_draw_text(&f.c, 0, 0, "W", -3, INK, ISK_BLEND_OVER);
    fence_check(&f);
}
Test(hostile, isk_font_glyph)
{
    for (int ch = 0; ch < 256; ch++)
        cr_assert_not_null(isk_font_glyph((unsigned char)ch));
}

/* ---- raster: sprites ------------------------------------------------------- */

Test(hostile, isk_sprite_init)
{
    isk_sprite s;
    cr_assert_eq(isk_sprite_init(NUL, ISK_SPRITE_DISC, 4, INK), ISK_ERR_NULL);
    cr_assert_eq(isk_sprite_init(&s, (isk_sprite_kind)7, 4, INK), ISK_ERR_RANGE);
    const int bad[] = {0, -1, ISK_SPRITE_MAX_SIZE + 1, INT_MAX, INT_MIN};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        cr_assert_eq(isk_sprite_init(&s, ISK_SPRITE_DISC, bad[i], INK), ISK_ERR_SIZE);
}
Test(hostile, isk_sprite_free)
{
    isk_sprite_free(NUL);
    isk_sprite s;
    memset(&s, 0, sizeof s);
    isk_sprite_free(&s);
    isk_sprite_free(&s);
}
Test(hostile, isk_sprite_alpha)
{
    for (int i = 0; i < NBAD; i++) {
        double a = isk_sprite_alpha(ISK_SPRITE_LINEAR, BAD[i], 8);
        cr_assert(a >= 0.0 && a <= 1.0, "d = %g gave %g", BAD[i], a);
    }
    cr_assert_eq(isk_sprite_alpha(ISK_SPRITE_DISC, 0.0, 0), 0.0);
    cr_assert_eq(isk_sprite_alpha(ISK_SPRITE_DISC, 0.0, INT_MIN), 0.0);
    double a = isk_sprite_alpha((isk_sprite_kind)42, 0.0, 8);
    cr_assert(a >= 0.0 && a <= 1.0);
}
Test(hostile, isk_draw_sprite)
{
    isk_sprite s;
    cr_assert_eq(isk_sprite_init(&s, ISK_SPRITE_SMOOTH, 5, INK), ISK_OK);
    EACH_HOSTILE_CANVAS(c) isk_draw_sprite(c, &s, 1, 1, ISK_BLEND_ADD);
    fenced f;
    fence_init(&f);
    isk_draw_sprite(&f.c, NUL, 1, 1, ISK_BLEND_ADD);
    isk_sprite empty;
    memset(&empty, 0, sizeof empty);
    isk_draw_sprite(&f.c, &empty, 1, 1, ISK_BLEND_ADD);
    isk_draw_sprite(&f.c, &s, 1, 1, (isk_blend)9);
    for (int i = 0; i < NBAD; i++)
        for (int j = 0; j < NBAD; j++)
            isk_draw_sprite(&f.c, &s, BAD[i], BAD[j], ISK_BLEND_ADD);
    fence_check(&f);
    isk_sprite_free(&s);
}
Test(hostile, isk_draw_sprite_tinted)
{
    isk_sprite s;
    cr_assert_eq(isk_sprite_init(&s, ISK_SPRITE_LINEAR, 6, INK), ISK_OK);
    EACH_HOSTILE_CANVAS(c) isk_draw_sprite_tinted(c, &s, 1, 1, INK, ISK_BLEND_OVER);
    fenced f;
    fence_init(&f);
    isk_draw_sprite_tinted(&f.c, NUL, 1, 1, INK, ISK_BLEND_OVER);
    for (int i = 0; i < NBAD; i++)
        isk_draw_sprite_tinted(&f.c, &s, BAD[i], 3, INK, ISK_BLEND_OVER);
    fence_check(&f);
    isk_sprite_free(&s);
}
Test(hostile, isk_sprite_cache_create)
{
    isk_sprite_cache *c = (isk_sprite_cache *)&c;
    cr_assert_eq(isk_sprite_cache_create(NUL, 4), ISK_ERR_NULL);
    const int bad[] = {0, -1, ISK_SPRITE_CACHE_MAX + 1, INT_MAX, INT_MIN};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        cr_assert_eq(isk_sprite_cache_create(&c, bad[i]), ISK_ERR_SIZE);
        cr_assert_null(c);
    }
}
Test(hostile, isk_sprite_cache_destroy) { isk_sprite_cache_destroy(NUL); }
Test(hostile, isk_sprite_cache_get)
{
    const isk_sprite *s;
    isk_sprite_cache *c;
    cr_assert_eq(isk_sprite_cache_create(&c, 1), ISK_OK);
    cr_assert_eq(isk_sprite_cache_get(NUL, ISK_SPRITE_DISC, 4, INK, &s), ISK_ERR_NULL);
    cr_assert_eq(isk_sprite_cache_get(c, ISK_SPRITE_DISC, 4, INK, NUL), ISK_ERR_NULL);
    cr_assert_eq(isk_sprite_cache_get(c, (isk_sprite_kind)-1, 4, INK, &s), ISK_ERR_RANGE);
    cr_assert_eq(isk_sprite_cache_get(c, ISK_SPRITE_DISC, 0, INK, &s), ISK_ERR_SIZE);
    cr_assert_eq(isk_sprite_cache_get(c, ISK_SPRITE_DISC, INT_MAX, INK, &s), ISK_ERR_SIZE);
    cr_assert_eq(isk_sprite_cache_get(c, ISK_SPRITE_DISC, 4, INK, &s), ISK_OK);
    cr_assert_eq(isk_sprite_cache_get(c, ISK_SPRITE_DISC, 5, INK, &s), ISK_ERR_FULL);
    isk_sprite_cache_destroy(c);
}
Test(hostile, isk_sprite_cache_clear) { isk_sprite_cache_clear(NUL); }
Test(hostile, isk_sprite_cache_count) { cr_assert_eq(isk_sprite_cache_count(NUL), 0); }
Test(hostile, isk_sprite_cache_bakes) { cr_assert_eq(isk_sprite_cache_bakes(NUL), 0); }

/* ---- view ---------------------------------------------------------------- */

Test(hostile, isk_view_window)
{
    isk_view v;
    cr_assert_eq(isk_view_window(NUL, 10, 10, 0, 1, 0, 1), ISK_ERR_NULL);
    cr_assert_eq(isk_view_window(&v, 0, 10, 0, 1, 0, 1), ISK_ERR_SIZE);
    cr_assert_eq(isk_view_window(&v, -10, 10, 0, 1, 0, 1), ISK_ERR_SIZE);
    cr_assert_eq(isk_view_window(&v, INT_MAX, 10, 0, 1, 0, 1), ISK_ERR_SIZE);
    cr_assert_eq(isk_view_window(&v, 10, 10, NAN, 1, 0, 1), ISK_ERR_NAN);
    cr_assert_eq(isk_view_window(&v, 10, 10, 1, 1, 0, 1), ISK_ERR_RANGE);
    cr_assert_eq(isk_view_window(&v, 10, 10, -1e308, 1e308, 0, 1), ISK_ERR_RANGE);
    cr_assert_eq(isk_view_window(&v, 10, 10, 0, 1e-320, 0, 1), ISK_ERR_RANGE);
}
Test(hostile, isk_view_camera)
{
    isk_view v;
    cr_assert_eq(isk_view_camera(NUL, 10, 10, 1, 0, 0), ISK_ERR_NULL);
    cr_assert_eq(isk_view_camera(&v, 10, INT_MIN, 1, 0, 0), ISK_ERR_SIZE);
    cr_assert_eq(isk_view_camera(&v, 10, 10, 0, 0, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_view_camera(&v, 10, 10, -1, 0, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_view_camera(&v, 10, 10, INFINITY, 0, 0), ISK_ERR_NAN);
    cr_assert_eq(isk_view_camera(&v, 10, 10, 1e-320, 0, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_view_camera(&v, 10, 10, 1, 1e308, 0), ISK_ERR_RANGE);
}
Test(hostile, isk_view_to_screen)
{
    double x = 7, y = 7;
    isk_view_to_screen(NUL, 1, 1, &x, &y);
    cr_assert(x == 0.0 && y == 0.0);
    isk_view v;
    cr_assert_eq(isk_view_window(&v, 10, 10, 0, 1, 0, 1), ISK_OK);
    isk_view_to_screen(&v, 1, 1, NUL, NUL);
}
Test(hostile, isk_view_to_world)
{
    double x = 7, y = 7;
    isk_view_to_world(NUL, 1, 1, &x, &y);
    cr_assert(x == 0.0 && y == 0.0);
    isk_view v;
    cr_assert_eq(isk_view_camera(&v, 10, 10, 1, 0, 0), ISK_OK);
    isk_view_to_world(&v, 1, 1, NUL, NUL);
}

/* World drawing: a NULL view or a hostile canvas draws nothing; hostile
 * world coordinates never land outside the canvas. */
#define WORLD_TEST(fn, call)                                                                                       \
    Test(hostile, fn)                                                                                              \
    {                                                                                                              \
        isk_view view;                                                                                             \
        cr_assert_eq(isk_view_window(&view, 8, 6, -1, 1, -1, 1), ISK_OK);                                          \
        const isk_view *v = &view;                                                                                 \
        EACH_HOSTILE_CANVAS(c)                                                                                     \
        {                                                                                                          \
            double a = 0, b = 0;                                                                                   \
            call;                                                                                                  \
        }                                                                                                          \
        fenced f;                                                                                                  \
        fence_init(&f);                                                                                            \
        isk_canvas *c = &f.c;                                                                                      \
        {                                                                                                          \
            const isk_view *saved = v;                                                                             \
            v = NUL;                                                                                               \
            double a = 0, b = 0;                                                                                   \
            call;                                                                                                  \
            v = saved;                                                                                             \
        }                                                                                                          \
        for (int i = 0; i < 8 * 6 * 4; i++)                                                                        \
            cr_assert_eq(f.c.pixels[(i / 32) * f.c.stride + i % 32], 0, "a NULL view drew");                       \
        for (int i = 0; i < NBAD; i++)                                                                             \
            for (int j = 0; j < NBAD; j++) {                                                                       \
                double a = BAD[i], b = BAD[j];                                                                     \
                call;                                                                                              \
            }                                                                                                      \
        fence_check(&f);                                                                                           \
    }

static const double WPTS[8] = {-0.5, -0.5, 0.5, -0.5, 0.5, 0.5, 1e300, NAN};

WORLD_TEST(isk_world_dot, isk_world_dot(c, v, a, b, INK, ISK_BLEND_OVER))
WORLD_TEST(isk_world_dot_browser, isk_world_dot_browser(c, v, a, b, INK, ISK_BLEND_OVER))
WORLD_TEST(isk_world_disc, isk_world_disc(c, v, a, b, 0.5, INK, ISK_BLEND_OVER))
WORLD_TEST(isk_world_text, (isk_world_text(c, v, a, b, "Hi", 1, INK, ISK_BLEND_OVER),
                            isk_world_text(c, v, a, b, "Hi", INT_MAX, INK, ISK_BLEND_OVER),
                            isk_world_text(c, v, a, b, NUL, 1, INK, ISK_BLEND_OVER)))
WORLD_TEST(isk_world_polyline, (isk_world_polyline(c, v, WPTS, 4, 1, INK, ISK_BLEND_OVER),
                                isk_world_polyline(c, v, WPTS, -4, 1, INK, ISK_BLEND_OVER),
                                isk_world_polyline(c, v, NUL, 4, 1, INK, ISK_BLEND_OVER), (void)a, (void)b))
WORLD_TEST(isk_world_polyline_hairline, (isk_world_polyline_hairline(c, v, WPTS, 4, 0, INK, ISK_BLEND_OVER),
                                         isk_world_polyline_hairline(c, v, WPTS, INT_MIN, 0, INK, ISK_BLEND_OVER),
                                         (void)a, (void)b))

/* ---- chart ----------------------------------------------------------------- */

Test(hostile, isk_chart_defaults) { isk_chart_defaults(NUL); }
Test(hostile, isk_chart_style_default)
{
    const int idx[] = {-1, INT_MIN, INT_MAX, 0, 1000};
    for (size_t i = 0; i < sizeof idx / sizeof idx[0]; i++) {
        isk_chart_style s = isk_chart_style_default(idx[i]);
        cr_assert_lt((unsigned)s.dash, (unsigned)ISK_DASH_COUNT);
        cr_assert_lt((unsigned)s.marker, (unsigned)ISK_MARKER_COUNT);
    }
}
Test(hostile, isk_chart_draw)
{
    isk_chart ch;
    isk_chart_defaults(&ch);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 200, 150), ISK_OK);
    cr_assert_eq(isk_chart_draw(NUL, &c), ISK_ERR_NULL);
    EACH_HOSTILE_CANVAS(h) cr_assert_neq(isk_chart_draw(&ch, h), ISK_OK);
    ch.nseries = 3; /* series NULL */
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_ERR_NULL);
    /* points a log axis cannot place are skipped; two remain */
    const double xs[4] = {1, NAN, 100, INFINITY}, ys[4] = {1e-300, 5, 1e300, 1};
    isk_chart_series s = {"s", xs, ys, 4, isk_chart_style_default(0)};
    ch.series = &s;
    ch.nseries = 1;
    ch.x_log = ch.y_log = 1;
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_OK);
    s.x = NULL;
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_ERR_NULL);
    s.x = xs;
    s.style.dash = (isk_chart_dash)-1;
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_ERR_RANGE);
    s.style = isk_chart_style_default(0);
    ch.legend = (isk_chart_legend)77;
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_ERR_RANGE);
    ch.legend = ISK_LEGEND_TOP_LEFT;
    ch.x_min = 5;
    ch.x_max = NAN;
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_ERR_RANGE);
    ch.x_min = -1;
    ch.x_max = 1; /* log axis from a negative number */
    cr_assert_eq(isk_chart_draw(&ch, &c), ISK_ERR_RANGE);
    isk_canvas small;
    cr_assert_eq(isk_canvas_init(&small, 10, 10), ISK_OK);
    ch.x_min = ch.x_max = NAN;
    cr_assert_eq(isk_chart_draw(&ch, &small), ISK_ERR_SIZE);
    isk_canvas_free(&small);
    isk_canvas_free(&c);
}

/* ---- io: png ----------------------------------------------------------------- */

Test(hostile, isk_png_write)
{
    isk_error e;
    fenced f;
    fence_init(&f);
    cr_assert_eq(isk_png_write(NUL, "out/x.png", &e), ISK_ERR_NULL);
    cr_assert_eq(isk_png_write(&f.c, NUL, &e), ISK_ERR_NULL);
    cr_assert_eq(isk_png_write(&f.c, "", &e), ISK_ERR_IO);
    EACH_HOSTILE_CANVAS(h) cr_assert_neq(isk_png_write(h, "out/hostile-never-written.png", NULL), ISK_OK);
    isk_canvas thin = f.c;
    thin.stride = 4; /* rows overlapping: stride < 4 * width */
    cr_assert_eq(isk_png_write(&thin, "out/hostile-never-written.png", &e), ISK_ERR_SIZE);
    cr_assert_eq(isk_png_write_stream(&f.c, NUL, "x", &e), ISK_ERR_NULL);
    cr_assert_eq(isk_png_write_stream(NUL, stdout, "x", &e), ISK_ERR_NULL);
}
Test(hostile, isk_png_read_info)
{
    isk_png_info info;
    isk_error e;
    cr_assert_eq(isk_png_read_info(NUL, &info, &e), ISK_ERR_NULL);
    cr_assert_eq(isk_png_read_info("refimg/fig09_stationary_particle.png", NUL, &e), ISK_ERR_NULL);
    cr_assert_eq(isk_png_read_info("", &info, &e), ISK_ERR_IO);
    cr_assert_eq(isk_png_read_info("/", &info, &e), ISK_ERR_IO);
}
Test(hostile, isk_png_read_max)
{
    isk_canvas c;
    const char *ok = "refimg/fig09_stationary_particle.png";
    const long long bad[] = {0, -1, LLONG_MIN, LLONG_MAX, 16384LL * 16384 + 1};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        cr_assert_eq(isk_png_read_max(&c, ok, bad[i], NULL), ISK_ERR_RANGE, "%lld", bad[i]);
        cr_assert_null(c.pixels);
    }
    cr_assert_eq(isk_png_read_max(NUL, ok, 100, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_png_read_max(&c, NUL, 100, NULL), ISK_ERR_NULL);
}
Test(hostile, isk_png_read_memory)
{
    isk_canvas c;
    static const unsigned char junk[16] = {137, 'P', 'N', 'G'};
    cr_assert_eq(isk_png_read_memory(NUL, junk, 16, "m", 100, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_png_read_memory(&c, NUL, 16, "m", 100, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_png_read_memory(&c, NUL, 0, "m", 100, NULL), ISK_ERR_FORMAT);
    cr_assert_eq(isk_png_read_memory(&c, junk, 0, NUL, 100, NULL), ISK_ERR_FORMAT);
    cr_assert_eq(isk_png_read_memory(&c, junk, sizeof junk, "m", 100, NULL), ISK_ERR_FORMAT);
    cr_assert_eq(isk_png_read_memory(&c, junk, sizeof junk, "m", -100, NULL), ISK_ERR_RANGE);
    cr_assert_null(c.pixels);
}
Test(hostile, isk_png_read)
{
    isk_canvas c;
    isk_error e;
    cr_assert_eq(isk_png_read(NUL, "refimg/fig09_stationary_particle.png", &e), ISK_ERR_NULL);
    cr_assert_eq(isk_png_read(&c, NUL, &e), ISK_ERR_NULL);
    cr_assert_eq(isk_png_read(&c, "", &e), ISK_ERR_IO);
    cr_assert_null(c.pixels);
    cr_assert_eq(isk_png_read(&c, "/", &e), ISK_ERR_IO);
    cr_assert_null(c.pixels);
}

/* ---- io: output files -------------------------------------------------------- */

Test(hostile, isk_outfile_open)
{
    isk_outfile o;
    isk_error e;
    cr_assert_eq(isk_outfile_open(NUL, "out/x", &e), ISK_ERR_NULL);
    cr_assert_eq(isk_outfile_open(&o, NUL, &e), ISK_ERR_NULL);
    cr_assert_null(o.f);
    cr_assert_eq(isk_outfile_open(&o, "", &e), ISK_ERR_IO);
    cr_assert_eq(isk_outfile_open(&o, "/", &e), ISK_ERR_IO);
    cr_assert_eq(isk_outfile_open(&o, "out/no/such/dir/x.png", &e), ISK_ERR_IO);
    cr_assert_null(o.f);
    cr_assert_null(o.temp);
}
Test(hostile, isk_outfile_commit)
{
    isk_outfile o;
    memset(&o, 0, sizeof o);
    cr_assert_eq(isk_outfile_commit(NUL, NULL), ISK_ERR_NULL);
    cr_assert_eq(isk_outfile_commit(&o, NULL), ISK_ERR_IO);
}
Test(hostile, isk_outfile_abort)
{
    isk_outfile o;
    memset(&o, 0, sizeof o);
    isk_outfile_abort(NUL);
    isk_outfile_abort(&o);
    isk_outfile_abort(&o);
}

/* ---- io: the SDL window (no window is opened: every call is refused first) -- */

#include "iskra/sdl.h"

static int never(void *user, isk_canvas *c, double dt, const isk_event *ev, int n)
{
    (void)user, (void)c, (void)dt, (void)ev, (void)n;
    return 1;
}

Test(hostile, isk_window_open)
{
    isk_window *w = (isk_window *)&w;
    isk_error e;
    cr_assert_eq(isk_window_open(NUL, "t", 10, 10, &e), ISK_ERR_NULL);
    const int bad[][2] = {{0, 10}, {10, 0}, {-1, 10}, {10, INT_MIN}, {INT_MAX, 10}, {ISK_CANVAS_MAX_DIM + 1, 1}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        cr_assert_eq(isk_window_open(&w, "t", bad[i][0], bad[i][1], &e), ISK_ERR_SIZE);
        cr_assert_null(w);
    }
}
Test(hostile, isk_window_set_size)
{
    cr_assert_eq(isk_window_set_size(NUL, 10, 10), ISK_ERR_NULL);
}
Test(hostile, isk_window_present)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 2, 2), ISK_OK);
    cr_assert_eq(isk_window_present(NUL, &c, NULL), ISK_ERR_NULL);
    isk_canvas_free(&c);
}
Test(hostile, isk_window_poll)
{
    isk_event ev;
    cr_assert_eq(isk_window_poll(NUL, &ev), 0);
}
Test(hostile, isk_window_push_event)
{
    isk_event ev;
    memset(&ev, 0, sizeof ev);
    cr_assert_eq(isk_window_push_event(NUL, &ev), ISK_ERR_NULL);
}
Test(hostile, isk_window_run)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 2, 2), ISK_OK);
    cr_assert_eq(isk_window_run(NUL, &c, never, NULL, 1, NULL), ISK_ERR_NULL);
    isk_canvas_free(&c);
}
Test(hostile, isk_window_close) { isk_window_close(NUL); }

/* ---- sim: forces and explosions ----------------------------------------------- */

static double arr[4][3];

Test(hostile, isk_force_potential)
{
    isk_potential pot;
    isk_potential_init(&pot, 1.0, (isk_vec2){0, 0}, -1.0);
    isk_force_potential(NUL, 3, arr[0], arr[1], arr[2], arr[3], ISK_FIDELITY_SOUND);
    isk_force_potential(&pot, 3, NUL, arr[1], arr[2], arr[3], ISK_FIDELITY_SOUND);
    isk_force_potential(&pot, 3, arr[0], arr[1], NUL, NUL, ISK_FIDELITY_SOUND);
}

Test(hostile, isk_forces_eval)
{
    isk_forces f;
    memset(&f, 0, sizeof f);
    double x[3] = {0}, y[3] = {0}, vx[3] = {0}, vy[3] = {0}, m[3] = {1, 1, 1}, fx[3], fy[3];
    isk_forces_eval(NUL, 3, x, y, vx, vy, m, fx, fy, NUL, NUL, 1);
    isk_forces_eval(&f, 3, NUL, NUL, NUL, NUL, NUL, NUL, NUL, NUL, NUL, 1);
    isk_forces_eval_step(NUL, 3, x, y, vx, vy, m, fx, fy, NUL, NUL, 1, 0.1);
    isk_force_gravity(3, NUL, 9.81, fy);
    isk_force_gravity(3, m, 9.81, NUL);
    isk_force_drag(3, NUL, vy, 0.5, fx, fy);
    isk_force_drag(3, vx, vy, 0.5, NUL, fy);
    isk_force_accel(3, NUL, 1, 1, fx, fy);
    isk_force_accel(3, m, 1, 1, fx, NUL);
}

/* The harmonic sum was added term by term: SIZE_MAX looped 10^19 times. */
Test(hostile, isk_multi_coulomb_release_time, .timeout = 5)
{
    cr_assert_eq(isk_multi_coulomb_release_time(0), 0.0);
    cr_assert_eq(isk_multi_coulomb_release_time(1), 0.0);
    cr_assert_eq(isk_multi_coulomb_release_time(3), 0.010 / 1.0 + 0.010 / 2.0, "small batches are the exact sum");
    const double big = isk_multi_coulomb_release_time(SIZE_MAX);
    /* 0.01 (ln SIZE_MAX + gamma): 0.4494 where size_t has 64 bits, 0.2276 where 32 */
    const double expected = 0.010 * (log((double)SIZE_MAX) + 0.57721566490153286);
    cr_assert(isfinite(big) && fabs(big - expected) < 1e-9, "%.17g, expected %.17g", big, expected);
    /* where the sum gives way to its expansion, the two agree (to the
     * rounding a million-term sum gathers, about 1e-12) */
    const size_t n = (size_t)1 << 20;
    double step = isk_multi_coulomb_release_time(n + 1) - isk_multi_coulomb_release_time(n);
    cr_assert(fabs(step - 0.010 / (double)n) < 1e-11, "a jump of %.3g where the terms are %.3g", step,
              0.010 / (double)n);
}

/* ---- ui: layout arithmetic saturates ---------------------------------------------- */

Test(hostile, isk_ui_cut)
{
    isk_ui_rect z = isk_ui_cut_top(NUL, 5);
    cr_assert(z.x == 0 && z.y == 0 && z.w == 0 && z.h == 0);
    z = isk_ui_cut_bottom(NUL, 5);
    cr_assert(z.w == 0 && z.h == 0);
    z = isk_ui_cut_left(NUL, 5);
    cr_assert(z.w == 0 && z.h == 0);
    z = isk_ui_cut_right(NUL, 5);
    cr_assert(z.w == 0 && z.h == 0);
    isk_ui_rect r = {INT_MAX - 3, INT_MAX - 3, 10, 10};
    isk_ui_rect c = isk_ui_cut_top(&r, 8);
    cr_assert(c.h == 8 && r.y == INT_MAX && r.h == 2, "y %d h %d", r.y, r.h);
    c = isk_ui_cut_right(&r, INT_MAX);
    cr_assert(c.w == 10 && r.w == 0);
}

Test(hostile, isk_ui_contains)
{
    cr_assert_not(isk_ui_contains((isk_ui_rect){INT_MIN, INT_MIN, 10, 10}, INT_MAX, INT_MAX),
                  "x - r.x overflowed and wrapped into the rectangle");
    cr_assert(isk_ui_contains((isk_ui_rect){INT_MAX - 5, 0, 10, 10}, INT_MAX, 3));
    cr_assert_not(isk_ui_contains((isk_ui_rect){0, 0, -5, 10}, 0, 0));
}

Test(hostile, isk_ui_inset)
{
    isk_ui_rect o = isk_ui_inset((isk_ui_rect){0, 0, 10, 10}, INT_MAX);
    cr_assert(o.w == 0 && o.h == 0 && o.x == 5 && o.y == 5, "%d %d %d %d", o.x, o.y, o.w, o.h);
    o = isk_ui_inset((isk_ui_rect){INT_MAX - 1, INT_MAX - 1, 4, 4}, INT_MIN);
    cr_assert(o.w == INT_MAX && o.x == INT_MIN + INT_MAX - 1, "%d %d", o.x, o.w);
    o = isk_ui_inset((isk_ui_rect){10, 10, 20, 20}, 3);
    cr_assert(o.x == 13 && o.y == 13 && o.w == 14 && o.h == 14);
}

Test(hostile, isk_ui_px)
{
    isk_ui ui;
    isk_ui_init(&ui, 3);
    cr_assert_eq(isk_ui_px(&ui, INT_MAX), INT_MAX);
    cr_assert_eq(isk_ui_px(&ui, INT_MIN), INT_MIN);
    cr_assert_eq(isk_ui_px(&ui, 7), 21);
    cr_assert_eq(isk_ui_px(NUL, 7), 7);
}

Test(hostile, isk_ui_cell)
{
    isk_ui_rect c = isk_ui_cell((isk_ui_rect){INT_MAX - 5, 0, 10, 10}, 2, 1, 1, 0, INT_MAX);
    cr_assert(c.x == INT_MAX && c.w >= 0, "%d %d", c.x, c.w);
    c = isk_ui_cell((isk_ui_rect){0, 0, 10, 10}, 2, 2, 1, 1, INT_MIN);
    cr_assert(c.w >= 0 && c.h >= 0);
}

/* It searched every scale up to max_scale: INT_MAX took seconds. */
Test(hostile, isk_ui_fit_scale, .timeout = 1)
{
    cr_assert_eq(isk_ui_fit_scale(INT_MAX, INT_MAX, 1, 1, INT_MAX), INT_MAX);
    cr_assert_eq(isk_ui_fit_scale(INT_MAX, INT_MAX, INT_MAX, INT_MAX, INT_MAX), 1);
    cr_assert_eq(isk_ui_fit_scale(100, 50, 10, 10, 8), 5);
    cr_assert_eq(isk_ui_fit_scale(5, 5, 10, 10, 8), 1);
    cr_assert_eq(isk_ui_fit_scale(-5, 5, 10, 10, 8), 1);
    cr_assert_eq(isk_ui_fit_scale(100, 100, 0, 0, 3), 3);
    cr_assert_eq(isk_ui_fit_scale(100, 100, 10, 10, INT_MIN), 1);
}

/* ---- ISKRA_THREADS ----------------------------------------------------------------- */

Test(hostile, isk_threads_from_text)
{
    const char *bad[] = {NULL, "", "0", "-1", "257", "99999999999999999999", "8 ", " 8", "1e2", "x", "4x"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        cr_assert_eq(isk_threads_from_text(bad[i]), 0, "\"%s\"", bad[i] ? bad[i] : "(null)");
    cr_assert_eq(isk_threads_from_text("1"), 1);
    cr_assert_eq(isk_threads_from_text("008"), 8);
    cr_assert_eq(isk_threads_from_text("256"), ISK_TASKS_MAX_WORKERS);
}
