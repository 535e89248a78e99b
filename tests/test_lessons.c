/* SPDX-License-Identifier: MIT */
/* Recorded lessons (tools/iskra/lesson.h): `iskra play --record` writes a
 * session's input frame by frame, `iskra play --replay` shows it again and
 * `iskra replay --check` turns it into a pixel-exact test.
 *
 * tests/lessons/fig22.txt is the figure 22 lesson (click modes, gravity,
 * drag, walls, a potential added and dragged), recorded by
 * tests/lessons/record_fig22.sh, with its four checkpoints in
 * tests/lessons/fig22/.  Checked here: it replays to its references; one
 * value changed in it (a typed gravity, one coordinate of the drag) makes
 * the check fail at the right checkpoint; a recording replays, in the
 * window and headless, to the bytes the recorded session showed; bad
 * lesson lines are named FILE:LINE; a reference is written only with
 * --update; a recording never replaces the scene. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/png.h"
#include "play_session.h"
#include "tool_cli.h"

#define OUT "out/test_lessons/"
#define LESSON "tests/lessons/fig22.txt"
#define REFS "tests/lessons/fig22"

/* Both PNGs read, and their pixels are the same. */
static int same_pixels(const char *a, const char *b)
{
    isk_canvas x, y;
    isk_error err;
    cr_assert_eq(isk_png_read(&x, a, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_png_read(&y, b, &err), ISK_OK, "%s", err.message);
    int same = isk_canvas_equal(&x, &y);
    isk_canvas_free(&x);
    isk_canvas_free(&y);
    return same;
}

/* The fig22 lesson with the first `from` replaced by `to`, written to path. */
static void changed_lesson(const char *path, const char *from, const char *to)
{
    char *text = cli_slurp(LESSON);
    char *at = strstr(text, from);
    cr_assert_not_null(at, "the lesson has no '%s'", from);
    size_t n = strlen(text) + strlen(to) + 1;
    char *out = malloc(n);
    cr_assert_not_null(out);
    snprintf(out, n, "%.*s%s%s", (int)(at - text), text, to, at + strlen(from));
    cli_write_file(path, out);
    free(out);
    free(text);
}

Test(lessons, the_fig22_lesson_replays_to_its_references, .timeout = 120)
{
    cli_fresh(OUT "check");
    int rc = cli_run(OUT "check", "replay " LESSON " --check " REFS " --actual " OUT "check/actual");
    char *out = cli_slurp(OUT "check/stdout.txt"), *err = cli_slurp(OUT "check/stderr.txt");
    cr_assert_eq(rc, 0, "%s%s", out, err);
    cr_expect(strstr(out, "260 frames, 4 shots the same"), "%s", out);
    for (int i = 1; i <= 4; i++) {
        char want[128];
        snprintf(want, sizeof want, "checkpoint-%d: same pixels as " REFS "/checkpoint-%d.png", i, i);
        cr_expect(strstr(out, want), "%s", out);
    }
    cr_expect_not(cli_exists(OUT "check/actual"), "nothing differed, yet something was written");
    free(out);
    free(err);
}

/* The gravity typed into the console, 5, becomes 6: the first checkpoint
 * (and every later one) differs, the references stay as they were. */
Test(lessons, one_changed_gravity_value_fails_the_check, .timeout = 120)
{
    cli_fresh(OUT "gravity");
    changed_lesson(OUT "gravity/fig22.txt", "type:5 ", "type:6 ");
    char *before = cli_slurp(REFS "/checkpoint-1.png");
    int rc = cli_run(OUT "gravity", "replay " OUT "gravity/fig22.txt --check " REFS " --actual " OUT "gravity/actual");
    char *err = cli_slurp(OUT "gravity/stderr.txt");
    cr_assert_eq(rc, 1, "%s", err);
    cr_expect(strstr(err, "shot checkpoint-1 after frame 105 differs from " REFS "/checkpoint-1.png"), "%s", err);
    cr_expect(strstr(err, "pixels differ, the first at ("), "%s", err);
    cr_expect(strstr(err, "4 of the lesson's shots do not match"), "%s", err);
    cr_expect(cli_exists(OUT "gravity/actual/checkpoint-1.actual.png"));
    cr_expect(cli_exists(OUT "gravity/actual/checkpoint-1.diff.png"));
    char *after = cli_slurp(REFS "/checkpoint-1.png");
    cr_expect_eq(strcmp(before, after), 0);
    cr_expect_eq(cli_count_files(REFS, "actual"), 0, "an actual image beside the references");
    free(before);
    free(after);
    free(err);
}

/* One pointer position of the potential's drag moves by a pixel: the two
 * checkpoints before it still match, the one after it does not. */
Test(lessons, one_changed_drag_coordinate_fails_the_check, .timeout = 120)
{
    cli_fresh(OUT "drag");
    changed_lesson(OUT "drag/fig22.txt", "up:360,320", "up:361,320");
    int rc = cli_run(OUT "drag", "replay " OUT "drag/fig22.txt --check " REFS " --actual " OUT "drag/actual");
    char *out = cli_slurp(OUT "drag/stdout.txt"), *err = cli_slurp(OUT "drag/stderr.txt");
    cr_assert_eq(rc, 1, "%s%s", out, err);
    cr_expect(strstr(out, "checkpoint-1: same pixels"), "%s", out);
    cr_expect(strstr(out, "checkpoint-2: same pixels"), "%s", out);
    cr_expect(strstr(err, "shot checkpoint-3 after frame 196 differs"), "%s", err);
    cr_expect_not(strstr(err, "shot checkpoint-1 "), "%s", err);
    free(out);
    free(err);
}

/* A session recorded while it runs (driven by a script through the
 * window's queue, as a user's input arrives) replays to the same window
 * bytes: in the window (--replay --shots) and headless (replay --update
 * writes what it saw). */
Test(lessons, a_recording_replays_to_the_same_window_bytes, .timeout = 120)
{
    cli_fresh(OUT "rec");
    int rc = cli_run(OUT "rec",
                     "play fig22_simulator_regular --screen 1280x720 --fixed-clock --frames 80 --record " OUT
                     "rec/lesson.txt --script 'wait:5 press:click/uniform wait:2 click:250,280 wait:10 "
                     "press:gravity wait:2 key:backspace type:3 key:return press:wall-top wait:4 "
                     "press:click/add-potential wait:2 click:300,300 wait:2 press:pot-k wait:2 type:20 key:return "
                     "wait:2 down:300,300 wait:1 move:330,310 wait:2 move:350,330 wait:1 up:350,330 wait:6 "
                     "wheel:1 wait:3 shot:" OUT "rec/recorded.png f9 wait:2'");
    cr_assert_eq(rc, 0, "%s", cli_slurp(OUT "rec/stderr.txt"));
    char *les = cli_slurp(OUT "rec/lesson.txt");
    cr_expect(strstr(les, "\nplay: fig22_simulator_regular --screen 1280x720\n"), "%s", les);
    cr_expect(strstr(les, " type:3 keydown:return"), "%s", les);
    cr_expect(strstr(les, " wheel:1"), "%s", les);
    cr_expect(strstr(les, " shot:checkpoint-1\n"), "%s", les);
    cr_expect(strstr(les, "frame:80 quit\n"), "%s", les);
    cr_expect_not(strstr(les, "f9"), "the checkpoint key is not an input: %s", les);
    free(les);

    rc = cli_run(OUT "rec", "replay " OUT "rec/lesson.txt --check " OUT "rec/refs --update");
    cr_assert_eq(rc, 0, "%s", cli_slurp(OUT "rec/stderr.txt"));
    cr_expect(same_pixels(OUT "rec/recorded.png", OUT "rec/refs/checkpoint-1.png"),
              "the headless replay's window is not the recorded session's");
    rc = cli_run(OUT "rec", "play --replay " OUT "rec/lesson.txt --fixed-clock --shots " OUT "rec/shots");
    cr_assert_eq(rc, 0, "%s", cli_slurp(OUT "rec/stderr.txt"));
    cr_expect(same_pixels(OUT "rec/recorded.png", OUT "rec/shots/checkpoint-1.png"),
              "the window's replay is not the recorded session's");
    rc = cli_run(OUT "rec", "replay " OUT "rec/lesson.txt --check " OUT "rec/refs");
    cr_expect_eq(rc, 0, "%s", cli_slurp(OUT "rec/stderr.txt"));
}

/* A bad line of a lesson: FILE:LINE and why, exit 2, for both commands. */
static void refused(const char *name, const char *text, const char *want)
{
    char dir[128], path[160], args[500];
    snprintf(dir, sizeof dir, OUT "bad-%s", name);
    cli_fresh(dir);
    snprintf(path, sizeof path, "%s/lesson.txt", dir);
    cli_write_file(path, text);
    const char *forms[] = {"replay %s --check %s/refs", "play --replay %s --shots %s/shots"};
    for (int i = 0; i < 2; i++) {
        snprintf(args, sizeof args, forms[i], path, dir);
        int rc = cli_run(dir, args);
        char *err = play_stderr(dir);
        char msg[400];
        snprintf(msg, sizeof msg, "%s:%s", path, want);
        cr_expect_eq(rc, 2, "%s: %s", args, err);
        cr_expect(strstr(err, msg), "%s: wanted \"%s\" in: %s", args, msg, err);
        free(err);
    }
    cr_expect_eq(cli_count_files(dir, "refs\\|shots"), 0, "%s: something was written", name);
}

Test(lessons, bad_lesson_lines_are_named_by_file_and_line, .timeout = 60)
{
    refused("token", "play: fig22_simulator_regular\nframe:3 move:1,1\nframe:4 jump:2\n", "3: unknown event 'jump:2'");
    refused("backwards", "# c\nplay: fig22_simulator_regular\nframe:5 move:1,1\nframe:3 move:2,2\n",
            "4: frame:3 comes after frame:5 (line 3)");
    refused("no-play", "# nothing\nframe:1 move:1,1\n", "2: expected the line 'play: SCENE [OPTIONS]'");
    refused("record", "play: fig22_simulator_regular --record x.txt\n", "1: a lesson's play: line cannot have --record");
    refused("shot-path", "play: fig22_simulator_regular\nframe:1 shot:../x\n", "2: unknown event 'shot:../x'");
    refused("escape", "play: fig22_simulator_regular\nframe:1 type:a%2\n", "2: unknown event 'type:a%2'");
    refused("button", "play: fig22_simulator_regular\n\nframe:1 down:1,2,3\n", "3: unknown event 'down:1,2,3'");
    refused("option", "play: fig22_simulator_regular --seed x\n", "1: in the play: line");
}

/* Without --update a missing reference is a failure that writes only the
 * actual image, in --actual; --update writes it; then the check passes. */
Test(lessons, a_reference_is_written_only_with_update, .timeout = 60)
{
    cli_fresh(OUT "update");
    cli_write_file(OUT "update/l.txt", "play: fig22_simulator_regular --screen 1280x720\n"
                                       "frame:3 move:300,300 down:300,300 up:300,300\n"
                                       "frame:9 shot:after-click canvas-shot:canvas\n");
    int rc = cli_run(OUT "update", "replay " OUT "update/l.txt --check " OUT "update/refs --actual " OUT "update/a");
    cr_expect_eq(rc, 1);
    cr_expect_not(cli_exists(OUT "update/refs"), "a reference was written without --update");
    cr_expect(cli_exists(OUT "update/a/after-click.actual.png"));
    rc = cli_run(OUT "update", "replay " OUT "update/l.txt --check " OUT "update/refs --update");
    cr_assert_eq(rc, 0, "%s", play_stderr(OUT "update"));
    isk_canvas c;
    play_read_png(OUT "update/refs/canvas.png", &c);
    cr_expect_eq(c.width, 600, "canvas-shot: the canvas alone");
    isk_canvas_free(&c);
    rc = cli_run(OUT "update", "replay " OUT "update/l.txt --check " OUT "update/refs");
    cr_expect_eq(rc, 0, "%s", play_stderr(OUT "update"));
    /* the same directory for the references and the actual images: refused */
    rc = cli_run(OUT "update", "replay " OUT "update/l.txt --check " OUT "update/refs --actual " OUT "update/refs");
    cr_expect_eq(rc, 2);
}

Test(lessons, a_recording_never_replaces_the_scene, .timeout = 60)
{
    cli_fresh(OUT "input");
    cli_write_file(OUT "input/s.ini", PLAY_SOUND_SCENE);
    int rc = cli_run(OUT "input", "play " OUT "input/s.ini --fixed-clock --frames 3 --record " OUT "input/s.ini");
    cr_expect_eq(rc, 2);
    char *err = play_stderr(OUT "input"), *text = cli_slurp(OUT "input/s.ini");
    cr_expect(strstr(err, "refusing to overwrite the input"), "%s", err);
    cr_expect_str_eq(text, PLAY_SOUND_SCENE);
    free(err);
    free(text);
    /* nor the lesson its replay's shots */
    cli_write_file(OUT "input/x.png", "play: fig22_simulator_regular\nframe:2 shot:x\nframe:3 quit\n");
    rc = cli_run(OUT "input", "play --replay " OUT "input/x.png --fixed-clock --shots " OUT "input");
    err = play_stderr(OUT "input");
    cr_expect(strstr(err, "refusing to overwrite"), "%s", err);
    text = cli_slurp(OUT "input/x.png");
    cr_expect(!strncmp(text, "play:", 5), "the lesson was replaced");
    free(err);
    free(text);
}

/* An event that cannot be played (a widget the window does not have) stops
 * the replay with the message and the lesson's line: exit 1. */
Test(lessons, an_event_that_fails_names_its_line, .timeout = 60)
{
    cli_fresh(OUT "fails");
    cli_write_file(OUT "fails/l.txt", "play: fig22_simulator_regular\n# a comment\nframe:2 press:wind\n"
                                      "frame:5 shot:never\n");
    int rc = cli_run(OUT "fails", "replay " OUT "fails/l.txt --check " OUT "fails/refs --update");
    char *err = play_stderr(OUT "fails");
    cr_expect_eq(rc, 1, "%s", err);
    cr_expect(strstr(err, "no widget 'wind'"), "%s", err);
    cr_expect(strstr(err, OUT "fails/l.txt:3: 'press:wind' failed"), "%s", err);
    cr_expect_not(cli_exists(OUT "fails/refs"), "a reference was written after the failure");
    free(err);
}
