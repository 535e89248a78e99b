/* Reference-image comparison for the tests (see tests/refimg.h). */
#include "refimg.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "iskra/png.h"

#define REF_DIR "refimg"
#define OUT_DIR "out/refimg"

const char *refimg_build_dir(void)
{
    const char *b = getenv("ISKRA_BUILD");
    return (b && *b) ? b : "build";
}

static int mkdirs(const char *path)
{
    char buf[512];
    size_t n = strlen(path);
    if (n >= sizeof buf)
        return -1;
    memcpy(buf, path, n + 1);
    for (char *p = buf + 1; *p; p++) {
        if (*p == '/') {
            *p = 0;
            if (mkdir(buf, 0777) != 0 && errno != EEXIST)
                return -1;
            *p = '/';
        }
    }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST)
        return -1;
    return 0;
}

static int update_mode(void)
{
    const char *u = getenv("ISKRA_REFIMG_UPDATE");
    return u && *u && strcmp(u, "0") != 0;
}

/* Diff image (iskra/canvas.h's isk_canvas_compare), sized to the larger of
 * the two so size mismatches are visible too. */
static void write_diff(const char *name, const isk_canvas *actual, const isk_canvas *ref)
{
    int w = actual->width > ref->width ? actual->width : ref->width;
    int h = actual->height > ref->height ? actual->height : ref->height;
    isk_canvas d;
    if (isk_canvas_init(&d, w, h) != ISK_OK)
        return;
    isk_canvas_compare(actual, ref, NULL, &d);
    char path[512];
    snprintf(path, sizeof path, OUT_DIR "/%s.diff.png", name);
    isk_png_write(&d, path, NULL);
    isk_canvas_free(&d);
}

static int check(const char *name, const isk_canvas *c, int tol, long max_pixels, const char *reason)
{
    char ref_path[512], act_path[512];
    snprintf(ref_path, sizeof ref_path, REF_DIR "/%s.png", name);
    snprintf(act_path, sizeof act_path, OUT_DIR "/%s.actual.png", name);
    isk_error err;

    if (update_mode()) {
        mkdirs(REF_DIR);
        if (isk_png_write(c, ref_path, &err) != ISK_OK) {
            fprintf(stderr, "refimg %s: cannot write reference: %s\n", name, err.message);
            return 0;
        }
        fprintf(stderr, "refimg %s: reference written to %s\n", name, ref_path);
        return 1;
    }

    isk_canvas ref;
    if (isk_png_read(&ref, ref_path, &err) != ISK_OK) {
        mkdirs(OUT_DIR);
        isk_png_write(c, act_path, NULL);
        fprintf(stderr,
                "refimg %s: no reference image (%s)\n"
                "  actual output: %s\n"
                "  HINT: if this output is right, create the reference with: tools/refimg update %s\n",
                name, err.message, act_path, name);
        return 0;
    }
    isk_canvas_diff diff;
    int same_size = isk_canvas_compare(c, &ref, &diff, NULL);
    long npix = diff.differing;
    int maxd = diff.max_channel;
    int pass = same_size && (npix == 0 || (maxd <= tol && npix <= max_pixels));
    if (!pass) {
        mkdirs(OUT_DIR);
        isk_png_write(c, act_path, NULL);
        write_diff(name, c, &ref);
        if (!same_size)
            fprintf(stderr, "refimg %s: size %dx%d, reference %dx%d\n", name, c->width, c->height,
                    ref.width, ref.height);
        else
            fprintf(stderr, "refimg %s: %ld pixels differ, max channel difference %d%s%s\n", name, npix,
                    maxd, reason ? "; tolerance reason: " : "", reason ? reason : "");
        fprintf(stderr,
                "  actual: %s\n  diff:   " OUT_DIR "/%s.diff.png\n"
                "  HINT: if this change is intentional, update the reference with: tools/refimg update %s\n",
                act_path, name, name);
    }
    isk_canvas_free(&ref);
    return pass;
}

int refimg_check(const char *name, const isk_canvas *c)
{
    return check(name, c, 0, 0, NULL);
}

int refimg_check_tol(const char *name, const isk_canvas *c, int max_channel_diff, long max_pixels,
                     const char *reason)
{
    if (!reason || !*reason) {
        fprintf(stderr, "refimg %s: a tolerance needs a written reason\n", name);
        return 0;
    }
    return check(name, c, max_channel_diff, max_pixels, reason);
}
