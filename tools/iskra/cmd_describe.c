/* SPDX-License-Identifier: MIT */
/* iskra describe SCENE — the compiled pipeline: per emitter, its stages in
 * the order they run, one per line; then the drawings and the settings
 * (isk_effect_describe). */
#include <stdio.h>
#include <string.h>

#include "cmd.h"
#include "iskra/effect.h"
#include "scene_args.h"

static void help(FILE *f)
{
    fprintf(f, "usage: iskra describe SCENE [--seed N] [--size WxH] [--dt S] [--substeps N]\n"
               "  Prints the pipeline the scene compiles to: for each emitter, the stages\n"
               "  that run every step, in order, one per line.  Forces no emitter uses,\n"
               "  zero-strength forces and disabled potentials are not in it.  Then the\n"
               "  drawings, and every key of [scene], [bounds], each [deflector NAME] and\n"
               "  [click] as key = value (the seed, the clicks, start_paused, ...).\n");
    scene_args_help(f);
    fprintf(f, "  exit status: 0 success, 2 usage or scene error\n");
}

int cmd_describe(int argc, char **argv)
{
    scene_args a = {.cmd = "describe"};
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help(stdout);
            return 0;
        }
        if (scene_args_take(&a, argc, argv, &i) < 0)
            return 2;
    }
    if (!a.scene) {
        help(stderr);
        return 2;
    }
    isk_effect_def def;
    isk_effect *fx;
    int rc = scene_args_open(&a, &def, &fx);
    if (rc)
        return rc;
    isk_effect_describe(fx, stdout);
    isk_effect_destroy(fx);
    isk_effect_def_free(&def);
    return fflush(stdout) == 0 ? 0 : 1;
}
