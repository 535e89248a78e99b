/* SPDX-License-Identifier: MIT */
/* `iskra play`: a live edit that moves the scene's drag across iskra's cap
 * (b*h/m = 1) or across its integrator's drag edge (iskra/stability.h)
 * puts a warning in the status line; back below the cap says so; the
 * scene as loaded, and edits that cross nothing, say nothing. */
#include <criterion/criterion.h>
#include <stdlib.h>
#include <string.h>

#include "play_session.h"

#define OUT "out/test_play_stability/"

/* b*h/m = b/60/substeps for a particle of mass 1 at dt = 1/60. */
static void scene(const char *dir, double b, int substeps, const char *integrator)
{
    char path[256], text[512];
    snprintf(path, sizeof path, "%s/drag.ini", dir);
    snprintf(text, sizeof text,
             "[scene]\ndt = 1/60\nsubsteps = %d\nintegrator = %s\n[force drag]\nb = %g\n"
             "[emitter p]\nsource = particle\nvelocity = 3, 4\nmass = 1\nforces = drag\n",
             substeps, integrator, b);
    cli_write_file(path, text);
}

static char *session(const char *dir, double b, int substeps, const char *integrator, const char *script)
{
    char args[1024];
    cli_fresh(dir);
    scene(dir, b, substeps, integrator);
    snprintf(args, sizeof args, "play --fixed-clock %s/drag.ini --frames 40 --script '%s'", dir, script);
    cr_assert_eq(cli_run(dir, args), 0);
    char p[256];
    snprintf(p, sizeof p, "%s/stderr.txt", dir);
    return cli_slurp(p);
}

#define SUBSTEPS(n) "wait:2 press:section/scene wait:1 press:scene/substeps ctrl+a type:" #n " return wait:3"

Test(play_stability, crossing_the_cap_and_back_warns_and_clears)
{
    /* b = 90: 0.75 at 2 substeps, 1.5 at 1 (capped), 0.5 at 3 */
    char *err = session(OUT "cap", 90, 2, "semi-euler", SUBSTEPS(1) " " "press:scene/substeps ctrl+a type:3 return wait:3");
    const char *warn = strstr(err, "warning: b*h/m = 1.5 for 'p' is past iskra's drag cap of 1");
    cr_assert_not_null(warn, "%s", err);
    cr_assert_not_null(strstr(warn, "b*h/m = 0.5 for 'p': below iskra's drag cap again"), "%s", err);
    free(err);
}

Test(play_stability, crossing_the_methods_edge_warns)
{
    /* b = 150 under explicit Euler: 1.25 at 2 substeps (capped as loaded: no word), 2.5 at 1: past its edge 2 */
    char *err = session(OUT "edge", 150, 2, "euler", SUBSTEPS(1));
    cr_assert_not_null(strstr(err, "warning: b*h/m = 2.5 for 'p' is past euler's drag edge 2:"), "%s", err);
    cr_assert_null(strstr(err, "drag cap of 1"), "the scene as loaded says nothing:\n%s", err);
    free(err);
}

Test(play_stability, an_edit_that_crosses_nothing_says_nothing)
{
    char *err = session(OUT "quiet", 30, 2, "rk4", SUBSTEPS(1));
    cr_assert_null(strstr(err, "b*h/m"), "%s", err);
    free(err);
}

Test(play_stability, crossing_a_potential_cores_spring_edge_warns)
{
    /* a spring of w = 120 * 2^(1/4) (tests/data/accuracy/spring.ini): w*h = 1.19 at 2 substeps, 2.38 at 1 */
    const char *dir = OUT "spring";
    cli_fresh(dir);
    cli_write_file(OUT "spring/spring.ini", "[scene]\ndt = 1/60\nsubsteps = 2\n[force spring]\nkind = potential\n"
                                            "k = 20364.675298172568\nposition = 0, 0\nexponent = 0\n[emitter p]\nsource = particle\n"
                                            "position = 1, 0\nmass = 1\nforces = spring\n");
    /* a scene with a potential gets the thesis's console: its precision field is the substeps */
    cr_assert_eq(cli_run(dir, "play --fixed-clock " OUT "spring/spring.ini --frames 40 --script 'wait:2 "
                              "press:precision ctrl+a type:1 return wait:3'"),
                 0);
    char *err = cli_slurp(OUT "spring/stderr.txt");
    cr_assert_not_null(strstr(err, "warning: w*h = 2.38 for 'p' is past semi-euler's spring edge 2:"), "%s", err);
    free(err);
}
