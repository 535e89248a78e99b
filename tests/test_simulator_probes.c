/* SPDX-License-Identifier: MIT */
/* The simulator's probe chart: a scene with a gate and a region charts the
 * gate's rates and the region's count beside the particle count (the
 * reference image simulator_probe_chart); a scene without probes has no
 * such chart (the existing simulator images stay as they were). */
#include <criterion/criterion.h>

#include "play_session.h"
#include "refimg.h"

#define OUT "out/test_simulator_probes/"

Test(simulator_probes, the_probe_chart_after_150_frames)
{
    cr_assert_eq(play_session(OUT "chart", "tests/data/probes_play.ini --ui-scale 1 --frames 160 --script 'tab "
                                           "wait:150 tab wait:3 shot:" OUT "chart/window.png'"),
                 0, "%s", play_stderr(OUT "chart"));
    isk_canvas c;
    play_read_png(OUT "chart/window.png", &c);
    cr_expect(refimg_check("simulator_probe_chart", &c));
    isk_canvas_free(&c);
}
