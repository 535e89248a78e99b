/* SPDX-License-Identifier: MIT */
/* src/scene/effect_check.h — validation of effect definitions (internal).
 *
 * One set of checks serves the scene parser and isk_effect_create: the
 * rows of the key table check each field (type, range), and one function
 * per section checks what involves several fields (a layer's count against
 * its limit, a stream's shape, a view's window...).  Only the reporter
 * differs: the parser says "FILE:LINE: [emitter smoke] rate: ..." with the
 * key's line, create says "emitter 'smoke' (line 12): rate: ...".
 */
#ifndef ISKRA_SCENE_EFFECT_CHECK_H
#define ISKRA_SCENE_EFFECT_CHECK_H

#include "iskra/effect.h"
#include "iskra/keys.h"

typedef struct fx_report fx_report;

struct fx_report {
    /* A failure of item `index` of `section`: `key` is the key it is about
     * (its line is the best place to point at) or NULL for the item as a
     * whole; with show_key the message reads "key: msg", else "msg". */
    void (*emit)(fx_report *r, isk_status s, isk_section_kind section, int index, const char *key, int show_key,
                 const char *msg);
    void *ctx;
    isk_status status; /* ISK_OK until the first failure */
};

/* Checks one item: its fields against their rows (with `rows`), then what
 * spans fields.  ISK_OK, or the first failure's status after reporting it. */
isk_status isk__fx_check_item(const isk_effect_def *d, isk_section_kind s, int index, int rows, fx_report *r);

/* The whole definition: structure (counts, arrays, unique names), then
 * every item with its rows. */
isk_status isk__fx_check_def(const isk_effect_def *d, fx_report *r);

#endif
