/* SPDX-License-Identifier: MIT */
/* The README gallery's strips: each preset scene's frames side by side, as
 * `iskra render SCENE --frames N --every K --strip FILE.png` draws them,
 * byte for byte against refimg/NAME_strip.png (suite "refimg"). */
#include <criterion/criterion.h>
#include <stdio.h>

#include "iskra/png.h"
#include "refimg.h"
#include "tool_cli.h"

typedef struct strip_case {
    const char *scene;
    long frames, every;
} strip_case;

static const strip_case strips[] = {
    {"preset_galaxy", 360, 60},
    {"preset_smoke", 300, 50},
    {"preset_fireworks", 300, 50},
    {"preset_rain", 120, 20},
    {"preset_magic", 180, 30},
};

static void check_strip(const strip_case *sc)
{
    char dir[128], args[400], path[200], name[96];
    snprintf(dir, sizeof dir, "out/test_gallery_strips/%s", sc->scene);
    cli_fresh(dir);
    snprintf(path, sizeof path, "%s/strip.png", dir);
    snprintf(args, sizeof args, "render scenes/%s.ini --frames %ld --every %ld --strip %s", sc->scene, sc->frames,
             sc->every, path);
    cr_assert_eq(cli_run(dir, args), 0, "iskra %s", args);
    isk_canvas c;
    cr_assert_eq(isk_png_read(&c, path, NULL), ISK_OK);
    snprintf(name, sizeof name, "%s_strip", sc->scene);
    cr_expect(refimg_check(name, &c), "refimg %s differs", name);
    isk_canvas_free(&c);
}

Test(refimg, gallery_strips, .timeout = 240)
{
    for (size_t i = 0; i < sizeof strips / sizeof strips[0]; i++)
        check_strip(&strips[i]);
}
