/* SPDX-License-Identifier: MIT */
/* tests/play_session.h — scripted `iskra play` sessions for the
 * simulator's tests (header-only; include it after
 * <criterion/criterion.h>).
 *
 *     #define OUT "out/test_x/"
 *     cr_assert_eq(play_session(OUT "case", "fig22_simulator_regular --frames 3 --script 'wait:1 shot:" OUT
 *                               "case/w.png'"),
 *                  0, "%s", play_stderr(OUT "case"));
 *     isk_canvas c;
 *     play_read_png(OUT "case/w.png", &c);   // isk_canvas_free it
 *
 * play_session runs `iskra play --fixed-clock ARGS` (one step a frame, so
 * a script gives the same pixels every time) under SDL's dummy driver in
 * a fresh directory, which gets its stdout.txt and stderr.txt, and
 * returns the exit status (tests/tool_cli.h runs it).  Give each test its
 * own directory: Criterion runs tests in parallel. */
#ifndef ISKRA_TESTS_PLAY_SESSION_H
#define ISKRA_TESTS_PLAY_SESSION_H

#include <stdio.h>
#include <time.h>

#include "iskra/png.h"
#include "tool_cli.h"

static inline int play_session(const char *dir, const char *args)
{
    char a[4000];
    cli_fresh(dir);
    snprintf(a, sizeof a, "play --fixed-clock %s", args);
    return cli_run(dir, a);
}

/* What the last session in dir wrote on stderr (free it). */
static inline char *play_stderr(const char *dir)
{
    char p[256];
    snprintf(p, sizeof p, "%s/stderr.txt", dir);
    return cli_slurp(p);
}

/* A screenshot the session wrote (asserts it reads). */
static inline void play_read_png(const char *path, isk_canvas *c)
{
    isk_error err;
    cr_assert_eq(isk_png_read(c, path, &err), ISK_OK, "%s", err.message);
}

/* A scene in sound fidelity (a value out of range is refused, where the
 * thesis's scenes replace it) with gravity, drag, a floor and a click: for
 * the tests of how the panel refuses a value. */
#define PLAY_SOUND_SCENE                                                                                               \
    "[scene]\nseed = 3\n[view]\nxmin = 0\nxmax = 10\nymin = 0\nymax = 10\n[force gravity]\ng = 9.81\n"                 \
    "[force drag]\nb = 0.1\n[bounds]\nsides = bottom\n[emitter p]\nsource = layer\ncount = 200\n"                      \
    "rect = 0, 10, 0, 2\nforces = gravity, drag\n[click]\nexplosion = gauss\ncount = 300\nemitter = p\n"

/* For sessions in real time, which run in the background. */
static inline void play_sleep_ms(long ms)
{
    struct timespec t = {ms / 1000, (ms % 1000) * 1000000L};
    nanosleep(&t, NULL);
}

#endif
