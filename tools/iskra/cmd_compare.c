/* SPDX-License-Identifier: MIT */
/* iskra compare A.png B.png [--diff OUT.png] [--max-pixels N] [--json]
 *               [--max-channel-diff N] [--max-differing N] [--reason TEXT]
 * Comparison for people testing rendered buffers: the number of differing
 * pixels and by how much (the figures of iskra/refimg.h), as a sentence or
 * as JSON for CI scripts; exact by default, or within the tolerance that
 * isk_refimg_opts has (a tolerance needs a written reason).
 * Exit 0 the same (or within the tolerance), 1 different, 2 an image
 * unreadable, the diff image not written, or a usage error: as cmp(1). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cleanup.h"
#include "cmd.h"
#include "iskra/png.h"
#include "iskra/refimg.h"
#include "outpath.h"
#include "scene_args.h"

/* The exit statuses (help() and the tests say the same). */
enum { SAME = 0, DIFFERENT = 1, TROUBLE = 2 };

static void help(FILE *f)
{
    fprintf(f, "usage: iskra compare A.png B.png [--diff OUT.png] [--max-pixels N] [--json]\n"
               "                     [--max-channel-diff N] [--max-differing N] [--reason TEXT]\n"
               "  Compares two images pixel by pixel (all four channels).  The headers\n"
               "  are compared first: images of different sizes differ without decoding.\n"
               "  --diff OUT.png  write an image with differing pixels in magenta (missing\n"
               "                  directories are created; OUT must not be A or B)\n"
               "  --max-pixels N  decode at most N pixels per image (default %lld,\n"
               "                  8192x8192; up to %lld): a small file can declare a\n"
               "                  huge image\n"
               "  --max-channel-diff N  a pixel whose channels all differ by at most N (0..255)\n"
               "                  counts as the same (default 0: exact)\n"
               "  --max-differing N  the images count as the same when at most N pixels are\n"
               "                  beyond --max-channel-diff (default 0)\n"
               "  --reason TEXT   why exactness cannot hold here; required with a tolerance\n"
               "                  (the rule of isk_refimg_opts, iskra/refimg.h)\n"
               "  --json          print the figures as one JSON object on stdout:\n"
               "                  a, b, a_width, a_height, b_width, b_height, same_size,\n"
               "                  pixels, differing, max_channel, mean_abs, identical,\n"
               "                  beyond_tolerance, within_tolerance, tolerance, diff\n"
               "                  (or a, b, error when an image cannot be read)\n"
               "  exit status: 0 the same (or within the tolerance), 1 different,\n"
               "               2 an image unreadable or too large, the diff image not\n"
               "               written, or a usage error\n",
            (long long)ISK_PNG_MAX_PIXELS_DEFAULT, (long long)ISK_CANVAS_MAX_DIM * ISK_CANVAS_MAX_DIM);
}

/* How far the images may differ and still count as the same. */
typedef struct tolerance {
    int max_channel_diff; /* 0..255 */
    long max_differing;   /* pixels beyond max_channel_diff */
    const char *reason;   /* NULL unless given */
} tolerance;

typedef struct report {
    const char *a, *b, *diff_path; /* diff_path: NULL unless written */
    isk_png_info ia, ib;
    int same_size;
    isk_canvas_diff d;             /* zero when the sizes differ */
    long beyond;                   /* pixels beyond the tolerance's channel difference */
    tolerance tol;
    char error[600];               /* set: the comparison could not be made */
} report;

static int tolerance_set(const tolerance *t) { return t->max_channel_diff || t->max_differing; }

/* Same size, and at most max_differing pixels beyond the channel tolerance
 * (with no tolerance: identical). */
static int within(const report *r) { return r->same_size && r->beyond <= r->tol.max_differing; }

static void json_string(const char *s)
{
    putchar('"');
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '"' || *p == '\\')
            printf("\\%c", *p);
        else if (*p < 0x20)
            printf("\\u%04x", *p);
        else
            putchar(*p);
    }
    putchar('"');
}

static void print_json(const report *r)
{
    printf("{\"a\": ");
    json_string(r->a);
    printf(", \"b\": ");
    json_string(r->b);
    if (r->error[0]) {
        printf(", \"error\": ");
        json_string(r->error);
        printf("}\n");
        return;
    }
    printf(", \"a_width\": %d, \"a_height\": %d, \"b_width\": %d, \"b_height\": %d, \"same_size\": %s,"
           " \"pixels\": %ld, \"differing\": %ld, \"max_channel\": %d, \"mean_abs\": %.6f, \"identical\": %s,"
           " \"beyond_tolerance\": ",
           r->ia.width, r->ia.height, r->ib.width, r->ib.height, r->same_size ? "true" : "false", r->d.pixels,
           r->d.differing, r->d.max_channel, r->d.mean_abs, r->same_size && !r->d.differing ? "true" : "false");
    if (r->same_size)
        printf("%ld", r->beyond);
    else
        printf("null");
    printf(", \"within_tolerance\": %s, \"tolerance\": ", within(r) ? "true" : "false");
    if (tolerance_set(&r->tol)) {
        printf("{\"max_channel_diff\": %d, \"max_differing\": %ld, \"reason\": ", r->tol.max_channel_diff,
               r->tol.max_differing);
        json_string(r->tol.reason);
        printf("}");
    } else {
        printf("null");
    }
    printf(", \"diff\": ");
    if (r->diff_path)
        json_string(r->diff_path);
    else
        printf("null");
    printf("}\n");
}

static void print_text(const report *r)
{
    if (r->error[0])
        return; /* already on stderr */
    if (!r->same_size) {
        printf("size differs: %dx%d vs %dx%d\n", r->ia.width, r->ia.height, r->ib.width, r->ib.height);
        return;
    }
    char line[300];
    printf("%s", isk_refimg_summary(&r->d, line, sizeof line));
    if (tolerance_set(&r->tol))
        printf("; %s the tolerance (%ld pixel%s beyond %d per channel, %ld allowed: %s)",
               within(r) ? "within" : "beyond", r->beyond, r->beyond == 1 ? "" : "s", r->tol.max_channel_diff,
               r->tol.max_differing, r->tol.reason);
    printf("\n");
}

/* The comparison itself; fills r (r->error on failure, also printed). */
static void run(report *r, long long max_pixels)
{
    isk_error err;
    for (int k = 0; k < 2; k++)
        if (isk_png_read_info(k ? r->b : r->a, k ? &r->ib : &r->ia, &err) != ISK_OK) {
            snprintf(r->error, sizeof r->error, "%s", err.message);
            return;
        }
    /* The headers first: images of different sizes are different without
     * decoding a pixel (a tiny file may declare a huge image). */
    r->same_size = r->ia.width == r->ib.width && r->ia.height == r->ib.height;
    if (!r->same_size && !r->diff_path)
        return;
    int w = r->ia.width > r->ib.width ? r->ia.width : r->ib.width;
    int h = r->ia.height > r->ib.height ? r->ia.height : r->ib.height;
    if (r->diff_path && (long long)w * h > max_pixels) {
        snprintf(r->error, sizeof r->error,
                 "the diff image would be %dx%d = %lld pixels, more than the limit of %lld (see --max-pixels)", w, h,
                 (long long)w * h, max_pixels);
        return;
    }
    isk_canvas a = {0}, b = {0}, img = {0};
    isk_status s;
    if ((s = isk_png_read_max(&a, r->a, max_pixels, &err)) != ISK_OK ||
        (s = isk_png_read_max(&b, r->b, max_pixels, &err)) != ISK_OK) {
        snprintf(r->error, sizeof r->error, "%s%s", err.message, s == ISK_ERR_SIZE ? " (see --max-pixels)" : "");
    } else if (r->diff_path && isk_canvas_init(&img, w, h) != ISK_OK) {
        snprintf(r->error, sizeof r->error, "out of memory for the diff image");
    } else {
        r->same_size = isk_canvas_compare(&a, &b, &r->d, r->diff_path ? &img : NULL);
        if (r->same_size)
            r->beyond = isk_canvas_count_beyond(&a, &b, r->tol.max_channel_diff); /* refimg's rule */
        if (r->diff_path) {
            if (outpath_make_parents("compare", r->diff_path))
                snprintf(r->error, sizeof r->error, "cannot write %s", r->diff_path);
            else if (cleanup_png_write(&img, r->diff_path))
                snprintf(r->error, sizeof r->error, "cannot write %s", r->diff_path);
        }
    }
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_canvas_free(&img);
}

int cmd_compare(int argc, char **argv)
{
    report r;
    memset(&r, 0, sizeof r);
    const char *files[2] = {0, 0};
    long long max_pixels = ISK_PNG_MAX_PIXELS_DEFAULT;
    int nfiles = 0, json = 0;
    for (int i = 1; i < argc; i++) {
        const char *v;
        int k;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help(stdout);
            return 0;
        } else if (!strcmp(argv[i], "--json")) {
            json = 1;
        } else if ((k = arg_value("compare", argc, argv, &i, "--diff", &v)) != 0) {
            if (k < 0)
                return TROUBLE;
            r.diff_path = v;
        } else if ((k = arg_value("compare", argc, argv, &i, "--max-pixels", &v)) != 0) {
            long n;
            if (k < 0 || !arg_long("compare", "--max-pixels", v, 1, (long)ISK_CANVAS_MAX_DIM * ISK_CANVAS_MAX_DIM, &n))
                return TROUBLE;
            max_pixels = n;
        } else if ((k = arg_value("compare", argc, argv, &i, "--max-channel-diff", &v)) != 0) {
            long n;
            if (k < 0 || !arg_long("compare", "--max-channel-diff", v, 0, 255, &n))
                return TROUBLE;
            r.tol.max_channel_diff = (int)n;
        } else if ((k = arg_value("compare", argc, argv, &i, "--max-differing", &v)) != 0) {
            long n;
            if (k < 0 || !arg_long("compare", "--max-differing", v, 0, (long)ISK_CANVAS_MAX_DIM * ISK_CANVAS_MAX_DIM,
                                   &n))
                return TROUBLE;
            r.tol.max_differing = n;
        } else if ((k = arg_value("compare", argc, argv, &i, "--reason", &v)) != 0) {
            if (k < 0)
                return TROUBLE;
            r.tol.reason = v;
        } else if (argv[i][0] == '-' && argv[i][1]) {
            fprintf(stderr, "iskra compare: unknown option '%s'\n", argv[i]);
            help(stderr);
            return TROUBLE;
        } else if (nfiles < 2) {
            files[nfiles++] = argv[i];
        } else {
            fprintf(stderr, "iskra compare: too many files\n");
            return TROUBLE;
        }
    }
    if (nfiles != 2) {
        help(stderr);
        return TROUBLE;
    }
    if (tolerance_set(&r.tol) && (!r.tol.reason || !*r.tol.reason)) {
        fprintf(stderr, "iskra compare: a tolerance (--max-channel-diff, --max-differing) needs --reason: why "
                        "exactness cannot hold here\n");
        return TROUBLE;
    }
    if (r.diff_path && !*r.diff_path) {
        fprintf(stderr, "iskra compare: --diff needs a file name\n");
        return TROUBLE;
    }
    if (outpath_refuse_input("compare", r.diff_path, files[0]) ||
        outpath_refuse_input("compare", r.diff_path, files[1]))
        return TROUBLE;
    r.a = files[0];
    r.b = files[1];
    cleanup_install("compare");
    run(&r, max_pixels);
    if (r.error[0]) {
        fprintf(stderr, "iskra compare: %s\n", r.error);
        r.diff_path = NULL; /* not written, or not whole */
    }
    if (json)
        print_json(&r);
    else
        print_text(&r);
    return r.error[0] ? TROUBLE : within(&r) ? SAME : DIFFERENT;
}
