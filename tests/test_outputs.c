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

/* Reads the FIFO to its end in a child process, copying it into `copy`. */
static pid_t drain(const char *fifo, const char *copy)
{
    pid_t pid = fork();
    cr_assert_neq(pid, -1);
    if (pid == 0) {
        int in = open(fifo, O_RDONLY), out = open(copy, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        char buf[4096];
        ssize_t n;
        while (in >= 0 && out >= 0 && (n = read(in, buf, sizeof buf)) > 0)
            if (write(out, buf, (size_t)n) != n)
                _exit(1);
        _exit(in < 0 || out < 0);
    }
    return pid;
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
    pid_t pid = drain(OUT "/state_kinds/pipe.csv", OUT "/state_kinds/copy.csv");
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
    pid_t pid = drain(OUT "/save_kinds/pipe.ini", OUT "/save_kinds/copy.ini");
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
    const char *as_input[] = {"--out", "--strip", "--state"};
    for (int k = 0; k < 3; k++) {
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
