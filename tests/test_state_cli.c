/* SPDX-License-Identifier: MIT */
/* iskra render --state / --state-every: every live particle as CSV in
 * round-trip precision (the values read back are the library's bits), the
 * sequence beside the frames, the option checks; and the report of
 * particles removed because their state went non-finite, on stderr. */
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "tool_cli.h"

#define OUT "out/test_state_cli"

static isk_effect *open_scene(const char *path)
{
    isk_effect_def d;
    isk_error err;
    isk_effect *fx = NULL;
    cr_assert_eq(isk_scene_load_file(&d, path, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_def_free(&d);
    return fx;
}

/* The CSV against the effect stepped the same number of frames in this
 * process: every row, every value, the same bits. */
static void check_csv(const char *csv_path, const isk_effect *fx)
{
    char *text = cli_slurp(csv_path);
    char *save = NULL, *line = strtok_r(text, "\n", &save);
    cr_assert_str_eq(line, "emitter,index,x,y,vx,vy,mass,age,life");
    const isk_effect_def *d = isk_effect_definition(fx);
    size_t rows = 0;
    for (int g = 0; g < isk_effect_emitter_count(fx); g++) {
        const isk_particles *p = isk_effect_particles(fx, g);
        for (size_t i = 0; i < p->count; i++, rows++) {
            line = strtok_r(NULL, "\n", &save);
            cr_assert_not_null(line, "row %zu missing", rows);
            char name[64];
            size_t idx;
            double v[7];
            cr_assert_eq(sscanf(line, "%63[^,],%zu,%lf,%lf,%lf,%lf,%lf,%lf,%lf", name, &idx, &v[0], &v[1], &v[2], &v[3],
                                &v[4], &v[5], &v[6]),
                         9, "%s", line);
            cr_assert_str_eq(name, d->emitters[g].name);
            cr_assert_eq(idx, i);
            const double want[7] = {p->x[i], p->y[i], p->vx[i], p->vy[i], p->m[i], p->age[i], p->life[i]};
            for (int k = 0; k < 7; k++)
                cr_assert(memcmp(&v[k], &want[k], sizeof v[k]) == 0, "%s row %zu column %d: %.17g vs %.17g",
                          csv_path, rows, k, v[k], want[k]);
        }
    }
    cr_assert_null(strtok_r(NULL, "\n", &save), "extra rows");
    cr_assert_gt(rows, 0);
    free(text);
}

Test(state_cli, the_state_reads_back_to_the_same_bits)
{
    cli_fresh(OUT "/one");
    cr_assert_eq(cli_run(OUT "/one", "render scenes/fire_campfire.ini --frames 45 --state " OUT "/one/s.csv"), 0);
    isk_effect *fx = open_scene("scenes/fire_campfire.ini");
    for (int f = 0; f < 45; f++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    check_csv(OUT "/one/s.csv", fx);
    isk_effect_destroy(fx);
    cr_assert(!cli_exists(OUT "/one/x.png"));
}

Test(state_cli, state_every_writes_beside_the_frames)
{
    cli_fresh(OUT "/seq");
    cr_assert_eq(cli_run(OUT "/seq", "render scenes/fig19_coulomb.ini --frames 1e1 --out-dir " OUT
                                     "/seq/d --every 5 --state-every 4"),
                 0);
    cr_assert(cli_exists(OUT "/seq/d/frame_000005.png") && cli_exists(OUT "/seq/d/frame_000010.png"));
    isk_effect *fx = open_scene("scenes/fig19_coulomb.ini");
    for (long f = 0; f <= 10; f++) {
        char path[256];
        snprintf(path, sizeof path, OUT "/seq/d/state_%06ld.csv", f);
        cr_assert_eq(cli_exists(path), f % 4 == 0, "%s", path);
        if (f % 4 == 0)
            check_csv(path, fx);
        if (f < 10)
            cr_assert_eq(isk_effect_step(fx), ISK_OK);
    }
    isk_effect_destroy(fx);
}

Test(state_cli, option_errors_write_nothing)
{
    cli_fresh(OUT "/bad");
    cr_assert_eq(cli_run(OUT "/bad", "render scenes/fig19_coulomb.ini --state-every 2 --state " OUT "/bad/s.csv"), 2);
    char *err = cli_slurp(OUT "/bad/stderr.txt");
    cr_assert(strstr(err, "--state-every needs --out-dir"), "%s", err);
    free(err);
    cr_assert(!cli_exists(OUT "/bad/s.csv"));
    cr_assert_eq(cli_run(OUT "/bad", "render scenes/fig19_coulomb.ini --state-every 0 --out-dir " OUT "/bad/d"), 2);
    cr_assert_eq(cli_run(OUT "/bad", "render scenes/fig19_coulomb.ini --frames 1.5 --state " OUT "/bad/s.csv"), 2);
    err = cli_slurp(OUT "/bad/stderr.txt");
    cr_assert(strstr(err, "--frames: expected a whole number between 0 and 100000000, got \"1.5\""), "%s", err);
    free(err);
    cr_assert(!cli_exists(OUT "/bad/s.csv"));
    cr_assert_eq(cli_run(OUT "/bad", "render scenes/fig19_coulomb.ini --frames 1e2 --state " OUT "/bad/s.csv"), 0);
}

/* The thesis's centre rule gives a particle exactly on a potential NaN; it
 * is removed, counted, and the render says so on stderr. */
static const char *THESIS_NAN =
    "[scene]\ndt = 1/60\ncentre = thesis\n"
    "[force well]\nkind = potential\nk = 1\nposition = 0, 0\n"
    "[emitter on]\nsource = particle\nposition = 0, 0\nforces = well\n"
    "[emitter near]\nsource = layer\nrect = 1, 2, 1, 2\ncount = 5\nforces = well\n";

Test(state_cli, a_state_gone_non_finite_is_removed_counted_and_reported)
{
    isk_effect_def d;
    isk_error err;
    isk_effect *fx = NULL;
    cr_assert_eq(isk_scene_load_string(&d, THESIS_NAN, "nan", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_def_free(&d);
    cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_effect_particles(fx, 0)->count, 0, "the NaN particle is gone");
    cr_assert_eq(isk_effect_removed_nonfinite(fx, 0), 1);
    cr_assert_eq(isk_effect_particles(fx, 1)->count, 5, "the others are kept");
    cr_assert_eq(isk_effect_removed_nonfinite(fx, 1), 0);
    isk_effect_destroy(fx);

    cli_fresh(OUT "/nan");
    FILE *f = fopen(OUT "/nan/nan.ini", "w");
    cr_assert_not_null(f);
    fputs(THESIS_NAN, f);
    fclose(f);
    cr_assert_eq(cli_run(OUT "/nan", "render " OUT "/nan/nan.ini --frames 3 --state " OUT "/nan/s.csv"), 0);
    char *msg = cli_slurp(OUT "/nan/stderr.txt");
    cr_assert_str_eq(msg, "iskra render: emitter 'on': 1 particle removed: its state went non-finite\n");
    free(msg);
    char *csv = cli_slurp(OUT "/nan/s.csv");
    cr_assert(!strstr(csv, "nan") && !strstr(csv, "\non,"), "%s", csv);
    free(csv);
}
