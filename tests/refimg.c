/* SPDX-License-Identifier: MIT */
/* The suite's reference-image checks: a thin wrapper over iskra/refimg.h
 * with the project's layout (see tests/refimg.h). */
#include "refimg.h"

#include <stdio.h>
#include <stdlib.h>

#include "iskra/refimg.h"

#define REF_DIR "refimg"
#define OUT_DIR "out/refimg"

const char *refimg_build_dir(void)
{
    const char *b = getenv("ISKRA_BUILD");
    return (b && *b) ? b : "build";
}

static int check(const char *name, const isk_canvas *c, int tol, long max_pixels, const char *reason)
{
    char ref[512];
    snprintf(ref, sizeof ref, REF_DIR "/%s.png", name);
    isk_refimg_result res;
    isk_refimg_opts o = {0};
    o.out_dir = OUT_DIR;
    o.max_channel_diff = tol;
    o.max_differing = max_pixels;
    o.reason = reason;
    o.result = &res;
    isk_error err;
    if (isk_refimg_check(c, ref, &o, &err) == ISK_OK) {
        if (res.updated)
            fprintf(stderr, "refimg %s: reference written to %s\n", name, ref);
        return 1;
    }
    fprintf(stderr, "%s\n  HINT: if this output is right, update the reference with: tools/refimg update %s\n",
            err.message, name);
    return 0;
}

int refimg_check(const char *name, const isk_canvas *c)
{
    return check(name, c, 0, 0, NULL);
}

int refimg_check_tol(const char *name, const isk_canvas *c, int max_channel_diff, long max_pixels,
                     const char *reason)
{
    return check(name, c, max_channel_diff, max_pixels, reason);
}
