/* SPDX-License-Identifier: MIT */
/* iskra/keys.h — every key of a scene file, as one table: the only place
 * where a key's type, field, range, default, enum names, liveness and
 * meaning are written down.
 *
 * Everything that knows about keys reads these rows: the INI parser
 * (iskra/scene.h), the validation of C definitions in isk_effect_create,
 * the defaults isk_effect_def_init and the isk_effect_def_add_* functions
 * set, live changes (isk_effect_set / isk_effect_get), `iskra keys`, the key
 * tables of docs/scene-format.md (generated from here; a test fails when
 * they differ) and the simulator's panel.  Adding a key is adding a row.
 *
 * Example:
 *
 *     for (int i = 0; i < isk_key_count(); i++) {
 *         const isk_key *k = isk_key_at(i);
 *         printf("[%s] %s = %s  ; %s\n", isk_section_name(k->section), k->name, k->dflt, k->meaning);
 *     }
 *     const isk_key *rate = isk_key_find(ISK_SECTION_EMITTER, "rate");   // NULL: no such key
 *     if (rate) printf("rate: %g to %g\n", rate->min, rate->max);           // 0 to 1e+07
 *
 * A row's `offset` is the field's offsetof in the section's item struct:
 * isk_effect_def for [scene] and [view], isk_force_def, isk_deflector_def,
 * isk_bounds, isk_emitter_def (a field of one of its parts:
 * offsetof(isk_emitter_def, born.rate) for `rate`), isk_drawing_def,
 * isk_click_def and isk_probe_def.
 *
 * Kinds: some sections have a kind that decides which keys apply (a
 * force's `kind`, an emitter's `source`, a drawing's or a probe's `kind`,
 * the walls' `mode`, the view's window or camera).  `applies`, `required` and `live`
 * are bit sets over that kind's values (bit k: value k); 0 in `applies`
 * means every kind.
 */
#ifndef ISKRA_KEYS_H
#define ISKRA_KEYS_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum isk_section_kind {
    ISK_SECTION_SCENE = 0, /* [scene] */
    ISK_SECTION_VIEW,      /* [view] */
    ISK_SECTION_FORCE,     /* [force NAME] */
    ISK_SECTION_DEFLECTOR, /* [deflector NAME] */
    ISK_SECTION_BOUNDS,    /* [bounds] */
    ISK_SECTION_EMITTER,   /* [emitter NAME] */
    ISK_SECTION_DRAWING,   /* [drawing NAME] */
    ISK_SECTION_CLICK,     /* [click] */
    ISK_SECTION_PROBE,     /* [probe NAME] */
    ISK_SECTION_COUNT
} isk_section_kind;

typedef enum isk_key_type {
    ISK_KEY_NUMBER = 0,   /* double: decimal or a fraction "1/60" */
    ISK_KEY_WHOLE,        /* int: a number without a fraction ("1e4" is fine) */
    ISK_KEY_LONG,         /* long, likewise */
    ISK_KEY_COUNT,        /* size_t, likewise */
    ISK_KEY_SEED,         /* uint64_t: decimal digits */
    ISK_KEY_BOOL,         /* int 0/1: true/false, yes/no, on/off, 1/0 */
    ISK_KEY_COLOR,        /* isk_color: #rrggbb, #rrggbbaa or a CSS name */
    ISK_KEY_ENUM,         /* an int-sized enum: one of `names` */
    ISK_KEY_VECTOR,       /* two doubles "x, y" */
    ISK_KEY_POINT,        /* an optional point: two doubles, or "none"; `aux` is the int "given" flag */
    ISK_KEY_ANGLE,        /* double in radians, written in degrees ("90") or radians ("1.5 rad") */
    ISK_KEY_PAIR,         /* two doubles "min, max" with min <= max */
    ISK_KEY_NUMBERS4,     /* four doubles */
    ISK_KEY_COLOR_STOPS,  /* isk_color_ramp: "t:colour, ..." or "off" */
    ISK_KEY_SCALAR_STOPS, /* isk_scalar_ramp: "t:value, ..." or "off" */
    ISK_KEY_TEXT,         /* char[aux]: the rest of the line */
    ISK_KEY_SIDES,        /* unsigned bit set of ISK_SIDE_*: "top, left", "all", "none" */
    ISK_KEY_POINTS,       /* double *points (owned) with int npoints at `aux` */
    ISK_KEY_REFS,         /* names of [force]s or [deflector]s -> int indices, count at `aux` */
    ISK_KEY_REF,          /* the name of an [emitter] -> int index (-1: the first) */
    ISK_KEY_TYPE_COUNT
} isk_key_type;

/* Bounds of a range: none, inclusive (<=) or exclusive (<). */
enum { ISK_BOUND_NONE = 0, ISK_BOUND_INCL = 1, ISK_BOUND_EXCL = 2 };

/* A word that stands for a value ("forever" = INFINITY, "off" = -1). */
typedef struct isk_key_word {
    const char *word;
    double value;
} isk_key_word;

typedef struct isk_key {
    isk_section_kind section;
    const char *name;
    isk_key_type type;
    size_t offset;            /* offsetof the field in the section's item struct */
    size_t aux;               /* TEXT: buffer size; POINT: offset of the int flag; POINTS/REFS:
                                 offset of the int count */
    unsigned applies;         /* kinds it applies to (0: every kind) */
    unsigned required;        /* kinds for which a scene file must give it */
    unsigned char lo_bound, hi_bound; /* ISK_BOUND_*: the range [min, max] of the value (of each
                                 item for lists; of the degrees for angles; of the count of
                                 points for POINTS; of the values of scalar stops) */
    double min, max;
    const char *const *names; /* ENUM: names[value], nnames of them; SIDES: the side names; TEXT:
                                 the names it accepts (`preset`), or NULL for any text */
    int nnames;
    const isk_key_word *words; /* NUMBER, WHOLE, COUNT, ENUM: words standing for values (NULL-terminated) */
    const char *what;         /* how messages name the value ("a number of seconds"); for lists of
                                 numbers, their form ("x0, y0, x1, y1"); NULL: by type */
    isk_section_kind refers;  /* REFS, REF: the section whose names it lists */
    const char *dflt;         /* the default, in the key's own syntax ("" when there is none) */
    const char *dflt_doc;     /* when the default is not a constant: how it is chosen (else NULL) */
    unsigned live;            /* kinds for which isk_effect_set applies it from the next step; other
                                 kinds: stored at once, used from the next isk_effect_reset */
    int create_only;          /* 1: only at creation (isk_effect_set refuses it) */
    int directive;            /* 1: acts where it stands in a scene file (`preset`); what it did is in
                                 the other fields, so scene files are written without it */
    const char *meaning;      /* one line; it never lists the names: the range text lists them
                                 (isk_key_range_text), and `notes` say what each means */
    const char *const *notes; /* ENUM: notes[value], what each name means (nnames of them), or
                                 NULL; isk_key_meaning_text joins them to the meaning */
} isk_key;

#define ISK_KEY_ALL_KINDS (~0u)

/* The rows, section by section, in the order of docs/scene-format.md. */
int isk_key_count(void);
const isk_key *isk_key_at(int i);                 /* NULL when out of range */
const isk_key *isk_key_find(isk_section_kind section, const char *name); /* NULL: no such key */

/* "scene", "view", "force", ... ; NULL when out of range. */
const char *isk_section_name(isk_section_kind section);
/* 1 for sections written [type NAME] (force, deflector, emitter, drawing, probe). */
int isk_section_named(isk_section_kind section);
/* The section type of a name ("emitter" -> ISK_SECTION_EMITTER); -1 if none. */
int isk_section_find(const char *type);
/* How the section's kind is spelled ("kind", "source", "mode"; "" for
 * [view]'s window/camera; NULL when the section has no kinds), and the names
 * of its kinds (count in *n). */
const char *isk_section_kind_key(isk_section_kind section);
const char *const *isk_section_kind_names(isk_section_kind section, int *n);

/* "number", "whole", "boolean", ... (for tables). */
const char *isk_key_type_name(isk_key_type type);

/* The words an ENUM (or SIDES) key accepts: its names, then the words that
 * stand for values ("scene"); at most max into out, returns how many. */
int isk_key_choices(const isk_key *k, const char **out, int max);

/* ---- a definition's sections, item by item ---------------------------------
 * For panels that show a running scene's keys (`iskra play`'s inspector):
 *
 *     const isk_effect_def *d = isk_effect_definition(fx);
 *     for (int i = 0; i < isk_key_items(d, ISK_SECTION_EMITTER); i++) {
 *         int kind = isk_key_item_kind(d, ISK_SECTION_EMITTER, i);          // its source
 *         for (int r = 0; r < isk_key_count(); r++) {
 *             const isk_key *k = isk_key_at(r);
 *             if (k->section == ISK_SECTION_EMITTER && isk_key_applies(k, kind) &&
 *                 isk_key_when_set(k, kind) != ISK_KEY_WHEN_CREATED)
 *                 ...;  // "emitter NAME", k->name: a key isk_effect_set takes
 *         }
 *     }
 */
struct isk_effect_def;
/* How many items of section s the definition holds (1 for the unnamed
 * sections [scene], [view], [bounds], [click]; 0 for a NULL definition). */
int isk_key_items(const struct isk_effect_def *d, isk_section_kind s);
/* Item i's name ("" for the unnamed sections and out of range), its kind
 * (the value of its kind key: a force's kind, an emitter's source, the
 * walls' mode, the view's window or camera; -1 for sections without kinds
 * and out of range), and the struct its keys' offsets point into (NULL
 * out of range). */
const char *isk_key_item_name(const struct isk_effect_def *d, isk_section_kind s, int i);
int isk_key_item_kind(const struct isk_effect_def *d, isk_section_kind s, int i);
const void *isk_key_item(const struct isk_effect_def *d, isk_section_kind s, int i);
/* Whether the key applies to an item of that kind (-1: any kind). */
int isk_key_applies(const isk_key *k, int kind);
/* What isk_effect_set does with the key for an item of that kind. */
typedef enum isk_key_when {
    ISK_KEY_WHEN_LIVE = 0, /* applies from the next step */
    ISK_KEY_WHEN_RESET,    /* stored at once, used from the next isk_effect_reset */
    ISK_KEY_WHEN_CREATED   /* refused: fixed when the effect is created (the kinds, width, height) */
} isk_key_when;
isk_key_when isk_key_when_set(const isk_key *k, int kind);

/* A row in words, for tables (`iskra keys`, docs/scene-format.md, panels):
 *   range:   "0..10000000", "> 0", "semi-euler, euler, ..." (the names of enums and of
 *            keys that take a name from a list), ""
 *   kinds:   the kinds of `mask` ("explosion, layer, stream"); "" for every kind
 *   default: the default as written, how it is chosen, or "required"
 *   live:    "yes", "at reset", "no" (only at creation), or "stream (others at reset)" */
void isk_key_range_text(const isk_key *k, char *buf, size_t n);
void isk_key_kinds_text(const isk_key *k, unsigned mask, char *buf, size_t n);
void isk_key_default_text(const isk_key *k, char *buf, size_t n);
void isk_key_live_text(const isk_key *k, char *buf, size_t n);
/* The meaning with what each name means, when the row has notes:
 *   "what the emitter is: particle = one particle; explosion = ..." */
void isk_key_meaning_text(const isk_key *k, char *buf, size_t n);

#ifdef __cplusplus
}
#endif

#endif
