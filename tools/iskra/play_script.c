/* SPDX-License-Identifier: MIT */
/* --script: a session played into the window as if a user did it, for
 * tests and unattended demos.  Tokens, separated by spaces, run in order;
 * everything up to a wait:N happens at the end of one frame (the events
 * reach the widgets from the next frame on, one click per frame, as real
 * input would; a shot sees the frame just drawn):
 *
 *   wait:N            let N frames pass
 *   click:X,Y         left click at window pixel (X, Y) (the canvas starts at 0, 0)
 *   double-click:X,Y  two clicks there, the second a double click's
 *   move:X,Y          the pointer moves there
 *   drag:X0,Y0,X1,Y1  press at one point, move to the other, release
 *   press:NAME        click the middle of the widget NAME (as laid out in the last frame;
 *                     an inspector key scrolled out of view is brought into view first)
 *   type:TEXT         text typed into the focused field
 *   key:NAME          a key: space return tab esc backspace delete left right up down home end f1..f12
 *   space esc tab return f1..f12 kp+ kp-   the same keys, without "key:"
 *   C                 any one printable character: its key (and the text it types)
 *   ctrl+C            the key C held with Ctrl (ctrl+a: select all in a field)
 *   shot:PATH         the window as last shown, to a PNG
 *   canvas-shot:PATH  the canvas alone, to a PNG */
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
               "                   (select all); double-click:X,Y.  --list-widgets lists the WIDGET names\n");
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

/* What a token is; 1 if it is one we know (checked before anything runs). */
static int known(const char *t)
{
    int a, b, c, d, used = 0;
    if (sscanf(t, "wait:%d%n", &a, &used) == 1 && !t[used] && a >= 0)
        return 1;
    if ((sscanf(t, "click:%d,%d%n", &a, &b, &used) == 2 || sscanf(t, "move:%d,%d%n", &a, &b, &used) == 2 ||
         sscanf(t, "double-click:%d,%d%n", &a, &b, &used) == 2) &&
        !t[used])
        return 1;
    if (!strncmp(t, "ctrl+", 5))
        return strlen(t + 5) == 1 && t[5] > 32 && t[5] < 127;
    if (sscanf(t, "drag:%d,%d,%d,%d%n", &a, &b, &c, &d, &used) == 4 && !t[used])
        return 1;
    if ((!strncmp(t, "press:", 6) || !strncmp(t, "type:", 5) || !strncmp(t, "shot:", 5) ||
         !strncmp(t, "canvas-shot:", 12)) &&
        strchr(t, ':')[1])
        return 1;
    if (!strncmp(t, "key:", 4))
        return key_named(t + 4) != 0 || (strlen(t + 4) == 1 && t[4] > 32 && t[4] < 127);
    return key_named(t) != 0 || (strlen(t) == 1 && t[0] > 32 && t[0] < 127);
}

int play_script_parse(play_script *s, const char *text)
{
    memset(s, 0, sizeof *s);
    s->text = malloc(strlen(text) + 1);
    if (!s->text) {
        fprintf(stderr, "iskra play: out of memory\n");
        return 1;
    }
    strcpy(s->text, text);
    for (char *save = NULL, *t = strtok_r(s->text, " \t\n", &save); t; t = strtok_r(NULL, " \t\n", &save)) {
        if (!known(t)) {
            fprintf(stderr, "iskra play: --script: unknown event '%s' (iskra play --help lists them)\n", t);
            return 2;
        }
        if (s->n == PLAY_SCRIPT_MAX) {
            fprintf(stderr, "iskra play: --script: more than %d events\n", PLAY_SCRIPT_MAX);
            return 2;
        }
        s->tokens[s->n++] = t;
    }
    return 0;
}

void play_script_free(play_script *s)
{
    free(s->text);
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

static int type_text(player *p, const char *text)
{
    isk_event ev;
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
    if (sscanf(t, "wait:%d%n", &a, &used) == 1 && !t[used]) {
        s->wait_until = p->frames_shown + a;
        return 0;
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
    if (!strncmp(t, "shot:", 5)) {
        play_screenshot(p, 1, t + 5);
        return 0;
    }
    if (!strncmp(t, "canvas-shot:", 12)) {
        play_screenshot(p, 0, t + 12);
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
    while (s->next < s->n && p->frames_shown >= s->wait_until && !p->failed)
        if (run_one(p, s->tokens[s->next++]) != 0)
            return -1;
    return 0;
}
