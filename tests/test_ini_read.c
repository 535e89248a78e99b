/* SPDX-License-Identifier: MIT */
/* INI reading: line numbers, errors as FILE:LINE, did-you-mean. */
#include <criterion/criterion.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
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
    static char text[ISK_INI_MAX_LINE + 40];
    strcpy(text, "[a]\nkey = ");
    memset(text + strlen(text), '9', ISK_INI_MAX_LINE - 5);
    text[10 + ISK_INI_MAX_LINE - 5] = '\n';
    text[10 + ISK_INI_MAX_LINE - 4] = 0;
    seen s = {0};
    isk_error err = {0};
    cr_assert_eq(isk__ini_parse_string(text, "long.ini", record, &s, &err), ISK_ERR_FORMAT);
    cr_assert_str_eq(err.message, "long.ini:2: line too long (at most 65535 characters)");
    cr_assert_eq(s.n, 0);
}

/* A line longer than libinih's buffer (199 characters) is one key, its
 * value whole (a blank inside kept, an inline comment cut), in order with
 * the short lines around it; the longest line is read too. */
typedef struct long_seen {
    int n, line[4];
    char key[4][8];
    size_t len[4];
    int sevens[4]; /* the value is 7s with one blank, as written */
} long_seen;

static isk_status record_long(void *u, const char *sec, const char *key, const char *val, int line, isk_error *err)
{
    (void)sec;
    (void)err;
    long_seen *s = u;
    if (s->n < 4) {
        snprintf(s->key[s->n], sizeof s->key[s->n], "%s", key);
        s->line[s->n] = line;
        s->len[s->n] = strlen(val);
        s->sevens[s->n] = strspn(val, "7 ") == strlen(val);
    }
    s->n++;
    return ISK_OK;
}

Test(ini_read, long_lines_are_read_whole)
{
    static char text[ISK_INI_MAX_LINE + 40];
    const size_t lengths[] = {5000, ISK_INI_MAX_LINE - 6}; /* "key = " and the value: the longest line */
    for (int t = 0; t < 2; t++) {
        const size_t n = lengths[t];
        strcpy(text, "[a]\nx = 1\nkey = ");
        const size_t at = strlen(text);
        memset(text + at, '7', n);
        text[at + n / 2] = ' ';
        strcpy(text + at + n, t == 0 ? " ; a comment\ny = 2\n" : "\ny = 2\n");
        long_seen s = {0};
        isk_error err = {0};
        cr_assert_eq(isk__ini_parse_string(text, "long.ini", record_long, &s, &err), ISK_OK, "%s", err.message);
        cr_assert_eq(s.n, 3);
        cr_assert_str_eq(s.key[0], "x");
        cr_assert_str_eq(s.key[1], "key");
        cr_assert_eq(s.line[1], 3);
        cr_assert_eq(s.len[1], n);
        cr_assert(s.sevens[1]);
        cr_assert_str_eq(s.key[2], "y");
        cr_assert_eq(s.line[2], 4);
    }
}

/* ---- the two routes: libinih's and the reader's own split ---------------- */

typedef struct calls {
    char *log;          /* every call: "S|section|line" or "K|section|key|value|line", one a line */
    size_t len, cap;
} calls;

static void log_call(calls *c, const char *fmt, const char *a, const char *b, const char *v, int line)
{
    size_t need = strlen(a) + strlen(b) + strlen(v) + 40;
    if (c->len + need >= c->cap) {
        c->cap = (c->len + need) * 2;
        c->log = realloc(c->log, c->cap);
        cr_assert_not_null(c->log);
    }
    c->len += (size_t)snprintf(c->log + c->len, c->cap - c->len, fmt, a, b, v, line);
}

static isk_status on_key_log(void *u, const char *sec, const char *key, const char *val, int line, isk_error *err)
{
    (void)err;
    log_call(u, "K|%s|%s|%s|%d\n", sec, key, val, line);
    return ISK_OK;
}

static isk_status on_section_log(void *u, const char *header, int line, isk_error *err)
{
    (void)err;
    log_call(u, "S|%s%s%s|%d\n", header, "", "", line);
    return ISK_OK;
}

/* Both routes over one text: the same calls in the same order, the same
 * status and message. */
static void same_both_ways(const char *text, const char *what)
{
    calls a = {0}, b = {0};
    isk_error ea = {0}, eb = {0};
    isk_status sa = isk__ini_parse_split_from(text, "t.ini", on_section_log, on_key_log, &a, ISK_INI_MAX_LINE, &ea);
    isk_status sb = isk__ini_parse_split_from(text, "t.ini", on_section_log, on_key_log, &b, 0, &eb);
    cr_assert_eq(sa, sb, "%s: status %d by libinih, %d split by the reader", what, (int)sa, (int)sb);
    if (sa != ISK_OK)
        cr_assert_str_eq(ea.message, eb.message, "%s", what);
    cr_assert_eq(a.len, b.len, "%s: libinih called back\n%s\nthe reader's split\n%s", what, a.log ? a.log : "",
                 b.log ? b.log : "");
    if (a.len)
        cr_assert(!memcmp(a.log, b.log, a.len), "%s: libinih called back\n%s\nthe reader's split\n%s", what, a.log,
                  b.log);
    free(a.log);
    free(b.log);
}

Test(ini_read, both_routes_alike_on_every_scene)
{
    int files = 0;
    DIR *dir = opendir("scenes");
    cr_assert_not_null(dir);
    for (struct dirent *ent; (ent = readdir(dir)) != NULL;) {
        const size_t n = strlen(ent->d_name);
        if (n < 5 || strcmp(ent->d_name + n - 4, ".ini"))
            continue;
        char path[512];
        snprintf(path, sizeof path, "scenes/%s", ent->d_name);
        char *text;
        isk_error err;
        cr_assert_eq(isk__ini_read_file(path, &text, &err), ISK_OK, "%s", err.message);
        same_both_ways(text, path);
        free(text);
        files++;
    }
    closedir(dir);
    cr_assert_gt(files, 20);
}

Test(ini_read, both_routes_alike_on_tricky_lines)
{
    static const char *const texts[] = {
        "\xEF\xBB\xBF[scene]\nseed = 1\n",              /* a byte order mark */
        "\xEF\xBB\xBF\xEF\xBB\xBFkey = 1\n",              /* two: libinih takes the second off */
        "\xEF\xBB\xBF  [a]\n",                           /* a mark, then blanks */
        "[a]\nk: v\nk2 : v2 ; c\nk3 = a:b\nk4:a=b\n",       /* ':' separates as '=' does */
        "[a]\nk = v;not a comment\nk = v ;comment\nk = v\t;tab comment\nk=;x\nk = ;x\n",
        "[a] ; c\n[b]# c\n[ spaced name ]\n[]\n",        /* headers: comments, blanks kept, empty */
        "[a]\n\n   \n\t\n; c\n# c\n  ; c\nk =\nk = \n = v\n", /* blanks, comments, empty values, no key */
        "[a]\r\nk = v\r\n  indented = yes\r\n",          /* CRLF, an indented key */
        "[a]\nk = v \v\f\r\n",                           /* trailing blanks of every kind */
        "[a]\nk ;= v\n",                                  /* a comment before '=': no key */
        "[a]\nk\n",                                       /* no '=' */
        "[a\n",                                            /* no ']' */
        "[a]x\n",                                          /* text after ']' */
        "[a;b] ; c\nk = 1\n[a ;b]\n",                     /* ';' inside a header, then a comment */
        "[0123456789012345678901234567890123456789012345678901234567890123456789]\nk = v\n", /* cut at 49 */
        "k = before any section\n[a]\nk = after\n",
        "[a]\nk = v\n[b]\nk = w\n",
        "[a]\nk = v", /* no final newline */
        "",
    };
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        char what[32];
        snprintf(what, sizeof what, "tricky text %zu", i);
        same_both_ways(texts[i], what);
    }
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
