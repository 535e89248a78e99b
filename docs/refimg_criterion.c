/* SPDX-License-Identifier: MIT */
/* Pixel-exact tests of your own drawing in a Criterion test suite.
 *
 *     cc refimg_criterion.c -o tests $(pkg-config --cflags --libs iskra criterion)
 *     ISKRA_REFIMG_UPDATE=1 ./tests   # first run: writes the references in ref/ (look at them)
 *     ./tests                         # from then on: exact comparisons
 *
 * A failing test says how many pixels differ and by how much, and leaves
 * out/refimg/NAME.actual.png and NAME.diff.png to look at. */
#include <criterion/criterion.h>
#include <iskra.h>

static isk_canvas canvas;

static void setup(void) { cr_assert_eq(isk_canvas_init(&canvas, 64, 48), ISK_OK); }
static void teardown(void) { isk_canvas_free(&canvas); }

/* Exact comparison with ref/NAME.png; the message is the library's. */
#define ASSERT_LOOKS_LIKE(name)                                                                   \
    do {                                                                                          \
        isk_refimg_opts opts = {0};                                                               \
        opts.out_dir = "out/refimg";                                                              \
        isk_error err;                                                                            \
        cr_assert_eq(isk_refimg_check(&canvas, "ref/" name ".png", &opts, &err), ISK_OK, "%s",    \
                     err.message);                                                                \
    } while (0)

TestSuite(drawing, .init = setup, .fini = teardown);

Test(drawing, target)
{
    isk_canvas_fill(&canvas, ISK_WHITE);
    for (int r = 20; r > 0; r -= 5)
        isk_fill_circle_aa(&canvas, 32, 24, r, r % 10 ? ISK_RED : ISK_WHITE, ISK_BLEND_OVER);
    ASSERT_LOOKS_LIKE("target");
}

Test(drawing, stripes_with_a_tolerance)
{
    for (int y = 0; y < 48; y++)
        isk_fill_rect(&canvas, 0, y, 64, 1, isk_rgba((uint8_t)(y * 5), 0, 128, 255), ISK_BLEND_REPLACE);
    isk_refimg_opts opts = {0};
    opts.out_dir = "out/refimg";
    opts.max_channel_diff = 1; /* a tolerance must say why */
    opts.reason = "example: the stripe colours are computed in floating point elsewhere";
    isk_error err;
    cr_assert_eq(isk_refimg_check(&canvas, "ref/stripes.png", &opts, &err), ISK_OK, "%s", err.message);
}
