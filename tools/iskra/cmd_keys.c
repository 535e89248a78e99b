/* SPDX-License-Identifier: MIT */
/* iskra keys [SECTION] [--csv | --markdown] — every key of a scene file,
 * printed from the key table (iskra/keys.h), the one place keys are
 * described.  docs/scene-format.md's key tables are this command's
 * --markdown output (tools/gen_key_docs.sh; a test keeps them equal). */
#include <stdio.h>
#include <string.h>

#include "cmd.h"
#include "iskra/keys.h"
#include "scene/scene_values.h"

/* "scene, view, force, ... or click": every section, from the key table. */
static void section_list(char *buf, size_t n)
{
    size_t used = 0;
    buf[0] = 0;
    for (int s = 0; s < ISK_SECTION_COUNT && used < n; s++)
        used += (size_t)snprintf(buf + used, n - used, "%s%s", s == 0 ? "" : s == ISK_SECTION_COUNT - 1 ? " or " : ", ",
                                 isk_section_name((isk_section_kind)s));
}

static void help(FILE *f)
{
    char sections[200];
    section_list(sections, sizeof sections);
    fprintf(f, "usage: iskra keys [SECTION] [--csv | --markdown]\n"
               "  Prints every key of a scene file: type, default, range, the kinds it applies to,\n"
               "  whether a running effect takes a change at once (isk_effect_set), and what it means.\n"
               "  SECTION       only that section: %s\n"
               "  --csv         one row per key: section,key,type,default,min,max,applies_to,meaning\n"
               "  --markdown    the tables of docs/scene-format.md (needs SECTION)\n"
               "  exit status: 0 success, 2 usage error\n",
            sections);
}

/* A CSV field, quoted when it must be. */
static void csv_field(const char *s, int last)
{
    if (strpbrk(s, ",\"\n")) {
        putchar('"');
        for (; *s; s++) {
            if (*s == '"')
                putchar('"');
            putchar(*s);
        }
        putchar('"');
    } else {
        fputs(s, stdout);
    }
    putchar(last ? '\n' : ',');
}

static void bound_text(unsigned char kind, double v, const char *excl, char *buf, size_t n)
{
    if (kind == ISK_BOUND_NONE)
        buf[0] = 0;
    else
        snprintf(buf, n, "%s%.17g", kind == ISK_BOUND_EXCL ? excl : "", v);
}

static void print_csv(int section)
{
    printf("section,key,type,default,min,max,applies_to,meaning\n");
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        if (section >= 0 && (int)k->section != section)
            continue;
        char dflt[200], lo[40], hi[40], kinds[200];
        isk_key_default_text(k, dflt, sizeof dflt);
        bound_text(k->lo_bound, k->min, ">", lo, sizeof lo);
        bound_text(k->hi_bound, k->max, "<", hi, sizeof hi);
        isk_key_kinds_text(k, k->applies, kinds, sizeof kinds);
        for (char *c = kinds; *c; c++)
            if (*c == ',')
                *c = '|';
        char *w = kinds, *r = kinds; /* "a| b" -> "a|b" */
        for (; *r; r++)
            if (!(*r == ' ' && r > kinds && r[-1] == '|'))
                *w++ = *r;
        *w = 0;
        csv_field(isk_section_name(k->section), 0);
        csv_field(k->name, 0);
        csv_field(isk_key_type_name(k->type), 0);
        csv_field(dflt, 0);
        csv_field(lo, 0);
        csv_field(hi, 0);
        csv_field(kinds[0] ? kinds : "all", 0);
        char meaning[2000];
        isk_key_meaning_text(k, meaning, sizeof meaning);
        csv_field(meaning, 1);
    }
}

/* A row's columns in words. */
typedef struct row_text {
    char dflt[200], range[300], kinds[200], live[200], meaning[2000];
} row_text;

static void row_words(const isk_key *k, row_text *t)
{
    isk_key_default_text(k, t->dflt, sizeof t->dflt);
    isk_key_range_text(k, t->range, sizeof t->range);
    isk_key_kinds_text(k, k->applies, t->kinds, sizeof t->kinds);
    isk_key_live_text(k, t->live, sizeof t->live);
    isk_key_meaning_text(k, t->meaning, sizeof t->meaning);
}

/* One markdown cell (a '|' inside is escaped). */
static void md_cell(const char *s)
{
    putchar(' ');
    for (; *s; s++) {
        if (*s == '|')
            putchar('\\');
        putchar(*s);
    }
    fputs(" |", stdout);
}

static void print_markdown(int section)
{
    int nkinds;
    isk_section_kind_names((isk_section_kind)section, &nkinds);
    const char *kind_col = !nkinds ? NULL : section == ISK_SECTION_EMITTER ? "sources" : "kinds";
    printf("| key |");
    if (kind_col)
        printf(" %s |", kind_col);
    printf(" type | default | range | live | meaning |\n|---|%s---|---|---|---|---|\n", kind_col ? "---|" : "");
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        if ((int)k->section != section)
            continue;
        row_text t;
        row_words(k, &t);
        printf("| `%s` |", k->name);
        if (kind_col)
            md_cell(t.kinds);
        md_cell(isk_key_type_name(k->type));
        md_cell(t.dflt);
        md_cell(t.range);
        md_cell(t.live);
        md_cell(t.meaning);
        putchar('\n');
    }
}

static void print_readable(int section)
{
    for (int s = 0; s < ISK_SECTION_COUNT; s++) {
        if (section >= 0 && s != section)
            continue;
        int nkinds;
        const char *const *kinds = isk_section_kind_names((isk_section_kind)s, &nkinds);
        printf("[%s%s]", isk_section_name((isk_section_kind)s), isk_section_named((isk_section_kind)s) ? " NAME" : "");
        if (nkinds) {
            const char *kk = isk_section_kind_key((isk_section_kind)s);
            printf("  %s:", *kk ? kk : "window or camera");
            for (int i = 0; i < nkinds; i++)
                printf(" %s", kinds[i]);
        }
        printf("\n");
        for (int i = 0; i < isk_key_count(); i++) {
            const isk_key *k = isk_key_at(i);
            if ((int)k->section != s)
                continue;
            row_text t;
            row_words(k, &t);
            printf("  %-19s %-12s default %s", k->name, isk_key_type_name(k->type), *t.dflt ? t.dflt : "none");
            if (*t.range)
                printf("; range %s", t.range);
            if (*t.kinds)
                printf("; for %s", t.kinds);
            printf("; live: %s\n", t.live);
            printf("  %-19s %s\n", "", t.meaning);
        }
        printf("\n");
    }
}

int cmd_keys(int argc, char **argv)
{
    int section = -1, csv = 0, markdown = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help(stdout);
            return 0;
        }
        if (!strcmp(argv[i], "--csv")) {
            csv = 1;
        } else if (!strcmp(argv[i], "--markdown")) {
            markdown = 1;
        } else if (argv[i][0] == '-') {
            fprintf(stderr, "iskra keys: unknown option '%s' (iskra keys --help)\n", argv[i]);
            return 2;
        } else if (section >= 0) {
            fprintf(stderr, "iskra keys: one section only (got '%s' after '%s')\n", argv[i],
                    isk_section_name((isk_section_kind)section));
            return 2;
        } else if ((section = isk_section_find(argv[i])) < 0) {
            char sections[200];
            section_list(sections, sizeof sections);
            const char *names[ISK_SECTION_COUNT];
            for (int s = 0; s < ISK_SECTION_COUNT; s++)
                names[s] = isk_section_name((isk_section_kind)s);
            const char *guess = scv_suggest(argv[i], names, ISK_SECTION_COUNT);
            fprintf(stderr, "iskra keys: no section '%s'%s%s%s (%s)\n", argv[i], guess ? "; did you mean '" : "",
                    guess ? guess : "", guess ? "'?" : "", sections);
            return 2;
        }
    }
    if (csv && markdown) {
        fprintf(stderr, "iskra keys: --csv or --markdown, not both\n");
        return 2;
    }
    if (markdown && section < 0) {
        fprintf(stderr, "iskra keys: --markdown needs a SECTION\n");
        return 2;
    }
    if (csv)
        print_csv(section);
    else if (markdown)
        print_markdown(section);
    else
        print_readable(section);
    return fflush(stdout) == 0 ? 0 : 1;
}
