/* SPDX-License-Identifier: MIT */
/* iskra render --snapshot FILE.snap and --from FILE.snap: a run stopped at
 * frame k and resumed by another process gives the bytes of one run (the
 * frame, the state, the probes, a numbered sequence), on any number of
 * threads; a snapshot of another scene or other overrides, a damaged one,
 * one past --frames, a scene that draws over its last frame and an output
 * over the snapshot are refused with a message, nothing written. */
#include <criterion/criterion.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tool_cli.h"

#define OUT "out/test_snapshot_cli"
#define PROBES "tests/data/probes_stream.ini"

/* The whole file's bytes (asserts it exists). */
static unsigned char *bytes_of(const char *path, long *n)
{
    FILE *f = fopen(path, "rb");
    cr_assert_not_null(f, "%s", path);
    cr_assert_eq(fseek(f, 0, SEEK_END), 0);
    *n = ftell(f);
    rewind(f);
    unsigned char *b = malloc((size_t)*n + 1);
    cr_assert_not_null(b);
    cr_assert_eq(fread(b, 1, (size_t)*n, f), (size_t)*n);
    fclose(f);
    return b;
}

static void expect_same_file(const char *a, const char *b)
{
    long na, nb;
    unsigned char *x = bytes_of(a, &na), *y = bytes_of(b, &nb);
    cr_expect(na == nb && !memcmp(x, y, (size_t)na), "%s and %s differ", a, b);
    free(x);
    free(y);
}

static int exists(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f)
        fclose(f);
    return f != NULL;
}

Test(snapshot_cli, a_run_resumed_in_another_process_has_the_bytes_of_one_run, .timeout = 120)
{
    const char *dir = OUT "/campfire";
    cli_fresh(dir);
    cr_assert_eq(cli_run(dir, "render fire_campfire --frames 90 --threads 1 --out " OUT "/campfire/one.png --state "
                              OUT "/campfire/one.csv --out-dir " OUT "/campfire/one --every 25"),
                 0);
    cr_assert_eq(cli_run(dir, "render fire_campfire --frames 40 --threads 1 --snapshot " OUT "/campfire/at40.snap"),
                 0);
    cr_assert_eq(cli_run(dir, "render fire_campfire --from " OUT "/campfire/at40.snap --frames 90 --threads 2 --out "
                              OUT "/campfire/two.png --state " OUT "/campfire/two.csv --out-dir " OUT
                              "/campfire/two --every 25"),
                 0);
    expect_same_file(OUT "/campfire/one.png", OUT "/campfire/two.png");
    expect_same_file(OUT "/campfire/one.csv", OUT "/campfire/two.csv");
    /* the sequence from the snapshot's frame on: 50 and 75, not 0 and 25 */
    expect_same_file(OUT "/campfire/one/frame_000050.png", OUT "/campfire/two/frame_000050.png");
    expect_same_file(OUT "/campfire/one/frame_000075.png", OUT "/campfire/two/frame_000075.png");
    cr_expect(!exists(OUT "/campfire/two/frame_000025.png"), "no frame before the snapshot's");
    /* a snapshot taken from a resumed run is the straight run's */
    cr_assert_eq(cli_run(dir, "render fire_campfire --from " OUT "/campfire/at40.snap --frames 60 --snapshot " OUT
                              "/campfire/at60b.snap"),
                 0);
    cr_assert_eq(cli_run(dir, "render fire_campfire --frames 60 --snapshot " OUT "/campfire/at60a.snap"), 0);
    expect_same_file(OUT "/campfire/at60a.snap", OUT "/campfire/at60b.snap");
}

/* The probes' counts and windows are in the snapshot: the rows from its
 * frame on are the straight run's rows, bit for bit. */
Test(snapshot_cli, probes_go_on_counting, .timeout = 120)
{
    const char *dir = OUT "/probes";
    cli_fresh(dir);
    cr_assert_eq(cli_run(dir, "render " PROBES " --frames 80 --probes " OUT "/probes/one.csv"), 0);
    cr_assert_eq(cli_run(dir, "render " PROBES " --frames 30 --snapshot " OUT "/probes/at30.snap"), 0);
    cr_assert_eq(cli_run(dir, "render " PROBES " --from " OUT "/probes/at30.snap --frames 80 --probes " OUT
                              "/probes/two.csv"),
                 0);
    char *one = cli_slurp(OUT "/probes/one.csv"), *two = cli_slurp(OUT "/probes/two.csv");
    const char *row30 = strstr(one, "\n30,");
    cr_assert_not_null(row30);
    const char *header_end = strchr(two, '\n');
    cr_assert_not_null(header_end);
    cr_expect(!strncmp(one, two, (size_t)(header_end - two)), "the same columns");
    cr_expect_str_eq(header_end, row30, "rows 30..80 are the straight run's");
    free(one);
    free(two);
}

/* Each refusal exits 2, says why on stderr, and writes nothing. */
static void expect_refused(const char *dir, const char *args, const char *says, const char *not_written)
{
    cr_assert_eq(cli_run(dir, args), 2, "iskra %s", args);
    char path[256];
    snprintf(path, sizeof path, "%s/stderr.txt", dir);
    char *err = cli_slurp(path);
    cr_expect(strstr(err, says) != NULL, "iskra %s: expected '%s' in: %s", args, says, err);
    free(err);
    if (not_written)
        cr_expect(!exists(not_written), "iskra %s wrote %s", args, not_written);
}

Test(snapshot_cli, what_cannot_go_on_is_refused, .timeout = 120)
{
    const char *dir = OUT "/refused";
    cli_fresh(dir);
    cr_assert_eq(cli_run(dir, "render fire_campfire --frames 40 --snapshot " OUT "/refused/at40.snap"), 0);
    long n0;
    unsigned char *before = bytes_of(OUT "/refused/at40.snap", &n0);

    expect_refused(dir, "render preset_smoke --from " OUT "/refused/at40.snap --frames 60 --out " OUT "/refused/x.png",
                   "a snapshot of another scene", OUT "/refused/x.png");
    expect_refused(dir, "render fire_campfire --seed 5 --from " OUT "/refused/at40.snap --frames 60 --out " OUT
                        "/refused/x.png",
                   "other overrides", OUT "/refused/x.png");
    expect_refused(dir, "render fire_campfire --from " OUT "/refused/at40.snap --frames 20 --out " OUT "/refused/x.png",
                   "is at frame 40, after the last frame 20", OUT "/refused/x.png");
    expect_refused(dir, "render fig12_gravity --from " OUT "/refused/at40.snap --frames 60 --out " OUT "/refused/x.png",
                   "clear = false", OUT "/refused/x.png");
    expect_refused(dir, "render fire_campfire --from " OUT "/refused/at40.snap --frames 60 --every 10 --strip " OUT
                        "/refused/x.png",
                   "a strip's panels start at frame 0", OUT "/refused/x.png");
    expect_refused(dir, "render fire_campfire --from " OUT "/refused/at40.snap --frames 60 --snapshot " OUT
                        "/refused/at40.snap",
                   "refusing to overwrite the input", NULL);
    expect_refused(dir, "render fire_campfire --frames 60 --snapshot -", "a snapshot is a file", NULL);
    expect_refused(dir, "render fire_campfire --from " OUT "/refused/none.snap --frames 60 --out " OUT
                        "/refused/x.png",
                   "none.snap", OUT "/refused/x.png");

    /* the input is untouched by every refusal */
    long n1;
    unsigned char *after = bytes_of(OUT "/refused/at40.snap", &n1);
    cr_expect(n0 == n1 && !memcmp(before, after, (size_t)n0), "the snapshot was changed");

    /* a damaged snapshot: one byte of its state flipped */
    after[n1 - 9] ^= 0x40;
    FILE *f = fopen(OUT "/refused/bad.snap", "wb");
    cr_assert_not_null(f);
    cr_assert_eq(fwrite(after, 1, (size_t)n1, f), (size_t)n1);
    fclose(f);
    expect_refused(dir, "render fire_campfire --from " OUT "/refused/bad.snap --frames 60 --out " OUT "/refused/x.png",
                   "bad.snap", OUT "/refused/x.png");
    free(before);
    free(after);
}
