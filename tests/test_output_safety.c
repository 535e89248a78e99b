/* SPDX-License-Identifier: MIT */
/* Outputs never destroy what they replace (iskra/outfile.h): a regular file
 * is replaced atomically with its permissions kept, a symlink is followed
 * (the link stays, its target is replaced), a dangling link, a directory
 * or a socket is refused, and a character device or a FIFO is written
 * through, never replaced.  The commands refuse an output that is one of
 * their inputs.  Nothing here needs root: a FIFO, a socket and symlinks
 * in a scratch directory, and /dev/null, /dev/full as character devices. */
#include <criterion/criterion.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include "iskra/outfile.h"
#include "iskra/png.h"
#include "tool_cli.h"

#define OUT "out/test_output_safety"

static void fresh(const char *dir) { cli_fresh(dir); }

static void picture(isk_canvas *c, int w, int h, uint8_t seed)
{
    cr_assert_eq(isk_canvas_init(c, w, h), ISK_OK);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint8_t *p = isk_canvas_at(c, x, y);
            p[0] = (uint8_t)(x * 9 + seed);
            p[1] = (uint8_t)(y * 5);
            p[2] = seed;
            p[3] = 255;
        }
}

static int temporaries_in(const char *dir) { return cli_count_files(dir, "\\.tmp\\."); }

static mode_t kind(const char *path, int follow)
{
    struct stat st;
    int r = follow ? stat(path, &st) : lstat(path, &st);
    cr_assert_eq(r, 0, "%s: %s", path, strerror(errno));
    return st.st_mode & S_IFMT;
}

static void same_picture(const char *path, const isk_canvas *want)
{
    isk_canvas r;
    isk_error err;
    cr_assert_eq(isk_png_read(&r, path, &err), ISK_OK, "%s", err.message);
    cr_assert(isk_canvas_equal(&r, want), "%s holds another picture", path);
    isk_canvas_free(&r);
}

Test(output_safety, a_regular_file_is_replaced_whole_with_its_permissions)
{
    const char *d = OUT "/regular";
    fresh(d);
    isk_canvas a, b;
    picture(&a, 5, 4, 1);
    picture(&b, 7, 3, 2);
    cr_assert_eq(isk_png_write(&a, OUT "/regular/x.png", NULL), ISK_OK);
    struct stat st;
    cr_assert_eq(stat(OUT "/regular/x.png", &st), 0);
    cr_assert_eq(st.st_mode & 0777, 0644, "a new file is 0644, got %o", (unsigned)(st.st_mode & 0777));
    cr_assert_eq(chmod(OUT "/regular/x.png", 0640), 0);
    cr_assert_eq(isk_png_write(&b, OUT "/regular/x.png", NULL), ISK_OK);
    cr_assert_eq(stat(OUT "/regular/x.png", &st), 0);
    cr_assert_eq(st.st_mode & 0777, 0640, "the replaced file's mode is kept, got %o", (unsigned)(st.st_mode & 0777));
    same_picture(OUT "/regular/x.png", &b);
    /* an aborted write leaves the old file exactly as it was */
    isk_outfile o;
    cr_assert_eq(isk_outfile_open(&o, OUT "/regular/x.png", NULL), ISK_OK);
    cr_assert_not_null(o.temp);
    cr_assert_eq(o.streaming, 0);
    fputs("half a file", o.f);
    isk_outfile_abort(&o);
    same_picture(OUT "/regular/x.png", &b);
    cr_assert_eq(temporaries_in(d), 0);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(output_safety, a_symlink_is_followed_and_stays_a_link)
{
    const char *d = OUT "/symlink";
    fresh(d);
    cr_assert_eq(mkdir(OUT "/symlink/real", 0777), 0);
    isk_canvas a, b;
    picture(&a, 4, 4, 3);
    picture(&b, 6, 2, 4);
    cr_assert_eq(isk_png_write(&a, OUT "/symlink/real/target.png", NULL), ISK_OK);
    cr_assert_eq(symlink("real/target.png", OUT "/symlink/link.png"), 0);
    isk_error err;
    cr_assert_eq(isk_png_write(&b, OUT "/symlink/link.png", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(kind(OUT "/symlink/link.png", 0), S_IFLNK, "the link was replaced by a file");
    same_picture(OUT "/symlink/real/target.png", &b);
    cr_assert_eq(temporaries_in(d), 0);
    cr_assert_eq(temporaries_in(OUT "/symlink/real"), 0);
    /* a dangling link is refused and nothing is created */
    cr_assert_eq(symlink("real/missing.png", OUT "/symlink/dangling.png"), 0);
    cr_assert_eq(isk_png_write(&b, OUT "/symlink/dangling.png", &err), ISK_ERR_IO);
    cr_assert_not_null(strstr(err.message, "symbolic link to a missing file"), "%s", err.message);
    cr_assert_not(cli_exists(OUT "/symlink/real/missing.png"));
    cr_assert_eq(kind(OUT "/symlink/dangling.png", 0), S_IFLNK);
    /* a link to a device is written through to the device */
    cr_assert_eq(symlink("/dev/null", OUT "/symlink/null.png"), 0);
    cr_assert_eq(isk_png_write(&b, OUT "/symlink/null.png", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(kind(OUT "/symlink/null.png", 0), S_IFLNK);
    cr_assert_eq(temporaries_in(d), 0);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

Test(output_safety, a_character_device_is_written_through_never_replaced)
{
    isk_canvas a;
    picture(&a, 8, 8, 5);
    isk_outfile o;
    isk_error err;
    cr_assert_eq(isk_outfile_open(&o, "/dev/null", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(o.streaming, 1, "/dev/null must be streamed into");
    cr_assert_null(o.temp, "no temporary may be made beside /dev/null (as root it would replace it)");
    cr_assert_eq(isk_png_write_stream(&a, o.f, "/dev/null", &err), ISK_OK);
    cr_assert_eq(isk_outfile_commit(&o, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(kind("/dev/null", 1), S_IFCHR);
    cr_assert_eq(isk_png_write(&a, "/dev/null", &err), ISK_OK, "%s", err.message);
    /* a device that fails: the error is reported, the device stays */
    if (cli_exists("/dev/full")) {
        cr_assert_eq(isk_png_write(&a, "/dev/full", &err), ISK_ERR_IO);
        cr_assert_not_null(strstr(err.message, "/dev/full"), "%s", err.message);
        cr_assert_eq(kind("/dev/full", 1), S_IFCHR);
    }
    isk_canvas_free(&a);
}

Test(output_safety, a_fifo_is_streamed_to_its_reader, .timeout = 30)
{
    const char *d = OUT "/fifo";
    fresh(d);
    cr_assert_eq(mkfifo(OUT "/fifo/pipe.png", 0644), 0);
    isk_canvas a;
    picture(&a, 16, 9, 6);
    pid_t pid = cli_drain_fifo(OUT "/fifo/pipe.png", OUT "/fifo/copy.png");
    isk_error err;
    cr_assert_eq(isk_png_write(&a, OUT "/fifo/pipe.png", &err), ISK_OK, "%s", err.message);
    int status;
    cr_assert_eq(waitpid(pid, &status, 0), pid);
    cr_assert(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    cr_assert_eq(kind(OUT "/fifo/pipe.png", 0), S_IFIFO, "the FIFO was replaced");
    same_picture(OUT "/fifo/copy.png", &a);
    cr_assert_eq(temporaries_in(d), 0);
    /* the command line does the same: iskra render ... --out FIFO */
    pid = cli_drain_fifo(OUT "/fifo/pipe.png", OUT "/fifo/render.png");
    cr_assert_eq(cli_run(d, "render fig09_stationary_particle --out " OUT "/fifo/pipe.png"), 0);
    cr_assert_eq(waitpid(pid, &status, 0), pid);
    cr_assert_eq(kind(OUT "/fifo/pipe.png", 0), S_IFIFO);
    isk_canvas ref;
    cr_assert_eq(isk_png_read(&ref, "refimg/fig09_stationary_particle.png", NULL), ISK_OK);
    same_picture(OUT "/fifo/render.png", &ref);
    isk_canvas_free(&ref);
    isk_canvas_free(&a);
}

Test(output_safety, directories_and_sockets_are_refused)
{
    const char *d = OUT "/refused";
    fresh(d);
    cr_assert_eq(mkdir(OUT "/refused/dir.png", 0777), 0);
    isk_canvas a;
    picture(&a, 3, 3, 7);
    isk_error err;
    cr_assert_eq(isk_png_write(&a, OUT "/refused/dir.png", &err), ISK_ERR_IO);
    cr_assert_not_null(strstr(err.message, "is a directory"), "%s", err.message);
    cr_assert_eq(kind(OUT "/refused/dir.png", 0), S_IFDIR);
    int s = socket(AF_UNIX, SOCK_STREAM, 0);
    cr_assert_geq(s, 0);
    struct sockaddr_un addr;
    memset(&addr, 0, sizeof addr);
    addr.sun_family = AF_UNIX;
    snprintf(addr.sun_path, sizeof addr.sun_path, OUT "/refused/sock.png");
    cr_assert_eq(bind(s, (struct sockaddr *)&addr, sizeof addr), 0, "%s", strerror(errno));
    cr_assert_eq(isk_png_write(&a, OUT "/refused/sock.png", &err), ISK_ERR_IO);
    cr_assert_eq(kind(OUT "/refused/sock.png", 0), S_IFSOCK);
    close(s);
    cr_assert_eq(isk_png_write(&a, "", &err), ISK_ERR_IO);
    cr_assert_eq(temporaries_in(d), 0);
    isk_canvas_free(&a);
}

static char *slurp_bytes(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    cr_assert_not_null(f, "%s", path);
    static char buf[1 << 16];
    *n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    char *copy = malloc(*n);
    memcpy(copy, buf, *n);
    return copy;
}

static void unchanged(const char *path, const char *before, size_t n)
{
    size_t m;
    char *now = slurp_bytes(path, &m);
    cr_assert(m == n && !memcmp(now, before, n), "%s was changed", path);
    free(now);
}

Test(output_safety, commands_refuse_to_overwrite_their_inputs)
{
    const char *d = OUT "/inputs";
    fresh(d);
    isk_canvas a, b;
    picture(&a, 6, 6, 8);
    picture(&b, 6, 6, 9);
    cr_assert_eq(isk_png_write(&a, OUT "/inputs/a.png", NULL), ISK_OK);
    cr_assert_eq(isk_png_write(&b, OUT "/inputs/b.png", NULL), ISK_OK);
    size_t na, ns;
    char *abytes = slurp_bytes(OUT "/inputs/a.png", &na);
    cr_assert_eq(system("cp scenes/fig12_gravity.ini " OUT "/inputs/s.ini"), 0);
    char *sbytes = slurp_bytes(OUT "/inputs/s.ini", &ns);
    cr_assert_eq(symlink("a.png", OUT "/inputs/alias.png"), 0);
    const char *refused[] = {
        "compare --diff " OUT "/inputs/a.png " OUT "/inputs/a.png " OUT "/inputs/b.png",
        "compare " OUT "/inputs/a.png " OUT "/inputs/b.png --diff " OUT "/inputs/b.png",
        "compare " OUT "/inputs/b.png " OUT "/inputs/a.png --diff " OUT "/inputs/alias.png",
        "compare " OUT "/inputs/b.png " OUT "/inputs/a.png --diff " OUT "/inputs/../inputs/a.png",
        "render " OUT "/inputs/s.ini --out " OUT "/inputs/s.ini",
        "render " OUT "/inputs/s.ini --out ./" OUT "/inputs/s.ini",
    };
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        cr_assert_eq(cli_run(d, refused[i]), 2, "%s", refused[i]);
        char *err = cli_slurp(OUT "/inputs/stderr.txt");
        cr_assert_not_null(strstr(err, "refusing to overwrite the input"), "%s: %s", refused[i], err);
        free(err);
    }
    unchanged(OUT "/inputs/a.png", abytes, na);
    unchanged(OUT "/inputs/s.ini", sbytes, ns);
    cr_assert_eq(kind(OUT "/inputs/alias.png", 0), S_IFLNK);
    /* other outputs are fine, /dev/null included */
    cr_assert_eq(cli_run(d, "compare " OUT "/inputs/a.png " OUT "/inputs/b.png --diff " OUT "/inputs/d.png"), 1);
    cr_assert(cli_exists(OUT "/inputs/d.png"));
    cr_assert_eq(cli_run(d, "compare " OUT "/inputs/a.png " OUT "/inputs/b.png --diff /dev/null"), 1);
    cr_assert_eq(cli_run(d, "render " OUT "/inputs/s.ini --out /dev/null"), 0);
    cr_assert_eq(kind("/dev/null", 1), S_IFCHR);
    free(abytes);
    free(sbytes);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}
