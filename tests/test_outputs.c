/* SPDX-License-Identifier: MIT */
/* What the tool and the library write, against what is already there:
 *
 *   - every writer goes through the one output path (iskra/outfile.h): a
 *     symlink stays a link, a FIFO or a device stays what it is, an
 *     existing file keeps its mode (--state, the simulator's save,
 *     isk_scene_save);
 *   - no output replaces an input (the scene, its textures) or another
 *     output of the same command;
 *   - nothing half-written survives a signal, a file size limit or a
 *     killed writer, messages say what was written (streams too), and
 *     --resume rewrites a truncated frame.
 *
 * Nothing here needs root: FIFOs and symlinks in scratch directories. */
#include <criterion/criterion.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "iskra/outfile.h"
#include "iskra/png.h"
#include "iskra/scene.h"
#include "play_session.h"
#include "refimg.h"
#include "tool_cli.h"

#define OUT "out/test_outputs"

static mode_t kind_of(const char *path)
{
    struct stat st;
    cr_assert_eq(lstat(path, &st), 0, "%s: %s", path, strerror(errno));
    return st.st_mode & S_IFMT;
}

static unsigned mode_of(const char *path)
{
    struct stat st;
    cr_assert_eq(stat(path, &st), 0, "%s: %s", path, strerror(errno));
    return (unsigned)(st.st_mode & 07777);
}

static int starts_with_file(const char *path, const char *prefix)
{
    char *text = cli_slurp(path);
    int yes = strncmp(text, prefix, strlen(prefix)) == 0;
    free(text);
    return yes;
}

static void drained(pid_t pid)
{
    int st;
    cr_assert_eq(waitpid(pid, &st, 0), pid);
    cr_assert(WIFEXITED(st) && WEXITSTATUS(st) == 0, "the FIFO's reader failed");
}

#define CSV_HEADER "emitter,index,x,y,vx,vy,mass,age,life\n"

/* --state went through its own temporary and rename: it replaced a
 * symlink by a file and a FIFO by a file (as root, /dev/null by a file). */
Test(outputs, state_keeps_links_fifos_and_modes, .timeout = 60)
{
    const char *d = OUT "/state_kinds";
    cli_fresh(d);
    cli_write_file(OUT "/state_kinds/real.csv", "old\n");
    cr_assert_eq(chmod(OUT "/state_kinds/real.csv", 0600), 0);
    cr_assert_eq(symlink("real.csv", OUT "/state_kinds/link.csv"), 0);
    cr_assert_eq(cli_run(d, "render fig19_coulomb --frames 3 --state " OUT "/state_kinds/link.csv"), 0, "%s",
                 cli_slurp(OUT "/state_kinds/stderr.txt"));
    cr_assert_eq(kind_of(OUT "/state_kinds/link.csv"), S_IFLNK, "--state replaced the symlink");
    cr_assert(starts_with_file(OUT "/state_kinds/real.csv", CSV_HEADER), "the link's target was not written");
    cr_assert_eq(mode_of(OUT "/state_kinds/real.csv"), 0600, "the mode became %o", mode_of(OUT "/state_kinds/real.csv"));

    cr_assert_eq(mkfifo(OUT "/state_kinds/pipe.csv", 0644), 0);
    pid_t pid = cli_drain_fifo(OUT "/state_kinds/pipe.csv", OUT "/state_kinds/copy.csv");
    cr_assert_eq(cli_run(d, "render fig19_coulomb --frames 3 --state " OUT "/state_kinds/pipe.csv"), 0);
    drained(pid);
    cr_assert_eq(kind_of(OUT "/state_kinds/pipe.csv"), S_IFIFO, "--state replaced the FIFO");
    cr_assert(starts_with_file(OUT "/state_kinds/copy.csv", CSV_HEADER), "the FIFO's reader got no CSV");
    /* a device is written through (the test is not root: /dev/null could
     * not be replaced here, but the path is the same one) */
    cr_assert_eq(cli_run(d, "render fig19_coulomb --frames 3 --state /dev/null"), 0);
    cr_assert_eq(kind_of("/dev/null"), S_IFCHR);
    cr_assert_eq(cli_count_files(d, "\\.tmp\\."), 0);
}

/* The library's save and the simulator's Save (F2): a 0600 file stays
 * 0600, a link stays a link, a device or FIFO is written through. */
Test(outputs, saves_keep_links_fifos_and_modes, .timeout = 120)
{
    const char *d = OUT "/save_kinds";
    cli_fresh(d);
    isk_effect_def def;
    isk_error err;
    cr_assert_eq(isk_scene_load_file(&def, "scenes/fig19_coulomb.ini", &err), ISK_OK, "%s", err.message);
    char *text;
    cr_assert_eq(isk_scene_write(&def, &text, &err), ISK_OK, "%s", err.message);

    cli_write_file(OUT "/save_kinds/real.ini", "; mine\n");
    cr_assert_eq(chmod(OUT "/save_kinds/real.ini", 0600), 0);
    cr_assert_eq(symlink("real.ini", OUT "/save_kinds/link.ini"), 0);
    cr_assert_eq(isk_scene_save(&def, OUT "/save_kinds/link.ini", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(kind_of(OUT "/save_kinds/link.ini"), S_IFLNK);
    cr_assert_eq(mode_of(OUT "/save_kinds/real.ini"), 0600);
    char *saved = cli_slurp(OUT "/save_kinds/real.ini");
    cr_assert_str_eq(saved, text);
    free(saved);

    cr_assert_eq(isk_scene_save(&def, "/dev/null", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(kind_of("/dev/null"), S_IFCHR);
    cr_assert_eq(mkfifo(OUT "/save_kinds/pipe.ini", 0644), 0);
    pid_t pid = cli_drain_fifo(OUT "/save_kinds/pipe.ini", OUT "/save_kinds/copy.ini");
    cr_assert_eq(isk_scene_save(&def, OUT "/save_kinds/pipe.ini", &err), ISK_OK, "%s", err.message);
    drained(pid);
    cr_assert_eq(kind_of(OUT "/save_kinds/pipe.ini"), S_IFIFO);
    saved = cli_slurp(OUT "/save_kinds/copy.ini");
    cr_assert_str_eq(saved, text);
    free(saved);
    free(text);
    isk_effect_def_free(&def);

    /* the simulator's Save, over a 0600 file through a link */
    cli_fresh(OUT "/save_kinds/play");
    cli_write_file(OUT "/save_kinds/play/mine.ini", "; mine\n");
    cr_assert_eq(chmod(OUT "/save_kinds/play/mine.ini", 0600), 0);
    cr_assert_eq(symlink("mine.ini", OUT "/save_kinds/play/s.ini"), 0);
    char args[512];
    snprintf(args, sizeof args, "play --fixed-clock fig19_coulomb --ui-scale 1 --frames 10 --save %s --script 'wait:2 f2'",
             OUT "/save_kinds/play/s.ini");
    cr_assert_eq(cli_run(OUT "/save_kinds/play", args), 0, "%s", cli_slurp(OUT "/save_kinds/play/stderr.txt"));
    cr_assert_eq(kind_of(OUT "/save_kinds/play/s.ini"), S_IFLNK, "the save replaced the link");
    cr_assert_eq(mode_of(OUT "/save_kinds/play/mine.ini"), 0600, "the save changed the mode");
    cr_assert(starts_with_file(OUT "/save_kinds/play/mine.ini", "; an iskra scene"));
    cr_assert_eq(cli_count_files(OUT "/save_kinds/play", "\\.tmp\\."), 0);
}

/* Runs iskra ARGS in dir and expects exit 2 with `want` on stderr. */
static void refused(const char *dir, const char *args, const char *want)
{
    cr_assert_eq(cli_run(dir, args), 2, "%s was not refused", args);
    char p[256];
    snprintf(p, sizeof p, "%s/stderr.txt", dir);
    char *err = cli_slurp(p);
    cr_assert_not_null(strstr(err, want), "%s: %s", args, err);
    free(err);
}

static char *file_bytes(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    cr_assert_not_null(f, "%s", path);
    fseek(f, 0, SEEK_END);
    *n = (size_t)ftell(f);
    rewind(f);
    char *b = malloc(*n + 1);
    cr_assert_eq(fread(b, 1, *n, f), *n);
    fclose(f);
    return b;
}

/* Before, only the scene itself was checked: --out, --strip and --state
 * overwrote the scene's texture, and two outputs with one name lost one. */
Test(outputs, no_output_replaces_an_input_or_another_output, .timeout = 120)
{
    const char *d = OUT "/clash";
    cli_fresh(d);
    cr_assert_eq(system("mkdir -p " OUT "/clash/textures " OUT "/clash/seq && cp scenes/preset_magic.ini " OUT
                        "/clash/ && cp scenes/textures/sparkle.png " OUT "/clash/textures/ && cp "
                        "scenes/textures/sparkle.png " OUT "/clash/seq/frame_000004.png"),
                 0);
    size_t n;
    char *before = file_bytes(OUT "/clash/textures/sparkle.png", &n);
    const char *scene = OUT "/clash/preset_magic.ini ";
    const char *tex = OUT "/clash/textures/sparkle.png";
    char args[1024];
    const char *as_input[] = {"--out", "--strip", "--state", "--snapshot"};
    for (int k = 0; k < 4; k++) {
        snprintf(args, sizeof args, "render %s--frames 6 %s%s %s", scene, k == 1 ? "--every 2 " : "", as_input[k], tex);
        refused(d, args, "refusing to overwrite the input " OUT "/clash/textures/sparkle.png (a texture of the scene)");
    }
    /* another spelling of the texture, through a link to its directory */
    cr_assert_eq(symlink("textures", OUT "/clash/t"), 0);
    snprintf(args, sizeof args, "render %s--out " OUT "/clash/t/../textures/./sparkle.png", scene);
    refused(d, args, "(a texture of the scene)");
    snprintf(args, sizeof args, "render %s--out " OUT "/clash/t/sparkle.png", scene);
    refused(d, args, "(a texture of the scene)");
    /* a texture that a sequence would overwrite */
    cli_write_file(OUT "/clash/seq.ini", "[scene]\nframes = 8\n[emitter e]\nsource = particle\nposition = 0, 0\n"
                                         "texture = seq/frame_000004.png\n");
    refused(d, "render " OUT "/clash/seq.ini --every 2 --out-dir " OUT "/clash/seq",
            "with number 4 of --out-dir " OUT "/clash/seq");
    cr_assert_eq(cli_run(d, "render " OUT "/clash/seq.ini --every 3 --out-dir " OUT "/clash/seq2"), 0, "%s",
                 cli_slurp(OUT "/clash/stderr.txt"));
    unsigned char *after = (unsigned char *)file_bytes(tex, &n);
    cr_assert(!memcmp(before, after, n), "the texture was changed");
    free(after);
    free(before);

    /* two outputs with one name */
    refused(d, "render fig19_coulomb --frames 4 --out " OUT "/clash/a.gif --state " OUT "/clash/a.gif",
            "--out " OUT "/clash/a.gif and --state " OUT "/clash/a.gif are the same file");
    refused(d, "render fig19_coulomb --frames 4 --every 2 --out " OUT "/clash/p.png --strip " OUT "/clash/p.png",
            "are the same file: one output would replace the other");
    refused(d, "render fig19_coulomb --frames 4 --out " OUT "/clash/new/../p.png --state ./" OUT "/clash/p.png",
            "are the same file");
    refused(d, "render fig19_coulomb --frames 4 --every 2 --out-dir " OUT "/clash/o --out " OUT "/clash/o/frame_000002.png",
            "is number 2 of --out-dir");
    refused(d, "render fig19_coulomb --frames 4 --out-dir " OUT "/clash/o --state-every 2 --state " OUT
               "/clash/o/state_000004.csv",
            "is number 4 of --state-every");
    cr_assert(!cli_exists(OUT "/clash/a.gif") && !cli_exists(OUT "/clash/p.png") && !cli_exists(OUT "/clash/o"),
              "a refused command wrote something");
    /* names that only look alike are fine, and so is /dev/null twice */
    cr_assert_eq(cli_run(d, "render fig19_coulomb --frames 4 --every 2 --out-dir " OUT "/clash/o --out " OUT
                            "/clash/o/frame_000003.png --state " OUT "/clash/o/state_000002.csv"),
                 0, "%s", cli_slurp(OUT "/clash/stderr.txt"));
    cr_assert_eq(cli_run(d, "render fig19_coulomb --frames 4 --out /dev/null --state /dev/null"), 0);
    /* the simulator's --save */
    snprintf(args, sizeof args, "play --fixed-clock %s--frames 2 --save %s", scene, tex);
    refused(d, args, "(a texture of the scene) with the output");
    snprintf(args, sizeof args, "play --fixed-clock %s--frames 2 --save " OUT "/clash/./preset_magic.ini", scene);
    refused(d, args, "(the scene)");
}

static int exit_status(pid_t pid)
{
    int st;
    cr_assert_eq(waitpid(pid, &st, 0), pid);
    cr_assert(WIFEXITED(st), "killed by signal %d instead of exiting", WIFSIGNALED(st) ? WTERMSIG(st) : 0);
    return WEXITSTATUS(st);
}

static void nap(void)
{
    struct timespec ts = {0, 10 * 1000 * 1000};
    nanosleep(&ts, NULL);
}

/* --state-every had its own temporary, unknown to the signal handler, and
 * the message counted only frames ("nothing was written" without
 * --out-dir frames).  Signals land at different points of the writes. */
Test(outputs, a_signal_during_state_files_leaves_none_half_written, .timeout = 240)
{
    const int sigs[] = {SIGINT, SIGTERM, SIGINT};
    for (int k = 0; k < 3; k++) {
        const char *d = OUT "/sig_state";
        cli_fresh(d);
        const char *args[] = {"render", "fire_campfire", "--frames", "100000", "--every", "1000", "--out-dir",
                              OUT "/sig_state/seq", "--state-every", "1", NULL};
        pid_t pid = cli_start(d, -1, 0, args);
        for (int i = 0; i < 3000 && cli_count_files(OUT "/sig_state/seq", "^state_.*csv$") < 3 + 5 * k; i++)
            nap();
        cr_assert_eq(kill(pid, sigs[k]), 0);
        cr_assert_eq(exit_status(pid), 128 + sigs[k]);
        cr_assert_eq(cli_count_files(OUT "/sig_state/seq", "\\.tmp\\."), 0, "a temporary was left behind");
        const int n = cli_count_files(OUT "/sig_state/seq", "^state_.*csv$");
        char *err = cli_slurp(OUT "/sig_state/stderr.txt");
        char want[256];
        snprintf(want, sizeof want,
                 "; " OUT "/sig_state/seq: frame 0 was written (1 file); " OUT "/sig_state/seq: states 0 to %d were "
                 "written (%d files); rerun with --resume to continue\n",
                 n - 1, n);
        cr_assert_not_null(strstr(err, want), "%s\nwanted: %s", err, want);
        free(err);
    }
}

/* Past `ulimit -f` the tool was killed by SIGXFSZ: no message, and the
 * temporary stayed.  Now the write fails like a full disk. */
Test(outputs, a_file_size_limit_is_reported_and_cleaned_up, .timeout = 120)
{
    const char *d = OUT "/fsize";
    const char *outs[][2] = {{"--out", OUT "/fsize/a.gif"}, {"--state", OUT "/fsize/s.csv"},
                             {"--out", OUT "/fsize/a.png"}, {"--snapshot", OUT "/fsize/a.snap"}};
    for (int k = 0; k < 4; k++) {
        cli_fresh(d);
        const char *args[] = {"render", "fire_campfire", "--frames", "40", outs[k][0], outs[k][1], NULL};
        pid_t pid = cli_start(d, -1, 2048, args);
        cr_assert_eq(exit_status(pid), 1, "%s", outs[k][1]);
        char *err = cli_slurp(OUT "/fsize/stderr.txt");
        cr_assert_not_null(strstr(err, outs[k][1]), "%s", err);
        cr_assert_not_null(strstr(err, "File too large"), "%s", err);
        free(err);
        cr_assert_not(cli_exists(outs[k][1]), "a part of %s was left", outs[k][1]);
        cr_assert_eq(cli_count_files(d, "\\.tmp\\."), 0, "a temporary was left behind");
    }
}

/* --resume checked a frame's PNG header only: a frame cut short after
 * its header was kept. */
Test(outputs, resume_writes_a_truncated_frame_again, .timeout = 120)
{
    const char *d = OUT "/resume";
    cli_fresh(d);
    cr_assert_eq(cli_run(d, "render fig16_regular --frames 6 --every 2 --out-dir " OUT "/resume/seq"), 0);
    cr_assert_eq(system("cp -r " OUT "/resume/seq " OUT "/resume/whole"), 0);
    const char *cut = OUT "/resume/seq/frame_000004.png";
    struct stat st;
    cr_assert_eq(stat(cut, &st), 0);
    cr_assert_eq(truncate(cut, st.st_size / 2), 0);
    isk_png_info info;
    cr_assert_eq(isk_png_read_info(cut, &info, NULL), ISK_OK, "the cut frame must keep its header for this test");
    cr_assert_eq(cli_run(d, "render fig16_regular --frames 6 --every 2 --out-dir " OUT "/resume/seq --resume"), 0);
    char *err = cli_slurp(OUT "/resume/stderr.txt");
    cr_assert_str_eq(err, "iskra render: " OUT "/resume/seq: 1 frames written, 3 already there kept\n");
    free(err);
    isk_canvas a, b;
    cr_assert_eq(isk_png_read(&a, cut, NULL), ISK_OK);
    cr_assert_eq(isk_png_read(&b, OUT "/resume/whole/frame_000004.png", NULL), ISK_OK);
    cr_assert(isk_canvas_equal(&a, &b));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

/* A run killed by SIGKILL leaves its temporaries; the next run writing
 * the same outputs removes them, and only them: not one a running writer
 * holds, not another file's. */
Test(outputs, a_later_run_removes_its_old_temporaries, .timeout = 120)
{
    const char *d = OUT "/stale";
    cli_fresh(d);
    cr_assert_eq(system("mkdir -p " OUT "/stale/seq"), 0);
    const char *stale[] = {OUT "/stale/x.png.tmp.abcdef", OUT "/stale/seq/frame_000002.png.tmp.ghijkl",
                           OUT "/stale/seq/state_000000.csv.tmp.mnopqr"};
    const char *kept[] = {OUT "/stale/other.png.tmp.abcdef", OUT "/stale/x.png.tmp.toolong",
                          OUT "/stale/seq/frame_x.png.tmp.abcdef", OUT "/stale/seq/notes.txt"};
    for (int i = 0; i < 3; i++)
        cli_write_file(stale[i], "half");
    for (int i = 0; i < 4; i++)
        cli_write_file(kept[i], "other");
    isk_outfile live;
    cr_assert_eq(isk_outfile_open(&live, OUT "/stale/x.png", NULL), ISK_OK);
    cr_assert_eq(isk_outfile_remove_stale(live.temp), 0, "a live temporary was taken for a stale one");
    cr_assert_eq(cli_run(d, "render fig16_regular --frames 4 --every 2 --out " OUT "/stale/x.png --out-dir " OUT
                            "/stale/seq --state-every 2"),
                 0);
    char *err = cli_slurp(OUT "/stale/stderr.txt");
    cr_assert_str_eq(err, "iskra render: removed 3 temporary files that an interrupted run left\n");
    free(err);
    for (int i = 0; i < 3; i++)
        cr_assert_not(cli_exists(stale[i]), "%s is still there", stale[i]);
    for (int i = 0; i < 4; i++)
        cr_assert(cli_exists(kept[i]), "%s was removed", kept[i]);
    cr_assert(cli_exists(live.temp), "the running writer's temporary was removed");
    isk_outfile_abort(&live);
    cr_assert_eq(cli_count_files(d, "\\.tmp\\."), 2);
}
