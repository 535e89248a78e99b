/* SPDX-License-Identifier: MIT */
/* `iskra play` in a classroom (docs/simulator.md): what two outside reviews
 * of a lesson found, each as the class of problem it is, driven by scripted
 * sessions under SDL's dummy driver with --fixed-clock (the same pixels
 * every time) and --screen (the layout a real screen of that size gets):
 *
 *   typing into a field replaces its value (spin-box selection)
 *   messages are whole: wrapped inside their column, a reload error on the
 *     canvas until the file loads
 *   the window fits 1280x720 and 1366x768 with text 10 px tall, and the
 *     window at both sizes matches refimg/simulator_*x*.png and
 *     refimg/inspector_*x*.png exactly
 *   the panel shows what the scene has: the console for the explosion
 *     thesis's scenes, the inspector with every section's live keys for the
 *     others
 *   names: --list-widgets, suggestions for a wrong one; a save reloads to
 *     the same state
 *   `play --help`'s usage names every option. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/keys.h"
#include "iskra/scene.h"
#include "iskra/ui.h"
#include "play_session.h"
#include "refimg.h"
#include "scene_open.h"
#include "tool_cli.h"

#define OUT "out/test_simulator_classroom/"

/* ---- 1. typing replaces -------------------------------------------------------------- */

/* "type 10 into Gravity" gave 9.811: the focus now selects the value. */
Test(classroom, typing_into_a_field_replaces_its_value)
{
    cr_assert_eq(play_session(OUT "typing",
                              "fig22_simulator_regular --screen 1280x720 --frames 40 --save " OUT "typing/s.ini "
                              "--script 'press:gravity wait:2 type:10 key:return press:drag wait:2 type:0.3 "
                              "key:return press:explosion-count wait:2 key:end type:5 ctrl+a type:250 key:return "
                              "wait:2 f2'"),
                 0, "%s", play_stderr(OUT "typing"));
    isk_effect *fx = scene_open_file(OUT "typing/s.ini");
    scene_expect_key(fx, "force gravity", "g", "10");
    scene_expect_key(fx, "force drag", "b", "0.3");
    scene_expect_key(fx, "click", "count", "250");
    isk_effect_destroy(fx);
    /* the inspector's fields, the same */
    cr_assert_eq(play_session(OUT "typing2",
                              "fire_campfire --screen 1280x720 --frames 30 --save " OUT "typing2/s.ini --script "
                              "'press:emitter-flame/rate wait:2 type:60 key:return press:emitter-sparks/size wait:2 "
                              "type:0.2 key:return wait:2 f2'"),
                 0, "%s", play_stderr(OUT "typing2"));
    fx = scene_open_file(OUT "typing2/s.ini");
    scene_expect_key(fx, "emitter flame", "rate", "60");
    scene_expect_key(fx, "emitter sparks", "size", "0.2");
    isk_effect_destroy(fx);
}

/* ---- 2. messages ---------------------------------------------------------------------- */

/* The bounding box of the pixels in the widgets' error colour. */
static int error_box(const isk_canvas *c, int *x0, int *x1, int *y0, int *y1)
{
    isk_ui ui;
    isk_ui_init(&ui, 1);
    const isk_color e = ui.style.error;
    int n = 0;
    *x0 = *y0 = 1 << 30;
    *x1 = *y1 = -1;
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++) {
            isk_color p = isk_canvas_get(c, x, y);
            if (p.r == e.r && p.g == e.g && p.b == e.b) {
                n++;
                *x0 = x < *x0 ? x : *x0;
                *x1 = x > *x1 ? x : *x1;
                *y0 = y < *y0 ? y : *y0;
                *y1 = y > *y1 ? y : *y1;
            }
        }
    return n;
}

/* A refused value's message wraps inside the console's column (it was
 * centred on the field, wider than the column, cut at both edges). */
Test(classroom, a_refused_value_s_message_stays_in_its_column)
{
    (void)system("mkdir -p " OUT);
    cli_write_file(OUT "sound.ini", PLAY_SOUND_SCENE);
    cr_assert_eq(play_session(OUT "refused",
                              OUT "sound.ini --screen 1280x720 --frames 30 --script 'press:gravity wait:2 "
                                  "type:-5 key:return wait:3 shot:" OUT "refused/window.png'"),
                 0, "%s", play_stderr(OUT "refused"));
    isk_canvas c;
    play_read_png(OUT "refused/window.png", &c);
    int x0, x1, y0, y1;
    cr_assert_gt(error_box(&c, &x0, &x1, &y0, &y1), 0);
    /* the console's column: the first third of the panel right of the 600 px canvas */
    const int column_end = 600 + (c.width - 600) / 3;
    cr_expect(x0 >= 600 && x1 < column_end, "the message spans x %d..%d, the column 600..%d", x0, x1, column_end - 1);
    cr_assert(refimg_check("simulator_1280x720", &c));
    isk_canvas_free(&c);
}

static void wait_for(const char *path)
{
    for (int i = 0; i < 200 && !cli_exists(path); i++)
        play_sleep_ms(50);
    cr_assert(cli_exists(path), "%s never came", path);
    play_sleep_ms(100); /* written whole */
}

/* The class watches the projector, not the terminal: a scene file that
 * stops loading shows its whole FILE:LINE: message on the canvas until it
 * loads again.  (Real time: the file changes while it plays.) */
Test(classroom, a_reload_error_shows_in_the_window_until_the_file_is_fixed, .timeout = 60)
{
    const char *dir = OUT "reload";
    cli_fresh(dir);
    const char *scene = OUT "reload/scene.ini";
    const char *good = "[scene]\nwidth = 400\nheight = 300\n[view]\nxmin = 0\nxmax = 10\nymin = 0\nymax = 10\n"
                       "[emitter dots]\nsource = layer\ncount = 50\nrect = 0, 10, 0, 5\n";
    const char *bad = "[scene]\nwidth = 400\nheight = 300\n[view]\nxmin = 0\nxmax = 10\nymin = 0\nymax = 10\n"
                      "[emitter dots]\nsource = layer\ncount = 50\nrect = 0, 10, 0, 5\nsize = -3\n";
    cli_write_file(scene, good);
    char cmd[1200];
    snprintf(cmd, sizeof cmd,
             "SDL_VIDEODRIVER=dummy %s/bin/iskra play %s --screen 1280x720 --frames 400 --script 'wait:2 shot:%s/a.png "
             "wait:120 shot:%s/b.png wait:120 shot:%s/c.png' >%s/stdout.txt 2>%s/stderr.txt &",
             refimg_build_dir(), scene, dir, dir, dir, dir, dir);
    cr_assert_eq(system(cmd), 0);
    char a[256], b[256], c[256];
    snprintf(a, sizeof a, "%s/a.png", dir);
    snprintf(b, sizeof b, "%s/b.png", dir);
    snprintf(c, sizeof c, "%s/c.png", dir);
    wait_for(a);
    cli_write_file(scene, bad);
    wait_for(b);
    cli_write_file(scene, good);
    wait_for(c);
    char p[256];
    snprintf(p, sizeof p, "%s/stderr.txt", dir);
    char *e = cli_slurp(p);
    const char *want = "reload/scene.ini:13: [emitter dots] size: expected a number > 0 and <= 1e6, got \"-3\"";
    cr_expect(strstr(e, want), "%s", e);
    free(e);
    isk_canvas shot;
    int x0, x1, y0, y1;
    play_read_png(b, &shot);
    cr_expect_gt(error_box(&shot, &x0, &x1, &y0, &y1), 0, "the message is on the canvas");
    cr_expect(x1 < 400 && y1 < 300 && y0 > 150, "at the canvas's foot: x %d..%d, y %d..%d", x0, x1, y0, y1);
    /* whole: the band is as tall as the message's lines wrapped to the canvas */
    isk_ui ui;
    isk_ui_init(&ui, 1);
    ui.font = ISK_FONT_6X13;
    char text[400], lines[500];
    snprintf(text, sizeof text, "out/test_simulator_classroom/%s (the last version keeps running)", want);
    const int n = isk_ui_wrap(&ui, text, 400 - 8, lines, sizeof lines);
    cr_expect_eq(300 - y0, n * isk_ui_line_height(&ui) + 8, "%d lines: a band of %d px, not %d", n,
                 n * isk_ui_line_height(&ui) + 8, 300 - y0);
    isk_canvas_free(&shot);
    play_read_png(c, &shot);
    cr_expect_eq(error_box(&shot, &x0, &x1, &y0, &y1), 0, "fixed: the message is gone");
    isk_canvas_free(&shot);
}

/* ---- 3. screens ------------------------------------------------------------------------- */

typedef struct screen {
    int w, h;
} screen;

static const screen screens[] = {{1280, 720}, {1366, 768}};

/* "a WxH window for a SxS screen: ..., text N px tall" from play's stderr. */
static void window_line(const char *err, int *w, int *h, int *text)
{
    const char *l = strstr(err, "iskra play: a ");
    cr_assert_not_null(l, "%s", err);
    int sw, sh;
    cr_assert_eq(sscanf(l, "iskra play: a %dx%d window for a %dx%d screen", w, h, &sw, &sh), 4, "%s", l);
    const char *t = strstr(l, "text ");
    cr_assert_not_null(t, "%s", l);
    cr_assert_eq(sscanf(t, "text %d px tall", text), 1);
}

Test(classroom, the_window_fits_classroom_screens_with_text_10_px_tall)
{
    static const char *const scenes[] = {"fig22_simulator_regular", "fig29_mushroom_four_potentials", "fire_campfire",
                                         "motion_orbit", "simulator"};
    for (size_t s = 0; s < sizeof screens / sizeof screens[0]; s++)
        for (size_t k = 0; k < sizeof scenes / sizeof scenes[0]; k++) {
            char args[400];
            snprintf(args, sizeof args, "%s --screen %dx%d --frames 3 --script 'wait:1 shot:" OUT "fits/w.png'",
                     scenes[k], screens[s].w, screens[s].h);
            cr_assert_eq(play_session(OUT "fits", args), 0, "%s", play_stderr(OUT "fits"));
            char *e = play_stderr(OUT "fits");
            int w, h, text;
            window_line(e, &w, &h, &text);
            free(e);
            cr_expect_leq(w, screens[s].w, "%s at %dx%d: %d wide", scenes[k], screens[s].w, screens[s].h, w);
            cr_expect_leq(h, screens[s].h - 48, "%s at %dx%d: %d tall (a title bar needs room)", scenes[k],
                          screens[s].w, screens[s].h, h);
            cr_expect_geq(text, 10, "%s at %dx%d: text %d px", scenes[k], screens[s].w, screens[s].h, text);
            isk_canvas c;
            play_read_png(OUT "fits/w.png", &c);
            cr_expect(c.width == w && c.height == h, "the window is %dx%d", c.width, c.height);
            isk_canvas_free(&c);
        }
}

/* The thesis's console at 1366x768: the mushroom's potential editor, a
 * potential selected and its k typed; the reference image shows it. */
Test(classroom, the_console_at_1366x768)
{
    cr_assert_eq(play_session(OUT "console768",
                              "fig29_mushroom_four_potentials --screen 1366x768 --frames 40 --script "
                              "'press:potentials/1 wait:2 press:pot-k wait:2 type:640000 key:return press:play "
                              "wait:20 shot:" OUT "console768/window.png'"),
                 0, "%s", play_stderr(OUT "console768"));
    isk_canvas c;
    play_read_png(OUT "console768/window.png", &c);
    cr_assert(refimg_check("simulator_1366x768", &c));
    isk_canvas_free(&c);
}

/* ---- 4. the inspector -------------------------------------------------------------------- */

/* The campfire edited live, as an effect tinkerer does: the flame's rate
 * and colour over life, the sparks' spin. */
Test(classroom, the_inspector_edits_the_campfire_while_it_runs)
{
    const char *script = "'press:emitter-flame/rate wait:2 type:90 key:return press:emitter-flame/color_over_life "
                         "wait:2 type:0:#80c0ff50,0.5:#4060ff30,1:#20004000 key:return press:emitter-sparks/spin "
                         "wait:2 type:720 key:return press:emitter-flame/blend wait:2 press:emitter-flame/blend/add "
                         "press:section/emitter-flame wait:40 f2 wait:2 shot:" OUT "insp/window.png'";
    char args[1200];
    snprintf(args, sizeof args, "fire_campfire --screen 1280x720 --frames 80 --save " OUT "insp/s.ini --script %s",
             script);
    cr_assert_eq(play_session(OUT "insp", args), 0, "%s", play_stderr(OUT "insp"));
    isk_effect *fx = scene_open_file(OUT "insp/s.ini");
    scene_expect_key(fx, "emitter flame", "rate", "90");
    scene_expect_key(fx, "emitter flame", "color_over_life", "0:#80c0ff50, 0.5:#4060ff30, 1:#20004000");
    scene_expect_key(fx, "emitter sparks", "spin", "720");
    scene_expect_key(fx, "emitter flame", "blend", "add");
    isk_effect_destroy(fx);
    isk_canvas c;
    play_read_png(OUT "insp/window.png", &c);
    cr_assert(refimg_check("inspector_1280x720", &c));
    isk_canvas_free(&c);
}

/* At 1366x768: a refused value's message under its key (the table's
 * message), and a choice's list open over the keys. */
Test(classroom, the_inspector_at_1366x768_says_why_it_refuses)
{
    cr_assert_eq(play_session(OUT "insp768",
                              "fire_campfire --screen 1366x768 --frames 30 --script 'press:emitter-sparks/spin "
                              "wait:2 type:9000000 key:return wait:3 shot:" OUT "insp768/window.png'"),
                 0, "%s", play_stderr(OUT "insp768"));
    isk_canvas c;
    play_read_png(OUT "insp768/window.png", &c);
    int x0, x1, y0, y1;
    cr_assert_gt(error_box(&c, &x0, &x1, &y0, &y1), 0);
    cr_expect(x0 >= 480, "the message is in the inspector, right of the 480 px canvas: x %d", x0);
    cr_assert(refimg_check("inspector_1366x768", &c));
    isk_canvas_free(&c);
}

/* Whether `name` is a line of the list (which starts with a '\n'). */
static int listed(const char *list, const char *name)
{
    char line[200];
    snprintf(line, sizeof line, "\n%s\n", name);
    return strstr(list, line) != NULL;
}

/* The inspector shows every section of the running scene with the keys
 * isk_effect_set takes for its kind, and none it refuses. */
Test(classroom, the_inspector_lists_every_section_and_its_live_keys)
{
    cli_fresh(OUT "list");
    cr_assert_eq(cli_run(OUT "list", "play fire_campfire --list-widgets"), 0);
    char *out = cli_slurp(OUT "list/stdout.txt");
    size_t len = strlen(out);
    char *list = malloc(len + 2);
    cr_assert_not_null(list);
    list[0] = '\n';
    memcpy(list + 1, out, len + 1);
    free(out);
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load(&d, "fire_campfire", &err), ISK_OK, "%s", err.message);
    int keys = 0;
    for (int s = 0; s < ISK_SECTION_COUNT; s++)
        for (int i = 0; i < isk_key_items(&d, (isk_section_kind)s); i++) {
            const char *name = isk_key_item_name(&d, (isk_section_kind)s, i);
            char token[80], id[128];
            snprintf(token, sizeof token, "%s%s%s", isk_section_name((isk_section_kind)s), *name ? "-" : "", name);
            snprintf(id, sizeof id, "section/%s", token);
            cr_expect(listed(list, id), "no %s", id);
            const int kind = isk_key_item_kind(&d, (isk_section_kind)s, i);
            for (int r = 0; r < isk_key_count(); r++) {
                const isk_key *k = isk_key_at(r);
                if ((int)k->section != s)
                    continue;
                snprintf(id, sizeof id, "%s/%s", token, k->name);
                const int live = isk_key_applies(k, kind) && !k->directive &&
                                 isk_key_when_set(k, kind) != ISK_KEY_WHEN_CREATED;
                cr_expect_eq(listed(list, id), live, "%s: %s", id, live ? "missing" : "shown, but not live");
                keys += live;
            }
        }
    cr_expect_gt(keys, 300);
    isk_effect_def_free(&d);
    free(list);
    /* the explosion thesis's scenes keep the console; --panel chooses */
    cr_assert_eq(cli_run(OUT "list", "play fig22_simulator_regular --list-widgets"), 0);
    out = cli_slurp(OUT "list/stdout.txt");
    cr_expect(strstr(out, "explosion-count\n") && !strstr(out, "section/"), "%s", out);
    free(out);
    cr_assert_eq(cli_run(OUT "list", "play fig22_simulator_regular --panel inspector --list-widgets"), 0);
    out = cli_slurp(OUT "list/stdout.txt");
    cr_expect(strstr(out, "section/emitter-particles\n") && strstr(out, "force-gravity/g\n"), "%s", out);
    free(out);
    cr_assert_eq(cli_run(OUT "list", "play fig22_simulator_regular --panel sideways --list-widgets"), 2);
}

/* ---- 5. names, saves ----------------------------------------------------------------------- */

Test(classroom, a_wrong_widget_name_gets_suggestions)
{
    cr_assert_eq(play_session(OUT "names", "fig22_simulator_regular --frames 5 --script 'press:explosions'"), 1);
    char *e = play_stderr(OUT "names");
    cr_expect(strstr(e, "no widget 'explosions'"), "%s", e);
    cr_expect(strstr(e, "did you mean 'explosion-count'?"), "%s", e);
    cr_expect(strstr(e, "--list-widgets"), "%s", e);
    free(e);
    cr_assert_eq(play_session(OUT "names", "fire_campfire --frames 5 --script 'press:colour_over_life'"), 1);
    e = play_stderr(OUT "names");
    cr_expect(strstr(e, "'emitter-flame/color_over_life'"), "%s", e);
    free(e);
    /* a key scrolled out of view is brought into view, then pressed */
    cr_assert_eq(play_session(OUT "names", "fire_campfire --frames 8 --script 'press:drawing-log2_core_b/radius'"), 0,
                 "%s", play_stderr(OUT "names"));
}

/* A save reloads to the same state: "add potential" is the console's
 * mode, not the scene's (it wrote [click] enabled = false), enums are
 * written by name (osc_table = true was floor's old spelling), and text
 * not given is not written (texture =). */
Test(classroom, a_save_reloads_to_the_same_state)
{
    cr_assert_eq(play_session(OUT "save",
                              "fig22_simulator_regular --ui-scale 1 --frames 20 --save " OUT "save/s.ini --script "
                              "'press:click/add-potential wait:2 click:300,300 wait:2 f2'"),
                 0, "%s", play_stderr(OUT "save"));
    char *text = cli_slurp(OUT "save/s.ini");
    cr_expect_null(strstr(text, "osc_table = true"));
    cr_expect_null(strstr(text, "texture =\n"));
    cr_expect_null(strstr(text, "texture = \n"));
    const char *click = strstr(text, "\n[click]\n");
    cr_assert_not_null(click);
    cr_expect(strstr(click, "\nenabled = true\n") && strstr(click, "\nexplosion = ring\n"), "%s", click);
    cr_expect(strstr(text, "\n[force P1]\nkind = potential\n"), "%s", text);
    /* load it and write it again: the same text */
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load_file(&d, OUT "save/s.ini", &err), ISK_OK, "%s", err.message);
    char *again;
    cr_assert_eq(isk_scene_write(&d, &again, &err), ISK_OK, "%s", err.message);
    cr_expect_str_eq(again, text);
    free(again);
    isk_effect_def_free(&d);
    free(text);
}

/* ---- 6. the help -------------------------------------------------------------------------- */

/* Every option the help explains is in its usage lines (--shots,
 * --threads and --max-memory were not). */
Test(classroom, the_usage_line_names_every_option)
{
    cli_fresh(OUT "help");
    cr_assert_eq(cli_run(OUT "help", "play --help"), 0);
    char *help = cli_slurp(OUT "help/stdout.txt");
    const char *body = strstr(help, "\n  Runs ");
    cr_assert_not_null(body, "%s", help);
    const size_t usage_len = (size_t)(body - help);
    int options = 0;
    for (const char *p = body; (p = strstr(p, "--")) != NULL; p += 2) {
        if (p[2] < 'a' || p[2] > 'z')
            continue;
        char opt[40], form[60];
        size_t n = strspn(p, "-abcdefghijklmnopqrstuvwxyz");
        snprintf(opt, sizeof opt, "[%.*s", (int)n, p);
        snprintf(form, sizeof form, "iskra play %.*s ", (int)n, p); /* a usage line of its own: --replay */
        char *found = strstr(help, opt), *own = strstr(help, form);
        cr_expect((found && (size_t)(found - help) < usage_len) || (own && (size_t)(own - help) < usage_len),
                  "the usage lines do not name %s", opt + 1);
        options++;
    }
    cr_expect_geq(options, 20);
    free(help);
}

/* docs/scene-format.md's section on the `iskra` command names play's keys
 * as the tool has them (it listed an old set). */
Test(classroom, the_scene_format_page_names_play_s_keys)
{
    cli_fresh(OUT "keys");
    cr_assert_eq(cli_run(OUT "keys", "play --help"), 0);
    char *help = cli_slurp(OUT "keys/stdout.txt"), *doc = cli_slurp("docs/scene-format.md");
    char *section = strstr(doc, "\n## The `iskra` command");
    cr_assert_not_null(section);
    char *end = strstr(section + 1, "\n## ");
    if (end)
        *end = 0;
    char *from = strstr(help, "\n  keys ("), *to = strstr(help, "\n  --frames");
    cr_assert(from && to && from < to, "%s", help);
    from = strchr(from + 1, '\n');
    *to = 0;
    int named = 0;
    for (char *item = strtok(from, ";\n"); item; item = strtok(NULL, ";\n")) {
        char key[16];
        if (sscanf(item, " %15s", key) != 1 || strlen(key) < 2 || !strcmp(key, "1-7"))
            continue; /* single letters and signs: too common to look for */
        cr_expect(strstr(section, key), "docs/scene-format.md's `iskra` section does not name %s", key);
        named++;
    }
    cr_expect_geq(named, 6);
    free(help);
    free(doc);
}
