/* SPDX-License-Identifier: MIT */
/* Rewind in the simulator: B steps back one frame, T shows the timeline,
 * a bar along the canvas's foot.  Clicking or dragging the bar goes to
 * that frame; the bar shows the frames since the last reset (light), the
 * checkpoints kept (ticks) and where the run is now (a marker).  Editing
 * anything while in the past forks the timeline there (iskra/timeline.h).
 * A step, Play and the script's frames go on from wherever the run is. */
#include <stdio.h>

#include "iskra/draw.h"
#include "iskra/text.h"
#include "play.h"
#include "play_shadow.h"

static void timeline_failed(player *p, isk_status s)
{
    play_say(p, "rewind: %s", isk_status_str(s));
    p->failed = s == ISK_ERR_NOMEM;
}

void play_rewind_restart(player *p)
{
    if (!p->timeline && !(p->timeline = isk_timeline_create(PLAY_TIMELINE_BYTES))) {
        timeline_failed(p, ISK_ERR_NOMEM);
        return;
    }
    isk_status s = isk_timeline_restart(p->timeline, p->fx, &p->sim);
    if (s != ISK_OK)
        timeline_failed(p, s);
}

void play_rewind_watch(player *p)
{
    isk_status s = isk_timeline_watch(p->timeline, p->fx, &p->sim);
    if (s != ISK_OK)
        timeline_failed(p, s);
}

void play_rewind_stepped(player *p)
{
    isk_status s = isk_timeline_stepped(p->timeline, p->fx, &p->sim);
    if (s != ISK_OK)
        timeline_failed(p, s);
}

void play_rewind_to(player *p, long frame)
{
    if (isk_timeline_is_off(p->timeline)) {
        play_say(p, "rewind is off: one frame of this scene needs more than %zu MB",
                 isk_timeline_budget(p->timeline) / 4 >> 20);
        return;
    }
    const long now = isk_effect_frame(p->fx);
    if (frame < isk_timeline_first(p->timeline)) {
        play_say(p, "frame %ld is the first one kept", isk_timeline_first(p->timeline));
        frame = isk_timeline_first(p->timeline);
    }
    if (frame == now)
        return;
    isk_status s = isk_timeline_seek(p->timeline, p->fx, &p->sim, frame);
    if (s != ISK_OK) {
        timeline_failed(p, s);
        return;
    }
    play_charts_reset(p); /* the charts follow a run forward */
    play_shadow_restart(p); /* the reference starts again from here */
}

void play_rewind_back(player *p)
{
    p->paused = 1;
    p->timeline_shown = 1;
    play_rewind_to(p, isk_effect_frame(p->fx) - 1);
}

/* The bar: the bottom rows of the canvas, a line of text over a track. */
static int text_h(const player *p) { return 8 * p->ui.scale + 2; }

static isk_ui_rect bar_rect(const player *p)
{
    const int h = text_h(p) + 4 * p->ui.scale + 4;
    const isk_ui_rect c = p->lay.canvas;
    return (isk_ui_rect){c.x, c.y + c.h - h, c.w, h};
}

int play_rewind_input(player *p, const isk_ui_area_state *a)
{
    if (!p->timeline_shown)
        return 0;
    const isk_ui_rect r = bar_rect(p);
    const int y = p->lay.canvas.y + a->y;
    if (a->pressed) /* the bar took the press: the drag stays with it */
        p->timeline_held = y >= r.y;
    if (!p->timeline_held)
        return 0;
    if (!(a->pressed || a->down || a->released))
        return 1;
    if (a->released) /* where the button comes up is where it goes */
        p->timeline_held = 0;
    const long first = isk_timeline_first(p->timeline), last = isk_timeline_last(p->timeline);
    double u = r.w > 1 ? (double)a->x / (double)(r.w - 1) : 0.0;
    u = u < 0 ? 0 : u > 1 ? 1 : u;
    p->paused = 1;
    play_rewind_to(p, first + (long)(u * (double)(last - first) + 0.5));
    return 1;
}

void play_rewind_draw(player *p)
{
    if (!p->timeline_shown)
        return;
    const isk_ui_rect r = bar_rect(p);
    isk_canvas *c = p->shown;
    const isk_timeline *t = p->timeline;
    const long first = isk_timeline_first(t), last = isk_timeline_last(t), now = isk_effect_frame(p->fx);
    const double span = last > first ? (double)(last - first) : 1.0;
    isk_fill_rect(c, r.x, r.y, r.w, r.h, (isk_color){0, 0, 0, 170}, ISK_BLEND_OVER);
    const int ty = r.y + text_h(p), th = r.h - text_h(p); /* the track, under the text */
    isk_fill_rect(c, r.x, ty + th / 2 - 1, r.w, 2, (isk_color){120, 120, 120, 255}, ISK_BLEND_OVER);
    for (int i = 0; i < isk_timeline_checkpoints(t); i++) { /* what is kept */
        const int x = r.x + (int)((double)(isk_timeline_checkpoint_frame(t, i) - first) / span * (r.w - 1));
        isk_fill_rect(c, x, ty + 1, 1, th - 2,
                      isk_timeline_checkpoint_edit(t, i) ? p->ui.style.focus : (isk_color){200, 200, 200, 255},
                      ISK_BLEND_OVER);
    }
    const int x = r.x + (int)((double)(now - first) / span * (r.w - 1));
    isk_fill_rect(c, x - 1, ty, 3, th, (isk_color){255, 210, 60, 255}, ISK_BLEND_OVER);
    char text[128];
    snprintf(text, sizeof text, "frame %ld of %ld..%ld; %d checkpoints, %zu kB kept; B back, T hide", now, first,
             last, isk_timeline_checkpoints(t), isk_timeline_bytes(t) >> 10);
    isk_draw_text(c, r.x + 4, r.y + 2, text, p->ui.scale, ISK_WHITE, ISK_BLEND_OVER);
}
