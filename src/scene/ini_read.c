/* SPDX-License-Identifier: MIT */
/* INI reading with line numbers on top of libinih (see ini_read.h). */
#include "ini_read.h"

#include <ctype.h>
#include <errno.h>
#include <ini.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* libinih keeps the current section name in a buffer of this size
 * (MAX_SECTION in its ini.c): longer names reach the key callback cut. */
#define INIH_SECTION_MAX 50

typedef struct reader {
    const char *text;   /* remaining input */
    const char *name;
    int line;           /* number of the line last read (libinih counts the same) */
    size_t split_from;  /* a line longer than this is split here, not by libinih */
    char section[INIH_SECTION_MAX]; /* libinih's name of the current section */
    char *long_line;    /* room for one line the reader splits itself */
    isk_ini_section_fn section_fn;
    isk_ini_key_fn fn;
    void *user;
    isk_error *err;
    int stop_line;      /* the reader refused this line (too long, bad syntax) */
    const char *stop_msg;
    int failed;         /* a callback reported an error */
} reader;

isk_status isk__ini_error(isk_error *err, const char *name, int line, const char *fmt, ...)
{
    if (err) {
        char msg[400];
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg, sizeof msg, fmt, ap);
        va_end(ap);
        isk_error_set(err, ISK_ERR_FORMAT, "%s:%d: %s", name, line, msg);
    }
    return ISK_ERR_FORMAT;
}

static int blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

/* libinih's inline-comment rule: ';' at the start or after a blank. */
static const char *find_chars_or_comment(const char *s, const char *end, const char *chars)
{
    int was_space = 0;
    for (; s < end; s++) {
        if (strchr(chars, *s) || (was_space && *s == ';'))
            return s;
        was_space = blank(*s);
    }
    return end;
}

/* What libinih would refuse on this (stripped) line, or NULL; a header is
 * reported to the section callback here. */
static const char *classify(reader *r, char *s, size_t len)
{
    char *e = s + len;
    while (e > s && blank(e[-1]))
        e--;
    if (e == s || *s == ';' || *s == '#')
        return NULL;
    if (*s == '[') {
        const char *close = find_chars_or_comment(s + 1, e, "]");
        if (close == e || *close != ']')
            return "section header without ']'";
        const char *after = close + 1;
        while (after < e && blank(*after))
            after++;
        if (after < e && *after != ';' && *after != '#')
            return "unexpected text after ']' (a comment starts with ';')";
        /* the header, whole, to the section callback; libinih's copy of
         * the name is cut (strncpy0 into INIH_SECTION_MAX bytes) */
        const size_t n = (size_t)(close - s - 1);
        const size_t kept = n < INIH_SECTION_MAX - 1 ? n : INIH_SECTION_MAX - 1;
        memcpy(r->section, s + 1, kept);
        r->section[kept] = 0;
        if (r->section_fn) {
            const char saved = s[1 + n];
            s[1 + n] = 0;
            isk_status st = r->section_fn(r->user, s + 1, r->line, r->err);
            s[1 + n] = saved;
            if (st != ISK_OK) {
                r->failed = 1;
                return NULL;
            }
        }
        return NULL;
    }
    const char *eq = find_chars_or_comment(s, e, "=:");
    if (eq == e || (*eq != '=' && *eq != ':'))
        return "cannot parse this line: expected [section], key = value, or a ; comment";
    const char *ke = eq;
    while (ke > s && blank(ke[-1]))
        ke--;
    if (ke == s)
        return "missing key name before '='";
    return NULL;
}

/* ---- the long route: a line split by libinih's own rules ------------------- */

/* libinih's blanks are isspace's; its helpers, on a NUL-terminated line. */
static char *inih_rstrip(char *s)
{
    char *p = s + strlen(s);
    while (p > s && isspace((unsigned char)p[-1]))
        *--p = 0;
    return s;
}

static char *inih_lskip(char *s)
{
    while (*s && isspace((unsigned char)*s))
        s++;
    return s;
}

/* The first of `chars` (NULL: none) or an inline comment (';' after a
 * blank), or the end. */
static char *inih_find(char *s, const char *chars)
{
    int was_space = 0;
    while (*s && (!chars || !strchr(chars, *s)) && !(was_space && *s == ';')) {
        was_space = isspace((unsigned char)*s);
        s++;
    }
    return s;
}

/* What libinih does with one line (ini_parse_stream, with inline comments
 * and a byte order mark allowed): trimmed, a comment or blank line
 * ignored, a header setting the section, "name = value" or "name: value"
 * split, the value cut at an inline comment, both trimmed, then the key
 * callback.  classify() has refused every line libinih would (and already
 * noted a header's section), and leading blanks are gone, so a line is
 * never a continuation. */
static void split_line(reader *r, char *line)
{
    char *start = line;
    if (r->line == 1 && (unsigned char)start[0] == 0xEF && (unsigned char)start[1] == 0xBB &&
        (unsigned char)start[2] == 0xBF)
        start += 3;
    start = inih_lskip(inih_rstrip(start));
    if (!*start || *start == ';' || *start == '#' || *start == '[')
        return;
    char *end = inih_find(start, "=:");
    if (*end != '=' && *end != ':')
        return;
    *end = 0;
    char *name = inih_rstrip(start), *value = end + 1;
    end = inih_find(value, NULL);
    *end = 0;
    value = inih_lskip(value);
    inih_rstrip(value);
    if (r->fn(r->user, r->section, name, value, r->line, r->err) != ISK_OK)
        r->failed = 1;
}

/* ---- the reader ----------------------------------------------------------------- */

/* libinih's ini_reader: like fgets, one line per call, leading blanks
 * removed; NULL (the end, for libinih) at a line it must not see.  A line
 * longer than libinih's buffer (or than split_from) is split here by the
 * same rules (split_line), and libinih gets a stand-in that keeps its line
 * count and its section: an empty line, or the header as it keeps it. */
static char *read_line(char *buf, int size, void *stream)
{
    reader *r = stream;
    if (r->stop_line || r->failed || !*r->text)
        return NULL;
    const char *nl = strchr(r->text, '\n');
    size_t len = nl ? (size_t)(nl - r->text) : strlen(r->text);
    r->line++;
    if (len > ISK_INI_MAX_LINE) {
        r->stop_line = r->line;
        r->stop_msg = "line too long";
        return NULL;
    }
    const char *s = r->text;
    r->text += len + (nl ? 1 : 0);
    if (r->line == 1 && len >= 3 && (unsigned char)s[0] == 0xEF && (unsigned char)s[1] == 0xBB &&
        (unsigned char)s[2] == 0xBF) {
        s += 3;
        len -= 3;
    }
    while (len && blank(*s)) {
        s++;
        len--;
    }
    const int split_here = len > r->split_from || len + 2 > (size_t)size;
    char *line = buf;
    if (split_here) {
        if (!r->long_line && !(r->long_line = malloc(ISK_INI_MAX_LINE + 1))) {
            r->stop_line = r->line;
            r->stop_msg = "out of memory";
            return NULL;
        }
        line = r->long_line;
    }
    memcpy(line, s, len);
    line[len] = 0;
    const char *bad = classify(r, line, len);
    if (r->failed)
        return NULL;
    if (bad) {
        r->stop_line = r->line;
        r->stop_msg = bad;
        return NULL;
    }
    if (split_here) {
        const int header = *line == '[';
        split_line(r, line);
        if (r->failed)
            return NULL;
        snprintf(buf, (size_t)size, header ? "[%s]\n" : "\n", r->section);
        return buf;
    }
    buf[len] = '\n';
    buf[len + 1] = 0;
    return buf;
}

static int on_pair(void *user, const char *section, const char *key, const char *value)
{
    reader *r = user;
    if (r->failed)
        return 0;
    if (r->fn(r->user, section, key, value, r->line, r->err) != ISK_OK) {
        r->failed = 1;
        return 0;
    }
    return 1;
}

isk_status isk__ini_parse_split_from(const char *text, const char *name, isk_ini_section_fn section,
                                     isk_ini_key_fn fn, void *user, size_t split_from, isk_error *err)
{
    if (!text || !fn)
        return isk_error_set(err, ISK_ERR_NULL, "scene: NULL text or callback");
    if (!name)
        name = "<string>";
    reader r;
    memset(&r, 0, sizeof r);
    r.text = text;
    r.name = name;
    r.split_from = split_from;
    r.section_fn = section;
    r.fn = fn;
    r.user = user;
    r.err = err;
    int rc = ini_parse_stream(read_line, &r, on_pair, &r);
    free(r.long_line);
    if (r.failed)
        return err ? err->status : ISK_ERR_FORMAT;
    if (r.stop_line) {
        if (!strcmp(r.stop_msg, "out of memory"))
            return isk_error_set(err, ISK_ERR_NOMEM, "%s:%d: out of memory for a long line", name, r.stop_line);
        if (!strcmp(r.stop_msg, "line too long"))
            isk__ini_error(err, name, r.stop_line, "line too long (at most %d characters)", ISK_INI_MAX_LINE);
        else
            isk__ini_error(err, name, r.stop_line, "%s", r.stop_msg);
        return ISK_ERR_FORMAT;
    }
    if (rc > 0) { /* cannot happen with the checks above, but libinih may know more */
        isk__ini_error(err, name, rc, "cannot parse this line: expected [section], key = value, or a ; comment");
        return ISK_ERR_FORMAT;
    }
    if (rc < 0) {
        isk_error_set(err, ISK_ERR_NOMEM, "%s: out of memory while parsing", name);
        return ISK_ERR_NOMEM;
    }
    return ISK_OK;
}

isk_status isk__ini_parse(const char *text, const char *name, isk_ini_section_fn section, isk_ini_key_fn fn,
                         void *user, isk_error *err)
{
    return isk__ini_parse_split_from(text, name, section, fn, user, ISK_INI_MAX_LINE, err);
}

isk_status isk__ini_parse_string(const char *text, const char *name, isk_ini_key_fn fn, void *user,
                                isk_error *err)
{
    return isk__ini_parse(text, name, NULL, fn, user, err);
}

isk_status isk__ini_read_file(const char *path, char **text, isk_error *err)
{
    *text = NULL;
    if (!path)
        return isk_error_set(err, ISK_ERR_NULL, "scene: NULL path");
    FILE *f = fopen(path, "rb");
    if (!f)
        return isk_error_set(err, ISK_ERR_IO, "%s: %s", path, strerror(errno));
    char *buf = malloc(ISK_INI_MAX_BYTES + 1);
    if (!buf) {
        fclose(f);
        return isk_error_set(err, ISK_ERR_NOMEM, "%s: out of memory", path);
    }
    size_t n = fread(buf, 1, ISK_INI_MAX_BYTES + 1, f);
    int read_error = ferror(f);
    fclose(f);
    if (read_error) {
        free(buf);
        return isk_error_set(err, ISK_ERR_IO, "%s: read error (is it a directory?)", path);
    }
    if (n > ISK_INI_MAX_BYTES) {
        free(buf);
        return isk_error_set(err, ISK_ERR_SIZE, "%s: file larger than %u bytes", path, ISK_INI_MAX_BYTES);
    }
    const char *nul = memchr(buf, 0, n);
    if (nul) {
        /* A NUL byte would silently end the text early: refuse binary input. */
        int line = 1;
        for (const char *q = buf; q < nul; q++)
            line += *q == '\n';
        free(buf);
        isk__ini_error(err, path, line, "contains a NUL byte (not a text file?)");
        return ISK_ERR_FORMAT;
    }
    buf[n] = 0;
    *text = buf;
    return ISK_OK;
}

isk_status isk__ini_parse_file(const char *path, isk_ini_key_fn fn, void *user, isk_error *err)
{
    char *text;
    isk_status s = isk__ini_read_file(path, &text, err);
    if (s != ISK_OK)
        return s;
    s = isk__ini_parse_string(text, path, fn, user, err);
    free(text);
    return s;
}

static size_t edit_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b);
    if (la > 64 || lb > 64)
        return (size_t)-1;
    size_t row[65];
    for (size_t j = 0; j <= lb; j++)
        row[j] = j;
    for (size_t i = 1; i <= la; i++) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= lb; j++) {
            size_t up = row[j];
            size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            size_t best = diag + cost;
            if (up + 1 < best) best = up + 1;
            if (row[j - 1] + 1 < best) best = row[j - 1] + 1;
            row[j] = best;
            diag = up;
        }
    }
    return row[lb];
}

const char *isk__ini_suggest(const char *word, const char *const *candidates, size_t n)
{
    if (!word)
        return NULL;
    size_t len = strlen(word);
    /* a third of the word, rounded up: "sparx" (5 letters) is 2 edits
     * from "sparks" */
    size_t limit = (len + 2) / 3 > 1 ? (len + 2) / 3 : 1;
    const char *best = NULL;
    size_t best_d = (size_t)-1;
    for (size_t i = 0; i < n; i++) {
        size_t d = edit_distance(word, candidates[i]);
        if (d < best_d) {
            best_d = d;
            best = candidates[i];
        }
    }
    return best_d <= limit ? best : NULL;
}
