/* SPDX-License-Identifier: MIT */
/* The strip of `iskra render --strip` (render_strip.h). */
#include "render_strip.h"

#include <stdio.h>
#include <string.h>

#include "cleanup.h"
#include "iskra/text.h"

enum { GAP = 4 };

int render_strip_size(int width, int height, long last, long every, int *w, int *h)
{
    const long panels = every > 0 ? last / every : 0;
    if (panels < 1 || panels > RENDER_STRIP_MAX_PANELS)
        return 0;
    const int pw = width / 2 > 0 ? width / 2 : 1, ph = height / 2 > 0 ? height / 2 : 1;
    const long sw = panels * pw + (panels - 1) * GAP;
    if (sw > ISK_CANVAS_MAX_DIM)
        return 0;
    *w = (int)sw;
    *h = ph;
    return (int)panels;
}

int render_strip_begin(render_strip *s, const char *path, int width, int height, long last, long every)
{
    memset(&s->out, 0, sizeof s->out);
    s->path = path;
    if (!path)
        return 0;
    const long panels = last / every;
    int sw, sh;
    if (panels >= 1 && panels <= RENDER_STRIP_MAX_PANELS && !render_strip_size(width, height, last, every, &sw, &sh)) {
        fprintf(stderr, "iskra render: --strip: %ld panels of %d pixels would be wider than %d pixels (fewer "
                        "panels: a larger --every, or a smaller --size)\n",
                panels, width / 2 > 0 ? width / 2 : 1, ISK_CANVAS_MAX_DIM);
        return 2;
    }
    if (!render_strip_size(width, height, last, every, &sw, &sh)) {
        fprintf(stderr, "iskra render: --strip shows frames %ld, %ld, ... <= %ld: that is %ld panels, not 1..%d "
                        "(choose --every around %ld)\n",
                every, 2 * every, last, panels, RENDER_STRIP_MAX_PANELS, last / 6 > 0 ? last / 6 : 1);
        return 2;
    }
    s->every = every;
    s->panels = (int)panels;
    s->pw = width / 2 > 0 ? width / 2 : 1;
    s->ph = sh;
    if (isk_canvas_init(&s->out, sw, sh) != ISK_OK) {
        fprintf(stderr, "iskra render: out of memory (a strip of %d panels)\n", s->panels);
        return 1;
    }
    isk_canvas_fill(&s->out, isk_rgba(60, 60, 60, 255));
    return 0;
}

int render_strip_wants(const render_strip *s, long f)
{
    return s->path && f > 0 && f % s->every == 0 && f / s->every <= s->panels;
}

/* Each panel pixel is the rounded mean of its 2x2 source pixels. */
void render_strip_frame(render_strip *s, const isk_canvas *c, long f, double time)
{
    const int k = (int)(f / s->every) - 1;
    isk_canvas panel;
    if (isk_canvas_view(&panel, &s->out, k * (s->pw + GAP), 0, s->pw, s->ph) != ISK_OK)
        return;
    for (int y = 0; y < s->ph; y++) {
        const int y0 = 2 * y < c->height ? 2 * y : c->height - 1, y1 = y0 + 1 < c->height ? y0 + 1 : y0;
        uint8_t *d = panel.pixels + (size_t)y * panel.stride;
        const uint8_t *r0 = c->pixels + (size_t)y0 * c->stride, *r1 = c->pixels + (size_t)y1 * c->stride;
        for (int x = 0; x < s->pw; x++) {
            const int x0 = 2 * x < c->width ? 2 * x : c->width - 1, x1 = x0 + 1 < c->width ? x0 + 1 : x0;
            for (int ch = 0; ch < 4; ch++)
                d[4 * x + ch] = (uint8_t)((r0[4 * x0 + ch] + r0[4 * x1 + ch] + r1[4 * x0 + ch] + r1[4 * x1 + ch] + 2) / 4);
        }
    }
    char label[48];
    snprintf(label, sizeof label, "t=%.2fs", time);
    isk_draw_text(&panel, 4, 4, label, 1, isk_rgba(200, 200, 200, 255), ISK_BLEND_OVER);
}

int render_strip_end(render_strip *s)
{
    if (!s->path)
        return 0;
    int rc = cleanup_png_write(&s->out, s->path);
    isk_canvas_free(&s->out);
    s->path = NULL;
    return rc;
}
