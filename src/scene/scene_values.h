/* SPDX-License-Identifier: MIT */
/* src/scene/scene_values.h — value syntax of scene files (internal).
 *
 * Pure string -> value functions, no messages: each returns 1 when the whole
 * string is a valid value and 0 otherwise; the parser (scene_parse.c) turns a
 * 0 into "FILE:LINE: [section] key: expected ..., got "..."".
 *
 *   number   decimal only: [+-]digits[.digits][e[+-]digits] (".5" and "5."
 *            too), or a fraction of two such numbers "1/60"; the result must
 *            be finite (no nan, inf, hex floats, trailing junk, empty string)
 *   colour   #rrggbb, #rrggbbaa (hex, any case) or a CSS colour name
 *   bool     true/false, yes/no, on/off, 1/0 (any case)
 *   list     comma-separated items, each trimmed, none empty
 */
#ifndef ISKRA_SCENE_VALUES_H
#define ISKRA_SCENE_VALUES_H

#include <stddef.h>
#include <stdint.h>

#include "iskra/color.h"

/* Longest item of a list (one number, name or colour). */
#define SCV_ITEM_MAX 200
/* Most items in one list: every deflector an emitter may name. */
#define SCV_LIST_MAX 256

int isk__scv_number(const char *s, double *out);
/* Decimal digits only, 0..2^64-1. */
int isk__scv_u64(const char *s, uint64_t *out);
int isk__scv_bool(const char *s, int *out);
int isk__scv_color(const char *s, isk_color *out);
/* Splits `s` at commas into trimmed items (pointers into `buf`, which must
 * hold strlen(s)+1 bytes).  Returns 0 for more than `max` items or an empty
 * item; *n = 0 for an empty or blank string. */
int isk__scv_split(const char *s, char *buf, size_t bufsize, char sep, char **items, int max, int *n);
/* Blanks (space, tab, CR) removed from both ends, in place. */
char *isk__scv_trim(char *s);
/* Case-insensitive lookup of s in names[0..n-1]: the index, or -1. */
int isk__scv_lookup(const char *s, const char *const *names, int n);
/* The likely intended one of names[0..n-1] for a misspelt `word` (edit
 * distance, or one swap of adjacent letters: "widht" -> "width"), or NULL. */
const char *isk__scv_suggest(const char *word, const char *const *names, int n);
/* The CSS name of a colour if it has one ("yellow"), else NULL. */
const char *isk__scv_color_name(isk_color c);

/* The CSS colour names we accept (isk__scv_color_count of them, for messages and
 * did-you-mean): the i-th, or NULL. */
const char *isk__scv_color_name_at(int i);
extern const int isk__scv_color_count;

#endif
