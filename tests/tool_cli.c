/* SPDX-License-Identifier: MIT */
/* Running the built `iskra` command from a test (see tool_cli.h). */
#include "tool_cli.h"

#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "iskra/png.h"
#include "refimg.h"

void cli_fresh(const char *dir)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "rm -rf %s && mkdir -p %s", dir, dir);
    cr_assert_eq(system(cmd), 0, "%s", cmd);
}

int cli_run(const char *dir, const char *args)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "SDL_VIDEODRIVER=dummy %s/bin/iskra %s >%s/stdout.txt 2>%s/stderr.txt",
             refimg_build_dir(), args, dir, dir);
    int rc = system(cmd);
    cr_assert(WIFEXITED(rc), "%s did not exit normally", cmd);
    return WEXITSTATUS(rc);
}

/* `path` made absolute against the repository root (the tests' cwd). */
static void absolute(const char *path, char *out, size_t n)
{
    char cwd[512];
    cr_assert_not_null(getcwd(cwd, sizeof cwd));
    snprintf(out, n, "%s%s%s", path[0] == '/' ? "" : cwd, path[0] == '/' ? "" : "/", path);
}

int cli_run_in(const char *cwd, const char *dir, const char *args)
{
    char tool[1024], d[1024], c[1024], cmd[16384];
    snprintf(cmd, sizeof cmd, "%s/bin/iskra", refimg_build_dir());
    absolute(cmd, tool, sizeof tool);
    absolute(dir, d, sizeof d);
    absolute(cwd, c, sizeof c);
    snprintf(cmd, sizeof cmd, "cd '%s' && SDL_VIDEODRIVER=dummy '%s' %s >'%s/stdout.txt' 2>'%s/stderr.txt'", c, tool,
             args, d, d);
    int rc = system(cmd);
    cr_assert(WIFEXITED(rc), "%s did not exit normally", cmd);
    return WEXITSTATUS(rc);
}

char *cli_slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    cr_assert_not_null(f, "%s is missing", path);
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    cr_assert_geq(n, 0, "%s", path);
    char *buf = malloc((size_t)n + 1);
    cr_assert_not_null(buf);
    cr_assert_eq(fread(buf, 1, (size_t)n, f), (size_t)n, "%s", path);
    buf[n] = 0;
    fclose(f);
    return buf;
}

int cli_count_files(const char *dir, const char *pattern)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "ls -a '%s' 2>/dev/null | grep -c '%s'", dir, pattern);
    FILE *p = popen(cmd, "r");
    cr_assert_not_null(p, "%s", cmd);
    int n = -1;
    cr_assert_eq(fscanf(p, "%d", &n), 1, "%s", cmd);
    pclose(p);
    return n;
}

void cli_write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    cr_assert_not_null(f, "%s", path);
    fputs(text, f);
    fclose(f);
}

int cli_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

void cli_check_chart(const char *path, int min_w, int min_h)
{
    isk_canvas c;
    isk_error err;
    cr_assert_eq(isk_png_read(&c, path, &err), ISK_OK, "%s: %s", path, err.message);
    cr_assert(c.width >= min_w && c.height >= min_h, "%s: %dx%d", path, c.width, c.height);
    size_t n = (size_t)c.width * (size_t)c.height, ink = 0;
    for (int y = 0; y < c.height; y++)
        for (int x = 0; x < c.width; x++)
            ink += memcmp(c.pixels + (size_t)y * c.stride + (size_t)x * 4, c.pixels, 4) != 0;
    cr_assert_gt(ink, n / 100, "%s: only %zu pixels drawn", path, ink);
    isk_canvas_free(&c);
}

pid_t cli_start(const char *dir, int out_fd, long fsize, const char *const *args)
{
    char tool[512], errp[512], outp[512];
    snprintf(tool, sizeof tool, "%s/bin/iskra", refimg_build_dir());
    snprintf(errp, sizeof errp, "%s/stderr.txt", dir);
    snprintf(outp, sizeof outp, "%s/stdout.txt", dir);
    pid_t pid = fork();
    cr_assert_neq(pid, -1);
    if (pid == 0) {
        int e = open(errp, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int o = out_fd >= 0 ? out_fd : open(outp, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (e < 0 || o < 0 || dup2(e, 2) < 0 || dup2(o, 1) < 0)
            _exit(99);
        for (int s = 1; s < 32; s++)
            signal(s, SIG_DFL);
        struct rlimit rl = {(rlim_t)fsize, (rlim_t)fsize};
        if (fsize > 0 && setrlimit(RLIMIT_FSIZE, &rl) != 0)
            _exit(97);
        char *argv[32];
        int n = 0;
        argv[n++] = tool;
        for (; args[n - 1] && n < 31; n++)
            argv[n] = (char *)args[n - 1];
        argv[n] = NULL;
        execv(tool, argv);
        _exit(98);
    }
    return pid;
}

pid_t cli_drain_fifo(const char *fifo, const char *copy)
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
