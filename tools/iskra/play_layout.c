/* SPDX-License-Identifier: MIT */
/* Where the simulator's parts sit in the window, for the screen it must
 * fit.  The scene's canvas is always at the top-left, shown 1:1 (the
 * window itself is only ever scaled by whole numbers, iskra/sdl.h).
 *
 *   console, wide      the thesis page's layout: the console and the side
 *                      column (charts, integrators) beside the canvas, the
 *                      click modes, potentials, layer and files below; the
 *                      5x8 font at scale s (sizes in play.h, times s)
 *   console, compact   the same parts in three columns beside the canvas,
 *                      the 6x13 font: 1260 x 600 for the thesis's 600 x 600
 *                      canvas, so it fits 1280x720 and 1366x768
 *   inspector          its column beside the canvas, messages and charts
 *                      below the canvas; the 6x13 font at scale s
 *
 * The choice (play_choose_layout): the wide console at the largest scale
 * from 2 that fits the screen, else the compact one; the inspector at the
 * largest scale that fits.  So text is at least 10 px tall (the 5x8 font at
 * scale 2 is 14, the 6x13 font at scale 1 is 10) on any screen from
 * 1280x720, unless --ui-scale asks otherwise. */
#include <string.h>

#include "play.h"

play_panel_kind play_panel_for(const isk_effect_def *d)
{
    for (int i = 0; i < d->nemitters; i++)
        if (d->emitters[i].born.source == ISK_SOURCE_LAYER)
            return PLAY_PANEL_CONSOLE;
    for (int i = 0; i < d->nforces; i++)
        if (d->forces[i].kind == ISK_FORCE_POTENTIAL)
            return PLAY_PANEL_CONSOLE;
    return PLAY_PANEL_INSPECTOR;
}

static int clamp(int v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : v; }

/* What a window's title bar and sides take of the screen (none in a page). */
static int title_h(const player *p) { return p->borderless ? 0 : SCREEN_TITLE_H; }
static int side_w(const player *p) { return p->borderless ? 0 : SCREEN_SIDE_W; }

/* Panel widths and heights at scale s for the screen (in pixels). */
static int compact_w(const player *p, int cw, int s)
{
    return clamp((p->screen_w - side_w(p) - cw) / s, COMPACT_MIN_W, COMPACT_MAX_W) * s;
}

static int inspector_w(const player *p, int cw, int s)
{
    return clamp((p->screen_w - side_w(p) - cw) / s, INSPECTOR_MIN_W, INSPECTOR_MAX_W) * s;
}

static int inspector_h(const player *p, int s)
{
    return clamp((p->screen_h - title_h(p)) / s, INSPECTOR_MIN_H, INSPECTOR_MAX_H) * s;
}

void play_layout_plan(const player *p, int cw, int ch, int panel, play_layout *l)
{
    const int s = p->ui.scale;
    memset(l, 0, sizeof *l);
    l->canvas = (isk_ui_rect){0, 0, cw, ch};
    l->window = l->canvas;
    if (!panel)
        return;
    if (p->panel_kind == PLAY_PANEL_INSPECTOR) {
        const int w = inspector_w(p, cw, s), h = ch > inspector_h(p, s) ? ch : inspector_h(p, s);
        l->window = (isk_ui_rect){0, 0, cw + w, h};
        l->inspector = (isk_ui_rect){cw, 0, w, h};
        l->under = (isk_ui_rect){0, ch, cw, h - ch};
        return;
    }
    if (p->arrangement == PLAY_COMPACT) {
        const int w = compact_w(p, cw, s), h = ch > COMPACT_H * s ? ch : COMPACT_H * s;
        l->window = (isk_ui_rect){0, 0, cw + w, h};
        isk_ui_rect all = {cw, 0, w, h};
        for (int i = 0; i < 3; i++)
            l->column[i] = isk_ui_cell(all, 3, 1, i, 0, 0);
        l->under = (isk_ui_rect){0, ch, cw, h - ch};
        return;
    }
    const int top = ch > CONSOLE_MIN_H * s ? ch : CONSOLE_MIN_H * s;
    l->window = (isk_ui_rect){0, 0, cw + (CONSOLE_W + SIDE_W) * s, top + BOTTOM_H * s};
    l->console = (isk_ui_rect){cw, 0, CONSOLE_W * s, top};
    l->side = (isk_ui_rect){cw + CONSOLE_W * s, 0, SIDE_W * s, top};
    l->bottom = (isk_ui_rect){0, top, l->window.w, BOTTOM_H * s};
}

void play_layout_compute(player *p)
{
    const isk_effect_def *d = isk_effect_definition(p->fx);
    play_layout_plan(p, d->width, d->height, p->panel, &p->lay);
}

static int fits(const player *p, const play_layout *l)
{
    return l->window.w <= p->screen_w && l->window.h <= p->screen_h - title_h(p);
}

/* Sets the scale, font and arrangement in p; the layout they give. */
static void try_layout(player *p, int scale, isk_font font, play_arrangement a, play_layout *l)
{
    p->ui.scale = scale;
    p->ui.font = font;
    p->arrangement = a;
    const isk_effect_def *d = isk_effect_definition(p->fx);
    play_layout_plan(p, d->width, d->height, 1, l);
}

void play_choose_layout(player *p, int asked)
{
    play_layout l;
    if (p->panel_kind == PLAY_PANEL_INSPECTOR) {
        for (int s = asked ? asked : 4; s >= 1; s--) {
            try_layout(p, s, ISK_FONT_6X13, PLAY_WIDE, &l);
            if (asked || fits(p, &l))
                return;
        }
        return; /* scale 1: the smallest there is */
    }
    if (asked) {
        try_layout(p, asked, ISK_FONT_5X8, PLAY_WIDE, &l);
        return;
    }
    for (int s = 4; s >= 2; s--) {
        try_layout(p, s, ISK_FONT_5X8, PLAY_WIDE, &l);
        if (fits(p, &l))
            return;
    }
    try_layout(p, 1, ISK_FONT_6X13, PLAY_COMPACT, &l);
    if (fits(p, &l))
        return;
    try_layout(p, 1, ISK_FONT_5X8, PLAY_WIDE, &l); /* a screen smaller than 1280x720: the smallest layout */
}
