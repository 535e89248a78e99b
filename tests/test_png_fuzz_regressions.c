/* SPDX-License-Identifier: MIT */
/* Replays every input kept for the PNG fuzzer (tests/fuzz/png_regressions/,
 * crashers; tests/fuzz/png_corpus/, seeds) through the reader: each must be
 * read, or refused with a message and no canvas (the suite also runs under
 * ASan+UBSan).  The seeds include what must be read. */
#include <criterion/criterion.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/png.h"

/* Returns how many files were read successfully; *total counts them all. */
static int replay_dir(const char *dir, int *total)
{
    DIR *d = opendir(dir);
    cr_assert_not_null(d, "%s", dir);
    int ok = 0;
    struct dirent *ent;
    static unsigned char buf[1 << 20];
    while ((ent = readdir(d))) {
        if (ent->d_name[0] == '.')
            continue;
        char path[512];
        snprintf(path, sizeof path, "%s/%s", dir, ent->d_name);
        FILE *f = fopen(path, "rb");
        cr_assert_not_null(f, "%s", path);
        size_t n = fread(buf, 1, sizeof buf, f);
        fclose(f);
        isk_canvas c, from_file;
        isk_error err = {0};
        isk_status s = isk_png_read_memory(&c, buf, n, path, 1024 * 1024, &err);
        isk_status t = isk_png_read_max(&from_file, path, 1024 * 1024, &err);
        cr_expect_eq(s, t, "%s: memory and file reads disagree", path);
        if (s == ISK_OK) {
            ok++;
            cr_expect(isk_canvas_equal(&c, &from_file), "%s", path);
            isk_canvas_free(&c);
            isk_canvas_free(&from_file);
        } else {
            cr_expect_null(c.pixels, "%s: a canvas after a refusal", path);
            cr_expect_neq(err.message[0], 0, "%s: refused without a message", path);
            if (t == ISK_OK)
                isk_canvas_free(&from_file);
        }
        (*total)++;
    }
    closedir(d);
    return ok;
}

Test(png_fuzz, every_kept_input_is_read_or_refused_cleanly)
{
    int total = 0;
    replay_dir("tests/fuzz/png_regressions", &total);
    int seeds = 0, read = replay_dir("tests/fuzz/png_corpus", &seeds);
    cr_assert_geq(seeds, 10);
    cr_assert_eq(read, seeds - 1, "every seed but the hostile text chunk reads");
}
