/* SPDX-License-Identifier: MIT */
/* Names in the key table (iskra/keys.h) cannot drift, checked over every
 * row:
 *   - a row's meaning never lists its names by hand (at most one of them
 *     appears in it): the lists come from the name tables, as the range
 *     text (every name) and the notes (what each name means);
 *   - a row with notes has one for every name, and isk_key_meaning_text
 *     shows each;
 *   - the `preset` row's names are the presets (isk_preset_name);
 *   - every key that names another item (on_death, on_hit, forces,
 *     deflectors, the click's emitter: the REF and REFS rows) suggests the
 *     item meant for a misspelt name, as does a misspelt preset, and a
 *     force or drawing section named like a kind it is not. */
#include <criterion/criterion.h>
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/keys.h"
#include "iskra/presets.h"
#include "iskra/scene.h"

/* `word` appears in `text` as a whole word (letters, digits, '-' and '_'
 * around it do not count as boundaries). */
static int has_word(const char *text, const char *word)
{
    size_t n = strlen(word);
    for (const char *p = strstr(text, word); p; p = strstr(p + 1, word)) {
        int before = p > text && (isalnum((unsigned char)p[-1]) || p[-1] == '-' || p[-1] == '_');
        int after = isalnum((unsigned char)p[n]) || p[n] == '-' || p[n] == '_';
        if (!before && !after)
            return 1;
    }
    return 0;
}

static const char *row_label(const isk_key *k, char *buf, size_t n)
{
    snprintf(buf, n, "[%s] %s", isk_section_name(k->section), k->name);
    return buf;
}

Test(key_meanings, no_meaning_lists_names_by_hand)
{
    int rows_with_names = 0;
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        if (!k->names)
            continue;
        rows_with_names++;
        char label[80], found[400] = "";
        int hits = 0;
        for (int j = 0; j < k->nnames; j++)
            if (has_word(k->meaning, k->names[j])) {
                hits++;
                snprintf(found + strlen(found), sizeof found - strlen(found), " %s", k->names[j]);
            }
        cr_assert_leq(hits, 1,
                      "%s: its meaning names%s by hand (\"%s\"): say what each name means in the row's notes, "
                      "which isk_key_meaning_text joins to it",
                      row_label(k, label, sizeof label), found, k->meaning);
        /* ... and the range text lists every one */
        char range[600];
        isk_key_range_text(k, range, sizeof range);
        for (int j = 0; j < k->nnames; j++)
            cr_assert(has_word(range, k->names[j]), "%s: range \"%s\" lacks %s", label, range, k->names[j]);
    }
    cr_assert_geq(rows_with_names, 25, "the rows with names: %d", rows_with_names);
}

Test(key_meanings, notes_say_what_every_name_means)
{
    int rows_with_notes = 0;
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        char label[80], text[3000];
        row_label(k, label, sizeof label);
        isk_key_meaning_text(k, text, sizeof text);
        cr_assert_eq(strncmp(text, k->meaning, strlen(k->meaning)), 0, "%s: %s", label, text);
        if (!k->notes) {
            cr_assert_str_eq(text, k->meaning, "%s", label);
            continue;
        }
        rows_with_notes++;
        cr_assert(k->type == ISK_KEY_ENUM && k->names, "%s: notes on a row without names", label);
        for (int j = 0; j < k->nnames; j++) {
            cr_assert(k->notes[j] && *k->notes[j], "%s: no note for %s", label, k->names[j]);
            char want[600];
            snprintf(want, sizeof want, "%s%s = %s", j ? "; " : ": ", k->names[j], k->notes[j]);
            cr_assert_not_null(strstr(text, want), "%s: \"%s\" lacks \"%s\"", label, text, want);
        }
    }
    cr_assert_geq(rows_with_notes, 10);
    /* the source key names all five sources, sub included */
    char text[3000];
    isk_key_meaning_text(isk_key_find(ISK_SECTION_EMITTER, "source"), text, sizeof text);
    cr_assert_not_null(strstr(text, "; sub = a sub-emitter"), "%s", text);
    isk_key_meaning_text(NULL, text, sizeof text);
    cr_assert_str_eq(text, "");
    /* no buffer, an empty one, a short one (truncated, terminated) */
    const isk_key *draw = isk_key_find(ISK_SECTION_EMITTER, "draw");
    isk_key_meaning_text(draw, NULL, 10);
    char small[8] = "xyzxyzx";
    isk_key_meaning_text(draw, small, 0);
    cr_assert_str_eq(small, "xyzxyzx");
    isk_key_meaning_text(draw, small, sizeof small);
    cr_assert_str_eq(small, "how a p");
}

Test(key_meanings, the_preset_key_names_every_preset)
{
    const isk_key *k = isk_key_find(ISK_SECTION_EMITTER, "preset");
    cr_assert_not_null(k);
    cr_assert_eq(k->nnames, isk_preset_count());
    char range[600];
    isk_key_range_text(k, range, sizeof range);
    for (int i = 0; i < isk_preset_count(); i++) {
        cr_assert_str_eq(k->names[i], isk_preset_name(i));
        cr_assert(has_word(range, isk_preset_name(i)), "%s lacks %s", range, isk_preset_name(i));
    }
}

/* The scene is refused with a message containing `want`. */
static void refused_with(const char *scene, const char *want)
{
    isk_effect_def d;
    isk_error err = {0};
    isk_status s = isk_scene_load_string(&d, scene, "t.ini", &err);
    if (s == ISK_OK)
        isk_effect_def_free(&d);
    cr_assert_neq(s, ISK_OK, "accepted:\n%s", scene);
    cr_assert_not_null(strstr(err.message, want), "\"%s\" lacks \"%s\" for:\n%s", err.message, want, scene);
}

/* An item of section `type` named `name` that loads by itself. */
static void item_text(isk_section_kind type, const char *name, char *buf, size_t n)
{
    switch (type) {
    case ISK_SECTION_FORCE: snprintf(buf, n, "[force %s]\nkind = gravity\ng = 1\n", name); return;
    case ISK_SECTION_DEFLECTOR: snprintf(buf, n, "[deflector %s]\nsegment = 0, 0, 1, 0\n", name); return;
    case ISK_SECTION_EMITTER: snprintf(buf, n, "[emitter %s]\nsource = sub\ncount = 1\n", name); return;
    default: cr_assert_fail("a reference to [%s]: teach item_text its items", isk_section_name(type));
    }
}

Test(key_meanings, every_key_naming_an_item_suggests_the_one_meant)
{
    int refs = 0;
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        if (k->type != ISK_KEY_REF && k->type != ISK_KEY_REFS)
            continue;
        refs++;
        /* the user's section, of a kind the key applies to */
        char user[200], target[200], scene[600];
        if (k->section == ISK_SECTION_EMITTER) {
            int kind = ISK_SOURCE_STREAM;
            if (k->applies && !(k->applies >> kind & 1u))
                for (kind = 0; !(k->applies >> kind & 1u); kind++)
                    ;
            snprintf(user, sizeof user, "[emitter user]\nsource = %s\n", isk_source_names[kind]);
        } else if (k->section == ISK_SECTION_PROBE) {
            snprintf(user, sizeof user, "[probe user]\nkind = totals\n");
        } else {
            cr_assert(!isk_section_named(k->section), "[%s] %s: teach this test its section",
                      isk_section_name(k->section), k->name);
            snprintf(user, sizeof user, "[%s]\n", isk_section_name(k->section));
        }
        /* the misspelling of the brief: two edits in five letters */
        item_text(k->refers, "sparks", target, sizeof target);
        snprintf(scene, sizeof scene, "%s%s%s = sparx\n", target, user, k->name);
        char want[120];
        snprintf(want, sizeof want, "%s: no %s named 'sparx'; did you mean 'sparks'?", k->name,
                 isk_section_name(k->refers));
        refused_with(scene, want);
    }
    cr_assert_geq(refs, 5, "on_death, on_hit, forces, deflectors, the click's emitter: %d rows", refs);
}

Test(key_meanings, presets_and_kinds_by_name_suggest_too)
{
    refused_with("[emitter e]\npreset = firee\n", "no preset 'firee'; did you mean 'fire'? (the presets: fire, smoke");
    refused_with("[emitter e]\npreset = fireworx, 2\n", "did you mean 'fireworks'?");
    refused_with("[force gravty]\ng = 1\n",
                 "[force gravty] needs kind = gravity, drag, wind, potential or turbulence; did you mean [force "
                 "gravity]?");
    refused_with("[drawing polylin]\ncolor = red\n", "needs kind = polyline, disc, text, polygon or sprite; did "
                                                     "you mean [drawing polyline]?");
    /* the lists are the name tables': every force kind and drawing kind */
    const isk_key *kinds[] = {isk_key_find(ISK_SECTION_FORCE, "kind"), isk_key_find(ISK_SECTION_DRAWING, "kind")};
    const char *scenes[] = {"[force zzzz]\ng = 1\n", "[drawing zzzz]\ncolor = red\n"};
    for (int i = 0; i < 2; i++) {
        isk_effect_def d;
        isk_error err = {0};
        cr_assert_neq(isk_scene_load_string(&d, scenes[i], "t.ini", &err), ISK_OK);
        for (int j = 0; j < kinds[i]->nnames; j++)
            cr_assert(has_word(err.message, kinds[i]->names[j]), "%s lacks %s", err.message, kinds[i]->names[j]);
    }
}
