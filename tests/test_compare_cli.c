/* SPDX-License-Identifier: MIT */
/* `iskra compare`: its exit statuses (0 the same or within the tolerance,
 * 1 different, 2 unreadable or a usage error, as cmp(1)), and the
 * tolerance of isk_refimg_opts (--max-channel-diff, --max-differing, with
 * --reason: a tolerance without a reason is refused), in words, in JSON
 * and in --help. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/canvas.h"
#include "iskra/png.h"
#include "iskra/refimg.h"
#include "tool_cli.h"

#define OUT "out/test_compare_cli"

/* Criterion runs the tests in parallel: each in a directory of its own,
 * OUT/NAME, kept in D. */
static char D[256];

/* D/a.png and D/b.png, 10x10: b differs from a in 3 pixels by 2 in one
 * channel and in 1 pixel by 9 (and by 4 in another channel); D/c.png is
 * 10x11; D/junk.png is text. */
static void make_images(const char *name)
{
    snprintf(D, sizeof D, OUT "/%s", name);
    cli_fresh(D);
    char a_png[300], b_png[300], c_png[300];
    snprintf(a_png, sizeof a_png, "%s/a.png", D);
    snprintf(b_png, sizeof b_png, "%s/b.png", D);
    snprintf(c_png, sizeof c_png, "%s/c.png", D);
    isk_canvas a, b, c;
    cr_assert_eq(isk_canvas_init(&a, 10, 10), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, 10, 10), ISK_OK);
    cr_assert_eq(isk_canvas_init(&c, 10, 11), ISK_OK);
    isk_canvas_fill(&a, (isk_color){40, 80, 120, 255});
    isk_canvas_fill(&b, (isk_color){40, 80, 120, 255});
    isk_canvas_fill(&c, (isk_color){40, 80, 120, 255});
    for (int i = 0; i < 3; i++)
        isk_canvas_at(&b, i, 0)[1] += 2;
    isk_canvas_at(&b, 5, 5)[0] += 9;
    isk_canvas_at(&b, 5, 5)[2] -= 4;
    cr_assert_eq(isk_png_write(&a, a_png, NULL), ISK_OK);
    cr_assert_eq(isk_png_write(&b, b_png, NULL), ISK_OK);
    cr_assert_eq(isk_png_write(&c, c_png, NULL), ISK_OK);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_canvas_free(&c);
    char junk[300];
    snprintf(junk, sizeof junk, "%s/junk.png", D);
    FILE *f = fopen(junk, "w");
    cr_assert_not_null(f);
    fputs("not a picture\n", f);
    fclose(f);
}

/* Runs `iskra compare D/A D/B EXTRA` ("A B": files in D), checks the exit
 * status, returns stdout. */
static char *compare(const char *files, const char *extra, int want)
{
    char args[1024], f1[64], f2[64] = "", path[300];
    cr_assert_geq(sscanf(files, "%63s %63s", f1, f2), 1);
    snprintf(args, sizeof args, "compare %s/%s %s%s%s %s", D, f1, *f2 ? D : "", *f2 ? "/" : "", f2, extra);
    int rc = cli_run(D, args);
    snprintf(path, sizeof path, "%s/stderr.txt", D);
    char *err = cli_slurp(path);
    cr_assert_eq(rc, want, "iskra %s: exit %d, not %d; stderr: %s", args, rc, want, err);
    free(err);
    snprintf(path, sizeof path, "%s/stdout.txt", D);
    return cli_slurp(path);
}

static char *slurp_in_d(const char *name)
{
    char path[300];
    snprintf(path, sizeof path, "%s/%s", D, name);
    return cli_slurp(path);
}

static void contains(const char *text, const char *want)
{
    cr_assert_not_null(strstr(text, want), "expected \"%s\" in:\n%s", want, text);
}

#define AB "a.png b.png"

Test(compare_cli, exit_status_is_same_different_or_trouble)
{
    make_images("exit_status_is_same_different_or_trouble");
    free(compare("a.png a.png", "", 0));
    char *o = compare(AB, "", 1);
    cr_assert_str_eq(o, "4 of 100 pixels differ, max channel difference 9, mean absolute difference 0.0475\n");
    free(o);
    o = compare("a.png c.png", "", 1);
    cr_assert_str_eq(o, "size differs: 10x10 vs 10x11\n");
    free(o);
    /* unreadable: 2, whatever the other file */
    free(compare("a.png missing.png", "", 2));
    free(compare("junk.png a.png", "", 2));
    /* too large to decode, or a diff image too large: 2 */
    free(compare(AB, "--max-pixels 99", 2));
    /* usage */
    free(compare("a.png", "", 2));
    free(compare(AB, "--frobnicate", 2));
}

Test(compare_cli, a_tolerance_counts_pixels_beyond_it)
{
    make_images("a_tolerance_counts_pixels_beyond_it");
    /* 1 pixel differs by more than 2: beyond the tolerance unless 1 is allowed */
    char *o = compare(AB, "--max-channel-diff 2 --reason 'libm differs'", 1);
    contains(o, "; beyond the tolerance (1 pixel beyond 2 per channel, 0 allowed: libm differs)\n");
    free(o);
    o = compare(AB, "--max-channel-diff 2 --max-differing 1 --reason 'libm differs'", 0);
    contains(o, "4 of 100 pixels differ, max channel difference 9");
    contains(o, "; within the tolerance (1 pixel beyond 2 per channel, 1 allowed: libm differs)\n");
    free(o);
    free(compare(AB, "--max-channel-diff 8 --reason r", 1));
    free(compare(AB, "--max-channel-diff 9 --reason r", 0));
    /* without a channel tolerance every differing pixel counts */
    free(compare(AB, "--max-differing 3 --reason r", 1));
    free(compare(AB, "--max-differing=4 --reason=r", 0));
    /* sizes that differ are never within a tolerance */
    free(compare("a.png c.png", "--max-channel-diff 255 --max-differing 1000 --reason r", 1));
}

Test(compare_cli, a_tolerance_needs_a_reason_and_a_range)
{
    make_images("a_tolerance_needs_a_reason_and_a_range");
    const char *bad[] = {"--max-channel-diff 2", "--max-differing 1", "--max-channel-diff 2 --reason ''",
                         "--max-channel-diff 256 --reason r", "--max-channel-diff -1 --reason r",
                         "--max-differing -1 --reason r", "--max-differing x --reason r", "--reason",
                         "--max-channel-diff"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char *o = compare(AB, bad[i], 2);
        cr_assert_str_eq(o, "", "%s printed a result", bad[i]);
        free(o);
    }
    free(compare(AB, "--max-channel-diff 2", 2));
    char *err = slurp_in_d("stderr.txt");
    contains(err, "iskra compare: a tolerance (--max-channel-diff, --max-differing) needs --reason");
    free(err);
    /* a zero tolerance is exactness: no reason needed */
    free(compare(AB, "--max-channel-diff 0 --max-differing 0", 1));
}

Test(compare_cli, json_carries_the_tolerance)
{
    make_images("json_carries_the_tolerance");
    char *o = compare(AB, "--json --max-channel-diff 2 --max-differing 1 --reason 'say \"why\"'", 0);
    contains(o, "\"differing\": 4, \"max_channel\": 9,");
    contains(o, "\"identical\": false, \"beyond_tolerance\": 1, \"within_tolerance\": true, \"tolerance\": "
                "{\"max_channel_diff\": 2, \"max_differing\": 1, \"reason\": \"say \\\"why\\\"\"}, \"diff\": null}");
    free(o);
    o = compare(AB, "--json", 1);
    contains(o, "\"beyond_tolerance\": 4, \"within_tolerance\": false, \"tolerance\": null,");
    free(o);
    o = compare("a.png c.png", "--json", 1);
    contains(o, "\"same_size\": false,");
    contains(o, "\"beyond_tolerance\": null, \"within_tolerance\": false,");
    free(o);
}

Test(compare_cli, help_documents_the_tolerance_and_the_exit_statuses)
{
    cli_fresh(OUT "/help");
    cr_assert_eq(cli_run(OUT "/help", "compare --help"), 0);
    char *o = cli_slurp(OUT "/help/stdout.txt");
    const char *want[] = {"--max-channel-diff N", "--max-differing N", "--reason TEXT", "required with a tolerance",
                          "exit status: 0 the same (or within the tolerance), 1 different,",
                          "2 an image unreadable or too large"};
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++)
        contains(o, want[i]);
    free(o);
}

/* The tool's tolerance is isk_refimg_check's: the same pixels beyond it,
 * the same verdict, for every channel tolerance and allowance tried. */
Test(compare_cli, the_tolerance_is_the_librarys)
{
    make_images("library");
    isk_canvas b;
    char b_png[300], ref[300], out_dir[300];
    snprintf(b_png, sizeof b_png, "%s/b.png", D);
    snprintf(ref, sizeof ref, "%s/a.png", D);
    snprintf(out_dir, sizeof out_dir, "%s/refimg", D);
    cr_assert_eq(isk_png_read(&b, b_png, NULL), ISK_OK);
    for (int tol = 0; tol <= 10; tol++)
        for (long allowed = 0; allowed <= 4; allowed++) {
            isk_refimg_result r;
            isk_refimg_opts o = {0};
            o.out_dir = out_dir;
            o.update = ISK_REFIMG_UPDATE_NEVER;
            o.max_channel_diff = tol;
            o.max_differing = allowed;
            o.reason = "the same rule";
            o.result = &r;
            isk_status s = isk_refimg_check(&b, ref, &o, NULL);
            char extra[200];
            snprintf(extra, sizeof extra, "--json --max-channel-diff %d --max-differing %ld --reason r", tol,
                     allowed);
            char *json = compare("b.png a.png", extra, s == ISK_OK ? 0 : 1);
            char want[80];
            snprintf(want, sizeof want, "\"beyond_tolerance\": %ld,", r.beyond_tolerance);
            contains(json, want);
            free(json);
        }
    isk_canvas_free(&b);
}
