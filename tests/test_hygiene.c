/* SPDX-License-Identifier: MIT */
/* Library hygiene: the shared libraries export only the public API (isk_*),
 * the version is one fact (header, library, tool), and every public header
 * stands alone in C (and in C++: tests/cxx_link.cpp, run by run_all.sh). */
#include <criterion/criterion.h>
#include <criterion/logging.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/version.h"
#include "refimg.h"
#include "tool_cli.h"

/* Reads `cmd`'s output, a name a line (after skipping `skip` words), into
 * a sorted list; returns how many. */
static int read_names(const char *cmd, int skip, char names[][96], int most)
{
    FILE *p = popen(cmd, "r");
    cr_assert_not_null(p, "%s", cmd);
    char line[1024];
    int n = 0;
    while (fgets(line, sizeof line, p)) {
        char w[4][96] = {{0}};
        int got = sscanf(line, "%95s %95s %95s %95s", w[0], w[1], w[2], w[3]);
        if (got <= skip)
            continue;
        cr_assert_lt(n, most, "%s: more than %d names", cmd, most);
        snprintf(names[n++], 96, "%s", w[skip]);
    }
    cr_assert_eq(pclose(p), 0, "%s failed", cmd);
    qsort(names, (size_t)n, sizeof names[0], (int (*)(const void *, const void *))strcmp);
    return n;
}

static int listed(char names[][96], int n, const char *name)
{
    return bsearch(name, names, (size_t)n, sizeof names[0], (int (*)(const void *, const void *))strcmp) != NULL;
}

enum { MOST_NAMES = 4096 };
static char exported[MOST_NAMES][96], declared[MOST_NAMES][96];

/* The ABI is what include/ declares: every isk_* name the two shared
 * libraries export is a function or an object declared by a public header
 * (internals are isk__ or static, and src/exports.map exports isk_ followed
 * by a letter or digit only), and every function a public header declares
 * (not static inline) is exported by one of them.  The declarations come
 * from the compiler itself (gcc's -aux-info lists every prototype it read,
 * with the header and line it came from); the objects from their extern
 * declarations. */
Test(hygiene, the_exported_names_are_the_declared_ones, .timeout = 120)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd,
             "nm -D --defined-only %s/lib/libiskra.so %s/lib/libiskra-sdl.so | awk 'NF == 3 && $3 ~ /^isk_/ "
             "{print $3}' | sort -u",
             refimg_build_dir(), refimg_build_dir());
    const int ne = read_names(cmd, 0, exported, MOST_NAMES);
    cr_assert_gt(ne, 300, "%s: %d names", cmd, ne);
    /* functions: every prototype the public headers give, as gcc saw them */
    snprintf(cmd, sizeof cmd,
             "printf '#include <iskra.h>\n#include <iskra/sdl.h>\n#include <iskra/ui_sdl.h>\n' > "
             "out/test_hygiene/abi.c && gcc -std=c11 -Iinclude $(pkg-config --cflags sdl2 2>/dev/null) "
             "-fsyntax-only -aux-info out/test_hygiene/abi.aux out/test_hygiene/abi.c && "
             "grep -E '^/\\* include/iskra' out/test_hygiene/abi.aux | grep -v ':N[CF] \\*/ static ' | "
             "grep -oE '\\bisk_[a-z0-9_]+ \\(' | sed 's/ (//'; "
             "cat include/iskra.h include/iskra/*.h | grep -oE 'extern [^;(]*\\bisk_[a-z0-9_]+ *(\\[[^]]*\\])? *;' | "
             "grep -oE 'isk_[a-z0-9_]+ *(\\[[^]]*\\])? *;$' | grep -oE '^isk_[a-z0-9_]+'");
    cli_fresh("out/test_hygiene");
    char full[1200];
    snprintf(full, sizeof full, "( %s ) | sort -u", cmd);
    const int nd = read_names(full, 0, declared, MOST_NAMES);
    cr_assert_gt(nd, 300, "%d declarations read", nd);
    /* and nothing but isk_* and the linker's or runtime's own (_edata,
     * __bss_start, the sanitizers') */
    snprintf(cmd, sizeof cmd,
             "nm -D --defined-only %s/lib/libiskra.so %s/lib/libiskra-sdl.so | awk 'NF == 3 && $3 !~ /^(isk_|_)/ "
             "{print $3}'",
             refimg_build_dir(), refimg_build_dir());
    static char others[MOST_NAMES][96];
    const int no = read_names(cmd, 0, others, MOST_NAMES);
    for (int i = 0; i < no; i++)
        cr_log_error("exported and not the API: %s (see src/exports.map)", others[i]);
    int bad = no;
    for (int i = 0; i < ne; i++)
        if (!listed(declared, nd, exported[i])) {
            cr_log_error("exported but declared by no public header: %s (internal: isk__ or static)", exported[i]);
            bad++;
        }
    for (int i = 0; i < nd; i++)
        if (!listed(exported, ne, declared[i])) {
            cr_log_error("declared by a public header but not exported: %s", declared[i]);
            bad++;
        }
    cr_assert_eq(bad, 0, "%d names differ between the headers and the libraries (above)", bad);
}

Test(hygiene, one_version_everywhere)
{
    cr_assert_str_eq(isk_version(), ISKRA_VERSION_STRING);
    char want[64];
    snprintf(want, sizeof want, "%d.%d.%d", ISKRA_VERSION_MAJOR, ISKRA_VERSION_MINOR, ISKRA_VERSION_PATCH);
    cr_assert_str_eq(ISKRA_VERSION_STRING, want);
    cli_fresh("out/test_hygiene/version");
    cr_assert_eq(cli_run("out/test_hygiene/version", "--version"), 0);
    char *out = cli_slurp("out/test_hygiene/version/stdout.txt");
    char line[80];
    snprintf(line, sizeof line, "iskra %s\n", ISKRA_VERSION_STRING);
    cr_assert_str_eq(out, line);
    free(out);
    /* the shared library's soname carries MAJOR.MINOR */
    char cmd[512];
    snprintf(cmd, sizeof cmd, "objdump -p %s/lib/libiskra.so | grep -q 'SONAME *libiskra.so.%d.%d$'",
             refimg_build_dir(), ISKRA_VERSION_MAJOR, ISKRA_VERSION_MINOR);
    cr_assert_eq(system(cmd), 0, "%s", cmd);
}

/* Each public header compiles on its own, first in its translation unit,
 * with the project's warnings as errors. */
Test(hygiene, every_public_header_stands_alone, .timeout = 120)
{
    FILE *ls = popen("ls include/iskra/*.h include/iskra.h", "r");
    cr_assert_not_null(ls);
    char path[256];
    int n = 0;
    while (fgets(path, sizeof path, ls)) {
        path[strcspn(path, "\n")] = 0;
        const char *inc = strncmp(path, "include/", 8) ? path : path + 8;
        char cmd[768];
        snprintf(cmd, sizeof cmd,
                 "printf '#include \"%s\"\\nint main(void) { return 0; }\\n' | "
                 "cc -std=c11 -Wall -Wextra -Wpedantic -Werror -Iinclude -fsyntax-only -x c - 2>&1",
                 inc);
        cr_assert_eq(system(cmd), 0, "%s does not compile alone", path);
        n++;
    }
    pclose(ls);
    cr_assert_gt(n, 25);
}

/* The licence is MIT (LICENSE), and every source file says so on its first
 * lines (after a script's #! line), so a file copied out of the tree still
 * carries its terms.  third_party/ holds others' files under their own
 * licences, each beside them. */
Test(hygiene, every_source_file_names_its_licence)
{
    FILE *lic = fopen("LICENSE", "r");
    cr_assert_not_null(lic, "LICENSE is missing at the root");
    char first[64] = "";
    cr_assert_not_null(fgets(first, sizeof first, lic));
    fclose(lic);
    cr_assert_str_eq(first, "MIT License\n");
    FILE *p = popen("find src include tools tests bench examples docs web mk .ci Makefile -type f "
                    "\\( -name '*.c' -o -name '*.h' -o -name '*.cpp' -o -name '*.js' -o -name '*.mjs' -o -name '*.sh' -o -name '*.py' "
                    "-o -name '*.mk' -o -name '*.html' -o -name Makefile -o -name run -o -name refimg \\) "
                    "-not -path '*/regressions/*' | sort",
                    "r");
    cr_assert_not_null(p);
    char path[1024];
    int files = 0;
    while (fgets(path, sizeof path, p)) {
        path[strcspn(path, "\n")] = 0;
        FILE *f = fopen(path, "r");
        cr_assert_not_null(f, "%s", path);
        char line[256];
        int found = 0;
        for (int i = 0; i < 2 && fgets(line, sizeof line, f); i++)
            found |= strstr(line, "SPDX-License-Identifier: MIT") != NULL;
        fclose(f);
        cr_assert(found, "%s: no 'SPDX-License-Identifier: MIT' on its first lines", path);
        files++;
    }
    cr_assert_eq(pclose(p), 0);
    cr_assert_gt(files, 300, "only %d source files found: run from the project's root", files);
}

/* No clock in the library: nothing it computes or decides can depend on
 * when it runs (scheduling is from counts; docs/architecture.md).  The
 * SDL window's library and the tools may read one; libiskra may not. */
Test(hygiene, the_library_reads_no_clock)
{
    char cmd[512];
    snprintf(cmd, sizeof cmd, "nm -u %s/lib/libiskra.a", refimg_build_dir());
    FILE *p = popen(cmd, "r");
    cr_assert_not_null(p, "%s", cmd);
    static const char *const clocks[] = {"clock_gettime", "gettimeofday", "time", "clock", "timespec_get",
                                         "clock_getres", "times", "ftime"};
    char line[512];
    int symbols = 0;
    while (fgets(line, sizeof line, p)) {
        char type[8], name[400];
        if (sscanf(line, "%7s %399s", type, name) != 2)
            continue;
        symbols++;
        char *at = strchr(name, '@'); /* name@GLIBC_x */
        if (at)
            *at = 0;
        for (size_t k = 0; k < sizeof clocks / sizeof clocks[0]; k++)
            cr_assert(strcmp(name, clocks[k]) != 0, "libiskra.a calls %s", name);
    }
    cr_assert_eq(pclose(p), 0, "%s failed", cmd);
    cr_assert_gt(symbols, 10, "%s listed nothing", cmd);
}

/* One naming scheme: every global symbol of the static libraries is isk_
 * (the public API, which the test above holds to the headers) or isk__
 * (internal, shared between the library's files); everything else is
 * static (names with a leading underscore are the compiler's and the
 * sanitizers' own).  So a program linking libiskra.a meets no name of ours but
 * these two kinds. */
Test(hygiene, every_global_symbol_is_isk_or_isk__)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd,
             "nm %s/lib/libiskra.a %s/lib/libiskra-sdl.a 2>/dev/null | awk 'NF == 3 && $2 ~ /^[TDRBCV]$/ "
             "&& $3 !~ /^(isk_|_)/ {print $3}' | sort -u",
             refimg_build_dir(), refimg_build_dir());
    static char others[MOST_NAMES][96];
    const int n = read_names(cmd, 0, others, MOST_NAMES);
    for (int i = 0; i < n; i++)
        cr_log_error("a global symbol outside the scheme: %s (isk_ public, isk__ internal, or static)", others[i]);
    cr_assert_eq(n, 0, "%d global symbols outside the scheme (above)", n);
}

/* One output path: every file the library and the tool write is replaced
 * through iskra/outfile.h (src/io/outfile.c), which keeps links, devices,
 * FIFOs and modes as they are.  No other object file makes a temporary
 * or renames one into place (a second temp-and-rename is how --state
 * once replaced /dev/null as root and a save turned 0600 into 0644). */
Test(hygiene, only_outfile_makes_temporaries_and_renames)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd,
             "nm -A -u %s/lib/libiskra.a %s/lib/libiskra-sdl.a %s/obj/tools/iskra/*.o 2>/dev/null | awk '$NF ~ "
             "/^(rename|renameat|renameat2|mkstemp|mkstemp64|mkstemps|mkostemp|mkostemps|tmpfile|tmpnam|mktemp)"
             "(@.*)?$/ && $1 !~ /outfile\\.o:$/ {print $1 $NF}' | sort -u",
             refimg_build_dir(), refimg_build_dir(), refimg_build_dir());
    static char others[MOST_NAMES][96];
    const int n = read_names(cmd, 0, others, MOST_NAMES);
    for (int i = 0; i < n; i++)
        cr_log_error("a file written around iskra/outfile.h: %s", others[i]);
    cr_assert_eq(n, 0, "%d object files make their own temporaries (above)", n);
    /* the check itself finds the one that does */
    snprintf(cmd, sizeof cmd, "nm -A -u %s/lib/libiskra.a | grep -c 'outfile.o: *U rename'", refimg_build_dir());
    FILE *p = popen(cmd, "r");
    cr_assert_not_null(p);
    int found = 0;
    cr_assert_eq(fscanf(p, "%d", &found), 1);
    pclose(p);
    cr_assert_eq(found, 1, "nm does not show outfile.o calling rename: the check above sees nothing");
}
