/* SPDX-License-Identifier: MIT */
/* The iskra command: list, describe, render, play; exit statuses 0/1/2,
 * --help everywhere, nothing written on a scene error or a bad option. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "iskra/png.h"
#include "tool_cli.h"

#define OUT "out/test_scene_cli"

static const char *bin(void)
{
    static char path[256];
    const char *b = getenv("ISKRA_BUILD");
    snprintf(path, sizeof path, "%s/bin/iskra", b && *b ? b : "build");
    return path;
}

/* Runs `iskra ARGS` (stdout/stderr to files under OUT); returns the exit status. */
static int run(const char *args) { return cli_run(OUT, args); }

static char *slurp(const char *name)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", OUT, name);
    FILE *f = fopen(path, "rb");
    cr_assert_not_null(f, "%s", path);
    static char buf[65536];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = 0;
    fclose(f);
    return buf;
}

static void setup(void)
{
    cr_assert_eq(system("rm -rf " OUT " && mkdir -p " OUT), 0);
}

TestSuite(scene_cli, .init = setup);

Test(scene_cli, list_names_every_builtin)
{
    cr_assert_eq(run("list --names"), 0);
    char *out = slurp("stdout.txt");
    cr_assert_not_null(strstr(out, "fig12_gravity\n"));
    cr_assert_not_null(strstr(out, "fig16_regular\n"));
    cr_assert_eq(run("list extra"), 2);
}

Test(scene_cli, help_everywhere)
{
    const char *cmds[] = {"list", "describe", "render", "play", "compare"};
    for (int i = 0; i < 5; i++) {
        char a[64];
        snprintf(a, sizeof a, "%s --help", cmds[i]);
        cr_assert_eq(run(a), 0, "%s", a);
        cr_assert_not_null(strstr(slurp("stdout.txt"), "usage: iskra"), "%s", a);
    }
    cr_assert_eq(run("--help"), 0);
    cr_assert_eq(run(""), 2);
    cr_assert_eq(run("frobnicate"), 2);
}

Test(scene_cli, describe_prints_the_pipeline)
{
    cr_assert_eq(run("describe fig13_drag_gravity"), 0);
    char *out = slurp("stdout.txt");
    cr_assert_not_null(strstr(out, "emitter particle"), "%s", out);
    cr_assert_not_null(strstr(out, "walls"), "%s", out);
    cr_assert_not_null(strstr(out, "scene: 600x600 canvas, view x -10..10, y -10..10, dt 0.25 s"), "%s", out);
    /* a scene that only draws says what it draws */
    cr_assert_eq(run("describe fig01_triangle"), 0);
    out = slurp("stdout.txt");
    cr_assert_not_null(strstr(out, "drawings (before the particles):\n  polyline"), "%s", out);
    cr_assert_eq(run("describe"), 2);
    cr_assert_eq(run("describe no_such_scene"), 2);
    cr_assert_eq(run("describe fig12_gravity --bogus"), 2);
}

Test(scene_cli, render_one_frame_equals_the_example)
{
    cr_assert_eq(run("render scenes/fig12_gravity.ini --out " OUT "/f12.png"), 0, "%s", slurp("stderr.txt"));
    cr_assert_str_eq(slurp("stderr.txt"), "", "silent when stderr is not a terminal");
    isk_canvas a, b;
    cr_assert_eq(isk_png_read(&a, OUT "/f12.png", NULL), ISK_OK);
    cr_assert_eq(isk_png_read(&b, "refimg/fig12_gravity.png", NULL), ISK_OK);
    cr_assert_eq(a.width, b.width);
    cr_assert_eq(memcmp(a.pixels, b.pixels, (size_t)a.width * a.height * 4), 0);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

/* --strip: the panels are the example's (its --strip, the gallery's strip),
 * byte for byte; a strip of no panel or too many is refused before any
 * file is written. */
Test(scene_cli, render_strip_equals_the_examples_strip, .timeout = 120)
{
    cr_assert_eq(run("render fire_campfire --frames 60 --every 10 --strip " OUT "/strip/s.png"), 0, "%s",
                 slurp("stderr.txt"));
    isk_canvas a, b;
    cr_assert_eq(isk_png_read(&a, OUT "/strip/s.png", NULL), ISK_OK);
    cr_assert_eq(isk_png_read(&b, "refimg/fire_campfire_strip.png", NULL), ISK_OK);
    cr_assert(a.width == b.width && a.height == b.height);
    cr_assert_eq(memcmp(a.pixels, b.pixels, (size_t)a.width * a.height * 4), 0);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    cr_assert_eq(run("render fire_campfire --frames 60 --every 2 --strip " OUT "/strip/t.png"), 2);
    cr_assert(strstr(slurp("stderr.txt"), "30 panels, not 1..12"), "%s", slurp("stderr.txt"));
    cr_assert_eq(run("render fire_campfire --frames 5 --every 10 --strip " OUT "/strip/t.png"), 2);
    cr_assert_not(cli_exists(OUT "/strip/t.png"));
}

Test(scene_cli, render_sequence)
{
    cr_assert_eq(run("render fig16_regular --frames 5 --every 2 --out-dir " OUT "/seq/deep"), 0, "%s",
                 slurp("stderr.txt"));
    cr_assert(cli_exists(OUT "/seq/deep/frame_000000.png"));
    cr_assert(cli_exists(OUT "/seq/deep/frame_000002.png"));
    cr_assert(cli_exists(OUT "/seq/deep/frame_000004.png"));
    cr_assert_not(cli_exists(OUT "/seq/deep/frame_000001.png"));
    cr_assert_not(cli_exists(OUT "/seq/deep/frame_000005.png"));
    /* the last sequence frame equals a single render of that frame */
    cr_assert_eq(run("render fig16_regular --frames 4 --out " OUT "/f4.png"), 0);
    isk_canvas a, b;
    cr_assert_eq(isk_png_read(&a, OUT "/f4.png", NULL), ISK_OK);
    cr_assert_eq(isk_png_read(&b, OUT "/seq/deep/frame_000004.png", NULL), ISK_OK);
    cr_assert_eq(memcmp(a.pixels, b.pixels, (size_t)a.width * a.height * 4), 0);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    /* a trail scene's sequence ends with the same image as a single render */
    cr_assert_eq(run("render fig10_trajectory --frames 30 --every 10 --out-dir " OUT "/trail --out " OUT "/t30.png"),
                 0);
    cr_assert_eq(isk_png_read(&a, OUT "/t30.png", NULL), ISK_OK);
    cr_assert_eq(isk_png_read(&b, OUT "/trail/frame_000030.png", NULL), ISK_OK);
    cr_assert_eq(memcmp(a.pixels, b.pixels, (size_t)a.width * a.height * 4), 0);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(scene_cli, overrides)
{
    cr_assert_eq(run("render fig18_gauss --frames 10 --size 300x200 --seed 3 --dt 0.002 --substeps 2 --out " OUT
                     "/o.png"),
                 0, "%s", slurp("stderr.txt"));
    isk_canvas a, b;
    cr_assert_eq(isk_png_read(&a, OUT "/o.png", NULL), ISK_OK);
    cr_assert_eq(a.width, 300);
    cr_assert_eq(a.height, 200);
    /* another seed, another picture */
    cr_assert_eq(run("render fig18_gauss --frames 10 --size=300x200 --seed=4 --dt 0.002 --substeps 2 --out " OUT
                     "/p.png"),
                 0);
    cr_assert_eq(isk_png_read(&b, OUT "/p.png", NULL), ISK_OK);
    cr_assert_neq(memcmp(a.pixels, b.pixels, (size_t)a.width * a.height * 4), 0);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(scene_cli, usage_errors_write_nothing)
{
    const char *bad[] = {
        "render fig12_gravity --size 0x5 --out " OUT "/x.png",
        "render fig12_gravity --size 600 --out " OUT "/x.png",
        "render fig12_gravity --seed -1 --out " OUT "/x.png",
        "render fig12_gravity --seed abc --out " OUT "/x.png",
        "render fig12_gravity --dt nan --out " OUT "/x.png",
        "render fig12_gravity --dt 0 --out " OUT "/x.png",
        "render fig12_gravity --substeps 0 --out " OUT "/x.png",
        "render fig12_gravity --frames -1 --out " OUT "/x.png",
        "render fig12_gravity --frames 1.5 --out " OUT "/x.png",
        "render fig12_gravity --wat --out " OUT "/x.png",
        "render fig12_gravity",
        "render --out " OUT "/x.png",
        "render fig12_gravity fig10_trajectory --out " OUT "/x.png",
        "render fig12_gravity --every 2 --out " OUT "/x.png",
        "render fig12_gravity --out",
        "render fig12_gravity --every 0 --out-dir " OUT "/xdir",
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        cr_assert_eq(run(bad[i]), 2, "%s", bad[i]);
        cr_assert_neq(slurp("stderr.txt")[0], 0, "no message for: %s", bad[i]);
        cr_assert_not(cli_exists(OUT "/x.png"), "%s wrote a file", bad[i]);
        cr_assert_not(cli_exists(OUT "/xdir"), "%s made a directory", bad[i]);
    }
}

Test(scene_cli, scene_errors_exit_2_with_file_line_and_write_nothing)
{
    cr_assert_eq(run("render tests/data/bad_scenes/misspelt_key.ini --out " OUT "/x.png --out-dir " OUT "/xdir"), 2);
    cr_assert_str_eq(slurp("stderr.txt"),
                     "tests/data/bad_scenes/misspelt_key.ini:7: [emitter smoke] unknown key 'rat'; did you mean 'rate'?\n");
    cr_assert_not(cli_exists(OUT "/x.png"));
    cr_assert_not(cli_exists(OUT "/xdir"));
    cr_assert_eq(run("render tests/data/bad_scenes/runtime_invalid.ini --out " OUT "/x.png"), 2);
    cr_assert_str_eq(slurp("stderr.txt"),
                     "tests/data/bad_scenes/runtime_invalid.ini:7: [emitter sparks] count: must be 1..10000 (raise "
                     "limit for more)\n");
    cr_assert_not(cli_exists(OUT "/x.png"));
    cr_assert_eq(run("render no_such_scene.ini --out " OUT "/x.png"), 2);
    cr_assert_not(cli_exists(OUT "/x.png"));
}

/* Every broken scene under tests/data/bad_scenes/ fails with exactly the
 * message docs/scene-format.md quotes for it, and the page shows the file as
 * it is: the messages are written once, on that page. */
Test(scene_cli, bad_scene_messages)
{
    FILE *f = fopen("docs/scene-format.md", "rb");
    cr_assert_not_null(f);
    static char doc[200000];
    size_t n = fread(doc, 1, sizeof doc - 1, f);
    fclose(f);
    doc[n] = 0;
    FILE *ls = popen("ls tests/data/bad_scenes/*.ini", "r");
    cr_assert_not_null(ls);
    char path[256];
    int checked = 0;
    while (fgets(path, sizeof path, ls)) {
        path[strcspn(path, "\n")] = 0;
        /* "$ cat PATH\n<file>$ iskra render PATH --out x.png\n<message>\n" */
        char head[400], cmd[400];
        snprintf(head, sizeof head, "$ cat %s\n", path);
        snprintf(cmd, sizeof cmd, "$ iskra render %s --out x.png\n", path);
        const char *h = strstr(doc, head), *c = strstr(doc, cmd);
        cr_assert(h && c && c > h, "docs/scene-format.md does not show %s", path);
        FILE *bf = fopen(path, "rb");
        cr_assert_not_null(bf);
        char file[4096];
        size_t fl = fread(file, 1, sizeof file - 1, bf);
        fclose(bf);
        file[fl] = 0;
        const char *shown = h + strlen(head);
        cr_assert((size_t)(c - shown) == fl && !memcmp(shown, file, fl), "the page's copy of %s is not the file", path);
        const char *msg = c + strlen(cmd);
        const char *eol = strchr(msg, '\n');
        cr_assert_not_null(eol);
        char want[600];
        snprintf(want, sizeof want, "%.*s\n", (int)(eol - msg + 0), msg);
        char a[300];
        snprintf(a, sizeof a, "describe %s", path);
        cr_assert_eq(run(a), 2, "%s", a);
        cr_expect_str_eq(slurp("stderr.txt"), want, "%s", path);
        checked++;
    }
    pclose(ls);
    cr_assert_geq(checked, 12);
}

Test(scene_cli, write_failure_is_exit_1)
{
    /* --out and --out-dir under a regular file cannot be created */
    FILE *f = fopen(OUT "/plainfile", "w");
    cr_assert_not_null(f);
    fclose(f);
    cr_assert_eq(run("render fig09_stationary_particle --out " OUT "/plainfile/dir/x.png"), 1);
    cr_assert_neq(slurp("stderr.txt")[0], 0);
    cr_assert_eq(run("render fig09_stationary_particle --out-dir " OUT "/plainfile/sub"), 1);
}

Test(scene_cli, play_under_the_dummy_driver)
{
    int rc = run("play fig16_regular --frames 5");
    char *err = slurp("stderr.txt");
    if (rc == 1 && strstr(err, "window"))
        cr_skip("no SDL video available: %s", err);
    cr_assert_eq(rc, 0, "%s", err);
    /* scripted input: substeps up and down, pause twice, reset, overlay off
     * and on, a click (the scene has a [click]), a screenshot */
    char cmd[2048], cwd[512];
    cr_assert_not_null(getcwd(cwd, sizeof cwd));
    snprintf(cmd, sizeof cmd,
             "cd " OUT " && SDL_VIDEODRIVER=dummy %s/%s play %s/scenes/fig26_mushroom_one_potential.ini --frames 6 "
             "--script '+ + kp+ - kp- = space space r h h click:300,300 f12' >stdout.txt 2>stderr.txt",
             bin()[0] == '/' ? "" : cwd, bin(), cwd);
    rc = system(cmd);
    cr_assert(WIFEXITED(rc) && WEXITSTATUS(rc) == 0, "%s\n%s", cmd, slurp("stderr.txt"));
    cr_assert_not_null(strstr(slurp("stderr.txt"), "saved iskra-fig26_mushroom_one_potential-"), "%s",
                       slurp("stderr.txt"));
    cr_assert_eq(run("play fig16_regular --frames 2 --script 'jump'"), 2);
    cr_assert_eq(run("play"), 2);
    cr_assert_eq(run("play fig16_regular --frames x"), 2);
    cr_assert_eq(run("play tests/data/bad_scenes/bad_enum.ini --frames 1"), 2);
}

/* The tests share out/test_scene_cli/ (the commands take fixed paths), so
 * they run one at a time. */
int main(int argc, char *argv[])
{
    struct criterion_test_set *tests = criterion_initialize();
    criterion_options.jobs = 1;
    int result = 0;
    if (criterion_handle_args(argc, argv, true))
        result = !criterion_run_all_tests(tests);
    criterion_finalize(tests);
    return result;
}

/* (its own directory: this suite's setup empties OUT before every test) */
#define TOUT "out/test_scene_cli_threads"

/* A bad ISKRA_THREADS was ignored without a word (the library has no one
 * to tell): the tool says so, and renders on every core all the same. */
Test(scene_cli, a_bad_iskra_threads_is_named)
{
    const char *d = TOUT;
    cli_fresh(d);
    const char *bad[] = {"abc", "0", "1e2", "300"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        cr_assert_eq(setenv("ISKRA_THREADS", bad[i], 1), 0);
        cr_assert_eq(cli_run(d, "render fig19_coulomb --frames 2 --out " TOUT "/x.png"), 0);
        char *err = cli_slurp(TOUT "/stderr.txt");
        char want[160];
        snprintf(want, sizeof want,
                 "iskra render: ISKRA_THREADS=\"%s\" is not a number of threads 1..256: ignored, every core is used\n",
                 bad[i]);
        cr_assert_str_eq(err, want);
        free(err);
        /* --threads makes it moot */
        cr_assert_eq(cli_run(d, "render fig19_coulomb --frames 2 --threads 2 --out " TOUT "/x.png"), 0);
        err = cli_slurp(TOUT "/stderr.txt");
        cr_assert_str_eq(err, "");
        free(err);
    }
    cr_assert_eq(setenv("ISKRA_THREADS", "3", 1), 0);
    cr_assert_eq(cli_run(d, "render fig19_coulomb --frames 2 --out " TOUT "/x.png"), 0);
    char *err = cli_slurp(TOUT "/stderr.txt");
    cr_assert_str_eq(err, "");
    free(err);
    unsetenv("ISKRA_THREADS");
}
