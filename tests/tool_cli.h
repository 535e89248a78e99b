/* SPDX-License-Identifier: MIT */
/* tests/tool_cli.h — running the built `iskra` command from a test.
 *
 *     cli_fresh("out/test_x/case");                       // empty directory
 *     int status = cli_run("out/test_x/case", "bench accuracy --quick");
 *     char *err = cli_slurp("out/test_x/case/stderr.txt"); ... free(err);
 *
 * The tool is $ISKRA_BUILD/bin/iskra (default build/, see refimg.h), run
 * from the repository root with SDL_VIDEODRIVER=dummy (no window ever
 * opens).  Criterion runs tests in parallel: give each test its own
 * directory. */
#ifndef ISKRA_TESTS_TOOL_CLI_H
#define ISKRA_TESTS_TOOL_CLI_H

#include <sys/types.h>

/* rm -rf dir && mkdir -p dir (asserts success). */
void cli_fresh(const char *dir);

/* Starts `iskra ARGS...` (args NULL-terminated; no shell) with stderr to
 * dir/stderr.txt and stdout to out_fd, or to dir/stdout.txt when out_fd
 * is -1, every signal at its default and, for fsize > 0, a file size
 * limit of fsize bytes.  Returns at once: waitpid the result. */
pid_t cli_start(const char *dir, int out_fd, long fsize, const char *const *args);

/* Reads the FIFO to its end in a child process, copying it into `copy`
 * (the reader a write into a FIFO waits for). */
pid_t cli_drain_fifo(const char *fifo, const char *copy);

/* Runs `iskra ARGS` with stdout and stderr in dir/stdout.txt and
 * dir/stderr.txt; asserts a normal exit and returns the exit status. */
int cli_run(const char *dir, const char *args);

/* The same with `cwd` as the working directory (any directory, e.g. one
 * under /tmp: nothing may assume it is the repository); stdout and stderr
 * still go to dir/stdout.txt and dir/stderr.txt. */
int cli_run_in(const char *cwd, const char *dir, const char *args);

/* The whole file, malloc'd and NUL-terminated (asserts it exists). */
char *cli_slurp(const char *path);

/* How many names in dir (dot files too) match the grep pattern. */
int cli_count_files(const char *dir, const char *pattern);

/* Writes text as the whole file at path (asserts it can). */
void cli_write_file(const char *path, const char *text);

/* 1 when the path exists. */
int cli_exists(const char *path);

/* Reads a chart PNG and asserts it is at least min_w x min_h and not a
 * blank page: more than 1 % of its pixels differ from the corner's. */
void cli_check_chart(const char *path, int min_w, int min_h);

#endif
