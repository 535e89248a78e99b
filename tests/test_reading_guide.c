/* SPDX-License-Identifier: MIT */
/* docs/architecture.md's reading guide: to follow one particle through the
 * code, at most 5 files and 1,500 lines to see how it is stepped, and as
 * many to see how it is drawn.  Each list sits between
 * "<!-- reading: NAME -->" and "<!-- end -->", one file a numbered line
 * (its first `path`); this test reads the lists, checks that every file
 * exists, and counts their lines. */
#include <criterion/criterion.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tool_cli.h"

enum { MOST_FILES = 5, MOST_LINES = 1500 };

static long count_lines(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    long n = 0;
    int c, last = '\n';
    while ((c = fgetc(f)) != EOF) {
        n += c == '\n';
        last = c;
    }
    fclose(f);
    return n + (last != '\n');
}

/* The files of list `name`, their count and lines. */
static void check_list(const char *doc, const char *name)
{
    char open_tag[64];
    snprintf(open_tag, sizeof open_tag, "<!-- reading: %s -->", name);
    const char *at = strstr(doc, open_tag);
    cr_assert_not_null(at, "docs/architecture.md has no %s", open_tag);
    const char *end = strstr(at, "<!-- end -->");
    cr_assert_not_null(end, "%s is not closed by <!-- end -->", open_tag);
    int files = 0;
    long lines = 0;
    for (const char *p = at; p < end; p = strchr(p, '\n') + 1) {
        /* a numbered line: "N. `path`..." */
        int num, used = 0;
        if (sscanf(p, "%d. `%n", &num, &used) == 1 && used > 0) {
            const char *q = strchr(p + used, '`');
            cr_assert(q && q < end, "%s: an unclosed path", name);
            char path[256];
            snprintf(path, sizeof path, "%.*s", (int)(q - (p + used)), p + used);
            const long n = count_lines(path);
            cr_assert_geq(n, 0, "%s: %s does not exist", name, path);
            files++;
            lines += n;
            printf("reading %s: %s, %ld lines\n", name, path, n);
        }
        if (!strchr(p, '\n'))
            break;
    }
    printf("reading %s: %d files, %ld lines\n", name, files, lines);
    cr_expect_gt(files, 2, "%s: a list of %d files", name, files);
    cr_expect_leq(files, MOST_FILES, "%s: %d files, more than %d", name, files, MOST_FILES);
    cr_expect_leq(lines, MOST_LINES, "%s: %ld lines, more than %d", name, lines, MOST_LINES);
}

Test(reading_guide, one_particle_in_five_files_and_1500_lines)
{
    char *doc = cli_slurp("docs/architecture.md");
    cr_assert_not_null(doc);
    check_list(doc, "step");
    check_list(doc, "draw");
    free(doc);
}
