/* Issue 14, motion: the example scenes' reference images, byte for byte
 * (refimg/NAME.png; test_scene_render compares every scene that has one
 * too): the two-armed spiral of radial and tangential accelerations, smoke
 * stirred by turbulence, a fast emitter at 15 steps/s leaving no gaps (and
 * birth = frame beside it, in clumps), and a local-space fountain. */
#include <criterion/criterion.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "refimg.h"

static void check_scene(const char *name)
{
    char path[256];
    snprintf(path, sizeof path, "scenes/%s.ini", name);
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load(&d, path, &err), ISK_OK, "%s", err.message);
    isk_effect *fx;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, d.width, d.height), ISK_OK);
    cr_assert_eq(isk_effect_run(fx, &c, d.show.frames), ISK_OK);
    cr_assert(refimg_check(name, &c), "refimg %s differs", name);
    isk_canvas_free(&c);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

Test(refimg, motion_orbit, .timeout = 60) { check_scene("motion_orbit"); }
Test(refimg, motion_turbulence, .timeout = 60) { check_scene("motion_turbulence"); }
Test(refimg, motion_fast_emitter, .timeout = 60) { check_scene("motion_fast_emitter"); }
Test(refimg, motion_local_space, .timeout = 60) { check_scene("motion_local_space"); }
