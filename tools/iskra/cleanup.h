/* SPDX-License-Identifier: MIT */
/* Nothing half-written survives a signal.  The commands that write files
 * open them through here: each temporary (iskra/outfile.h) is registered
 * while it exists, and SIGINT, SIGTERM, SIGHUP or SIGPIPE removes every
 * registered temporary, says on stderr what was written, and exits with
 * 128 + the signal's number (as a shell reports a signal).
 *
 *     cleanup_install("render");
 *     if (cleanup_png_write(&canvas, path)) return 1;    // or:
 *     isk_outfile o;
 *     if (cleanup_outfile_open(&o, path)) return 1;  ...write o.f...
 *     if (cleanup_outfile_commit(&o)) return 1;       // or cleanup_outfile_abort(&o)
 *
 * A render tells it which numbered outputs are complete (cleanup_note:
 * frames, states, frames streamed), so an interrupted one says what was
 * written, or streamed, and that --resume continues.  SIGXFSZ (past
 * `ulimit -f`) is ignored: the write then fails with EFBIG and is
 * reported and cleaned up like any failed write.  The handler only calls unlink,
 * write and _exit (async-signal-safe); the registry is updated with the
 * signals blocked.  This is the tool's state, never the library's. */
#ifndef ISKRA_TOOL_CLEANUP_H
#define ISKRA_TOOL_CLEANUP_H

#include <signal.h>

#include "iskra/canvas.h"
#include "iskra/outfile.h"

/* Installs the handlers (a signal that was ignored at start, as under
 * nohup, stays ignored); cmd names the command in messages. */
void cleanup_install(const char *cmd);

/* isk_outfile_open / _commit / _abort with the temporary registered.
 * 0, or 1 after printing "iskra CMD: ..." (commit, abort: the file is
 * closed either way). */
int cleanup_outfile_open(isk_outfile *o, const char *path);
int cleanup_outfile_commit(isk_outfile *o);
void cleanup_outfile_abort(isk_outfile *o);

/* A whole PNG through the above.  0, or 1 after printing why. */
int cleanup_png_write(const isk_canvas *c, const char *path);

/* What a numbered output has done so far: `count` of them, first,
 * first + every, ..., last, in `where` (a directory, a file name or
 * "standard output"; it must outlive the command, e.g. an argv string).
 * The message after a signal lists each, and any other file written. */
typedef enum cleanup_series {
    CLEANUP_FRAMES, /* render --out-dir: "frames ... were written (N files)", --resume continues */
    CLEANUP_STATES, /* render --state-every: "states ... were written (N files)" */
    CLEANUP_STREAM, /* frames streamed into a pipe, FIFO or device: "frames ... were streamed" */
    CLEANUP_NSERIES
} cleanup_series;
void cleanup_note(cleanup_series k, const char *where, long first, long last, long every, long count);

/* Holds the signals back between hold and release (which nest), so that
 * writing a frame and noting it happen together: a frame the message
 * does not count is never already in place. */
void cleanup_hold(sigset_t *saved);
void cleanup_release(const sigset_t *saved);

#endif
