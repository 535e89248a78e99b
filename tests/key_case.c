/* SPDX-License-Identifier: MIT */
/* What every emitter key owes (tests/key_case.h). */
#include "key_case.h"

#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "tool_cli.h"

static char *scene_text(const char *base, const char *line)
{
    const char *hole = strstr(base, "%s");
    cr_assert_not_null(hole, "a key case's scene has no %%s");
    size_t n = strlen(base) + strlen(line) + 1;
    char *t = malloc(n);
    cr_assert_not_null(t);
    snprintf(t, n, "%.*s%s%s", (int)(hole - base), base, line, hole + 2);
    return t;
}

isk_canvas key_case_render(const char *base, const char *line, int frames)
{
    char *text = scene_text(base, line);
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load_string(&d, text, "case.ini", &err), ISK_OK, "%s\n%s", err.message, text);
    isk_effect *fx;
    isk_status s = isk_effect_create(&fx, &d, &err);
    cr_assert_eq(s, ISK_OK, "%s\n%s", err.message, text);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, d.width, d.height), ISK_OK);
    isk_effect_def_free(&d);
    for (int i = 0; i < frames; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK, "frame %d of\n%s", i, text);
    cr_assert_eq(isk_effect_render(fx, &c), ISK_OK);
    isk_effect_destroy(fx);
    free(text);
    return c;
}

int key_case_equal(const isk_canvas *a, const isk_canvas *b)
{
    if (a->width != b->width || a->height != b->height)
        return 0;
    for (int y = 0; y < a->height; y++)
        if (memcmp(a->pixels + (size_t)y * a->stride, b->pixels + (size_t)y * b->stride, (size_t)a->width * 4))
            return 0;
    return 1;
}

static void compare(const char *base, const char *line, int frames, int want_equal)
{
    isk_canvas with = key_case_render(base, line, frames);
    isk_canvas without = key_case_render(base, "", frames);
    int eq = key_case_equal(&with, &without);
    isk_canvas_free(&with);
    isk_canvas_free(&without);
    if (want_equal)
        cr_assert(eq, "'%s' changed the bytes", line);
    else
        cr_assert_not(eq, "'%s' did not change the bytes", line);
}

void key_case_differs(const char *base, const char *line, int frames) { compare(base, line, frames, 0); }
void key_case_same(const char *base, const char *line, int frames) { compare(base, line, frames, 1); }

void key_case_rejects(const char *base, const char *line, const char *fragment)
{
    char *text = scene_text(base, line);
    int at = 1;
    for (const char *p = base; p < strstr(base, "%s"); p++)
        at += *p == '\n';
    isk_effect_def d;
    isk_error err = {0};
    isk_status s = isk_scene_load_string(&d, text, "case.ini", &err);
    if (s == ISK_OK) {
        /* Some values are refused only when the effect is made. */
        isk_effect *fx = NULL;
        s = isk_effect_create(&fx, &d, &err);
        isk_effect_destroy(fx);
        isk_effect_def_free(&d);
    }
    cr_assert_neq(s, ISK_OK, "'%s' was accepted", line);
    char head[64];
    snprintf(head, sizeof head, "case.ini:%d: ", at);
    cr_assert(!strncmp(err.message, head, strlen(head)), "'%s': message '%s' does not start with '%s'", line,
              err.message, head);
    cr_assert(strstr(err.message, fragment), "'%s': message '%s' lacks '%s'", line, err.message, fragment);

    /* The command line: the same message from the file, exit 2. */
    char dir[128], path[160], args[200];
    unsigned long h = 5381;
    for (const char *p = text; *p; p++)
        h = h * 33 + (unsigned char)*p;
    snprintf(dir, sizeof dir, "out/key_case/%lx", h);
    cli_fresh(dir);
    snprintf(path, sizeof path, "%s/case.ini", dir);
    FILE *f = fopen(path, "wb");
    cr_assert_not_null(f);
    fputs(text, f);
    fclose(f);
    snprintf(args, sizeof args, "describe %s", path);
    cr_assert_eq(cli_run(dir, args), 2, "iskra %s", args);
    char want[200];
    snprintf(want, sizeof want, "%s:%d: ", path, at);
    char stderr_path[200];
    snprintf(stderr_path, sizeof stderr_path, "%s/stderr.txt", dir);
    char *msg = cli_slurp(stderr_path);
    cr_assert(!strncmp(msg, want, strlen(want)), "iskra %s said '%s'", args, msg);
    free(msg);
    free(text);
}
