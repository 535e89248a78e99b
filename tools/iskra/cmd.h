/* SPDX-License-Identifier: MIT */
/* Sub-commands of the `iskra` tool.  Each takes (argc, argv) with argv[0] =
 * the command name and returns the process exit status:
 * 0 success, 1 runtime failure, 2 usage error (compare, as cmp(1): 0 the
 * same, 1 different, 2 unreadable or a usage error). */
#ifndef ISKRA_TOOL_CMD_H
#define ISKRA_TOOL_CMD_H


typedef struct isk_command {
    const char *name;
    const char *summary;
    int (*run)(int argc, char **argv);
} isk_command;

int cmd_compare(int argc, char **argv);
int cmd_list(int argc, char **argv);
int cmd_describe(int argc, char **argv);
int cmd_render(int argc, char **argv);
int cmd_play(int argc, char **argv);
int cmd_replay(int argc, char **argv);
int cmd_bench(int argc, char **argv);
int cmd_keys(int argc, char **argv);

#endif
