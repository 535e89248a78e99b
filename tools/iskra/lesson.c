/* SPDX-License-Identifier: MIT */
/* Reading and recording lessons (lesson.h). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/outfile.h"
#include "lesson.h"
#include "play.h"

/* ---- reading -------------------------------------------------------------- */

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t len = 0, cap = 4096;
    char *buf = malloc(cap);
    for (size_t got; buf && (got = fread(buf + len, 1, cap - len - 1, f)) > 0;) {
        len += got;
        if (cap - len - 1 == 0) {
            char *more = realloc(buf, cap * 2);
            if (!more) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = more;
            cap *= 2;
        }
    }
    if (buf && ferror(f)) {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    if (buf)
        buf[len] = 0;
    return buf;
}

static int blank_or_comment(const char *line, const char *end)
{
    while (line < end && (*line == ' ' || *line == '\t' || *line == '\r'))
        line++;
    return line == end || *line == '#';
}

int lesson_load(lesson *l, const char *path)
{
    memset(l, 0, sizeof *l);
    l->text = slurp(path);
    if (!l->text) {
        perror(path);
        return 1;
    }
    /* The first line that is not blank or a comment is play: ARGS. */
    int line = 1;
    const char *c = l->text;
    for (;;) {
        const char *end = strchr(c, '\n');
        if (!end)
            end = c + strlen(c);
        if (!blank_or_comment(c, end)) {
            if (strncmp(c, "play:", 5)) {
                fprintf(stderr, "%s:%d: expected the line 'play: SCENE [OPTIONS]' before the events\n", path, line);
                return 2;
            }
            l->args_line = line;
            l->args_copy = malloc((size_t)(end - c) - 5 + 1);
            if (!l->args_copy) {
                fprintf(stderr, "iskra: out of memory\n");
                return 1;
            }
            memcpy(l->args_copy, c + 5, (size_t)(end - c) - 5);
            l->args_copy[end - c - 5] = 0;
            l->events = *end ? end + 1 : end;
            l->events_line = line + 1;
            break;
        }
        if (!*end) {
            fprintf(stderr, "%s:%d: no 'play: SCENE [OPTIONS]' line: not a lesson\n", path, line);
            return 2;
        }
        c = end + 1;
        line++;
    }
    l->argv[l->argc++] = "play";
    for (char *save = NULL, *t = strtok_r(l->args_copy, " \t\r", &save); t; t = strtok_r(NULL, " \t\r", &save)) {
        if (t[0] == '#')
            break;
        if (l->argc == LESSON_MAX_ARGS) {
            fprintf(stderr, "%s:%d: more than %d arguments\n", path, l->args_line, LESSON_MAX_ARGS - 1);
            return 2;
        }
        l->argv[l->argc++] = t;
    }
    l->argv[l->argc] = NULL;
    if (l->argc == 1) {
        fprintf(stderr, "%s:%d: 'play:' names no scene\n", path, l->args_line);
        return 2;
    }
    return 0;
}

void lesson_free(lesson *l)
{
    free(l->text);
    free(l->args_copy);
    memset(l, 0, sizeof *l);
}

/* ---- recording ------------------------------------------------------------ */

/* Appends printf-style text; on running out of memory the recorder fails
 * (said once) and records nothing more. */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void add(lesson_recorder *r, const char *fmt, ...)
{
    if (r->failed == 2)
        return;
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        int n = vsnprintf(r->buf + r->len, r->cap - r->len, fmt, ap);
        va_end(ap);
        if (n < 0)
            return;
        if ((size_t)n < r->cap - r->len) {
            r->len += (size_t)n;
            return;
        }
        size_t cap = r->cap * 2 + (size_t)n;
        char *more = realloc(r->buf, cap);
        if (!more) {
            fprintf(stderr, "iskra play: --record: out of memory; the lesson ends here\n");
            r->failed = 2;
            return;
        }
        r->buf = more;
        r->cap = cap;
    }
}

int lesson_record_begin(lesson_recorder *r, const char *path, int argc, char **argv, const int *skip,
                        int screen_w, int screen_h, int screen_given)
{
    memset(r, 0, sizeof *r);
    r->path = path;
    r->cap = 1 << 16;
    r->buf = malloc(r->cap);
    if (!r->buf) {
        fprintf(stderr, "iskra play: out of memory\n");
        return 1;
    }
    r->buf[0] = 0;
    for (int i = 1; i < argc; i++)
        if (!skip[i] && (!argv[i][0] || argv[i][0] == '#' || strpbrk(argv[i], " \t\r\n"))) {
            fprintf(stderr, "iskra play: --record: the argument \"%s\" cannot be written into a lesson "
                            "(empty, or a space or '#' in it)\n", argv[i]);
            return 2;
        }
    add(r, "# iskra lesson, recorded by iskra play --record: one simulation step per shown frame.\n"
           "# iskra play --replay FILE shows it; iskra replay FILE --check DIR compares its shots.\n"
           "# frame:N: after N shown frames (what follows reaches the simulator with the next).\n"
           "play:");
    for (int i = 1; i < argc; i++)
        if (!skip[i])
            add(r, " %s", argv[i]);
    if (!screen_given)
        add(r, " --screen %dx%d", screen_w, screen_h);
    add(r, "\n");
    return lesson_record_save(r, 0);
}

/* type:TEXT's escapes: everything but printable ASCII, space, '%' and '#'
 * as %XX (the parser's decode_text reads them back). */
static void add_text(lesson_recorder *r, const char *text)
{
    add(r, " type:");
    for (const unsigned char *c = (const unsigned char *)text; *c; c++)
        if (*c > 32 && *c < 127 && *c != '%' && *c != '#')
            add(r, "%c", *c);
        else
            add(r, "%%%02X", *c);
}

/* One event as the script's token (only what the simulator acts on: the
 * widget layer takes the left button, the wheel, key presses and text;
 * key releases and other buttons change nothing). */
static void add_event(lesson_recorder *r, const isk_event *e)
{
    char name[16];
    switch (e->type) {
    case ISK_EVENT_MOUSE_MOVE: add(r, " move:%d,%d", e->x, e->y); break;
    case ISK_EVENT_MOUSE_DOWN:
    case ISK_EVENT_MOUSE_UP:
        if (e->button == 1)
            add(r, " %s:%d,%d%s", e->type == ISK_EVENT_MOUSE_DOWN ? "down" : "up", e->x, e->y,
                e->clicks > 1 ? ",2" : "");
        break;
    case ISK_EVENT_WHEEL: add(r, " wheel:%d", e->wheel > 0 ? 1 : -1); break;
    case ISK_EVENT_TEXT:
        if (e->text[0])
            add_text(r, e->text);
        break;
    case ISK_EVENT_KEY_DOWN:
        if (play_script_key_name(e->key, name, sizeof name))
            add(r, " keydown:%s%s", e->mods & ISK_MOD_CTRL ? "ctrl+" : "", name);
        break;
    default: break;
    }
}

void lesson_record_frame(lesson_recorder *r, long frame, isk_event *ev, int *nev)
{
    const size_t start = r->len;
    int kept = 0, checkpoint = 0;
    add(r, "frame:%ld", frame);
    const size_t empty = r->len;
    for (int i = 0; i < *nev; i++) {
        if (ev[i].type == ISK_EVENT_KEY_DOWN && ev[i].key == LESSON_CHECKPOINT_KEY) {
            add(r, " shot:checkpoint-%d", ++r->checkpoints);
            fprintf(stderr, "iskra play: checkpoint-%d after frame %ld (in %s)\n", r->checkpoints, frame, r->path);
            checkpoint = 1;
            continue;
        }
        if (ev[i].type == ISK_EVENT_KEY_UP && ev[i].key == LESSON_CHECKPOINT_KEY)
            continue;
        add_event(r, &ev[i]);
        ev[kept++] = ev[i];
    }
    *nev = kept;
    if (r->failed == 2)
        return;
    if (r->len == empty) /* nothing the simulator acts on */
        r->len = start, r->buf[start] = 0;
    else
        add(r, "\n");
    if (checkpoint || frame - r->saved_frame >= LESSON_SAVE_FRAMES)
        (void)lesson_record_save(r, frame);
}

int lesson_record_save(lesson_recorder *r, long frames)
{
    isk_outfile o;
    isk_error err;
    r->saved_frame = frames;
    if (isk_make_parent_dirs(r->path, &err) != ISK_OK || isk_outfile_open(&o, r->path, &err) != ISK_OK) {
        fprintf(stderr, "iskra play: --record: %s\n", err.message);
        r->failed = r->failed ? r->failed : 1;
        return 1;
    }
    if (fwrite(r->buf, 1, r->len, o.f) != r->len || fprintf(o.f, "frame:%ld quit\n", frames) < 0) {
        isk_outfile_abort(&o);
        fprintf(stderr, "iskra play: --record: cannot write %s\n", r->path);
        r->failed = r->failed ? r->failed : 1;
        return 1;
    }
    if (isk_outfile_commit(&o, &err) != ISK_OK) {
        fprintf(stderr, "iskra play: --record: %s\n", err.message);
        r->failed = r->failed ? r->failed : 1;
        return 1;
    }
    if (r->failed == 1)
        r->failed = 0;
    return 0;
}

void lesson_record_free(lesson_recorder *r)
{
    free(r->buf);
    memset(r, 0, sizeof *r);
}
