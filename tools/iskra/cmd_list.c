/* SPDX-License-Identifier: MIT */
/* iskra list — the built-in scenes, one per line with the first sentence
 * of the scene's leading comment (its own description, so there is no
 * second copy to keep in step); --names prints the bare names. */
#include <stdio.h>
#include <string.h>

#include "cmd.h"
#include "iskra/scene.h"

#define LINE_MAX_COLS 100

/* The first sentence of the comment block at the top of a scene text:
 * its first paragraph (comment lines, ';' or '#', up to a blank one) with
 * runs of blanks made single spaces, cut after the first ". ".  Clipped to
 * fit `max` bytes (NUL included) at a word boundary, marked "...". */
static void describe(const char *text, char *out, size_t max)
{
    char para[2048];
    size_t n = 0;
    const char *p = text ? text : "";
    while (*p == '\n' || *p == '\r')
        p++;
    while (*p == ';' || *p == '#') {
        const char *q = p + 1;
        while (*q == ' ' || *q == '\t')
            q++;
        if (*q == '\n' || *q == '\r' || !*q)
            break; /* blank comment line: end of the paragraph */
        for (; *q && *q != '\n'; q++) {
            char c = (*q == '\t' || *q == '\r') ? ' ' : *q;
            if (n + 2 < sizeof para && !(c == ' ' && (n == 0 || para[n - 1] == ' ')))
                para[n++] = c;
        }
        if (n > 0 && para[n - 1] != ' ' && n + 2 < sizeof para)
            para[n++] = ' ';
        p = *q ? q + 1 : q;
    }
    para[n] = 0;
    char *stop = strstr(para, ". ");
    if (stop)
        stop[1] = 0;
    n = strlen(para);
    while (n > 0 && para[n - 1] == ' ')
        para[--n] = 0;
    if (n < max) {
        memcpy(out, para, n + 1);
        return;
    }
    size_t cut = max - 4; /* room for "..." and the NUL */
    while (cut > 0 && para[cut] != ' ')
        cut--;
    if (cut == 0)
        cut = max - 4;
    memcpy(out, para, cut);
    memcpy(out + cut, "...", 4);
}

int cmd_list(int argc, char **argv)
{
    int names_only = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            printf("usage: iskra list [--names]\n"
                   "  Prints the built-in scenes (the shipped scenes/*.ini), one per line with\n"
                   "  the first sentence of the scene's leading comment.  Any of them can be\n"
                   "  given as SCENE to describe, render and play.\n"
                   "  --names  the names only, one per line (for scripts)\n");
            return 0;
        }
        if (!strcmp(argv[i], "--names")) {
            names_only = 1;
            continue;
        }
        fprintf(stderr, "iskra list: unexpected argument '%s' (iskra list --help)\n", argv[i]);
        return 2;
    }
    int width = 0;
    for (int i = 0; i < isk_scene_builtin_count(); i++) {
        int n = (int)strlen(isk_scene_builtin_name(i));
        width = n > width ? n : width;
    }
    for (int i = 0; i < isk_scene_builtin_count(); i++) {
        const char *name = isk_scene_builtin_name(i);
        if (names_only) {
            printf("%s\n", name);
            continue;
        }
        char about[LINE_MAX_COLS + 1];
        int room = LINE_MAX_COLS - width - 2;
        describe(isk_scene_builtin_text(name), about, room > 16 ? (size_t)room + 1 : 17);
        printf("%-*s  %s\n", width, name, about);
    }
    return 0;
}
