/* iskra compare A.png B.png [--diff OUT.png]
 * Pixel-exact comparison for people testing rendered buffers: prints the
 * number of differing pixels and the largest channel difference.
 * Exit 0 identical, 1 different (or unreadable), 2 usage error. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd.h"
#include "iskra/png.h"
#include "outpath.h"

static void help(FILE *f)
{
    fprintf(f, "usage: iskra compare A.png B.png [--diff OUT.png]\n"
               "  Compares two images pixel by pixel (all four channels).\n"
               "  --diff OUT.png  write an image with differing pixels in magenta (missing\n"
               "                  directories are created; OUT must not be A or B)\n"
               "  exit status: 0 identical, 1 different or unreadable, 2 usage error\n");
}

int cmd_compare(int argc, char **argv)
{
    const char *files[2] = {0, 0}, *diff = NULL;
    int nfiles = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help(stdout);
            return 0;
        } else if (!strcmp(argv[i], "--diff")) {
            if (i + 1 >= argc) {
                fprintf(stderr, "iskra compare: --diff needs a file name\n");
                return 2;
            }
            diff = argv[++i];
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
    if (diff && !*diff) {
        fprintf(stderr, "iskra compare: --diff needs a file name\n");
        return 2;
    }
    if (outpath_refuse_input("compare", diff, files[0]) || outpath_refuse_input("compare", diff, files[1]))
        return 2;
    isk_canvas a, b;
    isk_error err;
    if (isk_png_read(&a, files[0], &err) != ISK_OK) {
        fprintf(stderr, "iskra compare: %s\n", err.message);
        return 1;
    }
    if (isk_png_read(&b, files[1], &err) != ISK_OK) {
        fprintf(stderr, "iskra compare: %s\n", err.message);
        isk_canvas_free(&a);
        return 1;
    }
    int rc = 0;
    isk_canvas_diff d;
    isk_canvas img = {0};
    if (diff) {
        int w = a.width > b.width ? a.width : b.width, h = a.height > b.height ? a.height : b.height;
        if (isk_canvas_init(&img, w, h) != ISK_OK) {
            fprintf(stderr, "iskra compare: out of memory for the diff image\n");
            diff = NULL;
            rc = 1;
        }
    }
    if (!isk_canvas_compare(&a, &b, &d, diff ? &img : NULL)) {
        printf("size differs: %dx%d vs %dx%d\n", a.width, a.height, b.width, b.height);
        rc = 1;
    } else {
        printf("%ld of %ld pixels differ, max channel difference %d, mean absolute difference %.4f\n",
               d.differing, d.pixels, d.max_channel, d.mean_abs);
        if (d.differing)
            rc = 1;
    }
    if (diff) {
        isk_error err;
        if (outpath_make_parents("compare", diff)) {
            rc = 1;
        } else if (isk_png_write(&img, diff, &err) != ISK_OK) {
            fprintf(stderr, "iskra compare: %s\n", err.message);
            rc = 1;
        }
        isk_canvas_free(&img);
    }
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    return rc;
}
