/* SPDX-License-Identifier: MIT */
/* The key table's view of a definition's items (iskra/keys.h), which a
 * panel uses to show a running scene's sections and their live keys:
 * counts, names, kinds and the struct of each item; which keys apply to a
 * kind; when isk_effect_set applies each (at once, at the next reset, or
 * never) agrees with what isk_effect_set does. */
#include <criterion/criterion.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/keys.h"
#include "iskra/scene.h"
#include "scene_open.h"

static isk_effect *campfire(void) { return scene_open_builtin("fire_campfire"); }

Test(key_items, the_items_of_a_definition)
{
    isk_effect *fx = campfire();
    const isk_effect_def *d = isk_effect_definition(fx);
    cr_assert_eq(isk_key_items(d, ISK_SECTION_EMITTER), 4);
    cr_assert_eq(isk_key_items(d, ISK_SECTION_FORCE), 2);
    cr_assert_eq(isk_key_items(d, ISK_SECTION_SCENE), 1);
    cr_assert_eq(isk_key_items(NULL, ISK_SECTION_SCENE), 0);
    cr_assert_eq(isk_key_items(d, ISK_SECTION_COUNT), 0);
    cr_assert_str_eq(isk_key_item_name(d, ISK_SECTION_EMITTER, 1), "flame");
    cr_assert_str_eq(isk_key_item_name(d, ISK_SECTION_CLICK, 0), "");
    cr_assert_str_eq(isk_key_item_name(d, ISK_SECTION_EMITTER, 9), "");
    cr_assert_eq(isk_key_item_kind(d, ISK_SECTION_EMITTER, 1), ISK_SOURCE_STREAM);
    cr_assert_eq(isk_key_item_kind(d, ISK_SECTION_FORCE, 1), ISK_FORCE_WIND);
    cr_assert_eq(isk_key_item_kind(d, ISK_SECTION_CLICK, 0), -1);
    cr_assert_eq(isk_key_item(d, ISK_SECTION_EMITTER, 1), &d->emitters[1]);
    cr_assert_eq(isk_key_item(d, ISK_SECTION_SCENE, 0), d);
    cr_assert_null(isk_key_item(d, ISK_SECTION_EMITTER, 4));
    /* a key's offset into the item is its field */
    const isk_key *rate = isk_key_find(ISK_SECTION_EMITTER, "rate");
    const char *item = isk_key_item(d, ISK_SECTION_EMITTER, 1);
    cr_assert_eq(*(const double *)(item + rate->offset), 420.0);
    isk_effect_destroy(fx);
}

Test(key_items, applies_and_when_agree_with_isk_effect_set)
{
    const isk_key *rate = isk_key_find(ISK_SECTION_EMITTER, "rate");
    cr_assert(isk_key_applies(rate, ISK_SOURCE_STREAM));
    cr_assert(!isk_key_applies(rate, ISK_SOURCE_LAYER));
    cr_assert(isk_key_applies(isk_key_find(ISK_SECTION_CLICK, "count"), -1));
    cr_assert(!isk_key_applies(NULL, -1));
    cr_assert_eq(isk_key_when_set(rate, ISK_SOURCE_STREAM), ISK_KEY_WHEN_LIVE);
    cr_assert_eq(isk_key_when_set(isk_key_find(ISK_SECTION_EMITTER, "count"), ISK_SOURCE_LAYER), ISK_KEY_WHEN_RESET);
    cr_assert_eq(isk_key_when_set(isk_key_find(ISK_SECTION_EMITTER, "source"), ISK_SOURCE_STREAM),
                 ISK_KEY_WHEN_CREATED);
    cr_assert_eq(isk_key_when_set(isk_key_find(ISK_SECTION_SCENE, "seed"), -1), ISK_KEY_WHEN_RESET);
    cr_assert_eq(isk_key_when_set(NULL, -1), ISK_KEY_WHEN_CREATED);
    /* every key of every campfire section: "created" ones are refused by
     * isk_effect_set, the others are taken (their own value set back) */
    isk_effect *fx = campfire();
    const isk_effect_def *d = isk_effect_definition(fx);
    int taken = 0, refused = 0;
    for (int s = 0; s < ISK_SECTION_COUNT; s++)
        for (int i = 0; i < isk_key_items(d, (isk_section_kind)s); i++) {
            char section[64];
            const char *name = isk_key_item_name(d, (isk_section_kind)s, i);
            snprintf(section, sizeof section, "%s%s%s", isk_section_name((isk_section_kind)s), *name ? " " : "", name);
            const int kind = isk_key_item_kind(d, (isk_section_kind)s, i);
            for (int r = 0; r < isk_key_count(); r++) {
                const isk_key *k = isk_key_at(r);
                if ((int)k->section != s || !isk_key_applies(k, kind) || k->directive)
                    continue;
                char v[512];
                isk_error err;
                if (isk_effect_get(fx, section, k->name, v, sizeof v, &err) != ISK_OK)
                    continue; /* a value too long for the buffer: not this test's matter */
                isk_status st = isk_effect_set(fx, section, k->name, v, &err);
                if (isk_key_when_set(k, kind) == ISK_KEY_WHEN_CREATED) {
                    cr_expect_neq(st, ISK_OK, "[%s] %s is fixed at creation but was taken", section, k->name);
                    refused++;
                } else {
                    cr_expect_eq(st, ISK_OK, "[%s] %s = %s: %s", section, k->name, v, err.message);
                    taken++;
                }
            }
        }
    cr_expect_gt(taken, 300);
    cr_expect_gt(refused, 10);
    isk_effect_destroy(fx);
}
