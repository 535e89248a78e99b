/* SPDX-License-Identifier: MIT */
/* Output directories and input/output clashes (see outpath.h). */
#include "outpath.h"

#include <stdio.h>
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
