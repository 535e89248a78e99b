/* SPDX-License-Identifier: MIT */
/* The key table (iskra/keys.h): every row is consistent, its default is a
 * valid value that reads back to itself, the parser and isk_effect_create
 * refuse the same values with the same message, `iskra keys --csv` has the
 * promised header, and docs/scene-format.md's tables are the generated ones. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/keys.h"
#include "iskra/scene.h"
#include "refimg.h"
#include "scene/key_value.h"
#include "scene_open.h"
#include "tool_cli.h"

#define OUT "out/test_keys"

/* The size of each section's item struct, for the offset check. */
static size_t item_size(isk_section_kind s)
{
    switch (s) {
    case ISK_SECTION_SCENE:
    case ISK_SECTION_VIEW: return sizeof(isk_effect_def);
    case ISK_SECTION_FORCE: return sizeof(isk_force_def);
    case ISK_SECTION_DEFLECTOR: return sizeof(isk_deflector_def);
    case ISK_SECTION_BOUNDS: return sizeof(isk_bounds);
    case ISK_SECTION_EMITTER: return sizeof(isk_emitter_def);
    case ISK_SECTION_DRAWING: return sizeof(isk_drawing_def);
    case ISK_SECTION_CLICK: return sizeof(isk_click_def);
    case ISK_SECTION_PROBE: return sizeof(isk_probe_def);
    default: return 0;
    }
}

Test(keys, every_row_is_consistent)
{
    cr_assert_gt(isk_key_count(), 100);
    cr_assert_null(isk_key_at(-1));
    cr_assert_null(isk_key_at(isk_key_count()));
    int per_section[ISK_SECTION_COUNT] = {0};
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        cr_assert_lt((unsigned)k->section, ISK_SECTION_COUNT);
        per_section[k->section]++;
        cr_assert(k->name && *k->name && k->meaning && *k->meaning, "row %d", i);
        cr_assert_lt((unsigned)k->type, ISK_KEY_TYPE_COUNT, "%s", k->name);
        cr_assert_lt(k->offset, item_size(k->section), "%s", k->name);
        cr_assert_eq(isk_key_find(k->section, k->name), k, "%s is not unique in its section", k->name);
        if (k->type == ISK_KEY_ENUM)
            cr_assert(k->names && k->nnames > 0, "%s", k->name);
        int nkinds;
        isk_section_kind_names(k->section, &nkinds);
        if (!nkinds)
            cr_assert(k->applies == 0 && (k->required == 0 || k->required == ISK_KEY_ALL_KINDS),
                      "%s: kinds in a section without", k->name);
        else
            cr_assert_eq(k->applies >> nkinds, 0u, "%s: applies to a kind that does not exist", k->name);
        if (k->lo_bound && k->hi_bound)
            cr_assert_leq(k->min, k->max, "%s", k->name);
        cr_assert(!(k->create_only && k->live), "%s: both live and creation-only", k->name);
    }
    for (int s = 0; s < ISK_SECTION_COUNT; s++) {
        cr_assert_gt(per_section[s], 0);
        cr_assert_eq(isk_section_find(isk_section_name((isk_section_kind)s)), s);
    }
    cr_assert_eq(isk_section_find("emiter"), -1);
    cr_assert_null(isk_key_find(ISK_SECTION_EMITTER, "rat"));
    cr_assert_eq(isk_key_find(ISK_SECTION_EMITTER, "rate")->max, 1e7);
}

/* A fresh item of a section with the table's defaults. */
static void *fresh_item(isk_effect_def *d, isk_section_kind s)
{
    isk_effect_def_init(d);
    switch (s) {
    case ISK_SECTION_FORCE: isk_effect_def_add_force(d, "f", ISK_FORCE_GRAVITY); break;
    case ISK_SECTION_DEFLECTOR: {
        isk_deflector seg = isk_deflector_segment(0, 0, 1, 0);
        isk_effect_def_add_deflector(d, "g", seg);
        break;
    }
    case ISK_SECTION_EMITTER: isk_effect_def_add_emitter(d, "e"); break;
    case ISK_SECTION_DRAWING: isk_effect_def_add_drawing(d, "w", ISK_DRAWING_POLYLINE); break;
    case ISK_SECTION_PROBE: isk_effect_def_add_probe(d, "p", ISK_PROBE_GATE); break;
    default: break;
    }
    return isk__fx_section_item(d, s, 0);
}

/* Defaults are valid, and format -> parse -> format is the identity. */
Test(keys, defaults_are_valid_and_read_back)
{
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        if (k->type == ISK_KEY_REFS || k->type == ISK_KEY_POINTS || k->type == ISK_KEY_TEXT)
            continue; /* no default beyond "none" / empty: covered by the parser tests */
        isk_effect_def d;
        void *item = fresh_item(&d, k->section);
        char why[400], a[400], b[400];
        cr_assert_eq(isk__fx_key_set_default(k, item), 0, "%s default '%s'", k->name, k->dflt);
        if (k->type != ISK_KEY_REF)
            cr_assert_eq(isk__fx_key_check(k, item, &d, why, sizeof why), 0, "%s: %s", k->name, why);
        cr_assert_eq(isk__fx_key_format(k, item, &d, a, sizeof a), 0, "%s", k->name);
        cr_assert_eq(isk__fx_key_parse(k, item, a, &d, why, sizeof why), 0, "%s: '%s': %s", k->name, a, why);
        cr_assert_eq(isk__fx_key_format(k, item, &d, b, sizeof b), 0);
        cr_assert_str_eq(a, b, "%s", k->name);
        isk_effect_def_free(&d);
    }
}

/* A default the docs give as a word is accepted written out: every key
 * whose empty default is documented as "none" (texture, on_death, on_hit)
 * reads "none" as that default (before: texture = none looked for a file
 * "none", on_death = none for an emitter of that name). */
Test(keys, the_documented_default_none_is_accepted)
{
    int seen = 0;
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        if (!(k->dflt && !*k->dflt && k->dflt_doc && !strcmp(k->dflt_doc, "none")))
            continue;
        seen++;
        isk_effect_def d, e;
        void *item = fresh_item(&d, k->section), *dflt = fresh_item(&e, k->section);
        char why[400], a[400], b[400];
        cr_assert_eq(isk__fx_key_set_default(k, dflt), 0, "%s", k->name);
        cr_assert_eq(isk__fx_key_parse(k, item, "none", &d, why, sizeof why), 0, "%s = none: %s", k->name, why);
        cr_assert_eq(isk__fx_key_format(k, item, &d, a, sizeof a), 0, "%s", k->name);
        cr_assert_eq(isk__fx_key_format(k, dflt, &e, b, sizeof b), 0, "%s", k->name);
        cr_assert_str_eq(a, b, "%s = none reads as '%s', the default is '%s'", k->name, a, b);
        isk_effect_def_free(&d);
        isk_effect_def_free(&e);
    }
    cr_assert_geq(seen, 3, "texture, on_death and on_hit at least");
}

/* Values that need every digit survive a round trip bit for bit (the
 * simulator's save and isk_effect_get depend on it). */
Test(keys, numbers_and_angles_round_trip_exactly)
{
    isk_effect_def d;
    isk_emitter_def *e = fresh_item(&d, ISK_SECTION_EMITTER);
    const isk_key *angle = isk_key_find(ISK_SECTION_EMITTER, "angle");
    const isk_key *life = isk_key_find(ISK_SECTION_EMITTER, "life");
    const double angles[] = {0.1, 1.5707963267948966, -3.0, 90 * (3.14159265358979323846 / 180), 1e-300};
    const double lives[] = {1.0 / 3, 0.6025, 1e-7, 123456789.125, INFINITY};
    char buf[80], why[300];
    for (int i = 0; i < 5; i++) {
        e->launch.angle = angles[i];
        cr_assert_eq(isk__fx_key_format(angle, e, &d, buf, sizeof buf), 0);
        e->launch.angle = 0;
        cr_assert_eq(isk__fx_key_parse(angle, e, buf, &d, why, sizeof why), 0, "%s: %s", buf, why);
        cr_assert(e->launch.angle == angles[i], "angle %.17g read back as %.17g from '%s'", angles[i], e->launch.angle,
                  buf);
        e->life.seconds = lives[i];
        cr_assert_eq(isk__fx_key_format(life, e, &d, buf, sizeof buf), 0);
        e->life.seconds = 1;
        cr_assert_eq(isk__fx_key_parse(life, e, buf, &d, why, sizeof why), 0, "%s: %s", buf, why);
        cr_assert(e->life.seconds == lives[i], "life %.17g read back as %.17g from '%s'", lives[i], e->life.seconds,
                  buf);
    }
    cr_assert_eq(
        isk__fx_key_format(angle, &(isk_emitter_def){.launch.angle = 3.14159265358979323846 / 2}, &d, buf, sizeof buf), 0);
    cr_assert_str_eq(buf, "90"); /* degrees when they are exact */
    isk_effect_def_free(&d);
}

/* The first kind a row applies to (0 when it applies to every kind). */
static int first_kind(const isk_key *k)
{
    for (int i = 0; i < 32; i++)
        if (!k->applies || (k->applies >> i & 1u))
            return i;
    return 0;
}

/* For every bounded number: a scene file and a C definition with the same
 * out-of-range value fail with the same message after "KEY: ". */
Test(keys, parser_and_create_refuse_alike)
{
    int tested = 0;
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        if (k->type != ISK_KEY_NUMBER && k->type != ISK_KEY_WHOLE && k->type != ISK_KEY_LONG &&
            k->type != ISK_KEY_COUNT)
            continue;
        if (!k->lo_bound && !k->hi_bound)
            continue;
        /* A whole number just past a bound: it prints the same in both
         * (past a bound beyond 2^53, where + 1 is no change, twice it). */
        double bad = k->hi_bound ? (k->max > 0x1p53 ? 2 * k->max : floor(k->max) + 1)
                                 : (k->min < -0x1p53 ? 2 * k->min : ceil(k->min) - 1);
        if (k->type == ISK_KEY_COUNT && bad < 0)
            continue; /* a size_t cannot hold it */
        if (k->lo_bound == ISK_BOUND_EXCL && !k->hi_bound)
            bad = k->min;
        int kind = first_kind(k);
        int nkinds;
        const char *const *kinds = isk_section_kind_names(k->section, &nkinds);
        const char *kk = isk_section_kind_key(k->section);
        char text[400];
        const char *sec = isk_section_name(k->section);
        int named = isk_section_named(k->section);
        snprintf(text, sizeof text, "[%s%s]\n%s%s%s%s%s = %.17g\n", sec, named ? " x" : "",
                 nkinds && kk && *kk ? kk : "", nkinds && kk && *kk ? " = " : "", nkinds && kk && *kk ? kinds[kind] : "",
                 nkinds && kk && *kk ? "\n" : "", k->name, bad);
        isk_effect_def d;
        isk_error err = {0};
        cr_assert_neq(isk_scene_load_string(&d, text, "t.ini", &err), ISK_OK, "accepted:\n%s", text);
        char want[300];
        snprintf(want, sizeof want, "%s: expected", k->name);
        const char *p = strstr(err.message, want);
        cr_assert_not_null(p, "%s -> %s", text, err.message);
        char parse_msg[400];
        snprintf(parse_msg, sizeof parse_msg, "%s", p);
        isk_effect_def_free(&d);

        /* the same value set from C */
        void *item = fresh_item(&d, k->section);
        if (nkinds && kk && *kk)
            isk__fx_key_parse(isk_key_find(k->section, kk), item, kinds[kind], &d, want, sizeof want);
        if (k->section == ISK_SECTION_VIEW)
            d.view_kind = (isk_view_def_kind)kind; /* the parser derives it from the keys given */
        char num[64];
        snprintf(num, sizeof num, "%.17g", bad);
        /* write the raw value past the parser's range check */
        switch (k->type) {
        case ISK_KEY_NUMBER: *(double *)((char *)item + k->offset) = bad; break;
        case ISK_KEY_WHOLE: *(int *)((char *)item + k->offset) = (int)bad; break;
        case ISK_KEY_LONG: *(long *)((char *)item + k->offset) = (long)bad; break;
        default: *(size_t *)((char *)item + k->offset) = (size_t)bad; break;
        }
        char why[400];
        cr_assert_neq(isk__fx_key_check(k, item, &d, why, sizeof why), 0, "%s accepted %s", k->name, num);
        char create_msg[500];
        snprintf(create_msg, sizeof create_msg, "%s: %s", k->name, why);
        cr_assert_str_eq(create_msg, parse_msg, "%s", k->name);
        isk_effect *fx = NULL;
        cr_assert_neq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s = %s created", k->name, num);
        cr_assert_not_null(strstr(err.message, create_msg), "%s vs %s", err.message, create_msg);
        isk_effect_def_free(&d);
        tested++;
    }
    cr_assert_gt(tested, 30);
}

Test(keys, csv_and_readable_listing)
{
    cli_fresh(OUT "/csv");
    cr_assert_eq(cli_run(OUT "/csv", "keys --csv"), 0);
    char *csv = cli_slurp(OUT "/csv/stdout.txt");
    cr_assert_eq(strncmp(csv, "section,key,type,default,min,max,applies_to,meaning\n", 52), 0, "%.80s", csv);
    int lines = 0;
    for (char *c = csv; *c; c++)
        lines += *c == '\n';
    cr_assert_eq(lines, isk_key_count() + 1);
    cr_assert_not_null(strstr(csv, "\nemitter,rate,number,0,0,10000000,stream,"));
    cr_assert_not_null(strstr(csv, "\nscene,dt,number,1/60,>0,1000,all,"));
    free(csv);
    cr_assert_eq(cli_run(OUT "/csv", "keys emitter"), 0);
    char *txt = cli_slurp(OUT "/csv/stdout.txt");
    cr_assert_not_null(strstr(txt, "[emitter NAME]"));
    cr_assert_null(strstr(txt, "[scene]"));
    free(txt);
    cr_assert_eq(cli_run(OUT "/csv", "keys emiter"), 2);
    cr_assert_eq(cli_run(OUT "/csv", "keys --markdown"), 2);
    cr_assert_eq(cli_run(OUT "/csv", "keys --bogus"), 2);
}

/* docs/scene-format.md's key tables are exactly `iskra keys --markdown`. */
Test(keys, documentation_tables_are_generated)
{
    cli_fresh(OUT "/docs");
    char cmd[512];
    snprintf(cmd, sizeof cmd, "sh tools/gen_key_docs.sh %s/bin/iskra docs/scene-format.md " OUT "/docs/scene-format.md",
             refimg_build_dir());
    cr_assert_eq(system(cmd), 0, "%s", cmd);
    char *want = cli_slurp(OUT "/docs/scene-format.md"), *have = cli_slurp("docs/scene-format.md");
    cr_assert_not_null(strstr(have, "<!-- keys emitter -->"));
    cr_assert(!strcmp(want, have), "docs/scene-format.md's key tables differ from the key table: run "
                                   "tools/gen_key_docs.sh (after make) and commit the result");
    free(want);
    free(have);
}

/* The page's complete example is a working scene. */
Test(keys, documentation_example_scene_works)
{
    char *doc = cli_slurp("docs/scene-format.md");
    char *start = strstr(doc, "## A complete example\n\n```ini\n");
    cr_assert_not_null(start);
    start = strchr(start, '\n') + 1;
    start = strchr(start, '\n') + 1;
    start = strchr(start, '\n') + 1;
    char *end = strstr(start, "```\n");
    cr_assert_not_null(end);
    *end = 0;
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load_string(&d, start, "example", &err), ISK_OK, "%s", err.message);
    isk_effect *fx = NULL;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    scene_steps(fx, 60);
    cr_assert_gt(isk_effect_particle_count(fx), 100);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
    free(doc);
}
