/* iskra render SCENE --frames N --out FILE.png
 * iskra render SCENE --frames N --out-dir DIR [--every K]
 * Renders frame N (frame 0 = the initial state, frame N = after N steps) to
 * a PNG, and/or a numbered sequence DIR/frame_000000.png ... of every K-th
 * frame up to N.  Everything is validated before anything is written. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd.h"
#include "iskra/effect.h"
#include "iskra/png.h"
#include "outpath.h"
#include "progress.h"
#include "scene_args.h"

static void help(FILE *f)
{
    fprintf(f, "usage: iskra render SCENE [--frames N] --out FILE.png\n"
               "       iskra render SCENE [--frames N] --out-dir DIR [--every K]\n"
               "  Renders frame N of the scene (0 = the initial state; N steps of dt).\n"
               "  --frames N       the frame to render, 0..100000000 (default: the scene's\n"
               "                   [scene] frames, else 0)\n"
               "  --out FILE.png   write frame N there\n"
               "  --out-dir DIR    write frames 0, K, 2K, ... <= N as DIR/frame_000000.png ...\n"
               "                   (missing directories of DIR and FILE are created)\n"
               "  --every K        sequence step, >= 1 (default 1)\n");
    scene_args_help(f);
    fprintf(f, "  A progress bar appears on stderr when it is a terminal and the render\n"
               "  takes a while.  exit status: 0 success, 1 cannot write, 2 usage or scene error\n");
}

static int write_png(const isk_canvas *c, const char *path)
{
    isk_error err;
    if (isk_png_write(c, path, &err) != ISK_OK) {
        fprintf(stderr, "iskra render: %s\n", err.message);
        return 1;
    }
    return 0;
}

int cmd_render(int argc, char **argv)
{
    scene_args a = {.cmd = "render"};
    const char *out = NULL, *out_dir = NULL;
    long frames = -1, every = 1;
    int have_every = 0;
    for (int i = 1; i < argc; i++) {
        const char *v;
        int r;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help(stdout);
            return 0;
        }
        if ((r = arg_value("render", argc, argv, &i, "--frames", &v)) != 0) {
            if (r < 0 || !arg_long("render", "--frames", v, 0, 100000000, &frames))
                return 2;
        } else if ((r = arg_value("render", argc, argv, &i, "--every", &v)) != 0) {
            if (r < 0 || !arg_long("render", "--every", v, 1, 100000000, &every))
                return 2;
            have_every = 1;
        } else if ((r = arg_value("render", argc, argv, &i, "--out-dir", &v)) != 0) {
            if (r < 0)
                return 2;
            out_dir = v;
        } else if ((r = arg_value("render", argc, argv, &i, "--out", &v)) != 0) {
            if (r < 0)
                return 2;
            out = v;
        } else if (scene_args_take(&a, argc, argv, &i) < 0) {
            return 2;
        }
    }
    if (!a.scene || (!out && !out_dir)) {
        fprintf(stderr, "iskra render: %s\n", !a.scene ? "which scene?" : "say where: --out FILE.png or --out-dir DIR");
        help(stderr);
        return 2;
    }
    if (have_every && !out_dir) {
        fprintf(stderr, "iskra render: --every needs --out-dir\n");
        return 2;
    }
    if ((out && !*out) || (out_dir && !*out_dir)) {
        fprintf(stderr, "iskra render: empty output name\n");
        return 2;
    }
    if (outpath_refuse_input("render", out, a.scene))
        return 2;

    isk_effect_def def;
    isk_effect *fx;
    int rc = scene_args_open(&a, &def, &fx);
    if (rc)
        return rc;
    if (frames < 0)
        frames = def.frames;
    isk_canvas canvas;
    if (isk_canvas_init(&canvas, def.width, def.height) != ISK_OK) {
        fprintf(stderr, "iskra render: cannot allocate a %dx%d canvas\n", def.width, def.height);
        isk_effect_destroy(fx);
        isk_effect_def_free(&def);
        return 1;
    }
    if ((out_dir && outpath_make_dirs("render", out_dir)) || (out && outpath_make_parents("render", out))) {
        rc = 1;
        goto done;
    }

    progress pg;
    progress_start(&pg, frames);
    /* Frame 0 is the initial state (with trails: the bare background).  A
     * scene that clears is drawn only when a frame is written; a trail scene
     * is drawn after every step, as isk_effect_run does. */
    int trails = !def.clear;
    isk_status s = isk_effect_run(fx, &canvas, 0);
    int drawn = 1;
    for (long f = 0; s == ISK_OK; f++) {
        if (out_dir && f % every == 0) {
            if (!drawn && (s = isk_effect_render(fx, &canvas)) != ISK_OK)
                break;
            drawn = 1;
            char path[4200];
            snprintf(path, sizeof path, "%s/frame_%06ld.png", out_dir, f);
            if (write_png(&canvas, path)) {
                rc = 1;
                goto done;
            }
        }
        progress_update(&pg, f);
        if (f == frames)
            break;
        s = trails ? isk_effect_step_render(fx, &canvas) : isk_effect_step(fx);
        drawn = trails;
    }
    if (s == ISK_OK && !drawn)
        s = isk_effect_render(fx, &canvas);
    if (s != ISK_OK) {
        fprintf(stderr, "iskra render: %s: frame %ld: %s\n", a.scene, isk_effect_frame(fx), isk_status_str(s));
        rc = 1;
        goto done;
    }
    progress_end(&pg);
    if (out && write_png(&canvas, out))
        rc = 1;
done:
    isk_canvas_free(&canvas);
    isk_effect_destroy(fx);
    isk_effect_def_free(&def);
    return rc;
}
