/* SPDX-License-Identifier: MIT */
/* The scene's settings in isk_effect_describe (see effect_describe.h). */
#include "effect_describe.h"

#include <string.h>

#include "key_value.h"

/* Every key of one item that applies to its kind, "key = value; ...", as a
 * scene file would say it.  An empty value (a reference to the first
 * emitter, no sub-emitter) is shown as its default in words. */
static void item_keys(const isk_effect_def *d, isk_section_kind s, int index, FILE *out)
{
    const void *item = isk__fx_section_item_c(d, s, index);
    const int kind = isk__fx_item_kind(d, s, index);
    int first = 1;
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        if (k->section != s || k->directive || !isk__fx_key_applies(k, kind))
            continue;
        char value[512];
        if (isk__fx_key_format(k, item, d, value, sizeof value) != ISK_OK)
            snprintf(value, sizeof value, "(too long to show)");
        else if (!value[0])
            isk_key_default_text(k, value, sizeof value);
        fprintf(out, "%s%s = %s", first ? "" : "; ", k->name, value);
        first = 0;
    }
    fputc('\n', out);
}

void isk__fx_describe_settings(const isk_effect_def *d, FILE *out)
{
    fprintf(out, "[scene] ");
    item_keys(d, ISK_SECTION_SCENE, 0, out);
    if (d->bounds.sides) {
        fprintf(out, "[bounds] ");
        item_keys(d, ISK_SECTION_BOUNDS, 0, out);
    }
    for (int i = 0; i < d->ndeflectors; i++) {
        fprintf(out, "[deflector %s] ", d->deflectors[i].name);
        item_keys(d, ISK_SECTION_DEFLECTOR, i, out);
    }
    if (d->click.enabled || d->click.at_start) {
        fprintf(out, "[click] ");
        item_keys(d, ISK_SECTION_CLICK, 0, out);
    }
}
