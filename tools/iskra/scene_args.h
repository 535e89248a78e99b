/* SPDX-License-Identifier: MIT */
/* Options shared by the scene commands (describe, render, play): the scene
 * argument, the overrides --seed, --size WxH, --dt, --substeps, and loading
 * + compiling the scene with messages on stderr. */
#ifndef ISKRA_TOOL_SCENE_ARGS_H
#define ISKRA_TOOL_SCENE_ARGS_H

#include <stdint.h>
#include <stdio.h>

#include "iskra/effect.h"

typedef struct scene_args {
    const char *cmd;      /* "render", for messages */
    const char *scene;    /* path or built-in name; with `text`, the name its messages give */
    const char *text;     /* the scene's text itself (the web page's editor), or NULL: read `scene` */
    int have_seed;
    uint64_t seed;
    int width, height;    /* 0: the scene's */
    double dt;            /* 0: the scene's */
    int substeps;         /* 0: the scene's */
    size_t max_memory;    /* 0: the library's default budget */
    double max_work;      /* 0: the library's default budget */
    /* What the command itself needs beside the effect (its encoders, a
     * strip), once the definition is known with the overrides applied: sets
     * def->host_memory and def->host_memory_for before the effect is
     * created, so the budget counts it.  NULL: nothing. */
    void (*host_needs)(isk_effect_def *def, const void *ctx);
    const void *host_ctx;
    int threads;          /* 0: ISKRA_THREADS, else every core */
} scene_args;

/* The value of option argv[*i] ("--opt VALUE" or "--opt=VALUE") if its name
 * is `name`: returns 1 and sets *value (advancing *i), 0 if argv[*i] is
 * another option, -1 (message printed) if the value is missing. */
int arg_value(const char *cmd, int argc, char **argv, int *i, const char *name, const char **value);

/* Strict parsers for option values; print "iskra CMD: --opt: ..." and
 * return 0 on error. */
int arg_long(const char *cmd, const char *opt, const char *s, long lo, long hi, long *out);
int arg_double_pos(const char *cmd, const char *opt, const char *s, double *out);

/* Handles argv[*i] if it is a scene override or the scene argument: 1 used,
 * 0 not ours, -1 error (printed, exit 2). */
int scene_args_take(scene_args *a, int argc, char **argv, int *i);

/* Help text for the overrides. */
void scene_args_help(FILE *f);

/* Loads the scene (file or built-in), applies the overrides and creates the
 * effect.  Returns 0, or the exit status (2: scene or usage error, 1:
 * runtime failure) after printing why.  On success *def holds the
 * (overridden) definition: free it with isk_effect_def_free. */
int scene_args_open(const scene_args *a, isk_effect_def *def, isk_effect **fx);
/* The same, printing nothing: the message ("FILE:LINE: why" for a scene
 * error) goes into why (n bytes), for a program that shows it itself. */
int scene_args_load(const scene_args *a, isk_effect_def *def, isk_effect **fx, char *why, size_t n);

#endif
