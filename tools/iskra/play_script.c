/* SPDX-License-Identifier: MIT */
/* --script: a session played into the window as if a user did it, for
 * tests and unattended demos; a recorded lesson (lesson.h) is the same
 * tokens in a file.  Tokens, separated by spaces, run in order;
 * everything up to a wait:N or frame:N happens at the end of one frame
 * (the events reach the widgets from the next frame on, one click per
 * frame, as real input would; a shot sees the frame just drawn):
 *
 *   wait:N            let N frames pass
 *   frame:N           wait until N frames have been shown (0: before the first)
 *   click:X,Y         left click at window pixel (X, Y) (the canvas starts at 0, 0)
 *   double-click:X,Y  two clicks there, the second a double click's
 *   move:X,Y          the pointer moves there
 *   down:X,Y          the left button goes down there (down:X,Y,2: a double click's second)
 *   up:X,Y            and up (up:X,Y,2 likewise)
 *   drag:X0,Y0,X1,Y1  press at one point, move to the other, release
 *   wheel:1, wheel:-1 the wheel turns a notch away from the user / towards
 *   press:NAME        click the middle of the widget NAME (as laid out in the last frame;
 *                     an inspector key scrolled out of view is brought into view first)
 *   type:TEXT         text typed into the focused field (%20 a space, %25 a '%', %23 a '#')
 *   key:NAME          a key: space return tab esc backspace delete left right up down home end f1..f12
 *   keydown:NAME      only the key's press (types nothing); keydown:ctrl+C with Ctrl
 *   space esc tab return f1..f12 kp+ kp-   the same keys, without "key:"
 *   C                 any one printable character: its key (and the text it types)
 *   ctrl+C            the key C held with Ctrl (ctrl+a: select all in a field)
 *   shot:PATH         the window as last shown, to a PNG (a lesson's shot:NAME: a checkpoint)
 *   canvas-shot:PATH  the canvas alone, to a PNG
 *   quit              the session ends after this frame, as when the window is closed */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "play.h"

void play_script_help(FILE *f)
{
    fprintf(f, "  --script EVENTS  play a session (for tests and demos), space-separated tokens in order:\n"
               "                   wait:N (frames)  click:X,Y  move:X,Y  drag:X0,Y0,X1,Y1 (window pixels)\n"
               "                   press:WIDGET  type:TEXT  key:NAME  shot:PATH  canvas-shot:PATH, and keys:\n"
               "                   space esc tab return f1..f12 kp+ kp- or any one character; ctrl+a\n"
               "                   (select all); double-click:X,Y.  --list-widgets lists the WIDGET names.\n"
               "                   What --record writes: frame:N (after N frames) down:X,Y up:X,Y\n"
               "                   wheel:1|-1 keydown:NAME type:TEXT (%%20 a space) quit\n");
}

typedef struct named_key {
    const char *name;
    int key;
} named_key;

static const named_key keys[] = {
    {"space", ' '},          {"esc", ISK_KEY_ESCAPE},     {"escape", ISK_KEY_ESCAPE}, {"tab", ISK_KEY_TAB},
    {"return", ISK_KEY_RETURN}, {"enter", ISK_KEY_RETURN}, {"backspace", ISK_KEY_BACKSPACE},
    {"delete", ISK_KEY_DELETE}, {"left", ISK_KEY_LEFT},    {"right", ISK_KEY_RIGHT},   {"up", ISK_KEY_UP},
    {"down", ISK_KEY_DOWN},  {"home", ISK_KEY_HOME},      {"end", ISK_KEY_END},       {"kp+", ISK_KEY_KP_PLUS},
    {"kp-", ISK_KEY_KP_MINUS},
};

/* The key a name stands for, or 0. */
static int key_named(const char *name)
{
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        if (!strcmp(keys[i].name, name))
            return keys[i].key;
    int n, used = 0;
    if ((name[0] == 'f' || name[0] == 'F') && sscanf(name + 1, "%d%n", &n, &used) == 1 && !name[1 + used] && n >= 1 &&
        n <= 12)
        return ISK_KEY_F1 + n - 1;
    return 0;
}

int play_script_key_name(int key, char *out, size_t n)
{
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        if (keys[i].key == key && strcmp(keys[i].name, "escape") && strcmp(keys[i].name, "enter"))
            return snprintf(out, n, "%s", keys[i].name) < (int)n;
    if (key >= ISK_KEY_F1 && key <= ISK_KEY_F12)
        return snprintf(out, n, "f%d", key - ISK_KEY_F1 + 1) < (int)n;
    if (key > 32 && key < 127)
        return snprintf(out, n, "%c", key) < (int)n;
    return 0;
}

static int hex_digit(char c)
{
    return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
}

/* type:TEXT's text with its %XX escapes decoded into out (n bytes); 0 when
 * an escape is malformed, the text is empty or does not fit. */
static int decode_text(const char *t, char *out, size_t n)
{
    size_t k = 0;
    for (; *t; t++) {
        int c = (unsigned char)*t;
        if (c == '%') {
            int hi = hex_digit(t[1]), lo = hi < 0 ? -1 : hex_digit(t[2]);
            if (lo < 0 || (hi == 0 && lo == 0))
                return 0;
            c = hi * 16 + lo;
            t += 2;
        }
        if (k + 1 >= n)
            return 0;
        out[k++] = (char)c;
    }
    out[k] = 0;
    return k > 0;
}

/* A key's name ("esc", "f9", one character) or, with ctrl, "ctrl+C". */
static int key_token_ok(const char *name, int ctrl_allowed)
{
    if (ctrl_allowed && !strncmp(name, "ctrl+", 5))
        return key_token_ok(name + 5, 0);
    return key_named(name) != 0 || (strlen(name) == 1 && name[0] > 32 && name[0] < 127);
}

/* A lesson's shot name: letters, digits, '-' and '_' (it becomes NAME.png
 * in a directory of references). */
static int shot_name_ok(const char *n)
{
    if (!*n || strlen(n) > 100)
        return 0;
    for (; *n; n++)
        if (!((*n >= 'a' && *n <= 'z') || (*n >= 'A' && *n <= 'Z') || (*n >= '0' && *n <= '9') || *n == '-' ||
              *n == '_'))
            return 0;
    return 1;
}

/* down:X,Y or down:X,Y,2 (and up:): 1 with the values when t is one. */
static int mouse_button_token(const char *t, const char *prefix, int *x, int *y, int *clicks)
{
    size_t len = strlen(prefix);
    int used = 0;
    if (strncmp(t, prefix, len))
        return 0;
    t += len;
    *clicks = 1;
    if (sscanf(t, "%d,%d%n", x, y, &used) != 2)
        return 0;
    if (!t[used])
        return 1;
    int more = 0;
    return sscanf(t + used, ",%d%n", clicks, &more) == 1 && !t[used + more] && (*clicks == 1 || *clicks == 2);
}

/* What a token is; 1 if it is one we know (checked before anything runs).
 * Frame counts have at most 9 digits, so they fit an int. */
static int known(const char *t, int lesson)
{
    int a, b, c, d, used = 0;
    char text[64];
    if ((sscanf(t, "wait:%9d%n", &a, &used) == 1 || sscanf(t, "frame:%9d%n", &a, &used) == 1) && !t[used] && a >= 0)
        return 1;
    if ((sscanf(t, "click:%d,%d%n", &a, &b, &used) == 2 || sscanf(t, "move:%d,%d%n", &a, &b, &used) == 2 ||
         sscanf(t, "double-click:%d,%d%n", &a, &b, &used) == 2) &&
        !t[used])
        return 1;
    if (mouse_button_token(t, "down:", &a, &b, &c) || mouse_button_token(t, "up:", &a, &b, &c))
        return 1;
    if (!strcmp(t, "wheel:1") || !strcmp(t, "wheel:+1") || !strcmp(t, "wheel:-1") || !strcmp(t, "quit"))
        return 1;
    if (!strncmp(t, "ctrl+", 5))
        return strlen(t + 5) == 1 && t[5] > 32 && t[5] < 127;
    if (sscanf(t, "drag:%d,%d,%d,%d%n", &a, &b, &c, &d, &used) == 4 && !t[used])
        return 1;
    if (!strncmp(t, "type:", 5))
        return decode_text(t + 5, text, sizeof text);
    if (!strncmp(t, "shot:", 5) || !strncmp(t, "canvas-shot:", 12))
        return lesson ? shot_name_ok(strchr(t, ':') + 1) : strchr(t, ':')[1] != 0;
    if (!strncmp(t, "press:", 6))
        return t[6] != 0;
    if (!strncmp(t, "keydown:", 8))
        return key_token_ok(t + 8, 1);
    if (!strncmp(t, "key:", 4))
        return key_token_ok(t + 4, 0);
    return key_token_ok(t, 0);
}

/* Room for one more token. */
static int grow(play_script *s)
{
    if (s->n < s->cap)
        return 1;
    int cap = s->cap ? s->cap * 2 : 64;
    char **tokens = realloc(s->tokens, (size_t)cap * sizeof *tokens);
    if (tokens)
        s->tokens = tokens;
    int *lines = tokens ? realloc(s->lines, (size_t)cap * sizeof *lines) : NULL;
    if (lines)
        s->lines = lines;
    if (!tokens || !lines)
        return 0;
    s->cap = cap;
    return 1;
}

/* The tokens of text into s; a message naming the token (FILE:LINE in a
 * lesson) and 2 for a bad one. */
static int parse(play_script *s, const char *text, const char *file, int line)
{
    memset(s, 0, sizeof *s);
    s->file = file;
    s->text = malloc(strlen(text) + 1);
    if (!s->text) {
        fprintf(stderr, "iskra play: out of memory\n");
        return 1;
    }
    strcpy(s->text, text);
    long last_frame = -1;
    int last_frame_line = 0;
    for (char *c = s->text; *c;) {
        if (*c == '\n' || *c == ' ' || *c == '\t' || *c == '\r') {
            line += *c == '\n';
            *c++ = 0;
            continue;
        }
        if (file && *c == '#') { /* a comment, to the end of the line */
            while (*c && *c != '\n')
                *c++ = 0;
            continue;
        }
        char *t = c;
        while (*c && *c != '\n' && *c != ' ' && *c != '\t' && *c != '\r')
            c++;
        const int newline_after = *c == '\n';
        if (*c)
            *c++ = 0;
        int frame, used = 0;
        const int bad = !known(t, file != NULL);
        if (bad) {
            if (file)
                fprintf(stderr, "%s:%d: unknown event '%s' (iskra play --help lists them)\n", file, line, t);
            else
                fprintf(stderr, "iskra play: --script: unknown event '%s' (iskra play --help lists them)\n", t);
            return 2;
        }
        if (file && sscanf(t, "frame:%9d%n", &frame, &used) == 1 && !t[used]) {
            if (frame < last_frame) {
                fprintf(stderr, "%s:%d: frame:%d comes after frame:%ld (line %d): frames go forward\n", file, line,
                        frame, last_frame, last_frame_line);
                return 2;
            }
            last_frame = frame;
            last_frame_line = line;
        }
        if (s->n == PLAY_SCRIPT_MAX) {
            if (file)
                fprintf(stderr, "%s:%d: more than %d events\n", file, line, PLAY_SCRIPT_MAX);
            else
                fprintf(stderr, "iskra play: --script: more than %d events\n", PLAY_SCRIPT_MAX);
            return 2;
        }
        if (!grow(s)) {
            fprintf(stderr, "iskra play: out of memory\n");
            return 1;
        }
        s->lines[s->n] = line;
        s->tokens[s->n++] = t;
        line += newline_after;
    }
    return 0;
}

int play_script_parse(play_script *s, const char *text) { return parse(s, text, NULL, 1); }

int play_script_parse_lesson(play_script *s, const char *text, const char *file, int first_line)
{
    return parse(s, text, file, first_line);
}

void play_script_free(play_script *s)
{
    free(s->text);
    free(s->tokens);
    free(s->lines);
    memset(s, 0, sizeof *s);
}

static int push(player *p, isk_event ev)
{
    if (!p->host.push_event || p->host.push_event(p->host.user, &ev) == ISK_OK)
        return 0;
    play_say(p, "--script: cannot queue an event");
    p->failed = 1;
    return -1;
}

static int mouse_clicks(player *p, isk_event_type type, int x, int y, int clicks)
{
    isk_event ev;
    memset(&ev, 0, sizeof ev);
    ev.type = type;
    ev.button = 1;
    ev.x = x;
    ev.y = y;
    ev.clicks = clicks;
    return push(p, ev);
}

static int mouse(player *p, isk_event_type type, int x, int y) { return mouse_clicks(p, type, x, y, 1); }

static int click(player *p, int x, int y)
{
    return mouse(p, ISK_EVENT_MOUSE_MOVE, x, y) || mouse(p, ISK_EVENT_MOUSE_DOWN, x, y) ||
           mouse(p, ISK_EVENT_MOUSE_UP, x, y);
}

static int double_click(player *p, int x, int y)
{
    return click(p, x, y) || mouse_clicks(p, ISK_EVENT_MOUSE_DOWN, x, y, 2) ||
           mouse_clicks(p, ISK_EVENT_MOUSE_UP, x, y, 2);
}

static int key_mods(player *p, int code, char typed, int mods)
{
    isk_event ev;
    memset(&ev, 0, sizeof ev);
    ev.type = ISK_EVENT_KEY_DOWN;
    ev.mods = mods;
    ev.key = code >= 'A' && code <= 'Z' ? code - 'A' + 'a' : code;
    if (push(p, ev))
        return -1;
    ev.type = ISK_EVENT_KEY_UP;
    if (push(p, ev))
        return -1;
    if (!typed)
        return 0;
    memset(&ev, 0, sizeof ev);
    ev.type = ISK_EVENT_TEXT;
    ev.text[0] = typed;
    return push(p, ev);
}

static int key(player *p, int code, char typed) { return key_mods(p, code, typed, 0); }

static int type_text(player *p, const char *encoded)
{
    isk_event ev;
    char text[64];
    if (!decode_text(encoded, text, sizeof text))
        return 0; /* checked when parsed */
    const size_t len = strlen(text);
    for (size_t i = 0; i < len; i += sizeof ev.text - 1) {
        memset(&ev, 0, sizeof ev);
        ev.type = ISK_EVENT_TEXT;
        snprintf(ev.text, sizeof ev.text, "%s", text + i);
        if (push(p, ev))
            return -1;
    }
    return 0;
}

static int run_one(player *p, const char *t)
{
    play_script *s = &p->script;
    int a, b, c, d, used = 0;
    if (sscanf(t, "wait:%9d%n", &a, &used) == 1 && !t[used]) {
        s->wait_until = p->frames_shown + a;
        return 0;
    }
    if (sscanf(t, "frame:%9d%n", &a, &used) == 1 && !t[used]) {
        s->wait_until = a;
        return 0;
    }
    if (!strcmp(t, "quit")) {
        p->quit = 1;
        return 0;
    }
    if (mouse_button_token(t, "down:", &a, &b, &c))
        return mouse_clicks(p, ISK_EVENT_MOUSE_DOWN, a, b, c);
    if (mouse_button_token(t, "up:", &a, &b, &c))
        return mouse_clicks(p, ISK_EVENT_MOUSE_UP, a, b, c);
    if (!strncmp(t, "wheel:", 6)) {
        isk_event ev;
        memset(&ev, 0, sizeof ev);
        ev.type = ISK_EVENT_WHEEL;
        ev.wheel = t[6] == '-' ? -1 : 1;
        return push(p, ev);
    }
    if (!strncmp(t, "keydown:", 8)) {
        const char *name = t + 8;
        const int ctrl = !strncmp(name, "ctrl+", 5);
        name += ctrl ? 5 : 0;
        isk_event ev;
        memset(&ev, 0, sizeof ev);
        ev.type = ISK_EVENT_KEY_DOWN;
        ev.mods = ctrl ? ISK_MOD_CTRL : 0;
        ev.key = key_named(name);
        if (!ev.key)
            ev.key = name[0] >= 'A' && name[0] <= 'Z' ? name[0] - 'A' + 'a' : name[0];
        return push(p, ev);
    }
    if (sscanf(t, "click:%d,%d%n", &a, &b, &used) == 2 && !t[used])
        return click(p, a, b);
    if (sscanf(t, "move:%d,%d%n", &a, &b, &used) == 2 && !t[used])
        return mouse(p, ISK_EVENT_MOUSE_MOVE, a, b);
    if (sscanf(t, "double-click:%d,%d%n", &a, &b, &used) == 2 && !t[used])
        return double_click(p, a, b);
    if (!strncmp(t, "ctrl+", 5))
        return key_mods(p, t[5], 0, ISK_MOD_CTRL); /* Ctrl types nothing */
    if (sscanf(t, "drag:%d,%d,%d,%d%n", &a, &b, &c, &d, &used) == 4 && !t[used])
        return mouse(p, ISK_EVENT_MOUSE_MOVE, a, b) || mouse(p, ISK_EVENT_MOUSE_DOWN, a, b) ||
               mouse(p, ISK_EVENT_MOUSE_MOVE, c, d) || mouse(p, ISK_EVENT_MOUSE_UP, c, d);
    if (!strncmp(t, "press:", 6)) {
        isk_ui_rect r;
        const char *name = t + 6;
        if (!isk_ui_find(&p->ui, name, &r)) {
            /* A key the inspector scrolled out of view: into view at the end
             * of the next frame, and the press again after the one after,
             * which shows it. */
            if (!s->revealing && play_inspector_reveal(p, name)) {
                s->revealing = 1;
                s->next--;
                s->wait_until = p->frames_shown + 2;
                return 0;
            }
            char hint[300];
            play_suggest_widget(p, name, hint, sizeof hint);
            play_say(p, "--script: no widget '%s' in the window now%s (iskra play %s --list-widgets lists them)",
                     name, hint, p->args.scene);
            p->failed = 1;
            return -1;
        }
        s->revealing = 0;
        return click(p, r.x + r.w / 2, r.y + r.h / 2);
    }
    if (!strncmp(t, "type:", 5))
        return type_text(p, t + 5);
    if (!strncmp(t, "shot:", 5) || !strncmp(t, "canvas-shot:", 12)) {
        const int whole = t[0] == 's';
        if (s->shot)
            s->shot(p, s->shot_user, strchr(t, ':') + 1, whole);
        else
            play_screenshot(p, whole, strchr(t, ':') + 1);
        return 0;
    }
    const char *name = !strncmp(t, "key:", 4) ? t + 4 : t;
    int k = key_named(name);
    if (k)
        return key(p, k, k == ' ' ? ' ' : 0);
    return key(p, name[0], name[0]);
}

int play_script_run(player *p)
{
    play_script *s = &p->script;
    while (s->next < s->n && p->frames_shown >= s->wait_until && !p->failed && !p->quit)
        if (run_one(p, s->tokens[s->next++]) != 0) {
            if (s->file) /* the message above says why; this says where */
                fprintf(stderr, "%s:%d: '%s' failed\n", s->file, s->lines[s->next - 1], s->tokens[s->next - 1]);
            return -1;
        }
    return 0;
}

int play_script_start(player *p)
{
    const play_script *s = &p->script;
    return s->n && !strcmp(s->tokens[0], "frame:0") ? play_script_run(p) : 0;
}

int play_script_done(const player *p) { return p->script.next >= p->script.n; }
