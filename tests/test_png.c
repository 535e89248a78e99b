/* SPDX-License-Identifier: MIT */
/* PNG write/read: exact round trips, atomic writes, reported errors. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include <png.h>
#include <stdlib.h>

#include "iskra/png.h"

static void make_dirs(void)
{
    mkdir("out", 0777);
    mkdir("out/test_png", 0777);
}

static int exists(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0;
}

Test(png, round_trip_is_byte_exact)
{
    make_dirs();
    isk_canvas c, r;
    cr_assert_eq(isk_canvas_init(&c, 37, 23), ISK_OK);
    for (int y = 0; y < c.height; y++)
        for (int x = 0; x < c.width; x++) {
            uint8_t *p = isk_canvas_at(&c, x, y);
            p[0] = (uint8_t)(x * 7); p[1] = (uint8_t)(y * 11); p[2] = (uint8_t)(x ^ y); p[3] = (uint8_t)(x * y);
        }
    isk_error err;
    cr_assert_eq(isk_png_write(&c, "out/test_png/rt.png", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_png_read(&r, "out/test_png/rt.png", &err), ISK_OK, "%s", err.message);
    cr_assert(isk_canvas_equal(&c, &r));
    isk_canvas_free(&c);
    isk_canvas_free(&r);
}

/* The whole file as bytes (at most 1 MiB); its size in *n. */
static unsigned char *slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    cr_assert_not_null(f, "%s", path);
    unsigned char *b = malloc(1 << 20);
    cr_assert_not_null(b);
    *n = fread(b, 1, 1 << 20, f);
    fclose(f);
    return b;
}

/* iskra writes with libpng's write struct (the browser's libpng has no
 * setjmp, which the simplified API needs): the files are byte for byte
 * those of libpng's simplified writer, as before. */
Test(png, files_are_the_simplified_writers_bytes)
{
    make_dirs();
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 301, 77), ISK_OK);
    for (int y = 0; y < c.height; y++)
        for (int x = 0; x < c.width; x++) {
            uint8_t *p = isk_canvas_at(&c, x, y);
            p[0] = (uint8_t)(x * 3 + y); p[1] = (uint8_t)(y * 5); p[2] = (uint8_t)((x * y) >> 3); p[3] = (uint8_t)(255 - x);
        }
    isk_error err;
    cr_assert_eq(isk_png_write(&c, "out/test_png/ours.png", &err), ISK_OK, "%s", err.message);
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = (png_uint_32)c.width;
    img.height = (png_uint_32)c.height;
    img.format = PNG_FORMAT_RGBA;
    cr_assert(png_image_write_to_file(&img, "out/test_png/simplified.png", 0, c.pixels, (png_int_32)c.stride, NULL));
    png_image_free(&img);
    size_t na, nb;
    unsigned char *a = slurp("out/test_png/ours.png", &na), *b = slurp("out/test_png/simplified.png", &nb);
    cr_assert_gt(na, 100);
    cr_assert_eq(na, nb);
    cr_assert(memcmp(a, b, na) == 0);
    free(a);
    free(b);
    isk_canvas_free(&c);
}

Test(png, writes_views_with_stride)
{
    make_dirs();
    isk_canvas big, view, r;
    cr_assert_eq(isk_canvas_init(&big, 50, 40), ISK_OK);
    isk_canvas_fill(&big, ISK_RED);
    cr_assert_eq(isk_canvas_view(&view, &big, 10, 5, 20, 10), ISK_OK);
    isk_canvas_fill(&view, ISK_BLUE);
    cr_assert_eq(isk_png_write(&view, "out/test_png/view.png", NULL), ISK_OK);
    cr_assert_eq(isk_png_read(&r, "out/test_png/view.png", NULL), ISK_OK);
    cr_assert_eq(r.width, 20);
    cr_assert_eq(r.height, 10);
    cr_assert(isk_canvas_equal(&view, &r));
    isk_canvas_free(&r);
    isk_canvas_free(&big);
}

Test(png, failed_write_reports_and_leaves_nothing)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 4, 4), ISK_OK);
    isk_error err = {0};
    cr_assert_eq(isk_png_write(&c, "out/test_png/no/such/dir/x.png", &err), ISK_ERR_IO);
    cr_assert(strstr(err.message, "out/test_png/no/such/dir/x.png") != NULL, "%s", err.message);
    cr_assert(!exists("out/test_png/no/such/dir/x.png"));
    cr_assert_eq(isk_png_write(NULL, "x.png", &err), ISK_ERR_NULL);
    cr_assert_eq(isk_png_write(&c, NULL, NULL), ISK_ERR_NULL);
    isk_canvas empty = {0};
    cr_assert_eq(isk_png_write(&empty, "out/test_png/empty.png", NULL), ISK_ERR_SIZE);
    cr_assert(!exists("out/test_png/empty.png"));
    isk_canvas_free(&c);
}

Test(png, overwrite_replaces_whole_file_and_leaves_no_temporaries)
{
    make_dirs();
    isk_canvas a, b, r;
    cr_assert_eq(isk_canvas_init(&a, 64, 64), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 3, 2), ISK_OK);
    isk_canvas_fill(&b, ISK_WHITE);
    cr_assert_eq(isk_png_write(&a, "out/test_png/over.png", NULL), ISK_OK);
    cr_assert_eq(isk_png_write(&b, "out/test_png/over.png", NULL), ISK_OK);
    cr_assert_eq(isk_png_read(&r, "out/test_png/over.png", NULL), ISK_OK);
    cr_assert(isk_canvas_equal(&b, &r));
    /* Only this test's file: other tests write into the folder concurrently. */
    FILE *ls = popen("ls out/test_png | grep -c over.png.tmp", "r");
    int n = -1;
    cr_assert_eq(fscanf(ls, "%d", &n), 1);
    pclose(ls);
    cr_assert_eq(n, 0, "temporary files left behind");
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_canvas_free(&r);
}

Test(png, read_errors)
{
    make_dirs();
    isk_canvas r;
    isk_error err = {0};
    cr_assert_eq(isk_png_read(&r, "out/test_png/does-not-exist.png", &err), ISK_ERR_IO);
    cr_assert(strstr(err.message, "does-not-exist.png") != NULL);
    FILE *f = fopen("out/test_png/garbage.png", "wb");
    fputs("this is not a png file at all", f);
    fclose(f);
    cr_assert_eq(isk_png_read(&r, "out/test_png/garbage.png", &err), ISK_ERR_FORMAT);
    cr_assert(r.pixels == NULL);
    /* A truncated PNG: the first half of a real one. */
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 100, 100), ISK_OK);
    for (int y = 0; y < 100; y++)
        for (int x = 0; x < 100; x++)
            isk_canvas_at(&c, x, y)[0] = (uint8_t)(x * y);
    cr_assert_eq(isk_png_write(&c, "out/test_png/full.png", NULL), ISK_OK);
    f = fopen("out/test_png/full.png", "rb");
    char buf[65536];
    size_t n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    f = fopen("out/test_png/trunc.png", "wb");
    fwrite(buf, 1, n / 2, f);
    fclose(f);
    cr_assert_neq(isk_png_read(&r, "out/test_png/trunc.png", &err), ISK_OK);
    cr_assert(r.pixels == NULL);
    isk_canvas_free(&c);
}
