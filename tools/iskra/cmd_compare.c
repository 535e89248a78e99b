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
#include "scene_args.h"

static void help(FILE *f)
{
    fprintf(f, "usage: iskra compare A.png B.png [--diff OUT.png] [--max-pixels N]\n"
               "  Compares two images pixel by pixel (all four channels).  The headers\n"
               "  are compared first: images of different sizes differ without decoding.\n"
               "  --diff OUT.png  write an image with differing pixels in magenta (missing\n"
               "                  directories are created; OUT must not be A or B)\n"
               "  --max-pixels N  decode at most N pixels per image (default %lld, 8192x8192;\n"
               "                  up to %lld): a small file can declare a huge image\n"
               "  exit status: 0 identical, 1 different or unreadable, 2 usage error\n",
            (long long)ISK_PNG_MAX_PIXELS_DEFAULT, (long long)ISK_CANVAS_MAX_DIM * ISK_CANVAS_MAX_DIM);
}

/* Reads one image within the limit; 0 or 1 after printing why. */
static int load(isk_canvas *c, const char *path, long long max_pixels)
{
    isk_error err;
    isk_status s = isk_png_read_max(c, path, max_pixels, &err);
    if (s == ISK_OK)
        return 0;
    fprintf(stderr, "iskra compare: %s%s\n", err.message, s == ISK_ERR_SIZE ? " (see --max-pixels)" : "");
    return 1;
}

int cmd_compare(int argc, char **argv)
{
    const char *files[2] = {0, 0}, *diff = NULL;
    long long max_pixels = ISK_PNG_MAX_PIXELS_DEFAULT;
    int nfiles = 0;
    for (int i = 1; i < argc; i++) {
        const char *v;
        int r;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help(stdout);
            return 0;
        } else if ((r = arg_value("compare", argc, argv, &i, "--diff", &v)) != 0) {
            if (r < 0)
                return 2;
            diff = v;
        } else if ((r = arg_value("compare", argc, argv, &i, "--max-pixels", &v)) != 0) {
            long n;
            if (r < 0 || !arg_long("compare", "--max-pixels", v, 1, (long)ISK_CANVAS_MAX_DIM * ISK_CANVAS_MAX_DIM, &n))
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
    if (diff && !*diff) {
        fprintf(stderr, "iskra compare: --diff needs a file name\n");
        return 2;
    }
    if (outpath_refuse_input("compare", diff, files[0]) || outpath_refuse_input("compare", diff, files[1]))
        return 2;
    /* The headers first: images of different sizes are different without
     * decoding a pixel (a tiny file may declare a huge image). */
    isk_png_info ia, ib;
    isk_error err;
    for (int k = 0; k < 2; k++)
        if (isk_png_read_info(files[k], k ? &ib : &ia, &err) != ISK_OK) {
            fprintf(stderr, "iskra compare: %s\n", err.message);
            return 1;
        }
    int same_size = ia.width == ib.width && ia.height == ib.height;
    if (!same_size && !diff) {
        printf("size differs: %dx%d vs %dx%d\n", ia.width, ia.height, ib.width, ib.height);
        return 1;
    }
    int w = ia.width > ib.width ? ia.width : ib.width, h = ia.height > ib.height ? ia.height : ib.height;
    if (diff && (long long)w * h > max_pixels) {
        fprintf(stderr, "iskra compare: the diff image would be %dx%d = %lld pixels, more than the limit of %lld "
                        "(see --max-pixels)\n", w, h, (long long)w * h, max_pixels);
        return 1;
    }
    isk_canvas a, b;
    if (load(&a, files[0], max_pixels))
        return 1;
    if (load(&b, files[1], max_pixels)) {
        isk_canvas_free(&a);
        return 1;
    }
    int rc = 0;
    isk_canvas_diff d;
    isk_canvas img = {0};
    if (diff && isk_canvas_init(&img, w, h) != ISK_OK) {
        fprintf(stderr, "iskra compare: out of memory for the diff image\n");
        diff = NULL;
        rc = 1;
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
