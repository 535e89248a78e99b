/* SPDX-License-Identifier: MIT */
/* The `iskra` command line: dispatches to one sub-command per file. */
#include <stdio.h>
#include <string.h>

#include "cmd.h"
#include "iskra/version.h"

static const isk_command commands[] = {
    {"list", "list the built-in scenes, each with its description", cmd_list},
    {"describe", "print the pipeline a scene compiles to", cmd_describe},
    {"keys", "every key of a scene file: type, default, range, meaning", cmd_keys},
    {"render", "render a scene to PNG, a PNG sequence, GIF, Y4M or raw frames", cmd_render},
    {"play", "run a scene in a window in real time", cmd_play},
    {"replay", "check a recorded lesson against reference images, headless", cmd_replay},
    {"compare", "compare two PNG images pixel by pixel", cmd_compare},
    {"bench", "measure what accuracy costs in time (bench accuracy)", cmd_bench},
};

static void usage(FILE *f)
{
    fprintf(f, "usage: iskra COMMAND [ARGS]   (iskra COMMAND --help for details)\n\ncommands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        fprintf(f, "  %-10s %s\n", commands[i].name, commands[i].summary);
    fprintf(f, "\n  --version  print the version\n  --help     this text\n");
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        usage(stdout);
        return 0;
    }
    if (!strcmp(argv[1], "--version")) {
        printf("iskra %s\n", ISKRA_VERSION_STRING);
        return 0;
    }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (!strcmp(argv[1], commands[i].name))
            return commands[i].run(argc - 1, argv + 1);
    fprintf(stderr, "iskra: unknown command '%s'\n", argv[1]);
    usage(stderr);
    return 2;
}
