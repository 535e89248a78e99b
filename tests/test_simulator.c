/* SPDX-License-Identifier: MIT */
/* `iskra play` as the thesis's simulator, driven by scripted sessions under
 * SDL's dummy driver (--fixed-clock: one step per frame, so a script gives
 * the same pixels every time): the console's controls change the running
 * scene through the key table, the window is compared with reference
 * images refimg/simulator_*.png, and what the controls did is read back
 * from the scene they save. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "play_session.h"
#include "refimg.h"
#include "scene_open.h"
#include "tool_cli.h"

#define OUT "out/test_simulator/"

/* The canvas a library run gives: the scene, `frames` steps, one render. */
static void library_canvas(const char *scene, long frames, isk_canvas *c)
{
    isk_effect *fx = scene_open_builtin(scene);
    const isk_effect_def *d = isk_effect_definition(fx);
    cr_assert_eq(isk_canvas_init(c, d->width, d->height), ISK_OK);
    cr_assert_eq(isk_effect_run(fx, c, frames), ISK_OK);
    isk_effect_destroy(fx);
}

/* ---- the thesis's behaviour ------------------------------------------------------ */

/* prviFrame: the mushroom scene runs one frame and holds; Step runs one more. */
Test(simulator, starts_paused_after_one_frame_and_steps)
{
    cr_assert_eq(play_session(OUT "paused", "fig26_mushroom_one_potential --ui-scale 1 --frames 12 --script "
                                            "'wait:4 canvas-shot:" OUT "paused/a.png press:step wait:3 canvas-shot:" OUT
                                            "paused/b.png n wait:3 canvas-shot:" OUT "paused/c.png'"),
                 0, "%s", play_stderr(OUT "paused"));
    const char *shots[3] = {OUT "paused/a.png", OUT "paused/b.png", OUT "paused/c.png"};
    for (int k = 0; k < 3; k++) {
        isk_canvas got, want;
        play_read_png(shots[k], &got);
        library_canvas("fig26_mushroom_one_potential", 1 + k, &want);
        cr_expect(isk_canvas_equal(&got, &want), "%s is not frame %d", shots[k], 1 + k);
        isk_canvas_free(&got);
        isk_canvas_free(&want);
    }
}

/* The console's fields in thesis fidelity: out-of-range gravity and drag
 * become 9.81 and 0.47, a fractional precision runs ceil(p) steps of
 * dt/p; every field goes through the key table. */
Test(simulator, thesis_fields_and_their_replacements)
{
    cr_assert_eq(play_session(OUT "thesis",
                              "fig22_simulator_regular --ui-scale 1 --frames 40 --save " OUT "thesis/s.ini "
                              "--script 'press:gravity wait:2 key:backspace type:-5 key:return "
                              "press:drag wait:2 key:backspace type:200000 key:return "
                              "press:precision wait:2 key:backspace type:2.5 key:return "
                              "press:explosion-count wait:2 key:backspace key:backspace key:backspace "
                              "key:backspace type:250 key:return wait:3 f2'"),
                 0, "%s", play_stderr(OUT "thesis"));
    isk_effect *fx = scene_open_file(OUT "thesis/s.ini");
    scene_expect_key(fx, "force gravity", "g", "9.81");
    scene_expect_key(fx, "force drag", "b", "0.47");
    scene_expect_key(fx, "scene", "substeps", "3");
    char want[64];
    snprintf(want, sizeof want, "%.17g", 1.0 / 60 * 3 / 2.5);
    char v[64];
    isk_error err;
    cr_assert_eq(isk_effect_get(fx, "scene", "dt", v, sizeof v, &err), ISK_OK);
    cr_expect_eq(strtod(v, NULL), strtod(want, NULL), "dt %s", v);
    scene_expect_key(fx, "click", "count", "250");
    isk_effect_destroy(fx);
    char *e = play_stderr(OUT "thesis");
    cr_expect(strstr(e, "the thesis puts 9.81"), "%s", e);
    cr_expect(strstr(e, "runs 3 steps of dt/2.5"), "%s", e);
    free(e);
}

/* In sound fidelity a refused value stays in its field with the key
 * table's own message under it, and changes nothing. */
Test(simulator, a_refused_value_shows_the_tables_message)
{
    (void)system("mkdir -p " OUT);
    cli_write_file(OUT "sound.ini", PLAY_SOUND_SCENE);
    cr_assert_eq(play_session(OUT "refused",
                              OUT "sound.ini --ui-scale 2 --frames 30 --save " OUT "refused/s.ini --script "
                                  "'press:gravity wait:2 key:backspace key:backspace key:backspace key:backspace "
                                  "type:-5 key:return wait:3 f2 wait:2 shot:" OUT "refused/window.png'"),
                 0, "%s", play_stderr(OUT "refused"));
    isk_effect *fx = scene_open_file(OUT "refused/s.ini");
    scene_expect_key(fx, "force gravity", "g", "9.81");
    isk_effect_destroy(fx);
    isk_canvas c;
    play_read_png(OUT "refused/window.png", &c);
    cr_expect(refimg_check("simulator_field_error", &c));
    isk_canvas_free(&c);
}

/* ---- potentials --------------------------------------------------------------------- */

Test(simulator, the_potential_editor_with_a_potential_selected)
{
    cr_assert_eq(play_session(OUT "editor",
                              "fig28_mushroom_three_potentials --ui-scale 2 --frames 30 --save " OUT
                              "editor/s.ini --script 'press:potentials/1 wait:2 press:pot-k wait:2 key:end "
                              "key:backspace type:5 key:return press:pot-off wait:3 f2 wait:2 shot:" OUT
                              "editor/window.png'"),
                 0, "%s", play_stderr(OUT "editor"));
    isk_effect *fx = scene_open_file(OUT "editor/s.ini");
    scene_expect_key(fx, "force C2", "k", "400005");
    scene_expect_key(fx, "force C2", "enabled", "false");
    scene_expect_key(fx, "force C1", "enabled", "true");
    isk_effect_destroy(fx);
    isk_canvas c;
    play_read_png(OUT "editor/window.png", &c);
    cr_expect(refimg_check("simulator_potential_editor", &c));
    isk_canvas_free(&c);
}

/* Add potential: a click puts one (k = 0, as the thesis) at the point; its
 * k is typed; its disc is dragged somewhere else. */
Test(simulator, add_a_potential_type_its_k_and_drag_it)
{
    const char *args = "simulator --ui-scale 2 --frames 40 --save " OUT "added/s.ini --script "
                       "'press:click/add-potential wait:2 click:300,300 wait:2 press:pot-k wait:2 key:backspace "
                       "type:40 key:return press:click/coulomb wait:2 drag:300,300,420,180 wait:3 click:150,450 "
                       "wait:20 f2 wait:2 shot:" OUT "added/window.png'";
    cr_assert_eq(play_session(OUT "added", args), 0, "%s", play_stderr(OUT "added"));
    isk_effect *fx = scene_open_file(OUT "added/s.ini");
    scene_expect_key(fx, "force P1", "kind", "potential");
    scene_expect_key(fx, "force P1", "k", "40");
    scene_expect_key(fx, "force P1", "position", "7, 7");
    scene_expect_key(fx, "click", "explosion", "coulomb");
    scene_expect_key(fx, "click", "enabled", "true");
    isk_effect_destroy(fx);
    isk_canvas c, d;
    play_read_png(OUT "added/window.png", &c);
    cr_expect(refimg_check("simulator_add_potential", &c));
    /* the same session again: the same bytes */
    cr_assert_eq(play_session(OUT "added", args), 0, "%s", play_stderr(OUT "added"));
    play_read_png(OUT "added/window.png", &d);
    cr_expect(isk_canvas_equal(&c, &d), "the same script gave different pixels");
    isk_canvas_free(&c);
    isk_canvas_free(&d);
}

/* ---- charts, integrators, panel --------------------------------------------------------- */

/* 300 frames of the mushroom (the panel hidden meanwhile: frames without
 * it are cheap); the energy and count charts, then rk4 chosen. */
Test(simulator, the_energy_chart_after_300_frames)
{
    cr_assert_eq(play_session(OUT "energy",
                              "fig26_mushroom_one_potential --ui-scale 2 --frames 320 --save " OUT "energy/s.ini "
                              "--script 'press:play tab wait:296 tab wait:3 shot:" OUT "energy/window.png "
                              "press:integrator/rk4 wait:2 f2'"),
                 0, "%s", play_stderr(OUT "energy"));
    isk_canvas c;
    play_read_png(OUT "energy/window.png", &c);
    cr_expect(refimg_check("simulator_energy_chart", &c));
    isk_canvas_free(&c);
    isk_effect *fx = scene_open_file(OUT "energy/s.ini");
    scene_expect_key(fx, "scene", "integrator", "rk4");
    isk_effect_destroy(fx);
}

Test(simulator, the_panel_hides_and_comes_back)
{
    cr_assert_eq(play_session(OUT "panel",
                              "fig22_simulator_regular --ui-scale 1 --frames 20 --script 'tab wait:3 shot:" OUT
                              "panel/hidden.png tab wait:3 shot:" OUT "panel/shown.png'"),
                 0, "%s", play_stderr(OUT "panel"));
    isk_canvas a, b;
    play_read_png(OUT "panel/hidden.png", &a);
    play_read_png(OUT "panel/shown.png", &b);
    cr_expect(a.width == 600 && a.height == 600, "hidden: %dx%d", a.width, a.height);
    cr_expect(b.width > 600 && b.height > 600, "shown: %dx%d", b.width, b.height);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    cr_assert_eq(play_session(OUT "nopanel", "fig22_simulator_regular --no-panel --frames 3 --script 'wait:1 shot:" OUT
                                             "nopanel/w.png'"),
                 0);
    play_read_png(OUT "nopanel/w.png", &a);
    cr_expect(a.width == 600 && a.height == 600);
    isk_canvas_free(&a);
}

Test(simulator, click_modes_and_speed_from_the_keys)
{
    cr_assert_eq(play_session(OUT "keys", "fig22_simulator_regular --ui-scale 1 --frames 20 --save " OUT "keys/s.ini "
                                          "--script '3 , , wait:2 click:300,300 wait:2 + + wait:2 f2'"),
                 0, "%s", play_stderr(OUT "keys"));
    isk_effect *fx = scene_open_file(OUT "keys/s.ini");
    scene_expect_key(fx, "click", "explosion", "gauss");
    scene_expect_key(fx, "scene", "substeps", "3");
    char v[64];
    isk_error err;
    cr_assert_eq(isk_effect_get(fx, "scene", "speed_divisor", v, sizeof v, &err), ISK_OK);
    cr_expect_float_eq(strtod(v, NULL), 1 + 29.0 * 200 / 999, 1e-12, "the slider at 800: f = %s", v);
    isk_effect_destroy(fx);
}

/* The scene file changes while it plays: the simulator reloads it. */
Test(simulator, reloads_when_the_file_changes)
{
    const char *dir = OUT "reload";
    cli_fresh(dir);
    const char *scene = OUT "reload/scene.ini";
    const char *v1 = "[view]\nxmin = 0\nxmax = 10\nymin = 0\nymax = 10\n[force gravity]\ng = %s\n"
                     "[emitter p]\nsource = layer\ncount = 50\nrect = 0, 10, 0, 5\nforces = gravity\n";
    FILE *f = fopen(scene, "w");
    cr_assert_not_null(f);
    fprintf(f, v1, "1");
    fclose(f);
    /* real time (paced at about 60 frames a second): about 4 s */
    char cmd[1024];
    snprintf(cmd, sizeof cmd,
             "SDL_VIDEODRIVER=dummy %s/bin/iskra play %s --ui-scale 1 --frames 240 --save %s/s.ini "
             "--script 'wait:230 f2' >%s/stdout.txt 2>%s/stderr.txt &",
             refimg_build_dir(), scene, dir, dir, dir);
    cr_assert_eq(system(cmd), 0);
    play_sleep_ms(1500);
    f = fopen(scene, "w");
    cr_assert_not_null(f);
    fprintf(f, v1, "7.5");
    fclose(f);
    char saved[256];
    snprintf(saved, sizeof saved, "%s/s.ini", dir);
    for (int i = 0; i < 300 && !cli_exists(saved); i++)
        play_sleep_ms(100);
    play_sleep_ms(300);
    char p[256];
    snprintf(p, sizeof p, "%s/stderr.txt", dir);
    char *e = cli_slurp(p);
    cr_expect(strstr(e, "changed: reloaded"), "%s", e);
    free(e);
    isk_effect *fx = scene_open_file(saved);
    scene_expect_key(fx, "force gravity", "g", "7.5");
    isk_effect_destroy(fx);
}

/* The keys `iskra play --help` lists (from the tool's one table of
 * actions) are the keys docs/simulator.md lists. */
Test(simulator, the_documented_keys_are_the_tools)
{
    cli_fresh(OUT "help");
    cr_assert_eq(cli_run(OUT "help", "play --help"), 0);
    char *help = cli_slurp(OUT "help/stdout.txt"), *doc = cli_slurp("docs/simulator.md");
    char *from = strstr(help, "\n  keys ("), *to = strstr(help, "\n  --frames");
    cr_assert(from && to && from < to, "%s", help);
    from = strchr(from + 1, '\n');
    *to = 0;
    int keys = 0;
    for (char *item = strtok(from, ";\n"); item; item = strtok(NULL, ";\n")) {
        while (*item == ' ')
            item++;
        char key[16], cell[24];
        if (sscanf(item, "%15s", key) != 1)
            continue;
        snprintf(cell, sizeof cell, "| %s |", key);
        cr_expect(strstr(doc, cell), "docs/simulator.md does not list the key %s", key);
        keys++;
    }
    cr_expect_geq(keys, 15);
    free(help);
    free(doc);
}

/* ---- refusals ------------------------------------------------------------------------------- */

Test(simulator, bad_options_and_scripts)
{
    cr_assert_eq(play_session(OUT "bad", "simulator --ui-scale 9 --frames 1"), 2);
    cr_assert_eq(play_session(OUT "bad", "simulator --save '' --frames 1"), 2);
    cr_assert_eq(play_session(OUT "bad", "simulator --frames 1 --script 'press:'"), 2);
    cr_assert_eq(play_session(OUT "bad", "simulator --frames 1 --script 'wait:-1'"), 2);
    cr_assert_eq(play_session(OUT "bad", "simulator --frames 5 --script 'press:no-such-widget'"), 1);
    char *e = play_stderr(OUT "bad");
    cr_expect(strstr(e, "no widget 'no-such-widget'"), "%s", e);
    free(e);
}

/* No display: SDL's offscreen fallback is refused, loudly, with exit 1;
 * make run then renders to out/. */
Test(simulator, without_a_display_it_says_so_and_exits_1)
{
    const char *dir = OUT "headless";
    cli_fresh(dir);
    char cmd[1024];
    snprintf(cmd, sizeof cmd,
             "env -u SDL_VIDEODRIVER -u WAYLAND_DISPLAY DISPLAY=:4093 %s/bin/iskra play simulator --frames 2 "
             ">%s/out.txt 2>&1",
             refimg_build_dir(), dir);
    int rc = system(cmd);
    char p[256];
    snprintf(p, sizeof p, "%s/out.txt", dir);
    char *e = cli_slurp(p);
    if (WIFEXITED(rc) && WEXITSTATUS(rc) == 0) {
        free(e);
        cr_skip_test("a video driver showed a window without a display here");
    }
    cr_expect(WIFEXITED(rc) && WEXITSTATUS(rc) == 1, "%s", e);
    cr_expect(strstr(e, "no display"), "%s", e);
    free(e);
    snprintf(cmd, sizeof cmd,
             "env -u SDL_VIDEODRIVER -u WAYLAND_DISPLAY DISPLAY=:4093 %s/examples/fig16_regular --window "
             ">%s/out.txt 2>&1",
             refimg_build_dir(), dir);
    rc = system(cmd);
    e = cli_slurp(p);
    cr_expect(WIFEXITED(rc) && WEXITSTATUS(rc) == 1, "%s", e);
    cr_expect(strstr(e, "no display"), "%s", e);
    free(e);
    snprintf(cmd, sizeof cmd,
             "cd %s && rm -rf out && env -u SDL_VIDEODRIVER -u WAYLAND_DISPLAY DISPLAY=:4093 BUILD=%s%s "
             "sh %s/tools/run_demo.sh >out.txt 2>&1",
             dir, refimg_build_dir()[0] == '/' ? "" : "../../../", refimg_build_dir(), "../../..");
    rc = system(cmd);
    e = cli_slurp(p);
    cr_expect(WIFEXITED(rc) && WEXITSTATUS(rc) == 0, "%s", e);
    cr_expect(strstr(e, "rendering to out/ instead"), "%s", e);
    free(e);
    char png[256];
    snprintf(png, sizeof png, "%s/out/fire_campfire.png", dir);
    cr_expect(cli_exists(png), "make run renders to out/ instead");
}

/* Criterion runs tests in parallel; each uses its own directory. */
