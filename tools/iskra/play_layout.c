/* SPDX-License-Identifier: MIT */
/* Where the simulator's parts sit in the window: the canvas at the
 * top-left, the console beside it, the charts and integrators beside that,
 * the click modes, potentials and layer below (sizes in play.h). */
#include <string.h>

#include "play.h"

void play_layout_size(int canvas_w, int canvas_h, int scale, int panel, int *w, int *h)
{
    if (!panel) {
        *w = canvas_w;
        *h = canvas_h;
        return;
    }
    int top = canvas_h > CONSOLE_MIN_H * scale ? canvas_h : CONSOLE_MIN_H * scale;
    *w = canvas_w + (CONSOLE_W + SIDE_W) * scale;
    *h = top + BOTTOM_H * scale;
}

void play_layout_compute(player *p, int width, int height)
{
    const isk_effect_def *d = isk_effect_definition(p->fx);
    const int s = p->ui.scale;
    play_layout *l = &p->lay;
    memset(l, 0, sizeof *l);
    l->window = (isk_ui_rect){0, 0, width, height};
    l->canvas = (isk_ui_rect){0, 0, d->width, d->height};
    if (!p->panel)
        return;
    const int top = height - BOTTOM_H * s;
    l->console = (isk_ui_rect){d->width, 0, CONSOLE_W * s, top};
    l->side = (isk_ui_rect){d->width + CONSOLE_W * s, 0, SIDE_W * s, top};
    l->bottom = (isk_ui_rect){0, top, width, BOTTOM_H * s};
}
