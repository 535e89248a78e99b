/* SPDX-License-Identifier: MIT */
/* The two world-to-screen mappings and their inverses, with the theses'
 * own numbers. */
#include <criterion/criterion.h>
#include <math.h>

#include "iskra/view.h"

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
