/* Output directories and input/output clashes (see outpath.h). */
#include "outpath.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

int outpath_make_dirs(const char *cmd, const char *dir)
{
    size_t n = dir ? strlen(dir) : 0;
    if (n == 0)
        return 0;
    char *buf = malloc(n + 1);
    if (!buf) {
        fprintf(stderr, "iskra %s: out of memory\n", cmd);
        return 1;
    }
    memcpy(buf, dir, n + 1);
    int failed = 0;
    /* Each prefix ending before a '/' (and the whole path), shortest first;
     * an existing one is fine whoever made it (another process may race us). */
    for (size_t i = 1; i <= n && !failed; i++) {
        if (buf[i] != '/' && buf[i] != 0)
            continue;
        if (buf[i - 1] == '/')
            continue; /* "a//b" */
        char c = buf[i];
        buf[i] = 0;
        if (mkdir(buf, 0777) != 0 && (errno != EEXIST || !is_dir(buf))) {
            int e = errno == EEXIST ? ENOTDIR : errno;
            fprintf(stderr, "iskra %s: cannot create directory %s: %s\n", cmd, buf, strerror(e));
            failed = 1;
        }
        buf[i] = c;
    }
    free(buf);
    return failed;
}

int outpath_make_parents(const char *cmd, const char *path)
{
    const char *slash = path ? strrchr(path, '/') : NULL;
    if (!slash || slash == path)
        return 0; /* "name.png" or "/name.png" */
    size_t n = (size_t)(slash - path);
    char *dir = malloc(n + 1);
    if (!dir) {
        fprintf(stderr, "iskra %s: out of memory\n", cmd);
        return 1;
    }
    memcpy(dir, path, n);
    dir[n] = 0;
    int rc = outpath_make_dirs(cmd, dir);
    free(dir);
    return rc;
}

int outpath_same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    if (!a || !b || stat(a, &sa) != 0 || stat(b, &sb) != 0)
        return 0;
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

int outpath_refuse_input(const char *cmd, const char *out, const char *in)
{
    if (!outpath_same_file(out, in))
        return 0;
    fprintf(stderr, "iskra %s: refusing to overwrite the input %s with the output %s\n", cmd, in, out);
    return 1;
}
