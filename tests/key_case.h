/* SPDX-License-Identifier: MIT */
/* tests/key_case.h — what every emitter key owes, checked in one line each:
 * with it the bytes differ, at its default (or without it) they are
 * today's, and a bad value names FILE:LINE and exits 2.
 *
 * A case is a scene text with one "%s" where the key line goes (inside the
 * section the key belongs to), and the frames to run:
 *
 *     static const char *base = "[scene]\nwidth = 64\nheight = 48\n"
 *                               "[emitter e]\nsource = stream\nrate = 200\n%s\n";
 *     key_case_differs(base, "spin = 90", 30);          // renders differ
 *     key_case_same(base, "spin = 0", 30);              // renders equal
 *     key_case_rejects(base, "spin = fast", "spin");    // "case.ini:7: ... spin ...", CLI exit 2
 *
 * The render is the effect's canvas after `frames` steps (ISK_OK asserted
 * at every step).  key_case_render gives it to a test that wants to look
 * further (free it). */
#ifndef ISKRA_TESTS_KEY_CASE_H
#define ISKRA_TESTS_KEY_CASE_H

#include "iskra/canvas.h"

/* The scene `base` with `line` in place of its "%s", parsed (asserted),
 * created, stepped `frames` times and rendered. */
isk_canvas key_case_render(const char *base, const char *line, int frames);

/* 1 when both canvases have the same size and bytes. */
int key_case_equal(const isk_canvas *a, const isk_canvas *b);

/* Asserts the render with `line` differs from the render with nothing. */
void key_case_differs(const char *base, const char *line, int frames);

/* Asserts the render with `line` equals the render with nothing. */
void key_case_same(const char *base, const char *line, int frames);

/* Asserts that the scene with `line` is refused with a message starting
 * "case.ini:L: " (L: the line `line` is on) that contains `fragment`, and
 * that `iskra describe` of the same scene as a file exits 2 with that
 * message on stderr. */
void key_case_rejects(const char *base, const char *line, const char *fragment);

#endif
