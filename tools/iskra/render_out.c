/* SPDX-License-Identifier: MIT */
/* The outputs of `iskra render` (see render_out.h). */
#include "render_out.h"

#include <errno.h>
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
        cleanup_note(CLEANUP_FRAMES, o->dir, -1, -1, o->every, 0);
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
    o->streaming = o->anim_stdout || o->anim_file.streaming;
    o->stream = f;
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

/* A sequence frame that a previous run finished: a PNG of this size that
 * decodes to its end, every chunk's CRC and the image data whole (this
 * tool renames a frame into place only when complete, but a frame copied
 * half-way, cut by a full disk elsewhere or left by another program is
 * truncated: it is written again, never kept). */
static int already_there(const render_out *o, const char *path)
{
    isk_png_info info;
    if (isk_png_read_info(path, &info, NULL) != ISK_OK || info.width != o->width || info.height != o->height)
        return 0;
    isk_canvas c;
    if (isk_png_read(&c, path, NULL) != ISK_OK)
        return 0;
    isk_canvas_free(&c);
    return 1;
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
                cleanup_note(CLEANUP_FRAMES, o->dir, o->seq_first, o->seq_last, o->every, o->seq_written);
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
        /* A stream cannot be taken back: each frame is pushed out whole,
         * so the message after a signal counts what the reader got. */
        if (o->streaming) {
            if (fflush(o->stream) != 0) {
                fprintf(stderr, "iskra render: %s: %s\n", o->anim_stdout ? "standard output" : o->anim_path,
                        strerror(errno));
                return 1;
            }
            if (o->anim_count++ == 0)
                o->anim_first = f;
            cleanup_note(CLEANUP_STREAM, o->anim_stdout ? "standard output" : o->anim_path, o->anim_first, f, o->every,
                         o->anim_count);
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
