/* SPDX-License-Identifier: MIT */
/* Thesis figure 14: the motion of figure 13 as an animation, shown as a strip.
 *
 * Same particle and forces as figure 13 (mass 1, start (-4,-4), velocity
 * (1,-2), gravity 0.25, drag 0.1, floor only), but animated the way the
 * thesis's file does it: every requestAnimationFrame
 *
 *     gks.ocisti();                                    // clear
 *     sila = silaTeza.F(mt); silaOtpora = otporSredstva.F(mt);
 *     mt.pomakni(dt, sila.zbroji(silaOtpora));         // dt = 0.001 per frame
 *     cestica.iscrtaj(gks);                            // draw
 *     cestica.zarobi(gks, false, false, true, false);  // bounce after drawing
 *
 * (dt is 0.001 in the file; the printed listing says 0.05.)  At 0.001 s per
 * frame the particle is slow: 1000 frames are one simulated second and it
 * first reaches the floor at frame 2857.
 *
 * What it shows: clearing and redrawing every frame turns the static path
 * of figure 13 into motion.  The thesis shows that as a comic strip read
 * left to right, and so does this example by default: six 300x300 panels
 * (the 600x600 view at half scale) at frames 0, 3000, 6000, ..., 15000, i.e.
 * t = 0..15 s: the fall, the first bounce, the rise and the second descent.
 * Each panel shows the particle as that frame drew it (one coverage dot,
 * full yellow) circled in red like the thesis's figure 9 annotation, and,
 * dimmed, where it was every 100 frames before, so the path reads at a
 * glance; the frame number is printed at the top left.  Trail, circle and
 * label are annotations of the strip, not part of the animation.
 *
 * --frames N instead renders frame N exactly as the thesis's 600x600 canvas
 * showed it (frame 0: the particle at its start, before the first render());
 * --window animates from there, one step per displayed frame, like the
 * browser.  --csv PATH writes one line per frame (see trajectory_csv.h) for
 * frames 1..N (N = --frames, or 15000 for the strip); the numbers equal the
 * thesis's JavaScript bit for bit.
 */
#include <math.h>

#include "example.h"
#include "trajectory_csv.h"

#define PANELS 6
#define PANEL_EVERY 3000L
#define PANEL_SIZE 300
#define GAP 4
#define TRAIL_EVERY 100L

typedef struct anim {
    isk_particle c;
    isk_view view;
    long frame;  /* render() calls so far */
    isk_vec2 drawn;  /* position the last frame drew */
    FILE *csv;
} anim;

/* One requestAnimationFrame of the thesis; draws into c unless c is NULL. */
static void render(anim *a, isk_canvas *c)
{
    const double dt = 0.001;
    if (c)
        isk_canvas_fill(c, ISK_BLACK); /* gks.ocisti(): clearRect over the black background */
    isk_vec2 sila = isk_gravity_force(&a->c.mp, 0.25);
    isk_vec2 otpor = isk_drag_force(&a->c.mp, 0.1);
    isk_mp_move(&a->c.mp, dt, isk_vec2_add(sila, otpor));
    if (c)
        isk_particle_draw(&a->c, c, &a->view);
    a->drawn = a->c.mp.r;
    isk_particle_zarobi(&a->c, &a->view, 0, 0, 1, 0);
    a->frame++;
    csv_row(a->csv, a->frame, a->drawn, &a->c);
}

static void window_frame(void *state, isk_canvas *c) { render(state, c); }

/* A thin red ring of radius r pixels around (x, y): the annotation. */
static void ring(isk_canvas *c, double x, double y, double r)
{
    double xy[2 * 24];
    for (int k = 0; k < 24; k++) {
        xy[2 * k] = x + r * cos(k * (2 * 3.141592653589793 / 24));
        xy[2 * k + 1] = y + r * sin(k * (2 * 3.141592653589793 / 24));
    }
    isk_stroke_polyline(c, xy, 24, 1, isk_rgba(255, 0, 0, 200), ISK_BLEND_OVER);
}

static int strip(anim *a, const example_opts *o)
{
    const long last = (PANELS - 1) * PANEL_EVERY;
    isk_vec2 *path = malloc(sizeof *path * (size_t)(last + 1));
    isk_canvas strip, panel;
    if (!path || isk_canvas_init(&strip, PANELS * PANEL_SIZE + (PANELS - 1) * GAP, PANEL_SIZE) != ISK_OK) {
        free(path);
        return 1;
    }
    isk_canvas_fill(&strip, isk_rgba(40, 40, 40, 255)); /* the gaps between panels */
    path[0] = a->c.mp.r;                               /* frame 0: the start */
    for (long f = 1; f <= last; f++) {
        render(a, NULL);
        path[f] = a->drawn;
    }
    isk_view pv; /* the same world window on a panel: 15 px per unit */
    isk_view_window(&pv, PANEL_SIZE, PANEL_SIZE, -10, 10, -10, 10);
    for (int k = 0; k < PANELS; k++) {
        long f = k * PANEL_EVERY;
        isk_canvas_view(&panel, &strip, k * (PANEL_SIZE + GAP), 0, PANEL_SIZE, PANEL_SIZE);
        isk_canvas_fill(&panel, ISK_BLACK);
        for (long t = TRAIL_EVERY; t < f; t += TRAIL_EVERY)
            isk_world_dot_browser(&panel, &pv, path[t].x, path[t].y, isk_rgba(255, 255, 0, 90), ISK_BLEND_OVER);
        isk_world_dot_browser(&panel, &pv, path[f].x, path[f].y, ISK_YELLOW, ISK_BLEND_OVER);
        double X, Y;
        isk_view_to_screen(&pv, path[f].x, path[f].y, &X, &Y);
        ring(&panel, X + 0.5, Y + 0.5, 7);
        char label[64];
        snprintf(label, sizeof label, "frame %ld  t = %ld s", f, f / 1000);
        isk_draw_text(&panel, 6, 6, label, 1, ISK_WHITE, ISK_BLEND_OVER);
    }
    int rc = example_show(&strip, o);
    isk_canvas_free(&strip);
    free(path);
    return rc;
}

int main(int argc, char **argv)
{
    example_opts o = {.frames = -1};
    example_parse(argc, argv, &o, EX_FRAMES | EX_CSV, "fig14_animation_strip",
                  "thesis figure 14: the figure-13 motion animated, as a strip of frames");

    anim a = {0};
    isk_particle_init(&a.c, 1, isk_vec2_make(-4, -4), isk_vec2_make(1, -2));
    isk_view_window(&a.view, 600, 600, -10, 10, -10, 10);
    if (csv_open(&a.csv, o.csv, o.name))
        return 1;

    int rc;
    if (o.frames < 0 && (o.png || !o.window)) {
        rc = strip(&a, &o);
    } else {
        long n = o.frames < 0 ? 0 : o.frames;
        isk_canvas c;
        if (isk_canvas_init(&c, 600, 600) != ISK_OK)
            return 1;
        isk_canvas_fill(&c, ISK_BLACK);
        if (n == 0) {
            isk_particle_draw(&a.c, &c, &a.view); /* frame 0: where it starts */
        } else {
            for (long f = 1; f < n; f++)
                render(&a, NULL);
            render(&a, &c);
        }
        rc = (o.png || o.window) ? example_write_png(&c, &o) : 0;
        if (!rc && o.window)
            rc = example_window(&c, &o, &a, window_frame);
        isk_canvas_free(&c);
    }
    rc |= csv_close(a.csv, o.csv, o.name);
    return rc;
}
