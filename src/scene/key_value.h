/* SPDX-License-Identifier: MIT */
/* src/scene/key_value.h — a key's value as text and as a field (internal).
 *
 * Three operations per row of the key table (iskra/keys.h), driven by its
 * type: parse text into the field, check the field's value (what
 * isk_effect_create does for C definitions), and format the field back into
 * text that parses to the same value (isk_effect_get, saving a scene).  The
 * parser and the validation share the range and the message: a failure
 * fills `why` with "expected a number between 0 and 10000000, got "1e8""
 * (the key and where it is are the caller's to add).
 *
 * Files: key_item.c (the items, the shared helpers below), key_parse.c,
 * key_check.c, key_format.c (formatting and the defaults).
 *
 * The items: [scene] and [view] keys live in the isk_effect_def itself,
 * [bounds] in its isk_bounds, [click] in its isk_click_def, the others in
 * the arrays of forces, deflectors, emitters and drawings.
 */
#ifndef ISKRA_SCENE_KEY_VALUE_H
#define ISKRA_SCENE_KEY_VALUE_H

#include <stddef.h>

#include "iskra/effect.h"
#include "iskra/keys.h"

/* How many items of a section the definition holds (1 for the unnamed
 * sections), the i-th item, its name ("" for unnamed sections) and the line
 * it was defined at (0 if unknown or unnamed). */
/* The name rule (names.c): 1 when s, within cap bytes, can name an item
 * in a scene file; and the words a section may not be named. */
int isk__fx_name_ok(const char *s, size_t cap);
int isk__fx_name_reserved(const char *s);

int isk__fx_section_items(const isk_effect_def *d, isk_section_kind s);
void *isk__fx_section_item(isk_effect_def *d, isk_section_kind s, int i);
const void *isk__fx_section_item_c(const isk_effect_def *d, isk_section_kind s, int i);
const char *isk__fx_item_name(const isk_effect_def *d, isk_section_kind s, int i);
int isk__fx_item_line(const isk_effect_def *d, isk_section_kind s, int i);
/* The item's kind (its force kind, source, ...); -1 for sections without. */
int isk__fx_item_kind(const isk_effect_def *d, isk_section_kind s, int i);
/* The most names a REFS list of that section holds (its array's size).  A
 * list of emitters (a probe's) reads "all" as the empty list: every
 * emitter. */
int isk__fx_refs_cap(isk_section_kind refers);
/* Whether a key applies to an item of that kind (-1: every key applies). */
int isk__fx_key_applies(const isk_key *k, int kind);
/* "only for source = stream (this emitter has source = particle)" */
void isk__fx_key_kind_message(const isk_key *k, int kind, char *buf, size_t n);

/* Text -> field.  `d` resolves names (REFS, REF); may be NULL otherwise.
 * ISK_OK, or ISK_ERR_RANGE (ISK_ERR_NOMEM) with the reason in `why`. */
isk_status isk__fx_key_parse(const isk_key *k, void *item, const char *text, const isk_effect_def *d, char *why, size_t n);
/* The field's value checked against the row: ISK_OK, or ISK_ERR_RANGE with
 * the reason. */
isk_status isk__fx_key_check(const isk_key *k, const void *item, const isk_effect_def *d, char *why, size_t n);
/* Field -> text (parses back to the same value); ISK_OK, or ISK_ERR_SIZE if
 * `buf` is too small. */
isk_status isk__fx_key_format(const isk_key *k, const void *item, const isk_effect_def *d, char *buf, size_t n);
/* The section's key most like a misspelt `word`, or NULL. */
const char *isk__fx_key_suggest(isk_section_kind section, const char *word);
/* "a number between 0 and 10000000", "ring, uniform, gauss, coulomb or multi-coulomb" */
void isk__fx_key_expect(const isk_key *k, char *buf, size_t n);

/* Sets the row's default (its `dflt` text) into the item; rows without a
 * default are left alone.  ISK_OK (a bad default is a bug the test of the
 * table catches). */
isk_status isk__fx_key_set_default(const isk_key *k, void *item);
/* Every default of a section into one item. */
void isk__fx_section_defaults(isk_section_kind s, void *item);

/* ---- shared by the key_*.c files ------------------------------------------- */

/* The field at `off` in an item, as a T (a row says which type it is). */
#define FX_AT(T, item, off) ((T *)(void *)((char *)(item) + (off)))
#define FX_AT_C(T, item, off) ((const T *)(const void *)((const char *)(item) + (off)))

/* Whole-number fields (int, long, size_t by the row's type), as a double. */
double isk__fx_whole_get(const isk_key *k, const void *item);
void isk__fx_whole_set(const isk_key *k, void *item, double v);
/* "a number between 0 and 1", "a number > 0" for the row's range. */
void isk__fx_range_words(const isk_key *k, const char *what, char *buf, size_t n);
int isk__fx_in_range(const isk_key *k, double v);
/* why = "expected <the row's expectation>, got "text"" (ISK_ERR_RANGE). */
isk_status isk__fx_expected(const isk_key *k, char *why, size_t n, const char *got);
/* The same with "; did you mean "x"?" from names. */
isk_status isk__fx_expected_or_guess(const isk_key *k, const char *text, const char *const *names, int count, char *why,
                                size_t n);
/* The word standing for a value: its index in k->words, or -1; the word of
 * a value, or NULL. */
int isk__fx_word_index(const isk_key *k, const char *s);
const char *isk__fx_word_of(const isk_key *k, double v);
/* "a, b or c" of the names whose bit is set in mask. */
void isk__fx_join_names(char *buf, size_t n, const char *const *names, int count, unsigned mask);

#endif
