/* SPDX-License-Identifier: MIT */
/* What `iskra play` (cmd_play.c) and `iskra replay` (cmd_replay.c) share:
 * play's options, opening a scene into a player, and a lesson's play:
 * line read as play's options.
 *
 *     static player p;                       // large: not on the stack
 *     play_opts o;
 *     int rc = play_cli_options(&p, &o, argc, argv, NULL);   // or play_cli_lesson
 *     if (!rc) rc = play_cli_open(&p, &o, &plan, NULL);
 *     ...frames...
 *     play_cli_close(&p);
 *
 * Not part of the web build (web/iskra_web.c opens its scenes itself). */
#ifndef ISKRA_TOOL_PLAY_CLI_H
#define ISKRA_TOOL_PLAY_CLI_H

#include "lesson.h"
#include "outpath.h"
#include "play.h"

/* A lesson without --screen is laid out for this screen (a classroom's). */
enum { PLAY_LESSON_SCREEN_W = 1366, PLAY_LESSON_SCREEN_H = 768 };

typedef struct play_opts {
    long max_frames, ui_scale;
    const char *script, *panel_kind;
    const char *record;        /* --record LESSON */
    const char *replay;        /* --replay LESSON */
    int no_panel, list, screen_given, fixed_clock;
} play_opts;

/* iskra play's help text. */
void play_cli_help(FILE *f);
/* Reads play's options from argv[1..] into p and o.  skip (argc entries,
 * or NULL) gets 1 for each argument a lesson does not repeat (--record,
 * --script, --frames, --fixed-clock and their values).  0; -1 after
 * --help (printed); or the exit status after a message. */
int play_cli_options(player *p, play_opts *o, int argc, char **argv, int *skip);
/* Reads the lesson at path (lesson_load) and its play: line as play's
 * options into p and o (what a lesson may not hold, such as --record, is
 * refused), and its events into p->script.  0, or the exit status after
 * "FILE:LINE: message". */
int play_cli_lesson(player *p, play_opts *o, lesson *l, const char *path);
/* Opens the scene of p->args: refuses plan's outputs over the scene, its
 * textures and `lesson` (may be NULL), checks --follow, draws the first
 * canvas, sets up the panel.  0, or the exit status after a message
 * (p is then closed). */
int play_cli_open(player *p, const play_opts *o, outpath_plan *plan, const char *lesson);
/* Frees what play_cli_open and the frames made (p->shown is the caller's). */
void play_cli_close(player *p);

#endif
