/* SPDX-License-Identifier: MIT */
/* INI reading: line numbers, errors as FILE:LINE, did-you-mean. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "scene/ini_read.h"

typedef struct seen {
    int n;
    char sec[8][32], key[8][32], val[8][64];
    int line[8];
    int fail_on; /* line to fail on, 0 = never */
} seen;

static isk_status record(void *u, const char *sec, const char *key, const char *val, int line, isk_error *err)
{
    seen *s = u;
    if (s->fail_on == line)
        return isk__ini_error(err, "t.ini", line, "unknown key '%s'", key);
    if (s->n < 8) {
        snprintf(s->sec[s->n], 32, "%s", sec);
        snprintf(s->key[s->n], 32, "%s", key);
        snprintf(s->val[s->n], 64, "%s", val);
        s->line[s->n] = line;
    }
    s->n++;
    return ISK_OK;
}

Test(ini_read, keys_with_line_numbers)
{
    const char *text = "; comment\n[canvas]\nwidth = 600\n\n# another\nheight=400 ; inline\n[emitter fire]\nrate = 20\n";
    seen s = {0};
    isk_error err = {0};
    cr_assert_eq(isk__ini_parse_string(text, "t.ini", record, &s, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(s.n, 3);
    cr_assert_str_eq(s.sec[0], "canvas");
    cr_assert_str_eq(s.key[0], "width");
    cr_assert_str_eq(s.val[0], "600");
    cr_assert_eq(s.line[0], 3);
    cr_assert_str_eq(s.val[1], "400");
    cr_assert_eq(s.line[1], 6);
    cr_assert_str_eq(s.sec[2], "emitter fire");
    cr_assert_eq(s.line[2], 8);
}

Test(ini_read, callback_error_stops_with_file_and_line)
{
    seen s = {.fail_on = 3};
    isk_error err = {0};
    cr_assert_eq(isk__ini_parse_string("[a]\nx=1\ny=2\nz=3\n", "t.ini", record, &s, &err), ISK_ERR_FORMAT);
    cr_assert_str_eq(err.message, "t.ini:3: unknown key 'y'");
    cr_assert_eq(s.n, 1);
}

Test(ini_read, syntax_error_reports_line)
{
    seen s = {0};
    isk_error err = {0};
    cr_assert_eq(isk__ini_parse_string("[a]\nx=1\nthis line has no equals sign\n", "bad.ini", record, &s, &err),
                 ISK_ERR_FORMAT);
    cr_assert(strncmp(err.message, "bad.ini:3: ", 11) == 0, "%s", err.message);
    cr_assert_eq(isk__ini_parse_string("[unclosed\n", "bad.ini", record, &s, &err), ISK_ERR_FORMAT);
    cr_assert(strncmp(err.message, "bad.ini:1: ", 11) == 0, "%s", err.message);
}

Test(ini_read, overlong_line_is_an_error_not_two_lines)
{
    char text[600];
    strcpy(text, "[a]\nkey = ");
    memset(text + strlen(text), '9', 400);
    text[10 + 400] = '\n';
    text[10 + 401] = 0;
    seen s = {0};
    isk_error err = {0};
    cr_assert_eq(isk__ini_parse_string(text, "long.ini", record, &s, &err), ISK_ERR_FORMAT);
    cr_assert(strstr(err.message, "long.ini:2: line too long") != NULL, "%s", err.message);
    cr_assert_eq(s.n, 0);
}

Test(ini_read, files)
{
    seen s = {0};
    isk_error err = {0};
    cr_assert_eq(isk__ini_parse_file("out/no/such/file.ini", record, &s, &err), ISK_ERR_IO);
    cr_assert(strstr(err.message, "out/no/such/file.ini") != NULL);
    mkdir("out", 0777);
    FILE *f = fopen("out/nul.ini", "wb");
    cr_assert_not_null(f);
    fwrite("[a]\nx=1\ny=\0z\n", 1, 14, f);
    fclose(f);
    cr_assert_eq(isk__ini_parse_file("out/nul.ini", record, &s, &err), ISK_ERR_FORMAT);
    cr_assert(strstr(err.message, "out/nul.ini:3: contains a NUL byte") != NULL, "%s", err.message);
}

Test(ini_read, suggestions)
{
    const char *keys[] = {"gravity", "drag", "substeps", "integrator", "seed"};
    cr_assert_str_eq(isk__ini_suggest("gravty", keys, 5), "gravity");
    cr_assert_str_eq(isk__ini_suggest("substep", keys, 5), "substeps");
    cr_assert_str_eq(isk__ini_suggest("sed", keys, 5), "seed");
    cr_assert_null(isk__ini_suggest("colour", keys, 5));
    /* a third of the word, rounded up: 2 edits in 5 letters */
    const char *names[] = {"sparks", "a"};
    cr_assert_str_eq(isk__ini_suggest("sparx", names, 2), "sparks");
    cr_assert_null(isk__ini_suggest("spx", names, 2));
    cr_assert_null(isk__ini_suggest(NULL, keys, 5));
}
