/* SPDX-License-Identifier: MIT */
/* The two world-to-screen mappings and their inverses, with the theses'
 * own numbers. */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "iskra/rng.h"
#include "iskra/view.h"
#include "view/view_transform.h"

Test(view, window_minus10_10_on_600)
{
    isk_view v;
    cr_assert_eq(isk_view_window(&v, 600, 600, -10, 10, -10, 10), ISK_OK);
    cr_assert_eq(v.sx, 30.0);
    cr_assert_eq(v.sy, -30.0);
    cr_assert_eq(v.px, 300.0);
    cr_assert_eq(v.py, 300.0);
    /* x = 30*wx + 300, y = 300 - 30*wy, exactly. */
    for (double wx = -10; wx <= 10; wx += 0.25)
        for (double wy = -10; wy <= 10; wy += 0.25) {
            double X, Y;
            isk_view_to_screen(&v, wx, wy, &X, &Y);
            cr_assert_eq(X, 30 * wx + 300);
            cr_assert_eq(Y, 300 - 30 * wy);
        }
    double X, Y;
    isk_view_to_screen(&v, -4, -4, &X, &Y);
    cr_assert_eq(X, 180.0); /* thesis figure 9: the particle's pixel */
    cr_assert_eq(Y, 420.0);
}

Test(view, window_0_10_simulator_and_0_40)
{
    isk_view v;
    double X, Y;
    cr_assert_eq(isk_view_window(&v, 600, 600, 0, 10, 0, 10), ISK_OK);
    isk_view_to_screen(&v, 5, 5, &X, &Y);
    cr_assert_eq(X, 300.0);
    cr_assert_eq(Y, 300.0);
    cr_assert_eq(isk_view_window(&v, 600, 600, 0, 40, 0, 40), ISK_OK);
    isk_view_to_screen(&v, 20, 10, &X, &Y);
    cr_assert_eq(X, 300.0);
    cr_assert_eq(Y, 450.0);
}

Test(view, window_fig8)
{
    isk_view v;
    double X, Y;
    cr_assert_eq(isk_view_window(&v, 500, 500, -400, 400, -400, 400), ISK_OK);
    cr_assert_eq(v.sx, 0.625);
    isk_view_to_screen(&v, 275, 150, &X, &Y); /* triangle 1, vertex C */
    cr_assert_eq(X, 421.875);
    cr_assert_eq(Y, 156.25);
}

Test(view, window_inverse_round_trip)
{
    isk_view v;
    cr_assert_eq(isk_view_window(&v, 640, 480, -3.5, 7.25, -1, 2), ISK_OK);
    for (int i = 0; i < 1000; i++) {
        double wx = -3.5 + 10.75 * i / 999.0, wy = -1 + 3.0 * ((i * 37) % 1000) / 999.0;
        double X, Y, bx, by;
        isk_view_to_screen(&v, wx, wy, &X, &Y);
        isk_view_to_world(&v, X, Y, &bx, &by);
        cr_assert_float_eq(bx, wx, 1e-12);
        cr_assert_float_eq(by, wy, 1e-12);
    }
}

Test(view, window_rejects_invalid)
{
    isk_view v;
    cr_assert_eq(isk_view_window(&v, 600, 600, 10, -10, -10, 10), ISK_ERR_RANGE);
    cr_assert_eq(isk_view_window(&v, 600, 600, 1, 1, -10, 10), ISK_ERR_RANGE);
    cr_assert_eq(isk_view_window(&v, 600, 600, -10, 10, 5, 5), ISK_ERR_RANGE);
    cr_assert_eq(isk_view_window(&v, 600, 600, NAN, 10, -10, 10), ISK_ERR_NAN);
    cr_assert_eq(isk_view_window(&v, 600, 600, -10, INFINITY, -10, 10), ISK_ERR_NAN);
    cr_assert_eq(isk_view_window(&v, 0, 600, -10, 10, -10, 10), ISK_ERR_SIZE);
    cr_assert_eq(isk_view_window(&v, 600, -1, -10, 10, -10, 10), ISK_ERR_SIZE);
    cr_assert_eq(isk_view_window(NULL, 600, 600, -10, 10, -10, 10), ISK_ERR_NULL);
    /* min and max one ulp apart: the scale overflows, not a usable view. */
    cr_assert_eq(isk_view_window(&v, 600, 600, -1e308, 1e308, -10, 10), ISK_ERR_RANGE);
}

Test(view, camera_fire_thesis_example)
{
    isk_view v;
    double X, Y;
    cr_assert_eq(isk_view_camera(&v, 800, 600, 10, 0, 0), ISK_OK);
    cr_assert_eq(v.a, 70.0);
    isk_view_to_screen(&v, 1, 1, &X, &Y);
    cr_assert_eq(X, 470.0);
    cr_assert_eq(Y, 230.0);
    isk_view_to_screen(&v, 0, 0, &X, &Y);
    cr_assert_eq(X, 400.0);
    cr_assert_eq(Y, 300.0);
    /* Pan by t = (-1, 0): world (1, 0) comes to the centre. */
    cr_assert_eq(isk_view_camera(&v, 800, 600, 10, -1, 0), ISK_OK);
    isk_view_to_screen(&v, 1, 0, &X, &Y);
    cr_assert_eq(X, 400.0);
    cr_assert_eq(Y, 300.0);
}

Test(view, camera_inverse_and_invalid)
{
    isk_view v;
    cr_assert_eq(isk_view_camera(&v, 800, 600, 3.5, 0.25, -2), ISK_OK);
    for (int i = 0; i < 500; i++) {
        double wx = -5 + i * 0.02, wy = 3 - i * 0.013, X, Y, bx, by;
        isk_view_to_screen(&v, wx, wy, &X, &Y);
        isk_view_to_world(&v, X, Y, &bx, &by);
        cr_assert_float_eq(bx, wx, 1e-9);
        cr_assert_float_eq(by, wy, 1e-9);
    }
    cr_assert_eq(isk_view_camera(&v, 800, 600, 0, 0, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_view_camera(&v, 800, 600, -1, 0, 0), ISK_ERR_RANGE);
    cr_assert_eq(isk_view_camera(&v, 800, 600, NAN, 0, 0), ISK_ERR_NAN);
    cr_assert_eq(isk_view_camera(&v, 800, 600, 1, INFINITY, 0), ISK_ERR_NAN);
    cr_assert_eq(isk_view_camera(&v, 0, 600, 1, 0, 0), ISK_ERR_SIZE);
}

/* The transform helper every kernel shares (src/view/view_transform.h)
 * gives, bit for bit, the theses' formulas as iskra/view.h writes them:
 * the camera's X as w/2 + a*(x + tx) although the helper computes
 * w/2 - (-a)*(x + tx).  Random views of both kinds, points on and far off
 * the canvas, huge, infinite, zero of either sign. */
Test(view, helper_is_the_theses_formulas_bit_for_bit)
{
    isk_rng r;
    isk_rng_seed(&r, 3);
    const double special[] = {0.0, -0.0, 1e-300, -1e-300, 1e300, -1e300, INFINITY, -INFINITY, 0.5, -0.5};
    for (int n = 0; n < 2000; n++) {
        const int w = 1 + (int)isk_rng_below(&r, 2000), h = 1 + (int)isk_rng_below(&r, 2000);
        isk_view v;
        const int camera = (int)isk_rng_below(&r, 2);
        const isk_status st =
            camera ? isk_view_camera(&v, w, h, isk_rng_range(&r, 1e-3, 1e3), isk_rng_range(&r, -1e3, 1e3),
                                     isk_rng_range(&r, -1e3, 1e3))
                   : isk_view_window(&v, w, h, isk_rng_range(&r, -1e3, -1e-3), isk_rng_range(&r, 1e-3, 1e3),
                                     isk_rng_range(&r, -1e3, -1e-3), isk_rng_range(&r, 1e-3, 1e3));
        cr_assert_eq(st, ISK_OK);
        for (int k = 0; k < 200; k++) {
            const double x = k < 10 ? special[k] : isk_rng_range(&r, -3e3, 3e3);
            const double y = k < 10 ? special[9 - k] : isk_rng_range(&r, -3e3, 3e3);
            const double wantX = camera ? v.width / 2.0 + v.a * (x + v.tx) : v.sx * x + v.px;
            const double wantY = camera ? v.height / 2.0 - v.a * (y + v.ty) : v.sy * y + v.py;
            double X, Y, X1, Y1;
            isk__view_to_screen(&v, x, y, &X, &Y);
            isk_view_to_screen(&v, x, y, &X1, &Y1);
            const double gotX = isk__view_axis_map(isk__view_axis_x(&v), isk__view_is_camera(&v), x);
            const double gotY = isk__view_axis_map(isk__view_axis_y(&v), isk__view_is_camera(&v), y);
            if (isnan(wantX) || isnan(wantY)) { /* inf - inf: NaN either way */
                cr_assert(isnan(X) == isnan(wantX) && isnan(Y) == isnan(wantY));
                continue;
            }
            cr_assert(!memcmp(&X, &wantX, sizeof X) && !memcmp(&Y, &wantY, sizeof Y) && !memcmp(&X1, &wantX, sizeof X) &&
                          !memcmp(&Y1, &wantY, sizeof Y) && !memcmp(&gotX, &wantX, sizeof X) &&
                          !memcmp(&gotY, &wantY, sizeof Y),
                      "view %d (%s), point (%a, %a): (%a, %a), the formulas (%a, %a)", n, camera ? "camera" : "window",
                      x, y, X, Y, wantX, wantY);
        }
    }
}
