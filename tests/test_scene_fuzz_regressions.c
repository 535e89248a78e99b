/* SPDX-License-Identifier: MIT */
/* Replays every input the scene fuzzer ever found (tests/fuzz/regressions/)
 * and the broken scenes of tests/data/bad_scenes/: each must be rejected with
 * a message or parse, compile and run a few frames without crashing (the
 * suite also runs under ASan+UBSan). */
#include <criterion/criterion.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/scene.h"

static int replay_dir(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return 0;
    int n = 0;
    struct dirent *ent;
    while ((ent = readdir(d))) {
        if (ent->d_name[0] == '.')
            continue;
        char path[512];
        snprintf(path, sizeof path, "%s/%s", dir, ent->d_name);
        isk_effect_def def;
        isk_error err = {0};
        isk_status s = isk_scene_load_file(&def, path, &err);
        if (s != ISK_OK) {
            cr_expect_neq(err.message[0], 0, "%s: rejected without a message", path);
        } else if ((long)def.width * def.height <= 1024 * 1024) {
            isk_effect *fx;
            if (isk_effect_create(&fx, &def, &err) == ISK_OK) {
                isk_canvas c;
                if (isk_canvas_init(&c, def.width, def.height) == ISK_OK) {
                    for (int f = 0; f < 3; f++)
                        if (isk_effect_step_render(fx, &c) != ISK_OK)
                            break;
                    isk_canvas_free(&c);
                }
                isk_effect_destroy(fx);
            } else {
                cr_expect_neq(err.message[0], 0, "%s: create failed without a message", path);
            }
        }
        isk_effect_def_free(&def);
        n++;
    }
    closedir(d);
    return n;
}

Test(scene_fuzz, regressions_do_not_crash)
{
    int n = replay_dir("tests/fuzz/regressions");
    cr_log_info("replayed %d fuzzer regression inputs", n);
}

Test(scene_fuzz, bad_scenes_are_rejected)
{
    cr_assert_gt(replay_dir("tests/data/bad_scenes"), 5);
}
