/* iskra list — the built-in scenes, one name per line. */
#include <stdio.h>
#include <string.h>

#include "cmd.h"
#include "iskra/scene.h"

int cmd_list(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            printf("usage: iskra list\n"
                   "  Prints the built-in scenes (the shipped scenes/*.ini), one name per line.\n"
                   "  Any of them can be given as SCENE to describe, render and play.\n");
            return 0;
        }
        fprintf(stderr, "iskra list: unexpected argument '%s' (iskra list --help)\n", argv[i]);
        return 2;
    }
    for (int i = 0; i < isk_scene_builtin_count(); i++)
        printf("%s\n", isk_scene_builtin_name(i));
    return 0;
}
