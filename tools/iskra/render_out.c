/* SPDX-License-Identifier: MIT */
/* The outputs of `iskra render` (see render_out.h). */
#include "render_out.h"

#include <stdio.h>
#include <string.h>

#include "cleanup.h"
#include "iskra/png.h"
#include "outpath.h"

void render_out_frame_path(const char *dir, long f, char *path, size_t n)
{
    snprintf(path, n, "%s/" RENDER_FRAME_PREFIX "%06ld" RENDER_FRAME_SUFFIX, dir, f);
}

int render_out_begin(render_out *o, int width, int height, double fps)
{
    o->width = width;
    o->height = height;
    o->seq_first = o->seq_last = -1;
    if ((o->dir && outpath_make_dirs("render", o->dir)) || (o->png && outpath_make_parents("render", o->png)))
        return 1;
    if (o->dir)
        cleanup_note_frames(o->dir, -1, -1, o->every, 0);
    if (!o->anim_path)
        return 0;
    isk_error err;
    FILE *f;
    if (!strcmp(o->anim_path, "-")) {
        o->anim_stdout = 1;
        f = stdout;
    } else {
        if (outpath_make_parents("render", o->anim_path) || cleanup_outfile_open(&o->anim_file, o->anim_path))
            return 1;
        f = o->anim_file.f;
    }
    isk_anim_opts ao = {o->anim_format, width, height, fps};
    if (isk_anim_begin(&o->anim, f, &ao, &err) != ISK_OK) {
        fprintf(stderr, "iskra render: %s: %s\n", o->anim_path, err.message);
        render_out_abort(o);
        return 1;
    }
    return 0;
}

int render_out_wants(const render_out *o, long f)
{
    return f % o->every == 0 && (o->dir || o->anim);
}

/* A sequence frame that a previous run finished: a PNG of this size (a
 * frame is renamed into place only when complete, so one that exists is
 * whole; the header check guards against another render's leftovers). */
static int already_there(const render_out *o, const char *path)
{
    isk_png_info info;
    return isk_png_read_info(path, &info, NULL) == ISK_OK && info.width == o->width && info.height == o->height;
}

int render_out_frame(render_out *o, const isk_canvas *c, long f)
{
    if (f % o->every != 0)
        return 0;
    if (o->dir) {
        char path[4200];
        render_out_frame_path(o->dir, f, path, sizeof path);
        if (o->resume && already_there(o, path)) {
            o->seq_kept++;
        } else {
            sigset_t held;
            cleanup_hold(&held);
            int failed = cleanup_png_write(c, path);
            if (!failed) {
                o->seq_written++;
                if (o->seq_first < 0)
                    o->seq_first = f;
                o->seq_last = f;
                cleanup_note_frames(o->dir, o->seq_first, o->seq_last, o->every, o->seq_written);
            }
            cleanup_release(&held);
            if (failed)
                return 1;
        }
    }
    if (o->anim) {
        isk_error err;
        if (isk_anim_frame(o->anim, c, &err) != ISK_OK) {
            fprintf(stderr, "iskra render: %s: %s\n", o->anim_path, err.message);
            return 1;
        }
    }
    return 0;
}

int render_out_end(render_out *o, const isk_canvas *last)
{
    int rc = 0;
    isk_error err;
    if (o->anim) {
        isk_status s = isk_anim_end(o->anim, &err);
        o->anim = NULL;
        if (s != ISK_OK) {
            fprintf(stderr, "iskra render: %s: %s\n", o->anim_path, err.message);
            render_out_abort(o);
            rc = 1;
        } else if (!o->anim_stdout && cleanup_outfile_commit(&o->anim_file)) {
            rc = 1;
        }
    }
    if (!rc && o->png && cleanup_png_write(last, o->png))
        rc = 1;
    if (o->resume && o->dir)
        fprintf(stderr, "iskra render: %s: %ld frames written, %ld already there kept\n", o->dir, o->seq_written,
                o->seq_kept);
    return rc;
}

void render_out_abort(render_out *o)
{
    isk_anim_abort(o->anim);
    o->anim = NULL;
    if (!o->anim_stdout)
        cleanup_outfile_abort(&o->anim_file);
}
