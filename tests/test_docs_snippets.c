/* SPDX-License-Identifier: MIT */
/* The docs quote files as they are.  A block in a page of docs/ preceded by
 *
 *     <!-- file: docs/tutorial/step1.ini -->               (the whole file)
 *     <!-- file: docs/tutorial/step2.ini lines 13-14 -->   (lines 13 to 14)
 *
 * must be, between its ``` fences, exactly that file or those lines.  The
 * tests render, build or load the files (test_tutorial, test_from_engines,
 * tests/header_examples.sh), so what a reader copies is what was checked.
 * Every scene file and program in docs/tutorial/ and docs/from-love-godot/
 * must be quoted somewhere, so none is left unchecked. */
#include <criterion/criterion.h>
#include <criterion/logging.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tool_cli.h"

#define MAX_QUOTED 256

typedef struct quoted {
    char paths[MAX_QUOTED][256];
    int n;
} quoted;

static void note_quoted(quoted *q, const char *path)
{
    for (int i = 0; i < q->n; i++)
        if (!strcmp(q->paths[i], path))
            return;
    cr_assert_lt(q->n, MAX_QUOTED);
    snprintf(q->paths[q->n++], sizeof q->paths[0], "%s", path);
}

/* Lines first..last (1-based, inclusive) of text, each ending in '\n'
 * (malloc'd; NULL when the file has fewer lines). */
static char *lines_of(const char *text, long first, long last)
{
    const char *p = text;
    for (long l = 1; l < first; l++) {
        p = strchr(p, '\n');
        if (!p)
            return NULL;
        p++;
    }
    const char *end = p;
    for (long l = first; l <= last; l++) {
        end = strchr(end, '\n');
        if (!end)
            return NULL;
        end++;
    }
    size_t n = (size_t)(end - p);
    char *out = malloc(n + 1);
    cr_assert_not_null(out);
    memcpy(out, p, n);
    out[n] = 0;
    return out;
}

/* Each mismatch is logged as an error (which fails the run), except in the
 * checker's own test, which expects some. */
static int quiet;
#define report(...)                                                                                          \
    do {                                                                                                     \
        if (!quiet)                                                                                          \
            cr_log_error(__VA_ARGS__);                                                                       \
    } while (0)

/* Checks every marked block of one document; returns the number of
 * mismatches (each reported as DOC:LINE with what differs). */
static int check_doc(const char *doc, const char *text, quoted *q)
{
    int bad = 0;
    long lineno = 0;
    const char *p = text;
    while (*p) {
        const char *eol = strchr(p, '\n');
        size_t len = eol ? (size_t)(eol - p) : strlen(p);
        lineno++;
        char line[512];
        snprintf(line, sizeof line, "%.*s", (int)(len < sizeof line ? len : sizeof line - 1), p);
        p = eol ? eol + 1 : p + len;

        char path[256];
        long first = 0, last = 0;
        int whole = sscanf(line, "<!-- file: %255s -->", path) == 1 && strstr(line, " lines ") == NULL;
        int part = sscanf(line, "<!-- file: %255s lines %ld-%ld -->", path, &first, &last) == 3;
        if (!whole && !part)
            continue;
        long marker = lineno;
        /* the fence must follow at once */
        if (strncmp(p, "```", 3) != 0) {
            report("%s:%ld: the marker for %s is not followed by a ``` block", doc, marker, path);
            bad++;
            continue;
        }
        p = strchr(p, '\n');
        if (!p) {
            report("%s:%ld: the block for %s never starts", doc, marker, path);
            return bad + 1;
        }
        p++;
        lineno++;
        const char *body = p;
        const char *close = NULL;
        while (*p) {
            const char *e = strchr(p, '\n');
            lineno++;
            if (!strncmp(p, "```", 3) && (p[3] == '\n' || p[3] == 0)) {
                close = p;
                p = e ? e + 1 : p + strlen(p);
                break;
            }
            p = e ? e + 1 : p + strlen(p);
        }
        if (!close) {
            report("%s:%ld: the block for %s is not closed", doc, marker, path);
            return bad + 1;
        }
        size_t blen = (size_t)(close - body);
        if (!cli_exists(path)) {
            report("%s:%ld: quotes %s, which does not exist", doc, marker, path);
            bad++;
            continue;
        }
        char *file = cli_slurp(path);
        char *want = whole ? file : lines_of(file, first, last);
        if (!want || first > last) {
            report("%s:%ld: %s has no lines %ld-%ld", doc, marker, path, first, last);
            bad++;
        } else if (strlen(want) != blen || memcmp(want, body, blen) != 0) {
            /* the first line that differs */
            long l = 1;
            size_t i = 0;
            while (i < blen && want[i] && want[i] == body[i]) {
                if (want[i] == '\n')
                    l++;
                i++;
            }
            report("%s:%ld: the block differs from %s%s at its line %ld: copy the file into the page",
                         doc, marker, path, whole ? "" : " (the lines named)", l);
            bad++;
        }
        note_quoted(q, path);
        if (want != file)
            free(want);
        free(file);
    }
    return bad;
}

static int ends_with(const char *s, const char *tail)
{
    size_t n = strlen(s), t = strlen(tail);
    return n > t && !strcmp(s + n - t, tail);
}

Test(docs_snippets, the_checker_sees_a_changed_block)
{
    quoted q = {.n = 0};
    quiet = 1; /* the mismatches below are expected */
    char *file = cli_slurp("docs/tutorial/step1.ini");
    size_t n = strlen(file);
    char *doc = malloc(n + 256);
    cr_assert_not_null(doc);
    snprintf(doc, n + 256, "intro\n<!-- file: docs/tutorial/step1.ini -->\n```ini\n%s```\nafter\n", file);
    cr_expect_eq(check_doc("good.md", doc, &q), 0, "the file itself was refused");
    char *rate = strstr(doc, "rate = 200");
    cr_assert_not_null(rate);
    rate[7] = '3'; /* rate = 300 */
    cr_expect_eq(check_doc("changed.md", doc, &q), 1, "a changed line was not seen");
    snprintf(doc, n + 256, "<!-- file: docs/tutorial/step1.ini lines 2-3 -->\n```ini\n[scene]\nwidth = 320\n```\n");
    cr_expect_eq(check_doc("part.md", doc, &q), 0, "lines 2-3 were refused");
    snprintf(doc, n + 256, "<!-- file: docs/tutorial/step1.ini lines 2-3 -->\n```ini\n[scene]\n```\n");
    cr_expect_eq(check_doc("short.md", doc, &q), 1, "a missing line was not seen");
    free(doc);
    free(file);
}

Test(docs_snippets, every_quoted_file_is_quoted_as_it_is)
{
    quoted q = {.n = 0};
    int bad = 0, docs = 0;
    DIR *d = opendir("docs");
    cr_assert_not_null(d);
    struct dirent *e;
    while ((e = readdir(d))) {
        if (!ends_with(e->d_name, ".md"))
            continue;
        char path[512];
        snprintf(path, sizeof path, "docs/%s", e->d_name);
        char *text = cli_slurp(path);
        bad += check_doc(path, text, &q);
        free(text);
        docs++;
    }
    closedir(d);
    cr_assert_geq(docs, 8);
    cr_assert_eq(bad, 0, "%d quoted blocks differ from their files (above)", bad);

    /* every file of the quoted folders is quoted */
    const char *dirs[] = {"docs/tutorial", "docs/from-love-godot"};
    int files = 0;
    for (size_t k = 0; k < sizeof dirs / sizeof dirs[0]; k++) {
        DIR *dd = opendir(dirs[k]);
        cr_assert_not_null(dd, "%s is missing", dirs[k]);
        while ((e = readdir(dd))) {
            if (!ends_with(e->d_name, ".ini") && !ends_with(e->d_name, ".c"))
                continue;
            char path[512];
            snprintf(path, sizeof path, "%s/%s", dirs[k], e->d_name);
            int found = 0;
            for (int i = 0; i < q.n; i++)
                found |= !strcmp(q.paths[i], path);
            cr_expect(found, "%s is quoted by no page (add <!-- file: %s --> before its block)", path, path);
            files++;
        }
        closedir(dd);
    }
    cr_assert_geq(files, 6);
}
