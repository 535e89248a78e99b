/* SPDX-License-Identifier: MIT */
/* One shown frame of the simulator (play.h), whoever shows it: input into
 * the widget layer; the panel (its actions change the effect at once);
 * shortcuts; the simulation steps of the frame; the canvas and the HUD
 * into the window's canvas; then the frame's screenshots and the script's
 * next events. */
#include <string.h>

#include "iskra/ui_sdl.h"
#include "play.h"
#include "play_shadow.h"

/* The canvas into the window, then what lies over it. */
static void compose(player *p)
{
    const play_layout *l = &p->lay;
    for (int y = 0; y < l->canvas.h && y < p->shown->height; y++)
        memcpy(p->shown->pixels + (size_t)y * p->shown->stride, p->sim.pixels + (size_t)y * p->sim.stride,
               (size_t)(l->canvas.w < p->shown->width ? l->canvas.w : p->shown->width) * 4);
    play_shadow_draw(p);
    play_hud_draw(p);
    play_rewind_draw(p);
}

int play_frame(player *p, double dt_seconds, const isk_event *ev, int nev)
{
    if (p->fixed_clock)
        dt_seconds = p->ts.dt;
    p->elapsed += dt_seconds;
    p->frames_shown++;
    for (int i = 0; i < nev; i++) {
        isk_ui_feed_event(&p->ui, &ev[i]);
    }
    play_watch(p);

    isk_ui_begin(&p->ui, p->shown);
    isk_ui_clear(&p->ui);
    play_panel(p);
    play_canvas(p);
    isk_ui_end(&p->ui);
    play_shortcuts(p);
    play_stability_watch(p);
    if (p->quit || p->failed)
        return 1;
    play_rewind_watch(p); /* after this frame's edits, before its steps */

    const double dropped = p->ts.dropped;
    int steps = p->paused || p->physics_off ? 0 : isk_timestep_advance(&p->ts, dt_seconds);
    if (!p->paused && !p->physics_off)
        play_pace(p, dt_seconds, p->ts.dropped - dropped);
    play_simulate(p, steps);
    if (p->failed)
        return 1;
    if (p->panel_toggle) {
        p->panel_toggle = 0;
        play_toggle_panel(p);
    }
    compose(p);
    if (p->shot_pending & 1)
        play_screenshot(p, 0, NULL);
    if (p->shot_pending & 2)
        play_screenshot(p, 1, NULL);
    p->shot_pending = 0;
    /* After the frame is drawn: its widgets can be pressed, its window shot;
     * the events it queues arrive with the next frame. */
    return play_script_run(p) != 0 || p->failed || p->quit; /* a script's quit ends the session here */
}
