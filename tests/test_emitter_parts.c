/* SPDX-License-Identifier: MIT */
/* The parts of an emitter (isk_emitter_def in iskra/effect.h), the key
 * table and the table of docs/versioning.md agree, field by field:
 *   - each field is where its key writes: the key row's offset (a list's
 *     count at the row's aux, a pair's second number right after its
 *     first), so no key reaches into the wrong part;
 *   - every [emitter NAME] key has its field here (`preset`, a record at
 *     the top of the struct, too);
 *   - a field is named by the rule the header states: the key's name, less
 *     the part's name where the key starts with it (kind and seconds where
 *     nothing is left), _min and _max for a pair, n and the key for a
 *     list's count;
 *   - docs/versioning.md has a row "| `old` | `part.field` | `key`" for
 *     each, so a program moving from 0.2 finds every old field. */
#include <criterion/criterion.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/keys.h"

enum role { FIELD, COUNT, SECOND };

typedef struct part_field {
    const char *old;  /* the flat field of 0.2 */
    const char *part; /* its part now */
    const char *name; /* its name in the part */
    const char *key;  /* the scene key it holds */
    enum role role;   /* the key's own field, a list's count, a pair's second number */
    size_t offset;    /* offsetof(isk_emitter_def, part.name) */
} part_field;

#define ROW(old, part, name, key, role) {#old, #part, #name, key, role, offsetof(isk_emitter_def, part.name)}
/* a field new since the parts: no flat field of 0.2 to migrate from */
#define NEW(part, name, key) {NULL, #part, #name, key, FIELD, offsetof(isk_emitter_def, part.name)}

static const part_field fields[] = {
    ROW(source, born, source, "source", FIELD),
    ROW(pos, born, position, "position", FIELD),
    ROW(shape, born, shape, "shape", FIELD),
    ROW(shape_a, born, shape_a, "shape_a", FIELD),
    ROW(shape_b, born, shape_b, "shape_b", FIELD),
    ROW(shape_angle, born, shape_angle, "shape_angle", FIELD),
    ROW(shape_faithful, born, shape_faithful, "shape_faithful", FIELD),
    ROW(explosion, born, explosion, "explosion", FIELD),
    ROW(count, born, count, "count", FIELD),
    ROW(limit, born, limit, "limit", FIELD),
    ROW(kick, born, kick, "kick", FIELD),
    ROW(start, born, start, "start", FIELD),
    ROW(rect, born, rect, "rect", FIELD),
    ROW(rate, born, rate, "rate", FIELD),
    ROW(rate_mode, born, rate_mode, "rate_mode", FIELD),
    ROW(birth, born, birth, "birth", FIELD),
    ROW(burst_every, born, burst_every, "burst_every", FIELD),
    ROW(duration, born, duration, "duration", FIELD),
    ROW(loop, born, loop, "loop", FIELD),
    ROW(prewarm, born, prewarm, "prewarm", FIELD),
    ROW(emitter_velocity, born, emitter_velocity, "emitter_velocity", FIELD),
    ROW(space, born, space, "space", FIELD),
    ROW(capacity, born, capacity, "capacity", FIELD),
    NEW(born, active, "active"),
    ROW(launch, launch, kind, "launch", FIELD),
    ROW(vel, launch, velocity, "velocity", FIELD),
    ROW(angle, launch, angle, "angle", FIELD),
    ROW(spread, launch, spread, "spread", FIELD),
    ROW(speed_min, launch, speed_min, "speed_min", FIELD),
    ROW(speed_max, launch, speed_max, "speed_max", FIELD),
    ROW(mass, launch, mass, "mass", FIELD),
    ROW(mass_range, launch, mass_range, "mass_range", FIELD),
    ROW(inherit, launch, inherit, "inherit", FIELD),
    NEW(launch, outward, "launch_outward"),
    ROW(life, life, seconds, "life", FIELD),
    ROW(life_range, life, range, "life_range", FIELD),
    ROW(forces, motion, forces, "forces", FIELD),
    ROW(nforces, motion, nforces, "forces", COUNT),
    ROW(deflectors, motion, deflectors, "deflectors", FIELD),
    ROW(ndeflectors, motion, ndeflectors, "deflectors", COUNT),
    ROW(bounded, motion, bounded, "bounded", FIELD),
    NEW(motion, paused, "paused"),
    ROW(draw_before_bounce, motion, draw_before_bounce, "draw_before_bounce", FIELD),
    ROW(gravity_mult, motion, gravity_multiplier, "gravity_multiplier", FIELD),
    ROW(weight, motion, weight, "weight", FIELD),
    ROW(slowing, motion, slowing, "slowing", FIELD),
    ROW(slow_faithful, motion, slow_faithful, "slow_faithful", FIELD),
    ROW(radial_accel, motion, radial_accel, "radial_accel", FIELD),
    ROW(tangential_accel, motion, tangential_accel, "tangential_accel", FIELD),
    NEW(motion, radial_accel_range, "radial_accel_range"),
    NEW(motion, tangential_accel_range, "tangential_accel_range"),
    NEW(motion, wind_range, "wind_range"),
    NEW(motion, slowing_range, "slowing_range"),
    ROW(osc_omega_min, motion, osc_omega_min, "osc_omega", FIELD),
    ROW(osc_omega_max, motion, osc_omega_max, "osc_omega", SECOND),
    ROW(osc_amp_min, motion, osc_amplitude_min, "osc_amplitude", FIELD),
    ROW(osc_amp_max, motion, osc_amplitude_max, "osc_amplitude", SECOND),
    ROW(osc_decay, motion, osc_decay, "osc_decay", FIELD),
    ROW(osc_faithful, motion, osc_faithful, "osc_faithful", FIELD),
    ROW(osc_table, motion, osc_table, "osc_table", FIELD),
    ROW(osc_random_phase, motion, osc_random_phase, "osc_random_phase", FIELD),
    ROW(integrator, motion, integrator, "integrator", FIELD),
    ROW(substeps, motion, substeps, "substeps", FIELD),
    ROW(draw, look, draw, "draw", FIELD),
    ROW(sprite, look, sprite, "sprite", FIELD),
    ROW(size, look, size, "size", FIELD),
    ROW(size_range, look, size_range, "size_range", FIELD),
    ROW(color, look, color, "color", FIELD),
    ROW(color_pick, look, color_pick, "color_pick", FIELD),
    ROW(blend, look, blend, "blend", FIELD),
    ROW(color_over_life, look, color_over_life, "color_over_life", FIELD),
    ROW(alpha_over_life, look, alpha_over_life, "alpha_over_life", FIELD),
    ROW(size_over_life, look, size_over_life, "size_over_life", FIELD),
    ROW(order, look, order, "order", FIELD),
    NEW(look, draw_order, "draw_order"),
    ROW(rotation, look, rotation, "rotation", FIELD),
    ROW(rotation_range, look, rotation_range, "rotation_range", FIELD),
    ROW(spin, look, spin, "spin", FIELD),
    ROW(spin_range, look, spin_range, "spin_range", FIELD),
    NEW(look, spin_end, "spin_end"),
    ROW(align, look, align, "align", FIELD),
    ROW(texture, look, texture, "texture", FIELD),
    ROW(texture_grid, look, texture_grid, "texture_grid", FIELD),
    ROW(texture_fps, look, texture_fps, "texture_fps", FIELD),
    NEW(look, flipbook_random_start, "flipbook_random_start"),
    NEW(look, texture_origin, "texture_origin"),
    ROW(trail, look, trail, "trail", FIELD),
    ROW(trail_width, look, trail_width, "trail_width", FIELD),
    ROW(trail_fade, look, trail_fade, "trail_fade", FIELD),
    ROW(on_death, events, on_death, "on_death", FIELD),
    ROW(on_hit, events, on_hit, "on_hit", FIELD),
};

#define NFIELDS ((int)(sizeof fields / sizeof fields[0]))

static const isk_key *emitter_key(const char *name)
{
    const isk_key *k = isk_key_find(ISK_SECTION_EMITTER, name);
    cr_assert_not_null(k, "no [emitter] key %s", name);
    return k;
}

Test(emitter_parts, every_field_is_where_its_key_writes)
{
    for (int i = 0; i < NFIELDS; i++) {
        const part_field *f = &fields[i];
        const isk_key *k = emitter_key(f->key);
        size_t want = f->role == COUNT ? k->aux : f->role == SECOND ? k->offset + sizeof(double) : k->offset;
        cr_assert_eq(f->offset, want, "%s.%s: at %zu, the key %s writes at %zu", f->part, f->name, f->offset, f->key,
                     want);
    }
    cr_assert_eq(emitter_key("preset")->offset, offsetof(isk_emitter_def, preset));
}

Test(emitter_parts, every_key_has_its_field)
{
    int keys = 0;
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        if (k->section != ISK_SECTION_EMITTER || !strcmp(k->name, "preset"))
            continue;
        keys++;
        int found = 0;
        for (int j = 0; j < NFIELDS; j++)
            found += fields[j].role == FIELD && !strcmp(fields[j].key, k->name);
        cr_assert_eq(found, 1, "[emitter] %s: %d fields in the table, not one", k->name, found);
    }
    int own = 0; /* the rows that are a key's own field: not a count, not a pair's second */
    for (int j = 0; j < NFIELDS; j++)
        own += fields[j].role == FIELD;
    cr_assert_eq(keys, own, "%d [emitter] keys, %d in the table", keys, own);
}

Test(emitter_parts, every_field_is_named_after_its_key)
{
    for (int i = 0; i < NFIELDS; i++) {
        const part_field *f = &fields[i];
        char want[80];
        size_t np = strlen(f->part);
        const char *rest = !strncmp(f->key, f->part, np) && f->key[np] == '_' ? f->key + np + 1 : f->key;
        if (f->role == COUNT)
            snprintf(want, sizeof want, "n%s", f->key);
        else if (f->role == SECOND || (i + 1 < NFIELDS && fields[i + 1].role == SECOND))
            snprintf(want, sizeof want, "%s_%s", rest, f->role == SECOND ? "max" : "min");
        else if (!strcmp(f->key, f->part))
            snprintf(want, sizeof want, "%s", !strcmp(f->part, "launch") ? "kind" : "seconds");
        else
            snprintf(want, sizeof want, "%s", rest);
        cr_assert_str_eq(f->name, want, "the key %s is %s.%s; the rule names it %s.%s", f->key, f->part, f->name,
                         f->part, want);
    }
}

Test(emitter_parts, the_migration_table_lists_every_field)
{
    FILE *in = fopen("docs/versioning.md", "rb");
    cr_assert_not_null(in, "docs/versioning.md");
    static char doc[1 << 16];
    size_t n = fread(doc, 1, sizeof doc - 1, in);
    fclose(in);
    cr_assert_lt(n, sizeof doc - 1, "docs/versioning.md is longer than this test reads");
    doc[n] = 0;
    for (int i = 0; i < NFIELDS; i++) {
        const part_field *f = &fields[i];
        if (!f->old)
            continue;
        char row[200];
        snprintf(row, sizeof row, "| `%s` | `%s.%s` | `%s`", f->old, f->part, f->name, f->key);
        cr_assert_not_null(strstr(doc, row), "docs/versioning.md has no row %s", row);
    }
}
