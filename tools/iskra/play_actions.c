/* SPDX-License-Identifier: MIT */
/* The simulator's actions: one table gives each its widget name, label,
 * shortcut and meaning, so the buttons, the keys and the list of shortcuts
 * in the panel cannot disagree. */
#include <stdio.h>
#include <string.h>

#include "play.h"
#include "play_shadow.h"

static const play_action_info actions[PLAY_ACTION_COUNT] = {
    [PLAY_PLAY] = {"play", "Play", "P", 'p', 0, "run"},
    [PLAY_PAUSE] = {"pause", "Pause", "Space", 0, 0, "hold"},
    [PLAY_TOGGLE_PAUSE] = {"run-hold", "Run/hold", "Space", ' ', 0, "run / hold"},
    [PLAY_STOP] = {"stop", "Stop", "S", 's', 0, "hold and start again"},
    [PLAY_RESET] = {"reset", "Reset", "R", 'r', 0, "start again"},
    [PLAY_RELOAD] = {"reload", "Reload", "F5", ISK_UI_KEY_F1 + 4, 0,
                     "read the scene again (also when the file changes)"},
    [PLAY_STEP] = {"step", "Step", "N", 'n', 0, "one frame, then hold"},
    [PLAY_SLOWER] = {"slower", "Slower", ",", ',', 0, "slower"},
    [PLAY_FASTER] = {"faster", "Faster", ".", '.', 0, "faster"},
    [PLAY_MORE_PRECISION] = {"finer", "+", "+", '+', '=', "one substep more"},
    [PLAY_LESS_PRECISION] = {"coarser", "-", "-", '-', 0, "one substep fewer"},
    [PLAY_SAVE] = {"save", "Save", "F2", ISK_UI_KEY_F1 + 1, 0, "save the parameters as a scene"},
    [PLAY_SHOT] = {"shot", "Shot", "F12", ISK_UI_KEY_F12, 0, "PNG of the canvas"},
    [PLAY_SHOT_WINDOW] = {"shot-window", "Shot all", "F11", ISK_UI_KEY_F1 + 10, 0, "PNG of the window"},
    [PLAY_PANEL] = {"panel", "Panel", "Tab", ISK_UI_KEY_TAB, 0, "hide / show the panel"},
    [PLAY_HUD] = {"hud", "HUD", "H", 'h', 0, "HUD"},
    [PLAY_QUIT] = {"quit", "Quit", "Esc", ISK_UI_KEY_ESCAPE, 0, "quit"},
    [PLAY_BACK] = {"back", "Back", "B", 'b', 0, "one frame back"},
    [PLAY_TIMELINE] = {"timeline", "Timeline", "T", 't', 0, "timeline (click it: go there)"},
    [PLAY_SHADOW] = {"shadow", "Shadow", "G", 'g', 0, "shadow run: a finer reference, its error as ghosts"},
};

const play_action_info *play_action_at(play_action a)
{
    return (unsigned)a < PLAY_ACTION_COUNT ? &actions[a] : NULL;
}

static void reset(player *p)
{
    if (isk_effect_reset(p->fx) != ISK_OK || isk_effect_run(p->fx, &p->sim, 0) != ISK_OK) {
        play_say(p, "reset failed (out of memory?)");
        p->failed = 1;
    }
    isk_timestep_reset(&p->ts);
    play_restarted(p);
}

static void set_slider(player *p, double s)
{
    s = s < 1 ? 1 : s > 1000 ? 1000 : s;
    char v[40];
    snprintf(v, sizeof v, "%.17g", play_divisor_of_slider(s));
    if (play_set(p, "scene", "speed_divisor", v) == 0)
        p->slider = s;
}

static void substeps_by(player *p, int delta)
{
    int n = isk_effect_definition(p->fx)->substeps + delta;
    char v[16];
    snprintf(v, sizeof v, "%d", n);
    if (n >= 1)
        play_set(p, "scene", "substeps", v);
}

void play_toggle_panel(player *p)
{
    const isk_effect_def *d = isk_effect_definition(p->fx);
    play_layout l;
    play_layout_plan(p, d->width, d->height, !p->panel, &l);
    const int w = l.window.w, h = l.window.h;
    isk_canvas c;
    isk_error err;
    if (isk_canvas_init(&c, w, h) != ISK_OK) {
        play_say(p, "out of memory");
        return;
    }
    if (p->host.resize && p->host.resize(p->host.user, w, h, &err) != ISK_OK) {
        play_say(p, "cannot resize the window: %s", err.message);
        isk_canvas_free(&c);
        return;
    }
    isk_canvas_free(p->shown);
    *p->shown = c;
    p->panel = !p->panel;
    p->chart_drawn_n = -1; /* not drawn while hidden */
    p->lay = l;
}

void play_do(player *p, play_action a)
{
    switch (a) {
    case PLAY_PLAY:
        p->paused = 0;
        isk_timestep_reset(&p->ts);
        break;
    case PLAY_PAUSE: p->paused = 1; break;
    case PLAY_TOGGLE_PAUSE:
        p->paused = !p->paused;
        isk_timestep_reset(&p->ts);
        break;
    case PLAY_STOP:
        p->paused = 1;
        reset(p);
        break;
    case PLAY_RESET: reset(p); break;
    case PLAY_RELOAD: play_reload(p); break;
    case PLAY_STEP:
        p->paused = 1;
        if (!p->physics_off)
            play_simulate(p, 1);
        break;
    case PLAY_SLOWER: set_slider(p, p->slider - 100); break;
    case PLAY_FASTER: set_slider(p, p->slider + 100); break;
    case PLAY_MORE_PRECISION: substeps_by(p, +1); break;
    case PLAY_LESS_PRECISION: substeps_by(p, -1); break;
    case PLAY_SAVE: play_save(p); break;
    case PLAY_SHOT: p->shot_pending |= 1; break; /* at the end of the frame, when it is drawn */
    case PLAY_SHOT_WINDOW: p->shot_pending |= 2; break;
    case PLAY_PANEL: p->panel_toggle = 1; break; /* the window changes size between frames */
    case PLAY_HUD: p->hud = !p->hud; break;
    case PLAY_QUIT: p->quit = 1; break;
    case PLAY_BACK: play_rewind_back(p); break;
    case PLAY_TIMELINE: p->timeline_shown = !p->timeline_shown; break;
    case PLAY_SHADOW: play_shadow_toggle(p); break;
    default: break;
    }
}

void play_keys_help(FILE *f)
{
    /* Only actions with a key of their own (Pause is Space's run / hold). */
    int col = 0;
    for (int a = 0; a < PLAY_ACTION_COUNT; a++) {
        if (!actions[a].key)
            continue;
        char item[96];
        int n = snprintf(item, sizeof item, "%s %s", actions[a].keys, actions[a].meaning);
        if (col && col + 2 + n > 84) {
            fputs("\n", f);
            col = 0;
        }
        col += fprintf(f, "%s%s", col ? "; " : "        ", item);
    }
    fprintf(f, "%s1-%d click mode\n", col ? "; " : "        ", PLAY_CLICK_MODES);
}

void play_shortcuts(player *p)
{
    int keys[ISK_UI_FRAME_KEYS];
    int n = isk_ui_keys(&p->ui, keys, ISK_UI_FRAME_KEYS);
    for (int i = 0; i < n && !p->quit; i++) {
        for (int a = 0; a < PLAY_ACTION_COUNT; a++)
            if (actions[a].key && (keys[i] == actions[a].key || keys[i] == actions[a].key2)) {
                play_do(p, (play_action)a);
                break;
            }
        /* 1, 2, ...: the click modes in the order of the radio group */
        if (keys[i] >= '1' && keys[i] < '1' + PLAY_CLICK_MODES)
            play_set_click_mode(p, keys[i] - '1');
    }
}

/* The click mode: one of the [click] key's explosions (the scene's
 * [click] then explodes them), "none" (its clicks are off: enabled =
 * false), or the console's own "add potential", which is the console's
 * state, not the scene's: the scene's [click] stays as it was, so a save
 * in that mode reloads to the scene it was. */
void play_set_click_mode(player *p, int mode)
{
    if (mode < 0 || mode >= PLAY_CLICK_MODES)
        return;
    if (mode < ISK_EXPLOSION_COUNT) {
        if (play_set(p, "click", "explosion", isk_explosion_names[mode]) || play_set(p, "click", "enabled", "true"))
            return;
    } else if (mode == PLAY_CLICK_NONE && play_set(p, "click", "enabled", "false")) {
        return;
    }
    p->click_mode = mode;
}
