/* SPDX-License-Identifier: MIT */
/* src/scene/ini_read.h — INI reading with line numbers (internal).
 *
 * libinih splits each line into key and value (trimming, inline comments).
 * It is fed through our own line reader, because Debian's build of it
 * cannot do the rest of what scene files need:
 *   - no line numbers (built without INI_HANDLER_LINENO): the reader counts;
 *   - no call for a new section (INI_CALL_HANDLER_ON_NEW_SECTION is off), so
 *     sections without keys would be invisible, and names are cut at 50
 *     characters: the reader reports every header itself, whole, in order;
 *   - it goes on after a syntax error (INI_STOP_ON_FIRST_ERROR is off) and
 *     only says where the first one was at the very end, after calling back
 *     for later lines: the reader recognises a line libinih would refuse
 *     (a header without ']', text after ']', no '=' or ':', no key) and stops
 *     there, so errors always come in file order;
 *   - an indented line continues the previous value (INI_ALLOW_MULTILINE is
 *     on): the reader strips leading blanks, so indented keys are just keys;
 *   - its line buffer holds 199 characters (a longer line would be split
 *     in two): the reader splits a longer line into key and value itself,
 *     by the very rules libinih applies (trimming, inline comments), calls
 *     back in order, and hands libinih a stand-in that keeps its line count
 *     and section.  Lines are refused above ISK_INI_MAX_LINE.
 * Every callback gets its line; the first error stops the parse and is
 * reported as "FILE:LINE: message".
 *
 *     static int on_key(void *u, const char *sec, const char *key,
 *                       const char *val, int line, isk_error *err) { ... }
 *     isk__ini_parse_file("scene.ini", on_key, &state, &err);
 *
 * A callback returns ISK_OK to go on; any other isk_status stops parsing (it
 * has filled *err, normally through isk__ini_error()).
 */
#ifndef ISKRA_SCENE_INI_READ_H
#define ISKRA_SCENE_INI_READ_H

#include <stddef.h>

#include "iskra/status.h"

/* Longest accepted line, in bytes without the newline: 64 KiB - 1, room
 * for a 64-point polyline or a list of every deflector at full precision. */
#define ISK_INI_MAX_LINE 65535
/* Largest accepted input, so a scene can never make us read without bound. */
#define ISK_INI_MAX_BYTES (4u * 1024u * 1024u)

typedef isk_status (*isk_ini_key_fn)(void *user, const char *section, const char *key, const char *value,
                              int line, isk_error *err);

/* Called for every section header, with the text between '[' and ']'
 * (untrimmed), before any key of the section. */
typedef isk_status (*isk_ini_section_fn)(void *user, const char *header, int line, isk_error *err);

/* `text` is NUL-terminated; `name` is used in messages (a path or "<string>"). */
isk_status isk__ini_parse_string(const char *text, const char *name, isk_ini_key_fn fn, void *user,
                                isk_error *err);
/* The same with a callback for section headers too (`section` may be NULL). */
isk_status isk__ini_parse(const char *text, const char *name, isk_ini_section_fn section, isk_ini_key_fn fn,
                         void *user, isk_error *err);
/* isk__ini_parse, splitting itself every line longer than split_from
 * bytes (isk__ini_parse: libinih's buffer, ISK_INI_MAX_LINE), so a test can
 * check that both routes call back alike (split_from 0: every line). */
isk_status isk__ini_parse_split_from(const char *text, const char *name, isk_ini_section_fn section,
                                     isk_ini_key_fn fn, void *user, size_t split_from, isk_error *err);
/* Reads a whole text file (at most ISK_INI_MAX_BYTES, no NUL bytes) into a
 * malloc'd NUL-terminated string for the caller to free. */
isk_status isk__ini_read_file(const char *path, char **text, isk_error *err);
/* Reads the whole file (as isk__ini_read_file) and parses it. */
isk_status isk__ini_parse_file(const char *path, isk_ini_key_fn fn, void *user, isk_error *err);

/* Formats "NAME:LINE: message" into err with ISK_ERR_FORMAT and returns
 * ISK_ERR_FORMAT, so a callback can `return isk__ini_error(...)`. */
isk_status isk__ini_error(isk_error *err, const char *name, int line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* The candidate closest to `word` by edit distance if it is close enough to
 * be a likely misspelling (distance <= max(1, ceil(len/3))), else NULL. */
const char *isk__ini_suggest(const char *word, const char *const *candidates, size_t n);

#endif
