/* SPDX-License-Identifier: MIT */
/* The picture of `iskra bench stability` (see stability_map.h).
 *
 * A grid of panels, four across, one per integrator.  In a panel each
 * column is a frame step dt (log scale, sqrt 2 apart), each row a number
 * of substeps (1 at the bottom), each cell filled with its class's colour;
 * the scene's own setting has a black frame.  Where the scene has drag,
 * two lines cross the panel: grey where b*h/m reaches iskra's cap
 * (ISK_DRAG_SATURATION: beyond it drag stops particles within a step) and
 * dark red where it reaches the method's own drag edge; where it has a
 * linear spring (a potential's core), a blue line where w*h reaches the
 * method's spring edge.  h = dt/substeps, so in these coordinates every
 * edge is a straight line: one row up (twice the substeps) moves it two
 * columns right (twice the dt). */
#include <math.h>
#include <stdio.h>

#include "cleanup.h"
#include "iskra/canvas.h"
#include "iskra/draw.h"
#include "iskra/stability.h"
#include "iskra/text.h"
#include "stability_map.h"

static const isk_color CLASS_COLOR[STABILITY_CLASS_COUNT] = {
    {0x9c, 0xd8, 0x9c, 0xff}, /* stable: green */
    {0xf2, 0xc9, 0x4c, 0xff}, /* oscillating: amber */
    {0xe0, 0x60, 0x40, 0xff}, /* growing: vermillion */
    {0x5a, 0x2a, 0x6e, 0xff}, /* removed: dark purple */
};
static const char *const CLASS_LABEL[STABILITY_CLASS_COUNT] = {
    "stable", "oscillating (zigzags frame to frame)", "energy growing", "particles removed as non-finite"};
static const isk_color INK = {0, 0, 0, 0xff}, WHITE = {0xff, 0xff, 0xff, 0xff};
static const isk_color CAP = {0x70, 0x70, 0x70, 0xff}, EDGE = {0xa0, 0x00, 0x20, 0xff};
static const isk_color SPRING = {0x10, 0x40, 0xc0, 0xff};

enum { W = 1600, H = 800, COLS = 4, SCALE = 1, CELL_W = 20, CELL_H = 44 };
static const isk_font FONT = ISK_FONT_6X13;

static void text(isk_canvas *c, int x, int y, const char *s, isk_color col)
{
    isk_font_draw_text(c, FONT, x, y, s, SCALE, col, ISK_BLEND_OVER);
}

/* A line 3 px wide (three 1-px strokes side by side), clipped to the box. */
static void thick_line(isk_canvas *c, double x0, double y0, double x1, double y1, isk_color col)
{
    for (int d = -1; d <= 1; d++)
        isk_stroke_line(c, x0 + d, y0, x1 + d, y1, col, ISK_BLEND_OVER);
}

/* The line where a ratio proportional to h (b*h/m, w*h) reaches edge, in
 * the panel whose cells start at (px, py): column u (fractional, 0 = the
 * first dt) at row k (0 = 1 substep). */
static void edge_line(isk_canvas *c, int px, int py, double ratio1, double edge, isk_color col, const char *label)
{
    /* the ratio at column u, row k: ratio1 * 2^(u/2) / 2^k, ratio1 at u = 0, k = 0 */
    if (!(ratio1 > 0) || !isfinite(edge) || !(edge > 0))
        return;
    const double u0 = 2 * log2(edge / ratio1); /* at row 0 */
    const double grid_w = STABILITY_NDT * CELL_W, grid_h = STABILITY_NSUB * CELL_H;
    /* the row coordinate runs from -0.5 (bottom edge) to NSUB - 0.5 (top) */
    double ka = -0.5, kb = STABILITY_NSUB - 0.5;
    double ua = u0 + 2 * ka, ub = u0 + 2 * kb;
    /* clip to the columns' span, -0.5 .. NDT - 0.5 */
    if (ub < -0.5 || ua > STABILITY_NDT - 0.5)
        return;
    if (ua < -0.5) {
        ka += (-0.5 - ua) / 2;
        ua = -0.5;
    }
    if (ub > STABILITY_NDT - 0.5) {
        kb -= (ub - (STABILITY_NDT - 0.5)) / 2;
        ub = STABILITY_NDT - 0.5;
    }
    double x0 = px + (ua + 0.5) * CELL_W, x1 = px + (ub + 0.5) * CELL_W;
    double y0 = py + grid_h - (ka + 0.5) * CELL_H, y1 = py + grid_h - (kb + 0.5) * CELL_H;
    thick_line(c, x0, y0, x1, y1, col);
    if (label && x1 + 4 < px + grid_w + 60)
        text(c, (int)x1 + 4, (int)y1 - 2, label, col);
}

static void panel(isk_canvas *c, int x, int y, const stability_map *map, int m)
{
    char buf[96];
    const int gx = x + 70, gy = y + 34, grid_h = STABILITY_NSUB * CELL_H;
    const double edge = isk_integrator_drag_edge((isk_integrator)m);
    const double spring = isk_integrator_spring_edge((isk_integrator)m);
    char d[24], w[32];
    if (isfinite(edge))
        snprintf(d, sizeof d, "%.4g", edge);
    else
        snprintf(d, sizeof d, "none");
    if (spring > 0)
        snprintf(w, sizeof w, "%.4g", spring);
    else
        snprintf(w, sizeof w, "none (grows)");
    snprintf(buf, sizeof buf, "%s   edges: b*h/m %s, w*h %s", isk_integrator_name((isk_integrator)m), d, w);
    text(c, x + 10, y + 12, buf, INK);
    for (int k = 0; k < STABILITY_NSUB; k++) {
        snprintf(buf, sizeof buf, "x%d", map->substeps[k]);
        text(c, gx - 8 - isk_font_text_width(FONT, buf, SCALE), gy + grid_h - (k + 1) * CELL_H + CELL_H / 2 - 6, buf,
             INK);
        for (int j = 0; j < STABILITY_NDT; j++) {
            const stability_cell *cl = &map->cell[m][k][j];
            int cx = gx + j * CELL_W, cy = gy + grid_h - (k + 1) * CELL_H;
            isk_fill_rect(c, cx, cy, CELL_W, CELL_H, CLASS_COLOR[cl->cls], ISK_BLEND_OVER);
            isk_fill_rect(c, cx + CELL_W - 1, cy, 1, CELL_H, WHITE, ISK_BLEND_OVER);
            isk_fill_rect(c, cx, cy + CELL_H - 1, CELL_W, 1, WHITE, ISK_BLEND_OVER);
            int own = m == (int)map->scene_method && map->substeps[k] == map->scene_substeps &&
                      j == -STABILITY_DT_FIRST;
            if (own)
                for (int d = 0; d < 3; d++) {
                    isk_fill_rect(c, cx + d, cy + d, CELL_W - 1 - 2 * d, 1, INK, ISK_BLEND_OVER);
                    isk_fill_rect(c, cx + d, cy + CELL_H - 2 - d, CELL_W - 1 - 2 * d, 1, INK, ISK_BLEND_OVER);
                    isk_fill_rect(c, cx + d, cy + d, 1, CELL_H - 1 - 2 * d, INK, ISK_BLEND_OVER);
                    isk_fill_rect(c, cx + CELL_W - 2 - d, cy + d, 1, CELL_H - 1 - 2 * d, INK, ISK_BLEND_OVER);
                }
        }
    }
    /* dt labels every 4th column from the scene's: dt/2 (j = 0) has none */
    for (int j = -STABILITY_DT_FIRST % 4; j < STABILITY_NDT; j += 4) {
        snprintf(buf, sizeof buf, "%.3g", map->dt[j]);
        int w = isk_font_text_width(FONT, buf, SCALE);
        int cx = gx + j * CELL_W + CELL_W / 2;
        isk_fill_rect(c, cx, gy + grid_h, 1, 5, INK, ISK_BLEND_OVER);
        text(c, cx - w / 2, gy + grid_h + 8, buf, INK);
    }
    text(c, gx + 10 * CELL_W / 2, gy + grid_h + 26, "frame step dt (s)", INK);
    text(c, x + 4, gy + grid_h / 2 - 20, "sub-", INK);
    text(c, x + 4, gy + grid_h / 2 - 6, "steps", INK);
    /* b*h/m of the first column at one substep: the lines' anchor */
    const double r1 = map->cell[m][0][0].drag_ratio;
    edge_line(c, gx, gy, r1, ISK_DRAG_SATURATION, CAP, "cap");
    edge_line(c, gx, gy, r1, edge, EDGE, "edge");
    edge_line(c, gx, gy, map->cell[m][0][0].spring_ratio, spring, SPRING, "core");
}

int stability_map_write(const study_opts *o, const char *name, const stability_map *map)
{
    isk_canvas c;
    if (isk_canvas_init(&c, W, H) != ISK_OK) {
        fprintf(stderr, "iskra bench stability: out of memory\n");
        return 1;
    }
    isk_canvas_fill(&c, WHITE);
    char buf[256];
    snprintf(buf, sizeof buf, "%s: stability over frame step dt (across, log) x substeps (up) x integrator",
             map->stem);
    text(&c, 20, 14, buf, INK);
    snprintf(buf, sizeof buf,
             "each cell runs the scene for its simulated time at that setting; the framed cell is the scene's own "
             "(%s x%d, dt %.4g)",
             isk_integrator_name(map->scene_method), map->scene_substeps, map->scene_dt);
    text(&c, 20, 34, buf, INK);
    const int pw = W / COLS, ph = 290, top = 60;
    for (int m = 0; m < ISK_INTEGRATOR_COUNT; m++)
        panel(&c, (m % COLS) * pw, top + (m / COLS) * ph, map, m);
    int ly = top + 2 * ph + 10, lx = 20;
    for (int k = 0; k < STABILITY_CLASS_COUNT; k++) {
        isk_fill_rect(&c, lx, ly, 28, 18, CLASS_COLOR[k], ISK_BLEND_OVER);
        text(&c, lx + 36, ly + 3, CLASS_LABEL[k], INK);
        lx += 36 + isk_font_text_width(FONT, CLASS_LABEL[k], SCALE) + 40;
    }
    ly += 34;
    thick_line(&c, 20, ly + 7, 60, ly + 7, CAP);
    text(&c, 70, ly + 1, "cap: b*h/m = 1, where iskra's drag saturates (right of it drag stops a particle within a "
                         "step: wrong, but never unstable)", INK);
    ly += 24;
    thick_line(&c, 20, ly + 7, 60, ly + 7, EDGE);
    text(&c, 70, ly + 1, "edge: b*h/m where the textbook method's drag alone would grow (iskra/stability.h); "
                         "iskra's cap keeps every step left of it", INK);
    ly += 24;
    thick_line(&c, 20, ly + 7, 60, ly + 7, SPRING);
    text(&c, 70, ly + 1, "core: w*h at the method's spring edge, w of the stiffest linear spring (a potential's core "
                         "inside its min distance, or P = 0)", INK);
    ly += 24;
    text(&c, 20, ly + 1, "Lines only where the scene has drag or such a spring.  h = dt / substeps; m of the lightest "
                         "particle.", INK);
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", o->out_dir, name);
    int rc = cleanup_png_write(&c, path);
    isk_canvas_free(&c);
    return rc;
}
