/* SPDX-License-Identifier: MIT */
/* Library hygiene: the shared libraries export only the public API (isk_*),
 * the version is one fact (header, library, tool), and every public header
 * stands alone in C (and in C++: tests/cxx_link.cpp, run by run_all.sh). */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/version.h"
#include "refimg.h"
#include "tool_cli.h"

/* Every defined dynamic symbol of the library: isk_* or a linker/runtime
 * name (leading underscore: _edata, __bss_start, the sanitizers'). */
static void only_public_symbols(const char *lib)
{
    char cmd[512];
    snprintf(cmd, sizeof cmd, "nm -D --defined-only %s/lib/%s", refimg_build_dir(), lib);
    FILE *p = popen(cmd, "r");
    cr_assert_not_null(p, "%s", cmd);
    char line[512];
    int public_ones = 0;
    while (fgets(line, sizeof line, p)) {
        char addr[64], type[8], name[400];
        if (sscanf(line, "%63s %7s %399s", addr, type, name) != 3)
            continue;
        if (!strncmp(name, "isk_", 4) && name[4] != '_') {
            public_ones++;
            continue;
        }
        cr_assert(name[0] == '_', "%s exports '%s' (only isk_* may be exported, never the internal isk__*; see src/exports.map)", lib, name);
    }
    cr_assert_eq(pclose(p), 0, "%s failed", cmd);
    cr_assert_gt(public_ones, 5, "%s", lib);
}

Test(hygiene, shared_libraries_export_only_isk_symbols)
{
    only_public_symbols("libiskra.so");
    only_public_symbols("libiskra-sdl.so");
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
 * carries its terms. */
Test(hygiene, every_source_file_names_its_licence)
{
    FILE *lic = fopen("LICENSE", "r");
    cr_assert_not_null(lic, "LICENSE is missing at the root");
    char first[64] = "";
    cr_assert_not_null(fgets(first, sizeof first, lic));
    fclose(lic);
    cr_assert_str_eq(first, "MIT License\n");
    FILE *p = popen("find src include tools tests bench examples docs .ci Makefile -type f "
                    "\\( -name '*.c' -o -name '*.h' -o -name '*.cpp' -o -name '*.js' -o -name '*.sh' "
                    "-o -name Makefile -o -name run -o -name refimg \\) -not -path '*/regressions/*' | sort",
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
