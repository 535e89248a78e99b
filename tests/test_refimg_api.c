/* SPDX-License-Identifier: MIT */
/* The public reference-image check (iskra/refimg.h): exact by default, the
 * actual and diff images on a mismatch with how many pixels differ and by
 * how much, update mode from opts or from ISKRA_REFIMG_UPDATE read at each
 * call, tolerances only with a reason, and the reference never touched
 * outside update mode. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/png.h"
#include "iskra/refimg.h"
#include "tool_cli.h"

#define OUT "out/test_refimg_api"

static void picture(isk_canvas *c, int w, int h)
{
    cr_assert_eq(isk_canvas_init(c, w, h), ISK_OK);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint8_t *p = isk_canvas_at(c, x, y);
            p[0] = (uint8_t)(60 + x * 10);
            p[1] = (uint8_t)(90 + y * 20);
            p[2] = 30;
            p[3] = 255;
        }
}

/* A scratch directory with ref.png = picture(w, h). */
static void setup_dir(const char *dir, int w, int h)
{
    unsetenv("ISKRA_REFIMG_UPDATE"); /* whatever the caller's shell says */
    cli_fresh(dir);
    isk_canvas c;
    picture(&c, w, h);
    char ref[256];
    snprintf(ref, sizeof ref, "%s/ref.png", dir);
    cr_assert_eq(isk_png_write(&c, ref, NULL), ISK_OK);
    isk_canvas_free(&c);
}

static char *bytes_of(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    cr_assert_not_null(f, "%s", path);
    char *b = malloc(1 << 16);
    *n = fread(b, 1, 1 << 16, f);
    fclose(f);
    return b;
}

Test(refimg_api, same_pixels_pass_with_zero_figures)
{
    setup_dir(OUT "/same", 8, 6);
    isk_canvas c;
    picture(&c, 8, 6);
    isk_refimg_result r;
    isk_refimg_opts o = {0};
    o.out_dir = OUT "/same/out";
    o.result = &r;
    isk_error err;
    cr_assert_eq(isk_refimg_check(&c, OUT "/same/ref.png", &o, &err), ISK_OK, "%s", err.message);
    cr_assert(r.same_size);
    cr_assert_eq(r.diff.pixels, 48);
    cr_assert_eq(r.diff.differing, 0);
    cr_assert_eq(r.updated, 0);
    cr_assert_not(cli_exists(OUT "/same/out"), "nothing is written when all is well");
    cr_assert_eq(isk_refimg_check(&c, OUT "/same/ref.png", NULL, &err), ISK_OK, "opts may be NULL");
    isk_canvas_free(&c);
}

Test(refimg_api, a_mismatch_leaves_the_actual_and_diff_images_and_says_how_much)
{
    setup_dir(OUT "/mismatch", 8, 6);
    size_t n0;
    char *before = bytes_of(OUT "/mismatch/ref.png", &n0);
    isk_canvas c;
    picture(&c, 8, 6);
    isk_canvas_at(&c, 3, 2)[1] += 7; /* one pixel, one channel, by 7 */
    isk_refimg_result r;
    isk_refimg_opts o = {0};
    o.out_dir = OUT "/mismatch/deep/out";
    o.result = &r;
    isk_error err;
    cr_assert_eq(isk_refimg_check(&c, OUT "/mismatch/ref.png", &o, &err), ISK_ERR_MISMATCH);
    cr_assert_str_eq(err.message,
                     "refimg ref: 1 of 48 pixels differ, max channel difference 7, mean absolute difference 0.0365; "
                     "actual: " OUT "/mismatch/deep/out/ref.actual.png; diff: " OUT "/mismatch/deep/out/ref.diff.png; "
                     "if it is right, rerun with ISKRA_REFIMG_UPDATE=1");
    cr_assert_eq(r.diff.differing, 1);
    cr_assert_eq(r.diff.max_channel, 7);
    cr_assert_eq(r.beyond_tolerance, 1);
    isk_canvas a, d;
    cr_assert_eq(isk_png_read(&a, OUT "/mismatch/deep/out/ref.actual.png", NULL), ISK_OK);
    cr_assert(isk_canvas_equal(&a, &c));
    cr_assert_eq(isk_png_read(&d, OUT "/mismatch/deep/out/ref.diff.png", NULL), ISK_OK);
    const uint8_t *m = isk_canvas_at(&d, 3, 2), *k = isk_canvas_at(&d, 0, 0);
    cr_assert(m[0] == 255 && m[1] == 0 && m[2] == 255 && m[3] == 255, "the differing pixel is magenta");
    cr_assert(k[0] == 60 / 3 && k[1] == 90 / 3 && k[3] == 255, "the others a dimmed copy");
    size_t n1;
    char *after = bytes_of(OUT "/mismatch/ref.png", &n1);
    cr_assert(n0 == n1 && !memcmp(before, after, n0), "the reference was touched");
    free(before);
    free(after);
    isk_canvas_free(&a);
    isk_canvas_free(&d);
    isk_canvas_free(&c);
}

Test(refimg_api, sizes_that_differ_are_a_mismatch_with_a_full_size_diff)
{
    setup_dir(OUT "/size", 5, 4);
    isk_canvas c;
    picture(&c, 4, 4);
    isk_error err;
    isk_refimg_opts o = {0};
    o.update = ISK_REFIMG_UPDATE_NEVER;
    /* out_dir NULL: next to the reference */
    cr_assert_eq(isk_refimg_check(&c, OUT "/size/ref.png", &o, &err), ISK_ERR_MISMATCH);
    cr_assert_str_eq(err.message, "refimg ref: size 4x4, reference 5x4; actual: " OUT "/size/ref.actual.png; diff: " OUT
                                  "/size/ref.diff.png");
    isk_canvas d;
    cr_assert_eq(isk_png_read(&d, OUT "/size/ref.diff.png", NULL), ISK_OK);
    cr_assert_eq(d.width, 5);
    cr_assert_eq(isk_canvas_at(&d, 4, 0)[1], 0, "outside the smaller image: magenta");
    isk_canvas_free(&d);
    isk_canvas_free(&c);
}

Test(refimg_api, a_missing_reference_fails_and_says_how_to_make_it)
{
    setup_dir(OUT "/missing", 2, 2);
    isk_canvas c;
    picture(&c, 3, 3);
    isk_error err;
    isk_refimg_opts o = {0};
    o.out_dir = OUT "/missing/out";
    cr_assert_eq(isk_refimg_check(&c, OUT "/missing/nope.png", &o, &err), ISK_ERR_IO);
    cr_assert_not_null(strstr(err.message, "refimg nope: no usable reference (" OUT "/missing/nope.png: No such file"),
                       "%s", err.message);
    cr_assert_not_null(strstr(err.message, "rerun with ISKRA_REFIMG_UPDATE=1"), "%s", err.message);
    cr_assert(cli_exists(OUT "/missing/out/nope.actual.png"));
    cr_assert_not(cli_exists(OUT "/missing/nope.png"));
    isk_canvas_free(&c);
}

Test(refimg_api, update_mode_from_opts_or_from_the_environment_read_at_each_call)
{
    setup_dir(OUT "/update", 2, 2);
    isk_canvas c;
    picture(&c, 6, 5);
    isk_refimg_result r;
    isk_refimg_opts o = {0};
    o.result = &r;
    isk_error err;
    const char *ref = OUT "/update/new/dir/ref.png";
    o.update = ISK_REFIMG_UPDATE_ALWAYS;
    cr_assert_eq(isk_refimg_check(&c, ref, &o, &err), ISK_OK, "%s", err.message);
    cr_assert(r.updated);
    o.update = ISK_REFIMG_UPDATE_FROM_ENV;
    cr_assert_eq(isk_refimg_check(&c, ref, &o, &err), ISK_OK, "%s", err.message);
    cr_assert_not(r.updated);
    isk_canvas_at(&c, 0, 0)[0] ^= 1;
    cr_assert_eq(isk_refimg_check(&c, ref, &o, &err), ISK_ERR_MISMATCH);
    setenv("ISKRA_REFIMG_UPDATE", "1", 1); /* takes effect at the next call: nothing cached */
    cr_assert_eq(isk_refimg_check(&c, ref, &o, &err), ISK_OK, "%s", err.message);
    cr_assert(r.updated);
    o.update = ISK_REFIMG_UPDATE_NEVER; /* the environment ignored */
    isk_canvas_at(&c, 1, 0)[0] ^= 1;
    cr_assert_eq(isk_refimg_check(&c, ref, &o, &err), ISK_ERR_MISMATCH);
    cr_assert_null(strstr(err.message, "ISKRA_REFIMG_UPDATE"), "no env hint when the env is ignored: %s", err.message);
    o.update = ISK_REFIMG_UPDATE_FROM_ENV;
    setenv("ISKRA_REFIMG_UPDATE", "0", 1);
    cr_assert_eq(isk_refimg_check(&c, ref, &o, &err), ISK_ERR_MISMATCH);
    setenv("ISKRA_REFIMG_UPDATE", "", 1);
    cr_assert_eq(isk_refimg_check(&c, ref, &o, &err), ISK_ERR_MISMATCH);
    unsetenv("ISKRA_REFIMG_UPDATE");
    isk_canvas_free(&c);
}

Test(refimg_api, tolerances_need_a_reason_and_count_pixels_beyond_the_channel_limit)
{
    setup_dir(OUT "/tol", 8, 6);
    isk_canvas c;
    picture(&c, 8, 6);
    isk_canvas_at(&c, 0, 0)[0] += 2;
    isk_canvas_at(&c, 1, 0)[0] += 2;
    isk_canvas_at(&c, 2, 0)[2] += 9;
    isk_refimg_result r;
    isk_refimg_opts o = {0};
    o.out_dir = OUT "/tol/out";
    o.result = &r;
    isk_error err;
    const char *ref = OUT "/tol/ref.png";
    o.max_channel_diff = 2;
    cr_assert_eq(isk_refimg_check(&c, ref, &o, &err), ISK_ERR_RANGE);
    cr_assert_str_eq(err.message, "refimg: " OUT "/tol/ref.png: a tolerance needs a written reason");
    o.reason = "test: rounding differs by 2 at most";
    cr_assert_eq(isk_refimg_check(&c, ref, &o, &err), ISK_ERR_MISMATCH, "the 9 is beyond 2");
    cr_assert_eq(r.diff.differing, 3);
    cr_assert_eq(r.beyond_tolerance, 1);
    cr_assert_not_null(strstr(err.message, "(1 beyond the tolerance of 2 per channel, 0 allowed: test: rounding"),
                       "%s", err.message);
    o.max_differing = 1;
    cr_assert_eq(isk_refimg_check(&c, ref, &o, &err), ISK_OK, "%s", err.message);
    o.max_channel_diff = 0;
    o.max_differing = 2;
    cr_assert_eq(isk_refimg_check(&c, ref, &o, &err), ISK_ERR_MISMATCH);
    o.max_differing = 3;
    cr_assert_eq(isk_refimg_check(&c, ref, &o, &err), ISK_OK);
    o.max_differing = -1;
    cr_assert_eq(isk_refimg_check(&c, ref, &o, &err), ISK_ERR_RANGE);
    o.max_differing = 0;
    o.max_channel_diff = 256;
    cr_assert_eq(isk_refimg_check(&c, ref, &o, &err), ISK_ERR_RANGE);
    isk_canvas_free(&c);
}

Test(refimg_api, hostile_arguments)
{
    setup_dir(OUT "/hostile", 2, 2);
    isk_canvas c;
    picture(&c, 2, 2);
    isk_error err;
    cr_assert_eq(isk_refimg_check(NULL, OUT "/hostile/ref.png", NULL, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_refimg_check(&c, NULL, NULL, &err), ISK_ERR_NULL);
    isk_canvas bad = {NULL, 3, 3, 12, 0};
    cr_assert_eq(isk_refimg_check(&bad, OUT "/hostile/ref.png", NULL, &err), ISK_ERR_SIZE);
    isk_refimg_opts o = {0};
    o.update = (isk_refimg_update)42;
    cr_assert_eq(isk_refimg_check(&c, OUT "/hostile/ref.png", &o, &err), ISK_ERR_RANGE);
    cr_assert_eq(isk_refimg_check(&c, "", NULL, &err), ISK_ERR_RANGE);
    cr_assert_eq(isk_refimg_check(&c, OUT "/hostile/", NULL, &err), ISK_ERR_RANGE);
    char buf[8];
    cr_assert_str_eq(isk_refimg_summary(NULL, buf, sizeof buf), "no comp");
    cr_assert_null(isk_refimg_summary(NULL, NULL, 4));
    isk_canvas_free(&c);
}

/* The number after "key": in a one-line JSON object. */
static double json_number(const char *json, const char *key)
{
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\": ", key);
    const char *p = strstr(json, pat);
    cr_assert_not_null(p, "no %s in %s", key, json);
    return strtod(p + strlen(pat), NULL);
}

Test(refimg_api, compare_json_prints_the_same_figures)
{
    setup_dir(OUT "/json", 8, 6);
    isk_canvas c;
    picture(&c, 8, 6);
    isk_canvas_at(&c, 1, 1)[0] += 5;
    isk_canvas_at(&c, 2, 1)[3] -= 40;
    isk_refimg_result r;
    isk_refimg_opts o = {0};
    o.out_dir = OUT "/json/out";
    o.result = &r;
    cr_assert_eq(isk_refimg_check(&c, OUT "/json/ref.png", &o, NULL), ISK_ERR_MISMATCH);
    cr_assert_eq(cli_run(OUT "/json", "compare --json " OUT "/json/out/ref.actual.png " OUT "/json/ref.png"), 1);
    char *out = cli_slurp(OUT "/json/stdout.txt");
    cr_assert_eq(out[0], '{', "%s", out);
    cr_assert_eq(out[strlen(out) - 2], '}', "%s", out);
    cr_assert_not_null(strstr(out, "\"a\": \"" OUT "/json/out/ref.actual.png\""), "%s", out);
    cr_assert_not_null(strstr(out, "\"same_size\": true"), "%s", out);
    cr_assert_not_null(strstr(out, "\"identical\": false"), "%s", out);
    cr_assert_not_null(strstr(out, "\"diff\": null"), "%s", out);
    cr_assert_eq((long)json_number(out, "pixels"), r.diff.pixels);
    cr_assert_eq((long)json_number(out, "differing"), r.diff.differing);
    cr_assert_eq((int)json_number(out, "max_channel"), r.diff.max_channel);
    cr_assert_eq((int)json_number(out, "max_channel"), 40);
    double mean = json_number(out, "mean_abs");
    cr_assert(mean > r.diff.mean_abs - 1e-6 && mean < r.diff.mean_abs + 1e-6, "%g vs %g", mean, r.diff.mean_abs);
    cr_assert_eq((int)json_number(out, "a_width"), 8);
    free(out);
    /* the sentence form says the same as the library's message */
    cr_assert_eq(cli_run(OUT "/json", "compare " OUT "/json/out/ref.actual.png " OUT "/json/ref.png"), 1);
    out = cli_slurp(OUT "/json/stdout.txt");
    char want[300];
    isk_refimg_summary(&r.diff, want, sizeof want);
    strcat(want, "\n");
    cr_assert_str_eq(out, want);
    free(out);
    /* identical, a missing file, a diff path (a name needing JSON escapes) */
    cr_assert_eq(cli_run(OUT "/json", "compare --json " OUT "/json/ref.png " OUT "/json/ref.png --diff '" OUT
                                      "/json/q\"d.png'"),
                 0);
    out = cli_slurp(OUT "/json/stdout.txt");
    cr_assert_not_null(strstr(out, "\"identical\": true"), "%s", out);
    cr_assert_not_null(strstr(out, "\"diff\": \"" OUT "/json/q\\\"d.png\""), "%s", out);
    free(out);
    cr_assert_eq(cli_run(OUT "/json", "compare --json " OUT "/json/ref.png " OUT "/json/none.png"), 2);
    out = cli_slurp(OUT "/json/stdout.txt");
    cr_assert_not_null(strstr(out, "\"error\": \"" OUT "/json/none.png: No such file or directory\"}"), "%s", out);
    free(out);
    isk_canvas_free(&c);
}
