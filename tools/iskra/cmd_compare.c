/* SPDX-License-Identifier: MIT */
/* iskra compare A.png B.png [--diff OUT.png] [--max-pixels N] [--json]
 * Pixel-exact comparison for people testing rendered buffers: the number of
 * differing pixels and by how much (the figures of iskra/refimg.h), as a
 * sentence or as JSON for CI scripts.
 * Exit 0 identical, 1 different (or unreadable), 2 usage error. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cleanup.h"
#include "cmd.h"
#include "iskra/png.h"
#include "iskra/refimg.h"
#include "outpath.h"
#include "scene_args.h"

static void help(FILE *f)
{
    fprintf(f, "usage: iskra compare A.png B.png [--diff OUT.png] [--max-pixels N] [--json]\n"
               "  Compares two images pixel by pixel (all four channels).  The headers\n"
               "  are compared first: images of different sizes differ without decoding.\n"
               "  --diff OUT.png  write an image with differing pixels in magenta (missing\n"
               "                  directories are created; OUT must not be A or B)\n"
               "  --max-pixels N  decode at most N pixels per image (default %lld,\n"
               "                  8192x8192; up to %lld): a small file can declare a\n"
               "                  huge image\n"
               "  --json          print the figures as one JSON object on stdout:\n"
               "                  a, b, a_width, a_height, b_width, b_height, same_size,\n"
               "                  pixels, differing, max_channel, mean_abs, identical, diff\n"
               "                  (or a, b, error when an image cannot be read)\n"
               "  exit status: 0 identical, 1 different or unreadable, 2 usage error\n",
            (long long)ISK_PNG_MAX_PIXELS_DEFAULT, (long long)ISK_CANVAS_MAX_DIM * ISK_CANVAS_MAX_DIM);
}

typedef struct report {
    const char *a, *b, *diff_path; /* diff_path: NULL unless written */
    isk_png_info ia, ib;
    int same_size;
    isk_canvas_diff d;             /* zero when the sizes differ */
    char error[600];               /* set: the comparison could not be made */
} report;

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
           " \"diff\": ",
           r->ia.width, r->ia.height, r->ib.width, r->ib.height, r->same_size ? "true" : "false", r->d.pixels,
           r->d.differing, r->d.max_channel, r->d.mean_abs, r->same_size && !r->d.differing ? "true" : "false");
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
    printf("%s\n", isk_refimg_summary(&r->d, line, sizeof line));
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
                return 2;
            r.diff_path = v;
        } else if ((k = arg_value("compare", argc, argv, &i, "--max-pixels", &v)) != 0) {
            long n;
            if (k < 0 || !arg_long("compare", "--max-pixels", v, 1, (long)ISK_CANVAS_MAX_DIM * ISK_CANVAS_MAX_DIM, &n))
                return 2;
            max_pixels = n;
        } else if (argv[i][0] == '-' && argv[i][1]) {
            fprintf(stderr, "iskra compare: unknown option '%s'\n", argv[i]);
            help(stderr);
            return 2;
        } else if (nfiles < 2) {
            files[nfiles++] = argv[i];
        } else {
            fprintf(stderr, "iskra compare: too many files\n");
            return 2;
        }
    }
    if (nfiles != 2) {
        help(stderr);
        return 2;
    }
    if (r.diff_path && !*r.diff_path) {
        fprintf(stderr, "iskra compare: --diff needs a file name\n");
        return 2;
    }
    if (outpath_refuse_input("compare", r.diff_path, files[0]) ||
        outpath_refuse_input("compare", r.diff_path, files[1]))
        return 2;
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
    return r.error[0] || !r.same_size || r.d.differing ? 1 : 0;
}
