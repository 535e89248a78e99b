/* SPDX-License-Identifier: MIT */
/* Output files that never destroy what they replace (iskra/outfile.h). */
#define _DEFAULT_SOURCE /* realpath, fchown, flock */
#include "iskra/outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#ifndef __wasi__
#include <sys/file.h>
#endif

/* The browser's C library (wasm32-wasi) has no mkstemp, fchmod, fchown,
 * flock or realpath: there a temporary is the first free name of the
 * template (created exclusively, so it is still never an existing file),
 * files have no permissions or owners to give, nothing else runs that
 * could leave or remove a temporary, and a symbolic link is refused. */
#ifdef __wasi__
static int make_temp(char *tmpl)
{
    char *x = tmpl + strlen(tmpl) - 6;
    for (unsigned i = 0; i < 1000000u; i++) {
        snprintf(x, 7, "%06u", i);
        int fd = open(tmpl, O_WRONLY | O_CREAT | O_EXCL, 0644);
        if (fd >= 0 || errno != EEXIST)
            return fd;
    }
    errno = EEXIST;
    return -1;
}
#define fchmod(fd, mode) ((void)(fd), (void)(mode), 0)
#define fchown(fd, uid, gid) ((void)(fd), (void)(uid), (void)(gid), 0)
#define flock(fd, how) ((void)(fd), (void)(how), 0)
#define LOCK_EX 2
#define LOCK_NB 4
#else
#define make_temp mkstemp
#endif

static char *dup_str(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

static isk_status fail(isk_outfile *o, isk_error *err, isk_status s, const char *shown, const char *why)
{
    free(o->path);
    free(o->temp);
    memset(o, 0, sizeof *o);
    return isk_error_set(err, s, "%s: %s", shown, why);
}

/* A device or FIFO: open for writing as it is (no O_CREAT, no O_TRUNC). */
static isk_status open_stream(isk_outfile *o, const char *path, isk_error *err)
{
    int fd = open(path, O_WRONLY | O_NOCTTY);
    if (fd < 0)
        return fail(o, err, ISK_ERR_IO, path, strerror(errno));
    o->f = fdopen(fd, "wb");
    if (!o->f) {
        int e = errno;
        close(fd);
        return fail(o, err, ISK_ERR_IO, path, strerror(e));
    }
    o->streaming = 1;
    return ISK_OK;
}

/* A temporary made by make_temp and locked (flock) for as long as it is
 * open, which is how isk_outfile_remove_stale tells a live writer's
 * temporary from one a killed writer left.  A remover that catches the
 * name between the creation and the lock takes the lock first and
 * unlinks the file: the name then no longer leads to our file, and we
 * make another.  -1 with errno on failure. */
static int make_locked_temp(char *tmpl)
{
    const size_t n = strlen(tmpl);
    for (int attempt = 0; attempt < 100; attempt++) {
        memcpy(tmpl + n - 6, "XXXXXX", 6);
        int fd = make_temp(tmpl);
        if (fd < 0)
            return -1;
        struct stat mine, named;
        if (flock(fd, LOCK_EX) == 0 && fstat(fd, &mine) == 0 && stat(tmpl, &named) == 0 &&
            mine.st_dev == named.st_dev && mine.st_ino == named.st_ino)
            return fd;
        close(fd);
    }
    errno = EAGAIN;
    return -1;
}

/* A regular file (or none yet) at `target`: a temporary beside it. */
static isk_status open_temp(isk_outfile *o, const char *target, const char *shown, const struct stat *existing,
                            isk_error *err)
{
    size_t n = strlen(target);
    o->temp = malloc(n + sizeof ISK_OUTFILE_TEMP_MARK + 6);
    if (!o->temp)
        return fail(o, err, ISK_ERR_NOMEM, shown, "out of memory");
    memcpy(o->temp, target, n);
    memcpy(o->temp + n, ISK_OUTFILE_TEMP_MARK "XXXXXX", sizeof ISK_OUTFILE_TEMP_MARK + 6);
    int fd = make_locked_temp(o->temp);
    if (fd < 0) {
        char why[300];
        snprintf(why, sizeof why, "cannot create temporary file: %s", strerror(errno));
        return fail(o, err, ISK_ERR_IO, shown, why);
    }
    /* mkstemp makes it 0600, owned by us: give it the owner and the
     * permissions of the file it replaces (owner first: a change of owner
     * clears the set-id bits), or the usual 0644 for a new one.  Neither
     * is fatal: the file is still ours and readable by us (only root may
     * give a file away). */
    if (existing && fchown(fd, existing->st_uid, existing->st_gid) != 0) {
        /* keep our own */
    }
    if (fchmod(fd, existing ? (existing->st_mode & 07777) : 0644) != 0) {
        /* keep 0600 */
    }
    o->f = fdopen(fd, "wb");
    if (!o->f) {
        int e = errno;
        close(fd);
        unlink(o->temp);
        return fail(o, err, ISK_ERR_IO, shown, strerror(e));
    }
    return ISK_OK;
}

isk_status isk_outfile_open(isk_outfile *o, const char *path, isk_error *err)
{
    if (!o)
        return isk_error_set(err, ISK_ERR_NULL, "output: NULL outfile");
    memset(o, 0, sizeof *o);
    if (!path)
        return isk_error_set(err, ISK_ERR_NULL, "output: NULL path");
    if (!*path)
        return isk_error_set(err, ISK_ERR_IO, "output: empty file name");
    struct stat lst, st;
    if (lstat(path, &lst) != 0) {
        if (errno != ENOENT)
            return fail(o, err, ISK_ERR_IO, path, strerror(errno));
        o->path = dup_str(path);
        if (!o->path)
            return fail(o, err, ISK_ERR_NOMEM, path, "out of memory");
        return open_temp(o, path, path, NULL, err);
    }
    if (S_ISLNK(lst.st_mode)) {
        if (stat(path, &st) != 0)
            return fail(o, err, ISK_ERR_IO, path,
                        errno == ENOENT ? "a symbolic link to a missing file (refused: write to the target itself)"
                                        : strerror(errno));
    } else {
        st = lst;
    }
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
        o->path = dup_str(path);
        if (!o->path)
            return fail(o, err, ISK_ERR_NOMEM, path, "out of memory");
        return open_stream(o, path, err);
    }
    if (S_ISDIR(st.st_mode))
        return fail(o, err, ISK_ERR_IO, path, "is a directory");
    if (!S_ISREG(st.st_mode))
        return fail(o, err, ISK_ERR_IO, path, "not a regular file, character device or FIFO (refused)");
    if (S_ISLNK(lst.st_mode)) {
        /* Replace the file the link points to, beside it, so the rename
         * stays within one directory and the link keeps working. */
#ifdef __wasi__
        char *real = NULL;
        errno = ENOTSUP;
#else
        char *real = realpath(path, NULL);
#endif
        if (!real)
            return fail(o, err, ISK_ERR_IO, path, strerror(errno));
        o->path = real;
    } else {
        o->path = dup_str(path);
        if (!o->path)
            return fail(o, err, ISK_ERR_NOMEM, path, "out of memory");
    }
    return open_temp(o, o->path, path, &st, err);
}

isk_status isk_outfile_commit(isk_outfile *o, isk_error *err)
{
    if (!o)
        return isk_error_set(err, ISK_ERR_NULL, "output: NULL outfile");
    if (!o->f)
        return isk_error_set(err, ISK_ERR_IO, "output: not open");
    int ok = fflush(o->f) == 0;
    int e = ok ? 0 : errno;
    if (ok && !o->streaming && fsync(fileno(o->f)) != 0) {
        ok = 0;
        e = errno;
    }
    /* Renamed while still open: the lock on the temporary holds until it
     * has its final name (isk_outfile_remove_stale). */
    int renamed = 0, rename_errno = 0;
    if (ok && o->temp) {
        renamed = rename(o->temp, o->path) == 0;
        rename_errno = errno;
    }
    if (fclose(o->f) != 0 && ok && !renamed) {
        ok = 0;
        e = errno;
    }
    o->f = NULL;
    isk_status s = ISK_OK;
    if (!ok) {
        s = isk_error_set(err, ISK_ERR_IO, "%s: write failed: %s", o->path,
                          e == ENOSPC ? "no space left on device" : strerror(e ? e : EIO));
        if (o->temp)
            unlink(o->temp);
    } else if (o->temp && !renamed) {
        s = isk_error_set(err, ISK_ERR_IO, "%s: cannot rename the temporary file over it: %s", o->path,
                          strerror(rename_errno));
        unlink(o->temp);
    }
    free(o->temp);
    free(o->path);
    memset(o, 0, sizeof *o);
    return s;
}

void isk_outfile_abort(isk_outfile *o)
{
    if (!o)
        return;
    if (o->f)
        fclose(o->f);
    if (o->temp)
        unlink(o->temp);
    free(o->temp);
    free(o->path);
    memset(o, 0, sizeof *o);
}

int isk_outfile_remove_stale(const char *temp)
{
    if (!temp)
        return 0;
    const char *mark = strstr(temp, ISK_OUTFILE_TEMP_MARK);
    while (mark && strstr(mark + 1, ISK_OUTFILE_TEMP_MARK))
        mark = strstr(mark + 1, ISK_OUTFILE_TEMP_MARK);
    if (!mark || mark == temp || mark[-1] == '/' || strlen(mark) != sizeof ISK_OUTFILE_TEMP_MARK - 1 + 6 ||
        strchr(mark, '/'))
        return 0;
#ifdef __wasi__
    return 0; /* one program at a time: nothing can have been left by another */
#else
    int fd = open(temp, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY);
    if (fd < 0)
        return 0;
    struct stat st, named;
    int removed = 0;
    /* Held by nobody: its writer is gone.  The lock is kept until the
     * name is gone, so a writer that has just made it sees the loss. */
    if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && flock(fd, LOCK_EX | LOCK_NB) == 0 &&
        lstat(temp, &named) == 0 && named.st_dev == st.st_dev && named.st_ino == st.st_ino)
        removed = unlink(temp) == 0;
    close(fd);
    return removed;
#endif
}

static int is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

isk_status isk_make_dirs(const char *dir, isk_error *err)
{
    if (!dir)
        return isk_error_set(err, ISK_ERR_NULL, "mkdir: NULL path");
    size_t n = strlen(dir);
    if (n == 0)
        return ISK_OK;
    char *buf = dup_str(dir);
    if (!buf)
        return isk_error_set(err, ISK_ERR_NOMEM, "%s: out of memory", dir);
    isk_status s = ISK_OK;
    /* Each prefix ending before a '/' (and the whole path), shortest first;
     * an existing directory is fine whoever made it (another process may
     * be making the same tree). */
    for (size_t i = 1; i <= n && s == ISK_OK; i++) {
        if ((buf[i] != '/' && buf[i] != 0) || buf[i - 1] == '/')
            continue;
        char c = buf[i];
        buf[i] = 0;
        if (mkdir(buf, 0777) != 0 && (errno != EEXIST || !is_dir(buf)))
            s = isk_error_set(err, ISK_ERR_IO, "cannot create directory %s: %s", buf,
                              strerror(errno == EEXIST ? ENOTDIR : errno));
        buf[i] = c;
    }
    free(buf);
    return s;
}

isk_status isk_make_parent_dirs(const char *path, isk_error *err)
{
    if (!path)
        return isk_error_set(err, ISK_ERR_NULL, "mkdir: NULL path");
    const char *slash = strrchr(path, '/');
    if (!slash || slash == path)
        return ISK_OK; /* "name.png" or "/name.png" */
    size_t n = (size_t)(slash - path);
    char *dir = malloc(n + 1);
    if (!dir)
        return isk_error_set(err, ISK_ERR_NOMEM, "%s: out of memory", path);
    memcpy(dir, path, n);
    dir[n] = 0;
    isk_status s = isk_make_dirs(dir, err);
    free(dir);
    return s;
}
