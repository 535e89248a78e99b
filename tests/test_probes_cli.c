/* SPDX-License-Identifier: MIT */
/* iskra render --probes FILE.csv: a row per frame 1..N whose every value
 * is the library's reading after that frame, bit for bit; the same file
 * on 1 and 2 threads; refused over an input or another output, and for a
 * scene without probes. */
#include <criterion/criterion.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/probes.h"
#include "iskra/scene.h"
#include "tool_cli.h"

#define OUT "out/test_probes_cli"
#define SCENE "tests/data/probes_stream.ini"

static isk_effect *open_scene(void)
{
    isk_effect_def d;
    isk_error err;
    isk_effect *fx = NULL;
    cr_assert_eq(isk_scene_load_file(&d, SCENE, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_def_free(&d);
    return fx;
}

Test(probes_cli, a_row_per_frame_with_the_librarys_readings)
{
    cli_fresh(OUT "/rows");
    cr_assert_eq(cli_run(OUT "/rows", "render " SCENE " --frames 90 --probes " OUT "/rows/p.csv"), 0);
    char *text = cli_slurp(OUT "/rows/p.csv");
    char *save = NULL, *line = strtok_r(text, "\n", &save);
    cr_assert_not_null(line);
    cr_assert_str_eq(line, "frame,time,door.forward,door.backward,door.rate_forward,door.rate_backward,box.count,"
                           "box.mean_speed,box.kinetic,speeds.under,speeds.bin0,speeds.bin1,speeds.bin2,speeds.bin3,"
                           "speeds.bin4,speeds.bin5,speeds.bin6,speeds.bin7,speeds.over,totals.count,totals.px,"
                           "totals.py,totals.kinetic,totals.potential,totals.energy");
    isk_effect *fx = open_scene();
    long rows = 0;
    for (long f = 1; f <= 90; f++, rows++) {
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
        line = strtok_r(NULL, "\n", &save);
        cr_assert_not_null(line, "row of frame %ld", f);
        char *cell = NULL, *c = strtok_r(line, ",", &cell);
        cr_assert_eq(strtol(c, NULL, 10), f);
        c = strtok_r(NULL, ",", &cell);
        cr_assert(strtod(c, NULL) == isk_effect_time(fx));
        for (int i = 0; i < isk_effect_probe_count(fx); i++) {
            isk_probe_reading r;
            isk_probe_value v[80];
            cr_assert_eq(isk_effect_probe_read(fx, i, &r), ISK_OK);
            int n = isk_probe_values(&r, v, 80);
            for (int k = 0; k < n; k++) {
                c = strtok_r(NULL, ",", &cell);
                cr_assert_not_null(c, "frame %ld %s.%s", f, r.name, v[k].name);
                cr_assert(strtod(c, NULL) == v[k].value, "frame %ld %s.%s: %s vs %.17g", f, r.name, v[k].name, c,
                          v[k].value);
            }
        }
        cr_assert_null(strtok_r(NULL, ",", &cell), "frame %ld: more columns than readings", f);
    }
    cr_assert_null(strtok_r(NULL, "\n", &save), "a row per frame, no more");
    cr_assert_eq(rows, 90);
    isk_probe_reading door;
    cr_assert_eq(isk_effect_probe_read(fx, 0, &door), ISK_OK);
    cr_assert(door.forward > 100, "the gate counted");
    isk_effect_destroy(fx);
    free(text);
}

Test(probes_cli, the_same_file_on_one_and_two_threads)
{
    cli_fresh(OUT "/threads");
    cr_assert_eq(cli_run(OUT "/threads", "render " SCENE " --frames 60 --threads 1 --probes " OUT "/threads/1.csv"), 0);
    cr_assert_eq(cli_run(OUT "/threads", "render " SCENE " --frames 60 --threads 2 --probes " OUT "/threads/2.csv"), 0);
    char *a = cli_slurp(OUT "/threads/1.csv"), *b = cli_slurp(OUT "/threads/2.csv");
    cr_assert_str_eq(a, b);
    free(a);
    free(b);
}

Test(probes_cli, refused_over_an_input_another_output_or_without_probes)
{
    cli_fresh(OUT "/refuse");
    cli_write_file(OUT "/refuse/s.ini", "[emitter e]\nsource = stream\nrate = 10\n[probe t]\nkind = totals\n");
    char *before = cli_slurp(OUT "/refuse/s.ini");
    cr_assert_eq(cli_run(OUT "/refuse", "render " OUT "/refuse/s.ini --frames 3 --probes " OUT "/refuse/s.ini"), 2);
    char *err = cli_slurp(OUT "/refuse/stderr.txt");
    cr_assert_not_null(strstr(err, "refusing to overwrite the input"), "%s", err);
    free(err);
    char *after = cli_slurp(OUT "/refuse/s.ini");
    cr_assert_str_eq(before, after, "the scene is untouched");
    cr_assert_eq(cli_run(OUT "/refuse", "render " OUT "/refuse/s.ini --frames 3 --out " OUT "/refuse/x --probes " OUT
                                        "/refuse/x"),
                 2);
    cr_assert_eq(cli_count_files(OUT "/refuse", "^x"), 0, "nothing written");
    cr_assert_eq(cli_run(OUT "/refuse", "render fire_campfire --frames 3 --probes " OUT "/refuse/p.csv"), 2);
    err = cli_slurp(OUT "/refuse/stderr.txt");
    cr_assert_not_null(strstr(err, "has no [probe NAME] section"), "%s", err);
    cr_assert_eq(cli_count_files(OUT "/refuse", "^p.csv"), 0, "nothing written");
    free(err);
    free(before);
    free(after);
}
