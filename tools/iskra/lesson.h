/* SPDX-License-Identifier: MIT */
/* Recorded lessons: `iskra play --record LESSON.txt` writes a session's
 * input, `iskra play --replay LESSON.txt` shows it again, and `iskra
 * replay LESSON.txt --check DIR` compares its checkpoints with reference
 * PNGs.  A lesson file is the session's command line and its input, frame
 * by frame, in the --script format (play_script.c):
 *
 *     # iskra lesson (iskra play --replay FILE shows it)
 *     play: fig22_simulator_regular --screen 1366x768
 *     frame:12 move:300,200
 *     frame:14 down:300,200
 *     frame:15 up:300,200
 *     frame:40 shot:checkpoint-1
 *     frame:300 quit
 *
 * The `play:` line (the first that is not a comment) gives the arguments
 * of `iskra play`: the scene and its options.  Every later token is an
 * event; frame:N means "after N shown frames", so what follows reaches the
 * simulator with frame N + 1, as the recorded input did.  A session is
 * recorded and replayed at one simulation step per shown frame (the fixed
 * clock), so the same lesson gives the same pixels every time.
 *
 * The recorder keeps the lesson in memory and writes it whole through
 * iskra/outfile.h (a temporary renamed over the file) at every checkpoint,
 * every LESSON_SAVE_FRAMES frames and when the session ends, each time
 * ending with `frame:N quit` for the frames so far: the file on disk is
 * always a complete lesson, even after a crash. */
#ifndef ISKRA_TOOL_LESSON_H
#define ISKRA_TOOL_LESSON_H

#include <stddef.h>

#include "iskra/sdl.h"

#define LESSON_SAVE_FRAMES 600        /* about ten seconds at 60 frames a second */
#define LESSON_CHECKPOINT_KEY ISK_KEY_F9 /* while recording: a checkpoint (shot:checkpoint-N) */
#define LESSON_MAX_ARGS 64

/* A lesson file as read. */
typedef struct lesson {
    char *text;                /* the file, owned */
    char *args_copy;           /* the play: line's arguments, cut into argv */
    char *argv[LESSON_MAX_ARGS + 1]; /* "play", then the arguments */
    int argc;
    int args_line;             /* the play: line's number */
    const char *events;        /* the text after the play: line */
    int events_line;           /* its first line's number */
} lesson;

/* Reads `path`; 0, or 2 after "FILE:LINE: message" (1: cannot read it). */
int lesson_load(lesson *l, const char *path);
void lesson_free(lesson *l);

/* A session being recorded. */
typedef struct lesson_recorder {
    const char *path;
    char *buf;                 /* the lesson so far, without its final quit */
    size_t len, cap;
    int checkpoints;           /* shot:checkpoint-N written so far */
    long saved_frame;          /* the frames shown at the last write */
    int failed;                /* the last write failed (said on stderr) */
} lesson_recorder;

/* Starts a lesson: the header and the play: line from the arguments of
 * `iskra play` (argv[1..argc-1]) without skip[i] (--record and its value,
 * --script ...), then `--screen WxH` when they do not give one.  Writes
 * the file once, so a path that cannot be written is found at once.  0,
 * or 2 (an argument a lesson cannot hold) / 1 (cannot write) after a
 * message. */
int lesson_record_begin(lesson_recorder *r, const char *path, int argc, char **argv, const int *skip,
                        int screen_w, int screen_h, int screen_given);
/* The events that reached the simulator after `frame` shown frames, as one
 * line; the checkpoint key's presses become shot:checkpoint-N and are taken
 * out of ev (*nev shrinks).  Writes the file at a checkpoint and every
 * LESSON_SAVE_FRAMES frames. */
void lesson_record_frame(lesson_recorder *r, long frame, isk_event *ev, int *nev);
/* Writes the lesson, ending after `frames` shown frames; 0, or 1 after a message. */
int lesson_record_save(lesson_recorder *r, long frames);
void lesson_record_free(lesson_recorder *r);

#endif
