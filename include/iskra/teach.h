/* SPDX-License-Identifier: MIT */
/* iskra/teach.h — the thesis's classes, one particle at a time.
 *
 * For the single-particle examples (figures 9–14) and for teaching: reads
 * like the thesis's JavaScript, and runs on the same per-particle kernels as
 * the particle store (src/sim/kernels.h), so both give identical bits.  Its
 * own module (src/teach), above the simulation and the view: a particle is
 * moved by the simulation's kernels and drawn and bounced through a view.
 *
 *   Vektor2D            isk_vec2 (iskra/vec2.h)
 *   MaterijalnaTocka    isk_material_point   + isk_mp_move   (pomakni)
 *   SilaTeza(g).F(mt)   isk_gravity_force(&mt, g)   = (0, m*(-g))
 *   Otpor(o).F(mt)      isk_drag_force(&mt, o)      = (-o*vx, -o*vy)
 *   CoulombovPotencijal isk_potential (iskra/forces.h), .F -> isk_potential_force
 *   Cestica             isk_particle  + isk_particle_draw (iscrtaj)
 *                                     + isk_particle_zarobi (zarobi)
 *
 * Example: figure 13 (gravity 0.25 + drag 0.1), the thesis's loop line by line:
 *
 *     isk_view view;                                         // the thesis's world window:
 *     if (isk_view_window(&view, 600, 600, -10, 10, -10, 10) != ISK_OK) return 1;
 *     isk_canvas canvas;
 *     if (isk_canvas_init(&canvas, 600, 600) != ISK_OK) return 1;
 *     isk_canvas_fill(&canvas, ISK_BLACK);
 *     isk_particle c;
 *     isk_particle_init(&c, 1, isk_vec2_make(-4, -4), isk_vec2_make(1, -2));
 *     for (int i = 0; i < 1000; i++) {
 *         isk_vec2 F = isk_vec2_add(isk_gravity_force(&c.mp, 0.25), isk_drag_force(&c.mp, 0.1));
 *         isk_mp_move(&c.mp, 0.25, F);
 *         isk_particle_draw(&c, &canvas, &view);          // draw BEFORE the bounce
 *         isk_particle_zarobi(&c, &view, 0, 0, 1, 0);     // top, right, bottom, left
 *     }
 *     isk_error err;
 *     isk_status s = isk_png_write(&canvas, "fig13.png", &err);
 *     if (s != ISK_OK) fprintf(stderr, "%s\n", err.message);
 *     isk_canvas_free(&canvas);
 *     return s != ISK_OK;
 */
#ifndef ISKRA_TEACH_H
#define ISKRA_TEACH_H

#include "iskra/canvas.h"
#include "iskra/forces.h"
#include "iskra/vec2.h"
#include "iskra/view.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct isk_material_point {
    double m;      /* masa */
    isk_vec2 r;    /* position */
    isk_vec2 v;    /* velocity */
} isk_material_point;

/* pomakni(dt, F): c = dt/m; v += c*F; r += dt*v (semi-implicit Euler). */
void isk_mp_move(isk_material_point *mp, double dt, isk_vec2 F);
/* The text's explicit Euler, for comparison: r += dt*v_old; v += (dt/m)*F. */
void isk_mp_move_explicit(isk_material_point *mp, double dt, isk_vec2 F);

isk_vec2 isk_gravity_force(const isk_material_point *mp, double g);
isk_vec2 isk_drag_force(const isk_material_point *mp, double o);
/* CoulombovPotencijal.F(mt) (may switch the potential off, see forces.h). */
isk_vec2 isk_potential_force_on(isk_potential *pot, const isk_material_point *mp, isk_fidelity centre);

typedef struct isk_particle {
    double diameter;      /* promjer: 0.1; the bounce margin */
    isk_material_point mp;
    isk_color color;      /* boja: yellow */
} isk_particle;

/* new Cestica(0.1, new MaterijalnaTocka(m, r, v)) — yellow. */
void isk_particle_init(isk_particle *c, double m, isk_vec2 r, isk_vec2 v);

/* iscrtaj: isk_world_dot_browser (1x1 px square, top-left at the transformed
 * point), source-over. */
void isk_particle_draw(const isk_particle *c, isk_canvas *canvas, const isk_view *view);

/* zarobi(gks, top, right, bottom, left): the thesis bounce against the
 * view's window with margin = diameter (the five checks of iskra/bounds.h). */
void isk_particle_zarobi(isk_particle *c, const isk_view *view, int top, int right, int bottom, int left);

/* The same bounce against explicit walls (no view needed). */
void isk_particle_zarobi_box(isk_particle *c, double xmin, double xmax, double ymin, double ymax,
                             int top, int right, int bottom, int left);

#ifdef __cplusplus
}
#endif

#endif
