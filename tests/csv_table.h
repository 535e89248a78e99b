/* SPDX-License-Identifier: MIT */
/* tests/csv_table.h — the CSV files `iskra bench` writes, read for tests
 * (header-only; include it after <criterion/criterion.h> and
 * tests/tool_cli.h).
 *
 *     csv *c = csv_load("out/x/acc/budget_kepler.csv");   // asserts it parses
 *     const int ce = csv_col(c, "position_error");
 *     for (int r = 0; r < c->nrows; r++)
 *         total += csv_num(c->cell[r][ce]);
 *     csv_free(c);
 *
 * The text is split in place: a header and rows, every row with the
 * header's number of fields, fields by commas (no quoting: iskra writes
 * none). */
#ifndef ISKRA_TESTS_CSV_TABLE_H
#define ISKRA_TESTS_CSV_TABLE_H

#include <stdlib.h>
#include <string.h>

#include "iskra/integrate.h"

enum { CSV_MAX_ROWS = 4096, CSV_MAX_COLS = 16 };

typedef struct csv {
    char *text;
    int ncols, nrows;
    char *head[CSV_MAX_COLS];
    char *cell[CSV_MAX_ROWS][CSV_MAX_COLS];
} csv;

/* Reads path into *c (free c->text, or use csv_load / csv_free). */
static inline void csv_read(csv *c, const char *path)
{
    memset(c, 0, sizeof *c);
    c->text = cli_slurp(path);
    int row = -1;
    for (char *line = c->text, *next; *line; line = next) {
        next = strchr(line, '\n');
        cr_assert_not_null(next, "%s: the last line is not terminated", path);
        *next++ = 0;
        char **dst = row < 0 ? c->head : c->cell[row];
        int n = 0;
        for (char *f = line;; f = strchr(f, 0) + 1) {
            cr_assert_lt(n, CSV_MAX_COLS, "%s: too many fields", path);
            dst[n++] = f;
            char *comma = strchr(f, ',');
            if (!comma)
                break;
            *comma = 0;
        }
        if (row < 0)
            c->ncols = n;
        else
            cr_assert_eq(n, c->ncols, "%s row %d: %d fields, the header has %d", path, row + 1, n, c->ncols);
        cr_assert_lt(++row, CSV_MAX_ROWS);
    }
    c->nrows = row;
}

static inline csv *csv_load(const char *path)
{
    csv *c = malloc(sizeof *c);
    cr_assert_not_null(c);
    csv_read(c, path);
    return c;
}

static inline void csv_free(csv *c)
{
    if (c)
        free(c->text);
    free(c);
}

/* The column named `name` (asserts there is one). */
static inline int csv_col(const csv *c, const char *name)
{
    for (int i = 0; i < c->ncols; i++)
        if (!strcmp(c->head[i], name))
            return i;
    cr_assert_fail("no column %s", name);
    return -1;
}

/* A field that is a number, whole (asserts it is). */
static inline double csv_num(const char *s)
{
    char *end;
    double v = strtod(s, &end);
    cr_assert(end != s && *end == 0, "not a number: '%s'", s);
    return v;
}

/* The integrator a field names (asserts it names one). */
static inline int csv_integrator(const char *name)
{
    for (int m = 0; m < ISK_INTEGRATOR_COUNT; m++)
        if (!strcmp(name, isk_integrator_name((isk_integrator)m)))
            return m;
    cr_assert_fail("unknown integrator '%s'", name);
    return -1;
}

#endif
