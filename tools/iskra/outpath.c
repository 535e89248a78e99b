/* SPDX-License-Identifier: MIT */
/* Output directories, and outputs against inputs and each other (see
 * outpath.h). */
#define _DEFAULT_SOURCE /* realpath, strndup */
#include "outpath.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "iskra/outfile.h"

int outpath_make_dirs(const char *cmd, const char *dir)
{
    isk_error err;
    if (isk_make_dirs(dir ? dir : "", &err) == ISK_OK)
        return 0;
    fprintf(stderr, "iskra %s: %s\n", cmd, err.message);
    return 1;
}

int outpath_make_parents(const char *cmd, const char *path)
{
    isk_error err;
    if (isk_make_parent_dirs(path ? path : "", &err) == ISK_OK)
        return 0;
    fprintf(stderr, "iskra %s: %s\n", cmd, err.message);
    return 1;
}

/* wasi-libc (the browser's build) has no realpath: there a path that
 * exists is its name as given (the page's one directory has no links). */
#ifdef __wasi__
static char *real_path(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? strdup(path) : NULL;
}
#else
static char *real_path(const char *path) { return realpath(path, NULL); }
#endif

/* The absolute name a file not there yet will have: its directory
 * resolved (symlinks, "..") as far as it exists, the rest joined by name
 * (a directory not there yet is no symlink, so "a/../b" is "b").  NULL
 * when even the working directory cannot be resolved (or no memory). */
static char *resolved(const char *path)
{
    char *real = real_path(path);
    if (real || !strcmp(path, "."))
        return real;
    size_t n = strlen(path);
    while (n > 1 && path[n - 1] == '/')
        n--;
    size_t base = n;
    while (base > 0 && path[base - 1] != '/')
        base--;
    size_t dn = base;
    while (dn > 1 && path[dn - 1] == '/')
        dn--;
    char *dir = base == 0 ? strdup(".") : strndup(path, dn);
    char *parent = dir ? resolved(dir) : NULL;
    free(dir);
    if (!parent)
        return NULL;
    const char *name = path + base;
    const size_t nn = n - base;
    if (nn == 0 || (nn == 1 && name[0] == '.'))
        return parent;
    if (nn == 2 && name[0] == '.' && name[1] == '.') {
        char *up = strrchr(parent, '/');
        if (up)
            up[up == parent] = 0; /* "/a/b" -> "/a", "/a" -> "/" */
        return parent;
    }
    size_t pn = strlen(parent);
    char *joined = malloc(pn + 1 + nn + 1);
    if (joined)
        snprintf(joined, pn + 1 + nn + 1, "%s%s%.*s", parent, parent[pn - 1] == '/' ? "" : "/", (int)nn, name);
    free(parent);
    return joined;
}

int outpath_same_file(const char *a, const char *b)
{
    if (!a || !b || !strcmp(a, "-") || !strcmp(b, "-"))
        return 0;
    struct stat sa, sb;
    const int ea = stat(a, &sa) == 0, eb = stat(b, &sb) == 0;
    if (ea != eb)
        return 0;
    if (ea)
        return !S_ISCHR(sa.st_mode) && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    char *ra = resolved(a), *rb = resolved(b);
    const int same = ra && rb ? !strcmp(ra, rb) : !strcmp(a, b);
    free(ra);
    free(rb);
    return same;
}

void outpath_output(outpath_plan *p, const char *path, const char *what)
{
    if (path && strcmp(path, "-") != 0 && p->nout < OUTPATH_MAX_OUTPUTS) {
        p->out[p->nout] = path;
        p->out_what[p->nout++] = what;
    }
}

void outpath_series(outpath_plan *p, const char *dir, const char *prefix, const char *suffix, long every, long last,
                    const char *what)
{
    if (dir && every > 0 && p->nseries < OUTPATH_MAX_SERIES)
        p->series[p->nseries++] = (outpath_series_def){dir, prefix, suffix, what, every, last};
}

/* The number f when `path` is DIR/PREFIX%06ldSUFFIX of the series, one f
 * it writes; else -1. */
static long member(const outpath_series_def *s, const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const size_t np = strlen(s->prefix), ns = strlen(s->suffix), nb = strlen(base);
    if (nb <= np + ns || nb - np - ns > 18 || strncmp(base, s->prefix, np) != 0 || strcmp(base + nb - ns, s->suffix))
        return -1;
    long f = 0;
    for (size_t i = np; i < nb - ns; i++) {
        if (base[i] < '0' || base[i] > '9')
            return -1;
        f = f * 10 + (base[i] - '0');
    }
    char same_name[64];
    snprintf(same_name, sizeof same_name, "%06ld", f);
    if (strlen(same_name) != nb - np - ns || f % s->every != 0 || f > s->last)
        return -1; /* "frame_7.png" is not one of ours, nor a frame past the last */
    char *dir = slash ? strndup(path, slash == path ? 1 : (size_t)(slash - path)) : strdup(".");
    const int same_dir = dir && outpath_same_file(dir, s->dir);
    free(dir);
    return same_dir ? f : -1;
}

int outpath_clash(const outpath_plan *p)
{
    for (int i = 0; i < p->nout; i++) {
        for (int j = i + 1; j < p->nout; j++)
            if (outpath_same_file(p->out[i], p->out[j])) {
                fprintf(stderr, "iskra %s: %s %s and %s %s are the same file: one output would replace the other\n",
                        p->cmd, p->out_what[i], p->out[i], p->out_what[j], p->out[j]);
                return 1;
            }
        for (int k = 0; k < p->nseries; k++) {
            const long f = member(&p->series[k], p->out[i]);
            if (f >= 0) {
                fprintf(stderr, "iskra %s: %s %s is number %ld of %s %s: one output would replace the other\n",
                        p->cmd, p->out_what[i], p->out[i], f, p->series[k].what, p->series[k].dir);
                return 1;
            }
        }
    }
    return 0;
}

int outpath_refuse(const outpath_plan *p, const char *in, const char *what)
{
    struct stat st;
    if (!in || stat(in, &st) != 0)
        return 0; /* not a file: nothing to overwrite */
    for (int i = 0; i < p->nout; i++)
        if (outpath_same_file(p->out[i], in)) {
            fprintf(stderr, "iskra %s: refusing to overwrite the input %s (%s) with the output %s (%s)\n", p->cmd, in,
                    what, p->out[i], p->out_what[i]);
            return 1;
        }
    for (int k = 0; k < p->nseries; k++) {
        const long f = member(&p->series[k], in);
        if (f >= 0) {
            fprintf(stderr, "iskra %s: refusing to overwrite the input %s (%s) with number %ld of %s %s\n", p->cmd,
                    in, what, f, p->series[k].what, p->series[k].dir);
            return 1;
        }
    }
    return 0;
}

int outpath_refuse_input(const char *cmd, const char *out, const char *in)
{
    if (!outpath_same_file(out, in))
        return 0;
    fprintf(stderr, "iskra %s: refusing to overwrite the input %s with the output %s\n", cmd, in, out);
    return 1;
}

/* Removes the stale temporaries in dir named START DIGITS END.tmp.XXXXXX
 * (no digits for a single output: START is its name, END empty);
 * iskra/outfile.h decides which are stale.  How many were removed. */
static long remove_stale_in(const char *dir, const char *start, const char *end)
{
    DIR *d = opendir(dir);
    if (!d)
        return 0;
    long removed = 0;
    const size_t ns = strlen(start), ne = strlen(end);
    const struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        const char *mark = strstr(e->d_name, ISK_OUTFILE_TEMP_MARK);
        if (!mark || strncmp(e->d_name, start, ns) != 0 || (size_t)(mark - e->d_name) < ns + ne ||
            strncmp(mark - ne, end, ne) != 0 || strspn(e->d_name + ns, "0123456789") < (size_t)(mark - ne - e->d_name) - ns)
            continue;
        size_t n = strlen(dir) + 1 + strlen(e->d_name) + 1;
        char *path = malloc(n);
        if (path) {
            snprintf(path, n, "%s/%s", dir, e->d_name);
            removed += isk_outfile_remove_stale(path);
            free(path);
        }
    }
    closedir(d);
    return removed;
}

void outpath_remove_stale(const outpath_plan *p)
{
    long removed = 0;
    for (int i = 0; i < p->nout; i++) {
        const char *slash = strrchr(p->out[i], '/');
        char *dir = slash ? strndup(p->out[i], slash == p->out[i] ? 1 : (size_t)(slash - p->out[i])) : strdup(".");
        if (dir)
            removed += remove_stale_in(dir, slash ? slash + 1 : p->out[i], "");
        free(dir);
    }
    for (int k = 0; k < p->nseries; k++)
        removed += remove_stale_in(p->series[k].dir, p->series[k].prefix, p->series[k].suffix);
    if (removed > 0)
        fprintf(stderr, "iskra %s: removed %ld temporary file%s that an interrupted run left\n", p->cmd, removed,
                removed == 1 ? "" : "s");
}
