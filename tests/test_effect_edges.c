/* SPDX-License-Identifier: MIT */
/* A particle exactly on the canvas's edge is drawn.  Reflect
 * walls (margin 0) on the view's own rectangle hold a particle on each of the
 * four edges; every dot rule, with one colour (the batched kernels) and with
 * a colour ramp (the per-particle path), lights the edge's own row or column.
 * The thesis's walls and a scene without walls keep the plain window: a
 * point on the far edge is outside it, as the thesis's figures show. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"

#define W 20
#define H 10

/* The canvas is W x H pixels over [0, W] x [0, H]: one unit a pixel. */
static void render(isk_canvas *c, const char *draw, int ramp, const char *bounds, double x, double y)
{
    char text[1024];
    snprintf(text, sizeof text,
             "[scene]\nwidth = %d\nheight = %d\nbackground = black\n"
             "[view]\nxmin = 0\nxmax = %d\nymin = 0\nymax = %d\n%s"
             "[emitter p]\nsource = particle\nposition = %.17g, %.17g\nvelocity = 0, 0\n"
             "draw = %s\ncolor = white\n%s",
             W, H, W, H, bounds, x, y, draw, ramp ? "color_over_life = 0:white, 1:white\n" : "");
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load_string(&d, text, "edge.ini", &err), ISK_OK, "%s", err.message);
    isk_effect *fx = NULL;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_canvas_init(c, W, H), ISK_OK);
    cr_assert_eq(isk_effect_run(fx, c, 1), ISK_OK);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

static int lit(const isk_canvas *c, int x, int y)
{
    const uint8_t *p = c->pixels + (size_t)y * c->stride + (size_t)x * 4;
    return p[0] + p[1] + p[2];
}

static int lit_total(const isk_canvas *c)
{
    int n = 0;
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++)
            n += lit(c, x, y) > 0;
    return n;
}

static const char *const draws[] = {"dot", "pixel", "dot-browser"};
static const char walls[] = "[bounds]\nmode = reflect\nsides = all\n";

/* The four edges' midpoints and the pixel each must light. */
static const struct {
    const char *name;
    double x, y;
    int px, py;
} edges[] = {
    {"left", 0, 5, 0, 5},
    {"right", W, 5, W - 1, 5},
    {"top", 10, H, 10, 0},
    {"bottom", 10, 0, 10, H - 1},
};

Test(effect_edges, every_rule_draws_a_particle_on_each_edge_of_the_walls)
{
    for (size_t r = 0; r < sizeof draws / sizeof *draws; r++)
        for (int ramp = 0; ramp < 2; ramp++)
            for (size_t k = 0; k < sizeof edges / sizeof *edges; k++) {
                isk_canvas c;
                render(&c, draws[r], ramp, walls, edges[k].x, edges[k].y);
                cr_expect(lit(&c, edges[k].px, edges[k].py) > 0, "%s%s on the %s edge: pixel (%d, %d) is dark",
                          draws[r], ramp ? " with a ramp" : "", edges[k].name, edges[k].px, edges[k].py);
                cr_expect_eq(lit_total(&c), 1, "%s%s on the %s edge lights %d pixels, not one", draws[r],
                             ramp ? " with a ramp" : "", edges[k].name, lit_total(&c));
                isk_canvas_free(&c);
            }
}

/* Inside the canvas nothing moves: a dot half a pixel from the right edge
 * still covers two columns half each, with or without walls. */
Test(effect_edges, a_dot_inside_the_canvas_is_not_moved)
{
    isk_canvas a, b;
    render(&a, "dot", 0, walls, W - 1.5, 5);
    render(&b, "dot", 0, "", W - 1.5, 5);
    cr_expect_eq(memcmp(a.pixels, b.pixels, (size_t)a.stride * H), 0);
    cr_expect(lit(&a, W - 2, 5) > 0 && lit(&a, W - 1, 5) > 0);
    isk_canvas_free(&a);
    isk_canvas_free(&b);
}

/* Without walls, and with the thesis's walls, the view is a plain window:
 * the far edge is outside it (the thesis figures' bytes depend on it). */
Test(effect_edges, without_reflect_walls_the_far_edge_is_outside)
{
    const char *const other[] = {"", "[bounds]\nmode = thesis\nsides = all\nmargin = 0\n"};
    for (int o = 0; o < 2; o++)
        for (size_t r = 0; r < sizeof draws / sizeof *draws; r++) {
            isk_canvas c;
            render(&c, draws[r], 0, other[o], W, 5);
            cr_expect_eq(lit_total(&c), 0, "%s %s: the right edge is drawn", draws[r], o ? "thesis walls" : "no walls");
            isk_canvas_free(&c);
        }
}

/* A disc or a sprite whose centre lies off the canvas still shows the part
 * that reaches onto it (the band's early drop of far particles is the
 * sprites' own and counts their reach). */
Test(effect_edges, a_shape_centred_off_the_canvas_shows_its_part_on_it)
{
    const char *const shapes[] = {"disc\nsize = 4", "sprite\nsize = 4"};
    const struct {
        const char *name;
        double y;
        int row;
    } off[] = {{"above the top", H + 1.0, 0}, {"below the bottom", -1.0, H - 1}};
    for (size_t s = 0; s < sizeof shapes / sizeof *shapes; s++)
        for (size_t k = 0; k < sizeof off / sizeof *off; k++) {
            isk_canvas c;
            render(&c, shapes[s], 0, "", 10, off[k].y);
            cr_expect(lit(&c, 10, off[k].row) > 0, "%.4s centred one pixel %s: row %d is dark", shapes[s],
                      off[k].name, off[k].row);
            isk_canvas_free(&c);
        }
}
