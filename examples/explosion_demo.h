/* SPDX-License-Identifier: MIT */
/* examples/explosion_demo.h — the thesis's explosion demo page, shared by
 * figures 16-20 (each figure's file names its explosion and its numbers).
 *
 * The demos: 10,000 particles from one explosion at (0, -3) on the -10..10
 * view, animated with a fixed dt per frame, no force, and a floor only.  Per
 * requestAnimationFrame the thesis clears the canvas, then for every particle
 * calls pomakni (move), iscrtaj (draw) and zarobi (bounce).  Particles do not
 * interact, so stepping all, drawing all, then bouncing all gives the same
 * bits and the same picture; that is what advance() does.
 *
 *     static const explosion_demo demo = {"fig18_gauss", "...", ISK_EXPLOSION_GAUSS,
 *                                         0.001, 800, 1};
 *     int main(int argc, char **argv) { return explosion_demo_main(argc, argv, &demo); }
 */
#ifndef ISKRA_EXPLOSION_DEMO_H
#define ISKRA_EXPLOSION_DEMO_H

#include "example.h"

typedef struct explosion_demo {
    const char *name, *about;
    isk_explosion kind;
    double dt;    /* seconds per frame, as the thesis's file */
    long frames;  /* the frame rendered by default */
    int random;   /* 1: the explosion draws random numbers (--seed) */
} explosion_demo;

typedef struct explosion_state {
    isk_system s;
    isk_view view;
    double dt;
} explosion_state;

static inline void explosion_draw(explosion_state *st, isk_canvas *c)
{
    isk_canvas_fill(c, ISK_BLACK);
    const isk_particles *p = &st->s.particles;
    for (size_t i = 0; i < p->count; i++)
        isk_world_dot_browser(c, &st->view, p->x[i], p->y[i], ISK_YELLOW, ISK_BLEND_OVER);
}

/* One frame: move (zero force), draw (when c is not NULL), then bounce. */
static inline void explosion_advance(explosion_state *st, isk_canvas *c)
{
    isk_system_step(&st->s, st->dt);
    if (c)
        explosion_draw(st, c);
    isk_system_bounce(&st->s); /* zarobi(gks, false, false, true, false) */
}

static inline void explosion_window_frame(void *state, isk_canvas *c) { explosion_advance(state, c); }

static inline int explosion_demo_main(int argc, char **argv, const explosion_demo *d)
{
    example_opts o = {.seed = 1, .frames = d->frames};
    example_parse(argc, argv, &o, (d->random ? EX_SEED : 0) | EX_FRAMES, d->name, d->about);

    explosion_state st;
    isk_canvas c;
    st.dt = d->dt;
    if (isk_system_init(&st.s, o.seed, 10000) != ISK_OK || isk_canvas_init(&c, 600, 600) != ISK_OK)
        return 1;
    isk_view_window(&st.view, 600, 600, -10, 10, -10, 10);
    isk_bounds b;
    isk_bounds_thesis(&b, -10, 10, -10, 10, ISK_SIDE_BOTTOM);
    isk_system_set_bounds(&st.s, &b, 0); /* bounce after drawing, not in the step */
    if (isk_system_explode(&st.s, d->kind, 0, -3, 10000) != ISK_OK)
        return 1;

    /* Frame 0 shows the particles where they start; frame N is the canvas
     * after N frames.  Only the last frame needs drawing. */
    isk_canvas_fill(&c, ISK_BLACK);
    if (o.frames == 0)
        explosion_draw(&st, &c);
    for (long f = 1; f <= o.frames; f++)
        explosion_advance(&st, f == o.frames ? &c : NULL);
    int rc = example_write_png(&c, &o);
    if (!rc && o.window)
        rc = example_window(&c, &o, &st, explosion_window_frame);
    isk_canvas_free(&c);
    isk_system_free(&st.s);
    return rc;
}

#endif
