/* SPDX-License-Identifier: MIT */
/* `iskra bench accuracy --quick --only knobs`: the smoke run finishes with
 * status 0 and leaves, for every knob, a CSV whose header and rows are what
 * the docs read and a readable chart PNG, and no temporary files.  Under
 * the sanitizer build (make test SANITIZE=1) this also runs the whole
 * study's code under ASan and UBSan.  Timings are never checked. */
#include <criterion/criterion.h>
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "iskra/png.h"
#include "refimg.h"
#include "tool_cli.h"

#define TDIR "out/test_bench_knobs_cli"
#define RES TDIR "/res" /* the study's output directory */

/* Checks RES/<name>.csv: the header, `rows` data rows of the same number of
 * fields, and numbers (finite, or empty in column `may_be_empty`) in every
 * column from `first_number` on.  Returns the file's text (malloc'd). */
static char *check_csv(const char *name, const char *header, int rows, int first_number, int may_be_empty)
{
    char path[256];
    snprintf(path, sizeof path, RES "/%s.csv", name);
    char *text = cli_slurp(path);
    size_t hl = strlen(header);
    cr_assert(strncmp(text, header, hl) == 0 && text[hl] == '\n', "%s header: %.*s", name, (int)hl + 1, text);
    int fields = 1;
    for (const char *c = header; *c; c++)
        fields += *c == ',';
    int n = 0;
    for (char *line = text + hl + 1; *line; n++) {
        char *end = strchr(line, '\n');
        cr_assert_not_null(end, "%s: last line unterminated", name);
        char *field = line;
        for (int k = 0; k < fields; k++) {
            char *stop = k + 1 < fields ? memchr(field, ',', (size_t)(end - field)) : end;
            cr_assert_not_null(stop, "%s row %d: %d fields, expected %d", name, n + 1, k + 1, fields);
            if (k >= first_number && !(k == may_be_empty && stop == field)) {
                char *num_end;
                double v = strtod(field, &num_end);
                cr_assert(num_end == stop && isfinite(v), "%s row %d field %d: '%.*s'", name, n + 1, k + 1,
                          (int)(stop - field), field);
            }
            field = stop + 1;
        }
        cr_assert_eq(field, end + 1, "%s row %d: more than %d fields", name, n + 1, fields);
        line = end + 1;
    }
    cr_assert_eq(n, rows, "%s: %d rows, expected %d", name, n, rows);
    return text;
}

static void check_png(const char *name)
{
    char path[256];
    snprintf(path, sizeof path, RES "/%s.png", name);
    cli_check_chart(path, 640, 480);
}

Test(bench_knobs_cli, quick_run_writes_every_csv_and_chart)
{
    cli_fresh(TDIR);
    int rc = cli_run(TDIR, "bench accuracy --quick --only knobs --out " RES);
    char *err = cli_slurp(TDIR "/stderr.txt");
    cr_assert(rc == 0, "status %d\n%s", rc, err);
    cr_assert_str_eq(err, "");
    free(err);
    char *out = cli_slurp(TDIR "/stdout.txt");
    cr_assert_not_null(strstr(out, "every error is within its bound"), "%s", out);
    cr_assert_not_null(strstr(out, "AN EXPERIMENT, NOT A LIBRARY PATH"), "%s", out);
    cr_assert_not_null(strstr(out, "reproduced the library's bits"), "%s", out);

    /* quick: 11 sizes x 3 lookups; 3 rates x 4 frame rates x 2 modes;
     * 2 cases x 3 births x 4 frame rates; 3 sample counts x 2 modes;
     * (6 + 6 + 3) step sizes x 3 implementations */
    free(out);
    free(check_csv("sine", "mode,size,max_abs_error,bound,error_over_bound,ns_per_call,libm_ns_per_call", 33, 1, -1));
    /* the campfire: floor is the review's 3/255, lerp is libm's picture */
    char *camp = check_csv("campfire_sine",
                           "lookup,pixels_differing,max_channel_difference,max_x_offset_units,max_x_offset_px", 3, 1, -1);
    cr_assert_not_null(strstr(camp, "\nfloor,1256,3,"), "%s", camp);
    cr_assert_not_null(strstr(camp, "\nlerp,0,0,"), "%s", camp);
    free(camp);
    char *rate = check_csv("emission_rate",
                           "rate,steps_per_s,mode,count_at_1s,expected_at_1s,error_at_1s_percent,"
                           "max_abs_count_error,ns_per_step,ns_per_particle",
                           24, 3, 8);
    /* the thesis's rounding at 20/s and 60 steps/s emits nothing */
    cr_assert_not_null(strstr(rate, "\n20,60,thesis,0,20,-100.0000,"), "%s", rate);
    free(rate);
    free(check_csv("emission_birth",
              "scenario,mode,steps_per_s,particles,mean_position_error,max_position_error,ns_per_step,"
              "us_per_sim_second",
              24, 2, -1));
    free(check_csv("ellipse",
              "mode,samples,ks_distance,tip_fraction,tip_fraction_error,max_bin_deviation,ns_per_sample,us_total", 6,
              1, -1));
    free(check_csv("float", "case,x0,T,steps_per_s,impl,max_position_error,ns_per_particle_step,ns_per_particle_run", 45,
              5, -1));
    const char *charts[] = {"sine", "emission_rate", "emission_birth", "ellipse", "float"};
    for (int i = 0; i < 5; i++)
        check_png(charts[i]);

    /* Only the eleven outputs: the temporary names were all renamed. */
    DIR *d = opendir(RES);
    cr_assert_not_null(d);
    int files = 0;
    for (struct dirent *e; (e = readdir(d));)
        if (e->d_name[0] != '.') {
            files++;
            cr_expect_null(strstr(e->d_name, ".tmp"), "left behind: %s", e->d_name);
        }
    closedir(d);
    cr_assert_eq(files, 11);
}
