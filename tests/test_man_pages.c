/* SPDX-License-Identifier: MIT */
/* The manual pages man/iskra.1 and man/iskra-scene.5 are what
 * tools/gen_man.sh writes from their templates (man/iskra.1.in,
 * man/iskra-scene.5.in) and the iskra tool (every
 * command's --help, `iskra keys --man`): a change to a command's help or
 * to the key table that is not carried into the committed pages fails
 * here.  Also: every command and every key is in them, the page's example
 * scene runs, and, where mandoc and lexgrog are installed (they are not
 * needed to build or test), the pages pass `mandoc -Tlint` and lexgrog
 * reads their NAME lines. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/keys.h"
#include "iskra/scene.h"
#include "refimg.h"
#include "scene_open.h"
#include "tool_cli.h"

#define OUT "out/test_man_pages"

static const char *const pages[] = {"iskra.1", "iskra-scene.5"};

static void generate(const char *dir)
{
    cli_fresh(dir);
    char cmd[512];
    snprintf(cmd, sizeof cmd, "sh tools/gen_man.sh %s/bin/iskra %s", refimg_build_dir(), dir);
    cr_assert_eq(system(cmd), 0, "%s", cmd);
}

static char *page(const char *dir, const char *name)
{
    char path[300];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return cli_slurp(path);
}

Test(man_pages, the_committed_pages_are_generated)
{
    generate(OUT "/gen");
    for (int i = 0; i < 2; i++) {
        char *want = page(OUT "/gen", pages[i]), *have = page("man", pages[i]);
        cr_assert(!strcmp(want, have), "man/%s differs from what tools/gen_man.sh writes: run make man and commit "
                                       "the result (diff man/%s " OUT "/gen/%s)",
                  pages[i], pages[i], pages[i]);
        free(want);
        free(have);
    }
}

Test(man_pages, every_command_and_every_key_is_there)
{
    char *one = page("man", "iskra.1"), *five = page("man", "iskra-scene.5");
    /* the commands `iskra --help` lists */
    cli_fresh(OUT "/help");
    cr_assert_eq(cli_run(OUT "/help", "--help"), 0);
    char *help = cli_slurp(OUT "/help/stdout.txt");
    int commands = 0;
    for (char *l = strstr(help, "\ncommands:\n"); l && (l = strstr(l + 1, "\n  ")) && l[3] != '-';) {
        char name[32], want[80];
        if (sscanf(l + 3, "%31s", name) != 1)
            break;
        snprintf(want, sizeof want, "\n.SS \"iskra %s\"\n", name);
        cr_assert_not_null(strstr(one, want), "iskra.1 has no section for %s", name);
        commands++;
    }
    cr_assert_geq(commands, 7);
    /* each key under its section's heading, in the table's order */
    const char *at = five;
    for (int i = 0; i < isk_key_count(); i++) {
        const isk_key *k = isk_key_at(i);
        char heading[80], want[80];
        snprintf(heading, sizeof heading, "\n.SS \"[%s%s]\"\n", isk_section_name(k->section),
                 isk_section_named(k->section) ? " NAME" : "");
        const char *h = strstr(five, heading);
        cr_assert_not_null(h, "no %s", heading);
        if (h > at)
            at = h;
        snprintf(want, sizeof want, "\n.TP\n.B %s\n", k->name);
        const char *kl = strstr(at, want);
        cr_assert_not_null(kl, "[%s] %s is not in iskra-scene.5 after its heading", isk_section_name(k->section),
                           k->name);
        at = kl;
    }
    free(help);
    free(one);
    free(five);
}

/* The EXAMPLES scene of iskra-scene.5, unescaped, loads and runs. */
Test(man_pages, the_scene_example_runs)
{
    char *five = page("man", "iskra-scene.5");
    char *start = strstr(five, "\n.SH EXAMPLES\n");
    cr_assert_not_null(start);
    start = strstr(start, "\n.nf\n");
    cr_assert_not_null(start);
    start += 5;
    char *end = strstr(start, "\n.fi\n");
    cr_assert_not_null(end);
    *end = 0;
    char text[2000];
    size_t n = 0;
    for (const char *p = start; *p && n + 1 < sizeof text; p++) {
        if (!strncmp(p, ".RS", 3) || !strncmp(p, ".RE", 3)) { /* a request line */
            p = strchr(p, '\n');
            if (!p)
                break;
            continue;
        }
        if (p[0] == '\\' && p[1] == '-')
            p++;
        text[n++] = *p;
    }
    text[n] = 0;
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load_string(&d, text, "man-example", &err), ISK_OK, "%s\n%s", err.message, text);
    isk_effect *fx = NULL;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(d.ndeflectors, 1);
    cr_assert(d.deflectors[0].show);
    scene_steps(fx, 60);
    cr_assert_gt(isk_effect_particle_count(fx), 10);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
    free(five);
}

Test(man_pages, mandoc_lint_and_lexgrog_pass_where_installed)
{
    int have_mandoc = system("command -v mandoc >/dev/null 2>&1") == 0;
    int have_lexgrog = system("command -v lexgrog >/dev/null 2>&1") == 0;
    if (!have_mandoc && !have_lexgrog)
        cr_skip_test("neither mandoc nor lexgrog is installed (Debian: mandoc, man-db)");
    cli_fresh(OUT "/lint");
    if (have_mandoc) {
        int rc = system("mandoc -Tlint -Wstyle man/iskra.1 man/iskra-scene.5 > " OUT "/lint/mandoc.txt 2>&1");
        char *log = cli_slurp(OUT "/lint/mandoc.txt");
        cr_assert(rc == 0 && !*log, "mandoc -Tlint:\n%s", log);
        free(log);
    }
    if (have_lexgrog) {
        cr_assert_eq(system("lexgrog man/iskra.1 man/iskra-scene.5 > " OUT "/lint/lexgrog.txt 2>&1"), 0);
        char *log = cli_slurp(OUT "/lint/lexgrog.txt");
        cr_assert_not_null(strstr(log, "man/iskra.1: \"iskra - render, play and compare 2D particle scenes\""),
                           "%s", log);
        cr_assert_not_null(strstr(log, "man/iskra-scene.5: \"iskra-scene - the scene files of iskra\""), "%s", log);
        free(log);
    }
}
