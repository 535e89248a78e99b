/* SPDX-License-Identifier: MIT */
/* An interrupted render leaves nothing half-written: SIGINT, SIGTERM,
 * SIGHUP and SIGPIPE remove the temporary files and exit with 128 + the
 * signal; a sequence render says which frames were written, and --resume
 * keeps them and writes the rest, to the same bytes as one whole run.
 * The tool is started with fork/exec (not through a shell, which would
 * ignore SIGINT for a background job). */
#include <criterion/criterion.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "iskra/png.h"
#include "refimg.h"
#include "tool_cli.h"

#define OUT "out/test_render_signals"

static void nap(void)
{
    struct timespec ts = {0, 20 * 1000 * 1000};
    nanosleep(&ts, NULL);
}

/* Waits until dir holds at least n frame files (or 60 s). */
static void wait_for_frames(const char *dir, int n)
{
    for (int i = 0; i < 3000 && cli_count_files(dir, "^frame_.*png$") < n; i++)
        nap();
    cr_assert_geq(cli_count_files(dir, "^frame_.*png$"), n, "the render did not get going");
}

static int exit_status(pid_t pid)
{
    int st;
    cr_assert_eq(waitpid(pid, &st, 0), pid);
    cr_assert(WIFEXITED(st), "killed by signal %d instead of exiting", WIFSIGNALED(st) ? WTERMSIG(st) : 0);
    return WEXITSTATUS(st);
}

Test(render_signals, a_sequence_interrupted_says_what_it_wrote_and_resumes, .timeout = 240)
{
    const char *d = OUT "/resume";
    cli_fresh(d);
    const char *args[] = {"render", "fig16_regular", "--frames", "100000", "--every", "2", "--out-dir", OUT "/resume/seq",
                          NULL};
    pid_t pid = cli_start(d, -1, 0, args);
    wait_for_frames(OUT "/resume/seq", 4);
    cr_assert_eq(kill(pid, SIGTERM), 0);
    cr_assert_eq(exit_status(pid), 128 + SIGTERM);
    cr_assert_eq(cli_count_files(OUT "/resume/seq", "\\.tmp\\."), 0, "a temporary was left behind");
    char *err = cli_slurp(OUT "/resume/stderr.txt");
    int n = cli_count_files(OUT "/resume/seq", "^frame_.*png$");
    long last = 2L * (n - 1);
    char want[256];
    snprintf(want, sizeof want,
             "iskra render: interrupted by SIGTERM; " OUT "/resume/seq: frames 0 to %ld (every 2) were written (%d files); "
             "rerun with --resume to continue\n",
             last, n);
    cr_assert_str_eq(err, want);
    free(err);
    /* every file there is whole */
    for (long f = 0; f <= last; f += 2) {
        char path[256];
        snprintf(path, sizeof path, OUT "/resume/seq/frame_%06ld.png", f);
        isk_canvas c;
        isk_error e;
        cr_assert_eq(isk_png_read(&c, path, &e), ISK_OK, "%s", e.message);
        isk_canvas_free(&c);
    }
    /* --resume keeps them (same inode: not rewritten) and writes the rest */
    struct stat before;
    cr_assert_eq(stat(OUT "/resume/seq/frame_000000.png", &before), 0);
    FILE *junk = fopen(OUT "/resume/seq/frame_000002.png", "wb"); /* not a PNG: written again */
    fputs("junk", junk);
    fclose(junk);
    char args2[256];
    snprintf(args2, sizeof args2, "render fig16_regular --frames %ld --every 2 --out-dir " OUT "/resume/seq --resume",
             last + 6);
    cr_assert_eq(cli_run(d, args2), 0, "%s", cli_slurp(OUT "/resume/stderr.txt"));
    struct stat after;
    cr_assert_eq(stat(OUT "/resume/seq/frame_000000.png", &after), 0);
    cr_assert_eq(before.st_ino, after.st_ino, "a finished frame was written again");
    err = cli_slurp(OUT "/resume/stderr.txt");
    snprintf(want, sizeof want, "iskra render: " OUT "/resume/seq: 4 frames written, %d already there kept\n", n - 1);
    cr_assert_str_eq(err, want);
    free(err);
    /* the result is the same as one whole render */
    snprintf(args2, sizeof args2, "render fig16_regular --frames %ld --every 2 --out-dir " OUT "/resume/whole", last + 6);
    cr_assert_eq(cli_run(d, args2), 0);
    for (long f = 0; f <= last + 6; f += 2) {
        char a[256], b[256];
        snprintf(a, sizeof a, OUT "/resume/seq/frame_%06ld.png", f);
        snprintf(b, sizeof b, OUT "/resume/whole/frame_%06ld.png", f);
        isk_canvas x, y;
        cr_assert_eq(isk_png_read(&x, a, NULL), ISK_OK, "%s", a);
        cr_assert_eq(isk_png_read(&y, b, NULL), ISK_OK, "%s", b);
        cr_assert(isk_canvas_equal(&x, &y), "frame %ld differs after resuming", f);
        isk_canvas_free(&x);
        isk_canvas_free(&y);
    }
}

/* Each signal during an animation: no temporary, no output, 128 + sig. */
Test(render_signals, every_signal_removes_the_temporaries, .timeout = 240)
{
    const int sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
    const char *names[] = {"SIGINT", "SIGTERM", "SIGHUP", "SIGPIPE"};
    const char *outs[] = {OUT "/sigs/a.gif", OUT "/sigs/a.y4m", OUT "/sigs/seq/x.png", OUT "/sigs/a.gif"};
    for (int k = 0; k < 4; k++) {
        const char *d = OUT "/sigs";
        cli_fresh(d);
        const char *args[] = {"render", "fire_campfire", "--frames", "100000", "--out", outs[k], NULL};
        /* the PNG case: a sequence too, so there is something to wait for */
        const char *seq_args[] = {"render", "fire_campfire", "--frames", "100000", "--out", outs[k],
                                  "--out-dir", OUT "/sigs/seq", NULL};
        pid_t pid = cli_start(d, -1, 0, k == 2 ? seq_args : args);
        if (k == 2) {
            wait_for_frames(OUT "/sigs/seq", 2);
        } else {
            /* until the temporary exists */
            for (int i = 0; i < 3000 && cli_count_files(d, "\\.tmp\\.") < 1; i++)
                nap();
            cr_assert_eq(cli_count_files(d, "\\.tmp\\."), 1, "%s: no temporary to remove", names[k]);
        }
        cr_assert_eq(kill(pid, sigs[k]), 0);
        cr_assert_eq(exit_status(pid), 128 + sigs[k], "%s", names[k]);
        cr_assert_eq(cli_count_files(d, "\\.tmp\\."), 0, "%s left a temporary", names[k]);
        cr_assert_eq(cli_count_files(OUT "/sigs/seq", "\\.tmp\\."), 0, "%s left a temporary", names[k]);
        cr_assert_not(cli_exists(outs[k]), "%s: the unfinished output exists", names[k]);
        char *err = cli_slurp(OUT "/sigs/stderr.txt");
        char want[64];
        snprintf(want, sizeof want, "interrupted by %s", names[k]);
        cr_assert_not_null(strstr(err, want), "%s", err);
        free(err);
    }
}

/* A reader that goes away: SIGPIPE, exit 141, and the message says what
 * was streamed (the reader took frame 0 whole: it was not "nothing"). */
Test(render_signals, a_closed_pipe_ends_a_raw_render, .timeout = 120)
{
    const char *d = OUT "/pipe";
    cli_fresh(d);
    int fds[2];
    cr_assert_eq(pipe(fds), 0);
    cr_assert_eq(fcntl(fds[0], F_SETFD, FD_CLOEXEC), 0); /* the tool must not hold its own reader */
    const char *args[] = {"render", "fire_campfire", "--frames", "100000", "--raw", "--out", "-", NULL};
    pid_t pid = cli_start(d, fds[1], 0, args);
    close(fds[1]);
    static char buf[480 * 400 * 4];
    size_t got = 0;
    while (got < sizeof buf) {
        ssize_t r = read(fds[0], buf + got, sizeof buf - got);
        cr_assert_gt(r, 0);
        got += (size_t)r;
    }
    close(fds[0]);
    cr_assert_eq(exit_status(pid), 128 + SIGPIPE);
    char *err = cli_slurp(OUT "/pipe/stderr.txt");
    cr_assert_str_eq(err, "iskra render: interrupted by SIGPIPE; standard output: frame 0 was streamed (1 frame)\n");
    free(err);
}
