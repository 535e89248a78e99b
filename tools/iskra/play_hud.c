/* SPDX-License-Identifier: MIT */
/* Over the canvas: the thesis's FPS text (white, at pixel (15, 30), the
 * frames shown divided by the seconds since the start, six decimals) and,
 * with H, the HUD: the effective speed and whether real time is kept, the
 * simulated time and frame, what the frame's stepping costs; a ring
 * around the selected potential; and while the scene file does not load,
 * its whole "FILE:LINE: message" across the canvas's foot, where the class
 * looks.  Also the status line every part of the simulator reports
 * through (play_say). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "iskra/draw.h"
#include "iskra/text.h"
#include "play.h"

void play_pace(player *p, double real_seconds, double dropped_seconds)
{
    /* Over windows of a second: the share of real time that was simulated
     * (the accumulator drops what more than 5 steps a frame would need). */
    p->pace_real += real_seconds;
    p->pace_dropped += dropped_seconds;
    if (p->pace_real >= 1.0) {
        p->pace = 1.0 - p->pace_dropped / p->pace_real;
        if (p->pace_dropped > 0)
            p->behind_until = p->elapsed + 1.0;
        p->pace_real = p->pace_dropped = 0;
    }
}

void play_speed_text(const player *p, char *buf, size_t n)
{
    const isk_effect_def *d = isk_effect_definition(p->fx);
    /* dt/base_dt: the thesis's fractional precision makes time run faster. */
    const double speed = d->dt / p->base_dt / d->speed_divisor;
    char x[32];
    if (speed < 1)
        snprintf(x, sizeof x, "x1/%.3g", 1 / speed);
    else
        snprintf(x, sizeof x, "x%.3g", speed);
    const int kept = p->fixed_clock || p->elapsed >= p->behind_until;
    if (kept)
        snprintf(buf, n, "speed %s%s, real time kept", x, speed < 1 ? " (slow motion)" : speed > 1 ? " (fast)" : "");
    else
        snprintf(buf, n, "speed %s, behind: only %.0f%% of it", x, 100 * p->pace);
}

static void ring(isk_canvas *c, double cx, double cy, double r, isk_color col)
{
    double xy[2 * 32];
    for (int i = 0; i < 32; i++) {
        xy[2 * i] = cx + r * cos(i * (2 * 3.14159265358979323846 / 32));
        xy[2 * i + 1] = cy + r * sin(i * (2 * 3.14159265358979323846 / 32));
    }
    isk_stroke_polyline(c, xy, 32, 1, col, ISK_BLEND_OVER);
}

/* The reload error, wrapped, on a dark band across the canvas's foot. */
static void reload_error(player *p, isk_canvas *v)
{
    char lines[sizeof p->reload_error + 64], text[sizeof p->reload_error + 40];
    snprintf(text, sizeof text, "%s (the last version keeps running)", p->reload_error);
    const int s = p->ui.scale, pad = 4 * s;
    const int n = isk_ui_wrap(&p->ui, text, v->width - 2 * pad, lines, sizeof lines);
    if (n <= 0)
        return;
    const int h = n * isk_ui_line_height(&p->ui) + 2 * pad;
    isk_fill_rect(v, 0, v->height - h, v->width, h, isk_rgba(0, 0, 0, 215), ISK_BLEND_OVER);
    isk_fill_rect(v, 0, v->height - h, v->width, s, p->ui.style.error, ISK_BLEND_OVER);
    isk_font_draw_text(v, p->ui.font, pad, v->height - h + pad, lines, s, p->ui.style.error, ISK_BLEND_OVER);
}

void play_hud_draw(player *p)
{
    isk_canvas v;
    const play_layout *l = &p->lay;
    if (isk_canvas_view(&v, p->shown, l->canvas.x, l->canvas.y, l->canvas.w, l->canvas.h) != ISK_OK)
        return;
    size_t n;
    const isk_potential *pots = isk_effect_potentials(p->fx, &n);
    if (p->selected >= 0 && p->selected < (int)n) {
        double sx, sy;
        isk_view_to_screen(isk_effect_view(p->fx), pots[p->selected].r.x, pots[p->selected].r.y, &sx, &sy);
        ring(&v, sx, sy, 10, p->ui.style.focus);
        ring(&v, sx, sy, 11, p->ui.style.focus);
    }
    if (p->reload_error[0])
        reload_error(p, &v);
    char text[512];
    /* The thesis's 16px Arial at baseline y = 30: the font's capitals at scale 2 end there. */
    snprintf(text, sizeof text, "FPS: %.6f", p->elapsed > 0 ? (double)p->frames_shown / p->elapsed : 0.0);
    isk_draw_text(&v, 15, 30 - 7 * 2, text, 2, ISK_WHITE, ISK_BLEND_OVER);
    if (!p->hud)
        return;
    char speed[128], cost[64] = "";
    play_speed_text(p, speed, sizeof speed);
    if (!p->fixed_clock)
        snprintf(cost, sizeof cost, "\nstepping %.2f ms per shown frame", p->update_ms);
    snprintf(text, sizeof text, "%s\nt %.3f s, frame %ld, %zu particles%s%s%s", speed, isk_effect_time(p->fx),
             isk_effect_frame(p->fx), isk_effect_particle_count(p->fx), cost,
             p->paused ? "\nHOLDING: P or Space runs" : "",
             p->physics_off ? "\nPHYSICS OFF: the precision is not a number" : "");
    const isk_font f = p->ui.font;
    const int s = p->ui.scale, y = 30 + 3 * s, w = isk_font_text_width(f, text, s), h = isk_font_text_height(f, text, s);
    isk_fill_rect(&v, 15 - 3 * s, y - 2 * s, w + 5 * s, h + 3 * s, isk_rgba(0, 0, 0, 170), ISK_BLEND_OVER);
    isk_font_draw_text(&v, f, 15, y, text, s, ISK_WHITE, ISK_BLEND_OVER);
}


/* The status line (under the panel's keys) and stderr say the same. */
void play_say(player *p, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(p->status, sizeof p->status, fmt, ap);
    va_end(ap);
    fprintf(stderr, "iskra play: %s\n", p->status);
}
