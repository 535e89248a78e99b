/* SPDX-License-Identifier: MIT */
/* iskra keys [SECTION] [--csv | --markdown | --man] — every key of a scene
 * file, printed from the key table (iskra/keys.h), the one place keys are
 * described.  docs/scene-format.md's key tables are this command's
 * --markdown output (tools/gen_key_docs.sh), and iskra-scene(5)'s key
 * lists its --man output (tools/gen_man.sh); tests keep them equal. */
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
    fprintf(f, "usage: iskra keys [SECTION] [--csv | --markdown | --man]\n"
               "  Prints every key of a scene file: type, default, range, the kinds it applies to,\n"
               "  whether a running effect takes a change at once (isk_effect_set), and what it means.\n"
               "  SECTION       only that section: %s\n"
               "  --csv         one row per key: section,key,type,default,min,max,applies_to,meaning\n"
               "  --markdown    the tables of docs/scene-format.md (needs SECTION)\n"
               "  --man         the key lists of the iskra-scene(5) manual page (roff)\n"
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

/* The next key of section s at or after table row *i (which it moves past
 * it), with its columns in words in *t; NULL after the section's last. */
static const isk_key *next_key_row(int s, int *i, row_text *t)
{
    for (; *i < isk_key_count(); (*i)++) {
        const isk_key *k = isk_key_at(*i);
        if ((int)k->section == s) {
            (*i)++;
            row_words(k, t);
            return k;
        }
    }
    return NULL;
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
    row_text t;
    int i = 0;
    for (const isk_key *k; (k = next_key_row(section, &i, &t)) != NULL;) {
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

/* Text as roff lines: backslashes escaped, '-' as \- (what is typed:
 * "-10", "dot-browser", not a typographic hyphen), filled into lines of at
 * most 80 bytes (a longer word stays whole), a line that would start with
 * '.' or '\'' (a request) made text.  tools/gen_man.sh escapes the same
 * way. */
static void roff_text(const char *s)
{
    char esc[4096];
    size_t n = 0;
    for (; *s && n + 3 < sizeof esc; s++) {
        if (*s == '\\' || *s == '-')
            esc[n++] = '\\';
        esc[n++] = *s == '\\' ? 'e' : *s == '\n' ? ' ' : *s;
    }
    esc[n] = 0;
    size_t col = 0;
    for (char *w = strtok(esc, " "); w; w = strtok(NULL, " ")) {
        size_t len = strlen(w);
        if (col && col + 1 + len > 80) {
            putchar('\n');
            col = 0;
        }
        if (col) {
            putchar(' ');
            col++;
        } else if (*w == '.' || *w == '\'') {
            fputs("\\&", stdout);
            col += 2;
        }
        fputs(w, stdout);
        col += len;
    }
    putchar('\n');
}

/* Per section a subsection, per key a tagged paragraph:
 *     .SS [force NAME]
 *     kind: gravity, drag, ...
 *     .TP
 *     .B g
 *     number; default 0; range 0..1e12; for gravity; live: yes.
 *     .br
 *     F = (0, -m*g*gravity_multiplier) */
static void print_man(int section)
{
    for (int s = 0; s < ISK_SECTION_COUNT; s++) {
        if (section >= 0 && s != section)
            continue;
        printf(".SS \"[%s%s]\"\n", isk_section_name((isk_section_kind)s), isk_section_named((isk_section_kind)s) ? " NAME" : "");
        int nkinds;
        const char *const *kinds = isk_section_kind_names((isk_section_kind)s, &nkinds);
        if (nkinds) {
            const char *kk = isk_section_kind_key((isk_section_kind)s);
            char line[400];
            size_t used = (size_t)snprintf(line, sizeof line, "%s:", *kk ? kk : "window or camera, by the keys given");
            for (int i = 0; i < nkinds && used < sizeof line; i++)
                used += (size_t)snprintf(line + used, sizeof line - used, "%s %s", i ? "," : "", kinds[i]);
            roff_text(line);
        }
        row_text t;
        int i = 0;
        for (const isk_key *k; (k = next_key_row(s, &i, &t)) != NULL;) {
            char line[1200];
            const int required = !strcmp(t.dflt, "required");
            size_t used = (size_t)snprintf(line, sizeof line, "%s; %s%s", isk_key_type_name(k->type),
                                           required ? "" : "default ", *t.dflt ? t.dflt : "none");
            if (*t.range && used < sizeof line)
                used += (size_t)snprintf(line + used, sizeof line - used, "; range %s", t.range);
            if (*t.kinds && used < sizeof line)
                used += (size_t)snprintf(line + used, sizeof line - used, "; for %s", t.kinds);
            if (used < sizeof line)
                snprintf(line + used, sizeof line - used, "; live: %s.", t.live);
            printf(".TP\n.B ");
            roff_text(k->name);
            roff_text(line);
            printf(".br\n");
            roff_text(t.meaning);
        }
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
        row_text t;
        int i = 0;
        for (const isk_key *k; (k = next_key_row(s, &i, &t)) != NULL;) {
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
    int section = -1, csv = 0, markdown = 0, man = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help(stdout);
            return 0;
        }
        if (!strcmp(argv[i], "--csv")) {
            csv = 1;
        } else if (!strcmp(argv[i], "--markdown")) {
            markdown = 1;
        } else if (!strcmp(argv[i], "--man")) {
            man = 1;
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
            const char *guess = isk__scv_suggest(argv[i], names, ISK_SECTION_COUNT);
            fprintf(stderr, "iskra keys: no section '%s'%s%s%s (%s)\n", argv[i], guess ? "; did you mean '" : "",
                    guess ? guess : "", guess ? "'?" : "", sections);
            return 2;
        }
    }
    if (csv + markdown + man > 1) {
        fprintf(stderr, "iskra keys: one of --csv, --markdown and --man\n");
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
    else if (man)
        print_man(section);
    else
        print_readable(section);
    return fflush(stdout) == 0 ? 0 : 1;
}
