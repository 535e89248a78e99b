/* SPDX-License-Identifier: MIT */
/* The block stages of a batched dot draw (src/view/dot_block.h) on every
 * build this CPU runs: the scalar code, AVX2 and AVX-512 give the same
 * selected points and the same pixels and weights, bit for bit, for every
 * block length (the masked last steps) and every kind of coordinate: on the
 * canvas, on its edges, just off them, far off, huge, infinite and NaN.
 * The batch tests (test_raster_fast.c) check whichever build the CPU picks
 * against the per-pixel reference; this checks the builds it does not
 * pick. */
#include <criterion/criterion.h>

#include <float.h>
#include <math.h>
#include <string.h>

#include "iskra/rng.h"
#include "iskra/view.h"
#include "view/dot_block.h"
#include "view/view_transform.h"

/* A screen coordinate for a canvas dimension n (tests/test_raster_fast.c's
 * mix). */
static double coord(isk_rng *r, int n)
{
    switch (isk_rng_below(r, 20)) {
    case 0: return NAN;
    case 1: return isk_rng_below(r, 2) ? INFINITY : -INFINITY;
    case 2: return isk_rng_below(r, 2) ? DBL_MAX : -DBL_MAX;
    case 3: return isk_rng_range(r, -1e9, 1e9);
    case 4: return (double)(int)isk_rng_below(r, (uint32_t)n + 4) - 2.0;
    case 5: return ((double)(int)isk_rng_below(r, 2u * (uint32_t)n + 8) - 4.0) / 2.0;
    case 6: return (isk_rng_below(r, 2) ? -1.0 : (double)n) + isk_rng_range(r, -1e-9, 1e-9);
    case 7: return isk_rng_below(r, 2) ? -0.0 : 1e-300;
    case 8: return nextafter((double)(int)isk_rng_below(r, (uint32_t)n + 2), -INFINITY);
    default: return isk_rng_range(r, -3.0, n + 3.0);
    }
}

typedef struct build {
    const char *name;
    weights_fn weights;
    select_fn select;
} build;

/* The builds this CPU can run, the scalar one first. */
static int builds(build *b)
{
    int n = 0;
    b[n++] = (build){"scalar", weights_scalar, select_scalar};
#if ISK__CPU_AVX2
    if (isk__have_avx2())
        b[n++] = (build){"avx2", isk__dot_weights_avx2, isk__dot_select_avx2};
#endif
#if ISK__CPU_AVX512
    if (isk__have_avx512())
        b[n++] = (build){"avx512", isk__dot_weights_avx512, isk__dot_select_avx512};
#endif
    return n;
}

Test(dot_block, weights_are_the_same_on_every_build)
{
    build b[3];
    const int nb = builds(b);
    cr_log_info("builds: %d", nb);
    isk_rng r;
    isk_rng_seed(&r, 5);
    for (int n = 0; n < 20000; n++) {
        const int w = 1 + (int)isk_rng_below(&r, 64), h = 1 + (int)isk_rng_below(&r, 64);
        const int m = (int)isk_rng_below(&r, DOT_BATCH + 1); /* a draw's batch, up to its whole arrays */
        /* a tile: its first column and row, the canvas's last */
        const double X0 = (double)isk_rng_below(&r, (uint32_t)w), Y0 = (double)isk_rng_below(&r, (uint32_t)h);
        const double H1 = h - 1.0, W1 = w - 1.0;
        dot_block ref, got;
        memset(&ref, 0xA5, sizeof ref);
        for (int k = 0; k < m; k++) {
            ref.x[k] = coord(&r, w);
            ref.y[k] = coord(&r, h);
        }
        got = ref;
        b[0].weights(&ref, m, X0, W1, Y0, H1);
        for (int v = 1; v < nb; v++) {
            dot_block t = got;
            b[v].weights(&t, m, X0, W1, Y0, H1);
            for (int k = 0; k < m; k++) {
                cr_assert_eq(t.fast[k], ref.fast[k], "%s, case %d, point %d of %d: fast %d, scalar %d (x %a y %a)",
                             b[v].name, n, k, m, t.fast[k], ref.fast[k], ref.x[k], ref.y[k]);
                if (!ref.fast[k])
                    continue;
                cr_assert(t.ix[k] == ref.ix[k] && t.iy[k] == ref.iy[k] && !memcmp(t.w[k], ref.w[k], 4),
                          "%s, case %d, point %d: pixel (%d, %d) weights %d %d %d %d; scalar (%d, %d) %d %d %d %d",
                          b[v].name, n, k, t.ix[k], t.iy[k], t.w[k][0], t.w[k][1], t.w[k][2], t.w[k][3], ref.ix[k],
                          ref.iy[k], ref.w[k][0], ref.w[k][1], ref.w[k][2], ref.w[k][3]);
            }
        }
    }
}

Test(dot_block, select_is_the_same_on_every_build)
{
    build b[3];
    const int nb = builds(b);
    isk_rng r;
    isk_rng_seed(&r, 6);
    for (int n = 0; n < 20000; n++) {
        const int h = 1 + (int)isk_rng_below(&r, 64), m = (int)isk_rng_below(&r, DOT_BLOCK + 1);
        double y[DOT_BLOCK];
        for (int k = 0; k < m; k++)
            y[k] = coord(&r, h);
        const int r0 = (int)isk_rng_below(&r, (uint32_t)h), browser = (int)isk_rng_below(&r, 2);
        select_view sv = {.camera = (int)isk_rng_below(&r, 2), .keep = (int)isk_rng_below(&r, 2),
                          .axis = {h / 2.0, isk_rng_range(&r, -20, 20), isk_rng_range(&r, -2, 2),
                                   isk_rng_range(&r, -20, 20), isk_rng_range(&r, -5, h + 5.0)},
                          .lo = browser ? r0 - 2.0 : r0 - 1.0, .hi = browser ? h + 1.0 : (double)h, .height = h};
        /* y is a world coordinate: put some points on the rows */
        for (int k = 0; k < m; k++)
            if (isk_rng_below(&r, 2) && sv.axis.s != 0.0 && sv.axis.k != 0.0)
                y[k] = sv.camera ? (sv.axis.c - y[k]) / sv.axis.k - sv.axis.t : (y[k] - sv.axis.p) / sv.axis.s;
        double oy_ref[DOT_BLOCK], oy[DOT_BLOCK];
        int32_t ix_ref[DOT_BLOCK], ix[DOT_BLOCK];
        const int kept = b[0].select(&sv, y, m, oy_ref, ix_ref);
        for (int v = 1; v < nb; v++) {
            const int got = b[v].select(&sv, y, m, oy, ix);
            cr_assert_eq(got, kept, "%s, case %d: %d kept, scalar %d", b[v].name, n, got, kept);
            cr_assert(!memcmp(oy, oy_ref, (size_t)kept * sizeof *oy) && !memcmp(ix, ix_ref, (size_t)kept * sizeof *ix),
                      "%s, case %d: other points or rows kept", b[v].name, n);
        }
    }
}

/* Every build's select is view_transform.h's isk__view_axis_map lane by
 * lane: each kept point's screen coordinate is the helper's, bit for bit
 * (then moved by isk__keep_on_canvas when keep), and exactly the points
 * the helper puts strictly between lo and hi are kept, in order.  Real
 * views of both kinds, on both axes (X's camera form has k = -a). */
Test(dot_block, select_is_the_view_helper_point_by_point)
{
    build b[3];
    const int nb = builds(b);
    isk_rng r;
    isk_rng_seed(&r, 7);
    int compared = 0;
    for (int n = 0; n < 20000; n++) {
        const int w = 1 + (int)isk_rng_below(&r, 800), h = 1 + (int)isk_rng_below(&r, 600);
        isk_view v;
        const isk_status st =
            isk_rng_below(&r, 2) ? isk_view_camera(&v, w, h, isk_rng_range(&r, 0.05, 40), isk_rng_range(&r, -9, 9),
                                                   isk_rng_range(&r, -9, 9))
                                 : isk_view_window(&v, w, h, isk_rng_range(&r, -50, -0.5), isk_rng_range(&r, 0.5, 50),
                                                   isk_rng_range(&r, -50, -0.5), isk_rng_range(&r, 0.5, 50));
        cr_assert_eq(st, ISK_OK);
        const int on_x = (int)isk_rng_below(&r, 2), size = on_x ? w : h;
        const double first = (double)isk_rng_below(&r, (uint32_t)size);
        const select_view sv = {.camera = isk__view_is_camera(&v), .keep = (int)isk_rng_below(&r, 2),
                                .axis = on_x ? isk__view_axis_x(&v) : isk__view_axis_y(&v), .lo = first - 1.0,
                                .hi = (double)size, .height = size};
        const int m = (int)isk_rng_below(&r, DOT_BLOCK + 1);
        double u[DOT_BLOCK];
        for (int k = 0; k < m; k++) { /* world coordinates: on the canvas, near it, or anything */
            double world, dummy;
            if (on_x)
                isk_view_to_world(&v, coord(&r, size), 0.0, &world, &dummy);
            else
                isk_view_to_world(&v, 0.0, coord(&r, size), &dummy, &world);
            u[k] = isk_rng_below(&r, 8) ? world : coord(&r, size);
        }
        for (int bi = 0; bi < nb; bi++) {
            double oy[DOT_BLOCK];
            int32_t ix[DOT_BLOCK];
            const int kept = b[bi].select(&sv, u, m, oy, ix);
            int q = 0;
            for (int k = 0; k < m; k++) {
                double U = isk__view_axis_map(sv.axis, sv.camera, u[k]);
                if (sv.keep)
                    U = isk__keep_on_canvas(U, size);
                if (!(U > sv.lo && U < sv.hi))
                    continue;
                cr_assert(q < kept && ix[q] == k, "%s, case %d: point %d (u %a) not kept", b[bi].name, n, k, u[k]);
                cr_assert(!memcmp(&oy[q], &U, sizeof U), "%s, case %d, point %d on %s: %a, the helper %a",
                          b[bi].name, n, k, on_x ? "x" : "y", oy[q], U);
                q++;
                compared++;
            }
            cr_assert_eq(q, kept, "%s, case %d: %d kept, the helper keeps %d", b[bi].name, n, kept, q);
        }
    }
    cr_assert(compared > 100000, "only %d points compared", compared);
}
