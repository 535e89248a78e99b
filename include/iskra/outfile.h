/* SPDX-License-Identifier: MIT */
/* iskra/outfile.h — writing a file without ever destroying what it replaces.
 *
 * Example:
 *
 *     isk_outfile o;
 *     isk_error err;
 *     if (isk_make_parent_dirs("out/squares.txt", &err) != ISK_OK        // mkdir -p out
 *             || isk_outfile_open(&o, "out/squares.txt", &err) != ISK_OK) {
 *         fprintf(stderr, "%s\n", err.message);
 *         return 1;
 *     }
 *     int failed = 0;         // write to o.f (or hand it to isk_png_write_stream, isk_anim_begin)
 *     for (int i = 1; i <= 10; i++) failed |= fprintf(o.f, "%d\n", i * i) < 0;
 *     if (failed) { isk_outfile_abort(&o); return 1; }           // out/squares.txt as it was
 *     if (isk_outfile_commit(&o, &err) != ISK_OK) {
 *         fprintf(stderr, "%s\n", err.message);                    // the file as it was too
 *         return 1;
 *     }
 *
 * What happens depends on what the path names when it is opened.  The
 * rule is the same for every writer: the library's PNG writes and scene
 * saves (isk_png_write, isk_scene_save) and every file the iskra tool
 * writes (render's outputs, --state, the simulator's save and screenshots,
 * bench's CSV files) go through here and nowhere else:
 *
 *   nothing, or a regular file   the bytes go to a temporary file beside it,
 *                                PATH.tmp.XXXXXX, which is renamed over PATH
 *                                only by a successful commit (flushed and
 *                                fsynced first), keeping an existing file's
 *                                permissions (a 0600 file stays 0600) and,
 *                                where allowed (root), its owner and group;
 *                                a new file gets 0644.  Abort, or a failed
 *                                commit, removes the temporary: PATH is then
 *                                exactly as it was.
 *   a symbolic link              followed: the file it finally points to is
 *                                treated as above and replaced, the link
 *                                stays a link.  A dangling link is refused
 *                                (ISK_ERR_IO): we do not guess where it meant.
 *   a character device or FIFO   written through (streamed): opened for
 *                                writing, never created, truncated, replaced
 *                                or removed, so `/dev/null` stays a device
 *                                (a save there, even as root, discards the
 *                                bytes), `/dev/stdout` prints them, and a
 *                                reader at the other end of a FIFO gets them
 *                                (opening a FIFO waits for its reader).
 *                                Abort cannot take back what was written.
 *   a directory, a block device  refused (ISK_ERR_IO), nothing touched.
 *   or a socket
 *
 * `temp` names the temporary file while one exists (NULL when streaming,
 * and after commit or abort): a program that handles signals can unlink()
 * it from its handler (unlink is async-signal-safe).  The writer holds a
 * lock (flock) on its temporary until it has been renamed or removed, so
 * a temporary that a killed writer left (SIGKILL, a crash, a power cut)
 * can be told from one being written: isk_outfile_remove_stale removes
 * the first kind only.  The library itself installs no handlers and keeps
 * no global state.
 */
#ifndef ISKRA_OUTFILE_H
#define ISKRA_OUTFILE_H

#include <stdio.h>

#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What a temporary's name adds to the name of the file it becomes,
 * before six characters of its own: "out.png" -> "out.png.tmp.a1B2c3". */
#define ISK_OUTFILE_TEMP_MARK ".tmp."

typedef struct isk_outfile {
    FILE *f;          /* write here between open and commit/abort */
    char *path;       /* the file being written (a symlink's final target) */
    char *temp;       /* the temporary file, or NULL (streaming, or closed) */
    int streaming;    /* 1: written through to a device or FIFO */
} isk_outfile;

/* Errors: ISK_ERR_NULL, ISK_ERR_IO (empty name, refused kind of file,
 * cannot create the temporary: the message says which), ISK_ERR_NOMEM.
 * On error *o is zeroed and nothing exists that did not exist before. */
isk_status isk_outfile_open(isk_outfile *o, const char *path, isk_error *err);

/* Flushes, syncs and closes; for a temporary, renames it over the target.
 * On failure the temporary is removed (ISK_ERR_IO, "disk full?" etc.).
 * Either way *o is closed afterwards. */
isk_status isk_outfile_commit(isk_outfile *o, isk_error *err);

/* Closes and removes the temporary (safe on a zeroed or closed outfile). */
void isk_outfile_abort(isk_outfile *o);

/* Removes `temp` if it is a temporary that a writer left behind when it
 * died before commit or abort: a regular file named like one
 * (NAME.tmp.XXXXXX) that no isk_outfile holds.  A temporary being written
 * by this or another process is left alone.  1 if removed, else 0 (not
 * such a name, missing, or in use). */
int isk_outfile_remove_stale(const char *temp);

/* mkdir -p: creates `dir` and its missing parents (0777 before the umask).
 * An existing directory is fine.  Errors: ISK_ERR_NULL, ISK_ERR_IO (the
 * message names the level that could not be made and why), ISK_ERR_NOMEM. */
isk_status isk_make_dirs(const char *dir, isk_error *err);

/* isk_make_dirs of the directory part of `path` (nothing for "name.png"). */
isk_status isk_make_parent_dirs(const char *path, isk_error *err);

#ifdef __cplusplus
}
#endif

#endif
