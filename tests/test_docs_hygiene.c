/* SPDX-License-Identifier: MIT */
/* What users read names no internal tracker: no "issue N" (any case, also
 * "issues 13", "issue #14") in the scene files (whose leading comments
 * `iskra list` shows), the docs, the public headers, README.md and
 * CHANGELOG.md, nor in `iskra list`'s output.  Each hit is reported as
 * FILE:LINE with the line. */
#include <criterion/criterion.h>
#include <criterion/logging.h>
#include <dirent.h>
#include <regex.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "tool_cli.h"

#define OUT "out/test_docs_hygiene"

/* "issue" or "issues", then blanks or '#', then a digit; not inside a
 * longer word ("tissue 3" is not a reference). */
#define ISSUE_RE "(^|[^[:alpha:]])issues?[[:blank:]#]*[0-9]"

static regex_t issue_re;

static void compile_re(void)
{
    cr_assert_eq(regcomp(&issue_re, ISSUE_RE, REG_EXTENDED | REG_ICASE | REG_NEWLINE), 0);
}

/* Reports every line of `text` (named `what`) that matches; returns how many. */
static int report_hits(const char *what, const char *text)
{
    int hits = 0;
    long line = 1;
    const char *line_start = text;
    for (const char *p = text;; p++) {
        if (*p == '\n' || !*p) {
            size_t n = (size_t)(p - line_start);
            char buf[1024];
            if (n >= sizeof buf)
                n = sizeof buf - 1;
            memcpy(buf, line_start, n);
            buf[n] = 0;
            if (regexec(&issue_re, buf, 0, NULL, 0) == 0) {
                cr_log_error("%s:%ld: an internal reference: %s", what, line, buf);
                hits++;
            }
            if (!*p)
                break;
            line++;
            line_start = p + 1;
        }
    }
    return hits;
}

static int is_text_file(const char *name)
{
    static const char *const ext[] = {".ini", ".md", ".h", ".c", ".cpp", ".sh", ".txt"};
    size_t n = strlen(name);
    for (size_t i = 0; i < sizeof ext / sizeof ext[0]; i++) {
        size_t e = strlen(ext[i]);
        if (n > e && !strcmp(name + n - e, ext[i]))
            return 1;
    }
    return 0;
}

/* Checks one file, or every text file under a directory; counts the files. */
static int check_path(const char *path, int *files)
{
    struct stat st;
    cr_assert_eq(stat(path, &st), 0, "%s is missing", path);
    if (S_ISDIR(st.st_mode)) {
        int hits = 0;
        DIR *d = opendir(path);
        cr_assert_not_null(d, "cannot open %s", path);
        struct dirent *e;
        while ((e = readdir(d))) {
            if (e->d_name[0] == '.')
                continue;
            char sub[1024];
            snprintf(sub, sizeof sub, "%s/%s", path, e->d_name);
            struct stat sst;
            cr_assert_eq(stat(sub, &sst), 0);
            if (S_ISDIR(sst.st_mode) || is_text_file(e->d_name))
                hits += check_path(sub, files);
        }
        closedir(d);
        return hits;
    }
    if (!strcmp(path, "tests/test_docs_hygiene.c"))
        return 0; /* this file: its examples of what the pattern finds */
    char *text = cli_slurp(path);
    (*files)++;
    int hits = report_hits(path, text);
    free(text);
    return hits;
}

Test(docs_hygiene, the_pattern_finds_what_it_must)
{
    compile_re();
    const char *must[] = {"(issue 14)", "Issue 12 (speed)", "issues 13 and 14", "see issue #7", "issue14"};
    const char *must_not[] = {"an issue with the cull", "tissue 3", "the issue's numbers", "issued 3 times"};
    for (size_t i = 0; i < sizeof must / sizeof must[0]; i++)
        cr_expect_eq(regexec(&issue_re, must[i], 0, NULL, 0), 0, "not found in \"%s\"", must[i]);
    for (size_t i = 0; i < sizeof must_not / sizeof must_not[0]; i++)
        cr_expect_neq(regexec(&issue_re, must_not[i], 0, NULL, 0), 0, "found in \"%s\"", must_not[i]);
    regfree(&issue_re);
}

Test(docs_hygiene, no_issue_numbers_in_what_users_read)
{
    compile_re();
    const char *paths[] = {"scenes", "docs", "include", "README.md", "CHANGELOG.md"};
    int hits = 0, files = 0;
    for (size_t i = 0; i < sizeof paths / sizeof paths[0]; i++)
        hits += check_path(paths[i], &files);
    regfree(&issue_re);
    /* every scene, doc and header was read (not an empty walk) */
    cr_assert_geq(files, 80, "only %d files were read", files);
    cr_assert_eq(hits, 0, "%d lines name an issue (above): say what they are about instead", hits);
}

/* Nor in the code: issue numbers belong in the tracker, not in the
 * sources a student reads. */
Test(docs_hygiene, no_issue_numbers_in_the_code)
{
    compile_re();
    const char *paths[] = {"src", "tools", "tests", "bench", "examples", "web", "mk", "Makefile", ".ci/run"};
    int hits = 0, files = 0;
    for (size_t i = 0; i < sizeof paths / sizeof paths[0]; i++)
        hits += check_path(paths[i], &files);
    regfree(&issue_re);
    cr_assert_geq(files, 300, "only %d files were read", files);
    cr_assert_eq(hits, 0, "%d lines name an issue (above): say what they are about instead", hits);
}

/* Measurements, dates and machine names belong in docs/performance.md and
 * the benchmarks' output: the library's code and headers state rules and
 * name the section that holds the measures. */
Test(docs_hygiene, no_diaries_in_the_library)
{
    regex_t diary;
    cr_assert_eq(regcomp(&diary, "20[0-9][0-9]-[0-9][0-9]-[0-9][0-9]|this VM|Zen ?4|Xeon|EPYC|medians of",
                         REG_EXTENDED | REG_ICASE | REG_NEWLINE),
                 0);
    FILE *p = popen("find src include -name '*.[ch]' -not -name sinlut_table.c | sort", "r");
    cr_assert_not_null(p);
    char path[512];
    int files = 0, hits = 0;
    while (fgets(path, sizeof path, p)) {
        path[strcspn(path, "\n")] = 0;
        char *text = cli_slurp(path);
        files++;
        long line = 1;
        for (char *q = text, *start = text;; q++)
            if (*q == '\n' || !*q) {
                const char c = *q;
                *q = 0;
                if (regexec(&diary, start, 0, NULL, 0) == 0) {
                    cr_log_error("%s:%ld: a measurement's date or machine: %s", path, line, start);
                    hits++;
                }
                if (!c)
                    break;
                line++;
                start = q + 1;
            }
        free(text);
    }
    pclose(p);
    regfree(&diary);
    cr_assert_gt(files, 150);
    cr_assert_eq(hits, 0, "%d lines (above): move the measure to docs/performance.md and name its section", hits);
}

Test(docs_hygiene, iskra_list_names_no_issue)
{
    compile_re();
    cli_fresh(OUT "/list");
    cr_assert_eq(cli_run(OUT "/list", "list"), 0);
    char *list = cli_slurp(OUT "/list/stdout.txt");
    cr_assert_gt(strlen(list), 1000, "iskra list printed little:\n%s", list);
    int hits = report_hits("iskra list", list);
    free(list);
    regfree(&issue_re);
    cr_assert_eq(hits, 0, "iskra list shows %d issue references (scenes/*.ini's leading comments)", hits);
}
